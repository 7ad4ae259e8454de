//! Slowest faces to measure: `face_times FILE`.
fn main() {
    let path = std::env::args().nth(1).expect("file");
    let (part, _) = thinwall_step::read_file(&path).expect("read");
    let mut t: Vec<(f64, u64, &str, usize)> = part
        .face_ids()
        .map(|f| {
            let s = std::time::Instant::now();
            let p = thinwall_brep::compute_face_props(&part, f);
            std::hint::black_box(&p);
            let face = part.face(f);
            let n: usize = face
                .loops
                .iter()
                .map(|&l| part.loop_(l).coedges.len())
                .sum();
            (
                s.elapsed().as_secs_f64() * 1e3,
                face.step_id,
                face.surface.kind_name(),
                n,
            )
        })
        .collect();
    t.sort_by(|a, b| b.0.total_cmp(&a.0));
    for x in t.iter().take(8) {
        println!("{:.1} ms  #{} {} ({} coedges)", x.0, x.1, x.2, x.3);
    }
}
