//! The render tool's command-line contract: the output line, exit status 0, 1 and 2, and no
//! panic whatever it is given.

mod common;
#[path = "../examples/common/desktop.rs"]
mod desktop;

use std::path::PathBuf;
use std::process::{Command, Output};

use common::floor;

/// The render example of this test's build profile, brought up to date once per test run
/// (a test run with `--test cli` alone does not build examples).
fn tool() -> PathBuf {
    static TOOL: std::sync::OnceLock<PathBuf> = std::sync::OnceLock::new();
    TOOL.get_or_init(|| {
        let exe = std::env::current_exe().unwrap();
        let dir = exe.parent().unwrap().parent().unwrap(); // target/<profile>
        let profile = match dir.file_name().and_then(|n| n.to_str()) {
            Some("debug") | None => "dev",
            Some(other) => other,
        };
        let status = Command::new(env!("CARGO"))
            .args([
                "build",
                "--quiet",
                "--example",
                "render",
                "--profile",
                profile,
            ])
            .status()
            .unwrap();
        assert!(status.success());
        dir.join("examples")
            .join(format!("render{}", std::env::consts::EXE_SUFFIX))
    })
    .clone()
}

fn run(args: &[&str]) -> Output {
    Command::new(tool()).args(args).output().unwrap()
}

/// Runs the tool with `args` writing `out`, which must succeed, and reads the image back.
fn rendered(args: &[&str], out: &str) -> Vec<embedded_graphics::pixelcolor::Rgb888> {
    let o = run(args);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{args:?}: {err}");
    common::golden::read_png(std::path::Path::new(out))
        .unwrap()
        .2
}

fn out_png(name: &str) -> String {
    PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join(name)
        .to_string_lossy()
        .into_owned()
}

