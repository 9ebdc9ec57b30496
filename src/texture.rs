//! Textures: images mapped onto a model's triangles through the UVs of its mesh
//! ([`Mesh::with_uvs`](crate::mesh::Mesh::with_uvs)), lit by the model's shading.
//!
//! UV (0, 0) is the image's bottom-left corner and (1, 1) its top-right, as OBJ files assume;
//! texel `(i, j)` (column `i`, row `j` from the top) covers `u·width ∈ [i, i + 1)` and
//! `(1 − v)·height ∈ [j, j + 1)`. Outside [0, 1) a texture repeats or is clamped to its edge
//! ([`Wrap`]); a pixel takes the texel its centre falls in or blends the four nearest
//! ([`Filter`]); UVs are interpolated perspective-correctly or affinely ([`Mapping`]).
//!
//! ```
//! use embedded_graphics::pixelcolor::Rgb565;
//! use fixed3d::texture::{Filter, Texels, Texture, Wrap};
//! // A 2x2 checkerboard, in flash.
//! const W: Rgb565 = Rgb565::new(31, 63, 31);
//! const K: Rgb565 = Rgb565::new(0, 0, 0);
//! static CHECKER: [Rgb565; 4] = [W, K, K, W];
//! static TEXTURE: Texture = match Texture::new(Texels::Rgb565(&CHECKER), 2, 2) {
//!     Ok(t) => t.with_wrap(Wrap::Clamp).with_filter(Filter::Bilinear),
//!     Err(_) => panic!("bad texture"),
//! };
//! assert_eq!((TEXTURE.width(), TEXTURE.height()), (2, 2));
//! ```

use core::fmt;

use embedded_graphics::pixelcolor::{Bgr565, Bgr888, Gray8, Rgb565, Rgb888, RgbColor};

/// The largest width or height of a texture, in texels.
pub const MAX_SIDE: u16 = 4096;

/// A texture's texels, row after row from the top, in one of the colour formats
/// embedded-graphics images come in. Built with `From` from a slice of colours, or with
/// [`Texels::Rgb565Be`] from raw bytes (`include_bytes!` of a file such as
/// embedded-graphics' `ImageRawBE<Rgb565>` reads).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Texels<'a> {
    /// 16-bit colours.
    Rgb565(&'a [Rgb565]),
    /// 16-bit colours, blue in the high bits.
    Bgr565(&'a [Bgr565]),
    /// 24-bit colours.
    Rgb888(&'a [Rgb888]),
    /// 24-bit colours, blue first.
    Bgr888(&'a [Bgr888]),
    /// 8-bit grey.
    Gray8(&'a [Gray8]),
    /// Rgb565 as big-endian byte pairs (two bytes a texel; a trailing odd byte is ignored).
    Rgb565Be(&'a [u8]),
}

impl<'a> Texels<'a> {
    /// How many texels there are.
    #[must_use]
    pub const fn len(&self) -> usize {
        match self {
            Texels::Rgb565(s) => s.len(),
            Texels::Bgr565(s) => s.len(),
            Texels::Rgb888(s) => s.len(),
            Texels::Bgr888(s) => s.len(),
            Texels::Gray8(s) => s.len(),
            Texels::Rgb565Be(s) => s.len() / 2,
        }
    }

    /// True when there are none.
    #[must_use]
    pub const fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Texel `i` in 24-bit colour (black past the end).
    #[inline(always)]
    pub fn rgb(&self, i: usize) -> Rgb888 {
        let black = Rgb888::BLACK;
        match self {
            Texels::Rgb565(s) => s.get(i).map_or(black, |&c| widened(c.r(), c.g(), c.b())),
            Texels::Bgr565(s) => s.get(i).map_or(black, |&c| widened(c.r(), c.g(), c.b())),
            Texels::Rgb888(s) => s.get(i).copied().unwrap_or(black),
            Texels::Bgr888(s) => s.get(i).map_or(black, |&c| c.into()),
            Texels::Gray8(s) => s.get(i).map_or(black, |&c| c.into()),
            Texels::Rgb565Be(s) => {
                let at = i.wrapping_mul(2);
                match (s.get(at), s.get(at.wrapping_add(1))) {
                    (Some(&hi), Some(&lo)) => {
                        let raw = u16::from_be_bytes([hi, lo]);
                        widened((raw >> 11) as u8, (raw >> 5 & 63) as u8, raw as u8 & 31)
                    }
                    _ => black,
                }
            }
        }
    }
}

/// A 5-bit channel in 8 bits, as embedded-graphics converts it (`round(v · 255 / 31)`).
const WIDE5: [u8; 32] = widening_table::<32>();
/// A 6-bit channel in 8 bits, as embedded-graphics converts it (`round(v · 255 / 63)`).
const WIDE6: [u8; 64] = widening_table::<64>();

/// Each `N`-level channel value in 8 bits by embedded-graphics' own formula.
const fn widening_table<const N: usize>() -> [u8; N] {
    let scale = (255u32 << 24) / (N as u32 - 1);
    let mut table = [0; N];
    let mut v = 0;
    while v < N {
        table[v] = ((v as u32 * scale + (1 << 23)) >> 24) as u8;
        v += 1;
    }
    table
}

/// A 5/6/5-bit colour's channels in 24-bit colour, by table (what `Rgb888::from` gives, with
/// no product per channel).
#[inline(always)]
fn widened(r: u8, g: u8, b: u8) -> Rgb888 {
    let wide5 = |v: u8| WIDE5[usize::from(v & 31)];
    Rgb888::new(wide5(r), WIDE6[usize::from(g & 63)], wide5(b))
}

macro_rules! texels_from {
    ($($color:ident),*) => {$(
        impl<'a> From<&'a [$color]> for Texels<'a> {
            fn from(s: &'a [$color]) -> Self {
                Texels::$color(s)
            }
        }
        impl<'a, const N: usize> From<&'a [$color; N]> for Texels<'a> {
            fn from(s: &'a [$color; N]) -> Self {
                Texels::$color(s)
            }
        }
    )*};
}
texels_from!(Rgb565, Bgr565, Rgb888, Bgr888, Gray8);

/// What lies outside UVs [0, 1).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Wrap {
    /// The texture repeats (a UV of 1.25 reads what 0.25 reads).
    #[default]
    Repeat,
    /// The edge texels go on for ever.
    Clamp,
}

/// Which texels a pixel reads.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Filter {
    /// The texel the pixel's centre falls in.
    #[default]
    Nearest,
    /// The four texels around the pixel's centre, blended by its distance from theirs
    /// (four reads a pixel).
    Bilinear,
}

/// How UVs are interpolated across a triangle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Mapping {
    /// As the f64 reference does, through `1/w`: exact at the ends of every run of
    /// [`RUN`] pixels along a span (or as many as [`Texture::with_run`] says), linear between
    /// them. A triangle whose `1/w` varies so
    /// little that a linear map errs by under 1/8 texel anywhere in it is mapped linearly
    /// (no division per span), as are all under an orthographic projection.
    #[default]
    Perspective,
    /// Linear in screen space: cheaper, and swimming on surfaces seen at a slant.
    Affine,
}

