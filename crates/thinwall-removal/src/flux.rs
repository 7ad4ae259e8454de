//! `∫∫ h dA` of a piece's height over a polygon, exactly for planes (by
//! the polygon's moments) and by Green's theorem along the polygon's edges
//! for cylinders and cones, whose antiderivatives are closed forms. The
//! volume between two bounds over a cell is the difference of two fluxes.

use super::pieces::Height;
use geo::Polygon;
use thinwall_geom::quadrature::for_each_node;

/// Gauss nodes per polygon edge where the integrand is not polynomial.
const EDGE_NODES: usize = 16;

pub use crate::moments::area;
use crate::moments::region_sum;

/// `∫∫_p h dA`, mm³.
pub fn flux(h: &Height, p: &Polygon<f64>) -> f64 {
    match *h {
        Height::Plane { z0, gx, gy, .. } => crate::moments::plane_flux(z0, gx, gy, p),
        Height::Cylinder { o, a, r, sign } => {
            // In (u, s): u across the axis, s along it; ∫∫ g(u) = ∮ G(u) ds.
            let g = |u: f64| {
                let u = u.clamp(-r, r);
                0.5 * (u * (r * r - u * u).max(0.0).sqrt() + r * r * (u / r).asin())
            };
            let us = |x: f64, y: f64| {
                let (dx, dy) = (x - o[0], y - o[1]);
                (-dx * a[1] + dy * a[0], dx * a[0] + dy * a[1])
            };
            let half = region_sum(p, |ls| {
                let (mut i, mut area) = (0.0, 0.0);
                for w in ls.0.windows(2) {
                    let (u0, s0) = us(w[0].x, w[0].y);
                    let (u1, s1) = us(w[1].x, w[1].y);
                    let ds = s1 - s0;
                    area += 0.5 * (u0 + u1) * ds;
                    if ds == 0.0 {
                        continue;
                    }
                    if u0 == u1 {
                        i += g(u0) * ds;
                    } else {
                        for_each_node(0.0, 1.0, EDGE_NODES, |t, wt| {
                            i += g(u0 + (u1 - u0) * t) * ds * wt;
                        });
                    }
                }
                (i, area)
            });
            o[2] * area(p) + sign * half
        }
        // ∫∫ ρ dA: the radial field with F(ρ) = ρ/3.
        Height::Cone { c, z0, k, .. } => z0 * area(p) + k * radial_flux(p, c, |rho| rho / 3.0),
        Height::Facets { ref facets, .. } => facets.flux(p),
        Height::Revolved {
            c,
            zc,
            big_r,
            r,
            sign,
            ..
        } => zc * area(p) + sign * revolved_flux(p, c, big_r, r),
    }
}

/// `∫∫ √(r² − (ρ − R)²) dA` over a polygon about the axis through `c`, by
/// [`radial_flux`] with `ρ² F(ρ)` in closed form.
fn revolved_flux(p: &Polygon<f64>, c: [f64; 2], big_r: f64, r: f64) -> f64 {
    // ∫ (u + R) √(r² − u²) du, u = s − R.
    let prim = |u: f64| {
        let u = u.clamp(-r, r);
        let w = (r * r - u * u).max(0.0);
        -w * w.sqrt() / 3.0 + 0.5 * big_r * (u * w.sqrt() + r * r * (u / r).asin())
    };
    let u_lo = (-r).max(-big_r);
    let f_of = |rho: f64| {
        let d = rho - big_r;
        (r * r - d * d).max(0.0).sqrt()
    };
    let big_f = |rho: f64| {
        if rho < 1e-9 * r.max(1.0) {
            0.5 * f_of(0.0)
        } else {
            (prim(rho - big_r) - prim(u_lo)) / (rho * rho)
        }
    };
    radial_flux(p, c, big_f)
}

