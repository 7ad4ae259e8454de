//! Curved walls: material between two coaxial cylinders, or two coaxial
//! cones with parallel generators (issue 18).
//!
//! A cylinder is a cone of half-angle 0, so both are one *family* of
//! surfaces of revolution: one axis line, one half-angle α, and per surface
//! an *offset*, its distance across the generators from a reference cone
//! (for cylinders, the radius). Two surfaces of a family are parallel, the
//! offsets' difference their distance. A convex side (outward normal away
//! from the axis) pairs with the concave sides below it, nearest first, as
//! opposed planes do in `walls`: each face is a polygon in its
//! (angle, generator) coordinates, and where the polygons overlap, the
//! faces bound one slab. Coaxial faces at one offset (a skin split by
//! stringers) make one side, as coplanar faces do.
//!
//! The wall's region is *developed*: x is the arc length at the
//! mid-surface's radius (at the region's centre), y the distance along the
//! generator, both from the region's centre. Its `frame` is the tangent
//! frame of side 0 there (x along the arc, y along the generator, z the
//! outward normal), so a figure taken in that frame is the developed one.

pub use crate::wall::{CurvedWall, Development, Revolution, RevolutionDevelopment};

use crate::config::Config;
use geo::{Area, BooleanOps, BoundingRect, Centroid, Coord, LineString, MapCoords, MultiPolygon};
use serde::{Deserialize, Serialize};
use std::f64::consts::{PI, TAU};
use thinwall_analysis::polygon::{face_loops, intersect, map_loops, narrow_width, FaceLoops};
use thinwall_analysis::PartAnalysis;
use thinwall_brep::FaceId;
use thinwall_geom::{Frame, Point3, Surface, Vector3};

/// A curved wall's sides must curve gently: the mid-surface's radius at
/// least this many thicknesses (a boss around a hole is not a wall).
pub const MIN_RADIUS_TO_THICKNESS: f64 = 3.0;

/// Normals sampled along a free-form wall's centre line for its access
/// range.
const RANGE_SAMPLES: usize = 32;

/// Longest step along an arc when an outline is drawn in 3D, radians.
const OUTLINE_STEP: f64 = PI / 180.0;

impl Revolution {
    fn new(origin: Point3, axis: Vector3, half_angle: f64) -> Self {
        let u = thinwall_geom::frame::any_perpendicular(&axis);
        Self {
            origin,
            axis,
            u,
            v: axis.cross(&u),
            half_angle,
        }
    }

    /// (θ in (−π, π], s, offset) of a point.
    pub fn local(&self, p: &Point3) -> (f64, f64, f64) {
        let d = p - self.origin;
        let h = d.dot(&self.axis);
        let radial = d - self.axis * h;
        let rho = radial.norm();
        let theta = radial.dot(&self.v).atan2(radial.dot(&self.u));
        let (sa, ca) = self.half_angle.sin_cos();
        (theta, rho * sa + h * ca, rho * ca - h * sa)
    }

    /// The point at (θ, s, offset).
    pub fn world(&self, theta: f64, s: f64, off: f64) -> Point3 {
        let (sa, ca) = self.half_angle.sin_cos();
        let rho = off * ca + s * sa;
        let h = s * ca - off * sa;
        self.origin + self.radial(theta) * rho + self.axis * h
    }

    fn radial(&self, theta: f64) -> Vector3 {
        self.u * theta.cos() + self.v * theta.sin()
    }

    /// The unit normal at angle θ, pointing to larger offsets.
    pub fn normal(&self, theta: f64) -> Vector3 {
        let (sa, ca) = self.half_angle.sin_cos();
        self.radial(theta) * ca - self.axis * sa
    }

    /// The unit generator at angle θ (towards larger s).
    pub fn generator(&self, theta: f64) -> Vector3 {
        let (sa, ca) = self.half_angle.sin_cos();
        self.radial(theta) * sa + self.axis * ca
    }

    /// The unit tangent along the arc at angle θ.
    pub fn tangent(&self, theta: f64) -> Vector3 {
        self.v * theta.cos() - self.u * theta.sin()
    }

