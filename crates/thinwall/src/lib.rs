//! Thinwall in one crate: read a solid part from STEP, recognize what it is
//! made of (webs, ribs, flanges, holes, pockets…), plan the removal of the
//! stock round it and the operations that machine it, in one or several
//! set-ups. Every command of the `thinwall` CLI is one function here, over
//! one [`Study`] of the part (its analysis and results per set-up, each
//! computed at most once); [`render`] writes any result as the CLI does
//! (text, JSON, HTML, SVG).
//!
//! Depend on this crate alone:
//!
//! ```toml
//! [dependencies]
//! thinwall = { git = "…", package = "thinwall" }
//! ```
//!
//! # Recognize, plan, operate
//!
//! ```
//! # let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../fixtures/recognition/c_frame.step");
//! use thinwall::{LoadedPart, Study};
//! let part = LoadedPart::read_file(path)?;
//! let study = Study::new(&part);
//! let walls = thinwall::recognize(&study, &thinwall::recognize_request([0.0, 0.0, 1.0])?)?;
//! println!("{} stiffness features", walls.report.stiffness_features.len());
//! let plan = thinwall::plan(&study, &thinwall::plan_request([0.0, 0.0, 1.0])?)?;
//! println!("{} machining features", plan.plan.machining_features.len());
//! let ops = thinwall::operations(&study, &thinwall::operations_request([0.0, 0.0, 1.0])?)?;
//! println!("{}", thinwall::render(&ops.into(), thinwall::Format::Text)?);
//! # Ok::<(), thinwall::StudyError>(())
//! ```
//!
//! The requests made here are the CLI's defaults (`thinwall recognize`,
//! `plan --up`, `operations --up`): reach of wall sides judged with the
//! preferred Ø12 tool, the default sequence rules, the shipped tool
//! library. Fill a request's fields to change them; its `check()` holds
//! every rule about its values, and a use case refuses a bad one with the
//! same [`StudyError`] the CLI and the C ABI give.
//!
//! # Set-ups proposed
//!
//! Without an up, the planner proposes the set-ups (the fewest directions
//! that reach stock − part, the most material first) and plans them in
//! turn, each on what the ones before it left:
//!
//! ```
//! # let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../fixtures/recognition/c_frame.step");
//! use thinwall::{LoadedPart, Study};
//! let part = LoadedPart::read_file(path)?;
//! let study = Study::new(&part);
//! let mut request = thinwall::plan_request([0.0, 0.0, 1.0])?;
//! request.propose = true;
//! let planned = thinwall::plan(&study, &request)?;
//! let ups = 1 + planned.plan.then.len();
//! assert!(ups >= 1);
//! # Ok::<(), thinwall::StudyError>(())
//! ```
//!
//! # Reach, access, classify, size a wall
//!
//! ```
//! # let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../fixtures/recognition/c_frame.step");
//! use thinwall::{AccessRequest, LoadedPart, Study};
//! let part = LoadedPart::read_file(path)?;
//! let study = Study::new(&part);
//! let setup = thinwall::setup_of(Some([0.0, 0.0, 1.0]), thinwall::Machine::ThreeAxis)?;
//! let access = thinwall::access(&study, &AccessRequest::new(setup))?;
//! let text = thinwall::render(&access.into(), thinwall::Format::Json)?;
//! assert!(text.contains("\"schema\""));
//! # Ok::<(), thinwall::StudyError>(())
//! ```
//!
//! # Inspect, classify a removal volume, size a wall
//!
//! ```
//! # let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../../fixtures/classify/blind_slot");
//! use thinwall::{ClassifyRequest, LoadedPart, Study};
//! let part = LoadedPart::read_file(format!("{dir}/part.step"))?;
//! let study = Study::new(&part);
//! let faces = thinwall::inspect(&study)?;
//! assert!(faces.report.bodies.iter().map(|b| b.faces).sum::<usize>() > 0);
//! let request = ClassifyRequest {
//!     setup: thinwall::setup_of(Some([0.0, 0.0, 1.0]), thinwall::Machine::ThreeAxis)?,
//!     volumes: vec![thinwall::read_volume(format!("{dir}/v0.step"))?],
//!     before: vec![],
//! };
//! let classified = thinwall::classify(&study, request)?;
//! println!("{:?}", classified.report.volumes[0]);
//! use thinwall::sizing::{Milling, SizingParameters, WallDimensions};
//! let sizes = thinwall::size_wall(&thinwall::SizeWallRequest {
//!     wall: WallDimensions { length: 120.0, thickness: 1.5, height: 30.0 },
//!     parameters: SizingParameters::defaults(Milling::Peripheral),
//! })?;
//! println!("{}", thinwall::render(&sizes.into(), thinwall::Format::Text)?);
//! # Ok::<(), thinwall::StudyError>(())
//! ```

pub use thinwall_access::reach::Tool as ReachTool;
pub use thinwall_analysis::{Machine, Setup};
pub use thinwall_classify::Volume;
pub use thinwall_ops::ToolLibrary;
pub use thinwall_plan::sizing;
pub use thinwall_plan::RuleSet;
pub use thinwall_study::*;

/// The recognition `thinwall recognize --up UP` runs: the default
/// settings, reach of every wall side judged with the preferred tool
/// (the settings' `preferred_tool_diameter_mm`, Ø12 by default).
pub fn recognize_request(up: [f64; 3]) -> Result<RecognizeRequest, StudyError> {
    let setup = setup_of(Some(up), Machine::ThreeAxis)?;
    let mut r = RecognizeRequest {
        setup,
        ..Default::default()
    };
    r.reach_tool = Some(ReachTool::new(
        r.config.thresholds.preferred_tool_diameter_mm,
    ));
    Ok(r)
}

/// The plan `thinwall plan --up UP` makes: [`recognize_request`] and the
/// default sequence rules, one set-up (set `propose` for the set-ups
/// proposed, as `thinwall plan` without `--up`).
pub fn plan_request(up: [f64; 3]) -> Result<PlanRequest, StudyError> {
    Ok(PlanRequest::new(
        recognize_request(up)?,
        RuleSet::default_rules(),
    ))
}

/// The operations `thinwall operations --up UP` plans: the shipped tool
/// library, the whole removal layered at once.
pub fn operations_request(up: [f64; 3]) -> Result<OperationsRequest, StudyError> {
    Ok(OperationsRequest::new(setup_of(
        Some(up),
        Machine::ThreeAxis,
    )?))
}
