//! The u16 depth loops of solid-coloured triangles in hand-written Thumb-1, for Cortex-M0 and
//! M0+ (ARMv6-M), with the `asm` feature (with thumb2.rs, x86_64.rs and asm_rows.rs the only
//! `unsafe` code of the crate; without the feature the crate forbids it), and what sets them
//! up: each triangle's rows and small triangles' depth walks, the triangle walk's skip of
//! back faces and the vertex loop of an object inside every clip plane.
//!
//! A whole triangle's rows, both runs (above and below its middle vertex), in one naked
//! function: inline assembly on ARMv6-M gets six registers, and the pixel loop alone needs
//! eight, so the function saves and uses the high registers r8 to r11 and lr as the calling
//! convention lets it: the step along a row in r8, which the pixel loop adds; the colour in r9,
//! moved into r6 for each span while the block's address waits in lr; the depth walk, the row's
//! address and the width in r10 to r12. The edges and the triangle's constants live in one
//! block in memory ([`RowBlock`]), the edges as the exact quotient-and-remainder walk
//! (`CeilStepper`) the compiled loop steps, each edge's five words loaded by one `ldm`. A row
//! takes 25 instructions (2 more for each edge whose remainder borrows; both span ends tested
//! against the columns by two unsigned comparisons, a span that crosses a side clamped out of
//! line) and 10 more to enter a span, where the compiled row loop took about 60; a pixel 9
//! instructions (7 when the fragment loses), where the compiler's loop took 10. The reference
//! frame on the Cortex-M0 5.1% fewer instructions (3.536 M → 3.357 M), 510 bytes more flash.
//!
//! It computes exactly what the Rust loops compute: the same span ends (the same steps of the
//! same quotients and remainders, clamped to the same columns), the same depths (`acc >> 15`,
//! below 2¹⁶ since every value lies in [0, 2³¹)), the same test on the same stored depth, the
//! same stores and counts. The firmware presets' frame hashes, equal to the host's, check it
//! under emulation (`bench/mcu/run.sh`, in CI): the `variants` preset each of the four forms
//! (depth test × counted), on ties too, and spans clamped to the target's columns (its
//! `clipped` configuration).
//!
//! The set-up of those rows ([`triangle_runs`], a naked function with an edge routine of its
//! own): the sort of the corners, the rows and the three edges written into the same block,
//! with the place the lower edge takes (`slot`), as `thumb2::triangle_runs` does on the M3/M4
//! but with the M0's exact walks: each edge's quotient and remainder by subtraction (a few
//! turns for the usual edge, a long division past sixteen). About 257 instructions a
//! triangle (an edge 32 and two divisions of about 13 each), about 87 fewer than the
//! compiled `rows_in_range` and `TriangleRows::runs` with their edges' calls and the runs'
//! copy into the block (written in place here): the reference frame on the Cortex-M0 3.65%
//! fewer instructions (2.278 M → 2.195 M), 304 bytes more flash; 244 since the divisions
//! are in line and an edge keeps the sample line for the next (0.55% fewer). Its
//! output is checked under emulation by every preset's hash: the `bands` preset and the
//! `variants` preset's `clipped` and `triangles` take its edges set up below their first row
//! (started by a band's or the clip's first row), its long division and both signs of each
//! numerator and step.
//!
//! The vertex loop of an object known inside every clip plane with its projection in words
//! (`Known::InWords`, the reference torus) and no lit colour ([`project_split_in_words`], a
//! naked function): `SplitTransform`'s rows (each coordinate split at bit k, the high parts'
//! sums pushed, the low parts' rounded onto them) and `ShortQuotients`' divisions by w (the
//! top bit's index, the 16-bit reciprocal, the rounded digits of x and y, the depth's two),
//! each row read by one `ldm` from a block of the object's constants, where the compiled loop
//! reloads them from the stack: about 260 instructions a vertex where it took about 330,
//! the reference frame on the Cortex-M0 3.6% fewer instructions (2.195 M → 2.115 M), about
//! 870 bytes more flash (256 since the seed tables' addresses come from the literal pool and
//! a half size is kept for its quotient: 0.33%). Checked under emulation by the `variants`
//! preset's `vertices` (every vertex's position and depth, which the frames' colours show
//! only in part) and every preset's frames.
//!
//! A small triangle's depth walk ([`depth_walk`], a naked function writing into the row
//! loop's block itself): `RoundedRows::new` as the compiled code takes it on this core, its
//! numerators' four products of a depth difference and a short side from 16-bit halves,
//! its steps by `ShortQuotients`' two 15-bit digits from the area's 16-bit reciprocal, then
//! the row's start; a triangle whose doubled area reaches 2²⁹, with a long side or a step
//! beyond 2³⁰ left to the compiled set-up, the same walks. About 320 instructions a
//! triangle where the compiled set-up took about 410 and its call: the reference frame on
//! the Cortex-M0 3.75% fewer instructions (2.115 M → 2.036 M), about 1 KB more flash; with
//! the trims after it (the shift of `ShortQuotients::top` taken by one branch, the division
//! of the row set-up in line, the walk written into the block, and the others above) 1.993 M,
//! within issue #7's goal of 2.0 M. Checked under emulation by the `variants` preset's
//! `walks` (the walks of random triangles, every word, which the frames show only in part:
//! a walk one unit off changes few depths).
//!
//! The triangle walk's skip of back faces (`FrontFaces::next_stop`, on the walk's state in
//! asm_faces.rs): for an object inside every clip plane culled to its front faces, each
//! triangle's indices, points and signed area in one loop of assembly that stops only on a
//! triangle to draw (its corners copied for the call that fills it) or one of zero area. The
//! same classification as the Rust walk's (the same area, the same sign and zero tests),
//! checked under emulation by the `variants` preset's `front` (random triangles of both
//! windings and of zero area, every count in its hash): 29 instructions a back face where the
//! compiled walk took about 65, the reference frame on the Cortex-M0 2.8% fewer instructions
//! (2.352 M → 2.287 M), 450 bytes more flash.

use core::mem::{offset_of, size_of};
use core::ptr::addr_of;

use super::asm_faces::FrontFaces;
use super::asm_rows::{first_row, sorted_keys, RowBlock, EDGE};
use super::depth::{DepthTest, FragmentCount, RoundedRows, LOOP_HALF_STEP};
use super::surface::ScreenTriangle;
use crate::math::{SplitTransform, Vec3, BYTE_ZEROS, RECIPROCALS};
use crate::pipeline::{FaceStop, ScreenVertex};
use crate::raster::{Runs, ScreenPoint};

/// A naked function's entry here: r4 to r11 and the return address saved (r8 to r11 through
/// r4 to r7), as the calling convention requires of what it uses.
#[rustfmt::skip]
macro_rules! save_registers {
    () => {
        concat!(
            "push {{r4, r5, r6, r7, lr}}\n",
            "mov r4, r8\n",
            "mov r5, r9\n",
            "mov r6, r10\n",
            "mov r7, r11\n",
            "push {{r4, r5, r6, r7}}\n",
        )
    };
}

/// A naked function's return after [`save_registers`]: r4 to r11 restored, the return
/// address popped into pc.
#[rustfmt::skip]
macro_rules! restore_registers_and_return {
    () => {
        concat!(
            "pop {{r4, r5, r6, r7}}\n",
            "mov r8, r4\n",
            "mov r9, r5\n",
            "mov r10, r6\n",
            "mov r11, r7\n",
            "pop {{r4, r5, r6, r7, pc}}\n",
        )
    };
}

