//! `thinwall`: look at a STEP part the way a process planner for thin-walled
//! parts does. A thin face: clap → request → use case → render.

use clap::Parser;
use std::io::Write;
use std::path::Path;
use std::process::ExitCode;
use thinwall_study::{self as study, Format, LoadedPart, Rendered};

mod args;
mod batch;
mod check;
mod failure;
mod limits;
use args::{Cli, Command};
use failure::Failure;

fn main() -> ExitCode {
    let cli = Cli::parse();
    let ran = cli.time_limit().and_then(|limit| {
        limits::set_time_limit(limit);
        // A panic outside a use case is reported like one inside: exit 3,
        // one line, no backtrace (unless RUST_BACKTRACE asks for it).
        study::contained("the command line", "thinwall", || Ok(run(cli.command)))
            .unwrap_or_else(|e| Err(e.into()))
    });
    match ran {
        Ok(()) => ExitCode::SUCCESS,
        Err(failure) => {
            eprintln!("thinwall: error: {}", failure::shortened(failure.message()));
            ExitCode::from(failure.exit_code())
        }
    }
}

fn run(command: Command) -> Result<(), Failure> {
    match command {
        Command::Inspect { part, format } => {
            let loaded = LoadedPart::read_file(&part)?;
            emit(
                study::inspect(&limits::study(&loaded))?.into(),
                format,
                None,
            )
        }
        Command::Recognize(a) => {
            let request = a.flags.request()?;
            recognize(&a.part, &request, a.verbose, a.format, a.output.as_deref())
        }
        Command::Plan(a) => plan(a),
        Command::Access(a) => access(a),
        Command::Operations(a) => operations(a),
        Command::SizeWall(a) => emit(study::size_wall(&a.request())?.into(), a.format, None),
        Command::Classify(a) => classify(a),
        Command::Batch(a) => {
            let mut request = a.flags.request()?;
            // The parts run in parallel; each runs alone.
            request.parallel = false;
            batch::command(batch::Batch {
                inputs: a.inputs,
                out: a.out,
                jobs: limits::jobs(a.jobs)?,
                format: a.format,
                expect: a.expect,
                request,
            })
        }
        Command::Check(a) => {
            let tol = thinwall_report::expect::CheckTolerance {
                absolute_mm: a.tolerance_mm,
                relative: a.tolerance_rel,
            };
            check::command(&a.part, &a.expect, a.update, tol, a.flags.request()?)
        }
    }
}

fn plan(a: args::PlanArgs) -> Result<(), Failure> {
    let (recognize, later_ups) = a.flags.in_turn()?;
    // Without an up (flag or settings) the set-ups are proposed.
    let propose = !recognize.machining.in_setup;
    let mut request = study::PlanRequest::new(recognize, rules_of(a.rules.as_deref())?);
    request.later_ups = later_ups;
    request.propose = propose;
    let loaded = LoadedPart::read_file(&a.part)?;
    let s = limits::study(&loaded);
    let spinner = Spinner::new();
    let planned = study::plan_observed(&s, &request, &|m| spinner.say(m))?;
    drop(spinner);
    if let Some(dir) = &a.volumes_dir {
        let skipped = study::write_volumes(&planned.plan, dir)?;
        if skipped > 0 {
            eprintln!("note: {skipped} solid(s) bounded by a cylinder or cone are not written yet (their volumes are in the plan)");
        }
    }
    emit(planned.into(), a.format, a.output.as_deref())
}

fn access(a: args::AccessArgs) -> Result<(), Failure> {
    let setup = study::setup_of(a.up, a.machine.machine(a.tilt_limit))?;
    let mut request = study::AccessRequest::new(setup);
    request.tool = args::tool(a.tool_diameter, a.cutting_length, a.holder_diameter);
    request.tool_radius = a.tool_radius;
    request.threshold = a.threshold;
    request.check()?;
    let loaded = LoadedPart::read_file(&a.part)?;
    let s = limits::study(&loaded);
    let bar = Bar::new(loaded.part.faces.len());
    let accessed = study::access_observed(&s, &request, |_, _| bar.inc())?;
    drop(bar);
    emit(accessed.into(), a.format, a.output.as_deref())
}

fn operations(a: args::OperationsArgs) -> Result<(), Failure> {
    let setup = study::setup_of(a.up.first().copied(), thinwall_analysis::Machine::ThreeAxis)?;
    let mut request = study::OperationsRequest::new(setup);
    request.tools = tools_of(a.tools.as_deref())?;
    if let Some(m) = a.min_share {
        request.tools.min_share_mm2 = m;
    }
    request.axial_depth = a.axial_depth;
    request.by_feature = a.by_feature;
    request.both_sides = a.both_sides;
    request.later_ups = a.up.iter().skip(1).copied().collect();
    // Without an up the set-ups are proposed.
    request.choose_up = a.choose_up || (a.up.is_empty() && !a.both_sides);
    request.check()?;
    let loaded = LoadedPart::read_file(&a.part)?;
    let spinner = Spinner::new();
    let operated =
        study::operations_observed(&limits::study(&loaded), &request, &|m| spinner.say(m))?;
    drop(spinner);
    emit(operated.into(), a.format, a.output.as_deref())
}

