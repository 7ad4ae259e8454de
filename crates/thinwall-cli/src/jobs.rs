//! From a command's flags to the use case it asks for, and running it on a
//! study: the one step every face over the command line shares (the
//! `thinwall` binary, the Python package), so the same flags give the same
//! result and the same error everywhere.

use crate::args::{self, Command};
use crate::failure::Failure;
use std::path::{Path, PathBuf};
use thinwall_study::{self as study, Format, Rendered, Study};

/// A use case with its request, checked (the files its flags name read).
pub enum Job {
    Inspect,
    Recognize(study::RecognizeRequest),
    Plan(study::PlanRequest),
    Access(study::AccessRequest),
    Operations(study::OperationsRequest),
    Classify(Classify),
    SizeWall(study::SizeWallRequest),
}

/// `classify`'s set-up, the volumes' files and their order.
pub struct Classify {
    pub setup: thinwall_analysis::Setup,
    pub volumes: Vec<PathBuf>,
    pub before: Vec<(usize, usize)>,
}

/// What a command asks: the job, the part it runs on (none for
/// `size-wall`), and where its result goes.
pub struct Asked {
    pub job: Job,
    pub part: Option<PathBuf>,
    pub format: Format,
    pub output: Option<PathBuf>,
    /// `plan --volumes-dir`.
    pub volumes_dir: Option<PathBuf>,
}

/// How a long job reports progress: each stage as it begins, each face as
/// its reach is judged (`done`, `of`).
pub struct Progress<'a> {
    pub stage: &'a dyn Fn(&str),
    pub face: &'a (dyn Fn(usize, usize) + Sync),
}

impl Progress<'_> {
    /// No progress shown.
    pub const QUIET: Progress<'static> = Progress {
        stage: &|_| {},
        face: &|_, _| {},
    };
}

/// The job of a one-part command (not `batch` or `check`).
pub fn asked(command: Command) -> Result<Asked, Failure> {
    let asked = |job, part, format, output| Asked {
        job,
        part,
        format,
        output,
        volumes_dir: None,
    };
    Ok(match command {
        Command::Inspect { part, format } => asked(Job::Inspect, Some(part), format, None),
        Command::Recognize(a) => asked(
            Job::Recognize(a.flags.request()?),
            Some(a.part),
            a.format,
            a.output,
        ),
        Command::Plan(a) => Asked {
            job: Job::Plan(plan_request(a.flags, a.rules.as_deref())?),
            part: Some(a.part),
            format: a.format,
            output: a.output,
            volumes_dir: a.volumes_dir,
        },
        Command::Access(a) => {
            let format = a.format;
            let (part, output) = (a.part.clone(), a.output.clone());
            asked(Job::Access(access_request(a)?), Some(part), format, output)
        }
        Command::Operations(a) => {
            let format = a.format;
            let (part, output) = (a.part.clone(), a.output.clone());
            asked(
                Job::Operations(operations_request(a)?),
                Some(part),
                format,
                output,
            )
        }
        Command::SizeWall(a) => asked(Job::SizeWall(a.request()), None, a.format, None),
        Command::Classify(a) => asked(
            Job::Classify(Classify {
                setup: study::setup_of(a.up, thinwall_analysis::Machine::ThreeAxis)?,
                volumes: a.volume,
                before: a.before,
            }),
            Some(a.part),
            a.format,
            a.output,
        ),
        Command::Batch(_) | Command::Check(_) => {
            return Err(Failure::Usage(
                "batch and check run many parts or compare: not one job".into(),
            ))
        }
    })
}

fn plan_request(
    flags: args::RecognizeFlags,
    rules: Option<&Path>,
) -> Result<study::PlanRequest, Failure> {
    let (recognize, later_ups) = flags.in_turn()?;
    // Without an up (flag or settings) the set-ups are proposed.
    let propose = !recognize.machining.in_setup;
    let mut request = study::PlanRequest::new(recognize, rules_of(rules)?);
    request.later_ups = later_ups;
    request.propose = propose;
    Ok(request)
}

fn access_request(a: args::AccessArgs) -> Result<study::AccessRequest, Failure> {
    let setup = study::setup_of(a.up, a.machine.machine(a.tilt_limit))?;
    let mut request = study::AccessRequest::new(setup);
    request.tool = args::tool(a.tool_diameter, a.cutting_length, a.holder_diameter);
    request.tool_radius = a.tool_radius;
    request.threshold = a.threshold;
    request.check()?;
    Ok(request)
}

fn operations_request(a: args::OperationsArgs) -> Result<study::OperationsRequest, Failure> {
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
    Ok(request)
}

/// Run `job` on `study` (a part's; `size-wall` needs none), reporting
/// `progress`.
pub fn run<'p>(
    job: &Job,
    study: Option<&Study<'p>>,
    progress: &Progress,
) -> Result<Rendered<'p>, Failure> {
    let Some(s) = study else {
        return match job {
            Job::SizeWall(r) => Ok(study::size_wall(r)?.into()),
            _ => Err(Failure::Usage("this command needs a part".into())),
        };
    };
    Ok(match job {
        Job::Inspect => study::inspect(s)?.into(),
        Job::Recognize(r) => study::recognize(s, r)?.into(),
        Job::Plan(r) => study::plan_observed(s, r, progress.stage)?.into(),
        Job::Access(r) => study::access_observed(s, r, progress.face)?.into(),
        Job::Operations(r) => study::operations_observed(s, r, progress.stage)?.into(),
        Job::SizeWall(r) => study::size_wall(r)?.into(),
        Job::Classify(c) => {
            let volumes = c
                .volumes
                .iter()
                .map(study::read_volume)
                .collect::<Result<Vec<_>, _>>()?;
            let request = study::ClassifyRequest {
                setup: c.setup.clone(),
                volumes,
                before: c.before.clone(),
            };
            study::classify(s, request)?.into()
        }
    })
}

/// The sequence rules of `--rules`, or the shipped ones. An unreadable
/// file is an input failure.
fn rules_of(path: Option<&Path>) -> Result<thinwall_plan::RuleSet, Failure> {
    settings_of(
        path,
        thinwall_plan::RuleSet::default_rules,
        thinwall_plan::RuleSet::from_toml,
        Failure::Input,
    )
}

/// The tool library of `--tools`, or the shipped one. An unreadable file
/// is a usage failure (as it always was).
fn tools_of(path: Option<&Path>) -> Result<thinwall_ops::ToolLibrary, Failure> {
    settings_of(
        path,
        thinwall_ops::ToolLibrary::default_tools,
        thinwall_ops::ToolLibrary::from_toml,
        Failure::Usage,
    )
}

/// A settings file parsed by `parse` (its text, its name), or the shipped
/// settings without one; a file that cannot be read fails as `unreadable`.
fn settings_of<T, E>(
    path: Option<&Path>,
    shipped: fn() -> T,
    parse: fn(&str, &str) -> Result<T, E>,
    unreadable: fn(String) -> Failure,
) -> Result<T, Failure>
where
    study::StudyError: From<E>,
{
    let Some(p) = path else {
        return Ok(shipped());
    };
    let text =
        std::fs::read_to_string(p).map_err(|e| unreadable(format!("{}: {e}", p.display())))?;
    Ok(parse(&text, &p.display().to_string()).map_err(study::StudyError::from)?)
}
