//! `thinwall recognize`: the recognition report (JSON contract
//! `thinwall/recognition/1`, schema in `docs/schema/recognition.schema.json`).

use serde::{Deserialize, Serialize};
use std::fmt::Write as _;
use thinwall_analysis::{Warning, WarningSource};
use thinwall_brep::{Part, Units};
use thinwall_connect::{Connection, Setup, SideAccess};
use thinwall_geom::BoundingBox;
use thinwall_pipeline::Outcome;
use thinwall_recognize::{FeatureId, StiffnessFeature, StiffnessKind};

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

/// A body of the part: a solid, or a placed instance of one.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct BodySummary {
    /// Index used by `body` fields.
    pub index: u32,
    /// Entity id of the solid (shared by instances of one solid).
    pub step_id: u64,
    pub name: String,
    /// The product occurrence path placing it, for an assembly instance.
    pub placement: Option<String>,
}

/// One face of the part.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct FaceSummary {
    pub step_id: u64,
    /// Index of its body: with it, the `step_id` names one face even where
    /// instances share ids.
    pub body: u32,
    pub name: String,
    pub surface: String,
    /// mm².
    pub area: f64,
    /// Its ordinal in OpenCascade's face order (`opencascade_faces`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub occ_index: Option<u32>,
}

/// A stiffness feature with, for walls, the accessibility of its sides.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct FeatureEntry {
    #[serde(flatten)]
    pub feature: StiffnessFeature,
    /// Walls: per side (same order as `access_directions`), whether the
    /// tool reaches it in the set-up, and why.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub access: Option<[SideAccess; 2]>,
}

/// The settings a report was made with.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct SettingsUsed {
    pub recognition: thinwall_recognize::Config,
    pub connections: thinwall_connect::Options,
    /// The machining layer's request (set-up judging, stock).
    #[serde(default)]
    pub machining: thinwall_pipeline::MachiningRequest,
}

/// The whole recognition report.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct RecognitionReport {
    pub schema: String,
    /// The Thinwall version that wrote it.
    pub thinwall_version: String,
    pub part: PartSummary,
    /// The bodies (solids and placed instances) that `body` fields index.
    pub bodies: Vec<BodySummary>,
    pub setup: Setup,
    /// The settings in force (include/exclude only hide rows).
    pub settings: SettingsUsed,
    pub faces: Vec<FaceSummary>,
    pub stiffness_features: Vec<FeatureEntry>,
    pub connections: Vec<Connection>,
    /// Decisions of the connection layer worth knowing.
    pub notes: Vec<String>,
    /// Conventional machining features (holes, pockets, slots, steps,
    /// passages, chamfers, fillets), `docs/MACHINING.md`.
    pub machining_features: Vec<thinwall_machining::MachiningFeature>,
    /// Equal holes on a line or a circle.
    pub hole_patterns: Vec<thinwall_machining::HolePattern>,
    /// What the reader dropped or repaired and what the analysis found
    /// questionable, in full.
    pub warnings: Vec<Warning>,
    /// The part's faces in OpenCascade's order (`TopExp::MapShapes` over
    /// the shape it reads from the same file): entry `i` names the face a
    /// host built on OpenCascade numbers `i`, `null` for one of a
    /// supplemental surface model. Absent for a part not read from STEP.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub opencascade_faces: Vec<Option<thinwall_brep::FaceKey>>,
}

/// The reader's drops and repairs as warnings.
pub fn read_warnings(read: &thinwall_step::ReadReport) -> Vec<Warning> {
    read.dropped
        .iter()
        .map(|d| (d, "dropped"))
        .chain(read.repaired.iter().map(|r| (r, "repaired")))
        .map(|(issue, what)| Warning {
            source: WarningSource::Read,
            entity: issue.entity,
            message: match issue.entity {
                Some(id) => format!("#{id} {what}: {}", issue.message),
                None => format!("{what}: {}", issue.message),
            },
        })
        .collect()
}