#[test]
fn renders_and_prints_one_line() {
    let out = out_png("cli_torus.png");
    let o = run(&[
        "--shape",
        "torus",
        "--mode",
        "gouraud",
        "--size",
        "160x120",
        "--out",
        &out,
        "--light",
        "-1,1,1,0.7",
        "--light",
        "1,0,1,0.3",
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let line = String::from_utf8(o.stdout).unwrap();
    let words: Vec<&str> = line.split_whitespace().collect();
    assert_eq!(words[0..2], ["rendered", "160x120"]);
    assert_eq!(words[2], "in");
    assert!(words[3].parse::<u64>().is_ok());
    assert_eq!(words[4..7], ["us:", "covered", words[6]]);
    let covered: u32 = words[6].parse().unwrap();
    assert!(covered > 1000);
    assert_eq!(words[7..9], ["pixels,", "drew"]);
    assert_eq!(words[10..12], ["of", "2304"]);
    assert_eq!(words[12], "triangles");
    assert!(std::fs::metadata(&out).unwrap().len() > 100);
}

#[test]
fn bands_give_the_same_image() {
    let (a, b) = (out_png("cli_full.png"), out_png("cli_bands.png"));
    for (out, extra) in [(&a, None), (&b, Some("7"))] {
        let mut args = vec![
            "--obj",
            concat!(env!("CARGO_MANIFEST_DIR"), "/models/suzanne.obj"),
            "--out",
            out.as_str(),
        ];
        if let Some(rows) = extra {
            args.extend(["--bands", rows]);
        }
        assert_eq!(run(&args).status.code(), Some(0));
    }
    assert_eq!(std::fs::read(&a).unwrap(), std::fs::read(&b).unwrap());
}

#[test]
fn bad_arguments_exit_2() {
    let out = out_png("cli_bad.png");
    for args in [
        vec![],
        vec!["--shape", "blob"],
        vec!["--shape", "cube", "--size", "0x10"],
        vec!["--shape", "cube", "--size", "10"],
        vec!["--shape", "cube", "--mode", "shiny"],
        vec!["--shape", "cube", "--fov", "180"],
        vec!["--shape", "cube", "--fov", "nan"],
        vec!["--shape", "cube", "--eye", "1,2"],
        vec!["--shape", "cube", "--eye", "1e9,0,0"],
        vec!["--shape", "cube", "--eye", "0,0,0", "--target", "0,0,0"],
        vec!["--shape", "cube", "--color", "256,0,0"],
        vec!["--shape", "cube", "--ambient", "2"],
        vec!["--shape", "cube", "--light", "0,0,0"],
        vec!["--shape", "cube", "--light", "1,1,1,1,1"],
        vec!["--shape", "cube", "--light", "1,1,1,-1"],
        vec!["--shape", "cube", "--point-light", "0,0"],
        vec!["--shape", "cube", "--attenuation", "cubic"],
        vec!["--shape", "cube", "--range", "0"],
        vec!["--shape", "cube", "--specular", "2,8"],
        vec!["--shape", "cube", "--specular", "0.5,0"],
        vec!["--shape", "cube", "--specular", "0.5,2.5"],
        vec!["--shape", "cube", "--specular", "0.5"],
        vec!["--shape", "cube", "--near", "-1", "--far", "5"],
        vec!["--shape", "cube", "--bands", "0"],
        vec!["--shape", "cube", "--what"],
        vec!["--shape"],
    ] {
        let mut args = args.clone();
        args.extend(["--out", out.as_str()]);
        let o = run(&args);
        assert_eq!(
            o.status.code(),
            Some(2),
            "{args:?}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(
            err.contains("usage:") && !err.contains("panicked"),
            "{args:?}: {err}"
        );
    }
}

#[test]
fn bad_files_exit_1_with_the_line() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let bad = dir.join("cli_bad.obj");
    std::fs::write(&bad, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n").unwrap();
    let o = run(&["--obj", bad.to_str().unwrap(), "--out", &out_png("x.png")]);
    assert_eq!(o.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&o.stderr).contains("line 4"));
    let o = run(&["--obj", "/no/such/file.obj"]);
    assert_eq!(o.status.code(), Some(1));
    let binary = dir.join("cli_binary.obj");
    std::fs::write(&binary, [0u8, 159, 146, 150, 10, 255]).unwrap();
    let o = run(&[
        "--obj",
        binary.to_str().unwrap(),
        "--out",
        &out_png("y.png"),
    ]);
    assert_eq!(o.status.code(), Some(1));
    let o = run(&["--shape", "cube", "--out", "/no/such/dir/frame.png"]);
    assert_eq!(o.status.code(), Some(1));
}

#[test]
fn huge_models_are_rescaled() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let big = dir.join("cli_big.obj");
    std::fs::write(&big, "v -100000 0 0\nv 100000 0 0\nv 0 150000 0\nf 1 2 3\n").unwrap();
    let o = run(&[
        "--obj",
        big.to_str().unwrap(),
        "--out",
        &out_png("big.png"),
        "--no-cull",
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
}

/// Runs the tool with its address space limited to `megabytes` (Linux `ulimit -v`): storage
/// sized by the file rather than by the model it holds fails there.
fn run_within(megabytes: u32, args: &[&str]) -> Output {
    Command::new("sh")
        .arg("-c")
        .arg(format!(
            "ulimit -v {}; exec \"$0\" \"$@\"",
            megabytes * 1024
        ))
        .arg(tool())
        .args(args)
        .output()
        .unwrap()
}

/// The tool loading `file` within 200 MB of address space (see [`run_within`]).
fn load_within(file: &std::path::Path, png: &str) -> Output {
    let out = out_png(png);
    run_within(200, &["--obj", file.to_str().unwrap(), "--out", &out])
}

#[test]
fn a_file_without_triangles_is_an_error() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let points = dir.join("cli_points.obj");
    std::fs::write(&points, "v 0 0 0\nv 1 0 0\nv 0 1 0\n").unwrap();
    let path = points.to_str().unwrap();
    let o = run(&["--obj", path, "--out", &out_png("points.png")]);
    assert_eq!(o.status.code(), Some(1));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains(&format!("no triangles in {path}")), "{err}");
}

