//! Targets the triangle filler writes spans into.

use embedded_graphics::draw_target::DrawTarget;
use embedded_graphics::geometry::{Point, Size};
use embedded_graphics::pixelcolor::{PixelColor, Rgb888, RgbColor};
use embedded_graphics::primitives::Rectangle;

use super::carry::Carries;
use super::depth::{
    Counted, DepthBuffer, DepthFormat, DepthTest, FragmentCount, Less, RoundedRows, SpanColors,
    Uncounted,
};
use super::dither::{Nearest, OrderedDither, Quantize, TargetColor};
use super::framebuffer::FrameBuffer;
use super::grid::BufferError;
use crate::math::SUBPIXEL_SCALE;
use crate::raster::{
    line_pixels, rows_in_range, spans_in_range, PipelineEdge, PixelRect, Plane, RowStarts,
    ScreenPoint, Span, TriangleWalk,
};
use crate::shade::{Paint, SolidPaint};
use crate::stats::Stats;

/// One screen triangle to fill: its snapped vertices, their depths and its doubled signed
/// area, from which a target sets up its rows and the depth interpolation it needs (opaque).
#[derive(Clone, Copy, Debug, Default)]
pub struct ScreenTriangle {
    pub(super) p: [ScreenPoint; 3],
    pub(super) z: [i32; 3],
    pub(super) area: i64,
}

impl ScreenTriangle {
    /// The triangle `p` with depths `z` (Q1.30, in [0, 2³⁰]; any for a target without depth)
    /// and doubled signed area `area` (non-zero), within the pipeline's range.
    #[inline(always)]
    pub(crate) fn new(p: [ScreenPoint; 3], z: [i32; 3], area: i64) -> Self {
        ScreenTriangle { p, z, area }
    }

    /// The snapped vertices.
    #[inline(always)]
    pub(crate) fn points(&self) -> &[ScreenPoint; 3] {
        &self.p
    }

    /// Its spans clipped to `clip`, walked as the pipeline's triangles are.
    #[inline(always)]
    fn spans(&self, clip: PixelRect) -> TriangleWalk<PipelineEdge> {
        spans_in_range(self.p, clip, self.area)
    }

    /// The exact plane in Q1.44 (the pipeline's Q1.30 shifted by 14).
    #[inline]
    fn plane(&self) -> Plane {
        Plane::scaled(&self.p, self.z, 14, self.area)
    }

    /// The largest vertex depth (Q1.30).
    #[inline(always)]
    fn max(&self) -> i32 {
        let [a, b, c] = self.z;
        a.max(b).max(c)
    }
}

/// Something the triangle filler can write spans into: [`ColorDepth`] or [`Direct`].
pub trait RasterTarget {
    /// The error a write can return.
    type Error;
    /// The frame pixels this target receives (frame coordinates).
    fn clip(&self) -> PixelRect;
    /// The channel depths (red, green, blue) smooth shading hands this target its colours in:
    /// those of the colour type where the quantiser takes channels
    /// ([`Quantize::CHANNELS`]), 8 bits otherwise.
    #[doc(hidden)]
    const CHANNELS: [u8; 3] = [255; 3];
    /// Fills one triangle (per-triangle set-up happens here once, not per row).
    #[doc(hidden)]
    fn fill_triangle<P: Paint>(
        &mut self,
        triangle: &ScreenTriangle,
        paint: &P,
        stats: &mut Stats,
    ) -> Result<(), Self::Error>;
    /// Fills one triangle of colour `rgb`, drawing a band of a frame that [`Carries`] the
    /// triangles that go on below it into the next band (a target that carries none fills it
    /// as any other).
    #[doc(hidden)]
    fn fill_carrying(
        &mut self,
        triangle: &ScreenTriangle,
        rgb: Rgb888,
        carries: &mut Carries<'_>,
        stats: &mut Stats,
    ) -> Result<(), Self::Error> {
        let _ = carries;
        self.fill_triangle(triangle, &SolidPaint(rgb), stats)
    }
    /// Goes on with the triangle the band before carried for the one being drawn (see
    /// [`Carries`]): a target that carries none has none to go on with.
    #[doc(hidden)]
    fn resume_carried(
        &mut self,
        carries: &mut Carries<'_>,
        stats: &mut Stats,
    ) -> Result<(), Self::Error> {
        let _ = (carries, stats);
        Ok(())
    }
}

