//! L-zones and G-zones in a face's 2-D sketch (Harik & Ris §3.4–3.5).
//!
//! A flank-milling direction `r` lies in the face's plane: the tool's side
//! sweeps the face, its body coming from outside along `r`. Along a ray
//! parallel to `r` the tool reaches the face up to the first barrier (a
//! closed edge of the face, or an obstacle above it); the face behind a
//! barrier is the direction's L-zone (unreachable). The paper launches rays
//! from the bounding rectangle; here the same region is computed exactly:
//! each barrier swept along `r` past the sketch (its shadow), the L-zone is
//! the face inside the union of shadows. A tool of radius `R` lying on the
//! face is blocked that much to each side of a barrier (the paper's fig. 15):
//! barriers are widened by `R` across `r`.

use geo::{Area, BoundingRect};
use geo::{BooleanOps, ConvexHull, LineString, MultiPoint, MultiPolygon, Point, Polygon};

/// A barrier of the sketch: a closed edge's piece (two points) or an
/// obstacle's bounding shape (its corners).
#[derive(Clone, Debug)]
pub struct Barrier {
    pub points: Vec<[f64; 2]>,
}

/// A barrier in the direction's frame: `u` along the direction, `v` across
/// it. Its shadow is every point beyond its front, the least `u` of the
/// barrier at each `v`.
struct Front {
    /// The convex outline, (u, v) corners in order (two for a segment).
    ring: Vec<[f64; 2]>,
    lo: f64,
    hi: f64,
}

impl Front {
    /// `barrier` widened by `radius` across the direction, as its convex
    /// hull in the (u, v) frame of the unit direction `r`; `None` when its
    /// shadow has no width.
    fn new(barrier: &Barrier, r: [f64; 2], radius: f64, tiny: f64) -> Option<Front> {
        let pts: Vec<Point<f64>> = barrier
            .points
            .iter()
            .flat_map(|p| {
                let (u, v) = (p[0] * r[0] + p[1] * r[1], p[1] * r[0] - p[0] * r[1]);
                [Point::new(u, v - radius), Point::new(u, v + radius)]
            })
            .collect();
        let (lo, hi) = pts
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), p| {
                (l.min(p.y()), h.max(p.y()))
            });
        if hi - lo <= tiny || hi.is_nan() || lo.is_nan() {
            return None;
        }
        let hull = MultiPoint::from(pts.clone()).convex_hull();
        let mut ring: Vec<[f64; 2]> = hull.exterior().points().map(|p| [p.x(), p.y()]).collect();
        ring.pop();
        if hull.unsigned_area() <= tiny * tiny || ring.len() < 3 {
            // Collinear: the segment between its lowest and highest points.
            let end = |want: f64| {
                pts.iter()
                    .filter(|p| p.y() == want)
                    .map(|p| p.x())
                    .fold(f64::INFINITY, f64::min)
            };
            ring = vec![[end(lo), lo], [end(hi), hi]];
        }
        Some(Front { ring, lo, hi })
    }

    /// The least `u` of the outline at `v` (within its `v` range).
    fn at(&self, v: f64) -> f64 {
        let n = self.ring.len();
        let mut best = f64::INFINITY;
        for k in 0..n {
            let (a, b) = (self.ring[k], self.ring[(k + 1) % n]);
            let (l, h) = (a[1].min(b[1]), a[1].max(b[1]));
            if v < l || v > h {
                continue;
            }
            let u = if h - l > 0.0 {
                a[0] + (v - a[1]) / (b[1] - a[1]) * (b[0] - a[0])
            } else {
                a[0].min(b[0])
            };
            best = best.min(u);
        }
        if best.is_finite() {
            best
        } else {
            // Rounding put v a hair outside: the nearer end.
            self.ring
                .iter()
                .min_by(|p, q| (p[1] - v).abs().total_cmp(&(q[1] - v).abs()))
                .map_or(f64::INFINITY, |p| p[0])
        }
    }
}

