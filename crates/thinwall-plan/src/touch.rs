//! Which part faces a machining feature touches: the faces bounding its
//! pieces from below and above, and the vertical faces its cells run along
//! over a height they share.

use crate::types::Piece;
use std::collections::BTreeSet;
use thinwall_removal::{Bound, Removal};

/// `step_id`s of the part faces touching `pieces`, sorted.
pub fn faces_touched(r: &Removal, pieces: &[Piece], tol: f64) -> Vec<u64> {
    let mut out = BTreeSet::new();
    for p in pieces {
        for b in [p.lower, p.upper] {
            if let Bound::Part(i) = b {
                out.insert(r.part_step_id(i));
            }
        }
        let rings = p
            .region
            .0
            .iter()
            .flat_map(|poly| std::iter::once(poly.exterior()).chain(poly.interiors()));
        for ring in rings {
            for w in ring.0.windows(2) {
                let m = (0.5 * (w[0].x + w[1].x), 0.5 * (w[0].y + w[1].y));
                for v in r.vertical_near(m.0, m.1).iter().map(|&k| &r.vertical[k]) {
                    if out.contains(&v.step_id)
                        || v.z[1] < p.z[0] + tol
                        || v.z[0] > p.z[1] - tol
                        || m.0 < v.bbox.min().x - tol
                        || m.0 > v.bbox.max().x + tol
                        || m.1 < v.bbox.min().y - tol
                        || m.1 > v.bbox.max().y + tol
                    {
                        continue;
                    }
                    if v.segments.iter().any(|s| distance(m, s) <= tol) {
                        out.insert(v.step_id);
                    }
                }
            }
        }
    }
    out.into_iter().collect()
}

fn distance(p: (f64, f64), s: &[(f64, f64); 2]) -> f64 {
    let (a, b) = (s[0], s[1]);
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l2 = dx * dx + dy * dy;
    let t = if l2 > 0.0 {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p.0 - a.0 - t * dx).hypot(p.1 - a.1 - t * dy)
}
