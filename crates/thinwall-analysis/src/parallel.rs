//! How work on a part runs: on rayon's worker threads or on the calling
//! thread only (a host that asks for serial work, as the C ABI's `parallel`
//! option does, gets no thread started; the results are the same either
//! way), and within a time budget.
//!
//! A [`Budget`] holds the deadline of the call running now. Work checks it
//! between items; past the deadline the check unwinds with an
//! [`OverBudget`] payload, which `thinwall_study::contained` turns into a
//! typed `budget_exceeded` error (the unwinding is how a long computation
//! deep in a layer is stopped without every layer's error type knowing of
//! budgets).

use rayon::prelude::*;
use std::cell::Cell;
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// A deadline and the limit it came from.
type Deadline = Option<(Instant, Duration)>;

thread_local! {
    /// The deadline of the work this thread is doing now: set by
    /// [`Budget::start`] on the calling thread and by [`Work::map`] on each
    /// worker for each item, so code deep in a layer can check it with
    /// [`check_deadline`] without a handle.
    static DEADLINE: Cell<Deadline> = const { Cell::new(None) };
}

/// Unwind with [`OverBudget`] when the work this thread is doing is past
/// its deadline (a thread-local read and a clock read: cheap enough for a
/// loop over rows or pieces).
pub fn check_deadline() {
    if let Some((deadline, limit)) = DEADLINE.get() {
        if Instant::now() > deadline {
            std::panic::panic_any(OverBudget {
                limit_seconds: limit.as_secs_f64(),
            });
        }
    }
}

/// Restores the thread's deadline when dropped (also when unwinding).
pub struct DeadlineScope(Deadline);

/// Keep the thread's deadline as it is now, to be restored when the scope
/// ends.
pub fn deadline_scope() -> DeadlineScope {
    DeadlineScope(DEADLINE.get())
}

impl Drop for DeadlineScope {
    fn drop(&mut self) {
        DEADLINE.set(self.0);
    }
}

/// The payload of the unwinding that stops work past its deadline.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OverBudget {
    /// The limit that was exceeded, seconds.
    pub limit_seconds: f64,
}

/// The deadline of the work running now on one part (none by default).
#[derive(Debug, Default)]
pub struct Budget {
    deadline: Mutex<Option<(Instant, Duration)>>,
}

impl Budget {
    /// Let the work starting now take at most `limit` (`None`: no limit).
    /// The calling thread's deadline is set too.
    pub fn start(&self, limit: Option<Duration>) {
        let mut d = self.deadline.lock().unwrap_or_else(|p| p.into_inner());
        *d = limit.map(|l| (Instant::now() + l, l));
        DEADLINE.set(*d);
    }

    fn deadline(&self) -> Deadline {
        *self.deadline.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// Unwind with [`OverBudget`] when the deadline has passed.
    pub fn check(&self) {
        if let Some((deadline, limit)) = self.deadline() {
            if Instant::now() > deadline {
                std::panic::panic_any(OverBudget {
                    limit_seconds: limit.as_secs_f64(),
                });
            }
        }
    }
}

/// How to run work over many items: in parallel or not, within a budget.
#[derive(Clone, Copy, Debug)]
pub struct Work<'b> {
    pub parallel: bool,
    pub budget: &'b Budget,
}

/// No deadline, for [`Work::serial`].
static UNLIMITED: Budget = Budget {
    deadline: Mutex::new(None),
};

impl Work<'static> {
    /// Work on the calling thread with no time limit (a caller outside a
    /// study: a test, a tool).
    pub fn serial() -> Self {
        Work {
            parallel: false,
            budget: &UNLIMITED,
        }
    }
}

impl Work<'_> {
    /// `f` of each of `items`, in their order; on rayon's workers (one item
    /// per task: items may cost very different amounts) when parallel. The
    /// budget is checked before each item.
    pub fn map<I, T, F>(&self, items: &[I], f: F) -> Vec<T>
    where
        I: Sync,
        T: Send,
        F: Fn(&I) -> T + Sync + Send,
    {
        let deadline = self.budget.deadline();
        let one = |i: &I| {
            let _scope = deadline_scope();
            DEADLINE.set(deadline);
            check_deadline();
            f(i)
        };
        if self.parallel {
            items.par_iter().with_max_len(1).map(one).collect()
        } else {
            items.iter().map(one).collect()
        }
    }

    /// Unwind with [`OverBudget`] when the deadline has passed.
    pub fn check(&self) {
        self.budget.check();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn serial_and_parallel_give_the_same_results_in_order() {
        let budget = Budget::default();
        let items: Vec<u32> = (0..100).collect();
        let f = |x: &u32| x * x;
        let (par, ser) = (
            Work {
                parallel: true,
                budget: &budget,
            },
            Work {
                parallel: false,
                budget: &budget,
            },
        );
        assert_eq!(par.map(&items, f), ser.map(&items, f));
        assert_eq!(ser.map(&items, f)[7], 49);
    }

    #[test]
    fn work_past_its_deadline_unwinds_with_over_budget() {
        let budget = Budget::default();
        budget.start(Some(Duration::ZERO));
        std::thread::sleep(Duration::from_millis(2));
        let work = Work {
            parallel: false,
            budget: &budget,
        };
        let r = std::panic::catch_unwind(|| work.map(&[1, 2], |x| *x));
        let payload = r.unwrap_err();
        assert_eq!(
            payload.downcast_ref::<OverBudget>(),
            Some(&OverBudget { limit_seconds: 0.0 })
        );
        budget.start(None);
        assert_eq!(work.map(&[1, 2], |x| *x), vec![1, 2]);
    }

    #[test]
    fn code_deep_in_an_item_sees_its_deadline_and_a_scope_restores_it() {
        let budget = Budget::default();
        let scope = deadline_scope();
        budget.start(Some(Duration::ZERO));
        std::thread::sleep(Duration::from_millis(2));
        let work = Work {
            parallel: true,
            budget: &budget,
        };
        let deep = std::panic::catch_unwind(|| work.map(&[1], |_| 0));
        assert!(deep.unwrap_err().is::<OverBudget>());
        assert!(std::panic::catch_unwind(check_deadline).is_err());
        drop(scope);
        check_deadline();
    }
}