/// The lower envelope of lines over one interval of `v`, each line given
/// by its `u` at the interval's ends: the pieces (t0, u0, t1, u1) in
/// t ∈ [0, 1], where one line is least throughout.
fn envelope(lines: &[(f64, f64)]) -> Vec<(f64, f64, f64, f64)> {
    let value = |k: usize, t: f64| lines[k].0 + (lines[k].1 - lines[k].0) * t;
    // The least at t = 0, ties to the one that stays least.
    let Some(mut cur) = (0..lines.len()).min_by(|&a, &b| {
        lines[a]
            .0
            .total_cmp(&lines[b].0)
            .then(lines[a].1.total_cmp(&lines[b].1))
    }) else {
        return Vec::new();
    };
    let mut t = 0.0;
    let mut out = Vec::new();
    // The least of lines is concave: each line takes over at most once,
    // the one crossing first below the current one next.
    loop {
        let slope = |k: usize| lines[k].1 - lines[k].0;
        let next = (0..lines.len())
            .filter(|&k| slope(k) < slope(cur))
            .map(|k| {
                let gap = value(k, t) - value(cur, t);
                (k, t + gap.max(0.0) / (slope(cur) - slope(k)))
            })
            .filter(|&(_, at)| at < 1.0)
            .min_by(|a, b| a.1.total_cmp(&b.1).then(slope(a.0).total_cmp(&slope(b.0))));
        match next {
            Some((k, at)) => {
                if at > t {
                    out.push((t, value(cur, t), at, value(cur, at)));
                }
                t = at;
                cur = k;
            }
            None => {
                out.push((t, value(cur, t), 1.0, value(cur, 1.0)));
                return out;
            }
        }
    }
}

/// The L-zone of `face` for direction `r` (unit): the part of the face no
/// ray along `r` reaches before a barrier.
///
/// The union of the barriers' shadows is built directly rather than by
/// boolean unions of every shadow (which stalled for minutes on nearly
/// collinear shadows): in the direction's frame it is everything beyond
/// the lower envelope of the barriers' fronts, a polygon monotone across
/// the direction, cut once with the face.
pub fn l_zone(
    face: &MultiPolygon<f64>,
    barriers: &[Barrier],
    r: [f64; 2],
    radius: f64,
) -> MultiPolygon<f64> {
    let Some(rect) = face.bounding_rect() else {
        return MultiPolygon::new(vec![]);
    };
    let size = rect.width() + rect.height() + 2.0 * radius;
    let tiny = 1e-12 * size.max(1e-300);
    let fronts: Vec<Front> = barriers
        .iter()
        .filter_map(|b| Front::new(b, r, radius, tiny))
        .collect();
    // Beyond every barrier and the face.
    let corners = [
        [rect.min().x, rect.min().y],
        [rect.max().x, rect.min().y],
        [rect.min().x, rect.max().y],
        [rect.max().x, rect.max().y],
    ];
    let far = fronts
        .iter()
        .flat_map(|f| f.ring.iter().map(|p| p[0]))
        .chain(corners.iter().map(|p| p[0] * r[0] + p[1] * r[1]))
        .fold(f64::NEG_INFINITY, f64::max)
        + size;
    let mut levels: Vec<f64> = fronts
        .iter()
        .flat_map(|f| f.ring.iter().map(|p| p[1]))
        .collect();
    levels.sort_by(f64::total_cmp);
    levels.dedup_by(|a, b| *a - *b <= tiny);
    // The shade's outline, bottom to top, one polygon per run of levels
    // with a barrier.
    let mut polygons: Vec<Vec<[f64; 2]>> = Vec::new();
    let mut chain: Vec<[f64; 2]> = Vec::new();
    let close = |chain: &mut Vec<[f64; 2]>, polygons: &mut Vec<Vec<[f64; 2]>>| {
        if let (Some(&first), Some(&last)) = (chain.first(), chain.last()) {
            chain.push([far, last[1]]);
            chain.push([far, first[1]]);
            polygons.push(std::mem::take(chain));
        }
    };
    for w in levels.windows(2) {
        let (v0, v1) = (w[0], w[1]);
        let lines: Vec<(f64, f64)> = fronts
            .iter()
            .filter(|f| f.lo <= v0 + tiny && f.hi >= v1 - tiny)
            .map(|f| (f.at(v0), f.at(v1)))
            .collect();
        if lines.is_empty() {
            close(&mut chain, &mut polygons);
            continue;
        }
        for (t0, u0, t1, u1) in envelope(&lines) {
            for p in [[u0, v0 + (v1 - v0) * t0], [u1, v0 + (v1 - v0) * t1]] {
                if chain.last() != Some(&p) {
                    chain.push(p);
                }
            }
        }
    }
    close(&mut chain, &mut polygons);
    let shade = MultiPolygon::new(
        polygons
            .into_iter()
            .map(|ring| {
                let back = ring
                    .iter()
                    .map(|&[u, v]| (u * r[0] - v * r[1], u * r[1] + v * r[0]))
                    .collect::<Vec<_>>();
                Polygon::new(LineString::from(back), vec![])
            })
            .collect(),
    );
    face.intersection(&shade)
}