/// One row loop as a naked function of the block's address (r0), its fields at their offsets
/// (`const` operands): `$fail` the branch taken by a fragment that loses (`bhs`: strictly
/// nearer wins; `bhi`: nearer or equal), then the count's instructions at each span and after
/// the pixel loop (its failure path; none uncounted) and their operands. A row: each edge's
/// span end (its value, then the walk steps: the whole step, the remainder's, and one more
/// where the remainder borrows), the span clamped to
/// `0..width`, and where it holds pixels the depth at its first one and the pixel loop (z in
/// r0, the stored depth in r1, the walk in r2, the byte index in r3 from 2·(x0 − x1) up to 0,
/// the colour cell x1 in r4, the depth cell in r5); then the depth walk and the row address
/// step down. At the end of the first run the lower short edge takes its side, and the second
/// run goes on to `last`.
macro_rules! rows_fn {
    // Counted: each span's length added to `fragments` (from its byte index, 2·(x0 − x1)),
    // and each losing fragment to `failed`, on a path of its own.
    (counted $name:ident, $fail:literal) => {
        rows_fn!($name, $fail,
            ["asrs r1, r3, #1", "ldr r0, [r6, #{frag}]", "subs r0, r0, r1",
             "str r0, [r6, #{frag}]"],
            ["b 4f", "5:", "mov r0, lr", "ldr r1, [r0, #{frag} + 4]", "adds r1, #1",
             "str r1, [r0, #{frag} + 4]",
             "b 6b"], frag = const offset_of!(RowBlock, fragments));
    };
    ($name:ident, $fail:literal, [$($span:literal),*], [$($tail:literal),*]
     $(, $extra:ident = const $value:expr)*) => {
        /// The row loop (see `rows_fn!`) on the block at `block`.
        ///
        /// # Safety
        /// `block` points to a [`RowBlock`] that keeps its contract.
        #[unsafe(naked)]
        #[allow(unsafe_code)]
        unsafe extern "C" fn $name(block: *mut RowBlock) {
            core::arch::naked_asm!(
                save_registers!(),
                // The block in r6 and lr; the step, colour, walk, row and width above r7.
                "mov r6, r0",
                "mov lr, r0",
                "ldr r0, [r6, #{step_x}]",
                "mov r8, r0",
                "ldr r0, [r6, #{bits}]",
                "mov r9, r0",
                "ldr r0, [r6, #{row_z}]",
                "mov r10, r0",
                "ldr r0, [r6, #{row}]",
                "mov r11, r0",
                "ldr r0, [r6, #{width}]",
                "mov r12, r0",
                "2:",
                // Left end x0 (r0): the edge's five words loaded at once (value, remainder,
                // denominator, whole step, remainder's step), r5 left at the right edge; the
                // walk steps.
                "mov r5, r6",
                "ldm r5!, {{r0, r1, r2, r3, r4}}",
                "adds r3, r0, r3",
                "subs r1, r1, r4",
                "bpl 7f",
                "adds r1, r1, r2",
                "adds r3, #1",
                "7:",
                "str r3, [r6, #0]",
                "str r1, [r6, #4]",
                // Right end x1 (r1); its walk steps.
                "ldm r5, {{r1, r2, r3, r4, r5}}",
                "adds r4, r1, r4",
                "subs r2, r2, r5",
                "bpl 8f",
                "adds r2, r2, r3",
                "adds r4, #1",
                "8:",
                "str r4, [r6, #{right}]",
                "str r2, [r6, #{right} + 4]",
                // Pixels where 0 ≤ x0 < x1 ≤ width, by two unsigned comparisons (a negative
                // end is a large unsigned one; the width compared from r12 itself, `cmp`
                // taking high registers); a span that crosses a side of the buffers is clamped
                // to them out of line (the clamps in line took two instructions a row more).
                "cmp r1, r12",
                "bhi 21f",
                "12:",
                "cmp r0, r1",
                "bhs 22f",
                "13:",
                // The depth at x0; both buffers addressed from their cell x1.
                "mov r2, r8",
                "muls r2, r0, r2",
                "add r2, r10",
                "lsls r4, r1, #1",
                "add r4, r11",
                "ldr r5, [r6, #{delta}]",
                "adds r5, r5, r4",
                "subs r3, r0, r1",
                "lsls r3, r3, #1",
                $($span,)*
                // The colour in r6 for the pixel loop (the block stays in lr).
                "mov r6, r9",
                "3:",
                "lsrs r0, r2, #15",
                "ldrh r1, [r5, r3]",
                "add r2, r8",
                "cmp r0, r1",
                $fail,
                "strh r0, [r5, r3]",
                "strh r6, [r4, r3]",
                "6:",
                "adds r3, #2",
                "bne 3b",
                $($tail,)*
                "4:",
                // Next row: the depth walk and the row address; the run ends at `end`.
                "mov r6, lr",
                "ldr r0, [r6, #{step_y}]",
                "add r10, r0",
                "ldr r0, [r6, #{stride}]",
                "add r11, r0",
                "ldr r0, [r6, #{end}]",
                "cmp r11, r0",
                "bne 2b",
                // The last run ends at `last`; before it, the lower short edge takes its side.
                "ldr r0, [r6, #{last}]",
                "cmp r11, r0",
                "beq 1f",
                "str r0, [r6, #{end}]",
                "movs r0, #{lower}",
                "adds r0, r0, r6",
                "ldm r0!, {{r1, r2, r3, r4, r5}}",
                "ldr r0, [r6, #{slot}]",
                "adds r0, r0, r6",
                "stm r0!, {{r1, r2, r3, r4, r5}}",
                "b 2b",
                // x1 beyond the last column, or left of column 0 (then no pixels).
                "21:",
                "cmp r1, #0",
                "blt 4b",
                "mov r1, r12",
                "b 12b",
                // x0 ≥ x1 unsigned with 0 ≤ x1 ≤ width: no pixels, unless x0 is negative and
                // x1 positive (the span from column 0).
                "22:",
                "cmp r0, #0",
                "bge 4b",
                "cmp r1, #0",
                "beq 4b",
                "movs r0, #0",
                "b 13b",
                "1:",
                restore_registers_and_return!(),
                right = const EDGE, lower = const 2 * EDGE,
                step_x = const offset_of!(RowBlock, step_x),
                delta = const offset_of!(RowBlock, delta),
                step_y = const offset_of!(RowBlock, step_y),
                stride = const offset_of!(RowBlock, stride),
                width = const offset_of!(RowBlock, width),
                end = const offset_of!(RowBlock, end), last = const offset_of!(RowBlock, last),
                slot = const offset_of!(RowBlock, slot), bits = const offset_of!(RowBlock, bits),
                row_z = const offset_of!(RowBlock, row_z), row = const offset_of!(RowBlock, row),
                $($extra = const $value,)*
            )
        }
    };
}

rows_fn!(rows_less, "bhs 6f", [], []);
rows_fn!(rows_less_or_equal, "bhi 6f", [], []);
rows_fn!(counted rows_less_counted, "bhs 5f");
rows_fn!(counted rows_less_or_equal_counted, "bhi 5f");

// The edges lie at the block's start, one edge's size apart; every field lies within reach
// of Thumb-1's word loads from a register (offsets up to 124).
const _: () = {
    assert!(offset_of!(RowBlock, runs) == 0 && offset_of!(Runs, edges) == 0);
    assert!(size_of::<RowBlock>() <= 128);
};

/// This core's loop tests every span against the columns at two comparisons a row: no loop
/// without the clamps (see `asm_rows::solid_rows`).
pub(super) const WITHOUT_CLAMPS: bool = false;

/// In [`runs_of`], the keys in `$a` and `$b` swapped (by three exclusive ors) where `$a`'s is
/// the greater, and the long edge's side (r7) turned with them.
#[rustfmt::skip]
macro_rules! swap_if_greater {
    ($a:literal, $b:literal) => {
        concat!(
            "cmp ", $a, ", ", $b, "\n",
            "ble 1f\n",
            "eors ", $a, ", ", $b, "\n",
            "eors ", $b, ", ", $a, "\n",
            "eors ", $a, ", ", $b, "\n",
            "mvns r7, r7\n",
            "1:\n",
        )
    };
}

/// In [`runs_of`]'s division (`divide!`), one subtraction of the divisor (r7) from the
/// numerator (r0), counted in the quotient (r1), unless the numerator is below it: then the
/// division ends (at `49:`).
#[rustfmt::skip]
macro_rules! subtract {
    () => {
        concat!(
            "cmp r0, r7\n",
            "blo 49f\n",
            "subs r0, r0, r7\n",
            "adds r1, #1\n",
        )
    };
}

/// In [`runs_of`]'s edge, ⌊n / d⌋ into r1 and n mod d into r0 for n in r0 and d in r7
/// (unsigned, d > 0), in line: sixteen subtractions at most, in fours (the quotients of the
/// usual edge are a few), then the long division at `30:` for the rest (a call: the edge
/// keeps its return address on the stack).
#[rustfmt::skip]
macro_rules! divide {
    () => {
        concat!(
            "movs r1, #0\n",
            "41:\n",
            subtract!(),
            subtract!(),
            subtract!(),
            subtract!(),
            "cmp r1, #16\n",
            "bne 41b\n",
            "bl 30f\n",
            "49:\n",
        )
    };
}

