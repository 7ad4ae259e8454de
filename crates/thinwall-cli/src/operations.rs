//! `thinwall operations`: the operations of one set-up as an operation
//! sheet or JSON (`thinwall/operations/1`).

use crate::failure::Failure;
use std::path::{Path, PathBuf};

/// What the command was asked.
pub struct OperationsArgs {
    pub part: PathBuf,
    pub up: Option<[f64; 3]>,
    pub tools: Option<PathBuf>,
    pub axial_depth: Option<f64>,
    pub by_feature: bool,
    pub format: OpsFormat,
}

/// How the operations are written.
pub enum OpsFormat {
    Text,
    Json,
    /// A page: the operations in order over the part.
    Html,
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
    let (model, _) = thinwall_step::read_file(&args.part)?;
    let setup = thinwall_analysis::Setup::new(
        args.up.unwrap_or([0.0, 0.0, 1.0]),
        thinwall_analysis::Machine::ThreeAxis,
    )
    .map_err(Failure::usage)?;
    let a = thinwall_analysis::PartAnalysis::new(&model, setup.clone());
    let planned = if args.by_feature {
        thinwall_ops::setup::plan_setup_by_feature(
            &a,
            &args.part.display().to_string(),
            &lib,
            args.axial_depth,
        )
    } else {
        thinwall_ops::plan_setup(&a, &lib, args.axial_depth)
    };
    let (frame, setup_ops) = planned.map_err(|e| match e {
        thinwall_ops::OpsError::NoEndMill { .. } => Failure::Usage(e.to_string()),
        _ => Failure::Input(format!("{}: {e}", e.code())),
    })?;
    let report = thinwall_report::operations::OperationsReport::new(
        &args.part.display().to_string(),
        setup.up,
        &frame,
        lib,
        setup_ops,
    );
    Ok(match args.format {
        OpsFormat::Text => report.to_text(),
        OpsFormat::Json => report.to_json(),
        OpsFormat::Html => thinwall_report::html::operations_page(
            &format!("Operations: {}", args.part.display()),
            &a,
            &report,
        ),
    })
}
