//! A piecewise linear height: the triangles of a face the removal cannot
//! take exactly (a tilted cylinder, cone or torus, a free-form face), all
//! facing one way, as one graph piece over the union of their projections.
//! A grid over their boxes finds the triangle under a point; a flux over a
//! polygon is the sum of each triangle's plane over its part of the
//! polygon (the polygon's rings clipped by the triangle, `crate::clip`).

use crate::clip::{signed_area, Wound};
use geo::{Coord, MultiPolygon, Polygon, Rect};

/// Triangles (x, y, z in the removal frame) over their projections.
#[derive(Debug)]
pub struct Facets {
    tris: Vec<[[f64; 3]; 3]>,
    /// Per triangle, its plane `z = z0 + gx·x + gy·y`.
    planes: Vec<[f64; 3]>,
    boxes: Vec<Rect<f64>>,
    grid: Grid,
}

/// Triangles by square of a grid over their boxes.
#[derive(Debug)]
struct Grid {
    origin: [f64; 2],
    step: f64,
    nx: usize,
    ny: usize,
    cells: Vec<Vec<u32>>,
}

/// Squares of the grid along its longer side, at most.
const MAX_GRID: usize = 512;

impl Grid {
    fn new(boxes: &[Rect<f64>]) -> Self {
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for b in boxes {
            lo = [lo[0].min(b.min().x), lo[1].min(b.min().y)];
            hi = [hi[0].max(b.max().x), hi[1].max(b.max().y)];
        }
        let extent = (hi[0] - lo[0]).max(hi[1] - lo[1]).max(1e-9);
        let per_side = ((boxes.len() as f64).sqrt().ceil() as usize).clamp(1, MAX_GRID);
        let step = extent / per_side as f64;
        let nx = (((hi[0] - lo[0]) / step).ceil() as usize).clamp(1, MAX_GRID);
        let ny = (((hi[1] - lo[1]) / step).ceil() as usize).clamp(1, MAX_GRID);
        let mut grid = Grid {
            origin: lo,
            step,
            nx,
            ny,
            cells: vec![Vec::new(); nx * ny],
        };
        for (k, b) in boxes.iter().enumerate() {
            let ([i0, j0], [i1, j1]) = grid.span(b);
            for j in j0..=j1 {
                for i in i0..=i1 {
                    grid.cells[j * nx + i].push(k as u32);
                }
            }
        }
        grid
    }

    /// The squares a box covers: (first i, j), (last i, j).
    fn span(&self, b: &Rect<f64>) -> ([usize; 2], [usize; 2]) {
        let idx =
            |v: f64, o: f64, n: usize| (((v - o) / self.step).floor().max(0.0) as usize).min(n - 1);
        (
            [
                idx(b.min().x, self.origin[0], self.nx),
                idx(b.min().y, self.origin[1], self.ny),
            ],
            [
                idx(b.max().x, self.origin[0], self.nx),
                idx(b.max().y, self.origin[1], self.ny),
            ],
        )
    }

    /// The triangles whose boxes may meet `b`, each once.
    fn near(&self, b: &Rect<f64>) -> Vec<u32> {
        let ([i0, j0], [i1, j1]) = self.span(b);
        let mut out: Vec<u32> = (j0..=j1)
            .flat_map(|j| (i0..=i1).map(move |i| (i, j)))
            .flat_map(|(i, j)| self.cells[j * self.nx + i].iter().copied())
            .collect();
        out.sort_unstable();
        out.dedup();
        out
    }
}

fn overlaps(a: &Rect<f64>, b: &Rect<f64>) -> bool {
    a.min().x <= b.max().x
        && b.min().x <= a.max().x
        && a.min().y <= b.max().y
        && b.min().y <= a.max().y
}

/// A triangle's normal `(b − a) × (c − a)` (not unit: twice its area long).
pub(crate) fn normal(t: &[[f64; 3]; 3]) -> [f64; 3] {
    let [a, b, c] = *t;
    let (u, v) = (
        [b[0] - a[0], b[1] - a[1], b[2] - a[2]],
        [c[0] - a[0], c[1] - a[1], c[2] - a[2]],
    );
    [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ]
}

