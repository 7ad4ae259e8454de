//! The operations of one set-up from the analysed part, as the CLI and the
//! C ABI run them: the removal (stock = the part's oriented box, minus the
//! part), the holes along the tool axis, then [`operations`].

use crate::drilling::hole_sites;
use crate::operations::{operations, SetupOperations};
use crate::ToolLibrary;
use thinwall_analysis::PartAnalysis;
use thinwall_geom::Frame;
use thinwall_machining::MachiningFeature;
use thinwall_plan::StepLimit;
use thinwall_removal::{frame_of, Removal, RemovalError, StockShape};
use thiserror::Error;

/// Why a set-up's operations could not be planned.
#[derive(Debug, Error)]
pub enum OpsError {
    #[error("{library}: the library has no end mill to rough with")]
    NoEndMill { library: String },
    /// Stock − part could not be decomposed (a face that is no graph over
    /// the set-up plane).
    #[error("{0}")]
    Removal(#[from] RemovalError),
    /// The plan has no machining features (its removal could not be
    /// decomposed), with why.
    #[error("the plan has no machining features: removal.{code}: {0}", code = .0.code())]
    NoPlan(RemovalError),
}

impl OpsError {
    /// A stable machine-readable code: `tools.no_end_mill`,
    /// `removal.<kind>` or `machining.<kind>`.
    pub fn code(&self) -> String {
        match self {
            OpsError::NoEndMill { .. } => "tools.no_end_mill".to_string(),
            OpsError::Removal(e) => format!("removal.{}", e.code()),
            OpsError::NoPlan(_) => "plan.no_features".to_string(),
        }
    }
}

/// The library can rough, and the set-up's removal frame with the stock
/// box's corners in it.
fn frame_for(a: &PartAnalysis, lib: &ToolLibrary) -> Result<(Frame, [f64; 3], [f64; 3]), OpsError> {
    if lib.end_mills().next().is_none() {
        return Err(OpsError::NoEndMill {
            library: lib.source.clone(),
        });
    }
    Ok(frame_of(a, a.up()))
}

/// The operations of `a`'s set-up with `lib` (the stock is the part's
/// oriented box), and the removal frame their contours are in; no layer
/// beside a thin wall deeper than its `limits` allow
/// (`thinwall_plan::step_limits`).
/// `features` are the part's machining features found in this set-up (its
/// up the tool axis): the holes among them are drilled. Set-ups after
/// another: [`plan_in_turn`].
pub fn plan_setup(
    a: &PartAnalysis,
    features: &[MachiningFeature],
    lib: &ToolLibrary,
    axial_depth_mm: Option<f64>,
    limits: &[StepLimit],
) -> Result<(Frame, SetupOperations), OpsError> {
    let (frame, lo, hi) = frame_for(a, lib)?;
    let size = a.bounding_box().diagonal();
    let removal = Removal::new(
        a.part(),
        frame,
        &StockShape::Block { lo, hi },
        &[],
        size,
        a.work(),
    )?
    .checked()?;
    let (ops, _) = plan_in_turn(a, &removal, features, &[], lib, axial_depth_mm, limits)?;
    Ok((frame, ops))
}

/// The operations of one set-up of several planned in turn: its
/// `removal` has the blocks earlier set-ups reached `cleared`
/// ([`thinwall_setups::in_turn`]); `a` is the part analysed in this
/// set-up and `features` its machining features found in it. A hole whose
/// faces an earlier set-up drilled (`drilled_before`, their `step_id`s) is
/// not drilled again; the faces of the holes drilled here are returned.
pub fn plan_in_turn(
    a: &PartAnalysis,
    removal: &Removal,
    features: &[MachiningFeature],
    drilled_before: &[u64],
    lib: &ToolLibrary,
    axial_depth_mm: Option<f64>,
    limits: &[StepLimit],
) -> Result<(SetupOperations, Vec<u64>), OpsError> {
    frame_for(a, lib)?;
    let frame = removal.frame;
    let here = not_drilled(features, drilled_before);
    let holes = hole_sites(&here, &frame, lib);
    let mut ops = operations(removal, lib, axial_depth_mm, limits, &holes, a.work());
    ops.meshed = removal.meshed.clone();
    ops.out_of_reach_mm3 = crate::layers::out_of_reach_mm3(removal);
    ops.cleared_before_mm3 = removal.cleared_volume();
    finish_by_radii(&mut ops, a, &here, &frame, lib);
    Ok((ops, drilled_faces(&here, &holes)))
}

/// The operations of `a`'s set-up along its `plan`: each machining feature
/// layered and tooled on its own, the holes drilled, in an order that
/// keeps every relation of the plan.
pub fn along_plan(
    a: &PartAnalysis,
    plan: &thinwall_plan::Plan,
    features: &[MachiningFeature],
    lib: &ToolLibrary,
    axial_depth_mm: Option<f64>,
) -> Result<(Frame, SetupOperations), OpsError> {
    let (frame, _, _) = frame_for(a, lib)?;
    let (ops, _) = along_plan_in_turn(a, plan, features, &[], lib, axial_depth_mm)?;
    Ok((frame, ops))
}

/// [`along_plan`] for one set-up of several planned in turn (its `plan`
/// leaves out what the set-ups before took,
/// `thinwall_plan::plan_in_turn`): a hole whose faces an earlier set-up
/// drilled (`drilled_before`) is not drilled again; the faces of the holes
/// drilled here are returned.
pub fn along_plan_in_turn(
    a: &PartAnalysis,
    plan: &thinwall_plan::Plan,
    features: &[MachiningFeature],
    drilled_before: &[u64],
    lib: &ToolLibrary,
    axial_depth_mm: Option<f64>,
) -> Result<(SetupOperations, Vec<u64>), OpsError> {
    let (frame, lo, hi) = frame_for(a, lib)?;
    if let Some(why) = &plan.removal.unavailable {
        return Err(OpsError::NoPlan(why.clone()));
    }
    let stock = geo::Rect::new(
        geo::Coord { x: lo[0], y: lo[1] },
        geo::Coord { x: hi[0], y: hi[1] },
    );
    let size = a.bounding_box().diagonal();
    let here = not_drilled(features, drilled_before);
    let holes = hole_sites(&here, &frame, lib);
    let mut ops =
        crate::planned::by_feature(plan, lib, axial_depth_mm, &holes, stock, size, a.work());
    ops.meshed = plan.removal.meshed.clone();
    ops.cleared_before_mm3 = plan.removal.cleared_before_mm3;
    ops.recut_mm3 = plan.removal.recut_mm3;
    finish_by_radii(&mut ops, a, &here, &frame, lib);
    Ok((ops, drilled_faces(&here, &holes)))
}

/// The features no earlier set-up drilled (none of their faces in
/// `drilled_before`).
fn not_drilled(features: &[MachiningFeature], drilled_before: &[u64]) -> Vec<MachiningFeature> {
    features
        .iter()
        .filter(|m| !m.faces.iter().any(|f| drilled_before.contains(f)))
        .cloned()
        .collect()
}

/// The faces of the features among `here` that `holes` drill.
fn drilled_faces(here: &[MachiningFeature], holes: &[crate::drilling::HoleSite]) -> Vec<u64> {
    here.iter()
        .filter(|m| holes.iter().any(|h| h.id == m.id.to_string()))
        .flat_map(|m| m.faces.iter().copied())
        .collect()
}

/// The features finished by their radii and the holes' stages, their
/// operations put in.
fn finish_by_radii(
    ops: &mut SetupOperations,
    a: &PartAnalysis,
    features: &[MachiningFeature],
    frame: &Frame,
    lib: &ToolLibrary,
) {
    let finishes = crate::finishing::radius_finishes(a, features, frame, lib);
    crate::finishing::append(ops, &finishes, lib);
    ops.radius_finishes = finishes;
    let stages = crate::hole_stages::hole_stages(features, frame, lib, &ops.holes);
    crate::hole_stages::place(ops, &stages, lib);
    ops.hole_stages = stages;
}
