//! Walls: material between two opposed planar side faces (curved walls,
//! between coaxial cylinders and cones, in `curved`).
//!
//! For every planar face F, the planar faces G behind it (anti-parallel
//! normal, plane behind F) are taken nearest first; the part of G's
//! projection onto F not already claimed by a nearer face is where F and G
//! bound the same slab of material. Pairs are grouped by their pair of
//! planes, so coplanar faces on one side — a side split by crossing walls —
//! make one wall. A group is a wall when its region is at least as wide as
//! it is thick (a rib seen from below is a strip, not a wall).
//!
//! Drafted walls: side planes that lean towards each other by up to the
//! draft angle on each side (`thresholds.max_draft_deg`) also pair; such a
//! wall's thickness varies across its region, from `thickness_range.1`
//! (thickest) to `.0` (thinnest).

pub use crate::wall::Wall;

use crate::config::Config;
use geo::{Area, BooleanOps, BoundingRect, MultiPolygon};
use std::collections::HashMap;
use thinwall_analysis::polygon::{intersect, narrow_width};
use thinwall_analysis::{PartAnalysis, PlanarFace};
use thinwall_brep::FaceId;
use thinwall_geom::{Frame, Point3, Vector3};

/// The outer outline of a region drawn in `frame`'s xy plane, at height
/// `z` along `frame.z`, in model coordinates.
pub fn region_outline(frame: &Frame, region: &MultiPolygon<f64>, z: f64) -> Vec<Point3> {
    region
        .0
        .iter()
        .flat_map(|p| p.exterior().coords())
        .map(|c| frame.to_world(&Vector3::new(c.x, c.y, z)))
        .collect()
}

impl Wall {
    /// 3D points of the region's outline on the mid-plane (mid-surface).
    pub fn outline(&self) -> Vec<Point3> {
        match &self.curved {
            Some(c) => c.outline(&self.region, c.mid_offset()),
            None => region_outline(&self.frame, &self.region, -0.5 * self.thickness),
        }
    }

    /// A point on the mid-plane and its unit normal (side 0's); for a
    /// curved wall, on the mid-surface at the region's centre.
    pub fn mid_plane(&self) -> (Point3, Vector3) {
        let c = geo::Centroid::centroid(&self.region)
            .map(|p| (p.x(), p.y()))
            .unwrap_or((0.0, 0.0));
        if let Some(cw) = &self.curved {
            let p = cw.to_world(c.0, c.1, cw.mid_offset());
            return (p, cw.tangent_plane(0, &p).1);
        }
        (
            self.frame
                .to_world(&Vector3::new(c.0, c.1, -0.5 * self.thickness)),
            self.frame.z,
        )
    }

    /// A point on side `s`'s plane and that side's outward normal (a
    /// curved wall's tangent plane at the region's centre).
    pub fn side_plane(&self, s: usize) -> (Point3, Vector3) {
        if s == 0 {
            (self.frame.origin, self.normals[0])
        } else {
            (self.side1_point, self.normals[1])
        }
    }

    /// Whether the sides lean towards each other (a drafted wall).
    pub fn drafted(&self) -> bool {
        self.thickness_range.1 > self.thickness_range.0
    }

    /// The distance between the sides at a point of side 0's plane, mm:
    /// across the wall, along the bisector of the two outward normals (for
    /// a symmetric draft, the horizontal width at that height).
    pub fn thickness_at(&self, on_side0: &Point3) -> f64 {
        let across = (self.normals[0] - self.normals[1])
            .try_normalize(1e-12)
            .unwrap_or(self.frame.z);
        self.thickness_along(on_side0, &across)
    }

    /// The distance between the sides at a point of side 0's plane, mm,
    /// measured along `across` (a unit vector pointing out of side 0): the
    /// width of the wall's section normal to its height when `across` is
    /// side 0's normal without its height component (a flange drafted on
    /// its inner side only, dimensioned as drawn).
    pub fn thickness_along(&self, on_side0: &Point3, across: &Vector3) -> f64 {
        let n1 = self.normals[1];
        (on_side0 - self.side1_point).dot(&n1) / across.dot(&n1)
    }

    /// Side `s`'s tangent plane nearest a point: the side's plane for a
    /// flat wall.
    pub fn side_plane_near(&self, s: usize, p: &Point3) -> (Point3, Vector3) {
        match &self.curved {
            Some(c) => c.tangent_plane(s, p),
            None => self.side_plane(s),
        }
    }

