//! What each use case is asked, with every rule about its values in its
//! `check()`: a front end fills a request and never checks a value itself.

use crate::StudyError;
use thinwall_access::reach::Tool;
use thinwall_access::FlankOptions;
use thinwall_analysis::{Machine, Setup};
use thinwall_ops::ToolLibrary;
use thinwall_plan::sizing::{SizingParameters, WallDimensions};
use thinwall_plan::RuleSet;

/// `recognize`: the pipeline's request (set-up, settings, connections,
/// machining, reach of wall sides); its `check()` holds its rules.
pub type RecognizeRequest = thinwall_pipeline::Request;

/// The set-up of a command: `up` (+Z when not given) on `machine`. The one
/// place an `--up` becomes a set-up.
pub fn setup_of(up: Option<[f64; 3]>, machine: Machine) -> Result<Setup, StudyError> {
    Ok(Setup::new(up.unwrap_or([0.0, 0.0, 1.0]), machine)?)
}

/// `plan`: a recognition and the sequence rules; with `later_ups` or
/// `propose`, several set-ups planned in turn.
#[derive(Clone, Debug)]
pub struct PlanRequest {
    /// The recognition of the (first) set-up; later set-ups are
    /// recognized with the same settings along their ups.
    pub recognize: RecognizeRequest,
    pub rules: RuleSet,
    /// Set-ups after the first, by their ups, in order: each plans what
    /// the set-ups before it left.
    pub later_ups: Vec<[f64; 3]>,
    /// Propose the set-ups instead of taking the recognition's up and
    /// `later_ups` (`thinwall_setups::proposal`).
    pub propose: bool,
}

impl PlanRequest {
    /// One set-up: `recognize`'s.
    pub fn new(recognize: RecognizeRequest, rules: RuleSet) -> Self {
        Self {
            recognize,
            rules,
            later_ups: Vec::new(),
            propose: false,
        }
    }

    pub fn check(&self) -> Result<(), StudyError> {
        for up in &self.later_ups {
            Setup::new(*up, self.recognize.setup.machine)?;
        }
        self.recognize.check().map_err(StudyError::Request)
    }

    /// Whether it asks for set-ups in turn (proposed or several ups).
    pub fn several(&self) -> bool {
        self.propose || !self.later_ups.is_empty()
    }
}

/// `access`: flank milling and reach of every face with a tool and its
/// holder, in the set-up of `walls`: the recognition (without reach of its
/// own) whose wall sides are judged.
#[derive(Clone, Debug)]
pub struct AccessRequest {
    pub tool: Tool,
    /// Widen the unreachable zones by the tool's radius.
    pub tool_radius: bool,
    /// Share of a face that must be reached for it to be advisable, 0..=1.
    pub threshold: f64,
    /// The recognition the walls come from; its set-up is the access's.
    pub walls: RecognizeRequest,
}

impl AccessRequest {
    /// The defaults (Ø12 tool, threshold 0.95) in `setup`.
    pub fn new(setup: Setup) -> Self {
        let flank = FlankOptions::default();
        Self {
            walls: RecognizeRequest {
                setup,
                allow_open: true,
                ..Default::default()
            },
            tool: Tool::new(flank.tool_diameter),
            tool_radius: flank.tool_radius,
            threshold: flank.threshold,
        }
    }

    /// The set-up (the walls' recognition's).
    pub fn setup(&self) -> &Setup {
        &self.walls.setup
    }

    pub fn check(&self) -> Result<(), StudyError> {
        self.setup().validate()?;
        self.tool.check()?;
        if !(0.0..=1.0).contains(&self.threshold) {
            return Err(StudyError::invalid(
                "threshold",
                format!("must lie between 0 and 1, got {}", self.threshold),
            ));
        }
        self.walls.check().map_err(StudyError::Request)
    }

    /// The flank-milling options.
    pub fn flank(&self) -> FlankOptions {
        FlankOptions {
            tool_diameter: self.tool.diameter,
            tool_radius: self.tool_radius,
            threshold: self.threshold,
        }
    }
}

/// `operations`: a set-up's operations with a tool library.
#[derive(Clone, Debug)]
pub struct OperationsRequest {
    pub setup: Setup,
    pub tools: ToolLibrary,
    /// Depth of cut between levels, mm (none: the largest end mill's).
    pub axial_depth: Option<f64>,
    /// Follow the plan (each machining feature on its own) instead of
    /// layering the whole removal at once.
    pub by_feature: bool,
    /// Then the set-up from the opposite side (up reversed), after this
    /// one: what it could not reach under the part (a web pocketed from
    /// both sides). Whole-removal sheets only.
    pub both_sides: bool,
    /// Propose the set-ups instead of taking `setup.up`: the fewest ups
    /// from which a 3-axis machine reaches stock − part, the first the one
    /// from which the most is reachable (`thinwall_setups::proposal`).
    pub choose_up: bool,
    /// Set-ups after `setup`, by their ups, in order: each cuts what the
    /// set-ups before it left.
    pub later_ups: Vec<[f64; 3]>,
}

