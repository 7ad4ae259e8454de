//! The step approach per thin wall (Popma §4.1.1, fig. 4.1; DOMAIN.md
//! §5): the material beside a peripherally milled wall (rib, flange,
//! wall) split along its height into layers, large ones (`H_RF`) on one
//! side and small ones (`h_RF`) on the other, each `B_RF` wide, taken
//! alternately so the wall is always supported below the cut: the first
//! large layer, then the small layers down to its depth, then the next
//! large layer, and so on to the foot.
//!
//! Which side gets the large layers (§5.2): the side facing up for a wall
//! lying flat; otherwise the side with more stiffness features standing on
//! it; on a tie, the side facing more up, then side 0.
//!
//! This is the first part of issue 14: layers as boxes in the wall's
//! frame, their heights in the set-up, owners and the order within each
//! wall and across walls. Solids, interference, bulk features and
//! classification are still to come. Webs (face milling) get no layers
//! yet.

pub use crate::types::{Layer, SizeClass};

use crate::scene::Scene;
use crate::sequence::Sequence;
use crate::types::{Axis, WallShape};
use crate::types::{VolumeId, WallPlan};
use std::collections::BTreeMap;
use thinwall_analysis::FeatureId;
use thinwall_geom::tolerance::NEAR_PARALLEL_EPS;
use thinwall_geom::tolerance::SAME_LENGTH_MM;
use thinwall_geom::{Point3, Vector3};
use thinwall_pipeline::Outcome;

/// Layers of every sized thin wall, in an order that respects each wall's
/// step sequence and the stiffness-feature sequence (a wall that comes
/// later never starts before one that comes earlier ends).
pub fn layers(
    out: &Outcome,
    scene: &Scene,
    seq: &Sequence,
    walls: &[WallPlan],
    shapes: &BTreeMap<FeatureId, WallShape>,
) -> Vec<Layer> {
    let up = out.setup.up_in_part();
    let mut per_wall: BTreeMap<FeatureId, Vec<Layer>> = BTreeMap::new();
    for w in walls.iter().filter(|w| w.sizes.thin) {
        let Some(f) = out.recognition.feature(w.id) else {
            continue;
        };
        let Some(g) = &f.geometry else { continue };
        let Some(shape) = shapes.get(&w.id) else {
            continue;
        };
        let side = large_side(out, scene, w.id, g, &up);
        per_wall.insert(w.id, wall_layers(w, g, shape, side, &up));
    }
    // Walls in the plan's order (level by level), then each wall's steps.
    let mut ordered = Vec::new();
    for level in &seq.order {
        for id in level {
            if let Some(ls) = per_wall.remove(id) {
                ordered.extend(ls);
            }
        }
    }
    for (i, l) in ordered.iter_mut().enumerate() {
        l.id = VolumeId::new('V', i + 1);
    }
    ordered
}

/// The side (0 or 1) of the large layers (module docs).
pub(crate) fn large_side(
    out: &Outcome,
    scene: &Scene,
    id: FeatureId,
    g: &thinwall_recognize::WallGeometry,
    up: &Vector3,
) -> u8 {
    let n0 = g.frame.z;
    if n0.dot(up).abs() > 1.0 - NEAR_PARALLEL_EPS {
        return if n0.dot(up) > 0.0 { 0 } else { 1 };
    }
    let mid = g.frame.origin - n0 * (0.5 * g.thickness);
    let mut count = [0usize; 2];
    for f in &out.recognition.features {
        if scene.base.get(&f.id) != Some(&id) {
            continue;
        }
        let Some(c) = f.geometry.as_ref().map(|h| h.frame.origin) else {
            continue;
        };
        let s = (c - mid).dot(&n0);
        count[usize::from(s < 0.0)] += 1;
    }
    match count[0].cmp(&count[1]) {
        std::cmp::Ordering::Greater => 0,
        std::cmp::Ordering::Less => 1,
        std::cmp::Ordering::Equal if n0.dot(up) < -1e-9 => 1,
        std::cmp::Ordering::Equal => 0,
    }
}

