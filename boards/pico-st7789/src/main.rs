//! Raspberry Pi Pico (RP2040) + ST7789 240x240 over SPI: the lit torus of
//! `fixed3d_showcase` spinning, drawn in bands of 16 rows (the z-buffered frame would take
//! 225 KiB; the bands take 15 KiB a core).
//!
//! Each frame is prepared once (vertex stage and bins) on core 0; then core 0 draws the even
//! bands and core 1 the odd ones from that one prepared frame, and core 0 sends each finished
//! band to the display by DMA while the cores draw the next ones. The time of the last frame
//! is written in the top-left corner.
#![no_std]
#![no_main]

use core::cell::RefCell;
use core::fmt::Write as _;

use critical_section::Mutex;
use embedded_graphics::mono_font::{ascii::FONT_6X10, MonoTextStyle};
use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
use embedded_graphics::prelude::*;
use embedded_graphics::text::{Baseline, Text};
use embedded_hal::digital::OutputPin;
use embedded_hal::spi::{Operation, SpiBus, SpiDevice, MODE_3};
use fixed3d::buffer::FrameBuffer;
use fixed3d::math::Vec3;
use fixed3d::pipeline::{Bin, ScreenVertex};
use fixed3d::render::PreparedFrame;
use fixed3d_showcase::*;
use mipidsi::interface::SpiInterface;
use mipidsi::models::ST7789;
use mipidsi::options::ColorInversion;
use panic_halt as _;
use rp2040_hal::dma::{single_buffer, DMAExt};
use rp2040_hal::fugit::RateExtU32;
use rp2040_hal::gpio::{FunctionSpi, Pins};
use rp2040_hal::multicore::{Multicore, Stack};
use rp2040_hal::{clocks, entry, pac, Clock, Sio, Spi, Timer, Watchdog};

/// The second-stage boot loader for the Pico's W25Q080 flash.
#[link_section = ".boot2"]
#[used]
pub static BOOT2_FIRMWARE: [u8; 256] = rp2040_boot2::BOOT_LOADER_W25Q080;

/// The Pico's crystal.
const XTAL_HZ: u32 = 12_000_000;

/// A band as the ST7789 takes it: two bytes a pixel.
type BandBytes = [u8; 2 * LCD_BAND_CELLS];

/// Core 1's stack: 32 KiB, room for its band buffers being set up through it.
static CORE1_STACK: Stack<8192> = Stack::new();

/// The bytes of core 1's last band, passed between the cores: core 1 fills them when they are
/// not `filled`, core 0 sends them when they are and hands them back.
static CORE1_BAND: Mutex<RefCell<Slot>> = Mutex::new(RefCell::new(Slot {
    bytes: None,
    filled: false,
}));

struct Slot {
    bytes: Option<&'static mut BandBytes>,
    filled: bool,
}

/// Takes core 1's band bytes once they are `filled` (or, for core 1, once they are not).
fn take_band(filled: bool) -> &'static mut BandBytes {
    loop {
        let taken = critical_section::with(|cs| {
            let mut slot = CORE1_BAND.borrow_ref_mut(cs);
            if slot.filled == filled {
                slot.bytes.take()
            } else {
                None
            }
        });
        if let Some(bytes) = taken {
            return bytes;
        }
    }
}

/// Hands core 1's band bytes back, `filled` or not.
fn put_band(bytes: &'static mut BandBytes, filled: bool) {
    critical_section::with(|cs| {
        *CORE1_BAND.borrow_ref_mut(cs) = Slot {
            bytes: Some(bytes),
            filled,
        }
    });
}

/// The SPI bus and chip-select pin as one device for `mipidsi`, which can be taken apart
/// again to stream pixels by DMA.
struct Device<S, P> {
    spi: S,
    cs: P,
}

impl<S: SpiBus, P: OutputPin> embedded_hal::spi::ErrorType for Device<S, P> {
    type Error = S::Error;
}

