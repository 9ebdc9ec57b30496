//! What the `asm` feature's row loops share (src/target/thumb1.rs on ARMv6-M,
//! src/target/thumb2.rs on ARMv7-M and ARMv8-M mainline, src/target/x86_64.rs on x86-64): the
//! block they read, filled in and checked here, and a solid colour's two bytes. Each core's
//! module holds its assembly and the proof that it keeps to the block's contract
//! ([`RowBlock`]).

use core::mem::{align_of, size_of};
use core::ptr::{addr_of, addr_of_mut};

use super::depth::{DepthTest, FragmentCount, LoopWord, RoundedRows};
#[cfg(fixed3d_thumb1)]
use super::surface::ScreenTriangle;
#[cfg(fixed3d_thumb1)]
use super::thumb1 as core_rows;
#[cfg(fixed3d_thumb2)]
use super::thumb2 as core_rows;
#[cfg(target_arch = "x86_64")]
use super::x86_64 as core_rows;
use crate::pipeline::Stats;
#[cfg(not(fixed3d_thumb2))]
use crate::raster::EdgeWalk;
#[cfg(not(fixed3d_thumb))]
use crate::raster::TriangleRows;
use crate::raster::{columns_bound, Runs};
#[cfg(fixed3d_thumb)]
use crate::raster::{within_columns, ScreenPoint};

/// One edge's size in [`RowBlock`] (on ARMv6-M its value, remainder, denominator and two
/// steps; on x86-64 its walk and step; on ARMv7-M the edges' words are interleaved, see
/// `RunEdges`).
#[cfg(not(fixed3d_thumb2))]
pub(super) const EDGE: usize = size_of::<EdgeWalk>();

/// What a row loop in assembly reads and writes, each field at its `offset_of!` (which the
/// assembly takes as `const` operands): a triangle's runs of rows, its edges first, then its
/// depth walk, the buffers' layout, where the runs end, the colour and the counts. The fields
/// called pairs below are read together by the Cortex-M loops (`ldrd`, `ldm`).
///
/// Contract of the loops (`thumb1::rows`, `thumb2::rows`, `x86_64::rows`), which
/// `solid_rows` (on Cortex-M `solid_triangle`) establishes and checks before it calls them:
/// - `row` is the address of the first of `rows · width` cells of a colour buffer (2 bytes a
///   cell, aligned to 2) and `row + delta` that of the same cells of a u16 depth buffer, both
///   borrowed mutably for the call, with `runs.rows ≥ 1` and `0 < width < 2¹⁶`;
/// - `stride` is `2 · width`, `end` is `row + upper · stride` with `1 ≤ runs.upper ≤
///   runs.rows`, and `last` is `row + rows · stride`;
/// - `slot` is the offset of the edge the lower short edge replaces: 0 (left) or one edge's
///   size (right; on ARMv7-M, whose edges' words interleave, the offset of the right edge's
///   first word, `RunEdges::RIGHT`);
/// - `bits` holds the two bytes of a valid colour of the buffer's type;
/// - called without the clamps (`clamp` false), every row's span ends lie in `0..=width`
///   before any clamp (`within_columns`).
///
/// On x86-64 `row`, `delta`, `bits` and `row_z` come with the block in a `LoopStart`,
/// under the same contract.
#[repr(C)]
pub(super) struct RowBlock {
    /// Left, right and the lower short edge (`runs.edges`), and the rows.
    pub(super) runs: Runs,
    /// The depth walk's step along a row, then the depth buffer's address less the colour
    /// buffer's (read as a pair; x86-64's loop takes the second, as the others read only
    /// once a triangle, in a register: `LoopStart`).
    pub(super) step_x: i32,
    #[cfg(not(target_arch = "x86_64"))]
    pub(super) delta: usize,
    /// The depth walk's step down a column, then the bytes from one row to the next (a pair).
    pub(super) step_y: i32,
    pub(super) stride: usize,
    /// Pixels a row: spans are clamped to `0..width`.
    pub(super) width: i32,
    /// The colour address one past the current run's last row, then past the triangle's
    /// (`last`) and the offset of the edge the lower short edge replaces (`slot`, a pair).
    pub(super) end: usize,
    pub(super) last: usize,
    pub(super) slot: usize,
    /// The colour's two bytes, the depth walk at column 0 of the first row, and the colour
    /// address of the first row (on x86-64 in registers, `LoopStart`).
    #[cfg(not(target_arch = "x86_64"))]
    pub(super) bits: u32,
    #[cfg(not(target_arch = "x86_64"))]
    pub(super) row_z: i32,
    #[cfg(not(target_arch = "x86_64"))]
    pub(super) row: usize,
    /// Fragments tested and fragments that failed, when counted (a pair).
    pub(super) fragments: u32,
    pub(super) failed: u32,
}

