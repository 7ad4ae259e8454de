//! What went wrong, by kind, with one exit code per kind: 2 when the
//! command line or the settings cannot be used (usage), 1 when the input
//! data cannot be (a missing, unreadable or unsupported file), 3 when
//! Thinwall itself failed (internal: please report it).

/// A failed command.
#[derive(Debug)]
pub enum Failure {
    /// Exit 2: a flag, a value or a settings file that cannot be used.
    Usage(String),
    /// Exit 1: input data that cannot be read or used.
    Input(String),
    /// Exit 3: a defect of Thinwall.
    Internal(String),
    /// A use case's error (exit by its kind), with the message printed
    /// (naming the flag a bad value came from): a front end that reports
    /// more than the kind (the Python package's code and C status) reads
    /// them from `error`.
    Study {
        error: thinwall_study::StudyError,
        message: String,
    },
}

impl Failure {
    pub fn usage(e: impl std::fmt::Display) -> Self {
        Failure::Usage(e.to_string())
    }

    /// The kind, as the library names it (its exit code and name).
    fn error_kind(&self) -> thinwall_study::ErrorKind {
        use thinwall_study::ErrorKind;
        match self {
            Failure::Usage(_) => ErrorKind::Usage,
            Failure::Input(_) => ErrorKind::Input,
            Failure::Internal(_) => ErrorKind::Internal,
            Failure::Study { error, .. } => error.kind(),
        }
    }

    pub fn exit_code(&self) -> u8 {
        self.error_kind().exit_code()
    }

    /// `usage`, `input` or `internal`.
    pub fn kind(&self) -> &'static str {
        self.error_kind().name()
    }

    pub fn message(&self) -> &str {
        match self {
            Failure::Usage(m) | Failure::Input(m) | Failure::Internal(m) => m,
            Failure::Study { message, .. } => message,
        }
    }

    /// A stable machine-readable code: the use case's error's
    /// (`invalid.threshold`, `read.syntax`), or the kind's name for a
    /// failure of the command line itself.
    pub fn code(&self) -> String {
        match self {
            Failure::Study { error, .. } => error.code(),
            _ => self.kind().to_string(),
        }
    }

    /// The use case's error this failure is, if it is one.
    pub fn study_error(&self) -> Option<&thinwall_study::StudyError> {
        match self {
            Failure::Study { error, .. } => Some(error),
            _ => None,
        }
    }
}

impl From<thinwall_study::StudyError> for Failure {
    fn from(e: thinwall_study::StudyError) -> Self {
        // Name the flag a bad value came from.
        let message = match e.field() {
            Some(field) => format!("--{}: {e}", field.replace('_', "-")),
            None => e.to_string(),
        };
        Failure::Study { error: e, message }
    }
}

impl From<thinwall_step::StepError> for Failure {
    fn from(e: thinwall_step::StepError) -> Self {
        thinwall_study::StudyError::from(e).into()
    }
}

/// Longest line of an error message printed (a settings file's line or a
/// file name can be kilobytes long).
const LONGEST_LINE: usize = 400;

/// `message` with each line cut to [`LONGEST_LINE`] characters.
pub fn shortened(message: &str) -> String {
    message
        .lines()
        .map(|l| match l.char_indices().nth(LONGEST_LINE) {
            Some((at, _)) => format!("{}… ({} characters)", &l[..at], l.chars().count()),
            None => l.to_string(),
        })
        .collect::<Vec<_>>()
        .join("\n")
}
