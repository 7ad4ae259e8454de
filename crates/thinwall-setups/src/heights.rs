//! A height map of the part along an up (issue 37): over a grid on the
//! stock's footprint, the highest point of the part's mesh above each
//! square. What a tool along up reaches (material with nothing of the part
//! above it) is estimated on it in milliseconds, where the exact removal
//! takes seconds to minutes on a large part: the set-ups' candidates are
//! ranked on height maps, and only the set-ups chosen get their exact
//! removal (`proposal.rs`).

use thinwall_analysis::PartAnalysis;
use thinwall_geom::{Frame, Point3, Vector3};
use thinwall_removal::frame_of;

/// Squares along the footprint's longer side.
pub const SQUARES: usize = 512;

/// The part's highest point per square, in the removal frame of an up.
pub struct HeightMap {
    frame: Frame,
    lo: [f64; 3],
    hi: [f64; 3],
    n: [usize; 2],
    /// A square's sides along x and y (the squares tile the footprint
    /// exactly), mm.
    step: [f64; 2],
    /// Per square (row by row along y), the part's highest point; −∞
    /// where no part lies over it.
    top: Vec<f64>,
}

impl HeightMap {
    /// The map of `a`'s mesh along `up`, over the stock of that set-up.
    pub fn along(a: &PartAnalysis, up: Vector3) -> Self {
        let (frame, lo, hi) = frame_of(a, up);
        let side = (hi[0] - lo[0]).max(hi[1] - lo[1]).max(1e-9) / SQUARES as f64;
        let n = [
            (((hi[0] - lo[0]) / side).ceil() as usize).max(1),
            (((hi[1] - lo[1]) / side).ceil() as usize).max(1),
        ];
        let step = [
            (hi[0] - lo[0]).max(1e-9) / n[0] as f64,
            (hi[1] - lo[1]).max(1e-9) / n[1] as f64,
        ];
        let mut map = Self {
            frame,
            lo,
            hi,
            n,
            step,
            top: vec![f64::NEG_INFINITY; n[0] * n[1]],
        };
        let mesh = a.mesh();
        let local: Vec<Vector3> = mesh.points.iter().map(|p| frame.to_local(p)).collect();
        for t in mesh.faces.iter().flat_map(|f| &f.triangles) {
            map.triangle(t.map(|i| local[i as usize]));
        }
        map
    }

    /// The square holding (x, y), if any.
    fn square(&self, x: f64, y: f64) -> Option<usize> {
        let i = ((x - self.lo[0]) / self.step[0]).floor();
        let j = ((y - self.lo[1]) / self.step[1]).floor();
        let inside = i >= 0.0 && j >= 0.0 && (i as usize) < self.n[0] && (j as usize) < self.n[1];
        inside.then(|| j as usize * self.n[0] + i as usize)
    }

    fn raise(&mut self, x: f64, y: f64, z: f64) {
        if let Some(k) = self.square(x, y) {
            self.top[k] = self.top[k].max(z);
        }
    }

