//! Dedicated classification of machining-feature volumes (DOMAIN.md §5.3,
//! Popma 5.4.2, 6.2.3): each volume must match a type exactly, by its shape
//! (a planar profile swept along the tool direction, top open) and by which
//! of its faces are closed — coinciding over an area with the part, or with
//! a volume not removed before it — and which open.
//!
//! ```no_run
//! # let (part, _) = thinwall_step::read_file("part.step").unwrap();
//! # let (v0, _) = thinwall_step::read_file("v0.step").unwrap();
//! use thinwall_classify::{classify, Request, Volume};
//! let volumes = vec![Volume { name: "v0".into(), part: v0, current: None }];
//! let r = classify(&Request { part: &part, volumes: &volumes, before: &[], up: [0.0, 0.0, 1.0], priority: vec![] }).unwrap();
//! println!("{}", r[0].kind.name());
//! ```

pub mod types;

pub use types::*;

use geo::{Area, BoundingRect, Contains, Distance, Euclidean, MinimumRotatedRect, MultiPolygon};
use std::collections::HashSet;
use thinwall_brep::{FaceId, Part};
use thinwall_geom::{Point3, Surface, Vector3};
use thinwall_graph::{AdjacencyGraph, Convexity};
use thinwall_recognize::depressions::face_points;
use thinwall_recognize::planar::PlanarFace;

/// A volume to classify.
pub struct Volume {
    pub name: String,
    /// The volume as a solid (read from its own STEP file).
    pub part: Part,
    /// Its current type, tried first (re-classification keeps a type that
    /// still fits).
    pub current: Option<VolumeType>,
}

/// What to classify.
pub struct Request<'a> {
    pub part: &'a Part,
    pub volumes: &'a [Volume],
    /// `(a, b)`: volume `a` is removed before volume `b`.
    pub before: &'a [(usize, usize)],
    /// Up in the set-up; the tool direction is `-up` (from the access face in).
    pub up: [f64; 3],
    /// Type order; empty for [`DEFAULT_PRIORITY`].
    pub priority: Vec<VolumeType>,
}

/// A request that cannot be served.
#[derive(Debug, PartialEq)]
pub struct RequestError(pub String);

impl std::fmt::Display for RequestError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for RequestError {}

/// Planes within this angle are parallel, degrees.
const PARALLEL_DEG: f64 = 0.5;

/// Geometry of one face, prepared once.
struct FaceGeom {
    face: FaceId,
    step_id: u64,
    planar: Option<PlanarFace>,
    /// Axis point, axis, radius, same_sense for cylinders.
    cylinder: Option<(Point3, Vector3, f64, bool)>,
    bbox: thinwall_geom::BoundingBox,
}

fn prepare(part: &Part) -> Vec<FaceGeom> {
    part.face_ids()
        .map(|f| {
            let face = part.face(f);
            let mut bbox = thinwall_geom::BoundingBox::empty();
            for p in face_points(part, f) {
                bbox.add_point(&p);
            }
            FaceGeom {
                face: f,
                step_id: face.step_id,
                planar: PlanarFace::new(part, f),
                cylinder: match face.surface {
                    Surface::Cylinder { frame, radius } => {
                        Some((frame.origin, frame.z, radius, face.same_sense))
                    }
                    _ => None,
                },
                bbox,
            }
        })
        .collect()
}

struct Tol {
    lin: f64,
    cos: f64,
    min_area: f64,
}

fn boxes_touch(a: &thinwall_geom::BoundingBox, b: &thinwall_geom::BoundingBox, tol: f64) -> bool {
    (0..3).all(|k| a.min[k] <= b.max[k] + tol && b.min[k] <= a.max[k] + tol)
}

