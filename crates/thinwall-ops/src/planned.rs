//! Operations along the plan (issue 17 "builds on the plan where
//! present"): every machining feature of the plan this set-up reaches gets
//! its own roughing layers, cutter fields and tools, and the plan's
//! relations between features (what lies above first, each wall's step
//! approach, the stiffness-feature sequence) become precedences between
//! their operations, so the order respects every one of them.
//!
//! A feature's section at a level is the part of each of its solids
//! (a region between a lower and an upper height) crossing that level. A
//! contour edge is **blank** (the tool may come in over it) where just
//! across it lies air: outside the stock, or a feature the plan removes
//! earlier (Popma §5.3: a face touching a predecessor is open); it is
//! **part** where the part or a later feature is (a wall for the tool).
//! Floors are finished where the feature is bottom adjacent to the
//! product and a solid's flat bottom lies at the layer's bottom.

use crate::drilling::HoleSite;
use crate::layers::{field, without_slivers, CutterField, RoughingLayer, FLAT_SLOPE};
use crate::operations::{assemble, mills_and_depth, tools_for, Assembly, SetupOperations};
use crate::ToolLibrary;
use geo::{BoundingRect, Contains, Coord, MultiPolygon, Point, Polygon, Rect};
use std::collections::HashMap;
use thinwall_classify::ProductAdjacency;
use thinwall_plan::features::RemovalFeature;
use thinwall_plan::Plan;
use thinwall_removal::pieces::Height;
use thinwall_removal::slab;

/// A feature's solid as regions and heights.
struct Solid {
    region: MultiPolygon<f64>,
    bbox: Rect<f64>,
    lower: Height,
    upper: Height,
}

fn solids(f: &RemovalFeature) -> Vec<Solid> {
    f.solids
        .iter()
        .filter_map(|s| {
            let ring = |r: &Vec<[f64; 2]>| {
                geo::LineString::from(r.iter().map(|p| (p[0], p[1])).collect::<Vec<_>>())
            };
            let poly = Polygon::new(ring(&s.rings[0]), s.rings[1..].iter().map(ring).collect());
            let region = MultiPolygon::new(vec![poly]);
            Some(Solid {
                bbox: region.bounding_rect()?,
                region,
                lower: s.lower.clone(),
                upper: s.upper.clone(),
            })
        })
        .collect()
}

fn flat(h: &Height) -> Option<f64> {
    match *h {
        Height::Plane { z0, gx, gy, .. } if gx.hypot(gy) <= FLAT_SLOPE => Some(z0),
        _ => None,
    }
}

/// Whether (x, y) at height z lies inside the solid.
fn inside(s: &Solid, q: Coord<f64>, z: f64) -> bool {
    s.bbox.contains(&q)
        && s.lower.at(q.x, q.y) <= z
        && z < s.upper.at(q.x, q.y)
        && s.region.contains(&Point::from(q))
}

/// The levels of a feature, top down: every `a_p` from its top, at every
/// flat bottom or top of its solids, and at the entry and bottom of every
/// hole (a solid of the plan may run from a hole's bottom up through the
/// pocket above it).
fn levels(
    f: &RemovalFeature,
    solids: &[Solid],
    holes: &[HoleSite],
    a_p: f64,
    tol: f64,
) -> Vec<f64> {
    let [lo, hi] = f.z_range;
    let mut out: Vec<f64> = solids
        .iter()
        .flat_map(|s| [flat(&s.lower), flat(&s.upper)])
        .flatten()
        .chain(
            holes
                .iter()
                .filter(|h| {
                    let c = Coord {
                        x: h.centre[0],
                        y: h.centre[1],
                    };
                    solids.iter().any(|s| s.bbox.contains(&c))
                })
                .flat_map(|h| [h.z_top_mm, h.z_bottom_mm]),
        )
        .filter(|&z| z > lo - tol && z < hi - tol)
        .collect();
    let steps = ((hi - lo) / a_p).ceil().max(1.0) as usize;
    for k in 1..=steps {
        out.push((hi - k as f64 * a_p).max(lo));
    }
    out.sort_by(|a, b| b.total_cmp(a));
    out.dedup_by(|a, b| (*a - *b).abs() <= tol);
    out
}

