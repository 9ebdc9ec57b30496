//! Board glue + deterministic instruction counting under `qemu-system-arm -icount shift=S`.
//!
//! With `-icount shift=S` QEMU advances its virtual clock by exactly 2^S ns per
//! guest instruction, and timer peripherals are driven by that clock. So a
//! free-running hardware timer read before and after a region gives
//! `ticks = insns * 2^S / tick_ns`; with S=10 one instruction is 25.6 ticks of
//! the 25 MHz CMSDK timer (16.384 ticks of the nRF51's 16 MHz TIMER0), so the
//! instruction count is recovered exactly by rounding. `Meter::calibrate`
//! detects S from a hand-written loop of known length and refuses to run if
//! the clock is not instruction-driven (QEMU started without -icount).
#![no_std]

pub mod scenes;

use core::sync::atomic::{compiler_fence, AtomicU32, Ordering};

use cortex_m_semihosting::{debug, hprintln};

/// Frames per preset: the hash chain covers these frames, so the host test uses the same.
pub const FRAMES: u32 = scenes::FRAMES;
pub const TARGET: &str = env!("BENCH_TARGET");

const fn parse_u32(s: Option<&str>, default: u32) -> u32 {
    let b = match s {
        Some(s) if !s.is_empty() => s.as_bytes(),
        _ => return default,
    };
    let (mut i, mut v) = (0, 0u32);
    while i < b.len() {
        assert!(
            b[i].is_ascii_digit(),
            "BENCH_* build variables must be numbers"
        );
        v = v * 10 + (b[i] - b'0') as u32;
        i += 1;
    }
    v
}

#[inline(always)]
unsafe fn wr(addr: usize, v: u32) {
    core::ptr::write_volatile(addr as *mut u32, v)
}

#[inline(always)]
unsafe fn rd(addr: usize) -> u32 {
    core::ptr::read_volatile(addr as *const u32)
}

#[cfg(all(feature = "board-mps2", feature = "board-microbit"))]
compile_error!("enable exactly one board-* feature (use --no-default-features for microbit)");

#[cfg(feature = "board-mps2")]
pub mod board {
    //! QEMU mps2-an385 / mps2-an386. CMSDK APB TIMER0 @ 0x4000_0000, PCLK 25 MHz.
    use super::{rd, wr};
    pub const NAME: &str = "mps2";
    /// Framebuffer size; override at build time with BENCH_FB_W / BENCH_FB_H.
    pub const FB_W: u32 = super::parse_u32(option_env!("BENCH_FB_W"), 320);
    pub const FB_H: u32 = super::parse_u32(option_env!("BENCH_FB_H"), 240);
    /// One timer tick in ns, as NUM/DEN.
    pub const TICK_NS: (u64, u64) = (40, 1);
    const BASE: usize = 0x4000_0000;

    pub fn timer_start() {
        unsafe {
            wr(BASE, 0); // CTRL: stop
            wr(BASE + 0x8, 0xFFFF_FFFF); // RELOAD (also loads VALUE)
            wr(BASE + 0x4, 0xFFFF_FFFF); // VALUE
            wr(BASE + 0xC, 1); // clear INTSTATUS
            wr(BASE, 0b1001); // CTRL: EN | IRQEN (NVIC line stays disabled; only latches INTSTATUS)
        }
    }

    /// Up-counting view of the down-counter.
    #[inline(always)]
    pub fn now() -> u32 {
        0u32.wrapping_sub(unsafe { rd(BASE + 0x4) })
    }
}

#[cfg(feature = "board-microbit")]
pub mod board {
    //! QEMU microbit (nRF51822). TIMER0 @ 0x4000_8000, 16 MHz, 32-bit mode.
    use super::{rd, wr};
    pub const NAME: &str = "microbit";
    /// Framebuffer size; override at build time with BENCH_FB_W / BENCH_FB_H.
    pub const FB_W: u32 = super::parse_u32(option_env!("BENCH_FB_W"), 64);
    pub const FB_H: u32 = super::parse_u32(option_env!("BENCH_FB_H"), 48);
    pub const TICK_NS: (u64, u64) = (125, 2);
    const BASE: usize = 0x4000_8000;