    /// The distance from the axis at (s, offset), mm.
    pub fn radius(&self, s: f64, off: f64) -> f64 {
        let (sa, ca) = self.half_angle.sin_cos();
        off * ca + s * sa
    }
}

/// What the report shows of a curved wall's mid-surface.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct MidSurface {
    /// `cylinder`, `cone`, or `offset` (between free-form faces that are
    /// offsets of each other).
    pub kind: String,
    /// Cylinders and cones: a point on the axis and the axis (the radius
    /// grows along it for a cone), mm.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub axis_point: Option<[f64; 3]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub axis: Option<[f64; 3]>,
    /// Cylinders and cones: the mid-surface's distance from the axis at
    /// the region's centre, mm.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub radius: Option<f64>,
    /// The point of the mid-surface at the region's centre, and side 0's
    /// outward normal there.
    pub centre: [f64; 3],
    pub normal: [f64; 3],
    /// Cones: the half-angle, degrees.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub half_angle_deg: Option<f64>,
    /// Cylinders and cones: where angles are measured from (unit, normal
    /// to the axis), and the wall's angle range about the axis from it,
    /// degrees (right-handed).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reference: Option<[f64; 3]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub angle_range_deg: Option<[f64; 2]>,
    /// Offset walls: the thinnest and thickest distance sampled between
    /// the sides, mm.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub thickness_range: Option<[f64; 2]>,
}

impl RevolutionDevelopment {
    /// The angle at developed x.
    fn theta(&self, x: f64) -> f64 {
        self.theta_c + x / self.r_mid
    }

    fn to_world(&self, x: f64, y: f64, off: f64) -> Point3 {
        self.rev.world(self.theta(x), self.s_c + y, off)
    }

    fn develop(&self, p: &Point3) -> (f64, f64, f64) {
        let (theta, s, off) = self.rev.local(p);
        (wrap(theta - self.theta_c) * self.r_mid, s - self.s_c, off)
    }

    fn axes(&self, x: f64) -> (Vector3, Vector3) {
        let t = self.theta(x);
        (self.rev.tangent(t), self.rev.generator(t))
    }
}

impl Development {
    /// The point at developed (x, y) and offset `off`.
    pub fn to_world(&self, x: f64, y: f64, off: f64) -> Point3 {
        match self {
            Development::Revolution(r) => r.to_world(x, y, off),
            Development::Offset(o) => o.to_world(x, y, off),
        }
    }

    /// Developed (x, y) and offset of a point.
    pub fn develop(&self, p: &Point3) -> (f64, f64, f64) {
        match self {
            Development::Revolution(r) => r.develop(p),
            Development::Offset(o) => o.develop(p),
        }
    }

    /// The unit normal towards larger offsets at developed (x, y).
    pub fn normal(&self, x: f64, y: f64) -> Vector3 {
        match self {
            Development::Revolution(r) => r.rev.normal(r.theta(x)),
            Development::Offset(o) => o.normal(x, y),
        }
    }

    /// The developed x and y directions at (x, y) (unit; x × y = normal).
    pub fn axes(&self, x: f64, y: f64) -> (Vector3, Vector3) {
        match self {
            Development::Revolution(r) => r.axes(x),
            Development::Offset(o) => o.axes(x, y),
        }
    }

    /// Longest step along x when an outline is drawn in 3D, mm.
    fn outline_step(&self) -> f64 {
        match self {
            Development::Revolution(r) => OUTLINE_STEP * r.r_mid,
            Development::Offset(o) => o.outline_step(),
        }
    }
}

impl CurvedWall {
    /// The point at developed (x, y) at offset `off`.
    pub fn to_world(&self, x: f64, y: f64, off: f64) -> Point3 {
        self.dev.to_world(x, y, off)
    }

    /// Developed (x, y) and offset of a point.
    pub fn develop(&self, p: &Point3) -> (f64, f64, f64) {
        self.dev.develop(p)
    }

    pub fn mid_offset(&self) -> f64 {
        0.5 * (self.off[0] + self.off[1])
    }

