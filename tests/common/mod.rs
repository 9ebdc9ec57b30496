//! Shared test support: the exact integer model of the rasterisation rules (a different
//! algorithm from the crate's: per-pixel edge functions over the bounding box, in i128), and
//! helpers for hit-count images.
#![allow(dead_code)]

#[path = "../../examples/common/exact.rs"]
mod exact;
pub mod floor;
pub mod golden;
#[path = "../../examples/common/reference.rs"]
pub mod reference;
pub mod scene;
pub mod screen;
pub mod world;

#[allow(unused_imports)]
pub use exact::{model_triangle, S};

use fixed3d::raster::{line_pixels, triangle_spans, PixelRect, ScreenPoint};
use std::collections::BTreeSet;

/// The crate's coverage of one triangle as a set (panics on a pixel produced twice).
pub fn crate_triangle(v: [ScreenPoint; 3], clip: PixelRect) -> BTreeSet<(i32, i32)> {
    let mut out = BTreeSet::new();
    for s in triangle_spans(v, clip) {
        assert!(s.x0 < s.x1, "empty span {s:?}");
        for x in s.x0..s.x1 {
            assert!(
                clip.contains(x, s.y),
                "pixel ({x}, {}) outside {clip:?}",
                s.y
            );
            assert!(
                out.insert((x, s.y)),
                "pixel ({x}, {}) twice in one triangle",
                s.y
            );
        }
    }
    out
}

/// The exact model of the line rule: for x-major lines, in each column whose centre lies in
/// [a, b) along x, the row floor(y) at that centre (y-major: axes swapped).
pub fn model_line(a: ScreenPoint, b: ScreenPoint, clip: PixelRect) -> Vec<(i32, i32)> {
    let (ax, ay, bx, by) = (a.x as i128, a.y as i128, b.x as i128, b.y as i128);
    let (dx, dy) = (bx - ax, by - ay);
    let mut out = Vec::new();
    if dx == 0 && dy == 0 {
        return out;
    }
    let swapped = dx.abs() < dy.abs();
    let (a0, a1, b0, b1) = if swapped {
        (ay, ax, by, bx)
    } else {
        (ax, ay, bx, by)
    };
    let (lo, hi) = (a0.min(b0).div_euclid(S) - 1, a0.max(b0).div_euclid(S) + 1);
    for i in lo..=hi {
        let c = i * S + S / 2;
        let in_run = if b0 > a0 {
            c >= a0 && c < b0
        } else {
            c <= a0 && c > b0
        };
        if !in_run {
            continue;
        }
        // minor = floor((a1 + (c - a0) * (b1 - a1) / (b0 - a0)) / S)
        let num = a1 * (b0 - a0) + (c - a0) * (b1 - a1);
        let den = (b0 - a0) * S;
        let m = if den > 0 {
            num.div_euclid(den)
        } else {
            (-num).div_euclid(-den)
        };
        let (x, y) = if swapped { (m, i) } else { (i, m) };
        if x >= clip.x0 as i128
            && x < clip.x1 as i128
            && y >= clip.y0 as i128
            && y < clip.y1 as i128
        {
            out.push((x as i32, y as i32));
        }
    }
    out.sort();
    out
}

pub fn crate_line(a: ScreenPoint, b: ScreenPoint, clip: PixelRect) -> Vec<(i32, i32)> {
    let mut v: Vec<(i32, i32)> = line_pixels(a, b, clip).map(|p| (p.x, p.y)).collect();
    v.sort();
    let mut m = v.clone();
    m.dedup();
    assert_eq!(m.len(), v.len(), "a line produced a pixel twice");
    v
}

/// Sub-pixel point from pixel units given as f64 (snapped to nearest, ties away from zero).
pub fn sp(x: f64, y: f64) -> ScreenPoint {
    ScreenPoint::new((x * 16.0).round() as i32, (y * 16.0).round() as i32)
}

/// A hit-count image.
pub struct Hits {
    pub w: i32,
    pub h: i32,
    pub n: Vec<u32>,
}

impl Hits {
    pub fn new(w: i32, h: i32) -> Self {
        Hits {
            w,
            h,
            n: vec![0; (w * h) as usize],
        }
    }
    pub fn clip(&self) -> PixelRect {
        PixelRect::new(0, 0, self.w, self.h)
    }
    pub fn add_triangle(&mut self, v: [ScreenPoint; 3]) {
        for (x, y) in crate_triangle(v, self.clip()) {
            self.n[(y * self.w + x) as usize] += 1;
        }
    }
    pub fn count(&self, k: u32) -> usize {
        self.n.iter().filter(|&&c| c == k).count()
    }
}

/// A deterministic xorshift for test inputs.
pub struct Rng(pub u64);

impl Rng {
    pub fn next_u64(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * ((self.next_u64() >> 11) as f64 / (1u64 << 53) as f64)
    }
}

use embedded_graphics::pixelcolor::Rgb565;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

/// A draw target that counts how often each pixel is drawn (and never drops anything outside:
/// it records it, so tests can assert nothing went there).
pub struct HitCanvas {
    pub w: i32,
    pub h: i32,
    pub hits: Vec<u32>,
    pub outside: u32,
}

impl HitCanvas {
    pub fn new(w: i32, h: i32) -> Self {
        HitCanvas {
            w,
            h,
            hits: vec![0; (w * h) as usize],
            outside: 0,
        }
    }
    pub fn at(&self, x: i32, y: i32) -> u32 {
        self.hits[(y * self.w + x) as usize]
    }
    fn hit(&mut self, p: Point) {
        if p.x >= 0 && p.y >= 0 && p.x < self.w && p.y < self.h {
            self.hits[(p.y * self.w + p.x) as usize] += 1;
        } else {
            self.outside += 1;
        }
    }
}

impl OriginDimensions for HitCanvas {
    fn size(&self) -> Size {
        Size::new(self.w as u32, self.h as u32)
    }
}

impl DrawTarget for HitCanvas {
    type Color = Rgb565;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Self::Error> {
        for Pixel(p, _) in pixels {
            self.hit(p);
        }
        Ok(())
    }
    fn fill_solid(&mut self, area: &Rectangle, _: Rgb565) -> Result<(), Self::Error> {
        for p in area.points() {
            self.hit(p);
        }
        Ok(())
    }
    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(
        &mut self,
        area: &Rectangle,
        _: I,
    ) -> Result<(), Self::Error> {
        for p in area.points() {
            self.hit(p);
        }
        Ok(())
    }
}
