//! Exact golden images: PNGs under tests/golden, compared pixel for pixel (the pipeline is
//! integer and deterministic). `BLESS=1 cargo test` rewrites them; review the diff before
//! committing.
#![allow(dead_code)]

use embedded_graphics::pixelcolor::{Rgb888, RgbColor};
use std::path::PathBuf;

fn path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/golden")
        .join(format!("{name}.png"))
}

pub fn write_png(path: &std::path::Path, w: u32, h: u32, pixels: &[Rgb888]) {
    let file = std::fs::File::create(path).unwrap();
    let mut enc = png::Encoder::new(std::io::BufWriter::new(file), w, h);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    let mut writer = enc.write_header().unwrap();
    let data: Vec<u8> = pixels.iter().flat_map(|c| [c.r(), c.g(), c.b()]).collect();
    writer.write_image_data(&data).unwrap();
}

pub fn read_png(path: &std::path::Path) -> Option<(u32, u32, Vec<Rgb888>)> {
    let file = std::fs::File::open(path).ok()?;
    let mut dec = png::Decoder::new(std::io::BufReader::new(file))
        .read_info()
        .ok()?;
    let mut buf = vec![0; dec.output_buffer_size()?];
    let info = dec.next_frame(&mut buf).ok()?;
    let bytes = &buf[..info.buffer_size()];
    let px = match info.color_type {
        png::ColorType::Rgb => bytes
            .chunks(3)
            .map(|c| Rgb888::new(c[0], c[1], c[2]))
            .collect(),
        png::ColorType::Rgba => bytes
            .chunks(4)
            .map(|c| Rgb888::new(c[0], c[1], c[2]))
            .collect(),
        _ => return None,
    };
    Some((info.width, info.height, px))
}

/// Compares `pixels` with the golden image `name`; with `BLESS=1` writes it instead.
pub fn check(name: &str, w: u32, h: u32, pixels: &[Rgb888]) {
    let p = path(name);
    if std::env::var_os("BLESS").is_some() {
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        write_png(&p, w, h, pixels);
        return;
    }
    let Some((gw, gh, golden)) = read_png(&p) else {
        panic!(
            "golden image {} missing: run with BLESS=1 to create it",
            p.display()
        );
    };
    assert_eq!((gw, gh), (w, h), "golden image {name} has another size");
    let differ = golden.iter().zip(pixels).filter(|(a, b)| a != b).count();
    let largest = golden
        .iter()
        .zip(pixels)
        .map(|(a, b)| {
            let d = |x: u8, y: u8| x.abs_diff(y);
            d(a.r(), b.r()).max(d(a.g(), b.g())).max(d(a.b(), b.b()))
        })
        .max()
        .unwrap_or(0);
    if differ != 0 {
        let out = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("{name}.actual.png"));
        write_png(&out, w, h, pixels);
        panic!(
            "{differ} pixels differ from golden image {name} (by up to {largest} in a \
             channel); actual image: {}",
            out.display()
        );
    }
}
