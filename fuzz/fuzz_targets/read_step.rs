//! Any bytes: the reader returns a part or an error, and whatever it returns
//! can be measured and graphed without a panic.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok((part, _)) = thinwall_step::read_bytes(data, "fuzz.step") {
        for f in part.face_ids() {
            let _ = thinwall_brep::compute_face_props(&part, f);
        }
        let _ = thinwall_graph::AdjacencyGraph::build(&part, &part.tolerances());
    }
});
