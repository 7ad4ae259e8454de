//! The tool library: a TOML file a shop edits (`tools/default.toml` is
//! shipped), every entry checked, errors with the file and line.

use serde::{Deserialize, Serialize};
use thiserror::Error;

/// The shipped library.
pub const DEFAULT_TOOLS: &str = include_str!("../tools/default.toml");

/// What a tool is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ToolKind {
    /// Roughs, semi-finishes and finishes the layers (its corner radius a
    /// small protective one).
    FlatEndMill,
    /// An end mill whose corner radius forms a floor fillet: it finishes
    /// pockets by their radii only (never in the roughing cascade).
    BullNoseEndMill,
    Drill,
    /// A short stiff drill that spots a hole's centre before the drill
    /// (its point angle: 90° leaves a chamfer-ready spot).
    SpotDrill,
    /// A cone cutter for countersinks, and at 90° for a hole's chamfered
    /// edge (its point angle is the cone's included angle; its diameter
    /// the widest it cuts).
    Countersink,
}

impl ToolKind {
    /// Cuts with its side and a flat or rounded bottom (end mills), as
    /// opposed to a point.
    pub fn is_end_mill(self) -> bool {
        matches!(self, ToolKind::FlatEndMill | ToolKind::BullNoseEndMill)
    }

    /// Its order in the library: end mills, bull-noses, drills, spot
    /// drills, countersinks.
    fn rank(self) -> u8 {
        match self {
            ToolKind::FlatEndMill => 0,
            ToolKind::BullNoseEndMill => 1,
            ToolKind::Drill => 2,
            ToolKind::SpotDrill => 3,
            ToolKind::Countersink => 4,
        }
    }
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawTool {
    name: String,
    kind: ToolKind,
    diameter: f64,
    corner_radius: Option<f64>,
    cutting_length: f64,
    stick_out: f64,
    teeth: u32,
    cutting_speed_m_min: f64,
    feed_per_tooth_mm: f64,
    axial_depth_mm: Option<f64>,
    radial_depth_mm: Option<f64>,
    finish_radial_depth_mm: Option<f64>,
    finish_axial_depth_mm: Option<f64>,
    full_cut_axial_depth_mm: Option<f64>,
    point_angle_deg: Option<f64>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFile {
    min_share_mm2: Option<f64>,
    tool: Vec<toml::Spanned<RawTool>>,
}

/// The least area (mm²) a tool must take in a cutter field of a layer to
/// run there, unless the library says otherwise (`min_share_mm2`): what
/// a smaller share would take goes to the next smaller tool, or is left
/// as rest below the minimum.
pub const DEFAULT_MIN_SHARE_MM2: f64 = 20.0;

/// A checked tool. Lengths in mm.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CuttingTool {
    pub name: String,
    pub kind: ToolKind,
    pub diameter_mm: f64,
    pub corner_radius_mm: f64,
    pub cutting_length_mm: f64,
    pub stick_out_mm: f64,
    pub teeth: u32,
    pub cutting_speed_m_min: f64,
    pub feed_per_tooth_mm: f64,
    /// Roughing depth of cut a_p (end mills; drills: their cutting length).
    pub axial_depth_mm: f64,
    /// Roughing stepover a_e (end mills; drills: their diameter).
    pub radial_depth_mm: f64,
    /// Stepover of the pass along the product (Popma's boundary region:
    /// down milling, reduced stepover), mm; default 10 % of the diameter,
    /// at most a_e.
    pub finish_radial_depth_mm: f64,
    /// What a floor's separate finishing layer takes (Popma's bottom
    /// layer), mm; default 0.5, at most a_p.
    pub finish_axial_depth_mm: f64,
    /// Depth of cut where the tool cuts its full width (Popma's full-cut
    /// region), mm; default a_p / 2.
    pub full_cut_axial_depth_mm: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub point_angle_deg: Option<f64>,
    /// Line of the entry in its file.
    pub line: usize,
}

impl CuttingTool {
    /// Spindle speed n = 1000 · v_c / (π · d), rev/min.
    pub fn spindle_rpm(&self) -> f64 {
        1000.0 * self.cutting_speed_m_min / (std::f64::consts::PI * self.diameter_mm)
    }

