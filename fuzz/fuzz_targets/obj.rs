//! Fuzzes the OBJ parser with raw bytes and tiny capacities: it must never panic (overflow
//! checks and debug assertions are on), never write past the storage it is given, and on
//! success leave only valid indices.
#![no_main]

use fixed3d::math::{Scalar, Vec3};
use fixed3d::obj::{bounds, corner_normals_to_vertices, parse, ObjBuffers, Placement};
use libfuzzer_sys::fuzz_target;

const CANARY: Vec3 = Vec3::from_int(-7, -7, -7);

fuzz_target!(|data: &[u8]| {
    // The first byte picks the capacity (0..=31), the rest is the file.
    let (cap, file) = match data.split_first() {
        Some((c, rest)) => ((*c & 31) as usize, rest),
        None => return,
    };
    let mut pos = [CANARY; 40];
    let mut nor = [CANARY; 40];
    let mut tex = [[Scalar::MIN; 2]; 40];
    let mut tris = [[0xAAAAu16; 3]; 40];
    let mut tt = [[0xAAAAu16; 3]; 40];
    let mut tn = [[0xAAAAu16; 3]; 40];
    let placement = match bounds(file) {
        Ok(b) if cap & 1 == 1 => Placement::fit(&b, Scalar::from_num(100)),
        _ => Placement::AsIs,
    };
    let result = {
        let mut b = ObjBuffers {
            positions: &mut pos[..cap],
            texcoords: &mut tex[..cap],
            normals: &mut nor[..cap],
            triangles: &mut tris[..cap],
            triangle_texcoords: &mut tt[..cap],
            triangle_normals: &mut tn[..cap],
        };
        parse(file, &mut b, placement)
    };
    assert!(pos[cap..].iter().chain(&nor[cap..]).all(|v| *v == CANARY));
    assert!(tex[cap..].iter().all(|v| *v == [Scalar::MIN; 2]));
    assert!(tris[cap..].iter().chain(&tt[cap..]).chain(&tn[cap..]).all(|t| *t == [0xAAAA; 3]));
    if let Ok(c) = result {
        let n = c.triangles;
        for t in &tris[..n] {
            assert!(t.iter().all(|&i| (i as usize) < c.positions));
        }
        let mut per_vertex = [Vec3::ZERO; 40];
        corner_normals_to_vertices(&tris[..n], &tn[..n], &nor[..c.normals.min(cap)], &mut per_vertex[..c.positions]);
    }
});
