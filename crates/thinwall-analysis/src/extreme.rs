//! How far a part reaches along a direction, the bulges of its curved faces
//! included.
//!
//! Boundary samples bound a face whose extremes lie on its edges (planes,
//! cylinders and cones: along a direction a cylinder's or cone's height is
//! highest on a whole line, which runs to the face's edges). A sphere, a
//! torus or a free-form face can rise above all its edges: a bead on a
//! plate (a half torus standing on its two circles), a dome, a skin. For
//! those the surface's highest point (a sphere's pole along the direction,
//! a torus's top — a point, or a circle when the direction is its axis —,
//! a free-form face's local maximum found from its highest mesh vertex) is
//! taken when it lies on the face: on one of the face's triangles.
//!
//! Only a face whose surface's whole extent (a sphere's, a torus's, a
//! free-form control net's) passes beyond the boundary samples is
//! triangulated, alone and coarsely (a thousandth of the part's size): the
//! part's own mesh is not built for this (it made `recognize --no-reach`
//! ten times slower on parts with beads).

use crate::PartAnalysis;
use thinwall_brep::FaceId;
use thinwall_geom::{NurbsSurface, Point3, Surface, Vector3};

/// Most steps of the local ascent on a free-form surface.
const ASCENT_STEPS: usize = 400;

impl PartAnalysis<'_> {
    /// Lowest and highest extent of the whole part along unit `dir`, mm,
    /// curved faces' bulges included.
    pub fn part_extent(&self, dir: &Vector3) -> (f64, f64) {
        let all: Vec<FaceId> = self.part().face_ids().collect();
        self.with_bulges(dir, self.extent(&all, dir))
    }

    /// `(lo, hi)`, the part's extent along unit `dir` from its edges,
    /// widened to the curved faces that rise beyond it, mm.
    pub fn with_bulges(&self, dir: &Vector3, (mut lo, mut hi): (f64, f64)) -> (f64, f64) {
        let slack = self.tol().feature;
        for f in self.part().face_ids() {
            let s = &self.part().face(f).surface;
            let Some((slo, shi)) = surface_extent(s, dir) else {
                continue;
            };
            if shi > hi + slack {
                if let Some(h) = face_extreme(self, f, dir) {
                    hi = hi.max(h);
                }
            }
            if slo < lo - slack {
                if let Some(h) = face_extreme(self, f, &-dir) {
                    lo = lo.min(-h);
                }
            }
        }
        (lo, hi)
    }
}

/// The extent along `dir` of a whole surface that can rise above its face's
/// edges (a sphere, a torus, a free-form control net); `None` for the
/// kinds whose faces reach their extremes on their edges.
fn surface_extent(s: &Surface, dir: &Vector3) -> Option<(f64, f64)> {
    let around = |c: &Point3, r: f64| (c.coords.dot(dir) - r, c.coords.dot(dir) + r);
    match s {
        Surface::Sphere { frame, radius } => Some(around(&frame.origin, *radius)),
        Surface::Torus {
            frame,
            major_radius,
            minor_radius,
        } => {
            let across = (dir - frame.z * dir.dot(&frame.z)).norm();
            Some(around(&frame.origin, major_radius * across + minor_radius))
        }
        Surface::Freeform { nurbs, .. } => {
            let h = nurbs.control_points().map(|p| p.coords.dot(dir));
            Some(h.fold((f64::INFINITY, f64::NEG_INFINITY), |m, x| {
                (m.0.min(x), m.1.max(x))
            }))
        }
        _ => None,
    }
}

