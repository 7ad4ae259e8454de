//! Helpers shared by the workspace-level tests.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use thinwall_analysis::parallel::Work;

/// `../shared/data` beside the checkout (CI has it there too).
pub fn shared_data() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/data")
}

/// The project root.
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The text of a machining fixture (`fixtures/machining/NAME`).
pub fn machining_fixture(name: &str) -> String {
    std::fs::read_to_string(root().join("fixtures/machining").join(name)).unwrap()
}

/// STEP files in a folder, sorted.
/// The thin-walled parts the planner and the pictures are checked on:
/// every shared thin-walled part, every recognition and machining fixture.
pub fn thin_walled_parts() -> Vec<PathBuf> {
    let mut v = step_files(&shared_data().join("thinwall"));
    v.extend(step_files(&root().join("fixtures/recognition")));
    v.extend(step_files(&root().join("fixtures/machining")));
    v
}

/// Generated parts with their truth: the STEP files of the directory the
/// environment variable `var` names (a held-out seed range), else of the
/// project's `fixtures/<fixtures>`.
pub fn generated_parts(var: &str, fixtures: &str) -> Vec<PathBuf> {
    let dir = std::env::var(var)
        .map(PathBuf::from)
        .unwrap_or_else(|_| root().join("fixtures").join(fixtures));
    step_files(&dir)
}

pub fn step_files(dir: &Path) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| {
            matches!(
                p.extension()
                    .and_then(|e| e.to_str())
                    .map(str::to_ascii_lowercase)
                    .as_deref(),
                Some("step" | "stp")
            )
        })
        .collect();
    v.sort();
    v
}
pub mod fixtures;

/// Recognize the stiffness features of `part` in a 3-axis set-up with `up`.
pub fn recognize_with(
    part: &thinwall_brep::Part,
    up: [f64; 3],
    config: &thinwall_recognize::Config,
) -> thinwall_recognize::Recognition {
    let setup = thinwall_analysis::Setup::new(up, thinwall_analysis::Machine::ThreeAxis).unwrap();
    let a = thinwall_analysis::PartAnalysis::new(part, setup);
    thinwall_recognize::recognize(&a, config)
}

/// Read STEP text and plan it in a 3-axis set-up with `up` and `rules`.
pub fn plan_text(
    text: &str,
    up: [f64; 3],
    rules: &thinwall_plan::RuleSet,
) -> (thinwall_brep::Part, thinwall_plan::Plan) {
    let (part, _) = thinwall_step::read_bytes(text.as_bytes(), "part.step").unwrap();
    let req = thinwall_pipeline::Request {
        setup: thinwall_analysis::Setup::new(up, thinwall_analysis::Machine::ThreeAxis).unwrap(),
        ..Default::default()
    };
    let a = thinwall_analysis::PartAnalysis::new(&part, req.setup.clone());
    let out = thinwall_pipeline::run_on(&a, &req).unwrap();
    let p = thinwall_plan::plan("part.step", &a, &out, rules).expect("a plan");
    drop(a);
    (part, p)
}

/// The machining features of the analysed part found in its set-up (its
/// up the tool axis): the holes operations drill.
#[allow(dead_code)]
pub fn features_in_setup(
    a: &thinwall_analysis::PartAnalysis,
) -> Vec<thinwall_machining::MachiningFeature> {
    let req = thinwall_pipeline::Request {
        setup: a.setup().clone(),
        allow_open: true,
        machining: thinwall_pipeline::MachiningRequest {
            in_setup: true,
            ..Default::default()
        },
        ..Default::default()
    };
    thinwall_pipeline::run_on(a, &req).unwrap().machining
}

/// The STEP text of a part turned by a rigid motion: every 3-D
/// `CARTESIAN_POINT` is rotated by `r` and moved by `t`, every 3-D
/// `DIRECTION` rotated (2-D parameter-space ones are left alone). Works on
/// statements (split at `;`; the files' strings hold none). Returns the
/// text and how many entities were turned.
pub fn turned_step(
    text: &str,
    r: &nalgebra::Rotation3<f64>,
    t: &nalgebra::Vector3<f64>,
) -> (String, usize) {
    let mut out = String::with_capacity(text.len() + text.len() / 4);
    let mut turned = 0;
    for stmt in text.split_inclusive(';') {
        let is_point = stmt.contains("CARTESIAN_POINT(");
        let is_dir = stmt.contains("= DIRECTION(") || stmt.contains("=DIRECTION(");
        let coords = (is_point || is_dir)
            .then(|| {
                let open = stmt.rfind(",(")? + 2;
                let close = open + stmt[open..].find(')')?;
                let v: Vec<f64> = stmt[open..close]
                    .split(',')
                    .map(|x| x.trim().parse::<f64>())
                    .collect::<Result<_, _>>()
                    .ok()?;
                (v.len() == 3).then_some((open, close, v))
            })
            .flatten();
        match coords {
            Some((open, close, v)) => {
                let p = nalgebra::Vector3::new(v[0], v[1], v[2]);
                let q = if is_point { r * p + t } else { r * p };
                out.push_str(&stmt[..open]);
                out.push_str(&format!("{:.17E},{:.17E},{:.17E}", q.x, q.y, q.z));
                out.push_str(&stmt[close..]);
                turned += 1;
            }
            None => out.push_str(stmt),
        }
    }
    (out, turned)
}

