//! `thinwall`: look at a STEP part the way a process planner for thin-walled
//! parts does.

use clap::{Parser, Subcommand, ValueEnum};
use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;
use thinwall_graph::AdjacencyGraph;

#[derive(Parser)]
#[command(
    name = "thinwall",
    version,
    about = "Stiffness features and machining features of thin-walled parts, from STEP"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Clone, Copy, ValueEnum)]
enum Format {
    Text,
    Json,
}

#[derive(Subcommand)]
enum Command {
    /// Read a part and report its bodies, faces, edges and their convexity.
    Inspect {
        /// The STEP file (AP203, AP214 or AP242).
        part: PathBuf,
        /// Output format.
        #[arg(long, value_enum, default_value = "text")]
        format: Format,
    },
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("thinwall: error: {message}");
            ExitCode::FAILURE
        }
    }
}

fn run(cli: Cli) -> Result<(), String> {
    match cli.command {
        Command::Inspect { part, format } => {
            let (model, read) = thinwall_step::read_file(&part).map_err(|e| e.to_string())?;
            let graph = AdjacencyGraph::build(&model, &model.tolerances());
            let report =
                thinwall_report::inspect(&part.display().to_string(), &model, &read, &graph);
            let text = match format {
                Format::Text => report.to_text(),
                Format::Json => {
                    serde_json::to_string_pretty(&report).map_err(|e| e.to_string())? + "\n"
                }
            };
            std::io::stdout()
                .write_all(text.as_bytes())
                .map_err(|e| format!("cannot write output: {e}"))
        }
    }
}
