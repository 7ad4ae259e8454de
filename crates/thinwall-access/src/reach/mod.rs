//! Reach with obstruction (issue 16 §1): which part of each face a tool of
//! given diameter and cutting length, on a given axis, can touch without the
//! cutter or the holder above it cutting into other material.
//!
//! The tool is a flat end mill: a cylinder of its diameter from the tip up
//! to the cutting length, a holder of its own diameter above that without
//! end. It touches a point of a face with its end where the face is square
//! to the axis (a floor: any position whose end covers the point) and with
//! the corner of its end elsewhere (its axis one radius out along the
//! face's level normal, the tip at the point's height); a face turned away
//! from the axis (an undercut) it cannot touch. Obstacles are the part's
//! triangles (the report tessellation). Planar faces are judged exactly
//! (up to the integration, [`side`], and the disk polygons, [`floor`]);
//! curved faces at their triangles' middles ([`sampled`]).
//!
//! Three axes: the tool axis is the set-up's up. Five axes: up and axes
//! tilted by half the limit and the limit, twelve ways round (from the
//! part's longest straight edge, so a turned part is tried on turned axes);
//! a face reports the axes that reach it whole, or the best and its
//! fraction.

pub mod bore;
pub mod disk;
pub mod features;
pub mod floor;
pub mod interval;
pub mod largest;
pub mod obstacle;
pub mod sampled;
pub mod scene;
pub mod side;
pub mod standing;
pub mod stroke;
pub mod walls;
pub mod window;

pub use largest::{largest_tool, SMALLEST_TOOL, TOOL_PRECISION};
use scene::Scene;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use thinwall_analysis::{Machine, PartAnalysis, PlanarFace};
use thinwall_brep::tessellate::{Mesh, RELATIVE_DEVIATION};
use thinwall_brep::FaceId;
use thinwall_geom::{CurveKind, Frame, Vector3};
use thiserror::Error;

/// A face within this of square to the axis is a floor (cos 0.5°).
pub const FLOOR_COS: f64 = 0.999_961_923_064_171_3;
/// A face turned more than this below level faces away (sin 0.5°).
pub const UNDERCUT_SIN: f64 = 0.008_726_535_498_373_935;
/// A face counts as reached whole when at most this share of it is left
/// (the integration's and the disk polygons' rounding).
pub const WHOLE_SHARE: f64 = 1e-4;
/// Material within this share of the part's size of the tool's surface
/// touches it rather than cuts (planar faces: exact geometry).
const TOUCH: f64 = 1e-9;
/// A curved face is judged at pieces of its triangles at most this share
/// of the given tool's diameter long (3 mm for the Ø12 tool), unless no
/// longer than four times their width ([`sampled::Samples`]): what stops
/// the tool changes over about its radius.
const SAMPLE_SPACING: f64 = 0.25;
/// Areas that differ by less than this are a tie (ordered by id then),
/// mm²: symmetric blockers' lost areas differ in their last bits, which
/// rounding decides.
pub const AREA_TIE_MM2: f64 = 1e-6;

/// An area's rank for ordering blockers, the worst first: equal within
/// [`AREA_TIE_MM2`].
pub fn area_rank(mm2: f64) -> i64 {
    (mm2 / AREA_TIE_MM2).round() as i64
}

/// Ways round of the five-axis axes.
const AZIMUTHS: usize = 12;

/// A flat end mill in its holder, mm.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Tool {
    pub diameter: f64,
    /// From the tip to the holder.
    pub cutting_length: f64,
    /// The holder's envelope.
    pub holder_diameter: f64,
}

impl Tool {
    /// A tool of `diameter` with a cutting length of three diameters and
    /// a holder of two.
    pub fn new(diameter: f64) -> Self {
        Self {
            diameter,
            cutting_length: 3.0 * diameter,
            holder_diameter: 2.0 * diameter,
        }
    }

    /// The same proportions at another diameter.
    pub fn scaled(&self, diameter: f64) -> Self {
        let k = diameter / self.diameter;
        Self {
            diameter,
            cutting_length: self.cutting_length,
            holder_diameter: self.holder_diameter * k,
        }
    }

    pub fn check(&self) -> Result<(), ReachError> {
        let ok = |v: f64| v.is_finite() && v > 0.0 && v <= MAX_TOOL_MM;
        if !ok(self.diameter) {
            return Err(ReachError::Diameter(self.diameter));
        }
        if !ok(self.cutting_length) {
            return Err(ReachError::CuttingLength(self.cutting_length));
        }
        if !(self.holder_diameter.is_finite() && self.holder_diameter >= self.diameter) {
            return Err(ReachError::Holder {
                holder: self.holder_diameter,
                diameter: self.diameter,
            });
        }
        Ok(())
    }
}