    /// A triangle's heights over the square centres it covers; one that
    /// covers none (the top of a wall thinner than a square) along its
    /// edges instead. A triangle seen edge-on (a vertical wall) adds
    /// nothing: its neighbours above give its top, and marking the squares
    /// its edges cross would raise the half of each that lies off the wall.
    fn triangle(&mut self, [p, q, r]: [Vector3; 3]) {
        let det = (q.x - p.x) * (r.y - p.y) - (r.x - p.x) * (q.y - p.y);
        if det.abs() <= 1e-12 * self.step[0] * self.step[1] {
            return;
        }
        let (x0, x1) = (p.x.min(q.x).min(r.x), p.x.max(q.x).max(r.x));
        let (y0, y1) = (p.y.min(q.y).min(r.y), p.y.max(q.y).max(r.y));
        let step = self.step;
        // Only the squares near the triangle's run along each row are
        // tested (a sliver across the footprint has a large box and few
        // squares), each as before: the run is widened well past the
        // test's own tolerance.
        let margin = 1e-9 * ((x1 - x0) + (y1 - y0) + step[0] + step[1]);
        let mut covered = 0;
        for j in centres(y0, y1, self.lo[1], self.n[1], step[1]) {
            let cy = self.lo[1] + (j as f64 + 0.5) * step[1];
            let Some((rx0, rx1)) = run([p, q, r], cy, margin) else {
                continue;
            };
            let (i0, i1) = (rx0.max(x0), rx1.min(x1));
            for i in centres(i0, i1, self.lo[0], self.n[0], step[0]) {
                let cx = self.lo[0] + (i as f64 + 0.5) * step[0];
                let u = ((q.x - cx) * (r.y - cy) - (r.x - cx) * (q.y - cy)) / det;
                let v = ((r.x - cx) * (p.y - cy) - (p.x - cx) * (r.y - cy)) / det;
                let w = 1.0 - u - v;
                if u >= -1e-12 && v >= -1e-12 && w >= -1e-12 {
                    let k = j * self.n[0] + i;
                    self.top[k] = self.top[k].max(u * p.z + v * q.z + w * r.z);
                    covered += 1;
                }
            }
        }
        if covered > 0 {
            return;
        }
        for (a, b) in [(p, q), (q, r), (r, p)] {
            let steps = ((b - a).xy().norm() / (0.5 * step[0].min(step[1])))
                .ceil()
                .max(1.0) as usize;
            for k in 0..=steps {
                let c = a + (b - a) * (k as f64 / steps as f64);
                self.raise(c.x, c.y, c.z);
            }
        }
    }

    /// Material with nothing of the part above it: per square, from the
    /// part's highest point (the stock's bottom where none) up to the
    /// stock's top, mm³.
    pub fn reachable_mm3(&self) -> f64 {
        let area = self.step[0] * self.step[1];
        self.top
            .iter()
            .map(|t| area * (self.hi[2] - t.clamp(self.lo[2], self.hi[2])))
            .sum()
    }

    /// The stock's volume, mm³.
    pub fn stock_mm3(&self) -> f64 {
        (0..3).map(|k| self.hi[k] - self.lo[k]).product()
    }

    /// Whether a tool along up reaches world point `p` (nothing of the
    /// part above it, to a thousandth of a square).
    pub fn reaches(&self, p: &Point3) -> bool {
        let l = self.frame.to_local(p);
        self.square(l.x, l.y)
            .is_none_or(|k| l.z >= self.top[k] - 1e-3 * self.step[0])
    }
}

/// The squares (of `n` from `o`, `step` wide) whose centres lie within
/// [v0, v1].
fn centres(v0: f64, v1: f64, o: f64, n: usize, step: f64) -> std::ops::Range<usize> {
    let a = ((v0 - o) / step - 0.5).ceil().max(0.0);
    let b = (((v1 - o) / step - 0.5).floor() + 1.0).min(n as f64);
    if b > a {
        a as usize..b as usize
    } else {
        0..0
    }
}

/// The x extent of the triangle within `margin` of the line y = `cy`
/// (its part in that band: where its edges enter and leave the band, and
/// its corners in it), widened by `margin`; `None` when it misses the
/// band.
fn run([p, q, r]: [Vector3; 3], cy: f64, margin: f64) -> Option<(f64, f64)> {
    let (lo, hi) = (cy - margin, cy + margin);
    let mut x = (f64::INFINITY, f64::NEG_INFINITY);
    let mut take = |v: f64| x = (x.0.min(v), x.1.max(v));
    for (a, b) in [(p, q), (q, r), (r, p)] {
        let dy = b.y - a.y;
        if dy == 0.0 {
            if a.y >= lo && a.y <= hi {
                take(a.x);
                take(b.x);
            }
            continue;
        }
        let (t0, t1) = ((lo - a.y) / dy, (hi - a.y) / dy);
        let (t0, t1) = (t0.min(t1).max(0.0), t0.max(t1).min(1.0));
        if t0 <= t1 {
            take(a.x + t0 * (b.x - a.x));
            take(a.x + t1 * (b.x - a.x));
        }
    }
    (x.0 <= x.1).then_some((x.0 - margin, x.1 + margin))
}

