//! `thinwall inspect`: what a part is made of, before any recognition.

use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use thinwall_analysis::PartAnalysis;
use thinwall_brep::{BodyKind, Units};
use thinwall_geom::{BoundingBox, Point3, Vector3};
use thinwall_step::{ReadIssue, ReadReport};

/// Version tag of the JSON layout below.
pub const INSPECT_SCHEMA: &str = "thinwall/inspect/1";

/// One body.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct BodyEntry {
    pub step_id: u64,
    pub name: String,
    pub kind: BodyKind,
    pub shells: usize,
    pub voids: usize,
    pub faces: usize,
    pub placement: Option<String>,
}

/// One face of a solid body.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct FaceEntry {
    /// Entity id of the `ADVANCED_FACE`.
    pub step_id: u64,
    pub name: String,
    /// Index of its body in `bodies`.
    pub body: u32,
    /// `plane`, `cylinder`, `cone`, `sphere`, `torus`, `bspline`, …
    pub surface: String,
    /// mm².
    pub area: f64,
    pub centroid: Point3,
    pub bbox: BoundingBox,
    /// Outward unit normal (planes).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub normal: Option<Vector3>,
    /// Axis point and direction (cylinder, cone, sphere, torus).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub axis: Option<(Point3, Vector3)>,
    /// mm (cylinder, sphere, cone at its placement, torus minor radius).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub radius: Option<f64>,
    pub outer_loops: usize,
    pub inner_loops: usize,
    /// Its ordinal in OpenCascade's face order (`opencascade_faces`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub occ_index: Option<u32>,
}

/// One edge with its faces and how they meet.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct EdgeEntry {
    /// Entity id of the `EDGE_CURVE`.
    pub step_id: u64,
    pub curve: String,
    /// `step_id`s of the faces using it.
    pub faces: Vec<u64>,
    /// convex, concave, smooth, mixed, seam.
    pub convexity: String,
    /// Interior dihedral angle range along the edge, degrees.
    pub angle_min_deg: f64,
    pub angle_max_deg: f64,
}

/// Reader findings.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct ReadSummary {
    pub entities_read: usize,
    pub entities_kept: usize,
    pub dropped: Vec<ReadIssue>,
    pub repaired: Vec<ReadIssue>,
    /// Face-level computations that are approximate or failed.
    pub geometry_warnings: Vec<ReadIssue>,
}

/// The whole inspect report.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct InspectReport {
    pub schema: String,
    /// The Thinwall version that wrote it.
    pub thinwall_version: String,
    pub file: String,
    pub units: Units,
    pub bodies: Vec<BodyEntry>,
    pub bounding_box: BoundingBox,
    /// Faces of the solid bodies, by surface kind.
    pub face_counts: BTreeMap<String, usize>,
    /// Edges by convexity.
    pub edge_convexity_counts: BTreeMap<String, usize>,
    /// Faces of surface models outside any solid (never in `faces`).
    pub supplemental_faces: usize,
    pub supplemental_surface_models: Vec<u64>,
    pub faces: Vec<FaceEntry>,
    pub edges: Vec<EdgeEntry>,
    /// Face pairs sharing an edge (graph arcs).
    pub adjacencies: usize,
    pub read: ReadSummary,
    /// Every warning, in full: the reader's drops and repairs, approximate
    /// figures, open, non-manifold or unjudged edges.
    pub warnings: Vec<thinwall_analysis::Warning>,
    /// The part's faces in OpenCascade's order (`TopExp::MapShapes` over
    /// the shape it reads from the same file): entry `i` names the face a
    /// host built on OpenCascade numbers `i`, `null` for one of a
    /// supplemental surface model. Absent for a part not read from STEP.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub opencascade_faces: Vec<Option<thinwall_brep::FaceKey>>,
}

