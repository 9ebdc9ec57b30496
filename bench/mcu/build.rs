use std::{env, fs, path::PathBuf};

fn main() {
    let board = if env::var_os("CARGO_FEATURE_BOARD_MICROBIT").is_some() {
        "microbit"
    } else {
        "mps2"
    };
    let out = PathBuf::from(env::var_os("OUT_DIR").unwrap());
    fs::copy(format!("boards/{board}.x"), out.join("memory.x")).unwrap();
    println!("cargo:rustc-link-search={}", out.display());
    println!("cargo:rerun-if-changed=boards");
    for v in ["BENCH_FRAMES", "BENCH_FB_W", "BENCH_FB_H"] {
        println!("cargo:rerun-if-env-changed={v}");
    }
    println!(
        "cargo:rustc-env=BENCH_TARGET={}",
        env::var("TARGET").unwrap()
    );
    println!("cargo:rustc-env=BENCH_BOARD={board}");
}
