//! Edge walks: the span end `ceil((x(16·py + 8) − 8) / 16)` of a triangle edge, row by row.
//!
//! An edge `p → q` (`p.y < q.y`) at row `py` is the numerator `N = (p.x − 8)·dy + dx·t` over
//! `D = 16·dy` (`t = 16·py + 8 − p.y`, the sample line's offset from `p`), and each row adds
//! `16·dx` to `N`. Three walks of that rational, all exact, differ in what a row and a set-up
//! cost, which depends on the core:
//!
//! - [`CeilStepper`]: quotient and remainder (Bresenham's error term), a few instructions a row
//!   and a set-up whose small quotients a core without a divide finds by subtraction. Exact for
//!   any coordinates within ±[`COORD_LIMIT`](super::COORD_LIMIT): the public span iterator's
//!   walk, and the pipeline's on cores without a divide instruction (Cortex-M0/M0+).
//! - [`DivideStepper`]: the numerator itself in one word, one addition and one division a row:
//!   the pipeline's walk where a word divides in one instruction (Cortex-M3/M4/M7, x86-64).
//!   Exact for every edge the pipeline draws (vertices within
//!   ±[`PIPELINE_LIMIT`](super::PIPELINE_LIMIT)), which is all it is given; the proof is at
//!   its type.

use super::{CeilStepper, ScreenPoint};
use crate::math::{mul_wide, SUBPIXEL_BITS, SUBPIXEL_SCALE};

const S: i32 = SUBPIXEL_SCALE;
const HALF: i32 = S / 2;

/// A walk of an edge's span ends, one row at a time.
pub(crate) trait EdgeWalk: Copy {
    /// A walk that is never stepped (for triangles with no rows).
    const ZERO: Self;
    /// The walk of edge `p → q` (`p.y < q.y`) from row `py`, one of its rows.
    fn at_row(p: ScreenPoint, q: ScreenPoint, py: i32) -> Self;
    /// The span end on the current row.
    fn value(&self) -> i32;
    /// Moves to the next row.
    fn step(&mut self);
}

/// The walk the pipeline's triangles take where a word divides in one instruction (see the
/// [module documentation](self)): it pays for itself on the `full` firmware preset against the
/// exact stepper.
#[cfg(not(all(target_pointer_width = "32", not(target_has_atomic = "32"))))]
pub(crate) type PipelineEdge = DivideStepper;
/// The walk the pipeline's triangles take on the smallest cores, which divide by a routine
/// (told apart as `NARROW_CORE` tells them).
#[cfg(all(target_pointer_width = "32", not(target_has_atomic = "32")))]
pub(crate) type PipelineEdge = CeilStepper;

/// `(dx, dy, p.x − 8, t)` of edge `p → q` at row `py`: `N`'s terms (see the module
/// documentation). `dy` is positive for every edge with rows (a row's sample line lies in
/// `[p.y, q.y)`); a caller that divides by it keeps it so itself.
#[inline(always)]
fn edge_terms(p: ScreenPoint, q: ScreenPoint, py: i32) -> (i32, i32, i32, i32) {
    let dx = q.x.wrapping_sub(p.x);
    let dy = q.y.wrapping_sub(p.y);
    let x = p.x.wrapping_sub(HALF);
    // The row lies within the edge's rows: |16·py| below 2²⁵.
    let t = py.wrapping_mul(S).wrapping_add(HALF).wrapping_sub(p.y);
    (dx, dy, x, t)
}

impl EdgeWalk for CeilStepper {
    const ZERO: Self = CeilStepper::ZERO;

