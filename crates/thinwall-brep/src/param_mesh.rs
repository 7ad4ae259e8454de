//! Integration over a free-form face in its parameter space.
//!
//! The face's loops are sampled along their edges, projected onto the
//! surface (point inversion, each from the previous parameter), and the
//! resulting polygons are triangulated with spade's constrained Delaunay
//! triangulation. Triangles whose centre lies inside the loops (even–odd)
//! make up the face; each is integrated adaptively (midpoint rule,
//! subdivided until two levels agree to 1e-7 relative).

use crate::model::{Face, Part};
use spade::{ConstrainedDelaunayTriangulation, Point2, Triangulation};
use thinwall_geom::{BoundingBox, NurbsSurface, Point3, Vector3};

/// Area, centroid and box of a free-form face.
pub struct MeshIntegral {
    pub area: f64,
    pub centroid: Point3,
    pub bbox: BoundingBox,
    pub warnings: Vec<String>,
}

/// Samples per knot span of a boundary edge.
const SAMPLES_PER_SPAN: usize = 8;
/// Interior grid lines per knot span of the surface (Steiner points keep the
/// triangles well shaped, so the quadrature converges without subdividing).
const GRID_PER_SPAN: usize = 2;
/// Fewest and most interior grid lines in each parameter direction.
const GRID_MIN: usize = 6;
const GRID_MAX: usize = 24;
/// Deepest adaptive subdivision of a triangle.
const MAX_DEPTH: u32 = 5;
/// Relative error budget of a face's integral.
const REL_TOL: f64 = 1e-6;
/// Dunavant's 6-point rule (degree 4) on a triangle: the permutations of
/// barycentric `(a, b, b)`, `b = (1 − a)/2`, each with weight `w` (the
/// weights sum to 1 over the six points).
const RULE: [(f64, f64); 2] = [
    (0.108_103_018_168_070, 0.223_381_589_678_011),
    (0.816_847_572_980_459, 0.109_951_743_655_322),
];

/// The loops of `face` as polygons in the parameter space of `s`.
pub fn parameter_loops(
    part: &Part,
    face: &Face,
    s: &NurbsSurface,
    warnings: &mut Vec<String>,
) -> Vec<Vec<[f64; 2]>> {
    let ((u0, u1), (v0, v1)) = s.domain();
    let mut loops = Vec::new();
    let mut max_dist: f64 = 0.0;
    let mut wraps = false;
    for &l in &face.loops {
        let mut poly: Vec<[f64; 2]> = Vec::new();
        let mut hint = None;
        for ce in &part.loop_(l).coedges {
            let Some(c) = &part.edge(ce.edge).nurbs else {
                continue;
            };
            let mut ts: Vec<f64> = Vec::new();
            for (a, b) in c.spans() {
                for k in 0..SAMPLES_PER_SPAN {
                    ts.push(a + (b - a) * k as f64 / SAMPLES_PER_SPAN as f64);
                }
            }
            ts.push(c.domain().1);
            if !ce.forward {
                ts.reverse();
            }
            ts.pop(); // the next coedge starts there
            for t in ts {
                let (u, v, d) = s.invert(&c.point(t), hint);
                max_dist = max_dist.max(d);
                if let Some(&[pu, pv]) = poly.last() {
                    if (u - pu).abs() > 0.5 * (u1 - u0) || (v - pv).abs() > 0.5 * (v1 - v0) {
                        wraps = true;
                    }
                }
                hint = Some((u, v));
                poly.push([u, v]);
            }
        }
        if poly.len() >= 3 {
            loops.push(poly);
        }
    }
    if wraps {
        warnings.push("a loop crosses the seam of a closed surface; area is approximate".into());
    }
    let size = (s.eval(u0, v0).point - s.eval(u1, v1).point)
        .norm()
        .max(1.0);
    if max_dist > 1e-3 * size {
        warnings.push(format!(
            "boundary lies up to {max_dist:.3e} mm off the surface"
        ));
    }
    loops
}

