//! A height map of the part along an up (issue 37): over a grid on the
//! stock's footprint, the highest point of the part's mesh above each
//! square. What a tool along up reaches (material with nothing of the part
//! above it) is estimated on it in milliseconds, where the exact removal
//! takes seconds to minutes on a large part: the set-ups' candidates are
//! ranked on height maps, and only the set-ups chosen get their exact
//! removal ([`crate::proposal`]).

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
    step: f64,
    /// Per square (row by row along y), the part's highest point; −∞
    /// where no part lies over it.
    top: Vec<f64>,
}

impl HeightMap {
    /// The map of `a`'s mesh along `up`, over the stock of that set-up.
    pub fn along(a: &PartAnalysis, up: Vector3) -> Self {
        let (frame, lo, hi) = frame_of(a, up);
        let step = (hi[0] - lo[0]).max(hi[1] - lo[1]).max(1e-9) / SQUARES as f64;
        let n = [
            (((hi[0] - lo[0]) / step).ceil() as usize).max(1),
            (((hi[1] - lo[1]) / step).ceil() as usize).max(1),
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
        let i = ((x - self.lo[0]) / self.step).floor();
        let j = ((y - self.lo[1]) / self.step).floor();
        let inside = i >= 0.0 && j >= 0.0 && (i as usize) < self.n[0] && (j as usize) < self.n[1];
        inside.then(|| j as usize * self.n[0] + i as usize)
    }

    fn raise(&mut self, x: f64, y: f64, z: f64) {
        if let Some(k) = self.square(x, y) {
            self.top[k] = self.top[k].max(z);
        }
    }

    /// A triangle's heights over the square centres it covers, and along
    /// its edges (a wall thinner than a square, a face seen edge-on).
    fn triangle(&mut self, [p, q, r]: [Vector3; 3]) {
        for (a, b) in [(p, q), (q, r), (r, p)] {
            let steps = ((b - a).xy().norm() / (0.5 * self.step)).ceil().max(1.0) as usize;
            for k in 0..=steps {
                let c = a + (b - a) * (k as f64 / steps as f64);
                self.raise(c.x, c.y, c.z);
            }
        }
        let det = (q.x - p.x) * (r.y - p.y) - (r.x - p.x) * (q.y - p.y);
        if det.abs() <= 1e-12 * self.step * self.step {
            return;
        }
        let (x0, x1) = (p.x.min(q.x).min(r.x), p.x.max(q.x).max(r.x));
        let (y0, y1) = (p.y.min(q.y).min(r.y), p.y.max(q.y).max(r.y));
        let step = self.step;
        // The squares whose centres lie within [v0, v1] along one axis.
        let range = |v0: f64, v1: f64, o: f64, n: usize| {
            let a = ((v0 - o) / step - 0.5).ceil().max(0.0);
            let b = (((v1 - o) / step - 0.5).floor() + 1.0).min(n as f64);
            if b > a {
                a as usize..b as usize
            } else {
                0..0
            }
        };
        for j in range(y0, y1, self.lo[1], self.n[1]) {
            let cy = self.lo[1] + (j as f64 + 0.5) * step;
            for i in range(x0, x1, self.lo[0], self.n[0]) {
                let cx = self.lo[0] + (i as f64 + 0.5) * step;
                let u = ((q.x - cx) * (r.y - cy) - (r.x - cx) * (q.y - cy)) / det;
                let v = ((r.x - cx) * (p.y - cy) - (p.x - cx) * (r.y - cy)) / det;
                let w = 1.0 - u - v;
                if u >= -1e-12 && v >= -1e-12 && w >= -1e-12 {
                    let k = j * self.n[0] + i;
                    self.top[k] = self.top[k].max(u * p.z + v * q.z + w * r.z);
                }
            }
        }
    }

    /// Material with nothing of the part above it: per square, from the
    /// part's highest point (the stock's bottom where none) up to the
    /// stock's top, mm³.
    pub fn reachable_mm3(&self) -> f64 {
        let mut sum = 0.0;
        for j in 0..self.n[1] {
            let h = self
                .step
                .min(self.hi[1] - self.lo[1] - j as f64 * self.step);
            for i in 0..self.n[0] {
                let w = self
                    .step
                    .min(self.hi[0] - self.lo[0] - i as f64 * self.step);
                let from = self.top[j * self.n[0] + i].clamp(self.lo[2], self.hi[2]);
                sum += w * h * (self.hi[2] - from);
            }
        }
        sum
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
            .is_none_or(|k| l.z >= self.top[k] - 1e-3 * self.step)
    }
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
