//! The u16 depth loops of solid-coloured triangles in hand-written Thumb-2, for Cortex-M3, M4
//! and M7 (ARMv7-M) and ARMv8-M mainline cores, with the `asm` feature (with thumb1.rs,
//! x86_64.rs and asm_rows.rs the only `unsafe` code of the crate; without the feature the
//! crate forbids it).
//!
//! The pixel loop: nine instructions a pixel (ten when fragments are counted): the depth from
//! the loop's value by a shift, the stored depth loaded, compared, and both stores predicated
//! in one IT block; one index counts from −n up to 0 and addresses both buffers. The
//! compiler's loop takes twelve or thirteen (a branch over the stores, two pointers and a
//! counter, and the colour reloaded from the stack): the reference frame on the Cortex-M4F
//! 3.8% fewer instructions with it (1.790 M → 1.722 M).
//!
//! On cores with the DSP extension (Cortex-M4 and M7) the row loop takes the pixels of an
//! uncounted span two at a time (`pixel_pairs!`): both depths in one word, both stored depths
//! loaded in one (unaligned where the span starts at an odd column, which ARMv7-M loads and
//! stores do), one `usub16` and two `sel`s for the depths and colours that win, both words
//! stored back (a losing fragment's cells rewritten with their own bytes): 13 instructions
//! for two pixels, a span of odd length its first pixel as before. The reference frame on the
//! Cortex-M4F 4.7% fewer instructions (1.151 M → 1.097 M), 110 bytes more flash.
//!
//! The row loop ([`rows`], on the block `asm_rows::solid_triangle` fills in) around the same pixel
//! loop: a whole triangle, both runs of rows (above and below its middle vertex), in one
//! block of assembly. A row takes 20 instructions (each edge's end by one division of its
//! numerator, the depth walk and the row address; 4 more to clamp the span to the target's
//! columns, for a triangle that crosses its left or right side), 4 more to enter a span
//! (since then 13 a row without the clamps, see below, and 6 to enter a span with pairs),
//! where the compiler's row loop took about 49, moving the row's state between registers and
//! the stack around the pixel loop; here the edges and the constants are read in pairs from
//! one block in memory. Its set-up takes about 60 instructions a triangle more than the
//! compiler's (about 80 with the test of the columns); with it the reference frame on the
//! Cortex-M4F took 3.9% fewer instructions (1.722 M → 1.655 M).
//!
//! The set-up of those rows ([`triangle_runs`]): the sort of the corners, the rows and the three
//! edges of a triangle written into the same block, about 150 instructions a triangle in one block
//! of assembly (about 139 since its edges have no base, below; about 120 since it loads the
//! corners' x once for all three edges and takes the long edge's side from the area's high
//! word: the reference frame on the Cortex-M4F 0.28% and 0.50% fewer instructions, 1.026 M →
//! 1.023 M → 1.018 M; it also writes the lower edge's place into the row loop's block, 1.0%
//! fewer, 1.018 M → 1.007 M), where the compiler's code took
//! about as many but, with the depth walk's set-up
//! beside it, kept more values on the stack: with it the reference frame on the Cortex-M4F took
//! 1.9% fewer instructions (1.301 M → 1.276 M), for about 1.1 KB of flash (the depth walk's set-up
//! in line beside it, and out of line for the triangles it leaves to the general loops), and 1.2%
//! fewer again (1.262 M) with the block not cleared first, the set-up writing every field of its
//! runs. Its output is checked against the Rust set-up on random triangles of every case under
//! emulation (the `variants` preset's `triangles`). Its edges have no base (the column the
//! Rust stepper subtracts to keep its numerator unsigned): the numerator is signed, `N + D − 1`
//! in a word for every triangle of the pipeline, and the rows divide it signed, which rounds
//! toward zero where the floor is wanted only for a negative numerator, whose end (−1 or
//! less, or 0 for −1 by that rounding) the clamps take to 0 or to an empty span all the same:
//! 18 instructions an edge where the base took 27, 2 a row fewer (no base to add), the
//! reference frame 2.8% fewer instructions (in two steps, the first folding only bases from 0
//! up). The row loop without the clamps keeps the run's end in the register the clamped loop
//! gives the width: one load a row fewer, 0.6% (with the edges, 1.097 M → 1.059 M).
//!
//! The edges' words interleave ([`RunEdges`]: both numerators, both steps, both
//! denominators, then the lower edge's), so that a row loads both edges with one `ldm` and
//! stores both numerators back with one `strd`: 6 instructions for both span ends where two
//! `ldrd`s, two loads, two additions, two stores and the divisions took 10. A row takes 13
//! instructions (18 clamped), the lower edge's switch one more; the reference frame on the
//! Cortex-M4F 2.9% fewer instructions (1.059 M → 1.029 M), 32 bytes less flash. `ldm` wants
//! its registers in ascending order, so the row loop names r0 to r5 itself.
//!
//! Both loops compute exactly what the Rust loops compute: the same span ends (divisions of
//! numerators with the same quotients, clamped to the same columns, or already within them), the
//! same depths (`acc >> 15`, below 2¹⁶ since every value lies in [0, 2³¹)), the same test on
//! the same stored depth (zero-extended to 32 bits in both), the same stores and counts. The
//! row loop's runs are [`Runs`], whose walk a host test checks against the Rust row loops; the
//! firmware presets' frame hashes, equal to the host's, check both loops under emulation
//! (`bench/mcu/run.sh`, in CI): the `variants` preset each of the four forms (depth test ×
//! counted), on ties too, and spans clamped to the target's columns (its `clipped`
//! configuration), `bands` a band's first row other than 0.
//!
//! The depth walk's set-up of a small triangle ([`depth_walk`]: a doubled area below 2¹⁷
//! square sub-pixels): its numerators, its two steps and its row's start at column 0 in one
//! block of assembly, about 90 instructions a triangle where the compiled set-up took about 105
//! (with its paths for every size in line beside it; the others now take it out of line). The
//! same arithmetic as `RoundedRows::new`, step by step; checked under emulation by every
//! preset's hash (the torus takes both of its paths for the steps), the `variants` preset's
//! `triangles` and `front` with their depths (both windings): the reference frame on the
//! Cortex-M4F 1.4% fewer instructions (1.167 M → 1.151 M), 310 bytes less flash.
//!
//! The triangle walk's skip of back faces (`FrontFaces::next_stop`, on the walk's state in
//! asm_faces.rs): for an object inside every clip plane culled to its front faces, each
//! triangle's indices, points and signed area in one loop of assembly that stops only on a
//! triangle to draw (its corners copied for the call that fills it) or one of zero area. The
//! same classification as the Rust walk's (the same area, the same sign and zero tests),
//! checked under emulation by the `variants` preset's `front` (random triangles of both
//! windings and of zero area, every count in its hash): 22 instructions a back face (21 since
//! its area is taken in words) where the compiled walk took about 49, the reference frame on
//! the Cortex-M4F 3.4% fewer instructions (1.262 M → 1.219 M), 370 bytes more flash; a front
//! face's corners copied by one `ldm` and one `stm` each since, 0.48% fewer again (0.9995 M
//! → 0.9947 M).
//!
//! The vertex loop of an object known inside every clip plane with its projection in words
//! ([`project_known_in_words`], a naked function): the transform, the projection and the
//! depth of each vertex in 65 instructions, the matrix read from a block by `ldm` (one
//! instruction a row) where the compiled loop took about 125, loading it from the stack for
//! each vertex. The same arithmetic as `transform_short`, `div_round_word` and
//! `fraction_by_digits`, step by step; checked under emulation by every preset's hash (the
//! tori of `full`, `variants`, `bands`, `display`), the `variants` preset's `front` with its
//! depths: the reference frame on the Cortex-M4F 4.1% fewer instructions (1.219 M →
//! 1.170 M), 420 bytes more flash. Since then 61 instructions a vertex: the block's rows are
//! scaled by `2^(16 − shift)` and each point by `2^shift` as it is loaded (three shifts), so
//! that each clip coordinate is its sum's high word where it took two instructions to take
//! the sum's bits 16 to 47 (`ProjectBlock`; the same values for every shift, which a
//! mutation of the shift confirms under emulation): 0.57% fewer (1.0055 M → 0.9999 M).

use core::mem::{align_of, offset_of, size_of};