/// A direction's L-zone and how it changes the G-zone.
#[derive(Clone, Debug)]
pub struct Step {
    /// mm² of the face this direction alone leaves.
    pub l_zone: f64,
    /// mm² left after this direction and all before it.
    pub g_zone: f64,
    /// Reachable area / face area after it.
    pub visibility: f64,
}

/// Directions' L-zones (`l_zone`) taken in order until the visibility
/// ratio reaches `threshold`: the G-zone (their intersection), and each
/// step's figures. Stops after the first direction reaching it.
pub fn g_zone(
    face: &MultiPolygon<f64>,
    l_zones: &[MultiPolygon<f64>],
    threshold: f64,
) -> (MultiPolygon<f64>, Vec<Step>) {
    let area = face.unsigned_area().max(1e-300);
    let mut g: Option<MultiPolygon<f64>> = None;
    let mut steps = Vec::new();
    for l in l_zones {
        let next = match &g {
            None => l.clone(),
            Some(g) => g.intersection(l),
        };
        let left = next.unsigned_area().min(area);
        steps.push(Step {
            l_zone: l.unsigned_area(),
            g_zone: left,
            visibility: 1.0 - left / area,
        });
        g = Some(next);
        if 1.0 - left / area >= threshold {
            break;
        }
    }
    (g.unwrap_or_else(|| face.clone()), steps)
}

#[cfg(test)]
mod tests {
    use super::*;
    use geo::polygon;

    fn square(x0: f64, y0: f64, w: f64, h: f64) -> MultiPolygon<f64> {
        MultiPolygon::new(vec![polygon![
            (x: x0, y: y0), (x: x0 + w, y: y0), (x: x0 + w, y: y0 + h), (x: x0, y: y0 + h)
        ]])
    }

    fn rel(a: f64, b: f64) -> f64 {
        (a - b).abs() / b.abs().max(1e-300)
    }

    /// A 100 × 60 face with an obstacle box 10 × 10 at (40..50, 20..30):
    /// along +x the shadow is the strip 20..30 from x = 40 to the end,
    /// 60 × 10 = 600 mm²; along +y it is 40..50 from y = 20, 10 × 40 =
    /// 400 mm²; both together leave their overlap, the box, 100 mm².
    #[test]
    fn an_obstacle_shades_its_strip_by_construction() {
        let face = square(0.0, 0.0, 100.0, 60.0);
        let obstacle = Barrier {
            points: vec![[40.0, 20.0], [50.0, 20.0], [50.0, 30.0], [40.0, 30.0]],
        };
        let bs = [obstacle];
        let lx = l_zone(&face, &bs, [1.0, 0.0], 0.0).unsigned_area();
        assert!(rel(lx, 600.0) < 1e-9, "{lx}");
        let ly = l_zone(&face, &bs, [0.0, 1.0], 0.0).unsigned_area();
        assert!(rel(ly, 400.0) < 1e-9, "{ly}");
        let ls = [
            l_zone(&face, &bs, [1.0, 0.0], 0.0),
            l_zone(&face, &bs, [0.0, 1.0], 0.0),
        ];
        let (g, steps) = g_zone(&face, &ls, 0.999);
        assert_eq!(steps.len(), 2);
        assert!(rel(g.unsigned_area(), 100.0) < 1e-9);
        assert!(steps[1].g_zone < steps[0].g_zone);
        assert!(rel(steps[1].visibility, 1.0 - 100.0 / 6000.0) < 1e-12);
    }

    /// The tool's radius widens the shadow across the direction: radius 2
    /// makes the +x strip 14 wide, 60 × 14 = 840 mm² (the box's own
    /// 10 × 4 corners before it add nothing: the strip starts at x = 40).
    #[test]
    fn a_tool_radius_widens_the_shadow() {
        let face = square(0.0, 0.0, 100.0, 60.0);
        let obstacle = Barrier {
            points: vec![[40.0, 20.0], [50.0, 20.0], [50.0, 30.0], [40.0, 30.0]],
        };
        let l = l_zone(&face, &[obstacle], [1.0, 0.0], 2.0).unsigned_area();
        assert!(rel(l, 840.0) < 1e-9, "{l}");
    }

