//! Textures: images mapped onto a model's triangles through the UVs of its mesh
//! ([`Mesh::with_uvs`](crate::mesh::Mesh::with_uvs)), lit by the model's shading.
//!
//! UV (0, 0) is the image's bottom-left corner and (1, 1) its top-right, as OBJ files assume;
//! texel `(i, j)` (column `i`, row `j` from the top) covers `u·width ∈ [i, i + 1)` and
//! `(1 − v)·height ∈ [j, j + 1)`. Outside [0, 1) a texture repeats or is clamped to its edge
//! ([`Wrap`]); a pixel takes the texel its centre falls in or blends the four nearest
//! ([`Filter`]); UVs are interpolated perspective-correctly or affinely ([`Mapping`]).
//!
//! The fastest texture is an Rgb565 one ([`Texels::Rgb565`]) whose sides are powers of two
//! (from 2 up), that repeats and is read nearest (the defaults): its triangles take a pixel
//! loop of their own, which finds a texel by shifts alone, wherever they are mapped affinely
//! (every triangle under [`Mapping::Affine`]; under the perspective mapping, each that an
//! affine map misplaces by less than an eighth of a texel), with the same colours as the
//! general loop, which matches the texel format at every pixel.
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

use embedded_graphics::pixelcolor::{
    Bgr565, Bgr888, Gray8, GrayColor, IntoStorage, Rgb565, Rgb888, RgbColor,
};

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
            Texels::Rgb565(s) => s.get(i).map_or(black, |&c| c.into()),
            Texels::Bgr565(s) => s.get(i).map_or(black, |&c| c.into()),
            Texels::Rgb888(s) => s.get(i).copied().unwrap_or(black),
            Texels::Bgr888(s) => s.get(i).map_or(black, |&c| c.into()),
            Texels::Gray8(s) => s.get(i).map_or(black, |&c| c.into()),
            Texels::Rgb565Be(s) => {
                let at = i.wrapping_mul(2);
                match (s.get(at), s.get(at.wrapping_add(1))) {
                    (Some(&hi), Some(&lo)) => {
                        let raw = u16::from_be_bytes([hi, lo]);
                        let c =
                            Rgb565::new((raw >> 11) as u8, (raw >> 5 & 63) as u8, raw as u8 & 31);
                        c.into()
                    }
                    _ => black,
                }
            }
        }
    }
}

impl Texels<'_> {
    /// The largest value of each channel: 31, 63 and 31 for 16-bit formats, 255 for others.
    #[inline(always)]
    pub(crate) const fn depths(&self) -> [u8; 3] {
        match self {
            Texels::Rgb565(_) | Texels::Bgr565(_) | Texels::Rgb565Be(_) => [31, 63, 31],
            _ => [255; 3],
        }
    }

    /// Texel `i`'s red, green and blue in the format's own depths ([`depths`](Self::depths)),
    /// black past the end.
    #[inline(always)]
    pub(crate) fn raw(&self, i: usize) -> [u32; 3] {
        let wide = |r: u8, g: u8, b: u8| [u32::from(r), u32::from(g), u32::from(b)];
        let black = [0; 3];
        match self {
            Texels::Rgb565(s) => s
                .get(i)
                .map_or(black, |&c| rgb565_channels(c.into_storage())),
            Texels::Bgr565(s) => s.get(i).map_or(black, |&c| wide(c.r(), c.g(), c.b())),
            Texels::Rgb888(s) => s.get(i).map_or(black, |&c| wide(c.r(), c.g(), c.b())),
            Texels::Bgr888(s) => s.get(i).map_or(black, |&c| wide(c.r(), c.g(), c.b())),
            Texels::Gray8(s) => s
                .get(i)
                .map_or(black, |&c| wide(c.luma(), c.luma(), c.luma())),
            Texels::Rgb565Be(s) => {
                let at = i.wrapping_mul(2);
                match (s.get(at), s.get(at.wrapping_add(1))) {
                    (Some(&hi), Some(&lo)) => rgb565_channels(u16::from_be_bytes([hi, lo])),
                    _ => black,
                }
            }
        }
    }
}

