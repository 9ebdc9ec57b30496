//! The direction of a triangle's face normal, exact at any scale, and the shifts that keep
//! vectors within words: what both flat shading and the normals a mesh keeps compute, so
//! that a kept normal and one found every frame are the same.

use super::{
    below_bits, cross_in_words, cross_wide, magnitude_bits, map3, mul_wide, NewtonDirection,
};

/// Shifts a vector so that its largest component is below 2³⁰ (no division, no sqrt): enough
/// headroom for one more product with Q16.16 before normalising.
pub(crate) fn shrink(v: [i64; 3]) -> [i64; 3] {
    shrink_below(v, 30)
}

/// Shifts a vector so that every component lies within ±(2^`bits` − 1).
#[inline]
pub(crate) fn shrink_below(v: [i64; 3], bits: u32) -> [i64; 3] {
    // The common case, found by comparisons (counting bits is a library call on Cortex-M0).
    if below_bits(v[0], bits) && below_bits(v[1], bits) && below_bits(v[2], bits) {
        return v;
    }
    let magnitude = magnitude_bits(&v);
    if magnitude > bits {
        let s = magnitude - bits;
        map3(v, |c| c >> s)
    } else {
        v
    }
}

/// `m · v` for a normal matrix (entries within ±2³⁰) and a vector below 2³⁰.
pub(crate) fn apply(m: &[[i32; 3]; 3], v: [i64; 3]) -> [i64; 3] {
    // Each product is below 2⁶⁰ and three sum below 2⁶²: nothing to saturate.
    let [x, y, z] = map3(v, |c| c as i32);
    map3(*m, |[r0, r1, r2]| {
        mul_wide(r0, x)
            .wrapping_add(mul_wide(r1, y))
            .wrapping_add(mul_wide(r2, z))
    })
}

/// The face normal of a model-space triangle, counter-clockwise front, at some scale that fits
/// 32-bit words (every component within ±(2³¹ − 1); within ±2³⁰ through a normal matrix), in
/// world space through `normal_matrix` (in model space without one); zero for a zero-area
/// triangle. Without a normal matrix it is the exact cross product wherever that fits (every
/// triangle whose edges lie within ±2¹⁵, on every core alike), and shifted right as little as
/// brings it within range otherwise. Edges of any length: the cross product is exact in i64
/// after the edges are shifted below 2³⁰ (case T33). `extent` bounds every coordinate's
/// magnitude (the mesh's [`extent`](crate::mesh::Mesh::extent)): below 2²⁹ the edges need no
/// shifting, and are not even checked. `edge_extent` bounds every component of the edges
/// `b − a` and `c − a` (the mesh's `edge_extent`): below 2¹⁵ the cross product in words on
/// 32-bit cores needs no test of them either.
pub(crate) fn face_direction(
    p: [[i32; 3]; 3],
    normal_matrix: Option<&[[i32; 3]; 3]>,
    extent: u32,
    edge_extent: u32,
) -> [i32; 3] {
    let [a, b, c] = p;
    let short = extent < 1 << 29;
    let edge = |q: [i32; 3]| {
        let [q0, q1, q2] = q;
        let [a0, a1, a2] = a;
        if short {
            // Both coordinates below 2²⁹: the difference is below 2³⁰ and fits i32.
            return [
                q0.wrapping_sub(a0),
                q1.wrapping_sub(a1),
                q2.wrapping_sub(a2),
            ];
        }
        let d = |q: i32, a: i32| q as i64 - a as i64;
        map3(shrink([d(q0, a0), d(q1, a1), d(q2, a2)]), |c| c as i32)
    };
    let (u, v) = (edge(b), edge(c));
    // Every edge of the mesh within ±(2¹⁵ − 1), as the torus': the exact cross product in words,
    // with no test of each edge. It lies within ±(2³¹ − 2¹⁵), where `shrink_below(…, 31)`
    // leaves it too: the same direction whichever way it is found.
    if normal_matrix.is_none() && edge_extent < 1 << 15 {
        return cross_in_words(u, v);
    }
    // Both edges are below 2³⁰ after `shrink`: 32-bit factors, an exact cross product.
    let n = cross_wide(u, v);
    let n = match normal_matrix {
        Some(m) => shrink(apply(m, shrink(n))),
        None => shrink_below(n, 31),
    };
    // Within ±(2³¹ − 1) after `shrink_below`.
    map3(n, |c| c as i32)
}

/// The [`NewtonDirection`] of a model-space triangle's face normal (see [`face_direction`]);
/// `None` for a zero-area triangle.
pub(crate) fn face_newton_direction(
    p: [[i32; 3]; 3],
    (extent, edge_extent): (u32, u32),
) -> Option<NewtonDirection> {
    NewtonDirection::new(face_direction(p, None, extent, edge_extent))
}
