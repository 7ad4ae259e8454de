//! Why a use case failed: one typed error for every command, with its kind
//! (what a front end's exit code or status is chosen by) and a stable code.

use thinwall_pipeline::PipelineError;
use thiserror::Error;

/// What kind of failure an error is: the CLI's exit code and the C ABI's
/// status family follow it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ErrorKind {
    /// A value, a flag or a settings file that cannot be used (exit 2).
    Usage,
    /// Input data that cannot be read or used (exit 1).
    Input,
    /// A defect of Thinwall (exit 3).
    Internal,
}

impl ErrorKind {
    pub fn name(self) -> &'static str {
        match self {
            ErrorKind::Usage => "usage",
            ErrorKind::Input => "input",
            ErrorKind::Internal => "internal",
        }
    }

    /// The CLI's exit code.
    pub fn exit_code(self) -> u8 {
        match self {
            ErrorKind::Usage => 2,
            ErrorKind::Input => 1,
            ErrorKind::Internal => 3,
        }
    }
}

/// Why a use case could not give its result.
#[derive(Debug, Error)]
pub enum StudyError {
    /// A request value out of its range (`field` names it as the request
    /// does: `threshold`, `axial_depth`, `tolerance`).
    #[error("{field} {message}")]
    Invalid {
        field: &'static str,
        message: String,
    },
    /// A file that cannot be read or written (a settings file, an output).
    #[error("{path}: {message}")]
    Io { path: String, message: String },
    #[error(transparent)]
    Read(#[from] thinwall_step::StepError),
    #[error(transparent)]
    Setup(#[from] thinwall_analysis::SetupError),
    #[error(transparent)]
    Reach(#[from] thinwall_access::reach::ReachError),
    /// The recognition request is not usable (checked before any work).
    #[error(transparent)]
    Request(PipelineError),
    /// Recognition of the part failed.
    #[error("{file}: {source}")]
    Recognition { file: String, source: PipelineError },
    #[error(transparent)]
    Rules(#[from] thinwall_plan::RulesError),
    #[error(transparent)]
    Tools(#[from] thinwall_ops::ToolsError),
    #[error("{code}: {0}", code = .0.code())]
    Operations(#[from] thinwall_ops::OpsError),
    #[error(transparent)]
    Classify(#[from] thinwall_classify::ClassifyError),
    #[error(transparent)]
    Sizing(#[from] thinwall_plan::sizing::SizingError),
    /// The plan cannot be made (its sizing parameters are out of range).
    #[error("{code}: {0}", code = .0.code())]
    Plan(#[from] thinwall_plan::PlanError),
    /// The work took longer than the study's time limit.
    #[error("{file}: {stage} did not finish within its time limit of {limit_seconds} s (a setting: --time-limit)")]
    BudgetExceeded {
        stage: &'static str,
        file: String,
        limit_seconds: f64,
    },
    /// A defect of Thinwall: a panic, caught (see `contained`).
    #[error("{file}: internal error in {stage} (a Thinwall bug, please report it): {message} (at {location})")]
    Panic {
        stage: &'static str,
        file: String,
        message: String,
        location: String,
    },
}

impl StudyError {
    /// A value out of range.
    pub fn invalid(field: &'static str, message: impl Into<String>) -> Self {
        StudyError::Invalid {
            field,
            message: message.into(),
        }
    }

    /// The request field a bad value was given for (`threshold`,
    /// `tool_diameter`, `up`, `stock_offset`), when the error is about one:
    /// a front end names it as its user knows it (`--tool-diameter`).
    pub fn field(&self) -> Option<&'static str> {
        use thinwall_access::reach::ReachError as R;
        use thinwall_analysis::SetupError as SE;
        let reach = |e: &R| match e {
            R::Diameter(_) => Some("tool_diameter"),
            R::CuttingLength(_) => Some("cutting_length"),
            R::Holder { .. } => Some("holder_diameter"),
            R::TiltLimit(_) => Some("tilt_limit"),
        };
        let setup = |e: &SE| match e {
            SE::ZeroUp(_) | SE::NotFiniteUp(_) => Some("up"),
            SE::TiltLimit(_) => Some("tilt_limit"),
        };
        match self {
            StudyError::Invalid { field, .. } => Some(field),
            StudyError::Reach(e) | StudyError::Request(PipelineError::Reach(e)) => reach(e),
            StudyError::Setup(e) | StudyError::Request(PipelineError::Setup(e)) => setup(e),
            StudyError::Request(PipelineError::Machining(
                thinwall_machining::MachiningError::BadOffset(_),
            )) => Some("stock_offset"),
            _ => None,
        }
    }

    pub fn kind(&self) -> ErrorKind {
        use thinwall_ops::OpsError as O;
        match self {
            StudyError::Invalid { .. }
            | StudyError::Setup(_)
            | StudyError::Reach(_)
            | StudyError::Rules(_)
            | StudyError::Tools(_)
            | StudyError::Classify(_)
            | StudyError::Sizing(_)
            | StudyError::Plan(_) => ErrorKind::Usage,
            StudyError::Io { .. } => ErrorKind::Input,
            StudyError::Read(e) if e.code() == "internal" => ErrorKind::Internal,
            StudyError::Read(_) => ErrorKind::Input,
            StudyError::Request(e) | StudyError::Recognition { source: e, .. } => pipeline_kind(e),
            StudyError::Operations(O::NoEndMill { .. }) => ErrorKind::Usage,
            StudyError::Operations(O::Removal(_) | O::NoPlan(_)) => ErrorKind::Input,
            StudyError::Panic { .. } => ErrorKind::Internal,
            StudyError::BudgetExceeded { .. } => ErrorKind::Input,
        }
    }

    /// A stable machine-readable code (`invalid.threshold`, `read.syntax`,
    /// `recognition.setup.zero_up`, `operations.removal.unsupported_face`).
    pub fn code(&self) -> String {
        match self {
            StudyError::Invalid { field, .. } => format!("invalid.{field}"),
            StudyError::Io { .. } => "io".to_string(),
            StudyError::Read(e) => format!("read.{}", e.code()),
            StudyError::Setup(e) => format!("setup.{}", e.code()),
            StudyError::Reach(e) => format!("reach.{}", e.code()),
            StudyError::Request(e) | StudyError::Recognition { source: e, .. } => {
                format!("recognition.{}", e.code())
            }
            StudyError::Rules(_) => "rules".to_string(),
            StudyError::Tools(e) => format!("tools.{}", e.code()),
            StudyError::Operations(e) => format!("operations.{}", e.code()),
            StudyError::Classify(e) => format!("classify.{}", e.code()),
            StudyError::Sizing(_) => "sizing".to_string(),
            StudyError::Plan(e) => format!("plan.{}", e.code()),
            StudyError::Panic { .. } => "panic".to_string(),
            StudyError::BudgetExceeded { .. } => "budget_exceeded".to_string(),
        }
    }
}

/// The kind of a recognition failure.
fn pipeline_kind(e: &PipelineError) -> ErrorKind {
    use thinwall_machining::MachiningError as M;
    match e {
        PipelineError::Config(_) | PipelineError::Setup(_) | PipelineError::Reach(_) => {
            ErrorKind::Usage
        }
        PipelineError::Machining(M::BadOffset(_)) => ErrorKind::Usage,
        PipelineError::OpenShell { .. } | PipelineError::Machining(_) => ErrorKind::Input,
        PipelineError::Structure(_) | PipelineError::SetupMismatch => ErrorKind::Internal,
    }
}
