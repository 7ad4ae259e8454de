//! Per-face properties: area, centroid, bounding box, outward normal of a
//! plane, axis and radius of a surface of revolution.
//!
//! Areas and centroids are exact up to quadrature error (≈1e-12 relative),
//! by Green's theorem over the face boundary, for planes and for the
//! surfaces of revolution (cylinder, cone, sphere, torus), whose area
//! element depends on `v` only: the area is `∮ −G(v) du` with `G' = |S_u×S_v|`,
//! plus a pole term when a loop winds around a sphere pole or a cone apex.
//! Free-form faces are triangulated in their parameter space
//! ([`crate::param_mesh`]) and integrated there.

use crate::model::{Face, FaceId, Part};
use crate::param_mesh;
use serde::{Deserialize, Serialize};
use std::f64::consts::{PI, TAU};
use thinwall_geom::quadrature::for_each_node;
use thinwall_geom::{BoundingBox, NurbsCurve, Point3, Surface, Vector3};

/// Properties of one face.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FaceProps {
    /// mm².
    pub area: f64,
    pub centroid: Point3,
    pub bbox: BoundingBox,
    /// Outward unit normal of a planar face.
    pub normal: Option<Vector3>,
    /// Axis point and direction of a cylinder, cone, sphere or torus.
    pub axis: Option<(Point3, Vector3)>,
    /// Radius of a cylinder, sphere, cone (at its placement) or torus (minor).
    pub radius: Option<f64>,
    /// What could not be computed exactly, for the read report.
    pub warnings: Vec<String>,
}

/// Number of Gauss nodes on a knot span of an edge curve.
fn nodes_for(curve: &NurbsCurve) -> usize {
    if curve.degree == 1 && curve.is_polynomial() {
        2
    } else {
        16
    }
}

/// Calls `f(point, derivative, weight)` at the quadrature nodes of every
/// coedge of the face, the derivative following the loop direction.
fn for_each_boundary_node(part: &Part, face: &Face, mut f: impl FnMut(&Point3, &Vector3, f64)) {
    for &l in &face.loops {
        for ce in &part.loop_(l).coedges {
            let Some(curve) = &part.edge(ce.edge).nurbs else {
                continue;
            };
            let sign = if ce.forward { 1.0 } else { -1.0 };
            let n = nodes_for(curve);
            for (a, b) in curve.spans() {
                for_each_node(a, b, n, |t, w| {
                    let (p, d) = curve.eval(t);
                    f(&p, &(d * sign), w);
                });
            }
        }
    }
}

fn boundary_box(part: &Part, face: &Face) -> BoundingBox {
    let mut bb = BoundingBox::empty();
    for &l in &face.loops {
        let lp = part.loop_(l);
        if let Some(v) = lp.vertex {
            bb.add_point(&part.vertex(v).point);
        }
        for ce in &lp.coedges {
            let e = part.edge(ce.edge);
            bb.add_point(&part.vertex(e.start).point);
            bb.add_point(&part.vertex(e.end).point);
            if let Some(c) = &e.nurbs {
                if c.degree > 1 || !c.is_polynomial() {
                    for (a, b) in c.spans() {
                        for k in 1..32 {
                            bb.add_point(&c.point(a + (b - a) * k as f64 / 32.0));
                        }
                    }
                }
            }
        }
    }
    bb
}

