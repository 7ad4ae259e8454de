//! How deep one layer beside a thin wall may be cut (DOMAIN.md §5, Popma
//! §4.1.1): the operations planner's layers go down in global levels, so
//! beside a thin wall standing along up no layer may be deeper than the
//! wall's small step `h_RF`. Then each step of the wall is finished with
//! the material below it still in place, which is what the sizing model
//! allows for (the large side's `H_RF` assumes the other side's support
//! `B_RF`, which a layer cut right across both sides does not leave).

use crate::types::{Axis, WallPlan};
use serde::Serialize;
use thinwall_analysis::FeatureId;
use thinwall_pipeline::Outcome;

/// A thin wall standing along up, the heights it spans and the deepest
/// layer allowed beside it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct StepLimit {
    pub wall: FeatureId,
    /// Its foot and free edge, as heights along up (the set-up's heights,
    /// the removal frame's z), mm; lowest first.
    pub z_mm: [f64; 2],
    /// The deepest layer beside it: its `h_RF`, mm.
    pub depth_mm: f64,
}

/// The limits of the thin walls among `walls` that are milled with the
/// tool's flank and stand along the set-up's up (or hang along it). A
/// web (face milled) or a wall lying across up has none: its layers are
/// not the roughing levels'.
pub(crate) fn step_limits(out: &Outcome, walls: &[WallPlan]) -> Vec<StepLimit> {
    let up = out.setup.up_in_part();
    let mut limits = Vec::new();
    for w in walls.iter().filter(|w| w.sizes.thin) {
        if w.sizes.milling != crate::Milling::Peripheral {
            continue;
        }
        let Some(g) = out
            .recognition
            .feature(w.id)
            .and_then(|f| f.geometry.as_ref())
        else {
            continue;
        };
        let axis = Axis::of(g, w.sizes.wall.height);
        if !axis.stands_along(&up) {
            continue;
        }
        let (a, b) = (
            axis.height_along(&up, 0.0),
            axis.height_along(&up, axis.height),
        );
        limits.push(StepLimit {
            wall: w.id,
            z_mm: [a.min(b), a.max(b)],
            depth_mm: w.sizes.h,
        });
    }
    limits
}
