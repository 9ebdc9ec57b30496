//! Built-in shapes: the three smallest Platonic solids as `static` meshes, and a UV sphere and a
//! torus of any resolution generated into caller-supplied storage (integer trigonometry, so the
//! same vertices on every platform).

use core::fmt;

use super::{Edge, Mesh, Triangle, Uv};
use crate::math::{shr_round, Angle, Scalar, Vec3};

const fn v(x: i16, y: i16, z: i16) -> Vec3 {
    Vec3::from_int(x, y, z)
}

/// Unwraps a built-in mesh in a `static` initialiser: evaluated by the compiler, so an invalid
/// built-in mesh is a build error and nothing can panic at run time.
#[allow(clippy::panic)]
const fn checked(m: Result<Mesh<'static>, super::MeshError>) -> Mesh<'static> {
    match m {
        Ok(m) => m,
        Err(_) => panic!("built-in mesh is invalid"),
    }
}

static CUBE_POSITIONS: [Vec3; 8] = [
    v(-1, -1, -1),
    v(1, -1, -1),
    v(1, 1, -1),
    v(-1, 1, -1),
    v(-1, -1, 1),
    v(1, -1, 1),
    v(1, 1, 1),
    v(-1, 1, 1),
];
static CUBE_TRIANGLES: [Triangle; 12] = [
    [4, 5, 6],
    [4, 6, 7],
    [0, 3, 2],
    [0, 2, 1],
    [1, 2, 6],
    [1, 6, 5],
    [0, 4, 7],
    [0, 7, 3],
    [3, 7, 6],
    [3, 6, 2],
    [0, 1, 5],
    [0, 5, 4],
];
static CUBE_EDGES: [Edge; 12] = [
    [0, 1],
    [1, 2],
    [2, 3],
    [3, 0],
    [4, 5],
    [5, 6],
    [6, 7],
    [7, 4],
    [0, 4],
    [1, 5],
    [2, 6],
    [3, 7],
];

/// A cube from (−1, −1, −1) to (1, 1, 1): 8 vertices, 12 triangles, 12 edges.
pub static CUBE: Mesh<'static> = checked(match Mesh::new(&CUBE_POSITIONS, &CUBE_TRIANGLES) {
    Ok(m) => m.with_edges(&CUBE_EDGES),
    Err(e) => Err(e),
});

/// The cube's six faces, each four corners counter-clockwise seen from outside: the two
/// triangles `[a, b, c]`, `[a, c, d]` of [`CUBE`] that cover it.
const fn cube_quads() -> [[u16; 4]; 6] {
    let mut quads = [[0u16; 4]; 6];
    let mut f = 0;
    while f < 6 {
        let ([a, b, c], [_, _, d]) = (CUBE_TRIANGLES[2 * f], CUBE_TRIANGLES[2 * f + 1]);
        quads[f] = [a, b, c, d];
        f += 1;
    }
    quads
}

/// The textured cube's vertices: per face, its four corners with UVs (0, 0), (1, 0), (1, 1),
/// (0, 1) and the face's normal.
const fn textured_cube() -> ([Vec3; 24], [Uv; 24], [Vec3; 24], [Triangle; 12]) {
    let quads = cube_quads();
    let uv = [[0, 0], [1, 0], [1, 1], [0, 1]];
    let (mut p, mut t, mut n) = ([Vec3::ZERO; 24], [[Scalar::ZERO; 2]; 24], [Vec3::ZERO; 24]);
    let mut tri = [[0u16; 3]; 12];
    let mut f = 0;
    while f < 6 {
        let q = quads[f];
        // The axis on which the four corners agree is the normal's, with their coordinate.
        let mut normal = [0i32; 3];
        let mut k = 0;
        while k < 3 {
            let c = CUBE_POSITIONS[q[0] as usize].to_bits()[k];
            let mut same = true;
            let mut j = 1;
            while j < 4 {
                same = same && CUBE_POSITIONS[q[j] as usize].to_bits()[k] == c;
                j += 1;
            }
            if same {
                normal[k] = c;
            }
            k += 1;
        }
        let mut j = 0;
        while j < 4 {
            let v = 4 * f + j;
            p[v] = CUBE_POSITIONS[q[j] as usize];
            t[v] = [
                Scalar::from_bits(uv[j][0] << 16),
                Scalar::from_bits(uv[j][1] << 16),
            ];
            n[v] = Vec3::from_bits(normal[0], normal[1], normal[2]);
            j += 1;
        }
        let b = 4 * f as u16;
        tri[2 * f] = [b, b + 1, b + 2];
        tri[2 * f + 1] = [b, b + 2, b + 3];
        f += 1;
    }
    (p, t, n, tri)
}

