//! Finishing by the part's radii (issue 38; CAMWorks and NX feature-based
//! machining give a pocket its corner radius and floor fillet and choose
//! its finishing tools from them; Harik et al., cited by Popma §8.2, choose
//! "tool diameter and corner radius based on radii in the part geometry").
//!
//! A pocket, slot, step or passage the set-up's tool enters along up,
//! whose corners are rounded (radius R) or whose floor meets its walls in
//! a fillet (radius r), is finished by one contour per tool depth along
//! its walls, corners and floor fillet, with the end mill (flat or
//! bull-nose) that
//! - is no wider than the feature allows (2R at its corners, its floor's
//!   width: the recognizer's `largest_tool_diameter` and `tool_bound`, the
//!   one answer access gives too),
//! - has a corner radius no larger than r (a bull-nose with r forms the
//!   fillet in the contour; a smaller one contours it), and
//! - has flutes as long as the feature is deep,
//!
//! the roundest such corner first (it forms the fillet), then the widest.
//! Where no tool of the library meets all three, the walls and fillet go
//! to the widest tool that fits them and a narrower one finishes the
//! corners (a corner rest operation); what no tool finishes is a rest,
//! with the part's surface it leaves unfinished and the material standing
//! there.

use crate::operations::{Operation, SetupOperations};
use crate::rest::Adjacency;
use crate::stage::Stage;
pub use crate::stage::{RadiusFinish, RadiusRest, RestCause};
use crate::tools::{CuttingTool, ToolLibrary};
use thinwall_analysis::PartAnalysis;
use thinwall_geom::{Frame, Surface, Vector3};
use thinwall_machining::MachiningFeature;

/// Two radii or diameters closer than this are equal, mm.
pub const RADIUS_MATCH_MM: f64 = 1e-3;

/// The geometry of a feature's blends the choice needs.
struct Blends {
    /// Per corner: a concave cylinder along up.
    corners: Vec<Corner>,
    /// The floor fillets' length along the floor and area.
    fillet_length: f64,
    fillet_area: f64,
}

/// One rounded corner of a feature.
struct Corner {
    /// mm.
    radius: f64,
    /// How far it turns, rad (area / (radius · height)).
    turn: f64,
    /// Along up, mm.
    height: f64,
    /// mm².
    area: f64,
}

/// The features of `features` to finish by their radii in the set-up of
/// `a` (tool axis `frame.z`), each with its tools from `lib`.
pub fn radius_finishes(
    a: &PartAnalysis,
    features: &[MachiningFeature],
    frame: &Frame,
    lib: &ToolLibrary,
) -> Vec<RadiusFinish> {
    let mills = lib.finishing_mills();
    features
        .iter()
        .filter(|m| takes_radii(m, frame))
        .filter_map(|m| finish(a, m, frame, &mills))
        .collect()
}

/// A milled depression the tool enters along up, with a corner radius or
/// a floor fillet.
fn takes_radii(m: &MachiningFeature, frame: &Frame) -> bool {
    let dir = Vector3::new(m.direction[0], m.direction[1], m.direction[2]);
    thinwall_machining::takes_blends(m.kind)
        && m.reachable != Some(false)
        && dir.dot(&frame.z) < -1.0 + 1e-6
        && (m.corner_radius.is_some() || m.floor_fillet.is_some())
        && m.largest_tool_diameter.is_some()
}