    /// Feed rate v_f = f_z · z · n, mm/min.
    pub fn feed_mm_min(&self) -> f64 {
        self.feed_per_tooth_mm * self.teeth as f64 * self.spindle_rpm()
    }

    /// Material removal rate Q = a_p · a_e · f_z · z · n, mm³/min.
    pub fn removal_rate_mm3_min(&self) -> f64 {
        self.axial_depth_mm * self.radial_depth_mm * self.feed_mm_min()
    }

    /// Q along the product: a_p · a_e,finish · v_f, mm³/min.
    pub fn boundary_rate_mm3_min(&self) -> f64 {
        self.axial_depth_mm * self.finish_radial_depth_mm * self.feed_mm_min()
    }

    /// Q in a full cut: a_p,full · d · v_f, mm³/min.
    pub fn full_cut_rate_mm3_min(&self) -> f64 {
        self.full_cut_axial_depth_mm * self.diameter_mm * self.feed_mm_min()
    }

    /// Q of a floor's finishing layer: a_p,finish · a_e,finish · v_f,
    /// mm³/min.
    pub fn floor_rate_mm3_min(&self) -> f64 {
        self.finish_axial_depth_mm * self.finish_radial_depth_mm * self.feed_mm_min()
    }
}

/// The tools in force: end mills largest first, then drills smallest first.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ToolLibrary {
    /// Where they came from (a path, or `default`).
    pub source: String,
    /// The least area a tool must take in a cutter field of a layer to
    /// run there, mm² ([`DEFAULT_MIN_SHARE_MM2`] unless the file sets
    /// `min_share_mm2`).
    pub min_share_mm2: f64,
    pub tools: Vec<CuttingTool>,
}

/// A tool file that cannot be used.
#[derive(Debug, Error, PartialEq)]
pub enum ToolsError {
    /// Not TOML, or a key the file may not have (the message names the
    /// line and column).
    #[error("{file}: {message}")]
    Toml { file: String, message: String },
    #[error("{file}:{line}: tool '{tool}': {message}")]
    Invalid {
        file: String,
        tool: String,
        line: usize,
        message: String,
    },
}

impl ToolsError {
    /// A stable machine-readable code for the error kind.
    pub fn code(&self) -> &'static str {
        match self {
            ToolsError::Toml { .. } => "tools.toml",
            ToolsError::Invalid { .. } => "tools.invalid",
        }
    }
}

impl ToolLibrary {
    /// The shipped library.
    pub fn default_tools() -> Self {
        Self::from_toml(DEFAULT_TOOLS, "default").expect("the shipped tools are valid")
    }

    /// Parse and check a tool file (`file` names it in errors).
    pub fn from_toml(text: &str, file: &str) -> Result<Self, ToolsError> {
        let raw: RawFile = toml::from_str(text).map_err(|e| ToolsError::Toml {
            file: file.to_string(),
            message: e.to_string().trim_end().to_string(),
        })?;
        let min_share_mm2 = raw.min_share_mm2.unwrap_or(DEFAULT_MIN_SHARE_MM2);
        if !(min_share_mm2.is_finite() && min_share_mm2 >= 0.0) {
            return Err(ToolsError::Toml {
                file: file.to_string(),
                message: format!("`min_share_mm2` must be 0 or more, got {min_share_mm2}"),
            });
        }
        let mut tools: Vec<CuttingTool> = Vec::new();
        for spanned in raw.tool {
            let line = 1 + text[..spanned.span().start.min(text.len())]
                .matches('\n')
                .count();
            let raw = spanned.into_inner();
            let name = raw.name.clone();
            let invalid = |message: String| ToolsError::Invalid {
                file: file.to_string(),
                tool: name.clone(),
                line,
                message,
            };
            let tool = check(raw, line).map_err(&invalid)?;
            if let Some(other) = tools.iter().find(|t| t.name == tool.name) {
                return Err(invalid(format!(
                    "a second tool of this name (line {})",
                    other.line
                )));
            }
            tools.push(tool);
        }
        if tools.is_empty() {
            return Err(ToolsError::Toml {
                file: file.to_string(),
                message: "no [[tool]] in the file".to_string(),
            });
        }
        // End mills largest first, pointed tools smallest first.
        tools.sort_by(|a, b| {
            let key = |t: &CuttingTool| {
                let d = if t.kind.is_end_mill() {
                    -t.diameter_mm
                } else {
                    t.diameter_mm
                };
                (t.kind.rank(), d)
            };
            let (ka, kb) = (key(a), key(b));
            ka.0.cmp(&kb.0).then(ka.1.total_cmp(&kb.1))
        });
        Ok(Self {
            source: file.to_string(),
            min_share_mm2,
            tools,
        })
    }

