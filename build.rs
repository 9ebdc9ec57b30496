//! Tells the crate which Thumb instruction set its target runs, for the `asm` feature's loops:
//! `fixed3d_thumb2` where it has IT blocks and a divide (ARMv7-M and ARMv8-M mainline:
//! `thumbv7m`, `thumbv7em`, `thumbv8m.main`; src/target/thumb2.rs), `fixed3d_thumb1` on
//! ARMv6-M (`thumbv6m`; src/target/thumb1.rs), and `fixed3d_thumb` for either. No `cfg` tells
//! ARMv7-M from ARMv8-M baseline, which has the same atomics but neither IT blocks nor shifted
//! register offsets, nor ARMv6-M's edge walk (the crate walks edges by the target's atomics):
//! it gets neither. `fixed3d_asm_rows` marks every target with a row loop in assembly: those
//! two and x86-64 (src/target/x86_64.rs). `fixed3d_stages`, set by the environment variable
//! `FIXED3D_STAGES` (bench/host.sh's stage breakdown), keeps apart the functions whose
//! instructions that breakdown counts, which the crate otherwise has in line.
fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-env-changed=FIXED3D_STAGES");
    println!("cargo:rustc-check-cfg=cfg(fixed3d_stages)");
    if std::env::var_os("FIXED3D_STAGES").is_some() {
        println!("cargo:rustc-cfg=fixed3d_stages");
    }
    for cfg in [
        "fixed3d_thumb",
        "fixed3d_thumb1",
        "fixed3d_thumb2",
        "fixed3d_asm_rows",
        "fixed3d_dsp",
    ] {
        println!("cargo:rustc-check-cfg=cfg({cfg})");
    }
    let target = std::env::var("TARGET").unwrap_or_default();
    let starts = |prefixes: &[&str]| prefixes.iter().any(|p| target.starts_with(p));
    let set = if starts(&["thumbv7m-", "thumbv7em-", "thumbv8m.main-"]) {
        Some("fixed3d_thumb2")
    } else if starts(&["thumbv6m-"]) {
        Some("fixed3d_thumb1")
    } else {
        None
    };
    if let Some(cfg) = set {
        println!("cargo:rustc-cfg={cfg}");
        println!("cargo:rustc-cfg=fixed3d_thumb");
    }
    // The DSP extension's halfword instructions (`usub16`, `sel`): Cortex-M4 and M7.
    if starts(&["thumbv7em-"]) {
        println!("cargo:rustc-cfg=fixed3d_dsp");
    }
    if set.is_some() || std::env::var("CARGO_CFG_TARGET_ARCH").as_deref() == Ok("x86_64") {
        println!("cargo:rustc-cfg=fixed3d_asm_rows");
    }
}
