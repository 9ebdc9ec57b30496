//! x86-64's hand-written code, with the `asm` feature (with thumb1.rs, thumb2.rs and
//! asm_rows.rs the only `unsafe` code of the crate; without the feature the crate forbids
//! it): the u16 depth row loop of solid-coloured triangles, the vertex loop, the triangle
//! walk's skip of back faces and the edges' floor division, each below.
//!
//! A whole triangle's rows, both runs (above and below its middle vertex), in one block of
//! assembly on the block `asm_rows::solid_rows` fills in ([`RowBlock`]), as on the Cortex-M
//! cores. An edge is the walk the compiled loop steps (`FractionStepper`: its value in the
//! high half of one 64-bit word, one addition a row); both walks lie in one SSE2 register,
//! their steps in another, so that one `paddq` steps both (5 instructions a row for the two
//! span ends, where the walks in two general registers took 6: 0.64%). A row takes 13
//! instructions (both edges, two unsigned comparisons of the span's ends with the target's
//! columns, a span that crosses a side clamped out of line, the depth walk and the row
//! address), 10 in the windows' loop for a triangle within the columns (one comparison: 0.3%,
//! the test a triangle included; each end by one `pextrw`, the low word of its walk's high
//! half, which holds it whole: 1.4%; the test by the sign of i = x0 − x1, below); the first
//! row's colour address, the buffers' distance, the colour and the depth walk come in
//! registers (`asm_rows::LoopStart`), where each was a store and a load a triangle through the
//! block (1.0%); the compiled row loop took about 45 a row, 52 with pixels,
//! moving its edges, clip columns and buffers between the stack and registers around the pixel
//! loop and entering its unrolled pixel loop. The first form (14 a row, 7 instructions a
//! fragment and 2 more where it wins, against the compiled loop's 10.2) took the reference
//! frame 10% fewer instructions (1.660 M → 1.493 M).
//!
//! A span takes its cells eight at a time in SSE2, x86-64's baseline, wherever the buffers
//! hold 7 cells after the triangle's rows (all but a triangle on their last row, which takes
//! the pixel loop below): the window of eight cells from the span's first read, merged and
//! written back whole (the cells beyond the span unchanged), its depths from the walk
//! broadcast and the steps to each lane, the test by a signed comparison of words less 2¹⁵,
//! the depths written the lesser of each pair, the colours merged under the winning lanes: 21
//! instructions a window (19 for a whole one) and 4 to enter the span, about 25 for the
//! torus' span where the pixel loop took about 40, and 17 more a triangle to set up its
//! registers: the reference frame 3.5% fewer instructions (1.175 M → 1.134 M). The windows'
//! rows keep the depth walk as the lanes of a row's first window at column 0 (`xmm13`, stepped
//! down a row by one `paddd`), so that a span's lanes are those plus the step to its first
//! cell broadcast, and a window's high lanes its low ones plus four steps: one instruction a
//! window fewer; for a triangle within the columns the row's test is the sign of i = x0 − x1,
//! which the span needs anyway (one a row fewer): 0.9% together (1.025 M → 1.016 M).
//! Strictly nearer and uncounted, the lanes that lose are found by `pcmpeqw` of the lesser
//! depth with the stored one, and the colours merged as `new ^ ((new ^ old) & loses)`, which
//! needs no copy of the old ones (0.8%: 19 instructions a window, 18 for a whole one, 8 to
//! enter a span). Counted, each
//! span's length is added on entry and each window's winning lanes to a register's words
//! (one instruction a window), summed once a triangle: the counted frame 2.8% fewer than
//! through the pixel loop (1.185 M → 1.152 M). The pixel loop takes two pixels a turn, the
//! second at the next cells' displacement, so that the turn's index step and branch serve
//! both: 5 instructions a fragment, 2 more where it wins, and 2 a turn; a span of odd length
//! takes its first pixel apart, 4 more.
//!
//! It computes exactly what the Rust loops compute: the same span ends (the same walks' high
//! halves, clamped to the same columns), the same depths (`acc >> 15`, below 2¹⁶ since every
//! value lies in [0, 2³¹)), the same test on the same stored depth, the same stores and
//! counts. The host's tests run it with the feature (`.ci/run`): every golden image and
//! every rasteriser test over a [`ColorDepth`](super::ColorDepth) with u16 depth, the
//! reference frame counted and not, and asm_rows.rs's own tests against the loops'
//! definition (both middle-vertex sides, both clamps, a band's first row, ties, counts,
//! buffers with and without the cells after the rows, random triangles' spans of every
//! length over stored depths near their own) and of what the set-up refuses.
//!
//! The vertex loop of an object known inside every clip plane in words
//! ([`project_known_in_words`], as on the Cortex-M cores): the transform's four rows by 64-bit
//! products, the quotients by w as `div_round_word` and `fraction_in_words` take them, each
//! result stored as it is found (the depth and the zero word after it by one store of its
//! 64-bit quotient): 83 instructions a vertex where the compiled loop took about 92. The
//! host's tests run it under every golden image with the feature.
//!
//! The floor division of an edge's packed quotients ([`floor_divide`], for
//! `raster::packed_quotient32`): one `cqo` and `idiv` and the correction of the truncation by
//! the remainder's sign, where the compiled unsigned form tests for 32-bit operands and turns
//! the sign twice (the frame 0.3% fewer instructions); checked against the two-division
//! quotient by the raster's tests with the feature.
//!
//! The triangle walk's skip of back faces (`FrontFaces::next_stop`, on the walk's state in
//! asm_faces.rs): for an object inside every clip plane culled to its front faces, each
//! triangle's indices, points and signed area in one loop of assembly that stops only on a
//! triangle to draw or one of zero area. The same classification as the Rust walk's (the same
//! area, the same sign and zero tests), checked by the host's tests with the feature (every
//! golden image, every count the pipeline's tests assert): 24 instructions a back face where
//! the compiled walk took about 50, the reference frame 3.3% fewer instructions (1.233 M →
//! 1.193 M). A front face's corners leave the block in registers (each x and y as one qword),
//! where they were copied to memory for the call that filled it: with that triangle's set-up
//! in line in the walk (`Prepared::fill_face`) they stay in registers, the frame 2.3% fewer
//! instructions (1.082 M → 1.056 M).

