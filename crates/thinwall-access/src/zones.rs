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
use geo::{BooleanOps, ConvexHull, MultiPoint, MultiPolygon, Point, Polygon};

/// A barrier of the sketch: a closed edge's piece (two points) or an
/// obstacle's bounding shape (its corners).
#[derive(Clone, Debug)]
pub struct Barrier {
    pub points: Vec<[f64; 2]>,
}

/// The region behind `barrier` along the unit direction `r`, widened by
/// `radius` across it, out to `reach` beyond.
fn shadow(barrier: &Barrier, r: [f64; 2], radius: f64, reach: f64) -> Option<Polygon<f64>> {
    let across = [-r[1], r[0]];
    let mut pts: Vec<Point<f64>> = Vec::with_capacity(barrier.points.len() * 4);
    for p in &barrier.points {
        for side in [-radius, radius] {
            let q = [p[0] + across[0] * side, p[1] + across[1] * side];
            pts.push(Point::new(q[0], q[1]));
            pts.push(Point::new(q[0] + r[0] * reach, q[1] + r[1] * reach));
        }
    }
    let hull = MultiPoint::from(pts).convex_hull();
    (hull.unsigned_area() > 0.0).then_some(hull)
}

/// The L-zone of `face` for direction `r` (unit): the part of the face no
/// ray along `r` reaches before a barrier.
pub fn l_zone(
    face: &MultiPolygon<f64>,
    barriers: &[Barrier],
    r: [f64; 2],
    radius: f64,
) -> MultiPolygon<f64> {
    let Some(rect) = face.bounding_rect() else {
        return MultiPolygon::new(vec![]);
    };
    // Far enough to leave the face whatever the barrier.
    let reach = 4.0 * (rect.width() + rect.height()) + 4.0 * radius + 1.0;
    let mut shade = MultiPolygon::new(vec![]);
    for b in barriers {
        if let Some(s) = shadow(b, r, radius, reach) {
            shade = shade.union(&MultiPolygon::new(vec![s]));
        }
    }
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
}
