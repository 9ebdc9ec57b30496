//! Error against run time: every precision knob on every report scene, against the f64
//! reference, with instruction counts and host time measured in the same run.
//!
//! ```text
//! cargo run --release --features micromath --example accuracy            # writes the report
//! cargo run --release --example accuracy -- --no-count                    # no callgrind
//! ```
//!
//! Writes `docs/accuracy.md` (tables) and `docs/images/accuracy.svg` (error against
//! instructions, Pareto front marked). Instruction counts come from callgrind (valgrind is
//! used when installed; `--no-count` skips them): the program runs itself under callgrind once
//! per configuration, counting only `measured_frame` (vertex stage, culling, shading and
//! filling; buffer clears excluded). Cortex-M4 and Cortex-M0 counts of the torus come from the
//! firmware benchmark's `knobs` preset under QEMU (`bench/mcu/run.sh`, when
//! `qemu-system-arm` is installed: `bench/mcu/run.sh setup`; `--no-mcu` skips them). Exits
//! with 1 if the default configuration breaks a required limit (M1 = 0, no missing or
//! unexpected pixel, no occlusion error, depth within 1 LSB of the snapped plane, flat colour
//! within 1 LSB, every plain textured pixel showing its texel, vertices within their bound).

#[path = "common/accuracy.rs"]
mod accuracy;
#[path = "common/desktop.rs"]
mod desktop;
#[path = "common/exact.rs"]
mod exact;
#[path = "common/reference.rs"]
mod reference;

use std::collections::HashMap;
use std::fmt::Write as _;
use std::process::{Command, ExitCode};

use accuracy::{configs, ideal, measure, render, scenes, Config, Ideal, Metrics, Shade};

const MODELS: &str = "models";
const TIMED_FRAMES: usize = 7;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let models = std::path::Path::new(MODELS).is_dir().then_some(MODELS);
    // Child mode under callgrind: render every scene (or one) in one configuration, once.
    if let Some(i) = args.iter().position(|a| a == "--count") {
        let (Some(name), only) = (args.get(i + 1), args.get(i + 2)) else {
            return ExitCode::from(2);
        };
        let Some(config) = configs().into_iter().find(|c| c.name == name) else {
            return ExitCode::from(2);
        };
        for scene in scenes(models, false) {
            if only.is_none_or(|o| *o == scene.name) {
                let _ = render(&scene, &config, 1);
            }
        }
        return ExitCode::SUCCESS;
    }
    let count = !args.iter().any(|a| a == "--no-count") && valgrind_available();
    let scenes = scenes(models, false);
    let configs = configs();
    if models.is_none() {
        eprintln!("note: {MODELS} not found: the OBJ model scenes are left out");
    }
    if !cfg!(feature = "micromath") {
        eprintln!("note: built without the micromath feature: its configurations are left out");
    }
    let mut results: Vec<(usize, usize, Metrics, f64)> = Vec::new();
    for (si, scene) in scenes.iter().enumerate() {
        let mut ideals: HashMap<(bool, u32), Ideal> = HashMap::new();
        for (ci, config) in configs.iter().enumerate() {
            let key = (
                config.shade != Shade::Flat,
                config.precision.subpixel_bits(),
            );
            let reference = ideals.entry(key).or_insert_with(|| {
                let shade = if key.0 {
                    Shade::Perspective
                } else {
                    Shade::Flat
                };
                ideal(scene, shade, key.1)
            });
            let Some((image, time)) = render(scene, config, TIMED_FRAMES) else {
                eprintln!("{}: cannot render {}", scene.name, config.name);
                return ExitCode::FAILURE;
            };
            let m = measure(scene, config, reference, &image);
            results.push((si, ci, m, time));
        }
        eprintln!("{}: measured", scene.name);
    }
    let mcu = if !args.iter().any(|a| a == "--no-mcu") && qemu_available() {
        firmware_counts()
    } else {
        eprintln!("note: no Cortex-M counts (qemu-system-arm missing or --no-mcu)");
        HashMap::new()
    };
    let mut counts: HashMap<&str, (u64, u64)> = HashMap::new();
    if count {
        for config in &configs {
            let all = callgrind(config.name, None);
            let torus = callgrind(config.name, Some("torus"));
            if let (Some(all), Some(torus)) = (all, torus) {
                counts.insert(config.name, (torus, all));
            }
            eprintln!("{}: counted", config.name);
        }
    } else {
        eprintln!("note: no instruction counts (valgrind missing or --no-count)");
    }
    let report = Report {
        scenes: &scenes,
        configs: &configs,
        results: &results,
        counts: &counts,
        mcu: &mcu,
    };
    let failures = report.default_failures();
    let md = report.markdown(&failures);
    let svg = report.svg();
    let written = std::fs::create_dir_all("docs/images")
        .and_then(|_| std::fs::write("docs/accuracy.md", md))
        .and_then(|_| std::fs::write("docs/images/accuracy.svg", svg));
    if let Err(e) = written {
        eprintln!("cannot write the report: {e}");
        return ExitCode::FAILURE;
    }
    for line in report.summary() {
        println!("{line}");
    }
    println!("wrote docs/accuracy.md and docs/images/accuracy.svg");
    if failures.is_empty() {
        println!("default configuration: every required limit holds on every scene");
        ExitCode::SUCCESS
    } else {
        for f in &failures {
            println!("REQUIRED LIMIT BROKEN: {f}");
        }
        ExitCode::FAILURE
    }
}

