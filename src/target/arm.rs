//! What the `asm` feature's loops on Cortex-M share (src/target/thumb1.rs on ARMv6-M,
//! src/target/thumb2.rs on ARMv7-M and ARMv8-M mainline): a solid colour's two bytes, and the
//! row loops' checks and counts around the assembly.

use core::mem::{align_of, size_of};

use super::depth::FragmentCount;
use crate::pipeline::Stats;
use crate::raster::TriangleSpans;

/// The row loops' width of a row as their assembly reads it, and the triangle's first row in
/// the buffers (which hold frame rows from `first_row`); `None` where the spans are not
/// clipped to the buffers' columns `0..width` (which the assembly clamps them to).
#[inline(always)]
pub(super) fn row_frame(spans: &TriangleSpans, first_row: i32, width: u32) -> Option<(i32, u32)> {
    match i32::try_from(width) {
        Ok(w) if w > 0 && spans.columns() == (0, w) => {
            Some((w, spans.row().wrapping_sub(first_row) as u32))
        }
        _ => None,
    }
}

/// A row loop's counts into `stats`, when `K` counts.
#[inline(always)]
pub(super) fn add_counts<K: FragmentCount>(stats: &mut Stats, fragments: u32, failed: u32) {
    if K::COUNTED {
        stats.fragments = stats.fragments.saturating_add(fragments);
        // Each failed fragment was counted among the fragments: no wrap.
        stats.written = stats.written.saturating_add(fragments.wrapping_sub(failed));
    }
}

/// The two bytes of a colour of 2 bytes and alignment 2, as a word for the loops in assembly;
/// `None` for other colour types (their spans take the caller's loop).
#[inline(always)]
#[allow(unsafe_code)]
pub(super) fn color_bits<C: Copy>(color: &C) -> Option<u32> {
    if size_of::<C>() != 2 || align_of::<C>() != 2 {
        return None;
    }
    let bits: u32;
    // SAFETY: reads the two bytes at `color` (a valid reference to 2 bytes, aligned to 2) into
    // a register; no Rust value is made of them (they could be padding for some `C`), and
    // the block reads nothing else and writes no memory.
    unsafe {
        core::arch::asm!(
            "ldrh {bits}, [{color}]",
            bits = out(reg) bits,
            color = in(reg) color as *const C,
            options(pure, readonly, nostack, preserves_flags)
        );
    }
    Some(bits)
}

/// The cells of `rows` rows of `width` from row `first` in both buffers, or `None` where
/// either buffer does not hold them all (never, for spans clipped to the target).
#[inline(always)]
pub(super) fn run_cells<'b, C>(
    colors: &'b mut [C],
    depths: &'b mut [u16],
    first: u32,
    rows: u32,
    width: usize,
) -> Option<(&'b mut [C], &'b mut [u16])> {
    let start = product(first, width)?;
    let cells = start..start.checked_add(product(rows, width)?)?;
    Some((colors.get_mut(cells.clone())?, depths.get_mut(cells)?))
}

/// `a · b`, or `None` where it overflows: on ARMv6-M for factors below 2¹⁶ (every frame's rows
/// and columns) by one multiply, where `checked_mul` takes a 64-bit product (a library
/// routine there: 2% of the Cortex-M0's frame); a long multiply elsewhere (the M4F's frame
/// 0.4% fewer instructions than the test of the factors).
#[inline(always)]
fn product(a: u32, b: usize) -> Option<usize> {
    if cfg!(fixed3d_thumb1) && a < 1 << 16 && b < 1 << 16 {
        Some((a as usize).wrapping_mul(b))
    } else {
        (a as usize).checked_mul(b)
    }
}