/// A wall's layers in its own step order.
fn wall_layers(
    w: &WallPlan,
    g: &thinwall_recognize::WallGeometry,
    shape: &WallShape,
    large: u8,
    up: &Vector3,
) -> Vec<Layer> {
    let (h, big_h) = (w.sizes.h, w.sizes.big_h);
    // The recognised height (foot to free edge), down from the free edge:
    // the region may stop short of the foot where a fillet meets the base.
    let wall_h = w.sizes.wall.height;
    let axis = Axis::of(g, wall_h);
    let (hd, ld, foot) = (axis.height_dir, axis.length_dir, axis.foot);
    let (l0, l1) = axis.length;
    let mut out = Vec::new();
    let mut step = 0;
    let mut make = |side: u8, class: SizeClass, from: f64, to: f64| {
        step += 1;
        // Side 0 lies on frame.z's side of the wall, side 1 beyond the far face.
        let b = shape.width[usize::from(side)];
        let (n0, n1) = if side == 0 {
            (0.0, b)
        } else {
            (-g.thickness - b, -g.thickness)
        };
        let corner = |hh: f64, l: f64, n: f64| -> Point3 {
            g.frame.origin + hd * (foot + hh) + ld * l + g.frame.z * n
        };
        let mut corners: Vec<Point3> = Vec::with_capacity(8);
        for hh in [from, to] {
            for l in [l0, l1] {
                for n in [n0, n1] {
                    corners.push(corner(hh, l, n));
                }
            }
        }
        let zs: Vec<f64> = corners.iter().map(|p| p.coords.dot(up)).collect();
        Layer {
            id: VolumeId::default(),
            owner: w.id,
            side,
            size_class: class,
            step,
            from_foot: [from, to],
            z_range: [
                zs.iter().copied().fold(f64::INFINITY, f64::min),
                zs.iter().copied().fold(f64::NEG_INFINITY, f64::max),
            ],
            // A wall standing along up is cut at heights on its axis; a
            // web's layer (a slab over it) between its lowest and highest.
            cut_heights: if axis.stands_along(up) {
                [axis.height_along(up, from), axis.height_along(up, to)]
            } else {
                [
                    zs.iter().copied().fold(f64::INFINITY, f64::min),
                    zs.iter().copied().fold(f64::NEG_INFINITY, f64::max),
                ]
            },
            width: b,
            height: to - from,
            length: l1 - l0,
            corners: corners.iter().map(|p| [p.x, p.y, p.z]).collect(),
        }
    };
    let small = 1 - large;
    // From the top: a large layer, then the small ones down to its depth.
    for (from, to) in large_spans(wall_h, big_h, shape.align_at) {
        out.push(make(large, SizeClass::Large, from, to));
        let mut small_bottom = to;
        while small_bottom > from + SAME_LENGTH_MM {
            let top = small_bottom;
            let bottom = match small_bottom - h {
                v if v > from + SAME_LENGTH_MM => v,
                _ => from,
            };
            out.push(make(small, SizeClass::Small, bottom, top));
            small_bottom = bottom;
        }
    }
    out
}

/// The large layers' spans above the foot, from the top: `big_h` each,
/// the last one down to the foot; with a step separation line, the part
/// above it in equal layers no taller than `big_h`, so that one ends there.
fn large_spans(wall_h: f64, big_h: f64, align_at: Option<f64>) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    let mut bottom = wall_h;
    if let Some(line) = align_at.filter(|&a| a > SAME_LENGTH_MM && a < wall_h - SAME_LENGTH_MM) {
        let n = ((wall_h - line) / big_h - SAME_LENGTH_MM).ceil().max(1.0);
        let each = (wall_h - line) / n;
        for k in 0..n as usize {
            let to = wall_h - each * k as f64;
            out.push(((to - each).max(line), to));
        }
        bottom = line;
    }
    while bottom > SAME_LENGTH_MM {
        // A remainder within rounding of the foot is the foot.
        let from = match bottom - big_h {
            v if v > SAME_LENGTH_MM => v,
            _ => 0.0,
        };
        out.push((from, bottom));
        bottom = from;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::large_spans;

    #[test]
    fn large_layers_end_at_the_step_separation_line() {
        assert_eq!(
            large_spans(48.0, 24.0, None),
            vec![(24.0, 48.0), (0.0, 24.0)]
        );
        // Line at 30: 18 above it in one layer, then 24 and the rest.
        assert_eq!(
            large_spans(48.0, 24.0, Some(30.0)),
            vec![(30.0, 48.0), (6.0, 30.0), (0.0, 6.0)]
        );
        // 36 above a line at 12 with H 24: two layers of 18.
        assert_eq!(
            large_spans(48.0, 24.0, Some(12.0)),
            vec![(30.0, 48.0), (12.0, 30.0), (0.0, 12.0)]
        );
    }
}