fn qemu_available() -> bool {
    Command::new("qemu-system-arm")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success())
}

/// Instructions per frame of the torus in each configuration on the emulated Cortex-M4 and
/// Cortex-M0: `(configuration, "m4" | "m0") → count`, from the `knobs` firmware preset.
fn firmware_counts() -> HashMap<(String, &'static str), u64> {
    let mut out = HashMap::new();
    let run = Command::new("bench/mcu/run.sh")
        .env("PRESETS", "knobs")
        .env("TARGETS", "thumbv7em-none-eabihf thumbv6m-none-eabi")
        .output();
    let Ok(run) = run else {
        eprintln!("note: bench/mcu/run.sh did not start");
        return out;
    };
    for line in String::from_utf8_lossy(&run.stdout).lines() {
        let field = |k: &str| {
            line.split_whitespace()
                .find_map(|w| w.strip_prefix(k)?.strip_prefix('='))
        };
        let (Some(name), Some(target), Some(n)) = (
            field("preset").and_then(|p| p.strip_prefix("knobs:")),
            field("target"),
            field("instructions_per_frame").and_then(|n| n.parse().ok()),
        ) else {
            continue;
        };
        let core = if target.starts_with("thumbv7em") {
            "m4"
        } else {
            "m0"
        };
        out.insert((name.to_string(), core), n);
    }
    eprintln!("Cortex-M counts: {} configurations", out.len() / 2);
    out
}

fn valgrind_available() -> bool {
    Command::new("valgrind")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success())
}

/// Instructions inside `measured_frame` when this program renders `config` under callgrind.
fn callgrind(config: &str, only: Option<&str>) -> Option<u64> {
    let exe = std::env::current_exe().ok()?;
    let out = std::env::temp_dir().join(format!(
        "fixed3d-accuracy-{}-{config}-{}.cg",
        std::process::id(),
        only.unwrap_or("all")
    ));
    let mut cmd = Command::new("valgrind");
    cmd.arg("--tool=callgrind")
        .arg("--toggle-collect=*measured_frame*")
        .arg(format!("--callgrind-out-file={}", out.display()))
        .arg(exe)
        .arg("--count")
        .arg(config);
    if let Some(o) = only {
        cmd.arg(o);
    }
    let status = cmd.output().ok()?.status;
    let text = std::fs::read_to_string(&out).ok();
    let _ = std::fs::remove_file(&out);
    if !status.success() {
        return None;
    }
    text?
        .lines()
        .find_map(|l| {
            l.strip_prefix("totals:")
                .or_else(|| l.strip_prefix("summary:"))
        })
        .and_then(|v| v.split_whitespace().next()?.parse().ok())
}