/// `TriangleRows::runs` of `rows_in_range` (the same edges, `CeilStepper`s as the row loop
/// steps them) in one naked function, for the points at `p` (a [`ScreenTriangle`]'s, within
/// ±[`PIPELINE_LIMIT`]) whose doubled signed area is not 0 and has the high word `side`, in
/// the rows `y0..y1`: written into the block's runs with its `slot`, the first row returned
/// (see [`triangle_runs`]).
///
/// What it computes, as the Rust does:
/// - The sort and the rows as `thumb2::triangle_runs` takes them (keys `4·y + i`, three
///   compare-and-swaps in `sort_by_y`'s order, each turning the long edge's side; the first
///   row, the end and the split row by `first_centre_from32`).
/// - An edge from `p` to `q` (sorted, `p.y < q.y`) at the row whose sample line is `s`
///   (16·row + 8), at `20:`: `dx`, `dy`, `x = p.x − 8`, `t = s − p.y` and `D = 16·dy` as
///   `edge_terms`; for `0 ≤ t < 16` (an edge set up at its first row) the whole pixels
///   `k = x >> 4` apart and the numerator `N = (x & 15)·dy + dx·t`, otherwise `k = 0` and
///   `N = x·dy + dx·t`, both exact in a word (the first within ±2²¹, the second within
///   ±(2¹¹ + 1)·D, its ceiling over `D` a span end within ±2¹¹ + 1 for corners within
///   ±2¹⁵); the value `k + ⌈N / D⌉` and the remainder `value·D − (N + k·D)` in `[0, D)`, from
///   one unsigned division (of `N + D − 1` for `N ≥ 0`, of `−N` otherwise); the step's
///   floor quotient and remainder by `D` of `16·dx` (of `−16·dx + D − 1` for a negative
///   one, as `small_floor_divmod32` takes it). Every quotient and remainder is the one
///   `floor_divmod32` finds, whatever the path.
/// - The edges: the long one (a, c) and the short one, (a, b) above the split or (b, c) where
///   the split row is the first, at the first row, on their sides (the short one at `slot`);
///   the lower one (b, c) at the split row where it lies strictly between the first row and
///   the end, else the words of six registers (any words: the row loop reads the lower edge
///   only after `upper` rows, and `upper` is then `rows`).
///
/// Every denominator is positive, as in `thumb2::triangle_runs`.
///
/// [`ScreenTriangle`]: super::ScreenTriangle
/// [`PIPELINE_LIMIT`]: crate::raster::PIPELINE_LIMIT
///
/// # Safety
/// `p` points to three [`ScreenPoint`]s and `block` is valid for writes of a [`RowBlock`],
/// borrowed by nothing else for the call.
#[unsafe(naked)]
#[allow(unsafe_code)]
unsafe extern "C" fn runs_of(
    p: *const ScreenPoint,
    block: *mut RowBlock,
    y0: i32,
    y1: i32,
    side: i32,
) -> i32 {
    core::arch::naked_asm!(
        "push {{r4, r5, r6, r7, lr}}",
        // The points in r12; the long edge's side in r7: −1 where it lies on the left (an
        // area of 0 or more, its high word's sign), else 0.
        "mov r12, r0",
        "ldr r7, [sp, #20]",
        "asrs r7, r7, #31",
        "mvns r7, r7",
        // Keys 4·y + i in r4 to r6, sorted.
        sorted_keys!(swap_if_greater, "r0", "r4", "r5", "r6"),
        // The first row y (r2) and the row past the last (r3); none unless rows > 0.
        first_row!("r0", "r4"),
        "cmp r0, r2",
        "ble 1f",
        "movs r2, r0",
        "1:",
        first_row!("r0", "r6"),
        "cmp r0, r3",
        "bge 1f",
        "movs r3, r0",
        "1:",
        "subs r0, r3, r2",
        "bgt 1f",
        "movs r0, #0",
        "1:",
        "str r0, [r1, #{rows}]",
        "ble 9f",
        "str r0, [r1, #{upper}]",
        // The short edge's place: the right edge's where the long edge lies on the left.
        "movs r0, #{right}",
        "ands r0, r7",
        "str r0, [r1, #{slot}]",
        // The split row (r0).
        first_row!("r0", "r5"),
        "cmp r0, r2",
        "bge 1f",
        "movs r0, r2",
        "1:",
        "cmp r0, r3",
        "ble 1f",
        "movs r0, r3",
        "1:",
        // The sorted points' addresses in r4 to r6 (p + 8·(key & 3)), the block in r7, the
        // first row's sample line 16·y + 8 and y itself on the stack.
        "lsls r4, r4, #30",
        "lsrs r4, r4, #27",
        "add r4, r12",
        "lsls r5, r5, #30",
        "lsrs r5, r5, #27",
        "add r5, r12",
        "lsls r6, r6, #30",
        "lsrs r6, r6, #27",
        "add r6, r12",
        "movs r7, r1",
        "lsls r1, r2, #4",
        "adds r1, #8",
        "push {{r1, r2}}",
        "cmp r0, r2",
        "beq 3f",
        "cmp r0, r3",
        "beq 4f",
        // A split: upper = split − y, and the lower edge (b, c) at the split row.
        "subs r1, r0, r2",
        "str r1, [r7, #{upper}]",
        "lsls r2, r0, #4",
        "adds r2, #8",
        "movs r0, r5",
        "movs r1, r6",
        "movs r3, r7",
        "adds r3, #{lower}",
        "bl 20f",
        "b 5f",
        // No split: the lower edge's words any (never read); the short edge (a, b) where the
        // split row is the end, (b, c) where it is the first.
        "4:",
        "movs r3, r7",
        "adds r3, #{lower}",
        "stm r3!, {{r0, r1, r2, r4, r5}}",
        "5:",
        "movs r0, r4",
        "movs r1, r5",
        "b 6f",
        "3:",
        "movs r3, r7",
        "adds r3, #{lower}",
        "stm r3!, {{r0, r1, r2, r4, r5}}",
        "movs r0, r5",
        "movs r1, r6",
        "6:",
        "ldr r2, [sp]",
        "ldr r3, [r7, #{slot}]",
        "adds r3, r3, r7",
        "bl 20f",
        // The long edge (a, c) on the other side, at the same sample line (r2, kept).
        "movs r0, r4",
        "movs r1, r6",
        "ldr r3, [r7, #{slot}]",
        "subs r3, r7, r3",
        "adds r3, #{right}",
        "bl 20f",
        "pop {{r1, r2}}",
        "9:",
        "movs r0, r2",
        "pop {{r4, r5, r6, r7, pc}}",
        // The edge from the point at r0 to the point at r1 at sample line r2, its five words
        // (value, remainder, denominator, whole step, remainder's step) stored from r3; r2 and
        // r4 to r7 kept. The usual paths fall through: an edge set up at its first row, a
        // numerator of 0 or more, a step of 0 or more.
        "20:",
        "push {{r2, r4, r5, r6, r7, lr}}",
        "ldm r0!, {{r4, r5}}",
        "ldm r1!, {{r6, r7}}",
        // dx (r6), dy (r7), t (r5), x (r4); k (r2) and N's first factor.
        "subs r6, r6, r4",
        "subs r7, r7, r5",
        "subs r5, r2, r5",
        "subs r4, #8",
        "asrs r2, r4, #4",
        "cmp r5, #16",
        "bhs 21f",
        "lsls r4, r4, #28",
        "lsrs r4, r4, #28",
        "22:",
        "muls r4, r7, r4",
        "muls r5, r6, r5",
        "lsls r7, r7, #4",
        "adds r0, r4, r5",
        "bmi 23f",
        // N ≥ 0: the quotient and remainder of N + D − 1; value k + q, remainder D − 1 − r.
        "adds r0, r0, r7",
        "subs r0, #1",
        divide!(),
        "adds r4, r2, r1",
        "subs r5, r7, #1",
        "subs r5, r5, r0",
        "24:",
        "stm r3!, {{r4, r5}}",
        // The step 16·dx by D, floored.
        "lsls r0, r6, #4",
        "bmi 25f",
        divide!(),
        "26:",
        "str r7, [r3]",
        "str r1, [r3, #4]",
        "str r0, [r3, #8]",
        "pop {{r2, r4, r5, r6, r7, pc}}",
        // Not at its first row: k = 0, N from x itself.
        "21:",
        "movs r2, #0",
        "b 22b",
        // N < 0: the quotient and remainder of −N; value k − q, remainder r.
        "23:",
        "rsbs r0, r0, #0",
        divide!(),
        "subs r4, r2, r1",
        "movs r5, r0",
        "b 24b",
        // A negative step: those of −16·dx + D − 1, the quotient negated and the remainder
        // D − 1 − r (as `small_floor_divmod32` takes it).
        "25:",
        "rsbs r0, r0, #0",
        "adds r0, r0, r7",
        "subs r0, #1",
        divide!(),
        "rsbs r1, r1, #0",
        "subs r2, r7, #1",
        "subs r0, r2, r0",
        "b 26b",
        // The rest of a quotient beyond sixteen (r1 holds 16 of it, r0 what is left of the
        // numerator): the largest multiple d·2^j not above half of it in r4 (its bit in r5),
        // then one subtraction tried for each bit down to d; r2 kept.
        "30:",
        "push {{r2}}",
        "movs r4, r7",
        "movs r5, #1",
        "lsrs r2, r0, #1",
        "31:",
        "cmp r4, r2",
        "bhi 32f",
        "lsls r4, r4, #1",
        "lsls r5, r5, #1",
        "b 31b",
        "32:",
        "cmp r0, r4",
        "blo 33f",
        "subs r0, r0, r4",
        "adds r1, r1, r5",
        "33:",
        "lsrs r4, r4, #1",
        "lsrs r5, r5, #1",
        "bne 32b",
        "pop {{r2}}",
        "bx lr",
        rows = const offset_of!(Runs, rows),
        upper = const offset_of!(Runs, upper),
        slot = const offset_of!(RowBlock, slot),
        right = const EDGE,
        lower = const 2 * EDGE,
    )
}