use core::mem::{offset_of, size_of};

use super::asm_faces::FrontFaces;
use super::asm_rows::{LoopStart, RowBlock, EDGE};
use super::depth::{DepthTest, FragmentCount};
use crate::math::{Mat4, Vec3};
use crate::pipeline::{FaceStop, ScreenVertex};
use crate::raster::{Runs, ScreenPoint};

/// One pixel of the pixel loop, at the cells `2·i` bytes past `d` and `c` and `$at` more: its
/// depth from the walk `acc`, which steps, tested against the stored one; a fragment that
/// loses branches by `$fail` (`jae` or `ja`) to `$to`.
macro_rules! pixel {
    ($at:literal, $fail:literal, $to:literal) => {
        concat!(
            "mov {x0:e}, {acc:e}\n",
            "shr {x0:e}, 15\n",
            "add {acc:e}, dword ptr [{s} + {step_x}]\n",
            "cmp {x0:x}, word ptr [{d} + 2 * {i}",
            $at,
            "]\n",
            $fail,
            " ",
            $to,
            "\n",
            "mov word ptr [{d} + 2 * {i}",
            $at,
            "], {x0:x}\n",
            "mov word ptr [{c} + 2 * {i}",
            $at,
            "], {col:x}",
        )
    };
}

/// A span's pixels one at a time, as `rows_loop!`'s span: `$fail` the branch taken by a
/// fragment that loses (`jae`: strictly nearer wins; `ja`: nearer or equal) and where it goes
/// from each of the pixel loop's three places (a span's odd first pixel, then the two of a
/// turn): past the pixel, or to the count's path for it; then the count's instructions before
/// the pixel loop and after it (none uncounted). Two pixels a turn, the depth in x0; a span
/// of odd length takes its first pixel apart (i = −n has n's parity).
macro_rules! pixels {
    ($fail:literal, [$odd:literal, $first:literal, $second:literal], [$($before:literal),*],
     [$($after:literal),*]) => {
        concat!(
            $($before, "\n",)*
            "test {i:l}, 1\n",
            "jz 6f\n",
            pixel!("", $fail, $odd), "\n",
            "17:\n",
            "add {i}, 1\n",
            "jz 28f\n",
            "6:\n",
            pixel!("", $fail, $first), "\n",
            "7:\n",
            pixel!(" + 2", $fail, $second), "\n",
            "27:\n",
            "add {i}, 2\n",
            "jnz 6b\n",
            "28:\n",
            $($after, "\n",)*
        )
    };
}

/// Eight cells of a span at once in SSE2 (x86-64's baseline), as `rows_loop!`'s span for
/// buffers that hold 7 cells more than the triangle's rows (`windows`): the window of the
/// eight cells from `c + 2·i` (both buffers', `d` the depths') read, merged and written back
/// whole. `$depths` puts the walk at its cells less 2³⁰ in `xmm1`'s lanes (cells 0 to 3) and
/// `$high`'s (4 to 7), `acc + k·step_x` from the first four in `xmm0` and four steps in each
/// lane (`xmm9`); shifted down by 15 and packed to words, they are the loop's
/// depths less 2¹⁵ (every value in [0, 2³¹) within the span, so that no lane of the span
/// saturates): the signed order of words is the unsigned depths' order. `$cells` then takes
/// the lanes beyond the span out (`pmaxsw` by [`WINDOW_BOUNDS`]' window: 0x7FFF there, no
/// stored depth less 2¹⁵ above it) and, for `or_equal`, leaves the span's lanes in `xmm4`
/// (the bounds' sign). The stored depths, taken down by 2¹⁵ the same way ([`WORD_BIAS`]):
/// a lane wins where the stored one is greater (`less`: `pcmpgtw`, which a lane beyond the
/// span never passes) or where the new one is not (`or_equal`: `pandn` of the reverse, with
/// the span's lanes). The depths written are the lesser of each pair (the new where it wins,
/// the stored elsewhere, beyond the span too), the colours `old ^ ((old ^ new) & wins)`
/// (`xmm12` the triangle's).
macro_rules! window {
    ($less:tt, $count:tt, [$($depths:literal),*], $high:literal, [$($cells:expr),*]) => {
        concat!(
            $($depths, "\n",)*
            "psrad xmm1, 15\n",
            "psrad ", $high, ", 15\n",
            "packssdw xmm1, ", $high, "\n",
            $($cells, "\n",)*
            "movdqu xmm3, xmmword ptr [{d} + 2 * {i}]\n",
            "pxor xmm3, xmmword ptr [rip + {bias}]\n",
            merge!($less, $count),
        )
    };
}

/// `window!`'s test, depths and colours, the new depths in `xmm1` and the stored ones in
/// `xmm3` (both less 2¹⁵). Strictly nearer and uncounted: the depths written the lesser of
/// each pair (`pminsw`), the lanes that lose those where that is the stored one (`pcmpeqw`:
/// a new depth not below it, as every lane beyond the span's is), and the colours
/// `new ^ ((new ^ old) & loses)`, which needs no copy of the old ones (one instruction a
/// window fewer than by the winning lanes: the reference frame 0.9% fewer instructions).
/// Otherwise by the winning lanes (`xmm5`, which the count sums): where the stored depth is
/// greater (`less`) or where the new one is not (`or_equal`, with the span's lanes), the
/// colours `old ^ ((old ^ new) & wins)`.
macro_rules! merge {
    (less, uncounted) => {
        concat!(
            "movdqa xmm5, xmm3\n",
            "pminsw xmm1, xmm3\n",
            "pcmpeqw xmm5, xmm1\n",
            "pxor xmm1, xmmword ptr [rip + {bias}]\n",
            "movdqu xmmword ptr [{d} + 2 * {i}], xmm1\n",
            "movdqu xmm2, xmmword ptr [{c} + 2 * {i}]\n",
            "pxor xmm2, xmm12\n",
            "pand xmm2, xmm5\n",
            "pxor xmm2, xmm12\n",
            "movdqu xmmword ptr [{c} + 2 * {i}], xmm2\n",
        )
    };
    ($less:tt, $count:tt) => {
        concat!(
            if_less!(
                $less,
                "movdqa xmm5, xmm3\npcmpgtw xmm5, xmm1",
                "movdqa xmm5, xmm1\npcmpgtw xmm5, xmm3\npandn xmm5, xmm4"
            ),
            "\n",
            "pminsw xmm1, xmm3\n",
            "pxor xmm1, xmmword ptr [rip + {bias}]\n",
            "movdqu xmmword ptr [{d} + 2 * {i}], xmm1\n",
            "movdqu xmm2, xmmword ptr [{c} + 2 * {i}]\n",
            "movdqa xmm1, xmm12\n",
            "pxor xmm1, xmm2\n",
            "pand xmm1, xmm5\n",
            "pxor xmm1, xmm2\n",
            "movdqu xmmword ptr [{c} + 2 * {i}], xmm1\n",
            if_counted!($count, "paddw xmm15, xmm5\n", ""),
        )
    };
}