/// What x86-64's loop reads once a triangle, in registers rather than through its
/// [`RowBlock`] (the block's fields of the same names on the Cortex-M cores, with the same
/// contract): the colour address of the first row, the depth buffer's address less the
/// colour buffer's, the colour's two bytes and the depth walk at column 0 of the first row.
/// Each was a store and a load a triangle through the block (the reference frame 0.6% more
/// instructions).
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy)]
pub(super) struct LoopStart {
    pub(super) row: usize,
    pub(super) delta: usize,
    pub(super) bits: u32,
    pub(super) row_z: i32,
}

// The pairs the Cortex-M loops load with one instruction lie one word apart.
#[cfg(fixed3d_thumb)]
const _: () = {
    use core::mem::offset_of;
    assert!(offset_of!(RowBlock, delta) == offset_of!(RowBlock, step_x) + 4);
    assert!(offset_of!(RowBlock, stride) == offset_of!(RowBlock, step_y) + 4);
    assert!(offset_of!(RowBlock, slot) == offset_of!(RowBlock, last) + 4);
    assert!(offset_of!(RowBlock, failed) == offset_of!(RowBlock, fragments) + 4);
};

/// In `triangle_runs` (both Cortex-M cores'), the corners' keys `4·y + i` loaded from the
/// points at `$p` (two words each, x then y) into `$ka`, `$kb` and `$kc` (register names, or
/// operands as `"{ka}"`) and sorted by three compare-and-swaps in `sort_by_y`'s order, each
/// by the core's own `$swap` (which turns the long edge's side with the keys): the loads in
/// flag-setting forms, which Thumb-1 has and Thumb-2 takes too (the flags are set again by
/// the first comparison).
#[cfg(fixed3d_thumb)]
#[rustfmt::skip]
macro_rules! sorted_keys {
    ($swap:ident, $p:literal, $ka:literal, $kb:literal, $kc:literal) => {
        concat!(
            "ldr ", $ka, ", [", $p, ", #4]\n",
            "ldr ", $kb, ", [", $p, ", #12]\n",
            "ldr ", $kc, ", [", $p, ", #20]\n",
            "lsls ", $ka, ", ", $ka, ", #2\n",
            "lsls ", $kb, ", ", $kb, ", #2\n",
            "adds ", $kb, ", ", $kb, ", #1\n",
            "lsls ", $kc, ", ", $kc, ", #2\n",
            "adds ", $kc, ", ", $kc, ", #2\n",
            $swap!($ka, $kb),
            $swap!($kb, $kc),
            $swap!($ka, $kb),
        )
    };
}
#[cfg(fixed3d_thumb)]
pub(super) use sorted_keys;

/// In `triangle_runs`, the first row at or below the point of key `$k` into `$row`:
/// `(y + 7) >> 4` of its `y = k >> 2` (`first_centre_from32`), in flag-setting forms (see
/// [`sorted_keys`]).
#[cfg(fixed3d_thumb)]
#[rustfmt::skip]
macro_rules! first_row {
    ($row:literal, $k:literal) => {
        concat!(
            "asrs ", $row, ", ", $k, ", #2\n",
            "adds ", $row, ", ", $row, ", #7\n",
            "asrs ", $row, ", ", $row, ", #4\n",
        )
    };
}
#[cfg(fixed3d_thumb)]
pub(super) use first_row;

