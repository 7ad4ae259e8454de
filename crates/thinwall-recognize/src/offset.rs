//! Free-form walls: material between two free-form faces that are offsets
//! of each other (issue 18).
//!
//! For a free-form face F, points inside it (a grid over its outline in
//! its parameter plane) are carried along F's inward normal onto each
//! nearby free-form face G of the same body (the nearest point of G's
//! surface): where the foot lies inside G, straight behind the point, and
//! G faces the other way, the two bound material there. F and G are a
//! wall's sides when at least half of F's points find G so, and the
//! distances agree within `OFFSET_SPREAD` of their mean (constant
//! thickness by sampling): the thickness is the mean.
//!
//! The region is developed along side 0's surface: x and y are arc lengths
//! on the mid-surface along the iso-parameter curves through the centre of
//! side 0's parameter domain (exact for a surface swept along a straight
//! line, such as an extruded curve; elsewhere the lengths along those two
//! curves). Both sides' outlines are carried onto side 0 along its normal,
//! and where they overlap is the region.

pub use crate::wall::OffsetDevelopment;

use crate::config::Config;
use crate::wall::{CurvedWall, Development};
use geo::{Area, Contains, Coord, MultiPolygon};
use thinwall_analysis::polygon::{face_loops, intersect, map_loops, narrow_width};
use thinwall_analysis::PartAnalysis;
use thinwall_brep::FaceId;
use thinwall_geom::surface::nurbs_normal;
use thinwall_geom::{BoundingBox, NurbsSurface, Point3, Surface, Vector3};

/// The sampled distances between two offset faces agree within this share
/// of their mean (constant thickness, allowing for a file's fitted
/// offsets).
pub const OFFSET_SPREAD: f64 = 0.01;

/// At least this share of a face's sample points must land on the other
/// face for the two to be a wall's sides.
const MIN_SHARE: f64 = 0.5;

/// Sample points per direction of a face's parameter box.
const SAMPLES: usize = 9;

/// Points per direction of the arc-length tables (chords of the
/// mid-surface's iso-curves: relative error about (κ·Δs)²/24).
const TABLE: usize = 4096;

/// Normals within this angle are parallel, radians (the planar pairing's
/// parallel angle is used where the config gives it).
fn cos_parallel(config: &Config) -> f64 {
    config.thresholds.parallel_angle_deg.to_radians().cos()
}

/// A free-form face with what pairing needs.
struct FreeFace {
    face: FaceId,
    body: u32,
    surface: NurbsSurface,
    /// +1 when the outward normal is S_u × S_v, else −1.
    sign: f64,
    /// Its outline in its parameter plane.
    uv: MultiPolygon<f64>,
    /// Points inside it with their outward normals.
    samples: Vec<(Point3, Vector3)>,
    bbox: BoundingBox,
}

impl FreeFace {
    fn new(a: &PartAnalysis, f: FaceId) -> Option<Self> {
        let face = a.part().face(f);
        let Surface::Freeform { nurbs, .. } = &face.surface else {
            return None;
        };
        let sign = if face.same_sense { 1.0 } else { -1.0 };
        let uv = parameter_outline(a, f, nurbs)?;
        let samples = interior_samples(nurbs, &uv, sign);
        let mut bbox = BoundingBox::empty();
        a.boundary_points(f).iter().for_each(|p| bbox.add_point(p));
        Some(Self {
            face: f,
            body: face.body.0,
            surface: nurbs.clone(),
            sign,
            uv,
            samples,
            bbox,
        })
    }

    fn normal(&self, u: f64, v: f64) -> Option<Vector3> {
        nurbs_normal(&self.surface, u, v).map(|n| n * self.sign)
    }

    /// Whether parameters (u, v) lie inside the face.
    fn contains(&self, u: f64, v: f64) -> bool {
        self.uv.contains(&geo::Point::new(u, v))
    }
}

/// A face's loops mapped into its surface's parameter plane.
fn parameter_outline(a: &PartAnalysis, f: FaceId, s: &NurbsSurface) -> Option<MultiPolygon<f64>> {
    let loops = face_loops(a.part(), f);
    let mut hint = None;
    let out = map_loops(&loops, |p| {
        let (u, v, _) = s.invert(p, hint);
        hint = Some((u, v));
        Coord { x: u, y: v }
    });
    (out.unsigned_area() > 0.0).then_some(out)
}

/// Grid points of the outline's parameter box that lie inside it, on the
/// surface, with their outward normals.
fn interior_samples(s: &NurbsSurface, uv: &MultiPolygon<f64>, sign: f64) -> Vec<(Point3, Vector3)> {
    use geo::BoundingRect;
    let Some(r) = uv.bounding_rect() else {
        return Vec::new();
    };
    let mut out = Vec::new();
    for i in 0..SAMPLES {
        for j in 0..SAMPLES {
            let u = r.min().x + r.width() * (i as f64 + 0.5) / SAMPLES as f64;
            let v = r.min().y + r.height() * (j as f64 + 0.5) / SAMPLES as f64;
            if !uv.contains(&geo::Point::new(u, v)) {
                continue;
            }
            if let Some(n) = nurbs_normal(s, u, v) {
                out.push((s.eval(u, v).point, n * sign));
            }
        }
    }
    out
}

