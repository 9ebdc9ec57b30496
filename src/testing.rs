//! Helpers for the crate's unit tests.

/// Marsaglia's xorshift64 (shifts 13, 7, 17): a fixed, dependency-free stream of test inputs.
pub(crate) struct XorShift(pub(crate) u64);

impl XorShift {
    /// The next state (never 0 for a non-zero seed).
    pub(crate) fn next_u64(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        self.0 = x;
        x
    }

    /// A value in `[−range, range]` (`range ≥ 0`).
    pub(crate) fn within(&mut self, range: i32) -> i32 {
        let x = self.next_u64();
        ((x % (2 * range as u64 + 1)) as i64 - range as i64) as i32
    }

    /// One of `items`, each as likely (`items` not empty).
    pub(crate) fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        let i = self.next_u64() % items.len() as u64;
        items[i as usize]
    }

    /// Three points within `scale` sub-pixels of `centre` on each axis: a random triangle,
    /// perhaps of zero area.
    pub(crate) fn triangle(
        &mut self,
        centre: crate::raster::ScreenPoint,
        scale: i32,
    ) -> [crate::raster::ScreenPoint; 3] {
        [(); 3].map(|_| {
            let (dx, dy) = (self.within(scale), self.within(scale));
            crate::raster::ScreenPoint::new(centre.x + dx, centre.y + dy)
        })
    }
}