/// Largest tool diameter and cutting length accepted, mm.
pub const MAX_TOOL_MM: f64 = 1e4;

impl Default for Tool {
    /// The preferred tool, Ø12.
    fn default() -> Self {
        Self::new(12.0)
    }
}

/// Why reach cannot be judged.
#[derive(Debug, Error, PartialEq)]
pub enum ReachError {
    #[error("tool diameter must be a positive number of mm up to 10,000, got {0}")]
    Diameter(f64),
    #[error("cutting length must be a positive number of mm up to 10,000, got {0}")]
    CuttingLength(f64),
    #[error("holder diameter {holder} mm must be at least the tool's {diameter} mm")]
    Holder { holder: f64, diameter: f64 },
    #[error("tilt limit must be between 0 and 90 degrees, got {0}")]
    TiltLimit(f64),
}

impl ReachError {
    pub fn code(&self) -> &'static str {
        match self {
            ReachError::Diameter(_) => "tool_diameter",
            ReachError::CuttingLength(_) => "cutting_length",
            ReachError::Holder { .. } => "holder_diameter",
            ReachError::TiltLimit(_) => "tilt_limit",
        }
    }
}

/// What to judge with.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ReachOptions {
    pub tool: Tool,
    /// Three axes (up) or five (up tilted within a limit).
    pub machine: Machine,
    /// Also find, per floor, the largest tool (same proportions) that
    /// reaches it whole.
    pub largest_tool: bool,
}

impl Default for ReachOptions {
    fn default() -> Self {
        Self {
            tool: Tool::default(),
            machine: Machine::ThreeAxis,
            largest_tool: false,
        }
    }
}

/// How the tool meets the face.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Contact {
    /// Planar, square to the axis: with the tool's end.
    Floor,
    /// Planar otherwise: with the side or the end's corner.
    Side,
    /// Curved: judged at its triangles.
    Curved,
    /// Turned away from the axis (an undercut): not reached from it.
    Away,
}

/// Which part of the tool meets the material.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ToolPart {
    Cutter,
    Holder,
}

/// A face in the way, and how much of the judged face it leaves.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Blocker {
    pub face: u64,
    pub body: u32,
    pub by: ToolPart,
    /// mm² of the judged face it stops the tool on (blockers may overlap).
    pub unreachable_mm2: f64,
}

/// The reach of one face.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FaceReach {
    pub face: u64,
    pub body: u32,
    pub contact: Contact,
    pub area_mm2: f64,
    /// Reached area / area, on `axis`.
    pub fraction: f64,
    pub unreachable_mm2: f64,
    /// The axis judged: up, or on five axes the best (unit).
    pub axis: [f64; 3],
    /// Its tilt from up, degrees.
    pub tilt_deg: f64,
    /// Five axes: every axis tried that reaches the whole face.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub whole_axes: Vec<[f64; 3]>,
    /// Largest first.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub blocked_by: Vec<Blocker>,
    /// Where the tool does not reach, as outlines on the face (mm).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub unreachable: Vec<Vec<[f64; 3]>>,
    /// Floors, when asked: the largest tool (the given one's proportions)
    /// that reaches the whole face, mm; none when even 0.5 mm does not.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub largest_tool_mm: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
}

impl FaceReach {
    pub fn whole(&self) -> bool {
        self.fraction >= 1.0 - WHOLE_SHARE
    }
}

/// One judgement of a face on one axis.
#[derive(Clone, Debug, Default)]
pub struct Judged {
    /// mm², as integrated.
    pub area: f64,
    pub reached: f64,
    /// mm² turned away from the axis.
    pub away: f64,
    /// mm² stopped per (mesh face, holder).
    pub blockers: BTreeMap<(u32, bool), f64>,
    pub unreachable: Vec<Vec<[f64; 3]>>,
    /// Stopped early, more than its budget lost: the rest is not judged.
    pub cut_short: bool,
    /// Curved faces: the triangles not reached (indices into the face's).
    pub lost: Vec<u32>,
}

impl Judged {
    pub fn fraction(&self) -> f64 {
        if self.area > 0.0 {
            (self.reached / self.area).clamp(0.0, 1.0)
        } else {
            1.0
        }
    }
}

