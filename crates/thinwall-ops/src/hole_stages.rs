//! A hole's stages besides its bores (issue 38; Cohen et al.'s holes with
//! subtypes): a planner makes a hole as one feature with one tool
//! sequence: spot, drill, counterbore or countersink, chamfer. The bores
//! are drilled, milled down a helix or (a counterbore) plunged by an end
//! mill ([`crate::drilling`]); here the spot before a drill, the
//! countersink or chamfer of its entry after it, and the stages no tool
//! of the library makes (a blended edge, an exit on the far side) are
//! named with why.

use crate::drilling::{entered_from_up, DrillKind, HoleSite};
use crate::operations::{Operation, SetupOperations};
use crate::rest::Adjacency;
use crate::stage::Stage;
pub use crate::stage::{HoleStage, HoleStep};
use crate::tools::{CuttingTool, ToolKind, ToolLibrary};
use thinwall_analysis::MachiningKind;
use thinwall_geom::Frame;
use thinwall_machining::{HoleEnd, MachiningFeature};

/// A countersink matches a cone when their included angles differ by no
/// more, degrees.
pub const ANGLE_MATCH_DEG: f64 = 0.5;

/// The stages of `features`' holes the tool reaches from up in `frame`,
/// given their bores' `sites` ([`crate::drilling::hole_sites`]).
pub fn hole_stages(
    features: &[MachiningFeature],
    frame: &Frame,
    lib: &ToolLibrary,
    sites: &[HoleSite],
) -> Vec<HoleStage> {
    let mut out = Vec::new();
    for m in features
        .iter()
        .filter(|m| m.kind == MachiningKind::Hole && m.reachable != Some(false))
    {
        let Some(down) = entered_from_up(m, frame) else {
            continue;
        };
        let id = m.id.to_string();
        let own: Vec<&HoleSite> = sites.iter().filter(|h| same_hole(&h.id, &id)).collect();
        let Some(top) = own.iter().map(|h| h.z_top_mm).reduce(f64::max) else {
            continue;
        };
        // The first drilled bore is spotted.
        if let Some(h) = own
            .iter()
            .filter(|h| drilled(h.kind) && h.drill.is_some())
            .max_by(|a, b| a.z_top_mm.total_cmp(&b.z_top_mm))
        {
            out.push(spot(m, h, lib));
        }
        let Some(form) = &m.hole else { continue };
        let narrowest = form
            .bores
            .iter()
            .map(|b| b.diameter)
            .fold(f64::INFINITY, f64::min);
        let (entry, exit) = if down {
            (&form.entry, &form.exit)
        } else {
            (&form.exit, &form.entry)
        };
        let first = if down {
            form.bores.first()
        } else {
            form.bores.last()
        };
        let bore = first.map_or(narrowest, |b| b.diameter);
        if let Some(e) = entry {
            out.push(end_stage(m, e, false, top, bore, lib));
        }
        if let Some(e) = exit {
            let bottom = own.iter().map(|h| h.z_bottom_mm).fold(top, f64::min);
            out.push(end_stage(m, e, true, bottom, bore, lib));
        }
    }
    out
}

/// Made by a drill's point (spotted first).
fn drilled(kind: DrillKind) -> bool {
    matches!(
        kind,
        DrillKind::Through | DrillKind::Blind | DrillKind::Peck
    )
}

/// The spot before bore `h` of `m`: the smallest spot drill at least as
/// wide as the bore (its point then reaches the bore's width), else the
/// widest.
fn spot(m: &MachiningFeature, h: &HoleSite, lib: &ToolLibrary) -> HoleStage {
    let spots: Vec<&CuttingTool> = lib.of_kind(ToolKind::SpotDrill).collect();
    let tool = spots
        .iter()
        .find(|t| t.diameter_mm >= h.diameter_mm)
        .or(spots.last())
        .copied();
    let angle = tool.and_then(|t| t.point_angle_deg);
    let depth = angle.map_or(0.0, |a| cone_depth(h.diameter_mm, 0.0, a));
    HoleStage {
        hole: m.id.to_string(),
        step: HoleStep::Spot,
        at_exit: false,
        angle_deg: angle,
        diameter_mm: h.diameter_mm,
        z_top_mm: h.z_top_mm,
        depth_mm: depth,
        tool: tool.map(|t| t.name.clone()),
        missing: tool
            .is_none()
            .then(|| "no spot drill in the library".to_string()),
    }
}

