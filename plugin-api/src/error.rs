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
    /// The recognition settings are not usable (a non-positive model
    /// parameter, a kind both included and excluded).
    TW_ERR_INVALID_CONFIG = 10,
    /// The set-up is not usable (a zero up direction, a tilt limit outside 0–90°).
    TW_ERR_INVALID_SETUP = 11,
    /// Recognition produced an inconsistent result (a connection structure
    /// that is not a forest): a defect of Thinwall; the message names it.
    TW_ERR_RECOGNITION = 12,
    /// A removal sequence names volumes that are not there.
    TW_ERR_INVALID_SEQUENCE = 13,
    /// The part has geometry the computation does not take yet (a face
    /// that is no graph over the set-up plane, for operations); the
    /// message names the face.
    TW_ERR_UNSUPPORTED = 14,
    /// The input or the work it asks for exceeds a budget (file size,
    /// faces placed, time); the message names the limit.
    TW_ERR_BUDGET_EXCEEDED = 15,
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

/// Run `body` (the C function `stage`) inside a panic boundary: a panic
/// becomes `TW_ERR_PANIC` with a message naming the stage and where it
/// happened (and the file, when it happened in a use case), an `Err` its
/// status and message; success clears the error. Nothing is printed.
pub(crate) fn guard(
    stage: &'static str,
    body: impl FnOnce() -> Result<(), (tw_status, String)>,
) -> tw_status {
    match thinwall_study::contained(stage, "libthinwall", || Ok(body())) {
        Ok(Ok(())) => {
            clear_error();
            tw_status::TW_OK
        }
        Ok(Err((status, message))) => {
            set_error(message);
            status
        }
        Err(panic) => {
            set_error(panic.to_string());
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

/// A failure to report: its status and message.
pub(crate) type Failure = (tw_status, String);

/// A constructor's boundary: `*out` is NULL unless `make` succeeds, and then
/// owns the new object.
pub(crate) unsafe fn construct<T>(
    stage: &'static str,
    out: *mut *mut T,
    make: impl FnOnce() -> Result<T, Failure>,
) -> tw_status {
    if !out.is_null() {
        *out = std::ptr::null_mut();
    }
    guard(stage, || {
        if out.is_null() {
            return Err(null("out"));
        }
        let value = make()?;
        *out = Box::into_raw(Box::new(value));
        Ok(())
    })
}

/// `*out_json` = a new string (free with `tw_string_free`) made from `*obj`;
/// NULL on failure.
pub(crate) unsafe fn json_into<T>(
    stage: &'static str,
    obj: *const T,
    out_json: *mut *mut c_char,
    json: impl FnOnce(&T) -> String,
) -> tw_status {
    if !out_json.is_null() {
        *out_json = std::ptr::null_mut();
    }
    guard(stage, || {
        if out_json.is_null() {
            return Err(null("out_json"));
        }
        if obj.is_null() {
            return Err(null("res"));
        }
        *out_json = cstring(&json(&*obj)).into_raw();
        Ok(())
    })
}

/// A string owned by `*obj`, or NULL for a NULL object, a missing entry or a panic.
pub(crate) unsafe fn string_at<T>(
    obj: *const T,
    pick: impl FnOnce(&T) -> Option<&CString>,
) -> *const c_char {
    if obj.is_null() {
        return std::ptr::null();
    }
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        pick(&*obj).map_or(std::ptr::null(), |s| s.as_ptr())
    }))
    .unwrap_or(std::ptr::null())
}

/// A count read from `*obj`, 0 for a NULL object or a panic.
pub(crate) unsafe fn count<T>(obj: *const T, len: impl FnOnce(&T) -> usize) -> usize {
    if obj.is_null() {
        return 0;
    }
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| len(&*obj))).unwrap_or(0)
}

/// Free an object made by [`construct`]; NULL is allowed.
pub(crate) unsafe fn free<T>(ptr: *mut T) {
    if !ptr.is_null() {
        let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| drop(Box::from_raw(ptr))));
    }
}

