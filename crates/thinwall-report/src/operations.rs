//! The operations report (`thinwall operations`, schema
//! `thinwall/operations/2`): the tool library in force and the operations
//! of each set-up in turn (layers, cutter fields, tools with rest areas and
//! their regions, operations in order), the first's at the top level and
//! the later ones' under `then`; with several set-ups what none reaches
//! (`residue`); when the set-ups were proposed, why (`proposal`); `not_yet`
//! says what the issue asks that the report does not cover yet.

use serde::Serialize;
use std::fmt::Write;
use thinwall_ops::operations::SetupOperations;
use thinwall_ops::ToolLibrary;

pub const OPERATIONS_SCHEMA: &str = "thinwall/operations/2";

#[derive(Clone, Debug, Serialize)]
pub struct OperationsReport {
    pub schema: String,
    pub thinwall_version: String,
    pub part: String,
    pub up: [f64; 3],
    /// The removal frame: origin, x, y, z (= up); contours are in its
    /// (x, y), mm.
    pub frame: [[f64; 3]; 4],
    pub tools: ToolLibrary,
    pub setup: SetupOperations,
    /// The set-ups after the first, in order, each after those before it.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub then: Vec<LaterSetup>,
    /// With several set-ups: what none of them reaches.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub residue: Option<thinwall_setups::turn::Residue>,
    /// The set-ups proposed (no up given), with why.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub proposal: Option<thinwall_setups::proposal::Proposal>,
    pub not_yet: Vec<String>,
    /// The part's faces in OpenCascade's order (`TopExp::MapShapes` over
    /// the shape it reads from the same file): entry `i` names the face a
    /// host built on OpenCascade numbers `i`, `null` for one of a
    /// supplemental surface model. Absent for a part not read from STEP.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub opencascade_faces: Vec<Option<thinwall_brep::FaceKey>>,
}

/// A set-up after the first: its stock is what the set-ups before it
/// left (their blocks `cleared` in its removal).
#[derive(Clone, Debug, Serialize)]
pub struct LaterSetup {
    pub up: [f64; 3],
    /// Its removal frame: origin, x, y, z (= its up), mm.
    pub frame: [[f64; 3]; 4],
    pub setup: SetupOperations,
}

impl LaterSetup {
    pub fn new(up: [f64; 3], frame: &thinwall_geom::Frame, setup: SetupOperations) -> Self {
        Self {
            up,
            frame: frame_rows(frame),
            setup,
        }
    }
}

/// A frame as rows: origin, x, y, z.
fn frame_rows(frame: &thinwall_geom::Frame) -> [[f64; 3]; 4] {
    let v = |p: thinwall_geom::Vector3| [p.x, p.y, p.z];
    let o = frame.origin;
    [[o.x, o.y, o.z], v(frame.x), v(frame.y), v(frame.z)]
}