/// `$yes` where `$count` is `counted`, else (`uncounted`) `$no`.
macro_rules! if_counted {
    (counted, $yes:literal, $no:literal) => {
        $yes
    };
    (uncounted, $yes:literal, $no:literal) => {
        $no
    };
}

/// `$yes` where `$less` is `less`, else (`or_equal`) `$no` (`window!`'s two depth tests).
macro_rules! if_less {
    (less, $yes:literal, $no:literal) => {
        $yes
    };
    (or_equal, $yes:literal, $no:literal) => {
        $no
    };
}

/// A span in windows of eight cells (`window!`): the walk at its first four cells in `xmm0`
/// (the row's lanes at column 0, `xmm13`, plus `x0 · step_x` broadcast: `x0` holds that product
/// on entry); while more than eight cells are left (i < −8) a whole window, the walk then
/// eight steps on (`xmm11`, eight times `step_x` in each lane); then the last window, its
/// lanes those of the cells left, and on to the next row.
macro_rules! windows {
    ($less:tt, $count:tt) => {
        concat!(
            if_counted!($count, "sub dword ptr [{s} + {frag}], {i:e}\n", ""),
            "movd xmm0, {x0:e}\n",
            "pshufd xmm0, xmm0, 0\n",
            "paddd xmm0, xmm13\n",
            "cmp {i}, -8\n",
            "jge 41f\n",
            "40:\n",
            window!(
                $less,
                $count,
                ["movdqa xmm1, xmm0", "movdqa xmm2, xmm0", "paddd xmm2, xmm9"],
                "xmm2",
                [if_less!($less, "", "pcmpeqw xmm4, xmm4")]
            ),
            "paddd xmm0, xmm11\n",
            "add {i}, 8\n",
            "cmp {i}, -8\n",
            "jl 40b\n",
            "41:\n",
            window!(
                $less,
                $count,
                ["movdqa xmm1, xmm0", "paddd xmm0, xmm9"],
                "xmm0",
                [
                    "movdqu xmm4, xmmword ptr [{col} + 2 * {i}]",
                    "pmaxsw xmm1, xmm4",
                    if_less!($less, "", "psraw xmm4, 15")
                ]
            ),
        )
    };
}

/// What `windows!` keeps in registers for a whole triangle, after `rows_loop!`'s own set-up:
/// the colour's two bytes in each word of `xmm12`, four steps (`4 · step_x`) in each lane of
/// `xmm9` and eight in each of `xmm11`, the depth walk less 2³⁰ (so is every lane then) at
/// columns 0 to 3 of the row in `xmm13` (`rowz` broadcast plus `k · step_x` for k from 0 to 3,
/// `[0, s, s, s] + [0, 0, s, s] + [0, 0, 0, s]`, the step broadcast and shifted up by lanes),
/// its step down a row in each lane of `xmm10`, and `col` the address of [`WINDOW_BOUNDS`]'
/// end.
macro_rules! windows_setup {
    () => {
        concat!(
            "movd xmm12, {col:e}\n",
            "pshuflw xmm12, xmm12, 0\n",
            "pshufd xmm12, xmm12, 0\n",
            "movd xmm8, dword ptr [{s} + {step_x}]\n",
            "pshufd xmm8, xmm8, 0\n",
            "movdqa xmm9, xmm8\n",
            "pslld xmm9, 2\n",
            "pslldq xmm8, 4\n",
            "movdqa xmm11, xmm8\n",
            "pslldq xmm11, 4\n",
            "paddd xmm11, xmm8\n",
            "pslldq xmm8, 8\n",
            "paddd xmm8, xmm11\n",
            "movdqa xmm11, xmm9\n",
            "paddd xmm11, xmm11\n",
            "sub {rowz:e}, 0x40000000\n",
            "movd xmm13, {rowz:e}\n",
            "pshufd xmm13, xmm13, 0\n",
            "paddd xmm13, xmm8\n",
            "movd xmm10, dword ptr [{s} + {step_y}]\n",
            "pshufd xmm10, xmm10, 0\n",
            "lea {col}, [rip + {lanes} + 16]\n",
        )
    };
}

/// 0x8000 in each of eight words, aligned for `pxor`'s operand: the depths' bias.
static WORD_BIAS: Aligned = Aligned([0x8000; 8]);

/// Sixteen bytes on a 16-byte boundary (SSE2's memory operands but loads and stores).
#[repr(C, align(16))]
struct Aligned([u16; 8]);

/// Eight words of 0x8000 (the least word), then eight of 0x7FFF (the greatest): the 16 bytes
/// ending `2n` bytes before its end hold the first for a window's first `n` lanes (n from 0 to
/// 8) and the second for the rest.
static WINDOW_BOUNDS: [u16; 16] = [
    0x8000, 0x8000, 0x8000, 0x8000, 0x8000, 0x8000, 0x8000, 0x8000, 0x7FFF, 0x7FFF, 0x7FFF, 0x7FFF,
    0x7FFF, 0x7FFF, 0x7FFF, 0x7FFF,
];