/// Build the report of a pipeline run on `part` (read from `file`). The
/// run's include/exclude settings hide rows here: features of hidden kinds,
/// connections touching them, and links to them; ids and connections among
/// the features shown are those of the whole recognition.
pub fn recognition_report(file: &str, part: &Part, out: &Outcome) -> RecognitionReport {
    let config = &out.request.config;
    let shown = |id: &FeatureId| config.reports(id.kind);
    let faces = part
        .face_ids()
        .map(|f| {
            let face = part.face(f);
            FaceSummary {
                step_id: face.step_id,
                body: face.body.0,
                name: face.name.clone(),
                surface: face.surface.kind_name().to_string(),
                area: out.face_props[f.index()].area,
                occ_index: part.occ_ordinal(f),
            }
        })
        .collect();
    let connections = out
        .structure
        .connections
        .iter()
        .filter(|c| match c {
            Connection::BaseLeaf { base, leaf } => shown(base) && shown(leaf),
            Connection::Crossing { features } => features.iter().all(shown),
        })
        .cloned()
        .collect();
    let mut machining_features = out.machining.clone();
    for m in &mut machining_features {
        m.related.retain(shown);
    }
    RecognitionReport {
        schema: RECOGNITION_SCHEMA.to_string(),
        thinwall_version: env!("CARGO_PKG_VERSION").to_string(),
        part: PartSummary {
            file: file.to_string(),
            units: part.units.clone(),
            bodies: part.bodies.len(),
            faces: part.faces.len(),
            bounding_box: part.bounding_box(),
        },
        bodies: part
            .bodies
            .iter()
            .enumerate()
            .map(|(i, b)| BodySummary {
                index: i as u32,
                step_id: b.step_id,
                name: b.name.clone(),
                placement: b.placement.clone(),
            })
            .collect(),
        setup: out.setup.clone(),
        settings: SettingsUsed {
            recognition: config.clone(),
            connections: out.request.connect.clone(),
            machining: out.request.machining.clone(),
        },
        faces,
        stiffness_features: out
            .recognition
            .features
            .iter()
            .filter(|f| shown(&f.id))
            .map(|f| FeatureEntry {
                feature: f.clone(),
                access: out.structure.access.get(&f.id).cloned(),
            })
            .collect(),
        connections,
        notes: out
            .structure
            .notes
            .iter()
            .chain(&out.view_notes)
            .cloned()
            .collect(),
        machining_features,
        hole_patterns: out.hole_patterns.clone(),
        warnings: out.warnings.clone(),
        opencascade_faces: part.occ_faces(),
    }
}

impl RecognitionReport {
    /// The report with the reader's warnings first.
    pub fn with_read(mut self, read: &thinwall_step::ReadReport) -> Self {
        let mut w = read_warnings(read);
        w.append(&mut self.warnings);
        self.warnings = w;
        self
    }
}

/// What the walls table's columns mean.
pub const WALLS_LEGEND: &str = "  (t: thickness, a drafted wall's thinnest; h: a rib's, flange's or wall's height above its base; \
span: a web's largest unsupported radius, the inscribed circle of its face, which it is sized on; \
L: length; defl.: deflection under the cutting force; h/t: h or span over t; sides are numbered 1 and 2)";

