//! Projections (view → clip space) and the viewport (clip → screen).
//!
//! Both projections map the visible depth range to `z/w` in [0, 1]: 0 at the near plane, 1 at
//! the far plane. Constructors check their arguments and return a [`ProjectionError`] instead
//! of a matrix that would divide by zero or overflow.

use core::fmt;

use crate::math::{div_round, Angle, Mat4, Scalar};

/// Why a projection or viewport could not be built.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ProjectionError {
    /// `near` is below [`Projection::MIN_NEAR`] (perspective) or the depth range is empty.
    NearTooSmall,
    /// `far` is not beyond `near`, or so close to it that depth cannot be represented.
    FarNotBeyondNear,
    /// The field of view is not strictly between 0 and 180 degrees, or so narrow that the
    /// matrix overflows.
    FieldOfView,
    /// The aspect ratio or the view height is not positive, or makes an entry overflow.
    Aspect,
    /// A viewport dimension is zero or above [`Viewport::MAX_SIZE`].
    ViewportSize,
}

impl fmt::Display for ProjectionError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            ProjectionError::NearTooSmall => "near plane too close to the eye (minimum 1/1024)",
            ProjectionError::FarNotBeyondNear => "far plane not far enough beyond the near plane",
            ProjectionError::FieldOfView => {
                "field of view must be strictly between 0 and 180 degrees"
            }
            ProjectionError::Aspect => {
                "aspect ratio or view height must be positive and representable"
            }
            ProjectionError::ViewportSize => {
                "viewport dimensions must be between 1 and 2048 pixels"
            }
        })
    }
}

impl core::error::Error for ProjectionError {}

/// A perspective or orthographic projection.
///
/// ```
/// use fixed3d::math::{Angle, Scalar};
/// use fixed3d::projection::{Projection, ProjectionError};
/// let s = Scalar::from_num;
/// let p = Projection::perspective(Angle::from_degrees(60), s(4) / s(3), s(1), s(10)).unwrap();
/// assert!(p.is_perspective());
/// let bad = Projection::perspective(Angle::from_degrees(60), s(1), s(0), s(10));
/// assert_eq!(bad, Err(ProjectionError::NearTooSmall));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Projection {
    matrix: Mat4,
    perspective: bool,
}

const ONE: i64 = 1 << 16;

impl Projection {
    /// The smallest near distance a perspective projection accepts: 1/1024. Below it the
    /// Q16.16 entries of the matrix lose more than a tenth of a percent of the near distance.
    pub const MIN_NEAR: Scalar = Scalar::from_bits(64);

    /// Perspective from the vertical field of view, the aspect ratio (width / height) and the
    /// near and far distances (positive, along the camera's −Z):
    ///
    /// ```text
    /// [ f/aspect  0   0             0                ]      f = 1 / tan(fov_y / 2)
    /// [ 0         f   0             0                ]
    /// [ 0         0   far/(n−f)     near·far/(n−f)   ]      z/w: near → 0, far → 1
    /// [ 0         0  −1             0                ]
    /// ```
    pub fn perspective(
        fov_y: Angle,
        aspect: Scalar,
        near: Scalar,
        far: Scalar,
    ) -> Result<Self, ProjectionError> {
        if near < Self::MIN_NEAR {
            return Err(ProjectionError::NearTooSmall);
        }
        if far <= near {
            return Err(ProjectionError::FarNotBeyondNear);
        }
        if aspect <= Scalar::ZERO {
            return Err(ProjectionError::Aspect);
        }
        // fov in (0, 180): as a binary angle, (0, 2^31).
        if fov_y.to_bits() == 0 || fov_y.to_bits() >= Angle::HALF_TURN.to_bits() {
            return Err(ProjectionError::FieldOfView);
        }
        let half = Angle::from_bits(fov_y.to_bits() / 2);
        let (s, c) = (half.sin_bits() as i64, half.cos_bits() as i64);
        if s <= 0 {
            return Err(ProjectionError::FieldOfView);
        }
        let f = div_round(c << 16, s);
        let fx = div_round(f << 16, aspect.to_bits() as i64);
        let (n, fa) = (near.to_bits() as i64, far.to_bits() as i64);
        let a = -div_round(fa << 16, fa - n);
        let b = -div_round(n * fa, fa - n);
        let fit = |v: i64| i32::try_from(v).ok();
        let (Some(f), Some(fx)) = (fit(f), fit(fx)) else {
            return Err(if f > i32::MAX as i64 {
                ProjectionError::FieldOfView
            } else {
                ProjectionError::Aspect
            });
        };
        let (Some(a), Some(b)) = (fit(a), fit(b)) else {
            return Err(ProjectionError::FarNotBeyondNear);
        };
        Ok(Projection {
            matrix: Mat4::from_bits([
                [fx, 0, 0, 0],
                [0, f, 0, 0],
                [0, 0, a, b],
                [0, 0, -(ONE as i32), 0],
            ]),
            perspective: true,
        })
    }

