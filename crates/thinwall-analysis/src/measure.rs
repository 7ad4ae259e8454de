//! Measures over points and faces: boundary samples of a face, extents
//! along a direction.

use thinwall_brep::{FaceId, Part};
use thinwall_geom::{Point3, Vector3};

/// Samples per knot span of an edge when a face's boundary is sampled.
const BOUNDARY_SAMPLES_PER_SPAN: usize = 4;

/// Sample points on a face's boundary: the vertex of a vertex loop, and
/// `BOUNDARY_SAMPLES_PER_SPAN + 1` points on every knot span of every edge.
pub fn boundary_points(part: &Part, f: FaceId) -> Vec<Point3> {
    let mut pts = Vec::new();
    for &l in &part.face(f).loops {
        let lp = part.loop_(l);
        if let Some(v) = lp.vertex {
            pts.push(part.vertex(v).point);
        }
        for ce in &lp.coedges {
            let e = part.edge(ce.edge);
            match &e.nurbs {
                Some(c) => {
                    for (a, b) in c.spans() {
                        for k in 0..=BOUNDARY_SAMPLES_PER_SPAN {
                            let t = a + (b - a) * k as f64 / BOUNDARY_SAMPLES_PER_SPAN as f64;
                            pts.push(c.point(t));
                        }
                    }
                }
                None => pts.push(part.vertex(e.start).point),
            }
        }
    }
    pts
}

/// Lowest and highest `p · dir` over the points; `(+∞, −∞)` when there are none.
pub fn extent<'a>(points: impl IntoIterator<Item = &'a Point3>, dir: &Vector3) -> (f64, f64) {
    points
        .into_iter()
        .map(|p| p.coords.dot(dir))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |m, x| {
            (m.0.min(x), m.1.max(x))
        })
}

/// `hi − lo` of [`extent`], 0 when there are no points, mm.
pub fn span<'a>(points: impl IntoIterator<Item = &'a Point3>, dir: &Vector3) -> f64 {
    let (lo, hi) = extent(points, dir);
    if lo.is_finite() {
        hi - lo
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn extents_of_points() {
        let pts = [Point3::new(0.0, 1.0, 2.0), Point3::new(3.0, -1.0, 5.0)];
        assert_eq!(extent(&pts, &Vector3::x()), (0.0, 3.0));
        assert_eq!(span(&pts, &Vector3::z()), 3.0);
        assert_eq!(span(&[], &Vector3::z()), 0.0);
    }
}