    /// A region's outer outlines in 3D at offset `off`, drawn in steps.
    pub fn outline(&self, region: &MultiPolygon<f64>, off: f64) -> Vec<Point3> {
        let step = self.dev.outline_step();
        let mut out = Vec::new();
        for ring in region.0.iter().map(|p| p.exterior()) {
            for w in ring.0.windows(2) {
                let n = ((w[1].x - w[0].x).abs() / step).ceil().max(1.0) as usize;
                for k in 0..n {
                    let t = k as f64 / n as f64;
                    let c = w[0] + (w[1] - w[0]) * t;
                    out.push(self.to_world(c.x, c.y, off));
                }
            }
        }
        out
    }

    /// Side `s`'s outward normal at developed (x, y).
    pub fn side_normal(&self, s: usize, x: f64, y: f64) -> Vector3 {
        let n = self.dev.normal(x, y);
        if s == 0 {
            n
        } else {
            -n
        }
    }

    /// The tangent plane of side `s` at the point of it nearest `p`: a
    /// point and the side's outward normal.
    pub fn tangent_plane(&self, s: usize, p: &Point3) -> (Point3, Vector3) {
        let (x, y, _) = self.develop(p);
        (self.to_world(x, y, self.off[s]), self.side_normal(s, x, y))
    }

    /// Whether a point lies within the slab between the sides (`tol` mm).
    pub fn within(&self, p: &Point3, tol: f64) -> bool {
        let (_, _, off) = self.develop(p);
        off <= self.off[0] + tol && off >= self.off[1] - tol
    }

    /// Per side, its outward normals at both ends of the region's
    /// developed x range, through the centre (the normal sweeps between
    /// them).
    ///
    /// A free-form side's normal need not sweep monotonically (an S-shaped
    /// wall turns back): its two normals are the furthest apart of those
    /// sampled along the line.
    pub fn access_range(&self, region: &MultiPolygon<f64>) -> [[[f64; 3]; 2]; 2] {
        let (x0, x1) = x_range(region);
        let (_, yc) = centre(region);
        let xyz = |v: Vector3| [v.x, v.y, v.z];
        let (a, b) = match self.dev {
            Development::Revolution(_) => (x0, x1),
            Development::Offset(_) => {
                let xs: Vec<f64> = (0..=RANGE_SAMPLES)
                    .map(|k| x0 + (x1 - x0) * k as f64 / RANGE_SAMPLES as f64)
                    .collect();
                let n: Vec<Vector3> = xs.iter().map(|&x| self.dev.normal(x, yc)).collect();
                let mut best = (x0, x1, -2.0);
                for i in 0..n.len() {
                    for j in i + 1..n.len() {
                        let apart = 1.0 - n[i].dot(&n[j]);
                        if apart > best.2 {
                            best = (xs[i], xs[j], apart);
                        }
                    }
                }
                (best.0, best.1)
            }
        };
        [0, 1].map(|s| {
            [
                xyz(self.side_normal(s, a, yc)),
                xyz(self.side_normal(s, b, yc)),
            ]
        })
    }

    pub fn mid_surface(&self, region: &MultiPolygon<f64>) -> MidSurface {
        let xyz = |v: Vector3| [v.x, v.y, v.z];
        let (cx, cy) = centre(region);
        let centre = self.to_world(cx, cy, self.mid_offset());
        let normal = xyz(self.dev.normal(cx, cy));
        match &self.dev {
            Development::Revolution(RevolutionDevelopment {
                rev,
                theta_c,
                r_mid,
                ..
            }) => {
                let (x0, x1) = x_range(region);
                let cone = rev.half_angle.abs() > 0.0;
                MidSurface {
                    kind: if cone { "cone" } else { "cylinder" }.into(),
                    axis_point: Some(xyz(rev.origin.coords)),
                    axis: Some(xyz(rev.axis)),
                    radius: Some(*r_mid),
                    centre: xyz(centre.coords),
                    normal,
                    half_angle_deg: cone.then(|| rev.half_angle.to_degrees()),
                    reference: Some(xyz(rev.u)),
                    angle_range_deg: Some([
                        (theta_c + x0 / r_mid).to_degrees(),
                        (theta_c + x1 / r_mid).to_degrees(),
                    ]),
                    thickness_range: None,
                }
            }
            Development::Offset(_) => MidSurface {
                kind: "offset".into(),
                axis_point: None,
                axis: None,
                radius: None,
                centre: xyz(centre.coords),
                normal,
                half_angle_deg: None,
                reference: None,
                angle_range_deg: None,
                thickness_range: self.measured.map(|(a, b)| [a, b]),
            },
        }
    }
}