/// The plan's operations: each reachable machining feature layered and
/// tooled on its own, every relation of the plan's feature sequence a
/// precedence between the features' operations; the `holes` a drill
/// matches are drilled, after every layer above their entry. `stock` is the stock's
/// footprint in the plan's frame (x, y); `size` the part's diagonal, mm.
pub fn by_feature(
    plan: &Plan,
    lib: &ToolLibrary,
    axial_depth_mm: Option<f64>,
    holes: &[HoleSite],
    stock: Rect<f64>,
    size: f64,
    work: thinwall_analysis::parallel::Work<'_>,
) -> SetupOperations {
    let (mills, a_p) = mills_and_depth(lib, axial_depth_mm);
    let smallest = mills.last().map_or(0.0, |t| t.diameter_mm);
    let tol = 1e-6 * size.max(1.0);
    let by_id: HashMap<&str, &RemovalFeature> = plan
        .machining_features
        .iter()
        .map(|f| (f.id.as_str(), f))
        .collect();
    let order: Vec<&RemovalFeature> = plan
        .feature_sequence
        .order
        .iter()
        .filter_map(|id| by_id.get(id.as_str()).copied())
        .filter(|f| f.reachable)
        .collect();
    let all: Vec<Vec<Solid>> = order.iter().map(|f| solids(f)).collect();
    let mut layers: Vec<RoughingLayer> = Vec::new();
    for (i, f) in order.iter().enumerate() {
        let earlier: Vec<&Solid> = all[..i].iter().flatten().collect();
        let air =
            |q: Coord<f64>, z: f64| !stock.contains(&q) || earlier.iter().any(|s| inside(s, q, z));
        let bottom = f.classification.as_ref().is_some_and(|c| {
            matches!(
                c.product_adjacency,
                ProductAdjacency::Bottom | ProductAdjacency::SideAndBottom
            )
        });
        let mut above = f.z_range[1];
        for z in levels(f, &all[i], holes, a_p, tol) {
            let pieces: Vec<Polygon<f64>> = all[i]
                .iter()
                .flat_map(|s| slab::between(&s.region, &s.lower, &s.upper, z + tol).0)
                .collect();
            let joined = crate::layers::join(&pieces, size);
            let fields: Vec<CutterField> = joined
                .iter()
                .filter_map(|p| without_slivers(p, tol))
                .map(|p| field(&p, 1e-4 * size.max(1.0), smallest, &|q| air(q, z + tol)))
                .collect();
            let floors: Vec<&Solid> = all[i]
                .iter()
                .filter(|s| bottom && flat(&s.lower).is_some_and(|h| (h - z).abs() <= tol))
                .collect();
            let floor_region = thinwall_analysis::boolean::union_all(
                floors.iter().map(|s| s.region.clone()).collect(),
            );
            layers.push(RoughingLayer {
                index: layers.len(),
                feature: Some(f.id.clone()),
                z_top_mm: above,
                z_bottom_mm: z,
                floors: Vec::new(),
                floor_region,
                area_mm2: fields.iter().map(|f| f.area_mm2).sum(),
                // The plan's step features are the step approach here.
                step_limit_mm: None,
                fields,
            });
            above = z;
        }
    }
    let groups: Vec<(thinwall_plan::VolumeId, thinwall_plan::VolumeId)> = plan
        .feature_sequence
        .relations
        .iter()
        .map(|r| (r.before.clone(), r.after.clone()))
        .collect();
    let field_tools = tools_for(&layers, &mills, lib.min_share_mm2, holes, tol, work);
    let mut ops = assemble(
        Assembly {
            lib,
            a_p,
            holes,
            groups: &groups,
            tol,
        },
        layers,
        field_tools,
    );
    ops.other_setup = plan
        .feature_sequence
        .order
        .iter()
        .filter(|id| by_id.get(id.as_str()).is_some_and(|f| !f.reachable))
        .cloned()
        .collect();
    ops
}
