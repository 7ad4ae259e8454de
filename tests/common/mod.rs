//! Helpers shared by the workspace-level tests.
#![allow(dead_code)]

use std::path::{Path, PathBuf};

/// `../shared/data` beside the checkout (CI has it there too).
pub fn shared_data() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/data")
}

/// The project root.
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// STEP files in a folder, sorted.
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