/// Pixels between exact divisions along a span, for [`Mapping::Perspective`], unless
/// [`Texture::with_run`] gives another number (`docs/accuracy.md` weighs them).
pub const RUN: u8 = 16;

/// Why a texture was refused.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum TextureError {
    /// A side is 0 or larger than [`MAX_SIDE`].
    Size,
    /// Fewer texels than width times height.
    TooFewTexels {
        /// Width times height.
        needed: usize,
        /// Texels given.
        given: usize,
    },
}

impl fmt::Display for TextureError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TextureError::Size => write!(f, "a texture's sides must be 1 to {MAX_SIDE} texels"),
            TextureError::TooFewTexels { needed, given } => {
                write!(f, "a texture of {needed} texels was given {given}")
            }
        }
    }
}

impl core::error::Error for TextureError {}

/// An image for textured models: texels (in flash or RAM), their size, and how they are read.
///
/// ```
/// use embedded_graphics::pixelcolor::Rgb888;
/// use fixed3d::texture::{Mapping, Texels, Texture, TextureError};
/// let texels = [Rgb888::new(255, 0, 0); 6];
/// let t = Texture::new(Texels::from(&texels), 3, 2).unwrap().with_mapping(Mapping::Affine);
/// assert_eq!(t.mapping(), Mapping::Affine);
/// assert_eq!(
///     Texture::new(Texels::from(&texels), 4, 2).unwrap_err(),
///     TextureError::TooFewTexels { needed: 8, given: 6 }
/// );
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Texture<'a> {
    texels: Texels<'a>,
    width: u16,
    height: u16,
    wrap: Wrap,
    filter: Filter,
    mapping: Mapping,
    /// Pixels between exact divisions along a span (at least 1).
    run: u8,
}

impl<'a> Texture<'a> {
    /// `width` x `height` texels, row after row from the top; repeated, nearest-sampled and
    /// perspective-correct until told otherwise. A `const fn`: a texture can be a `static`.
    pub const fn new(texels: Texels<'a>, width: u16, height: u16) -> Result<Self, TextureError> {
        if width == 0 || height == 0 || width > MAX_SIDE || height > MAX_SIDE {
            return Err(TextureError::Size);
        }
        let needed = width as usize * height as usize;
        if texels.len() < needed {
            return Err(TextureError::TooFewTexels {
                needed,
                given: texels.len(),
            });
        }
        Ok(Texture {
            texels,
            width,
            height,
            wrap: Wrap::Repeat,
            filter: Filter::Nearest,
            mapping: Mapping::Perspective,
            run: RUN,
        })
    }