    /// A curved wall's developed length across `height_dir` (a unit
    /// vector): the region's extent along the developed direction (arc or
    /// generator) most nearly normal to it.
    pub fn developed_span(&self, height_dir: &Vector3) -> Option<f64> {
        let (w, _) = self.developed_extents(height_dir)?;
        Some(w)
    }

    /// A curved wall's developed height along `height_dir`: the region's
    /// extent along the developed direction (generator or arc) nearest it.
    pub fn developed_height(&self, height_dir: &Vector3) -> Option<f64> {
        let (_, h) = self.developed_extents(height_dir)?;
        Some(h)
    }

    /// (across, along) `height_dir` of a curved wall's developed region.
    fn developed_extents(&self, height_dir: &Vector3) -> Option<(f64, f64)> {
        self.curved.as_ref()?;
        let (x, y) = (height_dir.dot(&self.frame.x), height_dir.dot(&self.frame.y));
        let r = geo::BoundingRect::bounding_rect(&self.region)?;
        Some(if y.abs() >= x.abs() {
            (r.width(), r.height())
        } else {
            (r.height(), r.width())
        })
    }

    pub fn contains_side_face(&self, f: FaceId) -> Option<usize> {
        (0..2).find(|&s| self.sides[s].contains(&f))
    }
}

/// Planes shared by coplanar faces of one body: `plane_of[face]` for
/// planar faces (`body[face]` its body: instances of an assembly never
/// share a plane, so no wall spans two of them).
fn plane_ids(faces: &[&PlanarFace], body: &[u32], lin_tol: f64, cos_tol: f64) -> Vec<usize> {
    let mut ids = vec![usize::MAX; faces.len()];
    let mut planes: Vec<(Vector3, f64)> = Vec::new();
    // Bucket by body and rounded normal to keep this near-linear.
    let mut buckets: HashMap<(u32, i64, i64, i64), Vec<usize>> = HashMap::new();
    for (i, f) in faces.iter().enumerate() {
        let n = f.normal();
        let key = (
            body[i],
            (n.x * 50.0).round() as i64,
            (n.y * 50.0).round() as i64,
            (n.z * 50.0).round() as i64,
        );
        let mut found = None;
        'search: for dx in -1..=1 {
            for dy in -1..=1 {
                for dz in -1..=1 {
                    if let Some(list) = buckets.get(&(key.0, key.1 + dx, key.2 + dy, key.3 + dz)) {
                        for &p in list {
                            let (pn, po) = planes[p];
                            if pn.dot(&n) > cos_tol && (po - f.offset()).abs() < lin_tol {
                                found = Some(p);
                                break 'search;
                            }
                        }
                    }
                }
            }
        }
        let p = found.unwrap_or_else(|| {
            planes.push((n, f.offset()));
            buckets.entry(key).or_default().push(planes.len() - 1);
            planes.len() - 1
        });
        ids[i] = p;
    }
    ids
}

/// Per planar face and per plane, what pairing needs, prepared once.
struct Pairing<'p> {
    faces: Vec<&'p PlanarFace>,
    plane_of: Vec<usize>,
    members: Vec<Vec<usize>>,
    plane_normal: Vec<Vector3>,
    plane_point: Vec<Point3>,
    own: Vec<MultiPolygon<f64>>,
    own_area: Vec<f64>,
    boxes: Vec<thinwall_geom::BoundingBox>,
    lin: f64,
    cos_tol: f64,
    /// Opposed planes leaning by up to twice the draft angle still pair.
    cos_draft: f64,
    /// `min_extent_to_thickness`: how much longer than thick a wall is.
    min_extent: f64,
    min_area: f64,
    /// Per plane: the body its faces belong to.
    plane_body: Vec<u32>,
    /// Per face: a point on it (the mean of its outer loop's samples).
    inside: Vec<Point3>,
}

/// Two opposed side planes bounding a slab, while their faces are collected.
struct Group {
    faces: [Vec<FaceId>; 2],
    frame: Frame,
    normals: [Vector3; 2],
    thickness: f64,
    side1_point: Point3,
    parts: Vec<geo::Polygon<f64>>,
}