const TEXTURED_CUBE_DATA: ([Vec3; 24], [Uv; 24], [Vec3; 24], [Triangle; 12]) = textured_cube();
static TEXTURED_CUBE_POSITIONS: [Vec3; 24] = TEXTURED_CUBE_DATA.0;
static TEXTURED_CUBE_UVS: [Uv; 24] = TEXTURED_CUBE_DATA.1;
static TEXTURED_CUBE_NORMALS: [Vec3; 24] = TEXTURED_CUBE_DATA.2;
static TEXTURED_CUBE_TRIANGLES: [Triangle; 12] = TEXTURED_CUBE_DATA.3;

/// [`CUBE`] with a whole image on each face: 24 vertices (four a face, each with the face's
/// UV corner and normal), 12 triangles. Face normals as vertex normals: Gouraud shades it
/// flat.
pub static TEXTURED_CUBE: Mesh<'static> = checked(
    match Mesh::new(&TEXTURED_CUBE_POSITIONS, &TEXTURED_CUBE_TRIANGLES) {
        Ok(m) => match m.with_uvs(&TEXTURED_CUBE_UVS) {
            Ok(m) => m.with_normals(&TEXTURED_CUBE_NORMALS),
            Err(e) => Err(e),
        },
        Err(e) => Err(e),
    },
);

static TETRA_POSITIONS: [Vec3; 4] = [v(1, 1, 1), v(1, -1, -1), v(-1, 1, -1), v(-1, -1, 1)];
static TETRA_TRIANGLES: [Triangle; 4] = [[1, 3, 2], [0, 2, 3], [0, 3, 1], [0, 1, 2]];
static TETRA_EDGES: [Edge; 6] = [[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]];

/// A regular tetrahedron inscribed in the cube [−1, 1]³: 4 vertices, 4 triangles, 6 edges.
pub static TETRAHEDRON: Mesh<'static> =
    checked(match Mesh::new(&TETRA_POSITIONS, &TETRA_TRIANGLES) {
        Ok(m) => m.with_edges(&TETRA_EDGES),
        Err(e) => Err(e),
    });

static OCTA_POSITIONS: [Vec3; 6] = [
    v(1, 0, 0),
    v(-1, 0, 0),
    v(0, 1, 0),
    v(0, -1, 0),
    v(0, 0, 1),
    v(0, 0, -1),
];
static OCTA_TRIANGLES: [Triangle; 8] = [
    [0, 2, 4],
    [1, 4, 2],
    [0, 4, 3],
    [0, 5, 2],
    [1, 3, 4],
    [1, 2, 5],
    [0, 3, 5],
    [1, 5, 3],
];
static OCTA_EDGES: [Edge; 12] = [
    [0, 2],
    [0, 3],
    [0, 4],
    [0, 5],
    [1, 2],
    [1, 3],
    [1, 4],
    [1, 5],
    [2, 4],
    [2, 5],
    [3, 4],
    [3, 5],
];

/// A regular octahedron with vertices at ±1 on each axis: 6 vertices, 8 triangles, 12 edges.
pub static OCTAHEDRON: Mesh<'static> = checked(match Mesh::new(&OCTA_POSITIONS, &OCTA_TRIANGLES) {
    Ok(m) => m.with_edges(&OCTA_EDGES),
    Err(e) => Err(e),
});

/// Why a shape could not be generated.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ShapeError {
    /// Fewer than 3 segments around (or 2 rings for a sphere).
    Resolution,
    /// More than 65,536 vertices (indices are 16-bit).
    TooManyVertices,
    /// The storage given is too small: this many vertices and triangles are needed.
    StorageTooSmall {
        /// Vertices needed (positions and normals, and UVs for a textured shape).
        vertices: usize,
        /// Triangles needed.
        triangles: usize,
    },
}

impl fmt::Display for ShapeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ShapeError::Resolution => f.write_str("a shape needs at least 3 segments and 2 rings"),
            ShapeError::TooManyVertices => f.write_str("a mesh holds at most 65536 vertices"),
            ShapeError::StorageTooSmall {
                vertices,
                triangles,
            } => write!(
                f,
                "storage too small: {vertices} vertices and {triangles} triangles needed"
            ),
        }
    }
}

