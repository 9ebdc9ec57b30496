//! The crate's independent float64 reference, for tests, benchmarks and reports: f64 look-at and
//! perspective, f64 near-plane clipping, no snapping, and a renderer written as a different
//! algorithm from the crate's (per-pixel edge functions over each triangle's bounding box,
//! depth from barycentric weights, flat Lambert in f64). For tests, each pixel can also be
//! classified like dEQP does: FULL or NONE when every edge is further than `tol` pixels from its
//! centre, PARTIAL otherwise (anything goes there: snapping may move an edge by up to half a
//! sub-pixel).
#![allow(dead_code)]

pub type V3 = [f64; 3];

pub fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
pub fn cross(a: V3, b: V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
pub fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
pub fn norm(a: V3) -> V3 {
    let l = dot(a, a).sqrt();
    [a[0] / l, a[1] / l, a[2] / l]
}

/// `a · b` for 4x4 matrices.
pub fn mul4(a: &[[f64; 4]; 4], b: &[[f64; 4]; 4]) -> [[f64; 4]; 4] {
    let mut m = [[0.0; 4]; 4];
    for i in 0..4 {
        for j in 0..4 {
            m[i][j] = (0..4).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    m
}

/// `m · (p, 1)`.
pub fn apply4(m: &[[f64; 4]; 4], p: V3) -> [f64; 4] {
    let v = [p[0], p[1], p[2], 1.0];
    [0, 1, 2, 3].map(|i| (0..4).map(|k| m[i][k] * v[k]).sum())
}

/// Clip-from-world in f64: perspective (z to [0, 1]) times look-at.
#[derive(Clone, Copy, Debug)]
pub struct Camera {
    pub m: [[f64; 4]; 4],
    pub width: f64,
    pub height: f64,
}

impl Camera {
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        eye: V3,
        target: V3,
        up: V3,
        fov_deg: f64,
        near: f64,
        far: f64,
        w: u32,
        h: u32,
    ) -> Self {
        let z = norm(sub(eye, target));
        let x = norm(cross(up, z));
        let y = cross(z, x);
        let view = [
            [x[0], x[1], x[2], -dot(x, eye)],
            [y[0], y[1], y[2], -dot(y, eye)],
            [z[0], z[1], z[2], -dot(z, eye)],
            [0.0, 0.0, 0.0, 1.0],
        ];
        let f = 1.0 / (fov_deg.to_radians() / 2.0).tan();
        let aspect = w as f64 / h as f64;
        let proj = [
            [f / aspect, 0.0, 0.0, 0.0],
            [0.0, f, 0.0, 0.0],
            [0.0, 0.0, far / (near - far), near * far / (near - far)],
            [0.0, 0.0, -1.0, 0.0],
        ];
        Camera {
            m: mul4(&proj, &view),
            width: w as f64,
            height: h as f64,
        }
    }

    pub fn clip(&self, p: V3) -> [f64; 4] {
        apply4(&self.m, p)
    }

    /// Screen position (pixels, y down) and depth z/w of a clip-space point with w > 0.
    pub fn screen(&self, c: [f64; 4]) -> [f64; 3] {
        [
            (c[0] / c[3] + 1.0) * self.width / 2.0,
            (1.0 - c[1] / c[3]) * self.height / 2.0,
            c[2] / c[3],
        ]
    }

    /// The triangle clipped against the near plane (z_clip > 0) and projected: a convex
    /// polygon in screen pixels with depth, empty if nothing is in front.
    pub fn project_triangle(&self, tri: [V3; 3]) -> Vec<[f64; 3]> {
        let c: Vec<[f64; 4]> = tri.iter().map(|&p| self.clip(p)).collect();
        let mut out = Vec::new();
        for i in 0..3 {
            let (a, b) = (c[i], c[(i + 1) % 3]);
            let (ia, ib) = (a[2] > 0.0, b[2] > 0.0);
            if ia {
                out.push(a);
            }
            if ia != ib {
                let t = a[2] / (a[2] - b[2]);
                out.push([0, 1, 2, 3].map(|k| a[k] + t * (b[k] - a[k])));
            }
        }
        out.into_iter().map(|c| self.screen(c)).collect()
    }
}

/// A clip-space polygon (any attributes carried after the four coordinates) clipped against
/// the near plane (z > 0) and the far plane (z ≤ w), attributes interpolated linearly in clip
/// space (which is what makes them perspective-correct on screen).
pub fn clip_near_far<const N: usize>(poly: &[[f64; N]]) -> Vec<[f64; N]> {
    let mut out: Vec<[f64; N]> = poly.to_vec();
    let planes: [fn(&[f64; N]) -> f64; 2] = [|c| c[2], |c| c[3] - c[2]];
    for (k, dist) in planes.iter().enumerate() {
        let input = std::mem::take(&mut out);
        for i in 0..input.len() {
            let (a, b) = (input[i], input[(i + 1) % input.len()]);
            let (da, db) = (dist(&a), dist(&b));
            let inside = |d: f64| if k == 0 { d > 0.0 } else { d >= 0.0 };
            if inside(da) {
                out.push(a);
            }
            if inside(da) != inside(db) {
                let t = da / (da - db);
                let mut v = [0.0; N];
                for j in 0..N {
                    v[j] = a[j] + t * (b[j] - a[j]);
                }
                out.push(v);
            }
        }
    }
    out
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cover {
    Full,
    Partial,
    None,
}

/// Signed area of a polygon (y down; negative = front face, counter-clockwise in world).
pub fn polygon_area<const N: usize>(p: &[[f64; N]]) -> f64 {
    let mut a = 0.0;
    for i in 0..p.len() {
        let (u, v) = (p[i], p[(i + 1) % p.len()]);
        a += u[0] * v[1] - v[0] * u[1];
    }
    a
}

/// How far `(x, y)` lies inside a convex polygon whose doubled area has sign `sign` (x, y in
/// the first two coordinates of each vertex): the distance to the nearest edge line, negative
/// outside.
pub fn inside_distance<const N: usize>(poly: &[[f64; N]], sign: f64, x: f64, y: f64) -> f64 {
    let mut min_d = f64::INFINITY;
    for i in 0..poly.len() {
        let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
        let (ex, ey) = (b[0] - a[0], b[1] - a[1]);
        let len = (ex * ex + ey * ey).sqrt();
        if len > 0.0 {
            min_d = min_d.min(sign * (ex * (y - a[1]) - ey * (x - a[0])) / len);
        }
    }
    min_d
}

/// Classifies the centre of pixel (px, py) against a convex polygon.
pub fn classify(poly: &[[f64; 3]], px: i32, py: i32, tol: f64) -> Cover {
    if poly.len() < 3 {
        return Cover::None;
    }
    let area = polygon_area(poly);
    if area == 0.0 {
        return Cover::None;
    }
    let min_d = inside_distance(poly, area.signum(), px as f64 + 0.5, py as f64 + 0.5);
    if min_d > tol {
        Cover::Full
    } else if min_d < -tol {
        Cover::None
    } else {
        Cover::Partial
    }
}

/// Depth z/w at a pixel centre on the plane of a projected polygon (its first three vertices).
pub fn depth_at(poly: &[[f64; 3]], px: i32, py: i32) -> f64 {
    let (a, b, c) = (poly[0], poly[1], poly[2]);
    let (x, y) = (px as f64 + 0.5, py as f64 + 0.5);
    let det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
    let l1 = ((x - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (y - a[1])) / det;
    let l2 = ((b[0] - a[0]) * (y - a[1]) - (x - a[0]) * (b[1] - a[1])) / det;
    a[2] + l1 * (b[2] - a[2]) + l2 * (c[2] - a[2])
}

/// What the reference renderer produced.
pub struct RefImage {
    pub width: u32,
    pub height: u32,
    /// RGB per pixel (`None`: background).
    pub color: Vec<Option<[u8; 3]>>,
    /// z/w per pixel (1.0 where nothing was drawn).
    pub depth: Vec<f64>,
    /// Front-facing triangles after clipping.
    pub drawn: usize,
}

/// Renders triangles (world space, counter-clockwise front) with back-face culling, a
/// depth buffer (strictly nearer wins) and flat Lambert shading:
/// `colour = floor(base · clamp(ambient + Σ intensity · max(0, n·l)))` per channel.
pub fn render_flat(
    cam: &Camera,
    tris: &[[V3; 3]],
    base: [u8; 3],
    ambient: f64,
    lights: &[(V3, f64)],
) -> RefImage {
    let (w, h) = (cam.width as usize, cam.height as usize);
    let mut img = RefImage {
        width: cam.width as u32,
        height: cam.height as u32,
        color: vec![None; w * h],
        depth: vec![1.0; w * h],
        drawn: 0,
    };
    let lights: Vec<(V3, f64)> = lights.iter().map(|(d, i)| (norm(*d), *i)).collect();
    for t in tris {
        let poly = cam.project_triangle(*t);
        if poly.len() < 3 || polygon_area(&poly) >= 0.0 {
            continue; // behind the camera, degenerate or back-facing (y down: front is negative)
        }
        img.drawn += 1;
        let n = norm(cross(sub(t[1], t[0]), sub(t[2], t[0])));
        let s = (ambient
            + lights
                .iter()
                .map(|(l, i)| i * dot(n, *l).max(0.0))
                .sum::<f64>())
        .clamp(0.0, 1.0);
        let rgb = base.map(|c| (c as f64 * s).floor() as u8);
        for k in 1..poly.len() - 1 {
            fill(&mut img, [poly[0], poly[k], poly[k + 1]], rgb);
        }
    }
    img
}

/// One screen triangle by per-pixel edge functions over its bounding box.
fn fill(img: &mut RefImage, p: [[f64; 3]; 3], rgb: [u8; 3]) {
    let (w, h) = (img.width as i64, img.height as i64);
    let area =
        (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[2][0] - p[0][0]) * (p[1][1] - p[0][1]);
    if area == 0.0 {
        return;
    }
    let x0 = p
        .iter()
        .map(|v| v[0])
        .fold(f64::INFINITY, f64::min)
        .floor()
        .max(0.0) as i64;
    let x1 = p
        .iter()
        .map(|v| v[0])
        .fold(f64::NEG_INFINITY, f64::max)
        .ceil()
        .min(w as f64) as i64;
    let y0 = p
        .iter()
        .map(|v| v[1])
        .fold(f64::INFINITY, f64::min)
        .floor()
        .max(0.0) as i64;
    let y1 = p
        .iter()
        .map(|v| v[1])
        .fold(f64::NEG_INFINITY, f64::max)
        .ceil()
        .min(h as f64) as i64;
    for py in y0..y1 {
        for px in x0..x1 {
            let (x, y) = (px as f64 + 0.5, py as f64 + 0.5);
            // Barycentric weights, each positive inside whatever the winding.
            let e = |a: [f64; 3], b: [f64; 3]| {
                ((b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])) / area
            };
            let (l0, l1, l2) = (e(p[1], p[2]), e(p[2], p[0]), e(p[0], p[1]));
            if l0 < 0.0 || l1 < 0.0 || l2 < 0.0 {
                continue;
            }
            let z = l0 * p[0][2] + l1 * p[1][2] + l2 * p[2][2];
            let i = (py * w + px) as usize;
            if z < img.depth[i] {
                img.depth[i] = z;
                img.color[i] = Some(rgb);
            }
        }
    }
}