/// The walls table, thin ones first.
fn walls_text(s: &mut String, walls: &[&StiffnessFeature]) {
    let thin = walls.iter().filter(|f| f.thin == Some(true)).count();
    let _ = writeln!(s, "walls: {} ({} thin)", walls.len(), thin);
    let _ = writeln!(
        s,
        "  {:<6}{:<8}{:<6}{:>10}{:>10}{:>10}{:>10}{:>12}{:>8}{:>7}  on",
        "id", "kind", "thin", "t mm", "h mm", "span mm", "L mm", "defl. mm", "h/t", "faces"
    );
    let mut sorted = walls.to_vec();
    sorted.sort_by_key(|f| (f.thin != Some(true), f.kind, f.id.to_string()));
    for f in sorted {
        // A web's figure across its face is its span, not a height.
        let web = f.kind == thinwall_analysis::StiffnessKind::Web;
        let (h, span) = if web {
            (String::new(), mm(f.height))
        } else {
            (mm(f.height), String::new())
        };
        let _ = writeln!(
            s,
            "  {:<6}{:<8}{:<6}{:>10}{:>10}{:>10}{:>10}{:>12}{:>8}{:>7}  {}",
            f.id,
            f.kind.name(),
            if f.thin == Some(true) { "yes" } else { "no" },
            mm(f.thickness),
            h,
            span,
            mm(f.length),
            f.deflection.map(|d| format!("{d:.4}")).unwrap_or_default(),
            f.slenderness.map(|d| format!("{d:.1}")).unwrap_or_default(),
            f.faces.len(),
            f.base.map(|b| b.to_string()).unwrap_or_default()
                + if f.other_side.is_some() {
                    " (through)"
                } else {
                    ""
                }
                + &curved_note(f)
        );
    }
    let _ = writeln!(s, "{WALLS_LEGEND}");
}

/// Walls through their base: their figures on its other side.
fn other_sides_text(s: &mut String, walls: &[&StiffnessFeature]) {
    for f in walls {
        let (Some(o), Some(base)) = (&f.other_side, f.base) else {
            continue;
        };
        let _ = writeln!(
            s,
            "  {}: runs through {base} to both of its sides; on the other: h {} mm, defl. {:.4} mm, h/t {:.1}, {}",
            f.id,
            mm(Some(o.height)),
            o.deflection,
            o.slenderness,
            if o.thin { "thin" } else { "not thin" }
        );
    }
}

/// A curved wall's mid-surface after its base: `  (cylinder r 479.20)`.
fn curved_note(f: &StiffnessFeature) -> String {
    f.mid_surface
        .as_ref()
        .map_or_else(String::new, |m| match m.radius {
            Some(r) => format!("  ({} r {r:.2})", m.kind),
            None => format!("  ({})", m.kind),
        })
}

/// Depressions and details, each with its size and the wall it is in or on.
fn others_text(s: &mut String, others: &[&StiffnessFeature]) {
    let _ = writeln!(s, "in and on walls: {}", others.len());
    for f in others {
        let flag = |on: Option<bool>, word: &'static str| if on == Some(true) { word } else { "" };
        let size = match f.kind {
            StiffnessKind::Hole => format!(
                "Ø{} h {}{}{}",
                mm(f.diameter),
                mm(f.height),
                flag(f.large, " large"),
                flag(f.through.map(|t| !t), " blind")
            ),
            StiffnessKind::Fillet => format!("r {}{}", mm(f.radius), flag(f.convex, " (round)")),
            _ => format!("depth {} width {}", mm(f.height), mm(f.width)),
        };
        let _ = writeln!(
            s,
            "  {:<6}{:<10}{:<28}{:>3} faces  in {}",
            f.id,
            f.kind.name(),
            size,
            f.faces.len(),
            match f.walls.split_first() {
                // A pocket's blends: in its web, on its walls.
                Some((web, on)) => format!(
                    "{web}, on {}",
                    on.iter()
                        .map(|w| w.to_string())
                        .collect::<Vec<_>>()
                        .join(" ")
                ),
                None => f.wall.map_or_else(|| "-".into(), |w| w.to_string()),
            }
        );
    }
}