    pub fn timer_start() {
        unsafe {
            wr(BASE + 0x004, 1); // TASKS_STOP
            wr(BASE + 0x504, 0); // MODE = timer
            wr(BASE + 0x508, 3); // BITMODE = 32 bit
            wr(BASE + 0x510, 0); // PRESCALER = 0 -> 16 MHz
            wr(BASE + 0x00C, 1); // TASKS_CLEAR
            wr(BASE + 0x000, 1); // TASKS_START
        }
    }

    #[inline(always)]
    pub fn now() -> u32 {
        unsafe {
            wr(BASE + 0x040, 1); // TASKS_CAPTURE[0]
            rd(BASE + 0x540) // CC[0]
        }
    }
}

/// Exactly `2 * n` instructions in the loop body (`subs` + `bne`); n must be >= 1.
/// (No guard for n == 0 on purpose: a guard is a branch on v6-M, which would
/// make the cost of n == 1 differ by one instruction from the rest.)
#[inline(never)]
pub fn spin(n: u32) {
    unsafe {
        core::arch::asm!(
            "2:",
            "subs {0}, #1",
            "bne 2b",
            inout(reg) n => _,
            options(nomem, nostack),
        );
    }
}

/// Raw timer ticks spent in `f` (wrapping: valid while a region is < 2^32 ticks).
#[inline(always)]
pub fn ticks<R>(f: impl FnOnce() -> R) -> (R, u32) {
    let t0 = board::now();
    compiler_fence(Ordering::SeqCst);
    let r = f();
    compiler_fence(Ordering::SeqCst);
    let t1 = board::now();
    (r, t1.wrapping_sub(t0))
}

/// Ticks spent inside [`excluded`] during the frame being counted (one core, no interrupt
/// touches it).
static EXCLUDED: AtomicU32 = AtomicU32::new(0);

/// Runs `f` and leaves its instructions out of the frame's count: a preset's stand-in for
/// work a real firmware hands to hardware (a display's DMA).
pub fn excluded(f: &mut dyn FnMut()) {
    let ((), t) = ticks(f);
    EXCLUDED.store(
        EXCLUDED.load(Ordering::Relaxed).wrapping_add(t),
        Ordering::Relaxed,
    );
}

pub struct Meter {
    /// Detected `-icount shift=S`.
    pub shift: u32,
    /// Raw ticks measured for 20000 instructions of `spin`.
    pub cal_ticks: u32,
    /// Instructions attributed to an empty region (timer reads), subtracted.
    pub overhead: u32,
}

pub enum CalError {
    /// Ticks for 20000 instructions matched no shift in 0..=10: no -icount?
    NotInstructionClocked(u32),
}

const CAL_INSNS: u64 = 20_000;

impl Meter {
    pub fn calibrate() -> Result<Meter, CalError> {
        board::timer_start();
        // Run once to get the loop translated; icount is not affected, but keep it tidy.
        spin(10);
        let (_, a) = ticks(|| spin(1_000));
        let (_, b) = ticks(|| spin(11_000));
        let d = b.wrapping_sub(a);
        let (num, den) = board::TICK_NS;
        let mut found = None;
        for s in 0..=10u32 {
            let expect = (CAL_INSNS << s) * den / num;
            let tol = expect / 100 + 2;
            if (d as u64).abs_diff(expect) <= tol {
                found = Some(s);
            }
        }
        let shift = found.ok_or(CalError::NotInstructionClocked(d))?;
        let mut m = Meter {
            shift,
            cal_ticks: d,
            overhead: 0,
        };
        let (_, o) = ticks(|| ());
        m.overhead = m.raw_insns(o);
        Ok(m)
    }

