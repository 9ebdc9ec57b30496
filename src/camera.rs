//! Cameras: where the eye is and where it looks, as a view matrix (world → view space).
//!
//! View space follows the conventions of the crate: the camera looks down its own −Z, +Y is up
//! and +X is right. Both cameras build their matrix afresh from exact inputs (positions and
//! integer angles), so nothing accumulates: after a hundred thousand small turns the view
//! matrix is as orthonormal as after one (case T31).

use core::fmt;

use crate::math::{normalize, shr_round, Angle, Mat4, Number, Scalar, Vec3, UNIT_ONE};
use crate::projection::{Projection, ProjectionError, Viewport};

/// Why a camera could not build its view matrix.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum CameraError {
    /// The eye and the target are the same point: there is no direction to look in.
    EyeAtTarget,
    /// The up vector is zero or parallel to the viewing direction.
    UpParallelToView,
}

impl fmt::Display for CameraError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            CameraError::EyeAtTarget => "the eye and the target are the same point",
            CameraError::UpParallelToView => {
                "the up vector is zero or parallel to the view direction"
            }
        })
    }
}

impl core::error::Error for CameraError {}

/// A camera at `eye` looking at `target`, with `up` giving the roll.
///
/// ```
/// use fixed3d::camera::LookAt;
/// use fixed3d::math::Vec3;
/// let view = LookAt::new(Vec3::from_int(0, 0, 5), Vec3::ZERO, Vec3::Y).view().unwrap();
/// // The target is 5 units straight ahead, down the camera's -Z.
/// assert_eq!(view.transform_point(Vec3::ZERO), Vec3::from_int(0, 0, -5));
/// assert!(LookAt::new(Vec3::ZERO, Vec3::ZERO, Vec3::Y).view().is_err());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct LookAt {
    /// Where the camera is.
    pub eye: Vec3,
    /// The point it looks at.
    pub target: Vec3,
    /// Which way is up (need not be unit length or perpendicular).
    pub up: Vec3,
}

impl LookAt {
    /// A look-at camera.
    #[must_use]
    pub const fn new(eye: Vec3, target: Vec3, up: Vec3) -> Self {
        LookAt { eye, target, up }
    }

    /// The view matrix: rows are the camera's right, up and backward axes (`z = normalize(eye −
    /// target)`, `x = normalize(up × z)`, `y = z × x`), with `−axis · eye` in the last column.
    pub fn view(&self) -> Result<Mat4, CameraError> {
        let e = self.eye.to_bits().map(i64::from);
        let t = self.target.to_bits().map(i64::from);
        let z =
            normalize([e[0] - t[0], e[1] - t[1], e[2] - t[2]]).ok_or(CameraError::EyeAtTarget)?;
        let up = self.up.to_bits().map(i64::from);
        let zw = z.map(i64::from);
        // up (Q16.16) × z (Q2.30): each product below 2⁶¹.
        let x = normalize([
            up[1] * zw[2] - up[2] * zw[1],
            up[2] * zw[0] - up[0] * zw[2],
            up[0] * zw[1] - up[1] * zw[0],
        ])
        .ok_or(CameraError::UpParallelToView)?;
        let y = cross_unit(z, x);
        Ok(view_from_axes([x, y, z], self.eye))
    }
}

/// A free-flying camera: a position, a yaw about world up (+Y) and a pitch about the camera's
/// right axis, kept within ±89 degrees so the view never flips over.
///
/// Yaw 0 and pitch 0 look down world −Z. A positive yaw turns left (counter-clockwise seen from
/// above), a positive pitch looks up. Movement is along the camera's own axes.
///
/// ```
/// use fixed3d::camera::FlyCamera;
/// use fixed3d::math::{Angle, Scalar, Vec3};
/// let mut cam = FlyCamera::new(Vec3::ZERO);
/// cam.turn(Angle::from_degrees(90), Angle::ZERO); // face world -X
/// cam.move_forward(Scalar::from_num(2));
/// assert_eq!(cam.position, Vec3::from_int(-2, 0, 0));
/// cam.turn(Angle::ZERO, Angle::from_degrees(120)); // pitch stops at 89 degrees
/// assert_eq!(cam.pitch(), Angle::from_degrees(89));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct FlyCamera {
    /// Where the camera is.
    pub position: Vec3,
    yaw: Angle,
    pitch: Angle,
}

const PITCH_LIMIT: Angle = Angle::from_degrees(89);

impl FlyCamera {
    /// A camera at `position` looking down world −Z.
    #[must_use]
    pub const fn new(position: Vec3) -> Self {
        FlyCamera {
            position,
            yaw: Angle::ZERO,
            pitch: Angle::ZERO,
        }
    }

