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
        "web",
        "rib",
        "flange",
        "wall",
        "hole",
        "cutout",
        "notch",
        "pocket",
        "chamfer",
        "fillet",
        "engraving",
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
    assert_eq!(
        out.status.code(),
        Some(2),
        "a bad flag value is a usage error"
    );
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
    assert_eq!(
        out.status.code(),
        Some(2),
        "unusable settings are a usage error"
    );
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

/// `thinwall classify` of the stacked fixture's two volumes.
fn classify_stacked() -> Command {
    let case = fixture("classify/stacked");
    let mut c = bin();
    c.arg("classify")
        .arg("--part")
        .arg(case.join("part.step"))
        .arg("--volume")
        .arg(case.join("v0.step"))
        .arg("--volume")
        .arg(case.join("v1.step"));
    c
}

/// Run `cmd` with `--format FORMAT -o FILE`; it must succeed and write
/// nothing to stdout. The file's text.
fn written(mut cmd: Command, format: &str, file: &std::path::Path) -> String {
    let out = cmd
        .args(["--format", format, "-o"])
        .arg(file)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(out.stdout.is_empty(), "wrote to stdout with -o");
    std::fs::read_to_string(file).unwrap()
}

#[test]
fn classify_json_and_errors() {
    let case = fixture("classify/stacked");
    let v = json_of(classify_stacked().args(["--before", "0:1", "--up", "0,0,1"]));
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
    assert_eq!(bad.status.code(), Some(2));
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

/// Check `value` against the parts of JSON Schema our schemas use:
/// `required`, `properties`, `items`, `type`, `enum`, `$ref` to the root or
/// its `$defs`, `pattern` (as a prefix or whole-match of simple patterns is
/// not needed: only presence and kinds). Returns the problems, with their
/// paths.
fn schema_problems(
    schema: &serde_json::Value,
    value: &serde_json::Value,
    path: &str,
) -> Vec<String> {
    schema_problems_in(schema, schema, value, path)
}

fn schema_problems_in(
    root: &serde_json::Value,
    schema: &serde_json::Value,
    value: &serde_json::Value,
    path: &str,
) -> Vec<String> {
    use serde_json::Value;
    if let Some(Value::String(r)) = schema.get("$ref") {
        if r == "#" {
            return schema_problems_in(root, root, value, path);
        }
        let name = r
            .strip_prefix("#/$defs/")
            .expect("refs to the root or $defs only");
        let def = &root["$defs"][name];
        assert!(def.is_object(), "{path}: no $defs/{name}");
        return schema_problems_in(root, def, value, path);
    }
    let mut out = Vec::new();
    if let Some(t) = schema.get("type") {
        let kinds: Vec<&str> = match t {
            Value::String(k) => vec![k.as_str()],
            Value::Array(ks) => ks.iter().filter_map(|k| k.as_str()).collect(),
            _ => vec![],
        };
        let ok = kinds.iter().any(|k| match *k {
            "object" => value.is_object(),
            "array" => value.is_array(),
            "string" => value.is_string(),
            "number" => value.is_number(),
            "integer" => value.is_u64() || value.is_i64(),
            "boolean" => value.is_boolean(),
            "null" => value.is_null(),
            _ => true,
        });
        if !ok {
            out.push(format!("{path}: {value} is not {kinds:?}"));
        }
    }
    if let Some(Value::Array(allowed)) = schema.get("enum") {
        if !allowed.contains(value) {
            out.push(format!("{path}: {value} not in {allowed:?}"));
        }
    }
    if let (Some(Value::Array(req)), Some(obj)) = (schema.get("required"), value.as_object()) {
        for k in req.iter().filter_map(|k| k.as_str()) {
            if !obj.contains_key(k) {
                out.push(format!("{path}: missing {k}"));
            }
        }
    }
    if let (Some(Value::Object(props)), Some(obj)) = (schema.get("properties"), value.as_object()) {
        for (k, sub) in props {
            if let Some(v) = obj.get(k) {
                out.extend(schema_problems_in(root, sub, v, &format!("{path}/{k}")));
            }
        }
    }
    if let (Some(items), Some(arr)) = (schema.get("items"), value.as_array()) {
        for (i, v) in arr.iter().enumerate() {
            out.extend(schema_problems_in(root, items, v, &format!("{path}/{i}")));
        }
    }
    out
}

fn schema(name: &str) -> serde_json::Value {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join(format!("../../docs/schema/{name}.schema.json"));
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

#[test]
fn every_json_output_follows_its_schema_and_names_its_version() {
    let version = env!("CARGO_PKG_VERSION");
    let of = |args: &[&str], file: &str| json_of(bin().args(args).arg(fixture(file)));
    let inspect = ["inspect", "--format", "json"];
    let mut outputs = vec![
        ("inspect", of(&inspect, "recognition/c_frame.step")),
        ("inspect", of(&inspect, "bracket_assembly.step")),
        (
            "recognition",
            of(&["recognize"], "recognition/rib_grid_panel.step"),
        ),
        (
            "recognition",
            of(
                &["recognize", "--exclude", "web"],
                "recognition/c_frame.step",
            ),
        ),
        (
            "recognition",
            of(
                &["recognize", "--up", "0,0,1", "--stock-offset", "1"],
                "machining/boss_plate.step",
            ),
        ),
    ];
    outputs.push((
        "classification",
        json_of(classify_stacked().args(["--before", "0:1"])),
    ));
    outputs.push(("plan", of(&["plan"], "recognition/rib_grid_panel.step")));
    outputs.push(("plan", of(&["plan"], "recognition/c_frame.step")));
    // Curved walls: mid-surfaces (cylinder, cone, offset), access ranges,
    // and the plan's limits.
    for part in [
        "curved/frame_r400.step",
        "curved/conical_flange.step",
        "curved/freeform_rib.step",
    ] {
        let v = of(&["recognize"], part);
        assert!(v["stiffness_features"]
            .as_array()
            .unwrap()
            .iter()
            .any(|f| f["mid_surface"].is_object() && f["access_range"].is_array()));
        outputs.push(("recognition", v));
    }
    let curved_plan = of(&["plan"], "curved/frame_r400.step");
    assert_eq!(curved_plan["limits"].as_array().map(Vec::len), Some(2));
    outputs.push(("plan", curved_plan));
    outputs.push(("access", of(&["access"], "access/two_ribs.step")));
    for part in ["ops/pocket_islands.step", "ops/drill_plate.step"] {
        outputs.push(("operations", of(&["operations", "--format", "json"], part)));
    }
    let by_feature = of(
        &["operations", "--by-feature", "--format", "json"],
        "recognition/notched_rib.step",
    );
    assert!(by_feature["setup"]["layers"]
        .as_array()
        .unwrap()
        .iter()
        .all(|l| l["feature"].is_string()));
    outputs.push(("operations", by_feature));
    // A web pocketed from both sides: two set-ups proposed, the second
    // cuts what the first left under the web; nothing is left.
    let both = of(
        &["operations", "--format", "json"],
        "pockets/pockets_4.step",
    );
    assert!(both["setup"]["out_of_reach_mm3"].as_f64().unwrap() > 0.0);
    // The first up proposed leads the ups tried, and is the sheet's.
    assert_eq!(both["proposal"]["candidates"][0]["up"], both["up"]);
    assert_eq!(both["proposal"]["ups"].as_array().map(Vec::len), Some(2));
    assert!(both["then"][0]["setup"]["operations"]
        .as_array()
        .is_some_and(|o| !o.is_empty()));
    assert_eq!(both["residue"]["blocks"], 0);
    outputs.push(("operations", both));
    for (name, v) in &outputs {
        let problems = schema_problems(&schema(name), v, name);
        assert!(problems.is_empty(), "{problems:#?}");
        assert_eq!(v["thinwall_version"], version, "{name}");
        assert!(v["schema"]
            .as_str()
            .unwrap()
            .starts_with(&format!("thinwall/{name}/")));
    }
    // The settings in force are in the recognition report.
    let r = &outputs[3].1;
    assert_eq!(
        r["settings"]["recognition"]["exclude"],
        serde_json::json!(["web"])
    );
    assert_eq!(r["settings"]["recognition"]["thinness"]["force_n"], 200.0);
    // A wrong output is caught: the checker is not a rubber stamp.
    let mut broken = outputs[2].1.clone();
    broken["stiffness_features"][0]["kind"] = serde_json::json!("girder");
    broken.as_object_mut().unwrap().remove("setup");
    assert_eq!(
        schema_problems(&schema("recognition"), &broken, "r").len(),
        2
    );
}

#[test]
fn exit_codes_follow_the_kind_of_error() {
    // 1: input data (a missing file); 2: usage (bad flag value, bad
    // settings, contradictory filters, an impossible sequence).
    let part = fixture("recognition/c_frame.step");
    let code = |args: &[&str], file: &std::path::Path| {
        bin().args(args).arg(file).output().unwrap().status.code()
    };
    assert_eq!(
        code(&["recognize"], std::path::Path::new("/no/such.step")),
        Some(1)
    );
    assert_eq!(code(&["recognize", "--force", "1e400"], &part), Some(2));
    assert_eq!(
        code(
            &["recognize", "--include", "hole", "--exclude", "hole"],
            &part
        ),
        Some(2)
    );
    assert_eq!(
        code(
            &["recognize", "--tilt-limit", "95", "--machine", "5-axis"],
            &part
        ),
        Some(2)
    );
    let out = bin()
        .args(["recognize", "--force", "1e400"])
        .arg(&part)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("force_n") && err.contains("finite"), "{err}");
    // Stock: a negative allowance is usage; a stock that does not hold the
    // part, or a missing stock file, is input.
    let plate = fixture("machining/boss_plate.step");
    assert_eq!(
        code(&["recognize", "--stock-offset", "-1"], &plate),
        Some(2)
    );
    let small = fixture("recognition/c_frame.step");
    let small = small.to_str().unwrap();
    assert_eq!(code(&["recognize", "--stock", small], &plate), Some(1));
    assert_eq!(
        code(&["recognize", "--stock", "/no/such.step"], &plate),
        Some(1)
    );
    let out = bin()
        .args(["recognize", "--stock", small])
        .arg(&plate)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("does not contain the part"), "{err}");
}

