//! Load + graph timing per file: `load_bench [--repeat N] FILE...`.
//!
//! Prints one JSON object per file: the median over N runs of reading the
//! STEP file into a part (`read_ms`), building the adjacency graph with
//! convexity (`graph_ms`), and computing every face's properties
//! (`props_ms`). Used by `scripts/bench_load.py`, which times OpenCascade
//! on the same files in the same run.

use std::time::Instant;
use thinwall_graph::AdjacencyGraph;

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let mut repeat = 5;
    if args.first().map(String::as_str) == Some("--repeat") {
        repeat = args[1].parse().expect("--repeat N");
        args.drain(..2);
    }
    for path in args {
        let (mut read, mut graph, mut props) = (vec![], vec![], vec![]);
        let mut faces = 0;
        for _ in 0..repeat {
            let t0 = Instant::now();
            let Ok((part, _)) = thinwall_step::read_file(&path) else {
                break;
            };
            let t1 = Instant::now();
            let g = AdjacencyGraph::build(&part, &part.tolerances());
            let t2 = Instant::now();
            for f in part.face_ids() {
                std::hint::black_box(thinwall_brep::compute_face_props(&part, f));
            }
            let t3 = Instant::now();
            std::hint::black_box(&g);
            faces = part.faces.len();
            read.push((t1 - t0).as_secs_f64() * 1e3);
            graph.push((t2 - t1).as_secs_f64() * 1e3);
            props.push((t3 - t2).as_secs_f64() * 1e3);
        }
        if read.is_empty() {
            println!("{{\"file\":{path:?},\"error\":true}}");
            continue;
        }
        println!(
            "{{\"file\":{path:?},\"faces\":{faces},\"read_ms\":{:.3},\"graph_ms\":{:.3},\"props_ms\":{:.3}}}",
            median(read),
            median(graph),
            median(props)
        );
    }
}
