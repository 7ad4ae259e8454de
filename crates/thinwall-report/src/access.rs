//! `thinwall access`: the accessibility report (`thinwall/access/1`): the
//! reach of every face and wall side with material in the way (a tool and
//! its holder along up, or within a five-axis tilt), and the flank-milling
//! G-zones of planar faces (Harik & Ris). What it does not cover yet is in
//! `not_yet`.

use serde::Serialize;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use thinwall_access::reach::features::{feature_tools, FeatureTool};
use thinwall_access::reach::walls::{wall_sides, SideReach};
use thinwall_access::reach::{FaceReach, Tool};
use thinwall_access::{FlankOptions, Nature, PlanarFaceAccess};
use thinwall_analysis::{FeatureId, Machine, PartAnalysis};

/// What reach was judged with.
#[derive(Clone, Debug, Serialize)]
pub struct ReachSettings {
    pub tool: Tool,
    pub machine: Machine,
}

/// Reach of the part's faces, with what follows from it for its walls and
/// machining features.
#[derive(Clone, Debug, Default)]
pub struct ReachResult {
    pub faces: Vec<FaceReach>,
    pub wall_sides: BTreeMap<FeatureId, [SideReach; 2]>,
    pub features: Vec<FeatureTool>,
}

impl ReachResult {
    /// From every face's reach (`faces`, the largest-tool search on) and
    /// the pipeline's recognition and machining features of the same part.
    pub fn new(
        a: &PartAnalysis,
        faces: Vec<FaceReach>,
        outcome: &thinwall_pipeline::Outcome,
        tool_diameter: f64,
    ) -> Self {
        Self {
            wall_sides: wall_sides(a, &outcome.recognition, &faces, tool_diameter),
            features: feature_tools(a, &outcome.machining, &faces),
            faces,
        }
    }
}

/// Version tag of the JSON layout.
pub const ACCESS_SCHEMA: &str = "thinwall/access/1";

/// The whole accessibility report.
#[derive(Clone, Debug, Serialize)]
pub struct AccessReport {
    pub schema: String,
    pub thinwall_version: String,
    pub part: String,
    pub up: [f64; 3],
    pub flank_milling: FlankOptions,
    /// Every planar face's flank-milling verdict, in part order.
    pub planar_faces: Vec<PlanarFaceAccess>,
    pub reach: ReachSettings,
    /// Every face's reach, in part order.
    pub faces: Vec<FaceReach>,
    /// Each wall's two sides (by feature id of the recognition report).
    pub wall_sides: BTreeMap<FeatureId, [SideReach; 2]>,
    /// Each machining feature's largest tool along up (by id of the
    /// recognition report's machining features).
    pub features: Vec<FeatureTool>,
    /// What this report does not cover yet.
    pub not_yet: Vec<String>,
    /// The part's faces in OpenCascade's order (`TopExp::MapShapes` over
    /// the shape it reads from the same file): entry `i` names the face a
    /// host built on OpenCascade numbers `i`, `null` for one of a
    /// supplemental surface model. Absent for a part not read from STEP.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub opencascade_faces: Vec<Option<thinwall_brep::FaceKey>>,
}