/// Compute the properties of face `id`.
pub fn compute_face_props(part: &Part, id: FaceId) -> FaceProps {
    let face = part.face(id);
    let sigma = if face.same_sense { 1.0 } else { -1.0 };
    let mut props = FaceProps {
        area: 0.0,
        centroid: Point3::origin(),
        bbox: boundary_box(part, face),
        normal: None,
        axis: None,
        radius: None,
        warnings: Vec::new(),
    };
    if face
        .loops
        .iter()
        .flat_map(|&l| &part.loop_(l).coedges)
        .any(|ce| part.edge(ce.edge).nurbs.is_none())
    {
        props
            .warnings
            .push("an edge has no usable curve; area and centroid are partial".into());
    }
    match &face.surface {
        Surface::Plane { frame } => {
            props.normal = Some(frame.z * sigma);
            let (a, mx, my) = plane_integrals(part, face, frame);
            finish(&mut props, sigma * a, |area| {
                frame.origin + frame.x * (sigma * mx / area) + frame.y * (sigma * my / area)
            });
        }
        Surface::Freeform { nurbs, .. } => match param_mesh::integrate(part, face, nurbs) {
            Ok(r) => {
                props.area = r.area;
                props.centroid = r.centroid;
                props.bbox.add_box(&r.bbox);
                props.warnings.extend(r.warnings);
            }
            Err(e) => props.warnings.push(format!("free-form face: {e}")),
        },
        Surface::Unsupported { keyword } => props
            .warnings
            .push(format!("surface {keyword} is not supported: no area")),
        revolution => {
            let surface_frame = *revolution.frame().expect("analytic surface has a frame");
            let rev = Revolution::of(revolution).expect("surface of revolution");
            props.axis = Some((surface_frame.origin, surface_frame.z));
            props.radius = Some(rev.radius_for_report());
            let r = revolution_integrals(part, face, revolution, &rev, sigma);
            let frame = r.frame;
            props.warnings.extend(r.warnings);
            if let Some(pole) = r.pole {
                props.bbox.add_point(&frame.to_world(&pole));
            }
            finish(&mut props, r.area, |area| {
                frame.to_world(&Vector3::new(r.mx / area, r.my / area, r.mz / area))
            });
        }
    }
    props
}

fn finish(props: &mut FaceProps, signed_area: f64, centroid: impl Fn(f64) -> Point3) {
    if signed_area < 0.0 {
        props.warnings.push(format!(
            "face loops run against the face orientation (signed area {signed_area:.6} mm²)"
        ));
    }
    let area = signed_area.abs();
    props.area = area;
    props.centroid = if area > 0.0 {
        let mut c = centroid(signed_area);
        if !(c.x.is_finite() && c.y.is_finite() && c.z.is_finite()) {
            c = Point3::origin();
        }
        c
    } else {
        Point3::origin()
    };
}

/// `(∮ ½(X dY − Y dX), ∮ ½X² dY, −∮ ½Y² dX)` in the plane's frame.
fn plane_integrals(part: &Part, face: &Face, frame: &thinwall_geom::Frame) -> (f64, f64, f64) {
    let (mut a, mut mx, mut my) = (0.0, 0.0, 0.0);
    for_each_boundary_node(part, face, |p, d, w| {
        let r = p - frame.origin;
        let (x, y) = (r.dot(&frame.x), r.dot(&frame.y));
        let (dx, dy) = (d.dot(&frame.x), d.dot(&frame.y));
        a += w * 0.5 * (x * dy - y * dx);
        mx += w * 0.5 * x * x * dy;
        my -= w * 0.5 * y * y * dx;
    });
    (a, mx, my)
}

/// The area element of a surface of revolution as functions of `v`.
enum Revolution {
    Cylinder { r: f64 },
    Cone { r: f64, c: f64, t: f64 },
    Sphere { r: f64 },
    Torus { big: f64, r: f64 },
}

impl Revolution {
    fn of(s: &Surface) -> Option<Self> {
        Some(match *s {
            Surface::Cylinder { radius, .. } => Revolution::Cylinder { r: radius },
            Surface::Cone {
                radius, semi_angle, ..
            } => Revolution::Cone {
                r: radius,
                c: semi_angle.cos(),
                t: semi_angle.tan(),
            },
            Surface::Sphere { radius, .. } => Revolution::Sphere { r: radius },
            Surface::Torus {
                major_radius,
                minor_radius,
                ..
            } => Revolution::Torus {
                big: major_radius,
                r: minor_radius,
            },
            _ => return None,
        })
    }

    fn radius_for_report(&self) -> f64 {
        match *self {
            Revolution::Cylinder { r }
            | Revolution::Cone { r, .. }
            | Revolution::Sphere { r }
            | Revolution::Torus { r, .. } => r,
        }
    }

    /// `(G, ρ·g, K)` at `v`: `G' = g = |S_u×S_v|`, `K' = z·g`.
    fn terms(&self, v: f64) -> (f64, f64, f64) {
        match *self {
            Revolution::Cylinder { r } => (r * v, r * r, 0.5 * r * v * v),
            Revolution::Cone { r, c, t } => {
                let rho = r + v * t;
                (
                    (r * v + 0.5 * t * v * v) / c,
                    rho * rho / c,
                    (0.5 * r * v * v + t * v * v * v / 3.0) / c,
                )
            }
            Revolution::Sphere { r } => {
                let (s, co) = v.sin_cos();
                (r * r * s, r * r * r * co * co, 0.5 * r * r * r * s * s)
            }
            Revolution::Torus { big, r } => {
                let (s, co) = v.sin_cos();
                let rho = big + r * co;
                (
                    r * (big * v + r * s),
                    r * rho * rho,
                    -r * r * big * co - 0.5 * r * r * r * co * co,
                )
            }
        }
    }

