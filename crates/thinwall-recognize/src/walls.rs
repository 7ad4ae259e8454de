//! Walls: material between two opposed planar side faces.
//!
//! For every planar face F, the planar faces G behind it (anti-parallel
//! normal, plane behind F) are taken nearest first; the part of G's
//! projection onto F not already claimed by a nearer face is where F and G
//! bound the same slab of material. Pairs are grouped by their pair of
//! planes, so coplanar faces on one side — a side split by crossing walls —
//! make one wall. A group is a wall when its region is at least as wide as
//! it is thick (a rib seen from below is a strip, not a wall).

use crate::config::Config;
use crate::planar::{intersect, narrow_width, PlanarFace};
use geo::{Area, BooleanOps, BoundingRect, MultiPolygon};
use std::collections::HashMap;
use thinwall_brep::{FaceId, Part};
use thinwall_geom::{Frame, Point3, Vector3};

/// A wall before it is classified.
#[derive(Clone, Debug)]
pub struct Wall {
    /// Faces of side 0 (in plane `frame`, outward normal `frame.z`).
    pub sides: [Vec<FaceId>; 2],
    /// Outward normals of the two sides (tool access directions).
    pub normals: [Vector3; 2],
    /// Frame of side 0's plane: z is side 0's outward normal.
    pub frame: Frame,
    /// Distance between the side planes, mm.
    pub thickness: f64,
    /// Where the two sides bound the slab, in `frame`'s xy coordinates.
    pub region: MultiPolygon<f64>,
}

impl Wall {
    /// 3D points of the region's outline on the mid-plane.
    pub fn outline(&self) -> Vec<Point3> {
        let mut pts = Vec::new();
        for poly in &self.region.0 {
            for c in poly.exterior().coords() {
                pts.push(
                    self.frame
                        .to_world(&Vector3::new(c.x, c.y, -0.5 * self.thickness)),
                );
            }
        }
        pts
    }

    /// A point on the mid-plane and its unit normal (side 0's).
    pub fn mid_plane(&self) -> (Point3, Vector3) {
        let c = geo::Centroid::centroid(&self.region)
            .map(|p| (p.x(), p.y()))
            .unwrap_or((0.0, 0.0));
        (
            self.frame
                .to_world(&Vector3::new(c.0, c.1, -0.5 * self.thickness)),
            self.frame.z,
        )
    }

    pub fn contains_side_face(&self, f: FaceId) -> Option<usize> {
        (0..2).find(|&s| self.sides[s].contains(&f))
    }
}

