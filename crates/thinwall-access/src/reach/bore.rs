//! A concave cylinder around the tool axis (a bore, an upright inside
//! corner's blend) bounds the tool exactly: a cylinder of radius R touching
//! an arc of smaller radius r from inside, tangent at a point, cuts the arc
//! on both sides of it. So a tool wider than the bore reaches none of the
//! face (its ends, where it meets its neighbours, are lines of no area),
//! and one as wide as the bore may reach it all.
//!
//! The triangles cannot tell this: a curved face's own chords touch the
//! tool within twice the tessellation's deviation, which let a tool up to
//! four deviations over the bore through (NIST CTC 05's Ø19.05 holes came
//! out Ø20.8). The surface knows the radius; this layer asks it first.

use super::sampled::Samples;
use super::scene::Scene;
use super::{Ctx, Judged};
use thinwall_analysis::PartAnalysis;
use thinwall_brep::FaceId;
use thinwall_geom::tolerance::PARALLEL_ANGLE_RAD;

/// The diameter of face `f` when it is a concave cylinder whose axis is
/// the scene's (within [`PARALLEL_ANGLE_RAD`]), mm: no tool wider reaches
/// any of it on that axis.
pub fn limit(a: &PartAnalysis, scene: &Scene, f: FaceId) -> Option<f64> {
    let c = a.concave_cylinder(f)?;
    let along = scene.local_vector(&c.axis)[2].abs();
    (along >= PARALLEL_ANGLE_RAD.cos()).then_some(2.0 * c.radius)
}

/// Whether the tool is wider than the bound `limit` (beyond the exact
/// geometry's touching distance on each side).
pub fn too_wide(ctx: &Ctx, limit: f64) -> bool {
    ctx.tool.diameter > limit + 2.0 * ctx.touch
}

/// Face `own` (mesh index) not reached anywhere: every sample lost, the
/// face's own arc in the cutter's way.
pub fn none_reached(samples: &Samples, own: u32) -> Judged {
    let all = 0..samples.len() as u32;
    let area: f64 = all.clone().map(|k| samples.area(k)).sum();
    let mut j = Judged {
        area,
        lost: all.clone().collect(),
        unreachable: samples.outlines(all),
        ..Judged::default()
    };
    if area > 0.0 {
        j.blockers.insert((own, false), area);
    }
    j
}