/// `rows_loop!`'s ends and test of a row's span: each end the high half of its walk (32-bit
/// moves clear the high halves), the walks stepped; pixels where 0 ≤ x0 < x1 ≤ width, by two
/// unsigned comparisons (a negative end is a large unsigned one); a span that crosses a side
/// of the buffers is clamped to them out of line (the clamps in line took two instructions a
/// row more); then i = x0 − x1 (its label 13, where the clamp of x0 comes back).
macro_rules! clamped_test {
    () => {
        concat!(
            "pshufd xmm14, xmm6, 0x0D\n",
            "paddq xmm6, xmm7\n",
            "movd {x0:e}, xmm14\n",
            "psrlq xmm14, 32\n",
            "movd {x1:e}, xmm14\n",
            "cmp {x1:e}, dword ptr [{s} + {width}]\nja 31f\n3:\ncmp {x0:e}, {x1:e}\njae 12f\n",
            "13:\nmov {i}, {x0}\nsub {i}, {x1}",
        )
    };
}

/// `rows_loop!`'s ends and test of a row's span for a triangle within the columns (every span
/// end in `0..=width` before any clamp, `within_columns`, and width below 2¹⁶): each end the
/// low word of its walk's high half, zero-extended by `pextrw` (the whole end, which lies in
/// [0, 2¹⁶)), the walks stepped; pixels where x0 < x1, that is where i = x0 − x1 (of two
/// zero-extended words) is negative. Two instructions a row fewer than `clamped_test!`'s
/// ends (the reference frame 1.4% fewer instructions), and one fewer for the test by the
/// sign of i, which a span needs anyway.
macro_rules! within_test {
    () => {
        concat!(
            "pextrw {x0:e}, xmm6, 2\n",
            "pextrw {x1:e}, xmm6, 6\n",
            "paddq xmm6, xmm7\n",
            "mov {i}, {x0}\nsub {i}, {x1}\njge 4f",
        )
    };
}

/// The row loop in assembly: `$test` a row's span ends and test (`clamped_test!` or
/// `within_test!`, which leave i = x0 − x1 for a span with pixels), `$setup` after the
/// block's values are loaded, `$span` a span's pixels (from its cells `c + 2·i` and
/// `d + 2·i`, i from x0 − x1 to 0, `x0` holding `x0 · step_x`, the step from the row's
/// column 0 to its first cell), `$rowstep` the depth walk's step down a row, `$paths` out of
/// line and `$finish` at the end; then the block's address and the loop's own operands. A
/// row: each edge's span end (the high half of its walk, which then steps), the span's test,
/// and where it holds pixels the span; then the depth walk and the row address step down. At the end of the first run the
/// lower short edge takes its side, and the second run goes on to `last`.
macro_rules! rows_loop {
    ($test:expr, [$($setup:expr),*], $span:expr, $rowstep:expr, [$($paths:expr),*],
     [$($finish:expr),*]; $block:expr, $($extra:tt)*) => {
        core::arch::asm!(
            // The first row's colour address, the depth walk, the colour and the distance
            // from the colour buffer to the depth buffer in registers (`LoopStart`); the two
            // edges' walks.
            "movq xmm6, qword ptr [{s}]",
            "movhps xmm6, qword ptr [{s} + {right}]",
            "movq xmm7, qword ptr [{s} + 8]",
            "movhps xmm7, qword ptr [{s} + {right} + 8]",
            $($setup,)*
            "2:",
            // The span's ends (each its walk's high half: both walks in xmm6, left then right,
            // their steps in xmm7), the walks stepped, and the span's test.
            // With pixels, i = x0 − x1 (0 ≤ x0 < x1, both zero-extended: the 64-bit
            // difference is negative).
            $test,
            // The step to the depth at x0; both buffers addressed from their cell x1, i from
            // x0 − x1 to 0.
            "imul {x0:e}, dword ptr [{s} + {step_x}]",
            "lea {c}, [{cptr} + 2 * {x1}]",
            "lea {d}, [{c} + {delta}]",
            $span,
            "4:",
            // Next row: the depth walk and the row address; the run ends at `end`.
            $rowstep,
            "add {cptr}, qword ptr [{s} + {stride}]",
            "cmp {cptr}, qword ptr [{s} + {end}]",
            "jne 2b",
            // The last run ends at `last`; before it, the lower short edge takes its side:
            // its walk and its step that side's lanes.
            "mov {x0}, qword ptr [{s} + {last}]",
            "cmp {cptr}, {x0}",
            "je 5f",
            "mov qword ptr [{s} + {end}], {x0}",
            "cmp qword ptr [{s} + {slot}], 0",
            "jne 9f",
            "movlps xmm6, qword ptr [{s} + {lower}]",
            "movlps xmm7, qword ptr [{s} + {lower} + 8]",
            "jmp 2b",
            "9:",
            "movhps xmm6, qword ptr [{s} + {lower}]",
            "movhps xmm7, qword ptr [{s} + {lower} + 8]",
            "jmp 2b",
            // x1 beyond the last column, or left of column 0 (then no pixels).
            "31:",
            "test {x1:e}, {x1:e}",
            "js 4b",
            "mov {x1:e}, dword ptr [{s} + {width}]",
            "jmp 3b",
            // x0 ≥ x1 unsigned with 0 ≤ x1 ≤ width: no pixels, unless x0 is negative and
            // x1 positive (the span from column 0).
            "12:",
            "test {x0:e}, {x0:e}",
            "jns 4b",
            "test {x1:e}, {x1:e}",
            "jz 4b",
            "xor {x0:e}, {x0:e}",
            "jmp 13b",
            $($paths,)*
            "5:",
            $($finish,)*
            s = in(reg) $block.0, cptr = inout(reg) $block.1.row => _,
            rowz = inout(reg) u64::from($block.1.row_z as u32) => _,
            col = inout(reg) u64::from($block.1.bits) => _,
            delta = inout(reg) $block.1.delta => _, x0 = out(reg) _, x1 = out(reg) _,
            i = out(reg) _, c = out(reg) _, d = out(reg) _,
            right = const EDGE, lower = const 2 * EDGE,
            width = const offset_of!(RowBlock, width), step_x = const offset_of!(RowBlock, step_x),
            step_y = const offset_of!(RowBlock, step_y), stride = const offset_of!(RowBlock, stride),
            end = const offset_of!(RowBlock, end), last = const offset_of!(RowBlock, last),
            slot = const offset_of!(RowBlock, slot),
            out("xmm6") _, out("xmm7") _, out("xmm14") _,
            $($extra)*
            options(nostack),
        )
    };
}