use super::asm_faces::FrontFaces;
use super::asm_rows::{first_row, sorted_keys, RowBlock};
use super::depth::{DepthTest, FragmentCount, RoundedRows, LOOP_HALF_STEP};
use super::surface::ScreenTriangle;
use crate::math::{Mat4, Vec3};
use crate::pipeline::{FaceStop, ScreenVertex};
use crate::raster::{RunEdges, Runs, ScreenPoint};

/// One pixel of `pixels!` (its arguments), before the index steps: the depth from the walk,
/// which steps, tested against the stored one, both stores where the fragment wins.
#[rustfmt::skip]
macro_rules! one_pixel {
    ([$z:literal, $o:literal, $st:literal, $d:literal, $c:literal], $it:literal, $pass:literal) => {
        concat!(
            "lsr ", $z, ", {acc}, #15\n",
            "ldrh ", $o, ", [", $d, ", {i}, lsl #1]\n",
            "add {acc}, ", $st, "\n",
            "cmp ", $z, ", ", $o, "\n",
            $it, " ", $pass, "\n",
            "strh", $pass, " ", $z, ", [", $d, ", {i}, lsl #1]\n",
            "strh", $pass, " {col}, [", $c, ", {i}, lsl #1]\n",
        )
    };
}

/// The pixel loop's instructions as one template: from label `$l`, with the registers (each
/// as the template writes it: `{name}` for an operand, or a register's own name) of the depth
/// `$z`, the stored depth `$o`, the step `$st`, the depth and colour cells `$d` and `$c` (and a
/// free one `$b`, which only `pixel_pairs!` uses; the others named `acc`, `i`, `col`); `$it`
/// the IT block (`itt`, or `itte` with the failure count), `$pass` the condition where the
/// fragment wins (`lo`: strictly nearer; `ls`: nearer or equal), then the failure count's
/// instruction if any. One index counts from −n up to 0 and addresses both buffers, from
/// their cells n (`$d` and `$c`); the loop ends where it reaches 0.
macro_rules! pixels {
    ($l:literal, [$z:literal, $o:literal, $st:literal, $d:literal, $c:literal, $b:literal],
     $it:literal, $pass:literal, [$($count:literal)?]) => {
        concat!(
            $l, ":\n",
            one_pixel!([$z, $o, $st, $d, $c], $it, $pass),
            $($count, "\n",)?
            "adds {i}, {i}, #1\n",
            "bne ", $l, "b",
        )
    };
}

/// The row loop's pixels two at a time, for uncounted fragments on cores with the DSP
/// extension (Cortex-M4 and M7): the same arguments as `pixels!` (the count none), `$b` for
/// the flags' result. A span of odd length takes its first pixel as
/// `pixels!` does (then ends if it had one); each pair then takes both depths in one word
/// (the second's from the walk's next value, bits 15 to 30 into the high half by `pkhbt`),
/// both stored depths in one (a word load at any halfword: ARMv7-M loads and stores words
/// unaligned), one `usub16` whose flags say, per half, where the stored depth stays, and
/// one `sel` each for the depths and the colours (`col` holds the colour in both halves),
/// both words stored back: 13 instructions for two pixels where `pixels!` takes 18. A
/// fragment that loses writes back the cells' own bytes.
#[cfg(fixed3d_dsp)]
macro_rules! pixel_pairs {
    // `usub16 b, x, y` sets each half's GE flag where x ≥ y, and each `sel` takes there the
    // value paired with y (the depth, or its colour), elsewhere the one paired with x. For `lo`
    // x is the new depth and y the stored one: the stored depth and colour stay where the new
    // depth is not nearer. For `ls` x is the stored depth and y the new one: the new depth and
    // the colour win where the new depth is nearer or equal.
    ($l:literal, [$z:literal, $o:literal, $st:literal, $d:literal, $c:literal, $b:literal],
     $it:literal, "lo", []) => {
        pixel_pairs!(@ [$z, $o, $st, $d, $c, $b], $it, "lo", [$z, $o], ["{col}", $o])
    };
    ($l:literal, [$z:literal, $o:literal, $st:literal, $d:literal, $c:literal, $b:literal],
     $it:literal, "ls", []) => {
        pixel_pairs!(@ [$z, $o, $st, $d, $c, $b], $it, "ls", [$o, $z], [$o, "{col}"])
    };
    (@ [$z:literal, $o:literal, $st:literal, $d:literal, $c:literal, $b:literal], $it:literal,
     $pass:literal, [$x:literal, $y:literal], [$cx:literal, $cy:literal]) => {
        concat!(
            "tst {i}, #1\n",
            "beq 6f\n",
            one_pixel!([$z, $o, $st, $d, $c], $it, $pass),
            "adds {i}, {i}, #1\n",
            "beq 7f\n",
            "6:\n",
            "lsr ", $z, ", {acc}, #15\n",
            "add {acc}, ", $st, "\n",
            "pkhbt ", $z, ", ", $z, ", {acc}, lsl #1\n",
            "add {acc}, ", $st, "\n",
            "ldr ", $o, ", [", $d, ", {i}, lsl #1]\n",
            "usub16 ", $b, ", ", $x, ", ", $y, "\n",
            "sel ", $z, ", ", $y, ", ", $x, "\n",
            "str ", $z, ", [", $d, ", {i}, lsl #1]\n",
            "ldr ", $o, ", [", $c, ", {i}, lsl #1]\n",
            "sel ", $o, ", ", $cy, ", ", $cx, "\n",
            "str ", $o, ", [", $c, ", {i}, lsl #1]\n",
            "adds {i}, {i}, #2\n",
            "bne 6b\n",
            "7:",
        )
    };
}

/// The row loop's pixel loop for uncounted fragments: two at a time where the core has the DSP
/// extension's halfword instructions (`pixel_pairs!`), one at a time elsewhere (`pixels!`).
#[cfg(fixed3d_dsp)]
macro_rules! uncounted_pixels {
    ($($args:tt)*) => { pixel_pairs!($($args)*) };
}
/// The row loop's pixel loop for uncounted fragments (see the DSP cores' definition).
#[cfg(not(fixed3d_dsp))]
macro_rules! uncounted_pixels {
    ($($args:tt)*) => { pixels!($($args)*) };
}

/// The pixel loop in assembly (`pixels!`), then the operands.
macro_rules! span_loop {
    ($it:literal, $pass:literal, [$($count:literal)?], $($operands:tt)*) => {
        core::arch::asm!(
            pixels!("2", ["{z}", "{o}", "{st}", "{d}", "{c}", ""], $it, $pass, [$($count)?]),
            $($operands)*
        )
    };
}

/// Depth-tests a span whose every pixel has the colour whose two bytes
/// [`color_bits`](super::asm_rows::color_bits) gave as `bits` (so `C` has 2 bytes and alignment
/// 2): the loop's value `acc` (in [0, 2³¹) at every pixel, see `DepthFormat::unclamped`)
/// stepped by `st`. Returns the failures so far: `failed` plus the span's, when `K` counts
/// them.
#[inline(always)]
#[allow(unsafe_code)]
pub(super) fn solid_span<C: Copy, T: DepthTest, K: FragmentCount>(
    depths: &mut [u16],
    colors: &mut [C],
    acc: u32,
    st: u32,
    bits: u32,
    failed: u32,
) -> u32 {
    let n = depths.len().min(colors.len());
    // The size and alignment are `color_bits`' conditions, which gave `bits`: checked again
    // here, where the block relies on them (a constant test, compiled away).
    if n == 0 || size_of::<C>() != 2 || align_of::<C>() != 2 {
        return failed;
    }
    // One past the last pixel of each buffer's first n cells (in bounds or one past the end:
    // no pointer leaves its allocation), and −n: the loop visits indices n − n .. n − 1.
    let d = depths.as_mut_ptr().wrapping_add(n);
    let c = colors.as_mut_ptr().wrapping_add(n);
    let mut i = n.wrapping_neg();
    let (mut acc, mut f) = (acc, failed);
    // SAFETY:
    // - Memory: the loop reads and writes the halfwords at d + 2i and c + 2i for i from −n to
    //   −1, that is cells 0 to n − 1 of `depths` and of `colors` (2 bytes each, aligned to 2),
    //   which this function borrows mutably (n ≤ both lengths, n ≥ 1); it touches nothing
    //   else, and no stack (`nostack`).
    // - Values: a depth cell gets a u16 (any bit pattern is one). A colour cell gets `bits`,
    //   the two bytes of a valid `C` (see `asm_rows::color_bits`) unchanged: a byte-for-byte
    //   copy of a valid value is the same valid value, exactly what `*cell = color` stores.
    // - Termination: i starts at −n (n < 2³¹ for a slice of 2-byte cells on a 32-bit core)
    //   and rises by one to 0, where the loop ends; `acc` wraps by definition (it never does
    //   for the values the caller passes).
    // - Registers: every register the block writes is an output (`z`, `o`, `acc`, `i`, `f`);
    //   the flags it changes are not preserved, as asm! allows by default.
    unsafe {
        match (T::OR_EQUAL, K::COUNTED) {
            (false, true) => span_loop!("itte", "lo", ["addhs {f}, {f}, #1"],
                z = out(reg) _, o = out(reg) _, acc = inout(reg) acc, st = in(reg) st,
                d = in(reg) d, c = in(reg) c, i = inout(reg) i, f = inout(reg) f,
                col = in(reg) bits, options(nostack)),
            (true, true) => span_loop!("itte", "ls", ["addhi {f}, {f}, #1"],
                z = out(reg) _, o = out(reg) _, acc = inout(reg) acc, st = in(reg) st,
                d = in(reg) d, c = in(reg) c, i = inout(reg) i, f = inout(reg) f,
                col = in(reg) bits, options(nostack)),
            (false, false) => span_loop!("itt", "lo", [],
                z = out(reg) _, o = out(reg) _, acc = inout(reg) acc, st = in(reg) st,
                d = in(reg) d, c = in(reg) c, i = inout(reg) i,
                col = in(reg) bits, options(nostack)),
            (true, false) => span_loop!("itt", "ls", [],
                z = out(reg) _, o = out(reg) _, acc = inout(reg) acc, st = in(reg) st,
                d = in(reg) d, c = in(reg) c, i = inout(reg) i,
                col = in(reg) bits, options(nostack)),
        }
    }
    let _ = (acc, i);
    f
}

