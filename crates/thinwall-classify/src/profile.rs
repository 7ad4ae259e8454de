//! The 2.5D shape of a volume along the tool direction (top, bottom, sides
//! in cyclic order, corner radii looked through) and the types its pattern
//! of closed faces fits.

use crate::coincide::{FaceGeom, Tol};
use crate::{
    Classification, FaceRole, Judged, ProductAdjacency, Touch, Volume, VolumeFace, VolumeType,
};
use geo::{BoundingRect, Contains, Distance, Euclidean, MultiPolygon};
use std::collections::HashSet;
use thinwall_analysis::polygon::min_rect_sides;
use thinwall_analysis::PartAnalysis;
use thinwall_brep::FaceId;
use thinwall_geom::{Frame, Vector3};
use thinwall_graph::Convexity;

/// What shaping a volume reads besides its faces.
pub struct Context<'a> {
    pub vol: &'a Volume,
    pub analysis: &'a PartAnalysis<'a>,
    pub part: &'a PartAnalysis<'a>,
    pub part_faces: &'a [FaceGeom<'a>],
    /// The part's faces by their boxes.
    pub part_index: &'a crate::index::BoxIndex,
    pub up: &'a Vector3,
    pub tol: &'a Tol,
}

fn unknown(mut c: Classification, why: &str) -> Classification {
    c.kind = VolumeType::Unknown;
    c.reason = Some(why.to_string());
    c
}

fn touches_part(j: &Judged) -> bool {
    j.touches.iter().any(|t| matches!(t, Touch::Part { .. }))
}

/// The classification before typing: faces, product adjacency, direction.
fn start(ctx: &Context, vi: usize, faces: &[Judged]) -> Classification {
    let up = ctx.up;
    let side_part = faces
        .iter()
        .any(|j| j.role == FaceRole::Side && j.closed && touches_part(j));
    let bottom_part = faces
        .iter()
        .any(|j| j.role == FaceRole::Bottom && j.closed && touches_part(j));
    Classification {
        index: vi,
        name: ctx.vol.name.clone(),
        kind: VolumeType::Unknown,
        reason: None,
        product_adjacency: match (side_part, bottom_part) {
            (false, false) => ProductAdjacency::None,
            (true, false) => ProductAdjacency::Side,
            (false, true) => ProductAdjacency::Bottom,
            (true, true) => ProductAdjacency::SideAndBottom,
        },
        direction: [-up.x, -up.y, -up.z],
        bottom_open: false,
        faces: faces
            .iter()
            .map(|j| VolumeFace {
                step_id: j.geom.step_id,
                role: j.role,
                surface: ctx
                    .vol
                    .part
                    .face(j.geom.face)
                    .surface
                    .kind_name()
                    .to_string(),
                closed: j.closed,
                touches: j.touches.clone(),
            })
            .collect(),
        product_adjacent_sides: faces
            .iter()
            .filter(|j| j.role == FaceRole::Side && touches_part(j))
            .map(|j| j.geom.step_id)
            .collect(),
        depth: 0.0,
        length: 0.0,
        width: 0.0,
        corner_radii: Vec::new(),
    }
}

/// Classify one volume from its judged faces.
pub fn shape(
    ctx: &Context,
    vi: usize,
    faces: Vec<Judged>,
    priority: &[VolumeType],
) -> Classification {
    let mut c = start(ctx, vi, &faces);
    let height = |g: &FaceGeom| g.planar.map_or(0.0, |p| p.frame.origin.coords.dot(ctx.up));
    let of_role =
        |r: FaceRole| -> Vec<usize> { (0..faces.len()).filter(|&i| faces[i].role == r).collect() };
    let (tops, bottoms, sides) = (
        of_role(FaceRole::Top),
        of_role(FaceRole::Bottom),
        of_role(FaceRole::Side),
    );
    if faces.iter().any(|f| f.role == FaceRole::Other) {
        return unknown(
            c,
            "not a 2.5D volume along the tool direction (a face is neither top, bottom nor side)",
        );
    }
    if tops.is_empty() || bottoms.is_empty() || sides.is_empty() {
        return unknown(c, "no top, bottom or side faces along the tool direction");
    }
    let hs = |ix: &[usize]| {
        ix.iter()
            .map(|&i| height(faces[i].geom))
            .collect::<Vec<f64>>()
    };
    let (top_hs, bot_hs) = (hs(&tops), hs(&bottoms));
    let top_h = top_hs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let bot_h = bot_hs.iter().copied().fold(f64::INFINITY, f64::min);
    c.depth = top_h - bot_h;
    if top_hs.iter().any(|h| (h - top_h).abs() > ctx.tol.lin) {
        return unknown(c, "access faces at several heights");
    }
    if bot_hs.iter().any(|h| (h - bot_h).abs() > ctx.tol.lin) {
        return unknown(c, "stepped bottom: bottom faces at several heights");
    }
    // Profile from the top face(s), in a frame whose z is up.
    let frame = faces[tops[0]].geom.planar.expect("planar top").frame;
    let profile = MultiPolygon::new(
        tops.iter()
            .flat_map(|&i| faces[i].geom.planar.expect("planar").polygon_in(&frame).0)
            .collect(),
    );
    if let Some((long, short)) = min_rect_sides(&profile) {
        c.length = long;
        c.width = short;
    }
    if tops.iter().any(|&i| faces[i].closed) {
        return unknown(c, "the access face is closed");
    }
    if overlaps_material(ctx, &profile, &frame, bot_h, top_h) {
        return unknown(c, "overlaps part material");
    }
    c.bottom_open = !bottoms.iter().any(|&i| faces[i].closed);
    let Some(order) = cyclic_sides(ctx.analysis, &faces, &sides) else {
        return unknown(c, "the profile has islands or several loops");
    };
    match side_pattern(ctx, &faces, &order, &mut c) {
        Ok(candidates) => pick(c, &candidates, ctx.vol.current, priority),
        Err(why) => unknown(c, why),
    }
}

