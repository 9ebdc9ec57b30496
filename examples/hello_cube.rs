//! A lit cube spinning for a few seconds: the common path of fixed3d, whole.
//!
//! ```text
//! cargo run --example hello_cube                      # PNG frames in target/hello_cube/
//! cargo run --example hello_cube --features window    # in a window (needs SDL2)
//! ```
//!
//! The display is embedded-graphics' simulator; on a board it is the display driver, and the
//! loop is the same. The buffers hold 20 rows: the frame is drawn in twelve bands.

use embedded_graphics::pixelcolor::{Rgb565, Rgb888, RgbColor};
use embedded_graphics::prelude::*;
use embedded_graphics_simulator::SimulatorDisplay;
use fixed3d::mesh::CUBE;
use fixed3d::{Camera, Light, Model, Renderer, Storage};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut display = SimulatorDisplay::<Rgb565>::new(Size::new(240, 240));
    let camera = Camera::perspective(60, 1, 10).looking_at([2, 2, 3], [0, 0, 0]);
    let lights = [Light::ambient(0.2), Light::directional([-1, 1, 1], 0.8)];
    let mut storage = Storage::<8, 12>::new(); // the cube's 8 vertices and 12 triangles
    let (mut color, mut depth) = ([Rgb565::BLACK; 240 * 20], [0u16; 240 * 20]);
    let mut renderer = Renderer::new(&mut storage, &mut color, &mut depth);
    let mut output = output::Output::new()?;
    for frame in 0..90 {
        let cube = Model::new(&CUBE, Rgb888::new(255, 160, 64)).rotated_y(frame * 4);
        renderer.render(&[cube.rotated_x(25)], &lights, &camera, &mut display)?;
        if !output.show(&display, frame)? {
            break;
        }
    }
    Ok(())
}

/// Where the frames go: a window with the `window` feature, else every tenth frame as a PNG.
mod output {
    use embedded_graphics::pixelcolor::Rgb565;
    use embedded_graphics_simulator::{OutputSettings, SimulatorDisplay};

    #[cfg(feature = "window")]
    pub struct Output(embedded_graphics_simulator::Window);

    #[cfg(feature = "window")]
    impl Output {
        pub fn new() -> Result<Self, String> {
            let settings = OutputSettings::default();
            Ok(Output(embedded_graphics_simulator::Window::new(
                "hello cube",
                &settings,
            )))
        }

        /// Shows `display`; false once the window is closed.
        pub fn show(&mut self, display: &SimulatorDisplay<Rgb565>, _: i32) -> Result<bool, String> {
            use embedded_graphics_simulator::SimulatorEvent;
            self.0.update(display);
            std::thread::sleep(std::time::Duration::from_millis(33));
            Ok(!self.0.events().any(|e| e == SimulatorEvent::Quit))
        }
    }

    #[cfg(not(feature = "window"))]
    pub struct Output(std::path::PathBuf);

    #[cfg(not(feature = "window"))]
    impl Output {
        pub fn new() -> Result<Self, std::io::Error> {
            let dir =
                std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target/hello_cube");
            std::fs::create_dir_all(&dir)?;
            Ok(Output(dir))
        }

        /// Saves every tenth frame.
        pub fn show(
            &mut self,
            display: &SimulatorDisplay<Rgb565>,
            frame: i32,
        ) -> Result<bool, String> {
            if frame % 10 == 0 {
                let path = self.0.join(format!("frame-{frame:03}.png"));
                let image = display.to_rgb_output_image(&OutputSettings::default());
                image.save_png(&path).map_err(|e| e.to_string())?;
                println!("{}", path.display());
            }
            Ok(true)
        }
    }
}
