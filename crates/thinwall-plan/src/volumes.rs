//! Layers as solids: each step-approach layer is a box swept from one
//! corner along its three edges with `truck-modeling` (no booleans), and
//! written as STEP by `truck-stepio`. truck uses cgmath: points cross the
//! boundary here and nowhere else.

use crate::types::Layer;
use truck_modeling::{builder, Point3, Solid};

/// The layer's box as a truck solid, outward oriented.
pub fn layer_solid(layer: &Layer) -> Solid {
    let c = &layer.corners;
    // Corners are ordered height-major, then length, then the normal
    // (steps.rs): 0 origin, 1 across the normal, 2 along the length, 4 up
    // the height.
    let p = |i: usize| Point3::new(c[i][0], c[i][1], c[i][2]);
    let (o, a, b, h) = (p(0), p(1), p(2), p(4));
    let (mut e1, mut e2, e3) = (a - o, b - o, h - o);
    use truck_modeling::InnerSpace;
    if e1.cross(e2).dot(e3) < 0.0 {
        std::mem::swap(&mut e1, &mut e2);
    }
    let v = builder::vertex(o);
    let edge = builder::tsweep(&v, e1);
    let face = builder::tsweep(&edge, e2);
    builder::tsweep(&face, e3)
}

/// The layer's solid as STEP text (AP203/214, as truck writes it).
pub fn layer_step(layer: &Layer) -> String {
    use truck_stepio::out::{CompleteStepDisplay, StepHeaderDescriptor, StepModel};
    let solid = layer_solid(layer).compress();
    CompleteStepDisplay::new(
        StepModel::from(&solid),
        StepHeaderDescriptor {
            file_name: format!("{}.step", layer.id),
            organization_system: "thinwall".to_string(),
            ..Default::default()
        },
    )
    .to_string()
}

/// A feature solid as a truck solid: between two planes by
/// [`planar_solid`]; bounded by a half cylinder over a rectangle along its
/// axis by [`swept_solid`]. `None` for the rest (a cone, a cylinder over
/// another shape: not written yet).
pub fn feature_solid(frame: &[[f64; 3]; 4], s: &crate::types::FeatureSolid) -> Option<Solid> {
    use thinwall_removal::pieces::Height;
    match (&s.lower, &s.upper) {
        (Height::Plane { .. }, Height::Plane { .. }) => planar_solid(frame, s),
        (Height::Cylinder { .. }, _) | (_, Height::Cylinder { .. }) => swept_solid(frame, s),
        _ => None,
    }
}

/// A point of the removal frame in world coordinates.
fn to_world(frame: &[[f64; 3]; 4], x: f64, y: f64, z: f64) -> Point3 {
    let c = |k: usize| frame[0][k] + x * frame[1][k] + y * frame[2][k] + z * frame[3][k];
    Point3::new(c(0), c(1), c(2))
}

/// A solid bounded below or above by a half cylinder about a horizontal
/// axis, over a rectangle along that axis: its profile square to the axis
/// (arcs where a bound is the cylinder, lines where it is a plane level
/// along the axis) swept along it. `None` where the region is not such a
/// rectangle.
pub fn swept_solid(frame: &[[f64; 3]; 4], s: &crate::types::FeatureSolid) -> Option<Solid> {
    use thinwall_removal::pieces::Height;
    let (o, a) = match (&s.lower, &s.upper) {
        (Height::Cylinder { o, a, .. }, _) | (_, Height::Cylinder { o, a, .. }) => (*o, *a),
        _ => return None,
    };
    if s.rings.len() != 1 {
        return None;
    }
    let r = AxisRect::of(&s.rings[0], o, a)?;
    // A plane bound must be level along the axis.
    for h in [&s.lower, &s.upper] {
        if let Height::Plane { gx, gy, .. } = h {
            if (gx * a[0] + gy * a[1]).abs() > 1e-9 {
                return None;
            }
        }
    }
    let face = profile_face(frame, s, o, a, &r)?;
    let d = frame_vector(frame, a[0] * (r.s1 - r.s0), a[1] * (r.s1 - r.s0));
    Some(builder::tsweep(&face, d))
}

