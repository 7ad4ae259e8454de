//! The library entry point: one call runs the analysis of a part in a
//! set-up, stiffness feature recognition, connections (validated) and
//! machining features, links each machining feature to the stiffness
//! features on its faces, and returns typed results. The CLI and the C ABI
//! both call [`run`]; `thinwall-report` only turns its [`Outcome`] into
//! JSON and text.
//!
//! ```no_run
//! let (part, _) = thinwall_step::read_file("panel.step").unwrap();
//! let out = thinwall_pipeline::run(&part, None, &thinwall_pipeline::Request::default()).unwrap();
//! println!("{} stiffness features, {} machining features",
//!     out.recognition.features.len(), out.machining.len());
//! ```

mod settings;

pub use settings::Settings;

use std::collections::BTreeMap;
use std::time::Instant;
use thinwall_analysis::{FeatureId, PartAnalysis, Setup, SetupError, Warning};
use thinwall_brep::{FaceProps, Part};
use thinwall_connect::{Options, Structure, StructureError};
use thinwall_graph::AdjacencyGraph;
use thinwall_machining::MachiningFeature;
use thinwall_recognize::{Config, ConfigError, Recognition};
use thiserror::Error;

/// What to run: the set-up, recognition settings, connection options.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Request {
    pub setup: Setup,
    pub config: Config,
    pub connect: Options,
    /// Use worker threads (rayon) inside the run; the results are the same
    /// either way. A host that runs its own threads may turn it off.
    #[serde(skip)]
    pub parallel: bool,
    /// Recognize a part whose shell is open (free edges) instead of refusing it.
    pub allow_open: bool,
    /// What the machining-feature layer is asked.
    pub machining: MachiningRequest,
    /// Judge each wall side's reach with this tool, material in the way
    /// (`thinwall_access::reach`); none (the default): by direction only.
    /// The CLI asks for it with the preferred tool unless `--no-reach`.
    pub reach_tool: Option<thinwall_access::reach::Tool>,
}

/// The machining-feature layer's part of a request.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct MachiningRequest {
    /// Judge features in the set-up (its up is the tool axis): the block
    /// has up as an axis, features are entered from up where they open
    /// there, and each says whether the tool reaches it. Off: every block
    /// direction is a candidate.
    pub in_setup: bool,
    /// Uniform allowance on the block, mm (0: faces on the block are
    /// stock).
    pub stock_offset: f64,
    /// A given stock solid (a blank, a casting envelope) and the file it
    /// came from.
    #[serde(skip)]
    pub stock: Option<std::sync::Arc<Part>>,
    /// The stock file, for the report.
    pub stock_file: Option<String>,
}

impl MachiningRequest {
    /// The stock this request describes: the one place a request becomes
    /// a [`thinwall_machining::StockSpec`] (recognition and the plan read it).
    pub fn stock_spec(&self) -> thinwall_machining::StockSpec<'_> {
        match &self.stock {
            Some(solid) => thinwall_machining::StockSpec::Solid(solid),
            None if self.stock_offset != 0.0 => {
                thinwall_machining::StockSpec::Offset(self.stock_offset)
            }
            None => thinwall_machining::StockSpec::Block,
        }
    }
}

impl Request {
    /// Every rule about the request's values: usable recognition settings,
    /// a usable set-up, a reach tool that is a tool, a stock allowance of
    /// 0 mm or more.
    pub fn check(&self) -> Result<(), PipelineError> {
        self.config.validate()?;
        self.setup.validate()?;
        if let Some(tool) = &self.reach_tool {
            tool.check()?;
        }
        let offset = self.machining.stock_offset;
        if !(offset.is_finite() && offset >= 0.0) {
            return Err(thinwall_machining::MachiningError::BadOffset(offset).into());
        }
        Ok(())
    }
}

impl Default for Request {
    fn default() -> Self {
        Self {
            setup: Setup::default(),
            config: Config::default(),
            connect: Options::default(),
            parallel: true,
            allow_open: false,
            machining: MachiningRequest::default(),
            reach_tool: None,
        }
    }
}

