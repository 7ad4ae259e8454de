//! Adaptations of the step approach to what is in and on a wall (Popma
//! §4.1.3; DOMAIN.md §5.2). Each one changed is reported with its rule.
//!
//! - **Connected walls** (fig. 4.6): a wall standing on a thin web gets
//!   its layers on the web's side no wider than the web's permissible
//!   height there (`H_RF` on the web's large side, `h_RF` on the other).
//! - **Large cut-outs** (fig. 4.7c): a cut-out deeper than the wall's
//!   `h_RF` weakens it: the wall is sized again as the shortest piece of
//!   wall left between its cut-outs and ends.
//! - **Cut-outs** (fig. 4.7b): a cut-out's feature goes into its wall's
//!   sequence right after the first layer that reaches its bottom (the
//!   large one, unless that had nothing to remove).
//! - **Large holes** (fig. 4.8): a hole taller than 1.5 × the tool is
//!   large; the wall's layers get a boundary at the step separation line,
//!   2 × the tool below the top of its highest large hole. A large hole the
//!   line crosses is two features (`hole_splits`, cut in `features.rs`);
//!   the part above the line comes after the layers above it and before
//!   those below. Small holes, and the parts below the line, come once the
//!   layers down to their bottom are out, before those below.
//! - **Chamfers** (fig. 4.10): a chamfer's material is a feature of its
//!   own (`features.rs`); a large one (wider than the wall's `h_RF`: our
//!   reading, Popma gives no figure) before all of its wall's layers, a
//!   small one after the first layer on each side.
//!
//! Not done: a lower part taller than the wall's `H_RF` is not split again,
//! and a capped width is applied to the whole side rather than only where
//! the web's layers are (fig. 4.6a's ellipse).

pub use crate::types::{AdaptRule, Adaptation, Axis, HoleSplit, WallShape};

use crate::scene::Scene;
use crate::sizing::{size_wall, WallDimensions};
use crate::types::Layer;
use crate::types::RemovalFeature;
use crate::types::{LayerConstraint, VolumeId, WallPlan};
use std::collections::{BTreeMap, HashMap};
use thinwall_analysis::measure::boundary_points;
use thinwall_analysis::{FeatureId, StiffnessKind};
use thinwall_brep::{FaceId, Part};
use thinwall_geom::tolerance::NEAR_PARALLEL_EPS;
use thinwall_geom::{Point3, Vector3};
use thinwall_pipeline::Outcome;
use thinwall_recognize::{StiffnessFeature, WallGeometry};

impl Axis {
    pub fn of(g: &WallGeometry, height: f64) -> Self {
        let hd = g.height_direction;
        let ld = g.frame.z.cross(&hd).normalize();
        let outline = g.outline();
        let along = |d: &Vector3| span(outline.iter(), &g.frame.origin, d);
        let (_, top) = along(&hd);
        Self {
            origin: g.frame.origin,
            height_dir: hd,
            length_dir: ld,
            foot: top - height,
            height,
            length: along(&ld),
        }
    }
}

impl Axis {
    /// The height along `up` of the wall's axis `from_foot` mm above its
    /// foot.
    pub fn height_along(&self, up: &Vector3, from_foot: f64) -> f64 {
        (self.origin + self.height_dir * (self.foot + from_foot))
            .coords
            .dot(up)
    }

    /// Whether the wall stands along `up` (or hangs along it).
    pub fn stands_along(&self, up: &Vector3) -> bool {
        self.height_dir.dot(up).abs() > 1.0 - NEAR_PARALLEL_EPS
    }
}

fn span<'p>(pts: impl Iterator<Item = &'p Point3>, origin: &Point3, d: &Vector3) -> (f64, f64) {
    pts.map(|p| (p - origin).dot(d))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| {
            (lo.min(x), hi.max(x))
        })
}

/// The part's faces by step id, to measure features.
pub struct Faces<'a> {
    part: &'a Part,
    by_step: HashMap<u64, FaceId>,
}

impl<'a> Faces<'a> {
    pub fn new(part: &'a Part) -> Self {
        Self {
            part,
            by_step: part.face_ids().map(|f| (part.face(f).step_id, f)).collect(),
        }
    }

    /// Boundary points of a feature's faces.
    fn points(&self, f: &StiffnessFeature) -> Vec<Point3> {
        f.faces
            .iter()
            .filter_map(|s| self.by_step.get(s))
            .flat_map(|&face| boundary_points(self.part, face))
            .collect()
    }

