//! Integrals over a region's part inside a convex polygon, without a
//! boolean: each ring clipped by the convex polygon's sides in turn
//! (Sutherland–Hodgman).
//!
//! Clipping a closed ring by a half-plane keeps its winding number at
//! every point of the half-plane and makes it zero outside; where the
//! ring leaves and re-enters, the output runs along the clipping line
//! there and back, which adds nothing to a boundary integral. So the
//! signed moments of the clipped ring are the moments of the ring's part
//! inside, counted by winding number, whatever the ring's shape: a valid
//! region's rings (outlines one way round, holes the other) give the
//! region's part exactly. The output is not a valid polygon (it may touch
//! itself along the cuts) and is only ever integrated.

use geo::{MultiPolygon, Rect};

/// A region as rings with weights: its integral is the sum over rings of
/// weight × the ring's signed integral (weight +1 for a counter-clockwise
/// outline, −1 for a clockwise one, the opposite for holes).
#[derive(Clone, Debug, Default)]
pub struct Wound {
    pub rings: Vec<(Vec<[f64; 2]>, f64)>,
}

impl Wound {
    /// `m`'s rings (closing repeat dropped), each weighted so that the
    /// outlines count +1 and the holes −1 whichever way they run.
    pub fn of(m: &MultiPolygon<f64>) -> Self {
        let mut rings = Vec::new();
        for p in m {
            let mut put = |ls: &geo::LineString<f64>, outline: bool| {
                let mut pts: Vec<[f64; 2]> = ls.coords().map(|c| [c.x, c.y]).collect();
                if pts.len() > 1 && pts.first() == pts.last() {
                    pts.pop();
                }
                let a = signed_area(&pts);
                if pts.len() >= 3 && a != 0.0 {
                    let w = if (a > 0.0) == outline { 1.0 } else { -1.0 };
                    rings.push((pts, w));
                }
            };
            put(p.exterior(), true);
            for h in p.interiors() {
                put(h, false);
            }
        }
        Self { rings }
    }

    /// Corners over all rings.
    pub fn corners(&self) -> usize {
        self.rings.iter().map(|(r, _)| r.len()).sum()
    }

    pub fn is_empty(&self) -> bool {
        self.rings.is_empty()
    }

    /// The part inside `rect`.
    pub fn in_rect(&self, rect: &Rect<f64>) -> Self {
        let (lo, hi) = (rect.min(), rect.max());
        let square = [[lo.x, lo.y], [hi.x, lo.y], [hi.x, hi.y], [lo.x, hi.y]];
        self.in_convex(&square)
    }

    /// The part inside the convex polygon `convex` (counter-clockwise).
    pub fn in_convex(&self, convex: &[[f64; 2]]) -> Self {
        let rings = self
            .rings
            .iter()
            .filter_map(|(r, w)| {
                let c = clip_convex(r, convex);
                (c.len() >= 3).then_some((c, *w))
            })
            .collect();
        Self { rings }
    }

    /// `∫∫ (z0 + gx·x + gy·y) dA` over the region, mm³ (exact).
    pub fn plane_flux(&self, z0: f64, gx: f64, gy: f64) -> f64 {
        self.rings
            .iter()
            .map(|(r, w)| {
                let (a, mx, my) = moments(r);
                w * (z0 * a + gx * mx + gy * my)
            })
            .sum()
    }
}

/// Signed area of an open ring (counter-clockwise positive).
pub fn signed_area(r: &[[f64; 2]]) -> f64 {
    moments(r).0
}

/// Signed area and first moments of an open ring: (A, ∫x, ∫y).
pub(crate) fn moments(r: &[[f64; 2]]) -> (f64, f64, f64) {
    let (mut a, mut mx, mut my) = (0.0, 0.0, 0.0);
    for k in 0..r.len() {
        let (p, q) = (r[k], r[(k + 1) % r.len()]);
        let c = p[0] * q[1] - q[0] * p[1];
        a += c;
        mx += (p[0] + q[0]) * c;
        my += (p[1] + q[1]) * c;
    }
    (0.5 * a, mx / 6.0, my / 6.0)
}