struct Report<'a> {
    scenes: &'a [accuracy::SceneDef],
    configs: &'a [Config],
    results: &'a [(usize, usize, Metrics, f64)],
    counts: &'a HashMap<&'a str, (u64, u64)>,
    mcu: &'a HashMap<(String, &'static str), u64>,
}

/// A configuration's metrics over all scenes: sums of counts, maxima of errors, means of means.
#[derive(Default)]
struct Summary {
    m: Metrics,
    psnr_min: f64,
    rmse_mean: f64,
    torus_time: f64,
    total_time: f64,
}

impl Report<'_> {
    fn of(&self, ci: usize) -> impl Iterator<Item = &(usize, usize, Metrics, f64)> {
        self.results.iter().filter(move |r| r.1 == ci)
    }

    fn summary_of(&self, ci: usize) -> Summary {
        let mut s = Summary {
            psnr_min: f64::INFINITY,
            ..Summary::default()
        };
        let (mut n, mut colored) = (0.0, 0.0f64);
        for (si, _, m, t) in self.of(ci) {
            let a = &mut s.m;
            a.covered += m.covered;
            a.m1 += m.m1;
            a.missing += m.missing;
            a.unexpected += m.unexpected;
            a.partial += m.partial;
            a.occlusion += m.occlusion;
            a.vertex_over_bound += m.vertex_over_bound;
            a.depth_plane_max = a.depth_plane_max.max(m.depth_plane_max);
            a.depth_max = a.depth_max.max(m.depth_max);
            a.depth_mean += m.depth_mean;
            // A textured scene's colour error is its texel error, counted on its own.
            if self.scenes[*si].textured {
                a.texel_max = a.texel_max.max(m.texel_max);
                a.texel_over += m.texel_over;
                a.texel_compared += m.texel_compared;
            } else {
                a.color_max = a.color_max.max(m.color_max);
                a.color_mean += m.color_mean;
                s.psnr_min = s.psnr_min.min(m.psnr);
                colored += 1.0;
            }
            a.vertex_max = a.vertex_max.max(m.vertex_max);
            s.rmse_mean += m.image_rmse;
            s.total_time += t;
            if self.scenes[*si].name == "torus" {
                s.torus_time = *t;
            }
            n += 1.0;
        }
        if n > 0.0 {
            s.m.depth_mean /= n;
            s.m.color_mean /= colored.max(1.0);
            s.rmse_mean /= n;
        }
        s
    }

    fn default_failures(&self) -> Vec<String> {
        let mut out = Vec::new();
        for (si, _, m, _) in self.of(0) {
            let name = self.scenes[*si].name;
            let mut check = |ok: bool, what: String| {
                if !ok {
                    out.push(format!("{name}: {what}"));
                }
            };
            check(m.m1 == 0, format!("M1 = {}", m.m1));
            check(m.missing == 0, format!("{} missing pixels", m.missing));
            check(
                m.unexpected == 0,
                format!("{} unexpected pixels", m.unexpected),
            );
            check(
                m.occlusion == 0,
                format!("{} occlusion errors", m.occlusion),
            );
            check(
                m.depth_plane_max <= 1.0,
                format!("depth {:.2} LSB from the plane", m.depth_plane_max),
            );
            if self.scenes[*si].textured {
                check(
                    m.texel_over == 0,
                    format!("{} pixels show another texel", m.texel_over),
                );
            } else {
                check(m.color_max <= 1.0, format!("colour error {}", m.color_max));
            }
            check(
                m.vertex_over_bound == 0,
                format!("{} vertices beyond their bound", m.vertex_over_bound),
            );
        }
        out
    }

    fn counts_of(&self, c: &Config) -> Option<(u64, u64)> {
        self.counts.get(c.name).copied()
    }

    /// (x, y) of each configuration in the plot: instructions over all scenes (or host time
    /// when not counted) and the mean image RMSE.
    fn points(&self) -> Vec<(f64, f64)> {
        (0..self.configs.len())
            .map(|ci| {
                let s = self.summary_of(ci);
                let x = match self.counts_of(&self.configs[ci]) {
                    Some((_, all)) => all as f64 / 1e6,
                    None => s.total_time * 1e3,
                };
                (x, s.rmse_mean)
            })
            .collect()
    }

    fn pareto(&self) -> Vec<bool> {
        let p = self.points();
        p.iter()
            .map(|a| {
                !p.iter()
                    .any(|b| (b.0 <= a.0 && b.1 <= a.1) && (b.0 < a.0 || b.1 < a.1))
            })
            .collect()
    }

    fn summary(&self) -> Vec<String> {
        let front = self.pareto();
        (0..self.configs.len())
            .map(|ci| {
                let c = &self.configs[ci];
                let s = self.summary_of(ci);
                let ir = self
                    .counts_of(c)
                    .map_or("-".into(), |(t, a)| format!("{:.2} M torus, {:.2} M all", t as f64 / 1e6, a as f64 / 1e6));
                format!(
                    "{:<20} RMSE {:.3}  missing {} unexpected {} occlusion {}  colour max {:.0}  vertex max {:.2} sub-px  {}{}",
                    c.name,
                    s.rmse_mean,
                    s.m.missing,
                    s.m.unexpected,
                    s.m.occlusion,
                    s.m.color_max,
                    s.m.vertex_max,
                    ir,
                    if front[ci] { "  (Pareto)" } else { "" }
                )
            })
            .collect()
    }

    fn markdown(&self, failures: &[String]) -> String {
        let mut md = String::new();
        let front = self.pareto();
        let counted = !self.counts.is_empty();
        let _ = writeln!(
            md,
            "# Error against run time\n\n\
             Generated by `cargo run --release --features micromath --example accuracy` (do not edit by\n\
             hand). Every configuration renders every scene; each image is compared with REF_EXACT\n\
             (the same snapped vertices through i128 edge functions) and REF_IDEAL (f64 matrices\n\
             from the exact angles, f64 near/far clipping, no snapping, per-pixel edge functions,\n\
             f64 Lambert, perspective-correct Gouraud). Inputs are the same numbers for both, so\n\
             every difference is the renderer's. Metrics are named as in [cases.md](cases.md) (M1–M12);\n\
             colours are in 8-bit units (Rgb888), depths in units of the configuration's depth\n\
             format (LSB), vertex errors in sixteenths of a pixel.\n"
        );
        let _ = writeln!(
            md,
            "Run time: instructions counted by callgrind inside `measured_frame` (vertex stage,\n\
             culling, shading, filling; clears excluded) for the torus and for all scenes; host time\n\
             is the median of {TIMED_FRAMES} frames per scene on the machine that generated this file,\n\
             measured in the same run (noisy; the counts are exact). Cortex-M4 and Cortex-M0 counts\n\
             are the torus's instructions per frame under QEMU (`-icount`), from the firmware\n\
             benchmark's `knobs` preset (`bench/mcu`, `opt-level = \"s\"`, fat LTO, every\n\
             configuration in one binary, so its default costs a little more than the `full`\n\
             preset's); for the texture knobs, those of the `textured` preset's torus\n\
             (`texture-run-16` is its default).\n"
        );
        let _ = writeln!(md, "![error against instructions](images/accuracy.svg)\n");
        let _ = writeln!(md, "## Configurations (summed or worst over all scenes)\n");
        let _ = writeln!(
            md,
            "| configuration | knob | instructions, torus | instructions, all scenes | Cortex-M4, torus | Cortex-M0, torus | host time, all scenes | image RMSE | M1 | missing | unexpected | partial | occlusion | depth vs plane (max LSB) | depth vs ideal (max / mean LSB) | colour max / mean (untextured) | PSNR (worst untextured scene) | vertex max (sub-px) | texel error max (texels) / wrong texels of plain pixels | Pareto |"
        );
        let _ = writeln!(
            md,
            "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|:-:|"
        );
        for (ci, c) in self.configs.iter().enumerate() {
            let s = self.summary_of(ci);
            let (t, a) = match self.counts_of(c) {
                Some((t, a)) => (
                    format!("{:.3} M", t as f64 / 1e6),
                    format!("{:.2} M", a as f64 / 1e6),
                ),
                None => ("-".into(), "-".into()),
            };
            let m = |core: &'static str| {
                self.mcu
                    .get(&(c.name.to_string(), core))
                    .map_or("-".to_string(), |n| format!("{:.2} M", *n as f64 / 1e6))
            };
            let _ = writeln!(
                md,
                "| `{}` | {} | {} | {} | {} | {} | {:.2} ms | {:.3} | {} | {} | {} | {} | {} | {:.2} | {:.0} / {:.1} | {:.0} / {:.3} | {:.1} dB | {:.2} | {:.3} / {} of {} | {} |",
                c.name,
                if c.knob.is_empty() { "—" } else { c.knob },
                t,
                a,
                m("m4"),
                m("m0"),
                s.total_time * 1e3,
                s.rmse_mean,
                s.m.m1,
                s.m.missing,
                s.m.unexpected,
                s.m.partial,
                s.m.occlusion,
                s.m.depth_plane_max,
                s.m.depth_max,
                s.m.depth_mean,
                s.m.color_max,
                s.m.color_mean,
                s.psnr_min,
                s.m.vertex_max,
                s.m.texel_max,
                s.m.texel_over,
                s.m.texel_compared,
                if front[ci] { "●" } else { "" }
            );
        }
        let _ = writeln!(md, "\nWhat each configuration is:\n");
        for c in self.configs {
            let _ = writeln!(md, "- `{}`: {}", c.name, c.describe());
        }
        let _ = writeln!(md, "\n## Scenes\n");
        for s in self.scenes {
            let _ = writeln!(
                md,
                "- **{}** ({} triangles, {}x{}): {}",
                s.name,
                s.model.triangles.len(),
                s.width,
                s.height,
                s.what
            );
        }
        let _ = writeln!(
            md,
            "\n## The default configuration, scene by scene\n\n\
             Required ([cases.md](cases.md)): M1 = 0; 0 missing and 0 unexpected pixels outside\n\
             the partial band; 0 occlusion errors; depth within 1 LSB of the plane through the\n\
             snapped vertices; flat Lambert colour within 1 LSB per channel (in the textured\n\
             scenes: every plain pixel showing its texel); every vertex within half a sub-pixel\n\
             per axis plus its transform bound.\n"
        );
        md.push_str(&self.scene_table(0));
        if failures.is_empty() {
            let _ = writeln!(md, "\nEvery required limit holds on every scene.");
        } else {
            let _ = writeln!(md, "\n**Required limits broken:**\n");
            for f in failures {
                let _ = writeln!(md, "- {f}");
            }
        }
        let _ = writeln!(md, "\n## Every configuration, scene by scene\n");
        for (ci, c) in self.configs.iter().enumerate().skip(1) {
            let _ = writeln!(md, "### `{}` ({})\n", c.name, c.describe());
            md.push_str(&self.scene_table(ci));
            md.push('\n');
        }
        let _ = writeln!(
            md,
            "## How to read it\n\n\
             - *partial* pixels are those whose centre lies within the tolerance of an edge of the\n\
               ideal polygon (half a snapping cell per axis plus the default matrix's rounding\n\
               carried to the screen); anything goes there, as in dEQP. Missing and unexpected\n\
               pixels are outside that band.\n\
             - *occlusion* counts pixels whose depth is nearer another surface of the ideal image\n\
               than the visible one, where the two are more than 2 LSB apart.\n\
             - *depth vs ideal* and *colour* are measured over pixels the ideal visible polygon\n\
               covers by more than the tolerance, excluding occlusion errors and surfaces closer\n\
               than 2 LSB.\n\
             - *image RMSE* compares the whole image with the ideal one, background included: the\n\
               error a viewer sees, and the plot's vertical axis.\n\
             - In the textured scenes (a white ambient light of 1 alone, a texture whose texels all\n\
               differ) a pixel's colour tells which texel it shows. *texel error* is how far the\n\
               exact f64 texel coordinates lie outside that texel, over the pixels compared for\n\
               colour whose texel is *plain*: the exact point stays in one texel when the pixel's\n\
               sample moves by 1/8 pixel and the coordinates by 1/16 texel (where texels are\n\
               smaller than that, which one nearest sampling shows is aliasing). Their colour\n\
               error is left out of the *colour* and *PSNR* columns of the configuration table.\n\
             - The plot's horizontal axis is the instruction count over all scenes{}.\n",
            if counted { "" } else { " (here host time: valgrind was not available)" }
        );
        md
    }

    fn scene_table(&self, ci: usize) -> String {
        let mut md = String::new();
        let _ = writeln!(
            md,
            "| scene | covered | host time | image RMSE | M1 | missing | unexpected | partial | occlusion | depth vs plane (max LSB) | depth vs ideal (max / mean LSB) | colour max / mean | PSNR | vertex max (sub-px) | texel error max / wrong texels of plain pixels |"
        );
        let _ = writeln!(
            md,
            "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
        );
        for (si, _, m, t) in self.of(ci) {
            let _ = writeln!(
                md,
                "| {} | {} | {:.0} µs | {:.3} | {} | {} | {} | {} | {} | {:.2} | {:.0} / {:.1} | {:.0} / {:.3} | {:.1} dB | {:.2} | {} |",
                self.scenes[*si].name,
                m.covered,
                t * 1e6,
                m.image_rmse,
                m.m1,
                m.missing,
                m.unexpected,
                m.partial,
                m.occlusion,
                m.depth_plane_max,
                m.depth_max,
                m.depth_mean,
                m.color_max,
                m.color_mean,
                m.psnr,
                m.vertex_max,
                if self.scenes[*si].textured {
                    format!("{:.3} / {} of {}", m.texel_max, m.texel_over, m.texel_compared)
                } else {
                    "—".into()
                }
            );
        }
        md
    }

    fn svg(&self) -> String {
        let points = self.points();
        let front = self.pareto();
        let counted = !self.counts.is_empty();
        let (w, h, left, right, top, bottom) = (800.0, 460.0, 80.0, 220.0, 40.0, 60.0);
        let xmax = points.iter().map(|p| p.0).fold(0.0, f64::max) * 1.1;
        let xmin = points.iter().map(|p| p.0).fold(f64::INFINITY, f64::min) * 0.9;
        let (ylo, yhi) = {
            let lo = points
                .iter()
                .map(|p| p.1.max(1e-3))
                .fold(f64::INFINITY, f64::min);
            let hi = points.iter().map(|p| p.1.max(1e-3)).fold(0.0, f64::max);
            (
                lo.log10().floor(),
                hi.log10().ceil().max(lo.log10().floor() + 1.0),
            )
        };
        let px = |x: f64| left + (x - xmin) / (xmax - xmin).max(1e-9) * (w - left - right);
        let py = |y: f64| top + (yhi - y.max(1e-3).log10()) / (yhi - ylo) * (h - top - bottom);
        let mut s = String::new();
        let _ = writeln!(
            s,
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="sans-serif" font-size="12">"#
        );
        let _ = writeln!(s, r#"<rect width="{w}" height="{h}" fill="white"/>"#);
        let _ = writeln!(
            s,
            r#"<text x="{}" y="22" text-anchor="middle" font-size="15">fixed3d: image error against run time, one point per configuration</text>"#,
            w / 2.0
        );
        // Axes and grid.
        let (x0, x1, y0, y1) = (left, w - right, top, h - bottom);
        let _ = writeln!(
            s,
            r#"<line x1="{x0}" y1="{y1}" x2="{x1}" y2="{y1}" stroke="black"/>"#
        );
        let _ = writeln!(
            s,
            r#"<line x1="{x0}" y1="{y0}" x2="{x0}" y2="{y1}" stroke="black"/>"#
        );
        let mut e = ylo;
        while e < yhi + 1e-9 {
            for k in [1.0, 2.0, 5.0] {
                let v = k * 10f64.powf(e);
                if v > 10f64.powf(yhi) * 1.001 {
                    break;
                }
                let y = py(v);
                let _ = writeln!(
                    s,
                    r##"<line x1="{x0}" y1="{y:.1}" x2="{x1}" y2="{y:.1}" stroke="#ddd"/><text x="{}" y="{:.1}" text-anchor="end">{v}</text>"##,
                    x0 - 6.0,
                    y + 4.0
                );
            }
            e += 1.0;
        }
        for i in 0..=5 {
            let v = xmin + (xmax - xmin) * i as f64 / 5.0;
            let x = px(v);
            let _ = writeln!(
                s,
                r##"<line x1="{x:.1}" y1="{y1}" x2="{x:.1}" y2="{}" stroke="black"/><text x="{x:.1}" y="{}" text-anchor="middle">{v:.1}</text>"##,
                y1 + 5.0,
                y1 + 20.0
            );
        }
        let xlabel = if counted {
            "instructions over all scenes (millions, callgrind)"
        } else {
            "host time over all scenes (ms)"
        };
        let _ = writeln!(
            s,
            r#"<text x="{}" y="{}" text-anchor="middle">{xlabel}</text>"#,
            (x0 + x1) / 2.0,
            h - 15.0
        );
        let _ = writeln!(
            s,
            r#"<text x="18" y="{}" text-anchor="middle" transform="rotate(-90 18 {})">image RMSE against the f64 reference (8-bit units, log)</text>"#,
            (y0 + y1) / 2.0,
            (y0 + y1) / 2.0
        );
        // The Pareto front as a staircase through its points.
        let mut f: Vec<(f64, f64)> = points
            .iter()
            .zip(&front)
            .filter(|(_, on)| **on)
            .map(|(p, _)| *p)
            .collect();
        f.sort_by(|a, b| a.0.total_cmp(&b.0));
        let path: Vec<String> = f
            .iter()
            .map(|p| format!("{:.1},{:.1}", px(p.0), py(p.1)))
            .collect();
        let _ = writeln!(
            s,
            r##"<polyline points="{}" fill="none" stroke="#c33" stroke-width="2" stroke-dasharray="5,3"/>"##,
            path.join(" ")
        );
        // Points, each named in a column right of the plot (in the order of their heights),
        // joined to its name by a thin line.
        let mut order: Vec<usize> = (0..points.len()).collect();
        order.sort_by(|a, b| py(points[*a].1).total_cmp(&py(points[*b].1)));
        let column = x1 + 30.0;
        let first = (top + 70.0).max(y0);
        for (row, i) in order.into_iter().enumerate() {
            let (p, on, c) = (points[i], front[i], &self.configs[i]);
            let (x, y) = (px(p.0), py(p.1));
            let ly = first + 17.0 * row as f64;
            let (fill, r) = if on { ("#c33", 6) } else { ("#36c", 4) };
            let _ = writeln!(
                s,
                r##"<polyline points="{x:.1},{y:.1} {:.1},{ly:.1} {:.1},{ly:.1}" fill="none" stroke="#bbb"/>"##,
                column - 12.0,
                column - 4.0
            );
            let _ = writeln!(
                s,
                r#"<circle cx="{x:.1}" cy="{y:.1}" r="{r}" fill="{fill}"/>"#
            );
            let _ = writeln!(
                s,
                r#"<text x="{column:.1}" y="{:.1}">{}</text>"#,
                ly + 4.0,
                c.name
            );
        }
        let _ = writeln!(
            s,
            r##"<circle cx="{}" cy="{}" r="6" fill="#c33"/><text x="{}" y="{}">Pareto front</text>"##,
            w - right + 20.0,
            top + 10.0,
            w - right + 32.0,
            top + 14.0
        );
        let _ = writeln!(
            s,
            r##"<circle cx="{}" cy="{}" r="4" fill="#36c"/><text x="{}" y="{}">dominated</text>"##,
            w - right + 20.0,
            top + 30.0,
            w - right + 32.0,
            top + 34.0
        );
        s.push_str("</svg>\n");
        s
    }
}
