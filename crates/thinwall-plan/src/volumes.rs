//! Layers as solids: each step-approach layer is a box swept from one
//! corner along its three edges with `truck-modeling` (no booleans), and
//! written as STEP by `truck-stepio`. truck uses cgmath: points cross the
//! boundary here and nowhere else.

use crate::steps::Layer;
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

/// A feature solid between two planes as a truck solid: its rings at the
/// lower and the upper height, joined by vertical quads (faces attached
/// to shared edges, so the shell is closed). `None` for a solid bounded
/// by a cylinder or a cone (not written yet) or one whose two ends meet.
pub fn feature_solid(frame: &[[f64; 3]; 4], s: &crate::features::FeatureSolid) -> Option<Solid> {
    use crate::removal::pieces::Height;
    use truck_modeling::{Edge, Face, Shell, Vertex, Wire};
    if !matches!(s.lower, Height::Plane { .. }) || !matches!(s.upper, Height::Plane { .. }) {
        return None;
    }
    let world = |x: f64, y: f64, z: f64| {
        let c = |k: usize| frame[0][k] + x * frame[1][k] + y * frame[2][k] + z * frame[3][k];
        Point3::new(c(0), c(1), c(2))
    };
    let mut bottom_wires = Vec::new();
    let mut top_wires = Vec::new();
    let mut sides: Vec<Face> = Vec::new();
    for ring in &s.rings {
        let n = ring.len();
        if n < 3 {
            return None;
        }
        let mut vb: Vec<Vertex> = Vec::with_capacity(n);
        let mut vt: Vec<Vertex> = Vec::with_capacity(n);
        for p in ring {
            let (zl, zu) = (s.lower.at(p[0], p[1]), s.upper.at(p[0], p[1]));
            if zu - zl <= 1e-9 * zu.abs().max(1.0) {
                return None;
            }
            vb.push(builder::vertex(world(p[0], p[1], zl)));
            vt.push(builder::vertex(world(p[0], p[1], zu)));
        }
        let eb: Vec<Edge> = (0..n)
            .map(|i| builder::line(&vb[i], &vb[(i + 1) % n]))
            .collect();
        let et: Vec<Edge> = (0..n)
            .map(|i| builder::line(&vt[i], &vt[(i + 1) % n]))
            .collect();
        let ev: Vec<Edge> = (0..n).map(|i| builder::line(&vb[i], &vt[i])).collect();
        for i in 0..n {
            let j = (i + 1) % n;
            let w: Wire = vec![
                eb[i].clone(),
                ev[j].clone(),
                et[i].inverse(),
                ev[i].inverse(),
            ]
            .into();
            sides.push(builder::try_attach_plane(&[w]).ok()?);
        }
        // The bottom runs against the ring (its normal points down), the
        // top along it.
        let bottom: Wire = eb.iter().rev().map(|e| e.inverse()).collect();
        let top: Wire = et.iter().cloned().collect();
        bottom_wires.push(bottom);
        top_wires.push(top);
    }
    let mut faces = vec![
        builder::try_attach_plane(&bottom_wires).ok()?,
        builder::try_attach_plane(&top_wires).ok()?,
    ];
    faces.extend(sides);
    Solid::try_new(vec![Shell::from(faces)]).ok()
}

/// A feature's solids as one STEP text, and how many could not be written.
pub fn feature_step(plan: &crate::Plan, f: &crate::features::RemovalFeature) -> (String, usize) {
    let solids: Vec<Solid> = f
        .solids
        .iter()
        .filter_map(|s| feature_solid(&plan.frame, s))
        .collect();
    let skipped = f.solids.len() - solids.len();
    (solids_step(&solids, &f.id), skipped)
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
