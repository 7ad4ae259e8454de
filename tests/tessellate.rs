//! Triangles of every face (for reports): watertight along shared edges
//! (every triangle side is used by exactly two triangles, in opposite
//! directions, on a closed solid) and of the faces' area within 0.5 %.

mod common;

use std::collections::HashMap;
use thinwall_analysis::{PartAnalysis, Setup};
use thinwall_brep::tessellate::tessellate;

fn parts() -> Vec<std::path::PathBuf> {
    let mut v = common::thin_walled_parts();
    let mut mfcad = common::step_files(&common::shared_data().join("mfcad/train"));
    mfcad.truncate(40);
    v.extend(mfcad);
    v
}

#[test]
fn every_part_is_watertight_and_of_its_area() {
    let (mut faces, mut parts_done) = (0, 0);
    let mut worst: f64 = 0.0;
    for path in parts() {
        let name = path.display().to_string();
        let (part, _) = thinwall_step::read_file(&path).unwrap();
        let size = part.bounding_box().diagonal();
        let mesh = tessellate(&part, 1e-3 * size);
        let a = PartAnalysis::new(&part, Setup::default());
        for fm in &mesh.faces {
            assert!(
                fm.issue.is_none(),
                "{name}: face #{}: {:?}",
                part.face(fm.face).step_id,
                fm.issue
            );
            let want = a.props(fm.face).area;
            let got = mesh.face_area(fm);
            let err = (got - want).abs() / want.max(1e-9);
            worst = worst.max(err);
            assert!(
                err <= 5e-3,
                "{name}: face #{} area {got} want {want}",
                part.face(fm.face).step_id
            );
            faces += 1;
        }
        // Closed: each directed side once, its reverse once.
        let mut sides: HashMap<(u32, u32), i32> = HashMap::new();
        for fm in &mesh.faces {
            for t in &fm.triangles {
                for k in 0..3 {
                    *sides.entry((t[k], t[(k + 1) % 3])).or_default() += 1;
                }
            }
        }
        for (&(a, b), &n) in &sides {
            assert_eq!(n, 1, "{name}: side {a}-{b} used {n} times one way");
            assert_eq!(
                sides.get(&(b, a)),
                Some(&1),
                "{name}: side {a}-{b} has no twin"
            );
        }
        parts_done += 1;
    }
    eprintln!("{parts_done} parts, {faces} faces tessellated; worst face area error {worst:.2e}");
}
