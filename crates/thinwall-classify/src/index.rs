//! A uniform 3-D grid of boxes, to find the faces near a face without
//! comparing it with every face (a 10,000-face part has thousands of
//! volumes).

use thinwall_geom::BoundingBox;

/// Boxes by grid cell.
pub struct BoxIndex {
    lo: [f64; 3],
    step: [f64; 3],
    n: usize,
    cells: Vec<Vec<usize>>,
    grow: f64,
}

impl BoxIndex {
    /// Cells per axis.
    const SIDE: usize = 24;

    /// Index `boxes`, each grown by `grow`.
    pub fn new(boxes: &[BoundingBox], grow: f64) -> Self {
        let n = Self::SIDE;
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for b in boxes {
            for k in 0..3 {
                lo[k] = lo[k].min(b.min[k] - grow);
                hi[k] = hi[k].max(b.max[k] + grow);
            }
        }
        let step = [0, 1, 2].map(|k| ((hi[k] - lo[k]) / n as f64).max(1e-9));
        let mut index = Self {
            lo,
            step,
            n,
            cells: vec![Vec::new(); n * n * n],
            grow,
        };
        for (i, b) in boxes.iter().enumerate() {
            let (a, z) = index.range(b);
            for x in a[0]..=z[0] {
                for y in a[1]..=z[1] {
                    for w in a[2]..=z[2] {
                        index.cells[(x * n + y) * n + w].push(i);
                    }
                }
            }
        }
        index
    }

    fn range(&self, b: &BoundingBox) -> ([usize; 3], [usize; 3]) {
        let at = |k: usize, v: f64| {
            if !v.is_finite() {
                return 0;
            }
            (((v - self.lo[k]) / self.step[k]).floor().max(0.0) as usize).min(self.n - 1)
        };
        (
            [0, 1, 2].map(|k| at(k, b.min[k] - self.grow)),
            [0, 1, 2].map(|k| at(k, b.max[k] + self.grow)),
        )
    }

    /// Indices of the boxes that may touch `b`, each once, ascending.
    pub fn near(&self, b: &BoundingBox) -> Vec<usize> {
        let (a, z) = self.range(b);
        let n = self.n;
        let mut out = Vec::new();
        for x in a[0]..=z[0] {
            for y in a[1]..=z[1] {
                for w in a[2]..=z[2] {
                    out.extend_from_slice(&self.cells[(x * n + y) * n + w]);
                }
            }
        }
        out.sort_unstable();
        out.dedup();
        out
    }
}