/// A region that is a rectangle in (u, s), across and along a horizontal
/// axis through `o` along `a`: its sides, size and tolerance, mm.
struct AxisRect {
    u0: f64,
    u1: f64,
    s0: f64,
    s1: f64,
    size: f64,
    tol: f64,
}

impl AxisRect {
    /// `None` where the ring is not such a rectangle.
    fn of(ring: &[[f64; 2]], o: [f64; 3], a: [f64; 2]) -> Option<Self> {
        // (u, s): across and along the axis.
        let us = |p: &[f64; 2]| {
            let (dx, dy) = (p[0] - o[0], p[1] - o[1]);
            (-dx * a[1] + dy * a[0], dx * a[0] + dy * a[1])
        };
        let pts: Vec<(f64, f64)> = ring.iter().map(us).collect();
        let (u0, u1, s0, s1) = pts.iter().fold(
            (
                f64::INFINITY,
                f64::NEG_INFINITY,
                f64::INFINITY,
                f64::NEG_INFINITY,
            ),
            |m, p| (m.0.min(p.0), m.1.max(p.0), m.2.min(p.1), m.3.max(p.1)),
        );
        let size = (u1 - u0).max(s1 - s0);
        let tol = 1e-7 * size.max(1.0);
        let on_side = |p: &(f64, f64)| {
            (p.0 - u0).abs() < tol
                || (p.0 - u1).abs() < tol
                || (p.1 - s0).abs() < tol
                || (p.1 - s1).abs() < tol
        };
        let rect = (u1 - u0) * (s1 - s0);
        let area: f64 = {
            let mut sum = 0.0;
            for i in 0..pts.len() {
                let (p, q) = (pts[i], pts[(i + 1) % pts.len()]);
                sum += p.0 * q.1 - q.0 * p.1;
            }
            0.5 * sum.abs()
        };
        if !pts.iter().all(on_side) || (area - rect).abs() > 1e-9 * rect.max(1.0) {
            return None;
        }
        Some(Self {
            u0,
            u1,
            s0,
            s1,
            size,
            tol,
        })
    }
}

