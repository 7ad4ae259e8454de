//! Print the C ABI's JSON of one part, through the exported functions (as a
//! host calls them, default options): recognition, plan, operations and,
//! with `--access`, access. Used by `scripts/snapshot_outputs.sh` to pin
//! the C ABI's output across changes.
//!
//!     cargo run --release -p thinwall-capi --example capi_json -- PART.step [--access]

use std::ffi::{c_char, CStr, CString};
use thinwall_capi::*;

/// One JSON string (or the failure's status and message), owned by Rust.
unsafe fn text(status: tw_status, json: *mut c_char) -> String {
    if status != tw_status::TW_OK {
        let m = CStr::from_ptr(tw_last_error_message()).to_string_lossy();
        return format!("error {status:?}: {m}\n");
    }
    let s = CStr::from_ptr(json).to_string_lossy().into_owned();
    tw_string_free(json);
    s + "\n"
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let Some(path) = args.first() else {
        eprintln!("usage: capi_json PART.step [--access]");
        std::process::exit(2);
    };
    let with_access = args.iter().any(|a| a == "--access");
    let c_path = CString::new(path.as_str()).expect("no NUL in a path");
    unsafe {
        let mut part = std::ptr::null_mut();
        let st = tw_part_load_file(c_path.as_ptr(), &mut part);
        if st != tw_status::TW_OK {
            print!("{}", text(st, std::ptr::null_mut()));
            return;
        }
        let null: *const tw_options = std::ptr::null();
        let mut json = std::ptr::null_mut();

        let mut r = std::ptr::null_mut();
        let mut st = tw_recognize(part, null, &mut r);
        if st == tw_status::TW_OK {
            st = tw_result_to_json(r, &mut json);
            tw_result_free(r);
        }
        print!("== recognize\n{}", text(st, json));

        let mut p = std::ptr::null_mut();
        let mut st = tw_plan(part, null, std::ptr::null(), &mut p);
        if st == tw_status::TW_OK {
            st = tw_plan_to_json(p, &mut json);
            tw_plan_free(p);
        }
        print!("== plan\n{}", text(st, json));

        let mut o = std::ptr::null_mut();
        let mut st = tw_operations(part, null, std::ptr::null(), 0.0, &mut o);
        if st == tw_status::TW_OK {
            st = tw_operations_to_json(o, &mut json);
            tw_operations_free(o);
        }
        print!("== operations\n{}", text(st, json));

        if with_access {
            let mut a = std::ptr::null_mut();
            let mut st = tw_access(part, null, 0.0, 0.0, &mut a);
            if st == tw_status::TW_OK {
                st = tw_access_to_json(a, &mut json);
                tw_access_free(a);
            }
            print!("== access\n{}", text(st, json));
        }
        tw_part_free(part);
    }
}
