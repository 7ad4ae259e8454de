//! `thinwall recognize`: the recognition report (JSON contract
//! `thinwall/recognition/1`, schema in `docs/schema/recognition.schema.json`).

use serde::{Deserialize, Serialize};
use std::fmt::Write as _;
use thinwall_brep::{compute_face_props, Part, Units};
use thinwall_geom::BoundingBox;
use thinwall_recognize::{Recognition, StiffnessFeature};

/// Version tag of the JSON layout.
pub const RECOGNITION_SCHEMA: &str = "thinwall/recognition/1";

/// The part the report is about.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct PartSummary {
    pub file: String,
    pub units: Units,
    pub bodies: usize,
    pub faces: usize,
    pub bounding_box: BoundingBox,
}

/// One face of the part.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct FaceSummary {
    pub step_id: u64,
    pub name: String,
    pub surface: String,
    /// mm².
    pub area: f64,
}

/// The set-up recognition ran in.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Setup {
    /// Unit up direction (tool axis).
    pub up: [f64; 3],
}

/// A connection between two features (filled by the connections layer).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Connection {
    BaseLeaf { base: String, leaf: String },
    Crossing { features: [String; 2] },
}

/// The whole recognition report.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct RecognitionReport {
    pub schema: String,
    pub part: PartSummary,
    pub setup: Setup,
    pub faces: Vec<FaceSummary>,
    pub stiffness_features: Vec<StiffnessFeature>,
    pub connections: Vec<Connection>,
    /// Filled by the machining-feature layer.
    pub machining_features: Vec<serde_json::Value>,
}

/// Build the report.
pub fn recognition_report(
    file: &str,
    part: &Part,
    up: [f64; 3],
    r: &Recognition,
    connections: Vec<Connection>,
) -> RecognitionReport {
    let faces = part
        .face_ids()
        .map(|f| {
            let face = part.face(f);
            FaceSummary {
                step_id: face.step_id,
                name: face.name.clone(),
                surface: face.surface.kind_name().to_string(),
                area: compute_face_props(part, f).area,
            }
        })
        .collect();
    RecognitionReport {
        schema: RECOGNITION_SCHEMA.to_string(),
        part: PartSummary {
            file: file.to_string(),
            units: part.units.clone(),
            bodies: part.bodies.len(),
            faces: part.faces.len(),
            bounding_box: part.bounding_box(),
        },
        setup: Setup { up },
        faces,
        stiffness_features: r.features.clone(),
        connections,
        machining_features: Vec::new(),
    }
}

fn mm(v: Option<f64>) -> String {
    v.map(|x| format!("{x:.2}")).unwrap_or_else(|| "-".into())
}

impl RecognitionReport {
    /// A table a process planner can scan: walls first (thin ones on top),
    /// then what is in and on them.
    pub fn to_text(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(
            s,
            "{}: {} faces, up ({:.3}, {:.3}, {:.3})",
            self.part.file, self.part.faces, self.setup.up[0], self.setup.up[1], self.setup.up[2]
        );
        let walls: Vec<&StiffnessFeature> = self
            .stiffness_features
            .iter()
            .filter(|f| f.kind.is_wall())
            .collect();
        let thin = walls.iter().filter(|f| f.thin == Some(true)).count();
        let _ = writeln!(s, "walls: {} ({} thin)", walls.len(), thin);
        let _ = writeln!(
            s,
            "  {:<6}{:<8}{:<6}{:>10}{:>10}{:>10}{:>12}{:>8}{:>7}  on",
            "id", "kind", "thin", "t mm", "h mm", "L mm", "defl. mm", "h/t", "faces"
        );
        let mut sorted = walls.clone();
        sorted.sort_by_key(|f| (f.thin != Some(true), f.kind, f.id.clone()));
        for f in sorted {
            let _ = writeln!(
                s,
                "  {:<6}{:<8}{:<6}{:>10}{:>10}{:>10}{:>12}{:>8}{:>7}  {}",
                f.id,
                f.kind.name(),
                if f.thin == Some(true) { "yes" } else { "no" },
                mm(f.thickness),
                mm(f.height),
                mm(f.length),
                f.deflection.map(|d| format!("{d:.4}")).unwrap_or_default(),
                f.slenderness.map(|d| format!("{d:.1}")).unwrap_or_default(),
                f.faces.len(),
                f.base.clone().unwrap_or_default()
            );
        }
        let others: Vec<&StiffnessFeature> = self
            .stiffness_features
            .iter()
            .filter(|f| !f.kind.is_wall())
            .collect();
        let _ = writeln!(s, "in and on walls: {}", others.len());
        for f in others {
            let size = match f.kind {
                thinwall_recognize::Kind::Hole => format!(
                    "Ø{} h {}{}{}",
                    mm(f.diameter),
                    mm(f.height),
                    if f.large == Some(true) { " large" } else { "" },
                    if f.through == Some(false) {
                        " blind"
                    } else {
                        ""
                    }
                ),
                thinwall_recognize::Kind::Fillet => format!(
                    "r {}{}",
                    mm(f.radius),
                    if f.convex == Some(true) {
                        " (round)"
                    } else {
                        ""
                    }
                ),
                _ => format!("depth {} width {}", mm(f.height), mm(f.width)),
            };
            let _ = writeln!(
                s,
                "  {:<6}{:<8}{:<28}{:>3} faces  in {}",
                f.id,
                f.kind.name(),
                size,
                f.faces.len(),
                f.wall.clone().unwrap_or_else(|| "-".into())
            );
        }
        if !self.connections.is_empty() {
            let _ = writeln!(s, "connections: {}", self.connections.len());
        }
        s
    }
}