/// `rows_loop!` a pixel at a time: `$fail` and the places and count instructions of
/// [`pixels!`], and the count's path for a fragment that loses from each place (none
/// uncounted).
macro_rules! pixel_rows {
    ($fail:literal, $places:tt, $before:tt, $after:tt, [$($path:literal)?]; $block:expr,
     $($extra:tt)*) => {
        rows_loop!(clamped_test!(), [],
            concat!("lea {acc:e}, [{x0} + {rowz}]\n", pixels!($fail, $places, $before, $after)),
            "add {rowz:e}, dword ptr [{s} + {step_y}]",
            [$(concat!("22:\n", $path, "\njmp 7b\n23:\n", $path, "\njmp 17b\n24:\n", $path,
                "\njmp 27b"))?], [];
            $block, acc = out(reg) _, $($extra)*)
    };
}

/// `rows_loop!` in windows of eight cells (`windows!`), for `$less`'s depth test, `$test`'s
/// rows, and `counted` or not: counted, each span's length added to the fragments on entry,
/// each window's winning lanes to `xmm15`'s words (less one for each: `paddw` of the mask),
/// and once a triangle the failures found from them (`windows_count!`).
macro_rules! window_rows {
    ($less:tt, $test:expr, uncounted; $block:expr) => {
        rows_loop!($test, [windows_setup!()], windows!($less, uncounted), "paddd xmm13, xmm10",
            [], []; $block,
            lanes = sym WINDOW_BOUNDS, bias = sym WORD_BIAS,
            out("xmm0") _, out("xmm1") _, out("xmm2") _, out("xmm3") _, out("xmm4") _,
            out("xmm5") _, out("xmm8") _, out("xmm9") _, out("xmm10") _, out("xmm11") _,
            out("xmm12") _, out("xmm13") _,)
    };
    ($less:tt, $test:expr, counted; $block:expr) => {
        rows_loop!($test, [windows_setup!(), "pxor xmm15, xmm15"], windows!($less, counted),
            "paddd xmm13, xmm10",
            [], [windows_count!()]; $block,
            lanes = sym WINDOW_BOUNDS, bias = sym WORD_BIAS,
            frag = const offset_of!(RowBlock, fragments),
            out("xmm0") _, out("xmm1") _, out("xmm2") _, out("xmm3") _, out("xmm4") _,
            out("xmm5") _, out("xmm8") _, out("xmm9") _, out("xmm10") _, out("xmm11") _,
            out("xmm12") _, out("xmm13") _, out("xmm15") _,)
    };
}

/// A counted triangle's failures from its windows' count of winning lanes (`xmm15`, each
/// word less one for every win in its lane: at most 2¹⁵ of them, see `asm_rows::run_cells`):
/// the words summed in pairs by `pmaddwd` with ones (signed: each word in [−2¹⁵, 0]), the
/// four sums summed, and the fragments (each span's length, added on entry) less the wins.
macro_rules! windows_count {
    () => {
        concat!(
            "pcmpeqw xmm1, xmm1\n",
            "psrlw xmm1, 15\n",
            "pmaddwd xmm15, xmm1\n",
            "pshufd xmm1, xmm15, 0x4E\n",
            "paddd xmm15, xmm1\n",
            "pshufd xmm1, xmm15, 0xB1\n",
            "paddd xmm15, xmm1\n",
            "movd {x0:e}, xmm15\n",
            "add {x0:e}, dword ptr [{s} + {frag}]\n",
            "mov dword ptr [{s} + {frag} + 4], {x0:e}",
        )
    };
}

// The edges lie at the block's start, one edge's size apart, each its walk then its step.
const _: () = assert!(offset_of!(RowBlock, runs) == 0 && offset_of!(Runs, edges) == 0);
const _: () = assert!(EDGE == 16);
// The counts lie one word apart.
const _: () = assert!(offset_of!(RowBlock, failed) == offset_of!(RowBlock, fragments) + 4);

/// The windows of eight cells have a loop without the clamps (`within_test!`: one
/// comparison a row, not `clamped_test!`'s two), for triangles within the columns (see
/// `asm_rows::solid_rows`): the reference frame 0.3% fewer instructions. The loops a pixel
/// at a time clamp every row.
pub(super) const WITHOUT_CLAMPS: bool = true;