impl core::error::Error for ShapeError {}

/// Vertices and triangles of a torus with `ring` segments around its axis and `tube` segments
/// around the tube.
#[must_use]
pub const fn torus_counts(ring: u16, tube: u16) -> (usize, usize) {
    let n = ring as usize * tube as usize;
    (n, 2 * n)
}

/// Vertices and triangles of a UV sphere with `segments` around and `rings` from pole to pole.
#[must_use]
pub const fn uv_sphere_counts(segments: u16, rings: u16) -> (usize, usize) {
    let s = segments as usize;
    let r = rings as usize;
    (2 + s * r.saturating_sub(1), 2 * s * r.saturating_sub(1))
}

/// The caller's storage for a generated shape, cut to the shape's size.
struct Storage<'a> {
    positions: &'a mut [Vec3],
    normals: &'a mut [Vec3],
    /// For a shape with UVs.
    uvs: Option<&'a mut [Uv]>,
    triangles: &'a mut [Triangle],
    too_small: ShapeError,
}

impl<'a> Storage<'a> {
    fn new(
        (vertices, tris): (usize, usize),
        positions: &'a mut [Vec3],
        normals: &'a mut [Vec3],
        uvs: Option<&'a mut [Uv]>,
        triangles: &'a mut [Triangle],
    ) -> Result<Self, ShapeError> {
        if vertices > 65_536 {
            return Err(ShapeError::TooManyVertices);
        }
        let too_small = ShapeError::StorageTooSmall {
            vertices,
            triangles: tris,
        };
        let uvs = match uvs {
            Some(uvs) => Some(uvs.get_mut(..vertices).ok_or(too_small)?),
            None => None,
        };
        match (
            positions.get_mut(..vertices),
            normals.get_mut(..vertices),
            triangles.get_mut(..tris),
        ) {
            (Some(positions), Some(normals), Some(triangles)) => Ok(Storage {
                positions,
                normals,
                uvs,
                triangles,
                too_small,
            }),
            _ => Err(too_small),
        }
    }

    /// The positions, normals, UVs (empty for a shape without them) and triangles to fill.
    #[allow(clippy::type_complexity)]
    fn parts(&mut self) -> (&mut [Vec3], &mut [Vec3], &mut [Uv], &mut [Triangle]) {
        (
            &mut *self.positions,
            &mut *self.normals,
            self.uvs.as_deref_mut().unwrap_or(&mut []),
            &mut *self.triangles,
        )
    }

    /// The mesh over the filled storage (its indices are checked once more).
    fn into_mesh(self) -> Result<Mesh<'a>, ShapeError> {
        let too_small = self.too_small;
        let mesh =
            Mesh::new(self.positions, self.triangles).and_then(|m| m.with_normals(self.normals));
        match self.uvs {
            Some(uvs) => mesh.and_then(|m| m.with_uvs(uvs)),
            None => mesh,
        }
        .map_err(|_| too_small)
    }
}

/// `a · b` for Q16.16 `a` and Q2.30 `b`, Q16.16.
fn mul_unit(a: i64, b: i32) -> i64 {
    shr_round(a * b as i64, 30)
}

fn sat(v: i64) -> i32 {
    v.clamp(i32::MIN as i64, i32::MAX as i64) as i32
}

/// A torus around the Y axis (major radius `major`, tube radius `minor`) with unit normals,
/// generated into the given storage. Vertex `i·tube + j` sits at angle `2πi/ring` around the axis
/// and `2πj/tube` around the tube, so the layout matches the reference scene's torus.
///
/// ```
/// use fixed3d::math::{Scalar, Vec3};
/// use fixed3d::mesh::{torus, torus_counts};
/// let (nv, nt) = torus_counts(48, 24);
/// let (mut p, mut n, mut t) = ([Vec3::ZERO; 1152], [Vec3::ZERO; 1152], [[0u16; 3]; 2304]);
/// assert_eq!((nv, nt), (1152, 2304));
/// let mesh = torus(Scalar::from_num(1), Scalar::from_num(0.4), 48, 24, &mut p, &mut n, &mut t).unwrap();
/// assert_eq!(mesh.triangles().len(), 2304);
/// assert_eq!(mesh.positions()[0], Vec3::new(Scalar::from_num(1.4), Scalar::ZERO, Scalar::ZERO));
/// ```
pub fn torus<'a>(
    major: Scalar,
    minor: Scalar,
    ring: u16,
    tube: u16,
    positions: &'a mut [Vec3],
    normals: &'a mut [Vec3],
    triangles: &'a mut [Triangle],
) -> Result<Mesh<'a>, ShapeError> {
    let shape = ((major, minor), (ring, tube));
    torus_into(shape, positions, normals, None, triangles)
}

