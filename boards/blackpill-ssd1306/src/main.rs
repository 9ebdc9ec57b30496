//! STM32F411 "Black Pill" + SSD1306 128x64 over I2C: the small torus of `fixed3d_showcase`
//! spinning, lit flat and dithered to one bit, each frame drawn whole (8 KiB of pixels and
//! 16 KiB of depth) and sent over I2C at 400 kHz.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use embedded_graphics::pixelcolor::BinaryColor;
use fixed3d::buffer::FrameBuffer;
use fixed3d::math::Vec3;
use fixed3d::pipeline::ScreenVertex;
use fixed3d_showcase::*;
use panic_halt as _;
use ssd1306::prelude::*;
use ssd1306::{I2CDisplayInterface, Ssd1306};
use stm32f4xx_hal::pac;
use stm32f4xx_hal::prelude::*;
use stm32f4xx_hal::rcc::Config;

#[entry]
fn main() -> ! {
    let Some(dp) = pac::Peripherals::take() else {
        panic!("peripherals taken twice")
    };
    // The Black Pill's 25 MHz crystal, the core at 100 MHz.
    let mut rcc = dp.RCC.freeze(Config::hse(25.MHz()).sysclk(100.MHz()));
    // SSD1306 on I2C1: SCL PB6, SDA PB7 (the module has its own pull-ups).
    let gpiob = dp.GPIOB.split(&mut rcc);
    let i2c = dp.I2C1.i2c((gpiob.pb6, gpiob.pb7), 400.kHz(), &mut rcc);
    let mut oled = Ssd1306::new(
        I2CDisplayInterface::new(i2c),
        DisplaySize128x64,
        DisplayRotation::Rotate0,
    )
    .into_buffered_graphics_mode();
    if oled.init().is_err() {
        panic!("SSD1306 init");
    }

    let (Some(positions), Some(normals), Some(triangles)) = (
        cortex_m::singleton!(: [Vec3; SMALL_VERTICES] = [Vec3::ZERO; SMALL_VERTICES]),
        cortex_m::singleton!(: [Vec3; SMALL_VERTICES] = [Vec3::ZERO; SMALL_VERTICES]),
        cortex_m::singleton!(: [[u16; 3]; SMALL_TRIANGLES] = [[0; 3]; SMALL_TRIANGLES]),
    ) else {
        panic!("storage")
    };
    let (Some(vertices), Some(pixels), Some(depth)) = (
        cortex_m::singleton!(: [ScreenVertex; SMALL_VERTICES] = [ScreenVertex::DEFAULT; SMALL_VERTICES]),
        cortex_m::singleton!(: [BinaryColor; OLED_CELLS] = [BinaryColor::Off; OLED_CELLS]),
        cortex_m::singleton!(: [u16; OLED_CELLS] = [0; OLED_CELLS]),
    ) else {
        panic!("storage")
    };
    let mesh = torus_mesh(SMALL_RING, SMALL_TUBE, positions, normals, triangles);
    let mut frame = 0u32;
    loop {
        let _ = draw_oled(
            &mesh,
            frame,
            &mut vertices[..],
            &mut pixels[..],
            &mut depth[..],
        );
        if let Ok(image) = FrameBuffer::new(&mut pixels[..], OLED_WIDTH, OLED_HEIGHT) {
            let _ = image.present(&mut oled);
        }
        let _ = oled.flush();
        frame = frame.wrapping_add(1);
    }
}