    /// The end mills, largest first.
    pub fn end_mills(&self) -> impl Iterator<Item = &CuttingTool> {
        self.tools
            .iter()
            .filter(|t| t.kind == ToolKind::FlatEndMill)
    }

    /// The end mills that finish by the part's radii: flat ones and
    /// bull-noses, largest first.
    pub fn finishing_mills(&self) -> Vec<&CuttingTool> {
        let mut v: Vec<&CuttingTool> = self.tools.iter().filter(|t| t.kind.is_end_mill()).collect();
        v.sort_by(|a, b| b.diameter_mm.total_cmp(&a.diameter_mm));
        v
    }

    /// The drills, smallest first.
    pub fn drills(&self) -> impl Iterator<Item = &CuttingTool> {
        self.of_kind(ToolKind::Drill)
    }

    /// The tools of one kind, in the library's order.
    pub fn of_kind(&self, kind: ToolKind) -> impl Iterator<Item = &CuttingTool> {
        self.tools.iter().filter(move |t| t.kind == kind)
    }
}

/// Check one entry; the error says what is wrong.
fn check(raw: RawTool, line: usize) -> Result<CuttingTool, String> {
    if raw.name.trim().is_empty() {
        return Err("empty name".to_string());
    }
    let d = positive(raw.diameter, "diameter")?;
    let cutting = positive(raw.cutting_length, "cutting_length")?;
    let stick_out = positive(raw.stick_out, "stick_out")?;
    if stick_out < cutting {
        return Err(format!(
            "`stick_out` ({stick_out}) is shorter than `cutting_length` ({cutting})"
        ));
    }
    if raw.teeth == 0 {
        return Err("`teeth` must be at least 1".to_string());
    }
    let vc = positive(raw.cutting_speed_m_min, "cutting_speed_m_min")?;
    let fz = positive(raw.feed_per_tooth_mm, "feed_per_tooth_mm")?;
    let mill_only = |v: Option<f64>, key: &str| -> Result<(), String> {
        match (raw.kind.is_end_mill(), v) {
            (false, Some(_)) => Err(format!(
                "`{key}` is for end mills, not pointed tools (drills, spot drills, countersinks)"
            )),
            _ => Ok(()),
        }
    };
    mill_only(raw.corner_radius, "corner_radius")?;
    mill_only(raw.axial_depth_mm, "axial_depth_mm")?;
    mill_only(raw.radial_depth_mm, "radial_depth_mm")?;
    mill_only(raw.finish_radial_depth_mm, "finish_radial_depth_mm")?;
    mill_only(raw.finish_axial_depth_mm, "finish_axial_depth_mm")?;
    mill_only(raw.full_cut_axial_depth_mm, "full_cut_axial_depth_mm")?;
    let (corner, a_p, a_e) = if raw.kind.is_end_mill() {
        end_mill_cut(&raw, d, cutting)?
    } else {
        drill_cut(&raw, d, cutting)?
    };
    if raw.kind == ToolKind::BullNoseEndMill && corner <= 0.0 {
        return Err("a bull-nose end mill needs a `corner_radius` above 0".to_string());
    }
    let (finish_a_e, finish_a_p, full_a_p) = finishing(&raw, d, a_p, a_e)?;
    Ok(CuttingTool {
        name: raw.name,
        kind: raw.kind,
        diameter_mm: d,
        corner_radius_mm: corner,
        cutting_length_mm: cutting,
        stick_out_mm: stick_out,
        teeth: raw.teeth,
        cutting_speed_m_min: vc,
        feed_per_tooth_mm: fz,
        axial_depth_mm: a_p,
        radial_depth_mm: a_e,
        finish_radial_depth_mm: finish_a_e,
        finish_axial_depth_mm: finish_a_p,
        full_cut_axial_depth_mm: full_a_p,
        point_angle_deg: raw.point_angle_deg,
        line,
    })
}

