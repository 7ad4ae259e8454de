//! Our areas and edge convexity against OpenCascade 7.9 on the shared data.
//!
//! `tests/oracle/<set>/<file>.json` were written by `scripts/occ_oracle.py`
//! (areas by `BRepGProp`, convexity by `BRepOffset_Analyse` with a 0.01 rad
//! tangency angle). OCP's binding does not give STEP ids back, so faces are
//! matched by centroid and surface kind, edges by the point OpenCascade
//! reports at their parameter midpoint.

mod common;

use serde::Deserialize;
use std::path::Path;
use thinwall_brep::{compute_face_props, Part};
use thinwall_geom::Point3;
use thinwall_graph::{AdjacencyGraph, Convexity};

#[derive(Deserialize)]
struct OracleFace {
    area: f64,
    centroid: [f64; 3],
    surface: String,
}

#[derive(Deserialize)]
struct OracleEdge {
    midpoint: [f64; 3],
    convexity: Vec<String>,
}

#[derive(Deserialize)]
struct Oracle {
    file: String,
    faces: Vec<OracleFace>,
    edges: Vec<OracleEdge>,
}

/// Relative area tolerance by surface kind (issue #2).
fn area_tolerance(surface: &str) -> f64 {
    if surface == "plane" {
        1e-6
    } else {
        1e-3
    }
}

#[derive(Default)]
struct Tally {
    faces: usize,
    worst_plane: (f64, String),
    worst_curved: (f64, String),
    area_failures: Vec<String>,
    edges: usize,
    unmatched_edges: Vec<String>,
    convexity_differences: Vec<String>,
    /// Differences with a known cause (see `explain_*`), by cause.
    explained: std::collections::BTreeMap<&'static str, usize>,
}

/// OpenCascade's `ChFi3d::IsTangentFaces` tests G1 continuity with a fixed
/// 0.1 rad angular tolerance, whatever angle `BRepOffset_Analyse` is given:
/// a kink under 5.73° is `Tangential` there, convex or concave here
/// (our tangent angle is 0.01 rad).
const OCC_G1_ANGLE_DEG: f64 = 5.729_577_951;

/// Largest distance between a face's vertices and the ends of its edge
/// curves: a file whose vertices sit off their curves (within its own
/// uncertainty) can be read two ways, vertex-to-vertex or along the curves.
fn vertex_gap(part: &Part, face: usize) -> (f64, f64) {
    let mut gap: f64 = 0.0;
    let mut perimeter = 0.0;
    for &l in &part.faces[face].loops {
        for ce in &part.loop_(l).coedges {
            let e = part.edge(ce.edge);
            let Some(c) = &e.nurbs else { continue };
            let (t0, t1) = c.domain();
            gap = gap.max((c.point(t0) - part.vertex(e.start).point).norm());
            gap = gap.max((c.point(t1) - part.vertex(e.end).point).norm());
            perimeter += (c.point(t1) - c.point(t0)).norm().max(1e-9);
        }
    }
    (gap, perimeter)
}

fn polyline(part: &Part, e: usize) -> Vec<Point3> {
    let edge = &part.edges[e];
    let Some(c) = &edge.nurbs else {
        return vec![];
    };
    let mut pts = Vec::new();
    for (a, b) in c.spans() {
        for k in 0..=64 {
            pts.push(c.point(a + (b - a) * k as f64 / 64.0));
        }
    }
    pts
}

fn distance_to_polyline(p: &Point3, pts: &[Point3]) -> f64 {
    pts.windows(2)
        .map(|w| {
            let d = w[1] - w[0];
            let t = if d.norm_squared() > 0.0 {
                ((p - w[0]).dot(&d) / d.norm_squared()).clamp(0.0, 1.0)
            } else {
                0.0
            };
            (p - (w[0] + d * t)).norm()
        })
        .fold(f64::INFINITY, f64::min)
}

fn ours_kind(surface: &str) -> &str {
    match surface {
        "plane" | "cylinder" | "cone" | "sphere" | "torus" => surface,
        _ => "other",
    }
}

