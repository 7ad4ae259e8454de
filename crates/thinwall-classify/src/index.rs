//! Boxes in an R-tree (rstar), to find the faces near a face without
//! comparing it with every face (a 10,000-face part has thousands of
//! volumes). A uniform grid did this before; on a rib-grid panel the faces
//! spanning it (the ribs' top, the web's bottom) and the large volumes made
//! every query gather most cells, 10 % of a plan's time.

use rstar::primitives::{GeomWithData, Rectangle};
use rstar::{RTree, AABB};
use thinwall_geom::BoundingBox;

type Entry = GeomWithData<Rectangle<[f64; 3]>, usize>;

/// Boxes by place.
pub struct BoxIndex {
    tree: RTree<Entry>,
    /// Boxes without finite corners (an empty face's): near everything.
    everywhere: Vec<usize>,
    grow: f64,
}

impl BoxIndex {
    /// Index `boxes`, each grown by `grow`.
    pub fn new(boxes: &[BoundingBox], grow: f64) -> Self {
        let mut everywhere = Vec::new();
        let mut entries = Vec::with_capacity(boxes.len());
        for (i, b) in boxes.iter().enumerate() {
            match grown(b, grow) {
                Some((lo, hi)) => entries.push(Entry::new(Rectangle::from_corners(lo, hi), i)),
                None => everywhere.push(i),
            }
        }
        Self {
            tree: RTree::bulk_load(entries),
            everywhere,
            grow,
        }
    }

    /// Indices of the boxes that may touch `b` (both grown), each once,
    /// ascending.
    pub fn near(&self, b: &BoundingBox) -> Vec<usize> {
        let mut out = self.everywhere.clone();
        match grown(b, self.grow) {
            Some((lo, hi)) => out.extend(
                self.tree
                    .locate_in_envelope_intersecting(&AABB::from_corners(lo, hi))
                    .map(|e| e.data),
            ),
            None => out.extend(self.tree.iter().map(|e| e.data)),
        }
        out.sort_unstable();
        out
    }
}

/// The corners of `b` grown by `grow`, when they are finite.
fn grown(b: &BoundingBox, grow: f64) -> Option<([f64; 3], [f64; 3])> {
    let lo = [0, 1, 2].map(|k| b.min[k] - grow);
    let hi = [0, 1, 2].map(|k| b.max[k] + grow);
    (lo.iter().chain(&hi).all(|v| v.is_finite()) && (0..3).all(|k| lo[k] <= hi[k]))
        .then_some((lo, hi))
}
