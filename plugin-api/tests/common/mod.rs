//! Helpers shared by the C ABI's tests: where the crate and the built
//! library are, whether a tool is installed, compiling an example host.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

pub fn crate_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The directory holding `libthinwall.so` and `libthinwall.a`, built (or
/// found up to date) by the cargo running this test, in the test's own
/// profile. `cargo test` never builds them itself: `thinwall-clib` is a
/// cdylib and staticlib only, which no test target can link, so the first
/// caller in a test binary runs `cargo build -p thinwall-clib` (a no-op
/// when it is fresh; cargo holds no lock while tests run).
pub fn lib_dir() -> PathBuf {
    static BUILT: OnceLock<PathBuf> = OnceLock::new();
    BUILT.get_or_init(build_library).clone()
}

fn build_library() -> PathBuf {
    let exe = std::env::current_exe().unwrap();
    // target/<profile>/deps/<test binary>
    let profile_dir = exe.parent().and_then(Path::parent).unwrap().to_path_buf();
    let profile = profile_dir
        .file_name()
        .unwrap()
        .to_string_lossy()
        .into_owned();
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let profile_arg = if profile == "debug" {
        "dev"
    } else {
        profile.as_str()
    };
    let out = Command::new(cargo)
        .args([
            "build",
            "--quiet",
            "-p",
            "thinwall-clib",
            "--profile",
            profile_arg,
        ])
        .env("CARGO_TARGET_DIR", profile_dir.parent().unwrap())
        .current_dir(crate_dir())
        .output()
        .expect("cargo");
    assert!(
        out.status.success(),
        "cargo build -p thinwall-clib --profile {profile_arg} failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        profile_dir.join("libthinwall.so").exists(),
        "libthinwall.so not found in {} after building it",
        profile_dir.display()
    );
    profile_dir
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
