//! Reach of a floor (a planar face square to the tool axis), which the tool
//! meets with its end: a point is reached when some free position of the
//! tool's axis lies within one radius of it. The free positions are the
//! plane less every obstacle grown by the cutter's radius (material above
//! the floor within the cutting length) or the holder's (above that); the
//! reached floor is the free positions grown again by the radius (a
//! morphological opening). Disks are 128-gons with their corners on the
//! circle, one on the face's own x axis: a straight boundary square to the
//! face's axes comes out exact (others within 3·10⁻⁴ of the radius), a
//! sharp inner corner's uncut area r²(1 − π/4) 0.15 % high.

use super::obstacle::Obstacle;
use super::scene::{clip_tagged, Scene};
use super::{Ctx, Judged};
use geo::{Area, BoundingRect, ConvexHull, Coord, MultiPoint, MultiPolygon, Point};
use geo::{Polygon, Rect};
use std::collections::BTreeMap;
use thinwall_analysis::boolean::{difference, intersection, union_all};
use thinwall_analysis::PlanarFace;
use thinwall_geom::{Frame, Vector3};

/// Corners of the polygon standing for a disk.
const DISK_CORNERS: usize = 128;

/// `named`: also which obstacles stop the tool, and how much (the
/// largest-tool search needs only the fraction).
pub fn judge(ctx: &Ctx, scene: &Scene, pf: &PlanarFace, own: u32, named: bool) -> Judged {
    let axis = scene.frame.z;
    let Some(frame) = Frame::from_axis(pf.frame.origin, axis, Some(pf.frame.x)) else {
        return Judged::default();
    };
    let region = pf.polygon_in(&frame);
    let area = region.unsigned_area();
    let Some(rect) = region.bounding_rect() else {
        return Judged::default();
    };
    let tool = &ctx.tool;
    let r = 0.5 * tool.diameter;
    let big = 0.5 * tool.holder_diameter;
    let corners: Vec<[f64; 3]> = region
        .iter()
        .flat_map(|p| p.exterior().coords().copied().collect::<Vec<_>>())
        .map(|c| scene.local(&frame.to_world(&Vector3::new(c.x, c.y, 0.0))))
        .collect();
    let h = corners
        .iter()
        .map(|c| c[2])
        .fold(f64::NEG_INFINITY, f64::max);
    let reach = r + big;
    let lo = [
        corners.iter().map(|c| c[0]).fold(f64::INFINITY, f64::min) - reach,
        corners.iter().map(|c| c[1]).fold(f64::INFINITY, f64::min) - reach,
    ];
    let hi = [
        corners
            .iter()
            .map(|c| c[0])
            .fold(f64::NEG_INFINITY, f64::max)
            + reach,
        corners
            .iter()
            .map(|c| c[1])
            .fold(f64::NEG_INFINITY, f64::max)
            + reach,
    ];
    let to_face = |p: [f64; 2]| -> [f64; 2] {
        let w = scene.frame.to_world(&Vector3::new(p[0], p[1], h));
        let l = frame.to_local(&w);
        [l.x, l.y]
    };
    let (small_disk, holder_disk) = (disk(r), disk(big));
    // Tessellated material touches within its own tolerance.
    let slack = ctx.touch_tessellated();
    let (small_tess, holder_tess) = (disk((r - slack).max(0.0)), disk((big - slack).max(0.0)));
    let mut obstacles: BTreeMap<(u32, bool), Obstacle> = BTreeMap::new();
    let top = h + tool.cutting_length;
    for k in scene.near(lo, hi, h + ctx.touch) {
        let t = &scene.tris[k as usize];
        if t.face == own {
            continue;
        }
        for (holder, a, b) in [
            (false, h + ctx.touch, top),
            (true, top + ctx.touch, f64::INFINITY),
        ] {
            let clipped = clip_tagged(&t.p, a, b);
            if !clipped.is_empty() {
                obstacles
                    .entry((t.face, holder))
                    .or_default()
                    .push(t, clipped, to_face);
            }
        }
    }
    let groups: Vec<((u32, bool), MultiPolygon<f64>)> = obstacles
        .into_iter()
        .map(|((face, holder), ob)| {
            let d = match (holder, ob.tessellated) {
                (false, false) => &small_disk,
                (false, true) => &small_tess,
                (true, false) => &holder_disk,
                (true, true) => &holder_tess,
            };
            ((face, holder), ob.grown(d))
        })
        .collect();
    let stopped = union_all(groups.iter().map(|(_, g)| g.clone()).collect());
    let margin = 1.01 * r + 1e-6;
    let frame_box = Rect::new(
        Coord {
            x: rect.min().x - margin,
            y: rect.min().y - margin,
        },
        Coord {
            x: rect.max().x + margin,
            y: rect.max().y + margin,
        },
    );
    let free = difference(&MultiPolygon::new(vec![frame_box.to_polygon()]), &stopped);
    let reached = intersection(&region, &opened(&free, &small_disk));
    let lost = difference(&region, &reached);
    let mut out = Judged {
        area,
        reached: reached.unsigned_area().min(area),
        ..Judged::default()
    };
    if named && area - out.reached > 1e-9 * area {
        out.blockers = blockers(&groups, &lost);
        out.unreachable = lost
            .iter()
            .flat_map(|p| std::iter::once(p.exterior()).chain(p.interiors()))
            .map(|ring| {
                ring.coords()
                    .map(|c| frame.to_world(&Vector3::new(c.x, c.y, 0.0)).into())
                    .collect()
            })
            .collect();
    }
    out
}

