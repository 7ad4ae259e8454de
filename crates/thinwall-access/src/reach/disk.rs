//! The tool's disk as a polygon, and a point set grown by it (their
//! Minkowski sum): what floors and obstacles alike are grown with.

use geo::{Area, ConvexHull, Coord, MultiPoint, Point, Polygon};

/// Corners of the polygon standing for a disk.
const DISK_CORNERS: usize = 128;

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