/// Fills the rows `triangle` of a triangle whose every pixel has the colour whose two bytes
/// [`color_bits`] gave as `bits`, clipped to the columns `0..width` (those of a
/// [`ColorDepth`](super::ColorDepth)'s clip rectangle, always its buffers': not compared here,
/// x86-64's frame 0.6% fewer instructions, the Cortex-M4's 0.2%, the M0's 0.17%), into u16
/// depth and colour buffers of `width` pixels a row holding frame rows from `first_row`, its
/// depths from the walk `depth` (every value in [0, 2³¹), see `DepthFormat::unclamped`): what
/// the span loop over
/// [`for_each_row`](crate::raster::TriangleSpans::for_each_row) does, the counts into `stats`
/// when `K` counts, with the whole row loop in assembly. False, with nothing drawn, where
/// `width` is 0 or from 2¹⁶ on, or the edges would be set up again on the way down (none
/// happens to the pipeline's triangles in a [`ColorDepth`](super::ColorDepth) of fewer than
/// 2¹⁶ columns); nothing is drawn where the
/// buffers do not hold the triangle's rows (never, for rows clipped to the target).
#[inline(always)]
#[allow(unsafe_code, clippy::too_many_arguments)]
#[cfg(not(fixed3d_thumb))]
pub(super) fn solid_rows<C: Copy, T: DepthTest, K: FragmentCount, W: LoopWord>(
    triangle: &TriangleRows,
    depth: &RoundedRows<W>,
    colors: &mut [C],
    depths: &mut [u16],
    first_row: i32,
    width: u32,
    bits: u32,
    stats: &mut Stats,
) -> bool {
    let Some(w) = block_width(width) else {
        return false;
    };
    let Some(runs) = triangle.runs() else {
        return false;
    };
    // A loop without the clamps for a triangle within the columns (x86-64's windows).
    let clamp = !(core_rows::WITHOUT_CLAMPS && triangle.within_columns(columns_bound(w)));
    // The triangle's first row in the buffers.
    let first = triangle.row().wrapping_sub(first_row) as u32;
    let mut block = RowBlock {
        runs,
        step_x: depth.step_x.to_i32(),
        step_y: depth.step_y.to_i32(),
        stride: 0,
        width: w,
        end: 0,
        last: 0,
        slot: if runs.lower_is_left { 0 } else { EDGE },
        fragments: 0,
        failed: 0,
    };
    let start = (bits, depth.row.to_i32());
    // SAFETY: `block` is a local, every field initialised above.
    unsafe {
        run_block::<C, T, K>(
            &mut block, clamp, colors, depths, first, width, start, stats,
        )
    };
    true
}

/// `solid_rows` of the triangle `p` (a [screen triangle](super::ScreenTriangle)'s points,
/// `area` its doubled signed area) in the rows `y0..y1`, the buffers' first: its runs set up
/// by `triangle_runs` in assembly, its depth walk by `depth` from its first row (on
/// Cortex-M0 by `thumb1::walk_into` of `triangle` first, which writes a small triangle's walk
/// into the block itself). False, with nothing drawn, where `solid_rows` declines the
/// triangle or `depth` gives no walk; true where it covers none of the rows.
#[cfg(fixed3d_thumb)]
#[inline(always)]
#[allow(unsafe_code, clippy::too_many_arguments)]
pub(super) fn solid_triangle<C: Copy, T: DepthTest, K: FragmentCount, W: LoopWord>(
    #[cfg(fixed3d_thumb1)] triangle: &ScreenTriangle,
    p: &[ScreenPoint; 3],
    area: i64,
    (y0, y1): (i32, i32),
    depth: impl FnOnce(i32) -> Option<(RoundedRows<W>, i32)>,
    colors: &mut [C],
    depths: &mut [u16],
    width: u32,
    bits: u32,
    stats: &mut Stats,
) -> bool {
    let Some(w) = block_width(width) else {
        return false;
    };
    // The block is not cleared first: its runs come from `triangle_runs`, each other field
    // is written once (clearing it took the reference frame 1.2% more instructions).
    let mut slot = core::mem::MaybeUninit::<RowBlock>::uninit();
    let block = slot.as_mut_ptr();
    // SAFETY: `block` is valid for writes of a `RowBlock` (a local's), unshared; the fields
    // are written in place, and read only once written: `runs.rows` by `triangle_runs`
    // always, the rest of the runs and `slot` by it whenever rows are left (its contract).
    let (y, rows) = unsafe {
        let y = core_rows::triangle_runs(p, area, (y0, y1), block);
        (y, addr_of!((*block).runs.rows).read())
    };
    if rows == 0 {
        return true;
    }
    // SAFETY: `block` as above (`walk_into` writes three of its fields, or none).
    #[cfg(fixed3d_thumb1)]
    let written = unsafe { core_rows::walk_into(triangle, y, block) };
    #[cfg(not(fixed3d_thumb1))]
    let written = false;
    if !written {
        let Some((walk, _)) = depth(y) else {
            return false;
        };
        // SAFETY: `block` as above.
        unsafe { write_walk(block, &walk) };
    }
    // This core has a loop without the clamps: spans that cannot cross the columns take it
    // (the reference frame's triangles all do: 4 instructions a row fewer, the frame 1.05%
    // fewer instructions, for about 200 bytes of flash).
    let clamp = !(core_rows::WITHOUT_CLAMPS && within_columns(p, columns_bound(w)));
    let first = y.wrapping_sub(y0) as u32;
    // SAFETY: as above; with these, the walk's and the runs (all of them written, rows being
    // left) every field but the seven `run_block` writes holds a valid value, as it requires.
    unsafe {
        addr_of_mut!((*block).width).write(w);
        addr_of_mut!((*block).bits).write(bits);
        run_block::<C, T, K>(block, clamp, colors, depths, first, width, stats);
    }
    true
}