/// `TriangleRows::runs` of `rows_in_range` for the points `p` (a `ScreenTriangle`'s), whose
/// doubled signed area `area` is not 0, in the rows `y0..y1`, set up by [`runs_of`]: written
/// into `block`'s runs, every field of them, and its `slot` (the lower edge's place: the right
/// edge's where the long edge lies on the left, else the left's), the first row returned;
/// `rows` is 0 (and nothing else written) where the triangle covers none of those rows.
///
/// # Safety
/// `block` is valid for writes of a `RowBlock` (its memory need not hold one) and borrowed
/// by nothing else for the call.
#[inline(always)]
#[allow(unsafe_code)]
pub(super) unsafe fn triangle_runs(
    p: &[ScreenPoint; 3],
    area: i64,
    (y0, y1): (i32, i32),
    block: *mut RowBlock,
) -> i32 {
    // SAFETY:
    // - Calling convention: `runs_of` is `extern "C"` (AAPCS) and keeps it: it saves r4 to
    //   r7 and the return address on entry (its edge routine r2 and r4 to r7 with its own
    //   return address, for the call it makes to the long division, which saves r2) and
    //   restores them on return (r0 to r3, r12 and the flags are the caller's to lose), uses
    //   the stack only for that and two words of its own (balanced), and returns with
    //   `pop {.., pc}`; its arguments come in r0 to r3 and the fifth on the stack.
    // - Memory: it reads the six words of `p` (borrowed; at offsets 0 to 20 by its layout,
    //   asserted below), each point at `p + 8·i` for an index `i = key & 3` of keys made from
    //   the indices 0, 1 and 2 and only moved about, and writes words of `block` (valid for
    //   writes and unshared, the caller's contract): its runs' three edges (15 words),
    //   `upper` and `rows`, and its `slot`; nothing else.
    // - Values: every field written is an i32 or u32 (any word), `slot` 0 or `EDGE`.
    // - Termination: the subtractions stop after sixteen; the long division's doubling stops
    //   below half the numerator (below 2³¹, so never wraps), its halving after as many
    //   steps.
    unsafe { runs_of(p.as_ptr(), block, y0, y1, (area >> 32) as i32) }
}

// The layouts `runs_of` reads and writes: points of two words (x, y); the runs' edges of
// five words from the block's start, then `upper` and `rows` within reach of its loads.
const _: () = {
    assert!(size_of::<ScreenPoint>() == 8 && offset_of!(ScreenPoint, y) == 4);
    assert!(offset_of!(ScreenPoint, x) == 0 && EDGE == 20);
};

/// The rows of a triangle in `block` (see [`RowBlock`]) through the naked function of `T` and
/// `K` (`clamp` is not read: see [`WITHOUT_CLAMPS`]).
///
/// # Safety
/// `block` keeps [`RowBlock`]'s contract.
#[inline(always)]
#[allow(unsafe_code)]
pub(super) unsafe fn rows<T: DepthTest, K: FragmentCount>(block: &mut RowBlock, clamp: bool) {
    let _ = clamp;
    let block: *mut RowBlock = block;
    // SAFETY (the caller keeps `RowBlock`'s contract):
    // - Calling convention: the functions are `extern "C"` (AAPCS) and keep it: they save r4
    //   to r11 and the return address on entry and restore them on return (r0 to r3, r12 and
    //   the flags are the caller's to lose), use the stack only for that (balanced), and
    //   return with `pop {.., pc}`; their argument, the block's address, comes in r0.
    // - Memory: row k (0 ≤ k < rows) starts at cell k·width of the colour cells at `row` (the
    //   row address, r11, steps by a row's bytes, `stride`). A row's pixels are touched only
    //   where 0 ≤ x0 < x1 ≤ width: two unsigned comparisons pass only then (x1 ≤ width as
    //   unsigned, so 0 ≤ x1 < 2³¹, and x0 < x1 as unsigned, so x0 ≥ 0), and otherwise the
    //   out-of-line paths clamp x1 to width (only where it is positive) or x0 to 0 (only
    //   where x1 > 0) before the same test, or skip the row: the halfwords at r4 + i and
    //   r5 + i for byte indices i from 2·(x0 − x1) to −2, with r4 the address of the row's
    //   cell x1 and r5 = r4 + delta the same cell of the depth cells: cells k·width + x for
    //   x0 ≤ x < x1, below rows·width, which the caller holds mutably. It also reads the block
    //   (borrowed mutably) and writes its edges' values and remainders (the first two words of
    //   the first two edges), the lower edge over the one at `slot` (0 or one edge's size),
    //   `end` and, counted, its counts; nothing else.
    // - Values: a depth cell gets a u16, a colour cell `bits`, the two bytes of a valid colour
    //   unchanged; an edge gets a copy of a valid edge or new i32s, `end` the address `last`,
    //   the counts u32s.
    // - Termination: each row ends with the byte index rising by 2 to 0 from 2·(x0 − x1)
    //   ≥ −2·width. The row address rises by `stride` > 0 a row from the first cell: it meets
    //   `end` after `upper` ≥ 1 rows; unless that is `last` (upper = rows), `end` becomes
    //   `last`, which it meets after the other rows ≥ 1.
    unsafe {
        match (T::OR_EQUAL, K::COUNTED) {
            (false, false) => rows_less(block),
            (true, false) => rows_less_or_equal(block),
            (false, true) => rows_less_counted(block),
            (true, true) => rows_less_or_equal_counted(block),
        }
    }
}

/// The walk on ARMv6-M: a back face takes 29 instructions (its three indices loaded, its
/// points by `ldm`, the area by two 32-bit multiplies as `short_sides_area` takes it, every
/// side of such a triangle lying within ±2¹⁵, its sign and its zero tested, the count of
/// triangles left stepped), where the compiled walk took about 65, keeping its state on the
/// stack around the call it makes for the faces it draws. Inline assembly on ARMv6-M gets r0
/// to r5 of the low registers (and high registers only as clobbers): the count left, the
/// vertices' address and `out`'s wait in r8 to r10, the third corner's address in r12.
impl<'t> FrontFaces<'t, '_> {
    /// The next triangle that is not a back face, or [`FaceStop::End`]; for a front face its
    /// vertices' positions and depths written to `out`.
    #[inline(always)]
    #[allow(unsafe_code)]
    pub(crate) fn next_stop(&mut self, out: &mut [(ScreenPoint, i32); 3]) -> FaceStop<'t> {
        let stop: u32;
        let area: i32;
        // SAFETY:
        // - Memory: the block reads the three indices of each of the `left` triangles from
        //   `next` (within `triangles`: `next` lies within it or at its end, `left` triangles
        //   before the end, and moves by one triangle as `left` counts down to 0), and the
        //   words at `v + 16·i` and `v + 16·i + 4` and (for a front face) `v + 16·i + 8` for
        //   each index `i` of those triangles: within `vertices`, whose elements take 16 bytes
        //   with x, y and z at 0, 4 and 8 (asserted in asm_faces.rs), as `i` is below the
        //   mesh's number of positions (the invariant of `Mesh`), which is `vertices.len()`
        //   (checked by `FrontFaces::new`). Where it stops on a front face it writes `out`
        //   (borrowed mutably): that face's three vertices' x, y and z to the three words at
        //   0, 12 and 24 (its layout, asserted there); no other memory, and no stack
        //   (`nostack`).
        // - Values: `next` leaves at one past the triangle the walk stopped on, or at the end,
        //   `left` as the triangles after it; `out` gets `i32`s (any word is one).
        // - Registers: every register the block writes is an output or a clobber; the flags
        //   it changes are not preserved, as asm! allows by default.
        unsafe {
            core::arch::asm!(
                // The count left (in r1 at the end), the vertices' and `out`'s addresses into
                // high registers.
                "mov r8, r1",
                "mov r9, r2",
                "mov r10, r3",
                "cmp r1, #0",
                "beq 5f",
                "2:",
                "ldrh r0, [r5, #0]",
                "ldrh r1, [r5, #2]",
                "ldrh r2, [r5, #4]",
                "adds r5, #6",
                // a = (r0, r3), b − a = (r1, r4), c's address in r12.
                "lsls r0, r0, #4",
                "add r0, r9",
                "ldm r0, {{r0, r3}}",
                "lsls r1, r1, #4",
                "add r1, r9",
                "ldm r1, {{r1, r4}}",
                "subs r1, r1, r0",
                "subs r4, r4, r3",
                "lsls r2, r2, #4",
                "add r2, r9",
                "mov r12, r2",
                // (b − a).x·(c.y − a.y) − (c − a).x·(b − a).y, in words.
                "ldr r2, [r2, #4]",
                "subs r2, r2, r3",
                "muls r2, r1, r2",
                "mov r3, r12",
                "ldr r3, [r3, #0]",
                "subs r3, r3, r0",
                "muls r3, r4, r3",
                "subs r2, r2, r3",
                "bmi 3f",
                "beq 4f",
                // A back face: the count left stepped (in r1), the next face unless none.
                "mov r1, r8",
                "subs r1, #1",
                "mov r8, r1",
                "bne 2b",
                "5:",
                "movs r0, #{end_}",
                "b 9f",
                "4:",
                "movs r0, #{degenerate}",
                "b 8f",
                // A front face: its corners' x, y and z to `out` (the area kept in r12).
                "3:",
                "mov r12, r2",
                "subs r1, r5, #6",
                "mov r4, r10",
                "ldrh r0, [r1, #0]",
                "lsls r0, r0, #4",
                "add r0, r9",
                "ldm r0, {{r0, r2, r3}}",
                "stm r4!, {{r0, r2, r3}}",
                "ldrh r0, [r1, #2]",
                "lsls r0, r0, #4",
                "add r0, r9",
                "ldm r0, {{r0, r2, r3}}",
                "stm r4!, {{r0, r2, r3}}",
                "ldrh r0, [r1, #4]",
                "lsls r0, r0, #4",
                "add r0, r9",
                "ldm r0, {{r0, r2, r3}}",
                "stm r4!, {{r0, r2, r3}}",
                "mov r2, r12",
                "movs r0, #{front}",
                // A stop on a face: the count left stepped past it (in r1).
                "8:",
                "mov r1, r8",
                "subs r1, #1",
                "9:",
                inout("r5") self.next,
                inout("r1") self.left,
                inout("r2") self.vertices.as_ptr() => area,
                inout("r3") out.as_mut_ptr() => _,
                out("r0") stop, out("r4") _,
                out("r8") _, out("r9") _, out("r10") _, out("r12") _,
                front = const FaceStop::FRONT,
                degenerate = const FaceStop::DEGENERATE,
                end_ = const FaceStop::END,
                options(nostack),
            );
        }
        self.stopped(stop, i64::from(area))
    }
}