/// The profile of a swept solid square to its axis, at s = s0: arcs where
/// a bound is the cylinder, lines where it is a plane, and the vertical
/// sides where the bounds do not meet.
fn profile_face(
    frame: &[[f64; 3]; 4],
    s: &crate::types::FeatureSolid,
    o: [f64; 3],
    a: [f64; 2],
    r: &AxisRect,
) -> Option<truck_modeling::Face> {
    use thinwall_removal::pieces::Height;
    use truck_modeling::Wire;
    let (size, tol, s0) = (r.size, r.tol, r.s0);
    // An end within the sliver width of the cylinder's silhouette is on it:
    // there the height is a square root, and the arrangement's rounding of
    // 1e-8 in u would stand a wall of microns between the two halves.
    let radius = [&s.lower, &s.upper]
        .iter()
        .filter_map(|h| match h {
            Height::Cylinder { r, .. } => Some(*r),
            _ => None,
        })
        .fold(0.0, f64::max);
    let snap = |u: f64| match (u.abs() - radius).abs()
        <= thinwall_geom::tolerance::SLIVER_WIDTH * size.max(1.0)
    {
        true => radius.copysign(u),
        false => u,
    };
    let (u0, u1) = (snap(r.u0), snap(r.u1));
    // Frame coordinates of a profile point at (u, z), at s = s0.
    let at = |u: f64, z: f64| {
        let (x, y) = (o[0] + a[0] * s0 - a[1] * u, o[1] + a[1] * s0 + a[0] * u);
        to_world(frame, x, y, z)
    };
    let (zl0, zl1) = (s.lower.at_us(&o, &a, u0, s0), s.lower.at_us(&o, &a, u1, s0));
    let (zu0, zu1) = (s.upper.at_us(&o, &a, u0, s0), s.upper.at_us(&o, &a, u1, s0));
    let meet = |p: f64, q: f64| (p - q).abs() <= tol;
    let v_l0 = builder::vertex(at(u0, zl0));
    let v_l1 = builder::vertex(at(u1, zl1));
    let v_u1 = if meet(zl1, zu1) {
        v_l1.clone()
    } else {
        builder::vertex(at(u1, zu1))
    };
    let v_u0 = if meet(zl0, zu0) {
        v_l0.clone()
    } else {
        builder::vertex(at(u0, zu0))
    };
    let bound_edge = |h: &Height,
                      from: &truck_modeling::Vertex,
                      to: &truck_modeling::Vertex,
                      ua: f64,
                      ub: f64| {
        match h {
            Height::Cylinder { .. } => {
                let um = 0.5 * (ua + ub);
                builder::circle_arc(from, to, at(um, h.at_us(&o, &a, um, s0)))
            }
            _ => builder::line(from, to),
        }
    };
    let mut edges = vec![bound_edge(&s.lower, &v_l0, &v_l1, u0, u1)];
    if !meet(zl1, zu1) {
        edges.push(builder::line(&v_l1, &v_u1));
    }
    edges.push(bound_edge(&s.upper, &v_u1, &v_u0, u1, u0));
    if !meet(zl0, zu0) {
        edges.push(builder::line(&v_u0, &v_l0));
    }
    let wire: Wire = edges.into();
    builder::try_attach_plane(&[wire]).ok()
}

/// A vector of the removal frame's xy plane in world coordinates.
fn frame_vector(frame: &[[f64; 3]; 4], x: f64, y: f64) -> truck_modeling::Vector3 {
    let c = |k: usize| x * frame[1][k] + y * frame[2][k];
    truck_modeling::Vector3::new(c(0), c(1), c(2))
}

/// A solid between two planes: its rings at the lower and the upper
/// height, joined by vertical quads (faces attached to shared edges, so
/// the shell is closed). `None` where its two ends meet or a bound is not
/// a plane.
pub fn planar_solid(frame: &[[f64; 3]; 4], s: &crate::types::FeatureSolid) -> Option<Solid> {
    use thinwall_removal::pieces::Height;
    use truck_modeling::{Edge, Face, Shell, Vertex, Wire};
    if !matches!(s.lower, Height::Plane { .. }) || !matches!(s.upper, Height::Plane { .. }) {
        return None;
    }
    let world = |x: f64, y: f64, z: f64| to_world(frame, x, y, z);
    let knife = knife_edge(s);
    let mut bottom_wires = Vec::new();
    let mut top_wires = Vec::new();
    let mut sides: Vec<Face> = Vec::new();
    let mut thick = false;
    for ring in &s.rings {
        let n = ring.len();
        if n < 3 {
            return None;
        }
        // Where the bounds meet (a wedge beside a drafted wall) the top
        // and bottom corners are one vertex, and no upright edge joins them.
        let mut vb: Vec<Vertex> = Vec::with_capacity(n);
        let mut vt: Vec<Vertex> = Vec::with_capacity(n);
        let mut meet = Vec::with_capacity(n);
        for p in ring {
            let (zl, zu) = (s.lower.at(p[0], p[1]), s.upper.at(p[0], p[1]));
            if zu - zl < -knife {
                return None;
            }
            let b = builder::vertex(world(
                p[0],
                p[1],
                if zu - zl <= knife {
                    0.5 * (zl + zu)
                } else {
                    zl
                },
            ));
            meet.push(zu - zl <= knife);
            thick |= zu - zl > knife;
            vt.push(if zu - zl <= knife {
                b.clone()
            } else {
                builder::vertex(world(p[0], p[1], zu))
            });
            vb.push(b);
        }
        let eb: Vec<Edge> = (0..n)
            .map(|i| builder::line(&vb[i], &vb[(i + 1) % n]))
            .collect();
        let et: Vec<Edge> = (0..n)
            .map(|i| match meet[i] && meet[(i + 1) % n] {
                true => eb[i].clone(),
                false => builder::line(&vt[i], &vt[(i + 1) % n]),
            })
            .collect();
        let ev: Vec<Option<Edge>> = (0..n)
            .map(|i| (!meet[i]).then(|| builder::line(&vb[i], &vt[i])))
            .collect();
        for i in 0..n {
            let j = (i + 1) % n;
            if meet[i] && meet[j] {
                continue;
            }
            let mut w: Vec<Edge> = vec![eb[i].clone()];
            w.extend(ev[j].clone());
            w.push(et[i].inverse());
            w.extend(ev[i].as_ref().map(|e| e.inverse()));
            sides.push(builder::try_attach_plane(&[w.into_iter().collect::<Wire>()]).ok()?);
        }
        // The bottom runs against the ring (its normal points down), the
        // top along it.
        let bottom: Wire = eb.iter().rev().map(|e| e.inverse()).collect();
        let top: Wire = et.iter().cloned().collect();
        bottom_wires.push(bottom);
        top_wires.push(top);
    }
    if !thick {
        return None;
    }
    let mut faces = vec![
        builder::try_attach_plane(&bottom_wires).ok()?,
        builder::try_attach_plane(&top_wires).ok()?,
    ];
    faces.extend(sides);
    Solid::try_new(vec![Shell::from(faces)]).ok()
}

