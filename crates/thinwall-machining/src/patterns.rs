//! Hole patterns: equal holes (same diameter, depth, profile, through or
//! blind, parallel axes, entering at one level) whose centres lie on a line
//! at equal pitch or on a circle at equal angles. Real parts have them
//! (bolt circles, rows of rivet holes); a planner drills them as one
//! operation.
//!
//! Found greedily: among the holes of one kind not yet in a pattern, the
//! line through two centres or the circle through three that holds the
//! most centres at equal spacing (three at least; on a circle, four, or
//! three at 120°) becomes a pattern, and so on until none is left. Lines
//! are tried before circles.

use crate::MachiningFeature;
use serde::{Deserialize, Serialize};
use thinwall_analysis::{MachiningId, MachiningKind, PartAnalysis};
use thinwall_geom::{Point3, Vector3};

/// Holes whose axes are within this of parallel are one family (cosine).
const PARALLEL_COS: f64 = 1.0 - 1e-6;
/// The fewest holes that make a pattern.
const MIN_HOLES: usize = 3;

/// The layout of a pattern.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "layout", rename_all = "snake_case")]
pub enum Layout {
    /// Centres on a line, `pitch` mm apart, from the first along `along`.
    Linear { along: [f64; 3], pitch: f64 },
    /// Centres on a circle about `centre` (on the entry level), `radius`
    /// mm, `step_deg` degrees apart.
    Circular {
        centre: [f64; 3],
        radius: f64,
        step_deg: f64,
    },
}

/// Equal holes in a row or on a circle.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct HolePattern {
    /// `HP1`, `HP2`, … in the order of their first hole.
    pub id: String,
    /// The holes, in order along the line or around the circle.
    pub holes: Vec<MachiningId>,
    /// Their common diameter, mm.
    pub diameter: f64,
    #[serde(flatten)]
    pub layout: Layout,
}

/// One hole: its feature, entry centre, axis.
struct Hole<'m> {
    m: &'m MachiningFeature,
    centre: Point3,
    axis: Vector3,
}

/// The hole patterns among `features`.
pub fn hole_patterns(a: &PartAnalysis, features: &[MachiningFeature]) -> Vec<HolePattern> {
    patterns_within(features, a.tol().feature * 100.0)
}

/// The hole patterns, positions alike within `tol` mm.
fn patterns_within(features: &[MachiningFeature], tol: f64) -> Vec<HolePattern> {
    let holes: Vec<Hole> = features
        .iter()
        .filter(|m| m.kind == MachiningKind::Hole)
        .filter_map(|m| {
            let c = m.centre?;
            Some(Hole {
                m,
                centre: Point3::new(c[0], c[1], c[2]),
                axis: Vector3::new(m.direction[0], m.direction[1], m.direction[2]),
            })
        })
        .collect();
    let mut out = Vec::new();
    for family in families(&holes, tol) {
        out.extend(patterns_in(&family, tol));
    }
    out.sort_by_key(|p| p.holes.first().map(|h| h.0));
    for (i, p) in out.iter_mut().enumerate() {
        p.id = format!("HP{}", i + 1);
    }
    out
}

/// Holes alike (kind, profile, through, diameter, depth) with parallel
/// axes entering at one level.
fn families<'h, 'm>(holes: &'h [Hole<'m>], tol: f64) -> Vec<Vec<&'h Hole<'m>>> {
    let mut out: Vec<Vec<&Hole>> = Vec::new();
    for h in holes {
        let alike = |g: &&Hole| {
            g.m.profile == h.m.profile
                && g.m.through == h.m.through
                && (g.m.length - h.m.length).abs() < tol
                && (g.m.depth - h.m.depth).abs() < tol
                && g.axis.dot(&h.axis) > PARALLEL_COS
                && (g.centre - h.centre).dot(&h.axis).abs() < tol
        };
        match out.iter_mut().find(|f| alike(&f[0])) {
            Some(f) => f.push(h),
            None => out.push(vec![h]),
        }
    }
    out.retain(|f| f.len() >= MIN_HOLES);
    out
}

/// Greedy patterns in one family (module docs).
fn patterns_in(family: &[&Hole], tol: f64) -> Vec<HolePattern> {
    let mut left: Vec<&Hole> = family.to_vec();
    let mut out = Vec::new();
    while left.len() >= MIN_HOLES {
        let Some((members, layout)) = best_line(&left, tol).or_else(|| best_circle(&left, tol))
        else {
            break;
        };
        out.push(HolePattern {
            id: String::new(),
            holes: members.iter().map(|&k| left[k].m.id).collect(),
            diameter: left[members[0]].m.length,
            layout,
        });
        left = left
            .into_iter()
            .enumerate()
            .filter(|(k, _)| !members.contains(k))
            .map(|(_, h)| h)
            .collect();
    }
    out
}

/// Equal steps between sorted positions (all within `tol` of the first).
fn equal_steps(sorted: &[f64], tol: f64) -> Option<f64> {
    let step = sorted.get(1)? - sorted[0];
    (step > tol && sorted.windows(2).all(|w| (w[1] - w[0] - step).abs() < tol)).then_some(step)
}