    /// Within ±2²⁴ every difference is a 32-bit factor, `N` stays below 2⁵⁴ and `D` below 2²⁹.
    fn at_row(p: ScreenPoint, q: ScreenPoint, py: i32) -> Self {
        let (dx, dy, x, t) = edge_terms(p, q, py);
        let dy = dy.max(1);
        // Below 2²⁹ (sides below 2²⁵).
        let (den, step) = (S.wrapping_mul(dy), S.wrapping_mul(dx));
        // The whole pixels of p.x − 8 come out by a shift:
        // ceil(((16k + m)·dy + …) / 16dy) = k + ceil((m·dy + …) / 16dy), a small quotient for
        // steep edges started at their top, which a core without a divide finds by
        // subtraction.
        let (k, m) = (x >> SUBPIXEL_BITS, x & (S - 1));
        // Started within its top pixel (0 ≤ t < 16: every edge of a whole frame but those a
        // clip or a band's top cuts) both products are below 2²⁹: 32-bit operands throughout.
        let mut e = if (0..S).contains(&t) {
            CeilStepper::new32(
                m.wrapping_mul(dy).wrapping_add(dx.wrapping_mul(t)),
                den,
                step,
            )
        } else {
            let n = mul_wide(m, dy).wrapping_add(mul_wide(dx, t));
            CeilStepper::new(n, den as i64, step as i64)
        };
        e.value = e.value.wrapping_add(k);
        e
    }

    #[inline(always)]
    fn value(&self) -> i32 {
        self.value
    }

    #[inline(always)]
    fn step(&mut self) {
        CeilStepper::step(self);
    }
}

/// `ceil(N(k) / D)` where a word divides in one instruction: the numerator itself steps, one
/// addition a row, and each value is one division, `b + ⌊(N(k) − b·D + D − 1) / D⌋`, of a base
/// `b = ⌊(min(p.x, q.x) − 8) / 16⌋`. On the edge's rows (`0 ≤ t < dy`) the crossing
/// `N / dy = p.x − 8 + dx·t / dy` lies between `min − 8` and `max − 8`, and `min − 8 − 16b` in
/// `[0, 15]`, so `0 ≤ N − b·D ≤ 15·dy + |dx|·(dy − 1)`, and with the ceiling's `D − 1` the
/// word is at most `(|dx| + 31)·dy − 1`: below 2³² for edges within
/// ±[`PIPELINE_LIMIT`](super::PIPELINE_LIMIT) (`|dx|, dy ≤ 2¹⁶ − 32`), so it holds the whole
/// numerator, exactly.
#[allow(
    dead_code,
    reason = "each core draws with one pipeline walk; all are tested on the host"
)]
#[derive(Clone, Copy, Debug)]
pub(crate) struct DivideStepper {
    /// `N(k) − b·D + D − 1`.
    num: u32,
    step: u32,
    den: core::num::NonZeroU32,
    base: i32,
}

impl EdgeWalk for DivideStepper {
    const ZERO: Self = DivideStepper {
        num: 0,
        step: 0,
        den: core::num::NonZeroU32::MIN,
        base: 0,
    };

    #[inline(always)]
    fn at_row(p: ScreenPoint, q: ScreenPoint, py: i32) -> Self {
        let (dx, dy, x, t) = edge_terms(p, q, py);
        let base = p.x.min(q.x).wrapping_sub(HALF) >> SUBPIXEL_BITS;
        // N − b·D modulo 2³², which the base keeps in range.
        let above = (x.wrapping_sub(base.wrapping_mul(S)) as u32)
            .wrapping_mul(dy as u32)
            .wrapping_add(dx.wrapping_mul(t) as u32);
        let den = core::num::NonZeroU32::new(dy.wrapping_mul(S) as u32)
            .unwrap_or(core::num::NonZeroU32::MIN);
        DivideStepper {
            num: above.wrapping_add(den.get() - 1),
            step: dx.wrapping_mul(S) as u32,
            den,
            base,
        }
    }

    #[inline(always)]
    fn value(&self) -> i32 {
        // The quotient is below 2³² / D: as i32 modulo 2³², which the true value fits.
        self.base.wrapping_add((self.num / self.den) as i32)
    }