/// The distances from `f`'s samples straight behind them to `g`, where
/// `g` is there and faces the other way.
fn distances_behind(f: &FreeFace, g: &FreeFace, cos: f64, lin: f64) -> Vec<f64> {
    let mut out = Vec::new();
    let mut hint = None;
    for (p, n) in &f.samples {
        let (u, v, d) = g.surface.invert(p, hint);
        hint = Some((u, v));
        if d <= lin || !g.contains(u, v) {
            continue;
        }
        let q = g.surface.eval(u, v).point;
        let behind = (p - q) / d;
        let facing = g.normal(u, v).is_some_and(|m| m.dot(n) < -cos);
        if behind.dot(n) > cos && facing {
            out.push(d);
        }
    }
    out
}

/// Mean, least and greatest of the distances when they agree within
/// `OFFSET_SPREAD`.
fn constant(ds: &[f64]) -> Option<(f64, f64, f64)> {
    let mean = ds.iter().sum::<f64>() / ds.len().max(1) as f64;
    let lo = ds.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = ds.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    (!ds.is_empty() && hi - lo <= OFFSET_SPREAD * mean).then_some((mean, lo, hi))
}

/// Find the walls between free-form faces that are offsets of each other.
pub fn find_offset_walls(a: &PartAnalysis, config: &Config) -> Vec<crate::wall::Wall> {
    let faces: Vec<FreeFace> = a
        .part()
        .face_ids()
        .filter(|&f| !a.is_blend_candidate(f))
        .filter_map(|f| FreeFace::new(a, f))
        .filter(|f| !f.samples.is_empty())
        .collect();
    let (cos, lin) = (cos_parallel(config), a.tol().coplanar);
    let reach = a.bounding_box().diagonal() / config.thresholds.min_extent_to_thickness;
    let mut walls = Vec::new();
    let mut used = vec![false; faces.len()];
    for i in 0..faces.len() {
        if used[i] {
            continue;
        }
        // The nearest partner by mean distance, both ways constant.
        let best = (0..faces.len())
            .filter(|&j| j != i && !used[j] && faces[j].body == faces[i].body)
            .filter(|&j| boxes_near(&faces[i].bbox, &faces[j].bbox, reach))
            .filter_map(|j| {
                let there = distances_behind(&faces[i], &faces[j], cos, lin);
                let back = distances_behind(&faces[j], &faces[i], cos, lin);
                let enough = |d: &Vec<f64>, k: usize| {
                    d.len() as f64 >= MIN_SHARE * faces[k].samples.len() as f64
                };
                if !enough(&there, i) || !enough(&back, j) {
                    return None;
                }
                let all: Vec<f64> = there.iter().chain(&back).copied().collect();
                constant(&all).map(|c| (j, c))
            })
            .min_by(|x, y| x.1 .0.total_cmp(&y.1 .0));
        let Some((j, (t, lo, hi))) = best else {
            continue;
        };
        if let Some(w) = build(a, &faces[i], &faces[j], t, (lo, hi), config) {
            used[i] = true;
            used[j] = true;
            walls.push(w);
        }
    }
    walls
}

fn boxes_near(a: &BoundingBox, b: &BoundingBox, reach: f64) -> bool {
    (0..3).all(|k| a.min[k] <= b.max[k] + reach && b.min[k] <= a.max[k] + reach)
}

/// The wall between side 0 `f` and side 1 `g`, `t` apart.
fn build(
    a: &PartAnalysis,
    f: &FreeFace,
    g: &FreeFace,
    t: f64,
    measured: (f64, f64),
    config: &Config,
) -> Option<crate::wall::Wall> {
    let dev = OffsetDevelopment::new(f.surface.clone(), f.sign, &f.uv, -0.5 * t)?;
    let develop_face = |face: FaceId| -> MultiPolygon<f64> {
        map_loops(&face_loops(a.part(), face), |p| {
            let (x, y, _) = dev.develop(p);
            Coord { x, y }
        })
    };
    let (p0, p1) = (develop_face(f.face), develop_face(g.face));
    let region = intersect(&p0, &p1);
    if region.unsigned_area() <= a.tol().min_overlap_area
        || narrow_width(&region) < config.thresholds.min_width_to_thickness * t
    {
        return None;
    }
    let curved = CurvedWall {
        dev: Development::Offset(Box::new(dev)),
        off: [0.0, -t],
        side_polygons: [vec![(f.face, p0)], vec![(g.face, p1)]],
        measured: Some(measured),
    };
    Some(curved.into_wall([vec![f.face], vec![g.face]], region))
}