/// Find the walls of a part.
pub fn find_walls(a: &PartAnalysis, config: &Config) -> Vec<Wall> {
    let p = Pairing::new(a, config);
    let mut groups: HashMap<(usize, usize), Group> = HashMap::new();
    for i in 0..p.faces.len() {
        p.pair_face(i, &mut groups);
    }
    let mut keys: Vec<_> = groups.keys().copied().collect();
    keys.sort();
    let mut walls = Vec::new();
    for k in keys {
        let mut g = groups.remove(&k).expect("key");
        if g.parts.is_empty() {
            continue;
        }
        let region = MultiPolygon::new(std::mem::take(&mut g.parts));
        let width = narrow_width(&region);
        if width < config.thresholds.min_width_to_thickness * g.thickness {
            continue;
        }
        g.faces.iter_mut().for_each(|v| v.sort());
        let mut wall = Wall {
            sides: g.faces,
            normals: g.normals,
            frame: g.frame,
            thickness: g.thickness,
            thickness_range: (g.thickness, g.thickness),
            side1_point: g.side1_point,
            region,
            curved: None,
        };
        if wall.normals[0].dot(&wall.normals[1]) >= -p.cos_tol && !drafted_thickness(&mut wall) {
            continue; // the sides cross within the region: no slab
        }
        walls.push(wall);
    }
    walls.extend(crate::curved::find_curved_walls(a, config));
    walls.extend(crate::offset::find_offset_walls(a, config));
    walls
}

/// Measure a drafted wall's thickness over its region: thinnest, thickest,
/// and the mean for its geometry. False when the sides meet within it. How
/// much thicker the foot is than the top is no test: the pairing bounds
/// the draft (`max_draft_deg` per side), and a tall rib drafted 5° per
/// side is 0.9 mm at its top and 6.15 mm at its foot 30 mm below.
fn drafted_thickness(wall: &mut Wall) -> bool {
    let at: Vec<f64> = region_outline(&wall.frame, &wall.region, 0.0)
        .iter()
        .map(|p| wall.thickness_at(p))
        .collect();
    let lo = at.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = at.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if !(lo > 0.0 && hi.is_finite()) {
        return false;
    }
    wall.thickness_range = (lo, hi);
    wall.thickness = 0.5 * (lo + hi);
    true
}

impl<'p> Pairing<'p> {
    fn new(a: &'p PartAnalysis, config: &Config) -> Self {
        let lin = a.tol().coplanar;
        let cos_tol = config.thresholds.parallel_angle_deg.to_radians().cos();
        let draft = config.thresholds.max_draft_deg.max(0.0);
        // A draft of just the largest, turned, is within rounding of it.
        let slack = thinwall_geom::tolerance::PARALLEL_ANGLE_RAD;
        let cos_draft = ((2.0 * draft).to_radians() + slack).cos().min(cos_tol);
        let faces: Vec<&PlanarFace> = a.planar_faces().collect();
        let body: Vec<u32> = faces.iter().map(|f| a.part().face(f.face).body.0).collect();
        let plane_of = plane_ids(&faces, &body, lin, cos_tol);
        let n_planes = plane_of.iter().copied().max().map_or(0, |m| m + 1);
        let mut members: Vec<Vec<usize>> = vec![Vec::new(); n_planes];
        for (i, &p) in plane_of.iter().enumerate() {
            members[p].push(i);
        }
        // Per plane: its normal and a point (of its first face).
        let plane_normal = members.iter().map(|m| faces[m[0]].normal()).collect();
        let plane_point = members.iter().map(|m| faces[m[0]].frame.origin).collect();
        let plane_body = members.iter().map(|m| body[m[0]]).collect();
        let own: Vec<MultiPolygon<f64>> = faces.iter().map(|f| f.polygon_in(&f.frame)).collect();
        let own_area = own.iter().map(|p| p.unsigned_area()).collect();
        let inside = faces
            .iter()
            .map(|f| {
                let pts: Vec<&Point3> = f.loops.outer.iter().flatten().collect();
                let sum = pts.iter().fold(Vector3::zeros(), |s, p| s + p.coords);
                Point3::from(sum / pts.len().max(1) as f64)
            })
            .collect();
        let boxes = faces
            .iter()
            .map(|f| {
                let mut b = thinwall_geom::BoundingBox::empty();
                f.loops.outer.iter().flatten().for_each(|p| b.add_point(p));
                b
            })
            .collect();
        Self {
            faces,
            plane_of,
            members,
            plane_normal,
            plane_point,
            own,
            own_area,
            boxes,
            lin,
            cos_tol,
            cos_draft,
            min_extent: config.thresholds.min_extent_to_thickness,
            min_area: a.tol().min_overlap_area,
            plane_body,
            inside,
        }
    }

