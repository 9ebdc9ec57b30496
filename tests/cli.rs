//! The render tool's command-line contract: the output line, exit status 0, 1 and 2, and no
//! panic whatever it is given.

use std::path::PathBuf;
use std::process::{Command, Output};

/// The render example, built by `cargo test` next to the test binaries (built here if missing).
fn tool() -> PathBuf {
    let exe = std::env::current_exe().unwrap();
    let dir = exe.parent().unwrap().parent().unwrap(); // target/<profile>
    let path = dir
        .join("examples")
        .join(format!("render{}", std::env::consts::EXE_SUFFIX));
    if !path.exists() {
        let status = Command::new(env!("CARGO"))
            .args(["build", "--example", "render"])
            .status()
            .unwrap();
        assert!(status.success());
    }
    path
}

fn run(args: &[&str]) -> Output {
    Command::new(tool()).args(args).output().unwrap()
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
