//! `thinwall._native`: the Python package's way into Thinwall. A command is
//! given as the command line's words (the package turns keyword arguments
//! into them), parsed by the command line's own parser and run by its own
//! job runner (`thinwall_cli::jobs`), so a keyword argument means what its
//! flag means and the result is the command line's JSON. Work runs with the
//! GIL released; a failure is a Python exception with the command line's
//! kind and exit code, the use case's code and the C ABI's status.

use pyo3::exceptions::PyException;
use pyo3::prelude::*;
use std::path::PathBuf;
use std::sync::Arc;
use thinwall_capi::tw_status;
use thinwall_cli::args::Cli;
use thinwall_cli::failure::Failure;
use thinwall_cli::jobs::{self, Progress};
use thinwall_study::{Format, LoadedPart, Study};

pyo3::create_exception!(_native, ThinwallError, PyException, "Any Thinwall failure.");
pyo3::create_exception!(
    _native,
    UsageError,
    ThinwallError,
    "A value, an argument or a settings file that cannot be used (the CLI's exit 2)."
);
pyo3::create_exception!(
    _native,
    InputError,
    ThinwallError,
    "Input data that cannot be read or used (the CLI's exit 1)."
);
pyo3::create_exception!(
    _native,
    InternalError,
    ThinwallError,
    "A defect of Thinwall, please report it (the CLI's exit 3)."
);

/// A part read from STEP, with its adjacency graph: read once, studied by
/// every command it is given to.
#[pyclass(frozen, module = "thinwall._native")]
struct Part {
    loaded: Arc<LoadedPart>,
}

#[pymethods]
impl Part {
    /// Read the STEP file at `path`.
    #[staticmethod]
    fn from_path(py: Python<'_>, path: PathBuf) -> PyResult<Part> {
        let read = py.detach(|| LoadedPart::read_file(&path));
        Ok(Part {
            loaded: Arc::new(read.map_err(|e| raise(py, &e.into()))?),
        })
    }

    /// Read STEP text from `data`, named `name` in results and messages.
    #[staticmethod]
    fn from_bytes(py: Python<'_>, data: Vec<u8>, name: String) -> PyResult<Part> {
        let read = py.detach(|| LoadedPart::read_bytes(&data, &name));
        Ok(Part {
            loaded: Arc::new(read.map_err(|e| raise(py, &e.into()))?),
        })
    }

    /// The name results give the part (its path, or the name given).
    #[getter]
    fn name(&self) -> String {
        self.loaded.name.clone()
    }

    /// Number of faces of its solid bodies.
    #[getter]
    fn face_count(&self) -> usize {
        self.loaded.part.faces.len()
    }

    /// Number of faces OpenCascade numbers in the shape it reads from the
    /// same text (the solids' and the supplemental surface models').
    #[getter]
    fn occ_face_count(&self) -> usize {
        self.loaded.part.occ_faces().len()
    }
}

/// Run the command `argv` (as after `thinwall` on the command line) and
/// return its JSON. With `part`, the command runs on it instead of reading
/// the file its arguments name.
#[pyfunction]
#[pyo3(signature = (argv, part=None))]
fn run(py: Python<'_>, argv: Vec<String>, part: Option<PyRef<'_, Part>>) -> PyResult<String> {
    let loaded = part.map(|p| p.loaded.clone());
    py.detach(|| {
        thinwall_study::contained("the Python package", "thinwall", || {
            Ok(run_words(argv, loaded))
        })
        .unwrap_or_else(|e| Err(e.into()))
    })
    .map_err(|f| raise(py, &f))
}

fn run_words(argv: Vec<String>, part: Option<Arc<LoadedPart>>) -> Result<String, Failure> {
    use clap::Parser;
    let words = std::iter::once("thinwall".to_string()).chain(argv);
    let cli = Cli::try_parse_from(words).map_err(|e| {
        let text = e.to_string();
        Failure::Usage(text.strip_prefix("error: ").unwrap_or(&text).to_string())
    })?;
    let limit = cli.time_limit()?;
    let asked = jobs::asked(cli.command)?;
    let loaded = match (part, &asked.part) {
        (Some(p), _) => Some(p),
        (None, Some(path)) => Some(Arc::new(LoadedPart::read_file(path)?)),
        (None, None) => None,
    };
    let study = loaded
        .as_deref()
        .map(|l| Study::new(l).with_time_limit(limit));
    let rendered = jobs::run(&asked.job, study.as_ref(), &Progress::QUIET)?;
    Ok(thinwall_study::render(&rendered, Format::Json)?)
}

/// The exception of `failure`, with its kind, exit code, code and status.
fn raise(py: Python<'_>, failure: &Failure) -> PyErr {
    let message = failure.message().trim_end().to_string();
    let err = match failure.kind() {
        "usage" => UsageError::new_err(message),
        "input" => InputError::new_err(message),
        _ => InternalError::new_err(message),
    };
    let status = match failure.study_error() {
        Some(e) => thinwall_capi::study_status(e),
        None => match failure.kind() {
            "usage" => tw_status::TW_ERR_INVALID_ARGUMENT,
            "input" => tw_status::TW_ERR_IO,
            _ => tw_status::TW_ERR_INTERNAL,
        },
    };
    let value = err.value(py);
    // Setting an attribute on a fresh exception object cannot fail.
    let _ = value.setattr("kind", failure.kind());
    let _ = value.setattr("code", failure.code());
    let _ = value.setattr("exit_code", failure.exit_code());
    let _ = value.setattr("status", status as i32);
    let _ = value.setattr("status_name", format!("{status:?}"));
    err
}

/// The colours of Thinwall's pictures by name (`stiffness.web`,
/// `machining.hole`, `plan.large`, …), as `#rrggbb`: a host colours alike.
#[pyfunction]
fn palette() -> std::collections::BTreeMap<String, String> {
    thinwall_report::palette::table()
}

/// The Thinwall version of the library.
#[pyfunction]
fn version() -> &'static str {
    env!("CARGO_PKG_VERSION")
}

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add_class::<Part>()?;
    m.add_function(wrap_pyfunction!(run, m)?)?;
    m.add_function(wrap_pyfunction!(version, m)?)?;
    m.add_function(wrap_pyfunction!(palette, m)?)?;
    m.add("ThinwallError", py.get_type::<ThinwallError>())?;
    m.add("UsageError", py.get_type::<UsageError>())?;
    m.add("InputError", py.get_type::<InputError>())?;
    m.add("InternalError", py.get_type::<InternalError>())?;
    Ok(())
}