/// The side faces in cyclic order around the profile, or `None` when they
/// do not form one loop.
fn cyclic_sides(a: &PartAnalysis, faces: &[Judged], sides: &[usize]) -> Option<Vec<usize>> {
    let side_set: HashSet<FaceId> = sides.iter().map(|&i| faces[i].geom.face).collect();
    let index_of = |f: FaceId| sides.iter().copied().find(|&i| faces[i].geom.face == f);
    let mut order: Vec<usize> = vec![sides[0]];
    loop {
        let last = faces[*order.last().expect("start")].geom.face;
        let next = a
            .graph()
            .neighbours(last)
            .filter(|(g, _)| side_set.contains(g))
            .filter_map(|(g, _)| index_of(g))
            .find(|i| !order.contains(i));
        match next {
            Some(n) => order.push(n),
            None => break,
        }
    }
    (order.len() == sides.len()).then_some(order)
}

/// The types the pattern of closed sides fits (corner radii recorded in
/// `c`), or why it fits none.
fn side_pattern(
    ctx: &Context,
    faces: &[Judged],
    order: &[usize],
    c: &mut Classification,
) -> Result<Vec<VolumeType>, &'static str> {
    let side_set: HashSet<FaceId> = order.iter().map(|&i| faces[i].geom.face).collect();
    let curved: Vec<usize> = order
        .iter()
        .copied()
        .filter(|&i| faces[i].geom.planar.is_none())
        .collect();
    if curved.len() == order.len() && one_cylinder(order.iter().map(|&i| &faces[i]), ctx.tol) {
        c.corner_radii.clear();
        return Ok(vec![VolumeType::Hole]);
    }
    // A corner radius: a cylinder tangent to the sides before and after it.
    let mut free = false;
    for &i in &curved {
        let tangent = ctx
            .analysis
            .graph()
            .neighbours(faces[i].geom.face)
            .filter(|(g, a)| side_set.contains(g) && a.convexity == Convexity::Smooth)
            .count();
        match faces[i].geom.cylinder {
            Some(cyl) if tangent >= 2 => c.corner_radii.push(cyl.radius),
            _ => free = true,
        }
    }
    let planar_sides: Vec<usize> = order
        .iter()
        .copied()
        .filter(|&i| faces[i].geom.planar.is_some())
        .collect();
    let closed: Vec<bool> = planar_sides.iter().map(|&i| faces[i].closed).collect();
    let all = closed.iter().all(|&x| x) && curved.iter().all(|&i| faces[i].closed || !free);
    if all {
        return Ok(vec![match (free, c.bottom_open) {
            (false, false) => VolumeType::Pocket,
            (false, true) => VolumeType::Passage,
            (true, false) => VolumeType::FreePocket,
            (true, true) => VolumeType::FreePassage,
        }]);
    }
    if !closed.iter().any(|&x| x) {
        if c.bottom_open {
            return Err("no face is closed: nothing bounds it");
        }
        return Ok(vec![VolumeType::Face]);
    }
    if free {
        return Ok(vec![VolumeType::FreeStep]);
    }
    let normal = |k: usize| faces[planar_sides[k]].geom.planar.expect("planar").normal();
    closed_runs(&closed, normal, ctx.tol)
}

