//! A part read from STEP, with what the reader reported and its adjacency
//! graph: what every study of it shares.

use crate::StudyError;
use std::path::Path;
use thinwall_brep::Part;
use thinwall_graph::AdjacencyGraph;
use thinwall_step::ReadReport;

/// A part read into memory (immutable; share it between threads freely).
pub struct LoadedPart {
    /// The name results give it (the path it was read from, or the name a
    /// host gave its bytes).
    pub name: String,
    pub part: Part,
    /// What the reader dropped or repaired.
    pub read: ReadReport,
    pub graph: AdjacencyGraph,
}

impl LoadedPart {
    /// A part already read, named `name`; builds its graph.
    pub fn new(name: impl Into<String>, part: Part, read: ReadReport) -> Self {
        let graph = AdjacencyGraph::build(&part, &part.tolerances());
        Self {
            name: name.into(),
            part,
            read,
            graph,
        }
    }

    /// Read the STEP file at `path`.
    pub fn read_file(path: impl AsRef<Path>) -> Result<Self, StudyError> {
        let path = path.as_ref();
        let name = path.display().to_string();
        crate::contained("read", &name, || {
            let (part, read) = thinwall_step::read_file(path)?;
            Ok(Self::new(name.clone(), part, read))
        })
    }

    /// Read STEP text from memory; `name` names it in results and errors.
    pub fn read_bytes(bytes: &[u8], name: &str) -> Result<Self, StudyError> {
        crate::contained("read", name, || {
            let (part, read) = thinwall_step::read_bytes(bytes, name)?;
            Ok(Self::new(name, part, read))
        })
    }
}