/// `v` if it is a finite positive number.
fn positive(v: f64, key: &str) -> Result<f64, String> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(format!("`{key}` must be a positive number, got {v}"))
    }
}

/// An end mill's corner radius, axial and radial depth of cut, mm.
fn end_mill_cut(raw: &RawTool, d: f64, cutting: f64) -> Result<(f64, f64, f64), String> {
    if raw.point_angle_deg.is_some() {
        return Err("`point_angle_deg` is for drills, not end mills".to_string());
    }
    let corner = raw.corner_radius.unwrap_or(0.0);
    if !(corner.is_finite() && (0.0..=d / 2.0).contains(&corner)) {
        return Err(format!(
            "`corner_radius` must lie within 0..{} (half the diameter), got {corner}",
            d / 2.0
        ));
    }
    let a_p = positive(
        raw.axial_depth_mm
            .ok_or("`axial_depth_mm` is missing (an end mill needs it)")?,
        "axial_depth_mm",
    )?;
    if a_p > cutting {
        return Err(format!(
            "`axial_depth_mm` ({a_p}) exceeds `cutting_length` ({cutting})"
        ));
    }
    let a_e = positive(
        raw.radial_depth_mm
            .ok_or("`radial_depth_mm` is missing (an end mill needs it)")?,
        "radial_depth_mm",
    )?;
    if a_e > d {
        return Err(format!(
            "`radial_depth_mm` ({a_e}) exceeds the diameter ({d})"
        ));
    }
    Ok((corner, a_p, a_e))
}

/// A pointed tool's cut (drill, spot drill, countersink): no corner
/// radius, its cutting length deep, its diameter wide.
fn drill_cut(raw: &RawTool, d: f64, cutting: f64) -> Result<(f64, f64, f64), String> {
    let angle = raw
        .point_angle_deg
        .ok_or("`point_angle_deg` is missing (a pointed tool needs it)")?;
    if !(angle.is_finite() && angle > 0.0 && angle < 180.0) {
        return Err(format!(
            "`point_angle_deg` must lie strictly between 0 and 180, got {angle}"
        ));
    }
    Ok((0.0, cutting, d))
}

/// Optional finishing data, each within its roughing counterpart: the
/// finishing radial and axial depths and the full-cut axial depth, mm.
fn finishing(raw: &RawTool, d: f64, a_p: f64, a_e: f64) -> Result<(f64, f64, f64), String> {
    let within = |v: Option<f64>, key: &str, default: f64, max: f64, of: &str| {
        let v = v.unwrap_or(default.min(max));
        let v = positive(v, key)?;
        if v > max {
            return Err(format!("`{key}` ({v}) exceeds {of} ({max})"));
        }
        Ok(v)
    };
    let finish_a_e = within(
        raw.finish_radial_depth_mm,
        "finish_radial_depth_mm",
        0.1 * d,
        a_e,
        "`radial_depth_mm`",
    )?;
    let finish_a_p = within(
        raw.finish_axial_depth_mm,
        "finish_axial_depth_mm",
        0.5,
        a_p,
        "`axial_depth_mm`",
    )?;
    let full_a_p = within(
        raw.full_cut_axial_depth_mm,
        "full_cut_axial_depth_mm",
        0.5 * a_p,
        a_p,
        "`axial_depth_mm`",
    )?;
    Ok((finish_a_e, finish_a_p, full_a_p))
}

#[cfg(test)]
mod tests {
    use super::*;