/// Writes `walk` into the row loop's block at `block` (its `step_x`, `step_y` and `row_z`).
///
/// # Safety
/// `block` is valid for writes of a `RowBlock` (its memory need not hold one), unshared.
#[cfg(fixed3d_thumb)]
#[inline(always)]
#[allow(unsafe_code)]
pub(super) unsafe fn write_walk<W: LoopWord>(block: *mut RowBlock, walk: &RoundedRows<W>) {
    // SAFETY: writes of three fields in place, as the caller's contract allows.
    unsafe {
        addr_of_mut!((*block).step_x).write(walk.step_x.to_i32());
        addr_of_mut!((*block).step_y).write(walk.step_y.to_i32());
        addr_of_mut!((*block).row_z).write(walk.row.to_i32());
    }
}

/// The block's width for buffers of `width` columns: rows of fewer than 2¹⁶ pixels (every
/// display's), and at least one.
#[inline(always)]
fn block_width(width: u32) -> Option<i32> {
    match u16::try_from(width) {
        Ok(w) if w > 0 => Some(i32::from(w)),
        _ => None,
    }
}

/// The row loop of a triangle's block, filled in but for the buffers' addresses and the
/// counts, on the rows from `first` of buffers of `width` columns: what `solid_rows` does
/// once it has the runs. Nothing is drawn where the buffers do not hold the rows.
///
/// # Safety
/// `block` is valid for reads and writes of a `RowBlock` and borrowed by nothing else for
/// the call, and every field of it but `row`, `stride`, `end`, `last`, `delta`, `fragments`
/// and `failed` holds a valid value (on Cortex-M the caller writes the others into
/// memory never cleared: only those are read before this writes the rest).
#[inline(always)]
#[allow(unsafe_code)]
#[allow(clippy::too_many_arguments)]
unsafe fn run_block<C: Copy, T: DepthTest, K: FragmentCount>(
    block: *mut RowBlock,
    clamp: bool,
    colors: &mut [C],
    depths: &mut [u16],
    first: u32,
    width: u32,
    #[cfg(target_arch = "x86_64")] (bits, row_z): (u32, i32),
    stats: &mut Stats,
) {
    // SAFETY: fields the caller initialised, read in place through `block` (valid, unshared).
    let (upper, rows) = unsafe {
        (
            addr_of!((*block).runs.upper).read(),
            addr_of!((*block).runs.rows).read(),
        )
    };
    // The rows' cells in both buffers, and the rest of the contract, checked here (constants,
    // or known to the caller: compiled away).
    let width = width as usize;
    let Some((colors, depths, windows)) = run_cells::<C, K>(colors, depths, first, rows, width)
    else {
        return;
    };
    if !(1..=rows).contains(&upper) || size_of::<C>() != 2 || align_of::<C>() != 2 {
        return;
    }
    let row = colors.as_mut_ptr();
    // Below the buffer's length in bytes, so no overflow; the last one past the rows' last
    // cell (within `colors`, or one past its end: no pointer leaves its allocation).
    let end = row.wrapping_add((upper as usize).wrapping_mul(width)) as usize;
    let last = row.wrapping_add(colors.len().wrapping_sub(spare(windows))) as usize;
    let delta = (depths.as_mut_ptr() as usize).wrapping_sub(row as usize);
    // SAFETY: writes of the seven fields the caller left (`block` valid for writes, unshared;
    // on x86-64 five, the others its loop's registers); with them every field holds a valid
    // value, so the block may be borrowed as a whole.
    let block = unsafe {
        #[cfg(not(target_arch = "x86_64"))]
        addr_of_mut!((*block).row).write(row as usize);
        addr_of_mut!((*block).stride).write(width.wrapping_mul(2));
        addr_of_mut!((*block).end).write(end);
        addr_of_mut!((*block).last).write(last);
        #[cfg(not(target_arch = "x86_64"))]
        addr_of_mut!((*block).delta).write(delta);
        addr_of_mut!((*block).fragments).write(0);
        addr_of_mut!((*block).failed).write(0);
        &mut *block
    };
    // SAFETY: the block keeps `RowBlock`'s contract. `colors` and `depths` are rows · width
    // cells long (`run_cells`), 7 more with `windows` (x86-64's loop then takes those too),
    // borrowed mutably here until the call returns; `C` has 2 bytes
    // and alignment 2 (checked); `rows ≥ upper ≥ 1` and `width > 0` (checked); `row`,
    // `delta`, `stride`, `end` and `last` are set from them just above; `slot` is 0 or an
    // edge's size (on Cortex-M from `triangle_runs`, on Cortex-M3/M4 0 or `RunEdges::RIGHT`);
    // `bits` came from `color_bits` of a valid `C` (the caller's); without the clamps,
    // `within_columns` holds for `width` and the triangle whose rows the edges in `runs` walk
    // (set up by `TriangleRows::runs`, on Cortex-M0 by `thumb1::triangle_runs`, which
    // computes the same walks, or on Cortex-M3/M4 by `thumb2::triangle_runs`, which computes
    // them with no base, the numerator signed: see its documentation).
    // (x86-64's loop also takes whether it may take windows of eight cells, and the fields
    // it reads once in registers.)
    #[cfg(target_arch = "x86_64")]
    let clamp = (
        clamp,
        windows,
        LoopStart {
            row: row as usize,
            delta,
            bits,
            row_z,
        },
    );
    unsafe { core_rows::rows::<T, K>(block, clamp) };
    if K::COUNTED {
        stats.fragments = stats.fragments.saturating_add(block.fragments);
        // Each failed fragment was counted among the fragments: no wrap.
        stats.written = stats
            .written
            .saturating_add(block.fragments.wrapping_sub(block.failed));
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
            #[cfg(fixed3d_thumb)]
            "ldrh {bits}, [{color}]",
            #[cfg(target_arch = "x86_64")]
            "movzx {bits:e}, word ptr [{color}]",
            bits = out(reg) bits,
            color = in(reg) color as *const C,
            options(pure, readonly, nostack, preserves_flags)
        );
    }
    Some(bits)
}