/// The machining features, a line each.
fn machining_text(s: &mut String, features: &[thinwall_machining::MachiningFeature]) {
    if features.is_empty() {
        return;
    }
    let _ = writeln!(s, "machining features: {}", features.len());
    for m in features {
        let _ = writeln!(
            s,
            "  {:<5}{:<8}{:<13}{:<9} depth {:>8.2}  {:>8.2} x {:<8.2} {:>3} faces{}{}{}{}{}",
            m.id,
            m.kind,
            m.profile,
            if m.through { "through" } else { "" },
            m.depth,
            m.length,
            m.width,
            m.faces.len(),
            match m.island_faces.len() {
                0 => String::new(),
                n => format!(" ({n} on islands)"),
            },
            blends_text(m),
            m.largest_tool_diameter
                .map(|d| format!("  tool <= {d:.2}"))
                .unwrap_or_default(),
            m.catalog.map(|c| format!("  [{c}]")).unwrap_or_default(),
            match m.reachable {
                Some(false) => "  not reachable from up",
                _ => "",
            }
        );
    }
}

/// A hole's stages from the entry down:
/// `  csk 90° Ø19.17 > Ø11.64 x 7.58 > point 118°`.
fn hole_text(h: &thinwall_machining::HoleForm) -> String {
    use thinwall_machining::{HoleEnd, HoleTip};
    let end = |e: &HoleEnd| match e {
        HoleEnd::Countersink {
            angle_deg,
            diameter,
        } => format!("csk {angle_deg:.0}° Ø{diameter:.2}"),
        HoleEnd::Chamfer {
            angle_deg,
            diameter,
        } => format!("chamfer {angle_deg:.0}° Ø{diameter:.2}"),
        HoleEnd::Blend { radius } => format!("blend r {radius:.2}"),
    };
    let mut stages: Vec<String> = h.entry.iter().map(end).collect();
    stages.extend(
        h.bores
            .iter()
            .map(|b| format!("Ø{:.2} x {:.2}", b.diameter, b.depth)),
    );
    stages.extend(h.exit.iter().map(end));
    match h.tip {
        HoleTip::Through => {}
        HoleTip::Flat => stages.push("flat".into()),
        HoleTip::DrillPoint { angle_deg } => stages.push(format!("point {angle_deg:.0}°")),
    }
    format!("  {}", stages.join(" > "))
}

/// A depression's corner radius, floor fillet and wall draft, or a hole's
/// stages, where it has them: `  R 8.00 / r 3.00  draft 2.0°`.
fn blends_text(m: &thinwall_machining::MachiningFeature) -> String {
    if let Some(h) = &m.hole {
        return hole_text(h);
    }
    let mut t = String::new();
    match (m.corner_radius, m.floor_fillet) {
        (Some(c), Some(f)) => t += &format!("  R {c:.2} / r {f:.2}"),
        (Some(c), None) => t += &format!("  R {c:.2}"),
        (None, Some(f)) => t += &format!("  r {f:.2}"),
        (None, None) => {}
    }
    if let Some(d) = m.wall_draft_deg.filter(|d| *d >= 0.05) {
        t += &format!("  draft {d:.1}°");
    }
    t
}

/// The hole patterns, a line each.
fn patterns_text(s: &mut String, patterns: &[thinwall_machining::HolePattern]) {
    if patterns.is_empty() {
        return;
    }
    let _ = writeln!(s, "hole patterns: {}", patterns.len());
    for p in patterns {
        let layout = match &p.layout {
            thinwall_machining::Layout::Linear { pitch, .. } => {
                format!("in a row, pitch {pitch:.2}")
            }
            thinwall_machining::Layout::Circular {
                radius, step_deg, ..
            } => {
                format!("on a circle R{radius:.2}, every {step_deg:.1} deg")
            }
        };
        let holes: Vec<String> = p.holes.iter().map(|h| h.to_string()).collect();
        let _ = writeln!(
            s,
            "  {:<5}{} x dia {:.2} {}: {}",
            p.id,
            p.holes.len(),
            p.diameter,
            layout,
            holes.join(" ")
        );
    }
}

fn mm(v: Option<f64>) -> String {
    v.map(|x| format!("{x:.2}")).unwrap_or_else(|| "-".into())
}