/// Raw Q16.16 UVs as texture coordinates ([`COORD_BITS`] fraction bits of the image's side;
/// `t` runs down from the top, `1 − v`). Repeating, they are kept modulo 2³², which leaves
/// the fraction bits (the ones read) exact; clamped, they are held within ±2³⁰ (1,024
/// images), which leaves them beyond the same edge.
#[inline(always)]
pub(crate) fn texture_coords(u: i32, v: i32, repeat: bool) -> [i32; 2] {
    let shift = COORD_BITS - 16;
    let limit = 1i64 << (30 - shift);
    let coord = |q: i64| {
        let q = if repeat { q } else { q.clamp(-limit, limit) };
        (q as i32).wrapping_shl(shift)
    };
    [coord(i64::from(u)), coord((1i64 << 16) - i64::from(v))]
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
    /// How triangles read it: made with the texture and again at each change of it, so that
    /// each textured triangle refers to it rather than making its own.
    sampler: Sampler<'a>,
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
        let texture = Texture {
            texels,
            width,
            height,
            wrap: Wrap::Repeat,
            filter: Filter::Nearest,
            mapping: Mapping::Perspective,
            run: RUN,
            sampler: Sampler::EMPTY,
        };
        Ok(texture.sampled())
    }

    /// The texture with its sampler made from its other fields.
    const fn sampled(self) -> Self {
        Texture {
            sampler: Sampler::new(&self),
            ..self
        }
    }

    /// With `wrap` outside [0, 1).
    #[must_use]
    pub const fn with_wrap(self, wrap: Wrap) -> Self {
        Texture { wrap, ..self }.sampled()
    }

    /// Sampled by `filter`.
    #[must_use]
    pub const fn with_filter(self, filter: Filter) -> Self {
        Texture { filter, ..self }.sampled()
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
        Texture { run, ..self }.sampled()
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

    /// The colour at UV `(u, v)` (raw Q16.16), wrapped or clamped and filtered as the
    /// texture says: what a textured pixel whose centre maps to `(u, v)` shows under a white
    /// light.
    #[must_use]
    pub fn sample(&self, u: i32, v: i32) -> Rgb888 {
        let sampler = &self.sampler;
        let scale = sampler.gains([255; 3]).map(|g| g * 255);
        let [r, g, b] = sampler.lit(texture_coords(u, v, sampler.repeats()), scale);
        Rgb888::new(r, g, b)
    }
}

/// Texture coordinates as the paint walks them: fractions of the image's side with this many
/// bits below the point (a coordinate of `1 << COORD_BITS` is one whole image across).
/// Repeating wraps them with a mask, whatever the image's size; a texel column is the product
/// of the coordinate and the side, shifted, which fits 32 bits for sides up to [`MAX_SIDE`].
pub(crate) const COORD_BITS: u32 = 20;
/// One image across, in texture coordinates.
pub(crate) const COORD_ONE: i32 = 1 << COORD_BITS;
/// The fraction bits of a light scale ([`Sampler::lit`]).
pub(crate) const SCALE_BITS: u32 = 23;

/// `⌈2³² / (255 · depth)⌉` for the texel depths there are (31, 63 and 255): a channel's gain
/// from the target's depth by one product (see [`gain`]).
const fn reciprocal(depth: u8) -> u32 {
    let d = 255 * depth as u64;
    ((1u64 << 32).div_ceil(d)) as u32
}

/// `target · 2²³ / (255 · texel)`, within 1.5 units: what a texel channel in its own depth
/// `texel` (31, 63 or 255) is multiplied by, times an 8-bit light, to give the channel in the
/// target's depth `target` with 23 fraction bits.
#[inline(always)]
pub(crate) fn gain(target: u8, texel: u8) -> u32 {
    // The reciprocal is below 2²⁰, the product below 2²⁸.
    const R31: u32 = reciprocal(31);
    const R63: u32 = reciprocal(63);
    const R255: u32 = reciprocal(255);
    let r = match texel {
        31 => R31,
        63 => R63,
        _ => R255,
    };
    (u32::from(target) * r) >> (32 - SCALE_BITS)
}

/// The red, green and blue of an Rgb565 texel's bits `v`, in their own depths (31, 63, 31).
#[inline(always)]
pub(crate) fn rgb565_channels(v: u16) -> [u32; 3] {
    let v = u32::from(v);
    [v >> 11, v >> 5 & 63, v & 31]
}

