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

/// Find the walls of a part.
pub fn find_walls(part: &Part, config: &Config) -> Vec<Wall> {
    let tol = part.tolerances();
    let lin = (tol.linear * 100.0).max(1e-4);
    let cos_tol = config.thresholds.parallel_angle_deg.to_radians().cos();
    let faces: Vec<PlanarFace> = part
        .face_ids()
        .filter_map(|f| PlanarFace::new(part, f))
        .collect();
    let plane_of = plane_ids(&faces, lin, cos_tol);
    // Each face's polygon in its own frame, and its 3D box for prefiltering.
    let own: Vec<MultiPolygon<f64>> = faces.iter().map(|f| f.polygon_in(&f.frame)).collect();
    let boxes: Vec<thinwall_geom::BoundingBox> = faces
        .iter()
        .map(|f| {
            let mut b = thinwall_geom::BoundingBox::empty();
            f.loops.outer.iter().flatten().for_each(|p| b.add_point(p));
            b
        })
        .collect();
    let min_area = (lin * lin * 100.0).max(1e-6);
    // (plane a, plane b) -> (faces a, faces b, region in a's frame, frame a, thickness)
    struct Group {
        faces: [Vec<FaceId>; 2],
        frame: Frame,
        normals: [Vector3; 2],
        thickness: f64,
        region: MultiPolygon<f64>,
    }
    let mut groups: HashMap<(usize, usize), Group> = HashMap::new();
    for (i, f) in faces.iter().enumerate() {
        let n = f.normal();
        let mut candidates: Vec<(f64, usize)> = faces
            .iter()
            .enumerate()
            .filter(|(j, g)| {
                *j != i
                    && g.normal().dot(&n) < -cos_tol
                    && boxes_overlap_across(&boxes[i], &boxes[*j], &n)
            })
            .map(|(j, g)| ((f.frame.origin - g.frame.origin).dot(&n), j))
            .filter(|(d, _)| *d > lin)
            .collect();
        candidates.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut covered: MultiPolygon<f64> = MultiPolygon::new(vec![]);
        for (d, j) in candidates {
            let proj = faces[j].polygon_in(&f.frame);
            let overlap = intersect(&own[i], &proj);
            if overlap.unsigned_area() <= min_area {
                continue;
            }
            let fresh = if covered.0.is_empty() {
                overlap.clone()
            } else {
                overlap.difference(&covered)
            };
            covered = if covered.0.is_empty() {
                overlap
            } else {
                covered.union(&overlap)
            };
            if fresh.unsigned_area() <= min_area {
                continue;
            }
            // Canonical side 0: the lower plane id.
            let (pa, pb) = (plane_of[i], plane_of[j]);
            let (key, swap) = if pa < pb {
                ((pa, pb), false)
            } else {
                ((pb, pa), true)
            };
            let (side0, side1) = if swap { (j, i) } else { (i, j) };
            let g = groups.entry(key).or_insert_with(|| Group {
                faces: [Vec::new(), Vec::new()],
                frame: faces[side0].frame,
                normals: [faces[side0].normal(), faces[side1].normal()],
                thickness: d,
                region: MultiPolygon::new(vec![]),
            });
            for (s, k) in [(0, side0), (1, side1)] {
                if !g.faces[s].contains(&faces[k].face) {
                    g.faces[s].push(faces[k].face);
                }
            }
            // Region into the group's frame (side 0's plane).
            let in_frame = reproject(&fresh, &f.frame, &g.frame);
            g.region = if g.region.0.is_empty() {
                in_frame
            } else {
                g.region.union(&in_frame)
            };
        }
    }
    let mut keys: Vec<_> = groups.keys().copied().collect();
    keys.sort();
    let mut walls = Vec::new();
    for k in keys {
        let mut g = groups.remove(&k).expect("key");
        let width = narrow_width(&g.region);
        if width < config.thresholds.min_width_to_thickness * g.thickness {
            continue;
        }
        g.faces.iter_mut().for_each(|v| v.sort());
        walls.push(Wall {
            sides: g.faces,
            normals: g.normals,
            frame: g.frame,
            thickness: g.thickness,
            region: g.region,
        });
    }
    walls
}

/// Whether the boxes of two faces overlap when seen along `n` (their
/// projections onto the plane normal to `n` intersect).
fn boxes_overlap_across(
    a: &thinwall_geom::BoundingBox,
    b: &thinwall_geom::BoundingBox,
    n: &Vector3,
) -> bool {
    // Axes perpendicular to n: test the box extents on two in-plane axes.
    let u = thinwall_geom::frame::any_perpendicular(n);
    let v = n.cross(&u);
    let corners = |bb: &thinwall_geom::BoundingBox| {
        let mut out = Vec::with_capacity(8);
        for i in 0..8 {
            out.push(Vector3::new(
                if i & 1 == 0 { bb.min[0] } else { bb.max[0] },
                if i & 2 == 0 { bb.min[1] } else { bb.max[1] },
                if i & 4 == 0 { bb.min[2] } else { bb.max[2] },
            ));
        }
        out
    };
    let (ca, cb) = (corners(a), corners(b));
    for axis in [u, v] {
        let (amin, amax) = ca
            .iter()
            .map(|c| c.dot(&axis))
            .fold((f64::INFINITY, f64::NEG_INFINITY), |m, x| {
                (m.0.min(x), m.1.max(x))
            });
        let (bmin, bmax) = cb
            .iter()
            .map(|c| c.dot(&axis))
            .fold((f64::INFINITY, f64::NEG_INFINITY), |m, x| {
                (m.0.min(x), m.1.max(x))
            });
        if amax < bmin || bmax < amin {
            return false;
        }
    }
    true
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