impl OperationsReport {
    /// The report of `setup`, planned in the removal `frame`.
    pub fn new(
        part: &str,
        up: [f64; 3],
        frame: &thinwall_geom::Frame,
        tools: ToolLibrary,
        setup: SetupOperations,
    ) -> Self {
        Self {
            schema: OPERATIONS_SCHEMA.to_string(),
            thinwall_version: env!("CARGO_PKG_VERSION").to_string(),
            part: part.to_string(),
            up,
            frame: frame_rows(frame),
            tools,
            setup,
            then: Vec::new(),
            residue: None,
            proposal: None,
            opencascade_faces: Vec::new(),
            not_yet: vec![
                "holes wider than twice the largest end mill are pocketed with the layers (no boring subtype)".into(),
                "the plan's relations bind the order with --by-feature only; the default keeps the geometric precedences".into(),
                "a web keeps the support of the material under it (no step layers while a later set-up's material is there) with --by-feature only, along each set-up's plan".into(),
                "with --by-feature a later set-up's contours treat what earlier set-ups took as walls, not open (no tool comes in over it)".into(),
            ],
        }
    }

    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
            + "\n"
    }

    /// A readable operation sheet (and each later set-up's after it).
    pub fn to_text(&self) -> String {
        let mut s = String::new();
        if let Some(p) = &self.proposal {
            crate::setups::proposal_text(&mut s, p);
        }
        s.push_str(&self.sheet_text(&self.setup));
        for (k, later) in self.then.iter().enumerate() {
            let u = later.up;
            let _ = writeln!(
                s,
                "\nset-up {}: up ({:.3}, {:.3}, {:.3}), after the set-up(s) before: the {:.1} mm³ they reached are gone",
                k + 2,
                u[0],
                u[1],
                u[2],
                later.setup.cleared_before_mm3
            );
            s.push_str(&self.sheet_text(&later.setup));
        }
        if let Some(r) = &self.residue {
            crate::setups::residue_text(&mut s, r);
        }
        let _ = writeln!(s, "not yet: {}", self.not_yet.join("; "));
        s
    }

    /// One set-up's sheet.
    fn sheet_text(&self, r: &SetupOperations) -> String {
        let mut s = String::new();
        let _ = writeln!(
            s,
            "{}: {} layer(s) of at most {:.2} mm, {} operation(s), {} tool change(s) ({} layer by layer), travel {:.0} mm ({:.0}), about {:.1} min",
            self.part,
            r.layers.len(),
            r.axial_depth_mm,
            r.operations.len(),
            r.tool_changes,
            r.plain_tool_changes,
            r.travel_mm,
            r.plain_travel_mm,
            r.time_min
        );
        let _ = writeln!(
            s,
            "tools: {} ({} in the library)",
            self.tools.source,
            self.tools.tools.len()
        );
        let stepped: Vec<f64> = r.layers.iter().filter_map(|l| l.step_limit_mm).collect();
        if let Some(least) = stepped.iter().copied().min_by(f64::total_cmp) {
            let _ = writeln!(
                s,
                "step approach: {} layer(s) beside thin walls, none deeper than the walls' h_RF (at least {least:.2} mm), each pass finishing its walls (boundary) while the layer below holds them",
                stepped.len()
            );
        }
        if !r.meshed.is_empty() {
            let _ = writeln!(
                s,
                "meshed: {}: sections there exact to that deviation, the removal within ±{:.3} mm³",
                crate::plan::meshed_faces(&r.meshed),
                r.meshed.volume_bound_mm3
            );
        }
        let _ = writeln!(
            s,
            "{:>4}  {:<11} {:<8} {:>6}  {:<7} {:>7}  {:>17}  {:>12}  {:>26}  {:>13}  {:>8}  after",
            "step",
            "stage",
            "tool",
            "Ø mm",
            "feature",
            "layers",
            "z mm",
            "area mm²",
            "boundary/full cut/rough",
            "volume mm³",
            "min"
        );
        for o in &r.operations {
            operation_line(&mut s, o);
        }
        tool_sheet_text(&mut s, &r.tool_sheet);
        let small: usize = r
            .layers
            .iter()
            .zip(&r.field_tools)
            .map(|(l, fts)| {
                l.fields
                    .iter()
                    .zip(fts)
                    .filter(|(f, ft)| f.too_small && ft.drilled.is_none() && !ft.rest.is_empty())
                    .count()
            })
            .sum();
        if small > 0 {
            let _ = writeln!(s, "{small} field(s) narrower than the smallest tool");
        }
        crate::rests::write_rests(&mut s, &r.rest, self.tools.min_share_mm2);
        for f in &r.radius_finishes {
            radius_line(&mut s, f);
        }
        for h in &r.hole_stages {
            hole_stage_line(&mut s, h);
        }
        between_setups(&mut s, r);
        s
    }
}

/// What a set-up leaves to others and may cut again after them.
fn between_setups(s: &mut String, r: &SetupOperations) {
    if r.out_of_reach_mm3 > 0.0 {
        let _ = writeln!(
            s,
            "left to another set-up: {:.1} mm³ under the part, which a tool along this set-up's up does not reach",
            r.out_of_reach_mm3
        );
    }
    if r.recut_mm3 > 0.0 {
        let _ = writeln!(
            s,
            "cut again: up to {:.1} mm³ of what it cuts a set-up before it along another axis took (blocks reached in part are cut whole)",
            r.recut_mm3
        );
    }
    if !r.other_setup.is_empty() {
        let _ = writeln!(
            s,
            "left to another set-up (the plan's features this tool axis does not reach): {}",
            r.other_setup.join(" ")
        );
    }
}

