//! The same bad value gets the same error through the command line and
//! through the C ABI: both fill a use case's request and its `check()`
//! judges it, so the CLI exits 2 (usage) with the message the C ABI
//! returns with an invalid-argument/setup/config status (the CLI names
//! the flag before it). One case per
//! checked value: up, tilt limit, threshold, tool sizes, stock offset,
//! axial depth.

use std::ffi::{CStr, CString};
use std::path::PathBuf;
use std::process::Command;
use thinwall_capi::*;

fn part_path() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/recognition/rib_grid_panel.step")
}

/// The CLI's exit code and error message (after `thinwall: error: `).
fn cli(args: &[&str]) -> (i32, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_thinwall"))
        .args(args)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr).trim().to_string();
    let message = err
        .strip_prefix("thinwall: error: ")
        .unwrap_or(&err)
        .to_string();
    (out.status.code().unwrap(), message)
}

/// The status and last error message of a C ABI call.
fn last(status: tw_status) -> (tw_status, String) {
    let m = unsafe { CStr::from_ptr(tw_last_error_message()) };
    (status, m.to_string_lossy().into_owned())
}

/// The usage statuses of the C ABI.
const USAGE: [tw_status; 3] = [
    tw_status::TW_ERR_INVALID_ARGUMENT,
    tw_status::TW_ERR_INVALID_SETUP,
    tw_status::TW_ERR_INVALID_CONFIG,
];

fn same(what: &str, cli: (i32, String), capi: (tw_status, String)) {
    assert_eq!(cli.0, 2, "{what}: the CLI exits 2 (usage): {}", cli.1);
    assert!(USAGE.contains(&capi.0), "{what}: C ABI status {:?}", capi.0);
    assert!(!capi.1.is_empty(), "{what}: no message");
    assert!(
        cli.1.ends_with(&capi.1),
        "{what}: the CLI says '{}', the C ABI '{}'",
        cli.1,
        capi.1
    );
}

#[test]
fn the_same_bad_value_gets_the_same_error_in_the_cli_and_the_c_abi() {
    let path = part_path();
    let p = path.to_str().unwrap();
    let c_path = CString::new(p).unwrap();
    unsafe {
        let mut part = std::ptr::null_mut();
        assert_eq!(
            tw_part_load_file(c_path.as_ptr(), &mut part),
            tw_status::TW_OK
        );
        let mut opt = std::ptr::null_mut();
        assert_eq!(tw_options_new(&mut opt), tw_status::TW_OK);

        same(
            "zero up",
            cli(&["recognize", "--no-reach", "--up", "0,0,0", p]),
            last(tw_options_set_up(opt, 0.0, 0.0, 0.0)),
        );
        same(
            "tilt limit",
            cli(&["recognize", "--machine", "5-axis", "--tilt-limit", "120", p]),
            last(tw_options_set_five_axis(opt, 120.0)),
        );
        same(
            "stock offset",
            cli(&["recognize", "--stock-offset=-1", p]),
            last(tw_options_set_stock_offset(opt, -1.0)),
        );
        let mut acc = std::ptr::null_mut();
        same(
            "threshold",
            cli(&["access", "--threshold", "1.5", p]),
            last(tw_access(part, std::ptr::null(), 0.0, 1.5, &mut acc)),
        );
        same(
            "tool diameter",
            cli(&["access", "--tool-diameter=-4", p]),
            last(tw_access(part, std::ptr::null(), -4.0, 0.0, &mut acc)),
        );
        assert!(acc.is_null());
        let mut ops = std::ptr::null_mut();
        same(
            "axial depth",
            cli(&["operations", "--axial-depth=-2", p]),
            last(tw_operations(
                part,
                std::ptr::null(),
                std::ptr::null(),
                -2.0,
                &mut ops,
            )),
        );
        assert!(ops.is_null());
        let tools = CString::new("[[tool]]\nname = \"X\"\n").unwrap();
        let file = std::env::temp_dir().join(format!("same_errors_{}.toml", std::process::id()));
        std::fs::write(&file, tools.to_bytes()).unwrap();
        let (code, message) = cli(&["operations", "--tools", file.to_str().unwrap(), p]);
        let (status, c_message) = last(tw_operations(
            part,
            std::ptr::null(),
            tools.as_ptr(),
            0.0,
            &mut ops,
        ));
        let _ = std::fs::remove_file(&file);
        assert_eq!(
            (code, status),
            (2, tw_status::TW_ERR_INVALID_CONFIG),
            "{message} / {c_message}"
        );
        tw_options_free(opt);
        tw_part_free(part);
    }
}
