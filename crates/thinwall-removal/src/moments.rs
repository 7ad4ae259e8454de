//! Polygon moments: area and first moments of rings, and the flux of a
//! plane over a polygon (exact), for the fluxes of every height kind.

use geo::{LineString, Polygon};

/// Signed area and first moments of a closed ring: (A, ∫x, ∫y).
pub(crate) fn moments(ls: &LineString<f64>) -> (f64, f64, f64) {
    let (mut a, mut mx, mut my) = (0.0, 0.0, 0.0);
    for w in ls.0.windows(2) {
        let (p, q) = (w[0], w[1]);
        let c = p.x * q.y - q.x * p.y;
        a += c;
        mx += (p.x + q.x) * c;
        my += (p.y + q.y) * c;
    }
    (0.5 * a, mx / 6.0, my / 6.0)
}

/// Unsigned area of a polygon (exterior minus holes).
pub fn area(p: &Polygon<f64>) -> f64 {
    region_sum(p, |ls| {
        let (a, _, _) = moments(ls);
        (a, a)
    })
}

/// Sums a ring quantity over a polygon as region integrals: `f` returns
/// (the ring integral, the ring's signed area in the same traversal).
pub(crate) fn region_sum(p: &Polygon<f64>, f: impl Fn(&LineString<f64>) -> (f64, f64)) -> f64 {
    let ring = |ls: &LineString<f64>| {
        let (i, a) = f(ls);
        if a < 0.0 {
            -i
        } else {
            i
        }
    };
    ring(p.exterior()) - p.interiors().iter().map(ring).sum::<f64>()
}

/// `∫∫_p (z0 + gx·x + gy·y) dA`, mm³.
pub fn plane_flux(z0: f64, gx: f64, gy: f64, p: &Polygon<f64>) -> f64 {
    region_sum(p, |ls| {
        let (a, mx, my) = moments(ls);
        (z0 * a + gx * mx + gy * my, a)
    })
}