/// How a pixel reads a texture: its nearest texel, in the texture's format, or (`Bilinear`)
/// the four nearest blended. It repeats [`Texels`]' variants on purpose: one flat tag for
/// format and filter, so that one match a pixel decides both (a flag beside `Texels`, or an
/// `Option<Texels>`, measured slower in the span loop).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum Read<'a> {
    Rgb565(&'a [Rgb565]),
    Bgr565(&'a [Bgr565]),
    Rgb888(&'a [Rgb888]),
    Bgr888(&'a [Bgr888]),
    Gray8(&'a [Gray8]),
    Rgb565Be(&'a [u8]),
    Bilinear,
}

/// A texture as each triangle's paint reads it: the texels' slice, the sides and how they are
/// read, found from the texture's settings once (the texture keeps it).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct Sampler<'a> {
    texels: Texels<'a>,
    read: Read<'a>,
    width: u32,
    height: u32,
    /// What a coordinate is masked with before it is clamped into one image: its fraction
    /// bits when the texture repeats, all of them when it is clamped.
    mask: i32,
    /// Pixels between exact divisions along a span (perspective, at least 1).
    pub(crate) run: u8,
    /// The sides' bits where both are powers of two from 2 up, else zeros (see
    /// [`tiled565`](Self::tiled565)).
    tile_bits: [u8; 2],
    /// Whether the texels' channels are 16-bit colours' (depths 31, 63, 31), not 8 bits:
    /// decided once here, for each triangle's [`gains`](Self::gains).
    sixteen_bit: bool,
}

impl<'a> Sampler<'a> {
    /// A sampler of no texels (for a texture being made).
    const EMPTY: Self = Sampler {
        texels: Texels::Gray8(&[]),
        read: Read::Gray8(&[]),
        width: 1,
        height: 1,
        mask: -1,
        run: 1,
        tile_bits: [0; 2],
        sixteen_bit: false,
    };

    /// The texture's sampler.
    #[inline(always)]
    pub(crate) fn of(texture: &'a Texture<'a>) -> &'a Self {
        &texture.sampler
    }

    /// The sampler of `texture`'s settings (its own sampler aside).
    const fn new(texture: &Texture<'a>) -> Self {
        // `Texture::new` takes no side of 0.
        Sampler {
            texels: texture.texels,
            width: texture.width as u32,
            height: texture.height as u32,
            mask: if matches!(texture.wrap, Wrap::Repeat) {
                COORD_ONE - 1
            } else {
                -1
            },
            read: match (texture.filter, texture.texels) {
                (Filter::Bilinear, _) => Read::Bilinear,
                (_, Texels::Rgb565(s)) => Read::Rgb565(s),
                (_, Texels::Bgr565(s)) => Read::Bgr565(s),
                (_, Texels::Rgb888(s)) => Read::Rgb888(s),
                (_, Texels::Bgr888(s)) => Read::Bgr888(s),
                (_, Texels::Gray8(s)) => Read::Gray8(s),
                (_, Texels::Rgb565Be(s)) => Read::Rgb565Be(s),
            },
            run: texture.run,
            tile_bits: if texture.width > 1
                && texture.height > 1
                && texture.width.is_power_of_two()
                && texture.height.is_power_of_two()
            {
                [
                    texture.width.trailing_zeros() as u8,
                    texture.height.trailing_zeros() as u8,
                ]
            } else {
                [0; 2]
            },
            sixteen_bit: matches!(texture.texels.depths(), [31, 63, 31]),
        }
    }

    /// Whether the texture repeats.
    #[inline(always)]
    pub(crate) fn repeats(&self) -> bool {
        self.mask != -1
    }

    /// The sides in texels.
    #[inline(always)]
    pub(crate) fn sides(&self) -> (u32, u32) {
        (self.width, self.height)
    }

    /// Per channel, the [`gain`] from the texels' depth to `target`'s (largest channel
    /// values): what a channel times an 8-bit light is scaled by.
    #[inline(always)]
    pub(crate) fn gains(&self, target: [u8; 3]) -> [u32; 3] {
        let [r, g, b] = target;
        if self.sixteen_bit {
            [gain(r, 31), gain(g, 63), gain(b, 31)]
        } else {
            [gain(r, 255), gain(g, 255), gain(b, 255)]
        }
    }

    /// A texture coordinate in the image: wrapped or clamped into [0, 1), times `side`, with
    /// [`COORD_BITS`] fraction bits (below 2³²: sides are at most [`MAX_SIDE`]).
    #[inline(always)]
    fn in_texels(&self, c: i32, side: u32) -> u32 {
        ((c & self.mask).clamp(0, COORD_ONE - 1) as u32).wrapping_mul(side)
    }

    /// The channels at texture coordinates `c`, each scaled by `scale` (a channel's
    /// [`gain`] times its 8-bit light) and rounded: the lit colour in the target's depths.
    #[inline(always)]
    pub(crate) fn lit(&self, c: [i32; 2], scale: [u32; 3]) -> [u8; 3] {
        let x = self.in_texels(c[0], self.width) >> COORD_BITS;
        let y = self.in_texels(c[1], self.height) >> COORD_BITS;
        let i = self.index(x as i32, y as i32);
        // Each arm's format is known, so the read's own match folds into this one.
        let texels = match self.read {
            Read::Rgb565(s) => Texels::Rgb565(s),
            Read::Bgr565(s) => Texels::Bgr565(s),
            Read::Rgb888(s) => Texels::Rgb888(s),
            Read::Bgr888(s) => Texels::Bgr888(s),
            Read::Gray8(s) => Texels::Gray8(s),
            Read::Rgb565Be(s) => Texels::Rgb565Be(s),
            Read::Bilinear => return self.bilinear(c, scale),
        };
        let raw = texels.raw(i);
        // A channel is at most its depth `d` and its scale at most 255 times its gain, within
        // 1.5 of 2²³ · target / (255 · d): the product and the half below 2³².
        let half = 1 << (SCALE_BITS - 1);
        let ch = |k: usize| (raw[k].wrapping_mul(scale[k]).wrapping_add(half) >> SCALE_BITS) as u8;
        [ch(0), ch(1), ch(2)]
    }

    /// The texels of a repeating Rgb565 texture read nearest whose sides are powers of two
    /// from 2 up (the tiled form a paint can take: see `TiledPaint`), and the sides' bits; or
    /// `None`.
    #[inline(always)]
    pub(crate) fn tiled565(&self) -> Option<(&'a [Rgb565], [u32; 2])> {
        let [w, h] = self.tile_bits;
        match self.read {
            Read::Rgb565(s) if self.repeats() && w != 0 => Some((s, [u32::from(w), u32::from(h)])),
            _ => None,
        }
    }

    /// The index of texel `(x, y)` of the image.
    #[inline(always)]
    fn index(&self, x: i32, y: i32) -> usize {
        (y as u32 as usize)
            .wrapping_mul(self.width as usize)
            .wrapping_add(x as u32 as usize)
    }

    /// Texel column or row `v` of an image `side` texels across, for `v` within one side of
    /// it: wrapped round when repeating, else clamped to the edge.
    #[inline(always)]
    fn wrapped(&self, v: i32, side: u32) -> i32 {
        let side = side as i32;
        if !self.repeats() {
            v.clamp(0, side - 1)
        } else if v < 0 {
            v + side
        } else if v >= side {
            v - side
        } else {
            v
        }
    }

    /// The four texels around `c` blended by 8-bit weights in their own depth, then scaled.
    fn bilinear(&self, c: [i32; 2], scale: [u32; 3]) -> [u8; 3] {
        // Texel centres lie at half units: blend from the one up and left of the sample.
        let half = 1i64 << (COORD_BITS - 1);
        let s = i64::from(self.in_texels(c[0], self.width)) - half;
        let t = i64::from(self.in_texels(c[1], self.height)) - half;
        let (x, y) = ((s >> COORD_BITS) as i32, (t >> COORD_BITS) as i32);
        let weight = |v: i64| (v >> (COORD_BITS - 8) & 255) as u32;
        let (fx, fy) = (weight(s), weight(t));
        let (x0, x1) = (self.wrapped(x, self.width), self.wrapped(x + 1, self.width));
        let (y0, y1) = (
            self.wrapped(y, self.height),
            self.wrapped(y + 1, self.height),
        );
        let at = |x: i32, y: i32| self.texels.raw(self.index(x, y));
        let (a, b, c, d) = (at(x0, y0), at(x1, y0), at(x0, y1), at(x1, y1));
        let ch = |k: usize| {
            let top = a[k] * (256 - fx) + b[k] * fx;
            let bottom = c[k] * (256 - fx) + d[k] * fx;
            // The blend, below 2²⁴ (16 fraction bits), times the scale (below 2³¹).
            let v = u64::from(top * (256 - fy) + bottom * fy) * u64::from(scale[k]);
            ((v + (1 << (SCALE_BITS + 15))) >> (SCALE_BITS + 16)) as u8
        };
        [ch(0), ch(1), ch(2)]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The tiled form is taken exactly by repeating, nearest-read Rgb565 textures whose sides
    /// are both powers of two from 2 up, with the sides' bits, whatever the builder methods
    /// change after `Texture::new`; the sampler a texture keeps is the one its settings make.
    #[test]
    fn tiled_form_is_taken_by_power_of_two_repeating_rgb565() {
        let texels = [Rgb565::BLACK; 128 * 64];
        let rgb888 = [Rgb888::BLACK; 64 * 64];
        let tiled = |t: Texture<'_>| {
            assert_eq!(*Sampler::of(&t), Sampler::new(&t));
            Sampler::of(&t).tiled565().map(|(_, bits)| bits)
        };
        let rgb565 = |w: u16, h: u16| Texture::new(Texels::from(&texels[..]), w, h).unwrap();
        assert_eq!(tiled(rgb565(64, 64)), Some([6, 6]));
        assert_eq!(tiled(rgb565(128, 32)), Some([7, 5]));
        assert_eq!(tiled(rgb565(2, 2)), Some([1, 1]));
        for (w, h) in [(1, 64), (64, 1), (48, 64), (64, 48), (3, 3)] {
            assert_eq!(tiled(rgb565(w, h)), None, "{w}x{h}");
        }
        let square = rgb565(64, 64).with_mapping(Mapping::Affine).with_run(4);
        assert_eq!(tiled(square), Some([6, 6]));
        assert_eq!(tiled(square.with_wrap(Wrap::Clamp)), None);
        assert_eq!(tiled(square.with_filter(Filter::Bilinear)), None);
        let other = Texture::new(Texels::from(&rgb888[..]), 64, 64).unwrap();
        assert_eq!(tiled(other), None);
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

    /// A texel channel scaled by an 8-bit light into a target's depth is the exact value
    /// `raw · light · target / (255 · texel depth)` rounded (within 2⁻⁸ of a step of a tie),
    /// and under a white light into its own depth the texel itself.
    #[test]
    fn lit_channels_round_once() {
        let half = 1u32 << (SCALE_BITS - 1);
        for texel in [31u8, 63, 255] {
            for target in [1u8, 3, 15, 31, 63, 255] {
                let gain = gain(target, texel);
                for light in 0..=255u32 {
                    for raw in 0..=u32::from(texel) {
                        let out = (raw * light * gain + half) >> SCALE_BITS;
                        let exact =
                            f64::from(raw * light * u32::from(target)) / (255.0 * f64::from(texel));
                        let err = (f64::from(out) - exact).abs();
                        assert!(err <= 0.5 + 1.0 / 256.0, "{raw} {light} {target} {texel}");
                        if light == 255 && target == texel {
                            assert_eq!(out, raw);
                        }
                    }
                }
            }
        }
    }

    /// Repeat wraps both ways; clamp holds the edge; bilinear at a texel's centre reads it,
    /// and half-way between two texels blends them evenly.
    #[test]
    fn addressing_and_filters() {
        let texels = [0u8, 60, 120, 180, 240, 250, 10, 20].map(Gray8::new);
        let t = Texture::new(Texels::from(&texels), 4, 2).unwrap();
        // Texel units (column, row from the top) as UVs.
        let at = |t: &Texture, s: f64, r: f64| {
            let q = |v: f64| (v * 65536.0).round() as i32;
            t.sample(q(s / 4.0), q(1.0 - r / 2.0)).r()
        };
        assert_eq!(at(&t, 0.5, 0.5), 0);
        assert_eq!(at(&t, -0.5, 0.5), 180);
        assert_eq!(at(&t, 5.2, 2.5), 60);
        let clamp = t.with_wrap(Wrap::Clamp);
        assert_eq!(at(&clamp, -7.0, 9.0), 240);
        let bi = t.with_filter(Filter::Bilinear).with_wrap(Wrap::Clamp);
        assert_eq!(at(&bi, 1.5, 0.5), 60);
        assert_eq!(at(&bi, 1.0, 0.5), 30);
        assert_eq!(at(&bi, 1.5, 1.0), 155);
        assert_eq!(at(&bi.with_wrap(Wrap::Repeat), 0.0, 0.5), 90);
        assert_eq!(
            Texture::new(Texels::from(&texels), 0, 1),
            Err(TextureError::Size)
        );
    }
}
