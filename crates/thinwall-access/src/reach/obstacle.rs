//! One face's material in one zone of the tool (the cutter's slab or the
//! holder's), seen along the tool axis and grown by the tool's disk: where
//! the tool's axis must not be.
//!
//! Growing every triangle by the disk and joining them is exact but slow:
//! each grown triangle is a polygon of the disk's many corners. A region
//! grown by a convex disk around the origin is the region itself and its
//! outline grown (R ⊕ D = R ∪ ∂R ⊕ D: from a point of R towards a point
//! of R ⊕ D, the first boundary crossing is within D of it). So a
//! triangle none of whose edges can be on the outline enters as itself, a
//! polygon of three corners: every edge is a mesh edge shared, within the
//! face, with one triangle projected on its other side, none is a cut by
//! the zone's levels, and it is not seen edge-on. Every other triangle is
//! grown whole, as before. An edge taken for the outline wrongly only
//! costs time.
//!
//! Growing only the outline edges of the other triangles (and joining
//! collinear ones) would leave fewer corners still, but i_overlay stalled
//! on those unions (over two minutes on NIST CTC 05), as it did on the
//! joined outlines of whole faces.

use super::disk::grown;
use super::scene::Tri;
use geo::{Coord, MultiPolygon, Polygon};
use std::collections::{HashMap, HashSet};
use thinwall_analysis::boolean::union_all;

/// A projected corner this close to its edge's line (as a sine of the
/// angle at the edge) leaves the side undecided: the edge is grown.
const SIDE_SINE: f64 = 1e-9;
/// A projected piece whose area is below this share of its perimeter
/// squared is seen edge-on.
const EDGE_ON: f64 = 1e-9;

/// The pieces of one face's triangles within one zone.
#[derive(Default)]
pub struct Obstacle {
    pieces: Vec<Piece>,
    /// Its triangles only approximate their face ([`Tri::tessellated`]).
    pub tessellated: bool,
}

struct Piece {
    /// The clipped triangle's corners, projected.
    corners: Vec<[f64; 2]>,
    /// Per corner, the triangle's edge the piece's edge from it lies on.
    tags: Vec<Option<u8>>,
    /// The whole triangle: its mesh corners and their projections.
    v: [u32; 3],
    tri: [[f64; 2]; 3],
}

impl Piece {
    /// Whether none of the piece's edges can be on the region's outline.
    fn inside(&self, inner: &HashSet<(u32, u32)>) -> bool {
        !edge_on(&self.corners)
            && self
                .tags
                .iter()
                .all(|tag| tag.is_some_and(|k| inner.contains(&edge_key(&self.v, k as usize))))
    }
}

impl Obstacle {
    /// Adds triangle `t`'s part within the zone (`clipped`, from
    /// [`super::scene::clip_tagged`]); `project` maps scene `x, y` to the
    /// floor's plane.
    pub fn push(
        &mut self,
        t: &Tri,
        clipped: Vec<([f64; 3], Option<u8>)>,
        project: impl Fn([f64; 2]) -> [f64; 2],
    ) {
        if clipped.is_empty() {
            return;
        }
        self.tessellated |= t.tessellated;
        let (corners, tags) = clipped
            .into_iter()
            .map(|(p, tag)| (project([p[0], p[1]]), tag))
            .unzip();
        self.pieces.push(Piece {
            corners,
            tags,
            v: t.v,
            tri: t.p.map(|p| project([p[0], p[1]])),
        });
    }

    /// Keeps the pieces whose projected corners pass `keep`.
    pub fn retain(&mut self, keep: impl Fn(&[[f64; 2]]) -> bool) {
        self.pieces.retain(|p| keep(&p.corners));
    }

    pub fn is_empty(&self) -> bool {
        self.pieces.is_empty()
    }

    /// The pieces grown by `disk` (convex, counter-clockwise, around the
    /// origin) and joined.
    pub fn grown(&self, disk: &[[f64; 2]]) -> MultiPolygon<f64> {
        let inner = self.inner_edges();
        let parts = self.pieces.iter().filter_map(|piece| {
            if piece.inside(&inner) {
                Some(ccw_polygon(&piece.corners))
            } else {
                grown(&piece.corners, disk)
            }
        });
        union_all(parts.map(|p| MultiPolygon::new(vec![p])).collect())
    }

    /// Mesh edges shared by exactly two triangles of the face that lie on
    /// opposite sides of them in projection.
    fn inner_edges(&self) -> HashSet<(u32, u32)> {
        // Per edge: how many triangles, and how many on each side.
        let mut sides: HashMap<(u32, u32), [u32; 3]> = HashMap::new();
        for piece in &self.pieces {
            for k in 0..3 {
                let key = edge_key(&piece.v, k);
                let (a, b) = if piece.v[k] == key.0 {
                    (piece.tri[k], piece.tri[(k + 1) % 3])
                } else {
                    (piece.tri[(k + 1) % 3], piece.tri[k])
                };
                let c = piece.tri[(k + 2) % 3];
                let (e, f) = ([b[0] - a[0], b[1] - a[1]], [c[0] - a[0], c[1] - a[1]]);
                let cross = e[0] * f[1] - e[1] * f[0];
                let scale = e[0].hypot(e[1]) * f[0].hypot(f[1]);
                let entry = sides.entry(key).or_default();
                entry[0] += 1;
                if cross > SIDE_SINE * scale {
                    entry[1] += 1;
                } else if cross < -SIDE_SINE * scale {
                    entry[2] += 1;
                }
            }
        }
        sides
            .into_iter()
            .filter(|(_, s)| *s == [2, 1, 1])
            .map(|(key, _)| key)
            .collect()
    }
}

