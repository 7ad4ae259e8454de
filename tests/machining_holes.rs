//! Compound holes (issue 38): generated parts
//! (`scripts/make_hole_fixtures.py`: plain, countersunk 82°/90°/100°,
//! counterbored, chamfered and blended entries, a chamfered exit, stepped,
//! blind with a drill point or a flat bottom; in a flat plate and in an
//! upright wall; random diameters and depths) with their truth. Every hole
//! is one feature holding every face of the hole, entered along its
//! direction, with each stage's sizes within 1e-6; the same as built and
//! turned. A through hole with no seat at either end (plain, chamfered or
//! blended) has no preferred side: it may be read from either end.
//!
//! `THINWALL_HOLES_DIR=DIR` runs the same checks on another directory of
//! generated parts (a seed range never looked at: the held-out figure).

mod common;

use thinwall_analysis::{MachiningKind, PartAnalysis, Setup};
use thinwall_machining::{recognize, Bore, HoleEnd, HoleForm, HoleTip, MachiningFeature};

#[derive(serde::Deserialize)]
struct Truth {
    holes: Vec<Hole>,
}

#[derive(serde::Deserialize)]
struct Hole {
    kind: String,
    entry_point: [f64; 3],
    direction: [f64; 3],
    entry: Option<End>,
    bores: Vec<TruthBore>,
    exit: Option<End>,
    tip: serde_json::Value,
}

#[derive(serde::Deserialize, Clone)]
struct End {
    kind: String,
    angle_deg: Option<f64>,
    diameter: Option<f64>,
    radius: Option<f64>,
}

#[derive(serde::Deserialize, Clone)]
struct TruthBore {
    diameter: f64,
    depth: f64,
}

const TOL: f64 = 1e-6;

fn near(a: f64, b: f64) -> bool {
    (a - b).abs() <= TOL
}

fn end_matches(got: &Option<HoleEnd>, want: &Option<End>) -> bool {
    match (got, want) {
        (None, None) => true,
        (Some(HoleEnd::Blend { radius }), Some(w)) => {
            w.kind == "blend" && w.radius.is_some_and(|r| near(*radius, r))
        }
        (
            Some(HoleEnd::Countersink {
                angle_deg,
                diameter,
            }),
            Some(w),
        ) => w.kind == "countersink" && same_cone(*angle_deg, *diameter, w),
        (
            Some(HoleEnd::Chamfer {
                angle_deg,
                diameter,
            }),
            Some(w),
        ) => w.kind == "chamfer" && same_cone(*angle_deg, *diameter, w),
        _ => false,
    }
}

fn same_cone(angle: f64, diameter: f64, w: &End) -> bool {
    w.angle_deg.is_some_and(|x| near(angle, x)) && w.diameter.is_some_and(|x| near(diameter, x))
}

fn tip_matches(got: &HoleTip, want: &serde_json::Value) -> bool {
    match got {
        HoleTip::Through => want == "through",
        HoleTip::Flat => want == "flat",
        HoleTip::DrillPoint { angle_deg } => want["drill_point"]
            .as_f64()
            .is_some_and(|x| near(*angle_deg, x)),
    }
}

fn bores_match(got: &[Bore], want: &[TruthBore]) -> bool {
    got.len() == want.len()
        && got
            .iter()
            .zip(want)
            .all(|(g, w)| near(g.diameter, w.diameter) && near(g.depth, w.depth))
}

/// What is wrong with a hole's form read along `dir` (the feature's
/// direction, brought back to the part as built) against its truth.
fn form_errors(form: &HoleForm, dir: nalgebra::Vector3<f64>, h: &Hole) -> Option<String> {
    let want_dir = nalgebra::Vector3::from(h.direction);
    let seatless = h.tip == "through"
        && !matches!(&h.entry, Some(e) if e.kind == "countersink")
        && h.bores.len() == 1;
    let (entry, exit, bores) = if dir.dot(&want_dir) < 0.0 && seatless {
        // Read from the other end: its entry is the truth's exit.
        let mut b = h.bores.clone();
        b.reverse();
        (h.exit.clone(), h.entry.clone(), b)
    } else if dir.dot(&want_dir) > 1.0 - TOL {
        (h.entry.clone(), h.exit.clone(), h.bores.clone())
    } else {
        return Some(format!("direction {dir:?}, want {:?}", h.direction));
    };
    let ok = end_matches(&form.entry, &entry)
        && end_matches(&form.exit, &exit)
        && bores_match(&form.bores, &bores)
        && tip_matches(&form.tip, &h.tip);
    (!ok).then(|| format!("form {form:?}"))
}

