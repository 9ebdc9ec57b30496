//! What a frame shows: objects, an ambient colour, directional lights and point lights.
//!
//! Lambert's law, per colour channel: `colour = base · clamp(ambient + Σᵢ lightᵢ · aᵢ ·
//! max(0, N·Lᵢ), 0, 1)`, where `N` is the unit surface normal, `Lᵢ` the unit direction **from
//! the surface towards** light *i* and `aᵢ` its [`Attenuation`] at the surface's distance
//! (1 for a directional light). The lights live in a fixed-capacity list whose size the caller
//! chooses.

use core::fmt;

use embedded_graphics::pixelcolor::{Rgb888, RgbColor};

use crate::math::{
    div_floor, is_scaled_rotation, map3, normalize, unit_and_length, Number, Scalar, Vec3,
};
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
        self.bits().map(i64::from)
    }

    /// The channels' raw Q16.16 bits.
    pub(crate) const fn bits(&self) -> [i32; 3] {
        [self.r.to_bits(), self.g.to_bits(), self.b.to_bits()]
    }
}

/// Whether point lights are lit (the `point-light` feature): without it no code that lights by
/// them is linked, and adding one is [`LightError::Disabled`].
const POINT_LIGHT: bool = cfg!(feature = "point-light");

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
/// ambient, directional and point lights. Ambient lights add up.
///
/// ```
/// use fixed3d::scene::{Attenuation, Light, PointLight};
/// let lights = [
///     Light::ambient(0.2),
///     Light::directional([-1, 1, 1], 0.8),
///     Light::point([0, 2, 1], 0.5),
///     PointLight::new([2, 0, 0], 4).attenuated(Attenuation::InverseSquare).within(6).into(),
/// ];
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
    /// Light from a point in the world, in every direction.
    Point(PointLight),
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

    /// A point light at `position` (world space), not attenuated and not cut off: see
    /// [`PointLight`] for both.
    #[must_use]
    pub fn point(position: impl Into<Vec3>, color: impl Into<LightColor>) -> Self {
        Light::Point(PointLight::new(position, color))
    }
}

impl From<PointLight> for Light {
    fn from(light: PointLight) -> Self {
        Light::Point(light)
    }
}

/// How a point light weakens with the distance `d` (in world units) from it: the factor its
/// colour is scaled by.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Attenuation {
    /// 1 at every distance.
    #[default]
    None,
    /// `1 / (1 + d)`.
    Linear,
    /// `1 / (1 + d²)`: the physical fall-off, kept finite at the light.
    InverseSquare,
}

impl Attenuation {
    /// The factor (Q2.30, in [0, 1], rounded down) at distance `d` (raw Q16.16).
    fn factor(self, d: u64) -> i32 {
        const ONE: u64 = 1 << 30;
        let f = match self {
            Attenuation::None => ONE,
            // 2⁴⁶ / (2¹⁶ + d) is (1 / (1 + d)) in Q2.30.
            Attenuation::Linear => div_floor(ONE << 16, (1u64 << 16).saturating_add(d)),
            // d² below 2⁶², else the factor is below 2⁻³⁰.
            Attenuation::InverseSquare if d < 1 << 31 => div_floor(ONE << 32, (1 << 32) + d * d),
            Attenuation::InverseSquare => 0,
        };
        f as i32
    }
}

/// A light at a point, shining in every direction: a colour, how it weakens with distance and
/// a range beyond which it lights nothing.
///
/// ```
/// use fixed3d::scene::{Attenuation, Light, PointLight};
/// let lamp = PointLight::new([0, 3, 0], 2).attenuated(Attenuation::Linear).within(10);
/// let lights = [Light::ambient(0.1), lamp.into()];
/// # let _ = lights;
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct PointLight {
    /// Where it is, in world space.
    pub position: Vec3,
    /// Its colour and strength (before attenuation).
    pub color: LightColor,
    /// How it weakens with distance.
    pub attenuation: Attenuation,
    /// The distance from which it lights nothing; `None` for no limit.
    pub range: Option<Scalar>,
}

