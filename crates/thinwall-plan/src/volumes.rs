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