    /// Orthographic projection of a box `height` tall (and `height · aspect` wide) centred on
    /// the camera's −Z axis, from `near` to `far` (near may be zero or negative).
    ///
    /// ```
    /// use fixed3d::math::{Scalar, Vec3};
    /// use fixed3d::projection::Projection;
    /// let s = Scalar::from_num;
    /// let p = Projection::orthographic(s(4), s(2), s(1), s(5)).unwrap();
    /// // The box's right edge at mid depth maps to x = 1, z = 0.5.
    /// let c = p.matrix().transform_point(Vec3::from_int(4, 0, -3));
    /// assert_eq!((c.x, c.z), (s(1), Scalar::from_num(0.5)));
    /// ```
    pub fn orthographic(
        height: Scalar,
        aspect: Scalar,
        near: Scalar,
        far: Scalar,
    ) -> Result<Self, ProjectionError> {
        if height <= Scalar::ZERO || aspect <= Scalar::ZERO {
            return Err(ProjectionError::Aspect);
        }
        if far <= near {
            return Err(ProjectionError::FarNotBeyondNear);
        }
        let h = height.to_bits() as i64;
        let w = (h * aspect.to_bits() as i64) >> 16;
        if w <= 0 {
            return Err(ProjectionError::Aspect);
        }
        let (n, fa) = (near.to_bits() as i64, far.to_bits() as i64);
        let depth = fa - n;
        let fit = |v: i64| i32::try_from(v).ok();
        let sx = fit(div_round(2 << 32, w)).ok_or(ProjectionError::Aspect)?;
        let sy = fit(div_round(2 << 32, h)).ok_or(ProjectionError::Aspect)?;
        let a = fit(-div_round(1 << 32, depth)).ok_or(ProjectionError::FarNotBeyondNear)?;
        let b = fit(-div_round(n << 16, depth)).ok_or(ProjectionError::FarNotBeyondNear)?;
        Ok(Projection {
            matrix: Mat4::from_bits([
                [sx, 0, 0, 0],
                [0, sy, 0, 0],
                [0, 0, a, b],
                [0, 0, 0, ONE as i32],
            ]),
            perspective: false,
        })
    }

    /// The clip-from-view matrix.
    #[must_use]
    pub const fn matrix(&self) -> &Mat4 {
        &self.matrix
    }

    /// True for a perspective projection.
    #[must_use]
    pub const fn is_perspective(&self) -> bool {
        self.perspective
    }

    /// For a perspective projection, `−a` in Q1.30 (`a` the third row's depth entry): the depth
    /// after projection is `d = z/w = −a + b/w`, so `1/w` is proportional to this minus `d`.
    /// `None` for an orthographic projection, whose `w` is 1 everywhere.
    pub(crate) const fn inverse_w_offset(&self) -> Option<i64> {
        if self.perspective {
            Some(-(self.matrix.to_bits()[2][2] as i64) << 14)
        } else {
            None
        }
    }
}

/// The pixel size of the image: clip space `[-1, 1]²` maps to `[0, width] × [0, height]` with
/// y flipped (`x = (x_ndc + 1)·W/2`, `y = (1 − y_ndc)·H/2`), snapped to sub-pixels.
///
/// ```
/// use fixed3d::projection::Viewport;
/// let v = Viewport::new(320, 240).unwrap();
/// assert_eq!((v.width(), v.height()), (320, 240));
/// assert!(Viewport::new(0, 240).is_err());
/// assert!(Viewport::new(4096, 240).is_err());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Viewport {
    width: u16,
    height: u16,
}

impl Viewport {
    /// The largest width or height: 2048 pixels. The guard band (±1024 pixels around the
    /// centre in sub-pixels of 1/16) and the i64 attribute setup are sized for it.
    pub const MAX_SIZE: u32 = 2048;

    /// A viewport of `width × height` pixels, each from 1 to [`Viewport::MAX_SIZE`].
    pub const fn new(width: u32, height: u32) -> Result<Self, ProjectionError> {
        if width == 0 || height == 0 || width > Self::MAX_SIZE || height > Self::MAX_SIZE {
            return Err(ProjectionError::ViewportSize);
        }
        Ok(Viewport {
            width: width as u16,
            height: height as u16,
        })
    }

    /// Width in pixels.
    #[must_use]
    pub const fn width(&self) -> u32 {
        self.width as u32
    }

    /// Height in pixels.
    #[must_use]
    pub const fn height(&self) -> u32 {
        self.height as u32
    }

    /// Width / height, for [`Projection::perspective`].
    #[must_use]
    pub fn aspect(&self) -> Scalar {
        Scalar::from_bits(div_round((self.width as i64) << 16, self.height as i64) as i32)
    }
}
