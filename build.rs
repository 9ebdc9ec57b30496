//! Tells the crate whether its target runs Thumb-2 with IT blocks (ARMv7-M and ARMv8-M
//! mainline: `thumbv7m`, `thumbv7em`, `thumbv8m.main`), where the `asm` feature's pixel loop
//! (src/target/thumb2.rs) assembles; no `cfg` tells those apart from ARMv8-M baseline, which
//! has the same atomics but neither IT blocks nor shifted register offsets.
fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rustc-check-cfg=cfg(fixed3d_thumb2)");
    let target = std::env::var("TARGET").unwrap_or_default();
    if ["thumbv7m-", "thumbv7em-", "thumbv8m.main-"]
        .iter()
        .any(|prefix| target.starts_with(prefix))
    {
        println!("cargo:rustc-cfg=fixed3d_thumb2");
    }
}