/// The box in the scene's plane around points (x, y of each), grown by
/// `pad` on every side, mm.
fn xy_bounds(points: &[[f64; 3]], pad: f64) -> ([f64; 2], [f64; 2]) {
    let fold =
        |i: usize, init: f64, f: fn(f64, f64) -> f64| points.iter().map(|c| c[i]).fold(init, f);
    (
        [
            fold(0, f64::INFINITY, f64::min) - pad,
            fold(1, f64::INFINITY, f64::min) - pad,
        ],
        [
            fold(0, f64::NEG_INFINITY, f64::max) + pad,
            fold(1, f64::NEG_INFINITY, f64::max) + pad,
        ],
    )
}

/// Settings shared by the judgements of one run.
pub struct Ctx {
    pub tool: Tool,
    /// mm: exact geometry.
    pub touch: f64,
    /// mm: tessellated geometry (a curved face against its own triangles).
    pub touch_curved: f64,
}

impl Ctx {
    pub fn new(a: &PartAnalysis, tool: Tool) -> Self {
        let size = a.part().size().max(1e-3);
        Self {
            tool,
            touch: TOUCH * size,
            touch_curved: 2.0 * RELATIVE_DEVIATION * size,
        }
    }
}

/// Tessellated material (a curved face's triangles, or a planar face's
/// with a curved edge) touches the tool within this share of its radius
/// (and within twice the tessellation's deviation): the chords of a
/// concave blend the tool runs along lie inside the arc, by
/// R·(1 − cos 0.075) for the mesh's 0.15 rad steps, 2 % of the radius for
/// a blend up to seven times the tool's.
pub const TESSELLATED_TOUCH: f64 = 0.02;

impl Ctx {
    /// mm: how near tessellated material may come and only touch.
    pub fn touch_tessellated(&self) -> f64 {
        self.touch_curved
            .min(TESSELLATED_TOUCH * 0.5 * self.tool.diameter)
            .max(self.touch)
    }
}

/// The tool axes tried (unit, world): up first.
pub fn axes(a: &PartAnalysis, machine: &Machine) -> Result<Vec<Vector3>, ReachError> {
    let up = a.up();
    let tilt = match machine {
        Machine::ThreeAxis => return Ok(vec![up]),
        Machine::FiveAxis { tilt_limit_deg } => *tilt_limit_deg,
    };
    if !(tilt.is_finite() && (0.0..90.0).contains(&tilt)) {
        return Err(ReachError::TiltLimit(tilt));
    }
    let mut out = vec![up];
    if tilt == 0.0 {
        return Ok(out);
    }
    let x = azimuth_reference(a, &up);
    let y = up.cross(&x);
    for t in [0.5 * tilt, tilt] {
        let (s, c) = t.to_radians().sin_cos();
        for k in 0..AZIMUTHS {
            let phi = std::f64::consts::TAU * k as f64 / AZIMUTHS as f64;
            out.push((up * c + (x * phi.cos() + y * phi.sin()) * s).normalize());
        }
    }
    Ok(out)
}

/// Level direction of the part's longest straight edge (the earliest in
/// the file among equals), so that axes turn with the part.
fn azimuth_reference(a: &PartAnalysis, up: &Vector3) -> Vector3 {
    let part = a.part();
    let mut best: Option<(f64, Vector3)> = None;
    for e in &part.edges {
        if !matches!(e.curve, CurveKind::Line { .. }) {
            continue;
        }
        let d = part.vertex(e.end).point - part.vertex(e.start).point;
        let level = d - up * d.dot(up);
        let len = level.norm();
        if len > 1e-9 && best.is_none_or(|(l, _)| len > l * (1.0 + 1e-9)) {
            best = Some((len, level / len));
        }
    }
    best.map(|b| b.1)
        .unwrap_or_else(|| thinwall_geom::frame::any_perpendicular(up))
}

/// The reach of every face of the analysed part.
pub fn reach(
    a: &PartAnalysis,
    mesh: &Mesh,
    opts: &ReachOptions,
) -> Result<Vec<FaceReach>, ReachError> {
    reach_of(a, mesh, opts, |_| true)
}

/// The reach of the faces `wanted` accepts (every face is still in the
/// way of the others).
pub fn reach_of(
    a: &PartAnalysis,
    mesh: &Mesh,
    opts: &ReachOptions,
    wanted: impl Fn(FaceId) -> bool + Sync,
) -> Result<Vec<FaceReach>, ReachError> {
    reach_observed(a, mesh, opts, wanted, |_, _| {})
}

