//! The u16 depth loop of a solid-coloured span in hand-written Thumb-2, for Cortex-M3, M4 and
//! M7 (ARMv7-M) and ARMv8-M mainline cores, with the `asm` feature (the only `unsafe` code of
//! the crate; without the feature the crate forbids it).
//!
//! Nine instructions a pixel (ten when fragments are counted): the depth from the loop's
//! value by a shift, the stored depth loaded, compared, and both stores predicated in one IT
//! block; one index counts from −n up to 0 and addresses both buffers. The compiler's loop
//! takes twelve or thirteen (a branch over the stores, two pointers and a counter, and the
//! colour reloaded from the stack): the reference frame on the Cortex-M4F 3.8% fewer
//! instructions with it (1.790 M → 1.722 M).
//!
//! It computes exactly what `unclamped_u16` computes for a span whose colour is constant:
//! the same depth (`acc >> 15`, below 2¹⁶ since every value lies in [0, 2³¹)), the same test
//! on the same stored depth (zero-extended to 32 bits in both), the same stores and counts.
//! The firmware presets' frame hashes, equal to the host's, check it under emulation
//! (`bench/mcu/run.sh`, in CI): the `variants` preset each of its four forms (depth test ×
//! counted), on ties too.

use core::mem::{align_of, size_of};

use super::depth::{DepthTest, FragmentCount};

/// The pixel loop in assembly: `$it` the IT block (`itt`, or `itte` with the failure count),
/// `$pass` the condition where the fragment wins (`lo`: strictly nearer; `ls`: nearer or
/// equal), then the failure count's instruction if any, then the operands.
macro_rules! span_loop {
    ($it:literal, $pass:literal, [$($count:literal)?], $($operands:tt)*) => {
        core::arch::asm!(
            "2:",
            "lsr {z}, {acc}, #15",
            "ldrh {o}, [{d}, {i}, lsl #1]",
            "add {acc}, {st}",
            "cmp {z}, {o}",
            concat!($it, " ", $pass),
            concat!("strh", $pass, " {z}, [{d}, {i}, lsl #1]"),
            concat!("strh", $pass, " {col}, [{c}, {i}, lsl #1]"),
            $($count,)?
            "adds {i}, {i}, #1",
            "bne 2b",
            $($operands)*
        )
    };
}

/// The two bytes of a colour of 2 bytes and alignment 2, as a word for [`solid_span`]; `None`
/// for other colour types (their spans take the caller's loop).
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

/// Depth-tests a span whose every pixel has the colour whose two bytes [`color_bits`] gave as
/// `bits` (so `C` has 2 bytes and alignment 2): the loop's value `acc` (in [0, 2³¹) at every
/// pixel, see `DepthFormat::unclamped`) stepped by `st`. Returns the failures so far: `failed`
/// plus the span's, when `K` counts them.
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
    //   the two bytes of a valid `C` (see `color_bits`) unchanged: a byte-for-byte copy of a
    //   valid value is the same valid value, exactly what `*cell = color` stores.
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