/// In [`project_split`], the sum of the row read from r3 (advanced past it) into r4: its
/// fourth word plus the words in r0 to r2 times its coefficients (r5 to r7 clobbered).
#[rustfmt::skip]
macro_rules! row_sum {
    () => {
        concat!(
            "ldm r3!, {{r4, r5, r6, r7}}\n",
            "muls r4, r0, r4\n",
            "muls r5, r1, r5\n",
            "muls r6, r2, r6\n",
            "adds r4, r4, r5\n",
            "adds r4, r4, r6\n",
            "adds r4, r4, r7\n",
        )
    };
}

/// In [`project_split`], the `A` of the row read from r3: its translation word plus the high
/// parts in r0 to r2 times its coefficients, pushed.
macro_rules! high_row {
    () => {
        concat!(row_sum!(), "push {{r4}}\n")
    };
}

/// What [`project_split`]'s loop reads: first the shifts and the projection's constants, then
/// the transform's rows twice, each as `SplitTransform` holds it (its coefficients, then a
/// word to start the sum from): for the high parts' sums `A` in the order w, x, y, z with the
/// row's translation times 2^(16−k), for the low parts' sums `L` in the reverse order (the
/// loop pushes the `A`s and pops them back) with 2¹⁵, the rounding.
#[repr(C)]
struct SplitBlock {
    /// `k`, `16 − k` and `32 − k` for the split at bit `k`.
    k: u32,
    s: u32,
    lead: u32,
    end: *const Vec3,
    half_w: i32,
    half_h: i32,
    high: [[i32; 4]; 4],
    low: [[i32; 4]; 4],
}

/// In [`project_split`], the clip coordinate of the row read from r3 (advanced past it), from
/// the low parts in r0 to r2 and the row's `A` on the stack (popped): `L + 2¹⁵` summed, then
/// `(A + ((L + 2¹⁵) >> k)) >> (16 − k)` into r4 (`SplitTransform::transform_words`).
#[rustfmt::skip]
macro_rules! low_row {
    () => {
        concat!(
            row_sum!(),
            "mov r6, r12\n",
            "asrs r4, r6\n",
            "pop {{r5}}\n",
            "adds r4, r4, r5\n",
            "mov r6, lr\n",
            "asrs r4, r6\n",
        )
    };
}

/// `ShortQuotients::top` of `$v` in place (`(v << up) >> down`, from `below` in r5: a shift
/// right by `below − 15`, or left by `15 − below`), `$t` a temporary: `$t` is set to `$from`
/// less `$minus` (one of them r5, the other 15), and where that is 0 or more the shift
/// `$usual` by it is taken by one branch, else the other one (`$other`, by its negation)
/// falls through: four instructions for the usual size of divisor, six for the other.
#[rustfmt::skip]
macro_rules! top_by {
    ($v:literal, $t:literal, $from:literal, $minus:literal, $usual:literal, $other:literal) => {
        concat!(
            "movs ", $t, ", ", $from, "\n",
            "subs ", $t, ", ", $t, ", ", $minus, "\n",
            "bpl 1f\n",
            "rsbs ", $t, ", ", $t, ", #0\n",
            $other, " ", $v, ", ", $t, "\n",
            "b 2f\n",
            "1:\n",
            $usual, " ", $v, ", ", $t, "\n",
            "2:\n",
        )
    };
}

/// [`top_by`] for [`project_split`]'s divisor, a vertex's w (from 2¹⁵ up, usually): the
/// right shift by `below − 15` the usual one.
macro_rules! top_right {
    ($v:literal, $t:literal) => {
        top_by!($v, $t, "r5", "#15", "lsrs", "lsls")
    };
}

/// [`top_by`] for [`walk_of`]'s divisor, a triangle's doubled area (below 2¹⁵, usually): the
/// left shift by `15 − below` the usual one.
macro_rules! top_left {
    ($v:literal, $t:literal) => {
        top_by!($v, $t, "#15", "r5", "lsls", "lsrs")
    };
}

/// `ShortQuotients::new` of the divisor d in r0 and r7 (kept in r7): the index of its top
/// bit (`below`) into r5, by two halving steps and the top byte's count from `BYTE_ZEROS`,
/// then the reciprocal ⌊2³¹ / (top(d) + 1)⌋ into r6 (`reciprocal16`: the seed from
/// `RECIPROCALS`, its index masked to the table, one Newton step, one test), `$top` the
/// `top` of the usual divisor's size; r0 to r3 clobbered. The tables' addresses come from
/// the literal pool (the operands `zeros` and `reciprocals`).
#[rustfmt::skip]
macro_rules! divisor {
    ($top:ident) => {
        concat!(
            "movs r5, #0\n",
            "lsrs r1, r0, #16\n",
            "beq 1f\n",
            "movs r0, r1\n",
            "movs r5, #16\n",
            "1:\n",
            "lsrs r1, r0, #8\n",
            "beq 1f\n",
            "movs r0, r1\n",
            "adds r5, #8\n",
            "1:\n",
            "ldr r1, ={zeros}\n",
            "ldrb r1, [r1, r0]\n",
            "subs r5, r5, r1\n",
            "adds r5, #7\n",
            "movs r0, r7\n",
            $top!("r0", "r1"),
            "lsls r1, r0, #17\n",
            "lsrs r1, r1, #25\n",
            "lsls r1, r1, #1\n",
            "ldr r2, ={reciprocals}\n",
            "ldrh r2, [r2, r1]\n",
            "adds r0, #1\n",
            "movs r1, r0\n",
            "muls r1, r2, r1\n",
            "movs r3, #1\n",
            "lsls r3, r3, #31\n",
            "subs r1, r3, r1\n",
            "asrs r1, r1, #8\n",
            "muls r1, r2, r1\n",
            "asrs r1, r1, #23\n",
            "adds r6, r2, r1\n",
            "movs r1, r6\n",
            "muls r1, r0, r1\n",
            "subs r1, r3, r1\n",
            "cmp r1, r0\n",
            "blo 1f\n",
            "adds r6, #1\n",
            "1:\n",
        )
    };
}

/// In [`project_split`], `ShortQuotients::digit`'s three corrections of the quotient `$q` and
/// the remainder `$rem` by the divisor in r7 (written out, each ending the digit once the
/// remainder is below it).
#[rustfmt::skip]
macro_rules! corrections {
    ($q:literal, $rem:literal) => {
        concat!(
            "cmp ", $rem, ", r7\n",
            "blo 3f\n",
            "adds ", $q, ", #1\n",
            "subs ", $rem, ", ", $rem, ", r7\n",
            "cmp ", $rem, ", r7\n",
            "blo 3f\n",
            "adds ", $q, ", #1\n",
            "subs ", $rem, ", ", $rem, ", r7\n",
            "cmp ", $rem, ", r7\n",
            "blo 3f\n",
            "adds ", $q, ", #1\n",
            "subs ", $rem, ", ", $rem, ", r7\n",
            "3:\n",
        )
    };
}