impl OffsetDevelopment {
    fn new(surface: NurbsSurface, sign: f64, uv: &MultiPolygon<f64>, mid: f64) -> Option<Self> {
        use geo::BoundingRect;
        let r = uv.bounding_rect()?;
        let (uc, vc) = (0.5 * (r.min().x + r.max().x), 0.5 * (r.min().y + r.max().y));
        let ((u0, u1), (v0, v1)) = surface.domain();
        let mut d = Self {
            surface,
            sign,
            u_table: Vec::new(),
            v_table: Vec::new(),
            length: 0.0,
        };
        d.u_table = d.table(u0, u1, uc, |t| (t, vc), mid)?;
        d.v_table = d.table(v0, v1, vc, |t| (uc, t), mid)?;
        d.length = arc_span(&d.u_table).max(arc_span(&d.v_table));
        Some(d)
    }

    /// Arc lengths on the mid-surface (offset `mid`) along a parameter line
    /// from `t0` to `t1`, from 0 at `tc`.
    fn table(
        &self,
        t0: f64,
        t1: f64,
        tc: f64,
        at: impl Fn(f64) -> (f64, f64),
        mid: f64,
    ) -> Option<Vec<(f64, f64)>> {
        let mut out = Vec::with_capacity(TABLE + 1);
        let mut s = 0.0;
        let mut prev: Option<Point3> = None;
        for k in 0..=TABLE {
            let t = t0 + (t1 - t0) * k as f64 / TABLE as f64;
            let (u, v) = at(t);
            let p = self.surface.eval(u, v).point + self.normal_uv(u, v)? * mid;
            if let Some(q) = prev {
                s += (p - q).norm();
            }
            prev = Some(p);
            out.push((t, s));
        }
        let at_c = lookup(&out, tc, false);
        out.iter_mut().for_each(|e| e.1 -= at_c);
        Some(out)
    }

    fn normal_uv(&self, u: f64, v: f64) -> Option<Vector3> {
        nurbs_normal(&self.surface, u, v).map(|n| n * self.sign)
    }

    fn params(&self, x: f64, y: f64) -> (f64, f64) {
        (
            lookup(&self.u_table, x, true),
            lookup(&self.v_table, y, true),
        )
    }

    pub fn to_world(&self, x: f64, y: f64, off: f64) -> Point3 {
        let (u, v) = self.params(x, y);
        self.surface.eval(u, v).point + self.normal_uv(u, v).unwrap_or_default() * off
    }

    pub fn develop(&self, p: &Point3) -> (f64, f64, f64) {
        let (u, v, _) = self.surface.invert(p, None);
        let q = self.surface.eval(u, v).point;
        let n = self.normal_uv(u, v).unwrap_or_default();
        (
            lookup(&self.u_table, u, false),
            lookup(&self.v_table, v, false),
            (p - q).dot(&n),
        )
    }

    pub fn normal(&self, x: f64, y: f64) -> Vector3 {
        let (u, v) = self.params(x, y);
        self.normal_uv(u, v).unwrap_or_default()
    }

    /// The developed directions at (x, y): along u, and along v made
    /// square to it (x × y = the normal).
    pub fn axes(&self, x: f64, y: f64) -> (Vector3, Vector3) {
        let (u, v) = self.params(x, y);
        let sp = self.surface.eval(u, v);
        let n = self.normal_uv(u, v).unwrap_or_default();
        let ex = sp.du.try_normalize(1e-14).unwrap_or_default();
        (ex, n.cross(&ex))
    }

    pub fn outline_step(&self) -> f64 {
        self.length / 256.0
    }
}

/// The span of a table's arc lengths.
fn arc_span(t: &[(f64, f64)]) -> f64 {
    t.last().map_or(0.0, |l| l.1) - t.first().map_or(0.0, |f| f.1)
}

/// Interpolate a monotone table: arc length at a parameter, or (`inverse`)
/// the parameter at an arc length; clamped to its ends.
fn lookup(table: &[(f64, f64)], key: f64, inverse: bool) -> f64 {
    let k = |e: &(f64, f64)| if inverse { e.1 } else { e.0 };
    let val = |e: &(f64, f64)| if inverse { e.0 } else { e.1 };
    let i = table
        .partition_point(|e| k(e) < key)
        .clamp(1, table.len() - 1);
    let (a, b) = (&table[i - 1], &table[i]);
    let span = k(b) - k(a);
    let t = if span.abs() > 0.0 {
        ((key - k(a)) / span).clamp(0.0, 1.0)
    } else {
        0.0
    };
    val(a) + (val(b) - val(a)) * t
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tables_interpolate_both_ways() {
        let t = vec![(0.0, -1.0), (0.5, 0.0), (1.0, 2.0)];
        assert!((lookup(&t, 0.75, false) - 1.0).abs() < 1e-12);
        assert!((lookup(&t, 1.0, true) - 0.75).abs() < 1e-12);
        // Clamped at the ends.
        assert!((lookup(&t, 5.0, true) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn distances_agree_within_the_spread_or_not_at_all() {
        assert!(constant(&[2.0, 2.001, 1.999]).is_some());
        assert!(constant(&[2.0, 2.1]).is_none());
        assert!(constant(&[]).is_none());
    }
}
