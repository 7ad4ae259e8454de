//! The whole removal plan (issue 14): on every thin-walled part of
//! `../shared/data/thinwall` and every recognition fixture, the machining
//! features are exactly stock − part (volumes add up to 1e-6, checked
//! against the part's volume taken along other axes and, for planar
//! parts, by the divergence theorem over the reader's face properties);
//! no two features and no feature and the part overlap; the order keeps
//! every relation; a turned part and set-up give the same plan.

mod common;

use geo::{Area, BooleanOps, BoundingRect, Contains, InteriorPoint, MultiPolygon};
use thinwall_analysis::parallel::Work;
use thinwall_analysis::{PartAnalysis, Setup};
use thinwall_brep::Part;
use thinwall_geom::tolerance::SLIVER;
use thinwall_geom::{Frame, Point3, Surface, Vector3};
use thinwall_plan::features::{FeatureClass, FeatureSolid};
use thinwall_plan::{Plan, RuleSet};
use thinwall_removal::pieces::{pieces, Facing};
use thinwall_removal::{frame_of, Removal, StockShape};

fn plan_text(text: &str, up: [f64; 3]) -> (Part, Plan) {
    common::plan_text(text, up, &RuleSet::default_rules())
}

fn parts() -> Vec<std::path::PathBuf> {
    common::thin_walled_parts()
}

/// The set-up's up: a recognition fixture's own, +Z for the others.
fn up_of(path: &std::path::Path) -> [f64; 3] {
    let expected = path.with_extension("expected.json");
    match std::fs::read_to_string(&expected) {
        Ok(text) => {
            let v: serde_json::Value = serde_json::from_str(&text).unwrap();
            let u = &v["up"];
            [0, 1, 2].map(|k| u[k].as_f64().unwrap())
        }
        Err(_) => [0.0, 0.0, 1.0],
    }
}

fn plan_file(path: &std::path::Path) -> (Part, Plan) {
    plan_text(&std::fs::read_to_string(path).unwrap(), up_of(path))
}

fn frame(p: &Plan) -> Frame {
    let v = |a: [f64; 3]| Vector3::new(a[0], a[1], a[2]);
    Frame {
        origin: Point3::from(v(p.frame[0])),
        x: v(p.frame[1]),
        y: v(p.frame[2]),
        z: v(p.frame[3]),
    }
}

/// The part's volume seen along another of the stock's axes.
fn volume_along(part: &Part, dir: Vector3) -> f64 {
    let a = PartAnalysis::new(part, Setup::default());
    let (f, lo, hi) = frame_of(&a, dir);
    let size = a.bounding_box().diagonal();
    Removal::new(
        part,
        f,
        &StockShape::Block { lo, hi },
        &[],
        size,
        Work::serial(),
    )
    .unwrap()
    .part_volume
}

/// A planar part's volume by the divergence theorem: Σ (n · c) A / 3.
fn planar_volume(part: &Part) -> Option<f64> {
    let a = PartAnalysis::new(part, Setup::default());
    part.face_ids()
        .map(|f| {
            matches!(part.face(f).surface, Surface::Plane { .. }).then(|| {
                let p = a.props(f);
                p.normal.unwrap().dot(&p.centroid.coords) * p.area / 3.0
            })
        })
        .sum()
}