    /// With `wrap` outside [0, 1).
    #[must_use]
    pub const fn with_wrap(self, wrap: Wrap) -> Self {
        Texture { wrap, ..self }
    }

    /// Sampled by `filter`.
    #[must_use]
    pub const fn with_filter(self, filter: Filter) -> Self {
        Texture { filter, ..self }
    }

    /// Mapped by `mapping`.
    #[must_use]
    pub const fn with_mapping(self, mapping: Mapping) -> Self {
        Texture { mapping, ..self }
    }

    /// Perspective-correct with an exact division every `pixels` pixels along a span (1: at
    /// every pixel; 0 counts as 1), linear between them: fewer divisions for longer runs, a
    /// texel error that grows with them on surfaces seen at a slant.
    #[must_use]
    pub const fn with_run(self, pixels: u8) -> Self {
        let run = if pixels == 0 { 1 } else { pixels };
        Texture { run, ..self }
    }

    /// Width in texels.
    #[must_use]
    pub const fn width(&self) -> u16 {
        self.width
    }

    /// Height in texels.
    #[must_use]
    pub const fn height(&self) -> u16 {
        self.height
    }

    /// The texels.
    #[must_use]
    pub const fn texels(&self) -> Texels<'a> {
        self.texels
    }

    /// What lies outside [0, 1).
    #[must_use]
    pub const fn wrap(&self) -> Wrap {
        self.wrap
    }

    /// How texels are read.
    #[must_use]
    pub const fn filter(&self) -> Filter {
        self.filter
    }

    /// How UVs are interpolated.
    #[must_use]
    pub const fn mapping(&self) -> Mapping {
        self.mapping
    }

    /// Pixels between exact divisions along a span ([`with_run`](Self::with_run)).
    #[must_use]
    pub const fn run(&self) -> u8 {
        self.run
    }

    /// The colour at texel coordinates `(s, t)` (Q16.16 texel units: `s = u·width`,
    /// `t = (1 − v)·height`), wrapped or clamped and filtered as the texture says: what a
    /// textured pixel whose centre maps to `(s, t)` shows under a white light.
    #[must_use]
    pub fn sample(&self, s: i32, t: i32) -> Rgb888 {
        let sampler = Sampler::new(self);
        let (ps, pt) = sampler.periods();
        let (s, t) = if sampler.repeat {
            (s.rem_euclid(ps), t.rem_euclid(pt))
        } else {
            (s, t)
        };
        sampler.texel(s, t)
    }
}

/// A texture as each triangle's paint reads it (copied into the paint: the texels' slice,
/// the sides and how they are read).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Sampler<'a> {
    texels: Texels<'a>,
    width: i32,
    height: i32,
    repeat: bool,
    bilinear: bool,
    /// Pixels between exact divisions along a span (perspective, at least 1).
    pub(crate) run: u8,
}

impl<'a> Sampler<'a> {
    #[inline(always)]
    pub(crate) fn new(texture: &Texture<'a>) -> Self {
        Sampler {
            texels: texture.texels,
            width: i32::from(texture.width).max(1),
            height: i32::from(texture.height).max(1),
            repeat: texture.wrap == Wrap::Repeat,
            bilinear: texture.filter == Filter::Bilinear,
            run: texture.run,
        }
    }

    /// The sides in Q16.16 texel units (below 2³¹: sides are at most [`MAX_SIDE`]).
    #[inline(always)]
    pub(crate) fn periods(&self) -> (i32, i32) {
        (self.width << 16, self.height << 16)
    }

    /// Whether the texture repeats.
    #[inline(always)]
    pub(crate) fn repeats(&self) -> bool {
        self.repeat
    }

    /// The colour at `(s, t)` (Q16.16 texel units), each in `[0, period)` when the texture
    /// repeats, anything when it is clamped.
    #[inline(always)]
    pub(crate) fn texel(&self, s: i32, t: i32) -> Rgb888 {
        if self.bilinear {
            return self.bilinear(s, t);
        }
        // Repeating, the coordinates lie in the image already: the clamps change nothing.
        let x = (s >> 16).clamp(0, self.width - 1);
        let y = (t >> 16).clamp(0, self.height - 1);
        self.texels.rgb(self.index(x, y))
    }

    /// The index of texel `(x, y)` of the image.
    #[inline(always)]
    fn index(&self, x: i32, y: i32) -> usize {
        (y as u32 as usize)
            .wrapping_mul(self.width as u32 as usize)
            .wrapping_add(x as u32 as usize)
    }