/// The row loop in assembly: `clamped` or `within` (spans clamped to `0..width`, or known to
/// lie within it), `$it` and `$pass` as in `pixels!`, then the count's instructions before the
/// pixel loop, in it, and after it (none uncounted), then the block's address and the counts'
/// operands if any. The block's fields at their offsets (`const` operands), first the first
/// row's colour address, the depth walk and the colour. A row: both edges' numerators, steps
/// and denominators by one `ldm` (the layout of [`RunEdges`]), each edge's span end by one
/// signed division, both numerators stepped and stored back as a pair, the span clamped to
/// `0..width` if `clamped`, and where it holds pixels the depth at its first one and the
/// pixel loop; then the depth walk and the row address step down. At the end of the first run
/// the lower short edge takes its side, and the second run goes on to `last`.
///
/// The `ldm` needs its six registers in ascending order: r0 to r5, named in the template
/// itself (an operand the compiler places cannot be), each with one use: r0 and r1 the
/// numerators, then temporaries (`a`, `b` before); r2 and r3 the steps, then the span's cells
/// (`c`, `d`); r4 and r5 the denominators, then the span's ends (`x0`, `x1`). The other seven
/// (the block, the row's colour address and depth, the colour, the index, the depth walk,
/// the run's end or the width) take the registers left (r6, r8 to r12, lr).
macro_rules! rows_loop {
    // x0 = max(x0, 0), x1 = min(x1, width), the width in a register of its own (the M4's
    // frame 0.44% fewer instructions than loaded each row); the run's end loaded from the
    // block each row.
    (clamped [$($width:tt)*] $($rest:tt)*) => {
        rows_loop!(["bic r4, r4, r4, asr #31", "cmp r5, {w}", "it gt",
                    "movgt r5, {w}"], [], ["ldr r0, [{s}, #{end}]", "cmp {cptr}, r0"],
                   ["str r0, [{s}, #{end}]"] [w = in(reg) $($width)*,] $($rest)*)
    };
    // The run's end in the register the width takes in the other loop (the M4's frame 0.6%
    // fewer instructions).
    (within [$($width:tt)*] $($rest:tt)*) => {
        rows_loop!([], ["ldr {e}, [{s}, #{end}]"], ["cmp {cptr}, {e}"],
                   ["mov {e}, r0"] [e = out(reg) _,] $($rest)*)
    };
    ([$($clamp:literal),*],
     [$($end_init:literal)?], [$($end_cmp:literal),*], [$set_end:literal]
     [$($width:tt)*] $it:tt, $pass:tt,
     [$($before:literal),*], [$($count:literal)?], [$($after:literal)?], $pixels:ident;
     $block:expr $(, $extra:ident = const $value:expr)*) => {
        core::arch::asm!(
            // The first row's colour address, the depth walk and the colour from the block
            // (in both halves of its register, for `pixel_pairs!`).
            "ldr {cptr}, [{s}, #{row}]",
            "ldr {rowz}, [{s}, #{row_z}]",
            "ldr {col}, [{s}, #{bits}]",
            "orr {col}, {col}, {col}, lsl #16",
            $($end_init,)?
            "2:",
            // Both ends: numerator / denominator, signed; the numerators step.
            "ldm {s}, {{r0, r1, r2, r3, r4, r5}}",
            "sdiv r4, r0, r4",
            "sdiv r5, r1, r5",
            "add r0, r2",
            "add r1, r3",
            "strd r0, r1, [{s}]",
            // The clamps if any; no pixels unless x0 < x1 (signed).
            $($clamp,)*
            "subs {i}, r4, r5",
            "bge 4f",
            // The depth at x0; both buffers addressed from their cell x1, i from x0 − x1 to 0.
            "ldrd r0, r1, [{s}, #{step_x}]",
            "mla {acc}, r0, r4, {rowz}",
            "add r2, {cptr}, r5, lsl #1",
            "add r3, r2, r1",
            $($before,)*
            // The pixel loop: the depth in r4, the stored depth in r5, the step in r0.
            $pixels!("3", ["r4", "r5", "r0", "r3", "r2", "r1"], $it, $pass, [$($count)?]),
            $($after,)?
            "4:",
            // Next row: the depth walk and the row address; the run ends at `end`.
            "ldrd r0, r1, [{s}, #{step_y}]",
            "add {rowz}, r0",
            "add {cptr}, r1",
            $($end_cmp,)*
            "bne 2b",
            // The last run ends at `last`; before it, the lower short edge takes its side
            // (`slot`: its numerator's offset, and its step and denominator two and four
            // words on).
            "ldrd r0, r1, [{s}, #{last}]",
            "cmp {cptr}, r0",
            "beq 5f",
            $set_end,
            "add r1, {s}",
            "ldrd r2, r3, [{s}, #{lower}]",
            "str r2, [r1]",
            "str r3, [r1, #8]",
            "ldr r2, [{s}, #{lower} + 8]",
            "str r2, [r1, #16]",
            "b 2b",
            "5:",
            s = in(reg) $block as *mut RowBlock, cptr = out(reg) _, rowz = out(reg) _,
            col = out(reg) _, i = out(reg) _, acc = out(reg) _,
            out("r0") _, out("r1") _, out("r2") _, out("r3") _, out("r4") _, out("r5") _,
            lower = const RunEdges::LOWER,
            step_x = const offset_of!(RowBlock, step_x),
            step_y = const offset_of!(RowBlock, step_y), end = const offset_of!(RowBlock, end),
            last = const offset_of!(RowBlock, last), row = const offset_of!(RowBlock, row),
            row_z = const offset_of!(RowBlock, row_z), bits = const offset_of!(RowBlock, bits),
            $($extra = const $value,)*
            $($width)*
            options(nostack),
        )
    };
}

// The edges' words lie at the block's start (`RunEdges`).
const _: () = assert!(offset_of!(RowBlock, runs) == 0 && offset_of!(Runs, edges) == 0);

/// This core has loops without the clamps to the columns, for triangles within them (see
/// `asm_rows::solid_triangle`).
pub(super) const WITHOUT_CLAMPS: bool = true;