/// Edge `k` of a triangle (corner `k` to `k + 1`), lower index first.
fn edge_key(v: &[u32; 3], k: usize) -> (u32, u32) {
    let (a, b) = (v[k], v[(k + 1) % 3]);
    (a.min(b), a.max(b))
}

fn signed_area(ring: &[[f64; 2]]) -> f64 {
    let n = ring.len();
    0.5 * (0..n)
        .map(|i| {
            let (p, q) = (ring[i], ring[(i + 1) % n]);
            p[0] * q[1] - p[1] * q[0]
        })
        .sum::<f64>()
}

/// Whether a projected piece has (almost) no area: a triangle seen
/// edge-on, or a point or segment left by the cut.
fn edge_on(ring: &[[f64; 2]]) -> bool {
    let n = ring.len();
    if n < 3 {
        return true;
    }
    let perimeter: f64 = (0..n)
        .map(|i| {
            let (p, q) = (ring[i], ring[(i + 1) % n]);
            (q[0] - p[0]).hypot(q[1] - p[1])
        })
        .sum();
    signed_area(ring).abs() <= EDGE_ON * perimeter * perimeter
}

fn ccw_polygon(ring: &[[f64; 2]]) -> Polygon<f64> {
    let mut coords: Vec<Coord<f64>> = ring.iter().map(|p| Coord { x: p[0], y: p[1] }).collect();
    if signed_area(ring) < 0.0 {
        coords.reverse();
    }
    Polygon::new(coords.into(), vec![])
}

#[cfg(test)]
mod tests {
    use super::super::disk::disk;
    use super::super::scene::clip_tagged;
    use super::*;
    use geo::{Area, BooleanOps};

    /// A tilted triangle cut in four at its edges' middles: the middle one
    /// shares all three edges. Levels that miss it, and one through it.
    /// Grown, the same region as every piece grown whole (area within
    /// 1e-9, nothing of either outside the other), with the middle piece
    /// entered as itself only where no cut crosses it.
    #[test]
    fn growing_the_outline_is_growing_every_triangle() {
        let d = disk(2.0);
        let corner = [[0.0, 0.0, 0.0], [12.0, 0.0, 3.0], [0.0, 12.0, 6.0]];
        let mid = |a: usize, b: usize| {
            let (p, q) = (corner[a], corner[b]);
            [
                0.5 * (p[0] + q[0]),
                0.5 * (p[1] + q[1]),
                0.5 * (p[2] + q[2]),
            ]
        };
        // Points 0..2 the corners, 3..5 the middles of 01, 12, 20.
        let pts = [
            corner[0],
            corner[1],
            corner[2],
            mid(0, 1),
            mid(1, 2),
            mid(2, 0),
        ];
        let tris: Vec<Tri> = [[0, 3, 5], [3, 1, 4], [5, 4, 2], [3, 4, 5]]
            .into_iter()
            .map(|v: [u32; 3]| Tri::new(v.map(|i| pts[i as usize]), v, 0, false))
            .collect();
        for (lo, hi, whole_middle) in [(-1.0, 10.0, true), (-1.0, 4.0, false)] {
            let mut ob = Obstacle::default();
            let mut each = Vec::new();
            for t in &tris {
                let clipped = clip_tagged(&t.p, lo, hi);
                let flat: Vec<[f64; 2]> = clipped.iter().map(|(p, _)| [p[0], p[1]]).collect();
                each.extend(grown(&flat, &d).map(|p| MultiPolygon::new(vec![p])));
                ob.push(t, clipped, |p| p);
            }
            let inner = ob.inner_edges();
            let raw = ob.pieces.iter().filter(|p| p.inside(&inner)).count();
            assert_eq!(raw, usize::from(whole_middle), "{lo}..{hi}");
            let want = union_all(each);
            let got = ob.grown(&d);
            let a = want.unsigned_area();
            assert!((a - got.unsigned_area()).abs() <= 1e-9 * a, "{lo}..{hi}");
            assert!(want.difference(&got).unsigned_area() <= 1e-9 * a);
            assert!(got.difference(&want).unsigned_area() <= 1e-9 * a);
        }
    }

    /// Edges are shared by their mesh corners, and only across: two
    /// triangles folded onto one side of their edge leave it outside.
    #[test]
    fn a_fold_is_not_an_inner_edge() {
        let pts = [
            [0.0, 0.0, 0.0],
            [10.0, 0.0, 0.0],
            [5.0, 5.0, 1.0],
            [5.0, 3.0, 4.0],
        ];
        let mut ob = Obstacle::default();
        for v in [[0u32, 1, 2], [1, 0, 3]] {
            let t = Tri::new(v.map(|i| pts[i as usize]), v, 0, false);
            ob.push(&t, clip_tagged(&t.p, -1.0, 10.0), |p| p);
        }
        assert!(ob.inner_edges().is_empty());
    }
}
