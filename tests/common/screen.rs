//! A display for tests that keeps what it is sent and counts the writes.
#![allow(dead_code)]

use embedded_graphics::draw_target::DrawTarget;
use embedded_graphics::geometry::{OriginDimensions, Size};
use embedded_graphics::pixelcolor::{PixelColor, Rgb888};
use embedded_graphics::Pixel;

/// `w` x `h` pixels of colour `C`, each written pixel counted.
pub struct Screen<C> {
    pub w: u32,
    pub h: u32,
    pub pixels: Vec<C>,
    pub writes: usize,
}

impl<C: PixelColor> Screen<C> {
    /// A screen filled with `blank` (a colour no frame draws, to tell what was written).
    pub fn new(w: u32, h: u32, blank: C) -> Self {
        Screen {
            w,
            h,
            pixels: vec![blank; (w * h) as usize],
            writes: 0,
        }
    }

    /// The pixels in 24-bit colour.
    pub fn rgb(&self) -> Vec<Rgb888>
    where
        C: Into<Rgb888>,
    {
        self.pixels.iter().map(|&p| p.into()).collect()
    }
}

impl<C> OriginDimensions for Screen<C> {
    fn size(&self) -> Size {
        Size::new(self.w, self.h)
    }
}

impl<C: PixelColor> DrawTarget for Screen<C> {
    type Color = C;
    type Error = core::convert::Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<C>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Self::Error> {
        for Pixel(p, c) in pixels {
            if p.x >= 0 && p.y >= 0 && (p.x as u32) < self.w && (p.y as u32) < self.h {
                self.pixels[(p.y as u32 * self.w + p.x as u32) as usize] = c;
                self.writes += 1;
            }
        }
        Ok(())
    }
}