/// The rows of a triangle in `block` (see [`RowBlock`]) through `rows_loop!`, the fragments
/// counted when `K` counts, the spans clamped to the columns if `clamp`.
///
/// # Safety
/// `block` keeps [`RowBlock`]'s contract.
#[inline(always)]
#[allow(unsafe_code)]
pub(super) unsafe fn rows<T: DepthTest, K: FragmentCount>(block: &mut RowBlock, clamp: bool) {
    // SAFETY (the caller keeps `RowBlock`'s contract):
    // - Memory: row k (0 ≤ k < rows) starts at cell k·width of the colour cells at `row`
    //   (`cptr` steps by a row's bytes, `stride`). A row's span is clamped to x0 ≥ 0 and
    //   x1 ≤ width with `clamp`, and lies within them without (the contract), and is
    //   touched only where x0 < x1: the halfwords at c + 2i and d + 2i for i
    //   from x0 − x1 to −1, with c the address of the row's cell x1 and d = c + delta the same
    //   cell of the depth cells: cells k·width + x for x0 ≤ x < x1, below rows·width, which
    //   the caller holds mutably. (The pairs of `pixel_pairs!` load and store the words at
    //   c + 2i and d + 2i only while i ≤ −2, so both halves are cells of the span; ARMv7-M
    //   loads and stores words at any halfword address in normal memory, as the buffers
    //   are.) It also reads `block` (borrowed mutably), and writes its
    //   edges' numerators (its first two words), the lower edge's three words over those of
    //   the edge at `slot` (0 or 4: the words at slot, slot + 8 and slot + 16 of `RunEdges`,
    //   all within its nine), `end` (with the clamps: without them the run's end waits in a
    //   register) and, counted, its counts; nothing else, and no stack (`nostack`).
    // - Values: a depth cell gets a u16, a colour cell `bits`, the two bytes of a valid colour
    //   unchanged, or (in a pair) its own two bytes; an edge's words get copies of the lower
    //   edge's or a new numerator (any u32), `end` the
    //   address `last`, the counts u32s.
    // - Division: every denominator is 16·dy of an edge with rows, positive and below 2²⁰
    //   (`triangle_runs`), so never 0, and no quotient overflows (only −2³¹ / −1 would).
    // - Termination: each row ends with i rising to 0 from x0 − x1 ≥ −width, by one, or in
    //   pairs by two from an even value only (an odd one first takes a single pixel). `cptr`
    //   rises by `stride` > 0 a row from the first cell: it meets `end` after `upper` ≥ 1
    //   rows; unless that is `last` (upper = rows), `end` becomes `last`, which it meets
    //   after the other rows ≥ 1.
    // - Registers: every register the block writes is an output; the flags it changes are
    //   not preserved, as asm! allows by default.
    let width = block.width;
    unsafe {
        macro_rules! by_test_and_count {
            ($clamp:ident $width:tt) => {
                match (T::OR_EQUAL, K::COUNTED) {
                    (false, true) => rows_loop!($clamp $width "itte", "lo",
                        ["ldrd r4, r1, [{s}, #{frag}]", "sub r4, r4, {i}",
                         "str r4, [{s}, #{frag}]"],
                        ["addhs r1, r1, #1"], ["str r1, [{s}, #{frag} + 4]"], pixels;
                        block, frag = const offset_of!(RowBlock, fragments)),
                    (true, true) => rows_loop!($clamp $width "itte", "ls",
                        ["ldrd r4, r1, [{s}, #{frag}]", "sub r4, r4, {i}",
                         "str r4, [{s}, #{frag}]"],
                        ["addhi r1, r1, #1"], ["str r1, [{s}, #{frag} + 4]"], pixels;
                        block, frag = const offset_of!(RowBlock, fragments)),
                    (false, false) => {
                        rows_loop!($clamp $width "itt", "lo", [], [], [], uncounted_pixels; block)
                    }
                    (true, false) => {
                        rows_loop!($clamp $width "itt", "ls", [], [], [], uncounted_pixels; block)
                    }
                }
            };
        }
        if clamp {
            by_test_and_count!(clamped[width])
        } else {
            by_test_and_count!(within [])
        }
    }
}

/// One edge of [`triangle_runs`]: the walk of a [`DivideStepper`](crate::raster::DivideStepper)
/// of the edge from the point of key `$p` and x `$xp` to that of key `$q` and x `$xq` (sorted:
/// `p.y ≤ q.y`) at the row whose sample line is `$r` (16·row + 8), its numerator in `t2`,
/// its step in `t3` and its denominator in `t4`, which the instructions `$store` store (they
/// may use `ye`, free by then; see [`RunEdges`] for where), as `edge_by_division` computes it
/// with its base `b` taken as 0: `dx = q.x − p.x`, `dy = q.y − p.y`, the numerator
/// `(p.x − 8)·dy + dx·t + D − 1` (as `p.x·dy + dx·t + 8·dy − 1`) with `t = r − p.y` and
/// `D = 16·dy`, the step `16·dx`, modulo 2³². That is `N + D − 1` for the edge's own numerator
/// `N` (`ceil(N / D)` its span end on the row), and it lies in a word, signed, on every row
/// the edge walks: `N + D − 1` lies in `[x·D, (x + 1)·D)` for the end `x`, within ±2¹¹ (its
/// corners within ±2¹⁵), and `D` is below 2²⁰, so within ±(2¹¹ + 1)·(2²⁰ − 512), inside
/// ±2³¹. The row loop divides it signed (`sdiv`): the floor, that end, where it is 0 or
/// more; toward zero, at most one above the floor and never above 0, where it is negative.
/// Temporaries `t2` to `t4` and `ye`.
macro_rules! edge {
    ($xp:literal, $xq:literal, $p:literal, $q:literal, $r:literal, [$($store:literal),*]) => {
        concat!(
            // dx and dy; p.x·dy + dx·t + 8·dy − 1, which is (p.x − 8)·dy + dx·t + D − 1.
            "sub {t3}, {", $xq, "}, {", $xp, "}\n",
            "asr {t4}, {", $q, "}, #2\n",
            "sub {t4}, {t4}, {", $p, "}, asr #2\n",
            "mul {t2}, {", $xp, "}, {t4}\n",
            "sub {ye}, {", $r, "}, {", $p, "}, asr #2\n",
            "mla {t2}, {t3}, {ye}, {t2}\n",
            "add {t2}, {t2}, {t4}, lsl #3\n",
            "sub {t2}, {t2}, #1\n",
            // D and the step.
            "lsl {t4}, {t4}, #4\n",
            "lsl {t3}, {t3}, #4\n",
            $($store, "\n",)*
        )
    };
}

/// In [`triangle_runs`], the sorted points' x, for the edges: a's into `p` (the points'
/// address, last used here), b's into `t1`, c's into `xc` (each at `p + 8·(key & 3)`).
#[rustfmt::skip]
macro_rules! sorted_xs {
    () => {
        concat!(
            "and {t2}, {kc}, #3\n",
            "ldr {xc}, [{p}, {t2}, lsl #3]\n",
            "and {t2}, {kb}, #3\n",
            "ldr {t1}, [{p}, {t2}, lsl #3]\n",
            "and {t2}, {ka}, #3\n",
            "ldr {p}, [{p}, {t2}, lsl #3]\n",
        )
    };
}

/// In [`triangle_runs`], the keys in `$a` and `$b` (operands, as `"{ka}"`) swapped where
/// `$a`'s is the greater, and the long edge's side (`side`) turned with them.
#[rustfmt::skip]
macro_rules! swap_if_greater {
    ($a:literal, $b:literal) => {
        concat!(
            "cmp ", $a, ", ", $b, "\n",
            "itttt gt\n",
            "movgt {t1}, ", $a, "\n",
            "movgt ", $a, ", ", $b, "\n",
            "movgt ", $b, ", {t1}\n",
            "eorgt {side}, {side}, #4\n",
        )
    };
}

