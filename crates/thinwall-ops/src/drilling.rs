//! Holes to drill (Cohen et al.: holes with subtypes, one drill per
//! diameter): every hole the machining features find along the set-up's
//! tool axis whose diameter a drill of the library matches, or else that
//! an end mill can mill down a helix. Its material leaves the milling
//! layers (the cutter fields that lie within its circle over its depth)
//! and becomes one drilling operation per tool and subtype.

use crate::tools::{CuttingTool, ToolLibrary};
use serde::Serialize;
use thinwall_analysis::MachiningKind;
use thinwall_geom::{Frame, Point3, Vector3};
use thinwall_machining::MachiningFeature;

/// A drill matches a hole when their diameters differ by no more, mm.
pub const DRILL_MATCH_MM: f64 = 0.05;

/// A hole deeper than this many diameters is peck drilled.
pub const PECK_DEPTH_RATIO: f64 = 4.0;

/// How a hole is drilled.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum DrillKind {
    /// Through the part.
    Through,
    /// To a bottom, the drill's point left in it.
    Blind,
    /// Deeper than [`PECK_DEPTH_RATIO`] diameters: drilled in pecks to
    /// clear the chips.
    Peck,
    /// No drill matches: an end mill between half and
    /// [`HELICAL_MAX_SHARE`] of the hole's diameter goes down a helix
    /// ([`HELIX_RAMP_DEG`]) and takes it whole.
    Helical,
    /// A counterbore (a bore with a flat shoulder below it): an end mill
    /// of its diameter plunges (a drill's point would cone the shoulder).
    Counterbore,
    /// A spot drill marks the centre of a hole a drill makes, first.
    Spot,
    /// A countersink cutter of the cone's angle cuts the seat, after the
    /// drill.
    Countersink,
    /// A 90° countersink breaks the hole's edge, after the drill.
    Chamfer,
}

impl DrillKind {
    pub fn name(self) -> &'static str {
        match self {
            DrillKind::Through => "through",
            DrillKind::Blind => "blind",
            DrillKind::Peck => "peck",
            DrillKind::Helical => "helical",
            DrillKind::Counterbore => "counterbore",
            DrillKind::Spot => "spot",
            DrillKind::Countersink => "countersink",
            DrillKind::Chamfer => "chamfer",
        }
    }
}

/// A helically milled hole's end mill is at most this share of its
/// diameter (room to spiral), and at least half (no core left standing).
pub const HELICAL_MAX_SHARE: f64 = 0.8;

/// The helix's ramp angle, degrees.
pub const HELIX_RAMP_DEG: f64 = 3.0;

/// A hole along the set-up's axis, in the removal frame.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct HoleSite {
    /// The machining feature's id (`M…`).
    pub id: String,
    /// Its axis in the frame's (x, y), mm.
    pub centre: [f64; 2],
    pub diameter_mm: f64,
    /// Where the drill enters and the hole's bottom along up, mm.
    pub z_top_mm: f64,
    pub z_bottom_mm: f64,
    pub kind: DrillKind,
    /// The tool of the library that makes it: a matching drill, or the
    /// end mill of a helical hole; none: the layers mill it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub drill: Option<String>,
}

impl HoleSite {
    /// Whether the point (x, y) lies within its circle, with a margin for
    /// the polygon the removal made of it.
    pub fn holds(&self, p: [f64; 2], tol: f64) -> bool {
        let r = 0.5 * self.diameter_mm * 1.02 + tol;
        (p[0] - self.centre[0]).hypot(p[1] - self.centre[1]) <= r
    }
}

/// The holes of `features` the tool drills from up in `frame` (z = up),
/// each with the library's matching drill, if any: a compound hole a site
/// per bore the tool reaches from its entry (`M4.1`, `M4.2`, …).
pub fn hole_sites(
    features: &[MachiningFeature],
    frame: &Frame,
    lib: &ToolLibrary,
) -> Vec<HoleSite> {
    let drills: Vec<&CuttingTool> = lib.drills().collect();
    let mills: Vec<&CuttingTool> = lib.end_mills().collect();
    let mut out = Vec::new();
    for m in features
        .iter()
        .filter(|m| m.kind == MachiningKind::Hole && m.reachable != Some(false))
    {
        let Some(down) = entered_from_up(m, frame) else {
            continue;
        };
        let Some(c) = m.centre else {
            continue;
        };
        let d = Point3::new(c[0], c[1], c[2]) - frame.origin;
        let entry = d.dot(&frame.z);
        let top = if down { entry } else { entry + m.depth };
        let centre = [d.dot(&frame.x), d.dot(&frame.y)];
        for (id, bore) in bores_from_top(m, down) {
            if !(bore.diameter > 0.0 && bore.depth > 0.0) {
                continue;
            }
            let (kind, drill) = drill_for(&bore, m.through, &drills, &mills);
            out.push(HoleSite {
                id,
                centre,
                diameter_mm: bore.diameter,
                z_top_mm: top - bore.below,
                z_bottom_mm: top - bore.below - bore.depth,
                kind,
                drill: drill.map(|t| t.name.clone()),
            });
        }
    }
    out
}