/// Build the report of a part read from `file`, from its analysis (any
/// set-up: nothing here depends on it).
pub fn inspect(file: &str, analysis: &PartAnalysis, read: &ReadReport) -> InspectReport {
    let part = analysis.part();
    let graph = analysis.graph();
    let mut face_counts = BTreeMap::new();
    let mut geometry_warnings = Vec::new();
    let mut faces = Vec::with_capacity(part.faces.len());
    for id in part.face_ids() {
        let f = part.face(id);
        let props = analysis.props(id);
        for w in &props.warnings {
            geometry_warnings.push(ReadIssue {
                entity: Some(f.step_id),
                message: w.clone(),
            });
        }
        let surface = f.surface.kind_name().to_string();
        *face_counts.entry(surface.clone()).or_insert(0) += 1;
        let outer = f.loops.iter().filter(|&&l| part.loop_(l).is_outer).count();
        faces.push(FaceEntry {
            step_id: f.step_id,
            name: f.name.clone(),
            body: f.body.0,
            surface,
            area: props.area,
            centroid: props.centroid,
            bbox: props.bbox,
            normal: props.normal,
            axis: props.axis,
            radius: props.radius,
            outer_loops: outer,
            inner_loops: f.loops.len() - outer,
            occ_index: part.occ_ordinal(id),
        });
    }
    let mut edge_convexity_counts = BTreeMap::new();
    for (c, n) in graph.convexity_counts() {
        edge_convexity_counts.insert(c.name().to_string(), n);
    }
    let edges = graph
        .edges
        .iter()
        .map(|e| EdgeEntry {
            step_id: e.step_id,
            curve: part.edge(e.edge).curve.name().to_string(),
            faces: e.faces.iter().map(|f| part.face(*f).step_id).collect(),
            convexity: e.convexity.name().to_string(),
            angle_min_deg: e.angle_min_deg,
            angle_max_deg: e.angle_max_deg,
        })
        .collect();
    let bodies = part
        .bodies
        .iter()
        .map(|b| BodyEntry {
            step_id: b.step_id,
            name: b.name.clone(),
            kind: b.kind,
            shells: b.shells.len(),
            voids: b.shells.iter().filter(|s| s.is_void).count(),
            faces: b.shells.iter().map(|s| s.faces.len()).sum(),
            placement: b.placement.clone(),
        })
        .collect();
    InspectReport {
        schema: INSPECT_SCHEMA.to_string(),
        thinwall_version: env!("CARGO_PKG_VERSION").to_string(),
        file: file.to_string(),
        units: part.units.clone(),
        bodies,
        bounding_box: part.bounding_box(),
        face_counts,
        edge_convexity_counts,
        supplemental_faces: part.supplemental.face_count,
        supplemental_surface_models: part.supplemental.surface_models.clone(),
        opencascade_faces: part.occ_faces(),
        faces,
        edges,
        adjacencies: graph.graph.edge_count(),
        warnings: crate::recognize::read_warnings(read)
            .into_iter()
            .chain(analysis.warnings())
            .collect(),
        read: ReadSummary {
            entities_read: read.entities_read,
            entities_kept: read.entities_kept,
            dropped: read.dropped.clone(),
            repaired: read.repaired.clone(),
            geometry_warnings,
        },
    }
}

impl InspectReport {
    /// The report as `thinwall inspect --format json` prints it
    /// (`docs/schema/inspect.schema.json`).
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
            + "\n"
    }

    /// A summary for people: bodies, size, counts, and what the reader did.
    pub fn to_text(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(s, "{}", self.file);
        let _ = writeln!(
            s,
            "  units       {} (×{} → mm), angles {}",
            self.units.length, self.units.mm_per_unit, self.units.angle
        );
        let size = self.bounding_box.size();
        let _ = writeln!(
            s,
            "  size        {:.3} × {:.3} × {:.3} mm (min {:.3}, {:.3}, {:.3})",
            size[0],
            size[1],
            size[2],
            self.bounding_box.min[0],
            self.bounding_box.min[1],
            self.bounding_box.min[2]
        );
        let _ = writeln!(s, "  bodies      {}", self.bodies.len());
        for (i, b) in self.bodies.iter().enumerate() {
            let _ = writeln!(
                s,
                "    [{i}] #{} {:?} '{}': {} faces, {} shell(s), {} void(s){}",
                b.step_id,
                b.kind,
                b.name,
                b.faces,
                b.shells,
                b.voids,
                b.placement
                    .as_ref()
                    .map(|p| format!(", placed at {p}"))
                    .unwrap_or_default()
            );
        }
        let total_area: f64 = self.faces.iter().map(|f| f.area).sum();
        let _ = writeln!(
            s,
            "  faces       {} (area {:.3} mm²)",
            self.faces.len(),
            total_area
        );
        for (k, n) in &self.face_counts {
            let _ = writeln!(s, "    {k:<12}{n:>6}");
        }
        let _ = writeln!(
            s,
            "  edges       {} ({} face pairs adjacent)",
            self.edges.len(),
            self.adjacencies
        );
        for (k, n) in &self.edge_convexity_counts {
            let _ = writeln!(s, "    {k:<12}{n:>6}");
        }
        if self.supplemental_faces > 0 {
            let _ = writeln!(
                s,
                "  supplemental surface geometry: {} faces in {} surface model(s), not part of the solid",
                self.supplemental_faces,
                self.supplemental_surface_models.len()
            );
        }
        let r = &self.read;
        let _ = writeln!(
            s,
            "  read        {} entities, {} kept, {} dropped, {} repaired, {} geometry warnings",
            r.entities_read,
            r.entities_kept,
            r.dropped.len(),
            r.repaired.len(),
            r.geometry_warnings.len()
        );
        if !self.warnings.is_empty() {
            let _ = writeln!(s, "warnings: {}", self.warnings.len());
            for w in &self.warnings {
                let _ = writeln!(s, "  {}", w.message);
            }
        }
        s
    }
}