/// `TriangleRows::runs` (the other cores') of [`rows_in_range`] in one block of
/// assembly, for the points `p` (within ±[`PIPELINE_LIMIT`], a [`ScreenTriangle`]'s), whose
/// doubled signed area `area` is not 0 (so its sign is its high word's), in the rows
/// `y0..y1`: written into `block`'s runs, every field of them, and the first row returned;
/// `rows` is 0 (and nothing else written) where the triangle covers none of those rows. About 120
/// instructions a triangle (the sort 28 with the long edge's side, the rows 21, the split row
/// 15, the corners' x 6, an edge 15 with its stores; with an edge of 27, about 150, it took
/// the reference frame 1.9% fewer instructions than the compiler's set-up, with the depth
/// walk set up in line after it: see the module's documentation).
///
/// What it computes, step by step as the Rust does it:
/// - The sort: keys `4·y + i` for the point `i`, sorted by three compare-and-swaps in
///   `sort_by_y`'s order. Its swaps move only points of different y (they compare strictly,
///   so points of equal y keep their order, that of their indices), and so do these: for keys
///   of different y the comparison is theirs, for equal y the smaller index is first already.
///   Each swap turns the long edge's side, as the permutation's parity turns it there.
/// - The rows: first rows `(y + 7) >> 4` (`first_centre_from32`), `y = max(first(a), y0)`,
///   `y_end = min(first(c), y1)`, none unless `y < y_end`, the split row
///   `min(max(first(b), y), y_end)`.
/// - The edges (`edge!`): the long one (a, c) and the short one, (a, b) above the split or
///   (b, c) where the split row is the first; the lower one (b, c) at the split row where it
///   lies strictly between the first and the end, the zero edge otherwise.
///
/// Every denominator is positive: the long edge is used only where `first(a) ≤ y < y_end ≤
/// first(c)`, so `a.y < c.y` (`first` is monotonic); the upper short edge where `y` is below
/// the split row, at most `first(b)`, so `a.y < b.y`; the lower one where the split row is at
/// most `y` or lies below it and is then `first(b)`, in both cases below `y_end`, so `b.y <
/// c.y`. Every difference is below 2¹⁶, so `16·dy` neither wraps nor vanishes.
///
/// [`rows_in_range`]: crate::raster::rows_in_range
/// [`ScreenTriangle`]: super::ScreenTriangle
/// [`PIPELINE_LIMIT`]: crate::raster::PIPELINE_LIMIT
///
/// Where rows are left it also writes the block's `slot`, the lower edge's place: the right
/// edge's (`RunEdges::RIGHT`) where the long edge lies on the left, else the left's (0),
/// from the long edge's side (in Rust from `Runs::lower_is_left`, which this core's runs do
/// not have: the reference frame 1.0% fewer instructions, 1.018 M → 1.007 M).
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
    let mut y = y0;
    // The area's high word: 0 or more for a positive area (it is not 0).
    let side = (area >> 32) as i32;
    // SAFETY:
    // - Memory: the block reads the six words of `p` (borrowed; at offsets 0 to 20 by its
    //   layout, asserted below) and writes words of `block` (valid for writes and unshared,
    //   the caller's contract): its runs' edges' nine words (`RunEdges`), `upper` and `rows`,
    //   and its `slot`; nothing else, and no stack (`nostack`). Point reads are `p + 8·i`
    //   for an index `i = key & 3` of keys made from the indices 0, 1 and 2 and only moved
    //   about.
    // - Values: `u32`s (the edges' words among them) any word, `slot` 0 or 4.
    // - Registers: every register the block writes is an output; the flags it changes are
    //   not preserved, as asm! allows by default.
    unsafe {
        core::arch::asm!(
            // The long edge's side as 4 (left, for a positive area: its words one word before
            // the right's) or 0, which each swap of the sort turns.
            "mvn {side}, {side}, asr #31",
            "and {side}, {side}, #4",
            // Keys 4·y + i, sorted.
            sorted_keys!(swap_if_greater, "{p}", "{ka}", "{kb}", "{kc}"),
            // The first row and the row past the last; none unless rows > 0.
            first_row!("{t1}", "{ka}"),
            "cmp {t1}, {y}",
            "it gt",
            "movgt {y}, {t1}",
            first_row!("{t1}", "{kc}"),
            "cmp {t1}, {ye}",
            "it lt",
            "movlt {ye}, {t1}",
            "subs {t2}, {ye}, {y}",
            "it le",
            "movle {t2}, #0",
            "str {t2}, [{s}, #{rows}]",
            "ble 9f",
            "str {t2}, [{s}, #{upper}]",
            "and {t1}, {side}, #4",
            "str {t1}, [{s}, #{slot}]",
            // The split row.
            first_row!("{t1}", "{kb}"),
            "cmp {t1}, {y}",
            "it lt",
            "movlt {t1}, {y}",
            "cmp {t1}, {ye}",
            "it gt",
            "movgt {t1}, {ye}",
            // At the first row the short edge is the lower one: bit 1 of `side` says so.
            "cmp {t1}, {y}",
            "it eq",
            "orreq {side}, {side}, #2",
            "it ne",
            "cmpne {t1}, {ye}",
            "bne 3f",
            // No split: zeros for the lower edge (never read), y as 16·y + 8.
            "mov {t2}, #0",
            "strd {t2}, {t2}, [{s}, #{lower}]",
            "str {t2}, [{s}, #{lower} + 8]",
            "lsl {y}, {y}, #4",
            "add {y}, {y}, #8",
            sorted_xs!(),
            "b 4f",
            // A split: upper = split − y, and the lower edge at the split row.
            "3:",
            "sub {t2}, {t1}, {y}",
            "str {t2}, [{s}, #{upper}]",
            "lsl {y}, {t1}, #4",
            "add {y}, {y}, #8",
            sorted_xs!(),
            edge!("t1", "xc", "kb", "kc", "y", ["strd {t2}, {t3}, [{s}, #{lower}]",
                                                "str {t4}, [{s}, #{lower} + 8]"]),
            "ldr {t2}, [{s}, #{upper}]",
            "sub {y}, {y}, {t2}, lsl #4",
            // The long edge on its side (left: one word before the right's when bit 2 of
            // `side` is set) and the short one on the other, upper or lower.
            "4:",
            edge!("p", "xc", "ka", "kc", "y", ["and {ye}, {side}, #4", "sub {ye}, {s}, {ye}",
                                                "str {t2}, [{ye}, #4]", "str {t3}, [{ye}, #12]",
                                                "str {t4}, [{ye}, #20]"]),
            "tst {side}, #2",
            "bne 5f",
            edge!("p", "t1", "ka", "kb", "y", ["and {ye}, {side}, #4", "add {ye}, {s}, {ye}",
                                                "str {t2}, [{ye}]", "str {t3}, [{ye}, #8]",
                                                "str {t4}, [{ye}, #16]"]),
            "b 6f",
            "5:",
            edge!("t1", "xc", "kb", "kc", "y", ["and {ye}, {side}, #4", "add {ye}, {s}, {ye}",
                                                "str {t2}, [{ye}]", "str {t3}, [{ye}, #8]",
                                                "str {t4}, [{ye}, #16]"]),
            "6:",
            "sub {y}, {y}, #8",
            "asr {y}, {y}, #4",
            "9:",
            p = inout(reg) p.as_ptr() => _,
            s = in(reg) block,
            side = inout(reg) side => _,
            y = inout(reg) y,
            ye = inout(reg) y1 => _,
            ka = out(reg) _, kb = out(reg) _, kc = out(reg) _,
            t1 = out(reg) _, xc = out(reg) _, t2 = out(reg) _, t3 = out(reg) _, t4 = out(reg) _,
            rows = const offset_of!(Runs, rows),
            upper = const offset_of!(Runs, upper),
            slot = const offset_of!(RowBlock, slot),
            lower = const RunEdges::LOWER,
            options(nostack),
        );
    }
    y
}

/// In [`depth_walk`], the step along one axis from its numerator `$lo`, `$hi` (64 bits, the sign
/// of the area already in it): `⌊(32·|n| + ⌊d/2⌋) / d⌋` with the sign of `n`, into `$lo` (the
/// others named `d`, `q`, `r`, `s`). A numerator that fits a word by two signed divisions
/// (declined to label 8 where the first quotient's magnitude reaches 2²⁵); a longer one at
/// label `$long` (`long_axis_step!`, out of the way), which returns to label `$back`.
#[rustfmt::skip]
macro_rules! axis_step {
    ($lo:literal, $hi:literal, $long:literal, $back:literal) => {
        concat!(
            "cmp {", $hi, "}, {", $lo, "}, asr #31\n",
            "bne ", $long, "f\n",
            "sdiv {q}, {", $lo, "}, {d}\n",
            "mls {r}, {q}, {d}, {", $lo, "}\n",
            "add {", $hi, "}, {q}, #0x2000000\n",
            "lsrs {", $hi, "}, {", $hi, "}, #26\n",
            "bne 8f\n",
            "asr {s}, {", $lo, "}, #31\n",
            "eor {", $hi, "}, {s}, {d}, lsr #1\n",
            "sub {", $hi, "}, {", $hi, "}, {s}\n",
            "add {r}, {", $hi, "}, {r}, lsl #5\n",
            "sdiv {r}, {r}, {d}\n",
            "add {", $lo, "}, {r}, {q}, lsl #5\n",
            $back, ":\n",
        )
    };
}