    /// A closed edge across the face's middle (a wall from y = 0 to 60 at
    /// x = 50, as on an L-shaped face) shades the half behind it: 3000 mm²
    /// along +x, nothing along +y (the ray runs beside the wall).
    #[test]
    fn a_closed_edge_shades_what_lies_behind_it() {
        let face = square(0.0, 0.0, 100.0, 60.0);
        let wall = Barrier {
            points: vec![[50.0, 0.0], [50.0, 60.0]],
        };
        let lx = l_zone(&face, std::slice::from_ref(&wall), [1.0, 0.0], 0.0).unsigned_area();
        assert!(rel(lx, 3000.0) < 1e-9, "{lx}");
        let ly = l_zone(&face, &[wall], [0.0, 1.0], 0.0).unsigned_area();
        assert!(ly < 1e-9, "{ly}");
    }

    /// Directions stop once the threshold is met.
    #[test]
    fn directions_stop_at_the_threshold() {
        let face = square(0.0, 0.0, 100.0, 60.0);
        let obstacle = Barrier {
            points: vec![[40.0, 20.0], [50.0, 20.0], [50.0, 30.0], [40.0, 30.0]],
        };
        // +x leaves 600 of 6000: 90 %; with 0.85 one direction is enough.
        let bs = [obstacle];
        let ls = [
            l_zone(&face, &bs, [1.0, 0.0], 0.0),
            l_zone(&face, &bs, [0.0, 1.0], 0.0),
        ];
        let (_, steps) = g_zone(&face, &ls, 0.85);
        assert_eq!(steps.len(), 1);
        assert!(rel(steps[0].visibility, 0.9) < 1e-12);
    }

    /// Barriers whose fronts cross: the envelope switches at the crossing.
    /// Along +x, a wall from (30, 0) to (70, 60) and one from (70, 0) to
    /// (30, 60) cross at (50, 30); the shade is everything right of the
    /// nearer: below y = 30 the first, above it the second. Left of the
    /// fronts the face keeps two triangles of 30 × 20 / 2 and the strip
    /// x < 30: 1800 + 2 × 300 = 2400 unshaded of 6000.
    #[test]
    fn crossing_fronts_switch_at_the_crossing() {
        let face = square(0.0, 0.0, 100.0, 60.0);
        let bs = [
            Barrier {
                points: vec![[30.0, 0.0], [70.0, 60.0]],
            },
            Barrier {
                points: vec![[70.0, 0.0], [30.0, 60.0]],
            },
        ];
        let l = l_zone(&face, &bs, [1.0, 0.0], 0.0).unsigned_area();
        assert!(rel(l, 3600.0) < 1e-9, "{l}");
    }

    /// Nearly collinear barriers along one edge (a closed edge and the
    /// hull of the wall face on it, a hair apart, as tessellation gives)
    /// once stalled the boolean union of shadows for minutes: the envelope
    /// takes them as they come. The face is the triangle below the 45°
    /// edge x = y: rays coming down (−y) meet the edge first and leave the
    /// whole face, 1800 mm², unreached; rays coming up (+y) reach all of it.
    #[test]
    fn nearly_collinear_barriers_are_cheap_and_exact() {
        let face = MultiPolygon::new(vec![polygon![
            (x: 0.0, y: 0.0), (x: 60.0, y: 0.0), (x: 60.0, y: 60.0)
        ]]);
        let along = |d: f64| Barrier {
            points: vec![
                [0.0 + d, 0.0 - d],
                [60.0 + d, 60.0 - d],
                [30.0 + d, 30.0 - d],
            ],
        };
        let bs: Vec<Barrier> = (0..50).map(|k| along(1e-10 * k as f64)).collect();
        // Travelling −y from above, every ray meets the edge first.
        let down = l_zone(&face, &bs, [0.0, -1.0], 0.0).unsigned_area();
        assert!(rel(down, 1800.0) < 1e-9, "{down}");
        // Travelling +y from below, the face lies before the edge.
        let up = l_zone(&face, &bs, [0.0, 1.0], 0.0).unsigned_area();
        assert!(up < 1e-6, "{up}");
    }
}