/// The rows of a triangle in `block` (see [`RowBlock`]) through `rows_loop!`, the fragments
/// counted when `K` counts; with `windows` in windows of eight cells (`window_rows!`, without
/// the clamps unless `clamp`), else a pixel at a time (`pixel_rows!`, which clamp every
/// row).
///
/// # Safety
/// `block` and `start` keep [`RowBlock`]'s contract (without `clamp`, every span end within
/// `0..=width`); with `windows`, the 7 cells after the rows' last (`last` and on, in both
/// buffers) are held by the caller mutably too.
#[inline(always)]
#[allow(unsafe_code)]
pub(super) unsafe fn rows<T: DepthTest, K: FragmentCount>(
    block: &mut RowBlock,
    (clamp, windows, start): (bool, bool, LoopStart),
) {
    // The block, and the values the loop takes in registers (`cptr`, `delta`, `col`, `rowz`).
    let block = (block as *mut RowBlock, start);
    // SAFETY (the caller keeps `RowBlock`'s contract with `start`, and with `windows` holds
    // the 7 cells after the rows too):
    // - Memory: row k (0 ≤ k < rows) starts at cell k·width of the colour cells at `row`
    //   (`cptr` steps by a row's bytes, `stride`). A row's pixels are touched only where
    //   0 ≤ x0 < x1 ≤ width: two unsigned comparisons pass only then (x1 ≤ width as
    //   unsigned, so 0 ≤ x1 < 2³¹, and x0 < x1 as unsigned, so x0 ≥ 0), and otherwise the
    //   out-of-line paths clamp x1 to width (only where it is positive) or x0 to 0 (only
    //   where x1 > 0) before the same test, or skip the row; without `clamp` (windows only)
    //   both ends lie in 0..=width (the contract), below 2¹⁶ (`RowBlock`'s width is), so
    //   that the low words of the walks' high halves, zero-extended, are the ends whole,
    //   and one comparison of x0 < x1 passes only where 0 ≤ x0 < x1 ≤ width. With c the address of the
    //   row's cell x1 and d = c + delta the same cell of the depth cells, a pixel at a time
    //   the loop touches the u16s at c + 2i and d + 2i for i from x0 − x1 to −1 (a turn of
    //   two pixels takes i and i + 1 only while i + 2 ≤ 0, the count left being even):
    //   cells k·width + x for x0 ≤ x < x1, below rows·width, which the caller holds
    //   mutably. In windows it reads and writes the eight u16s from c + 2i and d + 2i for i
    //   from x0 − x1, by eight while i < −8, then once for −8 ≤ i ≤ −1: cells k·width + x
    //   for x0 ≤ x < x1 + 7 ≤ width + 7, below rows·width + 7, which the caller holds with
    //   `windows`. It also reads `block` (borrowed mutably) and the statics WORD_BIAS
    //   (aligned to 16, as `pxor` needs) and the 16 bytes of WINDOW_BOUNDS from 2i bytes
    //   before its end (−8 ≤ i ≤ −1: within it), and writes `end` and, counted, its
    //   counts; nothing else, and no stack (`nostack`).
    // - Values: a depth cell of the span gets a u16, a colour cell `bits`' two low bytes,
    //   those of a valid colour unchanged; a window's cells beyond the span get the two
    //   bytes they held (a lane beyond the span never wins, and its new depth, the greatest
    //   word after `pmaxsw`, leaves the lesser of the pair the stored one). `end` gets the
    //   address `last`, the counts u32s.
    // - Termination: each row ends with i rising to 0 from x0 − x1 ≥ −width, by one for a
    //   span of odd length and then by two, so that it meets 0 exactly (in windows, by
    //   eight to −8 ≤ i ≤ −1, then once). `cptr` rises by `stride` > 0 a row from the first
    //   cell: it meets `end` after `upper` ≥ 1 rows; unless that is `last` (upper = rows),
    //   `end` becomes `last`, which it meets after the other rows ≥ 1.
    // - Registers: every register the block writes is an output (xmm0 to xmm15 among them,
    //   each where its loop writes it); the flags it changes are not preserved, as asm!
    //   allows by default.
    unsafe {
        match (T::OR_EQUAL, K::COUNTED, windows) {
            (false, true, false) => pixel_rows!("jae", ["23f", "22f", "24f"],
                ["sub dword ptr [{s} + {frag}], {i:e}", "mov {x1:e}, dword ptr [{s} + {frag} + 4]"],
                ["mov dword ptr [{s} + {frag} + 4], {x1:e}"], ["add {x1:e}, 1"];
                block, frag = const offset_of!(RowBlock, fragments),),
            (true, true, false) => pixel_rows!("ja", ["23f", "22f", "24f"],
                ["sub dword ptr [{s} + {frag}], {i:e}", "mov {x1:e}, dword ptr [{s} + {frag} + 4]"],
                ["mov dword ptr [{s} + {frag} + 4], {x1:e}"], ["add {x1:e}, 1"];
                block, frag = const offset_of!(RowBlock, fragments),),
            (false, false, false) => pixel_rows!("jae", ["17f", "7f", "27f"], [], [], []; block,),
            (true, false, false) => pixel_rows!("ja", ["17f", "7f", "27f"], [], [], []; block,),
            (false, false, true) if clamp => window_rows!(less, clamped_test!(), uncounted; block),
            (true, false, true) if clamp => {
                window_rows!(or_equal, clamped_test!(), uncounted; block)
            }
            (false, false, true) => window_rows!(less, within_test!(), uncounted; block),
            (true, false, true) => window_rows!(or_equal, within_test!(), uncounted; block),
            (false, true, true) if clamp => window_rows!(less, clamped_test!(), counted; block),
            (true, true, true) if clamp => window_rows!(or_equal, clamped_test!(), counted; block),
            (false, true, true) => window_rows!(less, within_test!(), counted; block),
            (true, true, true) => window_rows!(or_equal, within_test!(), counted; block),
        }
    }
}