/// In [`project_split`], one screen coordinate: the clip coordinate at `$at` in the vertex
/// (r10) times the half size at `$half` in the block (r11), rounded over w
/// (`ShortQuotients::round`: the magnitude plus d/2, its bits from `below` times the
/// reciprocal for the digit, corrected; the sign put back), then added to the half size
/// (`$op` `adds`) or taken from it (`subs`), stored back at `$at`.
#[rustfmt::skip]
macro_rules! screen_axis {
    ($at:literal, $half:literal, $op:literal) => {
        concat!(
            "mov r3, r10\n",
            "ldr r0, [r3, #", $at, "]\n",
            "mov r3, r11\n",
            "ldr r3, [r3, #{", $half, "}]\n",
            "muls r0, r3, r0\n",
            "asrs r2, r0, #31\n",
            "eors r0, r2\n",
            "subs r0, r0, r2\n",
            "lsrs r1, r7, #1\n",
            "adds r0, r0, r1\n",
            "movs r1, r0\n",
            "lsrs r1, r5\n",
            "muls r1, r6, r1\n",
            "lsrs r1, r1, #16\n",
            "movs r4, r1\n",
            "muls r4, r7, r4\n",
            "subs r0, r0, r4\n",
            corrections!("r1", "r0"),
            "eors r1, r2\n",
            "subs r1, r1, r2\n",
            $op, " r1, r3, r1\n",
            "mov r3, r10\n",
            "str r1, [r3, #", $at, "]\n",
        )
    };
}

/// The vertex stage of an object whose every vertex is known inside every clip plane with its
/// projection's operands in words (`Known::InWords`) and no lit colour, on ARMv6-M: each of
/// `positions` through the split transform `h` into the vertex of `out` at its index, as the
/// vertex loop in Rust computes it (`project_words` of `SplitTransform::transform_words`), in
/// one loop of assembly: the coordinates split at bit k (their low k bits, signed, and the
/// rest), each row's sums of the high parts `A` (pushed) and of the low parts `L`, the row
/// `(A + ((L + 2¹⁵) >> k)) >> (16 − k)` kept in the vertex until it is projected; w's
/// `ShortQuotients` (its bits below the top one by two halving steps and the top byte's
/// count, its 16-bit reciprocal from the seed table and one Newton step, exact after one
/// test), the screen position from `x·half_w` and `y·half_h` rounded over w, and the depth
/// `z·2³⁰/w` by two digits, rounded. About 260 instructions a vertex where the compiled loop
/// takes about 314, keeping the matrix on the stack.
#[allow(unsafe_code)]
pub(crate) fn project_split_in_words(
    h: &SplitTransform,
    (half_w, half_h): (i32, i32),
    positions: &[Vec3],
    out: &mut [ScreenVertex],
) {
    let n = positions.len().min(out.len());
    let (rows, t, k) = h.parts();
    let [x, y, z, w] = *rows;
    let [tx, ty, tz, tw] = t;
    let high = |r: [i32; 3], t: i32| [r[0], r[1], r[2], t];
    let low = |r: [i32; 3]| [r[0], r[1], r[2], 1 << 15];
    let block = SplitBlock {
        k,
        s: 16 - k,
        lead: 32 - k,
        end: positions.as_ptr().wrapping_add(n),
        half_w,
        half_h,
        high: [high(w, tw), high(x, tx), high(y, ty), high(z, tz)],
        low: [low(z), low(y), low(x), low(w)],
    };
    // SAFETY: `project_split` keeps the calling convention (see its documentation) and reads
    // `block` (borrowed for the call), the statics `RECIPROCALS` and `BYTE_ZEROS` (their
    // addresses from the literal pool, the indices masked to their lengths, see its
    // documentation), the `n` positions from
    // `positions` up to `block.end` (within the slice), and writes the `n` vertices from
    // `out` (borrowed mutably, at least `n` long): 16 bytes each, x, y, z and a zero word
    // over `rgb` and `outcode` at 0, 4, 8 and 12 (asserted below), valid values of every
    // field (any `i32`, bytes 0).
    unsafe { project_split(&block, positions.as_ptr(), out.as_mut_ptr()) };
}

/// [`project_split_in_words`]' loop, from the block's address (r0), the first position (r1)
/// and the first vertex (r2) to the positions' end (the block's `end`). Registers across the
/// loop: the positions in r8, their end in r9, the vertices in r10, the block in r11, `k` in
/// r12 and `16 − k` in lr; for each vertex the point in r0 to r2, the rows' words in r4 to
/// r7 (read from r3), then w (the divisor) in r7, its reciprocal in r6 and the index of its
/// top bit (`below`) in r5. The table reads are masked: the reciprocal's seed index
/// `(top >> 8) & 127` (by two shifts) of 128 entries, the byte count's index below 256 (the
/// value left after the halving steps, its top byte).
///
/// # Safety
/// `block` points to a [`SplitBlock`] whose `end` lies at or after `positions` (within one
/// slice of `Vec3`), and `out` to as many writable vertices.
#[unsafe(naked)]
#[allow(unsafe_code)]
unsafe extern "C" fn project_split(
    block: *const SplitBlock,
    positions: *const Vec3,
    out: *mut ScreenVertex,
) {
    core::arch::naked_asm!(
        save_registers!(),
        "mov r11, r0",
        "mov r8, r1",
        "mov r10, r2",
        "ldr r3, [r0, #{k}]",
        "mov r12, r3",
        "ldr r3, [r0, #{s}]",
        "mov lr, r3",
        "ldr r3, [r0, #{end}]",
        "mov r9, r3",
        "cmp r8, r9",
        "blo 8f",
        "b 9f",
        "8:",
        // The point, split: its low k bits, signed, into r4 to r6, the rest shifted down into
        // r0 to r2 (`split`).
        "mov r3, r8",
        "ldm r3!, {{r0, r1, r2}}",
        "mov r8, r3",
        "mov r3, r11",
        "ldr r3, [r3, #{lead}]",
        "mov r7, r12",
        "movs r4, r0",
        "lsls r4, r3",
        "asrs r4, r3",
        "subs r0, r0, r4",
        "asrs r0, r7",
        "movs r5, r1",
        "lsls r5, r3",
        "asrs r5, r3",
        "subs r1, r1, r5",
        "asrs r1, r7",
        "movs r6, r2",
        "lsls r6, r3",
        "asrs r6, r3",
        "subs r2, r2, r6",
        "asrs r2, r7",
        "push {{r4, r5, r6}}",
        // Each row's A (w, x, y, z), pushed.
        "mov r3, r11",
        "adds r3, #{high}",
        high_row!(),
        high_row!(),
        high_row!(),
        high_row!(),
        // The low parts back, then each row (z, y, x, w) with its A popped: z, y and x kept in
        // the vertex, w in r4.
        "ldr r0, [sp, #16]",
        "ldr r1, [sp, #20]",
        "ldr r2, [sp, #24]",
        low_row!(),
        "mov r5, r10",
        "str r4, [r5, #8]",
        low_row!(),
        "mov r5, r10",
        "str r4, [r5, #4]",
        low_row!(),
        "mov r5, r10",
        "str r4, [r5, #0]",
        low_row!(),
        "add sp, #12",
        // w's `ShortQuotients`: d in r7, below (its top bit's index) in r5.
        "movs r7, r4",
        "movs r0, r4",
        divisor!(top_right),
        // x: half_w + round(x·half_w / w); y: half_h − round(y·half_h / w).
        screen_axis!("0", "half_w", "adds"),
        screen_axis!("4", "half_h", "subs"),
        // The depth: z·2³⁰/w by two digits (`round_fraction`), rounded.
        "mov r3, r10",
        "ldr r0, [r3, #8]",
        "movs r1, r0",
        top_right!("r1", "r2"),
        "lsls r0, r0, #15",
        "muls r1, r6, r1",
        "lsrs r1, r1, #16",
        "movs r3, r1",
        "muls r3, r7, r3",
        "subs r0, r0, r3",
        corrections!("r1", "r0"),
        "movs r2, r0",
        top_right!("r2", "r3"),
        "lsls r0, r0, #15",
        "muls r2, r6, r2",
        "lsrs r2, r2, #16",
        "movs r3, r2",
        "muls r3, r7, r3",
        "subs r0, r0, r3",
        corrections!("r2", "r0"),
        "lsrs r3, r7, #1",
        "adds r0, r0, r3",
        "lsls r1, r1, #15",
        "adds r1, r1, r2",
        "cmp r0, r7",
        "blo 1f",
        "adds r1, #1",
        "1:",
        "mov r3, r10",
        "str r1, [r3, #8]",
        "movs r0, #0",
        "str r0, [r3, #12]",
        "adds r3, #16",
        "mov r10, r3",
        // (The loop is longer than a conditional branch reaches.)
        "cmp r8, r9",
        "bhs 9f",
        "b 8b",
        "9:",
        restore_registers_and_return!(),
        k = const offset_of!(SplitBlock, k),
        s = const offset_of!(SplitBlock, s),
        lead = const offset_of!(SplitBlock, lead),
        end = const offset_of!(SplitBlock, end),
        half_w = const offset_of!(SplitBlock, half_w),
        half_h = const offset_of!(SplitBlock, half_h),
        zeros = sym BYTE_ZEROS,
        reciprocals = sym RECIPROCALS,
        high = const offset_of!(SplitBlock, high),
    )
}