/// The line through two centres holding the most centres at equal pitch.
fn best_line(left: &[&Hole], tol: f64) -> Option<(Vec<usize>, Layout)> {
    let mut best: Option<(Vec<usize>, Layout)> = None;
    for i in 0..left.len() {
        for j in i + 1..left.len() {
            let Some(along) = (left[j].centre - left[i].centre).try_normalize(tol) else {
                continue;
            };
            let mut on: Vec<(f64, usize)> = (0..left.len())
                .filter_map(|k| {
                    let d = left[k].centre - left[i].centre;
                    let t = d.dot(&along);
                    ((d - along * t).norm() < tol).then_some((t, k))
                })
                .collect();
            on.sort_by(|x, y| x.0.total_cmp(&y.0));
            let ts: Vec<f64> = on.iter().map(|x| x.0).collect();
            let bigger = best.as_ref().is_none_or(|b| on.len() > b.0.len());
            if on.len() >= MIN_HOLES && bigger {
                if let Some(pitch) = equal_steps(&ts, tol) {
                    let along = if ts[0] <= ts[ts.len() - 1] {
                        along
                    } else {
                        -along
                    };
                    best = Some((
                        on.iter().map(|x| x.1).collect(),
                        Layout::Linear {
                            along: [along.x, along.y, along.z],
                            pitch,
                        },
                    ));
                }
            }
        }
    }
    best
}

/// The circle through three centres holding the most centres at equal
/// angles. Circles through every triple are bucketed by centre and radius
/// (to `tol`), so the search is cubic in the holes, not quartic.
fn best_circle(left: &[&Hole], tol: f64) -> Option<(Vec<usize>, Layout)> {
    let axis = left[0].axis;
    let n = left.len();
    let key = |c: &Point3, r: f64| {
        let q = |v: f64| (v / (10.0 * tol)).round() as i64;
        (q(c.x), q(c.y), q(c.z), q(r))
    };
    let mut circles: std::collections::HashMap<(i64, i64, i64, i64), (Point3, f64)> =
        std::collections::HashMap::new();
    for i in 0..n {
        for j in i + 1..n {
            for k in j + 1..n {
                if let Some((c, r)) =
                    circumcircle(&left[i].centre, &left[j].centre, &left[k].centre, tol)
                {
                    circles.entry(key(&c, r)).or_insert((c, r));
                }
            }
        }
    }
    let mut best: Option<(Vec<usize>, Layout)> = None;
    let mut found: Vec<(Point3, f64)> = circles.into_values().collect();
    // The same answer whatever the map's order.
    found.sort_by(|a, b| {
        (a.0.x, a.0.y, a.0.z, a.1)
            .partial_cmp(&(b.0.x, b.0.y, b.0.z, b.1))
            .unwrap_or(std::cmp::Ordering::Equal)
    });
    for (c, r) in found {
        let on: Vec<usize> = (0..n)
            .filter(|&q| ((left[q].centre - c).norm() - r).abs() < tol)
            .collect();
        if on.len() < MIN_HOLES || best.as_ref().is_some_and(|b| b.0.len() >= on.len()) {
            continue;
        }
        let Some((order, step)) = equal_angles(left, &on, &c, &axis, r, tol) else {
            continue;
        };
        // Any three holes at the corners of an isosceles triangle lie on a
        // circle at equal angles: three make a circle only when they go
        // all the way round.
        let round = (step * 3.0 - std::f64::consts::TAU).abs() * r < tol;
        if on.len() > MIN_HOLES || round {
            best = Some((
                order,
                Layout::Circular {
                    centre: [c.x, c.y, c.z],
                    radius: r,
                    step_deg: step.to_degrees(),
                },
            ));
        }
    }
    best
}

/// The members ordered around `axis` from the widest gap, and their equal
/// angular step (radians), if the steps are equal (arc length within `tol`).
fn equal_angles(
    left: &[&Hole],
    on: &[usize],
    c: &Point3,
    axis: &Vector3,
    r: f64,
    tol: f64,
) -> Option<(Vec<usize>, f64)> {
    let d0 = left[on[0]].centre - c;
    let u = d0 / d0.norm();
    let v = axis.cross(&u);
    let mut angles: Vec<(f64, usize)> = on
        .iter()
        .map(|&q| {
            let d = left[q].centre - c;
            (
                d.dot(&v).atan2(d.dot(&u)).rem_euclid(std::f64::consts::TAU),
                q,
            )
        })
        .collect();
    angles.sort_by(|x, y| x.0.total_cmp(&y.0));
    // Start after the widest gap, so an arc reads in order.
    let m = angles.len();
    let gap = |i: usize| (angles[(i + 1) % m].0 - angles[i].0).rem_euclid(std::f64::consts::TAU);
    let widest = (0..m).max_by(|&x, &y| gap(x).total_cmp(&gap(y)))?;
    let order: Vec<(f64, usize)> = (1..=m).map(|s| angles[(widest + s) % m]).collect();
    let unwrapped: Vec<f64> = order
        .iter()
        .map(|x| (x.0 - order[0].0).rem_euclid(std::f64::consts::TAU) * r)
        .collect();
    let step = equal_steps(&unwrapped, tol)? / r;
    Some((order.iter().map(|x| x.1).collect(), step))
}