/// The faces of a hole (the part posed by `r`, `t`): centroids (brought
/// back to the part as built)
/// within its widest radius of its axis and inside the wall, apart from
/// the wall's faces across the axis (larger than the hole).
fn hole_faces(
    part: &thinwall_brep::Part,
    a: &PartAnalysis,
    h: &Hole,
    r: &nalgebra::Rotation3<f64>,
    t: &nalgebra::Vector3<f64>,
) -> Vec<u64> {
    let back = |c: nalgebra::Point3<f64>| r.inverse() * (c - t);
    let p = nalgebra::Point3::from(h.entry_point);
    let u = nalgebra::Vector3::from(h.direction);
    let bore = h.bores.iter().map(|b| b.diameter).fold(0.0, f64::max);
    // A blended end reaches its radius beyond the bore.
    let widest = [h.entry.as_ref(), h.exit.as_ref()]
        .into_iter()
        .flatten()
        .filter_map(|e| e.diameter.or(e.radius.map(|r| bore + 2.0 * r)))
        .fold(bore, f64::max);
    let reach = widest / 2.0 + 0.01;
    let depth: f64 = h.bores.iter().map(|b| b.depth).sum::<f64>() + 5.0;
    let mut v: Vec<u64> = part
        .face_ids()
        .filter(|&f| {
            let c = back(a.props(f).centroid);
            let t = (c - p).dot(&u);
            let off = ((c - p) - u * t).norm();
            let big_across = a
                .props(f)
                .normal
                .is_some_and(|n| (r.inverse() * n).dot(&u).abs() > 0.99)
                && a.props(f).area > std::f64::consts::PI * reach * reach;
            off < reach && t > -TOL && t < depth && !big_across
        })
        .map(|f| part.face(f).step_id)
        .collect();
    v.sort();
    v
}

/// Every hole of one part, posed by `seed` (none: as built): what is
/// wrong, one line each.
fn part_errors(path: &std::path::Path, seed: Option<u64>) -> (usize, Vec<String>) {
    let truth: Truth =
        serde_json::from_str(&std::fs::read_to_string(path.with_extension("truth.json")).unwrap())
            .unwrap();
    let text = common::posed_step(&std::fs::read_to_string(path).unwrap(), seed);
    if let (Ok(dir), Some(s)) = (std::env::var("TW_DUMP"), seed) {
        let name = path.file_stem().unwrap().to_string_lossy();
        std::fs::write(format!("{dir}/{name}_{s}.step"), &text).unwrap();
    }
    let (part, _) = thinwall_step::read_bytes(text.as_bytes(), "holes.step").unwrap();
    let a = PartAnalysis::new(&part, Setup::default());
    let features = recognize(&a);
    let (r, t) = seed.map_or(
        (nalgebra::Rotation3::identity(), nalgebra::Vector3::zeros()),
        common::rigid_motion,
    );
    let name = format!("{} {seed:?}", path.display());
    let mut errors = Vec::new();
    for h in &truth.holes {
        let want = hole_faces(&part, &a, h, &r, &t);
        let found: Vec<&MachiningFeature> = features
            .iter()
            .filter(|m| m.faces.iter().any(|f| want.contains(f)))
            .collect();
        let what = format!("{name} {} hole at {:?}", h.kind, h.entry_point);
        match found.as_slice() {
            [m] if m.kind == MachiningKind::Hole && m.faces == want => {
                let d = r.inverse() * nalgebra::Vector3::from(m.direction);
                match m.hole.as_ref() {
                    Some(form) => {
                        errors.extend(form_errors(form, d, h).map(|e| format!("{what}: {e}")))
                    }
                    None => errors.push(format!("{what}: no form")),
                }
            }
            _ => errors.push(format!(
                "{what}: its faces {:?} are in {:?}",
                want.iter()
                    .map(|s| {
                        let f = part.face_by_step_id(*s).unwrap();
                        (*s, part.face(f).surface.kind_name(), a.props(f).area)
                    })
                    .collect::<Vec<_>>(),
                found
                    .iter()
                    .map(|m| (m.id.to_string(), m.kind, m.faces.len()))
                    .collect::<Vec<_>>()
            )),
        }
    }
    (truth.holes.len(), errors)
}

#[test]
fn every_hole_is_one_feature_with_its_stages_in_any_pose() {
    let parts = common::generated_parts("THINWALL_HOLES_DIR", "holes");
    assert!(!parts.is_empty());
    let (mut holes, mut errors) = (0, Vec::new());
    for (k, path) in parts.iter().enumerate() {
        for seed in [None, Some(5100 + k as u64)] {
            let (n, e) = part_errors(path, seed);
            holes += n;
            errors.extend(e);
        }
    }
    eprintln!(
        "{} parts as built and turned: {holes} holes, {} wrong",
        parts.len(),
        errors.len()
    );
    assert!(errors.is_empty(), "{}", errors.join("\n"));
}
