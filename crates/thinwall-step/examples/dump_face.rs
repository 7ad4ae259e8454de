//! Print a face's surface, loops and edges: `dump_face FILE STEP_ID`.
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let (part, report) = thinwall_step::read_file(&args[1]).expect("read");
    let id: u64 = args[2].parse().expect("step id");
    let f = part.face_by_step_id(id).expect("face");
    let face = part.face(f);
    println!(
        "face #{} same_sense={} surface={:?}",
        face.step_id, face.same_sense, face.surface
    );
    for &l in &face.loops {
        let lp = part.loop_(l);
        println!(" loop outer={} vertex={:?}", lp.is_outer, lp.vertex);
        for ce in &lp.coedges {
            let e = part.edge(ce.edge);
            let (a, b) = (part.vertex(e.start).point, part.vertex(e.end).point);
            let ends = e.nurbs.as_ref().map(|n| {
                let (t0, t1) = n.domain();
                (n.point(t0), n.point(t1), n.degree)
            });
            println!(
                "  edge #{} fwd={} {:?} start {a} end {b} nurbs {:?}",
                e.step_id,
                ce.forward,
                e.curve.name(),
                ends
            );
        }
    }
    let p = thinwall_brep::compute_face_props(&part, f);
    println!(
        "area {} centroid {} warnings {:?}",
        p.area, p.centroid, p.warnings
    );
    for r in report
        .repaired
        .iter()
        .filter(|r| r.message.contains("edge"))
        .take(5)
    {
        println!("{r:?}");
    }
}