impl<S: SpiBus, P: OutputPin> SpiDevice for Device<S, P> {
    fn transaction(&mut self, operations: &mut [Operation<'_, u8>]) -> Result<(), S::Error> {
        let _ = self.cs.set_low();
        for op in operations {
            match op {
                Operation::Write(b) => self.spi.write(b)?,
                Operation::Read(b) => self.spi.read(b)?,
                Operation::Transfer(r, w) => self.spi.transfer(r, w)?,
                Operation::TransferInPlace(b) => self.spi.transfer_in_place(b)?,
                Operation::DelayNs(_) => {}
            }
        }
        self.spi.flush()?;
        let _ = self.cs.set_high();
        Ok(())
    }
}

#[entry]
fn main() -> ! {
    let Some(mut pac) = pac::Peripherals::take() else {
        panic!("peripherals taken twice")
    };
    let mut watchdog = Watchdog::new(pac.WATCHDOG);
    let Ok(clocks) = clocks::init_clocks_and_plls(
        XTAL_HZ,
        pac.XOSC,
        pac.CLOCKS,
        pac.PLL_SYS,
        pac.PLL_USB,
        &mut pac.RESETS,
        &mut watchdog,
    ) else {
        panic!("clocks")
    };
    let mut timer = Timer::new(pac.TIMER, &mut pac.RESETS, &clocks);
    let mut sio = Sio::new(pac.SIO);
    let pins = Pins::new(
        pac.IO_BANK0,
        pac.PADS_BANK0,
        sio.gpio_bank0,
        &mut pac.RESETS,
    );

    // ST7789 on SPI0: SCK GP18, MOSI GP19, CS GP17, DC GP16, reset GP21, backlight GP20.
    let spi_pins = (
        pins.gpio19.into_function::<FunctionSpi>(),
        pins.gpio18.into_function::<FunctionSpi>(),
    );
    let spi = Spi::<_, _, _, 8>::new(pac.SPI0, spi_pins).init(
        &mut pac.RESETS,
        clocks.peripheral_clock.freq(),
        62_500_000u32.Hz(),
        MODE_3,
    );
    let cs = pins.gpio17.into_push_pull_output();
    let mut dc = pins.gpio16.into_push_pull_output();
    let reset = pins.gpio21.into_push_pull_output();
    let mut backlight = pins.gpio20.into_push_pull_output();
    let mut command_buffer = [0u8; 64];
    let interface = SpiInterface::new(Device { spi, cs }, dc, &mut command_buffer);
    let Ok(display) = mipidsi::Builder::new(ST7789, interface)
        .display_size(LCD_SIZE as u16, LCD_SIZE as u16)
        .invert_colors(ColorInversion::Inverted)
        .reset_pin(reset)
        .init(&mut timer)
    else {
        panic!("ST7789 init")
    };
    let _ = backlight.set_high();
    // mipidsi has set the panel up; from here the pixels are streamed by DMA.
    let (interface, _, _) = display.release();
    let (device, released_dc) = interface.release();
    dc = released_dc;
    let Device { spi, mut cs } = device;
    let _ = cs.set_low();

    // The model and the frame's storage, in RAM for the whole run.
    let Some(positions) =
        cortex_m::singleton!(: [Vec3; TORUS_VERTICES] = [Vec3::ZERO; TORUS_VERTICES])
    else {
        panic!("storage")
    };
    let Some(normals) =
        cortex_m::singleton!(: [Vec3; TORUS_VERTICES] = [Vec3::ZERO; TORUS_VERTICES])
    else {
        panic!("storage")
    };
    let Some(triangles) =
        cortex_m::singleton!(: [[u16; 3]; TORUS_TRIANGLES] = [[0; 3]; TORUS_TRIANGLES])
    else {
        panic!("storage")
    };
    let Some(vertices) = cortex_m::singleton!(: [ScreenVertex; TORUS_VERTICES] = [ScreenVertex::DEFAULT; TORUS_VERTICES])
    else {
        panic!("storage")
    };
    let Some(bins) = cortex_m::singleton!(: [Bin; LCD_BINS] = [Bin::EMPTY; LCD_BINS]) else {
        panic!("storage")
    };
    let Some(color) =
        cortex_m::singleton!(: [Rgb565; LCD_BAND_CELLS] = [Rgb565::BLACK; LCD_BAND_CELLS])
    else {
        panic!("storage")
    };
    let Some(depth) = cortex_m::singleton!(: [u16; LCD_BAND_CELLS] = [0; LCD_BAND_CELLS]) else {
        panic!("storage")
    };
    let Some(own_bytes) = cortex_m::singleton!(: BandBytes = [0; 2 * LCD_BAND_CELLS]) else {
        panic!("storage")
    };
    let Some(core1_bytes) = cortex_m::singleton!(: BandBytes = [0; 2 * LCD_BAND_CELLS]) else {
        panic!("storage")
    };
    put_band(core1_bytes, false);
    let mesh = torus_mesh(TORUS_RING, TORUS_TUBE, positions, normals, triangles);

    let mut multicore = Multicore::new(&mut pac.PSM, &mut pac.PPB, &mut sio.fifo);
    let Some(stack) = CORE1_STACK.take() else {
        panic!("core 1's stack")
    };
    if multicore.cores()[1].spawn(stack, core1).is_err() {
        panic!("core 1 did not start");
    }

    let dma = pac.DMA.split(&mut pac.RESETS);
    let mut link = Some((dma.ch0, spi));
    // The transfer on its way to the display, and whether its bytes are core 1's.
    let mut in_flight = None;
    let mut own_bytes = Some(own_bytes);
    let mut frame_ms = 0u64;
    let mut frame = 0u32;
    // Whether this core's band buffers hold only black and the far depth (see draw_lcd_band).
    let mut clean = false;
    loop {
        let start = timer.get_counter();
        let models = lcd_models(&mesh, frame);
        frame = frame.wrapping_add(1);
        let Ok(prepared) = prepare_lcd(&models, &mut vertices[..], &mut bins[..]) else {
            continue;
        };
        // The whole screen as the window and RAMWR: then every band's bytes in order.
        if let Some((_, spi)) = link.as_mut() {
            window(spi, &mut dc);
        }
        sio.fifo
            .write_blocking(&prepared as *const PreparedFrame<'_> as u32);
        for band in 0..LCD_BANDS {
            // This band's bytes, drawn here (even bands) while the last one goes out, or by
            // core 1 (odd ones).
            let (bytes, core1) = match own_bytes.take() {
                Some(bytes) if band % 2 == 0 => {
                    clean = draw_lcd_band(&prepared, band, &mut color[..], &mut depth[..], clean)
                        .unwrap_or(false);
                    if band == 0 {
                        frame_time(&mut color[..], frame_ms);
                        clean = false;
                    }
                    lcd_bytes(&color[..], &mut bytes[..]);
                    (bytes, false)
                }
                mine => {
                    own_bytes = mine;
                    let _ = sio.fifo.read_blocking();
                    (take_band(true), true)
                }
            };
            // The last band has been sent: its bytes go back to whoever fills them.
            if let Some((transfer, was_core1)) = in_flight.take() {
                let (channel, sent, spi) = single_buffer::Transfer::wait(transfer);
                if was_core1 {
                    put_band(sent, false);
                } else {
                    own_bytes = Some(sent);
                }
                link = Some((channel, spi));
            }
            if let Some((channel, spi)) = link.take() {
                in_flight = Some((
                    single_buffer::Config::new(channel, bytes, spi).start(),
                    core1,
                ));
            }
        }
        if let Some((transfer, was_core1)) = in_flight.take() {
            let (channel, sent, mut spi) = single_buffer::Transfer::wait(transfer);
            if was_core1 {
                put_band(sent, false);
            } else {
                own_bytes = Some(sent);
            }
            let _ = spi.flush();
            link = Some((channel, spi));
        }
        frame_ms = (timer.get_counter() - start).to_millis();
    }
}

/// Core 1: draws the odd bands of each frame core 0 prepares, into its own buffers.
fn core1() {
    // SAFETY: core 1 touches only the SIO's inter-core FIFO of these peripherals (each core
    // has its own end of it).
    let pac = unsafe { pac::Peripherals::steal() };
    let mut sio = Sio::new(pac.SIO);
    let (Some(color), Some(depth)) = (
        cortex_m::singleton!(: [Rgb565; LCD_BAND_CELLS] = [Rgb565::BLACK; LCD_BAND_CELLS]),
        cortex_m::singleton!(: [u16; LCD_BAND_CELLS] = [0; LCD_BAND_CELLS]),
    ) else {
        return;
    };
    // Whether this core's band buffers hold only black and the far depth (see draw_lcd_band).
    let mut clean = false;
    loop {
        let address = sio.fifo.read_blocking();
        // SAFETY: core 0 sends the address of a frame it has prepared, and keeps it alive and
        // unchanged until it has read this core's last band of the frame, after which this
        // core reads nothing of it.
        let frame = unsafe { &*(address as *const PreparedFrame<'static>) };
        for band in (1..LCD_BANDS).step_by(2) {
            clean =
                draw_lcd_band(frame, band, &mut color[..], &mut depth[..], clean).unwrap_or(false);
            let bytes = take_band(false);
            lcd_bytes(&color[..], &mut bytes[..]);
            put_band(bytes, true);
            sio.fifo.write_blocking(band);
        }
    }
}

/// Sends the ST7789 the whole screen as its window and starts a memory write: the bytes sent
/// next (data, DC high) fill it row by row.
fn window<S: SpiBus, P: OutputPin>(spi: &mut S, dc: &mut P) {
    let last = (LCD_SIZE - 1) as u8;
    for (command, args) in [
        (0x2a, &[0, 0, 0, last][..]), // CASET: columns 0 to 239
        (0x2b, &[0, 0, 0, last][..]), // RASET: rows 0 to 239
        (0x2c, &[][..]),              // RAMWR
    ] {
        let _ = dc.set_low();
        let _ = spi.write(&[command]);
        let _ = spi.flush();
        let _ = dc.set_high();
        let _ = spi.write(args);
        let _ = spi.flush();
    }
}

/// Writes the last frame's time in the band's top-left corner.
fn frame_time(color: &mut [Rgb565], ms: u64) {
    let Ok(mut band) = FrameBuffer::new(color, LCD_SIZE, LCD_BAND_ROWS) else {
        return;
    };
    let mut text = heapless::String::<16>::new();
    let _ = write!(text, "{ms} ms");
    let style = MonoTextStyle::new(&FONT_6X10, Rgb565::WHITE);
    let _ = Text::with_baseline(&text, Point::new(2, 3), style, Baseline::Top).draw(&mut band);
}
