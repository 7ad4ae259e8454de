//! Reach of wall sides: a side's faces' reach added up, and why it is not
//! whole, in a planner's words ("gap to R3 is 8.0 mm, narrower than the
//! Ø12 tool").

use super::{area_rank, FaceReach, ToolPart, WHOLE_SHARE};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use thinwall_analysis::{FeatureId, PartAnalysis};
use thinwall_recognize::Recognition;

/// Tolerance on facing planes for a gap, degrees.
const FACING_DEG: f64 = 1.0;

/// The reach of one side of a wall.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SideReach {
    /// Reached area / the side's area.
    pub fraction: f64,
    pub tool_diameter: f64,
    /// Features in the way, the worst first.
    pub blocked_by: Vec<FeatureId>,
    /// Why not whole (none when whole).
    pub reason: Option<String>,
}

/// Each wall's two sides, from the faces' reach.
pub fn wall_sides(
    a: &PartAnalysis,
    rec: &Recognition,
    faces: &[FaceReach],
    tool_diameter: f64,
) -> BTreeMap<FeatureId, [SideReach; 2]> {
    let by_face: BTreeMap<(u32, u64), &FaceReach> =
        faces.iter().map(|f| ((f.body, f.face), f)).collect();
    // Each face's features, walls first.
    let mut owner: BTreeMap<(u32, u64), Vec<FeatureId>> = BTreeMap::new();
    for wall_first in [true, false] {
        for f in rec
            .features
            .iter()
            .filter(|f| f.kind.is_wall() == wall_first)
        {
            for &s in &f.faces {
                owner.entry((f.body, s)).or_default().push(f.id);
            }
        }
    }
    let mut out = BTreeMap::new();
    for f in &rec.features {
        let Some(sides) = &f.sides else { continue };
        let judge = |side: &Vec<u64>| -> SideReach {
            let mut area = 0.0;
            let mut reached = 0.0;
            // Per feature in the way: mm², the tool part, (side face, its face) pairs.
            type Lost = (f64, ToolPart, Vec<(u64, u64)>);
            let mut lost: BTreeMap<FeatureId, Lost> = BTreeMap::new();
            for s in side {
                let Some(r) = by_face.get(&(f.body, *s)) else {
                    continue;
                };
                area += r.area_mm2;
                reached += r.fraction * r.area_mm2;
                for b in &r.blocked_by {
                    let Some(ids) = owner.get(&(b.body, b.face)) else {
                        continue;
                    };
                    let Some(&id) = ids.iter().find(|&&id| id != f.id).or(ids.first()) else {
                        continue;
                    };
                    let e = lost.entry(id).or_insert((0.0, b.by, Vec::new()));
                    e.0 += b.unreachable_mm2;
                    e.2.push((*s, b.face));
                }
            }
            let fraction = if area > 0.0 { reached / area } else { 1.0 };
            let mut worst: Vec<(FeatureId, Lost)> = lost.into_iter().collect();
            worst.sort_by(|x, y| {
                area_rank(y.1 .0)
                    .cmp(&area_rank(x.1 .0))
                    .then(x.0.cmp(&y.0))
            });
            let whole = fraction >= 1.0 - WHOLE_SHARE;
            let reason = (!whole).then(|| {
                let head = format!(
                    "{:.0} % reached by the Ø{} tool",
                    100.0 * fraction,
                    tool_diameter
                );
                match worst.first() {
                    Some((id, (_, by, pairs))) => {
                        let narrowest = pairs
                            .iter()
                            .filter_map(|&(s, b)| gap(a, f.body, s, b))
                            .min_by(f64::total_cmp);
                        let why = match narrowest {
                            _ if *id == f.id && *by == ToolPart::Holder => format!(
                                "the holder meets {id}'s own top: the side is taller than the cutting length"
                            ),
                            Some(g) if g < tool_diameter => {
                                format!("gap to {id} is {g:.1} mm, narrower than the tool")
                            }
                            _ if *by == ToolPart::Holder => format!("{id} is in the holder's way"),
                            _ => format!("{id} is in the tool's way"),
                        };
                        format!("{head}: {why}")
                    }
                    None if fraction <= 0.0 => format!("{head}: turned away from the tool axis"),
                    None => head,
                }
            });
            SideReach {
                fraction,
                tool_diameter,
                blocked_by: if whole {
                    Vec::new()
                } else {
                    worst.iter().map(|w| w.0).collect()
                },
                reason,
            }
        };
        out.insert(f.id, [judge(&sides[0]), judge(&sides[1])]);
    }
    out
}

/// The distance between two planar faces facing each other, mm.
fn gap(a: &PartAnalysis, body: u32, side: u64, blocker: u64) -> Option<f64> {
    let part = a.part();
    let find = |s: u64| {
        part.face_ids()
            .find(|&f| part.face(f).step_id == s && part.face(f).body.0 == body)
    };
    let (p, q) = (a.planar(find(side)?)?, a.planar(find(blocker)?)?);
    let (n, m) = (p.normal(), q.normal());
    if n.dot(&m) > -FACING_DEG.to_radians().cos() {
        return None;
    }
    let d = (q.frame.origin - p.frame.origin).dot(&n);
    (d > 0.0).then_some(d)
}