// The layouts `project_split` reads and writes: the block's rows one after the other (the
// low parts' after the high parts'), points of three words, vertices of 16 bytes with x, y,
// z and a word of `rgb` and `outcode`; every field within reach of a word load.
const _: () = {
    assert!(offset_of!(SplitBlock, low) == offset_of!(SplitBlock, high) + 64);
    assert!(offset_of!(SplitBlock, high) <= 255 && offset_of!(SplitBlock, half_h) <= 124);
    assert!(size_of::<Vec3>() == 12 && offset_of!(Vec3, y) == 4 && offset_of!(Vec3, z) == 8);
    assert!(offset_of!(ScreenVertex, rgb) == 12 && offset_of!(ScreenVertex, outcode) == 15);
    assert!(size_of::<ScreenVertex>() == 16 && offset_of!(ScreenVertex, z) == 8);
    assert!(offset_of!(ScreenVertex, x) == 0 && offset_of!(ScreenVertex, y) == 4);
};

/// In [`walk_of`], the exact product `v·s` into `$lo`, `$hi` (64 bits) of a word `$v` within
/// ±2³⁰ and a short `$s` (within ±2¹⁵, kept): its halves' products, each a word, the high
/// one's shifted in (`mul_short`'s halves); `$v` and `$t` clobbered.
#[rustfmt::skip]
macro_rules! product {
    ($v:literal, $s:literal, $lo:literal, $hi:literal, $t:literal) => {
        concat!(
            "uxth ", $lo, ", ", $v, "\n",
            "asrs ", $v, ", ", $v, ", #16\n",
            "muls ", $lo, ", ", $s, ", ", $lo, "\n",
            "muls ", $v, ", ", $s, ", ", $v, "\n",
            "asrs ", $hi, ", ", $lo, ", #31\n",
            "lsls ", $t, ", ", $v, ", #16\n",
            "asrs ", $v, ", ", $v, ", #16\n",
            "adds ", $lo, ", ", $lo, ", ", $t, "\n",
            "adcs ", $hi, ", ", $v, "\n",
        )
    };
}

/// In [`walk_of`], a numerator `u·(c₁ − a) − v·(c₂ − a)` stored at `$at` on the stack (two
/// words, low first): the corner coordinates at offsets `$a`, `$c1` and `$c2` of the triangle's
/// points (r7), the depth differences `u` in r1 and `v` in r2 (after the instructions
/// `$load`), each product exact ([`product`]).
#[rustfmt::skip]
macro_rules! numerator {
    ($a:literal, $c1:literal, $c2:literal, $at:literal, [$($load:literal),*]) => {
        concat!(
            "ldr r0, [r7, #{p} + ", $a, "]\n",
            "ldr r3, [r7, #{p} + ", $c1, "]\n",
            "subs r3, r3, r0\n",
            "ldr r4, [r7, #{p} + ", $c2, "]\n",
            "subs r4, r4, r0\n",
            $($load, "\n",)*
            product!("r1", "r3", "r0", "r5", "r6"),
            product!("r2", "r4", "r1", "r3", "r6"),
            "subs r0, r0, r1\n",
            "sbcs r5, r3\n",
            "str r0, [sp, #", $at, "]\n",
            "str r5, [sp, #", $at, " + 4]\n",
        )
    };
}

/// In [`walk_of`], the side from the point at offset `$a` to the one at `$b` in the triangle
/// (r7) tested short (within ±2¹⁵): the walk is declined otherwise (r0 and r1 clobbered).
#[rustfmt::skip]
macro_rules! short_side {
    ($a:literal, $b:literal) => {
        concat!(
            "ldr r0, [r7, #{p} + ", $a, "]\n",
            "ldr r1, [r7, #{p} + ", $b, "]\n",
            "subs r1, r1, r0\n",
            "lsls r0, r1, #16\n",
            "asrs r0, r0, #16\n",
            "cmp r0, r1\n",
            "bne 90f\n",
        )
    };
}

/// In [`walk_of`], one step, `ShortQuotients::round_below_2_30` of 32 times the numerator whose
/// words lie at `$at` on the stack, into r0: the magnitude times 32 plus d/2 (d in r7), its
/// bits from 30 up below d (else declined), two 15-bit digits by the reciprocal (r6) from
/// `below` (r5), corrected, the sign put back (kept at sp + 0 meanwhile).
#[rustfmt::skip]
macro_rules! step {
    ($at:literal) => {
        concat!(
            "ldr r0, [sp, #", $at, "]\n",
            "ldr r1, [sp, #", $at, " + 4]\n",
            "lsls r1, r1, #5\n",
            "lsrs r2, r0, #27\n",
            "orrs r1, r2\n",
            "lsls r0, r0, #5\n",
            "asrs r4, r1, #31\n",
            "eors r0, r4\n",
            "eors r1, r4\n",
            "subs r0, r0, r4\n",
            "sbcs r1, r4\n",
            "str r4, [sp, #0]\n",
            "lsrs r2, r7, #1\n",
            "adds r0, r0, r2\n",
            "movs r2, #0\n",
            "adcs r1, r2\n",
            // a >> 30, below d, the first digit's remainder to start from.
            "lsls r1, r1, #2\n",
            "lsrs r2, r0, #30\n",
            "orrs r1, r2\n",
            "cmp r1, r7\n",
            "blo 4f\n",
            "b 90f\n",
            "4:\n",
            // The first digit: c = bits 15 to 29 of a.
            "lsls r2, r0, #2\n",
            "lsrs r2, r2, #17\n",
            "movs r3, r1\n",
            top_left!("r3", "r4"),
            "movs r4, r2\n",
            "lsrs r4, r5\n",
            "adds r3, r3, r4\n",
            "lsls r1, r1, #15\n",
            "orrs r1, r2\n",
            "muls r3, r6, r3\n",
            "lsrs r3, r3, #16\n",
            "movs r4, r3\n",
            "muls r4, r7, r4\n",
            "subs r1, r1, r4\n",
            corrections!("r3", "r1"),
            // The second: c = a's low 15 bits.
            "lsls r2, r0, #17\n",
            "lsrs r2, r2, #17\n",
            "movs r0, r1\n",
            top_left!("r0", "r4"),
            "movs r4, r2\n",
            "lsrs r4, r5\n",
            "adds r0, r0, r4\n",
            "lsls r1, r1, #15\n",
            "orrs r1, r2\n",
            "muls r0, r6, r0\n",
            "lsrs r0, r0, #16\n",
            "movs r4, r0\n",
            "muls r4, r7, r4\n",
            "subs r1, r1, r4\n",
            corrections!("r0", "r1"),
            "lsls r3, r3, #15\n",
            "orrs r0, r3\n",
            "ldr r4, [sp, #0]\n",
            "eors r0, r4\n",
            "subs r0, r0, r4\n",
        )
    };
}

/// `RoundedRows::new` of `triangle`'s depth walk on row `y` (the first row of its runs) by
/// [`walk_of`], for a triangle whose doubled area's magnitude lies below 2²⁹ and whose sides
/// are short (every triangle of an object inside every clip plane): `None` where it declines
/// (a larger triangle, a long side, or a step of 2³⁰ or more), and the caller then sets the
/// walk up in Rust, which returns the same walk or `None`.
#[inline(always)]
#[allow(unsafe_code)]
pub(super) fn depth_walk(triangle: &ScreenTriangle, y: i32) -> Option<RoundedRows<i32>> {
    let mut out = core::mem::MaybeUninit::<RowBlock>::uninit();
    let block = out.as_mut_ptr();
    // SAFETY: `block` is a local's, valid for writes of a `RowBlock`; the three fields are
    // read only where `walk_into` wrote them.
    unsafe {
        if !walk_into(triangle, y, block) {
            return None;
        }
        Some(RoundedRows {
            row: addr_of!((*block).row_z).read(),
            step_x: addr_of!((*block).step_x).read(),
            step_y: addr_of!((*block).step_y).read(),
        })
    }
}