/// 30 MB of blank lines hold no model: the tool reads them piece by piece in a few megabytes
/// (it once sized storage by the line count and read the whole file first: 13 bytes of
/// storage a byte of file).
#[test]
fn memory_is_bounded_by_the_model_not_the_file() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let blank = dir.join("cli_blank.obj");
    std::fs::write(&blank, vec![b'\n'; 30 << 20]).unwrap();
    let o = load_within(&blank, "blank.png");
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("no triangles in"), "{err}");
    // A real model among as many blank lines loads within the same limit.
    let mut padded =
        std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/models/suzanne.obj")).unwrap();
    padded.extend(vec![b'\n'; 30 << 20]);
    std::fs::write(&blank, padded).unwrap();
    let o = load_within(&blank, "padded.png");
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    std::fs::remove_file(&blank).unwrap();
}

/// A sparse 1 GB file (all NUL bytes) fails on its first line, within a small address space.
#[test]
fn a_sparse_file_fails_on_its_first_line() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let sparse = dir.join("cli_sparse.obj");
    std::fs::File::create(&sparse)
        .unwrap()
        .set_len(1 << 30)
        .unwrap();
    let o = load_within(&sparse, "sparse.png");
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("line 1,"), "{err}");
    std::fs::remove_file(&sparse).unwrap();
}

/// The rest of a file after its first bad line is never read: from a pipe whose writer stays
/// open, the tool still exits at once.
#[test]
fn reading_stops_at_the_first_bad_line() {
    use std::io::Write;
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let fifo = dir.join("cli_fifo.obj");
    let _ = std::fs::remove_file(&fifo);
    assert!(Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .unwrap()
        .success());
    let mut child = Command::new(tool())
        .args([
            "--obj",
            fifo.to_str().unwrap(),
            "--out",
            &out_png("fifo.png"),
        ])
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let mut writer = std::fs::OpenOptions::new().write(true).open(&fifo).unwrap();
    writer.write_all(b"v 0 0 0\n").unwrap();
    // A line of NUL bytes longer than any line the tool holds; the writer stays open.
    let _ = writer.write_all(&vec![0u8; 1 << 15]);
    let start = std::time::Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break Some(status);
        }
        if start.elapsed() > std::time::Duration::from_secs(30) {
            child.kill().unwrap();
            break None;
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    };
    drop(writer);
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(status.and_then(|s| s.code()), Some(1), "{err}");
    assert!(err.contains("line 2,"), "{err}");
    std::fs::remove_file(&fifo).unwrap();
}

/// Framing or depth ranges past the fixed-point range are reported by their cause.
#[test]
fn range_errors_name_their_cause() {
    for (args, cause) in [
        (
            &["--fov", "0.000001"][..],
            "--fov 0.000001: too narrow for the fixed-point range",
        ),
        (&["--eye", "30000,30000,30000"], "automatic far plane"),
        (
            &["--eye", "20000,0,0"],
            "--eye: the eye is 20000 units from",
        ),
    ] {
        let mut all = vec!["--shape", "torus", "--out", "/dev/null"];
        all.extend(args);
        let o = run(&all);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(cause), "{args:?}: {err}");
        assert!(!err.contains("far plane not far enough"), "{args:?}: {err}");
    }
}

/// Without `--out` the picture goes under `target/`, not into the working directory.
#[test]
fn the_default_output_lies_under_target() {
    let cwd = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli_cwd");
    let _ = std::fs::remove_dir_all(&cwd);
    std::fs::create_dir_all(&cwd).unwrap();
    let o = Command::new(tool())
        .args(["--shape", "cube", "--size", "32x24"])
        .current_dir(&cwd)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(std::fs::read_dir(&cwd).unwrap().count(), 0);
    let png = concat!(env!("CARGO_MANIFEST_DIR"), "/target/render/frame.png");
    assert!(std::fs::metadata(png).unwrap().len() > 0);
}