/// Whether the sides are all pieces of one cylinder (a round hole written
/// as one face, or as halves).
fn one_cylinder<'a>(mut sides: impl Iterator<Item = &'a Judged<'a>>, tol: &Tol) -> bool {
    let Some(first) = sides.next().and_then(|j| j.geom.cylinder) else {
        return false;
    };
    sides.all(|j| {
        j.geom.cylinder.is_some_and(|c| {
            let d = c.origin - first.origin;
            (c.radius - first.radius).abs() <= tol.lin
                && c.axis.dot(&first.axis).abs() >= tol.cos
                && (d - first.axis * d.dot(&first.axis)).norm() <= tol.lin
        })
    })
}

/// Types from the runs of closed sides around the profile: one run (a
/// blind slot when all but one side, a corner notch when two sides at an
/// angle, a step), or two single opposite sides (a through slot).
fn closed_runs(
    closed: &[bool],
    normal: impl Fn(usize) -> Vector3,
    tol: &Tol,
) -> Result<Vec<VolumeType>, &'static str> {
    let n = closed.len();
    let start = (0..n).find(|&i| !closed[i]).expect("an open side");
    let mut runs: Vec<Vec<usize>> = Vec::new();
    for k in 1..=n {
        let i = (start + k) % n;
        if closed[i] {
            if k == 1 || !closed[(start + k - 1) % n] {
                runs.push(Vec::new());
            }
            runs.last_mut().expect("run").push(i);
        }
    }
    match runs.as_slice() {
        [run] => {
            let mut v = Vec::new();
            if run.len() == n - 1 {
                v.push(VolumeType::BlindSlot);
            }
            // Two sides at a corner: more than 60° apart.
            const CORNER_MAX_COS: f64 = 0.5;
            if run.len() == 2 && normal(run[0]).dot(&normal(run[1])).abs() < CORNER_MAX_COS {
                v.push(VolumeType::CornerNotch);
            }
            v.push(VolumeType::Step);
            Ok(v)
        }
        [a, b] if a.len() == 1 && b.len() == 1 && normal(a[0]).dot(&normal(b[0])) < -tol.cos => {
            Ok(vec![VolumeType::ThroughSlot])
        }
        _ => Err("closed sides in separate runs that are not two opposite sides"),
    }
}

fn pick(
    mut c: Classification,
    candidates: &[VolumeType],
    current: Option<VolumeType>,
    priority: &[VolumeType],
) -> Classification {
    c.kind = match current.filter(|t| candidates.contains(t)) {
        Some(t) => t,
        None => priority
            .iter()
            .copied()
            .find(|t| candidates.contains(t))
            .unwrap_or(candidates[0]),
    };
    c
}

/// Whether part material reaches into the volume: a point of a part face
/// strictly inside the prism (inside the profile and between bottom and
/// top, by more than the tolerance).
fn overlaps_material(
    ctx: &Context,
    profile: &MultiPolygon<f64>,
    frame: &Frame,
    bot_h: f64,
    top_h: f64,
) -> bool {
    let Some(rect) = profile.bounding_rect() else {
        return false;
    };
    let margin = ctx.tol.lin * 10.0;
    // Only faces whose box meets the volume's can reach into it.
    let own = ctx.analysis.bounding_box();
    for g in ctx
        .part_index
        .near(own)
        .into_iter()
        .map(|i| &ctx.part_faces[i])
    {
        if (0..3)
            .any(|k| g.bbox.min[k] > own.max[k] + margin || g.bbox.max[k] < own.min[k] - margin)
        {
            continue;
        }
        // Its boundary points, and a point inside a planar face, for faces
        // crossing the volume without a boundary point in it (a floor the
        // volume cuts through).
        let inner = g.inner_point();
        let pts = ctx.part.boundary_points(g.face).iter().chain(inner.iter());
        for p in pts {
            // Outside the volume's box: not in it.
            if (0..3).any(|k| p[k] < own.min[k] - margin || p[k] > own.max[k] + margin) {
                continue;
            }
            let h = p.coords.dot(ctx.up);
            if h <= bot_h + margin || h >= top_h - margin {
                continue;
            }
            let l = frame.to_local(p);
            if l.x < rect.min().x || l.x > rect.max().x || l.y < rect.min().y || l.y > rect.max().y
            {
                continue;
            }
            let q = geo::Point::new(l.x, l.y);
            if profile.contains(&q)
                && profile
                    .0
                    .iter()
                    .all(|poly| Euclidean.distance(&q, poly.exterior()) > margin)
            {
                return true;
            }
        }
    }
    false
}
