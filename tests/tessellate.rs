//! Triangles of every face (for the reports) on every shared part and
//! every fixture: watertight along shared edges (every triangle side used
//! by exactly two triangles, in opposite directions, on a closed solid)
//! and of each face's exact area within 0.5 %.
//!
//! Where the file itself is defective the test says how, from the part's
//! topology and geometry, independently of the tessellation:
//! - an edge used by one face only (the file's shell is open there) has
//!   no twin side;
//! - a loop that does not close in the file (an edge ends at another
//!   vertex than the next starts at) is closed by a chord, so its face and
//!   the sides along it cannot match, and its exact area is undefined;
//! - a vertex off its edge's curve by the file's own gap moves the face's
//!   outline by that much: the area may differ by up to gap × perimeter.

mod common;

use std::collections::{HashMap, HashSet};
use thinwall_analysis::{PartAnalysis, Setup};
use thinwall_brep::tessellate::{open_loop, part_mesh, Mesh};
use thinwall_brep::{FaceId, Part};

fn parts() -> Vec<std::path::PathBuf> {
    let data = common::shared_data();
    let mut v = common::thin_walled_parts();
    for dir in ["mfcad/train", "mfcadpp_gen", "mfinstseg", "nist"] {
        v.extend(common::step_files(&data.join(dir)));
    }
    v
}

/// The largest distance between a vertex of the face and the end of its
/// edge's curve there (the file's gap), and the face's perimeter in the
/// mesh.
fn gap_and_perimeter(part: &Part, mesh: &Mesh, f: FaceId) -> (f64, f64) {
    let (mut gap, mut perimeter) = (0.0f64, 0.0);
    for &l in &part.face(f).loops {
        for ce in &part.loop_(l).coedges {
            let e = part.edge(ce.edge);
            for w in mesh.edges[ce.edge.index()].windows(2) {
                perimeter += (mesh.points[w[1] as usize] - mesh.points[w[0] as usize]).norm();
            }
            let Some(c) = &e.nurbs else { continue };
            let spans = c.spans();
            if let (Some(first), Some(last)) = (spans.first(), spans.last()) {
                gap = gap.max((c.point(first.0) - part.vertex(e.start).point).norm());
                gap = gap.max((c.point(last.1) - part.vertex(e.end).point).norm());
            }
        }
    }
    (gap, perimeter)
}

/// The chords closing loops the file leaves open: (end, start) vertex
/// (point) ids of each gap.
fn loop_gaps(part: &Part) -> Vec<(u32, u32)> {
    let mut gaps = Vec::new();
    for f in part.face_ids() {
        for &l in &part.face(f).loops {
            let coedges = &part.loop_(l).coedges;
            let ends = |k: usize| {
                let ce = &coedges[k];
                let e = part.edge(ce.edge);
                if ce.forward {
                    (e.start.0, e.end.0)
                } else {
                    (e.end.0, e.start.0)
                }
            };
            for k in 0..coedges.len() {
                let (end, start) = (ends(k).1, ends((k + 1) % coedges.len()).0);
                if end != start {
                    gaps.push((end, start));
                }
            }
        }
    }
    gaps
}

/// Edges the file's shell uses once, and edges of faces with open loops.
fn defective_edges(part: &Part) -> HashSet<u32> {
    let mut uses: HashMap<u32, usize> = HashMap::new();
    let mut bad = HashSet::new();
    for f in part.face_ids() {
        let face = part.face(f);
        let open = open_loop(part, face).is_some();
        for &l in &face.loops {
            for ce in &part.loop_(l).coedges {
                *uses.entry(ce.edge.0).or_default() += 1;
                if open {
                    bad.insert(ce.edge.0);
                }
            }
        }
    }
    bad.extend(uses.into_iter().filter(|&(_, n)| n == 1).map(|(e, _)| e));
    bad
}