/// Planes shared by coplanar faces: `plane_of[face]` for planar faces.
fn plane_ids(faces: &[PlanarFace], lin_tol: f64, cos_tol: f64) -> Vec<usize> {
    let mut ids = vec![usize::MAX; faces.len()];
    let mut planes: Vec<(Vector3, f64)> = Vec::new();
    // Bucket by rounded normal to keep this near-linear.
    let mut buckets: HashMap<(i64, i64, i64), Vec<usize>> = HashMap::new();
    for (i, f) in faces.iter().enumerate() {
        let n = f.normal();
        let key = (
            (n.x * 50.0).round() as i64,
            (n.y * 50.0).round() as i64,
            (n.z * 50.0).round() as i64,
        );
        let mut found = None;
        'search: for dx in -1..=1 {
            for dy in -1..=1 {
                for dz in -1..=1 {
                    if let Some(list) = buckets.get(&(key.0 + dx, key.1 + dy, key.2 + dz)) {
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

/// Find the walls of a part, with its tolerances (`Part::tolerances`, which
/// costs a pass over the part's edges: callers usually have them already).
pub fn find_walls(part: &Part, config: &Config, tol: &thinwall_geom::Tolerances) -> Vec<Wall> {
    let lin = (tol.linear * 100.0).max(1e-4);
    let cos_tol = config.thresholds.parallel_angle_deg.to_radians().cos();
    let faces: Vec<PlanarFace> = part
        .face_ids()
        .filter_map(|f| PlanarFace::new(part, f))
        .collect();
    let plane_of = plane_ids(&faces, lin, cos_tol);
    let n_planes = plane_of.iter().copied().max().map_or(0, |m| m + 1);
    let mut members: Vec<Vec<usize>> = vec![Vec::new(); n_planes];
    for (i, &p) in plane_of.iter().enumerate() {
        members[p].push(i);
    }
    // Per plane: its normal and a point (of its first face).
    let plane_normal: Vec<Vector3> = members.iter().map(|m| faces[m[0]].normal()).collect();
    let plane_point: Vec<Point3> = members.iter().map(|m| faces[m[0]].frame.origin).collect();
    let own: Vec<MultiPolygon<f64>> = faces.iter().map(|f| f.polygon_in(&f.frame)).collect();
    let own_area: Vec<f64> = own.iter().map(|p| p.unsigned_area()).collect();
    let boxes: Vec<thinwall_geom::BoundingBox> = faces
        .iter()
        .map(|f| {
            let mut b = thinwall_geom::BoundingBox::empty();
            f.loops.outer.iter().flatten().for_each(|p| b.add_point(p));
            b
        })
        .collect();
    let min_area = (lin * lin * 100.0).max(1e-6);
    struct Group {
        faces: [Vec<FaceId>; 2],
        frame: Frame,
        normals: [Vector3; 2],
        thickness: f64,
        parts: Vec<geo::Polygon<f64>>,
    }
    let mut groups: HashMap<(usize, usize), Group> = HashMap::new();
    for (i, f) in faces.iter().enumerate() {
        let n = f.normal();
        // Opposed planes behind F, nearest first.
        let mut behind: Vec<(f64, usize)> = (0..n_planes)
            .filter(|&p| plane_normal[p].dot(&n) < -cos_tol)
            .map(|p| ((f.frame.origin - plane_point[p]).dot(&n), p))
            .filter(|(d, _)| *d > lin)
            .collect();
        behind.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut covered: MultiPolygon<f64> = MultiPolygon::new(vec![]);
        let mut covered_area = 0.0;
        for (d, p) in behind {
            if covered_area >= own_area[i] - min_area {
                break; // F is bounded everywhere by nearer faces
            }
            let overlapping: Vec<usize> = members[p]
                .iter()
                .copied()
                .filter(|&j| boxes_overlap_across(&boxes[i], &boxes[j], &n))
                .collect();
            if overlapping.is_empty() {
                continue;
            }
            let projected = MultiPolygon::new(
                overlapping
                    .iter()
                    .flat_map(|&j| faces[j].polygon_in(&f.frame).0)
                    .collect(),
            );
            let region = intersect(&own[i], &projected);
            let region_area = region.unsigned_area();
            if region_area <= min_area {
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
            if fresh.unsigned_area() <= min_area {
                continue;
            }
            // The faces of plane p that bound the fresh part.
            // (Tested against the fresh components near each face only:
            // a plane may hold thousands of faces.)
            let components: Vec<(geo::Rect<f64>, &geo::Polygon<f64>)> = fresh
                .0
                .iter()
                .filter_map(|c| c.bounding_rect().map(|r| (r, c)))
                .collect();
            let partners: Vec<usize> = overlapping
                .into_iter()
                .filter(|&j| {
                    let proj = faces[j].polygon_in(&f.frame);
                    let Some(pr) = proj.bounding_rect() else {
                        return false;
                    };
                    let near: Vec<geo::Polygon<f64>> = components
                        .iter()
                        .filter(|(r, _)| rects_overlap(r, &pr))
                        .map(|(_, c)| (*c).clone())
                        .collect();
                    !near.is_empty()
                        && intersect(&MultiPolygon::new(near), &proj).unsigned_area() > min_area
                })
                .collect();
            if partners.is_empty() {
                continue;
            }
            let pa = plane_of[i];
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
                    frame: faces[s0].frame,
                    normals: [faces[s0].normal(), faces[s1].normal()],
                    thickness: d,
                    parts: Vec::new(),
                }
            });
            let (mine, theirs) = if f_is_side0 { (0, 1) } else { (1, 0) };
            if !g.faces[mine].contains(&f.face) {
                g.faces[mine].push(f.face);
            }
            for j in partners {
                if !g.faces[theirs].contains(&faces[j].face) {
                    g.faces[theirs].push(faces[j].face);
                }
            }
            // Regions are collected from side 0's faces only: they are
            // disjoint, so the group's region is their plain collection.
            if f_is_side0 {
                g.parts.extend(reproject(&fresh, &f.frame, &g.frame).0);
            }
        }
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
        walls.push(Wall {
            sides: g.faces,
            normals: g.normals,
            frame: g.frame,
            thickness: g.thickness,
            region,
        });
    }
    walls
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

/// The extent of a region's outline along a 3D direction.
pub fn extent_along(points: &[Point3], dir: &Vector3) -> f64 {
    let (lo, hi) = points
        .iter()
        .map(|p| p.coords.dot(dir))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |m, x| {
            (m.0.min(x), m.1.max(x))
        });
    if lo.is_finite() {
        hi - lo
    } else {
        0.0
    }
}

/// Longest side of the region's minimum rotated rectangle.
pub fn long_side(region: &MultiPolygon<f64>) -> f64 {
    use geo::MinimumRotatedRect;
    region
        .minimum_rotated_rect()
        .map(|r| {
            let c: Vec<geo::Coord<f64>> = r.exterior().coords().copied().collect();
            let a = ((c[1].x - c[0].x).powi(2) + (c[1].y - c[0].y).powi(2)).sqrt();
            let b = ((c[2].x - c[1].x).powi(2) + (c[2].y - c[1].y).powi(2)).sqrt();
            a.max(b)
        })
        .or_else(|| region.bounding_rect().map(|r| r.width().max(r.height())))
        .unwrap_or(0.0)
}
