//! Fuzzes the renderer: random meshes (any coordinates, invalid indices among them, with or
//! without vertex normals and UVs), cameras, ambient, directional and point lights, viewports,
//! band heights, storage sizes (room to carry triangles from band to band among them),
//! shadings, styles, textures (24-bit and 5/6/5 texels, every wrap, filter, mapping and run)
//! and highlights. It must never panic (overflow checks and
//! debug assertions are on), never write outside its buffers (canary cells after them) or the
//! display, and draw a frame in bands as it draws it in one pass.
#![no_main]

use embedded_graphics::draw_target::DrawTarget;
use embedded_graphics::geometry::{OriginDimensions, Size};
use embedded_graphics::pixelcolor::{Rgb565, Rgb888};
use embedded_graphics::{Drawable, Pixel};
use fixed3d::buffer::Carried;
use fixed3d::math::{Scalar, Vec3};
use fixed3d::mesh::{Mesh, Specular};
use fixed3d::scene::{Attenuation, PointLight};
use fixed3d::texture::{Filter, Mapping, Texels, Texture, Wrap};
use fixed3d::pipeline::{Bin, Cull, ScreenVertex};
use fixed3d::render::{Model, Renderer, Shade, Wireframe};
use fixed3d::{Camera, Light};
use libfuzzer_sys::fuzz_target;

/// Bytes read in order; zero once they run out.
struct Bytes<'a>(&'a [u8]);

impl Bytes<'_> {
    fn u8(&mut self) -> u8 {
        let (first, rest) = self.0.split_first().map_or((0, &[][..]), |(f, r)| (*f, r));
        self.0 = rest;
        first
    }
    fn i32(&mut self) -> i32 {
        i32::from_le_bytes([self.u8(), self.u8(), self.u8(), self.u8()])
    }
    /// A coordinate: usually small, sometimes anything Q16.16 holds.
    fn scalar(&mut self) -> Scalar {
        let raw = self.i32();
        match self.u8() % 4 {
            0 => Scalar::from_bits(raw),
            _ => Scalar::from_bits(raw >> 12),
        }
    }
    fn vec3(&mut self) -> Vec3 {
        Vec3::new(self.scalar(), self.scalar(), self.scalar())
    }
}

/// A display that fails on any pixel outside it.
struct Screen {
    size: Size,
    pixels: Vec<Rgb565>,
}

impl OriginDimensions for Screen {
    fn size(&self) -> Size {
        self.size
    }
}

impl DrawTarget for Screen {
    type Color = Rgb565;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(&mut self, pixels: I) -> Result<(), Self::Error> {
        for Pixel(p, c) in pixels {
            assert!(p.x >= 0 && p.y >= 0, "{p:?} outside the display");
            let (x, y) = (p.x as u32, p.y as u32);
            assert!(x < self.size.width && y < self.size.height, "{p:?} outside the display");
            self.pixels[(y * self.size.width + x) as usize] = c;
        }
        Ok(())
    }
}

const CANARY: u16 = 0xBEEF;

