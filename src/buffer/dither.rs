//! From the shaded 24-bit colour to the target's colour type.

use embedded_graphics::pixelcolor::raw::RawData;
use embedded_graphics::pixelcolor::{PixelColor, Rgb888, RgbColor};

/// Turns a shaded colour at a pixel into the target's colour.
pub trait Quantize<C>: Copy + core::fmt::Debug {
    /// True when the result does not depend on the pixel position (a solid span converts once).
    const UNIFORM: bool;
    /// The colour for `rgb` at pixel `(x, y)`.
    fn quantize(&self, rgb: Rgb888, x: i32, y: i32) -> C;
}

/// embedded-graphics' own conversion (`C::from(Rgb888)`): nearest colour, no dithering.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Nearest;

impl<C: From<Rgb888>> Quantize<C> for Nearest {
    const UNIFORM: bool = true;
    #[inline(always)]
    fn quantize(&self, rgb: Rgb888, _: i32, _: i32) -> C {
        C::from(rgb)
    }
}

/// Ordered (4x4 Bayer) dithering before the conversion, scaled to the target's colour depth:
/// a 1-bit display (an SSD1306's `BinaryColor`) shows Lambert shading as a pattern density, a
/// grey or RGB565 display loses its banding. The offset added to each channel is symmetric
/// around zero and one quantisation step wide, so flat areas keep their mean brightness.
///
/// ```
/// use embedded_graphics::pixelcolor::{BinaryColor, Rgb888};
/// use fixed3d::buffer::{OrderedDither, Quantize};
/// let grey = Rgb888::new(128, 128, 128);
/// let on = (0..4)
///     .flat_map(|y| (0..4).map(move |x| (x, y)))
///     .filter(|&(x, y)| Quantize::<BinaryColor>::quantize(&OrderedDither, grey, x, y).is_on())
///     .count();
/// assert_eq!(on, 8); // half the pattern lit for 50% grey
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct OrderedDither;

const BAYER4: [[u8; 4]; 4] = [[0, 8, 2, 10], [12, 4, 14, 6], [3, 11, 1, 9], [15, 7, 13, 5]];

/// One quantisation step of a channel of `C`, in 8-bit units.
fn step<C: PixelColor>() -> i32 {
    match C::Raw::BITS_PER_PIXEL {
        1 => 255,
        2 => 85,
        4 => 17,
        16 => 8,
        18 => 4,
        _ => 1,
    }
}

impl<C: PixelColor + From<Rgb888>> Quantize<C> for OrderedDither {
    const UNIFORM: bool = false;
    #[inline]
    fn quantize(&self, rgb: Rgb888, x: i32, y: i32) -> C {
        let s = step::<C>();
        if s <= 1 {
            return C::from(rgb);
        }
        let b = BAYER4
            .get((y & 3) as usize)
            .and_then(|r| r.get((x & 3) as usize))
            .copied()
            .unwrap_or(0) as i32;
        // Threshold offset in (−s/2, s/2), centred.
        let off = ((2 * b + 1) * s) / 32 - s / 2;
        let ch = |v: u8| (v as i32 + off).clamp(0, 255) as u8;
        C::from(Rgb888::new(ch(rgb.r()), ch(rgb.g()), ch(rgb.b())))
    }
}