/// The textured receding floor from an OBJ file with `vt` (its corners' UVs split at a seam)
/// and a PNG texture named by the file's `mtllib` and `map_Kd`, under `--ambient 1`: every
/// pixel the exact f64 map puts clearly inside a texel shows that texel; `--texture` gives the
/// same image, and `--affine` does not.
#[test]
fn render_tool_draws_the_textured_floor_texel_for_texel() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("textured_floor");
    std::fs::create_dir_all(&dir).unwrap();
    let texels = floor::texels();
    let png = dir.join("checker.png");
    common::golden::write_png(&png, 64, 64, &texels);
    std::fs::write(dir.join("floor.mtl"), "newmtl floor\nmap_Kd checker.png\n").unwrap();
    // The floor of tests/texture.rs with a seam along its diagonal: the first face's UVs are
    // the second's moved by a whole repeat, so its two shared corners are split in two.
    let obj = "mtllib floor.mtl\nv -20 0 4\nv 20 0 4\nv 20 0 -60\nv -20 0 -60\n\
               vt 0 0\nvt 10 16\nvt 0 16\nvt 1 0\nvt 11 0\nvt 11 16\n\
               usemtl floor\nf 1/4 2/5 3/6\nf 1/1 3/2 4/3\n";
    let obj_path = dir.join("floor.obj");
    std::fs::write(&obj_path, obj).unwrap();
    let [ex, ey, ez] = floor::EYE;
    let [tx, ty, tz] = floor::TARGET;
    let (eye, target) = (format!("{ex},{ey},{ez}"), format!("{tx},{ty},{tz}"));
    let render = |name: &str, extra: &[&str]| {
        let out = dir.join(name).to_string_lossy().into_owned();
        let mut args = vec![
            "--obj",
            obj_path.to_str().unwrap(),
            "--eye",
            &eye,
            "--target",
            &target,
            "--fov",
            "60",
            "--near",
            "0.5",
            "--far",
            "100",
            "--ambient",
            "1",
            "--out",
            &out,
        ];
        args.extend_from_slice(extra);
        rendered(&args, &out)
    };
    let pixels = render("mtl.png", &[]);
    let (compared, differ) = floor::compare_with_reference(&pixels, &texels);
    assert!(compared > 15_000, "{compared} pixels compared");
    assert_eq!(
        differ, 0,
        "{differ} of {compared} pixels show another texel"
    );
    assert!(render("flag.png", &["--texture", png.to_str().unwrap()]) == pixels);
    let affine = render("affine.png", &["--affine"]);
    assert!(floor::compare_with_reference(&affine, &texels).1 > 5_000);
    // A material whose texture is missing leaves it out, with a warning; --texture naming a
    // missing file is an error.
    std::fs::write(dir.join("floor.mtl"), "newmtl floor\nmap_Kd gone.png\n").unwrap();
    let out = dir.join("untextured.png").to_string_lossy().into_owned();
    let _ = std::fs::remove_file(dir.join("gone.png"));
    let o = run(&["--obj", obj_path.to_str().unwrap(), "--out", &out]);
    assert!(o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("warning: the material's texture"));
    let o = run(&[
        "--obj",
        obj_path.to_str().unwrap(),
        "--out",
        &out,
        "--texture",
        "gone.png",
    ]);
    assert_eq!(o.status.code(), Some(1));
}