/// A countersink, chamfer or blend at one end of `m` (`at_exit`: the far
/// end, at height `z`), its tool or why none.
fn end_stage(
    m: &MachiningFeature,
    e: &HoleEnd,
    at_exit: bool,
    z: f64,
    bore: f64,
    lib: &ToolLibrary,
) -> HoleStage {
    let (step, angle, diameter) = match *e {
        HoleEnd::Countersink {
            angle_deg,
            diameter,
        } => (HoleStep::Countersink, Some(angle_deg), diameter),
        HoleEnd::Chamfer {
            angle_deg,
            diameter,
        } => (HoleStep::Chamfer, Some(angle_deg), diameter),
        HoleEnd::Blend { radius } => (HoleStep::Blend, None, bore + 2.0 * radius),
    };
    let cone = angle.and_then(|a| {
        lib.of_kind(ToolKind::Countersink).find(|t| {
            t.point_angle_deg
                .is_some_and(|p| (p - a).abs() <= ANGLE_MATCH_DEG)
                && t.diameter_mm >= diameter
        })
    });
    let missing = if at_exit {
        Some("at the far end: from the other side (no back-chamfering tool)".to_string())
    } else if step == HoleStep::Blend {
        Some("no corner-rounding cutter in the library".to_string())
    } else if cone.is_none() {
        Some(format!(
            "no countersink of {:.0}° at least {diameter:.2} mm wide in the library",
            angle.unwrap_or(0.0)
        ))
    } else {
        None
    };
    let depth = match (step, angle) {
        (HoleStep::Blend, _) => 0.5 * (diameter - bore),
        (_, Some(a)) => cone_depth(diameter, bore, a),
        _ => 0.0,
    };
    HoleStage {
        hole: m.id.to_string(),
        step,
        at_exit,
        angle_deg: angle,
        diameter_mm: diameter,
        z_top_mm: z,
        depth_mm: depth,
        tool: if missing.is_none() {
            cone.map(|t| t.name.clone())
        } else {
            None
        },
        missing,
    }
}

/// How deep a cone of included angle `angle_deg` is from diameter `wide`
/// down to `narrow`, mm.
fn cone_depth(wide: f64, narrow: f64, angle_deg: f64) -> f64 {
    0.5 * (wide - narrow).max(0.0) / (0.5 * angle_deg).to_radians().tan()
}

/// Put the stages' operations into `ops`: one per tool and step, the
/// spots just before the first drilling operation (each drill of a
/// spotted hole after its spot), the countersinks and chamfers last, each
/// after the drilling of its holes.
pub fn place(ops: &mut SetupOperations, stages: &[HoleStage], lib: &ToolLibrary) {
    let made = |step: HoleStep, stages: &[HoleStage]| -> Vec<Operation> {
        let mut out: Vec<Operation> = Vec::new();
        for s in stages.iter().filter(|s| s.step == step) {
            let Some(t) = s
                .tool
                .as_deref()
                .and_then(|n| lib.tools.iter().find(|t| t.name == n))
            else {
                continue;
            };
            let op = match out.iter_mut().find(|o| o.tool == t.name) {
                Some(o) => o,
                None => {
                    out.push(stage_operation(t, step, s));
                    out.last_mut().expect("just pushed")
                }
            };
            op.z_top_mm = op.z_top_mm.max(s.z_top_mm);
            op.z_bottom_mm = op.z_bottom_mm.min(s.z_top_mm - s.depth_mm);
            op.area_mm2 += std::f64::consts::FRAC_PI_4 * s.diameter_mm.powi(2);
            op.time_min += s.depth_mm / t.feed_mm_min();
            op.holes.push(s.hole.clone());
        }
        out
    };
    // Spots: one operation per spot drill and group of drilling
    // operations waiting for the same (holes entered at one level), just
    // before the first of them; each of them then waits for its spot.
    let spotted: Vec<&HoleStage> = stages
        .iter()
        .filter(|s| s.step == HoleStep::Spot && s.tool.is_some())
        .collect();
    let spotted_holes: Vec<&str> = spotted.iter().map(|s| s.hole.as_str()).collect();
    loop {
        // A drilling operation of spotted holes not yet after its spot.
        let waiting = |all: &[Operation], o: &Operation| {
            drills_bore_of(o, &spotted_holes)
                && !o
                    .after
                    .iter()
                    .any(|&a| all[a - 1].drill == Some(DrillKind::Spot))
        };
        let all = &ops.operations;
        let Some(first) = all.iter().position(|o| waiting(all, o)) else {
            break;
        };
        let level = all[first].after.clone();
        let group: Vec<usize> = (first..all.len())
            .filter(|&i| waiting(all, &all[i]) && all[i].after == level)
            .collect();
        let holes: Vec<String> = group
            .iter()
            .flat_map(|&i| ops.operations[i].holes.clone())
            .collect();
        let ours: Vec<HoleStage> = spotted
            .iter()
            .filter(|s| holes.iter().any(|h| same_hole(h, &s.hole)))
            .map(|s| (*s).clone())
            .collect();
        let mut new = made(HoleStep::Spot, &ours);
        for op in &mut new {
            op.after = level.clone();
        }
        let n = new.len();
        insert(&mut ops.operations, first, new);
        for &i in &group {
            let o = &mut ops.operations[i + n];
            o.after.extend((first + 1)..=(first + n));
            o.after.sort_unstable();
        }
        if n == 0 {
            // No spot drill for these: nothing waits.
            break;
        }
    }
    let drills_of = |ops: &[Operation], holes: &[String]| -> Vec<usize> {
        let holes: Vec<&str> = holes.iter().map(String::as_str).collect();
        ops.iter()
            .filter(|o| drills_bore_of(o, &holes))
            .map(|o| o.step)
            .collect()
    };
    for step in [HoleStep::Countersink, HoleStep::Chamfer] {
        for mut op in made(step, stages) {
            op.after = drills_of(&ops.operations, &op.holes);
            op.step = ops.operations.len() + 1;
            ops.operations.push(op);
        }
    }
    crate::operations::recount(ops);
}