impl Facets {
    /// `tris` in the removal frame, none standing vertical.
    pub fn new(tris: Vec<[[f64; 3]; 3]>) -> Self {
        let planes = tris
            .iter()
            .map(|t| {
                let (a, n) = (t[0], normal(t));
                let (gx, gy) = (-n[0] / n[2], -n[1] / n[2]);
                [a[2] - gx * a[0] - gy * a[1], gx, gy]
            })
            .collect();
        let boxes: Vec<Rect<f64>> = tris
            .iter()
            .map(|t| {
                let xs = t.map(|p| p[0]);
                let ys = t.map(|p| p[1]);
                Rect::new(
                    Coord {
                        x: xs.iter().copied().fold(f64::INFINITY, f64::min),
                        y: ys.iter().copied().fold(f64::INFINITY, f64::min),
                    },
                    Coord {
                        x: xs.iter().copied().fold(f64::NEG_INFINITY, f64::max),
                        y: ys.iter().copied().fold(f64::NEG_INFINITY, f64::max),
                    },
                )
            })
            .collect();
        let grid = Grid::new(&boxes);
        Self {
            tris,
            planes,
            boxes,
            grid,
        }
    }

    /// The triangles' own area, mm².
    pub fn area(&self) -> f64 {
        self.tris
            .iter()
            .map(|[a, b, c]| {
                let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
                let v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
                let n = [
                    u[1] * v[2] - u[2] * v[1],
                    u[2] * v[0] - u[0] * v[2],
                    u[0] * v[1] - u[1] * v[0],
                ];
                0.5 * (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt()
            })
            .sum()
    }

    pub fn len(&self) -> usize {
        self.tris.len()
    }

    pub fn is_empty(&self) -> bool {
        self.tris.is_empty()
    }

    fn plane_at(&self, k: usize, x: f64, y: f64) -> f64 {
        let [z0, gx, gy] = self.planes[k];
        z0 + gx * x + gy * y
    }

    /// The smallest barycentric coordinate of (x, y) in triangle `k`
    /// (≥ 0 inside).
    fn inside_by(&self, k: usize, x: f64, y: f64) -> f64 {
        let [a, b, c] = self.tris[k];
        let d = (b[1] - c[1]) * (a[0] - c[0]) + (c[0] - b[0]) * (a[1] - c[1]);
        if d == 0.0 {
            return f64::NEG_INFINITY;
        }
        let l1 = ((b[1] - c[1]) * (x - c[0]) + (c[0] - b[0]) * (y - c[1])) / d;
        let l2 = ((c[1] - a[1]) * (x - c[0]) + (a[0] - c[0]) * (y - c[1])) / d;
        l1.min(l2).min(1.0 - l1 - l2)
    }

    /// The height at (x, y): the plane of the triangle under it (the
    /// nearest one where rounding puts the point just outside all).
    pub fn at(&self, x: f64, y: f64) -> f64 {
        let p = Rect::new(Coord { x, y }, Coord { x, y });
        let mut near = self.grid.near(&p);
        if near.is_empty() {
            near = (0..self.tris.len() as u32).collect();
        }
        let best = near
            .iter()
            .map(|&k| (k as usize, self.inside_by(k as usize, x, y)))
            .max_by(|a, b| a.1.total_cmp(&b.1).then(b.0.cmp(&a.0)));
        best.map_or(f64::NAN, |(k, _)| self.plane_at(k, x, y))
    }

    /// The lowest and highest height over `region`: at its corners and at
    /// the corners of the triangles within its box (a triangle's corner
    /// just outside the region but inside its box can widen the range by
    /// at most that triangle's rise: a bound, cheap for a region of
    /// thousands of corners).
    pub fn range_over(&self, region: &MultiPolygon<f64>) -> [f64; 2] {
        use geo::BoundingRect;
        let mut z = [f64::INFINITY, f64::NEG_INFINITY];
        let mut add = |v: f64| z = [z[0].min(v), z[1].max(v)];
        for c in region.0.iter().flat_map(|p| p.exterior().0.iter()) {
            add(self.at(c.x, c.y));
        }
        let Some(bb) = region.bounding_rect() else {
            return z;
        };
        let inside = |p: &[f64; 3]| {
            p[0] >= bb.min().x && p[0] <= bb.max().x && p[1] >= bb.min().y && p[1] <= bb.max().y
        };
        for k in self.grid.near(&bb) {
            for p in self.tris[k as usize].iter().filter(|p| inside(p)) {
                add(p[2]);
            }
        }
        z
    }

    /// `∫∫_p h dA`, mm³: each triangle's plane over its part of `p`.
    pub fn flux(&self, p: &Polygon<f64>) -> f64 {
        use geo::BoundingRect;
        let Some(bb) = p.bounding_rect() else {
            return 0.0;
        };
        thinwall_analysis::parallel::check_deadline();
        let tris: Vec<usize> = self
            .grid
            .near(&bb)
            .into_iter()
            .map(|k| k as usize)
            .filter(|&k| overlaps(&self.boxes[k], &bb))
            .collect();
        let region = Wound::of(&MultiPolygon::new(vec![p.clone()]));
        self.flux_over(region, bb, tris, 0)
    }

    /// The flux of triangles `tris` over `region` (within `rect`):
    /// triangle by triangle where that is little work, else over the two
    /// halves of `rect`, the region clipped to each. The halves partition
    /// the region, so a triangle's part of it is the sum of its parts in
    /// the halves; and a large region (a meshed face's outline of
    /// thousands of corners) is cut once per level, not once per triangle.
    fn flux_over(&self, region: Wound, rect: Rect<f64>, tris: Vec<usize>, depth: usize) -> f64 {
        if region.is_empty() || tris.is_empty() {
            return 0.0;
        }
        if tris.len() * region.corners() <= DIRECT_WORK
            || tris.len() <= 2
            || depth >= MAX_SPLIT_DEPTH
        {
            return tris.iter().map(|&k| self.triangle_flux(k, &region)).sum();
        }
        thinwall_analysis::parallel::check_deadline();
        crate::halving::halves(&rect)
            .into_iter()
            .map(|h| {
                let mine: Vec<usize> = tris
                    .iter()
                    .copied()
                    .filter(|&k| overlaps(&self.boxes[k], &h))
                    .collect();
                self.flux_over(region.in_rect(&h), h, mine, depth + 1)
            })
            .sum()
    }

    /// Triangle `k`'s plane over its part of `region` (clipped by the
    /// triangle, [`crate::clip`]; a triangle seen edge-on holds nothing).
    fn triangle_flux(&self, k: usize, region: &Wound) -> f64 {
        let [a, b, c] = self.tris[k];
        let mut tri = [[a[0], a[1]], [b[0], b[1]], [c[0], c[1]]];
        let turn = signed_area(&tri);
        if turn == 0.0 {
            return 0.0;
        }
        if turn < 0.0 {
            tri.swap(1, 2);
        }
        let [z0, gx, gy] = self.planes[k];
        region.in_convex(&tri).plane_flux(z0, gx, gy)
    }
}

/// Triangles × corners of the region under which the flux is taken
/// triangle by triangle.
const DIRECT_WORK: usize = 4096;

/// Halvings of a flux's box, at most (a 2⁻²⁴ share of it).
const MAX_SPLIT_DEPTH: usize = 24;

impl serde::Serialize for Facets {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct;
        let mut st = s.serialize_struct("Facets", 1)?;
        st.serialize_field("triangles", &self.tris.len())?;
        st.end()
    }
}