/// The long numerators of `axis_step!` (from label `$long`, back to `$back`): the magnitude,
/// below 2⁴⁸, by three 15-bit digits of `32·|n| + ⌊d/2⌋` (below 2⁵³; its top digit, below
/// 2²³, and each partial remainder shifted by 15 beside the next digit fit a word since
/// `d < 2¹⁷`), declined where the quotient would reach 2³¹.
#[rustfmt::skip]
macro_rules! long_axis_step {
    ($lo:literal, $hi:literal, $long:literal, $back:literal) => {
        concat!(
            $long, ":\n",
            "asr {s}, {", $hi, "}, #31\n",
            "eor {", $lo, "}, {", $lo, "}, {s}\n",
            "eor {", $hi, "}, {", $hi, "}, {s}\n",
            "subs {", $lo, "}, {", $lo, "}, {s}\n",
            "sbc {", $hi, "}, {", $hi, "}, {s}\n",
            "lsrs {q}, {", $hi, "}, #16\n",
            "bne 8f\n",
            "lsl {", $hi, "}, {", $hi, "}, #5\n",
            "orr {", $hi, "}, {", $hi, "}, {", $lo, "}, lsr #27\n",
            "lsl {", $lo, "}, {", $lo, "}, #5\n",
            "adds {", $lo, "}, {", $lo, "}, {d}, lsr #1\n",
            "adc {", $hi, "}, {", $hi, "}, #0\n",
            "lsl {r}, {", $hi, "}, #2\n",
            "orr {r}, {r}, {", $lo, "}, lsr #30\n",
            "udiv {q}, {r}, {d}\n",
            "cmp {q}, #1\n",
            "bhi 8f\n",
            "mls {r}, {q}, {d}, {r}\n",
            "ubfx {", $hi, "}, {", $lo, "}, #15, #15\n",
            "orr {r}, {", $hi, "}, {r}, lsl #15\n",
            "udiv {", $hi, "}, {r}, {d}\n",
            "mls {r}, {", $hi, "}, {d}, {r}\n",
            "add {q}, {", $hi, "}, {q}, lsl #15\n",
            "ubfx {", $hi, "}, {", $lo, "}, #0, #15\n",
            "orr {r}, {", $hi, "}, {r}, lsl #15\n",
            "udiv {", $hi, "}, {r}, {d}\n",
            "add {", $lo, "}, {", $hi, "}, {q}, lsl #15\n",
            "eor {", $lo, "}, {", $lo, "}, {s}\n",
            "sub {", $lo, "}, {", $lo, "}, {s}\n",
            "b ", $back, "b\n",
        )
    };
}

/// In [`depth_walk`], a numerator into `$lo`, `$hi`: `u·(c₁ − a) + v·(a − c₂)` for the first
/// corner's coordinate `a` and two others' `c₁`, `c₂` (the words at those offsets from the
/// points), the differences `u`, `v` in the registers named, by a widening multiply and a
/// multiply-accumulate (temporaries `r`, `s`).
#[rustfmt::skip]
macro_rules! numerator {
    ($a:literal, $c1:literal, $c2:literal, $u:literal, $v:literal, $lo:literal, $hi:literal) => {
        concat!(
            "ldr {r}, [{t}, #{p} + ", $a, "]\n",
            "ldr {s}, [{t}, #{p} + ", $c1, "]\n",
            "sub {s}, {s}, {r}\n",
            "smull {", $lo, "}, {", $hi, "}, {", $u, "}, {s}\n",
            "ldr {s}, [{t}, #{p} + ", $c2, "]\n",
            "sub {s}, {r}, {s}\n",
            "smlal {", $lo, "}, {", $hi, "}, {", $v, "}, {s}\n",
        )
    };
}

/// `RoundedRows::new` of `triangle`'s depth walk on row `y` (the first row of its runs) in one
/// block of assembly, for a triangle whose doubled area's magnitude lies below 2¹⁷ (every
/// small one): `None` where it declines (a larger triangle, or a step that would not fit a
/// word), and the caller then sets the walk up in Rust, which returns the same walk or `None`.
///
/// What it computes, step by step as the Rust does it (on Cortex-M3/M4: `numerators_as` with
/// sums, `round_shifted_i32`, `rounded_offset`):
/// - The depth differences `z₁ − z₀`, `z₂ − z₀`, negated where the area is negative, so that
///   the numerators (`dv₁·dy₂ + dv₂·(y₀ − y₁)` and `dv₂·dx₁ + dv₁·(x₀ − x₂)`, each by a
///   widening multiply and a multiply-accumulate) are those over the area's magnitude `d`,
///   as `over_positive_area` makes them: negating the depths' differences negates both
///   products (each below 2⁴⁷ in magnitude, the differences within ±2³⁰).
/// - Each step `sx`, `sy` by `axis_step!`: the rounded quotient of 32 times the numerator by
///   `d`, as `round_shifted_i32(n, 5)` rounds it on every path (`shifted_by_short`'s two
///   divisions compute the same quotient as a division of `32·|n| + ⌊d/2⌋`).
/// - The reference pixel `x_r = x₀ >> 4`, `y_r = (y₀ + 7) >> 4`, the centre's offsets
///   `dx = 8 − (x₀ & 15)` and `dy = 16·y_r + 8 − y₀`, the offset `(sx·dx + sy·dy + 8) >> 4`
///   (64-bit, its low word), and the walk's row at column 0
///   `2·z₀ + LOOP_HALF_STEP + offset + sy·(y − y_r) − sx·x_r`, modulo 2³².
///
/// About 90 instructions a triangle, where the compiled set-up took about 105 (see the
/// module's documentation).
#[inline(always)]
#[allow(unsafe_code)]
pub(super) fn depth_walk(triangle: &ScreenTriangle, y: i32) -> Option<RoundedRows<i32>> {
    let (ok, row, sx, sy): (u32, i32, i32, i32);
    // SAFETY:
    // - Memory: the block reads words of `triangle` (borrowed): its points, depths and area at
    //   their `offset_of!` (the points' words in pairs, asserted below); it writes no memory
    //   and no stack (`nostack`).
    // - Values: the outputs are integers (any word is one).
    // - Registers: every register the block writes is an output; the flags it changes are
    //   not preserved, as asm! allows by default.
    unsafe {
        core::arch::asm!(
            // The area's magnitude d, below 2¹⁷ and not 0.
            "ldrd {d}, {t1}, [{t}, #{area}]",
            "cmp {t1}, {d}, asr #31",
            "bne 8f",
            "ldrd {q}, {t1}, [{t}, #{z}]",
            "ldr {t2}, [{t}, #{z} + 8]",
            "sub {t1}, {t1}, {q}",
            "sub {t2}, {t2}, {q}",
            "cmp {d}, #0",
            "ittt lt",
            "rsblt {d}, {d}, #0",
            "rsblt {t1}, {t1}, #0",
            "rsblt {t2}, {t2}, #0",
            "sub {q}, {d}, #1",
            "lsrs {q}, {q}, #17",
            "bne 8f",
            // The numerators: dv₁·dy₂ + dv₂·(y₀ − y₁) and dv₂·dx₁ + dv₁·(x₀ − x₂).
            numerator!("4", "20", "12", "t1", "t2", "xl", "xh"),
            numerator!("0", "8", "16", "t2", "t1", "yl", "yh"),
            // The steps.
            axis_step!("xl", "xh", "2", "3"),
            axis_step!("yl", "yh", "4", "5"),
            // The reference pixel and the row's value at column 0.
            "ldrd {t1}, {t2}, [{t}, #{p}]",
            "and {r}, {t1}, #15",
            "rsb {r}, {r}, #8",
            "asr {t1}, {t1}, #4",
            "add {s}, {t2}, #7",
            "asr {q}, {s}, #4",
            "bic {s}, {s}, #15",
            "sub {s}, {s}, {t2}",
            "add {s}, {s}, #8",
            "smull {xh}, {yh}, {xl}, {r}",
            "smlal {xh}, {yh}, {yl}, {s}",
            "adds {xh}, {xh}, #8",
            "adc {yh}, {yh}, #0",
            "lsr {xh}, {xh}, #4",
            "orr {xh}, {xh}, {yh}, lsl #28",
            "ldr {t2}, [{t}, #{z}]",
            "add {xh}, {xh}, {t2}, lsl #1",
            "add {xh}, {xh}, #{half}",
            "sub {y}, {y}, {q}",
            "mla {xh}, {yl}, {y}, {xh}",
            "mls {y}, {xl}, {t1}, {xh}",
            "mov {d}, #1",
            "b 9f",
            long_axis_step!("xl", "xh", "2", "3"),
            long_axis_step!("yl", "yh", "4", "5"),
            "8:",
            "mov {d}, #0",
            "9:",
            t = in(reg) triangle,
            y = inout(reg) y => row,
            d = out(reg) ok,
            xl = out(reg) sx,
            yl = out(reg) sy,
            xh = out(reg) _, yh = out(reg) _,
            q = out(reg) _, r = out(reg) _, s = out(reg) _,
            t1 = out(reg) _, t2 = out(reg) _,
            p = const offset_of!(ScreenTriangle, p),
            z = const offset_of!(ScreenTriangle, z),
            area = const offset_of!(ScreenTriangle, area),
            half = const LOOP_HALF_STEP,
            options(pure, readonly, nostack),
        );
    }
    (ok != 0).then_some(RoundedRows {
        row,
        step_x: sx,
        step_y: sy,
    })
}