/// As [`reach_of`], telling `done(faces judged, faces wanted)` after each
/// face (from any thread): a caller's progress bar on long runs.
pub fn reach_observed(
    a: &PartAnalysis,
    mesh: &Mesh,
    opts: &ReachOptions,
    wanted: impl Fn(FaceId) -> bool + Sync,
    done: impl Fn(usize, usize) + Sync,
) -> Result<Vec<FaceReach>, ReachError> {
    opts.tool.check()?;
    let axes = axes(a, &opts.machine)?;
    let ctx = Ctx::new(a, opts.tool.clone());
    let scenes = scenes(a, mesh, &axes);
    let chosen: Vec<usize> = (0..mesh.faces.len())
        .filter(|&k| wanted(mesh.faces[k].face))
        .collect();
    let (total, count) = (chosen.len(), std::sync::atomic::AtomicUsize::new(0));
    let out = a.work().map(&chosen, |&k| {
        let r = face_reach(a, mesh, &ctx, &scenes, k as u32, opts.largest_tool);
        done(
            count.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1,
            total,
        );
        r
    });
    Ok(out)
}

/// One scene per axis, its frame centred on the part.
pub fn scenes(a: &PartAnalysis, mesh: &Mesh, axes: &[Vector3]) -> Vec<Scene> {
    let bb = a.bounding_box();
    let centre = thinwall_geom::Point3::new(
        0.5 * (bb.min[0] + bb.max[0]),
        0.5 * (bb.min[1] + bb.max[1]),
        0.5 * (bb.min[2] + bb.max[2]),
    );
    let reference = azimuth_reference(a, &a.up());
    let tess: Vec<bool> = mesh.faces.iter().map(|m| tessellated(a, m.face)).collect();
    a.work().map(axes, |ax| {
        let frame = Frame::from_axis(centre, *ax, Some(reference)).unwrap_or_else(Frame::world);
        Scene::new(mesh, frame, |k| tess[k])
    })
}

/// Whether a face's triangles only approximate it: a curved face, or a
/// planar one with a curved edge (its outline's chords cut inside the arc).
fn tessellated(a: &PartAnalysis, f: FaceId) -> bool {
    let part = a.part();
    a.planar(f).is_none()
        || part.face(f).loops.iter().any(|&l| {
            part.loop_(l)
                .coedges
                .iter()
                .any(|c| !matches!(part.edge(c.edge).curve, CurveKind::Line { .. }))
        })
}

/// How the tool meets face `f` on the scene's axis: none when the face is
/// turned away from it (an undercut).
pub fn contact<'p>(
    a: &'p PartAnalysis,
    scene: &Scene,
    f: FaceId,
) -> Option<(Contact, Option<&'p PlanarFace>)> {
    let Some(pf) = a.planar(f) else {
        return Some((Contact::Curved, None));
    };
    let n = scene.local_vector(&pf.normal());
    if n[2] < -UNDERCUT_SIN {
        None
    } else if n[2] >= FLOOR_COS {
        Some((Contact::Floor, Some(pf)))
    } else {
        Some((Contact::Side, Some(pf)))
    }
}

/// How face `own` (mesh index) is judged on one scene; `samples`: where
/// it is judged when curved ([`sampled::Samples`]).
pub fn judge(
    a: &PartAnalysis,
    mesh: &Mesh,
    ctx: &Ctx,
    scene: &Scene,
    own: u32,
    samples: &sampled::Samples,
) -> (Contact, Judged) {
    let f: FaceId = mesh.faces[own as usize].face;
    match contact(a, scene, f) {
        None => {
            let area = a.props(f).area;
            let j = Judged {
                area,
                away: area,
                unreachable: sampled_outline(mesh, own),
                ..Judged::default()
            };
            (Contact::Away, j)
        }
        Some((Contact::Floor, Some(pf))) => {
            (Contact::Floor, floor::judge(ctx, scene, pf, own, true))
        }
        Some((Contact::Side, Some(pf))) => (Contact::Side, side::judge(ctx, scene, pf, own)),
        Some(_) => match bore::limit(a, scene, f) {
            Some(d) if bore::too_wide(ctx, d) => {
                (Contact::Curved, bore::none_reached(samples, own))
            }
            _ => (Contact::Curved, sampled::judge(ctx, scene, samples)),
        },
    }
}

/// A face's triangles as outlines.
pub(crate) fn sampled_outline(mesh: &Mesh, own: u32) -> Vec<Vec<[f64; 3]>> {
    mesh.faces[own as usize]
        .triangles
        .iter()
        .map(|t| t.iter().map(|&i| mesh.points[i as usize].into()).collect())
        .collect()
}

/// A face stops the tool only where it leaves more than this share of the
/// judged face unreachable: below the 1e-6 to which fractions are stated,
/// the polygon booleans' slivers (1e-6 mm² on a 2,000 mm² web) named a
/// blocker in one pose and not in another.
const BLOCKER_SHARE: f64 = 1e-7;