/// `--point-light` lights the side of a sphere it stands beside; `--attenuation` dims it with
/// distance; from `--range` on it lights nothing (the image of the ambient light alone); a
/// coloured one tints.
#[test]
fn render_tool_point_lights() {
    let draw = |name: &str, extra: &[&str]| {
        let out = out_png(name);
        let mut args = vec!["--shape", "sphere", "--size", "80x60", "--out", &out];
        args.extend(["--ambient", "0.1", "--eye", "0,0,4", "--target", "0,0,0"]);
        args.extend(extra);
        rendered(&args, &out)
    };
    let halves = |p: &[embedded_graphics::pixelcolor::Rgb888]| {
        use embedded_graphics::pixelcolor::RgbColor;
        let mut sums = [0u64; 2];
        for (i, c) in p.iter().enumerate() {
            sums[usize::from(i % 80 >= 40)] += u64::from(c.r()) + u64::from(c.g());
        }
        sums
    };
    let left = halves(&draw("cli_lamp_left.png", &["--point-light", "-3,0,2,2"]));
    let right = halves(&draw("cli_lamp_right.png", &["--point-light", "3,0,2,2"]));
    assert!(
        left[0] > 2 * left[1] && right[1] > 2 * right[0],
        "{left:?} {right:?}"
    );
    let far = [
        "--point-light",
        "-3,0,2,2",
        "--attenuation",
        "inverse-square",
    ];
    let dimmed = halves(&draw("cli_lamp_dim.png", &far));
    assert!(dimmed[0] < left[0] / 2, "{dimmed:?} {left:?}");
    let ambient = draw("cli_lamp_none.png", &[]);
    let cut = draw(
        "cli_lamp_cut.png",
        &["--point-light", "-3,0,2,2", "--range", "2"],
    );
    assert_eq!(cut, ambient);
    use embedded_graphics::pixelcolor::RgbColor;
    let red = draw("cli_lamp_red.png", &["--point-light", "0,0,3,1,0,0"]);
    assert!(red.iter().any(|c| c.r() > 200) && red.iter().all(|c| c.g() < 30));
}

/// `--specular` whitens a Gouraud sphere where it faces the light and the viewer, and leaves
/// a flat one as it was; `--mode perspective-gouraud` shows the highlights too; `--ortho`
/// draws the sphere, not as the perspective camera does.
#[test]
fn render_tool_specular_ortho_and_perspective_gouraud() {
    use embedded_graphics::pixelcolor::RgbColor;
    let draw = |name: &str, extra: &[&str]| {
        let out = out_png(name);
        let mut args = vec!["--shape", "sphere", "--size", "80x80", "--out", &out];
        args.extend([
            "--color",
            "200,40,40",
            "--eye",
            "0,0,4",
            "--target",
            "0,0,0",
        ]);
        args.extend(["--light", "0,0,1,0.8"]);
        args.extend(extra);
        rendered(&args, &out)
    };
    let white = |p: &[embedded_graphics::pixelcolor::Rgb888]| {
        p.iter().filter(|c| c.g() > 180 && c.b() > 180).count()
    };
    let gouraud = draw("cli_matte.png", &["--mode", "gouraud"]);
    let glossy = draw(
        "cli_glossy.png",
        &["--mode", "gouraud", "--specular", "1,16"],
    );
    assert_eq!(white(&gouraud), 0);
    assert!(white(&glossy) > 20, "{}", white(&glossy));
    let perspective = ["--mode", "perspective-gouraud", "--specular", "1,16"];
    assert!(white(&draw("cli_glossy_p.png", &perspective)) > 20);
    let flat = draw("cli_flat.png", &["--mode", "flat"]);
    assert_eq!(
        draw(
            "cli_flat_glossy.png",
            &["--mode", "flat", "--specular", "1,16"]
        ),
        flat
    );
    let ortho = draw("cli_ortho.png", &["--ortho"]);
    let covered = |p: &[embedded_graphics::pixelcolor::Rgb888]| {
        p.iter()
            .filter(|c| **c != embedded_graphics::pixelcolor::Rgb888::BLACK)
            .count()
    };
    assert!(
        covered(&ortho) > 1000 && ortho != flat,
        "{}",
        covered(&ortho)
    );
}

