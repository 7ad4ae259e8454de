//! A C host built against the installed library (`scripts/install_capi.sh`
//! into a temporary prefix, then `pkg-config --cflags --libs thinwall`)
//! runs without `LD_LIBRARY_PATH`; the shared library of a release build
//! is small (no debug info).

mod common;

use common::{crate_dir, lib_dir};
use std::process::Command;

#[test]
fn a_host_built_with_pkg_config_runs_from_the_installed_library() {
    let prefix = std::env::temp_dir().join(format!("tw-install-{}", std::process::id()));
    let install = Command::new("bash")
        .arg(crate_dir().join("../scripts/install_capi.sh"))
        .arg("--prefix")
        .arg(&prefix)
        .arg("--from")
        .arg(lib_dir())
        .output()
        .unwrap();
    assert!(
        install.status.success(),
        "{}",
        String::from_utf8_lossy(&install.stderr)
    );
    let flags = Command::new("pkg-config")
        .env("PKG_CONFIG_PATH", prefix.join("lib/pkgconfig"))
        .args(["--cflags", "--libs", "thinwall"])
        .output()
        .expect("pkg-config");
    assert!(
        flags.status.success(),
        "{}",
        String::from_utf8_lossy(&flags.stderr)
    );
    let flags = String::from_utf8(flags.stdout).unwrap();
    let host = prefix.join("host");
    let cc = Command::new("gcc")
        .args(["-Wall", "-Werror", "-std=c11"])
        .arg(crate_dir().join("examples/host.c"))
        .arg("-o")
        .arg(&host)
        .args(flags.split_whitespace())
        .status()
        .expect("gcc");
    assert!(cc.success(), "host.c does not build with `{flags}`");
    let run = Command::new(&host)
        .env_remove("LD_LIBRARY_PATH")
        .arg(crate_dir().join("../fixtures/recognition/c_frame.step"))
        .output()
        .unwrap();
    assert!(
        run.status.success(),
        "{}{}",
        String::from_utf8_lossy(&run.stdout),
        String::from_utf8_lossy(&run.stderr)
    );
    let _ = std::fs::remove_dir_all(prefix);
}

#[test]
fn the_release_shared_library_is_small() {
    let built = lib_dir().join("libthinwall.so");
    let mb = std::fs::metadata(&built).unwrap().len() as f64 / 1e6;
    // Only a build without debug info is held to it (a `profiling` or debug
    // build is large by design).
    if cfg!(debug_assertions) || built.to_string_lossy().contains("profiling") {
        return;
    }
    assert!(mb < 15.0, "{} is {mb:.1} MB", built.display());
}