#[test]
fn every_shared_part_is_watertight_and_of_its_area() {
    let (mut faces, mut parts_done, mut open_loops, mut by_gap) = (0, 0, 0, 0);
    let mut worst: f64 = 0.0;
    for path in parts() {
        let name = path.display().to_string();
        let part = match thinwall_step::read_file(&path) {
            Ok((part, _)) => part,
            // NIST FTC 08 holds tessellated geometry only: nothing to draw.
            Err(e) => {
                assert_eq!(e.code(), "no_brep", "{name}: {e}");
                assert!(e.to_string().contains("tessellated geometry only"));
                continue;
            }
        };
        let mesh = part_mesh(&part);
        let a = PartAnalysis::new(&part, Setup::default());
        for fm in &mesh.faces {
            let face = part.face(fm.face);
            let id = face.step_id;
            assert!(
                !fm.triangles.is_empty(),
                "{name}: face #{id}: {:?}",
                fm.issue
            );
            if let Some(why) = open_loop(&part, face) {
                assert_eq!(fm.issue.as_deref(), Some(why.as_str()));
                open_loops += 1;
                continue;
            }
            assert!(fm.issue.is_none(), "{name}: face #{id}: {:?}", fm.issue);
            let want = a.props(fm.face).area;
            let got = mesh.face_area(fm);
            let err = (got - want).abs();
            let (gap, perimeter) = gap_and_perimeter(&part, &mesh, fm.face);
            assert!(
                err <= 5e-3 * want + gap * perimeter,
                "{name}: face #{id} area {got} want {want} (file gap {gap:.1e} mm)"
            );
            if err > 5e-3 * want {
                by_gap += 1;
            } else {
                worst = worst.max(err / want.max(1e-300));
            }
            faces += 1;
        }
        // Closed: each directed side once, its reverse once, but along the
        // file's own defects.
        let defective: HashSet<(u32, u32)> = defective_edges(&part)
            .into_iter()
            .flat_map(|e| {
                mesh.edges[e as usize]
                    .windows(2)
                    .map(|w| (w[0], w[1]))
                    .collect::<Vec<_>>()
            })
            .flat_map(|(a, b)| [(a, b), (b, a)])
            .collect();
        // Around a gap the file's faces do not meet: sides between the
        // gaps' vertices (the chords and what the missing edge would have
        // matched).
        let gap_vertices: HashSet<u32> = loop_gaps(&part)
            .into_iter()
            .flat_map(|(a, b)| [a, b])
            .collect();
        let mut sides: HashMap<(u32, u32), i32> = HashMap::new();
        for fm in &mesh.faces {
            for t in &fm.triangles {
                for k in 0..3 {
                    *sides.entry((t[k], t[(k + 1) % 3])).or_default() += 1;
                }
            }
        }
        for (&(a, b), &n) in &sides {
            if defective.contains(&(a, b))
                || (gap_vertices.contains(&a) && gap_vertices.contains(&b))
            {
                continue;
            }
            assert_eq!(n, 1, "{name}: side {a}-{b} used {n} times one way");
            assert_eq!(
                sides.get(&(b, a)),
                Some(&1),
                "{name}: side {a}-{b} has no twin"
            );
        }
        parts_done += 1;
    }
    assert!(parts_done > 450, "{parts_done} parts");
    eprintln!(
        "{parts_done} parts, {faces} faces within 0.5 % (worst {worst:.2e}); \
         {by_gap} more within the file's vertex gap; {open_loops} face(s) with loops the file leaves open"
    );
}

/// A cylinder is meshed in columns only where its triangles stay one
/// column wide (flat strips between generator lines): a triangle's centre
/// and sides' middles lie within twice the face's deviation of the
/// cylinder (√2 columns' sagitta) but for a few (279 of 175,738, at most
/// 0.5 % allowed) along chords of the boundary, on every shared part with
/// a B-rep; and those strips are
/// few (NIST FTC 07's 133 cylinders under 10,000 triangles). With rows
/// (before the change) the shared parts had 2,371,114 triangles on
/// cylinders, the worst 5.6 times the allowance; now 175,738, the worst 5.4.
#[test]
fn cylinders_in_columns_stay_within_twice_their_deviation() {
    use thinwall_brep::tessellate::RELATIVE_DEVIATION;
    use thinwall_geom::{Point3, Surface};
    let (mut checked, mut over, mut worst) = (0usize, 0usize, 0.0f64);
    for path in parts() {
        let Ok((part, _)) = thinwall_step::read_file(&path) else {
            continue;
        };
        let mesh = part_mesh(&part);
        let deviation = RELATIVE_DEVIATION * part.bounding_box().diagonal();
        let mut on_cylinders = 0;
        for fm in &mesh.faces {
            let face = part.face(fm.face);
            let Surface::Cylinder { frame, radius } = &face.surface else {
                continue;
            };
            if open_loop(&part, face).is_some() {
                continue;
            }
            on_cylinders += fm.triangles.len();
            let allowed = 2.0 * deviation.min(0.002 * radius) * (1.0 + 1e-6) + 1e-9;
            let off = |p: Point3| {
                let l = frame.to_local(&p);
                (l.x.hypot(l.y) - radius).abs()
            };
            let mid = |p: Point3, q: Point3| Point3::from(0.5 * (p.coords + q.coords));
            for t in &fm.triangles {
                let [a, b, c] = t.map(|i| mesh.points[i as usize]);
                let centre = Point3::from((a.coords + b.coords + c.coords) / 3.0);
                let d = [centre, mid(a, b), mid(b, c), mid(c, a)]
                    .map(off)
                    .into_iter()
                    .fold(0.0, f64::max);
                worst = worst.max(d / allowed);
                over += usize::from(d > allowed);
                checked += 1;
            }
        }
        if path.ends_with("nist_ftc_07_asme1_ap242-e2.stp") {
            assert!(on_cylinders < 10_000, "FTC 07: {on_cylinders} on cylinders");
        }
    }
    eprintln!(
        "{checked} triangles on cylinders, {over} over the allowance, worst {worst:.2} times"
    );
    assert!(checked > 100_000, "{checked} triangles");
    assert!(
        over * 200 <= checked,
        "{over} of {checked} over the allowance"
    );
    assert!(worst < 6.0, "worst {worst} times the allowance");
}