#[test]
fn the_features_are_stock_minus_part_on_every_part() {
    let (mut checked, mut typed, mut all) = (0, 0, 0);
    for path in parts() {
        let name = path.display().to_string();
        let (part, p) = plan_file(&path);
        let r = &p.removal;
        assert!(r.unavailable.is_none(), "{name}: {:?}", r.unavailable);
        // The part's volume three ways.
        let f = frame(&p);
        for dir in [f.x, f.y] {
            let v = volume_along(&part, dir);
            assert!(
                (v - r.part_volume_mm3).abs() <= 1e-7 * v,
                "{name}: part {} along up, {v} along {dir:?}",
                r.part_volume_mm3
            );
        }
        if let Some(v) = planar_volume(&part) {
            assert!((v - r.part_volume_mm3).abs() <= 1e-9 * v, "{name}: {v}");
        }
        let want = r.stock_volume_mm3 - r.part_volume_mm3;
        let sum: f64 = p.machining_features.iter().map(|f| f.volume_mm3).sum();
        assert!(
            (sum - want).abs() <= 1e-6 * want,
            "{name}: features {sum}, stock − part {want}"
        );
        assert!(
            r.slivers_mm3.abs() <= 1e-7 * want,
            "{name}: {}",
            r.slivers_mm3
        );
        for f in &p.machining_features {
            assert!(
                f.volume_mm3 > SLIVER * r.stock_volume_mm3,
                "{name}: {} is empty",
                f.id
            );
            let solids: f64 = f.solids.iter().map(|s| s.volume_mm3).sum();
            assert!(
                (solids - f.volume_mm3).abs() <= 1e-8 * r.stock_volume_mm3,
                "{name}: {} solids {solids} of {}",
                f.id,
                f.volume_mm3
            );
            assert!(f.z_range[0] < f.z_range[1], "{name}: {}", f.id);
            // Every feature has a type; `unknown` only with a reason.
            let c = f
                .classification
                .as_ref()
                .unwrap_or_else(|| panic!("{name}: {} untyped", f.id));
            assert!(
                c.kind != thinwall_analysis::VolumeType::Unknown || c.reason.is_some(),
                "{name}: {} unknown without a reason",
                f.id
            );
        }
        typed += p
            .machining_features
            .iter()
            .filter(|f| {
                f.classification
                    .as_ref()
                    .is_some_and(|c| c.kind != thinwall_analysis::VolumeType::Unknown)
            })
            .count();
        all += p.machining_features.len();
        checked += 1;
    }
    assert!(checked >= 25, "{checked} parts");
    eprintln!("{typed} of {all} features typed");
    assert!(typed * 10 >= all * 8, "{typed} of {all} typed");
}

fn poly(s: &FeatureSolid) -> MultiPolygon<f64> {
    let ring = |r: &Vec<[f64; 2]>| {
        let mut cs: Vec<geo::Coord<f64>> =
            r.iter().map(|p| geo::Coord { x: p[0], y: p[1] }).collect();
        cs.push(cs[0]);
        geo::LineString::new(cs)
    };
    MultiPolygon::new(vec![geo::Polygon::new(
        ring(&s.rings[0]),
        s.rings[1..].iter().map(ring).collect(),
    )])
}

/// Material intervals of the part over a point, from its faces (not from
/// the plan's cells).
fn material_at(pcs: &[thinwall_removal::pieces::Piece], pt: geo::Point<f64>) -> Vec<[f64; 2]> {
    let mut cross: Vec<(f64, Facing)> = pcs
        .iter()
        .filter(|p| p.region.contains(&pt))
        .map(|p| (p.height.at(pt.x(), pt.y()), p.facing))
        .collect();
    cross.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut out = Vec::new();
    let mut start = None;
    for (z, f) in cross {
        match (f, start) {
            (Facing::Down, None) => start = Some(z),
            (Facing::Up, Some(s)) => {
                out.push([s, z]);
                start = None;
            }
            _ => {}
        }
    }
    out
}