/// The walk on x86-64: a back face takes 24 instructions (its three indices loaded, its
/// points sign-extended to 64 bits, the area by two 64-bit multiplies as `doubled_area` takes
/// it, its sign and its zero tested, the count of triangles left stepped), where the compiled
/// walk took about 50, keeping its state on the stack around the call it makes for the faces
/// it draws.
impl<'t> FrontFaces<'t, '_> {
    /// The next triangle that is not a back face, or [`FaceStop::End`]; for a front face its
    /// vertices' positions and depths written to `out`.
    #[inline(always)]
    #[allow(unsafe_code)]
    pub(crate) fn next_stop(&mut self, out: &mut [(ScreenPoint, i32); 3]) -> FaceStop<'t> {
        let stop: u64;
        let area: i64;
        let (xya, za, xyb, zb, xyc, zc): (u64, u64, u64, u64, u64, u64);
        // SAFETY:
        // - Memory: the block reads the three indices of each of the `left` triangles from
        //   `next` (within `triangles`: `next` lies within it or at its end, `left` triangles
        //   before the end, and moves by one triangle as `left` counts down to 0), and the
        //   dwords at `v + 16·i` and `v + 16·i + 4` and (for a front face) the bytes `v + 16·i`
        //   to `v + 16·i + 12` for each index `i` of those triangles: within `vertices`, whose
        //   elements take 16 bytes with x, y and z at 0, 4 and 8 (asserted in asm_faces.rs),
        //   as `i` is below the mesh's number of positions (the invariant of `Mesh`), which is
        //   `vertices.len()` (checked by `FrontFaces::new`). It writes no memory, and no stack
        //   (`nostack`).
        // - Values: `next` leaves at one past the triangle the walk stopped on, or at the end,
        //   `left` as the triangles after it; the corners are any qwords and dwords (read
        //   only after a front face, whose they are).
        // - Registers: every register the block writes is an output; the flags it changes
        //   are not preserved, as asm! allows by default.
        unsafe {
            core::arch::asm!(
                "test {left}, {left}",
                "jz 5f",
                "2:",
                "movzx {ia:e}, word ptr [{t}]",
                "movzx {ib:e}, word ptr [{t} + 2]",
                "movzx {ic:e}, word ptr [{t} + 4]",
                "add {t}, 6",
                "shl {ia:e}, 4",
                "shl {ib:e}, 4",
                "shl {ic:e}, 4",
                // a = (ax, ay), b − a = (ux, uy), c − a = (cx, cy).
                "movsxd {ax}, dword ptr [{v} + {ia}]",
                "movsxd {ay}, dword ptr [{v} + {ia} + 4]",
                "movsxd {ux}, dword ptr [{v} + {ib}]",
                "movsxd {uy}, dword ptr [{v} + {ib} + 4]",
                "movsxd {cx}, dword ptr [{v} + {ic}]",
                "movsxd {cy}, dword ptr [{v} + {ic} + 4]",
                "sub {ux}, {ax}",
                "sub {uy}, {ay}",
                "sub {cx}, {ax}",
                "sub {cy}, {ay}",
                // (b − a).x·(c − a).y − (c − a).x·(b − a).y.
                "imul {ux}, {cy}",
                "imul {cx}, {uy}",
                "sub {ux}, {cx}",
                "jl 3f",
                "je 4f",
                // A back face: the count left stepped, the next face unless none.
                "sub {left}, 1",
                "jnz 2b",
                "5:",
                "mov {ay:e}, {end_}",
                "jmp 9f",
                "4:",
                "mov {ay:e}, {degenerate}",
                "jmp 8f",
                // A front face: its corners' x and y (one qword each) and z, left in registers.
                "3:",
                "mov {ax}, qword ptr [{v} + {ia}]",
                "mov {uy:e}, dword ptr [{v} + {ia} + 8]",
                "mov {ia}, qword ptr [{v} + {ib}]",
                "mov {ib:e}, dword ptr [{v} + {ib} + 8]",
                "mov {cx}, qword ptr [{v} + {ic}]",
                "mov {ic:e}, dword ptr [{v} + {ic} + 8]",
                "mov {ay:e}, {front}",
                // A stop on a face: the count left stepped past it.
                "8:",
                "sub {left}, 1",
                "9:",
                t = inout(reg) self.next,
                left = inout(reg) self.left,
                v = in(reg) self.vertices.as_ptr(),
                ia = out(reg) xyb, ib = out(reg) zb, ic = out(reg) zc,
                ax = out(reg) xya, ay = out(reg) stop, ux = out(reg) area,
                uy = out(reg) za, cx = out(reg) xyc, cy = out(reg) _,
                front = const FaceStop::FRONT,
                degenerate = const FaceStop::DEGENERATE,
                end_ = const FaceStop::END,
                options(nostack, readonly),
            );
        }
        // Each corner's qword holds its x (the low dword) and y (the high one), as a vertex's.
        *out = [(xya, za), (xyb, zb), (xyc, zc)].map(|(xy, z)| {
            (
                ScreenPoint::new(xy as u32 as i32, (xy >> 32) as u32 as i32),
                z as u32 as i32,
            )
        });
        self.stopped(stop as u32, area)
    }
}

/// What [`project_known_in_words`]' loop reads: each row of the matrix (w's first, then x's,
/// y's and z's) as its three coefficients and the start of its sums (the translation times
/// 2¹⁶ and half of 2¹⁶), 64-bit words for `imul`'s memory operand, and the viewport's half
/// sizes (sub-pixels).
#[repr(C)]
struct ProjectBlock {
    rows: [[i64; 4]; 4],
    half_w: i32,
    half_h: i32,
}

/// A clip coordinate of the point in `{x}`, `{y}`, `{z}` into `rax`: the row at `$row` of the
/// block at `{m}` as `Mat4::transform_short` takes it (three 64-bit products onto the row's
/// start, shifted down by 16).
macro_rules! clip_row {
    ($row:literal) => {
        concat!(
            "mov rax, {x}\n",
            "imul rax, qword ptr [{m} + ",
            $row,
            "]\n",
            "mov rcx, {y}\n",
            "imul rcx, qword ptr [{m} + ",
            $row,
            " + 8]\n",
            "add rax, rcx\n",
            "mov rcx, {z}\n",
            "imul rcx, qword ptr [{m} + ",
            $row,
            " + 16]\n",
            "add rax, rcx\n",
            "add rax, qword ptr [{m} + ",
            $row,
            " + 24]\n",
            "sar rax, 16\n",
        )
    };
}

/// The coordinate in `eax` times the half size at `$half`, divided by w (`{w}`) and rounded
/// as `div_round_word` rounds it: the magnitude plus half of w, divided, the sign put back
/// (by the mask `cdq` leaves in `edx`, kept in `{s}`).
macro_rules! rounded_axis {
    ($half:literal) => {
        concat!(
            "imul eax, dword ptr [{m} + ",
            $half,
            "]\n",
            "cdq\n",
            "mov {s:e}, edx\n",
            "xor eax, edx\n",
            "sub eax, edx\n",
            "add eax, {h:e}\n",
            "xor edx, edx\n",
            "div {w:e}\n",
            "xor eax, {s:e}\n",
            "sub eax, {s:e}\n",
        )
    };
}

