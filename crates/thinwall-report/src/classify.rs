//! `thinwall classify`: the classification report (`thinwall/classification/1`).

use serde::{Deserialize, Serialize};
use std::fmt::Write as _;
use thinwall_classify::Classification;

/// Version tag of the JSON layout.
pub const CLASSIFICATION_SCHEMA: &str = "thinwall/classification/1";

/// The whole classification report.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct ClassificationReport {
    pub schema: String,
    /// The Thinwall version that wrote it.
    pub thinwall_version: String,
    pub part: String,
    pub up: [f64; 3],
    /// `[a, b]`: volume `a` is removed before volume `b`.
    pub before: Vec<[usize; 2]>,
    /// In the order given.
    pub volumes: Vec<Classification>,
    /// The part's faces in OpenCascade's order (`TopExp::MapShapes` over
    /// the shape it reads from the same file): entry `i` names the face a
    /// host built on OpenCascade numbers `i`, `null` for one of a
    /// supplemental surface model. Absent for a part not read from STEP.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub opencascade_faces: Vec<Option<thinwall_brep::FaceKey>>,
}

impl ClassificationReport {
    pub fn new(
        part: &str,
        up: [f64; 3],
        before: &[(usize, usize)],
        volumes: Vec<Classification>,
    ) -> Self {
        Self {
            schema: CLASSIFICATION_SCHEMA.to_string(),
            thinwall_version: env!("CARGO_PKG_VERSION").to_string(),
            part: part.to_string(),
            up,
            before: before.iter().map(|&(a, b)| [a, b]).collect(),
            volumes,
            opencascade_faces: Vec::new(),
        }
    }

    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
            + "\n"
    }

    /// One line per volume, then its faces.
    pub fn to_text(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(
            s,
            "{}: {} volume(s), up ({:.3}, {:.3}, {:.3})",
            self.part,
            self.volumes.len(),
            self.up[0],
            self.up[1],
            self.up[2]
        );
        for c in &self.volumes {
            let _ = writeln!(
                s,
                "  [{}] {:<14} {:<14} depth {:.2} mm, profile {:.2} × {:.2} mm{}{}  ({})",
                c.index,
                c.kind.name(),
                c.product_adjacency.name(),
                c.depth,
                c.length,
                c.width,
                if c.bottom_open { ", bottom open" } else { "" },
                if c.corner_radii.is_empty() {
                    String::new()
                } else {
                    format!(", corner radii {:?}", c.corner_radii)
                },
                c.name
            );
            if let Some(r) = &c.reason {
                let _ = writeln!(s, "      unknown: {r}");
            }
            for f in &c.faces {
                let touches: Vec<String> = f
                    .touches
                    .iter()
                    .map(|t| match t {
                        thinwall_classify::Touch::Part { step_id } => format!("part #{step_id}"),
                        thinwall_classify::Touch::Volume { index, step_id } => {
                            format!("volume {index} #{step_id}")
                        }
                    })
                    .collect();
                let _ = writeln!(
                    s,
                    "      #{:<6} {:<7} {:<9} {:<7} {}",
                    f.step_id,
                    format!("{:?}", f.role).to_lowercase(),
                    f.surface,
                    if f.closed { "closed" } else { "open" },
                    touches.join(", ")
                );
            }
        }
        s
    }
}