// The layouts `triangle_runs` reads and writes: points of two words (x, y), the edges' nine
// words at the runs' start.
const _: () = {
    assert!(size_of::<ScreenPoint>() == 8 && offset_of!(ScreenPoint, y) == 4);
    assert!(offset_of!(ScreenPoint, x) == 0 && size_of::<RunEdges>() == 36);
    // The long edge's side, 4 where it lies on the left, is the lower edge's `slot` there.
    assert!(RunEdges::RIGHT == 4);
};

// The layout `depth_walk` reads: three points of two words, three words of depth, the area's
// low word then its high one (little-endian), each at a multiple of 4 (for `ldrd`).
const _: () = {
    assert!(size_of::<[ScreenPoint; 3]>() == 24 && size_of::<[i32; 3]>() == 12);
    assert!(offset_of!(ScreenTriangle, p) % 4 == 0 && offset_of!(ScreenTriangle, z) % 4 == 0);
    assert!(offset_of!(ScreenTriangle, area) % 4 == 0 && cfg!(target_endian = "little"));
};

/// One corner of a front face for `FrontFaces`: its vertex (the index at `t + $index`, `t`
/// one past the triangle) copied to `out` as its x, y and z by one `ldm` and one `stm` (into
/// r1 to r3, ascending as they need; `out` steps past the corner): four instructions where
/// two pairs and two single words took six (the reference frame 0.48% fewer).
#[rustfmt::skip]
macro_rules! corner {
    ($index:literal) => {
        concat!(
            "ldrh {ic}, [{t}, #", $index, "]\n",
            "add {ic}, {v}, {ic}, lsl #4\n",
            "ldm {ic}, {{r1, r2, r3}}\n",
            "stm {out}!, {{r1, r2, r3}}",
        )
    };
}

/// The walk on ARMv7-M: a back face takes 21 instructions (its three indices loaded, its
/// three points loaded in pairs, the area by a multiply and a multiply-accumulate in words as
/// `short_sides_area` takes it, its sign and its zero from one comparison), where the compiled
/// walk took about 49, keeping its state on the stack around the call it makes for the faces
/// it draws. The walk takes only objects inside every clip plane, whose sides lie within
/// ±2¹⁵ (see `inside_area2`): each product within ±2³⁰, the area within ±2³¹. (In 64 bits, by
/// a widening multiply and a multiply-accumulate, the zero test took one more instruction a
/// back face; the reference frame 0.04% more.)
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
        //   before the end, and moves by one triangle as `left` counts down; `left` leaves at
        //   0 where it would pass 0), and the words at `v + 16·i`, `v + 16·i + 4` and (for a
        //   front face) `v + 16·i + 8` for each index `i` of those triangles: within `vertices`,
        //   whose elements take 16 bytes with x, y and z at 0, 4 and 8 (asserted in
        //   asm_faces.rs), as `i` is below the mesh's number of positions (the invariant of
        //   `Mesh`), which is `vertices.len()` (checked by `new`). Where it stops on a front face
        //   it writes `out` (borrowed mutably): that face's three vertices' x, y and z to its
        //   nine words in order, each vertex's three at 0, 12 and 24 (its layout, asserted in
        //   asm_faces.rs), by three `stm`s from its start; no other memory, and no stack
        //   (`nostack`).
        // - Values: `next` leaves at one past the triangle the walk stopped on, or at the end,
        //   `left` as the triangles after it; `out` gets `i32`s (any word is one).
        // - Registers: every register the block writes is an output; the flags it changes
        //   are not preserved, as asm! allows by default.
        unsafe {
            core::arch::asm!(
                "2:",
                "subs {left}, {left}, #1",
                "blo 5f",
                "ldrh {ia}, [{t}]",
                "ldrh {ib}, [{t}, #2]",
                "ldrh {ic}, [{t}, #4]",
                "add {t}, {t}, #6",
                // The points: (ia, r1), (ib, r2), (ic, r3).
                "add {ia}, {v}, {ia}, lsl #4",
                "ldrd {ia}, r1, [{ia}]",
                "add {ib}, {v}, {ib}, lsl #4",
                "ldrd {ib}, r2, [{ib}]",
                "add {ic}, {v}, {ic}, lsl #4",
                "ldrd {ic}, r3, [{ic}]",
                // (b − a)·(c.y − a.y) + (c − a)·(a.y − b.y).
                "sub {ib}, {ib}, {ia}",
                "sub {ic}, {ic}, {ia}",
                "sub r3, r3, r1",
                "sub r2, r1, r2",
                "mul {ia}, {ib}, r3",
                "mla {ia}, {ic}, r2, {ia}",
                "cmp {ia}, #0",
                "blt 3f",
                "bne 2b",
                "movs {ib}, #{degenerate}",
                "b 9f",
                // A front face: its vertices' positions and depths into `out`.
                "3:",
                corner!(-6),
                corner!(-4),
                corner!(-2),
                "movs {ib}, #{front}",
                "b 9f",
                "5:",
                "movs {left}, #0",
                "movs {ib}, #{end_}",
                "9:",
                t = inout(reg) self.next,
                left = inout(reg) self.left,
                v = in(reg) self.vertices.as_ptr(),
                ia = out(reg) area, ib = out(reg) stop,
                out = inout(reg) out.as_mut_ptr() => _,
                ic = out(reg) _, out("r1") _, out("r2") _, out("r3") _,
                front = const FaceStop::FRONT,
                degenerate = const FaceStop::DEGENERATE,
                end_ = const FaceStop::END,
                options(nostack),
            );
        }
        self.stopped(stop, i64::from(area))
    }
}

/// One clip coordinate for `project_rows`: the row's coefficients (r3 to r5) and sum (r6 and
/// `$hi`) loaded by `$load`, the point's products (r0 to r2) accumulated onto the sum, whose
/// high word `$hi` is the coordinate (the block's rows and the points scaled for it).
macro_rules! clip_row {
    ($load:literal, $hi:literal) => {
        concat!(
            $load,
            "\n",
            "smlal r6, ",
            $hi,
            ", r3, r0\n",
            "smlal r6, ",
            $hi,
            ", r4, r1\n",
            "smlal r6, ",
            $hi,
            ", r5, r2",
        )
    };
}

/// A screen coordinate for `project_rows`: the next row's clip coordinate times the half size
/// that follows it in the block (r8), its rounded quotient by w (r9; half of it in r10, as
/// `div_round_word`: the magnitude plus half, divided, the sign put back), placed by `$place`
/// (from the half size) and stored at `$at` of the vertex.
macro_rules! screen_axis {
    ($place:literal, $at:literal) => {
        concat!(
            clip_row!("ldm lr!, {{r3, r4, r5, r6, r7, r8}}", "r7"),
            "\n",
            "mul r6, r7, r8\n",
            "cmp r6, #0\n",
            "it mi\n",
            "rsbmi r6, r6, #0\n",
            "add r6, r6, r9, lsr #1\n",
            "udiv r6, r6, r9\n",
            "it mi\n",
            "rsbmi r6, r6, #0\n",
            $place,
            "\n",
            "str r6, [r12, #",
            $at,
            "]",
        )
    };
}

/// What [`project_known_in_words`]'s loop reads for each vertex: the clip-from-model matrix'
/// rows w, x, y and z, each as its three coefficients shifted left by `16 − shift` and the
/// sum its products accumulate onto (`(t << 32) + 2³¹`, `t` the row's translation, as two
/// words, low first), x's and y's followed by the viewport's half width and height in
/// sub-pixels, z's by the end of the positions; then the shift of the points, `shift`. A
/// point shifted left by `shift` times those coefficients, summed onto that start, is
/// `2¹⁶·(s + 2¹⁵)` for `transform_short`'s sum `s` (its products onto `t << 16`): its high
/// word is `⌊(s + 2¹⁵) / 2¹⁶⌋`, the sum's bits 16 to 47 that `transform_short` takes, with no
/// shift of the sum (two instructions a row, eight a vertex, for the points' three shifts).
#[repr(C)]
struct ProjectBlock {
    w: [u32; 5],
    x: [u32; 6],
    y: [u32; 6],
    z: [u32; 5],
    end: *const Vec3,
    shift: u32,
}

