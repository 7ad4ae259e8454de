//! The command line on bad input: every class of the mutated-file corpus
//! ends, in every command, with one line naming the file and exit 1 or 2 —
//! never a panic (101), an abort (134) or a backtrace; `batch` writes a
//! summary line for every part, good or bad; and the option values named
//! as mishandled in issue 41 get their right exit code and message.

#[path = "../../../tests/common/mutate.rs"]
mod mutate;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn bin() -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_thinwall"));
    c.env_remove("RUST_BACKTRACE");
    c
}

fn repo(rel: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(rel)
}

fn temp_dir(what: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("tw-bad-{what}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// One mutant of each class, written to `dir`, with its expected code.
fn one_of_each_class(dir: &Path) -> Vec<(PathBuf, Option<&'static str>)> {
    let part = repo("../shared/data/thinwall/filleted_rib_04.step");
    let text = std::fs::read_to_string(part).unwrap();
    let assembly = std::fs::read_to_string(repo("fixtures/bracket_assembly.step")).unwrap();
    mutate::one_of_each_class(dir, "filleted_rib_04", &text, &assembly)
        .into_iter()
        .map(|(path, _, expect)| (path, expect))
        .collect()
}

/// Exit 1 or 2 with one line on stderr that names `file`, or success.
fn ended_cleanly(out: &Output, file: &Path, what: &str) {
    let err = String::from_utf8_lossy(&out.stderr);
    let code = out.status.code();
    assert!(
        matches!(code, Some(0..=2)),
        "{what}: exit {code:?} (a panic or abort): {err}"
    );
    assert!(
        !err.contains("panicked") && !err.contains("RUST_BACKTRACE"),
        "{what}: {err}"
    );
    if code != Some(0) {
        let lines: Vec<&str> = err
            .lines()
            .filter(|l| l.starts_with("thinwall: error:"))
            .collect();
        assert_eq!(lines.len(), 1, "{what}: {err}");
        assert!(
            err.contains(&file.display().to_string()),
            "{what}: the file is not named: {err}"
        );
    }
}

#[test]
fn every_class_of_bad_file_ends_cleanly_in_every_command() {
    let dir = temp_dir("classes");
    let files = one_of_each_class(&dir);
    assert!(files.len() >= 11, "{} classes", files.len());
    for (file, expect) in &files {
        for command in ["inspect", "recognize", "plan", "operations", "access"] {
            let out = bin().arg(command).arg(file).output().unwrap();
            let what = format!("{command} {}", file.display());
            ended_cleanly(&out, file, &what);
            if let Some(code) = expect {
                let err = String::from_utf8_lossy(&out.stderr);
                assert_eq!(out.status.code(), Some(1), "{what}: {err}");
                let words = code.replace('_', " ");
                let named = match *code {
                    "cyclic_reference" => err.contains("in a circle") && err.contains('#'),
                    "cyclic_assembly" => err.contains("cyclic") && err.contains('#'),
                    "bad_number" => err.contains("entity #") || err.contains(" unit, in "),
                    "budget_exceeded" => err.contains("budget"),
                    "syntax" => err.contains("ISO 10303-21"),
                    _ => err.contains(&words),
                };
                assert!(named, "{what}: expected {code}: {err}");
            }
        }
    }
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn a_device_that_never_ends_is_refused_by_size() {
    let out = bin().args(["inspect", "/dev/zero"]).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("/dev/zero") && err.contains("budget"), "{err}");
}

#[test]
fn batch_writes_a_summary_line_for_every_part_good_or_bad() {
    let dir = temp_dir("batch");
    let files = one_of_each_class(&dir);
    let mut inputs: Vec<PathBuf> = files.iter().map(|(p, _)| p.clone()).collect();
    let good = repo("fixtures/recognition/c_frame.step");
    inputs.push(good.clone());
    let out_dir = dir.join("out");
    let out = bin()
        .args(["batch", "--jobs", "2", "--no-reach", "--out"])
        .arg(&out_dir)
        .args(&inputs)
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let summary = std::fs::read_to_string(out_dir.join("summary.jsonl")).unwrap();
    let lines: Vec<serde_json::Value> = summary
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(lines.len(), inputs.len(), "{summary}");
    let line_of = |p: &Path| {
        lines
            .iter()
            .find(|l| l["file"] == p.display().to_string())
            .unwrap_or_else(|| panic!("no line for {}", p.display()))
    };
    assert_eq!(line_of(&good)["ok"], true, "{summary}");
    for (file, expect) in &files {
        let l = line_of(file);
        if expect.is_some() {
            assert_eq!(l["ok"], false, "{l}");
        }
        assert_ne!(l["error"][0], "internal", "{l}");
    }
    let _ = std::fs::remove_dir_all(dir);
}

/// Run `args` on the C-frame fixture; the exit code and stderr.
fn run(args: &[&str]) -> (Option<i32>, String) {
    let out = bin()
        .args(args)
        .arg(repo("fixtures/recognition/c_frame.step"))
        .output()
        .unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).to_string(),
    )
}

#[test]
fn option_values_get_their_right_exit_code_and_message() {
    // A huge but valid direction is a direction.
    assert_eq!(
        run(&["recognize", "--no-reach", "--up", "1e308,1e308,0"]).0,
        Some(0)
    );
    // The flag given is the one blamed.
    let (code, err) = run(&["access", "--tool-diameter", "1e308"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("--tool-diameter"), "{err}");
    // An axial depth that would cut the part into millions of layers.
    let (code, err) = run(&["operations", "--axial-depth", "1e-300"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("--axial-depth") && err.contains("layers"),
        "{err}"
    );
    // Negative numbers need no `=`.
    let (code, err) = run(&["recognize", "--force", "-5"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("force"), "{err}");
    // Jobs: none, or far more than the cores.
    for jobs in ["0", "100000"] {
        let (code, err) = run(&["batch", "--out", "/tmp", "--jobs", jobs]);
        assert_eq!(code, Some(2), "--jobs {jobs}: {err}");
        assert!(err.contains("--jobs"), "{err}");
    }
    // Settings files: not UTF-8 is a usage error like every other bad one,
    // and a 200 kB line is not echoed whole.
    let dir = temp_dir("config");
    let binary = dir.join("binary.toml");
    std::fs::write(&binary, [0xffu8, 0xfe, 0x00, 0x41]).unwrap();
    let (code, err) = run(&["recognize", "--config", binary.to_str().unwrap()]);
    assert_eq!(code, Some(2), "{err}");
    let long = dir.join("long.toml");
    std::fs::write(
        &long,
        format!("[thinness]\nforce_n = \"{}\"\n", "x".repeat(200_000)),
    )
    .unwrap();
    let (code, err) = run(&["recognize", "--config", long.to_str().unwrap()]);
    assert_eq!(code, Some(2), "{}", &err[..err.len().min(500)]);
    assert!(err.len() < 2_000, "{} bytes of error", err.len());
    // The time limit: a value that is not one, and work past it.
    let (code, err) = run(&["--time-limit", "-1", "inspect"]);
    assert_eq!(code, Some(2), "{err}");
    let panel = repo("fixtures/recognition/rib_grid_panel.step");
    let out = bin()
        .args(["access", "--time-limit", "0.001"])
        .arg(&panel)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(err.contains("time limit of 0.001 s"), "{err}");
    let _ = std::fs::remove_dir_all(dir);
}
