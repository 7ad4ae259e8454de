//! The minimum-area rectangle around a 2-D shape, with ties broken by the
//! shape itself rather than by where its points happen to start.
//!
//! Many shapes have several rectangles of the same least area: a right or
//! acute triangle has one flush with each edge whose ends both see the
//! opposite corner (a 2 × 2 right triangle fits 2 × 2 and 2.83 × 1.41).
//! geo's `MinimumRotatedRect` keeps whichever it meets first, and which one
//! that is changed between geo 0.29 and 0.33 (and depends on the hull's
//! first corner, so on the pose). Here the tie goes to the most compact
//! rectangle (the shorter long side), then to the one flush with the longer
//! hull edge: the sizes a recognizer reports do not change with a rigid
//! motion of the part.

use geo::{ConvexHull, Coord, CoordsIter, MultiPoint, Point};

/// Rectangles whose areas (and long sides) are this close, relatively,
/// are tied.
const TIE: f64 = 1e-9;

/// A minimum-area rectangle: its sides, mm, and the direction of the long
/// one (unit, in the shape's plane).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MinRect {
    pub long: f64,
    pub short: f64,
    pub long_dir: [f64; 2],
}

/// The minimum-area rectangle around every coordinate of `shape` (none
/// when it has none). A segment gives its length by 0; a point, 0 by 0.
pub fn min_rect<G: CoordsIter<Scalar = f64>>(shape: &G) -> Option<MinRect> {
    let pts: Vec<Point<f64>> = shape.coords_iter().map(Point::from).collect();
    if pts.is_empty() {
        return None;
    }
    let hull: Vec<Coord<f64>> = MultiPoint::from(pts).convex_hull().exterior().0.clone();
    // The ring is closed: its last corner repeats the first.
    let corners = &hull[..hull.len().saturating_sub(1).max(1)];
    let mut best: Option<(f64, MinRect, f64)> = None;
    for (i, a) in corners.iter().enumerate() {
        let b = corners[(i + 1) % corners.len()];
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        let edge = dx.hypot(dy);
        if edge <= 0.0 {
            continue;
        }
        let (ux, uy) = (dx / edge, dy / edge);
        let rect = flush(corners, [ux, uy]);
        let area = rect.long * rect.short;
        if best
            .as_ref()
            .is_none_or(|(ba, br, be)| better(area, &rect, edge, *ba, br, *be))
        {
            best = Some((area, rect, edge));
        }
    }
    Some(best.map_or(
        MinRect {
            long: 0.0,
            short: 0.0,
            long_dir: [1.0, 0.0],
        },
        |b| b.1,
    ))
}

/// The rectangle around `corners` with a side along unit `u`.
fn flush(corners: &[Coord<f64>], u: [f64; 2]) -> MinRect {
    let v = [-u[1], u[0]];
    let span = |d: [f64; 2]| {
        let (lo, hi) = corners
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), c| {
                let t = c.x * d[0] + c.y * d[1];
                (lo.min(t), hi.max(t))
            });
        hi - lo
    };
    let (along, across) = (span(u), span(v));
    if along >= across {
        MinRect {
            long: along,
            short: across,
            long_dir: u,
        }
    } else {
        MinRect {
            long: across,
            short: along,
            long_dir: v,
        }
    }
}

/// Whether a rectangle (its area, and the hull edge it is flush with)
/// beats the best so far: less area, or tied and more compact, or tied
/// again and flush with a longer edge.
fn better(
    area: f64,
    r: &MinRect,
    edge: f64,
    best_area: f64,
    best: &MinRect,
    best_edge: f64,
) -> bool {
    let scale = area.max(best_area).max(f64::MIN_POSITIVE);
    if (area - best_area).abs() > TIE * scale {
        return area < best_area;
    }
    let long = r.long.max(best.long).max(f64::MIN_POSITIVE);
    if (r.long - best.long).abs() > TIE * long {
        return r.long < best.long;
    }
    edge > best_edge * (1.0 + TIE)
}

