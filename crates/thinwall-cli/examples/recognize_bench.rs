//! Recognition timing: `recognize_bench [--repeat N] FILE...`.
//!
//! Per file, the median over N runs of: reading the STEP file, building the
//! adjacency graph, and the whole recognition (`thinwall_pipeline::run`:
//! face properties, stiffness features, connections, machining features).
//! Panels for it come from `scripts/make_bench_panels.py` (rib grids of
//! ~1k, 10k, 50k faces).

use std::time::Instant;

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let mut repeat = 3;
    if args.first().map(String::as_str) == Some("--repeat") {
        repeat = args[1].parse().expect("--repeat N");
        args.drain(..2);
    }
    println!(
        "{:>8} {:>10} {:>10} {:>12} {:>10} {:>8}",
        "faces", "read s", "graph s", "recognize s", "total s", "walls"
    );
    for path in args {
        let (mut read, mut graph, mut rec) = (vec![], vec![], vec![]);
        let (mut faces, mut walls) = (0, 0);
        for _ in 0..repeat {
            let t0 = Instant::now();
            let (part, _) = match thinwall_step::read_file(&path) {
                Ok(x) => x,
                Err(e) => {
                    eprintln!("{e}");
                    break;
                }
            };
            let t1 = Instant::now();
            let g = thinwall_graph::AdjacencyGraph::build(&part, &part.tolerances());
            let t2 = Instant::now();
            let r = match thinwall_pipeline::run(&part, Some(&g), &Default::default()) {
                Ok(out) => out.recognition,
                Err(e) => {
                    eprintln!("{path}: {e}");
                    break;
                }
            };
            let t3 = Instant::now();
            faces = part.faces.len();
            walls = r.features.iter().filter(|f| f.kind.is_wall()).count();
            read.push((t1 - t0).as_secs_f64());
            graph.push((t2 - t1).as_secs_f64());
            rec.push((t3 - t2).as_secs_f64());
        }
        if read.is_empty() {
            continue;
        }
        let (a, b, c) = (median(read), median(graph), median(rec));
        println!(
            "{faces:>8} {a:>10.4} {b:>10.4} {c:>12.4} {:>10.4} {walls:>8}",
            a + b + c
        );
    }
}