/// The developed x range of a region.
fn x_range(region: &MultiPolygon<f64>) -> (f64, f64) {
    region
        .bounding_rect()
        .map_or((0.0, 0.0), |r| (r.min().x, r.max().x))
}

/// A region's centroid (the origin when it has none).
fn centre(region: &MultiPolygon<f64>) -> (f64, f64) {
    region.centroid().map_or((0.0, 0.0), |p| (p.x(), p.y()))
}

/// An angle difference brought into (−π, π].
fn wrap(d: f64) -> f64 {
    let mut d = d % TAU;
    if d > PI {
        d -= TAU;
    } else if d <= -PI {
        d += TAU;
    }
    d
}

/// A cylinder or cone face in its family's coordinates.
struct RevFace {
    face: FaceId,
    /// Outward normal away from the axis.
    convex: bool,
    family: usize,
    off: f64,
    /// Its polygon in (θ, s), θ continuous over the face (cut in the
    /// widest gap between its boundary's angles).
    poly: MultiPolygon<f64>,
}

/// The family of a face's surface: its axis (radius growing along it for
/// a cone) and half-angle.
fn surface_axis(surface: &Surface) -> Option<(Point3, Vector3, f64)> {
    match surface {
        Surface::Cylinder { frame, .. } => Some((frame.origin, frame.z, 0.0)),
        Surface::Cone {
            frame, semi_angle, ..
        } => {
            let (axis, a) = if *semi_angle >= 0.0 {
                (frame.z, *semi_angle)
            } else {
                (-frame.z, -semi_angle)
            };
            Some((frame.origin, axis, a))
        }
        _ => None,
    }
}

/// Find the curved walls of a part.
pub fn find_curved_walls(a: &PartAnalysis, config: &Config) -> Vec<crate::wall::Wall> {
    let lin = a.tol().coplanar;
    let cos_tol = config.thresholds.parallel_angle_deg.to_radians().cos();
    let angle_tol = config.thresholds.parallel_angle_deg.to_radians();
    let mut families: Vec<(u32, Revolution)> = Vec::new();
    let mut faces: Vec<RevFace> = Vec::new();
    for f in a.part().face_ids() {
        let face = a.part().face(f);
        let Some((origin, axis, half)) = surface_axis(&face.surface) else {
            continue;
        };
        if a.is_blend_candidate(f) {
            continue; // a fillet or round, not a wall's side
        }
        let body = face.body.0;
        let same = |(b, r): &(u32, Revolution)| {
            let d = origin - r.origin;
            let along = if half == 0.0 {
                r.axis.dot(&axis).abs()
            } else {
                r.axis.dot(&axis)
            };
            *b == body
                && along > cos_tol
                && (r.half_angle - half).abs() < angle_tol
                && (d - r.axis * d.dot(&r.axis)).norm() < lin
        };
        let family = families.iter().position(same).unwrap_or_else(|| {
            families.push((body, Revolution::new(origin, axis, half)));
            families.len() - 1
        });
        let rev = families[family].1;
        let Some((off, poly)) = face_polygon(a, f, &rev) else {
            continue;
        };
        faces.push(RevFace {
            face: f,
            convex: face.same_sense,
            family,
            off,
            poly,
        });
    }
    let mut walls = Vec::new();
    for (fam, (_, rev)) in families.iter().enumerate() {
        let members: Vec<&RevFace> = faces.iter().filter(|f| f.family == fam).collect();
        walls.extend(pair_family(a, rev, &members, lin, config));
    }
    walls
}

