//! `thinwall access`: the accessibility report (`thinwall/access/1`): the
//! reach of every face and wall side with material in the way (a tool and
//! its holder along up, or within a five-axis tilt), and the flank-milling
//! G-zones of planar faces (Harik & Ris). What it does not cover yet is in
//! `not_yet`.

use serde::Serialize;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use thinwall_access::reach::walls::SideReach;
use thinwall_access::reach::{FaceReach, Tool};
use thinwall_access::{FlankOptions, Nature, PlanarFaceAccess};
use thinwall_analysis::{FeatureId, Machine};

/// What reach was judged with.
#[derive(Clone, Debug, Serialize)]
pub struct ReachSettings {
    pub tool: Tool,
    pub machine: Machine,
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
    /// What this report does not cover yet.
    pub not_yet: Vec<String>,
}

impl AccessReport {
    pub fn new(
        part: &str,
        up: [f64; 3],
        options: FlankOptions,
        planar_faces: Vec<PlanarFaceAccess>,
        reach: (
            ReachSettings,
            Vec<FaceReach>,
            BTreeMap<FeatureId, [SideReach; 2]>,
        ),
    ) -> Self {
        let (settings, faces, wall_sides) = reach;
        Self {
            schema: ACCESS_SCHEMA.to_string(),
            thinwall_version: env!("CARGO_PKG_VERSION").to_string(),
            part: part.to_string(),
            up,
            flank_milling: options,
            planar_faces,
            reach: settings,
            faces,
            wall_sides,
            not_yet: vec![
                "the largest tool is searched for floors only".into(),
                "five axes: up and 24 tilted axes are tried, not every axis within the limit"
                    .into(),
            ],
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
        for f in self.faces.iter().filter(|f| f.largest_tool_mm.is_some()) {
            let _ = writeln!(
                s,
                "  #{:<6} floor: largest tool reaching it whole Ø{:.2} mm",
                f.face,
                f.largest_tool_mm.unwrap_or(0.0)
            );
        }
        for (id, sides) in &self.wall_sides {
            for (k, side) in sides.iter().enumerate() {
                if let Some(r) = &side.reason {
                    let _ = writeln!(s, "  {id} side {k}: {r}");
                }
            }
        }
        let _ = writeln!(s, "not yet: {}", self.not_yet.join("; "));
        s
    }
}