/// A scene file of four objects (a glossy Gouraud torus, a textured OBJ floor with `vt`, a
/// wire cube depth-tested against them, an unlit octahedron), a directional and a point light
/// and a camera: the tool's image is, pixel for pixel, the one fixed3d's `Renderer` draws of the
/// same scene built here through the library's own API, in one pass and in bands.
#[test]
#[cfg(all(
    feature = "gouraud",
    feature = "point-light",
    feature = "specular",
    feature = "texture",
    feature = "wireframe"
))]
fn render_tool_draws_a_scene_file_as_the_renderer_does() {
    use embedded_graphics::pixelcolor::{Rgb888, RgbColor};
    use fixed3d::mesh::Specular;
    use fixed3d::pipeline::{Bin, ScreenVertex};
    use fixed3d::prelude::*;
    use fixed3d::texture::{Texels, Texture};
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("scene_file");
    std::fs::create_dir_all(&dir).unwrap();
    let texels = floor::texels();
    common::golden::write_png(&dir.join("tiles.png"), 64, 64, &texels);
    let obj = "v -3 0 2\nv 3 0 2\nv 3 0 -4\nv -3 0 -4\nvt 0 0\nvt 3 0\nvt 3 3\nvt 0 3\n\
               f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n";
    std::fs::write(dir.join("floor.obj"), obj).unwrap();
    let scene = r#"
        ambient = 0.1
        [camera]
        eye = [0.5, 2.0, 4.5]
        target = [0.0, 0.3, 0.0]
        fov = 55
        near = 0.5
        far = 40.0
        [[lights]]
        direction = [-1, 1, 1]
        intensity = 0.6
        [[lights]]
        position = [1.0, 1.5, 1.0]
        color = [1.0, 0.8, 0.5]
        attenuation = "inverse-square"
        range = 6
        [[objects]]
        shape = "torus"
        position = [0.0, 0.7, 0.0]
        rotation = [50, 20, 10]
        scale = 0.9
        color = [60, 130, 230]
        shade = "gouraud"
        specular = [1.0, 24]
        [[objects]]
        obj = "floor.obj"
        texture = "tiles.png"
        [[objects]]
        shape = "cube"
        position = [0.0, 0.7, 0.0]
        scale = 1.2
        rotation = [0, 30, 0]
        color = [255, 255, 255]
        style = "wire"
        [[objects]]
        shape = "octahedron"
        position = [-1.8, 0.5, -0.5]
        scale = 0.5
        color = [250, 200, 40]
        shade = "unlit"
    "#;
    let path = dir.join("scene.toml");
    std::fs::write(&path, scene).unwrap();
    let tool = |name: &str, extra: &[&str]| {
        let out = dir.join(name).to_string_lossy().into_owned();
        let mut args = vec!["--scene", path.to_str().unwrap(), "--size", "160x120"];
        args.extend(["--out", &out]);
        args.extend(extra);
        rendered(&args, &out)
    };
    // The same scene through the library.
    let torus = desktop::Model::shape("torus").unwrap();
    let cube = desktop::Model::shape("cube").unwrap();
    let gem = desktop::Model::shape("octahedron").unwrap();
    let floor = desktop::Model::load_obj(dir.join("floor.obj").to_str().unwrap()).unwrap();
    let meshes = [torus.mesh(), floor.mesh(), cube.mesh(), gem.mesh()];
    let (texels, w, h) = desktop::load_texels(dir.join("tiles.png").to_str().unwrap()).unwrap();
    let texture = Texture::new(Texels::Rgb888(&texels), w, h).unwrap();
    let gloss = Specular::new(Rgb888::new(255, 255, 255), 24);
    let models = [
        Model::new(&meshes[0], Rgb888::new(60, 130, 230))
            .scaled(0.9)
            .rotated_x(50)
            .rotated_y(20)
            .rotated_z(10)
            .translated([0.0, 0.7, 0.0])
            .shaded(Shade::Gouraud)
            .glossy(&gloss),
        Model::new(&meshes[1], Rgb888::new(255, 160, 64)).textured(&texture),
        Model::new(&meshes[2], Rgb888::new(255, 255, 255))
            .scaled(1.2)
            .rotated_y(30)
            .translated([0.0, 0.7, 0.0])
            .wireframe(),
        Model::new(&meshes[3], Rgb888::new(250, 200, 40))
            .scaled(0.5)
            .translated([-1.8, 0.5, -0.5])
            .shaded(Shade::Unlit),
    ];
    let lights = [
        Light::ambient(0.1),
        Light::directional([-1, 1, 1], 0.6),
        PointLight::new(
            [1.0, 1.5, 1.0],
            fixed3d::scene::LightColor::new(
                Scalar::ONE,
                Scalar::from_num(0.8),
                Scalar::from_num(0.5),
            ),
        )
        .attenuated(Attenuation::InverseSquare)
        .within(6)
        .into(),
    ];
    let camera = Camera::perspective(55, 0.5, 40).looking_at([0.5, 2.0, 4.5], [0.0, 0.3, 0.0]);
    let vertices: usize = meshes.iter().map(|m| m.positions().len()).sum();
    let triangles: usize = meshes.iter().map(|m| m.triangles().len()).sum();
    let (mut v, mut b) = (
        vec![ScreenVertex::DEFAULT; vertices],
        vec![Bin::EMPTY; triangles],
    );
    let (mut c, mut d) = (vec![Rgb888::BLACK; 160 * 120], vec![0u16; 160 * 120]);
    let mut renderer = Renderer::from_slices(&mut v, &mut b, &mut c, &mut d);
    let mut screen = common::screen::Screen::new(160, 120, Rgb888::BLACK);
    renderer
        .render(&models, &lights, &camera, &mut screen)
        .unwrap();
    let expected = screen.pixels;
    let textured = expected.iter().filter(|p| texels.contains(p)).count();
    let lit = expected.iter().filter(|p| **p != Rgb888::BLACK).count();
    assert!(lit > 4000 && textured < lit, "{lit} {textured}");
    assert!(tool("scene.png", &[]) == expected);
    assert!(tool("scene_bands.png", &["--bands", "7"]) == expected);
}