/// The cells of `rows` rows of `width` from row `first` in both buffers, or `None` where
/// either buffer does not hold them all (never, for spans clipped to the target); on x86-64
/// with the [`WINDOW_SPARE`] cells after them where both buffers hold those too (and,
/// counted, the rows hold at most 2¹⁵ windows), and then true (the loop's windows of eight
/// cells, `x86_64::rows`).
#[inline(always)]
fn run_cells<'b, C, K: FragmentCount>(
    colors: &'b mut [C],
    depths: &'b mut [u16],
    first: u32,
    rows: u32,
    width: usize,
) -> Option<(&'b mut [C], &'b mut [u16], bool)> {
    let (start, end) = rows_cells(first, rows, width)?;
    // Counted, each lane's count of wins stays within a word: at most 2¹⁵ windows, a row
    // holding at most width / 8 + 1.
    let windows = cfg!(target_arch = "x86_64")
        && (!K::COUNTED || (rows as usize).saturating_mul(width / 8 + 1) <= 1 << 15)
        && end
            .checked_add(WINDOW_SPARE)
            .is_some_and(|e| e <= colors.len());
    let cells = start..end.wrapping_add(spare(windows));
    Some((
        colors.get_mut(cells.clone())?,
        depths.get_mut(cells)?,
        windows,
    ))
}

/// The first cell of `rows` rows of `width` from row `first`, and the cell past their last;
/// `None` where that overflows.
#[cfg(not(target_pointer_width = "64"))]
#[inline(always)]
fn rows_cells(first: u32, rows: u32, width: usize) -> Option<(usize, usize)> {
    // The end first: `first · width` is no larger, so it cannot overflow where the end does
    // not (one product checked rather than two and their sum: the M4's frame 0.35% fewer
    // instructions, the M0's 0.1%).
    let end = product(first.checked_add(rows)?, width)?;
    Some(((first as usize).wrapping_mul(width), end))
}

/// `rows_cells` in 64-bit words, for `width` below 2¹⁶ (as `block_width` makes it; `None`
/// otherwise): the ends, below 2³³ · 2¹⁶, cannot overflow, so that no step needs a check
/// (x86-64's frame 0.5% fewer instructions; comparing the cells after the rows with the
/// shorter buffer's length once, rather than each buffer's, measured 0.5% more).
#[cfg(target_pointer_width = "64")]
#[inline(always)]
fn rows_cells(first: u32, rows: u32, width: usize) -> Option<(usize, usize)> {
    // (Known to the callers, after `block_width`: compiled away.)
    if width >= 1 << 16 {
        return None;
    }
    let end = (first as usize)
        .wrapping_add(rows as usize)
        .wrapping_mul(width);
    Some(((first as usize).wrapping_mul(width), end))
}