    /// A feature's lowest and highest height above a wall's foot.
    fn heights(&self, f: &StiffnessFeature, axis: &Axis) -> Option<(f64, f64)> {
        let pts = self.points(f);
        (!pts.is_empty()).then(|| {
            let (lo, hi) = span(pts.iter(), &axis.origin, &axis.height_dir);
            (lo - axis.foot, hi - axis.foot)
        })
    }

    /// A feature's extent along a wall's length.
    fn along(&self, f: &StiffnessFeature, axis: &Axis) -> Option<(f64, f64)> {
        let pts = self.points(f);
        (!pts.is_empty()).then(|| span(pts.iter(), &axis.origin, &axis.length_dir))
    }
}

/// A wall's geometry from the recognition.
fn geometry(out: &Outcome, id: FeatureId) -> Option<&WallGeometry> {
    out.recognition
        .feature(id)
        .and_then(|f| f.geometry.as_ref())
}

/// The depressions and details in or on `wall`, of `kind`.
fn on_wall(out: &Outcome, wall: FeatureId, kind: StiffnessKind) -> Vec<&StiffnessFeature> {
    out.recognition
        .features
        .iter()
        .filter(|f| f.kind == kind && f.wall == Some(wall))
        .collect()
}

/// Adapt the walls' sizes and layouts; `walls` are re-sized in place.
pub fn shapes(
    faces: &Faces,
    out: &Outcome,
    scene: &Scene,
    walls: &mut [WallPlan],
) -> (BTreeMap<FeatureId, WallShape>, Vec<Adaptation>) {
    let mut log = Vec::new();
    let mut shapes = BTreeMap::new();
    for w in walls.iter_mut().filter(|w| w.sizes.thin) {
        let Some(g) = geometry(out, w.id) else {
            continue;
        };
        resize_for_cutouts(faces, out, w, g, &mut log);
        let axis = Axis::of(g, w.sizes.wall.height);
        let align_at = step_separation_line(faces, out, w, &axis, &mut log);
        let b = w.sizes.b;
        shapes.insert(
            w.id,
            WallShape {
                width: [b, b],
                align_at,
            },
        );
    }
    connected_walls(out, scene, walls, &mut shapes, &mut log);
    (shapes, log)
}

/// Large cut-outs: size the wall as the shortest piece of it they leave.
fn resize_for_cutouts(
    faces: &Faces,
    out: &Outcome,
    w: &mut WallPlan,
    g: &WallGeometry,
    log: &mut Vec<Adaptation>,
) {
    let axis = Axis::of(g, w.sizes.wall.height);
    let cutouts = on_wall(out, w.id, StiffnessKind::Cutout);
    let large: Vec<&&StiffnessFeature> = cutouts
        .iter()
        .filter(|c| {
            c.height
                .is_some_and(|d| d > w.sizes.h + thinwall_geom::tolerance::SAME_LENGTH_MM)
        })
        .collect();
    let Some(first) = large.first() else {
        return;
    };
    let spans: Vec<(f64, f64)> = large.iter().filter_map(|c| faces.along(c, &axis)).collect();
    let shortest = shortest_piece(axis.length, &spans);
    if !shortest.is_finite() || shortest >= w.sizes.wall.length {
        return;
    }
    let dims = WallDimensions {
        length: shortest,
        ..w.sizes.wall
    };
    let Ok(sizes) = size_wall(&dims, &w.sizes.parameters) else {
        return;
    };
    if (sizes.b, sizes.h, sizes.big_h) == (w.sizes.b, w.sizes.h, w.sizes.big_h) {
        return;
    }
    log.push(Adaptation {
        wall: w.id,
        by: first.id,
        rule: AdaptRule::LargeCutouts,
        change: format!(
            "{} large cut-out(s) leave a shortest wall of {:.1} mm: sized as that wall, B_RF {:.1} → {:.1}, h_RF {:.1} → {:.1}, H_RF {:.1} → {:.1} mm",
            large.len(),
            shortest,
            w.sizes.b,
            sizes.b,
            w.sizes.h,
            sizes.h,
            w.sizes.big_h,
            sizes.big_h
        ),
    });
    w.sizes = sizes;
}