#[test]
fn features_overlap_neither_each_other_nor_the_part() {
    for path in parts() {
        let name = path.display().to_string();
        let (part, p) = plan_file(&path);
        let f = frame(&p);
        let size = part.bounding_box().diagonal();
        let deviation = thinwall_geom::tolerance::machining_deviation(size);
        let pcs = pieces(
            &part,
            &f,
            (deviation, Work::serial()),
            &mut Default::default(),
        )
        .unwrap();
        let tol = 1e-7 * size;
        let solids: Vec<(&str, &FeatureSolid, MultiPolygon<f64>)> = p
            .machining_features
            .iter()
            .flat_map(|m| m.solids.iter().map(move |s| (m.id.as_str(), s, poly(s))))
            .collect();
        let span = |s: &FeatureSolid, pt: geo::Point<f64>| {
            [s.lower.at(pt.x(), pt.y()), s.upper.at(pt.x(), pt.y())]
        };
        for (id, s, region) in &solids {
            let pt = region.interior_point().unwrap();
            let z = span(s, pt);
            for m in material_at(&pcs, pt) {
                assert!(
                    m[1] <= z[0] + tol || m[0] >= z[1] - tol,
                    "{name}: {id} {z:?} overlaps the part {m:?}"
                );
            }
        }
        for i in 0..solids.len() {
            for j in i + 1..solids.len() {
                let (a, b) = (&solids[i], &solids[j]);
                let (ra, rb) = (a.2.bounding_rect().unwrap(), b.2.bounding_rect().unwrap());
                if ra.max().x < rb.min().x
                    || rb.max().x < ra.min().x
                    || ra.max().y < rb.min().y
                    || rb.max().y < ra.min().y
                {
                    continue;
                }
                for common in a.2.intersection(&b.2).0 {
                    if common.unsigned_area() <= tol * size {
                        continue;
                    }
                    let pt = common.interior_point().unwrap();
                    let (za, zb) = (span(a.1, pt), span(b.1, pt));
                    assert!(
                        za[1] <= zb[0] + tol || zb[1] <= za[0] + tol,
                        "{name}: {} {za:?} and {} {zb:?} overlap",
                        a.0,
                        b.0
                    );
                }
            }
        }
    }
}

#[test]
fn the_order_keeps_every_relation_and_the_step_approach() {
    for path in parts() {
        let name = path.display().to_string();
        let (_, p) = plan_file(&path);
        let order = &p.feature_sequence.order;
        assert_eq!(order.len(), p.machining_features.len(), "{name}");
        let at = |id: &str| order.iter().position(|o| o == id).unwrap();
        for r in &p.feature_sequence.relations {
            assert!(at(&r.before) < at(&r.after), "{name}: {r:?}");
        }
        // Every relation says why; a feature lying on another reaches
        // above that one's bottom.
        let feature = |id: &str| p.machining_features.iter().find(|f| f.id == id).unwrap();
        for r in &p.feature_sequence.relations {
            assert!(!r.why.is_empty(), "{name}: {r:?}");
            if r.why.ends_with(&format!("lies above {}", r.after)) {
                let (a, b) = (feature(&r.before), feature(&r.after));
                assert!(a.z_range[1] > b.z_range[0], "{name}: {r:?}");
            }
        }
        // Each wall: its layers in step order, the large one first; a
        // small layer only once the large one beside it is down to its
        // depth (fig. 4.1).
        for w in &p.walls {
            let mine: Vec<&thinwall_plan::features::RemovalFeature> = order
                .iter()
                .filter_map(|id| p.machining_features.iter().find(|f| &f.id == id))
                .filter(|f| f.owner == Some(w.id) && f.step.is_some())
                .collect();
            let steps: Vec<usize> = mine.iter().map(|f| f.step.unwrap()).collect();
            let mut sorted = steps.clone();
            sorted.sort();
            assert_eq!(steps, sorted, "{name}: {} steps out of order", w.id);
            let mut deepest_large = f64::INFINITY;
            let large_side = mine
                .iter()
                .find(|f| f.size_class == FeatureClass::Large)
                .and_then(|f| f.side);
            for f in &mine {
                match f.size_class {
                    FeatureClass::Large => {
                        assert_eq!(f.side, large_side, "{name}: {}", f.id);
                        deepest_large = deepest_large.min(f.z_range[0]);
                    }
                    FeatureClass::Small => {
                        assert_ne!(f.side, large_side, "{name}: {}", f.id);
                        // (No large layer: that side is the stock's face.)
                        assert!(
                            deepest_large.is_infinite() || f.z_range[0] >= deepest_large - 1e-4,
                            "{name}: {} below the large cut",
                            f.id
                        );
                    }
                    _ => {}
                }
            }
        }
    }
}