/// Whether `o` drills (or mills down) a bore of one of `holes`, as opposed
/// to a stage of theirs.
fn drills_bore_of(o: &Operation, holes: &[&str]) -> bool {
    o.stage == Stage::Drill
        && o.drill.is_some_and(|d| !d.is_stage())
        && o.holes
            .iter()
            .any(|h| holes.iter().any(|x| same_hole(h, x)))
}

/// Site id `site` (`M4.2`) belongs to hole `hole` (`M4`).
fn same_hole(site: &str, hole: &str) -> bool {
    site == hole || site.strip_prefix(hole).is_some_and(|r| r.starts_with('.'))
}

/// Insert `new` (their `after` in the old numbering) at position `at`,
/// renumbering every step after it and every reference to one.
fn insert(ops: &mut Vec<Operation>, at: usize, new: Vec<Operation>) {
    let n = new.len();
    let shift = |s: usize| if s > at { s + n } else { s };
    for o in ops.iter_mut() {
        o.step = shift(o.step);
        for a in &mut o.after {
            *a = shift(*a);
        }
    }
    for (k, mut o) in new.into_iter().enumerate() {
        o.step = at + k + 1;
        for a in &mut o.after {
            *a = shift(*a);
        }
        ops.insert(at + k, o);
    }
}

impl DrillKind {
    /// A hole's stage other than a bore (spot, countersink, chamfer).
    pub fn is_stage(self) -> bool {
        matches!(
            self,
            DrillKind::Spot | DrillKind::Countersink | DrillKind::Chamfer
        )
    }
}

/// An operation of tool `t` for one step of holes' stages, to be filled
/// with its holes.
fn stage_operation(t: &CuttingTool, step: HoleStep, s: &HoleStage) -> Operation {
    let kind = match step {
        HoleStep::Spot => DrillKind::Spot,
        HoleStep::Countersink => DrillKind::Countersink,
        HoleStep::Chamfer | HoleStep::Blend => DrillKind::Chamfer,
    };
    Operation {
        drill: Some(kind),
        ..Operation::empty(
            Stage::Drill,
            t,
            [s.z_top_mm, s.z_top_mm - s.depth_mm],
            Adjacency::Side,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 90° cone from Ø12 down to Ø6 is 3 mm deep; a 82° one deeper.
    #[test]
    fn a_cones_depth_follows_its_angle() {
        assert!((cone_depth(12.0, 6.0, 90.0) - 3.0).abs() < 1e-12);
        assert!(cone_depth(12.0, 6.0, 82.0) > 3.0);
        assert_eq!(cone_depth(6.0, 12.0, 90.0), 0.0);
    }
}