#[cfg(test)]
mod tests {
    use super::*;
    use geo::{LineString, Polygon};

    fn turned(pts: &[[f64; 2]], angle: f64, shift: [f64; 2]) -> Polygon<f64> {
        let (s, c) = angle.sin_cos();
        Polygon::new(
            LineString::from(
                pts.iter()
                    .map(|p| {
                        (
                            c * p[0] - s * p[1] + shift[0],
                            s * p[0] + c * p[1] + shift[1],
                        )
                    })
                    .collect::<Vec<_>>(),
            ),
            vec![],
        )
    }

    /// A right triangle with legs 2 has two least rectangles (2 × 2 and
    /// 2√2 × √2); the compact one is taken however the triangle is turned
    /// or its corners ordered.
    #[test]
    fn ties_go_to_the_compact_rectangle_in_any_pose() {
        let tri = [[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]];
        for k in 0..24 {
            let mut pts = tri.to_vec();
            pts.rotate_left(k % 3);
            let r = min_rect(&turned(&pts, 0.27 * k as f64, [3.0 * k as f64, -7.0])).unwrap();
            assert!(
                (r.long - 2.0).abs() < 1e-9 && (r.short - 2.0).abs() < 1e-9,
                "{k}: {r:?}"
            );
        }
    }

    /// A 10 × 4 rectangle turned by 30°: 10 × 4, the long side along the
    /// turned x axis.
    #[test]
    fn a_turned_rectangle() {
        let a = 30f64.to_radians();
        let rect = [[0.0, 0.0], [10.0, 0.0], [10.0, 4.0], [0.0, 4.0]];
        let r = min_rect(&turned(&rect, a, [1.0, 2.0])).unwrap();
        assert!((r.long - 10.0).abs() < 1e-9 && (r.short - 4.0).abs() < 1e-9);
        let along = (r.long_dir[0] * a.cos() + r.long_dir[1] * a.sin()).abs();
        assert!((along - 1.0).abs() < 1e-9);
    }

    /// On scattered points, no rectangle at any of 20,000 angles is
    /// smaller, and the best of them is within 10⁻³ of ours (the sampled
    /// angles miss the exact one by up to π/40,000).
    #[test]
    fn no_angle_does_better() {
        let mut seed = 12345u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        for _ in 0..20 {
            let pts: Vec<Point<f64>> = (0..12)
                .map(|_| Point::new(10.0 * next(), 4.0 * next()))
                .collect();
            let cloud = MultiPoint::from(pts.clone());
            let r = min_rect(&cloud).unwrap();
            let corners: Vec<Coord<f64>> = pts.iter().map(|p| p.0).collect();
            let sampled = (0..20_000)
                .map(|k| {
                    let t = std::f64::consts::PI * k as f64 / 20_000.0;
                    let f = flush(&corners, [t.cos(), t.sin()]);
                    f.long * f.short
                })
                .fold(f64::INFINITY, f64::min);
            let ours = r.long * r.short;
            assert!(ours <= sampled * (1.0 + 1e-12), "{ours} > {sampled}");
            assert!(ours >= sampled * (1.0 - 1e-3), "{ours} << {sampled}");
        }
    }

    #[test]
    fn a_segment_and_a_point() {
        let seg = MultiPoint::from(vec![Point::new(0.0, 0.0), Point::new(3.0, 4.0)]);
        let r = min_rect(&seg).unwrap();
        assert!((r.long - 5.0).abs() < 1e-12 && r.short.abs() < 1e-12);
        let one = MultiPoint::from(vec![Point::new(1.0, 1.0)]);
        assert_eq!(min_rect(&one).map(|r| (r.long, r.short)), Some((0.0, 0.0)));
        assert!(min_rect(&MultiPoint::<f64>::new(vec![])).is_none());
    }
}
