//! The union of cells of one arrangement, by their shared edges rather
//! than by polygon booleans.
//!
//! Cells come from separate booleans, so an edge two cells share is
//! computed twice and the copies differ by rounding; a boolean union then
//! leaves hairline gaps, or not, depending on how the part sits in the
//! world. Here vertices closer than a snap distance are one vertex, a
//! vertex lying on another cell's edge splits it, edges met in both
//! directions cancel, and what is left is chained into rings: the same
//! rings in every pose.

use geo::{Coord, LineString, Polygon, Winding};
use rstar::{primitives::GeomWithData, RTree, AABB};
use std::collections::HashMap;

type Vertex = usize;

/// Vertices merged within `snap` of a first-seen representative.
struct Vertices {
    points: Vec<[f64; 2]>,
    grid: HashMap<(i64, i64), Vec<Vertex>>,
    snap: f64,
}

impl Vertices {
    fn new(snap: f64) -> Self {
        Self {
            points: Vec::new(),
            grid: HashMap::new(),
            snap,
        }
    }

    fn square(&self, p: [f64; 2]) -> (i64, i64) {
        (
            (p[0] / self.snap).floor() as i64,
            (p[1] / self.snap).floor() as i64,
        )
    }

    fn id(&mut self, p: [f64; 2]) -> Vertex {
        let (i, j) = self.square(p);
        for di in -1..=1 {
            for dj in -1..=1 {
                if let Some(found) = self.grid.get(&(i + di, j + dj)) {
                    for &v in found {
                        let q = self.points[v];
                        if (q[0] - p[0]).hypot(q[1] - p[1]) <= self.snap {
                            return v;
                        }
                    }
                }
            }
        }
        let v = self.points.len();
        self.points.push(p);
        self.grid.entry((i, j)).or_default().push(v);
        v
    }
}

/// The union of `cells` (each a polygon with holes, any orientation) as
/// polygons whose rings are the boundary edges of the union; two cells
/// meeting only at a vertex stay apart. Vertices within `snap` are one.
pub fn union(cells: &[Polygon<f64>], snap: f64) -> Vec<Polygon<f64>> {
    let mut verts = Vertices::new(snap);
    let mut edges: Vec<(Vertex, Vertex)> = Vec::new();
    for cell in cells {
        let outer = cell.exterior();
        let ccw = outer.is_ccw();
        push_ring(&mut verts, &mut edges, outer, ccw);
        for hole in cell.interiors() {
            push_ring(&mut verts, &mut edges, hole, hole.is_cw());
        }
    }
    let edges = split_at_vertices(&verts, edges);
    let boundary = cancel(edges);
    let rings = chain(&verts.points, boundary);
    assemble(
        rings
            .into_iter()
            .map(|r| drop_straight(&r, 1e-3 * snap))
            .filter(|r| r.len() >= 3)
            .collect(),
    )
}

/// A ring's edges, turned so the region lies on their left.
fn push_ring(
    verts: &mut Vertices,
    edges: &mut Vec<(Vertex, Vertex)>,
    ring: &LineString<f64>,
    keep_direction: bool,
) {
    let mut ids: Vec<Vertex> = ring.0.iter().map(|c| verts.id([c.x, c.y])).collect();
    if !keep_direction {
        ids.reverse();
    }
    for w in ids.windows(2) {
        if w[0] != w[1] {
            edges.push((w[0], w[1]));
        }
    }
}

/// Each edge split at every vertex within snap of its inside, in order.
fn split_at_vertices(verts: &Vertices, edges: Vec<(Vertex, Vertex)>) -> Vec<(Vertex, Vertex)> {
    let tree: RTree<GeomWithData<[f64; 2], Vertex>> = RTree::bulk_load(
        verts
            .points
            .iter()
            .enumerate()
            .map(|(i, p)| GeomWithData::new(*p, i))
            .collect(),
    );
    let snap = verts.snap;
    let mut out = Vec::with_capacity(edges.len());
    for (a, b) in edges {
        let (pa, pb) = (verts.points[a], verts.points[b]);
        let d = [pb[0] - pa[0], pb[1] - pa[1]];
        let len2 = d[0] * d[0] + d[1] * d[1];
        let envelope = AABB::from_corners(
            [pa[0].min(pb[0]) - snap, pa[1].min(pb[1]) - snap],
            [pa[0].max(pb[0]) + snap, pa[1].max(pb[1]) + snap],
        );
        let mut inside: Vec<(f64, Vertex)> = tree
            .locate_in_envelope_intersecting(&envelope)
            .filter(|g| g.data != a && g.data != b)
            .filter_map(|g| {
                let q = g.geom();
                let t = ((q[0] - pa[0]) * d[0] + (q[1] - pa[1]) * d[1]) / len2;
                let off = (q[0] - pa[0]) * d[1] - (q[1] - pa[1]) * d[0];
                let along = t * len2.sqrt();
                let inner = along > snap && along < len2.sqrt() - snap;
                (inner && off.abs() <= snap * len2.sqrt()).then_some((t, g.data))
            })
            .collect();
        inside.sort_by(|x, y| x.0.total_cmp(&y.0));
        let mut from = a;
        for (_, v) in inside {
            out.push((from, v));
            from = v;
        }
        out.push((from, b));
    }
    out
}

