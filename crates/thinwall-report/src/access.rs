//! `thinwall access`: the accessibility report (`thinwall/access/1`). So
//! far the flank-milling G-zones of planar faces (issue 16's part 2); the
//! obstruction-aware reach of faces and wall sides is not built yet, and
//! the report says so in `not_yet`.

use serde::Serialize;
use std::fmt::Write as _;
use thinwall_access::{FlankOptions, Nature, PlanarFaceAccess};

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
    /// What this report does not cover yet.
    pub not_yet: Vec<String>,
}

impl AccessReport {
    pub fn new(
        part: &str,
        up: [f64; 3],
        options: FlankOptions,
        planar_faces: Vec<PlanarFaceAccess>,
    ) -> Self {
        Self {
            schema: ACCESS_SCHEMA.to_string(),
            thinwall_version: env!("CARGO_PKG_VERSION").to_string(),
            part: part.to_string(),
            up,
            flank_milling: options,
            planar_faces,
            not_yet: vec![
                "reach of faces and wall sides with obstruction (tool body and holder) along up or a 5-axis cone".into(),
                "the largest tool reaching a face or pocket floor whole".into(),
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
        let _ = writeln!(s, "not yet: {}", self.not_yet.join("; "));
        s
    }
}