/// Whether two faces coincide over an area with opposite outward normals.
fn coincide(a: &FaceGeom, b: &FaceGeom, tol: &Tol) -> bool {
    if !boxes_touch(&a.bbox, &b.bbox, tol.lin) {
        return false;
    }
    match (&a.planar, &b.planar, &a.cylinder, &b.cylinder) {
        (Some(pa), Some(pb), _, _) => {
            if pa.normal().dot(&pb.normal()) > -tol.cos {
                return false;
            }
            if (pb.frame.origin - pa.frame.origin).dot(&pa.normal()).abs() > tol.lin {
                return false;
            }
            let own = pa.polygon_in(&pa.frame);
            let other = pb.polygon_in(&pa.frame);
            thinwall_recognize::planar::intersect(&own, &other).unsigned_area() > tol.min_area
        }
        (_, _, Some((oa, za, ra, sa)), Some((ob, zb, rb, sb))) => {
            if sa == sb || (ra - rb).abs() > tol.lin || za.dot(zb).abs() < tol.cos {
                return false;
            }
            let d = ob - oa;
            let off_axis = (d - za * d.dot(za)).norm();
            if off_axis > tol.lin {
                return false;
            }
            // Overlap along the axis.
            let span = |g: &FaceGeom| {
                let proj: Vec<f64> = (0..8)
                    .map(|i| {
                        let c = Vector3::new(
                            if i & 1 == 0 {
                                g.bbox.min[0]
                            } else {
                                g.bbox.max[0]
                            },
                            if i & 2 == 0 {
                                g.bbox.min[1]
                            } else {
                                g.bbox.max[1]
                            },
                            if i & 4 == 0 {
                                g.bbox.min[2]
                            } else {
                                g.bbox.max[2]
                            },
                        );
                        c.dot(za)
                    })
                    .collect();
                (
                    proj.iter().cloned().fold(f64::INFINITY, f64::min),
                    proj.iter().cloned().fold(f64::NEG_INFINITY, f64::max),
                )
            };
            let (a0, a1) = span(a);
            let (b0, b1) = span(b);
            a1.min(b1) - a0.max(b0) > tol.lin
        }
        _ => false,
    }
}

/// Classify every volume of the request.
pub fn classify(req: &Request) -> Result<Vec<Classification>, RequestError> {
    for &(a, b) in req.before {
        if a >= req.volumes.len() || b >= req.volumes.len() || a == b {
            return Err(RequestError(format!(
                "sequence {a} before {b} names volumes outside 0..{}",
                req.volumes.len()
            )));
        }
    }
    let up = Vector3::new(req.up[0], req.up[1], req.up[2])
        .try_normalize(1e-12)
        .ok_or_else(|| RequestError(format!("up {:?} has no length", req.up)))?;
    let priority = if req.priority.is_empty() {
        DEFAULT_PRIORITY.to_vec()
    } else {
        req.priority.clone()
    };
    let diag = req.part.bounding_box().diagonal().max(1.0);
    let tol = Tol {
        lin: (diag * 1e-6).max(1e-5),
        cos: PARALLEL_DEG.to_radians().cos(),
        min_area: (diag * 1e-6).max(1e-5).powi(2) * 100.0,
    };
    let part_faces = prepare(req.part);
    let vol_faces: Vec<Vec<FaceGeom>> = req.volumes.iter().map(|v| prepare(&v.part)).collect();
    let mut out = Vec::new();
    for (vi, vol) in req.volumes.iter().enumerate() {
        let predecessors: HashSet<usize> = req
            .before
            .iter()
            .filter(|(_, b)| *b == vi)
            .map(|(a, _)| *a)
            .collect();
        let graph = AdjacencyGraph::build(&vol.part, &vol.part.tolerances());
        let mut faces = Vec::new();
        for g in &vol_faces[vi] {
            let mut touches = Vec::new();
            let mut closed = false;
            for p in &part_faces {
                if coincide(g, p, &tol) {
                    touches.push(Touch::Part { step_id: p.step_id });
                    closed = true;
                }
            }
            for (wi, other) in vol_faces.iter().enumerate() {
                if wi == vi {
                    continue;
                }
                for h in other {
                    if coincide(g, h, &tol) {
                        touches.push(Touch::Volume {
                            index: wi,
                            step_id: h.step_id,
                        });
                        if !predecessors.contains(&wi) {
                            closed = true;
                        }
                    }
                }
            }
            faces.push((g, role(g, &up, &tol), closed, touches));
        }
        out.push(shape(
            vi,
            vol,
            &graph,
            faces,
            &up,
            &tol,
            &priority,
            req.part,
            &part_faces,
        ));
    }
    Ok(out)
}

fn role(g: &FaceGeom, up: &Vector3, tol: &Tol) -> FaceRole {
    if let Some(p) = &g.planar {
        let c = p.normal().dot(up);
        if c > tol.cos {
            return FaceRole::Top;
        }
        if c < -tol.cos {
            return FaceRole::Bottom;
        }
        if c.abs() < (1.0 - tol.cos * tol.cos).sqrt() {
            return FaceRole::Side;
        }
        return FaceRole::Other;
    }
    if let Some((_, z, _, _)) = g.cylinder {
        if z.dot(up).abs() > tol.cos {
            return FaceRole::Side;
        }
    }
    FaceRole::Other
}