/// The edges met more often one way than the other, that many times.
fn cancel(edges: Vec<(Vertex, Vertex)>) -> Vec<(Vertex, Vertex)> {
    let mut net: HashMap<(Vertex, Vertex), i64> = HashMap::new();
    for (a, b) in edges {
        if a < b {
            *net.entry((a, b)).or_default() += 1;
        } else {
            *net.entry((b, a)).or_default() -= 1;
        }
    }
    let mut out = Vec::new();
    let mut keys: Vec<_> = net.into_iter().filter(|(_, n)| *n != 0).collect();
    keys.sort();
    for ((a, b), n) in keys {
        let e = if n > 0 { (a, b) } else { (b, a) };
        out.extend(std::iter::repeat_n(e, n.unsigned_abs() as usize));
    }
    out
}

/// The boundary edges chained into closed rings. Where several edges
/// leave a vertex, the one turning most to the right is taken, so rings
/// touching at a vertex stay apart.
fn chain(points: &[[f64; 2]], edges: Vec<(Vertex, Vertex)>) -> Vec<Vec<[f64; 2]>> {
    let mut leaving: HashMap<Vertex, Vec<usize>> = HashMap::new();
    for (i, &(a, _)) in edges.iter().enumerate() {
        leaving.entry(a).or_default().push(i);
    }
    let angle = |a: Vertex, b: Vertex| {
        let (p, q) = (points[a], points[b]);
        (q[1] - p[1]).atan2(q[0] - p[0])
    };
    let mut used = vec![false; edges.len()];
    let mut rings = Vec::new();
    for start in 0..edges.len() {
        if used[start] {
            continue;
        }
        let mut ring = Vec::new();
        let mut e = start;
        loop {
            used[e] = true;
            let (a, b) = edges[e];
            ring.push(points[a]);
            let back = angle(b, a);
            // Clockwise from the way back: the first edge met.
            let next = leaving.get(&b).and_then(|out| {
                out.iter().copied().filter(|&k| !used[k]).min_by(|&x, &y| {
                    let turn = |k: usize| {
                        let t = back - angle(edges[k].0, edges[k].1);
                        t.rem_euclid(std::f64::consts::TAU)
                    };
                    turn(x).total_cmp(&turn(y))
                })
            });
            match next {
                Some(k) => e = k,
                None => break,
            }
            if e == start {
                break;
            }
        }
        if ring.len() >= 3 {
            rings.push(ring);
        }
    }
    rings
}

/// Vertices whose two edges run straight on (within `tol`) removed.
fn drop_straight(ring: &[[f64; 2]], tol: f64) -> Vec<[f64; 2]> {
    let mut r: Vec<[f64; 2]> = ring.to_vec();
    let mut changed = true;
    while changed && r.len() > 3 {
        changed = false;
        let n = r.len();
        for i in 0..n {
            let (p, q, s) = (r[(i + n - 1) % n], r[i], r[(i + 1) % n]);
            let d = [s[0] - p[0], s[1] - p[1]];
            let len = d[0].hypot(d[1]);
            let off = ((q[0] - p[0]) * d[1] - (q[1] - p[1]) * d[0]).abs();
            let ahead = (q[0] - p[0]) * d[0] + (q[1] - p[1]) * d[1];
            if len > 0.0 && off <= tol * len && ahead > 0.0 && ahead < len * len {
                r.remove(i);
                changed = true;
                break;
            }
        }
    }
    r
}

fn ring_area(r: &[[f64; 2]]) -> f64 {
    let n = r.len();
    (0..n)
        .map(|i| {
            let (p, q) = (r[i], r[(i + 1) % n]);
            p[0] * q[1] - q[0] * p[1]
        })
        .sum::<f64>()
        * 0.5
}

fn line(r: &[[f64; 2]]) -> LineString<f64> {
    let mut cs: Vec<Coord<f64>> = r.iter().map(|p| Coord { x: p[0], y: p[1] }).collect();
    cs.push(cs[0]);
    LineString::new(cs)
}