fn check_file(set: &str, oracles: &[Oracle], oracle: &Oracle, data: &Path, tally: &mut Tally) {
    let (part, _) = thinwall_step::read_file(data).unwrap_or_else(|e| panic!("{e}"));
    let diag = part.bounding_box().diagonal();
    let props: Vec<_> = part
        .face_ids()
        .map(|f| compute_face_props(&part, f))
        .collect();
    assert_eq!(
        oracle.faces.len(),
        part.faces.len(),
        "{set}/{}: face count differs from OpenCascade",
        oracle.file
    );
    // Global greedy matching on centroid distance and relative area difference.
    let mut pairs: Vec<(f64, usize, usize)> = Vec::new();
    for (k, of) in oracle.faces.iter().enumerate() {
        let c = Point3::new(of.centroid[0], of.centroid[1], of.centroid[2]);
        for (i, f) in part.faces.iter().enumerate() {
            if ours_kind(f.surface.kind_name()) != of.surface {
                continue;
            }
            let cost = (props[i].centroid - c).norm() / diag.max(1e-9)
                + (props[i].area - of.area).abs() / of.area.max(props[i].area).max(1e-12);
            pairs.push((cost, k, i));
        }
    }
    pairs.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut match_of = vec![None; oracle.faces.len()];
    let mut used = vec![false; part.faces.len()];
    for (_, k, i) in pairs {
        if match_of[k].is_none() && !used[i] {
            match_of[k] = Some(i);
            used[i] = true;
        }
    }
    for (of, m) in oracle.faces.iter().zip(match_of) {
        let Some(i) = m else {
            tally.area_failures.push(format!(
                "{set}/{}: no {} face for OCC face at {:?}",
                oracle.file, of.surface, of.centroid
            ));
            continue;
        };
        tally.faces += 1;
        let rel = (props[i].area - of.area).abs() / of.area.max(1e-12);
        let label = format!(
            "{set}/{} #{} ({})",
            oracle.file, part.faces[i].step_id, of.surface
        );
        let (gap, perimeter) = vertex_gap(&part, i);
        let cause = if rel <= area_tolerance(&of.surface) {
            None
        } else if gap > 1e-6 * diag && (props[i].area - of.area).abs() <= 4.0 * gap * perimeter {
            Some("area: vertices off their curves (file within its uncertainty)")
        } else if opencascade_twin_agrees(oracles, oracle, of, props[i].area) {
            Some("area: OpenCascade gives the same face our area in another file of the set")
        } else {
            tally.area_failures.push(format!(
                "{label}: area {:.9} vs OCC {:.9} (rel {rel:.2e}), centroid {} vs {:?}",
                props[i].area, of.area, props[i].centroid, of.centroid
            ));
            None
        };
        match cause {
            Some(c) => *tally.explained.entry(c).or_default() += 1,
            None => {
                let worst = if of.surface == "plane" {
                    &mut tally.worst_plane
                } else {
                    &mut tally.worst_curved
                };
                if rel > worst.0 {
                    *worst = (rel, label);
                }
            }
        }
    }
    let graph = AdjacencyGraph::build(&part, &part.tolerances());
    let lines: Vec<Vec<Point3>> = (0..part.edges.len()).map(|e| polyline(&part, e)).collect();
    for oe in &oracle.edges {
        let p = Point3::new(oe.midpoint[0], oe.midpoint[1], oe.midpoint[2]);
        let (e, d) = (0..part.edges.len())
            .map(|e| (e, distance_to_polyline(&p, &lines[e])))
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .expect("edges");
        if d > 1e-3 * diag && oe.convexity == ["other"] {
            // Periodic faces bounded without a seam in the file (a cone
            // closed by a circle and an apex vertex loop): OpenCascade's
            // healing adds a seam edge that the file does not have.
            *tally
                .explained
                .entry("edge: seam added by OpenCascade, not in the file")
                .or_default() += 1;
            continue;
        }
        if d > 1e-3 * diag
            && part.supplemental.face_count > 0
            && off_the_solid(&props, &p, 1e-3 * diag)
        {
            // OpenCascade maps the edges of every face in the file, those of
            // the supplemental surface models (PMI geometry) beside the
            // solid included; we keep those out of the part.
            *tally
                .explained
                .entry("edge: of a supplemental surface model, not of the solid")
                .or_default() += 1;
            continue;
        }
        if d > 1e-3 * diag {
            tally.unmatched_edges.push(format!(
                "{set}/{}: no edge through OCC's midpoint {p} (OCC {:?})",
                oracle.file, oe.convexity
            ));
            continue;
        }
        tally.edges += 1;
        let ours = graph.edges[e].convexity;
        let theirs = match oe.convexity.as_slice() {
            [one] => one.as_str(),
            _ => "mixed",
        };
        let agree = match (ours, theirs) {
            (Convexity::Convex, "convex")
            | (Convexity::Concave, "concave")
            | (Convexity::Smooth, "smooth")
            | (Convexity::Mixed, "mixed")
            // OpenCascade lists a seam (one face on both sides) as `other`.
            | (Convexity::Seam, "other") => true,
            _ => false,
        };
        let kink = (180.0 - graph.edges[e].angle_min_deg)
            .abs()
            .max((180.0 - graph.edges[e].angle_max_deg).abs());
        if !agree && theirs == "smooth" && kink < OCC_G1_ANGLE_DEG {
            *tally
                .explained
                .entry("convexity: kink under OCC's fixed 0.1 rad G1 tolerance")
                .or_default() += 1;
        } else if !agree && theirs == "other" && ours == Convexity::Smooth {
            *tally
                .explained
                .entry("convexity: OCC could not classify (other), ours smooth")
                .or_default() += 1;
        } else if !agree {
            tally.convexity_differences.push(format!(
                "{set}/{} edge #{}: ours {} (angles {:.3}..{:.3}°), OCC {:?}",
                oracle.file,
                graph.edges[e].step_id,
                ours.name(),
                graph.edges[e].angle_min_deg,
                graph.edges[e].angle_max_deg,
                oe.convexity
            ));
        }
    }
}