fuzz_target!(|data: &[u8]| {
    let mut b = Bytes(data);
    let vertices = 3 + b.u8() as usize % 30;
    let positions: Vec<Vec3> = (0..vertices).map(|_| b.vec3()).collect();
    let triangles: Vec<[u16; 3]> = (0..1 + b.u8() % 40)
        .map(|_| [0; 3].map(|_| u16::from(b.u8()) % (vertices as u16 + 2)))
        .collect();
    let normals: Vec<Vec3> = (0..vertices).map(|_| b.vec3()).collect();
    let uvs: Vec<[Scalar; 2]> = (0..vertices).map(|_| [b.scalar(), b.scalar()]).collect();
    let Ok(plain) = Mesh::new(&positions, &triangles) else {
        return;
    };
    let with = b.u8();
    let mesh = if with & 1 != 0 { plain.with_normals(&normals).unwrap_or(plain) } else { plain };
    let mesh = if with & 2 != 0 { mesh.with_uvs(&uvs).unwrap_or(mesh) } else { mesh };
    let texels: Vec<Rgb888> = (0..12).map(|_| Rgb888::new(b.u8(), b.u8(), b.u8())).collect();
    let (tw, th) = (1 + u16::from(b.u8() % 4), 1 + u16::from(b.u8() % 3));
    // Texels in 8-bit channels or in 5/6/5 (the two depth families the paint lights).
    let texels565: Vec<Rgb565> = texels.iter().map(|&c| c.into()).collect();
    let format = if b.u8() % 2 == 0 {
        Texels::Rgb888(&texels)
    } else {
        Texels::Rgb565(&texels565)
    };
    let Ok(texture) = Texture::new(format, tw, th) else {
        return;
    };
    let texture = texture
        .with_wrap([Wrap::Repeat, Wrap::Clamp][usize::from(b.u8() % 2)])
        .with_filter([Filter::Nearest, Filter::Bilinear][usize::from(b.u8() % 2)])
        .with_mapping([Mapping::Perspective, Mapping::Affine][usize::from(b.u8() % 2)])
        .with_run(b.u8());
    let gloss = Specular::new(
        Rgb888::new(b.u8(), b.u8(), b.u8()),
        u16::from_le_bytes([b.u8(), b.u8()]),
    );
    let models: Vec<Model<'_>> = (0..1 + b.u8() % 3)
        .map(|_| {
            let shade = [Shade::Unlit, Shade::Flat, Shade::Gouraud, Shade::PerspectiveGouraud]
                [usize::from(b.u8() % 4)];
            let mut model = Model::new(&mesh, Rgb888::new(b.u8(), b.u8(), b.u8()))
                .rotated_y(b.scalar())
                .rotated_x(b.scalar())
                .scaled(b.scalar())
                .translated(b.vec3())
                .shaded(shade);
            let extras = b.u8();
            if extras & 1 != 0 {
                model = model.textured(&texture);
            }
            if extras & 2 != 0 {
                model = model.glossy(&gloss);
            }
            if extras % 16 >= 12 {
                model = model.wireframe();
            }
            model
        })
        .collect();
    let camera = if b.u8() % 4 == 0 {
        Camera::orthographic(b.scalar(), b.scalar(), b.scalar())
    } else {
        Camera::perspective(b.scalar(), b.scalar(), b.scalar())
    }
    .looking_at(b.vec3(), b.vec3());
    let lights: Vec<Light> = (0..b.u8() % 6)
        .map(|_| match b.u8() % 3 {
            0 => Light::ambient(b.scalar()),
            1 => Light::directional(b.vec3(), b.scalar()),
            _ => {
                let attenuation = [Attenuation::None, Attenuation::Linear, Attenuation::InverseSquare]
                    [usize::from(b.u8() % 3)];
                let point = PointLight::new(b.vec3(), b.scalar()).attenuated(attenuation);
                if b.u8() % 2 == 0 { point.within(b.scalar()) } else { point }.into()
            }
        })
        .collect();
    let cull = [Cull::Back, Cull::Front, Cull::None][usize::from(b.u8() % 3)];
    let (w, h) = (1 + u32::from(b.u8() % 48), 1 + u32::from(b.u8() % 48));
    let rows = 1 + u32::from(b.u8()) % h;
    let cache = usize::from(b.u8()) % (3 * vertices + 2);
    let bins = usize::from(b.u8()) % 130;
    let carried = usize::from(b.u8()) % 40;

    let mut frames = Vec::new();
    for band_rows in [h, rows] {
        let mut screen = Screen {
            size: Size::new(w, h),
            pixels: vec![Rgb565::new(1, 2, 3); (w * h) as usize],
        };
        let n = (w * band_rows) as usize;
        let mut v = vec![ScreenVertex::DEFAULT; cache];
        let mut bin = vec![Bin::EMPTY; bins];
        let mut room = vec![Carried::EMPTY; carried];
        let mut color = vec![Rgb565::new(0, 0, 0); n + 8];
        let mut depth = vec![CANARY; n + 8];
        let (c, d) = (&mut color[..n], &mut depth[..n]);
        let drawn = Renderer::from_slices(&mut v, &mut bin, c, d)
            .with_carried(&mut room)
            .with_cull(cull)
            .render(&models, &lights, &camera, &mut screen);
        assert!(depth[n..].iter().all(|&x| x == CANARY));
        assert!(color[n..].iter().all(|&x| x == Rgb565::new(0, 0, 0)));
        frames.push((drawn.is_ok(), screen.pixels));
    }
    // One pass and bands: the same outcome, the same image.
    assert_eq!(frames[0].0, frames[1].0);
    assert!(frames[0].1 == frames[1].1, "bands differ from one pass");

    // Wireframes straight into the display.
    let mut screen = Screen {
        size: Size::new(w, h),
        pixels: vec![Rgb565::new(0, 0, 0); (w * h) as usize],
    };
    let mut v = vec![ScreenVertex::DEFAULT; cache];
    let mut rgb = ScreenRgb(&mut screen);
    let _ = Wireframe::new(&models, &camera, &mut v).draw(&mut rgb);
});

/// The display in `Rgb888`, for `Wireframe`.
struct ScreenRgb<'a>(&'a mut Screen);

impl OriginDimensions for ScreenRgb<'_> {
    fn size(&self) -> Size {
        self.0.size
    }
}

impl DrawTarget for ScreenRgb<'_> {
    type Color = Rgb888;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb888>>>(&mut self, pixels: I) -> Result<(), Self::Error> {
        self.0.draw_iter(pixels.into_iter().map(|Pixel(p, c)| Pixel(p, c.into())))
    }
}