    /// ticks -> instructions, rounded to nearest. Not inlined: otherwise LLVM
    /// may schedule parts of this pure computation (e.g. the 64-bit shift
    /// libcall on v6-M) between the two timer reads.
    #[inline(never)]
    pub fn raw_insns(&self, ticks: u32) -> u32 {
        let (num, den) = board::TICK_NS;
        let d = den << self.shift;
        ((ticks as u64 * num + d / 2) / d) as u32
    }

    /// Instructions executed inside `f`, measurement overhead removed.
    #[inline(always)]
    pub fn count<R>(&self, f: impl FnOnce() -> R) -> (R, u32) {
        let (r, t) = ticks(f);
        (r, self.raw_insns(t).wrapping_sub(self.overhead))
    }

    /// Instructions for `spin(n)` measured from one fixed call site, so the
    /// result is exactly `2n + c` with the same `c` for every n.
    #[inline(never)]
    pub fn count_spin(&self, n: u32) -> u32 {
        let n = core::hint::black_box(n);
        self.count(|| spin(n)).1
    }

    /// Ticks per instruction is >= 2 from shift 7 up (25 MHz) / 8 up (16 MHz):
    /// below that counts are quantised.
    pub fn exact(&self) -> bool {
        let (num, den) = board::TICK_NS;
        (den << self.shift) >= 2 * num
    }
}

/// Stack high-water mark of a region: paint below the current SP, run, scan.
pub mod stack {
    const PAINT: u32 = 0xCCCC_CCCC;
    /// How far below SP we paint/scan (the region must use less than this).
    pub const WINDOW: usize = 64 * 1024;
    /// Bytes just below SP left unpainted (the painter's own frame lives there).
    const GAP: usize = 128;

    extern "C" {
        // cortex-m-rt's linker script: lowest address the stack may grow to.
        static _stack_end: u32;
    }

    fn range(sp: usize) -> (usize, usize) {
        let bottom = core::ptr::addr_of!(_stack_end) as usize;
        let top = (sp - GAP) & !3;
        (core::cmp::max(bottom, top.saturating_sub(WINDOW)), top)
    }

    /// Current stack pointer (call in the function that will call the region).
    #[inline(always)]
    pub fn sp() -> usize {
        cortex_m::register::msp::read() as usize
    }

    #[inline(never)]
    pub fn paint(sp: usize) {
        let (lo, top) = range(sp);
        let mut p = lo;
        while p < top {
            unsafe { core::ptr::write_volatile(p as *mut u32, PAINT) };
            p += 4;
        }
    }

    /// Bytes below `sp` written since `paint(sp)` (None: the window was exhausted).
    #[inline(never)]
    pub fn used(sp: usize) -> Option<usize> {
        let (lo, top) = range(sp);
        let mut p = lo;
        while p < top && unsafe { core::ptr::read_volatile(p as *const u32) } == PAINT {
            p += 4;
        }
        if p == lo && lo < top {
            None
        } else {
            Some(sp - p)
        }
    }
}

/// What the harness asks of a preset.
#[derive(Clone, Copy, Debug)]
pub enum Op {
    /// Clear the buffers (not counted).
    Clear,
    /// Draw frame `n` (counted).
    Draw(u32),
    /// The hash of what was drawn.
    Hash,
}

fn fail() -> ! {
    debug::exit(debug::EXIT_FAILURE);
    loop {
        cortex_m::asm::bkpt();
    }
}

/// Runs a preset under QEMU: checks that the clock counts instructions, then for each of
/// `FRAMES` frames clears (not counted), draws (counted) and hashes; measures the stack of one
/// more frame; prints one line and exits.
pub fn run(preset: &str, mut op: impl FnMut(Op) -> u32) -> ! {
    run_each(&[preset], |_, o| op(o))
}

