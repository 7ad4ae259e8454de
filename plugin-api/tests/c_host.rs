//! The C ABI from C: the example host compiles with `gcc -Wall -Werror`
//! against the committed header, links against `libthinwall.so`, runs on a
//! fixture part (clean under valgrind when valgrind is present), and the
//! header compiles as C++ too.

mod common;

use common::{build_example, crate_dir, host, tool};
use std::path::{Path, PathBuf};
use std::process::Command;

/// Run the host under valgrind (when installed); no error and no leak allowed.
fn valgrind_clean(host_bin: &Path, args: &[PathBuf]) {
    if !tool("valgrind") {
        eprintln!("valgrind not installed: memory check skipped (.ci/run installs it)");
        return;
    }
    let vg = Command::new("valgrind")
        .env_remove("LD_LIBRARY_PATH")
        .args([
            "--leak-check=full",
            "--errors-for-leak-kinds=definite,indirect",
            "--error-exitcode=9",
            "-q",
        ])
        .arg(host_bin)
        .args(args)
        .output()
        .unwrap();
    assert!(
        vg.status.success(),
        "valgrind found errors:\n{}",
        String::from_utf8_lossy(&vg.stderr)
    );
}

fn build_host(out: &Path) {
    build_example("host.c", out);
}

fn fixture() -> PathBuf {
    crate_dir().join("../fixtures/recognition/c_frame.step")
}

#[test]
fn threads_recognizing_one_part_at_once_agree() {
    assert!(tool("gcc"), "gcc is required");
    let out = std::env::temp_dir().join(format!("thinwall-threads-{}", std::process::id()));
    build_example("threads.c", &out);
    let part = crate_dir().join("../fixtures/recognition/rib_grid_panel.step");
    for mode in ["serial", "parallel"] {
        let run = host(&out).arg(&part).arg("8").arg(mode).output().unwrap();
        let stdout = String::from_utf8_lossy(&run.stdout);
        assert!(
            run.status.success() && stdout.contains("threads: ok (8 threads)"),
            "{mode}: {stdout}{}",
            String::from_utf8_lossy(&run.stderr)
        );
    }
    // Under helgrind: no data race between the host's threads. (Calls run
    // without worker threads here: helgrind cannot follow rayon's atomics
    // and would report its hand-offs as races.)
    if tool("valgrind") {
        let hg = Command::new("valgrind")
            .env_remove("LD_LIBRARY_PATH")
            .args(["--tool=helgrind", "--error-exitcode=9", "-q"])
            .arg(&out)
            .arg(&part)
            .arg("3")
            .output()
            .unwrap();
        assert!(
            hg.status.success(),
            "helgrind found races:\n{}",
            String::from_utf8_lossy(&hg.stderr)
        );
    } else {
        eprintln!("valgrind not installed: race check skipped (.ci/run installs it)");
    }
    let _ = std::fs::remove_file(out);
}

#[test]
fn c_host_compiles_runs_and_reads_results() {
    assert!(tool("gcc"), "gcc is required");
    let out = std::env::temp_dir().join(format!("thinwall-host-{}", std::process::id()));
    build_host(&out);
    let run = host(&out).arg(fixture()).output().unwrap();
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        run.status.success(),
        "host failed:\n{stdout}\n{}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert!(stdout.contains("host: ok"), "{stdout}");
    assert!(
        stdout.contains("web") && stdout.contains("flange") && stdout.contains("hole"),
        "{stdout}"
    );
    assert!(
        stdout.contains("sequence: ") && stdout.contains("(flange-before-its-wall)"),
        "plan printed: {stdout}"
    );
    assert!(
        stdout.contains(" x ") && stdout.contains(" -> "),
        "connections printed: {stdout}"
    );
    assert!(
        stdout.contains("flank milling: ") && stdout.contains(" planar faces advisable"),
        "access printed: {stdout}"
    );
    assert!(
        stdout.contains("operations: ") && stdout.contains(" tool changes ("),
        "operations printed: {stdout}"
    );
    valgrind_clean(&out, &[fixture()]);
    // Machining features through the accessors: a generated part with
    // countersunk, counterbored and stepped holes (their bores listed).
    let holes = crate_dir().join("../fixtures/holes/holes_1.step");
    let run = host(&out).arg(&holes).output().unwrap();
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        run.status.success() && stdout.contains("host: ok"),
        "{stdout}{}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert!(
        stdout.contains("machining features: 9") && stdout.contains("    bore 3: "),
        "machining printed: {stdout}"
    );
    // Classification of two stacked volumes, upper removed first.
    let case = crate_dir().join("../fixtures/classify/stacked");
    let run = host(&out)
        .arg(case.join("part.step"))
        .arg(case.join("v0.step"))
        .arg(case.join("v1.step"))
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        run.status.success() && stdout.contains("host: ok"),
        "{stdout}{}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert!(
        stdout.contains("volume 0: pocket (side)")
            && stdout.contains("volume 1: pocket (side_and_bottom)"),
        "{stdout}"
    );
    valgrind_clean(
        &out,
        &[
            case.join("part.step"),
            case.join("v0.step"),
            case.join("v1.step"),
        ],
    );
    let _ = std::fs::remove_file(out);
}

#[test]
fn header_compiles_as_cpp() {
    assert!(tool("g++"), "g++ is required");
    let src = std::env::temp_dir().join(format!("thinwall-hdr-{}.cpp", std::process::id()));
    std::fs::write(
        &src,
        "#include \"thinwall.h\"\nint main() { return tw_version() == nullptr; }\n",
    )
    .unwrap();
    let status = Command::new("g++")
        .args(["-Wall", "-Werror", "-std=c++17", "-fsyntax-only", "-I"])
        .arg(crate_dir().join("include"))
        .arg(&src)
        .status()
        .unwrap();
    let _ = std::fs::remove_file(src);
    assert!(status.success(), "thinwall.h does not compile as C++");
}