/// Whether the tool along `frame.z` enters hole `m` from up: `Some(true)`
/// when it goes down into it (the hole's direction −up), `Some(false)` for
/// a through hole entered from below (drilled from up all the same, from
/// its other end), none otherwise.
pub(crate) fn entered_from_up(m: &MachiningFeature, frame: &Frame) -> Option<bool> {
    let dir = Vector3::new(m.direction[0], m.direction[1], m.direction[2]);
    let along = dir.dot(&frame.z);
    if along < -1.0 + 1e-6 {
        Some(true)
    } else if m.through && along > 1.0 - 1e-6 {
        Some(false)
    } else {
        None
    }
}

/// One bore of a hole as the tool meets it from the top: its diameter,
/// depth, how far below the top it starts, and whether it reaches the
/// hole's far end, mm.
struct TopBore {
    diameter: f64,
    depth: f64,
    below: f64,
    last: bool,
    /// A narrower bore follows: its bottom is a flat shoulder.
    shoulder: bool,
}

/// The bores a tool from the top reaches, each with its site id: a plain
/// hole whole (its id); a compound hole's bores from the top down while
/// none is wider than one above it (a counterbore at the far end is
/// another set-up's), `M4.1`, `M4.2`, ….
fn bores_from_top(m: &MachiningFeature, down: bool) -> Vec<(String, TopBore)> {
    let whole = || {
        vec![(
            m.id.to_string(),
            TopBore {
                diameter: m.width,
                depth: m.depth,
                below: 0.0,
                last: true,
                shoulder: false,
            },
        )]
    };
    let Some(form) = m.hole.as_ref().filter(|h| h.bores.len() > 1) else {
        return whole();
    };
    let mut bores: Vec<(usize, &thinwall_machining::Bore)> =
        form.bores.iter().enumerate().collect();
    if !down {
        bores.reverse();
    }
    let n = bores.len();
    let (mut below, mut narrowest) = (0.0, f64::INFINITY);
    let mut out = Vec::new();
    for (k, &(i, b)) in bores.iter().enumerate() {
        if b.diameter > narrowest + DRILL_MATCH_MM {
            break;
        }
        narrowest = narrowest.min(b.diameter);
        let next = bores.get(k + 1).map(|(_, n)| n.diameter);
        out.push((
            format!("{}.{}", m.id, i + 1),
            TopBore {
                diameter: b.diameter,
                depth: b.depth,
                below,
                last: k + 1 == n,
                shoulder: next.is_some_and(|d| d < b.diameter - DRILL_MATCH_MM),
            },
        ));
        below += b.depth;
    }
    out
}

/// How a bore is made: the library's matching drill (peck drilled when
/// its bottom lies deeper than [`PECK_DEPTH_RATIO`] diameters), or else
/// the largest end mill that spirals down it whole, or nothing.
fn drill_for<'t>(
    bore: &TopBore,
    through: bool,
    drills: &[&'t CuttingTool],
    mills: &[&'t CuttingTool],
) -> (DrillKind, Option<&'t CuttingTool>) {
    let diameter = bore.diameter;
    // Exactly 4 Ø deep is not deeper, whatever the rounding.
    let kind = if bore.below + bore.depth > PECK_DEPTH_RATIO * diameter * (1.0 + 1e-9) {
        DrillKind::Peck
    } else if through && bore.last {
        DrillKind::Through
    } else {
        DrillKind::Blind
    };
    if bore.shoulder {
        // A flat shoulder: an end mill of its diameter plunges, or a
        // narrower one spirals; never a drill's point.
        let plunge = mills
            .iter()
            .find(|t| (t.diameter_mm - diameter).abs() <= DRILL_MATCH_MM);
        let helical = mills.iter().find(|t| {
            t.diameter_mm <= HELICAL_MAX_SHARE * diameter && 2.0 * t.diameter_mm >= diameter
        });
        return match (plunge, helical) {
            (Some(t), _) => (DrillKind::Counterbore, Some(*t)),
            (None, Some(t)) => (DrillKind::Helical, Some(*t)),
            (None, None) => (DrillKind::Counterbore, None),
        };
    }
    let drill = drills
        .iter()
        .filter(|t| (t.diameter_mm - diameter).abs() <= DRILL_MATCH_MM)
        .min_by(|a, b| {
            (a.diameter_mm - diameter)
                .abs()
                .total_cmp(&(b.diameter_mm - diameter).abs())
        });
    let helical = mills
        .iter()
        .find(|t| t.diameter_mm <= HELICAL_MAX_SHARE * diameter && 2.0 * t.diameter_mm >= diameter);
    match (drill, helical) {
        (Some(t), _) => (kind, Some(*t)),
        (None, Some(t)) => (DrillKind::Helical, Some(*t)),
        (None, None) => (kind, None),
    }
}

/// Time of one hole of `kind`: its depth at the drill's feed v_f, or a
/// helix at [`HELIX_RAMP_DEG`] down that depth (depth / tan(ramp) long) at
/// the end mill's, min.
pub fn drilling_time_min(t: &CuttingTool, kind: DrillKind, depth_mm: f64) -> f64 {
    let path = match kind {
        DrillKind::Helical => depth_mm / HELIX_RAMP_DEG.to_radians().tan(),
        _ => depth_mm,
    };
    path / t.feed_mm_min()
}