/// The STEP text as built (`seed` none) or turned by `rigid_motion(seed)`.
pub fn posed_step(text: &str, seed: Option<u64>) -> String {
    match seed {
        Some(seed) => {
            let (r, t) = rigid_motion(seed);
            turned_step(text, &r, &t).0
        }
        None => text.to_string(),
    }
}

/// A deterministic rotation and translation for case `seed`.
pub fn rigid_motion(seed: u64) -> (nalgebra::Rotation3<f64>, nalgebra::Vector3<f64>) {
    let mut s = seed
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    let mut next = || {
        s = s
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((s >> 11) as f64) / ((1u64 << 53) as f64)
    };
    let axis = nalgebra::Vector3::new(next() - 0.5, next() - 0.5, next() - 0.5);
    let axis = nalgebra::Unit::new_normalize(axis + nalgebra::Vector3::new(1e-3, 0.0, 0.0));
    let angle = 0.2 + 2.8 * next();
    let t = nalgebra::Vector3::new(
        200.0 * next() - 100.0,
        200.0 * next() - 100.0,
        200.0 * next() - 100.0,
    );
    (nalgebra::Rotation3::from_axis_angle(&axis, angle), t)
}

/// The STEP text with its first shell's faces listed the other way round
/// (the same part; only the order in the file differs).
pub fn faces_reversed(text: &str) -> String {
    let start = text.find("CLOSED_SHELL('',(").expect("a closed shell") + "CLOSED_SHELL('',(".len();
    let end = start + text[start..].find(')').expect("the shell's face list");
    let mut ids: Vec<&str> = text[start..end].split(',').map(str::trim).collect();
    ids.reverse();
    format!("{}{}{}", &text[..start], ids.join(","), &text[end..])
}
pub mod mutate;

/// A part read from `path` and its removal from its own block along z
/// (world frame), unchecked.
pub fn block_removal(
    path: &Path,
) -> (
    thinwall_brep::Part,
    Result<thinwall_removal::Removal, thinwall_removal::RemovalError>,
) {
    let (part, _) = thinwall_step::read_file(path).unwrap();
    let a = thinwall_analysis::PartAnalysis::new(&part, thinwall_analysis::Setup::default());
    let bb = a.bounding_box();
    let stock = thinwall_removal::StockShape::Block {
        lo: bb.min,
        hi: bb.max,
    };
    let r = thinwall_removal::Removal::new(
        &part,
        thinwall_geom::Frame::world(),
        &stock,
        &[],
        bb.diagonal(),
        Work::serial(),
    );
    (part, r)
}

/// The removal's part volume is the tessellation's within `rel` of it.
pub fn assert_part_volume_is_the_tessellations(
    part: &thinwall_brep::Part,
    r: &thinwall_removal::Removal,
    rel: f64,
    what: &str,
) {
    let meshed = tessellated_volume(part);
    assert!(
        (r.part_volume - meshed).abs() <= rel * meshed,
        "{what}: removal's part {} against the tessellation's {meshed}",
        r.part_volume
    );
}

/// The signed volume of a part's watertight picture tessellation (an
/// independent computation of its volume), mm³.
pub fn tessellated_volume(part: &thinwall_brep::Part) -> f64 {
    let mesh = thinwall_brep::tessellate::part_mesh(part);
    mesh.faces
        .iter()
        .flat_map(|fm| fm.triangles.iter())
        .map(|t| {
            let p = |i: u32| mesh.points[i as usize].coords;
            p(t[0]).dot(&p(t[1]).cross(&p(t[2]))) / 6.0
        })
        .sum()
}