    /// Pair face `i` with the opposed planes behind it, nearest first, until
    /// it is bounded everywhere; record each pairing in its group.
    fn pair_face(&self, i: usize, groups: &mut HashMap<(usize, usize), Group>) {
        let f = self.faces[i];
        let n = f.normal();
        let own_body = self.plane_body[self.plane_of[i]];
        // A drafted partner must be near enough for a wall: a wall is at
        // least `min_extent_to_thickness` times longer and higher than thick.
        let drafted_reach = self.boxes[i].diagonal() / self.min_extent;
        let mut behind: Vec<(f64, usize)> = (0..self.members.len())
            .filter(|&p| self.plane_body[p] == own_body)
            .filter(|&p| self.plane_normal[p].dot(&n) < -self.cos_draft)
            .map(|p| (self.distance_behind(i, p), p))
            .filter(|(d, _)| *d > self.lin)
            .filter(|&(d, p)| self.plane_normal[p].dot(&n) < -self.cos_tol || d <= drafted_reach)
            .collect();
        // Nearest first, parallel or drafted: a flange's outer face has the
        // block's far side parallel behind it and its drafted inner side
        // 2 mm away. Drafted ones only while parallel planes leave the face
        // mostly unbounded (a drafted wall's sides have no parallel partner).
        let drafted = |p: usize| self.plane_normal[p].dot(&n) >= -self.cos_tol;
        behind.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        let mut covered: MultiPolygon<f64> = MultiPolygon::new(vec![]);
        let mut covered_area = 0.0;
        for (d, p) in behind {
            if covered_area >= self.own_area[i] - self.min_area {
                break; // F is bounded everywhere by nearer faces
            }
            if drafted(p) && covered_area > 0.5 * self.own_area[i] {
                break;
            }
            let overlapping: Vec<usize> = self.members[p]
                .iter()
                .copied()
                .filter(|&j| boxes_overlap_across(&self.boxes[i], &self.boxes[j], &n))
                .collect();
            if overlapping.is_empty() {
                continue;
            }
            let projected = MultiPolygon::new(
                overlapping
                    .iter()
                    .flat_map(|&j| self.faces[j].polygon_in(&f.frame).0)
                    .collect(),
            );
            let region = intersect(&self.own[i], &projected);
            if region.unsigned_area() <= self.min_area {
                continue;
            }
            let fresh = if covered.0.is_empty() {
                region.clone()
            } else {
                region.difference(&covered)
            };
            covered = if covered.0.is_empty() {
                region
            } else {
                covered.union(&region)
            };
            covered_area = covered.unsigned_area();
            if fresh.unsigned_area() <= self.min_area {
                continue;
            }
            let partners = self.partners(f, overlapping, &fresh);
            if !partners.is_empty() {
                self.record(i, p, d, &partners, &fresh, groups);
            }
        }
    }

    /// Whether faces `a` and `b` are anti-parallel within the parallel angle.
    fn normal_parallel(&self, a: usize, b: usize) -> bool {
        self.faces[a].normal().dot(&self.faces[b].normal()) < -self.cos_tol
    }

    /// How far plane `p` lies behind face `i`, along the face's normal:
    /// between parallel planes anywhere, between drafted ones from a point
    /// on the face.
    fn distance_behind(&self, i: usize, p: usize) -> f64 {
        let (f, n, np) = (self.faces[i], self.faces[i].normal(), self.plane_normal[p]);
        if np.dot(&n) < -self.cos_tol {
            return (f.frame.origin - self.plane_point[p]).dot(&n);
        }
        (self.inside[i] - self.plane_point[p]).dot(&np) / n.dot(&np)
    }

