//! Status codes, the thread-local last error message, and the panic
//! boundary every entry point runs in.

use std::cell::RefCell;
use std::ffi::{c_char, CString};

/// What a call did. Values are never reused for another meaning.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum tw_status {
    /// Success.
    TW_OK = 0,
    /// A required pointer argument was NULL.
    TW_ERR_NULL_ARGUMENT = 1,
    /// An argument was out of its valid range (a zero up vector, a negative force, bad UTF-8).
    TW_ERR_INVALID_ARGUMENT = 2,
    /// The file could not be read.
    TW_ERR_IO = 3,
    /// The data is not a readable ISO 10303-21 file.
    TW_ERR_PARSE = 4,
    /// The file holds no B-rep solid (e.g. tessellated geometry only).
    TW_ERR_NO_BREP = 5,
    /// The file's solids are malformed (an open shell where a solid is expected, inconsistent ids).
    TW_ERR_INVALID_PART = 6,
    /// An index was past the end.
    TW_ERR_OUT_OF_RANGE = 7,
    /// The caller's buffer is too small; the needed length was written.
    TW_ERR_BUFFER_TOO_SMALL = 8,
    /// The requested value does not apply to this item (a thickness of a hole).
    TW_ERR_NOT_APPLICABLE = 9,
    /// Thinwall failed internally; the message says how.
    TW_ERR_INTERNAL = 98,
    /// Thinwall panicked; the panic was caught at the boundary.
    TW_ERR_PANIC = 99,
}

thread_local! {
    static LAST_ERROR: RefCell<CString> = RefCell::new(CString::default());
}

pub(crate) fn set_error(message: impl Into<String>) {
    let mut m: String = message.into();
    m.retain(|c| c != '\0');
    LAST_ERROR.with(|e| *e.borrow_mut() = CString::new(m).unwrap_or_default());
}

pub(crate) fn clear_error() {
    LAST_ERROR.with(|e| *e.borrow_mut() = CString::default());
}

/// The message of the last failed call on this thread ("" after a success).
/// Valid until the next Thinwall call on this thread; never NULL.
#[no_mangle]
pub extern "C" fn tw_last_error_message() -> *const c_char {
    static EMPTY: &std::ffi::CStr = c"";
    std::panic::catch_unwind(|| LAST_ERROR.with(|e| e.borrow().as_ptr())).unwrap_or(EMPTY.as_ptr())
}

/// Run `body` inside a panic boundary: a panic becomes `TW_ERR_PANIC` with
/// its message, an `Err` its status and message; success clears the error.
pub(crate) fn guard(body: impl FnOnce() -> Result<(), (tw_status, String)>) -> tw_status {
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(body)) {
        Ok(Ok(())) => {
            clear_error();
            tw_status::TW_OK
        }
        Ok(Err((status, message))) => {
            set_error(message);
            status
        }
        Err(panic) => {
            let m = panic
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| panic.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown panic".into());
            set_error(format!("internal panic: {m}"));
            tw_status::TW_ERR_PANIC
        }
    }
}

/// `Err` for a NULL argument.
pub(crate) fn null(name: &str) -> (tw_status, String) {
    (
        tw_status::TW_ERR_NULL_ARGUMENT,
        format!("argument `{name}` is NULL"),
    )
}
