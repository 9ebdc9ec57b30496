//! A colour buffer over a caller-supplied slice.

use embedded_graphics::draw_target::DrawTarget;
use embedded_graphics::geometry::{Dimensions, OriginDimensions, Point, Size};
use embedded_graphics::pixelcolor::PixelColor;
use embedded_graphics::primitives::{PointsIter, Rectangle};
use embedded_graphics::Pixel;

use super::grid::{BufferError, Grid};

/// A `width × height` image in a caller-supplied slice, row-major, top row first.
///
/// It is a [`DrawTarget`] with fast `fill_solid` and `fill_contiguous`, and presents itself to
/// any other `DrawTarget` (a display driver) in one `fill_contiguous` call.
///
/// ```
/// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*};
/// use fixed3d::buffer::FrameBuffer;
/// let mut pixels = [BinaryColor::Off; 4 * 2];
/// let mut fb = FrameBuffer::new(&mut pixels, 4, 2).unwrap();
/// Pixel(Point::new(1, 0), BinaryColor::On).draw(&mut fb).unwrap();
/// let mut display = MockDisplay::new();
/// fb.present(&mut display).unwrap();
/// display.assert_pattern(&[".#..", "...."]);
/// ```
#[derive(Debug)]
pub struct FrameBuffer<'a, C> {
    grid: Grid<'a, C>,
}

impl<'a, C: PixelColor> FrameBuffer<'a, C> {
    /// Wraps `pixels` (at least `width · height` long; only that prefix is used).
    pub fn new(pixels: &'a mut [C], width: u32, height: u32) -> Result<Self, BufferError> {
        Ok(FrameBuffer {
            grid: Grid::new(pixels, width, height)?,
        })
    }

    /// Width in pixels.
    #[must_use]
    pub fn width(&self) -> u32 {
        self.grid.width()
    }

    /// Height in pixels.
    #[must_use]
    pub fn height(&self) -> u32 {
        self.grid.height()
    }

    /// The pixels, row-major.
    #[must_use]
    pub fn pixels(&self) -> &[C] {
        self.grid.cells()
    }

    /// The pixel at `(x, y)`, `None` outside.
    #[must_use]
    pub fn pixel(&self, x: i32, y: i32) -> Option<C> {
        self.grid.get(x, y)
    }

    /// Sets every pixel to `color`.
    pub fn fill(&mut self, color: C) {
        self.grid.fill(color);
    }

    /// Every pixel, row-major (`width · height` of them).
    #[inline]
    pub(crate) fn cells_all_mut(&mut self) -> &mut [C] {
        self.grid.cells_all_mut()
    }

    /// Row `y` as a mutable slice.
    pub(crate) fn row_mut(&mut self, y: i32) -> Option<&mut [C]> {
        self.grid.row_mut(y)
    }

    /// Sends the whole image to `display` with its top-left corner at the origin.
    pub fn present<D: DrawTarget<Color = C>>(&self, display: &mut D) -> Result<(), D::Error> {
        self.present_at(display, Point::zero())
    }

    /// Sends the whole image to `display` with its top-left corner at `top_left` (for a band,
    /// the band's first row).
    pub fn present_at<D: DrawTarget<Color = C>>(
        &self,
        display: &mut D,
        top_left: Point,
    ) -> Result<(), D::Error> {
        let area = Rectangle::new(top_left, self.size());
        display.fill_contiguous(&area, self.pixels().iter().copied())
    }
}

impl<C: PixelColor> OriginDimensions for FrameBuffer<'_, C> {
    fn size(&self) -> Size {
        Size::new(self.width(), self.height())
    }
}

impl<C: PixelColor> DrawTarget for FrameBuffer<'_, C> {
    type Color = C;
    type Error = core::convert::Infallible;

    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Pixel<C>>,
    {
        for Pixel(p, c) in pixels {
            if let Some(slot) = self.grid.get_mut(p.x, p.y) {
                *slot = c;
            }
        }
        Ok(())
    }

    fn fill_contiguous<I>(&mut self, area: &Rectangle, colors: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = C>,
    {
        let clipped = area.intersection(&self.bounding_box());
        if clipped == *area {
            // Fast path: the whole area is inside; copy row by row.
            let mut colors = colors.into_iter();
            let (x0, w) = (area.top_left.x, area.size.width as usize);
            for y in area.rows() {
                if let Some(row) = self.row_mut(y) {
                    let start = x0 as usize;
                    if let Some(dst) = row.get_mut(start..start + w) {
                        for (d, c) in dst.iter_mut().zip(&mut colors) {
                            *d = c;
                        }
                    }
                }
            }
            Ok(())
        } else {
            self.draw_iter(area.points().zip(colors).map(|(p, c)| Pixel(p, c)))
        }
    }

    fn fill_solid(&mut self, area: &Rectangle, color: C) -> Result<(), Self::Error> {
        // The area cut to the buffer: a span a firmware fills row by row takes a few
        // comparisons, where the rectangles' own intersection takes checked sums and corners.
        // The far sides are sums of 64 bits (an area may reach past i32's range); cut to the
        // buffer's sides, they fit words again.
        let (x, y) = (area.top_left.x, area.top_left.y);
        let end = |at: i32, size: u32, side: u32| {
            (i64::from(at) + i64::from(size)).min(i64::from(side)) as i32
        };
        let (x0, x1) = (x.max(0), end(x, area.size.width, self.width()));
        if x0 >= x1 {
            return Ok(());
        }
        for y in y.max(0)..end(y, area.size.height, self.height()) {
            if let Some(dst) = self
                .row_mut(y)
                .and_then(|row| row.get_mut(x0 as usize..x1 as usize))
            {
                dst.fill(color);
            }
        }
        Ok(())
    }

    fn clear(&mut self, color: C) -> Result<(), Self::Error> {
        self.fill(color);
        Ok(())
    }
}