    #[inline(always)]
    fn step(&mut self) {
        self.num = self.num.wrapping_add(self.step);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::raster::{first_centre_from32, COORD_LIMIT, PIPELINE_LIMIT};

    /// The span end of edge `p → q` on row `py`, from its definition in 64-bit arithmetic.
    fn edge_end(p: ScreenPoint, q: ScreenPoint, py: i32) -> i32 {
        let (dx, dy) = (q.x as i64 - p.x as i64, q.y as i64 - p.y as i64);
        let t = 16 * py as i64 + 8 - p.y as i64;
        crate::raster::ceil_div((p.x as i64 - 8) * dy + dx * t, 16 * dy) as i32
    }

    /// An edge `p → q` (`p.y < q.y`) within ±`lim` with some rows.
    fn edge_with_rows(rng: &mut crate::testing::XorShift, lim: i32) -> (ScreenPoint, ScreenPoint) {
        loop {
            let mut extreme = || {
                if rng.next_u64().is_multiple_of(4) {
                    rng.pick(&[-lim, lim, -lim + 1, lim - 1])
                } else {
                    rng.within(lim)
                }
            };
            let p = ScreenPoint::new(extreme(), extreme());
            let q = ScreenPoint::new(extreme(), extreme());
            let (p, q) = if p.y <= q.y { (p, q) } else { (q, p) };
            if first_centre_from32(p.y) < first_centre_from32(q.y) {
                return (p, q);
            }
        }
    }

    /// Edges within ±`lim`: across the whole range, corner to corner included (where the
    /// walks' words nearly fill), random ones, and small ones at every offset.
    fn edges(seed: u64, lim: i32) -> std::vec::Vec<(ScreenPoint, ScreenPoint)> {
        let mut rng = crate::testing::XorShift(seed);
        let corner = ScreenPoint::new;
        let mut edges = std::vec![
            (corner(-lim, -lim), corner(lim, lim)),
            (corner(lim, -lim), corner(-lim, lim)),
            (corner(-lim, -lim), corner(lim, -lim + 16)),
            (corner(lim, -lim), corner(-lim, lim - 7)),
        ];
        edges.extend((0..3000).map(|_| edge_with_rows(&mut rng, lim)));
        edges.extend((0..3000).map(|_| {
            let (p, q) = edge_with_rows(&mut rng, 300);
            // Whole pixels down, so that the edge keeps its rows.
            let off = ScreenPoint::new(rng.within(lim - 300), rng.within((lim - 300) / 16) * 16);
            let at = |v: ScreenPoint| ScreenPoint::new(v.x + off.x, v.y + off.y);
            (at(p), at(q))
        }));
        edges
    }

    /// Walks `W` down every edge from a row (its first, or one at random), up to `most` rows,
    /// against the definition; returns the rows walked.
    fn walk_is_exact<W: EdgeWalk>(lim: i32, most: i32) -> u64 {
        let mut rng = crate::testing::XorShift(0x2545_F491_4F6C_DD1Du64);
        let mut rows = 0u64;
        for (p, q) in edges(0x9E37_79B9_7F4A_7C15, lim) {
            let (first, end) = (first_centre_from32(p.y), first_centre_from32(q.y));
            let start = if rng.next_u64().is_multiple_of(3) {
                first + rng.within(end - first).abs().min(end - first - 1)
            } else {
                first
            };
            let mut e = W::at_row(p, q, start);
            for py in start..end.min(start.saturating_add(most)) {
                assert_eq!(e.value(), edge_end(p, q, py), "{p:?} {q:?} row {py}");
                e.step();
                rows += 1;
            }
        }
        rows
    }

    /// R1: each pipeline walk is exact on every row of edges within ±PIPELINE_LIMIT, from
    /// any of their rows.
    #[test]
    fn r1_pipeline_edge_walks_are_exact() {
        assert!(walk_is_exact::<DivideStepper>(PIPELINE_LIMIT, i32::MAX) > 3_000_000);
        assert!(walk_is_exact::<CeilStepper>(PIPELINE_LIMIT, i32::MAX) > 3_000_000);
    }

    /// R1: the exact stepper walks edges across the whole ±COORD_LIMIT (numerators of 64
    /// bits) from any of their rows; the longest have millions of rows, of which it walks
    /// thousands.
    #[test]
    fn r1_exact_walk_covers_the_coordinate_range() {
        assert!(walk_is_exact::<CeilStepper>(COORD_LIMIT, 4000) > 3_000_000);
    }
}