    /// `v` of the point where the potentials are made to vanish, so that
    /// a boundary running through it (a cone apex, a sphere's north pole)
    /// contributes nothing there. `None`: no such point.
    fn anchor(&self) -> Option<f64> {
        match *self {
            Revolution::Sphere { .. } => Some(PI / 2.0),
            Revolution::Cone { r, t, .. } if t.abs() > 1e-6 => Some(-r / t),
            _ => None,
        }
    }

    /// `(G, ρ·g, K)` with `G` and `K` shifted to vanish at the anchor.
    fn anchored_terms(&self, v: f64, anchor: Option<(f64, f64)>) -> (f64, f64, f64) {
        let (g, rg, k) = self.terms(v);
        match anchor {
            Some((ga, ka)) => (g - ga, rg, k - ka),
            None => (g, rg, k),
        }
    }

    /// The pole a loop winding `winding` times closes on, if its potential
    /// does not vanish there: `(v, local point)`.
    fn pole(&self, winding: i64) -> Option<(f64, Vector3)> {
        match *self {
            Revolution::Sphere { r } => {
                let v = if winding > 0 { PI / 2.0 } else { -PI / 2.0 };
                Some((v, Vector3::new(0.0, 0.0, r * v.sin())))
            }
            Revolution::Cone { r, t, .. } if t.abs() > 1e-6 => {
                let v = -r / t;
                Some((v, Vector3::new(0.0, 0.0, v)))
            }
            _ => None,
        }
    }
}

struct RevolutionIntegrals {
    /// The frame the integrals are expressed in (a sphere's may be turned).
    frame: thinwall_geom::Frame,
    area: f64,
    mx: f64,
    my: f64,
    mz: f64,
    pole: Option<Vector3>,
    warnings: Vec<String>,
}

/// Candidate axes for a sphere's integration frame.
fn sphere_axes(frame: &thinwall_geom::Frame) -> Vec<Vector3> {
    let mut axes = Vec::new();
    for a in [-1.0, 0.0, 1.0] {
        for b in [-1.0, 0.0, 1.0] {
            for c in [0.0, 1.0] {
                if c == 0.0 && (b < 0.0 || (b == 0.0 && a <= 0.0)) {
                    continue;
                }
                axes.push((frame.x * a + frame.y * b + frame.z * c).normalize());
            }
        }
    }
    axes
}

/// A frame at the sphere's centre whose axis stays as far as possible from
/// every boundary sample, so no loop passes near a pole of the
/// parametrisation (where `u` jumps).
fn sphere_frame(frame: &thinwall_geom::Frame, points: &[Point3]) -> thinwall_geom::Frame {
    let mut best = (frame.z, f64::NEG_INFINITY);
    for axis in sphere_axes(frame) {
        let min_rho = points
            .iter()
            .map(|p| (p - frame.origin).cross(&axis).norm())
            .fold(f64::INFINITY, f64::min);
        if min_rho > best.1 + 1e-12 {
            best = (axis, min_rho);
        }
    }
    thinwall_geom::Frame::from_axis(frame.origin, best.0, Some(frame.x)).unwrap_or(*frame)
}

/// Centre of the branch for torus `v` angles: opposite the middle of the
/// largest gap between the sampled angles, so a face never straddles the cut.
fn branch_centre(angles: &mut [f64]) -> f64 {
    if angles.is_empty() {
        return 0.0;
    }
    angles.sort_by(f64::total_cmp);
    let mut gap = (
        angles[0] + TAU - angles[angles.len() - 1],
        angles[angles.len() - 1],
    );
    for w in angles.windows(2) {
        if w[1] - w[0] > gap.0 {
            gap = (w[1] - w[0], w[0]);
        }
    }
    gap.1 + 0.5 * gap.0 + PI
}

fn wrap_to(v: f64, centre: f64) -> f64 {
    v - TAU * ((v - centre) / TAU).round()
}