/// Everything the pipeline found. Recognition and connections cover every
/// kind; `request.config.include`/`exclude` only say which rows a report
/// shows.
#[derive(Clone, Debug)]
pub struct Outcome {
    /// The settings in force.
    pub request: Request,
    pub setup: Setup,
    pub recognition: Recognition,
    pub structure: Structure,
    /// Conventional machining features, each with the stiffness features
    /// sharing its faces (`related`).
    pub machining: Vec<MachiningFeature>,
    /// Equal holes on a line or a circle (`thinwall_machining::patterns`).
    pub hole_patterns: Vec<thinwall_machining::HolePattern>,
    /// Every face's properties, by `face.index()`.
    pub face_props: Vec<FaceProps>,
    /// What the analysis found questionable (approximate figures, open or
    /// non-manifold edges), in full.
    pub warnings: Vec<Warning>,
    /// Where the stiffness and machining views name the same faces
    /// differently (a hole that machining calls a pocket), one note each.
    pub view_notes: Vec<String>,
    /// Seconds per stage, in order (for `--verbose`; the library never prints).
    pub timings: Vec<(&'static str, f64)>,
}

/// Why the pipeline could not run, or failed.
#[derive(Debug, Error)]
pub enum PipelineError {
    #[error(transparent)]
    Config(#[from] ConfigError),
    #[error(transparent)]
    Setup(#[from] SetupError),
    /// The part's shell is open (edges used by one face only) and the
    /// request does not allow it.
    #[error("the solid is not closed: {count} edges are used by one face only (first #{first}); recognition of an open shell needs allow_open")]
    OpenShell { count: usize, first: u64 },
    /// The connection layer produced a structure that is not a forest: a
    /// defect of Thinwall, reported rather than returned.
    #[error("internal error: invalid connection structure: {0}")]
    Structure(#[from] StructureError),
    /// The machining request cannot be met (a bad allowance, a stock that
    /// does not contain the part).
    #[error(transparent)]
    Machining(#[from] thinwall_machining::MachiningError),
    /// The reach tool is not a tool (a diameter of zero, a holder thinner
    /// than the cutter).
    #[error(transparent)]
    Reach(#[from] thinwall_access::reach::ReachError),
    /// The analysis handed in is of another set-up than the request's: a
    /// defect of the caller.
    #[error("internal error: the analysis is of another set-up than the request")]
    SetupMismatch,
}

impl PipelineError {
    /// A stable machine-readable code: the inner error's, prefixed by the layer.
    pub fn code(&self) -> String {
        match self {
            PipelineError::Config(e) => format!("config.{}", e.code()),
            PipelineError::Setup(e) => format!("setup.{}", e.code()),
            PipelineError::OpenShell { .. } => "input.open_shell".to_string(),
            PipelineError::Structure(e) => format!("structure.{}", e.code()),
            PipelineError::Machining(e) => format!("machining.{}", e.code()),
            PipelineError::Reach(e) => format!("reach.{}", e.code()),
            PipelineError::SetupMismatch => "setup.mismatch".to_string(),
        }
    }
}

/// Run analysis → recognizers → connections → machining on `part`, with
/// its adjacency graph when the caller already has one. Builds the
/// analysis; a caller that keeps one (the study) calls [`run_on`].
pub fn run(
    part: &Part,
    graph: Option<&AdjacencyGraph>,
    req: &Request,
) -> Result<Outcome, PipelineError> {
    req.check()?;
    let t0 = Instant::now();
    let a = match graph {
        Some(g) => PartAnalysis::with_graph(part, g, req.setup.clone()),
        None => PartAnalysis::new(part, req.setup.clone()),
    }
    .with_parallelism(req.parallel);
    let built = t0.elapsed().as_secs_f64();
    let mut out = run_on(&a, req)?;
    out.timings.insert(0, ("adjacency graph", built));
    Ok(out)
}

/// Recognizers → connections → machining on an analysis of the part in
/// the request's set-up (`a.setup()` must be `req.setup`).
pub fn run_on(a: &PartAnalysis, req: &Request) -> Result<Outcome, PipelineError> {
    req.check()?;
    if a.setup() != &req.setup {
        return Err(PipelineError::SetupMismatch);
    }
    let mut clock = Clock::start();
    let free = a.free_edges();
    if !free.is_empty() && !req.allow_open {
        return Err(PipelineError::OpenShell {
            count: free.len(),
            first: free[0],
        });
    }
    a.face_props();
    clock.lap("face properties");
    a.work().check();
    // The two recognizers only read the analysis: run them side by side.
    let stiffness = || timed(|| thinwall_recognize::recognize(a, &req.config));
    let m_opts = machining_options(req);
    let conventional = || timed(|| thinwall_machining::recognize_with(a, &m_opts));
    let ((recognition, t_stiff), (machining, t_mach)) = if req.parallel {
        rayon::join(stiffness, conventional)
    } else {
        (stiffness(), conventional())
    };
    let mut machining = machining?;
    clock.record("stiffness features", t_stiff);
    clock.record("machining features", t_mach);
    clock.lap("recognizers (wall time)");
    a.work().check();
    let mut recognition = recognition;
    let mut structure = thinwall_connect::connect(&recognition, &req.setup, &req.connect);
    structure.validate()?;
    relate(&mut machining, &mut recognition);
    clock.lap("connections and links");
    if let Some(tool) = &req.reach_tool {
        wall_reach(a, &recognition, &mut structure, tool)?;
        clock.lap("reach of wall sides");
    }
    let warnings = a.warnings();
    let view_notes = disagreements(&machining, &recognition);
    let hole_patterns = thinwall_machining::hole_patterns(a, &machining);
    Ok(Outcome {
        request: req.clone(),
        setup: req.setup.clone(),
        recognition,
        structure,
        machining,
        hole_patterns,
        face_props: a.face_props().to_vec(),
        warnings,
        view_notes,
        timings: clock.laps,
    })
}

/// Each wall side's reach with material in the way, added to its verdict.
fn wall_reach(
    a: &PartAnalysis,
    recognition: &Recognition,
    structure: &mut Structure,
    tool: &thinwall_access::reach::Tool,
) -> Result<(), PipelineError> {
    use thinwall_access::reach;
    if !recognition.features.iter().any(|f| f.sides.is_some()) {
        return Ok(());
    }
    let mesh = a.mesh();
    let opts = reach::ReachOptions {
        tool: tool.clone(),
        machine: a.setup().machine,
        largest_tool: false,
    };
    let part = a.part();
    let sides: std::collections::BTreeSet<(u32, u64)> = recognition
        .features
        .iter()
        .filter_map(|f| f.sides.as_ref().map(|s| (f.body, s)))
        .flat_map(|(b, s)| s.iter().flatten().map(move |&id| (b, id)))
        .collect();
    let faces = reach::reach_of(a, mesh, &opts, |f| {
        let face = part.face(f);
        sides.contains(&(face.body.0, face.step_id))
    })?;
    let sides = reach::walls::wall_sides(a, recognition, &faces, tool.diameter);
    for (id, judged) in sides {
        let Some(verdicts) = structure.access.get_mut(&id) else {
            continue;
        };
        for (v, s) in verdicts.iter_mut().zip(judged) {
            v.fraction = Some(s.fraction);
            v.tool_diameter = Some(s.tool_diameter);
            v.blocked_by = s.blocked_by;
            if let Some(why) = s.reason {
                v.reason = format!("{}; {why}", v.reason);
            }
        }
    }
    Ok(())
}

/// The machining layer's options from the request.
fn machining_options(req: &Request) -> thinwall_machining::Options<'_> {
    let tilt = match req.setup.machine {
        thinwall_analysis::Machine::ThreeAxis => 0.0,
        thinwall_analysis::Machine::FiveAxis { tilt_limit_deg } => tilt_limit_deg,
    };
    thinwall_machining::Options {
        up: req.machining.in_setup.then(|| req.setup.up_in_part()),
        tilt_limit_deg: tilt,
        stock: req.machining.stock_spec(),
    }
}

/// One note per machining feature and related stiffness feature whose
/// kinds tell different stories about the same faces.
fn disagreements(machining: &[MachiningFeature], r: &Recognition) -> Vec<String> {
    let mut out = Vec::new();
    for m in machining {
        for id in &m.related {
            let Some(f) = r.feature(*id) else { continue };
            if !f.kind.agrees_with(m.kind) {
                out.push(format!(
                    "{} ({}) and {} ({} {}) share faces: the stiffness view sees a {}, the machining view a {}",
                    f.id, f.kind, m.id, m.kind, m.profile, f.kind, m.kind
                ));
            }
        }
    }
    out
}

/// A result and the seconds it took.
fn timed<T>(f: impl FnOnce() -> T) -> (T, f64) {
    let t0 = Instant::now();
    let v = f();
    (v, t0.elapsed().as_secs_f64())
}

/// Stage times of a run.
struct Clock {
    last: Instant,
    laps: Vec<(&'static str, f64)>,
}

impl Clock {
    fn start() -> Self {
        Self {
            last: Instant::now(),
            laps: Vec::new(),
        }
    }

    /// The time since the last lap, as `stage`.
    fn lap(&mut self, stage: &'static str) {
        let now = Instant::now();
        self.laps.push((stage, (now - self.last).as_secs_f64()));
        self.last = now;
    }

    fn record(&mut self, stage: &'static str, seconds: f64) {
        self.laps.push((stage, seconds));
    }
}

/// Fill each machining feature's `related` (the stiffness features sharing
/// a face with it, in report order) and each stiffness feature's (the
/// machining features sharing one).
fn relate(machining: &mut [MachiningFeature], r: &mut Recognition) {
    let mut by_face: BTreeMap<u64, Vec<FeatureId>> = BTreeMap::new();
    for f in &r.features {
        for &face in &f.faces {
            by_face.entry(face).or_default().push(f.id);
        }
    }
    for m in machining.iter_mut() {
        let mut related: Vec<FeatureId> = Vec::new();
        for face in &m.faces {
            for &id in by_face.get(face).into_iter().flatten() {
                if !related.contains(&id) {
                    related.push(id);
                }
            }
        }
        let pos = |id: &FeatureId| r.features.iter().position(|f| f.id == *id);
        related.sort_by_key(pos);
        m.related = related;
    }
    for f in &mut r.features {
        f.related = machining
            .iter()
            .filter(|m| m.related.contains(&f.id))
            .map(|m| m.id)
            .collect();
    }
}