/// Whether a face goes all the way round its axis (its polygon is then the
/// whole turn): it has a seam (an edge its loops run twice), or a loop
/// winds round the axis. Its boundary samples cannot tell: they lie a few
/// degrees apart.
fn goes_round(a: &PartAnalysis, f: FaceId, loops: &FaceLoops, rev: &Revolution) -> bool {
    let mut edges: Vec<_> = a
        .part()
        .face(f)
        .loops
        .iter()
        .flat_map(|&l| a.part().loop_(l).coedges.iter().map(|c| c.edge))
        .collect();
    let n = edges.len();
    edges.sort();
    edges.dedup();
    let winds = |ring: &Vec<Point3>| {
        let t: Vec<f64> = ring.iter().map(|p| rev.local(p).0).collect();
        let turn: f64 = (0..t.len())
            .map(|k| wrap(t[(k + 1) % t.len()] - t[k]))
            .sum();
        turn.abs() > PI
    };
    edges.len() < n || loops.outer.iter().chain(&loops.inner).any(winds)
}

/// A face's offset and its polygon in (θ, s).
fn face_polygon(a: &PartAnalysis, f: FaceId, rev: &Revolution) -> Option<(f64, MultiPolygon<f64>)> {
    let loops = face_loops(a.part(), f);
    let pts: Vec<&Point3> = loops.outer.iter().chain(&loops.inner).flatten().collect();
    let locals: Vec<(f64, f64, f64)> = pts.iter().map(|p| rev.local(p)).collect();
    let off = locals.iter().map(|l| l.2).sum::<f64>() / locals.len().max(1) as f64;
    let mut angles: Vec<f64> = locals.iter().map(|l| l.0).collect();
    angles.sort_by(f64::total_cmp);
    let (first, last) = (*angles.first()?, *angles.last()?);
    // The cut: the middle of the widest gap between boundary angles.
    let (mut gap, mut cut) = (TAU - (last - first), last + 0.5 * (TAU - (last - first)));
    for w in angles.windows(2) {
        if w[1] - w[0] > gap {
            gap = w[1] - w[0];
            cut = 0.5 * (w[0] + w[1]);
        }
    }
    let unwrap = |theta: f64| cut + (theta - cut).rem_euclid(TAU) - TAU;
    let ss: Vec<f64> = locals.iter().map(|l| l.1).collect();
    let (s0, s1) = ss
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &s| {
            (lo.min(s), hi.max(s))
        });
    if goes_round(a, f, &loops, rev) {
        // Closed around the axis: the whole turn.
        let c = |x: f64, y: f64| Coord { x, y };
        let ring = LineString::new(vec![
            c(cut - TAU, s0),
            c(cut, s0),
            c(cut, s1),
            c(cut - TAU, s1),
            c(cut - TAU, s0),
        ]);
        return Some((
            off,
            MultiPolygon::new(vec![geo::Polygon::new(ring, vec![])]),
        ));
    }
    let poly = map_loops(&loops, |p| {
        let (t, s, _) = rev.local(p);
        Coord { x: unwrap(t), y: s }
    });
    Some((off, poly))
}

/// A polygon shifted by whole turns so it can overlap one near θ = 0.
fn shifted(p: &MultiPolygon<f64>, turns: f64) -> MultiPolygon<f64> {
    p.map_coords(|c| Coord {
        x: c.x + turns * TAU,
        y: c.y,
    })
}

/// Faces at one offset of a family: one side surface.
struct SideSurface {
    off: f64,
    convex: bool,
    /// Indices into the family's members.
    faces: Vec<usize>,
}

/// A convex and a concave surface bounding one slab, while their faces
/// and region (in (θ, s)) are collected.
struct Group {
    surfaces: (usize, usize),
    sides: [Vec<FaceId>; 2],
    parts: Vec<geo::Polygon<f64>>,
}

