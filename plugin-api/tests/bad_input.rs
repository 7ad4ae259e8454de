//! The C ABI on bad input: a C host (`examples/bad_input.c`) loads one
//! file of each class of the mutated-file corpus and, where it loads,
//! recognizes, plans and lists operations with serial work. It must survive
//! every file, get no `TW_ERR_PANIC`, and find the file named in every
//! error message; under valgrind (when installed) with no memory error.

#[path = "../../tests/common/mutate.rs"]
#[allow(dead_code)]
mod mutate;

mod common;

use common::{build_example, crate_dir, tool};
use std::path::PathBuf;
use std::process::Command;

fn build_host(out: &std::path::Path) {
    build_example("bad_input.c", out);
}

/// One mutant of each class in `dir`; the large assembly classes apart
/// (too slow under valgrind).
fn corpus(dir: &std::path::Path) -> (Vec<PathBuf>, Vec<PathBuf>) {
    let shared = crate_dir().join("../../shared/data/thinwall/filleted_rib_04.step");
    let text = std::fs::read_to_string(shared).unwrap();
    let assembly =
        std::fs::read_to_string(crate_dir().join("../fixtures/bracket_assembly.step")).unwrap();
    let (mut small, mut large) = (Vec::new(), Vec::new());
    for (path, class, _) in mutate::one_of_each_class(dir, "filleted_rib_04", &text, &assembly) {
        match class {
            "amplifying_tree" | "mapped_items" => large.push(path),
            _ => small.push(path),
        }
    }
    (small, large)
}

#[test]
fn a_c_host_survives_every_class_of_bad_file() {
    assert!(tool("gcc"), "gcc is required");
    let dir = std::env::temp_dir().join(format!("tw-capi-bad-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let host = dir.join("bad_input");
    build_host(&host);
    let (small, large) = corpus(&dir);
    assert!(small.len() >= 9, "{} classes", small.len());
    let run = Command::new(&host)
        .env_remove("LD_LIBRARY_PATH")
        .args(small.iter().chain(&large))
        .output()
        .unwrap();
    let (stdout, stderr) = (
        String::from_utf8_lossy(&run.stdout),
        String::from_utf8_lossy(&run.stderr),
    );
    assert!(run.status.success(), "{stdout}\n{stderr}");
    assert_eq!(
        stdout.lines().count(),
        small.len() + large.len(),
        "{stdout}"
    );
    // The library prints nothing on the host's stderr.
    assert!(stderr.is_empty(), "{stderr}");
    if tool("valgrind") {
        let vg = Command::new("valgrind")
            .env_remove("LD_LIBRARY_PATH")
            .args(["--error-exitcode=9", "-q"])
            .arg(&host)
            .args(&small)
            .output()
            .unwrap();
        assert!(
            vg.status.success(),
            "valgrind: {}",
            String::from_utf8_lossy(&vg.stderr)
        );
    } else {
        eprintln!("valgrind not installed: memory check skipped (.ci/run installs it)");
    }
    let _ = std::fs::remove_dir_all(dir);
}
