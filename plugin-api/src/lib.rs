//! The C ABI of Thinwall (`libthinwall.so`, `libthinwall.a`, header
//! `include/thinwall.h`). Every function returns a [`tw_status`] or a
//! value whose "nothing" case is documented, runs inside a panic boundary,
//! rejects NULL arguments, and sets out-pointers only on success (to NULL
//! on failure). Objects are immutable once created (options excepted, which
//! are filled before use) and can be shared between threads. See
//! `docs/C-API.md`.
#![allow(non_camel_case_types)]
#![allow(clippy::missing_safety_doc)] // every function documents its contract in the header

mod access;
mod classify;
mod error;
mod machining;
mod operations;
mod options;
mod part;
mod plan;
mod result;

pub use access::*;
pub use classify::*;
pub use error::{study_status, tw_last_error_message, tw_status};
pub use machining::*;
pub use operations::*;
pub use options::*;
pub use part::*;
pub use plan::*;
pub use result::*;

use std::ffi::{c_char, CStr};

/// The ABI version this header describes. A host checks at run time that
/// `tw_abi_version()` equals it; it changes whenever a signature, a struct
/// layout or the meaning of a status changes incompatibly.
pub const TW_ABI_VERSION: u32 = 1;

/// The ABI version of the loaded library (compare with `TW_ABI_VERSION`).
#[no_mangle]
pub extern "C" fn tw_abi_version() -> u32 {
    TW_ABI_VERSION
}

/// The library version, e.g. "0.1.0" (static storage).
#[no_mangle]
pub extern "C" fn tw_version() -> *const c_char {
    static VERSION: &CStr =
        match CStr::from_bytes_with_nul(concat!(env!("CARGO_PKG_VERSION"), "\0").as_bytes()) {
            Ok(v) => v,
            Err(_) => c"unknown",
        };
    std::panic::catch_unwind(|| VERSION.as_ptr()).unwrap_or(c"unknown".as_ptr())
}

/// Free a string returned by Thinwall (`tw_result_to_json`). NULL is allowed.
#[no_mangle]
pub unsafe extern "C" fn tw_string_free(s: *mut c_char) {
    if !s.is_null() {
        let _ = std::panic::catch_unwind(|| drop(std::ffi::CString::from_raw(s)));
    }
}
