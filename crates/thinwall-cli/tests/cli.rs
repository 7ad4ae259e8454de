//! The `thinwall` binary: output formats and exit codes.

use std::path::PathBuf;
use std::process::Command;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_thinwall"))
}

/// Run the command, require success (showing stderr otherwise), parse stdout as JSON.
fn json_of(cmd: &mut Command) -> serde_json::Value {
    let out = cmd.output().unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

fn shared(rel: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../../shared/data")
        .join(rel)
}

#[test]
fn inspect_json_lists_faces_and_edges_by_step_id() {
    let v = json_of(
        bin()
            .args(["inspect", "--format", "json"])
            .arg(shared("thinwall/loose_rib_00.step")),
    );
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

fn fixture(rel: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../fixtures")
        .join(rel)
}

#[test]
fn recognize_json_follows_the_contract() {
    let v = json_of(
        bin()
            .args(["recognize"])
            .arg(shared("thinwall/panel_06.step")),
    );
    assert!(v["schema"]
        .as_str()
        .unwrap()
        .starts_with("thinwall/recognition/"));
    assert_eq!(v["part"]["faces"], 45);
    assert_eq!(v["faces"].as_array().unwrap().len(), 45);
    assert_eq!(v["setup"]["up"], serde_json::json!([0.0, 0.0, 1.0]));
    let feats = v["stiffness_features"].as_array().unwrap();
    let kinds = [
        "web", "rib", "flange", "wall", "hole", "cutout", "notch", "chamfer", "fillet",
    ];
    for f in feats {
        assert!(kinds.contains(&f["kind"].as_str().unwrap()));
        assert!(!f["faces"].as_array().unwrap().is_empty());
        if ["web", "rib", "flange", "wall"].contains(&f["kind"].as_str().unwrap()) {
            for key in [
                "thin",
                "thickness",
                "height",
                "length",
                "deflection",
                "side_faces",
                "access_directions",
            ] {
                assert!(!f[key].is_null(), "{key} missing on {}", f["id"]);
            }
        }
    }
    assert_eq!(feats.iter().filter(|f| f["kind"] == "hole").count(), 3);
    assert!(v["connections"].is_array() && v["machining_features"].is_array());
    // The schema lists exactly these kinds.
    let schema: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(
            PathBuf::from(env!("CARGO_MANIFEST_DIR"))
                .join("../../docs/schema/recognition.schema.json"),
        )
        .unwrap(),
    )
    .unwrap();
    let listed = &schema["properties"]["stiffness_features"]["items"]["properties"]["kind"]["enum"];
    assert_eq!(listed, &serde_json::json!(kinds));
}

#[test]
fn recognize_text_options_and_errors() {
    let out = bin()
        .args([
            "recognize",
            "--format",
            "text",
            "--exclude",
            "hole,fillet",
            "--up",
            "0,0,1",
        ])
        .arg(fixture("recognition/c_frame.step"))
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    // Stiffness features come before the machining features (which list holes by themselves).
    let stiffness = text.split("machining features:").next().unwrap();
    assert!(
        stiffness.contains("web") && stiffness.contains("flange") && !stiffness.contains("hole"),
        "{text}"
    );
    assert!(text.contains("machining features:"), "{text}");
    // Unknown kind, bad vector, bad config: exit 1 or 2 with a message.
    let out = bin()
        .args(["recognize", "--include", "bogus"])
        .arg(fixture("recognition/c_frame.step"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("bogus"));
    let out = bin()
        .args(["recognize", "--up", "0,0"])
        .arg(fixture("recognition/c_frame.step"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let dir = std::env::temp_dir().join(format!("tw-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let cfg = dir.join("bad.toml");
    std::fs::write(&cfg, "[thinness]\nforce_n = -3\n").unwrap();
    let out = bin()
        .args(["recognize", "--config"])
        .arg(&cfg)
        .arg(fixture("recognition/c_frame.step"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("force_n"));
    // A stiffer machine (less force) makes walls less thin.
    let cfg = dir.join("soft.toml");
    std::fs::write(&cfg, "[thinness]\nforce_n = 1.0\n").unwrap();
    let out = bin()
        .args(["recognize", "--config"])
        .arg(&cfg)
        .arg(shared("thinwall/panel_06.step"))
        .output()
        .unwrap();
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let thin = v["stiffness_features"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|f| f["thin"] == true)
        .count();
    assert!(thin < 8, "{thin} thin walls with a 1 N force");
}

#[test]
fn classify_json_and_errors() {
    let case = fixture("classify/stacked");
    let v = json_of(
        bin()
            .arg("classify")
            .arg("--part")
            .arg(case.join("part.step"))
            .arg("--volume")
            .arg(case.join("v0.step"))
            .arg("--volume")
            .arg(case.join("v1.step"))
            .args(["--before", "0:1", "--up", "0,0,1"]),
    );
    assert_eq!(v["schema"], "thinwall/classification/1");
    let vols = v["volumes"].as_array().unwrap();
    assert_eq!(vols.len(), 2);
    assert_eq!(
        (
            vols[0]["type"].as_str(),
            vols[0]["product_adjacency"].as_str()
        ),
        (Some("pocket"), Some("side"))
    );
    assert_eq!(
        (
            vols[1]["type"].as_str(),
            vols[1]["product_adjacency"].as_str()
        ),
        (Some("pocket"), Some("side_and_bottom"))
    );
    for f in vols[0]["faces"].as_array().unwrap() {
        assert!(f["closed"].is_boolean() && f["touches"].is_array());
    }
    // A sequence naming a volume that does not exist, a malformed pair.
    let bad = bin()
        .arg("classify")
        .arg("--part")
        .arg(case.join("part.step"))
        .arg("--volume")
        .arg(case.join("v0.step"))
        .args(["--before", "0:5"])
        .output()
        .unwrap();
    assert_eq!(bad.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("0..1"));
    let bad = bin()
        .arg("classify")
        .arg("--part")
        .arg(case.join("part.step"))
        .arg("--volume")
        .arg(case.join("v0.step"))
        .args(["--before", "zero"])
        .output()
        .unwrap();
    assert_eq!(bad.status.code(), Some(2));
}