/// A C string of `s` (interior NULs dropped).
pub(crate) fn cstring(s: &str) -> CString {
    CString::new(s.replace('\0', "")).unwrap_or_default()
}

/// The status of a read error, by its kind (every variant named).
fn read_status(e: &thinwall_step::StepError) -> tw_status {
    use thinwall_step::StepError as E;
    match e {
        E::Io { .. } => tw_status::TW_ERR_IO,
        E::Syntax { .. } => tw_status::TW_ERR_PARSE,
        E::NoBrep { .. } => tw_status::TW_ERR_NO_BREP,
        E::OpenShell { .. }
        | E::IdMismatch { .. }
        | E::CyclicAssembly { .. }
        | E::CyclicReference { .. }
        | E::BadNumber { .. }
        | E::TooManyInstances { .. } => tw_status::TW_ERR_INVALID_PART,
        E::BudgetExceeded { .. } => tw_status::TW_ERR_BUDGET_EXCEEDED,
        E::Internal { .. } => tw_status::TW_ERR_INTERNAL,
    }
}

/// The status of a recognition error: every variant named, so a new one
/// is a compile error here rather than a silent `TW_ERR_INTERNAL`.
fn pipeline_status(e: &thinwall_pipeline::PipelineError) -> tw_status {
    use thinwall_pipeline::PipelineError as E;
    match e {
        E::Config(_) | E::Machining(_) => tw_status::TW_ERR_INVALID_CONFIG,
        E::Setup(_) => tw_status::TW_ERR_INVALID_SETUP,
        E::Reach(_) => tw_status::TW_ERR_INVALID_ARGUMENT,
        E::OpenShell { .. } => tw_status::TW_ERR_INVALID_PART,
        E::Structure(_) => tw_status::TW_ERR_RECOGNITION,
        E::SetupMismatch => tw_status::TW_ERR_INTERNAL,
    }
}

/// The status of a classification error, by its kind (every variant
/// named, as for recognition).
fn classify_status(e: &thinwall_classify::ClassifyError) -> tw_status {
    use thinwall_classify::ClassifyError as E;
    match e {
        E::Sequence { .. } | E::SelfPair { .. } | E::Cycle { .. } => {
            tw_status::TW_ERR_INVALID_SEQUENCE
        }
        E::MultiBody { .. } | E::Duplicate { .. } | E::PartAsVolume { .. } | E::Overlap { .. } => {
            tw_status::TW_ERR_INVALID_ARGUMENT
        }
    }
}

/// The status and message of a use case's error (the CLI prints the same
/// message and exits by the same error's kind).
pub(crate) fn study_failure(e: thinwall_study::StudyError) -> Failure {
    (study_status(&e), e.to_string())
}

/// The status of a use case's error (also the Python package's
/// exceptions' `status`).
pub fn study_status(e: &thinwall_study::StudyError) -> tw_status {
    use thinwall_ops::OpsError as O;
    use thinwall_study::StudyError as S;
    match e {
        S::Invalid { .. } | S::Reach(_) | S::Sizing(_) => tw_status::TW_ERR_INVALID_ARGUMENT,
        S::Io { .. } => tw_status::TW_ERR_IO,
        S::Read(r) => read_status(r),
        S::Setup(_) => tw_status::TW_ERR_INVALID_SETUP,
        S::Request(p) | S::Recognition { source: p, .. } => pipeline_status(p),
        S::Rules(_) | S::Tools(_) | S::Plan(_) => tw_status::TW_ERR_INVALID_CONFIG,
        S::Operations(O::NoEndMill { .. }) => tw_status::TW_ERR_INVALID_CONFIG,
        S::Operations(O::Removal(_) | O::NoPlan(_)) => tw_status::TW_ERR_UNSUPPORTED,
        S::Classify(c) => classify_status(c),
        S::Panic { .. } => tw_status::TW_ERR_PANIC,
        S::BudgetExceeded { .. } => tw_status::TW_ERR_BUDGET_EXCEEDED,
    }
}