/// Scene files that cannot be drawn are errors naming the file and the problem (exit 1);
/// flags a scene file replaces are usage errors (exit 2).
#[test]
fn bad_scene_files_exit_1() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("bad_scenes");
    std::fs::create_dir_all(&dir).unwrap();
    let camera = "[camera]\neye = [0, 0, 4]\n";
    let cube = "[[objects]]\nshape = \"cube\"\n";
    for (name, text, says) in [
        ("no_objects", camera.to_string(), "objects"),
        ("empty", format!("objects = []\n{camera}"), "no objects"),
        ("unknown_key", format!("{camera}{cube}glow = 1\n"), "glow"),
        (
            "bad_shape",
            format!("{camera}[[objects]]\nshape = \"blob\"\n"),
            "blob",
        ),
        (
            "two_meshes",
            format!("{camera}{cube}obj = \"x.obj\"\n"),
            "one of",
        ),
        (
            "bad_shade",
            format!("{camera}{cube}shade = \"shiny\"\n"),
            "shiny",
        ),
        (
            "bad_style",
            format!("{camera}{cube}style = \"dots\"\n"),
            "dots",
        ),
        (
            "missing_obj",
            format!("{camera}[[objects]]\nobj = \"gone.obj\"\n"),
            "gone.obj",
        ),
        (
            "missing_png",
            format!("{camera}{cube}texture = \"gone.png\"\n"),
            "gone.png",
        ),
        (
            "light_kind",
            format!("{camera}{cube}[[lights]]\nintensity = 1\n"),
            "direction",
        ),
        (
            "too_many",
            format!(
                "{camera}{cube}{}",
                "[[lights]]\nposition = [0, 1, 0]\n".repeat(5)
            ),
            "lights",
        ),
        ("not_toml", "camera = \n".to_string(), "not_toml.toml"),
    ] {
        let path = dir.join(format!("{name}.toml"));
        std::fs::write(&path, text).unwrap();
        let out = dir
            .join(format!("{name}.png"))
            .to_string_lossy()
            .into_owned();
        let o = run(&["--scene", path.to_str().unwrap(), "--out", &out]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(1), "{name}: {err}");
        assert!(
            err.contains(says) && !err.contains("panicked"),
            "{name}: {err}"
        );
    }
    let path = dir.join("ok.toml");
    std::fs::write(&path, format!("{camera}{cube}")).unwrap();
    let o = run(&["--scene", path.to_str().unwrap(), "--eye", "1,1,1"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--eye: with --scene"));
    let out = dir.join("ok.png").to_string_lossy().into_owned();
    assert_eq!(
        run(&["--scene", path.to_str().unwrap(), "--out", &out])
            .status
            .code(),
        Some(0)
    );
}