impl PointLight {
    /// A light at `position`, not attenuated, with no range limit.
    #[must_use]
    pub fn new(position: impl Into<Vec3>, color: impl Into<LightColor>) -> Self {
        PointLight {
            position: position.into(),
            color: color.into(),
            attenuation: Attenuation::None,
            range: None,
        }
    }

    /// With `attenuation`.
    #[must_use]
    pub const fn attenuated(self, attenuation: Attenuation) -> Self {
        PointLight {
            attenuation,
            ..self
        }
    }

    /// Lighting nothing at `range` (world units) and beyond.
    #[must_use]
    pub fn within(self, range: impl Number) -> Self {
        PointLight {
            range: Some(range.to_scalar()),
            ..self
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
    /// A point light, in a build without the `point-light` feature.
    Disabled,
}

impl fmt::Display for LightError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            LightError::Full => "no room for another light",
            LightError::ZeroDirection => "a light direction must not be zero",
            LightError::Disabled => "point lights need the `point-light` feature of fixed3d",
        })
    }
}

impl core::error::Error for LightError {}

/// A point light as lighting reads it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct PreparedPoint {
    /// World position, raw Q16.16.
    position: [i32; 3],
    /// Colour, raw Q16.16 per channel.
    pub(crate) color: [i32; 3],
    attenuation: Attenuation,
    /// Raw Q16.16 distance from which it lights nothing (`u32::MAX`: none; a range is below
    /// 2³¹).
    range: u32,
}

impl PreparedPoint {
    fn new(light: &PointLight) -> Self {
        PreparedPoint {
            position: light.position.to_bits(),
            color: light.color.bits(),
            attenuation: light.attenuation,
            range: light
                .range
                .map_or(u32::MAX, |r| r.to_bits().max(0).unsigned_abs()),
        }
    }