/// The vertex stage of an object whose every vertex is known inside every clip plane with its
/// projection's operands in words (`Known::InWords`, at the default sub-pixel precision) and
/// no lit colour, on x86-64: each of `positions` through `m` (a matrix whose transform fits
/// 32 bits, `Mat4::fits_32_bits`) into the vertex of `out` at its index, as the vertex loop in
/// Rust computes it (`Mat4::transform_short`, then `outcode_and_project`'s `Known::InWords`
/// path: `x·half_w` and `y·half_h` in words, their quotients by w rounded by
/// `div_round_word`, the depth by `fraction_in_words`, the position from the viewport's
/// centre, no outcode and no colour), in one loop of assembly: 84 instructions a vertex
/// (each product a copy and an `imul`) where the compiled loop took about 92, the reference
/// frame 0.77% fewer (1.113 M → 1.104 M); now 83, the depth and the zero word of `rgb` and
/// `outcode` by one store. Always true: 64-bit products need no bound on the
/// positions' extent (the Cortex-M4's loop, whose call this shares, declines some).
#[allow(unsafe_code)]
pub(crate) fn project_known_in_words(
    m: &Mat4,
    (half_w, half_h): (i32, i32),
    (positions, _extent): (&[Vec3], u32),
    out: &mut [ScreenVertex],
) -> bool {
    let n = positions.len().min(out.len());
    let [x, y, z, w] = m.to_bits();
    let row = |r: [i32; 4]| {
        [
            i64::from(r[0]),
            i64::from(r[1]),
            i64::from(r[2]),
            (i64::from(r[3]) << 16) + (1 << 15),
        ]
    };
    let block = ProjectBlock {
        rows: [row(w), row(x), row(y), row(z)],
        half_w,
        half_h,
    };
    if n == 0 {
        return true;
    }
    // SAFETY:
    // - Memory: the loop reads the `n` positions from `positions` (12 bytes each, x, y and z
    //   at 0, 4 and 8: asserted below) up to `end`, one past the n-th (within the slice, as
    //   n ≤ its length), and `block` (borrowed for the call); it writes the `n` vertices
    //   from `out` (borrowed mutably, at least `n` long), 16 bytes each: x, y and z at 0, 4
    //   and 8 and the word over `rgb` and `outcode` at 12 (asserted below), the depth and
    //   that word by one store of the depth's 64-bit quotient; no other memory, and no stack
    //   (`nostack`).
    // - Values: every field of a vertex gets a valid value (any `i32`, any bytes). The
    //   word at 12 is zero, as the Rust loop writes it: every vertex lies inside the near
    //   and far planes (0 ≤ z ≤ w, the object known inside every clip plane), so the depth's
    //   quotient, at most 2³⁰ plus one, has a zero high half.
    // - No fault: w is at least 1 (`cmp`/`adc` turn 0 into 1, as `NonZeroU32::new(w)
    //   .unwrap_or(MIN)` does); an axis' dividend, a magnitude at most 2³¹ plus half of w
    //   (below 2³¹), fits 32 bits with edx 0, so its quotient does; the depth's, z's word
    //   times 2³⁰ plus half of w, lies below 2⁶³ with rdx 0.
    // - Termination: the positions' pointer rises by 12 a vertex from the first to `end`,
    //   n ≥ 1 steps.
    // - Registers: every register the block writes is an output; the flags it changes are
    //   not preserved, as asm! allows by default.
    unsafe {
        core::arch::asm!(
            "2:",
            "movsxd {x}, dword ptr [{p}]",
            "movsxd {y}, dword ptr [{p} + 4]",
            "movsxd {z}, dword ptr [{p} + 8]",
            "add {p}, 12",
            clip_row!("0"),
            "mov {w:e}, eax",
            "cmp {w:e}, 1",
            "adc {w:e}, 0",
            "mov {h:e}, {w:e}",
            "shr {h:e}, 1",
            clip_row!("32"),
            rounded_axis!("{half_w}"),
            "add eax, dword ptr [{m} + {half_w}]",
            "mov dword ptr [{o}], eax",
            clip_row!("64"),
            rounded_axis!("{half_h}"),
            "mov ecx, dword ptr [{m} + {half_h}]",
            "sub ecx, eax",
            "mov dword ptr [{o} + 4], ecx",
            clip_row!("96"),
            "mov eax, eax",
            "shl rax, 30",
            "add rax, {h}",
            "xor edx, edx",
            "div {w}",
            // The depth and, in its high half, the zero word of `rgb` and `outcode`.
            "mov qword ptr [{o} + 8], rax",
            "add {o}, 16",
            "cmp {p}, {end}",
            "jb 2b",
            p = inout(reg) positions.as_ptr() => _,
            o = inout(reg) out.as_mut_ptr() => _,
            end = in(reg) positions.as_ptr().wrapping_add(n),
            m = in(reg) &block as *const ProjectBlock,
            x = out(reg) _, y = out(reg) _, z = out(reg) _,
            w = out(reg) _, h = out(reg) _, s = out(reg) _,
            out("rax") _, out("rcx") _, out("rdx") _,
            half_w = const offset_of!(ProjectBlock, half_w),
            half_h = const offset_of!(ProjectBlock, half_h),
            options(nostack),
        );
    }
    true
}

// The layouts `project_known_in_words` reads and writes: the block's rows of 32 bytes, w's
// first, the half sizes after them; points of three words; vertices of 16 bytes with x, y, z
// and a word of `rgb` and `outcode`.
const _: () = {
    assert!(offset_of!(ProjectBlock, half_w) == 128 && offset_of!(ProjectBlock, half_h) == 132);
    assert!(size_of::<Vec3>() == 12);
    assert!(size_of::<ScreenVertex>() == 16 && offset_of!(ScreenVertex, z) == 8);
    assert!(offset_of!(ScreenVertex, rgb) == 12 && offset_of!(ScreenVertex, outcode) == 15);
};

/// `⌊n / d⌋` for a positive `d` (`None` for a negative one), by one `idiv` (which truncates)
/// less one where the remainder is negative, without the compiler's test for operands of 32
/// bits.
#[inline(always)]
#[allow(unsafe_code)]
pub(crate) fn floor_divide(n: i64, d: core::num::NonZeroI64) -> Option<i64> {
    if d.get() < 0 {
        return None;
    }
    let (q, r): (i64, i64);
    // SAFETY: `idiv` of rdx:rax = n sign-extended (`cqo`) by d ≥ 1: the quotient's magnitude
    // is at most |n| ≤ 2⁶³, and −2⁶³ is a quotient only of n = −2⁶³ by 1, which fits; nothing
    // faults. Only the registers named are written.
    unsafe {
        core::arch::asm!(
            "cqo",
            "idiv {d}",
            d = in(reg) d.get(),
            inout("rax") n => q,
            out("rdx") r,
            options(pure, nomem, nostack),
        );
    }
    // Truncated toward zero: a negative remainder (n < 0, inexact) takes one off.
    Some(q.wrapping_add(r >> 63))
}
