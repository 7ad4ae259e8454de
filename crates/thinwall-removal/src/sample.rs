//! Face loops as points for projection, sampled so that areas stay exact.
//!
//! A curved edge is cut into short chords; each chord gets one extra point
//! at its middle, pushed out by 4/3 of the curve's sagitta there, so the
//! two half chords enclose the same area as the curve segment (exact for a
//! parabola, a relative 1e-4 of a tiny segment for a circle arc at 16
//! chords per span). A circle of 4 spans then keeps its area to 2e-7,
//! where plain chords lose 1.6e-3. Straight edges keep
//! their two ends. The same edge gives the same points on both faces it
//! bounds, so coincident projections coincide.
//!
//! A circle arc is cut evenly by angle between its ends, whatever its
//! parametrisation: two arcs with the same centre, radius and ends (a
//! pocket corner cylinder's top and bottom edges, which project onto one
//! arc) give the same points in any pose. Cut per knot span, their points
//! depended on where each circle's placement started it, and on a turned
//! part the two polygons parted by a few micrometres: sliver cells whose
//! columns saw one face and not the other.

use thinwall_analysis::polygon::coedge_params;
use thinwall_brep::{EdgeId, FaceId, Part};
use thinwall_geom::tolerance::{NEAR_PARALLEL_EPS, SAME_LENGTH_MM};
use thinwall_geom::{CurveKind, Frame, Point3, Surface};

/// Chords per knot span of a curved edge.
const CHORDS_PER_SPAN: usize = 16;

/// Every loop of a face as points in loop order (the closing point not
/// repeated), outer loop(s) as the model orders them.
pub fn face_loop_points(part: &Part, face: FaceId) -> Vec<Vec<Point3>> {
    let f = part.face(face);
    f.loops
        .iter()
        .map(|&l| {
            let mut pts = Vec::new();
            for ce in &part.loop_(l).coedges {
                let e = part.edge(ce.edge);
                let Some(c) = &e.nurbs else {
                    pts.push(part.vertex(if ce.forward { e.start } else { e.end }).point);
                    continue;
                };
                edge_points(part, ce.edge, c, ce.forward, &mut pts);
            }
            pts
        })
        .filter(|p| p.len() >= 3)
        .collect()
}

/// The points of edge `e` strictly between its vertices, start to end:
/// the same points [`face_loop_points`] gives the edge on either face, for
/// a face triangulated with that boundary (`thinwall_brep::tessellate::face_triangles`).
pub fn edge_interior_points(part: &Part, e: thinwall_brep::EdgeId) -> Vec<Point3> {
    let edge = part.edge(e);
    let Some(c) = &edge.nurbs else {
        return Vec::new();
    };
    let mut pts = Vec::new();
    edge_points(part, e, c, true, &mut pts);
    // Its start vertex is the loop's, not the edge's inside.
    if !pts.is_empty() {
        pts.remove(0);
    }
    pts
}

/// An edge's points from its start (its end left to the next edge): cut
/// evenly by angle about the axis it runs round — a cylinder one of its
/// faces is (so a cylinder's top and bottom edges, which project onto one
/// arc when it stands along up, are cut alike whatever their curves; the
/// widest such cylinder the edge turns one way round: where a cross hole
/// meets a bore, round the cross hole), else a circle's own — or per span
/// ([`chord_points`]) for any other curve or an edge along a cylinder's
/// generator.
fn edge_points(
    part: &Part,
    e: EdgeId,
    c: &thinwall_geom::NurbsCurve,
    forward: bool,
    pts: &mut Vec<Point3>,
) {
    let edge = part.edge(e);
    let circle = match &edge.curve {
        CurveKind::Circle { frame, radius } => Some((*frame, *radius)),
        _ => None,
    };
    let mut axes: Vec<(Frame, f64)> = part
        .edge_faces(e)
        .iter()
        .filter_map(|&f| match &part.face(f).surface {
            Surface::Cylinder { frame, radius } => Some((*frame, *radius)),
            _ => None,
        })
        .collect();
    axes.sort_by(|a, b| b.1.total_cmp(&a.1));
    axes.extend(circle);
    let done = axes.iter().any(|(axis, radius)| {
        // A circle coaxial with the axis is evaluated in closed form.
        let coaxial = circle.filter(|(cf, _)| {
            cf.z.dot(&axis.z).abs() > 1.0 - NEAR_PARALLEL_EPS
                && (cf.origin - axis.origin).cross(&axis.z).norm() <= SAME_LENGTH_MM
        });
        turn_points(
            (axis, *radius),
            coaxial.map(|(cf, r)| (cf.origin, r)),
            c,
            forward,
            pts,
        )
    });
    if !done {
        chord_points(c, forward, pts);
    }
}