    /// The unit direction (Q2.30) from a surface point `at` (raw Q16.16, in the lighting's
    /// space) towards the light, and the light's attenuation there (Q2.30, in [0, 1]); `None`
    /// at the light itself and from its range on.
    pub(crate) fn towards(&self, at: &[i64; 3]) -> Option<([i32; 3], i32)> {
        let [x, y, z] = self.position.map(i64::from);
        // Positions from the vertex stage are below 2⁴⁸: differences fit.
        let v = map3([(x, at[0]), (y, at[1]), (z, at[2])], |(p, a)| {
            p.saturating_sub(a)
        });
        let (unit, distance) = unit_and_length(v)?;
        let within = self.range == u32::MAX || distance < u64::from(self.range);
        within.then(|| (unit, self.attenuation.factor(distance)))
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct PreparedLight {
    /// Unit direction towards the light, Q2.30.
    pub(crate) direction: [i32; 3],
    /// Colour, raw Q16.16 per channel.
    pub(crate) color: [i32; 3],
}

/// An ambient colour and up to `N` directional and point lights.
///
/// ```
/// # if cfg!(not(feature = "point-light")) { return; }
/// use fixed3d::math::{Scalar, Vec3};
/// use fixed3d::scene::{DirectionalLight, LightColor, LightError, Lighting, PointLight};
/// let mut lighting = Lighting::<2>::new(LightColor::gray(Scalar::from_num(0.2)));
/// let sun = DirectionalLight::new(Vec3::from_int(-1, 1, 1), LightColor::gray(Scalar::from_num(0.8)));
/// assert_eq!(lighting.push(sun), Ok(()));
/// assert_eq!(lighting.push_point(PointLight::new([0, 2, 0], 1)), Ok(()));
/// assert_eq!(lighting.push(sun), Err(LightError::Full));
/// ```
#[derive(Clone, Debug)]
pub struct Lighting<const N: usize> {
    ambient: LightColor,
    lights: heapless::Vec<PreparedLight, N>,
    points: heapless::Vec<PreparedPoint, N>,
    /// True while every channel of the ambient colour and of every light lies in [0, 1] (the
    /// usual lights): Lambert's sums then fit words (see
    /// [`channels_in_words`](Self::channels_in_words)).
    unit: bool,
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
        Lighting {
            ambient,
            lights: heapless::Vec::new(),
            points: heapless::Vec::new(),
            unit: unit_channel(r as i64) && unit_channel(g as i64) && unit_channel(b as i64),
        }
    }

    /// Adds a directional light; its direction is normalised here, once.
    pub fn push(&mut self, light: DirectionalLight) -> Result<(), LightError> {
        let direction =
            normalize(light.direction.to_bits().map(i64::from)).ok_or(LightError::ZeroDirection)?;
        let prepared = PreparedLight {
            direction,
            color: light.color.bits(),
        };
        if self.len() >= N {
            return Err(LightError::Full);
        }
        self.lights.push(prepared).map_err(|_| LightError::Full)?;
        self.unit &= prepared.color.iter().all(|&c| unit_channel(c.into()));
        Ok(())
    }

    /// Adds a point light (its terms are summed per channel). [`LightError::Disabled`]
    /// without the `point-light` feature.
    pub fn push_point(&mut self, light: PointLight) -> Result<(), LightError> {
        if !POINT_LIGHT {
            return Err(LightError::Disabled);
        }
        if self.len() >= N {
            return Err(LightError::Full);
        }
        let prepared = PreparedPoint::new(&light);
        self.points.push(prepared).map_err(|_| LightError::Full)?;
        self.unit &= prepared.color.iter().all(|&c| unit_channel(c.into()));
        Ok(())
    }

    /// The lighting of a slice of [`Light`]s: the ambient lights summed (each channel
    /// saturated), the others in order. [`LightError::Full`] when there are more than `N`
    /// directional and point lights, [`LightError::ZeroDirection`] for a zero direction.
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
                Light::Directional { .. } | Light::Point(_) => sum,
            });
        let mut lighting = Lighting::new(ambient);
        for light in lights {
            match *light {
                Light::Ambient(_) => {}
                Light::Directional { towards, color } => {
                    lighting.push(DirectionalLight::new(towards, color))?;
                }
                Light::Point(point) => lighting.push_point(point)?,
            }
        }
        Ok(lighting)
    }

    /// The ambient colour.
    #[must_use]
    pub const fn ambient(&self) -> LightColor {
        self.ambient
    }

    /// How many directional and point lights there are.
    #[must_use]
    pub fn len(&self) -> usize {
        self.lights.len() + self.points.len()
    }

    /// True when there is no directional or point light.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The directional lights, at most `N` as the iterator says: a loop over them then has a
    /// known bound.
    pub(crate) fn lights(&self) -> impl Iterator<Item = &PreparedLight> + Clone {
        self.lights.iter().take(N)
    }

    /// How many directional lights there are (at most `N`).
    pub(crate) fn directional_count(&self) -> usize {
        self.lights.len().min(N)
    }

    /// The point lights, at most `N` (none without the `point-light` feature: then no code
    /// that lights by them is linked).
    pub(crate) fn points(&self) -> impl Iterator<Item = &PreparedPoint> + Clone {
        self.points.iter().take(if POINT_LIGHT { N } else { 0 })
    }

    /// True when every channel lies in [0, 1] and there are at most 2¹³ lights: a light's term
    /// (its channel times a cosine below 2³¹ in Q2.30) is then below 2¹⁷ in Q16.16, and the
    /// ambient and all terms of a channel sum below 2³¹.
    pub(crate) fn channels_in_words(&self) -> bool {
        self.unit && N <= 1 << 13
    }

    /// The same lights seen from an object's model space, for an object whose normal matrix
    /// (world from model, see [`Mat4::normal_matrix`](crate::math::Mat4)) is a rotation times a
    /// scale: then `n · l` in world space equals `n' · Rᵀl` in model space for the model-space
    /// unit normal `n'`, and flat shading needs no product by the normal matrix per triangle.
    /// `None` for any other matrix (a non-uniform scale or a shear: normals must be carried),
    /// and when there are point lights (they are lit from world-space positions).
    pub(crate) fn in_model_space(&self, normal_matrix: &[[i32; 3]; 3]) -> Option<Lighting<N>> {
        if self.points().next().is_some() || !is_scaled_rotation(normal_matrix) {
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
            points: heapless::Vec::new(),
            unit: self.unit,
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
