//! The harness alone, drawing nothing: its size is subtracted from each preset's to get the
//! library's share.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use panic_semihosting as _;

#[entry]
fn main() -> ! {
    mcu_bench::run("baseline", |op| match core::hint::black_box(op) {
        mcu_bench::Op::Draw(f) => f,
        _ => 0,
    })
}