/// [`depth_walk`] written into the row loop's block at `block` (its `row_z`, `step_x` and
/// `step_y`): true, or false with nothing written where it declines.
///
/// # Safety
/// `block` is valid for writes of a `RowBlock` (its memory need not hold one), unshared.
#[inline(always)]
#[allow(unsafe_code)]
pub(super) unsafe fn walk_into(triangle: &ScreenTriangle, y: i32, block: *mut RowBlock) -> bool {
    // SAFETY: `walk_of` keeps the calling convention (see its documentation), reads words of
    // `triangle` (borrowed) at their `offset_of!` and its `short_sides` byte, and writes the
    // block's three fields (at their `offset_of!`, the caller's contract) when it returns 1.
    unsafe { walk_of(triangle, y, block) != 0 }
}

/// [`depth_walk`]'s naked function: the walk into the row loop's block at `out` (its row at
/// column 0, `row_z`, and its steps along a row and down a column, `step_x` and `step_y`) and
/// 1 returned, or 0 (nothing written) where it declines. What it computes, step by
/// step as `RoundedRows::new` does it on Cortex-M0 (`numerators_as` with differences,
/// `ShortQuotients`, `rounded_offset_in_words`):
/// - `d = |area|`, declined unless `0 < d < 2²⁹`; the depth differences `z₁ − z₀`, `z₂ − z₀`
///   negated where the area is negative, so that the numerators `dv₁·dy₂ − dv₂·dy₁` and
///   `dv₂·dx₁ − dv₁·dx₂` are those over `d` (`over_positive_area`: the products are linear
///   in the differences), each product exact in 64 bits from the halves of its depth
///   difference (its side within ±2¹⁵, tested unless the triangle's sides are known short).
/// - d's `ShortQuotients`, as the vertex loop finds w's (`below`, the reciprocal).
/// - Each step by [`step`]'s digits (`round_below_2_30` of 32 times the numerator).
/// - The reference pixel `x_r = x₀ >> 4`, `y_r = (y₀ + 7) >> 4`, the offsets `dx = 8 −
///   (x₀ & 15)`, `dy = 16·y_r + 8 − y₀`, the offset in words (`(sx >> 4)·dx + (sy >> 4)·dy`
///   and the low parts' products rounded), and the row at column 0
///   `2·z₀ + LOOP_HALF_STEP + offset + sy·(y − y_r) − sx·x_r`, modulo 2³².
///
/// Calling convention (AAPCS, `extern "C"`): it saves r4 to r7 and the return address on
/// entry and restores them on return (`pop {.., pc}` on both paths), using the stack only for
/// that and its 40-byte frame (balanced: from sp, `d` then the sign, the depth differences
/// then the first step and the reference pixel, both numerators, then the arguments pushed:
/// the triangle, `y` and `out`). Memory: it reads the triangle's points, depths, area and
/// `short_sides` at their `offset_of!`, the two seed tables at masked indices (as
/// [`project_split`]), and writes the block's three fields only on success. No loop: it ends.
///
/// # Safety
/// `triangle` points to a [`ScreenTriangle`] and `out` is valid for writes of a [`RowBlock`].
#[unsafe(naked)]
#[allow(unsafe_code)]
unsafe extern "C" fn walk_of(triangle: *const ScreenTriangle, y: i32, out: *mut RowBlock) -> u32 {
    core::arch::naked_asm!(
        "push {{r4, r5, r6, r7, lr}}",
        "push {{r0, r1, r2}}",
        "sub sp, #28",
        "movs r7, r0",
        // d = |area| in [sp + 0]; the area's sign mask in r6.
        "ldr r0, [r7, #{area}]",
        "ldr r1, [r7, #{area} + 4]",
        "asrs r6, r1, #31",
        "eors r0, r6",
        "eors r1, r6",
        "subs r0, r0, r6",
        "sbcs r1, r6",
        "cmp r1, #0",
        "beq 1f",
        "b 90f",
        "1:",
        "subs r2, r0, #1",
        "movs r3, #1",
        "lsls r3, r3, #29",
        "subs r3, #1",
        "cmp r2, r3",
        "blo 1f",
        "b 90f",
        "1:",
        "str r0, [sp, #0]",
        // Unless the triangle's sides are known short, the four the numerators take are
        // tested (out of line).
        "movs r0, #{short}",
        "ldrb r0, [r7, r0]",
        "cmp r0, #0",
        "bne 81f",
        "b 80f",
        "81:",
        // The depth differences, signed as the area.
        "ldr r0, [r7, #{z}]",
        "ldr r1, [r7, #{z} + 4]",
        "ldr r2, [r7, #{z} + 8]",
        "subs r1, r1, r0",
        "subs r2, r2, r0",
        "eors r1, r6",
        "subs r1, r1, r6",
        "eors r2, r6",
        "subs r2, r2, r6",
        "str r1, [sp, #4]",
        "str r2, [sp, #8]",
        // nx = dv₁·dy₂ − dv₂·dy₁ at sp + 12, ny = dv₂·dx₁ − dv₁·dx₂ at sp + 20.
        numerator!("4", "20", "12", "12", []),
        numerator!("0", "8", "16", "20", ["ldr r1, [sp, #8]", "ldr r2, [sp, #4]"]),
        // d in r7, below in r5, the reciprocal in r6 (`ShortQuotients::new`).
        "ldr r7, [sp, #0]",
        "movs r0, r7",
        divisor!(top_left),
        // sx at sp + 4, sy in r0.
        step!("12"),
        "str r0, [sp, #4]",
        step!("20"),
        // The reference pixel and the row: r1 = sx, r0 = sy.
        "ldr r1, [sp, #4]",
        "ldr r7, [sp, #28]",
        "ldr r2, [r7, #{p}]",
        "ldr r3, [r7, #{p} + 4]",
        // dx = 8 − (x₀ & 15) in r4, x_r in r2; y_r in r3, dy = 16·y_r + 8 − y₀ in r5.
        "lsls r4, r2, #28",
        "lsrs r4, r4, #28",
        "rsbs r4, r4, #0",
        "adds r4, #8",
        "asrs r2, r2, #4",
        "movs r5, r3",
        "adds r3, #7",
        "asrs r3, r3, #4",
        "lsls r6, r3, #4",
        "adds r6, #8",
        "subs r5, r6, r5",
        "str r2, [sp, #8]",
        "str r3, [sp, #12]",
        // whole = (sx >> 4)·dx + (sy >> 4)·dy in r6, low = (sx & 15)·dx + (sy & 15)·dy in r7.
        "asrs r6, r1, #4",
        "muls r6, r4, r6",
        "asrs r7, r0, #4",
        "muls r7, r5, r7",
        "adds r6, r6, r7",
        "lsls r7, r1, #28",
        "lsrs r7, r7, #28",
        "muls r4, r7, r4",
        "lsls r7, r0, #28",
        "lsrs r7, r7, #28",
        "muls r5, r7, r5",
        "adds r4, r4, r5",
        "adds r4, #8",
        "asrs r4, r4, #4",
        "adds r6, r6, r4",
        // row = 2·z₀ + LOOP_HALF_STEP + offset + sy·(y − y_r) − sx·x_r.
        "ldr r7, [sp, #28]",
        "ldr r4, [r7, #{z}]",
        "lsls r4, r4, #1",
        "adds r6, r6, r4",
        "ldr r4, ={half_step}",
        "adds r6, r6, r4",
        "ldr r4, [sp, #32]",
        "ldr r5, [sp, #12]",
        "subs r4, r4, r5",
        "muls r4, r0, r4",
        "adds r6, r6, r4",
        "ldr r4, [sp, #8]",
        "muls r4, r1, r4",
        "subs r6, r6, r4",
        "ldr r2, [sp, #36]",
        "str r6, [r2, #{row_z}]",
        "str r1, [r2, #{step_x}]",
        "str r0, [r2, #{step_y}]",
        "movs r0, #1",
        "add sp, #40",
        "pop {{r4, r5, r6, r7, pc}}",
        "80:",
        short_side!("0", "8"),
        short_side!("4", "12"),
        short_side!("0", "16"),
        short_side!("4", "20"),
        "b 81b",
        "90:",
        "movs r0, #0",
        "add sp, #40",
        "pop {{r4, r5, r6, r7, pc}}",
        ".ltorg",
        area = const offset_of!(ScreenTriangle, area),
        z = const offset_of!(ScreenTriangle, z),
        p = const offset_of!(ScreenTriangle, p),
        short = const offset_of!(ScreenTriangle, short_sides),
        zeros = sym BYTE_ZEROS,
        reciprocals = sym RECIPROCALS,
        half_step = const LOOP_HALF_STEP,
        row_z = const offset_of!(RowBlock, row_z),
        step_x = const offset_of!(RowBlock, step_x),
        step_y = const offset_of!(RowBlock, step_y),
    )
}