/// The positions `free` grown by `disk`: the points the tool's end covers
/// from them (free positions, and each edge of their outline grown).
fn opened(free: &MultiPolygon<f64>, disk: &[[f64; 2]]) -> MultiPolygon<f64> {
    let mut pieces = vec![free.clone()];
    for poly in free {
        for ring in std::iter::once(poly.exterior()).chain(poly.interiors()) {
            for l in ring.lines() {
                if let Some(p) = grown(&[[l.start.x, l.start.y], [l.end.x, l.end.y]], disk) {
                    pieces.push(MultiPolygon::new(vec![p]));
                }
            }
        }
    }
    union_all(pieces)
}

/// Which obstacles stop the tool on the `lost` floor: every one whose
/// grown shape covers some of it, with the area it covers (overlapping).
/// Naming only the obstacles that stop the tool alone does not work face
/// by face: a rib's top and its sides each cover what the others do, so
/// none gains alone.
fn blockers(
    groups: &[((u32, bool), MultiPolygon<f64>)],
    lost: &MultiPolygon<f64>,
) -> BTreeMap<(u32, bool), f64> {
    groups
        .iter()
        .map(|(key, g)| (*key, intersection(lost, g).unsigned_area()))
        .filter(|(_, a)| *a > 0.0)
        .collect()
}

/// A disk of radius `r` as a polygon with its corners on the circle, one
/// on the x axis.
pub fn disk(r: f64) -> Vec<[f64; 2]> {
    let step = std::f64::consts::TAU / DISK_CORNERS as f64;
    (0..DISK_CORNERS)
        .map(|k| {
            let t = step * k as f64;
            [r * t.cos(), r * t.sin()]
        })
        .collect()
}

/// The convex hull of `pts` grown by `disk` (convex, counter-clockwise,
/// as [`disk`] makes it): their Minkowski sum, by merging the two
/// outlines' edges in the order of their directions (linear in the
/// corners; the hull of every sum, which this replaces, was a fifth of
/// `thinwall access`'s time).
pub fn grown(pts: &[[f64; 2]], disk: &[[f64; 2]]) -> Option<Polygon<f64>> {
    if pts.is_empty() || disk.is_empty() {
        return None;
    }
    let a = hull_ccw(pts);
    let ring = minkowski(&a, disk);
    let out = Polygon::new(
        ring.iter().map(|p| Coord { x: p[0], y: p[1] }).collect(),
        vec![],
    );
    (out.unsigned_area() > 0.0).then_some(out)
}