/// The cells x86-64's loop in windows reads and writes back unchanged after the rows' last
/// (its last window of eight cells may start at the last row's last cell).
const WINDOW_SPARE: usize = 7;

/// The cells after the rows that the loop takes: [`WINDOW_SPARE`] with `windows`, else none.
#[inline(always)]
fn spare(windows: bool) -> usize {
    if windows {
        WINDOW_SPARE
    } else {
        0
    }
}

/// `a · b`, or `None` where it overflows: on ARMv6-M for factors below 2¹⁶ (every frame's rows
/// and columns) by one multiply, where `checked_mul` takes a 64-bit product (a library
/// routine there: 2% of the Cortex-M0's frame); a long multiply elsewhere (the M4F's frame
/// 0.4% fewer instructions than the test of the factors).
#[cfg(not(target_pointer_width = "64"))]
#[inline(always)]
fn product(a: u32, b: usize) -> Option<usize> {
    if cfg!(fixed3d_thumb1) && a < 1 << 16 && b < 1 << 16 {
        Some((a as usize).wrapping_mul(b))
    } else {
        (a as usize).checked_mul(b)
    }
}

/// The loops' Rust side on the host (x86-64 with the `asm` feature; the Cortex-M cores run it
/// under emulation, bench/mcu/run.sh): what it refuses and what it draws.
#[cfg(test)]
mod tests {
    use std::{vec, vec::Vec};

    use embedded_graphics::pixelcolor::{Rgb565, RgbColor};

    use super::*;
    use crate::raster::{doubled_area, rows_in_range, triangle_spans, PixelRect, ScreenPoint};
    use crate::target::{Counted, Less, LessOrEqual, Uncounted};

    const W: usize = 24;
    const H: usize = 16;
    const FAR: u16 = 0xC000;

    /// The test's triangles: the first crosses the buffers' left and right columns with its
    /// middle vertex on the right; the second is its mirror image (the lower short edge then
    /// replaces the left edge); the third a needle less than a pixel wide (rows whose span is
    /// empty, x0 = x1, and rows of one pixel).
    #[derive(Clone, Copy, Debug)]
    enum Shape {
        Wide,
        Mirrored,
        Needle,
    }

    const SHAPES: [Shape; 3] = [Shape::Wide, Shape::Mirrored, Shape::Needle];

    /// The vertices of a triangle of `shape` in sub-pixels (16 to a pixel).
    fn vertices(shape: Shape) -> [ScreenPoint; 3] {
        let p = |x: i32, y: i32| {
            let x = if matches!(shape, Shape::Mirrored) {
                W as i32 - x
            } else {
                x
            };
            ScreenPoint::new(x * 16 + 3, y * 16 + 5)
        };
        match shape {
            Shape::Needle => [p(7, -2), ScreenPoint::new(7 * 16 + 15, 20 * 16), p(7, 20)],
            _ => [p(-4, -2), p(30, 6), p(5, 20)],
        }
    }

    /// A depth walk that crosses the far depth inside the triangle, so that both tests pass
    /// and fail, and ties occur.
    fn walk() -> RoundedRows<i32> {
        RoundedRows {
            row: 0x5F80_0000,
            step_x: 0x0008_0000,
            step_y: 0x0004_0000,
        }
    }

    /// What the loops draw, by definition: each row's span clamped to the buffers' columns
    /// (the spans' own clip), the depth `(row + step_x·x) >> 15`, `T`'s test against the
    /// stored depth; the fragments and writes counted.
    fn expected<T: DepthTest>(
        first_row: i32,
        (v, w): ([ScreenPoint; 3], &RoundedRows<i32>),
        colors: &mut [Rgb565],
        depths: &mut [u16],
    ) -> Stats {
        let mut stats = Stats::default();
        let clip = PixelRect::new(0, first_row, W as i32, first_row + H as i32);
        let spans = triangle_spans(v, clip);
        let y0 = spans.row();
        for s in spans {
            let row = w.row.wrapping_add(w.step_y.wrapping_mul(s.y - y0));
            for x in s.x0..s.x1 {
                let z = (row.wrapping_add(w.step_x.wrapping_mul(x)) as u32 >> 15) as u16;
                let cell = (s.y - first_row) as usize * W + x as usize;
                stats.fragments += 1;
                if z < depths[cell] || (T::OR_EQUAL && z == depths[cell]) {
                    depths[cell] = z;
                    colors[cell] = Rgb565::RED;
                    stats.written += 1;
                }
            }
        }
        stats
    }