/// Large holes: the step separation line, 2 × the tool below the top of
/// the highest large hole.
fn step_separation_line(
    faces: &Faces,
    out: &Outcome,
    w: &WallPlan,
    axis: &Axis,
    log: &mut Vec<Adaptation>,
) -> Option<f64> {
    let tool = out.request.config.thresholds.preferred_tool_diameter_mm;
    let (top, hole) = on_wall(out, w.id, StiffnessKind::Hole)
        .into_iter()
        .filter(|h| h.large == Some(true))
        .filter_map(|h| Some((faces.heights(h, axis)?.1, h.id)))
        .max_by(|a, b| a.0.total_cmp(&b.0))?;
    let line = top - 2.0 * tool;
    if line <= thinwall_geom::tolerance::SAME_LENGTH_MM
        || line >= axis.height - thinwall_geom::tolerance::SAME_LENGTH_MM
    {
        return None;
    }
    log.push(Adaptation {
        wall: w.id,
        by: hole,
        rule: AdaptRule::LargeHoles,
        change: format!(
            "layers aligned at the step separation line {line:.1} mm above the foot (2 × the Ø{tool} tool below the top of {hole})"
        ),
    });
    Some(line)
}

/// Connected walls: a wall on a thin web, no wider on the web's side than
/// the web's permissible height there.
fn connected_walls(
    out: &Outcome,
    scene: &Scene,
    walls: &[WallPlan],
    shapes: &mut BTreeMap<FeatureId, WallShape>,
    log: &mut Vec<Adaptation>,
) {
    let up = out.setup.up_in_part();

    for leaf in walls.iter().filter(|w| w.kind != StiffnessKind::Web) {
        let Some(&web_id) = scene.base.get(&leaf.id) else {
            continue;
        };
        let Some(web) = walls
            .iter()
            .find(|w| w.id == web_id && w.kind == StiffnessKind::Web)
        else {
            continue;
        };
        let (Some(gl), Some(gw), Some(shape)) = (
            geometry(out, leaf.id),
            geometry(out, web_id),
            shapes.get_mut(&leaf.id),
        ) else {
            continue;
        };
        // A web its sizes cannot hold (deflection over the limit) gives
        // no permissible height to respect.
        if !web.sizes.thin || web.sizes.deflection_mm > web.sizes.parameters.allowed_deflection_mm {
            continue;
        }
        // The web's side the leaf stands on (its height runs away from
        // it: for a wall through the web, the side this set-up machines),
        // and its permissible height.
        let web_side = u8::from(gl.height_direction.dot(&gw.frame.z) < 0.0);
        let large = crate::steps::large_side(out, scene, web_id, gw, &up);
        let cap = if web_side == large {
            web.sizes.big_h
        } else {
            web.sizes.h
        };
        // The leaf's sides the web reaches out from.
        let tol = thinwall_geom::tolerance::SAME_LENGTH_MM.max(1e-6 * gl.thickness);
        let d: Vec<f64> = gw
            .outline()
            .iter()
            .map(|p| (p - gl.frame.origin).dot(&gl.frame.z))
            .collect();
        let over = [
            d.iter().any(|&x| x > tol),
            d.iter().any(|&x| x < -gl.thickness - tol),
        ];
        for (k, &reaches) in over.iter().enumerate() {
            if reaches && cap < shape.width[k] - thinwall_geom::tolerance::SAME_LENGTH_MM {
                log.push(Adaptation {
                    wall: leaf.id,
                    by: web_id,
                    rule: AdaptRule::ConnectedWall,
                    change: format!(
                        "side {k}: layers {:.1} mm wide, not {:.1}: the web {web_id}'s permissible height on that side (fig. 4.6)",
                        cap, shape.width[k]
                    ),
                });
                shape.width[k] = cap;
            }
        }
    }
}

/// The large holes their wall's step separation line crosses.
pub fn hole_splits(
    faces: &Faces,
    out: &Outcome,
    walls: &[WallPlan],
    shapes: &BTreeMap<FeatureId, WallShape>,
) -> Vec<HoleSplit> {
    let up = out.setup.up_in_part();
    let tol = thinwall_geom::tolerance::SAME_LENGTH_MM;
    let mut splits = Vec::new();
    for w in walls {
        let (Some(line), Some(g)) = (
            shapes.get(&w.id).and_then(|s| s.align_at),
            geometry(out, w.id),
        ) else {
            continue;
        };
        let axis = Axis::of(g, w.sizes.wall.height);
        // Only a wall standing along up has the line at one height.
        if axis.height_dir.dot(&up).abs() < 1.0 - thinwall_geom::tolerance::NEAR_PARALLEL_EPS {
            continue;
        }
        let z = (axis.origin + axis.height_dir * (axis.foot + line))
            .coords
            .dot(&up);
        for h in on_wall(out, w.id, StiffnessKind::Hole) {
            let crosses = faces
                .heights(h, &axis)
                .is_some_and(|(lo, hi)| lo < line - tol && hi > line + tol);
            if h.large == Some(true) && crosses {
                splits.push(HoleSplit {
                    hole: h.id,
                    faces: h.faces.clone(),
                    z,
                });
            }
        }
    }
    splits
}