/// `ring` clipped by each side of the convex polygon `convex`
/// (counter-clockwise): empty when nothing is left.
pub fn clip_convex(ring: &[[f64; 2]], convex: &[[f64; 2]]) -> Vec<[f64; 2]> {
    let mut cur = ring.to_vec();
    let mut next = Vec::with_capacity(ring.len() + 4);
    for k in 0..convex.len() {
        if cur.is_empty() {
            break;
        }
        let (a, b) = (convex[k], convex[(k + 1) % convex.len()]);
        // Left of a→b (inside) where side ≥ 0.
        let side = |p: &[f64; 2]| (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
        next.clear();
        for i in 0..cur.len() {
            let (p, q) = (cur[i], cur[(i + 1) % cur.len()]);
            let (sp, sq) = (side(&p), side(&q));
            if sp >= 0.0 {
                next.push(p);
            }
            if (sp >= 0.0) != (sq >= 0.0) {
                let t = sp / (sp - sq);
                next.push([p[0] + (q[0] - p[0]) * t, p[1] + (q[1] - p[1]) * t]);
            }
        }
        std::mem::swap(&mut cur, &mut next);
    }
    cur
}

#[cfg(test)]
mod tests {
    use super::*;
    use geo::{Area, LineString, Polygon};

    fn square(x: f64, y: f64, s: f64) -> Vec<(f64, f64)> {
        vec![(x, y), (x + s, y), (x + s, y + s), (x, y + s), (x, y)]
    }

    /// A non-convex region with a hole (an L with a square hole), its
    /// rings either way round, clipped by triangles and boxes: the area
    /// and the plane's flux are those of the exact intersection (the
    /// booleans'), to rounding.
    #[test]
    fn clipped_integrals_are_the_intersections() {
        let l_shape = vec![
            (0.0, 0.0),
            (4.0, 0.0),
            (4.0, 1.0),
            (1.0, 1.0),
            (1.0, 4.0),
            (0.0, 4.0),
            (0.0, 0.0),
        ];
        for (outer_ccw, hole_ccw) in [(true, false), (false, true), (true, true)] {
            let mut o = l_shape.clone();
            if !outer_ccw {
                o.reverse();
            }
            let mut hole = square(0.25, 0.25, 0.5);
            if !hole_ccw {
                hole.reverse();
            }
            let region = MultiPolygon::new(vec![Polygon::new(
                LineString::from(o),
                vec![LineString::from(hole)],
            )]);
            let w = Wound::of(&region);
            let tris = [
                [[-1.0, -1.0], [5.0, 0.5], [0.5, 5.0]],
                [[0.5, 0.5], [3.0, 0.5], [0.5, 3.0]],
                [[2.0, 2.0], [3.0, 2.0], [2.0, 3.0]],
            ];
            for t in tris {
                let clip = MultiPolygon::new(vec![Polygon::new(
                    LineString::from(vec![t[0], t[1], t[2], t[0]]),
                    vec![],
                )]);
                let exact = thinwall_analysis::boolean::intersection(&region, &clip);
                let part = w.in_convex(&t);
                let a = part.plane_flux(1.0, 0.0, 0.0);
                assert!((a - exact.unsigned_area()).abs() < 1e-12, "{a}");
                let f = part.plane_flux(2.0, 0.5, -0.25);
                let g: f64 = exact
                    .0
                    .iter()
                    .map(|p| crate::moments::plane_flux(2.0, 0.5, -0.25, p))
                    .sum();
                assert!((f - g).abs() < 1e-12, "{f} {g}");
            }
            let b = Rect::new((0.5, -1.0), (2.0, 2.0));
            let exact = thinwall_analysis::boolean::intersection(
                &region,
                &MultiPolygon::new(vec![b.to_polygon()]),
            );
            let got = w.in_rect(&b).plane_flux(1.0, 0.0, 0.0);
            assert!((got - exact.unsigned_area()).abs() < 1e-12);
        }
    }

    /// A ring wholly outside leaves nothing; wholly inside, itself.
    #[test]
    fn outside_is_empty_and_inside_is_whole() {
        let r = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let far = [[5.0, 5.0], [6.0, 5.0], [5.0, 6.0]];
        assert!(clip_convex(&r, &far).is_empty());
        let big = [[-5.0, -5.0], [5.0, -5.0], [0.0, 9.0]];
        assert_eq!(clip_convex(&r, &big), r);
    }
}
