mod common;
use std::collections::HashMap;
use thinwall_analysis::{PartAnalysis, Setup};
use thinwall_brep::tessellate::tessellate;

#[test]
#[ignore]
fn diag() {
    let sd = common::shared_data();
    let mut v = common::step_files(&sd.join("nist"));
    v.extend(common::step_files(&sd.join("mfinstseg")));
    if std::env::var("ALL").is_ok() {
        v.extend(common::step_files(&sd.join("mfcadpp_gen")));
        v.extend(common::step_files(&sd.join("mfcad/train")));
        v.extend(common::step_files(&sd.join("thinwall")));
    }
    for path in v {
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        let Ok((part, _)) = thinwall_step::read_file(&path) else { eprintln!("{name}: unreadable"); continue };
        let size = part.bounding_box().diagonal();
        let t = std::time::Instant::now();
        let mesh = tessellate(&part, 1e-3 * size);
        let secs = t.elapsed().as_secs_f64();
        let a = PartAnalysis::new(&part, Setup::default());
        let mut issues: HashMap<String, usize> = HashMap::new();
        let mut area_bad = Vec::new();
        for fm in &mesh.faces {
            if let Some(i) = &fm.issue { *issues.entry(i.clone()).or_default() += 1; continue; }
            let want = a.props(fm.face).area;
            let got = mesh.face_area(fm);
            let err = (got - want).abs() / want.max(1e-9);
            if err > 5e-3 {
                let face = part.face(fm.face);
                let loops: Vec<String> = face.loops.iter().map(|&l| {
                    let lp = part.loop_(l);
                    let seams = lp.coedges.iter().filter(|ce| face.loops.iter().flat_map(|&m| part.loop_(m).coedges.iter()).filter(|c2| c2.edge == ce.edge).count() > 1).count();
                    format!("{}e{}s", lp.coedges.len(), seams)
                }).collect();
                area_bad.push((face.step_id, face.surface.kind_name(), (err * 1000.0).round() / 1000.0, loops));
            }
        }
        let mut sides: HashMap<(u32, u32), i32> = HashMap::new();
        for fm in &mesh.faces { for t in &fm.triangles { for k in 0..3 { *sides.entry((t[k], t[(k + 1) % 3])).or_default() += 1; } } }
        let open = sides.iter().filter(|(&(a, b), &n)| n != 1 || sides.get(&(b, a)) != Some(&1)).count();
        if open > 0 || !issues.is_empty() || !area_bad.is_empty() {
            eprintln!("{name}: faces {} open {open} issues {:?} area {:?} {secs:.2}s", part.faces.len(), issues, &area_bad[..area_bad.len().min(8)]);
        }
    }
}

#[test]
#[ignore]
fn one_face() {
    let file = std::env::var("FILE").unwrap();
    let want_id: u64 = std::env::var("FACE").unwrap().parse().unwrap();
    let (part, _) = thinwall_step::read_file(std::path::Path::new(&file)).unwrap();
    let size = part.bounding_box().diagonal();
    let mesh = tessellate(&part, 1e-3 * size);
    let a = PartAnalysis::new(&part, Setup::default());
    for fm in &mesh.faces {
        let face = part.face(fm.face);
        if face.step_id != want_id { continue; }
        eprintln!("surface {:?}", face.surface);
        eprintln!("area want {} got {} tris {}", a.props(fm.face).area, mesh.face_area(fm), fm.triangles.len());
        for &l in &face.loops {
            for ce in &part.loop_(l).coedges {
                let e = part.edge(ce.edge);
                eprintln!(" edge #{} fwd {} kind {:?} pts {}", e.step_id, ce.forward, e.curve, mesh.edges[ce.edge.index()].len());
                for &i in &mesh.edges[ce.edge.index()] { let p = mesh.points[i as usize]; eprint!("({:.3},{:.3},{:.3}) ", p.x, p.y, p.z); }
                eprintln!();
            }
        }
    }
}