/// Sequence relations the adaptations add between features: depressions
/// into their wall's sequence, chamfers before or after it.
pub fn relations(
    faces: &Faces,
    out: &Outcome,
    walls: &[WallPlan],
    shapes: &BTreeMap<FeatureId, WallShape>,
    layers: &[Layer],
    features: &[RemovalFeature],
    log: &mut Vec<Adaptation>,
) -> Vec<LayerConstraint> {
    let mut rel = Vec::new();
    for w in walls {
        let Some(g) = geometry(out, w.id) else {
            continue;
        };
        // The wall's layers that remain (a vanished one removes nothing
        // that needs ordering).
        let mine: Vec<&Layer> = layers
            .iter()
            .filter(|l| l.owner == w.id && features.iter().any(|f| f.id == l.id))
            .collect();
        if mine.is_empty() {
            continue;
        }
        let wall = InSequence {
            faces,
            out,
            w,
            axis: Axis::of(g, w.sizes.wall.height),
            mine,
            features,
        };
        wall.cutouts(&mut rel, log);
        wall.holes(shapes.get(&w.id).and_then(|s| s.align_at), &mut rel, log);
        wall.chamfers(&mut rel, log);
    }
    rel
}

/// One wall's remaining layers, with what the relations of the details on
/// it read.
struct InSequence<'a> {
    faces: &'a Faces<'a>,
    out: &'a Outcome,
    w: &'a WallPlan,
    axis: Axis,
    mine: Vec<&'a Layer>,
    features: &'a [RemovalFeature],
}