    const ONE: &str = r#"
[[tool]]
name = "EM12"
kind = "flat_end_mill"
diameter = 12.0
corner_radius = 1.0
cutting_length = 36.0
stick_out = 55.0
teeth = 3
cutting_speed_m_min = 600.0
feed_per_tooth_mm = 0.1
axial_depth_mm = 6.0
radial_depth_mm = 6.0
"#;

    #[test]
    fn the_shipped_library_has_every_end_mill_the_issue_asks_for() {
        let lib = ToolLibrary::default_tools();
        let mills: Vec<f64> = lib.end_mills().map(|t| t.diameter_mm).collect();
        assert_eq!(mills, [20.0, 16.0, 12.0, 10.0, 8.0, 6.0, 4.0]);
        assert!(lib.end_mills().all(|t| t.corner_radius_mm > 0.0));
        assert!(lib.drills().count() >= 3);
    }

    /// Q = a_p · a_e · f_z · z · n with n = 1000 v_c / (π d): for Ø12,
    /// v_c 600, 3 teeth, f_z 0.1, a_p = a_e = 6: n = 15915.5 rev/min,
    /// v_f = 4774.6 mm/min, Q = 171,887 mm³/min.
    #[test]
    fn removal_rate_follows_the_cutting_data() {
        let t = &ToolLibrary::from_toml(ONE, "t.toml").unwrap().tools[0];
        let n = 600_000.0 / (std::f64::consts::PI * 12.0);
        assert!((t.spindle_rpm() - n).abs() < 1e-9 * n);
        let q = 6.0 * 6.0 * 0.1 * 3.0 * n;
        assert!((t.removal_rate_mm3_min() - q).abs() < 1e-9 * q);
    }

    #[test]
    fn a_negative_diameter_is_rejected_with_its_line() {
        let text = ONE.replace("diameter = 12.0", "diameter = -12.0");
        let e = ToolLibrary::from_toml(&text, "t.toml").unwrap_err();
        assert_eq!(e.code(), "tools.invalid");
        // The [[tool]] header is on line 2.
        assert!(
            e.to_string().starts_with("t.toml:2: tool 'EM12'")
                && e.to_string().contains("diameter"),
            "{e}"
        );
    }

    #[test]
    fn an_unknown_key_is_rejected_with_its_line() {
        let text = ONE.replace("teeth = 3", "teeth = 3\nflutes = 3");
        let e = ToolLibrary::from_toml(&text, "t.toml").unwrap_err();
        assert_eq!(e.code(), "tools.toml");
        let s = e.to_string();
        assert!(s.contains("flutes") && s.contains("line 10"), "{s}");
    }

    #[test]
    fn inconsistent_entries_are_rejected() {
        for (from, to, what) in [
            (
                "corner_radius = 1.0",
                "corner_radius = 7.0",
                "corner_radius",
            ),
            ("stick_out = 55.0", "stick_out = 30.0", "stick_out"),
            (
                "axial_depth_mm = 6.0",
                "axial_depth_mm = 40.0",
                "axial_depth_mm",
            ),
            (
                "radial_depth_mm = 6.0",
                "radial_depth_mm = 13.0",
                "radial_depth_mm",
            ),
            ("teeth = 3", "teeth = 0", "teeth"),
            (
                "radial_depth_mm = 6.0",
                "radial_depth_mm = 6.0\nfinish_radial_depth_mm = 7.0",
                "finish_radial_depth_mm",
            ),
            (
                "radial_depth_mm = 6.0",
                "radial_depth_mm = 6.0\nfull_cut_axial_depth_mm = -1.0",
                "full_cut_axial_depth_mm",
            ),
            ("kind = \"flat_end_mill\"", "kind = \"reamer\"", "reamer"),
        ] {
            let e = ToolLibrary::from_toml(&ONE.replace(from, to), "t.toml").unwrap_err();
            assert!(e.to_string().contains(what), "{to}: {e}");
        }
        let twice = format!("{ONE}{ONE}");
        let e = ToolLibrary::from_toml(&twice, "t.toml").unwrap_err();
        assert!(e.to_string().contains("a second tool"), "{e}");
        let e = ToolLibrary::from_toml("", "t.toml").unwrap_err();
        assert_eq!(e.code(), "tools.toml");
    }
}