fn finish(
    a: &PartAnalysis,
    m: &MachiningFeature,
    frame: &Frame,
    mills: &[&CuttingTool],
) -> Option<RadiusFinish> {
    let largest = m.largest_tool_diameter?;
    let faces: Vec<_> = m
        .faces
        .iter()
        .filter_map(|&s| a.part().face_by_step_id(s))
        .collect();
    let (lo, hi) = a.extent(&faces, &frame.z);
    let base = frame.origin.coords.dot(&frame.z);
    let blends = blends(a, m, &frame.z);
    let walls_area: f64 = m
        .side_faces
        .iter()
        .filter_map(|&s| a.part().face_by_step_id(s))
        .map(|f| a.props(f).area)
        .sum();
    let depth = m.depth.max(0.0);
    let bounded_by = m.tool_bound?;
    let mut f = RadiusFinish {
        feature: m.id.to_string(),
        corner_radius_mm: m.corner_radius,
        floor_fillet_mm: m.floor_fillet,
        depth_mm: depth,
        largest_tool_mm: largest,
        bounded_by,
        walls_tool_mm: walls_bound(a, m).unwrap_or(largest).max(largest),
        walls: None,
        corners: None,
        rest: Vec::new(),
        z_top_mm: hi - base,
        z_bottom_mm: lo - base,
        area_mm2: walls_area,
        contour_mm: if depth > 0.0 { walls_area / depth } else { 0.0 },
        corner_area_mm2: blends.corners.iter().map(|c| c.area).sum(),
        corner_arc_mm: blends.corners.iter().map(|c| c.radius * c.turn).sum(),
        fillet_length_mm: blends.fillet_length,
    };
    choose(&mut f, &blends, mills);
    Some(f)
}

/// Whether tool `t` fits: its corner radius within the fillet, its
/// flutes as deep as the feature (`deep`), and its diameter within the
/// feature's bound (`corners`: the one answer, corners included) or its
/// walls' alone (the floor's width).
fn fits(t: &CuttingTool, f: &RadiusFinish, corners: bool, deep: bool) -> bool {
    let fillet = f
        .floor_fillet_mm
        .is_none_or(|r| t.corner_radius_mm <= r + RADIUS_MATCH_MM);
    let depth = !deep || t.cutting_length_mm >= f.depth_mm - RADIUS_MATCH_MM;
    let bound = if corners {
        f.largest_tool_mm
    } else {
        f.walls_tool_mm
    };
    fillet && depth && t.diameter_mm <= bound + RADIUS_MATCH_MM
}

/// The best of `mills` meeting `ok`: the roundest corner (it forms the
/// fillet), then the widest.
fn best<'t>(
    mills: &[&'t CuttingTool],
    ok: impl Fn(&CuttingTool) -> bool,
) -> Option<&'t CuttingTool> {
    mills.iter().copied().filter(|t| ok(t)).max_by(|a, b| {
        a.corner_radius_mm
            .total_cmp(&b.corner_radius_mm)
            .then(a.diameter_mm.total_cmp(&b.diameter_mm))
    })
}

/// The walls' and corners' tools of `f`, and its rests.
fn choose(f: &mut RadiusFinish, b: &Blends, mills: &[&CuttingTool]) {
    if let Some(t) = best(mills, |t| fits(t, f, true, true)) {
        f.walls = Some(t.name.clone());
        f.corners = Some(t.name.clone());
        return;
    }
    // The walls and fillet first: deep enough, then any that fits them.
    let walls = best(mills, |t| fits(t, f, false, true))
        .or_else(|| best(mills, |t| fits(t, f, false, false)))
        .or_else(|| {
            // No corner radius small enough: the least round tool.
            mills
                .iter()
                .copied()
                .filter(|t| t.cutting_length_mm >= f.depth_mm - RADIUS_MATCH_MM)
                .min_by(|a, b| a.corner_radius_mm.total_cmp(&b.corner_radius_mm))
        });
    f.walls = walls.map(|t| t.name.clone());
    if let Some(t) = walls {
        if let Some(r) = f
            .floor_fillet_mm
            .filter(|r| t.corner_radius_mm > r + RADIUS_MATCH_MM)
        {
            f.rest.push(RadiusRest {
                cause: RestCause::FloorFillet,
                tool: Some(t.name.clone()),
                area_mm2: b.fillet_area,
                volume_mm3: Some(
                    b.fillet_length
                        * (t.corner_radius_mm.powi(2) - r * r)
                        * (1.0 - std::f64::consts::FRAC_PI_4),
                ),
            });
        }
        if t.cutting_length_mm < f.depth_mm - RADIUS_MATCH_MM {
            let share = (f.depth_mm - t.cutting_length_mm) / f.depth_mm;
            f.rest.push(RadiusRest {
                cause: RestCause::Depth,
                tool: Some(t.name.clone()),
                area_mm2: f.area_mm2 * share,
                volume_mm3: None,
            });
        }
    }
    // The corners: a narrower tool, deep enough where one is.
    let corners = best(mills, |t| fits(t, f, true, true));
    f.corners = corners.map(|t| t.name.clone());
    if corners.is_none() {
        // What the walls' tool (or, without one, the narrowest of the
        // library) leaves in every corner narrower than its radius.
        let by = walls.or_else(|| mills.last().copied());
        let rho = by.map_or(0.0, |t| 0.5 * t.diameter_mm);
        let left: Vec<&Corner> = b
            .corners
            .iter()
            .filter(|c| c.radius < rho - RADIUS_MATCH_MM)
            .collect();
        if !left.is_empty() {
            f.rest.push(RadiusRest {
                cause: RestCause::Corner,
                tool: by.map(|t| t.name.clone()),
                area_mm2: left.iter().map(|c| c.area).sum(),
                volume_mm3: Some(
                    left.iter()
                        .map(|c| corner_rest_mm2(rho, c.radius, c.turn) * c.height)
                        .sum(),
                ),
            });
        }
    }
}