/// What must not change when the part and its set-up turn: every
/// feature's id, owner, side, step, class, faces, reach, type, adjacency,
/// other types and solid count (heights are compared apart, as numbers).
fn pose_key(p: &Plan) -> Vec<String> {
    p.machining_features
        .iter()
        .map(|f| {
            let c = f.classification.as_ref().expect("classified");
            format!(
                "{} {:?} {:?} {:?} {:?} {:?} {} {} {} {:?} {}",
                f.id,
                f.owner,
                f.side,
                f.step,
                f.size_class,
                f.faces,
                f.reachable,
                c.kind.name(),
                c.product_adjacency.name(),
                c.types,
                f.solids.len(),
            )
        })
        .collect()
}

/// Every feature's heights above the lowest feature's bottom, mm.
fn heights(p: &Plan) -> Vec<[f64; 2]> {
    let base = p
        .machining_features
        .iter()
        .map(|f| f.z_range[0])
        .fold(f64::INFINITY, f64::min);
    p.machining_features
        .iter()
        .map(|f| [f.z_range[0] - base, f.z_range[1] - base])
        .collect()
}

#[test]
fn a_turned_part_and_set_up_give_the_same_removal_plan_and_types() {
    let mut differ = Vec::new();
    for (k, path) in parts().iter().enumerate() {
        let name = path.display().to_string();
        let text = std::fs::read_to_string(path).unwrap();
        let (r, t) = common::rigid_motion(20 + k as u64);
        let (turned, _) = common::turned_step(&text, &r, &t);
        let up = up_of(path);
        let turned_up = r * Vector3::new(up[0], up[1], up[2]);
        let (_, a) = plan_text(&text, up);
        let (_, b) = plan_text(&turned, [turned_up.x, turned_up.y, turned_up.z]);
        assert_eq!(a.removal.unavailable, b.removal.unavailable, "{name}");
        let (ka, kb) = (pose_key(&a), pose_key(&b));
        if ka != kb {
            let first = ka.iter().zip(&kb).find(|(x, y)| x != y);
            differ.push(format!(
                "{name}: {} vs {} features, first difference {first:?}",
                ka.len(),
                kb.len()
            ));
            continue;
        }
        // Heights agree to a millionth of the stock's size (a drafted
        // face's cut rounds at about 1e-5 mm).
        let size = a.removal.stock_volume_mm3.cbrt();
        for (i, (ha, hb)) in heights(&a).iter().zip(heights(&b)).enumerate() {
            let id = &a.machining_features[i].id;
            assert!(
                (ha[0] - hb[0]).abs() <= 1e-6 * size,
                "{name}: {id} {ha:?} {hb:?}"
            );
            assert!(
                (ha[1] - hb[1]).abs() <= 1e-6 * size,
                "{name}: {id} {ha:?} {hb:?}"
            );
        }
        for (fa, fb) in a.machining_features.iter().zip(&b.machining_features) {
            assert!(
                (fa.volume_mm3 - fb.volume_mm3).abs() <= 1e-7 * a.removal.stock_volume_mm3,
                "{name}: {} {} {}",
                fa.id,
                fa.volume_mm3,
                fb.volume_mm3
            );
        }
        assert_eq!(a.feature_sequence.order, b.feature_sequence.order, "{name}");
        assert!(
            (a.removal.part_volume_mm3 - b.removal.part_volume_mm3).abs()
                <= 1e-7 * a.removal.part_volume_mm3.max(1.0)
        );
    }
    assert!(
        differ.is_empty(),
        "{} parts differ when turned:\n{}",
        differ.len(),
        differ.join("\n")
    );
}