/// A colour buffer and a depth buffer of the same size, z-buffered filling: a fragment is
/// written when it passes the [`DepthTest`] `T` ([`Less`], strictly nearer, by default), and
/// fragments and writes are counted into [`Stats`] unless `K` is [`Uncounted`].
///
/// For a band, the buffers hold rows `first_row..first_row + height` of the frame; render
/// every band of a frame and the result is identical to the whole frame at once.
///
/// ```
/// use embedded_graphics::pixelcolor::Rgb565;
/// use fixed3d::raster::PixelRect;
/// use fixed3d::buffer::{ColorDepth, DepthBuffer, FrameBuffer, RasterTarget};
/// let (mut c, mut d) = ([Rgb565::new(0, 0, 0); 320 * 16], [0u16; 320 * 16]);
/// let mut color = FrameBuffer::new(&mut c, 320, 16).unwrap();
/// let mut depth = DepthBuffer::new(&mut d, 320, 16).unwrap();
/// let band = ColorDepth::band(&mut color, &mut depth, 32).unwrap();
/// assert_eq!(band.clip(), PixelRect::new(0, 32, 320, 48)); // frame rows 32..48
/// ```
#[derive(Debug)]
pub struct ColorDepth<'t, 'a, C, D, Q = Nearest, T = Less, K = Counted> {
    color: &'t mut FrameBuffer<'a, C>,
    depth: &'t mut DepthBuffer<'a, D>,
    /// The frame's pixels the buffers hold (rows from the band's first, every column), found once
    /// here rather than for each triangle.
    clip: PixelRect,
    test: T,
    quantize: Q,
    count: K,
}

impl<'t, 'a, C: TargetColor, D: DepthFormat> ColorDepth<'t, 'a, C, D, Nearest> {
    /// The whole frame: both buffers must have the same size.
    pub fn new(
        color: &'t mut FrameBuffer<'a, C>,
        depth: &'t mut DepthBuffer<'a, D>,
    ) -> Result<Self, BufferError> {
        Self::band(color, depth, 0)
    }

    /// One band of a frame: the buffers (of the same size) hold frame rows from `first_row`.
    pub fn band(
        color: &'t mut FrameBuffer<'a, C>,
        depth: &'t mut DepthBuffer<'a, D>,
        first_row: u32,
    ) -> Result<Self, BufferError> {
        if color.width() != depth.width() || color.height() != depth.height() {
            return Err(BufferError::SizeMismatch);
        }
        let first_row = i32::try_from(first_row).map_err(|_| BufferError::TooLarge)?;
        let w = color.width().min(i32::MAX as u32) as i32;
        let h = color.height().min(i32::MAX as u32) as i32;
        let clip = PixelRect::new(0, first_row, w, first_row.saturating_add(h));
        Ok(ColorDepth {
            color,
            depth,
            clip,
            test: Less,
            quantize: Nearest,
            count: Counted,
        })
    }
}

impl<'t, 'a, C, D, Q, T, K> ColorDepth<'t, 'a, C, D, Q, T, K> {
    /// With another depth test ([`LessOrEqual`](super::LessOrEqual): the last of two equal
    /// depths stays).
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Rgb565;
    /// use fixed3d::buffer::{ColorDepth, DepthBuffer, FrameBuffer, LessOrEqual};
    /// let (mut c, mut d) = ([Rgb565::new(0, 0, 0); 16], [u16::MAX; 16]);
    /// let mut color = FrameBuffer::new(&mut c, 4, 4).unwrap();
    /// let mut depth = DepthBuffer::new(&mut d, 4, 4).unwrap();
    /// let target = ColorDepth::new(&mut color, &mut depth).unwrap().with_test(LessOrEqual);
    /// # let _ = target;
    /// ```
    #[must_use]
    pub fn with_test<U: DepthTest>(self, test: U) -> ColorDepth<'t, 'a, C, D, Q, U, K> {
        self.with_types(|quantize, _, count| (quantize, test, count))
    }

    /// Without counting fragments and writes ([`Stats::fragments`] and [`Stats::written`] stay
    /// 0; see [`FragmentCount`] for what the counts cost).
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Rgb565;
    /// use fixed3d::buffer::{ColorDepth, DepthBuffer, FrameBuffer};
    /// let (mut c, mut d) = ([Rgb565::new(0, 0, 0); 16], [u16::MAX; 16]);
    /// let mut color = FrameBuffer::new(&mut c, 4, 4).unwrap();
    /// let mut depth = DepthBuffer::new(&mut d, 4, 4).unwrap();
    /// let target = ColorDepth::new(&mut color, &mut depth).unwrap().uncounted();
    /// # let _ = target;
    /// ```
    #[must_use]
    pub fn uncounted(self) -> ColorDepth<'t, 'a, C, D, Q, T, Uncounted> {
        self.with_types(|quantize, test, _| (quantize, test, Uncounted))
    }

