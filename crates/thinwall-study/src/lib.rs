//! One study of a part that every command runs on, and one use-case
//! function per command.
//!
//! A [`LoadedPart`] is a part read from STEP with its adjacency graph. A
//! [`Study`] of it keeps, per set-up, the one [`PartAnalysis`] (with its
//! mesh) and every result computed on it — recognition outcomes, plans —
//! each computed at most once, on demand (rust-analyzer's analysis host is
//! the model). The use cases ([`inspect()`], [`recognize()`], [`plan()`],
//! [`access()`], [`operations()`], [`classify()`], [`size_wall()`]) take a
//! typed request whose `check()` holds every rule about its values, and
//! return a typed result or a [`StudyError`]; [`render()`] writes any
//! result in a [`Format`]. The CLI, the C ABI and (later) the Python
//! package are thin faces over these functions, so the same bad value gets
//! the same error everywhere.
//!
//! ```no_run
//! use thinwall_study::{LoadedPart, Study, RecognizeRequest, Format};
//! let part = LoadedPart::read_file("panel.step").unwrap();
//! let study = Study::new(&part);
//! let r = thinwall_study::recognize(&study, &RecognizeRequest::default()).unwrap();
//! println!("{}", thinwall_study::render(&r.into(), Format::Text).unwrap());
//! ```
//!
//! [`PartAnalysis`]: thinwall_analysis::PartAnalysis

mod contain;
mod error;
mod loaded;
mod memo;
mod render;
mod request;
mod study;
mod usecase;

pub use contain::{contained, panic_message};
pub use error::{ErrorKind, StudyError};
pub use loaded::LoadedPart;
pub use render::{render, Format, Rendered};
pub use request::{
    read_volume, setup_of, volume_of, AccessRequest, ClassifyRequest, OperationsRequest,
    PlanRequest, RecognizeRequest, SizeWallRequest,
};
pub use study::{AtSetup, Study};
pub use usecase::{
    access, access_observed, classify, inspect, operations, operations_observed, plan,
    plan_observed, recognize, size_wall, write_volumes, Accessed, Classified, Inspected, Operated,
    Planned, Recognized,
};