    /// The faces among `overlapping` that bound the fresh part of F (tested
    /// against the fresh components near each face only: a plane may hold
    /// thousands of faces).
    fn partners(
        &self,
        f: &PlanarFace,
        overlapping: Vec<usize>,
        fresh: &MultiPolygon<f64>,
    ) -> Vec<usize> {
        let components: Vec<(geo::Rect<f64>, &geo::Polygon<f64>)> = fresh
            .0
            .iter()
            .filter_map(|c| c.bounding_rect().map(|r| (r, c)))
            .collect();
        overlapping
            .into_iter()
            .filter(|&j| {
                let proj = self.faces[j].polygon_in(&f.frame);
                let Some(pr) = proj.bounding_rect() else {
                    return false;
                };
                let near: Vec<geo::Polygon<f64>> = components
                    .iter()
                    .filter(|(r, _)| rects_overlap(r, &pr))
                    .map(|(_, c)| (*c).clone())
                    .collect();
                !near.is_empty()
                    && intersect(&MultiPolygon::new(near), &proj).unsigned_area() > self.min_area
            })
            .collect()
    }

    /// Add face `i` (on plane pair with `p`, `d` apart) and its partners to
    /// their group.
    fn record(
        &self,
        i: usize,
        p: usize,
        d: f64,
        partners: &[usize],
        fresh: &MultiPolygon<f64>,
        groups: &mut HashMap<(usize, usize), Group>,
    ) {
        let f = self.faces[i];
        let pa = self.plane_of[i];
        let (key, f_is_side0) = if pa < p {
            ((pa, p), true)
        } else {
            ((p, pa), false)
        };
        let g = groups.entry(key).or_insert_with(|| {
            let (s0, s1) = if f_is_side0 {
                (i, partners[0])
            } else {
                (partners[0], i)
            };
            Group {
                faces: [Vec::new(), Vec::new()],
                frame: self.faces[s0].frame,
                normals: [self.faces[s0].normal(), self.faces[s1].normal()],
                thickness: d,
                side1_point: if self.normal_parallel(s0, s1) {
                    self.faces[s0].frame.origin - self.faces[s0].frame.z * d
                } else {
                    self.faces[s1].frame.origin
                },
                parts: Vec::new(),
            }
        });
        let (mine, theirs) = if f_is_side0 { (0, 1) } else { (1, 0) };
        if !g.faces[mine].contains(&f.face) {
            g.faces[mine].push(f.face);
        }
        for &j in partners {
            if !g.faces[theirs].contains(&self.faces[j].face) {
                g.faces[theirs].push(self.faces[j].face);
            }
        }
        // Regions are collected from side 0's faces only: they are
        // disjoint, so the group's region is their plain collection.
        if f_is_side0 {
            g.parts.extend(reproject(fresh, &f.frame, &g.frame).0);
        }
    }
}

fn rects_overlap(a: &geo::Rect<f64>, b: &geo::Rect<f64>) -> bool {
    a.min().x <= b.max().x
        && b.min().x <= a.max().x
        && a.min().y <= b.max().y
        && b.min().y <= a.max().y
}

/// Whether the boxes of two faces overlap when seen along `n` (their
/// projections onto the plane normal to `n` intersect).
fn boxes_overlap_across(
    a: &thinwall_geom::BoundingBox,
    b: &thinwall_geom::BoundingBox,
    n: &Vector3,
) -> bool {
    let u = thinwall_geom::frame::any_perpendicular(n);
    let v = n.cross(&u);
    let range = |bb: &thinwall_geom::BoundingBox, axis: &Vector3| {
        // Projection of a box onto an axis: centre ± half extents.
        let c = Vector3::new(
            bb.min[0] + bb.max[0],
            bb.min[1] + bb.max[1],
            bb.min[2] + bb.max[2],
        ) * 0.5;
        let h = Vector3::new(
            bb.max[0] - bb.min[0],
            bb.max[1] - bb.min[1],
            bb.max[2] - bb.min[2],
        ) * 0.5;
        let r = h.x * axis.x.abs() + h.y * axis.y.abs() + h.z * axis.z.abs();
        let m = c.dot(axis);
        (m - r, m + r)
    };
    [u, v].iter().all(|axis| {
        let (a0, a1) = range(a, axis);
        let (b0, b1) = range(b, axis);
        a1 >= b0 && b1 >= a0
    })
}

/// A region drawn in `from`'s xy plane, expressed in `to`'s xy plane (the
/// planes are parallel; points are projected along `to.z`).
fn reproject(region: &MultiPolygon<f64>, from: &Frame, to: &Frame) -> MultiPolygon<f64> {
    use geo::MapCoords;
    region.map_coords(|c| {
        let p = from.to_world(&Vector3::new(c.x, c.y, 0.0));
        let l = to.to_local(&p);
        geo::Coord { x: l.x, y: l.y }
    })
}