    /// The yaw (about world +Y).
    #[must_use]
    pub const fn yaw(&self) -> Angle {
        self.yaw
    }

    /// The pitch (about the camera's right axis), within ±89 degrees.
    #[must_use]
    pub const fn pitch(&self) -> Angle {
        self.pitch
    }

    /// Sets yaw and pitch (the pitch is clamped to ±89 degrees).
    pub fn set_orientation(&mut self, yaw: Angle, pitch: Angle) {
        self.yaw = yaw;
        self.pitch = Angle::ZERO;
        self.turn(Angle::ZERO, pitch);
    }

    /// Turns by `yaw` (exact, wrapping) and `pitch` (clamped to ±89 degrees; the delta is read
    /// as a signed angle in (−180, 180] degrees).
    pub fn turn(&mut self, yaw: Angle, pitch: Angle) {
        self.yaw += yaw;
        let limit = PITCH_LIMIT.to_bits() as i64;
        let p = (self.pitch.to_bits() as i32 as i64 + pitch.to_bits() as i32 as i64)
            .clamp(-limit, limit);
        self.pitch = Angle::from_bits(p as i32 as u32);
    }

    /// The camera's right, up and backward axes in world space (unit, Q2.30).
    fn axes(&self) -> [[i32; 3]; 3] {
        let (sy, cy) = (self.yaw.sin_bits() as i64, self.yaw.cos_bits() as i64);
        let (sp, cp) = (self.pitch.sin_bits() as i64, self.pitch.cos_bits() as i64);
        let m = |a: i64, b: i64| shr_round(a * b, 30) as i32;
        // Columns of Ry(yaw) · Rx(pitch).
        let right = [cy as i32, 0, -sy as i32];
        let up = [m(sy, sp), cp as i32, m(cy, sp)];
        let back = [m(sy, cp), -sp as i32, m(cy, cp)];
        [right, up, back]
    }

    /// The direction the camera looks in (unit length).
    #[must_use]
    pub fn forward(&self) -> Vec3 {
        let [_, _, b] = self.axes();
        unit_to_vec(b.map(|c| -c))
    }

    /// The camera's right axis (unit length).
    #[must_use]
    pub fn right(&self) -> Vec3 {
        unit_to_vec(self.axes()[0])
    }

    /// The camera's up axis (unit length).
    #[must_use]
    pub fn up(&self) -> Vec3 {
        unit_to_vec(self.axes()[1])
    }

    /// Moves along the viewing direction (negative: backwards). Saturates at the edge of the
    /// coordinate range.
    pub fn move_forward(&mut self, distance: Scalar) {
        let [_, _, b] = self.axes();
        self.shift(b.map(|c| -c), distance);
    }

    /// Moves along the camera's right axis (negative: left).
    pub fn strafe_right(&mut self, distance: Scalar) {
        self.shift(self.axes()[0], distance);
    }

    /// Moves along the camera's up axis (negative: down).
    pub fn move_up(&mut self, distance: Scalar) {
        self.shift(self.axes()[1], distance);
    }

    fn shift(&mut self, axis: [i32; 3], distance: Scalar) {
        let d = distance.to_bits() as i64;
        let step = axis.map(|a| shr_round(a as i64 * d, 30));
        let p = self.position.to_bits();
        let moved = [0, 1, 2].map(|i| {
            let s = step.get(i).copied().unwrap_or(0);
            let v = p.get(i).copied().unwrap_or(0) as i64 + s;
            v.clamp(i32::MIN as i64, i32::MAX as i64) as i32
        });
        self.position = Vec3::from_bits(moved[0], moved[1], moved[2]);
    }

    /// The view matrix, rebuilt from the position and the two integer angles.
    #[must_use]
    pub fn view(&self) -> Mat4 {
        view_from_axes(self.axes(), self.position)
    }
}

fn unit_to_vec(u: [i32; 3]) -> Vec3 {
    let q = u.map(|c| shr_round(c as i64, 14) as i32);
    Vec3::from_bits(q[0], q[1], q[2])
}

/// Cross product of two Q2.30 vectors, Q2.30.
fn cross_unit(a: [i32; 3], b: [i32; 3]) -> [i32; 3] {
    let [a0, a1, a2] = a.map(i64::from);
    let [b0, b1, b2] = b.map(i64::from);
    [a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0]
        .map(|v| shr_round(v, 30).clamp(-(UNIT_ONE as i64), UNIT_ONE as i64) as i32)
}

