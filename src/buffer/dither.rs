//! From the shaded 24-bit colour to the target's colour type.

use embedded_graphics::pixelcolor::raw::RawData;
use embedded_graphics::pixelcolor::{
    Bgr555, Bgr565, Bgr666, Bgr888, BinaryColor, Gray2, Gray4, Gray8, PixelColor, Rgb555, Rgb565,
    Rgb666, Rgb888, RgbColor,
};

/// A colour fixed3d draws into: any embedded-graphics colour, made from the shaded 24-bit
/// colour by its `From<Rgb888>`.
///
/// Colours of red, green and blue channels of their own depths (embedded-graphics' `Rgb565`,
/// `Bgr565`, `Rgb555`, `Rgb666`, `Rgb888` and the like) also give those depths, so that smooth
/// shading into them rounds each channel once, straight to the colour's own depth, rather than
/// to 8 bits and then again to the colour's. Every embedded-graphics colour implements it; a
/// colour type of your own takes the defaults with `impl TargetColor for MyColor {}`.
///
/// ```
/// use embedded_graphics::pixelcolor::{BinaryColor, Rgb565};
/// use fixed3d::buffer::TargetColor;
/// assert_eq!(Rgb565::CHANNELS, Some([31, 63, 31]));
/// assert_eq!(Rgb565::from_channels(31, 0, 1), Rgb565::new(31, 0, 1));
/// assert_eq!(BinaryColor::CHANNELS, None);
/// ```
pub trait TargetColor: PixelColor + From<Rgb888> {
    /// The largest value of each channel (red, green, blue) that
    /// [`from_channels`](Self::from_channels) takes; `None` (the default) for colours made
    /// from 24-bit colours only.
    const CHANNELS: Option<[u8; 3]> = None;
    /// The colour of channel values each at most its [`CHANNELS`](Self::CHANNELS) entry
    /// (called only where that is `Some`; the default goes through `From<Rgb888>`).
    #[inline(always)]
    fn from_channels(r: u8, g: u8, b: u8) -> Self {
        Self::from(Rgb888::new(r, g, b))
    }
}

/// The embedded-graphics colours of red, green and blue channels: their own depths.
macro_rules! rgb_target_colors {
    ($($color:ty),*) => {$(
        impl TargetColor for $color {
            const CHANNELS: Option<[u8; 3]> =
                Some([<$color>::MAX_R, <$color>::MAX_G, <$color>::MAX_B]);
            #[inline(always)]
            fn from_channels(r: u8, g: u8, b: u8) -> Self {
                <$color>::new(r, g, b)
            }
        }
    )*};
}

rgb_target_colors!(Rgb555, Bgr555, Rgb565, Bgr565, Rgb666, Bgr666, Rgb888, Bgr888);

impl TargetColor for BinaryColor {}
impl TargetColor for Gray2 {}
impl TargetColor for Gray4 {}
impl TargetColor for Gray8 {}

/// Turns a shaded colour at a pixel into the target's colour.
pub trait Quantize<C>: Copy + core::fmt::Debug {
    /// True when the result does not depend on the pixel position (a solid span converts once).
    const UNIFORM: bool;
    /// The colour for `rgb` at pixel `(x, y)`.
    fn quantize(&self, rgb: Rgb888, x: i32, y: i32) -> C;
    /// `C`'s channel depths ([`TargetColor::CHANNELS`]) where this quantiser rounds each channel
    /// on its own to them, adding no pattern: smooth shading then hands it channels already in
    /// those depths, through [`of_channels`](Self::of_channels). `None` (the default) otherwise.
    #[doc(hidden)]
    const CHANNELS: Option<[u8; 3]> = None;
    /// The colour of channels within [`CHANNELS`](Self::CHANNELS).
    #[doc(hidden)]
    #[inline(always)]
    fn of_channels(&self, r: u8, g: u8, b: u8) -> C {
        self.quantize(Rgb888::new(r, g, b), 0, 0)
    }
}

/// embedded-graphics' own conversion (`C::from(Rgb888)`): nearest colour, no dithering. Smooth
/// shading into a colour of channels rounds each channel straight to its depth (see
/// [`TargetColor`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Nearest;

impl<C: TargetColor> Quantize<C> for Nearest {
    const UNIFORM: bool = true;
    #[inline(always)]
    fn quantize(&self, rgb: Rgb888, _: i32, _: i32) -> C {
        C::from(rgb)
    }
    const CHANNELS: Option<[u8; 3]> = C::CHANNELS;
    #[inline(always)]
    fn of_channels(&self, r: u8, g: u8, b: u8) -> C {
        C::from_channels(r, g, b)
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

impl<C: TargetColor> Quantize<C> for OrderedDither {
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