    /// With ordered dithering (for 1-bit, grey and 16-bit displays).
    #[must_use]
    pub fn dithered(self) -> ColorDepth<'t, 'a, C, D, OrderedDither, T, K> {
        self.with_types(|_, test, count| (OrderedDither, test, count))
    }

    /// The same buffers and band, with the quantizer, depth test and count `types` makes of
    /// these.
    fn with_types<Q2, T2, K2>(
        self,
        types: impl FnOnce(Q, T, K) -> (Q2, T2, K2),
    ) -> ColorDepth<'t, 'a, C, D, Q2, T2, K2> {
        let (quantize, test, count) = types(self.quantize, self.test, self.count);
        ColorDepth {
            color: self.color,
            depth: self.depth,
            clip: self.clip,
            test,
            quantize,
            count,
        }
    }
}

impl<C, D, Q, T, K> ColorDepth<'_, '_, C, D, Q, T, K>
where
    C: PixelColor,
    D: DepthFormat,
    T: DepthTest,
    K: FragmentCount,
{
    /// Depth-tests the spans of one triangle; `colors_for(span)` gives the colour of each of
    /// the span's pixels in turn.
    #[inline(always)]
    fn depth_tested_spans<G: SpanColors<C>>(
        &mut self,
        triangle: &ScreenTriangle,
        stats: &mut Stats,
        colors_for: impl FnMut(Span) -> G,
    ) {
        let Some(rows) = rows_in_range(triangle.p, self.clip, triangle.area) else {
            return;
        };
        let y = rows.row();
        let columns = (self.clip.x0, self.clip.x1);
        // Decided once per triangle: spans whose depths need no clamping, in 32-bit words
        // from a walk set up at the triangle's own vertex (see `RoundedRows`), so that a band
        // starts them as the whole frame does.
        let unclamped = if D::unclamped(triangle.max()) {
            let (p, z, area) = (&triangle.p, triangle.z, triangle.area);
            RoundedRows::new(p, z, area, y)
        } else {
            None
        };
        match unclamped {
            Some((mut walk, st)) => {
                let mut spans = rows.spans(columns);
                self.each_span(
                    &mut spans,
                    &mut walk,
                    stats,
                    colors_for,
                    |ds, cs, start, g, w| {
                        D::test_span_unclamped::<C, T, K>(ds, cs, start, st, g, w)
                    },
                );
            }
            None => {
                // Spans start at column 0 or right of it (the clip rectangle's first column).
                let plane = triangle.plane();
                let step = plane.step_x();
                self.each_span(
                    &mut rows.spans(columns),
                    &mut plane.rows(0, y),
                    stats,
                    colors_for,
                    |ds, cs, start, g, w| D::test_span::<C, T, K>(ds, cs, start, step, g, w),
                )
            }
        }
    }

    /// The solid triangle `triangle` in colour `c` (`rgb` before quantizing), carried into
    /// the next band by `carries` if it goes on below the target's rows and its depths take
    /// the word walk (see [`Carries`]); [`fill_triangle`](RasterTarget::fill_triangle) fills
    /// the others.
    fn carrying_spans(
        &mut self,
        triangle: &ScreenTriangle,
        (c, rgb): (C, Rgb888),
        carries: &mut Carries<'_>,
        stats: &mut Stats,
    ) -> bool {
        let Some(rows) = rows_in_range(triangle.p, self.clip, triangle.area) else {
            return true;
        };
        let Some((walk, st)) = D::unclamped(triangle.max())
            .then(|| RoundedRows::new(&triangle.p, triangle.z, triangle.area, rows.row()))
            .flatten()
        else {
            return false;
        };
        let mut spans = rows.spans((self.clip.x0, self.clip.x1));
        self.solid_spans_carried(&mut spans, (walk, st), (c, rgb), carries, stats);
        true
    }

    /// Fills the spans of a solid triangle in colour `c` (`rgb` before quantizing), its depths
    /// the word walk `depth` stepped by `st` along a row, and carries it into the next band if
    /// it goes on below the target's rows, its walks stopped on the row past the target's last.
    #[inline(always)]
    fn solid_spans_carried(
        &mut self,
        spans: &mut TriangleWalk<PipelineEdge>,
        (mut depth, st): (RoundedRows, i32),
        (c, rgb): (C, Rgb888),
        carries: &mut Carries<'_>,
        stats: &mut Stats,
    ) {
        carries.solid(rgb);
        self.each_span(
            spans,
            &mut depth,
            stats,
            |_| move || c,
            |ds, cs, start, g, w| D::test_span_unclamped::<C, T, K>(ds, cs, start, st, g, w),
        );
        let end = self.clip.y1;
        if spans.row() == end && spans.past() > end {
            carries.keep(spans.stopped(), depth);
        }
    }

    /// Runs `test_span(depths, colours, depth at the first pixel, colour source, failures so
    /// far)`, which returns the failures so far with the span's added, on every span of a
    /// triangle, and counts the fragments and the writes (fragments less failures) into
    /// `stats`. One count of the fragments that fail (fewer than those that pass) carried
    /// through the pixel loops, with no sum after each span, costs less than a count of
    /// writes from zero for each span. The walks are left on the row past the last.
    #[inline(always)]
    fn each_span<G: SpanColors<C>, R: RowStarts>(
        &mut self,
        spans: &mut TriangleWalk<PipelineEdge>,
        depth: &mut R,
        stats: &mut Stats,
        mut colors_for: impl FnMut(Span) -> G,
        mut test_span: impl FnMut(&mut [D], &mut [C], R::Start, G, u32) -> u32,
    ) {
        let (mut y, width) = (spans.row(), self.color.width() as usize);
        let (colors, depths) = (self.color.cells_all_mut(), self.depth.cells_all_mut());
        // The same length for both (they are), so that one bounds check per span serves both.
        let n = colors.len().min(depths.len());
        let (Some(colors), Some(depths)) = (colors.get_mut(..n), depths.get_mut(..n)) else {
            return;
        };
        // Rows lie in the clip rectangle, the buffers' extent (same size, exactly
        // width · height cells): a span's cells are x0..x1 of its row in both.
        let mut row = (y.wrapping_sub(self.clip.y0) as u32 as usize).wrapping_mul(width);
        let (mut fragments, mut failed) = (0u32, 0u32);
        spans.for_each_row(|x0, x1| {
            if x0 < x1 {
                let first = row.wrapping_add(x0 as u32 as usize);
                let end = row.wrapping_add(x1 as u32 as usize);
                // One check: both buffers are `n` long, so the second range is the first's.
                if let Some(cs) = colors.get_mut(first..end) {
                    if let Some(ds) = depths.get_mut(first..end) {
                        if K::COUNTED {
                            fragments = fragments.wrapping_add(cs.len() as u32);
                        }
                        let g = colors_for(Span { y, x0, x1 });
                        failed = test_span(ds, cs, depth.at(x0), g, failed);
                    }
                }
            }
            depth.next_row();
            row = row.wrapping_add(width);
            y = y.wrapping_add(1);
        });
        stats.fragments = stats.fragments.saturating_add(fragments);
        // Each failed fragment was counted among the fragments: no wrap.
        stats.written = stats.written.saturating_add(fragments.wrapping_sub(failed));
    }
}