/// Like [`run`] for several configurations of one binary: one line per name, each measured
/// like a preset of its own (`op` is told which).
pub fn run_each(names: &[&str], mut op: impl FnMut(&str, Op) -> u32) -> ! {
    let meter = match Meter::calibrate() {
        Ok(m) => m,
        Err(CalError::NotInstructionClocked(d)) => {
            hprintln!("error: timer advanced {} ticks for 20000 instructions; run QEMU with -icount shift=10", d);
            fail()
        }
    };
    let mut c0 = None;
    for n in [1u32, 100, 12_345, 1_000_000] {
        let k = meter.count_spin(n);
        let c = k as i64 - 2 * n as i64;
        if *c0.get_or_insert(c) != c {
            hprintln!("error: instruction count is not exact/linear");
            fail();
        }
    }
    for name in names {
        let mut op = |o: Op| op(name, o);
        let (mut sum, mut min, mut max, mut chain) = (0u64, u32::MAX, 0u32, 0u32);
        for f in 0..FRAMES {
            op(Op::Clear);
            EXCLUDED.store(0, Ordering::Relaxed);
            let (_, n) = meter.count(|| frame(&mut op, f));
            let n = n.wrapping_sub(meter.raw_insns(EXCLUDED.load(Ordering::Relaxed)));
            chain = chain.rotate_left(5) ^ op(Op::Hash);
            sum += n as u64;
            min = min.min(n);
            max = max.max(n);
        }
        op(Op::Clear);
        let sp = stack::sp();
        stack::paint(sp);
        frame(&mut op, 0);
        let Some(stack_bytes) = stack::used(sp) else {
            hprintln!(
                "error: a frame used more than {} bytes of stack",
                stack::WINDOW
            );
            fail()
        };
        hprintln!(
            "preset={} target={} board={} instructions_per_frame={} min={} max={} frames={} hash=0x{:08x} stack={}",
            name,
            TARGET,
            board::NAME,
            sum / FRAMES.max(1) as u64,
            min,
            max,
            FRAMES,
            chain,
            stack_bytes
        );
    }
    debug::exit(debug::EXIT_SUCCESS);
    fail()
}

/// The measured region: one call, so nothing else is scheduled into it.
#[inline(never)]
fn frame(op: &mut impl FnMut(Op) -> u32, f: u32) {
    core::hint::black_box(op(Op::Draw(f)));
}

/// Declares statics inside a block and borrows each once: `storage!(NAME: Type = init, ...)`
/// gives a tuple of `&'static mut` references. Use it once, at start-up in `main`.
#[macro_export]
macro_rules! storage {
    ($($name:ident : $ty:ty = $init:expr),+ $(,)?) => {{
        $(static mut $name: $ty = $init;)+
        // SAFETY: the statics are declared in this block, which `main` runs once: these are the
        // only references ever taken to them.
        unsafe { ($(&mut *core::ptr::addr_of_mut!($name)),+) }
    }};
}

/// The torus's storage (vertex cache, positions, normals, triangles).
#[macro_export]
macro_rules! torus_storage {
    () => {
        $crate::storage!(
            CACHE: [fixed3d::pipeline::ScreenVertex; $crate::scenes::TORUS_VERTICES] =
                [fixed3d::pipeline::ScreenVertex::DEFAULT; $crate::scenes::TORUS_VERTICES],
            POS: [fixed3d::math::Vec3; $crate::scenes::TORUS_VERTICES] = [fixed3d::math::Vec3::ZERO; $crate::scenes::TORUS_VERTICES],
            NOR: [fixed3d::math::Vec3; $crate::scenes::TORUS_VERTICES] = [fixed3d::math::Vec3::ZERO; $crate::scenes::TORUS_VERTICES],
            TRI: [[u16; 3]; $crate::scenes::TORUS_TRIANGLES] = [[0; 3]; $crate::scenes::TORUS_TRIANGLES],
        )
    };
}
