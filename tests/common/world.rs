//! Whole-pipeline test scenes: triangles in world space rendered by the crate (hit counts) and
//! classified by the f64 reference.
#![allow(dead_code)]

use super::reference::{classify, Camera, Cover, V3};
use super::HitCanvas;
use embedded_graphics::pixelcolor::Rgb888;
use fixed3d::buffer::Direct;
use fixed3d::camera::LookAt;
use fixed3d::math::{Angle, Mat4, Scalar, Vec3};
use fixed3d::mesh::{Mesh, Object};
use fixed3d::pipeline::{Cull, Frame, ScreenVertex, Stats};
use fixed3d::projection::{Projection, Viewport};
use fixed3d::scene::{LightColor, Lighting, Scene};
use fixed3d::shade::Unlit;

pub fn q(v: V3) -> Vec3 {
    Vec3::from_f32(v[0] as f32, v[1] as f32, v[2] as f32).expect("coordinate in range")
}

pub fn back(v: Vec3) -> V3 {
    v.to_bits().map(|c| c as f64 / 65536.0)
}

#[derive(Clone, Copy, Debug)]
pub struct Setup {
    pub eye: V3,
    pub target: V3,
    pub up: V3,
    pub fov_deg: i32,
    pub near: f64,
    pub far: f64,
    pub w: u32,
    pub h: u32,
}

impl Setup {
    pub fn new(eye: V3, target: V3) -> Self {
        Setup {
            eye,
            target,
            up: [0.0, 1.0, 0.0],
            fov_deg: 60,
            near: 0.5,
            far: 100.0,
            w: 64,
            h: 48,
        }
    }

    pub fn frame(&self) -> Frame {
        let viewport = Viewport::new(self.w, self.h).unwrap();
        let view = LookAt::new(q(self.eye), q(self.target), q(self.up))
            .view()
            .unwrap();
        let s = |v: f64| Scalar::from_num(v);
        let p = Projection::perspective(
            Angle::from_degrees(self.fov_deg),
            viewport.aspect(),
            s(self.near),
            s(self.far),
        )
        .unwrap();
        Frame::new(&view, &p, viewport)
    }

    /// The f64 camera, built from the same quantised inputs as the crate's.
    pub fn camera(&self) -> Camera {
        let (near, far) = (
            Scalar::from_num(self.near).to_num::<f64>(),
            Scalar::from_num(self.far).to_num::<f64>(),
        );
        Camera::new(
            back(q(self.eye)),
            back(q(self.target)),
            back(q(self.up)),
            self.fov_deg as f64,
            near,
            far,
            self.w,
            self.h,
        )
    }

    /// Renders the triangles (unlit, one object) and counts hits per pixel.
    pub fn hits(&self, tris: &[[V3; 3]], cull: Cull) -> (HitCanvas, Stats) {
        let positions: Vec<Vec3> = tris.iter().flat_map(|t| t.iter().map(|&p| q(p))).collect();
        let triangles: Vec<[u16; 3]> = (0..tris.len())
            .map(|i| [3 * i as u16, 3 * i as u16 + 1, 3 * i as u16 + 2])
            .collect();
        self.hits_indexed(&positions, &triangles, cull)
    }

    pub fn hits_indexed(
        &self,
        positions: &[Vec3],
        triangles: &[[u16; 3]],
        cull: Cull,
    ) -> (HitCanvas, Stats) {
        let mesh = Mesh::new(positions, triangles).unwrap();
        let objects = [Object::new(
            &mesh,
            Mat4::IDENTITY,
            Rgb888::new(200, 100, 50),
        )];
        let scene = Scene::new(&objects, Lighting::<0>::new(LightColor::WHITE));
        let mut cache = vec![ScreenVertex::DEFAULT; scene.vertex_count()];
        let prepared = self
            .frame()
            .with_cull(cull)
            .prepare(&scene, &mut cache, Unlit)
            .unwrap();
        let mut canvas = HitCanvas::new(self.w as i32, self.h as i32);
        let stats = prepared.draw(&mut Direct::new(&mut canvas)).unwrap();
        assert_eq!(canvas.outside, 0, "nothing may be drawn outside the target");
        (canvas, stats)
    }

    /// Compares hit counts with the reference: returns (missing, unexpected, partial pixels).
    pub fn compare(&self, tris: &[[V3; 3]], cull: Cull, tol: f64) -> (usize, usize, usize) {
        let (canvas, _) = self.hits(tris, cull);
        let cam = self.camera();
        let polys: Vec<Vec<[f64; 3]>> = tris
            .iter()
            .map(|t| cam.project_triangle(t.map(|p| back(q(p)))))
            .filter(|p| {
                let a = super::reference::polygon_area(p);
                match cull {
                    Cull::Back => a < 0.0,
                    Cull::Front => a > 0.0,
                    Cull::None => true,
                }
            })
            .collect();
        let (mut missing, mut unexpected, mut partial) = (0, 0, 0);
        for y in 0..self.h as i32 {
            for x in 0..self.w as i32 {
                let covers: Vec<Cover> = polys.iter().map(|p| classify(p, x, y, tol)).collect();
                if covers.contains(&Cover::Partial) {
                    partial += 1;
                    continue;
                }
                let full = covers.iter().filter(|&&c| c == Cover::Full).count() as u32;
                let got = canvas.at(x, y);
                if got < full {
                    missing += 1;
                } else if got > full {
                    unexpected += 1;
                }
            }
        }
        (missing, unexpected, partial)
    }
}