/// The points of a curve running round `axis` (z the axis, x and y
/// across it), even in angle between its ends (the same angles for any
/// two curves with the same ends about one axis, either way round), each
/// chord followed by its midpoint pushed out by 4/3 of the sagitta;
/// `CHORDS_PER_SPAN` chords a quarter turn. A coaxial circle (its centre
/// and radius) is evaluated in closed form, any other curve at the
/// parameter where it reaches each angle. False, nothing pushed, for a
/// curve that does not turn about the axis (a generator).
fn turn_points(
    (axis, radius): (&Frame, f64),
    circle: Option<(Point3, f64)>,
    c: &thinwall_geom::NurbsCurve,
    forward: bool,
    pts: &mut Vec<Point3>,
) -> bool {
    use std::f64::consts::TAU;
    let (t0, t1) = c.domain();
    let angle = |p: &Point3| {
        let d = p - axis.origin;
        d.dot(&axis.y).atan2(d.dot(&axis.x))
    };
    let (a0, a1, am) = (
        angle(&c.point(t0)),
        angle(&c.point(t1)),
        angle(&c.point(0.5 * (t0 + t1))),
    );
    let ccw = |from: f64, to: f64| (to - from).rem_euclid(TAU);
    let closed = (c.point(t0) - c.point(t1)).norm() <= SAME_LENGTH_MM;
    let still = |x: f64| x <= TURN_EPS || TAU - x <= TURN_EPS;
    if !closed && still(ccw(a0, a1)) && still(ccw(a0, am)) {
        return false;
    }
    if !turns_one_way(c, &angle) {
        // It turns out and back (a blend's edge on a boss, NIST FTC 10's
        // #1483): its angle is no parameter along it.
        return false;
    }
    let sweep = if closed {
        // A whole turn: counter-clockwise when a quarter along the curve
        // lies less than half a turn that way.
        let aq = angle(&c.point(t0 + 0.25 * (t1 - t0)));
        if ccw(a0, aq) < std::f64::consts::PI {
            TAU
        } else {
            -TAU
        }
    } else {
        // Counter-clockwise when the middle lies on that side of the start.
        let turn = ccw(a0, a1);
        if ccw(a0, am) < turn {
            turn
        } else {
            turn - TAU
        }
    };
    let at = |theta: f64| -> Point3 {
        match circle {
            Some((o, r)) => o + (axis.x * theta.cos() + axis.y * theta.sin()) * r,
            None => c.point(param_at(c, &angle, (a0, sweep, closed), theta)),
        }
    };
    let ends = turn_angles(a0, sweep, chords_per_quarter(radius));
    let mut thetas: Vec<f64> = Vec::with_capacity(2 * ends.len());
    for w in ends.windows(2) {
        thetas.push(w[0]);
        thetas.push(0.5 * (w[0] + w[1]));
    }
    thetas.push(a0 + sweep);
    let n = ends.len() - 1;
    if !forward {
        thetas.reverse();
    }
    for k in 0..n {
        let (p, m, q) = (
            at(thetas[2 * k]),
            at(thetas[2 * k + 1]),
            at(thetas[2 * k + 2]),
        );
        let chord_mid = p + (q - p) * 0.5;
        pts.push(p);
        pts.push(chord_mid + (m - chord_mid) * (4.0 / 3.0));
    }
    true
}