/// Whether OpenCascade gives a face of the same kind at the same centroid
/// (within 0.05 mm) in another file of the set our area (within the kind's
/// tolerance): OpenCascade then disagrees with itself about one geometry,
/// and our value is the one it gives elsewhere. (NIST's FTC 07 and STC 07
/// carry one solid; OpenCascade's areas of some of its sphere faces differ
/// by ~6 % between them.)
fn opencascade_twin_agrees(
    oracles: &[Oracle],
    oracle: &Oracle,
    of: &OracleFace,
    ours: f64,
) -> bool {
    oracles.iter().filter(|o| o.file != oracle.file).any(|o| {
        o.faces.iter().any(|f| {
            f.surface == of.surface
                && (0..3).all(|k| (f.centroid[k] - of.centroid[k]).abs() < 0.05)
                && (f.area - ours).abs() <= area_tolerance(&f.surface) * ours
        })
    })
}

/// Whether a point lies off every face of the solid (outside each face's
/// box by more than `tol`): an OpenCascade edge there belongs to geometry
/// beside the solid (a supplemental surface model), which we keep apart.
fn off_the_solid(props: &[thinwall_brep::FaceProps], p: &Point3, tol: f64) -> bool {
    props
        .iter()
        .all(|pr| (0..3).any(|k| p[k] < pr.bbox.min[k] - tol || p[k] > pr.bbox.max[k] + tol))
}

fn run_set(set: &str) -> Tally {
    let oracle_dir = common::root().join("tests/oracle").join(set);
    let data_dir = match set {
        "mfcad" => common::shared_data().join("mfcad/train"),
        other => common::shared_data().join(other),
    };
    let mut tally = Tally::default();
    let mut files: Vec<_> = std::fs::read_dir(&oracle_dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    files.sort();
    let oracles: Vec<Oracle> = files
        .iter()
        .map(|path| serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap())
        .collect();
    for oracle in &oracles {
        check_file(
            set,
            &oracles,
            oracle,
            &data_dir.join(&oracle.file),
            &mut tally,
        );
    }
    println!(
        "{set}: {} faces, worst planar area rel. error {:.2e} ({}), worst curved {:.2e} ({}); {} edges, {} convexity differences",
        tally.faces,
        tally.worst_plane.0,
        tally.worst_plane.1,
        tally.worst_curved.0,
        tally.worst_curved.1,
        tally.edges,
        tally.convexity_differences.len()
    );
    println!(
        "  {} OCC edges not matched to ours by midpoint",
        tally.unmatched_edges.len()
    );
    for (cause, n) in &tally.explained {
        println!("  explained: {n} × {cause}");
    }
    let listing: Vec<&String> = tally
        .area_failures
        .iter()
        .chain(&tally.convexity_differences)
        .chain(&tally.unmatched_edges)
        .collect();
    for d in listing.iter().take(40) {
        println!("  {d}");
    }
    let out = common::root().join(format!("target/occ_agreement_{set}.txt"));
    let _ = std::fs::write(
        &out,
        listing.iter().map(|s| format!("{s}\n")).collect::<String>(),
    );
    tally
}

fn assert_set(set: &str) {
    let t = run_set(set);
    assert!(t.faces > 0 && t.edges > 0, "{set}: nothing compared");
    assert!(
        t.area_failures.is_empty(),
        "{set}: {} area disagreements",
        t.area_failures.len()
    );
    assert!(
        t.unmatched_edges.is_empty(),
        "{set}: {} OCC edges unmatched and unexplained",
        t.unmatched_edges.len()
    );
    assert!(
        t.convexity_differences.is_empty(),
        "{set}: {} convexity disagreements",
        t.convexity_differences.len()
    );
}

#[test]
fn thinwall_parts_agree_with_opencascade() {
    assert_set("thinwall");
}

#[test]
fn mfinstseg_parts_agree_with_opencascade() {
    assert_set("mfinstseg");
}

#[test]
fn mfcad_parts_agree_with_opencascade() {
    assert_set("mfcad");
}

#[test]
fn nist_parts_agree_with_opencascade() {
    assert_set("nist");
}
