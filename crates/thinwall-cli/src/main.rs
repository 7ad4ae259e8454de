//! `thinwall`: look at a STEP part the way a process planner for thin-walled
//! parts does. A thin face: clap → request → use case → render.

use clap::Parser;
use std::io::Write;
use std::path::Path;
use std::process::ExitCode;
use thinwall_study::{self as study, Format, LoadedPart, Rendered};

mod batch;
mod check;
mod limits;
use thinwall_cli::args::{Cli, Command};
use thinwall_cli::failure::{self, Failure};
use thinwall_cli::jobs::{self, Progress};

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
        Command::Recognize(a) => {
            let request = a.flags.request()?;
            recognize(&a.part, &request, a.verbose, a.format, a.output.as_deref())
        }
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
        command => one_job(jobs::asked(command)?),
    }
}

/// A one-part command: read the part, run its job with progress on a
/// terminal, write the result (and a plan's volumes).
fn one_job(asked: jobs::Asked) -> Result<(), Failure> {
    let loaded = match &asked.part {
        Some(path) => Some(LoadedPart::read_file(path)?),
        None => None,
    };
    let s = loaded.as_ref().map(limits::study);
    // Access counts faces on a bar; plan and operations say their stage.
    let by_face = matches!(asked.job, jobs::Job::Access(_));
    let staged = matches!(asked.job, jobs::Job::Plan(_) | jobs::Job::Operations(_));
    let spinner = staged.then(Spinner::new);
    let bar = by_face.then(|| Bar::new(loaded.as_ref().map_or(0, |l| l.part.faces.len())));
    let say = |m: &str| spinner.iter().for_each(|s| s.say(m));
    let face = |_: usize, _: usize| bar.iter().for_each(Bar::inc);
    let progress = Progress {
        stage: &say,
        face: &face,
    };
    let rendered = jobs::run(&asked.job, s.as_ref(), &progress);
    drop(bar);
    drop(spinner);
    let rendered = rendered?;
    if let (Some(dir), Rendered::Planned(planned)) = (&asked.volumes_dir, &rendered) {
        let skipped = study::write_volumes(&planned.plan, dir)?;
        if skipped > 0 {
            eprintln!("note: {skipped} solid(s) bounded by a cylinder or cone are not written yet (their volumes are in the plan)");
        }
    }
    emit(rendered, asked.format, asked.output.as_deref())
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