/// The chord ends of an arc from angle `a0` turning by `sweep`: its two
/// ends and, between them, the angles of a grid fixed on the axis (every
/// `1/per_quarter` of a quarter turn from the axis's x). Arcs of one
/// circle then share their chords wherever they overlap, whatever their
/// ends: a wall's top and bottom edges, split at different points, project
/// onto one polygon but near their ends.
fn turn_angles(a0: f64, sweep: f64, per_quarter: usize) -> Vec<f64> {
    use std::f64::consts::FRAC_PI_2;
    let step = FRAC_PI_2 / per_quarter as f64;
    let (from, to) = (a0 / step, (a0 + sweep) / step);
    let near = GRID_END_SHARE;
    let mut out = vec![a0];
    if sweep > 0.0 {
        let mut k = (from + near).ceil();
        while k < to - near {
            out.push(k * step);
            k += 1.0;
        }
    } else {
        let mut k = (from - near).floor();
        while k > to + near {
            out.push(k * step);
            k -= 1.0;
        }
    }
    out.push(a0 + sweep);
    out
}

/// Chords a quarter turn on a circle of radius `r` (mm): `CHORDS_PER_SPAN`,
/// more on a large circle, so that the outline keeping its area stays
/// within [`OUTLINE_DEVIATION_MM`] of it (a pushed midpoint stands a third
/// of the sagitta `r·θ²/8` outside the circle: θ ≤ √(24·d/r)).
fn chords_per_quarter(r: f64) -> usize {
    let theta = (24.0 * OUTLINE_DEVIATION_MM / r.max(1e-9)).sqrt();
    let need = (std::f64::consts::FRAC_PI_2 / theta).ceil();
    (need.min(MAX_CHORDS_PER_QUARTER as f64) as usize).max(CHORDS_PER_SPAN)
}

/// How far an arc's outline may stand off the circle, mm.
pub(crate) const OUTLINE_DEVIATION_MM: f64 = 0.005;
/// Most chords a quarter turn (a circle of 4.5 m at the deviation above).
const MAX_CHORDS_PER_QUARTER: usize = 1024;

/// A grid angle closer to an arc's end than this share of a grid step is
/// left out (no chord much shorter than the rest).
const GRID_END_SHARE: f64 = 1e-3;

/// Turns (radians) under this are no turn: an edge along a generator.
const TURN_EPS: f64 = 1e-9;

/// Samples along a curve to judge whether it turns one way round an axis.
const TURN_SAMPLES: usize = 64;

/// Whether curve `c`'s angle about an axis only grows or only shrinks
/// along it (samples at `TURN_SAMPLES` even parameters, steps within
/// `TURN_EPS` taken as still).
fn turns_one_way(c: &thinwall_geom::NurbsCurve, angle: &dyn Fn(&Point3) -> f64) -> bool {
    use std::f64::consts::{PI, TAU};
    let (t0, t1) = c.domain();
    let angles: Vec<f64> = (0..=TURN_SAMPLES)
        .map(|k| angle(&c.point(t0 + (t1 - t0) * k as f64 / TURN_SAMPLES as f64)))
        .collect();
    let steps = angles
        .windows(2)
        .map(|w| (w[1] - w[0] + PI).rem_euclid(TAU) - PI)
        .filter(|d| d.abs() > TURN_EPS);
    let (mut up, mut down) = (false, false);
    for d in steps {
        up |= d > 0.0;
        down |= d < 0.0;
    }
    !(up && down)
}