/// Vertices and triangles of a [`textured_torus`]: a seam's vertices twice.
#[must_use]
pub const fn textured_torus_counts(ring: u16, tube: u16) -> (usize, usize) {
    let n = (ring as usize + 1) * (tube as usize + 1);
    (n, 2 * ring as usize * tube as usize)
}

/// [`torus`] with UVs: `u` from 0 to 1 around the axis, `v` from 0 to 1 around the tube,
/// the seams' vertices doubled (their UVs differ): vertex `i·(tube + 1) + j` for `i` in
/// `0..=ring` and `j` in `0..=tube`.
///
/// ```
/// use fixed3d::math::{Scalar, Vec3};
/// use fixed3d::mesh::{textured_torus, textured_torus_counts};
/// assert_eq!(textured_torus_counts(8, 4), (45, 64));
/// let (mut p, mut n, mut uv, mut t) =
///     ([Vec3::ZERO; 45], [Vec3::ZERO; 45], [[Scalar::ZERO; 2]; 45], [[0u16; 3]; 64]);
/// let (one, minor) = (Scalar::ONE, Scalar::from_num(0.4));
/// let mesh = textured_torus(one, minor, 8, 4, &mut p, &mut n, &mut uv, &mut t).unwrap();
/// assert_eq!(mesh.uvs().unwrap()[44], [one, one]);
/// assert_eq!(mesh.positions()[44], mesh.positions()[0]);
/// ```
#[allow(clippy::too_many_arguments)]
pub fn textured_torus<'a>(
    major: Scalar,
    minor: Scalar,
    ring: u16,
    tube: u16,
    positions: &'a mut [Vec3],
    normals: &'a mut [Vec3],
    uvs: &'a mut [Uv],
    triangles: &'a mut [Triangle],
) -> Result<Mesh<'a>, ShapeError> {
    let shape = ((major, minor), (ring, tube));
    torus_into(shape, positions, normals, Some(uvs), triangles)
}

/// A torus into the caller's storage: without `uvs` a grid of `ring × tube` vertices wrapped
/// round ([`torus`]), with them one more each way, the last row and column at the first's
/// positions ([`textured_torus`]).
fn torus_into<'a>(
    ((major, minor), (ring, tube)): ((Scalar, Scalar), (u16, u16)),
    positions: &'a mut [Vec3],
    normals: &'a mut [Vec3],
    uvs: Option<&'a mut [Uv]>,
    triangles: &'a mut [Triangle],
) -> Result<Mesh<'a>, ShapeError> {
    if ring < 3 || tube < 3 {
        return Err(ShapeError::Resolution);
    }
    let seam = uvs.is_some();
    let counts = if seam {
        textured_torus_counts(ring, tube)
    } else {
        torus_counts(ring, tube)
    };
    let mut store = Storage::new(counts, positions, normals, uvs, triangles)?;
    let (pos, nor, uvs, tri) = store.parts();
    let (big, small) = (major.to_bits() as i64, minor.to_bits() as i64);
    let (rows, columns) = (ring as usize + seam as usize, tube as usize + seam as usize);
    for (k, (p, n)) in pos.iter_mut().zip(nor.iter_mut()).enumerate() {
        let (i, j) = ((k / columns) as u32, (k % columns) as u32);
        let u = Angle::turn_fraction(i % ring as u32, ring as u32);
        let w = Angle::turn_fraction(j % tube as u32, tube as u32);
        let (cu, su, cw, sw) = (u.cos_bits(), u.sin_bits(), w.cos_bits(), w.sin_bits());
        let reach = big + mul_unit(small, cw);
        *p = Vec3::from_bits(
            sat(mul_unit(reach, cu)),
            sat(mul_unit(small, sw)),
            sat(mul_unit(reach, su)),
        );
        let q = |a: i32, b: i32| sat(shr_round(shr_round(a as i64 * b as i64, 30), 14));
        *n = Vec3::from_bits(q(cw, cu), sat(shr_round(sw as i64, 14)), q(cw, su));
        if let Some(uv) = uvs.get_mut(k) {
            let fraction = |a: u32, b: u16| Scalar::from_bits(((a << 16) / u32::from(b)) as i32);
            *uv = [fraction(i, ring), fraction(j, tube)];
        }
    }
    let idx = |i: usize, j: usize| {
        if seam {
            (i * columns + j) as u16
        } else {
            ((i % rows) * columns + (j % columns)) as u16
        }
    };
    let tube_n = tube as usize;
    for (k, pair) in tri.chunks_exact_mut(2).enumerate() {
        let (i, j) = (k / tube_n, k % tube_n);
        let (p00, p01, p10, p11) = (idx(i, j), idx(i, j + 1), idx(i + 1, j), idx(i + 1, j + 1));
        if let [a, b] = pair {
            *a = [p00, p01, p11];
            *b = [p00, p11, p10];
        }
    }
    store.into_mesh()
}