/// The highest point of face `f` along `dir` that is not on its edges, as
/// its height, if the surface's top lies on the face.
fn face_extreme(a: &PartAnalysis, f: FaceId, dir: &Vector3) -> Option<f64> {
    let part = a.part();
    let (points, triangles) = thinwall_brep::tessellate::face_triangles(
        part,
        f,
        &|e| edge_samples(part, e),
        COARSE_DEVIATION * a.tol().diagonal,
    )
    .ok()?;
    let top = triangles
        .iter()
        .flatten()
        .map(|&i| points[i as usize])
        .max_by(|p, q| p.coords.dot(dir).total_cmp(&q.coords.dot(dir)))?;
    let candidate = match &part.face(f).surface {
        Surface::Freeform { nurbs, .. } => ascend(nurbs, &top, dir),
        s => surface_top_near(s, &top, dir)?,
    };
    let on_face = triangles.iter().any(|t| {
        let [p, q, r] = t.map(|i| points[i as usize]);
        on_triangle(&candidate, [p, q, r], chord_gap(&p, &q, &r))
    });
    let best = if on_face { candidate } else { top };
    Some(best.coords.dot(dir).max(top.coords.dot(dir)))
}

/// The deviation of a face triangulated to find its top, as a share of
/// the part's size.
const COARSE_DEVIATION: f64 = 1e-3;

/// Points strictly inside edge `e`, start to end: a few per knot span.
fn edge_samples(part: &thinwall_brep::Part, e: thinwall_brep::EdgeId) -> Vec<Point3> {
    let Some(c) = &part.edge(e).nurbs else {
        return Vec::new();
    };
    if c.degree == 1 && c.is_polynomial() {
        return Vec::new();
    }
    c.spans()
        .into_iter()
        .enumerate()
        .flat_map(|(k, (t0, t1))| {
            let first = if k == 0 { 1 } else { 0 };
            (first..EDGE_SAMPLES).map(move |i| t0 + (t1 - t0) * i as f64 / EDGE_SAMPLES as f64)
        })
        .map(|t| c.point(t))
        .collect()
}

/// Points per knot span of an edge bounding a face triangulated alone.
const EDGE_SAMPLES: usize = 8;

/// The point of a sphere's or torus's highest set along `dir` nearest `p`
/// (the pole; the torus's top point, or on its top circle when `dir` is
/// its axis).
fn surface_top_near(s: &Surface, p: &Point3, dir: &Vector3) -> Option<Point3> {
    match s {
        Surface::Sphere { frame, radius } => Some(frame.origin + dir * *radius),
        Surface::Torus {
            frame,
            major_radius,
            minor_radius,
        } => {
            let axial = dir.dot(&frame.z);
            let across = dir - frame.z * axial;
            let radial = if across.norm() > 1e-9 {
                across.normalize()
            } else {
                let l = p - frame.origin;
                let flat = l - frame.z * l.dot(&frame.z);
                if flat.norm() < 1e-12 {
                    return None;
                }
                flat.normalize()
            };
            let tube = radial * across.norm() + frame.z * axial;
            Some(frame.origin + radial * *major_radius + tube.normalize() * *minor_radius)
        }
        _ => None,
    }
}

/// A local highest point of a free-form surface along `dir`, climbing from
/// the surface point nearest `start` by compass search over the
/// parameters: the best of eight steps around, the step halved when none
/// climbs, until it is a 2^-40 of the domain.
fn ascend(s: &NurbsSurface, start: &Point3, dir: &Vector3) -> Point3 {
    let ((u0, u1), (v0, v1)) = s.domain();
    let (mut u, mut v, _) = s.invert(start, None);
    let height = |u: f64, v: f64| s.eval(u, v).point.coords.dot(dir);
    let mut here = height(u, v);
    let (mut du, mut dv) = (0.125 * (u1 - u0), 0.125 * (v1 - v0));
    let stop = (u1 - u0).min(v1 - v0) * 2f64.powi(-40);
    for _ in 0..ASCENT_STEPS {
        if du.min(dv) < stop {
            break;
        }
        let best = COMPASS
            .iter()
            .map(|&(a, b)| ((u + a * du).clamp(u0, u1), (v + b * dv).clamp(v0, v1)))
            .map(|(nu, nv)| (height(nu, nv), nu, nv))
            .max_by(|x, y| x.0.total_cmp(&y.0))
            .expect("eight directions");
        if best.0 > here {
            (here, u, v) = best;
        } else {
            du *= 0.5;
            dv *= 0.5;
        }
    }
    s.eval(u, v).point
}