/// Rows `axis` (Q2.30 → Q16.16) with `−axis · eye` in the last column.
fn view_from_axes(axes: [[i32; 3]; 3], eye: Vec3) -> Mat4 {
    let [x, y, z] = axes;
    let e = eye.to_bits();
    Mat4::from_bits([
        view_row(x, e),
        view_row(y, e),
        view_row(z, e),
        [0, 0, 0, 1 << 16],
    ])
}

/// A row of [`view_from_axes`]: `axis` (Q2.30 → Q16.16) and `−axis · eye`. Out of line: one
/// copy serves the three rows.
#[inline(never)]
fn view_row(a: [i32; 3], e: [i32; 3]) -> [i32; 4] {
    let d = a[0] as i64 * e[0] as i64 + a[1] as i64 * e[1] as i64 + a[2] as i64 * e[2] as i64;
    let t = (-shr_round(d, 30)).clamp(i32::MIN as i64, i32::MAX as i64) as i32;
    let q = a.map(|c| shr_round(c as i64, 14) as i32);
    [q[0], q[1], q[2], t]
}

/// A camera placement that shows a whole box: where to put a look-at camera and which near and
/// far planes to use (for viewers that open on a model of unknown size).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Framing {
    /// Looks at the box's centre.
    pub look_at: LookAt,
    /// A near plane just in front of the box.
    pub near: Scalar,
    /// A far plane just behind it.
    pub far: Scalar,
}

impl Framing {
    /// Frames the box `min..max` seen from `direction` (from the box's centre towards the eye,
    /// any non-zero length): the eye is far enough back that the box's bounding sphere fits in
    /// both the vertical field of view and the horizontal one (from `aspect`, width / height),
    /// with a 5% margin.
    ///
    /// ```
    /// use fixed3d::camera::Framing;
    /// use fixed3d::math::{Angle, Scalar, Vec3};
    /// let f = Framing::of_box(Vec3::from_int(-1, -1, -1), Vec3::from_int(1, 1, 1), Vec3::Z, Angle::from_degrees(90), Scalar::ONE).unwrap();
    /// // The sphere of radius √3 fits a 45-degree half-angle at distance √3 / sin 45° = √6 (plus 5%).
    /// let d = f.look_at.eye.z.to_num::<f64>();
    /// assert!((d - 6f64.sqrt() * 1.05).abs() < 1e-3);
    /// assert!(f.near < Scalar::from_num(d - 3f64.sqrt()) && f.far > Scalar::from_num(d + 3f64.sqrt()));
    /// ```
    pub fn of_box(
        min: Vec3,
        max: Vec3,
        direction: Vec3,
        fov_y: Angle,
        aspect: Scalar,
    ) -> Result<Framing, CameraError> {
        let dir = normalize(direction.to_bits().map(i64::from)).ok_or(CameraError::EyeAtTarget)?;
        let (lo, hi) = (min.to_bits().map(i64::from), max.to_bits().map(i64::from));
        let centre = [0, 1, 2]
            .map(|k| (lo.get(k).copied().unwrap_or(0) + hi.get(k).copied().unwrap_or(0)) / 2);
        let half = [0, 1, 2]
            .map(|k| (hi.get(k).copied().unwrap_or(0) - lo.get(k).copied().unwrap_or(0)).abs() / 2);
        let radius = crate::math::isqrt_u64(
            half.iter()
                .map(|h| (h * h) as u64)
                .fold(0u64, u64::saturating_add),
        ) as i64;
        let radius = radius.max(1 << 6);
        // Sine of the smaller half-angle of the view (Q2.30).
        let h = Angle::from_bits(fov_y.to_bits() / 2);
        let (s, c) = (h.sin_bits() as i64, h.cos_bits() as i64);
        let sin_min = if aspect >= Scalar::ONE {
            s
        } else {
            // tan_x = aspect · tan(h); sin_x = tan_x / sqrt(1 + tan_x²), all Q2.30.
            let tan_x = (aspect.to_bits() as i64 * crate::math::div_round(s << 30, c.max(1))) >> 16;
            let len = crate::math::isqrt_u64(((1i64 << 60) + tan_x * tan_x) as u64) as i64;
            crate::math::div_round(tan_x << 30, len.max(1))
        }
        .max(1 << 10);
        // distance = 1.05 · radius / sin
        let dist = crate::math::div_round((radius * 1075 / 1024).saturating_mul(1 << 30), sin_min)
            .min(1 << 32);
        let sat = |v: i64| v.clamp(i32::MIN as i64, i32::MAX as i64) as i32;
        let eye = [0, 1, 2].map(|k| {
            sat(centre.get(k).copied().unwrap_or(0)
                + ((dist * dir.get(k).copied().unwrap_or(0) as i64) >> 30))
        });
        let up = if dir[1].abs() > (UNIT_ONE / 16) * 15 {
            Vec3::from_int(0, 0, -1)
        } else {
            Vec3::Y
        };
        let near = (dist - radius * 9 / 8)
            .max(Projection::MIN_NEAR.to_bits() as i64)
            .max(dist / 1000);
        let far = (dist + radius * 9 / 8).max(near + 1);
        Ok(Framing {
            look_at: LookAt::new(
                Vec3::from_bits(eye[0], eye[1], eye[2]),
                Vec3::from_bits(sat(centre[0]), sat(centre[1]), sat(centre[2])),
                up,
            ),
            near: Scalar::from_bits(sat(near)),
            far: Scalar::from_bits(sat(far)),
        })
    }
}