/// A UV sphere of `radius` around the origin, poles on the Y axis, with unit normals,
/// generated into the given storage.
///
/// ```
/// use fixed3d::math::{Scalar, Vec3};
/// use fixed3d::mesh::{uv_sphere, uv_sphere_counts};
/// assert_eq!(uv_sphere_counts(16, 8), (114, 224));
/// let (mut p, mut n, mut t) = ([Vec3::ZERO; 114], [Vec3::ZERO; 114], [[0u16; 3]; 224]);
/// let mesh = uv_sphere(Scalar::from_num(2), 16, 8, &mut p, &mut n, &mut t).unwrap();
/// assert_eq!(mesh.positions()[0], Vec3::from_int(0, 2, 0));
/// ```
pub fn uv_sphere<'a>(
    radius: Scalar,
    segments: u16,
    rings: u16,
    positions: &'a mut [Vec3],
    normals: &'a mut [Vec3],
    triangles: &'a mut [Triangle],
) -> Result<Mesh<'a>, ShapeError> {
    sphere_into(
        (radius, segments, rings),
        positions,
        normals,
        None,
        triangles,
    )
}

/// Vertices and triangles of a [`textured_uv_sphere`]: a grid with the poles and the seam
/// repeated.
#[must_use]
pub const fn textured_uv_sphere_counts(segments: u16, rings: u16) -> (usize, usize) {
    let (_, triangles) = uv_sphere_counts(segments, rings);
    ((segments as usize + 1) * (rings as usize + 1), triangles)
}

/// [`uv_sphere`] with UVs: `u` from 0 to 1 around the Y axis, `v` from 1 at the north pole to
/// 0 at the south pole (an equirectangular image maps onto it as a globe): vertex
/// `k·(segments + 1) + s` for ring `k` in `0..=rings` (0 the north pole) and `s` in
/// `0..=segments`, the last column at the first's positions.
///
/// ```
/// use fixed3d::math::{Scalar, Vec3};
/// use fixed3d::mesh::{textured_uv_sphere, textured_uv_sphere_counts};
/// assert_eq!(textured_uv_sphere_counts(8, 4), (45, 48));
/// let (mut p, mut n, mut uv, mut t) =
///     ([Vec3::ZERO; 45], [Vec3::ZERO; 45], [[Scalar::ZERO; 2]; 45], [[0u16; 3]; 48]);
/// let one = Scalar::ONE;
/// let mesh = textured_uv_sphere(one, 8, 4, &mut p, &mut n, &mut uv, &mut t).unwrap();
/// assert_eq!(mesh.uvs().unwrap()[0], [Scalar::ZERO, one]);
/// assert_eq!(mesh.positions()[8], mesh.positions()[0]);
/// ```
#[allow(clippy::too_many_arguments)]
pub fn textured_uv_sphere<'a>(
    radius: Scalar,
    segments: u16,
    rings: u16,
    positions: &'a mut [Vec3],
    normals: &'a mut [Vec3],
    uvs: &'a mut [Uv],
    triangles: &'a mut [Triangle],
) -> Result<Mesh<'a>, ShapeError> {
    sphere_into(
        (radius, segments, rings),
        positions,
        normals,
        Some(uvs),
        triangles,
    )
}