/// The eight directions of the compass search.
const COMPASS: [(f64, f64); 8] = [
    (1.0, 0.0),
    (-1.0, 0.0),
    (0.0, 1.0),
    (0.0, -1.0),
    (1.0, 1.0),
    (1.0, -1.0),
    (-1.0, 1.0),
    (-1.0, -1.0),
];

/// How far a curved face may stand off its triangle's plane: a fifth of
/// the triangle's longest side (the chord sag of an arc up to ~90°).
fn chord_gap(p: &Point3, q: &Point3, r: &Point3) -> f64 {
    0.2 * (q - p).norm().max((r - q).norm()).max((p - r).norm())
}

/// Whether `x` lies over triangle `t` (its foot on the plane inside the
/// triangle) and within `gap` of the plane.
fn on_triangle(x: &Point3, t: [Point3; 3], gap: f64) -> bool {
    let [p, q, r] = t;
    let n = (q - p).cross(&(r - p));
    let area2 = n.norm();
    if area2 < 1e-300 {
        return false;
    }
    let n = n / area2;
    if (x - p).dot(&n).abs() > gap {
        return false;
    }
    let inside = |a: &Point3, b: &Point3| (b - a).cross(&(x - a)).dot(&n) >= -1e-12 * area2;
    inside(&p, &q) && inside(&q, &r) && inside(&r, &p)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A bicubic bump over [0, 40]²: its control net's middle raised, its
    /// highest point away from the net's points and the grid.
    fn bump() -> NurbsSurface {
        let n = 6;
        let points: Vec<Vec<[f64; 3]>> = (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| {
                        let (x, y) = (8.0 * i as f64, 8.0 * j as f64);
                        let z = if (1..4).contains(&i) && (2..5).contains(&j) {
                            6.0 + i as f64
                        } else {
                            0.0
                        };
                        [x, y, z]
                    })
                    .collect()
            })
            .collect();
        let knots = vec![0.0, 0.0, 0.0, 0.0, 0.3, 0.7, 1.0, 1.0, 1.0, 1.0];
        let weights = vec![vec![1.0; n]; n];
        NurbsSurface::new(3, 3, knots.clone(), knots, &points, &weights).unwrap()
    }

    #[test]
    fn the_ascent_reaches_a_free_form_crest_from_a_point_below_it() {
        let s = bump();
        let up = Vector3::new(0.05, -0.03, 1.0).normalize();
        // The crest by a fine search over the parameters.
        let steps = 600;
        let crest = (0..=steps)
            .flat_map(|i| (0..=steps).map(move |j| (i, j)))
            .map(|(i, j)| {
                s.eval(i as f64 / steps as f64, j as f64 / steps as f64)
                    .point
            })
            .map(|p| p.coords.dot(&up))
            .fold(f64::NEG_INFINITY, f64::max);
        let start = s.eval(0.45, 0.5).point;
        let top = ascend(&s, &start, &up).coords.dot(&up);
        assert!(top >= crest - 1e-6, "{top} below the crest {crest}");
        assert!(top <= crest + 1e-3, "{top} above the crest {crest}");
        assert!(top > start.coords.dot(&up) + 0.1, "climbed from {start}");
    }

    #[test]
    fn a_torus_top_is_its_crest_or_on_its_top_circle() {
        let frame = thinwall_geom::Frame::world();
        let torus = Surface::Torus {
            frame,
            major_radius: 20.0,
            minor_radius: 2.0,
        };
        let up = Vector3::z();
        let near = Point3::new(3.0, 19.0, 1.5);
        let top = surface_top_near(&torus, &near, &up).unwrap();
        assert!((top.z - 2.0).abs() < 1e-12 && (top.x.hypot(top.y) - 20.0).abs() < 1e-12);
        assert!(
            top.y / top.x - 19.0 / 3.0 < 1e-9,
            "on the circle at the point's angle"
        );
        let tilted = Vector3::new(1.0, 0.0, 1.0).normalize();
        let crest = surface_top_near(&torus, &near, &tilted).unwrap();
        let (_, hi) = surface_extent(&torus, &tilted).unwrap();
        assert!((crest.coords.dot(&tilted) - hi).abs() < 1e-12);
    }
}