/// The circle through three points: centre and radius; none when they are
/// (nearly) on a line.
fn circumcircle(a: &Point3, b: &Point3, c: &Point3, tol: f64) -> Option<(Point3, f64)> {
    let (ab, ac) = (b - a, c - a);
    let n = ab.cross(&ac);
    let n2 = n.norm_squared();
    if n2 < tol * tol * ab.norm_squared().max(ac.norm_squared()) {
        return None;
    }
    let centre =
        a + (ac.norm_squared() * n.cross(&ab) + ab.norm_squared() * ac.cross(&n)) / (2.0 * n2);
    Some((centre, (centre - a).norm()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn circumcircle_of_a_right_triangle_is_on_its_hypotenuse() {
        let (c, r) = circumcircle(
            &Point3::new(0.0, 0.0, 0.0),
            &Point3::new(4.0, 0.0, 0.0),
            &Point3::new(0.0, 3.0, 0.0),
            1e-9,
        )
        .unwrap();
        assert!((c - Point3::new(2.0, 1.5, 0.0)).norm() < 1e-12);
        assert!((r - 2.5).abs() < 1e-12);
        assert!(circumcircle(
            &Point3::origin(),
            &Point3::new(1.0, 0.0, 0.0),
            &Point3::new(2.0, 0.0, 0.0),
            1e-9
        )
        .is_none());
    }

    fn hole(id: u32, x: f64, y: f64) -> MachiningFeature {
        MachiningFeature {
            id: MachiningId(id),
            kind: MachiningKind::Hole,
            body: 0,
            through: true,
            profile: thinwall_analysis::Profile::Circular,
            catalog: None,
            direction: [0.0, 0.0, -1.0],
            faces: vec![u64::from(id)],
            bottom_faces: vec![],
            side_faces: vec![u64::from(id)],
            island_faces: vec![],
            open_to: vec![],
            depth: 5.0,
            length: 6.0,
            width: 6.0,
            centre: Some([x, y, 10.0]),
            radii: vec![3.0],
            blend_faces: vec![],
            chamfer_faces: vec![],
            corner_radius: None,
            corner_radii: vec![],
            floor_fillet: None,
            wall_draft_deg: None,
            hole: None,
            largest_tool_diameter: Some(6.0),
            tool_bound: Some(crate::ToolBound::Bore),
            reachable: None,
            related: vec![],
        }
    }

    #[test]
    fn a_bolt_circle_and_a_row_are_found_and_stray_holes_are_not() {
        let mut holes: Vec<MachiningFeature> = (0..6)
            .map(|k| {
                let t = f64::from(k) * std::f64::consts::TAU / 6.0;
                hole(k + 1, 50.0 + 20.0 * t.cos(), 50.0 + 20.0 * t.sin())
            })
            .collect();
        holes.extend((0..4).map(|k| hole(10 + k, 10.0 * f64::from(k), -30.0)));
        holes.push(hole(20, 200.0, 7.0));
        let found = patterns_within(&holes, 1e-6);
        assert_eq!(found.len(), 2, "{found:?}");
        let circle = found
            .iter()
            .find(|p| matches!(p.layout, Layout::Circular { .. }))
            .unwrap();
        assert_eq!(circle.holes.len(), 6);
        let Layout::Circular {
            radius,
            step_deg,
            centre,
        } = circle.layout
        else {
            unreachable!()
        };
        assert!((radius - 20.0).abs() < 1e-9 && (step_deg - 60.0).abs() < 1e-9);
        assert!((centre[0] - 50.0).abs() < 1e-9 && (centre[1] - 50.0).abs() < 1e-9);
        let row = found
            .iter()
            .find(|p| matches!(p.layout, Layout::Linear { .. }))
            .unwrap();
        assert_eq!(
            row.holes,
            vec![
                MachiningId(10),
                MachiningId(11),
                MachiningId(12),
                MachiningId(13)
            ]
        );
        // A different diameter is another family: no pattern of mixed holes.
        holes[0].length = 8.0;
        let found = patterns_within(&holes, 1e-6);
        let circle = found
            .iter()
            .find(|p| matches!(p.layout, Layout::Circular { .. }));
        assert!(circle.is_none_or(|c| !c.holes.contains(&MachiningId(1))));
    }

    #[test]
    fn equal_steps_need_all_steps_alike() {
        assert_eq!(equal_steps(&[0.0, 2.0, 4.0, 6.0], 1e-6), Some(2.0));
        assert_eq!(equal_steps(&[0.0, 2.0, 5.0], 1e-6), None);
    }
}