impl<C, D, Q, T, K> ColorDepth<'_, '_, C, D, Q, T, K>
where
    C: TargetColor,
    D: DepthFormat,
    Q: Quantize<C>,
    T: DepthTest,
    K: FragmentCount,
{
    /// Draws the line from `a` to `b` (snapped positions and Q1.30 depths) by the rule of
    /// [`line_pixels`], each pixel depth-tested like a triangle's: its depth is the endpoints'
    /// interpolated along the line's major axis at the pixel's centre.
    pub(crate) fn depth_line(
        &mut self,
        (a, za): (ScreenPoint, i32),
        (b, zb): (ScreenPoint, i32),
        rgb: Rgb888,
        stats: &mut Stats,
    ) {
        let pixels = line_pixels(a, b, self.clip);
        // Along the major axis (x where |dx| ≥ |dy|), in sub-pixels: within ±2²⁵ (the
        // rasteriser's coordinate limit), so every product below stays within i64.
        let (dx, dy) = (
            i64::from(b.x) - i64::from(a.x),
            i64::from(b.y) - i64::from(a.y),
        );
        let x_major = dx.abs() >= dy.abs();
        let (start, run) = if x_major { (a.x, dx) } else { (a.y, dy) };
        let Some(run) = core::num::NonZeroI64::new(run) else {
            return;
        };
        let mut depth = LineDepth::new(za, zb, start, run);
        let y0 = self.clip.y0;
        let (width, rows) = (self.color.width() as usize, self.color.height());
        let (colors, depths) = (self.color.cells_all_mut(), self.depth.cells_all_mut());
        let (mut fragments, mut failed) = (0u32, 0u32);
        for p in pixels {
            let z = depth.at(if x_major { p.x } else { p.y });
            // The pixels lie in the clip rectangle, inside the buffers. A row outside them (a
            // negative one too, as a word) is skipped all the same, and so is a negative
            // column (the sum overflows, or lies past the cells). The row's start is a word
            // product below `width · height`: a checked one is a 64-bit product on cores
            // without a long multiply.
            let row = p.y.wrapping_sub(y0) as u32;
            if row >= rows {
                continue;
            }
            let Some(i) = (row as usize).wrapping_mul(width).checked_add(p.x as usize) else {
                continue;
            };
            if let (Some(d), Some(c)) = (depths.get_mut(i..=i), colors.get_mut(i..=i)) {
                let color = self.quantize.quantize(rgb, p.x, p.y);
                fragments = fragments.wrapping_add(1);
                failed = D::test_span::<C, T, K>(d, c, z, 0, || color, failed);
            }
        }
        if K::COUNTED {
            stats.fragments = stats.fragments.saturating_add(fragments);
            stats.written = stats.written.saturating_add(fragments.wrapping_sub(failed));
        }
    }
}

