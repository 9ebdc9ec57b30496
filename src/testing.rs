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
}
