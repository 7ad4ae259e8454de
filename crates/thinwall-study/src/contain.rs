//! Panics are bugs, reported as such: every use case runs inside
//! [`contained`], which turns a panic into [`StudyError::Panic`] naming the
//! file and the stage, with the panic's message and where it happened.
//!
//! While a contained call runs, the process's panic hook records the
//! panic's location instead of printing it: a library writes nothing to its
//! host's stderr. Set `RUST_BACKTRACE` to have the hook print as usual (with
//! its backtrace) as well.

use crate::StudyError;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Mutex, Once};
use thinwall_analysis::parallel::OverBudget;

/// Contained calls running now, on any thread.
static QUIET: AtomicUsize = AtomicUsize::new(0);
/// Where the last panic of a contained call happened.
static LAST_LOCATION: Mutex<Option<String>> = Mutex::new(None);
static HOOK: Once = Once::new();

fn install_hook() {
    HOOK.call_once(|| {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            let asked = std::env::var_os("RUST_BACKTRACE").is_some_and(|v| v != "0");
            let over_budget = info.payload().is::<OverBudget>();
            if (QUIET.load(Ordering::SeqCst) == 0 || asked) && !over_budget {
                previous(info);
            }
            if let (Some(l), Ok(mut last)) = (info.location(), LAST_LOCATION.lock()) {
                *last = Some(format!("{}:{}", l.file(), l.line()));
            }
        }));
    });
}

/// Counts a contained call while it lives (also when it unwinds).
struct Quiet;

impl Quiet {
    fn new() -> Self {
        QUIET.fetch_add(1, Ordering::SeqCst);
        Quiet
    }
}

impl Drop for Quiet {
    fn drop(&mut self) {
        QUIET.fetch_sub(1, Ordering::SeqCst);
    }
}

/// The text of a panic's payload.
pub fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "a panic without a message".to_string())
}

/// Run `work` (stage `stage` of the study of `file`); a panic in it becomes
/// [`StudyError::Panic`], work stopped past its deadline
/// [`StudyError::BudgetExceeded`].
pub fn contained<T>(
    stage: &'static str,
    file: &str,
    work: impl FnOnce() -> Result<T, StudyError>,
) -> Result<T, StudyError> {
    install_hook();
    // The deadline a use case sets on this thread ends with it.
    let _deadline = thinwall_analysis::parallel::deadline_scope();
    let quiet = Quiet::new();
    let run = catch_unwind(AssertUnwindSafe(work));
    drop(quiet);
    run.unwrap_or_else(|payload| {
        if let Some(over) = payload.downcast_ref::<OverBudget>() {
            return Err(StudyError::BudgetExceeded {
                stage,
                file: file.to_string(),
                limit_seconds: over.limit_seconds,
            });
        }
        let location = LAST_LOCATION.lock().ok().and_then(|mut l| l.take());
        Err(StudyError::Panic {
            stage,
            file: file.to_string(),
            message: panic_message(payload.as_ref()),
            location: location.unwrap_or_else(|| "unknown".into()),
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_panic_is_an_internal_error_naming_file_stage_and_place() {
        let r: Result<(), _> = contained("plan", "part.step", || panic!("NaN in a hull"));
        let e = r.unwrap_err();
        assert_eq!(e.kind(), crate::ErrorKind::Internal);
        assert_eq!(e.code(), "panic");
        let m = e.to_string();
        assert!(m.starts_with("part.step: "), "{m}");
        assert!(m.contains("plan") && m.contains("NaN in a hull"), "{m}");
        assert!(m.contains("contain.rs:"), "{m}");
        assert_eq!(QUIET.load(Ordering::SeqCst), 0);
    }

    #[test]
    fn work_stopped_past_its_deadline_is_a_budget_error() {
        let r: Result<(), _> = contained("access", "part.step", || {
            std::panic::panic_any(OverBudget {
                limit_seconds: 60.0,
            })
        });
        let e = r.unwrap_err();
        assert_eq!(
            (e.code().as_str(), e.kind()),
            ("budget_exceeded", crate::ErrorKind::Input)
        );
        assert!(
            e.to_string()
                .contains("access did not finish within its time limit of 60 s"),
            "{e}"
        );
    }

    #[test]
    fn errors_and_results_pass_through() {
        assert_eq!(contained("x", "f", || Ok(3)).unwrap(), 3);
        let e = contained::<()>("x", "f", || Err(StudyError::invalid("threshold", "bad")));
        assert_eq!(e.unwrap_err().code(), "invalid.threshold");
    }
}