/// The depth of a line at its pixels' centres: `za + ⌊offset·dz / run⌋` (Q1.30) for a centre
/// `offset` sub-pixels from the start along the major axis, exactly, whichever pixel the walk
/// starts at, so that a line clipped to a band has the depths of the whole line. Stepped by
/// quotient and remainder between neighbouring pixels, found by division elsewhere.
struct LineDepth {
    za: i64,
    start: i64,
    /// `dz` times the sign of the run, and the run's length (positive).
    dz: i64,
    d: core::num::NonZeroI64,
    /// The pixel last asked for, and its quotient and remainder (in `[0, d)`).
    at: Option<(i32, i64, i64)>,
}

impl LineDepth {
    fn new(za: i32, zb: i32, start: i32, run: core::num::NonZeroI64) -> Self {
        let dz = i64::from(zb) - i64::from(za);
        LineDepth {
            za: i64::from(za),
            start: i64::from(start),
            dz: if run.get() < 0 { -dz } else { dz },
            d: run.abs(),
            at: None,
        }
    }

    /// The depth at the centre of pixel `major` along the major axis, in the interpolator's
    /// Q1.44. Offsets stay within ±2²⁶ and `dz` within ±2³², so products stay below 2⁵⁹.
    fn at(&mut self, major: i32) -> i64 {
        let d = self.d.get();
        let step = self.dz * i64::from(SUBPIXEL_SCALE);
        let (q, r) = match self.at {
            Some((m, q, r)) if m.checked_add(1) == Some(major) => {
                let (q, r) = (q + step.div_euclid(d), r + step.rem_euclid(d));
                if r >= d {
                    (q + 1, r - d)
                } else {
                    (q, r)
                }
            }
            Some((m, q, r)) if m.checked_sub(1) == Some(major) => {
                let (q, r) = (q - step.div_euclid(d), r - step.rem_euclid(d));
                if r < 0 {
                    (q - 1, r + d)
                } else {
                    (q, r)
                }
            }
            _ => {
                let offset = i64::from(major) * i64::from(SUBPIXEL_SCALE)
                    + i64::from(SUBPIXEL_SCALE / 2)
                    - self.start;
                let n = offset * self.dz;
                (n.div_euclid(d), n.rem_euclid(d))
            }
        };
        self.at = Some((major, q, r));
        (self.za + q).clamp(-(1 << 40), 1 << 40) << 14
    }
}

