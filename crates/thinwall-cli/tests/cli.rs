//! The `thinwall` binary: output formats and exit codes.

use std::path::PathBuf;
use std::process::Command;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_thinwall"))
}

fn shared(rel: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../../shared/data")
        .join(rel)
}

#[test]
fn inspect_json_lists_faces_and_edges_by_step_id() {
    let out = bin()
        .args(["inspect", "--format", "json"])
        .arg(shared("thinwall/loose_rib_00.step"))
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["schema"], "thinwall/inspect/1");
    let faces = v["faces"].as_array().unwrap();
    assert_eq!(faces.len(), 11);
    // Rib side faces from the ground truth are there, by entity id.
    for id in [535, 633] {
        assert!(faces.iter().any(|f| f["step_id"] == id), "face #{id}");
    }
    assert!(faces
        .iter()
        .all(|f| f["surface"] == "plane" && f["area"].as_f64().unwrap() > 0.0));
    let edges = v["edges"].as_array().unwrap();
    assert_eq!(edges.len(), 24);
    assert!(edges
        .iter()
        .all(|e| e["faces"].as_array().unwrap().len() == 2));
    assert_eq!(v["edge_convexity_counts"]["concave"], 4);
    assert_eq!(v["supplemental_faces"], 0);
}

#[test]
fn inspect_text_is_a_summary() {
    let out = bin()
        .arg("inspect")
        .arg(shared("nist/nist_ftc_10_asme1_ap242-e2.stp"))
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("faces") && text.contains("convex"), "{text}");
    assert!(
        text.contains("supplemental surface geometry: 18 faces"),
        "{text}"
    );
}

#[test]
fn bad_input_exits_non_zero_with_a_message() {
    let out = bin()
        .arg("inspect")
        .arg(shared("nist/nist_ftc_08_asme1_ap242-e1-tg.stp"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(
        err.contains("tessellated") && err.contains("nist_ftc_08"),
        "{err}"
    );
    let out = bin()
        .arg("inspect")
        .arg("/no/such/file.step")
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("/no/such/file.step"));
    let out = bin()
        .arg("inspect")
        .arg("--format")
        .arg("yaml")
        .arg("x.step")
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2), "usage errors exit 2");
}
