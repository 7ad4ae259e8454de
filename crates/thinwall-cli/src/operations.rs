//! `thinwall operations`: the operations of one set-up as an operation
//! sheet or JSON (`thinwall/operations/1`).

use crate::failure::Failure;
use std::path::{Path, PathBuf};
use thinwall_geom::Vector3;
use thinwall_plan::removal::{frame_of, Removal, StockShape};

/// What the command was asked.
pub struct OperationsArgs {
    pub part: PathBuf,
    pub up: Option<[f64; 3]>,
    pub tools: Option<PathBuf>,
    pub axial_depth: Option<f64>,
    pub json: bool,
}

/// The tool library: the file's, or the shipped one.
fn library(path: Option<&Path>) -> Result<thinwall_ops::ToolLibrary, Failure> {
    match path {
        None => Ok(thinwall_ops::ToolLibrary::default_tools()),
        Some(p) => {
            let text = std::fs::read_to_string(p)
                .map_err(|e| Failure::Usage(format!("{}: {e}", p.display())))?;
            thinwall_ops::ToolLibrary::from_toml(&text, &p.display().to_string())
                .map_err(Failure::usage)
        }
    }
}

pub fn run(args: OperationsArgs) -> Result<String, Failure> {
    if let Some(d) = args.axial_depth {
        if !(d.is_finite() && d > 0.0) {
            return Err(Failure::Usage(format!(
                "--axial-depth must be a positive length, got {d}"
            )));
        }
    }
    let lib = library(args.tools.as_deref())?;
    if lib.end_mills().next().is_none() {
        return Err(Failure::Usage(format!(
            "{}: the library has no end mill to rough with",
            lib.source
        )));
    }
    let (model, _) = thinwall_step::read_file(&args.part)?;
    let setup = thinwall_analysis::Setup::new(
        args.up.unwrap_or([0.0, 0.0, 1.0]),
        thinwall_analysis::Machine::ThreeAxis,
    )
    .map_err(Failure::usage)?;
    let a = thinwall_analysis::PartAnalysis::new(&model, setup.clone());
    let up = Vector3::from(setup.up).normalize();
    let (frame, lo, hi) = frame_of(&a, up);
    let size = a.bounding_box().diagonal();
    let removal = Removal::new(&model, frame, &StockShape::Block { lo, hi }, &[], size)
        .map_err(|e| Failure::Input(format!("removal.{}: {e}", e.code())))?;
    let holes = thinwall_ops::drilling::holes_of(&a, &frame, &lib)
        .map_err(|e| Failure::Input(format!("machining.{}: {e}", e.code())))?;
    let setup_ops = thinwall_ops::operations::operations(&removal, &lib, args.axial_depth, &holes);
    let v = |p: Vector3| [p.x, p.y, p.z];
    let report = thinwall_report::operations::OperationsReport::new(
        &args.part.display().to_string(),
        setup.up,
        [
            [frame.origin.x, frame.origin.y, frame.origin.z],
            v(frame.x),
            v(frame.y),
            v(frame.z),
        ],
        lib,
        setup_ops,
    );
    Ok(if args.json {
        report.to_json()
    } else {
        report.to_text()
    })
}