/// A UV sphere into the caller's storage: without `uvs` one vertex per pole and `segments`
/// per ring ([`uv_sphere`]), with them a grid of `(rings + 1) × (segments + 1)`
/// ([`textured_uv_sphere`]). The triangles are the same, in the same order.
fn sphere_into<'a>(
    (radius, segments, rings): (Scalar, u16, u16),
    positions: &'a mut [Vec3],
    normals: &'a mut [Vec3],
    uvs: Option<&'a mut [Uv]>,
    triangles: &'a mut [Triangle],
) -> Result<Mesh<'a>, ShapeError> {
    if segments < 3 || rings < 2 {
        return Err(ShapeError::Resolution);
    }
    let grid = uvs.is_some();
    let counts = if grid {
        textured_uv_sphere_counts(segments, rings)
    } else {
        uv_sphere_counts(segments, rings)
    };
    let mut store = Storage::new(counts, positions, normals, uvs, triangles)?;
    let (pos, nor, uvs, tri) = store.parts();
    let r = radius.to_bits() as i64;
    let (seg, last_ring) = (segments as usize, rings as usize);
    let south = counts.0 - 1;
    // Ring k (0 the north pole, `rings` the south one) and segment s of each vertex.
    let place = |idx: usize| {
        if grid {
            (idx / (seg + 1), idx % (seg + 1))
        } else if idx == 0 {
            (0, 0)
        } else if idx == south {
            (last_ring, 0)
        } else {
            ((idx - 1) / seg + 1, (idx - 1) % seg)
        }
    };
    for (idx, (p, n)) in pos.iter_mut().zip(nor.iter_mut()).enumerate() {
        let (k, s) = place(idx);
        let unit = if k == 0 {
            [0, 1 << 30, 0]
        } else if k == last_ring {
            [0, -(1 << 30), 0]
        } else {
            let theta = Angle::turn_fraction(k as u32, 2 * rings as u32);
            let phi = Angle::turn_fraction(s as u32 % seg as u32, segments as u32);
            let rho = theta.sin_bits() as i64;
            [
                shr_round(rho * phi.sin_bits() as i64, 30) as i32,
                theta.cos_bits(),
                shr_round(rho * phi.cos_bits() as i64, 30) as i32,
            ]
        };
        *p = Vec3::from_bits(
            sat(mul_unit(r, unit[0])),
            sat(mul_unit(r, unit[1])),
            sat(mul_unit(r, unit[2])),
        );
        let q = unit.map(|c| sat(shr_round(c as i64, 14)));
        *n = Vec3::from_bits(q[0], q[1], q[2]);
        if let Some(uv) = uvs.get_mut(idx) {
            let fraction = |a: usize, b: usize| Scalar::from_bits(((a << 16) / b) as i32);
            *uv = [fraction(s, seg), fraction(last_ring - k, last_ring)];
        }
    }
    let vertex = |k: usize, s: usize| {
        (if grid {
            k * (seg + 1) + s
        } else if k == 0 {
            0
        } else if k == last_ring {
            south
        } else {
            1 + (k - 1) * seg + s % seg
        }) as u16
    };
    let mut out = tri.iter_mut();
    let mut put = |t: Triangle| {
        if let Some(slot) = out.next() {
            *slot = t;
        }
    };
    for s in 0..seg {
        put([vertex(0, s), vertex(1, s), vertex(1, s + 1)]);
    }
    for k in 1..last_ring - 1 {
        for s in 0..seg {
            let (a0, a1) = (vertex(k, s), vertex(k, s + 1));
            let (b0, b1) = (vertex(k + 1, s), vertex(k + 1, s + 1));
            put([a0, b0, b1]);
            put([a0, b1, a1]);
        }
    }
    let last = last_ring - 1;
    for s in 0..seg {
        put([vertex(last, s), vertex(last_ring, s), vertex(last, s + 1)]);
    }
    store.into_mesh()
}

#[cfg(test)]
mod tests {
    use super::*;
    extern crate std;

