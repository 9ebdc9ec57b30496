//! Preset `display`: the `full` scene presented through real display drivers, the way a
//! firmware is written: an ILI9341 (320x240, RGB565) driven by `mipidsi` over SPI, fed band by
//! band from 15 KiB of buffers, and an SSD1306 (128x64, one bit) driven by the `ssd1306` crate
//! over I2C, showing the dithered Gouraud torus. The buses are stand-ins that accept every
//! transfer (and count the bytes), so the drivers' real code runs and is measured.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use embedded_graphics::pixelcolor::{BinaryColor, Rgb565, RgbColor};
use fixed3d::buffer::{Carried, FrameBuffer};
use fixed3d::pipeline::Bin;
use mcu_bench::scenes::*;
use mcu_bench::Op;
use mipidsi::interface::SpiInterface;
use mipidsi::models::ILI9341Rgb565;
use mipidsi::options::{Orientation, Rotation};
use panic_semihosting as _;
use ssd1306::prelude::*;
use ssd1306::{I2CDisplayInterface, Ssd1306};

/// An SPI bus, I2C bus, pins and delay that accept everything and count the bytes sent.
mod bus {
    use embedded_hal::{delay, digital, i2c, spi};

    #[derive(Default)]
    pub struct Spi(pub u32);
    impl spi::ErrorType for Spi {
        type Error = core::convert::Infallible;
    }
    impl spi::SpiDevice for Spi {
        fn transaction(&mut self, ops: &mut [spi::Operation<'_, u8>]) -> Result<(), Self::Error> {
            for op in ops.iter() {
                if let spi::Operation::Write(b) = op {
                    self.0 = self.0.wrapping_add(b.len() as u32);
                }
            }
            Ok(())
        }
    }

    #[derive(Default)]
    pub struct I2c(pub u32);
    impl i2c::ErrorType for I2c {
        type Error = core::convert::Infallible;
    }
    impl i2c::I2c for I2c {
        fn transaction(
            &mut self,
            _: u8,
            ops: &mut [i2c::Operation<'_>],
        ) -> Result<(), Self::Error> {
            for op in ops.iter() {
                if let i2c::Operation::Write(b) = op {
                    self.0 = self.0.wrapping_add(b.len() as u32);
                }
            }
            Ok(())
        }
    }

    pub struct Pin;
    impl digital::ErrorType for Pin {
        type Error = core::convert::Infallible;
    }
    impl digital::OutputPin for Pin {
        fn set_low(&mut self) -> Result<(), Self::Error> {
            Ok(())
        }
        fn set_high(&mut self) -> Result<(), Self::Error> {
            Ok(())
        }
    }

    pub struct NoDelay;
    impl delay::DelayNs for NoDelay {
        fn delay_ns(&mut self, _: u32) {}
    }
}

#[entry]
fn main() -> ! {
    let (cache, pos, nor, tri) = mcu_bench::torus_storage!();
    let (band, band_depth, bins, carried, mono_px, mono_depth, spi_buffer) = mcu_bench::storage!(
        BAND: [Rgb565; (W * BAND_ROWS) as usize] = [Rgb565::BLACK; (W * BAND_ROWS) as usize],
        BAND_DEPTH: [u16; (W * BAND_ROWS) as usize] = [0; (W * BAND_ROWS) as usize],
        BINS: [Bin; BAND_BINS] = [Bin::EMPTY; BAND_BINS],
        CARRIED: [Carried; BAND_CARRIED] = [Carried::EMPTY; BAND_CARRIED],
        MONO: [BinaryColor; (MONO_W * MONO_H) as usize] = [BinaryColor::Off; (MONO_W * MONO_H) as usize],
        MONO_DEPTH: [u16; (MONO_W * MONO_H) as usize] = [0; (MONO_W * MONO_H) as usize],
        SPI_BUFFER: [u8; 512] = [0; 512],
    );
    let mesh = torus_mesh(pos, nor, tri);
    let di = SpiInterface::new(bus::Spi::default(), bus::Pin, spi_buffer);
    let Ok(mut lcd) = mipidsi::Builder::new(ILI9341Rgb565, di)
        .display_size(240, 320)
        .orientation(Orientation::new().rotate(Rotation::Deg90))
        .init(&mut bus::NoDelay)
    else {
        panic!("ILI9341 init failed")
    };
    let mut oled = Ssd1306::new(
        I2CDisplayInterface::new(bus::I2c::default()),
        DisplaySize128x64,
        DisplayRotation::Rotate0,
    )
    .into_buffered_graphics_mode();
    if oled.init().is_err() {
        panic!("SSD1306 init failed");
    }
    let mut last = 0;
    mcu_bench::run("display", |op| match op {
        Op::Clear => 0,
        Op::Draw(f) => {
            let colour = bands(
                &mesh,
                f,
                cache,
                (&mut *bins, &mut *carried),
                band,
                band_depth,
                &mut lcd,
                &mut |w| w(),
            )
            .unwrap_or(0);
            let _ = mono(&mesh, f, cache, mono_px, mono_depth);
            if let Ok(fb) = FrameBuffer::new(&mut mono_px[..], MONO_W, MONO_H) {
                let _ = fb.present(&mut oled);
            }
            let _ = oled.flush();
            last = display_hash(colour, mono_hash(mono_px));
            last
        }
        Op::Hash => last,
    })
}