/// Most roughing layers an axial depth may cut a part into (the work grows
/// with their number).
pub const MOST_LAYERS: f64 = 10_000.0;

impl OperationsRequest {
    /// The axial depth against a part `size_mm` across: at most
    /// [`MOST_LAYERS`] layers through it.
    pub fn check_for_part(&self, size_mm: f64) -> Result<(), StudyError> {
        match self.axial_depth {
            Some(d) if d * MOST_LAYERS < size_mm => Err(StudyError::invalid(
                "axial_depth",
                format!(
                    "must be at least {:.4} mm on this part ({size_mm:.1} mm across: at most {MOST_LAYERS} layers), got {d}",
                    size_mm / MOST_LAYERS
                ),
            )),
            _ => Ok(()),
        }
    }

    /// Whether it asks for set-ups in turn (proposed, both sides or
    /// several ups), not one set-up.
    pub fn several(&self) -> bool {
        self.choose_up || self.both_sides || !self.later_ups.is_empty()
    }

    /// The shipped tool library in `setup`, the whole removal at once.
    pub fn new(setup: Setup) -> Self {
        Self {
            setup,
            tools: ToolLibrary::default_tools(),
            axial_depth: None,
            by_feature: false,
            both_sides: false,
            choose_up: false,
            later_ups: Vec::new(),
        }
    }

    pub fn check(&self) -> Result<(), StudyError> {
        self.setup.validate()?;
        if let Some(d) = self.axial_depth {
            if !(d.is_finite() && d > 0.0) {
                return Err(StudyError::invalid(
                    "axial_depth",
                    format!("must be a positive length, got {d}"),
                ));
            }
        }
        let m = self.tools.min_share_mm2;
        if !(m.is_finite() && m >= 0.0) {
            return Err(StudyError::invalid(
                "min_share",
                format!("must be an area of 0 mm² or more, got {m}"),
            ));
        }
        if self.choose_up && self.setup.placement.is_some() {
            return Err(StudyError::invalid(
                "choose_up",
                "the up is chosen in the part's own coordinates: not with a placement",
            ));
        }
        if !self.later_ups.is_empty() && (self.choose_up || self.setup.placement.is_some()) {
            return Err(StudyError::invalid(
                "up",
                "several set-ups are given in the part's own coordinates: not with a placement or with the set-ups proposed",
            ));
        }
        for up in &self.later_ups {
            Setup::new(*up, self.setup.machine)?;
        }
        if self.tools.end_mills().next().is_none() {
            return Err(thinwall_ops::OpsError::NoEndMill {
                library: self.tools.source.clone(),
            }
            .into());
        }
        Ok(())
    }
}

/// `classify`: volumes against the part, in a set-up, with the order in
/// which some are removed (`(a, b)`: volume a before volume b).
pub struct ClassifyRequest {
    pub setup: Setup,
    pub volumes: Vec<thinwall_classify::Volume>,
    pub before: Vec<(usize, usize)>,
}

impl ClassifyRequest {
    pub fn check(&self) -> Result<(), StudyError> {
        self.setup.validate()?;
        Ok(())
    }
}

/// A removal volume of a part already read, its tool from the set-up's
/// up.
pub fn volume_of(loaded: &crate::LoadedPart) -> thinwall_classify::Volume {
    thinwall_classify::Volume {
        name: loaded.name.clone(),
        part: loaded.part.clone(),
        current: None,
        up: None,
    }
}

/// A removal volume from its STEP file (named by its path), its tool
/// from the set-up's up; no adjacency graph is built for it.
pub fn read_volume(
    path: impl AsRef<std::path::Path>,
) -> Result<thinwall_classify::Volume, StudyError> {
    let path = path.as_ref();
    let name = path.display().to_string();
    crate::contained("read", &name, || {
        Ok(thinwall_classify::Volume {
            name: name.clone(),
            part: thinwall_step::read_file(path)?.0,
            current: None,
            up: None,
        })
    })
}

/// `size-wall`: a wall and the step-approach model's parameters (their
/// rules are the sizing model's own and are checked by it).
#[derive(Clone, Debug)]
pub struct SizeWallRequest {
    pub wall: WallDimensions,
    pub parameters: SizingParameters,
}