/// A fixture of `fixtures/recognition` (`NAME.step`) and the three-axis
/// set-up along the up its `NAME.expected.json` names.
pub fn recognition_fixture(name: &str) -> (thinwall_brep::Part, thinwall_analysis::Setup) {
    let dir = root().join("fixtures/recognition");
    let expected: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(dir.join(format!("{name}.expected.json"))).unwrap(),
    )
    .unwrap();
    let up: Vec<f64> = serde_json::from_value(expected["up"].clone()).unwrap();
    let (part, _) = thinwall_step::read_file(dir.join(format!("{name}.step"))).unwrap();
    let setup =
        thinwall_analysis::Setup::new([up[0], up[1], up[2]], thinwall_analysis::Machine::ThreeAxis)
            .unwrap();
    (part, setup)
}

/// In every layer of `ops` the tools' shares, the rest and the drilled
/// fields make up the section (1e-6).
pub fn assert_layers_add_up(ops: &thinwall_ops::operations::SetupOperations, what: &str) {
    for (l, fts) in ops.layers.iter().zip(&ops.field_tools) {
        let cleared: f64 = fts
            .iter()
            .flat_map(|ft| &ft.shares)
            .map(|s| s.cleared_mm2)
            .sum();
        let rest: f64 = fts.iter().map(|ft| ft.rest_mm2).sum();
        let drilled: f64 = l
            .fields
            .iter()
            .zip(fts)
            .filter(|(_, ft)| ft.drilled.is_some())
            .map(|(f, _)| f.area_mm2)
            .sum();
        assert!(
            (cleared + rest + drilled - l.area_mm2).abs() <= 1e-6 * l.area_mm2.max(1.0),
            "{what}: layer {} of {:?}: {cleared} cleared + {rest} rest + {drilled} drilled, section {}",
            l.index,
            l.feature,
            l.area_mm2
        );
    }
}

/// Every relation of `plan`'s feature sequence holds in `ops`' order: all
/// operations of the feature before come before all of the feature after.
/// Returns how many relations had operations on both sides.
pub fn assert_relations_kept(
    ops: &thinwall_ops::operations::SetupOperations,
    plan: &thinwall_plan::Plan,
    what: &str,
) -> usize {
    let steps = |id: &str| -> Vec<usize> {
        ops.operations
            .iter()
            .filter(|o| o.feature.as_deref() == Some(id))
            .map(|o| o.step)
            .collect()
    };
    let mut kept = 0;
    for r in &plan.feature_sequence.relations {
        let (a, b) = (steps(&r.before), steps(&r.after));
        if let (Some(last), Some(first)) = (a.iter().max(), b.iter().min()) {
            assert!(
                last < first,
                "{what}: {} before {} ({}) broken: step {last} after {first}",
                r.before,
                r.after,
                r.why
            );
            kept += 1;
        }
    }
    kept
}

/// Two removals are the same, bit for bit: cells (polygons, covers,
/// areas), bands, blocks, pieces, meshed faces and volumes.
pub fn assert_same_removal(
    a: &thinwall_removal::Removal,
    b: &thinwall_removal::Removal,
    what: &str,
) {
    assert_eq!(a.cells.len(), b.cells.len(), "{what}: cells");
    for (k, (x, y)) in a.cells.iter().zip(&b.cells).enumerate() {
        assert_eq!(x.poly, y.poly, "{what}: cell {k}'s polygon");
        assert_eq!(x.covers, y.covers, "{what}: cell {k}'s covers");
        assert_eq!(
            x.area.to_bits(),
            y.area.to_bits(),
            "{what}: cell {k}'s area"
        );
    }
    assert_eq!(a.cell_bands, b.cell_bands, "{what}: bands");
    assert_eq!(a.blocks.len(), b.blocks.len(), "{what}: blocks");
    for (x, y) in a.blocks.iter().zip(&b.blocks) {
        assert_eq!(
            (x.cell, x.reachable, x.open_below, x.volume.to_bits()),
            (y.cell, y.reachable, y.open_below, y.volume.to_bits()),
            "{what}: a block"
        );
    }
    assert_eq!(a.part_pieces.len(), b.part_pieces.len(), "{what}: pieces");
    assert_eq!(a.meshed, b.meshed, "{what}: meshed faces");
    assert_eq!(a.stock_volume.to_bits(), b.stock_volume.to_bits(), "{what}");
    assert_eq!(a.part_volume.to_bits(), b.part_volume.to_bits(), "{what}");
    assert_eq!(
        a.sliver_volume.to_bits(),
        b.sliver_volume.to_bits(),
        "{what}"
    );
}