/// The part's volume from its mesh (the divergence theorem), mm³.
pub fn mesh_volume(a: &PartAnalysis) -> f64 {
    let mesh = a.mesh();
    let o = mesh.points.first().copied().unwrap_or(Point3::origin());
    mesh.faces
        .iter()
        .flat_map(|f| &f.triangles)
        .map(|t| {
            let [p, q, r] = t.map(|i| mesh.points[i as usize] - o);
            p.dot(&q.cross(&r)) / 6.0
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn map(n: usize) -> HeightMap {
        HeightMap {
            frame: Frame::from_axis(Point3::origin(), Vector3::z(), None).unwrap(),
            lo: [0.0; 3],
            hi: [n as f64; 3],
            n: [n, n],
            step: [1.0, 1.0],
            top: vec![f64::NEG_INFINITY; n * n],
        }
    }

    /// Every square whose centre is in the triangle's box tested (what
    /// `triangle` did before it tested only the squares by each row's
    /// run); how many it raised.
    fn every_square(m: &mut HeightMap, [p, q, r]: [Vector3; 3]) -> usize {
        let det = (q.x - p.x) * (r.y - p.y) - (r.x - p.x) * (q.y - p.y);
        let (x0, x1) = (p.x.min(q.x).min(r.x), p.x.max(q.x).max(r.x));
        let (y0, y1) = (p.y.min(q.y).min(r.y), p.y.max(q.y).max(r.y));
        let mut covered = 0;
        for j in centres(y0, y1, 0.0, m.n[1], m.step[1]) {
            let cy = (j as f64 + 0.5) * m.step[1];
            for i in centres(x0, x1, 0.0, m.n[0], m.step[0]) {
                let cx = (i as f64 + 0.5) * m.step[0];
                let u = ((q.x - cx) * (r.y - cy) - (r.x - cx) * (q.y - cy)) / det;
                let v = ((r.x - cx) * (p.y - cy) - (p.x - cx) * (r.y - cy)) / det;
                let w = 1.0 - u - v;
                if u >= -1e-12 && v >= -1e-12 && w >= -1e-12 {
                    let k = j * m.n[0] + i;
                    m.top[k] = m.top[k].max(u * p.z + v * q.z + w * r.z);
                    covered += 1;
                }
            }
        }
        covered
    }

    /// Over 4,000 random triangles (slivers across the map, corners on
    /// square centres and a hair off them, level edges), the squares each
    /// raises and their heights are those every square tested gives, bit
    /// for bit.
    #[test]
    fn a_triangle_raises_the_squares_every_square_tested_would() {
        let mut seed = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut raised = 0;
        for k in 0..4000 {
            let mut corner = || {
                let centre = |v: f64| (v * 32.0).floor() + 0.5;
                match k % 4 {
                    0 => Vector3::new(centre(next()), centre(next()), next()),
                    // A hair outside the centre: inside the test's
                    // tolerance on one side, outside the exact run.
                    1 => {
                        let hair = 4e-14 * (next() - 0.5);
                        Vector3::new(centre(next()) + hair, centre(next()) - hair, next())
                    }
                    _ => Vector3::new(next() * 34.0 - 1.0, next() * 34.0 - 1.0, next()),
                }
            };
            let mut t = [corner(), corner(), corner()];
            if k % 5 == 2 {
                // A sliver: the third corner just off the first two's line.
                let s = next();
                t[2] = t[0] + (t[1] - t[0]) * s + Vector3::new(1e-3 * next(), -1e-3 * next(), 0.0);
            }
            if k % 7 == 3 {
                t[1].y = t[0].y;
            }
            let det = (t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[2].x - t[0].x) * (t[1].y - t[0].y);
            if det.abs() <= 1e-12 {
                continue;
            }
            let (mut a, mut b) = (map(32), map(32));
            a.triangle(t);
            if every_square(&mut b, t) > 0 {
                raised += 1;
                let differ =
                    (a.top.iter().zip(&b.top)).position(|(x, y)| x.to_bits() != y.to_bits());
                assert_eq!(differ, None, "triangle {k}: {t:?}");
            }
        }
        assert!(raised > 2000, "{raised}");
    }
}
