//! What a frame shows: objects, an ambient colour and directional lights.
//!
//! Lambert's law, per colour channel: `colour = base · clamp(ambient + Σᵢ lightᵢ · max(0, N·Lᵢ),
//! 0, 1)`, where `N` is the unit surface normal and `Lᵢ` the unit direction **from the surface
//! towards** light *i*. The lights live in a fixed-capacity list whose size the caller chooses.

use core::fmt;

use embedded_graphics::pixelcolor::{Rgb888, RgbColor};

use crate::math::{is_scaled_rotation, normalize, Number, Scalar, Vec3};
use crate::mesh::Object;

/// The colour and intensity of a light: one [`Scalar`] per channel, 1.0 is full strength
/// (values above 1 are allowed; the lit result is clamped).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct LightColor {
    /// Red.
    pub r: Scalar,
    /// Green.
    pub g: Scalar,
    /// Blue.
    pub b: Scalar,
}

impl LightColor {
    /// No light.
    pub const BLACK: LightColor = LightColor::gray(Scalar::ZERO);
    /// Full white.
    pub const WHITE: LightColor = LightColor::gray(Scalar::ONE);

    /// A colour from three intensities.
    #[must_use]
    pub const fn new(r: Scalar, g: Scalar, b: Scalar) -> Self {
        LightColor { r, g, b }
    }

    /// White at `intensity`.
    #[must_use]
    pub const fn gray(intensity: Scalar) -> Self {
        LightColor::new(intensity, intensity, intensity)
    }

    /// An [`Rgb888`] colour (255 is full) scaled by `intensity`.
    #[must_use]
    pub fn from_rgb888(c: Rgb888, intensity: Scalar) -> Self {
        let ch = |v: u8| {
            let raw = (intensity.to_bits() as i64 * v as i64 + 127) / 255;
            Scalar::from_bits(raw.clamp(i32::MIN as i64, i32::MAX as i64) as i32)
        };
        LightColor::new(ch(c.r()), ch(c.g()), ch(c.b()))
    }

    #[inline]
    pub(crate) fn channels(&self) -> [i64; 3] {
        [self.r, self.g, self.b].map(|c| c.to_bits() as i64)
    }
}

/// True for a channel (raw Q16.16) in [0, 1].
const fn unit_channel(c: i64) -> bool {
    0 <= c && c <= 1 << 16
}

impl<T: Number> From<T> for LightColor {
    /// White light of this intensity (see [`Number`]).
    ///
    /// ```
    /// use fixed3d::scene::LightColor;
    /// assert_eq!(LightColor::from(1), LightColor::WHITE);
    /// ```
    fn from(intensity: T) -> Self {
        LightColor::gray(intensity.to_scalar())
    }
}

impl From<Rgb888> for LightColor {
    /// Light of this colour at full strength.
    fn from(c: Rgb888) -> Self {
        LightColor::from_rgb888(c, Scalar::ONE)
    }
}

/// A light of a scene, as the [`Renderer`](crate::render::Renderer) takes them: a slice of
/// ambient and directional lights. Ambient lights add up.
///
/// ```
/// use fixed3d::scene::Light;
/// let lights = [Light::ambient(0.2), Light::directional([-1, 1, 1], 0.8)];
/// # let _ = lights;
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Light {
    /// Light from everywhere, added to every surface whatever its facing.
    Ambient(LightColor),
    /// Light from far away: `towards` is the direction from a surface to the light (any
    /// length but zero).
    Directional {
        /// From the surface towards the light.
        towards: Vec3,
        /// Its colour and strength.
        color: LightColor,
    },
}

impl Light {
    /// An ambient light: a number for white light of that strength, an `Rgb888`, or a
    /// [`LightColor`].
    #[must_use]
    pub fn ambient(color: impl Into<LightColor>) -> Self {
        Light::Ambient(color.into())
    }