#[allow(clippy::too_many_arguments)]
fn shape(
    vi: usize,
    vol: &Volume,
    graph: &AdjacencyGraph,
    faces: Vec<(&FaceGeom, FaceRole, bool, Vec<Touch>)>,
    up: &Vector3,
    tol: &Tol,
    priority: &[VolumeType],
    part: &Part,
    part_faces: &[FaceGeom],
) -> Classification {
    let height = |g: &FaceGeom| {
        g.planar
            .as_ref()
            .map_or(0.0, |p| p.frame.origin.coords.dot(up))
    };
    let tops: Vec<&FaceGeom> = faces
        .iter()
        .filter(|f| f.1 == FaceRole::Top)
        .map(|f| f.0)
        .collect();
    let bottoms: Vec<&FaceGeom> = faces
        .iter()
        .filter(|f| f.1 == FaceRole::Bottom)
        .map(|f| f.0)
        .collect();
    let sides: Vec<usize> = (0..faces.len())
        .filter(|&i| faces[i].1 == FaceRole::Side)
        .collect();
    let mut c = Classification {
        index: vi,
        name: vol.name.clone(),
        kind: VolumeType::Unknown,
        reason: None,
        product_adjacency: ProductAdjacency::None,
        direction: [-up.x, -up.y, -up.z],
        bottom_open: false,
        faces: faces
            .iter()
            .map(|(g, r, closed, t)| VolumeFace {
                step_id: g.step_id,
                role: *r,
                surface: vol.part.face(g.face).surface.kind_name().to_string(),
                closed: *closed,
                touches: t.clone(),
            })
            .collect(),
        product_adjacent_sides: faces
            .iter()
            .filter(|f| {
                f.1 == FaceRole::Side && f.3.iter().any(|t| matches!(t, Touch::Part { .. }))
            })
            .map(|f| f.0.step_id)
            .collect(),
        depth: 0.0,
        length: 0.0,
        width: 0.0,
        corner_radii: Vec::new(),
    };
    let touches_part = |i: usize| faces[i].3.iter().any(|t| matches!(t, Touch::Part { .. }));
    let side_part = sides.iter().any(|&i| faces[i].2 && touches_part(i));
    let bottom_part =
        (0..faces.len()).any(|i| faces[i].1 == FaceRole::Bottom && faces[i].2 && touches_part(i));
    c.product_adjacency = match (side_part, bottom_part) {
        (false, false) => ProductAdjacency::None,
        (true, false) => ProductAdjacency::Side,
        (false, true) => ProductAdjacency::Bottom,
        (true, true) => ProductAdjacency::SideAndBottom,
    };
    let unknown = |mut c: Classification, why: &str| {
        c.kind = VolumeType::Unknown;
        c.reason = Some(why.to_string());
        c
    };
    if faces.iter().any(|f| f.1 == FaceRole::Other) {
        return unknown(
            c,
            "not a 2.5D volume along the tool direction (a face is neither top, bottom nor side)",
        );
    }
    if tops.is_empty() || bottoms.is_empty() || sides.is_empty() {
        return unknown(c, "no top, bottom or side faces along the tool direction");
    }
    let top_h = tops
        .iter()
        .map(|g| height(g))
        .fold(f64::NEG_INFINITY, f64::max);
    let bot_h = bottoms
        .iter()
        .map(|g| height(g))
        .fold(f64::INFINITY, f64::min);
    c.depth = top_h - bot_h;
    if tops.iter().any(|g| (height(g) - top_h).abs() > tol.lin) {
        return unknown(c, "access faces at several heights");
    }
    if bottoms.iter().any(|g| (height(g) - bot_h).abs() > tol.lin) {
        return unknown(c, "stepped bottom: bottom faces at several heights");
    }
    // Profile from the top face(s), in a frame whose z is up.
    let frame = tops[0].planar.as_ref().expect("planar top").frame;
    let profile = MultiPolygon::new(
        tops.iter()
            .flat_map(|g| g.planar.as_ref().expect("planar").polygon_in(&frame).0)
            .collect(),
    );
    if let Some(r) = profile.minimum_rotated_rect() {
        let p: Vec<geo::Coord<f64>> = r.exterior().coords().copied().collect();
        let a = ((p[1].x - p[0].x).powi(2) + (p[1].y - p[0].y).powi(2)).sqrt();
        let b = ((p[2].x - p[1].x).powi(2) + (p[2].y - p[1].y).powi(2)).sqrt();
        c.length = a.max(b);
        c.width = a.min(b);
    }
    if faces.iter().any(|f| f.1 == FaceRole::Top && f.2) {
        return unknown(c, "the access face is closed");
    }
    if overlaps_material(&profile, &frame, bot_h, top_h, up, part, part_faces, tol) {
        return unknown(c, "overlaps part material");
    }
    c.bottom_open = !(0..faces.len()).any(|i| faces[i].1 == FaceRole::Bottom && faces[i].2);
    // Sides in cyclic order; corner radii looked through.
    let side_set: HashSet<FaceId> = sides.iter().map(|&i| faces[i].0.face).collect();
    let index_of = |f: FaceId| sides.iter().copied().find(|&i| faces[i].0.face == f);
    let mut order: Vec<usize> = vec![sides[0]];
    loop {
        let last = faces[*order.last().expect("start")].0.face;
        let next = graph
            .neighbours(last)
            .filter(|(g, _)| side_set.contains(g))
            .filter_map(|(g, _)| index_of(g))
            .find(|i| !order.contains(i));
        match next {
            Some(n) => order.push(n),
            None => break,
        }
    }
    if order.len() != sides.len() {
        return unknown(c, "the profile has islands or several loops");
    }
    let curved: Vec<usize> = order
        .iter()
        .copied()
        .filter(|&i| faces[i].0.planar.is_none())
        .collect();
    if sides.len() == 1 && curved.len() == 1 && faces[sides[0]].0.cylinder.is_some() {
        c.corner_radii.clear();
        return pick(c, &[VolumeType::Hole], vol.current, priority);
    }
    // A corner radius: a cylinder tangent to the sides before and after it.
    let mut free = false;
    for &i in &curved {
        let f = faces[i].0.face;
        let tangent = graph
            .neighbours(f)
            .filter(|(g, a)| side_set.contains(g) && a.convexity == Convexity::Smooth)
            .count();
        match faces[i].0.cylinder {
            Some((_, _, r, _)) if tangent >= 2 => c.corner_radii.push(r),
            _ => free = true,
        }
    }
    let planar_sides: Vec<usize> = order
        .iter()
        .copied()
        .filter(|&i| faces[i].0.planar.is_some())
        .collect();
    let closed: Vec<bool> = planar_sides.iter().map(|&i| faces[i].2).collect();
    let n = closed.len();
    let all = closed.iter().all(|&x| x) && curved.iter().all(|&i| faces[i].2 || !free);
    let none = !closed.iter().any(|&x| x);
    let candidates: Vec<VolumeType> = if all {
        match (free, c.bottom_open) {
            (false, false) => vec![VolumeType::Pocket],
            (false, true) => vec![VolumeType::Passage],
            (true, false) => vec![VolumeType::FreePocket],
            (true, true) => vec![VolumeType::FreePassage],
        }
    } else if none {
        if c.bottom_open {
            return unknown(c, "no face is closed: nothing bounds it");
        }
        vec![VolumeType::Face]
    } else if free {
        vec![VolumeType::FreeStep]
    } else {
        // Runs of closed sides around the profile.
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
        let normal = |i: usize| {
            faces[planar_sides[i]]
                .0
                .planar
                .as_ref()
                .expect("planar")
                .normal()
        };
        match runs.as_slice() {
            [run] => {
                let mut v = Vec::new();
                if run.len() == n - 1 {
                    v.push(VolumeType::BlindSlot);
                }
                if run.len() == 2 && normal(run[0]).dot(&normal(run[1])).abs() < 0.5 {
                    v.push(VolumeType::CornerNotch);
                }
                v.push(VolumeType::Step);
                v
            }
            [a, b]
                if a.len() == 1 && b.len() == 1 && normal(a[0]).dot(&normal(b[0])) < -tol.cos =>
            {
                vec![VolumeType::ThroughSlot]
            }
            _ => {
                return unknown(
                    c,
                    "closed sides in separate runs that are not two opposite sides",
                )
            }
        }
    };
    pick(c, &candidates, vol.current, priority)
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
#[allow(clippy::too_many_arguments)]
fn overlaps_material(
    profile: &MultiPolygon<f64>,
    frame: &thinwall_geom::Frame,
    bot_h: f64,
    top_h: f64,
    up: &Vector3,
    part: &Part,
    part_faces: &[FaceGeom],
    tol: &Tol,
) -> bool {
    let Some(rect) = profile.bounding_rect() else {
        return false;
    };
    let margin = tol.lin * 10.0;
    for g in part_faces {
        let mut pts = face_points(part, g.face);
        // Also a point inside a planar face, for faces crossing the volume
        // without a boundary point in it (a floor the volume cuts through).
        if let Some(pf) = &g.planar {
            use geo::InteriorPoint;
            if let Some(ip) = pf.polygon_in(&pf.frame).interior_point() {
                pts.push(pf.frame.to_world(&Vector3::new(ip.x(), ip.y(), 0.0)));
            }
        }
        for p in pts {
            let h = p.coords.dot(up);
            if h <= bot_h + margin || h >= top_h - margin {
                continue;
            }
            let l = frame.to_local(&p);
            if l.x < rect.min().x || l.x > rect.max().x || l.y < rect.min().y || l.y > rect.max().y
            {
                continue;
            }
            let q = geo::Point::new(l.x, l.y);
            if profile.contains(&q)
                && profile
                    .0
                    .iter()
                    .all(|poly| Euclidean::distance(&q, poly.exterior()) > margin)
            {
                return true;
            }
        }
    }
    false
}