/// The parameter where curve `c`, turning by `sweep` about an axis from
/// angle `a0` (a whole turn when `closed`), reaches angle `theta`, by
/// bisection: the share of the turn grows along the curve.
fn param_at(
    c: &thinwall_geom::NurbsCurve,
    angle: &dyn Fn(&Point3) -> f64,
    (a0, sweep, closed): (f64, f64, bool),
    theta: f64,
) -> f64 {
    use std::f64::consts::TAU;
    let (t0, t1) = c.domain();
    // The turn from the start at parameter t, unwrapped: just before the
    // start (rounding) is a little below 0, a whole turn's end near 2π. A
    // whole turn is unwrapped next to the share of it the parameter has
    // run (a curve's parameter follows its angle to well within half a
    // turn): deciding by which half of the parameter t lies in failed
    // where the angle is half a turn at the middle parameter exactly (an
    // ellipse round a tilted cylinder), all of the second half landing on
    // its middle.
    let turned = |t: f64| {
        let x = (sweep.signum() * (angle(&c.point(t)) - a0)).rem_euclid(TAU);
        if closed {
            let share = TAU * (t - t0) / (t1 - t0);
            return [x - TAU, x, x + TAU]
                .into_iter()
                .min_by(|p, q| (p - share).abs().total_cmp(&(q - share).abs()))
                .unwrap_or(x);
        }
        if x > 0.5 * (sweep.abs() + TAU) {
            x - TAU
        } else {
            x
        }
    };
    let want = (theta - a0) * sweep.signum();
    let (mut lo, mut hi) = (t0, t1);
    for _ in 0..PARAM_BISECTIONS {
        let mid = 0.5 * (lo + hi);
        if turned(mid) < want {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// Bisections of a parameter range: 2^-48 of it.
const PARAM_BISECTIONS: usize = 48;

/// A curve's chord ends from its start (its end left to the next edge),
/// each curved chord followed by its midpoint pushed out by 4/3 of the
/// sagitta; along `forward` or against it.
fn chord_points(c: &thinwall_geom::NurbsCurve, forward: bool, pts: &mut Vec<Point3>) {
    let (ts, straight) = coedge_params(c, forward, CHORDS_PER_SPAN);
    for w in ts.windows(2) {
        let (p, q) = (c.point(w[0]), c.point(w[1]));
        pts.push(p);
        if !straight {
            let chord_mid = p + (q - p) * 0.5;
            let curve_mid = c.point(0.5 * (w[0] + w[1]));
            pts.push(chord_mid + (curve_mid - chord_mid) * (4.0 / 3.0));
        }
    }
}

#[cfg(test)]
mod tests {
    /// The 4/3-sagitta midpoint keeps a circle's area to 2e-7 at 16 chords
    /// per quarter, where plain chords are off by 1.6e-3.
    #[test]
    fn pushed_midpoints_keep_a_circles_area() {
        let r: f64 = 5.0;
        let n = 64;
        let p = |t: f64| (r * t.cos(), r * t.sin());
        let (mut plain, mut pushed) = (Vec::new(), Vec::new());
        for k in 0..n {
            let (t0, t1) = (
                std::f64::consts::TAU * k as f64 / n as f64,
                std::f64::consts::TAU * (k + 1) as f64 / n as f64,
            );
            let (a, b, m) = (p(t0), p(t1), p(0.5 * (t0 + t1)));
            plain.push(a);
            pushed.push(a);
            let cm = (0.5 * (a.0 + b.0), 0.5 * (a.1 + b.1));
            pushed.push((
                cm.0 + (m.0 - cm.0) * 4.0 / 3.0,
                cm.1 + (m.1 - cm.1) * 4.0 / 3.0,
            ));
        }
        let area = |pts: &[(f64, f64)]| {
            let mut s = 0.0;
            for i in 0..pts.len() {
                let (a, b) = (pts[i], pts[(i + 1) % pts.len()]);
                s += a.0 * b.1 - b.0 * a.1;
            }
            0.5 * s
        };
        let exact = std::f64::consts::PI * r * r;
        assert!((area(&plain) - exact).abs() / exact > 1e-3);
        assert!((area(&pushed) - exact).abs() / exact < 3e-7);
    }

    /// Two arcs of one circle with different ends share every chord end
    /// of the axis's grid where they overlap; their own ends are their
    /// first and last, in their direction.
    #[test]
    fn arcs_of_one_circle_share_the_grid_between_their_ends() {
        use super::turn_angles;
        let step = std::f64::consts::FRAC_PI_2 / 16.0;
        let whole = turn_angles(0.0, std::f64::consts::PI, 16);
        let part = turn_angles(0.1253, -(0.1253 - 2.9981), 16);
        assert_eq!(whole.len(), 33);
        assert_eq!((part[0], *part.last().unwrap()), (0.1253, 2.9981));
        for t in &part[1..part.len() - 1] {
            assert!(
                whole.iter().any(|w| (w - t).abs() < 1e-15),
                "{t} on the grid"
            );
            assert!((t / step - (t / step).round()).abs() < 1e-12);
        }
        let back = turn_angles(2.9981, 0.1253 - 2.9981, 16);
        let mut reversed = back.clone();
        reversed.reverse();
        for (a, b) in reversed.iter().zip(&part) {
            assert!((a - b).abs() < 1e-15, "either way round");
        }
        // A grid angle a hair from an end is left out: no sliver chord.
        let near = turn_angles(step * 3.0 - 1e-9, 1.0, 16);
        assert!(near[1] - near[0] > 0.5 * step, "{near:?}");
    }
}