/// How a [`Camera`] projects: a perspective or orthographic lens.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum Lens {
    Perspective {
        fov_y: Angle,
        near: Scalar,
        far: Scalar,
    },
    Orthographic {
        height: Scalar,
        near: Scalar,
        far: Scalar,
    },
}

/// Where the camera stands and looks.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum Placement {
    LookAt(LookAt),
    View(Mat4),
}

/// A camera as the [`Renderer`](crate::render::Renderer) takes it: a lens and a placement.
/// The aspect ratio is not part of it: the renderer takes it from the display it draws into,
/// so the two cannot disagree. Bad values (a zero field of view, the far plane not beyond the
/// near one, the eye at the target) are reported when a frame is drawn, by
/// [`projection`](Self::projection) and [`view`](Self::view).
///
/// ```
/// use fixed3d::camera::Camera;
/// use fixed3d::projection::Viewport;
/// let camera = Camera::perspective(60, 1, 10).looking_at([0, 1, 4], [0, 0, 0]);
/// let viewport = Viewport::new(320, 240).unwrap();
/// assert!(camera.view().is_ok());
/// assert!(camera.projection(&viewport).is_ok());
/// // The far plane must lie beyond the near one:
/// assert!(Camera::perspective(60, 10, 1).projection(&viewport).is_err());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Camera {
    lens: Lens,
    placement: Placement,
}

impl Camera {
    /// A perspective camera with a vertical field of view of `fov_y_degrees` and near and far
    /// planes at those distances, at the origin looking down −Z until placed.
    #[must_use]
    pub fn perspective(fov_y_degrees: impl Number, near: impl Number, far: impl Number) -> Self {
        Camera {
            lens: Lens::Perspective {
                fov_y: Angle::degrees(fov_y_degrees),
                near: near.to_scalar(),
                far: far.to_scalar(),
            },
            placement: Placement::View(Mat4::IDENTITY),
        }
    }

    /// An orthographic camera showing a box `height` units tall (as wide as the display's
    /// aspect makes it), from `near` to `far`.
    #[must_use]
    pub fn orthographic(height: impl Number, near: impl Number, far: impl Number) -> Self {
        Camera {
            lens: Lens::Orthographic {
                height: height.to_scalar(),
                near: near.to_scalar(),
                far: far.to_scalar(),
            },
            placement: Placement::View(Mat4::IDENTITY),
        }
    }

    /// This camera at `eye`, looking at `target`, with +Y up.
    #[must_use]
    pub fn looking_at(self, eye: impl Into<Vec3>, target: impl Into<Vec3>) -> Self {
        let look = LookAt::new(eye.into(), target.into(), Vec3::Y);
        Camera {
            placement: Placement::LookAt(look),
            ..self
        }
    }

    /// This camera placed by a view matrix (world to view), e.g. a [`FlyCamera`]'s.
    #[must_use]
    pub fn with_view(self, view: Mat4) -> Self {
        Camera {
            placement: Placement::View(view),
            ..self
        }
    }

    /// The view matrix (world to view).
    pub fn view(&self) -> Result<Mat4, CameraError> {
        match self.placement {
            Placement::LookAt(look) => look.view(),
            Placement::View(m) => Ok(m),
        }
    }

    /// The projection for `viewport`, whose aspect ratio it takes.
    pub fn projection(&self, viewport: &Viewport) -> Result<Projection, ProjectionError> {
        let aspect = viewport.aspect();
        match self.lens {
            Lens::Perspective { fov_y, near, far } => {
                Projection::perspective(fov_y, aspect, near, far)
            }
            Lens::Orthographic { height, near, far } => {
                Projection::orthographic(height, aspect, near, far)
            }
        }
    }
}