/// Counter-clockwise rings are outlines; clockwise ones are holes of the
/// smallest outline around them.
fn assemble(rings: Vec<Vec<[f64; 2]>>) -> Vec<Polygon<f64>> {
    use geo::{Contains, Point};
    let (outers, holes): (Vec<_>, Vec<_>) = rings.into_iter().partition(|r| ring_area(r) > 0.0);
    let shells: Vec<Polygon<f64>> = outers
        .iter()
        .map(|r| Polygon::new(line(r), vec![]))
        .collect();
    let mut inner: Vec<Vec<LineString<f64>>> = vec![Vec::new(); outers.len()];
    for h in holes {
        let owner = (0..outers.len())
            .filter(|&k| {
                h.iter()
                    .any(|p| shells[k].contains(&Point::new(p[0], p[1])))
            })
            .min_by(|&a, &b| ring_area(&outers[a]).total_cmp(&ring_area(&outers[b])));
        if let Some(k) = owner {
            inner[k].push(line(&h));
        }
    }
    outers
        .iter()
        .zip(inner)
        .map(|(r, hs)| Polygon::new(line(r), hs))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use geo::polygon;

    fn area(ps: &[Polygon<f64>]) -> f64 {
        ps.iter().map(crate::flux::area).sum()
    }

    #[test]
    fn cells_with_rounded_shared_edges_make_one_polygon() {
        let a = polygon![(x: 0.0, y: 0.0), (x: 1.0, y: 0.0), (x: 1.0, y: 1.0), (x: 0.0, y: 1.0)];
        // Shares a's right edge up to rounding, with a vertex in its middle.
        let b = polygon![(x: 1.0 + 1e-13, y: -1e-13), (x: 2.0, y: 0.0), (x: 2.0, y: 1.0),
            (x: 1.0, y: 1.0 + 1e-13), (x: 1.0 - 1e-13, y: 0.5)];
        let u = union(&[a, b], 1e-9);
        assert_eq!(u.len(), 1);
        assert!(u[0].interiors().is_empty());
        assert_eq!(u[0].exterior().0.len(), 5, "{:?}", u[0]);
        assert!((area(&u) - 2.0).abs() < 1e-9);
    }

    #[test]
    fn cells_meeting_at_a_corner_stay_apart() {
        let a = polygon![(x: 0.0, y: 0.0), (x: 1.0, y: 0.0), (x: 1.0, y: 1.0), (x: 0.0, y: 1.0)];
        let b = polygon![(x: 1.0, y: 1.0), (x: 2.0, y: 1.0), (x: 2.0, y: 2.0), (x: 1.0, y: 2.0)];
        let u = union(&[a, b], 1e-9);
        assert_eq!(u.len(), 2);
        assert!((area(&u) - 2.0).abs() < 1e-12);
    }

    #[test]
    fn a_ring_of_cells_has_a_hole() {
        // Four cells around a unit square, one given clockwise.
        let cells = vec![
            polygon![(x: 0.0, y: 0.0), (x: 3.0, y: 0.0), (x: 3.0, y: 1.0), (x: 0.0, y: 1.0)],
            polygon![(x: 0.0, y: 2.0), (x: 0.0, y: 3.0), (x: 3.0, y: 3.0), (x: 3.0, y: 2.0)],
            polygon![(x: 0.0, y: 1.0), (x: 1.0, y: 1.0), (x: 1.0, y: 2.0), (x: 0.0, y: 2.0)],
            polygon![(x: 2.0, y: 1.0), (x: 3.0, y: 1.0), (x: 3.0, y: 2.0), (x: 2.0, y: 2.0)],
        ];
        let u = union(&cells, 1e-9);
        assert_eq!(u.len(), 1);
        assert_eq!(u[0].interiors().len(), 1);
        assert_eq!(u[0].exterior().0.len(), 5);
        assert!((area(&u) - 8.0).abs() < 1e-12);
    }

    #[test]
    fn the_union_does_not_depend_on_cell_order() {
        let cells = vec![
            polygon![(x: 0.0, y: 0.0), (x: 1.0, y: 0.0), (x: 1.0, y: 1.0), (x: 0.0, y: 1.0)],
            polygon![(x: 1.0, y: 0.0), (x: 2.0, y: 0.0), (x: 2.0, y: 1.0), (x: 1.0, y: 1.0)],
            polygon![(x: 0.0, y: 1.0), (x: 2.0, y: 1.0), (x: 1.0, y: 2.0)],
        ];
        let mut rev = cells.clone();
        rev.reverse();
        let (a, b) = (union(&cells, 1e-9), union(&rev, 1e-9));
        assert_eq!(a.len(), 1);
        assert_eq!(b.len(), 1);
        assert_eq!(a[0].exterior().0.len(), b[0].exterior().0.len());
        assert!((area(&a) - area(&b)).abs() < 1e-12);
    }
}