impl RecognitionReport {
    /// A table a process planner can scan: walls first (thin ones on top),
    /// then what is in and on them, the structure, the warnings and the
    /// machining features.
    pub fn to_text(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(
            s,
            "{}: {} faces, up ({:.3}, {:.3}, {:.3})",
            self.part.file, self.part.faces, self.setup.up[0], self.setup.up[1], self.setup.up[2]
        );
        let feats: Vec<&StiffnessFeature> =
            self.stiffness_features.iter().map(|e| &e.feature).collect();
        let (walls, others): (Vec<&StiffnessFeature>, Vec<&StiffnessFeature>) =
            feats.iter().copied().partition(|f| f.kind.is_wall());
        walls_text(&mut s, &walls);
        other_sides_text(&mut s, &walls);
        others_text(&mut s, &others);
        for f in walls.iter().filter(|f| f.model_note.is_some()) {
            let _ = writeln!(
                s,
                "  {}: {}",
                f.id,
                f.model_note.as_deref().unwrap_or_default()
            );
        }
        s.push_str(&self.structure_text());
        if !self.warnings.is_empty() {
            let _ = writeln!(s, "warnings: {}", self.warnings.len());
            for w in &self.warnings {
                let _ = writeln!(s, "  {}", w.message);
            }
        }
        machining_text(&mut s, &self.machining_features);
        patterns_text(&mut s, &self.hole_patterns);
        s
    }

    /// The connection structure as a tree from the root bases, crossings
    /// under it, then the wall sides the tool cannot reach in the set-up.
    pub fn structure_text(&self) -> String {
        use std::collections::{BTreeMap, BTreeSet};
        let mut s = String::new();
        if self.connections.is_empty() {
            return s;
        }
        // Ids as written, so the tree is ordered as the ids read.
        let mut children: BTreeMap<String, Vec<String>> = BTreeMap::new();
        let mut has_base = BTreeSet::new();
        let mut crossings = Vec::new();
        for c in &self.connections {
            match c {
                Connection::BaseLeaf { base, leaf } => {
                    children
                        .entry(base.to_string())
                        .or_default()
                        .push(leaf.to_string());
                    has_base.insert(leaf.to_string());
                }
                Connection::Crossing { features } => crossings.push(features),
            }
        }
        let kinds: BTreeMap<String, &'static str> = self
            .stiffness_features
            .iter()
            .map(|e| (e.feature.id.to_string(), e.feature.kind.name()))
            .collect();
        fn walk(
            s: &mut String,
            id: &str,
            depth: usize,
            children: &BTreeMap<String, Vec<String>>,
            kinds: &BTreeMap<String, &'static str>,
        ) {
            let _ = writeln!(
                s,
                "  {}{} {}",
                "  ".repeat(depth),
                id,
                kinds.get(id).copied().unwrap_or("?")
            );
            if depth > 64 {
                return;
            }
            for c in children.get(id).into_iter().flatten() {
                walk(s, c, depth + 1, children, kinds);
            }
        }
        let _ = writeln!(s, "structure:");
        for root in children.keys().filter(|r| !has_base.contains(*r)) {
            walk(&mut s, root, 0, &children, &kinds);
        }
        if !crossings.is_empty() {
            let _ = writeln!(s, "crossings:");
            for [a, b] in crossings {
                let _ = writeln!(s, "  {a} x {b}");
            }
        }
        let mut blocked = Vec::new();
        for e in &self.stiffness_features {
            for (i, a) in e.access.iter().flatten().enumerate() {
                if !a.reachable {
                    blocked.push(format!("  {} side {}: {}", e.feature.id, i + 1, a.reason));
                }
            }
        }
        if !blocked.is_empty() {
            let _ = writeln!(s, "not reachable in this set-up:");
            for b in blocked {
                let _ = writeln!(s, "{b}");
            }
        }
        for n in &self.notes {
            let _ = writeln!(s, "note: {n}");
        }
        s
    }
}

impl RecognitionReport {
    /// The report as `thinwall recognize --format json` prints it.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
            + "\n"
    }
}