/// Append to `ops` one finishing operation per tool of `finishes` (the
/// walls' tools, then the narrower corners' tools), each after every
/// milling operation in its features' depth, and count the tool changes
/// and the time they add.
pub fn append(ops: &mut SetupOperations, finishes: &[RadiusFinish], lib: &ToolLibrary) {
    let mut drafts: Vec<Operation> = Vec::new();
    for f in finishes {
        let jobs = [(f.walls.as_deref(), false), (f.corners.as_deref(), true)];
        for (name, corners) in jobs {
            let Some(t) = name.and_then(|n| lib.tools.iter().find(|t| t.name == n)) else {
                continue;
            };
            // The walls' tool finishes the corners too where it fits them.
            if corners && f.walls.as_deref() == Some(t.name.as_str()) {
                continue;
            }
            let (area, time) = contour(f, t, corners);
            let op = match drafts
                .iter_mut()
                .find(|o| o.tool == t.name && o.corners == corners)
            {
                Some(o) => o,
                None => {
                    drafts.push(Operation {
                        corners,
                        ..Operation::empty(
                            Stage::FinishRadii,
                            t,
                            [f.z_top_mm, f.z_bottom_mm],
                            Adjacency::SideAndBottom,
                        )
                    });
                    drafts.last_mut().expect("just pushed")
                }
            };
            op.z_top_mm = op.z_top_mm.max(f.z_top_mm);
            op.z_bottom_mm = op.z_bottom_mm.min(f.z_bottom_mm);
            op.area_mm2 += area;
            op.time_min += time;
            if !op.finishes.contains(&f.feature) {
                op.finishes.push(f.feature.clone());
            }
        }
    }
    // The widest first; corners after walls.
    drafts.sort_by(|a, b| {
        a.corners
            .cmp(&b.corners)
            .then(b.diameter_mm.total_cmp(&a.diameter_mm))
    });
    for mut op in drafts {
        op.after = ops
            .operations
            .iter()
            .filter(|o| o.stage != Stage::Drill && o.stage != Stage::FinishRadii)
            .filter(|o| o.z_bottom_mm < op.z_top_mm && o.z_top_mm > op.z_bottom_mm)
            .map(|o| o.step)
            .collect();
        op.step = ops.operations.len() + 1;
        ops.operations.push(op);
    }
    crate::operations::recount(ops);
}

