//! The precision knobs of a frame.

use crate::math::{magnitude_bits, product3, shr_round, Mat4, Normalize, SUBPIXEL_BITS};

/// How precisely a [`Frame`](super::Frame) computes: the knobs whose error and cost
/// `docs/accuracy.md` measures. [`Precision::DEFAULT`] is what every frame uses unless told
/// otherwise; the other settings exist so that their trade can be measured and chosen (the
/// report shows which of them save anything).
///
/// The other knobs are types and values chosen elsewhere: the depth format
/// ([`DepthBuffer`](crate::buffer::DepthBuffer) over `u16` or `u32`), the shading
/// ([`Flat`](crate::shade::Flat), [`Gouraud`](crate::shade::Gouraud) or
/// [`PerspectiveGouraud`](crate::shade::PerspectiveGouraud)) and the sine method of model
/// matrices ([`Transform::matrix_by`](crate::mesh::Transform::matrix_by)).
///
/// ```
/// use fixed3d::math::Normalize;
/// use fixed3d::pipeline::Precision;
/// let coarse = Precision::DEFAULT.with_subpixel_bits(2).with_normalize(Normalize::Exact);
/// assert_eq!(coarse.subpixel_bits(), 2);
/// assert_eq!(Precision::DEFAULT.with_subpixel_bits(9).subpixel_bits(), 4); // at most 4
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Precision {
    subpixel_bits: u32,
    matrix: MatrixFormat,
    normalize: Normalize,
}

/// The format of the clip-from-model matrix, the one matrix the vertex stage multiplies every
/// vertex by. `projection · view · model` is computed with at least 29 significant bits and
/// rounded once; the format says to what.
///
/// ```
/// use fixed3d::pipeline::{MatrixFormat, Precision};
/// let q16 = Precision::DEFAULT.with_matrix(MatrixFormat::Fixed(16));
/// assert_eq!(q16.matrix(), MatrixFormat::Fixed(16));
/// assert_eq!(Precision::DEFAULT.matrix(), MatrixFormat::Normalized);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum MatrixFormat {
    /// Q16.16, or more fraction bits when the object's clip coordinates would otherwise be
    /// small: scaled by a power of two so that they reach about 2¹⁹ units, the precision a
    /// unit-scale scene has in Q16.16 (the default). Clip coordinates are homogeneous, so the
    /// scale changes nothing but precision: a model a thousand times smaller (in its vertices
    /// or its matrix), or a camera very near it, keeps the precision of one at unit scale,
    /// while scenes at unit scale or larger keep Q16.16 and its cost (clip coordinates that fit
    /// 32 bits divide fast on Cortex-M0).
    #[default]
    Normalized,
    /// Every entry rounded to this many fraction bits (4 to 16): `Fixed(16)` is Q16.16, the
    /// format of every input matrix; `Fixed(8)` is the Q24.8 of narrower renderers.
    Fixed(u32),
}

impl Default for Precision {
    fn default() -> Self {
        Precision::DEFAULT
    }
}

impl Precision {
    /// 4 sub-pixel bits, [`MatrixFormat::Normalized`], [`Normalize::Newton`].
    pub const DEFAULT: Precision = Precision {
        subpixel_bits: SUBPIXEL_BITS,
        matrix: MatrixFormat::Normalized,
        normalize: Normalize::Newton,
    };

    /// With vertices snapped to `1/2^bits` of a pixel (0 to 4; larger values mean 4). The grid
    /// is centred on the viewport's centre. The rasteriser always works in sixteenths of a
    /// pixel, so coarser snapping saves nothing here; it shows what the coarser grids of other
    /// renderers cost in accuracy.
    #[must_use]
    pub const fn with_subpixel_bits(self, bits: u32) -> Self {
        let bits = if bits > SUBPIXEL_BITS {
            SUBPIXEL_BITS
        } else {
            bits
        };
        Precision {
            subpixel_bits: bits,
            ..self
        }
    }

    /// With the clip-from-model matrix in `format` (fraction bits of
    /// [`MatrixFormat::Fixed`] are clamped to 4..=16).
    #[must_use]
    pub const fn with_matrix(self, format: MatrixFormat) -> Self {
        let matrix = match format {
            MatrixFormat::Fixed(bits) if bits > 16 => MatrixFormat::Fixed(16),
            MatrixFormat::Fixed(bits) if bits < 4 => MatrixFormat::Fixed(4),
            other => other,
        };
        Precision { matrix, ..self }
    }

    /// With normals normalised by `method` for lighting.
    #[must_use]
    pub const fn with_normalize(self, method: Normalize) -> Self {
        Precision {
            normalize: method,
            ..self
        }
    }

    /// Sub-pixel bits of the snapping grid.
    #[must_use]
    pub const fn subpixel_bits(&self) -> u32 {
        self.subpixel_bits
    }

    /// The format of the clip-from-model matrix.
    #[must_use]
    pub const fn matrix(&self) -> MatrixFormat {
        self.matrix
    }

    /// The normalisation method of lighting.
    #[must_use]
    pub const fn normalize(&self) -> Normalize {
        self.normalize
    }

    /// `a · b · c`, rounded once to the matrix format, for points whose coordinates are at most
    /// `extent` (raw Q16.16) in magnitude.
    pub(crate) fn product(&self, a: &Mat4, b: &Mat4, c: &Mat4, extent: u32) -> Mat4 {
        let (m, frac) = product3(a, b, c);
        // Fraction bits to keep.
        let keep = match self.matrix {
            MatrixFormat::Fixed(bits) => bits as i32,
            MatrixFormat::Normalized => {
                // Integer bits of the largest entry.
                let bits = magnitude_bits(m.as_flattened()) as i32 - frac;
                let extent_bits = 32 - extent.max(1).leading_zeros() as i32;
                // Clip coordinates (entry · coordinate / 2¹⁶) of about 2¹⁹ units: what Q16.16
                // gives a unit-scale scene, whose coordinates then fit 32 bits (fast divisions
                // on Cortex-M0). Entries stay below 2³⁰; never fewer than 16 fraction bits.
                (19 + 16 - extent_bits - bits).min(30 - bits).max(16)
            }
        };
        let round = |v: i64| {
            let r = if frac >= keep {
                shr_round(v, (frac - keep).min(63) as u32)
            } else {
                v.saturating_mul(1i64 << (keep - frac).min(62))
            };
            r.clamp(i32::MIN as i64, i32::MAX as i64) as i32
        };
        Mat4::from_bits(m.map(|row| row.map(round)))
    }

    /// Sub-pixels per snapping step, as a shift.
    pub(crate) const fn snap_shift(&self) -> u32 {
        SUBPIXEL_BITS.saturating_sub(self.subpixel_bits)
    }
}