impl<C, D, Q, T, K> RasterTarget for ColorDepth<'_, '_, C, D, Q, T, K>
where
    C: TargetColor,
    D: DepthFormat,
    Q: Quantize<C>,
    T: DepthTest,
    K: FragmentCount,
{
    type Error = core::convert::Infallible;

    fn clip(&self) -> PixelRect {
        self.clip
    }

    const CHANNELS: [u8; 3] = match Q::CHANNELS {
        Some(channels) => channels,
        None => [255; 3],
    };

    #[inline]
    fn fill_carrying(
        &mut self,
        triangle: &ScreenTriangle,
        rgb: Rgb888,
        carries: &mut Carries<'_>,
        stats: &mut Stats,
    ) -> Result<(), Self::Error> {
        if Q::UNIFORM {
            let c = self.quantize.quantize(rgb, 0, 0);
            if self.carrying_spans(triangle, (c, rgb), carries, stats) {
                return Ok(());
            }
        }
        self.fill_triangle(triangle, &SolidPaint(rgb), stats)
    }

    /// Goes on with the triangle `carries` took for the one being drawn, in its colour, from
    /// the row where the band before stopped it.
    #[inline(never)]
    fn resume_carried(
        &mut self,
        carries: &mut Carries<'_>,
        stats: &mut Stats,
    ) -> Result<(), Self::Error> {
        let Some(c) = carries.take() else {
            return Ok(());
        };
        let Some(walk) = c.walk else {
            return Ok(());
        };
        let mut spans = walk.resume(self.clip.y0, self.clip.y1, (self.clip.x0, self.clip.x1));
        let color = self.quantize.quantize(c.rgb, 0, 0);
        let depth = (c.depth, c.depth.step_x);
        self.solid_spans_carried(&mut spans, depth, (color, c.rgb), carries, stats);
        Ok(())
    }

    #[inline]
    fn fill_triangle<P: Paint>(
        &mut self,
        triangle: &ScreenTriangle,
        paint: &P,
        stats: &mut Stats,
    ) -> Result<(), Self::Error> {
        match paint.solid() {
            Some(rgb) if Q::UNIFORM => {
                // One conversion per triangle.
                let c = self.quantize.quantize(rgb, 0, 0);
                self.depth_tested_spans(triangle, stats, |_| move || c);
            }
            _ if P::SCALED && Q::CHANNELS.is_some() => {
                // Channels in the colour's own depths (see `CHANNELS`).
                let quantize = self.quantize;
                self.depth_tested_spans(triangle, stats, |span| InDepths {
                    cursor: paint.cursor(span),
                    quantize,
                });
            }
            _ => {
                let quantize = self.quantize;
                self.depth_tested_spans(triangle, stats, |span| Quantized {
                    cursor: paint.cursor(span),
                    quantize,
                    x: span.x0,
                    y: span.y,
                });
            }
        }
        Ok(())
    }
}

/// A paint's colours along a span, already in the target colour's channel depths, packed.
struct InDepths<P, Q> {
    cursor: P,
    quantize: Q,
}

impl<C, P: Iterator<Item = Rgb888>, Q: Quantize<C>> SpanColors<C> for InDepths<P, Q> {
    // In the span loop: a call per pixel would cost more than the paint's own step.
    #[inline(always)]
    fn next_color(&mut self) -> C {
        let c = self.cursor.next().unwrap_or_default();
        self.quantize.of_channels(c.r(), c.g(), c.b())
    }
}

/// A paint's 8-bit colours along a span, quantised pixel by pixel (the pixel's position
/// chooses a dither's threshold).
struct Quantized<P, Q> {
    cursor: P,
    quantize: Q,
    x: i32,
    y: i32,
}

impl<C, P: Iterator<Item = Rgb888>, Q: Quantize<C>> SpanColors<C> for Quantized<P, Q> {
    #[inline(always)]
    fn next_color(&mut self) -> C {
        let c = self
            .quantize
            .quantize(self.cursor.next().unwrap_or_default(), self.x, self.y);
        self.x = self.x.wrapping_add(1);
        c
    }
}

/// Any embedded-graphics [`DrawTarget`] (a display driver, a framebuffer), filled with no depth
/// buffer: back-face culling and draw order decide visibility, which is exact for one convex
/// object. Solid spans are one `fill_solid` each, shaded spans one `fill_contiguous`.
///
/// ```
/// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::Rgb565};
/// use fixed3d::raster::PixelRect;
/// use fixed3d::buffer::{Direct, RasterTarget};
/// let mut display = MockDisplay::<Rgb565>::new();
/// let target = Direct::new(&mut display);
/// assert_eq!(target.clip(), PixelRect::new(0, 0, 64, 64));
/// ```
#[derive(Debug)]
pub struct Direct<'t, T, Q = Nearest> {
    target: &'t mut T,
    quantize: Q,
}