/// The surface a tool finishes in `f` and the time its contours take:
/// the walls and fillet (one contour per a_p down the walls, and where its
/// corner radius is below the fillet's, one per finishing stepover round
/// the fillet's arc), or the corners alone, min.
fn contour(f: &RadiusFinish, t: &CuttingTool, corners: bool) -> (f64, f64) {
    let passes = (f.depth_mm / t.axial_depth_mm).ceil().max(1.0);
    if corners {
        return (
            f.corner_area_mm2,
            f.corner_arc_mm * passes / t.feed_mm_min(),
        );
    }
    let round = f.floor_fillet_mm.map_or(0.0, |r| {
        if t.corner_radius_mm < r - RADIUS_MATCH_MM {
            (std::f64::consts::FRAC_PI_2 * r / t.finish_radial_depth_mm).ceil()
        } else {
            0.0
        }
    });
    let path = f.contour_mm * passes + f.fillet_length_mm * round;
    (f.area_mm2, path / t.feed_mm_min())
}

/// The area a tool of radius `rho` leaves in a corner of radius `r`
/// turning by `turn` (rad; a right angle's corner turns by π/2): between
/// the two arcs, (ρ² − r²)(tan(θ/2) − θ/2), mm².
pub fn corner_rest_mm2(rho: f64, r: f64, turn: f64) -> f64 {
    if rho <= r {
        return 0.0;
    }
    let half = 0.5 * turn.clamp(0.0, std::f64::consts::PI - 1e-9);
    (rho * rho - r * r) * (half.tan() - half)
}

/// The widest tool the floor of `m` takes, corners aside: its floors'
/// widest circle, and the fillet on either side, mm; none without floors.
fn walls_bound(a: &PartAnalysis, m: &MachiningFeature) -> Option<f64> {
    let floors: Vec<geo::Polygon<f64>> = m
        .bottom_faces
        .iter()
        .filter_map(|&s| a.part().face_by_step_id(s))
        .filter_map(|f| a.polygon(f))
        .flat_map(|p| p.0)
        .collect();
    if floors.is_empty() {
        return None;
    }
    let region = geo::MultiPolygon::new(floors);
    let r = thinwall_analysis::polygon::inscribed_radius(&region);
    Some(2.0 * (r + m.floor_fillet.unwrap_or(0.0)))
}

/// The corners (concave cylinders along `up`) and floor fillets among
/// `m`'s blends.
fn blends(a: &PartAnalysis, m: &MachiningFeature, up: &Vector3) -> Blends {
    let mut b = Blends {
        corners: Vec::new(),
        fillet_length: 0.0,
        fillet_area: 0.0,
    };
    for &s in &m.blend_faces {
        let Some(f) = a.part().face_by_step_id(s) else {
            continue;
        };
        let area = a.props(f).area;
        match a.part().face(f).surface {
            Surface::Cylinder { frame, radius } if frame.z.dot(up).abs() > 1.0 - 1e-6 => {
                let (lo, hi) = a.extent(&[f], up);
                let h = hi - lo;
                if h > 0.0 && radius > 0.0 {
                    b.corners.push(Corner {
                        radius,
                        turn: area / (radius * h),
                        height: h,
                        area,
                    });
                }
            }
            Surface::Cylinder { radius, .. } => {
                b.fillet_area += area;
                b.fillet_length += area / (radius * std::f64::consts::FRAC_PI_2);
            }
            Surface::Torus { minor_radius, .. } => {
                b.fillet_area += area;
                b.fillet_length += area / (minor_radius * std::f64::consts::FRAC_PI_2);
            }
            _ => b.fillet_area += area,
        }
    }
    b
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A right-angled corner of radius 3 left by a Ø20 tool: (10² − 3²)
    /// (1 − π/4); no rest from a tool as narrow as the corner.
    #[test]
    fn a_corner_keeps_what_a_wider_tool_cannot_reach() {
        let right = std::f64::consts::FRAC_PI_2;
        let want = (100.0 - 9.0) * (1.0 - std::f64::consts::FRAC_PI_4);
        assert!((corner_rest_mm2(10.0, 3.0, right) - want).abs() < 1e-12);
        assert_eq!(corner_rest_mm2(3.0, 3.0, right), 0.0);
        assert_eq!(corner_rest_mm2(2.0, 3.0, right), 0.0);
    }
}