/// Two facets are equal when they are the same triangles (one face's).
impl PartialEq for Facets {
    fn eq(&self, other: &Self) -> bool {
        std::ptr::eq(self, other) || self.tris == other.tris
    }
}

/// Serialize shared facets as the facets (serde's `rc` feature is off).
pub fn shared<S: serde::Serializer>(f: &std::sync::Arc<Facets>, s: S) -> Result<S::Ok, S::Error> {
    serde::Serialize::serialize(f.as_ref(), s)
}

#[cfg(test)]
mod tests {
    use super::*;
    use geo::LineString;

    /// A tilted plane over the unit square, in two triangles, and a
    /// paraboloid-like roof over a fan: heights and fluxes as exact as the
    /// planes they are made of.
    #[test]
    fn heights_and_fluxes_are_the_triangles_planes() {
        let z = |x: f64, y: f64| 1.0 + 0.5 * x - 0.25 * y;
        let p = |x: f64, y: f64| [x, y, z(x, y)];
        let f = Facets::new(vec![
            [p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0)],
            [p(0.0, 0.0), p(1.0, 1.0), p(0.0, 1.0)],
        ]);
        assert_eq!(f.len(), 2);
        for (x, y) in [(0.2, 0.1), (0.9, 0.95), (0.5, 0.5), (0.0, 1.0)] {
            assert!((f.at(x, y) - z(x, y)).abs() < 1e-12, "at {x}, {y}");
        }
        // ∫∫ over [0.25, 0.75]² of the plane: its area times its middle.
        let square = Polygon::new(
            LineString::from(vec![
                (0.25, 0.25),
                (0.75, 0.25),
                (0.75, 0.75),
                (0.25, 0.75),
                (0.25, 0.25),
            ]),
            vec![],
        );
        assert!((f.flux(&square) - 0.25 * z(0.5, 0.5)).abs() < 1e-12);
        let whole = MultiPolygon::new(vec![Polygon::new(
            LineString::from(vec![
                (0.0, 0.0),
                (1.0, 0.0),
                (1.0, 1.0),
                (0.0, 1.0),
                (0.0, 0.0),
            ]),
            vec![],
        )]);
        assert_eq!(f.range_over(&whole), [0.75, 1.5]);
        assert!((f.area() - 1.0 * (1.0f64 + 0.25 + 0.0625).sqrt()).abs() < 1e-12);
    }

    /// A fine roof (a paraboloid over a 60 × 60 grid of triangles) over a
    /// region of thousands of corners (an annulus of 3000-gons): the flux
    /// split over halves of its box (the region cut once per level) is the
    /// flux taken triangle by triangle over the whole region, and the
    /// exact integral of the triangles' planes to the triangulation's
    /// error.
    #[test]
    fn a_large_region_is_split_without_changing_its_flux() {
        let n = 60;
        let z = |x: f64, y: f64| 5.0 + 0.3 * x * x + 0.2 * y * y - 0.1 * x * y;
        let p = |i: usize, j: usize| {
            let (x, y) = (
                -1.0 + 2.0 * i as f64 / n as f64,
                -1.0 + 2.0 * j as f64 / n as f64,
            );
            [x, y, z(x, y)]
        };
        let mut tris = Vec::new();
        for i in 0..n {
            for j in 0..n {
                tris.push([p(i, j), p(i + 1, j), p(i + 1, j + 1)]);
                tris.push([p(i, j), p(i + 1, j + 1), p(i, j + 1)]);
            }
        }
        let f = Facets::new(tris);
        let ring = |r: f64, k: usize| {
            let mut v: Vec<(f64, f64)> = (0..k)
                .map(|t| {
                    let a = std::f64::consts::TAU * t as f64 / k as f64;
                    (0.1 + r * a.cos(), -0.05 + r * a.sin())
                })
                .collect();
            v.push(v[0]);
            LineString::from(v)
        };
        let mut hole = ring(0.3, 3000);
        hole.0.reverse();
        let annulus = Polygon::new(ring(0.85, 3000), vec![hole]);
        let split = f.flux(&annulus);
        let region = Wound::of(&MultiPolygon::new(vec![annulus.clone()]));
        let direct: f64 = (0..f.len()).map(|k| f.triangle_flux(k, &region)).sum();
        // Both sums clip the same rings, in other pieces: they differ by
        // rounding only.
        assert!(
            (split - direct).abs() < 1e-8 * direct.abs(),
            "{split} {direct}"
        );
        // The paraboloid's integral over the annulus (centre c, radii R, r):
        // ∫x² = A cx² + π(R⁴ − r⁴)/4, alike for y, ∫xy = A cx cy; to the
        // interpolation's error (h²/8 of the curvature, 1e-4 here).
        let (cx, cy, big, small) = (0.1f64, -0.05f64, 0.85f64, 0.3f64);
        let area = std::f64::consts::PI * (big * big - small * small);
        let ring4 = std::f64::consts::PI * (big.powi(4) - small.powi(4)) / 4.0;
        let exact = 5.0 * area + 0.3 * (area * cx * cx + ring4) + 0.2 * (area * cy * cy + ring4)
            - 0.1 * area * cx * cy;
        assert!((split - exact).abs() < 1e-3 * exact, "{split} {exact}");
    }

    /// A roof of four triangles round an apex: the flux over the whole is
    /// the pyramid's volume, over a quarter a quarter of it.
    #[test]
    fn a_pyramid_holds_its_volume() {
        let apex = [0.0, 0.0, 3.0];
        let c = [
            [-1.0, -1.0, 0.0],
            [1.0, -1.0, 0.0],
            [1.0, 1.0, 0.0],
            [-1.0, 1.0, 0.0],
        ];
        let f = Facets::new((0..4).map(|k| [c[k], c[(k + 1) % 4], apex]).collect());
        let square = |x0: f64, y0: f64, x1: f64, y1: f64| {
            Polygon::new(
                LineString::from(vec![(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)]),
                vec![],
            )
        };
        let volume = 4.0 * 3.0 / 3.0;
        assert!((f.flux(&square(-1.0, -1.0, 1.0, 1.0)) - volume).abs() < 1e-9);
        assert!((f.flux(&square(0.0, 0.0, 1.0, 1.0)) - volume / 4.0).abs() < 1e-9);
        assert!((f.at(0.0, 0.0) - 3.0).abs() < 1e-12);
        assert!((f.at(0.5, 0.0) - 1.5).abs() < 1e-12);
    }
}