/// Pair the convex faces of one family with the concave ones below them.
fn pair_family(
    a: &PartAnalysis,
    rev: &Revolution,
    members: &[&RevFace],
    lin: f64,
    config: &Config,
) -> Vec<crate::wall::Wall> {
    let mut surfaces: Vec<SideSurface> = Vec::new();
    for (i, f) in members.iter().enumerate() {
        match surfaces
            .iter_mut()
            .find(|s| s.convex == f.convex && (s.off - f.off).abs() < lin)
        {
            Some(s) => s.faces.push(i),
            None => surfaces.push(SideSurface {
                off: f.off,
                convex: f.convex,
                faces: vec![i],
            }),
        }
    }
    let mut groups: Vec<Group> = Vec::new();
    for (si, outer) in surfaces.iter().enumerate().filter(|(_, s)| s.convex) {
        let mut below: Vec<(usize, f64)> = surfaces
            .iter()
            .enumerate()
            .filter(|(_, s)| !s.convex && s.off < outer.off - lin)
            .map(|(k, s)| (k, outer.off - s.off))
            .collect();
        below.sort_by(|x, y| x.1.total_cmp(&y.1));
        for &fi in &outer.faces {
            pair_face(a, members, fi, si, &surfaces, &below, &mut groups);
        }
    }
    groups
        .into_iter()
        .filter_map(|mut g| {
            g.sides.iter_mut().for_each(|v| v.sort());
            let off = [surfaces[g.surfaces.0].off, surfaces[g.surfaces.1].off];
            build_wall(rev, members, g.sides, off, g.parts, config)
        })
        .collect()
}

/// Pair convex face `fi` (on surface `si`) with the concave surfaces
/// `below` it, nearest first, until it is bounded everywhere; record each
/// pairing's fresh region in its group.
fn pair_face(
    a: &PartAnalysis,
    members: &[&RevFace],
    fi: usize,
    si: usize,
    surfaces: &[SideSurface],
    below: &[(usize, f64)],
    groups: &mut Vec<Group>,
) {
    let min_area = a.tol().min_overlap_area;
    let f = members[fi];
    let own = f.poly.unsigned_area();
    let mut covered: MultiPolygon<f64> = MultiPolygon::new(vec![]);
    for &(k, _) in below {
        if covered.unsigned_area() >= own - min_area {
            break;
        }
        let mut fresh_all = Vec::new();
        let mut partners = Vec::new();
        for g in surfaces[k].faces.iter().map(|&gi| members[gi]) {
            for turns in [-1.0, 0.0, 1.0] {
                let common = intersect(&f.poly, &shifted(&g.poly, turns));
                if common.unsigned_area() <= min_area {
                    continue;
                }
                let fresh = if covered.0.is_empty() {
                    common.clone()
                } else {
                    common.difference(&covered)
                };
                if fresh.unsigned_area() > min_area {
                    if !partners.contains(&g.face) {
                        partners.push(g.face);
                    }
                    fresh_all.extend(fresh.0);
                }
                covered = if covered.0.is_empty() {
                    common
                } else {
                    covered.union(&common)
                };
            }
        }
        if partners.is_empty() {
            continue;
        }
        let slot = match groups.iter().position(|g| g.surfaces == (si, k)) {
            Some(p) => p,
            None => {
                groups.push(Group {
                    surfaces: (si, k),
                    sides: [Vec::new(), Vec::new()],
                    parts: Vec::new(),
                });
                groups.len() - 1
            }
        };
        let g = &mut groups[slot];
        if !g.sides[0].contains(&f.face) {
            g.sides[0].push(f.face);
        }
        for p in partners {
            if !g.sides[1].contains(&p) {
                g.sides[1].push(p);
            }
        }
        g.parts.extend(fresh_all);
    }
}

/// The pieces of a region in (θ, s), each shifted by the whole turns that
/// put it nearest the largest: a wall across the angle's seam (where it
/// falls depends on the surface's frame, so on the pose) stays in one
/// piece, and its centre is its centre.
fn unwrapped(parts: Vec<geo::Polygon<f64>>) -> Vec<geo::Polygon<f64>> {
    let theta = |p: &geo::Polygon<f64>| p.centroid().map_or(0.0, |c| c.x());
    let Some(reference) = parts
        .iter()
        .max_by(|a, b| a.unsigned_area().total_cmp(&b.unsigned_area()))
        .map(theta)
    else {
        return parts;
    };
    parts
        .into_iter()
        .map(|p| {
            let shift = -((theta(&p) - reference) / TAU).round() * TAU;
            if shift == 0.0 {
                p
            } else {
                p.map_coords(|q| Coord {
                    x: q.x + shift,
                    y: q.y,
                })
            }
        })
        .collect()
}