/// One row of [`ProjectBlock`]: the coefficients of `r` shifted left by `16 − shift` (each
/// below 2³¹ in magnitude after it: `shift_for`) and the accumulator's start.
fn project_row(r: [i32; 4], shift: u32) -> [u32; 5] {
    let start = ((r[3] as i64) << 32) + (1 << 31);
    let c = |v: i32| v.wrapping_shl(16 - shift) as u32;
    [
        c(r[0]),
        c(r[1]),
        c(r[2]),
        start as u32,
        (start >> 32) as u32,
    ]
}

/// The points' shift for [`ProjectBlock`] of the rows `m` (coefficients, then translation) and
/// points within ±`extent`: the largest up to 16 that keeps every shifted coordinate within
/// ±2³¹ (`extent·2^shift < 2³¹`), if every coefficient shifted left by `16 − shift` stays
/// within ±2³¹ too; `None` otherwise (a matrix and an extent within a factor of about 4 of
/// `fits_32_bits`' bound).
fn shift_for(m: &[[i32; 4]; 4], extent: u32) -> Option<u32> {
    // 31 less the extent's bits: extent < 2^(32 − zeros) ≤ 2^(31 − shift).
    let shift = extent.leading_zeros().saturating_sub(1).min(16);
    let largest = m
        .iter()
        .flat_map(|r| r.iter().take(3))
        .map(|v| v.unsigned_abs())
        .max()
        .unwrap_or(0);
    (u64::from(largest) << (16 - shift) < 1 << 31).then_some(shift)
}

/// The row of a [`ProjectBlock`] with one more word after it.
fn project_row_and(r: [i32; 4], shift: u32, word: u32) -> [u32; 6] {
    let [a, b, c, lo, hi] = project_row(r, shift);
    [a, b, c, lo, hi, word]
}

/// The vertex stage of an object whose every vertex is known inside every clip plane with its
/// projection's operands in words (`Known::InWords`, at the default sub-pixel precision) and
/// no lit colour, on ARMv7-M: each of `positions` through `m` (a matrix whose transform fits
/// 32 bits, `Mat4::fits_32_bits`) into the vertex of `out` at its index, as the vertex loop
/// in Rust computes it, in one loop of assembly (`project_words`): the clip coordinates as
/// `transform_short` takes them (three multiply-accumulates a row onto its start, the sum's
/// bits 16 to 47: here the high word, see [`ProjectBlock`]), `x·half_w` and `y·half_h` in
/// words, their rounded quotients by `w` (`div_round_word`: the magnitude plus half of w,
/// divided, the sign put back), the depth `z·2³⁰/w` rounded by three divisions
/// (`fraction_by_digits`), the position from the viewport's centre, no outcode and no colour.
/// 61 instructions a vertex (65 with the sums' bits 16 to 47 shifted into a word, the
/// reference frame 0.57% more), where the compiled loop took about 125, loading the matrix
/// from the stack for each vertex. False, with nothing written, where the points' positions
/// (within ±`extent`) and the matrix leave no shift for the block (see `shift_for`).
#[allow(unsafe_code)]
pub(crate) fn project_known_in_words(
    m: &Mat4,
    (half_w, half_h): (i32, i32),
    (positions, extent): (&[Vec3], u32),
    out: &mut [ScreenVertex],
) -> bool {
    let n = positions.len().min(out.len());
    let rows = m.to_bits();
    let Some(shift) = shift_for(&rows, extent) else {
        return false;
    };
    let [x, y, z, w] = rows;
    let block = ProjectBlock {
        w: project_row(w, shift),
        x: project_row_and(x, shift, half_w as u32),
        y: project_row_and(y, shift, half_h as u32),
        z: project_row(z, shift),
        end: positions.as_ptr().wrapping_add(n),
        shift,
    };
    // SAFETY: `project_rows` keeps the calling convention (see its documentation) and reads
    // `block` (borrowed for the call), the `n` positions from `positions` up to `block.end`
    // (within the slice), and writes the `n` vertices from `out` (borrowed mutably, at least
    // `n` long): 16 bytes each, x, y, z and a zero word over `rgb` and `outcode` at 0, 4, 8
    // and 12 (asserted below), valid values of every field (any `i32`, bytes 0).
    unsafe { project_rows(&block, positions.as_ptr(), out.as_mut_ptr()) };
    true
}

/// [`project_known_in_words`]' loop, from the block's address (r0), the first position (r1)
/// and the first vertex (r2) to the positions' end (the block's `end`). Registers: the point
/// in r0 to r2 (shifted left by the block's `shift`), a row's coefficients in r3 to r5 and its
/// sum in r6 and r7 (w's in r6 and r9), its extra word in r8, w in r9, the shift in r10, the
/// positions in r11, the vertices in r12, the block in lr. Each result is stored as it is
/// found.
///
/// # Safety
/// `block` points to a [`ProjectBlock`] whose `end` lies at or after `positions` (within one
/// slice of `Vec3`), and `out` to as many writable vertices.
#[unsafe(naked)]
#[allow(unsafe_code)]
unsafe extern "C" fn project_rows(
    block: *const ProjectBlock,
    positions: *const Vec3,
    out: *mut ScreenVertex,
) {
    core::arch::naked_asm!(
        "push {{r4, r5, r6, r7, lr}}",
        "push.w {{r8, r9, r10, r11}}",
        "mov lr, r0",
        "mov r11, r1",
        "mov r12, r2",
        "ldr r8, [lr, #{end}]",
        "ldr r10, [lr, #{shift}]",
        "cmp r11, r8",
        "bhs 9f",
        "2:",
        "ldm r11!, {{r0, r1, r2}}",
        "lsl r0, r0, r10",
        "lsl r1, r1, r10",
        "lsl r2, r2, r10",
        // w, at least 1 (as `NonZeroU32::new(w).unwrap_or(MIN)`).
        clip_row!("ldm lr!, {{r3, r4, r5, r6, r9}}", "r9"),
        "cmp r9, #1",
        "it lo",
        "movlo r9, #1",
        // x: half_w + round(x·half_w / w); y: half_h − round(y·half_h / w).
        screen_axis!("add r6, r8, r6", 0),
        screen_axis!("sub r6, r8, r6", 4),
        // The depth: z·2³⁰/w rounded, by the digits q1·2¹⁷ + q2·2⁴ + q3; the end in r8.
        clip_row!("ldm lr, {{r3, r4, r5, r6, r7, r8}}", "r7"),
        "lsl r6, r7, #13",
        "udiv r3, r6, r9",
        "mls r6, r3, r9, r6",
        "lsl r6, r6, #13",
        "udiv r4, r6, r9",
        "mls r6, r4, r9, r6",
        "lsl r6, r6, #4",
        "add r6, r6, r9, lsr #1",
        "udiv r6, r6, r9",
        "add r6, r6, r4, lsl #4",
        "add r6, r6, r3, lsl #17",
        "movs r7, #0",
        "strd r6, r7, [r12, #8]",
        "add r12, r12, #16",
        "sub lr, lr, #{rows}",
        "cmp r11, r8",
        "blo 2b",
        "9:",
        "pop.w {{r8, r9, r10, r11}}",
        "pop {{r4, r5, r6, r7, pc}}",
        end = const offset_of!(ProjectBlock, end),
        shift = const offset_of!(ProjectBlock, shift),
        rows = const offset_of!(ProjectBlock, z),
    )
}

// The layouts `project_rows` reads and writes: the block's rows one after the other, points of
// three words, vertices of 16 bytes with x, y, z and a word of `rgb` and `outcode`.
const _: () = {
    assert!(offset_of!(ProjectBlock, x) == 20 && offset_of!(ProjectBlock, y) == 44);
    assert!(offset_of!(ProjectBlock, z) == 68 && offset_of!(ProjectBlock, end) == 88);
    assert!(size_of::<Vec3>() == 12 && offset_of!(Vec3, y) == 4 && offset_of!(Vec3, z) == 8);
    assert!(offset_of!(ScreenVertex, rgb) == 12 && offset_of!(ScreenVertex, outcode) == 15);
    assert!(size_of::<ScreenVertex>() == 16 && offset_of!(ScreenVertex, z) == 8);
};