/// One operation's row of the sheet.
fn operation_line(s: &mut String, o: &thinwall_ops::operations::Operation) {
    let after = if o.after.is_empty() {
        "-".to_string()
    } else {
        o.after
            .iter()
            .map(|a| a.to_string())
            .collect::<Vec<_>>()
            .join(",")
    };
    let regions = o.regions.map_or(String::from("-"), |g| {
        format!(
            "{:.0}/{:.0}/{:.0}",
            g.boundary_mm2, g.full_cut_mm2, g.roughing_mm2
        )
    });
    let layers = match (o.passes.first(), o.passes.last(), o.drill) {
        (Some(a), Some(b), _) if a.layer == b.layer => format!("{}", a.layer + 1),
        (Some(a), Some(b), _) => format!("{}-{}", a.layer + 1, b.layer + 1),
        (_, _, Some(kind)) => kind.name().to_string(),
        _ if o.corners => "corners".to_string(),
        _ if !o.finishes.is_empty() => "contour".to_string(),
        _ => "-".to_string(),
    };
    // A finish by radii names the machining features it finishes.
    let feature = match (&o.feature, o.finishes.as_slice()) {
        (Some(f), _) => f.to_string(),
        (None, []) => "-".to_string(),
        (None, [one]) => one.clone(),
        (None, [first, rest @ ..]) => format!("{first}+{}", rest.len()),
    };
    let _ = writeln!(
            s,
            "{:>4}  {:<11} {:<8} {:>6.1}  {:<7} {:>7}  {:>8.2}..{:<8.2} {:>12.1}  {:>26}  {:>13.0}  {:>8.2}  {after}",
            o.step,
            o.stage.name(),
            o.tool,
            o.diameter_mm,
            feature,
            layers,
            o.z_top_mm,
            o.z_bottom_mm,
            o.area_mm2,
            regions,
            o.volume_mm3,
            o.time_min
        );
}

/// A feature finished by its radii: its radii, the bound, its tools and
/// what no tool finishes.
fn radius_line(s: &mut String, f: &thinwall_ops::finishing::RadiusFinish) {
    use thinwall_machining::ToolBound;
    use thinwall_ops::finishing::RestCause;
    let mm = |v: Option<f64>| v.map_or("-".to_string(), |v| format!("{v:.2}"));
    let bound = match f.bounded_by {
        ToolBound::CornerRadius => "2 x its corner radius",
        ToolBound::Width => "its floor's width",
        ToolBound::Bore => "its bore",
    };
    let tool = |t: &Option<String>| t.clone().unwrap_or_else(|| "none".to_string());
    let _ = writeln!(
        s,
        "radii: {} R {} / r {}, {:.2} deep: tool <= {:.2} ({bound}), corner radius <= {}; walls and fillet {}, corners {}",
        f.feature,
        mm(f.corner_radius_mm),
        mm(f.floor_fillet_mm),
        f.depth_mm,
        f.largest_tool_mm,
        mm(f.floor_fillet_mm),
        tool(&f.walls),
        tool(&f.corners)
    );
    for r in &f.rest {
        let why = match r.cause {
            RestCause::Corner => "its corners: no tool narrow enough",
            RestCause::FloorFillet => "its floor fillet: no tool's corner radius small enough",
            RestCause::Depth => "its walls below the tool's flutes: no tool long enough",
        };
        let _ = writeln!(
            s,
            "rest: {} {why}: {:.2} mm² of its surface{} left by {}",
            f.feature,
            r.area_mm2,
            r.volume_mm3
                .map_or(String::new(), |v| format!(", {v:.2} mm³")),
            r.tool.as_deref().unwrap_or("any tool")
        );
    }
}

/// A hole's stage: what it cuts and its tool, or why none.
fn hole_stage_line(s: &mut String, h: &thinwall_ops::hole_stages::HoleStage) {
    use thinwall_ops::hole_stages::HoleStep;
    let what = match h.step {
        HoleStep::Spot => "spot",
        HoleStep::Countersink => "countersink",
        HoleStep::Chamfer => "chamfer",
        HoleStep::Blend => "blended edge",
    };
    let angle = h.angle_deg.map_or(String::new(), |a| format!(" {a:.0}°"));
    let end = if h.at_exit { " at its exit" } else { "" };
    let by = match (&h.tool, &h.missing) {
        (Some(t), _) => t.clone(),
        (None, Some(why)) => format!("no tool: {why}"),
        (None, None) => "no tool".to_string(),
    };
    let _ = writeln!(
        s,
        "hole {}: {what}{angle} Ø{:.2}{end}, {:.2} deep: {by}",
        h.hole, h.diameter_mm, h.depth_mm
    );
}

/// The set-up's tools in the order they first run: what each does, its
/// operations, when it is in the spindle, what it cuts and its time.
fn tool_sheet_text(s: &mut String, sheet: &[thinwall_ops::operations::ToolUse]) {
    if sheet.is_empty() {
        return;
    }
    let _ = writeln!(s, "tools in order ({}):", sheet.len());
    for u in sheet {
        let stages: Vec<&str> = u.stages.iter().map(|st| st.name()).collect();
        let _ = writeln!(
            s,
            "  {:<8} Ø{:<5.1} {} operation(s), steps {}–{}, loaded {}×: {}; {:.0} mm³, {:.2} min",
            u.tool,
            u.diameter_mm,
            u.operations,
            u.first_step,
            u.last_step,
            u.loads,
            stages.join(", "),
            u.volume_mm3,
            u.time_min
        );
    }
}