/// A wall from its sides and region in (θ, s), or none when it is too
/// narrow or too tightly curved.
fn build_wall(
    rev: &Revolution,
    members: &[&RevFace],
    sides: [Vec<FaceId>; 2],
    off: [f64; 2],
    parts: Vec<geo::Polygon<f64>>,
    config: &Config,
) -> Option<crate::wall::Wall> {
    let region_ts = MultiPolygon::new(unwrapped(parts));
    let thickness = off[0] - off[1];
    let c = region_ts.centroid()?;
    let (theta_c, s_c) = (c.x(), c.y());
    let r_mid = rev.radius(s_c, 0.5 * (off[0] + off[1]));
    if r_mid < MIN_RADIUS_TO_THICKNESS * thickness {
        return None;
    }
    let develop = |p: &MultiPolygon<f64>, shift: f64| {
        p.map_coords(|q| Coord {
            x: (q.x + shift - theta_c) * r_mid,
            y: q.y - s_c,
        })
    };
    let region = develop(&region_ts, 0.0);
    if narrow_width(&region) < config.thresholds.min_width_to_thickness * thickness {
        return None;
    }
    // Side faces' polygons, each shifted by the whole turns that put it
    // nearest the centre.
    let side_polygons = [0, 1].map(|k| {
        sides[k]
            .iter()
            .filter_map(|&f| members.iter().find(|m| m.face == f))
            .map(|m| {
                let mc = m.poly.centroid().map_or(theta_c, |p| p.x());
                let shift = -((mc - theta_c) / TAU).round() * TAU;
                (m.face, develop(&m.poly, shift))
            })
            .collect()
    });
    let theta_c = wrap(theta_c);
    let curved = CurvedWall {
        dev: Development::Revolution(RevolutionDevelopment {
            rev: *rev,
            theta_c,
            s_c,
            r_mid,
        }),
        off,
        side_polygons,
        measured: None,
    };
    Some(curved.into_wall(sides, region))
}

impl CurvedWall {
    /// The wall: its frame is side 0's tangent frame at the region's
    /// centre (x, y developed, z the outward normal).
    pub(crate) fn into_wall(
        self,
        sides: [Vec<FaceId>; 2],
        region: MultiPolygon<f64>,
    ) -> crate::wall::Wall {
        let (cx, cy) = centre(&region);
        let n = self.dev.normal(cx, cy);
        let (x, y) = self.dev.axes(cx, cy);
        let frame = Frame {
            origin: self.to_world(cx, cy, self.off[0]),
            x,
            y,
            z: n,
        };
        crate::wall::Wall {
            sides,
            normals: [n, -n],
            frame,
            thickness: self.off[0] - self.off[1],
            thickness_range: (self.off[0] - self.off[1], self.off[0] - self.off[1]),
            side1_point: self.to_world(cx, cy, self.off[1]),
            region,
            curved: Some(Box::new(self)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn revolution_coordinates_round_trip() {
        let rev = Revolution::new(Point3::new(1.0, 2.0, 3.0), Vector3::new(0.0, 0.6, 0.8), 0.3);
        let p = rev.world(0.7, 12.0, 4.5);
        let (t, s, o) = rev.local(&p);
        assert!((t - 0.7).abs() < 1e-12 && (s - 12.0).abs() < 1e-12 && (o - 4.5).abs() < 1e-12);
        // Moving along the normal changes the offset only.
        let (_, s2, o2) = rev.local(&(p + rev.normal(0.7) * 2.0));
        assert!((s2 - 12.0).abs() < 1e-12 && (o2 - 6.5).abs() < 1e-12);
        // The tangent frame is right-handed: tangent × generator = normal.
        let n = rev.tangent(0.7).cross(&rev.generator(0.7));
        assert!((n - rev.normal(0.7)).norm() < 1e-12);
    }

    #[test]
    fn wrap_brings_angles_into_one_turn() {
        assert!((wrap(3.0 * PI) - PI).abs() < 1e-12);
        assert!((wrap(-1.5 * PI) - 0.5 * PI).abs() < 1e-12);
        assert!((wrap(0.25)).abs() - 0.25 < 1e-12);
    }
}
