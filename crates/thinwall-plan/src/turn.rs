//! A set-up planned after others (issue 37): its removal's blocks the
//! earlier set-ups took are no features of its own
//! ([`crate::whole::removal_plan`]), and a thin web keeps the support of
//! the material still under it.
//!
//! A web is face milled from the side facing up; what keeps it from
//! deflecting under the cut is what lies below it. While material a later
//! set-up removes is still there (the far side of a web pocketed from
//! both sides), the web is as thick as web and that material together:
//! it needs no step layers in this set-up. In the set-up that mills its
//! last side, what the first side left is gone, and its layers are sized
//! on its own thickness (Popma §4.1.1, DOMAIN.md §5).

use crate::types::WallPlan;
use std::collections::BTreeSet;
use thinwall_analysis::{FeatureId, StiffnessKind};
use thinwall_pipeline::Outcome;
use thinwall_removal::{Bound, Removal};

/// One set-up of several planned in turn.
#[derive(Clone, Copy)]
pub struct InTurn<'r> {
    /// This set-up's removal of the block stock (no layer bands), its
    /// blocks the earlier set-ups took marked `cleared`
    /// ([`thinwall_setups::in_turn`]).
    pub this: &'r Removal,
    /// The removals of the set-ups before it, in order.
    pub earlier: &'r [Removal],
}

/// Share of the area under a web that must still hold material for the
/// web to count as supported there.
pub const SUPPORTED_SHARE: f64 = 0.5;

/// The thin webs of `walls` with material still under them in this
/// set-up: over at least [`SUPPORTED_SHARE`] of the area of the removal's
/// cells just below the web's faces, a block no earlier set-up took.
pub fn supported_webs(out: &Outcome, walls: &[WallPlan], turn: &InTurn) -> BTreeSet<FeatureId> {
    let r = turn.this;
    walls
        .iter()
        .filter(|w| w.kind == StiffnessKind::Web && w.sizes.thin)
        .filter(|w| {
            let Some(f) = out.recognition.feature(w.id) else {
                return false;
            };
            let (mut under, mut held) = (0.0, 0.0);
            for b in &r.blocks {
                let Bound::Part(i) = b.upper else { continue };
                if !f.faces.contains(&r.part_step_id(i)) {
                    continue;
                }
                let area = r.cells[b.cell].area;
                under += area;
                if !b.cleared {
                    held += area;
                }
            }
            under > 0.0 && held >= SUPPORTED_SHARE * under
        })
        .map(|w| w.id)
        .collect()
}