/// Grid lines over `[lo, hi]`: each knot span of `knots` inside it cut in
/// [`GRID_PER_SPAN`], at least [`GRID_MIN`] and at most [`GRID_MAX`] lines.
fn grid_lines(knots: &[f64], lo: f64, hi: f64) -> Vec<f64> {
    let mut cuts: Vec<f64> = vec![lo];
    cuts.extend(knots.iter().copied().filter(|&k| k > lo && k < hi));
    cuts.push(hi);
    cuts.dedup_by(|a, b| (*a - *b).abs() <= 1e-12 * (hi - lo).abs().max(1e-300));
    let spans = cuts.len() - 1;
    let per = (GRID_PER_SPAN.max(GRID_MIN.div_ceil(spans.max(1)))).min(GRID_MAX / spans.max(1));
    if per == 0 {
        // More spans than grid lines: every k-th knot.
        let step = spans.div_ceil(GRID_MAX);
        return cuts.iter().copied().step_by(step).collect();
    }
    let mut out = Vec::new();
    for w in cuts.windows(2) {
        for k in 0..per {
            out.push(w[0] + (w[1] - w[0]) * k as f64 / per as f64);
        }
    }
    out.push(hi);
    out
}

/// Distance from `p` to the nearest boundary segment, with parameters
/// divided by `scale` (one cell in each direction is one unit).
fn boundary_distance(loops: &[Vec<[f64; 2]>], p: [f64; 2], scale: [f64; 2]) -> f64 {
    let at = |q: [f64; 2]| [(q[0] - p[0]) / scale[0], (q[1] - p[1]) / scale[1]];
    let p = [0.0, 0.0];
    let mut d2 = f64::INFINITY;
    for poly in loops {
        for i in 0..poly.len() {
            let (a, b) = (at(poly[i]), at(poly[(i + 1) % poly.len()]));
            let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
            let len2 = dx * dx + dy * dy;
            let t = if len2 > 0.0 {
                (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let (ex, ey) = (p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
            d2 = d2.min(ex * ex + ey * ey);
        }
    }
    d2.sqrt()
}

/// Interior Steiner points: the knot-aligned grid points inside the loops,
/// kept away from the boundary by half a grid cell.
fn interior_points(loops: &[Vec<[f64; 2]>], s: &NurbsSurface) -> Vec<[f64; 2]> {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in loops.iter().flatten() {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    if !(lo[0] < hi[0] && lo[1] < hi[1]) {
        return Vec::new();
    }
    let us = grid_lines(&s.knots_u, lo[0], hi[0]);
    let vs = grid_lines(&s.knots_v, lo[1], hi[1]);
    let cell = |lines: &[f64]| {
        lines
            .windows(2)
            .map(|w| w[1] - w[0])
            .fold(f64::INFINITY, f64::min)
    };
    let (cu, cv) = (cell(&us), cell(&vs));
    let mut out = Vec::new();
    for &u in &us[1..us.len() - 1] {
        for &v in &vs[1..vs.len() - 1] {
            let p = [u, v];
            if !inside(loops, p) {
                continue;
            }
            // Away from the boundary by half a cell.
            if boundary_distance(loops, p, [cu, cv]) > 0.5 {
                out.push(p);
            }
        }
    }
    out
}

fn inside(loops: &[Vec<[f64; 2]>], p: [f64; 2]) -> bool {
    let mut c = false;
    for poly in loops {
        let n = poly.len();
        for i in 0..n {
            let a = poly[i];
            let b = poly[(i + 1) % n];
            if (a[1] > p[1]) != (b[1] > p[1]) {
                let x = a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
                if p[0] < x {
                    c = !c;
                }
            }
        }
    }
    c
}

/// `∫ g` and `∫ S·g` over a parameter triangle (6-point degree-4 rule).
fn triangle_rule(s: &NurbsSurface, t: &[[f64; 2]; 3]) -> (f64, Vector3) {
    let jac = 0.5
        * ((t[1][0] - t[0][0]) * (t[2][1] - t[0][1]) - (t[2][0] - t[0][0]) * (t[1][1] - t[0][1]))
            .abs();
    let mut a = 0.0;
    let mut m = Vector3::zeros();
    for (x, w) in RULE {
        let b = 0.5 * (1.0 - x);
        for l in [[x, b, b], [b, x, b], [b, b, x]] {
            let u = l[0] * t[0][0] + l[1] * t[1][0] + l[2] * t[2][0];
            let v = l[0] * t[0][1] + l[1] * t[1][1] + l[2] * t[2][1];
            let sp = s.eval(u, v);
            let g = sp.du.cross(&sp.dv).norm();
            a += w * g;
            m += sp.point.coords * (w * g);
        }
    }
    (a * jac, m * jac)
}

/// Integrate over `t`, subdividing until two levels agree within `tol`
/// (absolute, mm²), at most [`MAX_DEPTH`] levels deep.
fn adaptive(
    s: &NurbsSurface,
    t: [[f64; 2]; 3],
    whole: (f64, Vector3),
    tol: f64,
    depth: u32,
) -> (f64, Vector3) {
    let parts = split(&t);
    let subs = parts.map(|p| triangle_rule(s, &p));
    let sum_a: f64 = subs.iter().map(|x| x.0).sum();
    let sum_m: Vector3 = subs.iter().map(|x| x.1).sum();
    if depth >= MAX_DEPTH || (sum_a - whole.0).abs() <= tol {
        return (sum_a, sum_m);
    }
    parts
        .iter()
        .zip(subs)
        .map(|(p, w)| adaptive(s, *p, w, 0.25 * tol, depth + 1))
        .fold((0.0, Vector3::zeros()), |acc, x| (acc.0 + x.0, acc.1 + x.1))
}

/// A triangle in parameter space.
type Triangle = [[f64; 2]; 3];

/// The integrals over all triangles. One subdivision of every triangle is
/// accepted when the total change is within the error budget; otherwise
/// each triangle is refined adaptively against its share of the budget.
fn integrate_triangles(
    s: &NurbsSurface,
    triangles: &[(Triangle, (f64, Vector3))],
    estimate: f64,
    domain: f64,
) -> (f64, Vector3) {
    let budget = REL_TOL * estimate.abs();
    let mut fine = Vec::with_capacity(triangles.len());
    let mut change = 0.0;
    for (t, whole) in triangles {
        let parts = split(t).map(|p| triangle_rule(s, &p));
        let a: f64 = parts.iter().map(|x| x.0).sum();
        let m: Vector3 = parts.iter().map(|x| x.1).sum();
        change += (a - whole.0).abs();
        fine.push((a, m));
    }
    if change <= budget {
        return fine
            .iter()
            .fold((0.0, Vector3::zeros()), |acc, x| (acc.0 + x.0, acc.1 + x.1));
    }
    let mut area = 0.0;
    let mut moment = Vector3::zeros();
    for (t, whole) in triangles {
        // Each triangle gets its share of the error budget.
        let tol = budget * param_area(t) / domain;
        let (a, m) = adaptive(s, *t, *whole, tol, 0);
        area += a;
        moment += m;
    }
    (area, moment)
}

/// A triangle cut into four at its edge midpoints.
fn split(t: &[[f64; 2]; 3]) -> [[[f64; 2]; 3]; 4] {
    let mid = |a: [f64; 2], b: [f64; 2]| [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
    let (m01, m12, m20) = (mid(t[0], t[1]), mid(t[1], t[2]), mid(t[2], t[0]));
    [
        [t[0], m01, m20],
        [m01, t[1], m12],
        [m20, m12, t[2]],
        [m01, m12, m20],
    ]
}

fn param_area(t: &[[f64; 2]; 3]) -> f64 {
    0.5 * ((t[1][0] - t[0][0]) * (t[2][1] - t[0][1]) - (t[2][0] - t[0][0]) * (t[1][1] - t[0][1]))
        .abs()
}

/// A parameter point for spade, which refuses coordinates that are not 0
/// but nearer it than about 1e-43 (`InsertionError::TooSmall`): a boundary
/// point mapped back to the surface can land 1e-60 off a domain edge
/// that is at 0. Such values are 0 here.
pub(crate) fn spade_point(u: f64, v: f64) -> Point2<f64> {
    let flush = |x: f64| if x.abs() < SPADE_FLUSH { 0.0 } else { x };
    Point2::new(flush(u), flush(v))
}

/// Parameters nearer 0 than this are 0 for the triangulation.
const SPADE_FLUSH: f64 = 1e-30;

/// Integrate area and first moments of a free-form face.
pub fn integrate(part: &Part, face: &Face, s: &NurbsSurface) -> Result<MeshIntegral, String> {
    let mut warnings = Vec::new();
    let loops = parameter_loops(part, face, s, &mut warnings);
    if loops.is_empty() {
        return Err("no boundary loop could be mapped to the surface".into());
    }
    let mut cdt: ConstrainedDelaunayTriangulation<Point2<f64>> = Default::default();
    let mut failed_constraints = 0usize;
    for poly in &loops {
        let mut handles = Vec::with_capacity(poly.len());
        for p in poly {
            if !(p[0].is_finite() && p[1].is_finite()) {
                return Err("non-finite parameter on the boundary".into());
            }
            let h = cdt
                .insert(spade_point(p[0], p[1]))
                .map_err(|e| format!("triangulation refused a point: {e:?}"))?;
            handles.push(h);
        }
        for i in 0..handles.len() {
            let (a, b) = (handles[i], handles[(i + 1) % handles.len()]);
            if a != b && cdt.try_add_constraint(a, b).is_empty() && !cdt.exists_constraint(a, b) {
                failed_constraints += 1;
            }
        }
    }
    for p in interior_points(&loops, s) {
        cdt.insert(spade_point(p[0], p[1]))
            .map_err(|e| format!("triangulation refused a point: {e:?}"))?;
    }
    if failed_constraints > 0 {
        warnings.push(format!(
            "{failed_constraints} boundary segments cross each other in parameter space"
        ));
    }
    // The face's triangles, with a first estimate of the whole.
    let mut triangles = Vec::new();
    let mut bbox = BoundingBox::empty();
    for f in cdt.inner_faces() {
        let v = f.vertices();
        let t = [
            [v[0].position().x, v[0].position().y],
            [v[1].position().x, v[1].position().y],
            [v[2].position().x, v[2].position().y],
        ];
        let c = [
            (t[0][0] + t[1][0] + t[2][0]) / 3.0,
            (t[0][1] + t[1][1] + t[2][1]) / 3.0,
        ];
        if !inside(&loops, c) {
            continue;
        }
        for p in &t {
            bbox.add_point(&s.eval(p[0], p[1]).point);
        }
        triangles.push((t, triangle_rule(s, &t)));
    }
    let estimate: f64 = triangles.iter().map(|x| x.1 .0).sum();
    let domain: f64 = triangles
        .iter()
        .map(|x| param_area(&x.0))
        .sum::<f64>()
        .max(1e-300);
    let (area, moment) = integrate_triangles(s, &triangles, estimate, domain);
    let centroid = if area > 0.0 {
        Point3::from(moment / area)
    } else {
        Point3::origin()
    };
    Ok(MeshIntegral {
        area,
        centroid,
        bbox,
        warnings,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parameters_a_hair_off_zero_are_zero_for_the_triangulation() {
        // spade refuses 1e-60 (TooSmall); a boundary point mapped back to
        // its surface lands there (the free-form rib fixture's side).
        let mut cdt: ConstrainedDelaunayTriangulation<Point2<f64>> = Default::default();
        assert!(cdt.insert(Point2::new(1e-60, 0.5)).is_err());
        assert!(cdt.insert(spade_point(1e-60, 0.5)).is_ok());
        assert_eq!(spade_point(1e-60, -2.5), Point2::new(0.0, -2.5));
    }

    #[test]
    fn triangle_rule_is_exact_for_quartics_on_a_flat_patch() {
        // Bilinear patch S(u,v) = (u, v, 0): g = 1, ∫ over the unit
        // triangle of 1 is 1/2, of x is 1/6.
        let s = NurbsSurface::new(
            1,
            1,
            vec![0.0, 0.0, 1.0, 1.0],
            vec![0.0, 0.0, 1.0, 1.0],
            &[
                vec![[0.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
                vec![[1.0, 0.0, 0.0], [1.0, 1.0, 0.0]],
            ],
            &[vec![1.0; 2], vec![1.0; 2]],
        )
        .unwrap();
        let (a, m) = triangle_rule(&s, &[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
        assert!((a - 0.5).abs() < 1e-14);
        assert!((m.x - 1.0 / 6.0).abs() < 1e-14 && (m.y - 1.0 / 6.0).abs() < 1e-14);
    }

    #[test]
    fn even_odd_inside_test_handles_holes() {
        let outer = vec![[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
        let hole = vec![[1.0, 1.0], [1.0, 3.0], [3.0, 3.0], [3.0, 1.0]];
        let loops = vec![outer, hole];
        assert!(inside(&loops, [0.5, 0.5]));
        assert!(!inside(&loops, [2.0, 2.0]));
        assert!(!inside(&loops, [5.0, 2.0]));
    }
}