fn classify(a: args::ClassifyArgs) -> Result<(), Failure> {
    let setup = study::setup_of(a.up, thinwall_analysis::Machine::ThreeAxis)?;
    let loaded = LoadedPart::read_file(&a.part)?;
    let volumes = a
        .volume
        .iter()
        .map(study::read_volume)
        .collect::<Result<Vec<_>, _>>()?;
    let request = study::ClassifyRequest {
        setup,
        volumes,
        before: a.before,
    };
    let classified = study::classify(&limits::study(&loaded), request)?;
    emit(classified.into(), a.format, a.output.as_deref())
}

/// `recognize`: the report, with the time of every stage on stderr when
/// `verbose`.
fn recognize(
    part: &Path,
    request: &study::RecognizeRequest,
    verbose: bool,
    format: Format,
    output: Option<&Path>,
) -> Result<(), Failure> {
    let t0 = std::time::Instant::now();
    let name = part.display().to_string();
    let (model, read) = study::contained("read", &name, || Ok(thinwall_step::read_file(part)?))?;
    let read_seconds = t0.elapsed().as_secs_f64();
    let loaded = study::contained("read", &name, || Ok(LoadedPart::new(&name, model, read)))?;
    let graph_seconds = t0.elapsed().as_secs_f64() - read_seconds;
    let s = limits::study(&loaded);
    let spinner = Spinner::new();
    spinner.say(if request.reach_tool.is_some() {
        "recognizing, the reach of every wall side judged (--no-reach skips it)"
    } else {
        "recognizing"
    });
    let recognized = study::recognize(&s, request);
    drop(spinner);
    let recognized = recognized?;
    if verbose {
        eprintln!("{read_seconds:>9.4} s  read");
        eprintln!("{graph_seconds:>9.4} s  adjacency graph");
        for (stage, seconds) in &recognized.timings {
            eprintln!("{seconds:>9.4} s  {stage}");
        }
        for w in &recognized.report.warnings {
            eprintln!("warning: {}", w.message);
        }
    }
    emit(recognized.into(), format, output)
}

/// The sequence rules of `--rules`, or the shipped ones. An unreadable
/// file is an input failure.
fn rules_of(path: Option<&Path>) -> Result<thinwall_plan::RuleSet, Failure> {
    match path {
        None => Ok(thinwall_plan::RuleSet::default_rules()),
        Some(p) => Ok(thinwall_plan::RuleSet::from_toml(
            &text_of(p, Failure::Input)?,
            &p.display().to_string(),
        )
        .map_err(study::StudyError::from)?),
    }
}

/// The tool library of `--tools`, or the shipped one. An unreadable file
/// is a usage failure (as it always was).
fn tools_of(path: Option<&Path>) -> Result<thinwall_ops::ToolLibrary, Failure> {
    match path {
        None => Ok(thinwall_ops::ToolLibrary::default_tools()),
        Some(p) => Ok(thinwall_ops::ToolLibrary::from_toml(
            &text_of(p, Failure::Usage)?,
            &p.display().to_string(),
        )
        .map_err(study::StudyError::from)?),
    }
}

/// The text of a settings file, or `failure` naming it.
fn text_of(path: &Path, failure: fn(String) -> Failure) -> Result<String, Failure> {
    std::fs::read_to_string(path).map_err(|e| failure(format!("{}: {e}", path.display())))
}

/// A progress bar on a terminal's stderr (nothing otherwise).
struct Bar(Option<indicatif::ProgressBar>);

impl Bar {
    fn new(faces: usize) -> Self {
        Self(
            std::io::IsTerminal::is_terminal(&std::io::stderr()).then(|| {
                let b = indicatif::ProgressBar::new(faces as u64);
                if let Ok(style) = indicatif::ProgressStyle::with_template(
                    "reach {bar:40} {pos}/{len} faces, {elapsed} ({eta} left)",
                ) {
                    b.set_style(style);
                }
                b
            }),
        )
    }

    fn inc(&self) {
        if let Some(b) = &self.0 {
            b.inc(1);
        }
    }
}

/// What a long command is doing, on a terminal only: set-ups in turn
/// take minutes on large parts.
struct Spinner(Option<indicatif::ProgressBar>);

impl Spinner {
    fn new() -> Self {
        Self(
            std::io::IsTerminal::is_terminal(&std::io::stderr()).then(|| {
                let b = indicatif::ProgressBar::new_spinner();
                if let Ok(style) =
                    indicatif::ProgressStyle::with_template("{spinner} {msg} ({elapsed})")
                {
                    b.set_style(style);
                }
                b.enable_steady_tick(std::time::Duration::from_millis(120));
                b
            }),
        )
    }

    fn say(&self, what: &str) {
        if let Some(b) = &self.0 {
            b.set_message(what.to_string());
        }
    }
}

impl Drop for Spinner {
    fn drop(&mut self) {
        if let Some(b) = &self.0 {
            b.finish_and_clear();
        }
    }
}

impl Drop for Bar {
    fn drop(&mut self) {
        if let Some(b) = &self.0 {
            b.finish_and_clear();
        }
    }
}

/// Render `result` and write it to `output`, or to stdout without one.
fn emit(result: Rendered, format: Format, output: Option<&Path>) -> Result<(), Failure> {
    let text = study::render(&result, format)?;
    match output {
        Some(path) => std::fs::write(path, text)
            .map_err(|e| Failure::Input(format!("{}: {e}", path.display()))),
        None => std::io::stdout()
            .write_all(text.as_bytes())
            .map_err(|e| Failure::Input(format!("cannot write output: {e}"))),
    }
}
