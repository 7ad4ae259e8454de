//! Helpers shared by the C ABI's tests: where the crate and the built
//! library are, whether a tool is installed, compiling an example host.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::Command;

pub fn crate_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The directory holding the `libthinwall.so` built with this test: the
/// test binary's `deps/` (the copy one level up is only refreshed by
/// `cargo build` and may be stale).
pub fn lib_dir() -> PathBuf {
    let exe = std::env::current_exe().unwrap();
    let deps = exe.parent().unwrap().to_path_buf();
    for dir in [deps.clone(), deps.parent().unwrap().to_path_buf()] {
        if dir.join("libthinwall.so").exists() {
            return dir;
        }
    }
    panic!("libthinwall.so not found near {}", deps.display());
}

/// The host binary, run without cargo's `LD_LIBRARY_PATH` (which may hold a
/// stale copy of the library).
pub fn host(path: &Path) -> Command {
    let mut c = Command::new(path);
    c.env_remove("LD_LIBRARY_PATH");
    c
}

pub fn tool(name: &str) -> bool {
    Command::new(name)
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success())
}

/// Compile `plugin-api/examples/<source>` against the header and library.
pub fn build_example(source: &str, out: &Path) {
    let lib = lib_dir();
    let status = Command::new("gcc")
        .args(["-Wall", "-Wextra", "-Werror", "-std=c11", "-g", "-pthread"])
        .arg("-I")
        .arg(crate_dir().join("include"))
        .arg(crate_dir().join("examples").join(source))
        .arg("-L")
        .arg(&lib)
        .arg(format!("-Wl,--disable-new-dtags,-rpath,{}", lib.display()))
        .args(["-lthinwall", "-o"])
        .arg(out)
        .status()
        .expect("gcc");
    assert!(status.success(), "{source} does not compile");
}