    /// Buffers of `H` rows, and `extra` cells more.
    fn buffers_and(extra: usize) -> (Vec<Rgb565>, Vec<u16>) {
        (vec![Rgb565::BLUE; W * H + extra], vec![FAR; W * H + extra])
    }

    fn buffers() -> (Vec<Rgb565>, Vec<u16>) {
        buffers_and(0)
    }

    /// `solid_rows` of the triangle `v` clipped to `clip` in red, the depths of `w`, into
    /// buffers of `W` columns holding rows from `first_row`: whether it drew.
    fn draw<T: DepthTest, K: FragmentCount>(
        (v, w): ([ScreenPoint; 3], &RoundedRows<i32>),
        clip: PixelRect,
        first_row: i32,
        (colors, depths): &mut (Vec<Rgb565>, Vec<u16>),
        stats: &mut Stats,
    ) -> bool {
        let Some(rows) = rows_in_range(v, clip, doubled_area(v[0], v[1], v[2])) else {
            return true;
        };
        let bits = color_bits(&Rgb565::RED).unwrap_or_default();
        solid_rows::<Rgb565, T, K, i32>(&rows, w, colors, depths, first_row, W as u32, bits, stats)
    }

    /// `draw` and the definition from the same `cells`, compared (colours, depths, counts).
    fn check<T: DepthTest, K: FragmentCount>(
        first_row: i32,
        triangle: ([ScreenPoint; 3], &RoundedRows<i32>),
        cells: &(Vec<Rgb565>, Vec<u16>),
    ) -> Stats {
        let mut drawn = cells.clone();
        let (mut want_c, mut want_d) = cells.clone();
        let want = expected::<T>(first_row, triangle, &mut want_c, &mut want_d);
        let clip = PixelRect::new(0, first_row, W as i32, first_row + H as i32);
        let mut stats = Stats::default();
        assert!(draw::<T, K>(
            triangle, clip, first_row, &mut drawn, &mut stats
        ));
        assert_eq!(drawn, (want_c, want_d), "{first_row}, {triangle:?}");
        if K::COUNTED {
            assert_eq!(
                (stats.fragments, stats.written),
                (want.fragments, want.written)
            );
        } else {
            assert_eq!(stats, Stats::default());
        }
        want
    }

    /// The loop draws what the definition draws, for both tests, counted or not, in a band
    /// whose first row is not 0, with spans clamped on both sides and empty ones; on x86-64
    /// in windows of eight cells where the buffers hold 7 cells after the rows (`extra`), a
    /// pixel at a time where they do not.
    #[test]
    fn r7_t21_solid_rows_draw_the_definition() {
        // Fragments pass and fail, and ties occur: the tests draw differently.
        let (mut c, mut d) = buffers();
        let wide = (vertices(Shape::Wide), &walk());
        let (less, or_equal) = (
            expected::<Less>(0, wide, &mut c.clone(), &mut d.clone()),
            expected::<LessOrEqual>(0, wide, &mut c, &mut d),
        );
        assert!(less.written < or_equal.written && or_equal.written < or_equal.fragments);
        for (first_row, shape) in [-2, 0, 3].into_iter().flat_map(|y| SHAPES.map(|s| (y, s))) {
            for extra in [0, 6, 7, W] {
                let (triangle, cells) = ((vertices(shape), &walk()), buffers_and(extra));
                assert!(check::<Less, Counted>(first_row, triangle, &cells).written > 0);
                check::<LessOrEqual, Counted>(first_row, triangle, &cells);
                check::<Less, Uncounted>(first_row, triangle, &cells);
                check::<LessOrEqual, Uncounted>(first_row, triangle, &cells);
            }
        }
    }