impl AccessReport {
    pub fn new(
        part: &str,
        up: [f64; 3],
        options: FlankOptions,
        planar_faces: Vec<PlanarFaceAccess>,
        settings: ReachSettings,
        reach: ReachResult,
    ) -> Self {
        Self {
            schema: ACCESS_SCHEMA.to_string(),
            thinwall_version: env!("CARGO_PKG_VERSION").to_string(),
            part: part.to_string(),
            up,
            flank_milling: options,
            planar_faces,
            reach: settings,
            faces: reach.faces,
            wall_sides: reach.wall_sides,
            features: reach.features,
            not_yet: vec![
                "five axes: up and 24 tilted axes are tried, not every axis within the limit"
                    .into(),
            ],
            opencascade_faces: Vec::new(),
        }
    }

    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
            + "\n"
    }

    /// A line per planar face: nature, visibility, verdict, directions used.
    pub fn to_text(&self) -> String {
        let mut s = String::new();
        let advisable = self.planar_faces.iter().filter(|f| f.advisable).count();
        let _ = writeln!(
            s,
            "{}: {} planar face(s), {} advisable for flank milling (Ø{} mm tool, threshold {:.0} %)",
            self.part,
            self.planar_faces.len(),
            advisable,
            self.flank_milling.tool_diameter,
            100.0 * self.flank_milling.threshold
        );
        for f in &self.planar_faces {
            let nature = match f.nature {
                Nature::Closed => "closed",
                Nature::Open => "open",
                Nature::SemiOpen => "semi-open",
            };
            let _ = write!(
                s,
                "  #{:<6} {:<9} {:>10.2} mm²  visible {:>6.2} %  {}",
                f.face,
                nature,
                f.area_mm2,
                100.0 * f.visibility,
                if f.advisable {
                    "advisable"
                } else {
                    "not advisable"
                }
            );
            let dirs: Vec<String> = f
                .used
                .iter()
                .map(|u| {
                    format!(
                        "({:.3}, {:.3}, {:.3})",
                        u.direction[0], u.direction[1], u.direction[2]
                    )
                })
                .collect();
            if !dirs.is_empty() {
                let _ = write!(s, "  along {}", dirs.join(" "));
            }
            if let Some(n) = &f.note {
                let _ = write!(s, "  ({n})");
            }
            s.push('\n');
        }
        let t = &self.reach.tool;
        let partly: Vec<&FaceReach> = self.faces.iter().filter(|f| !f.whole()).collect();
        let _ = writeln!(
            s,
            "reach (Ø{} mm, cutting {} mm, holder Ø{} mm): {} of {} face(s) not reached whole",
            t.diameter,
            t.cutting_length,
            t.holder_diameter,
            partly.len(),
            self.faces.len()
        );
        for f in partly {
            let _ = write!(
                s,
                "  #{:<6} {:<6} {:>10.2} mm²  reached {:>6.2} %",
                f.face,
                format!("{:?}", f.contact).to_lowercase(),
                f.area_mm2,
                100.0 * f.fraction
            );
            if let Some(b) = f.blocked_by.first() {
                let _ = write!(s, "  blocked by #{} ({:?})", b.face, b.by);
            }
            if let Some(n) = &f.note {
                let _ = write!(s, "  ({n})");
            }
            s.push('\n');
        }
        feature_lines(&mut s, &self.features);
        for (id, sides) in &self.wall_sides {
            for (k, side) in sides.iter().enumerate() {
                if let Some(r) = &side.reason {
                    let _ = writeln!(s, "  {id} side {}: {r}", k + 1);
                }
            }
        }
        let _ = writeln!(s, "not yet: {}", self.not_yet.join("; "));
        s
    }
}

/// What bounds a feature's largest tool, in words.
fn bound_name(b: thinwall_machining::ToolBound) -> &'static str {
    match b {
        thinwall_machining::ToolBound::CornerRadius => "corner radius",
        thinwall_machining::ToolBound::Width => "floor's width",
        thinwall_machining::ToolBound::Bore => "bore",
    }
}

/// One line per machining feature: its largest tool and what bounds it.
fn feature_lines(s: &mut String, features: &[FeatureTool]) {
    let mm = |d: Option<f64>| d.map_or("none".to_string(), |d| format!("Ø{d:.2}"));
    for m in features {
        let by = match (m.bound, m.bounded_by) {
            (Some(b), _) => format!("its {}", bound_name(b)),
            (None, Some(f)) => format!("#{f}"),
            (None, None) => "-".to_string(),
        };
        let largest = match m.largest_tool_mm {
            Some(d) => format!("largest tool Ø{d:.2} mm (bounded by {by})"),
            None => format!("no tool reaches it whole from up (face {by})"),
        };
        let _ = writeln!(
            s,
            "  {:<5} {:<9} {largest}, floors {}, fits {}",
            m.feature.to_string(),
            format!("{:?}", m.kind).to_lowercase(),
            mm(m.floors_mm),
            mm(m.fits_mm),
        );
    }
}