/// How close a solid's bounds may come at a corner and still meet there:
/// a millionth of its extent (a steep drafted face turns the rounding of
/// where the bounds cross into a height).
fn knife_edge(s: &crate::types::FeatureSolid) -> f64 {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in s.rings.iter().flatten() {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    thinwall_geom::tolerance::SLIVER_WIDTH * (hi[0] - lo[0]).hypot(hi[1] - lo[1])
}

/// A feature's solids as one STEP text, and how many could not be written.
pub fn feature_step(
    plan: &crate::types::Plan,
    f: &crate::types::RemovalFeature,
) -> (String, usize) {
    let solids: Vec<Solid> = f
        .solids
        .iter()
        .filter_map(|s| feature_solid(&plan.frame, s))
        .collect();
    let skipped = f.solids.len() - solids.len();
    (solids_step(&solids, f.id.as_str()), skipped)
}

/// Solids as one STEP text named `name`.
pub fn solids_step(solids: &[Solid], name: &str) -> String {
    use truck_stepio::out::{CompleteStepDisplay, StepHeaderDescriptor, StepModels};
    let compressed: Vec<_> = solids.iter().map(|s| s.compress()).collect();
    let models: StepModels<_, _, _> = compressed.iter().collect();
    CompleteStepDisplay::new(
        models,
        StepHeaderDescriptor {
            file_name: format!("{name}.step"),
            organization_system: "thinwall".to_string(),
            ..Default::default()
        },
    )
    .to_string()
}

/// A feature's solids as a part of their own (one body per solid; what
/// cannot be built is left out), for viewers.
pub fn feature_part(
    plan: &crate::types::Plan,
    f: &crate::types::RemovalFeature,
) -> Option<thinwall_brep::Part> {
    let solids: Vec<(String, Solid)> = f
        .solids
        .iter()
        .enumerate()
        .filter_map(|(i, s)| {
            Some((
                format!("{}#{}", f.id, i + 1),
                feature_solid(&plan.frame, s)?,
            ))
        })
        .collect();
    if solids.is_empty() {
        return None;
    }
    let named: Vec<(String, &Solid)> = solids.iter().map(|(n, s)| (n.clone(), s)).collect();
    crate::solid_part::part_of(&named).ok()
}