    fn outward(mesh: &Mesh<'_>) {
        for t in mesh.triangles() {
            let p = t.map(|i| {
                mesh.positions()[i as usize]
                    .to_bits()
                    .map(|c| c as f64 / 65536.0)
            });
            let e1 = [p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]];
            let e2 = [p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]];
            let n = [
                e1[1] * e2[2] - e1[2] * e2[1],
                e1[2] * e2[0] - e1[0] * e2[2],
                e1[0] * e2[1] - e1[1] * e2[0],
            ];
            let c = [0, 1, 2].map(|k| (p[0][k] + p[1][k] + p[2][k]) / 3.0);
            let d = n[0] * c[0] + n[1] * c[1] + n[2] * c[2];
            assert!(d > 0.0, "triangle {t:?} faces inwards");
        }
    }

    #[test]
    fn solids_face_outwards() {
        outward(&CUBE);
        outward(&TETRAHEDRON);
        outward(&OCTAHEDRON);
        outward(&TEXTURED_CUBE);
    }

    #[test]
    fn sphere_faces_outwards_and_normals_are_unit() {
        let (mut p, mut n, mut t) = ([Vec3::ZERO; 114], [Vec3::ZERO; 114], [[0u16; 3]; 224]);
        let mesh = uv_sphere(Scalar::from_num(3), 16, 8, &mut p, &mut n, &mut t).unwrap();
        outward(&mesh);
        for n in mesh.normals().unwrap() {
            let l = n.length().to_num::<f64>();
            assert!((l - 1.0).abs() < 1e-3);
        }
    }

    /// The textured sphere is the plain one with its poles and seam repeated: the same
    /// triangles at the same positions and normals, facing outwards, with UVs running round
    /// the axis and from pole to pole.
    #[test]
    fn textured_sphere_is_the_sphere_with_uvs() {
        let (nv, nt) = textured_uv_sphere_counts(16, 8);
        let (mut p, mut n, mut t) = ([Vec3::ZERO; 114], [Vec3::ZERO; 114], [[0u16; 3]; 224]);
        let plain = uv_sphere(Scalar::from_num(3), 16, 8, &mut p, &mut n, &mut t).unwrap();
        let (mut tp, mut tn, mut tt) = ([Vec3::ZERO; 153], [Vec3::ZERO; 153], [[0u16; 3]; 224]);
        let mut uv = [[Scalar::ZERO; 2]; 153];
        assert_eq!((nv, nt), (153, 224));
        let one = Scalar::from_num(3);
        let textured = textured_uv_sphere(one, 16, 8, &mut tp, &mut tn, &mut uv, &mut tt).unwrap();
        outward(&textured);
        for (a, b) in plain.triangles().iter().zip(textured.triangles()) {
            for (i, j) in a.iter().zip(b) {
                let (i, j) = (*i as usize, *j as usize);
                assert_eq!(plain.positions()[i], textured.positions()[j]);
                assert_eq!(plain.normals().unwrap()[i], textured.normals().unwrap()[j]);
            }
        }
        let uvs = textured.uvs().unwrap();
        assert_eq!(uvs[0], [Scalar::ZERO, Scalar::ONE]);
        assert_eq!(uvs[nv - 1], [Scalar::ONE, Scalar::ZERO]);
        assert_eq!(
            uvs[4 * 17 + 8],
            [Scalar::from_num(0.5), Scalar::from_num(0.5)]
        );
        let mut small = [[Scalar::ZERO; 2]; 152];
        let err = textured_uv_sphere(one, 16, 8, &mut tp, &mut tn, &mut small, &mut tt);
        assert!(matches!(err, Err(ShapeError::StorageTooSmall { .. })));
    }

    #[test]
    fn torus_storage_and_resolution_errors() {
        let (mut p, mut n, mut t) = ([Vec3::ZERO; 10], [Vec3::ZERO; 10], [[0u16; 3]; 10]);
        let err = torus(Scalar::ONE, Scalar::ONE, 4, 4, &mut p, &mut n, &mut t).unwrap_err();
        assert_eq!(
            err,
            ShapeError::StorageTooSmall {
                vertices: 16,
                triangles: 32
            }
        );
        let err = torus(Scalar::ONE, Scalar::ONE, 2, 4, &mut p, &mut n, &mut t).unwrap_err();
        assert_eq!(err, ShapeError::Resolution);
        // A textured torus needs its UVs' storage too.
        let (mut p, mut n, mut t) = ([Vec3::ZERO; 25], [Vec3::ZERO; 25], [[0u16; 3]; 32]);
        let mut uv = [[Scalar::ZERO; 2]; 24];
        let too_small = ShapeError::StorageTooSmall {
            vertices: 25,
            triangles: 32,
        };
        let one = Scalar::ONE;
        let err = textured_torus(one, one, 4, 4, &mut p, &mut n, &mut uv, &mut t);
        assert_eq!(err.unwrap_err(), too_small);
    }
}