#[test]
fn verbose_shows_stage_times_and_every_warning() {
    let out = bin()
        .args(["recognize", "--verbose", "--format", "text"])
        .arg(shared("nist/nist_ftc_07_asme1_ap242-e2.stp"))
        .output()
        .unwrap();
    assert!(out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    for stage in [
        "read",
        "adjacency graph",
        "face properties",
        "stiffness features",
        "machining features",
    ] {
        assert!(err.contains(&format!(" s  {stage}")), "{stage}: {err}");
    }
    // Every warning in full, in the report too.
    let text = String::from_utf8_lossy(&out.stdout);
    let listed = err.lines().filter(|l| l.starts_with("warning: ")).count();
    assert!(listed > 100, "{listed}");
    assert!(text.contains(&format!("warnings: {listed}")), "{text}");
    // Without --verbose, nothing on stderr.
    let quiet = bin()
        .args(["recognize", "--format", "text"])
        .arg(shared("nist/nist_ftc_07_asme1_ap242-e2.stp"))
        .output()
        .unwrap();
    assert!(quiet.stderr.is_empty());
}

#[test]
fn plan_and_size_wall_outputs_and_exit_codes() {
    let part = fixture("recognition/c_frame.step");
    let v = json_of(bin().arg("plan").arg(&part));
    assert!(!v["sequence"].as_array().unwrap().is_empty());
    assert!(!v["walls"].as_array().unwrap().is_empty());
    let text = bin()
        .args(["plan", "--format", "text"])
        .arg(&part)
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&text.stdout);
    assert!(
        text.contains("order (") && text.contains("rejected candidates"),
        "{text}"
    );
    // A malformed rule file: exit 2, naming the file, the rule and the line.
    let dir = std::env::temp_dir().join(format!("tw-plan-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let bad = dir.join("bad.toml");
    std::fs::write(
        &bad,
        "[[rule]]\nname = \"x\"\npriority = 1\nfirst = [\"girder\"]\nsecond = [\"web\"]\nrelation = \"before\"\n",
    )
    .unwrap();
    let out = bin()
        .arg("plan")
        .arg(&part)
        .arg("--rules")
        .arg(&bad)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("bad.toml:1: rule 'x'") && err.contains("girder"),
        "{err}"
    );
    let out = bin().args(["plan", "/no/such.step"]).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    // size-wall: the contract's keys; bad sizes are usage errors.
    let v = json_of(bin().args([
        "size-wall",
        "--length",
        "120",
        "--thickness",
        "1",
        "--height",
        "72",
    ]));
    assert_eq!(
        (v["B_RF"].as_f64(), v["h_RF"].as_f64(), v["H_RF"].as_f64()),
        (Some(11.0), Some(12.0), Some(36.0))
    );
    assert!(v["trace"].as_array().unwrap().len() >= 3);
    assert_eq!(v["parameters"]["allowed_deflection_mm"], 0.01);
    for args in [
        ["--length", "0", "--thickness", "1", "--height", "72"],
        ["--length", "120", "--thickness", "-1", "--height", "72"],
        ["--length", "120", "--thickness", "x", "--height", "72"],
    ] {
        let out = bin().arg("size-wall").args(args).output().unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// `thinwall check PART --expect EXPECT [extra…]`.
fn check(
    part: impl AsRef<std::ffi::OsStr>,
    expect: &PathBuf,
    extra: &[&str],
) -> std::process::Output {
    bin()
        .arg("check")
        .arg(part)
        .arg("--expect")
        .arg(expect)
        .args(extra)
        .output()
        .unwrap()
}

#[test]
fn check_passes_on_its_part_and_names_a_missing_rib() {
    let expect = fixture("check/rib_grid_panel.expect.json");
    let out = check(fixture("recognition/rib_grid_panel.step"), &expect, &[]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    assert!(String::from_utf8_lossy(&out.stdout).contains("as expected"));
    // The same panel without its y rib: exit 1, the rib and its
    // connections lost, the web's length changed.
    let out = check(
        fixture("check/rib_grid_panel_one_rib_less.step"),
        &expect,
        &[],
    );
    assert_eq!(out.status.code(), Some(1));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("lost     R1: rib, thickness 1.20, height 23.00, length 147.00"),
        "{text}"
    );
    assert!(
        text.contains("lost     connection base_leaf W1 R1 (R1 lost)"),
        "{text}"
    );
    assert!(text.contains("size     W1: length"), "{text}");
    assert!(!text.contains("added"), "{text}");
    // --update writes an expectation the part then passes.
    let dir = std::env::temp_dir().join(format!("tw-check-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let fresh = dir.join("expect.json");
    for args in [vec!["--update"], vec![]] {
        let out = check(
            fixture("check/rib_grid_panel_one_rib_less.step"),
            &fresh,
            &args,
        );
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    // An expectation that is not a report is an input error, not a pass.
    let bad = dir.join("bad.json");
    std::fs::write(&bad, "{\"x\": 1}").unwrap();
    let out = check(fixture("recognition/rib_grid_panel.step"), &bad, &[]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("not a recognition report"));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn batch_reports_every_part_and_a_bad_file_is_a_line_not_the_end() {
    let dir = std::env::temp_dir().join(format!("tw-batch-{}", std::process::id()));
    let out = dir.join("out");
    std::fs::create_dir_all(&dir).unwrap();
    let corrupt = dir.join("corrupt.step");
    std::fs::write(&corrupt, "not a STEP file").unwrap();
    let parts = [
        fixture("recognition/rib_grid_panel.step"),
        fixture("recognition/c_frame.step"),
        corrupt.clone(),
        shared("nist/nist_ftc_08_asme1_ap242-e1-tg.stp"),
    ];
    let run = bin()
        .arg("batch")
        .args(&parts)
        .arg("--out")
        .arg(&out)
        .args(["--jobs", "2"])
        .output()
        .unwrap();
    // Two good parts, two failures: exit 1, every part in the summary.
    assert_eq!(
        run.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let table = String::from_utf8_lossy(&run.stdout);
    assert!(table.contains("4 parts, 2 failed"), "{table}");
    let summary = std::fs::read_to_string(out.join("summary.jsonl")).unwrap();
    let lines: Vec<serde_json::Value> = summary
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(lines.len(), 4);
    let line = |name: &str| {
        lines
            .iter()
            .find(|l| l["file"].as_str().unwrap().ends_with(name))
            .unwrap()
    };
    let good = line("rib_grid_panel.step");
    assert_eq!(good["ok"], true);
    assert_eq!(good["features"]["rib"], 3);
    let report: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(good["report"].as_str().unwrap()).unwrap())
            .unwrap();
    assert_eq!(report["schema"], "thinwall/recognition/1");
    assert_eq!(line("corrupt.step")["error"][0], "input");
    let mesh = line("tg.stp");
    assert_eq!(mesh["ok"], false);
    assert!(
        mesh["error"][1].as_str().unwrap().contains("tessellated"),
        "{mesh}"
    );
    // Progress lines (not a terminal here), one per part.
    assert_eq!(
        String::from_utf8_lossy(&run.stderr).matches("] ").count(),
        4
    );
    // Against expectations: the panel's passes.
    let expect = dir.join("expect");
    std::fs::create_dir_all(&expect).unwrap();
    std::fs::copy(
        fixture("check/rib_grid_panel.expect.json"),
        expect.join("rib_grid_panel.expect.json"),
    )
    .unwrap();
    let run = bin()
        .arg("batch")
        .arg(fixture("recognition/rib_grid_panel.step"))
        .arg("--out")
        .arg(&out)
        .arg("--expect")
        .arg(&expect)
        .output()
        .unwrap();
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stdout)
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn recognize_draws_an_svg_picture_with_a_legend() {
    let dir = std::env::temp_dir().join(format!("tw-svg-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut cmd = bin();
    cmd.arg("recognize")
        .arg(fixture("recognition/rib_grid_panel.step"));
    let svg = written(cmd, "svg", &dir.join("panel.svg"));
    assert!(svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\""));
    assert!(svg.trim_end().ends_with("</svg>"));
    // Self-contained: the namespace is the only address in it.
    assert_eq!(svg.matches("http").count(), 1);
    assert!(!svg.contains("href"));
    assert!(svg.matches("<polygon").count() > 500);
    // The legend names every kind of the panel, with its faces.
    for kind in ["web (", "rib (", "flange (", "hole (", "cutout ("] {
        assert!(svg.contains(kind), "legend lacks {kind}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn recognize_plan_and_classify_write_html_pages() {
    let dir = std::env::temp_dir().join(format!("tw-html-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let panel = fixture("recognition/rib_grid_panel.step");
    let runs: [(&str, Command); 3] = [
        ("recognize", {
            let mut c = bin();
            c.arg("recognize").arg(&panel);
            c
        }),
        ("plan", {
            let mut c = bin();
            c.arg("plan").arg(&panel);
            c
        }),
        ("classify", classify_stacked()),
    ];
    for (name, cmd) in runs {
        let page = written(cmd, "html", &dir.join(format!("{name}.html")));
        assert!(page.starts_with("<!DOCTYPE html>"), "{name}");
        assert!(page.trim_end().ends_with("</html>"), "{name}");
        let data = thinwall_report::html::data_of(&page).expect("data block");
        let view = match name {
            "recognize" => "recognition",
            "classify" => "classification",
            other => other,
        };
        assert_eq!(data["view"], view);
    }
    // Plan and classification pictures: the volumes numbered, a legend.
    let mut cmd = bin();
    cmd.arg("plan").arg(&panel);
    let svg = written(cmd, "svg", &dir.join("plan.svg"));
    assert!(svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\""));
    assert!(
        svg.contains("large (") && svg.contains("bulk ("),
        "legend of classes"
    );
    assert!(svg.contains(">1</text>") && svg.contains("fill-opacity"));
    let svg = written(classify_stacked(), "svg", &dir.join("volumes.svg"));
    assert!(svg.contains("closed face") && svg.contains(">0 pocket</text>"));
    // A batch writes a page per part.
    let out = bin()
        .arg("batch")
        .arg(&panel)
        .arg(fixture("recognition/thin_plate.step"))
        .args(["--format", "html", "--out"])
        .arg(dir.join("batch"))
        .output()
        .unwrap();
    assert!(out.status.success());
    for name in ["rib_grid_panel", "thin_plate"] {
        let page = std::fs::read_to_string(dir.join(format!("batch/{name}.html"))).unwrap();
        let data = thinwall_report::html::data_of(&page).expect("data block");
        assert_eq!(data["view"], "recognition");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn access_reports_flank_milling_of_planar_faces() {
    // Two ribs 8 mm apart on a plate (docs/ACCESS.md): quick to judge.
    let panel = fixture("access/two_ribs.step");
    let json = json_of(bin().arg("access").arg(&panel));
    assert_eq!(json["schema"], "thinwall/access/1");
    let faces = json["planar_faces"].as_array().unwrap();
    assert_eq!(faces.len(), 14);
    // Every face's reach travels with it; the gap's floor is not reached.
    assert_eq!(json["faces"].as_array().unwrap().len(), 14);
    assert!(json["faces"]
        .as_array()
        .unwrap()
        .iter()
        .any(|f| f["contact"] == "floor" && f["fraction"].as_f64() == Some(0.0)));
    for f in faces {
        let v = f["visibility"].as_f64().unwrap();
        assert_eq!(f["advisable"].as_bool().unwrap(), v >= 0.95);
    }
    assert!(!json["not_yet"].as_array().unwrap().is_empty());
    let text = bin()
        .arg("access")
        .arg(&panel)
        .args(["--format", "text"])
        .output()
        .unwrap();
    assert!(text.status.success());
    let text = String::from_utf8_lossy(&text.stdout);
    assert!(text.contains("14 planar face(s), 13 advisable"), "{text}");
    for bad in [["--tool-diameter", "-3"], ["--threshold", "1.5"]] {
        let out = bin().arg("access").arg(&panel).args(bad).output().unwrap();
        assert_eq!(out.status.code(), Some(2), "{bad:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(bad[0]), "{err}");
    }
}

#[test]
fn operations_sheet_json_and_errors() {
    let pocket = fixture("ops/pocket_islands.step");
    let json = json_of(
        bin()
            .arg("operations")
            .arg(&pocket)
            .args(["--format", "json"]),
    );
    assert_eq!(json["schema"], "thinwall/operations/2");
    // Without --up the set-ups are proposed: one, up +Z, for this pocket.
    assert_eq!(
        json["proposal"]["ups"],
        serde_json::json!([[0.0, 0.0, 1.0]])
    );
    assert!(json.get("then").is_none());
    let ops = json["setup"]["operations"].as_array().unwrap();
    assert_eq!(ops[0]["tool"], "EM20");
    assert!(
        json["setup"]["tool_changes"].as_u64().unwrap()
            <= json["setup"]["plain_tool_changes"].as_u64().unwrap()
    );
    assert!(!json["not_yet"].as_array().unwrap().is_empty());
    let text = bin().arg("operations").arg(&pocket).output().unwrap();
    assert!(text.status.success());
    assert!(String::from_utf8_lossy(&text.stdout).contains("EM12"));

    // Nothing to remove: an empty list, not an error.
    let plain = json_of(
        bin()
            .arg("operations")
            .arg(fixture("ops/plain_block.step"))
            .args(["--format", "json"]),
    );
    assert!(plain["setup"]["operations"].as_array().unwrap().is_empty());
    assert!(plain["setup"]["layers"].as_array().unwrap().is_empty());

    // Both sides along their plans: the opposite set-up's plan has its
    // own features, none of them what the first took.
    let both = json_of(bin().arg("operations").arg(&pocket).args([
        "--by-feature",
        "--both-sides",
        "--format",
        "json",
    ]));
    assert_eq!(both["then"].as_array().map(Vec::len), Some(1));
    assert_eq!(both["then"][0]["up"], serde_json::json!([0.0, 0.0, -1.0]));
    assert!(
        both["then"][0]["setup"]["cleared_before_mm3"]
            .as_f64()
            .unwrap()
            > 0.0
    );
    // A one-sided part: the second side has nothing left to cut.
    let second =
        json_of(
            bin()
                .arg("operations")
                .arg(&pocket)
                .args(["--both-sides", "--format", "json"]),
        );
    assert!(second["then"][0]["setup"]["layers"]
        .as_array()
        .unwrap()
        .is_empty());
    // Several ups in turn: the second set-up's up as given; the residue is
    // reported.
    let given = json_of(
        bin()
            .arg("operations")
            .arg(&pocket)
            .args(["--up", "0,0,1", "--up", "1,0,0", "--format", "json"]),
    );
    assert_eq!(given["then"][0]["up"], serde_json::json!([1.0, 0.0, 0.0]));
    assert!(given["residue"]["volume_mm3"].as_f64().unwrap() >= 0.0);
    assert!(given.get("proposal").is_none());

    // A tool file with a negative diameter, or an unknown key: exit 2 and
    // the line.
    let dir = std::env::temp_dir().join(format!("tw-tools-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let good = "[[tool]]\nname = \"EM10\"\nkind = \"flat_end_mill\"\ndiameter = 10.0\ncutting_length = 30.0\nstick_out = 50.0\nteeth = 3\ncutting_speed_m_min = 600.0\nfeed_per_tooth_mm = 0.07\naxial_depth_mm = 5.0\nradial_depth_mm = 6.0\n";
    for (name, text, want) in [
        (
            "negative.toml",
            good.replace("diameter = 10.0", "diameter = -10.0"),
            ":1: tool 'EM10'",
        ),
        (
            "unknown.toml",
            good.replace("teeth = 3", "teeth = 3\nhelix = 30"),
            "line 8",
        ),
    ] {
        let path = dir.join(name);
        std::fs::write(&path, text).unwrap();
        let out = bin()
            .arg("operations")
            .arg(&pocket)
            .arg("--tools")
            .arg(&path)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{name}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(want), "{name}: {err}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