/// Who stops the tool on a face (face of the part, cutter or holder) and
/// how much of the face's `area` each leaves unreachable, most first.
fn blockers_of(part: &thinwall_brep::Part, mesh: &Mesh, j: &Judged, area: f64) -> Vec<Blocker> {
    let mut blocked_by: Vec<Blocker> = j
        .blockers
        .iter()
        .map(|(&(mf, holder), &mm2)| {
            let g = part.face(mesh.faces[mf as usize].face);
            Blocker {
                face: g.step_id,
                body: g.body.0,
                by: if holder {
                    ToolPart::Holder
                } else {
                    ToolPart::Cutter
                },
                unreachable_mm2: (mm2 * area / j.area.max(1e-300)).min((1.0 - j.fraction()) * area),
            }
        })
        .filter(|b| b.unreachable_mm2 > BLOCKER_SHARE * area)
        .collect();
    blocked_by.sort_by(|x, y| {
        area_rank(y.unreachable_mm2)
            .cmp(&area_rank(x.unreachable_mm2))
            .then(x.face.cmp(&y.face))
            .then(x.by.cmp(&y.by))
    });
    blocked_by
}

fn face_reach(
    a: &PartAnalysis,
    mesh: &Mesh,
    ctx: &Ctx,
    scenes: &[Scene],
    own: u32,
    largest: bool,
) -> FaceReach {
    let part = a.part();
    let f = mesh.faces[own as usize].face;
    let face = part.face(f);
    let samples = if a.planar(f).is_none() {
        sampled::Samples::of(face, mesh, own, SAMPLE_SPACING * ctx.tool.diameter)
    } else {
        sampled::Samples::default()
    };
    let judged: Vec<(Contact, Judged)> = scenes
        .iter()
        .map(|s| {
            a.work().check();
            judge(a, mesh, ctx, s, own, &samples)
        })
        .collect();
    let mut best = 0;
    for (k, j) in judged.iter().enumerate() {
        if j.1.fraction() > judged[best].1.fraction() + 1e-12 {
            best = k;
        }
    }
    let up = a.up();
    let whole_axes = if scenes.len() > 1 {
        judged
            .iter()
            .zip(scenes)
            .filter(|(j, _)| j.1.fraction() >= 1.0 - WHOLE_SHARE)
            .map(|(_, s)| s.frame.z.into())
            .collect()
    } else {
        Vec::new()
    };
    let (contact, j) = &judged[best];
    let axis = scenes[best].frame.z;
    let area = a.props(f).area;
    let fraction = j.fraction();
    let blocked_by = blockers_of(part, mesh, j, area);
    let narrow = bore::limit(a, &scenes[best], f).filter(|&d| bore::too_wide(ctx, d));
    let note = if let Some(d) = narrow {
        Some(format!(
            "a concave Ø{d:.3} around the tool axis, narrower than the Ø{:.3} tool",
            ctx.tool.diameter
        ))
    } else {
        (j.away > 0.5 * j.area && j.area > 0.0).then(|| {
            "turned away from the tool axis (an undercut): another set-up, or a tilted axis"
                .to_string()
        })
    };
    // Not for a face turned away from up: no tool reaches it.
    let facing = judged[0].1.away <= 0.5 * judged[0].1.area;
    let largest_tool_mm = (largest && facing)
        .then(|| largest_tool(a, mesh, ctx, &scenes[0], own, &samples, &judged[0].1))
        .flatten();
    FaceReach {
        face: face.step_id,
        body: face.body.0,
        contact: *contact,
        area_mm2: area,
        fraction,
        unreachable_mm2: (1.0 - fraction) * area,
        axis: axis.into(),
        tilt_deg: axis.dot(&up).clamp(-1.0, 1.0).acos().to_degrees(),
        whole_axes,
        blocked_by,
        unreachable: if fraction < 1.0 - WHOLE_SHARE {
            j.unreachable.clone()
        } else {
            Vec::new()
        },
        largest_tool_mm,
        note,
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// Numbers in [0, 1) from `seed` (xorshift): the reach tests' random
    /// shapes, the same on every run.
    pub(crate) fn uniform(mut s: u64) -> impl FnMut() -> f64 {
        move || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s >> 11) as f64 / (1u64 << 53) as f64
        }
    }

    /// Areas a rounding apart rank alike (the id orders them then);
    /// areas a tie apart do not.
    #[test]
    fn areas_within_rounding_tie() {
        let a = 1149.709356783899;
        assert_eq!(area_rank(a), area_rank(a * (1.0 + 1e-15)));
        assert_eq!(area_rank(7.605424848141204), area_rank(7.605424848141203));
        assert!(area_rank(a + 2.0 * AREA_TIE_MM2) > area_rank(a));
    }
}