    /// A directional light shining from direction `towards` (from the surface to the light:
    /// `[-1, 1, 1]` is up, left and in front of a camera on +z).
    #[must_use]
    pub fn directional(towards: impl Into<Vec3>, color: impl Into<LightColor>) -> Self {
        Light::Directional {
            towards: towards.into(),
            color: color.into(),
        }
    }
}

/// A light infinitely far away, shining along `-direction`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct DirectionalLight {
    /// The direction from the surface **towards** the light (any non-zero length).
    pub direction: Vec3,
    /// Colour and intensity.
    pub color: LightColor,
}

impl DirectionalLight {
    /// A light towards `direction`.
    #[must_use]
    pub const fn new(direction: Vec3, color: LightColor) -> Self {
        DirectionalLight { direction, color }
    }
}

/// Why a light could not be added.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum LightError {
    /// The list is full (its capacity is the `N` of [`Lighting<N>`]).
    Full,
    /// The direction is the zero vector.
    ZeroDirection,
}

impl fmt::Display for LightError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            LightError::Full => "no room for another light",
            LightError::ZeroDirection => "a light direction must not be zero",
        })
    }
}

impl core::error::Error for LightError {}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct PreparedLight {
    /// Unit direction towards the light, Q2.30.
    pub(crate) direction: [i32; 3],
    pub(crate) color: [i64; 3],
}

/// An ambient colour and up to `N` directional lights.
///
/// ```
/// use fixed3d::math::{Scalar, Vec3};
/// use fixed3d::scene::{DirectionalLight, LightColor, LightError, Lighting};
/// let mut lighting = Lighting::<1>::new(LightColor::gray(Scalar::from_num(0.2)));
/// let sun = DirectionalLight::new(Vec3::from_int(-1, 1, 1), LightColor::gray(Scalar::from_num(0.8)));
/// assert_eq!(lighting.push(sun), Ok(()));
/// assert_eq!(lighting.push(sun), Err(LightError::Full));
/// ```
#[derive(Clone, Debug)]
pub struct Lighting<const N: usize> {
    ambient: LightColor,
    lights: heapless::Vec<PreparedLight, N>,
    /// True while the ambient colour and every light are grey (equal channels): Lambert then
    /// sums one channel for all three.
    grey: bool,
    /// True while they are grey and every channel lies in [0, 1] (the usual lights): that one
    /// sum then fits a word (see [`in_words`](Self::in_words)).
    words: bool,
}

impl<const N: usize> Lighting<N> {
    /// Ambient light only.
    #[must_use]
    pub const fn new(ambient: LightColor) -> Self {
        let [r, g, b] = [
            ambient.r.to_bits(),
            ambient.g.to_bits(),
            ambient.b.to_bits(),
        ];
        let grey = r == g && g == b;
        Lighting {
            ambient,
            lights: heapless::Vec::new(),
            grey,
            words: grey && unit_channel(r as i64),
        }
    }

    /// Adds a light; its direction is normalised here, once.
    pub fn push(&mut self, light: DirectionalLight) -> Result<(), LightError> {
        let direction =
            normalize(light.direction.to_bits().map(i64::from)).ok_or(LightError::ZeroDirection)?;
        let prepared = PreparedLight {
            direction,
            color: light.color.channels(),
        };
        self.lights.push(prepared).map_err(|_| LightError::Full)?;
        let [r, g, b] = prepared.color;
        self.grey &= r == g && g == b;
        self.words &= self.grey && unit_channel(r);
        Ok(())
    }