fn revolution_integrals(
    part: &Part,
    face: &Face,
    surface: &Surface,
    rev: &Revolution,
    sigma: f64,
) -> RevolutionIntegrals {
    let mut nodes: Vec<(Point3, Vector3, f64)> = Vec::new();
    for_each_boundary_node(part, face, |p, d, w| nodes.push((*p, *d, w)));
    let mut frame = *surface.frame().expect("analytic");
    if let Revolution::Sphere { .. } = rev {
        let pts: Vec<Point3> = nodes.iter().map(|n| n.0).collect();
        frame = sphere_frame(&frame, &pts);
    }
    let v_of = |l: &Vector3| -> f64 {
        match rev {
            Revolution::Cylinder { .. } | Revolution::Cone { .. } => l.z,
            Revolution::Sphere { .. } => l.z.atan2(l.x.hypot(l.y)),
            Revolution::Torus { big, .. } => l.z.atan2(l.x.hypot(l.y) - big),
        }
    };
    let centre = match rev {
        Revolution::Torus { .. } => {
            let mut vs: Vec<f64> = nodes.iter().map(|n| v_of(&frame.to_local(&n.0))).collect();
            branch_centre(&mut vs)
        }
        _ => 0.0,
    };
    let anchor = rev.anchor().map(|va| {
        let (g, _, k) = rev.terms(va);
        (g, k)
    });
    let (mut a, mut mx, mut my, mut mz, mut wind) = (0.0, 0.0, 0.0, 0.0, 0.0);
    let has_edges = !nodes.is_empty();
    for (p, d, w) in &nodes {
        let l = frame.to_local(p);
        let dl = frame.vector_to_local(d);
        let rho2 = l.x * l.x + l.y * l.y;
        if rho2 < 1e-24 {
            continue; // on the axis: du is undefined, the forms vanish there
        }
        let rho = rho2.sqrt();
        let du = (l.x * dl.y - l.y * dl.x) / rho2;
        let u = l.y.atan2(l.x);
        let drho = (l.x * dl.x + l.y * dl.y) / rho;
        let dv = match rev {
            Revolution::Cylinder { .. } | Revolution::Cone { .. } => dl.z,
            Revolution::Sphere { .. } => (rho * dl.z - l.z * drho) / (rho2 + l.z * l.z),
            Revolution::Torus { big, .. } => {
                let q = rho - big;
                (q * dl.z - l.z * drho) / (q * q + l.z * l.z)
            }
        };
        let v = match rev {
            Revolution::Torus { .. } => wrap_to(v_of(&l), centre),
            _ => v_of(&l),
        };
        let (g, rho_g, k) = rev.anchored_terms(v, anchor);
        let (su, cu) = u.sin_cos();
        a -= w * g * du;
        mx += w * rho_g * su * dv;
        my -= w * rho_g * cu * dv;
        mz -= w * k * du;
        wind += w * du;
    }
    let mut out = RevolutionIntegrals {
        frame,
        area: sigma * a,
        mx: sigma * mx,
        my: sigma * my,
        mz: sigma * mz,
        pole: None,
        warnings: Vec::new(),
    };
    if !has_edges {
        return without_boundary(rev, out);
    }
    let winding = (sigma * wind / TAU).round() as i64;
    if winding != 0 {
        add_pole_term(&mut out, rev, winding, anchor, surface);
    }
    out
}

/// A closed surface without boundary: the whole sphere or torus.
fn without_boundary(rev: &Revolution, mut out: RevolutionIntegrals) -> RevolutionIntegrals {
    match *rev {
        Revolution::Sphere { r } => out.area = 2.0 * TAU * r * r,
        Revolution::Torus { big, r } => out.area = TAU * TAU * big * r,
        _ => out
            .warnings
            .push("unbounded face without edges: area unknown".into()),
    }
    out.mx = 0.0;
    out.my = 0.0;
    out.mz = 0.0;
    out
}

/// A boundary winding around the axis encloses the pole (or apex) too:
/// add its term.
fn add_pole_term(
    out: &mut RevolutionIntegrals,
    rev: &Revolution,
    winding: i64,
    anchor: Option<(f64, f64)>,
    surface: &Surface,
) {
    match rev.pole(winding) {
        Some((v, at)) => {
            let (g, _, k) = rev.anchored_terms(v, anchor);
            out.area += TAU * winding as f64 * g;
            out.mz += TAU * winding as f64 * k;
            out.pole = Some(at);
        }
        None => out.warnings.push(format!(
            "boundary winds {winding} times around the axis of a {}",
            surface.kind_name()
        )),
    }
}