impl<'t, T: DrawTarget> Direct<'t, T, Nearest> {
    /// Fills `target` directly.
    pub fn new(target: &'t mut T) -> Self {
        Direct {
            target,
            quantize: Nearest,
        }
    }

    /// With ordered dithering.
    #[must_use]
    pub fn dithered(self) -> Direct<'t, T, OrderedDither> {
        Direct {
            target: self.target,
            quantize: OrderedDither,
        }
    }
}

impl<T, Q> RasterTarget for Direct<'_, T, Q>
where
    T: DrawTarget,
    T::Color: From<Rgb888>,
    Q: Quantize<T::Color>,
{
    type Error = T::Error;

    fn clip(&self) -> PixelRect {
        PixelRect::from_rectangle(&self.target.bounding_box())
    }

    fn fill_triangle<P: Paint>(
        &mut self,
        triangle: &ScreenTriangle,
        paint: &P,
        stats: &mut Stats,
    ) -> Result<(), T::Error> {
        let spans = triangle.spans(self.clip());
        let solid = match paint.solid() {
            Some(rgb) if Q::UNIFORM => Some(self.quantize.quantize(rgb, 0, 0)),
            _ => None,
        };
        for span in spans {
            let n = span.x1.saturating_sub(span.x0).max(0) as u32;
            let area = Rectangle::new(Point::new(span.x0, span.y), Size::new(n, 1));
            stats.fragments = stats.fragments.saturating_add(n);
            stats.written = stats.written.saturating_add(n);
            match solid {
                Some(c) => self.target.fill_solid(&area, c)?,
                None => {
                    let q = self.quantize;
                    let y = span.y;
                    let colors = paint
                        .cursor(span)
                        .zip(span.x0..span.x1)
                        .map(move |(rgb, x)| q.quantize(rgb, x, y));
                    self.target.fill_contiguous(&area, colors)?;
                }
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {

    /// A line's depth at a pixel is the same whether the walk reached it from either
    /// neighbour or started there (a line clipped to a band has the whole line's depths).
    #[test]
    fn r7_line_depths_do_not_depend_on_where_the_walk_starts() {
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        for _ in 0..2_000 {
            let (za, zb) = (rng.within(1 << 30), rng.within(1 << 30));
            let start = rng.within(1 << 19);
            let run = i64::from(rng.within(1 << 19));
            let Some(run) = core::num::NonZeroI64::new(run) else {
                continue;
            };
            let first = (start >> 4) - 40;
            let exact: std::vec::Vec<i64> = (0..80)
                .map(|k| LineDepth::new(za, zb, start, run).at(first + k))
                .collect();
            let mut up = LineDepth::new(za, zb, start, run);
            let mut down = LineDepth::new(za, zb, start, run);
            for k in 0..80 {
                assert_eq!(up.at(first + k), exact[k as usize]);
                assert_eq!(down.at(first + 79 - k), exact[79 - k as usize]);
            }
        }
    }

    use embedded_graphics::pixelcolor::Rgb565;

    use super::*;

    /// A `ColorDepth`'s clip rectangle spans every column of its buffers, for a whole frame
    /// and for a band.
    #[test]
    fn r6_color_depth_clips_to_its_buffers_columns() {
        for (w, h, first) in [(1, 1, 0), (320, 16, 32), (7, 3, 1000)] {
            let mut c = std::vec![Rgb565::new(0, 0, 0); (w * h) as usize];
            let mut d = std::vec![0u16; (w * h) as usize];
            let mut color = FrameBuffer::new(&mut c, w, h).unwrap_or_else(|e| panic!("{e:?}"));
            let mut depth = DepthBuffer::new(&mut d, w, h).unwrap_or_else(|e| panic!("{e:?}"));
            let frame = ColorDepth::new(&mut color, &mut depth).map(|t| t.clip());
            assert_eq!(frame, Ok(PixelRect::new(0, 0, w as i32, h as i32)));
            let band = ColorDepth::band(&mut color, &mut depth, first).map(|t| t.clip());
            let rows = first as i32..(first + h) as i32;
            assert_eq!(band, Ok(PixelRect::new(0, rows.start, w as i32, rows.end)));
        }
    }
}