    /// Random triangles over random stored depths near their own (wins, losses and ties in
    /// every window), spans of every length from one cell to the buffers' width, each in
    /// windows of eight cells and a pixel at a time: what the definition draws.
    #[test]
    fn r7_t21_windows_draw_the_definition() {
        let mut seed = 0x9E37_79B9_7F4A_7C15_u64;
        let mut next = |n: u32| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 32) as u32 % n
        };
        let mut lengths = [false; W + 1];
        for _ in 0..400 {
            let mut point = || {
                let x = next(16 * (W as u32 + 8)) as i32 - 16 * 4;
                ScreenPoint::new(x, next(16 * (H as u32 + 4)) as i32 - 32)
            };
            let v = [point(), point(), point()];
            let w = RoundedRows {
                row: (1 << 29) + next(1 << 29) as i32,
                step_x: next(1 << 21) as i32 - (1 << 20),
                step_y: next(1 << 21) as i32 - (1 << 20),
            };
            // Stored depths within 32 of the walk's at the top left, some of them equal.
            let near = ((w.row as u32 >> 15) as u16).wrapping_sub(16);
            let (colors, mut depths) = buffers_and(7 + next(2) as usize);
            for d in depths.iter_mut() {
                *d = near.wrapping_add(next(32) as u16);
            }
            let cells = (colors, depths);
            let clip = PixelRect::new(0, 0, W as i32, H as i32);
            for s in triangle_spans(v, clip) {
                lengths[(s.x1 - s.x0) as usize] = true;
            }
            check::<Less, Uncounted>(0, (v, &w), &cells);
            check::<LessOrEqual, Uncounted>(0, (v, &w), &cells);
            check::<Less, Counted>(0, (v, &w), &cells);
            check::<LessOrEqual, Counted>(0, (v, &w), &cells);
        }
        assert!(lengths[1..].iter().all(|&seen| seen), "{lengths:?}");
    }

    /// A counted triangle of more than 2¹⁵ windows of eight cells (a lane of x86-64's count of
    /// wins would leave its word) takes the pixel loop, and counts every fragment it writes.
    #[test]
    fn r7_t21_counts_of_many_windows() {
        // Full rows of 32 windows each: 64,000 a lane.
        const WIDE: usize = 256;
        const ROWS: usize = 2000;
        let cells = WIDE * ROWS + 7;
        let (mut colors, mut depths) = (vec![Rgb565::BLUE; cells], vec![FAR; cells]);
        let v = [
            ScreenPoint::new(-16, -16),
            ScreenPoint::new(16 * WIDE as i32 * 3, -16),
            ScreenPoint::new(-16, 16 * 2 * ROWS as i32),
        ];
        let clip = PixelRect::new(0, 0, WIDE as i32, ROWS as i32);
        let rows = rows_in_range(v, clip, doubled_area(v[0], v[1], v[2]));
        let near = RoundedRows {
            row: 1 << 20,
            step_x: 0,
            step_y: 0,
        };
        let mut stats = Stats::default();
        let bits = color_bits(&Rgb565::RED).unwrap_or_default();
        let drew = rows.as_ref().is_some_and(|rows| {
            solid_rows::<Rgb565, Less, Counted, i32>(
                rows,
                &near,
                &mut colors,
                &mut depths,
                0,
                WIDE as u32,
                bits,
                &mut stats,
            )
        });
        let written = colors.iter().filter(|&&c| c == Rgb565::RED).count() as u32;
        assert!(drew && written == (WIDE * ROWS) as u32, "{drew} {written}");
        assert_eq!((stats.fragments, stats.written), (written, written));
    }

    /// Rows the buffers do not hold draw nothing.
    #[test]
    fn r6_solid_rows_refuse_what_they_cannot_draw() {
        let mut stats = Stats::default();
        let mut cells = buffers();
        let untouched = cells.clone();
        // The rows reach past the buffers' last row (the clip holds more rows): nothing drawn.
        let tall = PixelRect::new(0, 0, W as i32, 2 * H as i32);
        assert!(draw::<Less, Counted>(
            (vertices(Shape::Wide), &walk()),
            tall,
            0,
            &mut cells,
            &mut stats
        ));
        assert_eq!((&cells, stats), (&untouched, Stats::default()));
        // Rows of 2¹⁶ pixels or more (and of none) take the caller's loop: declined.
        let v = vertices(Shape::Wide);
        let full = PixelRect::new(0, 0, W as i32, H as i32);
        let rows = rows_in_range(v, full, doubled_area(v[0], v[1], v[2]));
        let bits = color_bits(&Rgb565::RED).unwrap_or_default();
        for width in [0, 1 << 16] {
            let (colors, depths) = &mut cells;
            let drew = rows.as_ref().is_some_and(|rows| {
                solid_rows::<Rgb565, Less, Counted, i32>(
                    rows,
                    &walk(),
                    colors,
                    depths,
                    0,
                    width,
                    bits,
                    &mut stats,
                )
            });
            assert!(!drew && rows.is_some(), "{width}");
        }
        assert_eq!((cells, stats), (untouched, Stats::default()));
        // Colours of another size take the caller's loop.
        assert_eq!(color_bits(&[0u8; 3]), None);
        assert_eq!(color_bits(&0u32), None);
    }
}
