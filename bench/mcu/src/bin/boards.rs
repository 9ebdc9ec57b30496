//! Preset `boards`: a frame of each board firmware under `boards/`, through their drawing code
//! (`boards/showcase`, compiled in from its source so that the other presets' builds do not
//! change): the 240x240 colour display's 15 bands of one prepared frame, each turned into the
//! bytes an ST7789 is sent, and the 128x64 one-bit frame. The firmwares draw exactly this (the
//! RP2040's two cores share the bands out); here one core draws them in order, and the hash is
//! the host's (`tests/firmware.rs`).
#![no_std]
#![no_main]

#[path = "../../../../boards/showcase/src/scene.rs"]
mod showcase;

use cortex_m_rt::entry;
use embedded_graphics::pixelcolor::{BinaryColor, Rgb565, RgbColor};
use fixed3d::math::Vec3;
use fixed3d::pipeline::{Bin, ScreenVertex};
use mcu_bench::scenes::{display_hash, mono_hash, Fnv};
use mcu_bench::{storage, Op};
use panic_semihosting as _;
use showcase::*;

#[entry]
fn main() -> ! {
    let (cache, pos, nor, tri, bins) = storage!(
        CACHE: [ScreenVertex; TORUS_VERTICES] = [ScreenVertex::DEFAULT; TORUS_VERTICES],
        POS: [Vec3; TORUS_VERTICES] = [Vec3::ZERO; TORUS_VERTICES],
        NOR: [Vec3; TORUS_VERTICES] = [Vec3::ZERO; TORUS_VERTICES],
        TRI: [[u16; 3]; TORUS_TRIANGLES] = [[0; 3]; TORUS_TRIANGLES],
        BINS: [Bin; LCD_BINS] = [Bin::EMPTY; LCD_BINS],
    );
    let (color, depth, bytes) = storage!(
        COLOR: [Rgb565; LCD_BAND_CELLS] = [Rgb565::BLACK; LCD_BAND_CELLS],
        DEPTH: [u16; LCD_BAND_CELLS] = [0; LCD_BAND_CELLS],
        BYTES: [u8; 2 * LCD_BAND_CELLS] = [0; 2 * LCD_BAND_CELLS],
    );
    let (small_cache, small_pos, small_nor, small_tri, pixels, small_depth) = storage!(
        SMALL_CACHE: [ScreenVertex; SMALL_VERTICES] = [ScreenVertex::DEFAULT; SMALL_VERTICES],
        SMALL_POS: [Vec3; SMALL_VERTICES] = [Vec3::ZERO; SMALL_VERTICES],
        SMALL_NOR: [Vec3; SMALL_VERTICES] = [Vec3::ZERO; SMALL_VERTICES],
        SMALL_TRI: [[u16; 3]; SMALL_TRIANGLES] = [[0; 3]; SMALL_TRIANGLES],
        PIXELS: [BinaryColor; OLED_CELLS] = [BinaryColor::Off; OLED_CELLS],
        SMALL_DEPTH: [u16; OLED_CELLS] = [0; OLED_CELLS],
    );
    let lcd = torus_mesh(TORUS_RING, TORUS_TUBE, pos, nor, tri);
    let small = torus_mesh(SMALL_RING, SMALL_TUBE, small_pos, small_nor, small_tri);
    let mut last = 0;
    mcu_bench::run("boards", |op| match op {
        Op::Clear => 0,
        Op::Draw(f) => {
            let mut h = Fnv::new();
            let models = lcd_models(&lcd, f);
            if let Ok(frame) = prepare_lcd(&models, cache, bins) {
                let _ = send_lcd_frame(&frame, color, depth, bytes, |b| h.bytes(b));
            }
            let _ = draw_oled(&small, f, small_cache, pixels, small_depth);
            last = display_hash(h.0, mono_hash(pixels));
            last
        }
        Op::Hash => last,
    })
}