/// `∫∫ f(ρ) dA` over a polygon, ρ the distance from `c`, given
/// `F(ρ) = (1/ρ²) ∫₀^ρ f(s) s ds`: the field `F(ρ)·(x, y)` has divergence
/// `f`, so the integral is `∮ F(ρ) (x dy − y dx)` along the rings.
fn radial_flux(p: &Polygon<f64>, c: [f64; 2], big_f: impl Fn(f64) -> f64) -> f64 {
    region_sum(p, |ls| {
        let (mut i, mut area) = (0.0, 0.0);
        for w in ls.0.windows(2) {
            let (x0, y0) = (w[0].x - c[0], w[0].y - c[1]);
            let (x1, y1) = (w[1].x - c[0], w[1].y - c[1]);
            let cross = x0 * y1 - x1 * y0;
            area += 0.5 * cross;
            if cross == 0.0 {
                continue;
            }
            for_each_node(0.0, 1.0, EDGE_NODES, |t, wt| {
                let (x, y) = (x0 + (x1 - x0) * t, y0 + (y1 - y0) * t);
                i += big_f(x.hypot(y)) * cross * wt;
            });
        }
        (i, area)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use geo::{Coord, Rect};

    fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Polygon<f64> {
        Rect::new(Coord { x: x0, y: y0 }, Coord { x: x1, y: y1 }).to_polygon()
    }

    #[test]
    fn a_sloped_plane_over_a_square_is_its_centre_height_times_area() {
        let h = Height::plane(1.0, 0.5, -0.25);
        let v = flux(&h, &rect(0.0, 0.0, 2.0, 2.0));
        assert!((v - 4.0 * (1.0 + 0.5 - 0.25)).abs() < 1e-12);
    }

    #[test]
    fn a_half_cylinder_over_its_shadow_is_half_the_cylinder() {
        // Axis along y through the origin at z = 0, r = 2, length 3.
        let h = Height::Cylinder {
            o: [0.0, 0.0, 0.0],
            a: [0.0, 1.0],
            r: 2.0,
            sign: 1.0,
        };
        let v = flux(&h, &rect(-2.0, 0.0, 2.0, 3.0));
        let want = 0.5 * std::f64::consts::PI * 4.0 * 3.0;
        assert!((v - want).abs() < 1e-12, "{v} {want}");
    }

    /// A fine midpoint sum of `h` over a box, to check a flux against.
    fn fine_sum(h: &Height, x0: f64, y0: f64, x1: f64, y1: f64) -> f64 {
        let n = 1000;
        let (dx, dy) = ((x1 - x0) / n as f64, (y1 - y0) / n as f64);
        let mut s = 0.0;
        for i in 0..n {
            for j in 0..n {
                s += h.at(x0 + (i as f64 + 0.5) * dx, y0 + (j as f64 + 0.5) * dy) * dx * dy;
            }
        }
        s
    }

    #[test]
    fn a_hemisphere_over_its_shadow_is_half_the_ball() {
        let h = Height::revolved([0.0, 0.0], 1.0, 0.0, 2.0, 1.0);
        let shadow = geo::Polygon::new(
            geo::LineString::from(
                (0..=4096)
                    .map(|k| {
                        let t = std::f64::consts::TAU * k as f64 / 4096.0;
                        (2.0 * t.cos(), 2.0 * t.sin())
                    })
                    .collect::<Vec<_>>(),
            ),
            vec![],
        );
        let want = area(&shadow) * 1.0 + 2.0 / 3.0 * std::f64::consts::PI * 8.0;
        let v = flux(&h, &shadow);
        assert!((v - want).abs() < 1e-4 * want, "{v} {want}");
    }

    #[test]
    fn a_torus_half_over_a_box_matches_a_fine_sum() {
        // A pocket corner: R 8 about (0.5, -0.3), r 3, the lower half.
        let h = Height::revolved([0.5, -0.3], 2.0, 8.0, 3.0, -1.0);
        for (x0, y0, x1, y1) in [(6.0, -2.0, 9.0, 2.0), (-4.0, 6.0, 3.0, 9.5)] {
            let v = flux(&h, &rect(x0, y0, x1, y1));
            let s = fine_sum(&h, x0, y0, x1, y1);
            assert!((v - s).abs() < 1e-4 * s.abs().max(1.0), "{v} {s}");
        }
    }

    #[test]
    fn a_cone_over_a_square_matches_a_fine_sum() {
        let h = Height::cone([0.3, -0.2], 1.0, 2.0);
        let v = flux(&h, &rect(-1.0, -1.0, 1.0, 1.0));
        let n = 1000;
        let mut s = 0.0;
        for i in 0..n {
            for j in 0..n {
                let (x, y) = (
                    -1.0 + (i as f64 + 0.5) * 2.0 / n as f64,
                    -1.0 + (j as f64 + 0.5) * 2.0 / n as f64,
                );
                s += h.at(x, y) * (2.0 / n as f64).powi(2);
            }
        }
        assert!((v - s).abs() < 1e-5, "{v} {s}");
    }
}