impl InSequence<'_> {
    /// The removal features a detail owns.
    fn owned(&self, id: FeatureId) -> Vec<&VolumeId> {
        self.features
            .iter()
            .filter(|f| f.owner == Some(id))
            .map(|f| &f.id)
            .collect()
    }

    /// A cut-out after the first layer reaching down to its bottom.
    fn cutouts(&self, rel: &mut Vec<LayerConstraint>, log: &mut Vec<Adaptation>) {
        for c in on_wall(self.out, self.w.id, StiffnessKind::Cutout) {
            let Some(bottom) = c.height.map(|d| self.axis.height - d) else {
                continue;
            };
            // The first layer (in step order: the large one where it
            // remains) reaching down to its bottom.
            let Some(after) = self
                .mine
                .iter()
                .find(|l| l.from_foot[0] <= bottom + thinwall_geom::tolerance::SAME_LENGTH_MM)
            else {
                continue;
            };
            for f in self.owned(c.id) {
                rel.push(LayerConstraint {
                    before: after.id.clone(),
                    after: f.clone(),
                    why: format!(
                        "{} inserted into {}'s step approach (§4.1.3)",
                        c.id, self.w.id
                    ),
                });
            }
            if !self.owned(c.id).is_empty() {
                log.push(Adaptation {
                    wall: self.w.id,
                    by: c.id,
                    rule: AdaptRule::CutoutInSequence,
                    change: format!(
                        "{} after {}, the first {:?} layer down to its bottom",
                        c.id, after.id, after.size_class
                    ),
                });
            }
        }
    }

    /// A hole once the layers above where it is exposed are out, before
    /// the first layer below on each side.
    fn holes(&self, line: Option<f64>, rel: &mut Vec<LayerConstraint>, log: &mut Vec<Adaptation>) {
        for h in on_wall(self.out, self.w.id, StiffnessKind::Hole) {
            let Some((bottom, _)) = self.faces.heights(h, &self.axis) else {
                continue;
            };
            let tol = thinwall_geom::tolerance::SAME_LENGTH_MM;
            // The line's height along up, where it crosses the hole.
            let line_z = line.map(|a| {
                (self.axis.origin + self.axis.height_dir * (self.axis.foot + a))
                    .coords
                    .dot(&self.out.setup.up_in_part())
            });
            for f in self.features.iter().filter(|f| f.owner == Some(h.id)) {
                // Exposed once the layers reaching below this are out: a
                // large hole's part above the line once those above it are,
                // the rest once those down to its bottom are; a hole
                // through a web once the web's layers are.
                let upper = line_z.is_some_and(|z| f.z_range[0] >= z - tol);
                let exposed = match (h.large, line) {
                    _ if self.w.kind == StiffnessKind::Web => f64::NEG_INFINITY,
                    (Some(true), Some(line)) if upper => line,
                    _ => bottom,
                };
                let (above, below): (Vec<&&Layer>, Vec<&&Layer>) = self
                    .mine
                    .iter()
                    .partition(|l| l.from_foot[1] > exposed + tol);
                let firsts_below: Vec<&&Layer> = [0, 1]
                    .iter()
                    .filter_map(|&s| below.iter().find(|l| l.side == s).copied())
                    .collect();
                let f = &f.id;
                for l in &above {
                    rel.push(LayerConstraint {
                        before: l.id.clone(),
                        after: f.clone(),
                        why: format!("{} machined once exposed (§4.1.3)", h.id),
                    });
                }
                for l in &firsts_below {
                    rel.push(LayerConstraint {
                        before: f.clone(),
                        after: l.id.clone(),
                        why: format!(
                            "{} before the layers below it, which still support the wall (§4.1.3)",
                            h.id
                        ),
                    });
                }
                let before = firsts_below
                    .iter()
                    .map(|l| l.id.as_str())
                    .collect::<Vec<_>>()
                    .join(" and ");
                log.push(Adaptation {
                    wall: self.w.id,
                    by: h.id,
                    rule: AdaptRule::HoleInSequence,
                    change: format!(
                        "{f} ({}{}) after the {} layer(s) {}{}",
                        h.id,
                        if upper { ", above the line" } else { "" },
                        above.len(),
                        match exposed.is_finite() {
                            true => format!("above {exposed:.1} mm"),
                            false => "of the web".to_string(),
                        },
                        match before.is_empty() {
                            true => String::new(),
                            false => format!(", before {before}"),
                        }
                    ),
                });
            }
        }
    }

    /// A large chamfer before all the wall's layers, a small one after the
    /// top layer on each side.
    fn chamfers(&self, rel: &mut Vec<LayerConstraint>, log: &mut Vec<Adaptation>) {
        for c in on_wall(self.out, self.w.id, StiffnessKind::Chamfer) {
            let feats = self.owned(c.id);
            if feats.is_empty() {
                continue;
            }
            let large = c.width.is_some_and(|x| x > self.w.sizes.h);
            let tops: Vec<&&Layer> = [0, 1]
                .iter()
                .filter_map(|&s| self.mine.iter().find(|l| l.side == s))
                .collect();
            for f in &feats {
                if large {
                    rel.push(LayerConstraint {
                        before: (*f).clone(),
                        after: self.mine[0].id.clone(),
                        why: format!(
                            "{} is large: before all of {}'s layers (§4.1.3)",
                            c.id, self.w.id
                        ),
                    });
                } else {
                    for l in &tops {
                        rel.push(LayerConstraint {
                            before: l.id.clone(),
                            after: (*f).clone(),
                            why: format!("{} after the top layers beside it (§4.1.3)", c.id),
                        });
                    }
                }
            }
            log.push(Adaptation {
                wall: self.w.id,
                by: c.id,
                rule: AdaptRule::Chamfer,
                change: match large {
                    true => format!("{} (large) before all of {}'s layers", c.id, self.w.id),
                    false => format!("{} after the top layer on each side", c.id),
                },
            });
        }
    }
}

/// The shortest piece of a wall (its extent along its length) left
/// between cut-outs (their extents) and its ends, mm; infinite when the
/// cut-outs leave none.
pub fn shortest_piece(wall: (f64, f64), cutouts: &[(f64, f64)]) -> f64 {
    let mut spans = cutouts.to_vec();
    spans.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut shortest = f64::INFINITY;
    let mut from = wall.0;
    for (a, b) in spans.into_iter().chain([(wall.1, wall.1)]) {
        let piece = a.min(wall.1) - from;
        if piece > thinwall_geom::tolerance::SAME_LENGTH_MM {
            shortest = shortest.min(piece);
        }
        from = from.max(b);
    }
    shortest
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_shortest_piece_between_cutouts_and_ends() {
        assert_eq!(
            shortest_piece((0.0, 100.0), &[(70.0, 72.0), (20.0, 30.0)]),
            20.0
        );
        // Overlapping cut-outs are one gap; a cut-out at an end leaves none there.
        assert_eq!(
            shortest_piece((0.0, 100.0), &[(0.0, 10.0), (40.0, 60.0), (50.0, 65.0)]),
            30.0
        );
        assert_eq!(shortest_piece((0.0, 100.0), &[]), 100.0);
        assert!(shortest_piece((0.0, 100.0), &[(0.0, 100.0)]).is_infinite());
    }
}
