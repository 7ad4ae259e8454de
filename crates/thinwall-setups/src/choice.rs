//! Choosing the set-up (issue 37): among the directions the part's planar
//! faces face (their outward normals, the largest by area), the up from
//! which a tool reaches the most of stock − part, estimated on a height
//! map of the part's mesh ([`crate::heights`]). A pocketed plate is
//! machined from the side its pockets open to; a frame pocketed from both
//! sides from the side with more to take, the other after it. The
//! directions come from the part's own faces, so turning the part turns
//! the choice with it.

use serde::Serialize;
use thinwall_analysis::PartAnalysis;
use thinwall_geom::tolerance::NEAR_PARALLEL_EPS;
use thinwall_geom::Vector3;
use thinwall_removal::Removal;

/// Candidate ups tried, at most (the directions of the most face area).
pub const MOST_CANDIDATES: usize = 6;

/// One up tried.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct UpCandidate {
    /// Unit, in the part's coordinates.
    pub up: [f64; 3],
    /// Area of the planar faces facing it, mm².
    pub facing_area_mm2: f64,
    /// What a tool along it reaches of stock − part, mm³, on the height
    /// map ([`crate::heights::SQUARES`] squares along the stock's longer
    /// side).
    pub reachable_mm3: Option<f64>,
    /// What it leaves under the part, mm³, likewise.
    pub out_of_reach_mm3: Option<f64>,
    /// The stock's volume along it, mm³.
    #[serde(skip)]
    pub stock_mm3: f64,
    /// Why the exact removal refused the part along it (`removal.<code>`),
    /// when it was tried.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub refused: Option<String>,
}

/// Directions closer than this (cosine of 5°) are one set-up: a face
/// drafted a degree off the block's side adds no set-up of its own.
pub const SAME_SETUP_COS: f64 = 0.996_194_698_091_745_5;

/// The directions the planar faces face, with their area, most area
/// first (directions within `NEAR_PARALLEL_EPS` are one; then one within
/// 5° of a direction with more area joins it).
fn directions(a: &PartAnalysis) -> Vec<(Vector3, f64)> {
    let mut dirs: Vec<(Vector3, f64)> = Vec::new();
    for f in a.part().face_ids() {
        let p = a.props(f);
        let Some(n) = p.normal else { continue };
        match dirs
            .iter_mut()
            .find(|(d, _)| d.dot(&n) > 1.0 - NEAR_PARALLEL_EPS)
        {
            Some(d) => d.1 += p.area,
            None => dirs.push((n, p.area)),
        }
    }
    dirs.sort_by(|x, y| y.1.total_cmp(&x.1));
    let mut merged: Vec<(Vector3, f64)> = Vec::new();
    for (d, area) in dirs {
        match merged.iter_mut().find(|(m, _)| m.dot(&d) > SAME_SETUP_COS) {
            Some(m) => m.1 += area,
            None => merged.push((d, area)),
        }
    }
    merged
}

/// The removal along `up` (refused: why), checked.
pub(crate) fn removal_along(a: &PartAnalysis, up: Vector3) -> Result<Removal, String> {
    // A direction the boolean library fails in (geo's i_overlay 4.5
    // panics on some inputs: the ledger) is refused, not the end of the
    // choice.
    let removal = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        crate::turn::removals_along(a, &[up])
    }));
    match removal {
        Err(panic) => Err(format!("internal: {}", panic_text(&panic))),
        Ok(Err(e)) => Err(format!("removal.{}: {e}", e.code())),
        Ok(Ok(mut r)) => Ok(r.remove(0)),
    }
}

/// A direction for the report: components within 1e-12 of 0 are 0 (no
/// `-0.000` from a normal's rounding).
pub fn clean(v: &Vector3) -> [f64; 3] {
    let c = |x: f64| if x.abs() < 1e-12 { 0.0 } else { x };
    [c(v.x), c(v.y), c(v.z)]
}

/// `up` scored on its height map (the part's volume `part_mm3`).
fn scored(a: &PartAnalysis, up: Vector3, area: f64, part_mm3: f64) -> UpCandidate {
    let map = crate::heights::HeightMap::along(a, up);
    let reachable = map.reachable_mm3();
    UpCandidate {
        up: clean(&up),
        facing_area_mm2: area,
        reachable_mm3: Some(reachable),
        out_of_reach_mm3: Some((map.stock_mm3() - part_mm3 - reachable).max(0.0)),
        stock_mm3: map.stock_mm3(),
        refused: None,
    }
}

/// The candidate ups, best first: the most reachable material (on their
/// height maps), then the most face area facing it.
pub fn up_candidates(a: &PartAnalysis) -> Vec<UpCandidate> {
    let size = a.bounding_box().diagonal();
    let part_mm3 = crate::heights::mesh_volume(a);
    let dirs: Vec<(Vector3, f64)> = directions(a).into_iter().take(MOST_CANDIDATES).collect();
    let mut out = a
        .work()
        .map(&dirs, |&(up, area)| scored(a, up, area, part_mm3));
    // Equal to rounding: then the larger face down on the table is the
    // better set-up (the proposal compares near ones exactly).
    let tol = 1e-6 * size.powi(3);
    out.sort_by(|x, y| {
        let (rx, ry) = (
            x.reachable_mm3.unwrap_or(-1.0),
            y.reachable_mm3.unwrap_or(-1.0),
        );
        if (rx - ry).abs() > tol {
            ry.total_cmp(&rx)
        } else {
            y.facing_area_mm2.total_cmp(&x.facing_area_mm2)
        }
    });
    out
}

/// A panic's message.
fn panic_text(panic: &Box<dyn std::any::Any + Send>) -> String {
    panic
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| panic.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "a panic".to_string())
}
