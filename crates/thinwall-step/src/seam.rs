//! A surface of revolution's seam turned away from its face. step-io
//! revolves a profile a full turn from an arbitrary direction (an
//! `AXIS1_PLACEMENT` has none of its own), so the u = 0 meridian can run
//! through the middle of the face: a pocket's corner where the corner
//! radius and the floor fillet meet (a spindle torus that OpenCascade
//! writes as a `SURFACE_OF_REVOLUTION`) then has a loop across the seam,
//! and meshing it in parameter space went wrong by millimetres. The full
//! turn is a rational circle of 9 control rows, 90° apart every second
//! row: starting it a quarter turn later is a cyclic shift of the rows, an
//! exact reparametrisation. The quarter whose start lies farthest from the
//! face's boundary is chosen.

/// The u knots of a full rational circle in four quarter arcs (over 0..1;
/// any range scaled to it).
const CIRCLE_KNOTS: [f64; 12] = [
    0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0,
];

use thinwall_geom::{Point3, Vector3};

type Grid<T> = Vec<Vec<T>>;

/// Turn the seam of a full-turn surface of revolution (`points` and
/// `weights` indexed `[u][v]`, u the circle) by the quarter turns that put
/// it farthest from `boundary` (points on the face's boundary, in the same
/// coordinates). Anything else is left as it is.
pub fn away_from(
    knots_u: &[f64],
    points: &mut Grid<[f64; 3]>,
    weights: &mut Grid<f64>,
    boundary: &[[f64; 3]],
) {
    if points.len() != 9 || knots_u.len() != 12 || boundary.is_empty() {
        return;
    }
    // Quarter arcs of equal spans, over any range.
    let (k0, k1) = (knots_u[0], knots_u[11]);
    let span = k1 - k0;
    if span.is_nan()
        || span <= 0.0
        || knots_u
            .iter()
            .zip(CIRCLE_KNOTS)
            .any(|(a, b)| ((a - k0) / span - b).abs() > 1e-12)
    {
        return;
    }
    let Some(angle) = Angles::of(points) else {
        return;
    };
    let thetas: Vec<f64> = boundary.iter().filter_map(|p| angle.of_point(p)).collect();
    let tau = std::f64::consts::TAU;
    // How far a seam at quarter k lies from the nearest boundary point.
    let clearance = |k: usize| {
        let seam = k as f64 * tau / 4.0;
        thetas
            .iter()
            .map(|t| {
                let d = (t - seam).rem_euclid(tau);
                d.min(tau - d)
            })
            .fold(f64::INFINITY, f64::min)
    };
    // The first quarter of the largest clearance.
    let best = (1..4).fold(0, |b, k| if clearance(k) > clearance(b) { k } else { b });
    if best == 0 {
        return;
    }
    rotate(points, 2 * best);
    rotate(weights, 2 * best);
}

/// Start a closed run of 9 rows (the last a repeat of the first) `by` rows
/// later.
fn rotate<T: Clone>(rows: &mut Grid<T>, by: usize) {
    let ring: Vec<Vec<T>> = rows[..8].to_vec();
    let mut out: Vec<Vec<T>> = (0..8).map(|i| ring[(i + by) % 8].clone()).collect();
    out.push(out[0].clone());
    *rows = out;
}

/// Angles about the axis of a full turn, measured from its seam.
struct Angles {
    centre: Point3,
    x: Vector3,
    y: Vector3,
}

impl Angles {
    /// From the profile control point farthest from the axis: rows 0 and
    /// 4 lie opposite each other (0° and 180°), row 2 at 90°.
    fn of(points: &Grid<[f64; 3]>) -> Option<Self> {
        let p = |i: usize, k: usize| Point3::from(points[i][k]);
        let j = (0..points[0].len()).max_by(|&a, &b| {
            (p(0, a) - p(4, a))
                .norm()
                .total_cmp(&(p(0, b) - p(4, b)).norm())
        })?;
        let centre = Point3::from((p(0, j).coords + p(4, j).coords) * 0.5);
        let x = (p(0, j) - centre).try_normalize(1e-12)?;
        let z = x.cross(&(p(2, j) - centre)).try_normalize(1e-12)?;
        Some(Self {
            centre,
            x,
            y: z.cross(&x),
        })
    }

    /// A point's angle from the seam, 0..2π; none on the axis.
    fn of_point(&self, p: &[f64; 3]) -> Option<f64> {
        let d = Point3::from(*p) - self.centre;
        let (a, b) = (d.dot(&self.x), d.dot(&self.y));
        (a.hypot(b) > 1e-9).then(|| b.atan2(a).rem_euclid(std::f64::consts::TAU))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cylinder of radius 2 about z as a full rational turn over
    /// v ∈ {0, 1} heights, and a face on its quarter from 0° to 90°: the
    /// seam moves to 180° (two quarters on), the rows shift by four, and
    /// every point of the surface stays on it.
    #[test]
    fn the_seam_moves_to_the_quarter_farthest_from_the_face() {
        let w = std::f64::consts::FRAC_1_SQRT_2;
        let corners = [
            (1.0, 0.0),
            (1.0, 1.0),
            (0.0, 1.0),
            (-1.0, 1.0),
            (-1.0, 0.0),
            (-1.0, -1.0),
            (0.0, -1.0),
            (1.0, -1.0),
            (1.0, 0.0),
        ];
        let mut points: Grid<[f64; 3]> = corners
            .iter()
            .map(|&(a, b)| vec![[2.0 * a, 2.0 * b, 0.0], [2.0 * a, 2.0 * b, 1.0]])
            .collect();
        let mut weights: Grid<f64> = (0..9)
            .map(|i| vec![if i % 2 == 0 { 1.0 } else { w }; 2])
            .collect();
        let before = points.clone();
        let boundary = [
            [2.0, 0.0, 0.0],
            [0.0, 2.0, 0.0],
            [2.0f64.sqrt(), 2.0f64.sqrt(), 1.0],
        ];
        away_from(&CIRCLE_KNOTS, &mut points, &mut weights, &boundary);
        assert_eq!(points[0], before[4]);
        assert_eq!(points[8], before[4]);
        assert_eq!(points[4], before[0]);
        assert_eq!(weights[1][0], w);
        // Not a circle's knots: left alone.
        let mut other = before.clone();
        away_from(&[0.0; 12], &mut other, &mut weights, &boundary);
        assert_eq!(other, before);
    }
}