/// The corners of the convex hull of `pts`, counter-clockwise (one or two
/// points when they are a point or a segment).
fn hull_ccw(pts: &[[f64; 2]]) -> Vec<[f64; 2]> {
    let hull = MultiPoint::from(
        pts.iter()
            .map(|p| Point::new(p[0], p[1]))
            .collect::<Vec<_>>(),
    )
    .convex_hull();
    let mut ring: Vec<[f64; 2]> = hull.exterior().coords().map(|c| [c.x, c.y]).collect();
    if ring.len() > 1 && ring.first() == ring.last() {
        ring.pop();
    }
    ring.dedup();
    if ring.is_empty() {
        ring.push(pts[0]);
    }
    ring
}

/// The Minkowski sum of two convex polygons, both counter-clockwise.
fn minkowski(a: &[[f64; 2]], b: &[[f64; 2]]) -> Vec<[f64; 2]> {
    // Each from its lowest corner (then leftmost).
    let start = |p: &[[f64; 2]]| {
        (0..p.len())
            .min_by(|&i, &j| {
                p[i][1]
                    .total_cmp(&p[j][1])
                    .then(p[i][0].total_cmp(&p[j][0]))
            })
            .unwrap_or(0)
    };
    let (sa, sb) = (start(a), start(b));
    let (n, m) = (a.len(), b.len());
    let at = |p: &[[f64; 2]], s: usize, k: usize| p[(s + k) % p.len()];
    let edge = |p: &[[f64; 2]], s: usize, k: usize| {
        let (u, v) = (at(p, s, k), at(p, s, k + 1));
        [v[0] - u[0], v[1] - u[1]]
    };
    let mut out = Vec::with_capacity(n + m);
    let (mut i, mut j) = (0, 0);
    while i < n || j < m {
        let (p, q) = (at(a, sa, i), at(b, sb, j));
        out.push([p[0] + q[0], p[1] + q[1]]);
        let (ea, eb) = (edge(a, sa, i), edge(b, sb, j));
        let cross = ea[0] * eb[1] - ea[1] * eb[0];
        let step_a = j >= m || (i < n && cross >= 0.0);
        let step_b = i >= n || (j < m && cross <= 0.0);
        if step_a {
            i += 1;
        }
        if step_b {
            j += 1;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The merged Minkowski sum is the hull of every sum: a point, a
    /// segment, a triangle and a clipped quadrilateral grown by a disk,
    /// the same area within 1e-9.
    #[test]
    fn grown_is_the_hull_of_every_sum() {
        let d = disk(3.0);
        for pts in [
            vec![[1.0, 2.0]],
            vec![[0.0, 0.0], [10.0, 4.0]],
            vec![[10.0, 4.0], [0.0, 0.0]],
            vec![[0.0, 0.0], [5.0, 1.0], [2.0, 7.0]],
            vec![[2.0, 7.0], [0.0, 0.0], [5.0, 1.0], [4.0, 6.0], [1.0, 3.0]],
        ] {
            let sums: Vec<Point<f64>> = pts
                .iter()
                .flat_map(|p| d.iter().map(move |q| Point::new(p[0] + q[0], p[1] + q[1])))
                .collect();
            let hull = MultiPoint::from(sums).convex_hull().unsigned_area();
            let got = grown(&pts, &d).unwrap().unsigned_area();
            assert!(
                (got - hull).abs() <= 1e-9 * hull,
                "{pts:?}: {got} vs {hull}"
            );
        }
    }

    #[test]
    fn the_disk_polygon_spans_the_diameter() {
        let d = disk(6.0);
        let xs: Vec<f64> = d.iter().map(|c| c[0]).collect();
        let ys: Vec<f64> = d.iter().map(|c| c[1]).collect();
        let span = |v: &[f64]| {
            v.iter().cloned().fold(f64::MIN, f64::max) - v.iter().cloned().fold(f64::MAX, f64::min)
        };
        assert!((span(&xs) - 12.0).abs() < 1e-12 && (span(&ys) - 12.0).abs() < 1e-12);
        let p = Polygon::new(
            d.iter().map(|c| Coord { x: c[0], y: c[1] }).collect(),
            vec![],
        );
        let a = p.unsigned_area();
        assert!(a < std::f64::consts::PI * 36.0 && a > 0.9995 * std::f64::consts::PI * 36.0);
    }
}