    /// The lighting of a slice of [`Light`]s: the ambient lights summed (each channel
    /// saturated), the directional ones in order. [`LightError::Full`] when there are more
    /// than `N` directional lights, [`LightError::ZeroDirection`] for a zero direction.
    ///
    /// ```
    /// use fixed3d::scene::{Light, LightError, Lighting};
    /// let lights = [Light::ambient(0.2), Light::directional([0, 0, 1], 0.8)];
    /// assert_eq!(Lighting::<1>::from_lights(&lights).map(|l| l.len()), Ok(1));
    /// assert_eq!(Lighting::<0>::from_lights(&lights).err(), Some(LightError::Full));
    /// ```
    pub fn from_lights(lights: &[Light]) -> Result<Self, LightError> {
        let ambient = lights
            .iter()
            .fold(LightColor::BLACK, |sum, light| match light {
                Light::Ambient(c) => LightColor::new(
                    sum.r.saturating_add(c.r),
                    sum.g.saturating_add(c.g),
                    sum.b.saturating_add(c.b),
                ),
                Light::Directional { .. } => sum,
            });
        let mut lighting = Lighting::new(ambient);
        for light in lights {
            if let Light::Directional { towards, color } = *light {
                lighting.push(DirectionalLight::new(towards, color))?;
            }
        }
        Ok(lighting)
    }

    /// The ambient colour.
    #[must_use]
    pub const fn ambient(&self) -> LightColor {
        self.ambient
    }

    /// How many lights there are.
    #[must_use]
    pub fn len(&self) -> usize {
        self.lights.len()
    }

    /// True when there is no directional light.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.lights.is_empty()
    }

    /// The directional lights, at most `N` as the iterator says: a loop over them then has a
    /// known bound.
    pub(crate) fn lights(&self) -> impl Iterator<Item = &PreparedLight> + Clone {
        self.lights.iter().take(N)
    }

    /// True when the ambient colour and every light have three equal channels.
    pub(crate) fn is_grey(&self) -> bool {
        self.grey
    }

    /// True when the lighting [`is_grey`](Self::is_grey), every channel lies in [0, 1] and
    /// there are at most 2¹³ lights: a light's term (its channel times a cosine below 2³¹ in
    /// Q2.30) is then below 2¹⁷ in Q16.16, and the ambient and all terms sum below 2³¹.
    pub(crate) fn in_words(&self) -> bool {
        self.words && N <= 1 << 13
    }

    /// The same lights seen from an object's model space, for an object whose normal matrix
    /// (world from model, see [`Mat4::normal_matrix`](crate::math::Mat4)) is a rotation times a
    /// scale: then `n · l` in world space equals `n' · Rᵀl` in model space for the model-space
    /// unit normal `n'`, and flat shading needs no product by the normal matrix per triangle.
    /// `None` for any other matrix (a non-uniform scale or a shear: normals must be carried).
    pub(crate) fn in_model_space(&self, normal_matrix: &[[i32; 3]; 3]) -> Option<Lighting<N>> {
        if !is_scaled_rotation(normal_matrix) {
            return None;
        }
        let mut lights = self.lights.clone();
        for light in &mut lights {
            // Nᵀl = s·Rᵀl: its direction is Rᵀl (entries within ±2³⁰: products below 2⁶⁰).
            let [x, y, z] = light.direction.map(i64::from);
            let back = core::array::from_fn(|j| {
                let col = |i: usize| normal_matrix[i][j] as i64;
                col(0) * x + col(1) * y + col(2) * z
            });
            light.direction = normalize(back)?;
        }
        Some(Lighting {
            ambient: self.ambient,
            lights,
            grey: self.grey,
            words: self.words,
        })
    }
}

/// The objects of a frame and their lighting.
#[derive(Clone, Debug)]
pub struct Scene<'a, const N: usize> {
    /// The objects, drawn in this order.
    pub objects: &'a [Object<'a>],
    /// Ambient and directional lights.
    pub lighting: Lighting<N>,
}

impl<'a, const N: usize> Scene<'a, N> {
    /// A scene.
    #[must_use]
    pub const fn new(objects: &'a [Object<'a>], lighting: Lighting<N>) -> Self {
        Scene { objects, lighting }
    }

    /// Vertices of all objects: the size of the vertex cache a frame needs.
    #[must_use]
    pub fn vertex_count(&self) -> usize {
        self.objects
            .iter()
            .fold(0usize, |n, o| n.saturating_add(o.mesh.positions().len()))
    }
}