    /// Texel column or row `v` of an image `side` texels across, for `v` within one side of
    /// it: wrapped round when repeating, else clamped to the edge.
    #[inline(always)]
    fn wrapped(&self, v: i32, side: i32) -> i32 {
        if !self.repeat {
            v.clamp(0, side - 1)
        } else if v < 0 {
            v + side
        } else if v >= side {
            v - side
        } else {
            v
        }
    }

    /// The four texels around `(s, t)` blended by 8-bit weights.
    fn bilinear(&self, s: i32, t: i32) -> Rgb888 {
        // Texel centres lie at half units: blend from the one up and left of the sample.
        let (s, t) = (s.saturating_sub(1 << 15), t.saturating_sub(1 << 15));
        let (x, y) = (s >> 16, t >> 16);
        let (fx, fy) = ((s >> 8 & 255) as u32, (t >> 8 & 255) as u32);
        let (x0, x1) = (self.wrapped(x, self.width), self.wrapped(x + 1, self.width));
        let (y0, y1) = (
            self.wrapped(y, self.height),
            self.wrapped(y + 1, self.height),
        );
        let at = |x: i32, y: i32| self.texels.rgb(self.index(x, y));
        let (a, b, c, d) = (at(x0, y0), at(x1, y0), at(x0, y1), at(x1, y1));
        let mix = |a: u8, b: u8, c: u8, d: u8| {
            let top = u32::from(a) * (256 - fx) + u32::from(b) * fx;
            let bottom = u32::from(c) * (256 - fx) + u32::from(d) * fx;
            ((top * (256 - fy) + bottom * fy + (1 << 15)) >> 16) as u8
        };
        Rgb888::new(
            mix(a.r(), b.r(), c.r(), d.r()),
            mix(a.g(), b.g(), c.g(), d.g()),
            mix(a.b(), b.b(), c.b(), d.b()),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 16-bit texels widen to what embedded-graphics' conversion gives, for every colour.
    #[test]
    fn widened_565_is_the_conversion() {
        for raw in 0..=u16::MAX {
            let c = Rgb565::new((raw >> 11) as u8, (raw >> 5 & 63) as u8, raw as u8 & 31);
            assert_eq!(widened(c.r(), c.g(), c.b()), Rgb888::from(c), "{raw:#06x}");
        }
    }

    /// Every format reads the colour it stores, and Rgb565 bytes read as the colour does.
    #[test]
    fn formats_read_their_colours() {
        let c = Rgb565::new(17, 40, 9);
        let raw = (17u16 << 11 | 40 << 5 | 9).to_be_bytes();
        let want = Rgb888::from(c);
        assert_eq!(Texels::from(&[c]).rgb(0), want);
        assert_eq!(Texels::Rgb565Be(&raw).rgb(0), want);
        assert_eq!(Texels::Rgb565Be(&raw).rgb(1), Rgb888::BLACK);
        assert_eq!(Texels::from(&[Bgr565::new(17, 40, 9)]).rgb(0), want);
        assert_eq!(
            Texels::from(&[Bgr888::new(1, 2, 3)]).rgb(0),
            Rgb888::new(1, 2, 3)
        );
        assert_eq!(
            Texels::from(&[Gray8::new(77)]).rgb(0),
            Rgb888::new(77, 77, 77)
        );
        assert_eq!(Texels::from(&[Rgb888::WHITE]).rgb(5), Rgb888::BLACK);
    }

    /// Repeat wraps both ways; clamp holds the edge; bilinear at a texel's centre reads it,
    /// and half-way between two texels blends them evenly.
    #[test]
    fn addressing_and_filters() {
        let texels = [0u8, 60, 120, 180, 240, 250].map(Gray8::new);
        let t = Texture::new(Texels::from(&texels), 3, 2).unwrap();
        let q = |v: f64| (v * 65536.0) as i32;
        let luma = |c: Rgb888| c.r();
        assert_eq!(luma(t.sample(q(0.5), q(0.5))), 0);
        assert_eq!(luma(t.sample(q(-0.5), q(0.5))), 120);
        assert_eq!(luma(t.sample(q(4.2), q(2.5))), 60);
        let clamp = t.with_wrap(Wrap::Clamp);
        assert_eq!(luma(clamp.sample(q(-7.0), q(9.0))), 180);
        let bi = t.with_filter(Filter::Bilinear).with_wrap(Wrap::Clamp);
        assert_eq!(luma(bi.sample(q(1.5), q(0.5))), 60);
        assert_eq!(luma(bi.sample(q(1.0), q(0.5))), 30);
        assert_eq!(luma(bi.sample(q(1.5), q(1.0))), 150);
        assert_eq!(
            Texture::new(Texels::from(&texels), 0, 1),
            Err(TextureError::Size)
        );
    }
}
