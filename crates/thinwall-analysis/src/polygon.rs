//! Planar faces as polygons: their loops sampled into 3D polylines, and
//! projected into the 2D frame of any plane for overlap tests (geo); and the
//! measures of 2-D regions every recognizer shares (minimum rectangle,
//! narrow width, inscribed circle).

use geo::{Area, BooleanOps, Coord, LineString, MultiPolygon, Orient, Polygon};
use thinwall_brep::{FaceId, Part};
use thinwall_geom::{Frame, Point3, Surface, Vector3};

/// Samples per knot span of a curved edge.
const SAMPLES_PER_SPAN: usize = 8;

/// A face's loops as closed 3D polylines (outer loops first).
#[derive(Clone, Debug)]
pub struct FaceLoops {
    pub outer: Vec<Vec<Point3>>,
    pub inner: Vec<Vec<Point3>>,
}

/// Which loops of a face are outer boundaries: those the file marks outer,
/// or, when it marks none (all `FACE_BOUND`s), the loop spanning the
/// largest extent.
pub fn outer_loops(part: &Part, face: FaceId) -> Vec<bool> {
    let f = part.face(face);
    let marked: Vec<bool> = f.loops.iter().map(|&l| part.loop_(l).is_outer).collect();
    if marked.iter().any(|&m| m) {
        return marked;
    }
    let extent = |l: thinwall_brep::LoopId| {
        let mut b = thinwall_geom::BoundingBox::empty();
        for ce in &part.loop_(l).coedges {
            let e = part.edge(ce.edge);
            b.add_point(&part.vertex(e.start).point);
            b.add_point(&part.vertex(e.end).point);
            if let Some(c) = &e.nurbs {
                if c.degree > 1 || !c.is_polynomial() {
                    let (t0, t1) = c.domain();
                    for k in 1..4 {
                        b.add_point(&c.point(t0 + (t1 - t0) * k as f64 / 4.0));
                    }
                }
            }
        }
        b.diagonal()
    };
    let largest =
        (0..f.loops.len()).max_by(|&a, &b| extent(f.loops[a]).total_cmp(&extent(f.loops[b])));
    (0..f.loops.len()).map(|i| Some(i) == largest).collect()
}

/// Parameters along an edge curve in the coedge's direction, both ends
/// included: the ends of a straight edge, `per_span` steps per knot span of
/// a curved one; and whether the edge is straight.
pub fn coedge_params(
    c: &thinwall_geom::NurbsCurve,
    forward: bool,
    per_span: usize,
) -> (Vec<f64>, bool) {
    let straight = c.degree == 1 && c.is_polynomial();
    let mut ts = Vec::new();
    for (a, b) in c.spans() {
        let n = if straight { 1 } else { per_span };
        for k in 0..n {
            ts.push(a + (b - a) * k as f64 / n as f64);
        }
    }
    ts.push(c.domain().1);
    if !forward {
        ts.reverse();
    }
    (ts, straight)
}

/// Sample the loops of a face.
pub fn face_loops(part: &Part, face: FaceId) -> FaceLoops {
    let f = part.face(face);
    let mut out = FaceLoops {
        outer: Vec::new(),
        inner: Vec::new(),
    };
    let outer = outer_loops(part, face);
    for (i, &l) in f.loops.iter().enumerate() {
        let lp = part.loop_(l);
        let mut pts = Vec::new();
        for ce in &lp.coedges {
            let e = part.edge(ce.edge);
            let Some(c) = &e.nurbs else {
                pts.push(part.vertex(if ce.forward { e.start } else { e.end }).point);
                continue;
            };
            let (mut ts, _) = coedge_params(c, ce.forward, SAMPLES_PER_SPAN);
            ts.pop();
            pts.extend(ts.into_iter().map(|t| c.point(t)));
        }
        if pts.len() < 3 {
            continue;
        }
        if outer[i] {
            out.outer.push(pts);
        } else {
            out.inner.push(pts);
        }
    }
    out
}

/// A planar face: its plane (z = outward normal) and loops.
#[derive(Clone, Debug)]
pub struct PlanarFace {
    pub face: FaceId,
    pub frame: Frame,
    pub loops: FaceLoops,
}

impl PlanarFace {
    pub fn new(part: &Part, face: FaceId) -> Option<Self> {
        let f = part.face(face);
        let Surface::Plane { frame } = &f.surface else {
            return None;
        };
        let mut frame = *frame;
        if !f.same_sense {
            frame = Frame {
                origin: frame.origin,
                x: frame.x,
                y: -frame.y,
                z: -frame.z,
            };
        }
        Some(Self {
            face,
            frame,
            loops: face_loops(part, face),
        })
    }

    pub fn normal(&self) -> Vector3 {
        self.frame.z
    }

    /// Signed offset of the plane along its normal.
    pub fn offset(&self) -> f64 {
        self.frame.origin.coords.dot(&self.frame.z)
    }

    /// This face as a polygon in `frame`'s xy coordinates.
    pub fn polygon_in(&self, frame: &Frame) -> MultiPolygon<f64> {
        project_loops(&self.loops, frame)
    }
}

/// Loops projected into a frame's xy plane as a (valid, oriented) polygon.
pub fn project_loops(loops: &FaceLoops, frame: &Frame) -> MultiPolygon<f64> {
    map_loops(loops, |p| {
        let l = frame.to_local(p);
        Coord { x: l.x, y: l.y }
    })
}

/// A face's loops mapped into a plane (a projection, a surface's parameter
/// plane, a development) as one region: the one home of loops → region.
/// One outer loop is the region with its inner loops as holes; several are
/// joined and the inner loops cut out. Points are mapped in loop order,
/// outer loops first (`map` may carry a hint from point to point).
pub fn map_loops(
    loops: &FaceLoops,
    mut map: impl FnMut(&Point3) -> Coord<f64>,
) -> MultiPolygon<f64> {
    let mut ring = |pts: &Vec<Point3>| {
        let mut cs: Vec<Coord<f64>> = pts.iter().map(&mut map).collect();
        if let Some(&first) = cs.first() {
            cs.push(first);
        }
        LineString::new(cs)
    };
    if loops.outer.len() == 1 {
        // The common case: one boundary with holes, built directly.
        let outer = ring(&loops.outer[0]);
        let interiors: Vec<LineString<f64>> = loops.inner.iter().map(&mut ring).collect();
        let poly = Polygon::new(outer, interiors).orient(geo::orient::Direction::Default);
        return MultiPolygon::new(vec![poly]);
    }
    let mut result = MultiPolygon::new(vec![]);
    for o in &loops.outer {
        let poly = Polygon::new(ring(o), vec![]).orient(geo::orient::Direction::Default);
        result = if result.0.is_empty() {
            MultiPolygon::new(vec![poly])
        } else {
            result.union(&poly)
        };
    }
    if !loops.inner.is_empty() && !result.0.is_empty() {
        let holes = MultiPolygon::new(
            loops
                .inner
                .iter()
                .map(|r| Polygon::new(ring(r), vec![]))
                .collect(),
        );
        result = result.difference(&holes);
    }
    result
}

/// Narrowest width of a region: the smaller of its minimum-area rectangle's
/// short side and `4·area/perimeter` (which is small for thin strips and
/// crosses whose rectangle is wide).
pub fn narrow_width(region: &MultiPolygon<f64>) -> f64 {
    use geo::{Euclidean, Length};
    let area = region.unsigned_area();
    if area <= 0.0 {
        return 0.0;
    }
    let perimeter: f64 = region
        .0
        .iter()
        .map(|p| {
            Euclidean.length(p.exterior())
                + p.interiors()
                    .iter()
                    .map(|r| Euclidean.length(r))
                    .sum::<f64>()
        })
        .sum();
    let strip = if perimeter > 0.0 {
        4.0 * area / perimeter
    } else {
        0.0
    };
    let rect = min_rect_sides(region).map_or(0.0, |(_, short)| short);
    strip.min(rect)
}

/// Long and short side of the minimum-area rectangle around `shape`, mm
/// ([`crate::min_rect`]: ties broken by the shape, not its pose).
pub fn min_rect_sides<G: geo::CoordsIter<Scalar = f64>>(shape: &G) -> Option<(f64, f64)> {
    crate::min_rect::min_rect(shape).map(|r| (r.long, r.short))
}

/// Longest side of the region's minimum rotated rectangle (of its bounding
/// rectangle when it has none), mm.
pub fn long_side(region: &MultiPolygon<f64>) -> f64 {
    use geo::BoundingRect;
    min_rect_sides(region)
        .map(|(long, _)| long)
        .or_else(|| region.bounding_rect().map(|r| r.width().max(r.height())))
        .unwrap_or(0.0)
}

/// `region`'s pieces of more than `min_area`, [`without_spikes`]: a
/// boolean's result as it is reported (slivers of no area along an edge
/// two operands share are no piece).
pub fn without_slivers(region: &MultiPolygon<f64>, min_area: f64) -> MultiPolygon<f64> {
    let pieces = region
        .iter()
        .filter(|p| p.unsigned_area() > min_area)
        .cloned()
        .collect();
    without_spikes(&MultiPolygon::new(pieces))
}

/// `region` without zero-width spikes: a corner where its ring turns
/// straight back (a boolean's antenna along an edge it touched) is
/// dropped, with the repeat it leaves, until none is left. The area is
/// unchanged; a spike would cut a circle inscribed in the region short.
fn without_spikes(region: &MultiPolygon<f64>) -> MultiPolygon<f64> {
    let clean = |ring: &LineString<f64>| -> LineString<f64> {
        let mut pts: Vec<Coord<f64>> = ring.coords().copied().collect();
        if pts.len() > 1 && pts.first() == pts.last() {
            pts.pop();
        }
        let mut k = 0;
        while pts.len() >= 3 && k < pts.len() {
            let n = pts.len();
            let (a, b, c) = (pts[(k + n - 1) % n], pts[k], pts[(k + 1) % n]);
            let (u, v) = (b - a, c - b);
            let cross = u.x * v.y - u.y * v.x;
            let dot = u.x * v.x + u.y * v.y;
            let scale = u.x.hypot(u.y) * v.x.hypot(v.y);
            if b == a || (dot < 0.0 && cross.abs() <= 1e-9 * scale) {
                pts.remove(k);
                k = k.saturating_sub(1);
            } else {
                k += 1;
            }
        }
        LineString::new(pts)
    };
    MultiPolygon::new(
        region
            .iter()
            .map(|p| {
                Polygon::new(
                    clean(p.exterior()),
                    p.interiors().iter().map(clean).collect(),
                )
            })
            .filter(|p| p.exterior().0.len() >= 3)
            .collect(),
    )
}

/// Radius of the largest circle inside `region` (approximate: a grid
/// search refined around the best point of each of its pieces), mm. Piece
/// by piece: one grid over pieces spread far apart (a rest of slivers
/// along a 140 mm wall) fell between them all and read 0.
pub fn inscribed_radius(region: &MultiPolygon<f64>) -> f64 {
    use geo::{BoundingRect, Distance, Euclidean};
    let mut pieces: Vec<(f64, &geo::Polygon<f64>)> = region
        .0
        .iter()
        .filter_map(|p| {
            p.bounding_rect()
                .map(|b| (0.5 * b.width().min(b.height()), p))
        })
        .collect();
    pieces.sort_by(|a, b| b.0.total_cmp(&a.0));
    let mut best: f64 = 0.0;
    for (bound, poly) in pieces {
        if bound <= best {
            break; // no circle wider than its box's half width
        }
        let one = MultiPolygon::new(vec![poly.clone()]);
        best = best.max(farthest(&one, |p, floor| {
            let mut d = f64::INFINITY;
            for ring in std::iter::once(poly.exterior()).chain(poly.interiors()) {
                d = d.min(Euclidean.distance(p, ring));
                if d <= floor {
                    return 0.0;
                }
            }
            d
        }));
    }
    best
}

/// Radius of the largest circle centred in `region` that crosses none of
/// `walls` (polylines in the region's plane), mm: where only some of a
/// floor's edges are walls (a face rises there) and the others open (the
/// floor drops away), the tool may overhang the open ones. Unbounded
/// (infinite) without walls. Approximate as [`inscribed_radius`].
pub fn clearance_radius(region: &MultiPolygon<f64>, walls: &[geo::LineString<f64>]) -> f64 {
    use geo::{Distance, Euclidean};
    if walls.is_empty() {
        return f64::INFINITY;
    }
    farthest(&over_openings(region, walls), |p, floor| {
        let mut d = f64::INFINITY;
        for w in walls {
            d = d.min(Euclidean.distance(p, w));
            if d <= floor {
                return 0.0;
            }
        }
        d
    })
}

/// `region` with its openings filled: a hole in a floor that no wall runs
/// along (a through hole in a pocket's floor drops away on every side) is
/// where a tool's centre may stand too. Without it the centre had to skirt
/// the opening, and where it came to rest on the opening's rim depended on
/// the search's start: a turned copy read a pocket's largest tool 10 %
/// apart.
fn over_openings(region: &MultiPolygon<f64>, walls: &[geo::LineString<f64>]) -> MultiPolygon<f64> {
    use geo::{Distance, Euclidean};
    let touches = |ring: &geo::LineString<f64>| {
        walls.iter().any(|w| {
            w.0.iter()
                .any(|c| Euclidean.distance(&geo::Point::from(*c), ring) <= OPENING_TOL)
        })
    };
    MultiPolygon::new(
        region
            .0
            .iter()
            .map(|p| {
                let kept = p
                    .interiors()
                    .iter()
                    .filter(|r| touches(r))
                    .cloned()
                    .collect();
                geo::Polygon::new(p.exterior().clone(), kept)
            })
            .collect(),
    )
}

/// How near a wall's point must be to a floor's inner ring for the wall to
/// run along it, mm (both come from the same edges' samples).
const OPENING_TOL: f64 = 1e-6;

/// The largest `dist` over points of `region` (a grid search refined
/// around the best points); `dist(p, floor)` may answer 0 as soon as it
/// knows it is at most `floor` (such a point cannot be the best).
///
/// The answer does not change with the pose of the region: the grid is laid
/// along the region's minimum rectangle, not the axes it is drawn in (a
/// grid along the drawing's axes read a web's widest cell 5 % apart on two
/// poses of one skin); every coarse point as good as the best (a ridge, a
/// symmetric region: which one a grid meets first is a matter of pose) is
/// refined, nearest the region's centroid first, up to [`STARTS`]; and the
/// refinement goes down to [`REFINED`] of the region's size.
fn farthest(region: &MultiPolygon<f64>, dist: impl Fn(&geo::Point<f64>, f64) -> f64) -> f64 {
    use geo::{Contains, Point};
    let Some(grid) = SearchBox::around(region) else {
        return 0.0;
    };
    let at = |s: f64, t: f64, floor: f64| -> f64 {
        let p = Point::from(grid.point(s, t));
        if !region.contains(&p) {
            return 0.0;
        }
        dist(&p, floor)
    };
    let n = 12;
    let (w, h) = (grid.size[0], grid.size[1]);
    let mut coarse: Vec<(f64, f64, f64)> = Vec::with_capacity((n + 1) * (n + 1));
    for i in 0..=n {
        for j in 0..=n {
            let (s, t) = (w * i as f64 / n as f64, h * j as f64 / n as f64);
            coarse.push((s, t, at(s, t, 0.0)));
        }
    }
    let top = coarse.iter().map(|c| c.2).fold(0.0, f64::max);
    let tie = REFINED * w.max(h);
    let centre = grid.local(region);
    let mut starts: Vec<(f64, f64, f64)> =
        coarse.into_iter().filter(|c| c.2 >= top - tie).collect();
    let from_centre = |c: &(f64, f64, f64)| (c.0 - centre.0).hypot(c.1 - centre.1);
    starts.sort_by(|a, b| from_centre(a).total_cmp(&from_centre(b)));
    starts.truncate(STARTS);
    let window = (w / (n as f64 / 2.0), h / (n as f64 / 2.0));
    let stop = REFINED * w.max(h);
    starts
        .into_iter()
        .map(|start| refine(&at, start, window, stop))
        .fold(0.0, f64::max)
}

/// A pattern search from `start` (s, t, its value): a 5 x 5 grid over a
/// window around the best point so far, the window halved each round
/// until it is under `stop`; the best value found.
fn refine(
    at: &impl Fn(f64, f64, f64) -> f64,
    start: (f64, f64, f64),
    (mut w, mut h): (f64, f64),
    stop: f64,
) -> f64 {
    let mut best = start;
    let m = 4;
    while w.max(h) > stop {
        let (cs, ct) = (best.0, best.1);
        for i in 0..=m {
            for j in 0..=m {
                let s = cs - w / 2.0 + w * i as f64 / m as f64;
                let t = ct - h / 2.0 + h * j as f64 / m as f64;
                let d = at(s, t, best.2);
                if d > best.2 {
                    best = (s, t, d);
                }
            }
        }
        w /= 2.0;
        h /= 2.0;
    }
    best.2
}

/// How many equally good coarse points [`farthest`] refines at most.
const STARTS: usize = 4;

/// How finely [`farthest`] pins its point, relative to the region's size.
const REFINED: f64 = 1e-9;

/// A region's minimum rectangle as a search grid's frame: a corner, its
/// long and short directions, and its sides.
struct SearchBox {
    corner: [f64; 2],
    axes: [[f64; 2]; 2],
    size: [f64; 2],
}

impl SearchBox {
    fn around(region: &MultiPolygon<f64>) -> Option<Self> {
        use geo::CoordsIter;
        let u = crate::min_rect::min_rect(region)?.long_dir;
        let axes = [u, [-u[1], u[0]]];
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        for c in region.coords_iter() {
            for k in 0..2 {
                let t = c.x * axes[k][0] + c.y * axes[k][1];
                lo[k] = lo[k].min(t);
                hi[k] = hi[k].max(t);
            }
        }
        if !(lo[0].is_finite() && lo[1].is_finite()) {
            return None;
        }
        let corner = [
            lo[0] * axes[0][0] + lo[1] * axes[1][0],
            lo[0] * axes[0][1] + lo[1] * axes[1][1],
        ];
        Some(Self {
            corner,
            axes,
            size: [hi[0] - lo[0], hi[1] - lo[1]],
        })
    }

    /// The region's centroid as (s, t) from the corner (the corner itself
    /// for a region without area).
    fn local(&self, region: &MultiPolygon<f64>) -> (f64, f64) {
        let Some(c) = geo::Centroid::centroid(region) else {
            return (0.0, 0.0);
        };
        let d = [c.x() - self.corner[0], c.y() - self.corner[1]];
        (
            d[0] * self.axes[0][0] + d[1] * self.axes[0][1],
            d[0] * self.axes[1][0] + d[1] * self.axes[1][1],
        )
    }

    /// The point `s` along the long side and `t` along the short one from
    /// the corner.
    fn point(&self, s: f64, t: f64) -> geo::Coord<f64> {
        geo::Coord {
            x: self.corner[0] + s * self.axes[0][0] + t * self.axes[1][0],
            y: self.corner[1] + s * self.axes[0][1] + t * self.axes[1][1],
        }
    }
}

/// The points of edge `e` from its start to its end: its ends when
/// straight, a few per knot span when curved (as a face's loops).
pub fn edge_points(part: &Part, e: thinwall_brep::EdgeId) -> Vec<Point3> {
    let edge = part.edge(e);
    match &edge.nurbs {
        Some(c) => coedge_params(c, true, SAMPLES_PER_SPAN)
            .0
            .into_iter()
            .map(|t| c.point(t))
            .collect(),
        None => vec![part.vertex(edge.start).point, part.vertex(edge.end).point],
    }
}

/// `a ∩ b`, empty when either is empty.
pub fn intersect(a: &MultiPolygon<f64>, b: &MultiPolygon<f64>) -> MultiPolygon<f64> {
    if a.0.is_empty() || b.0.is_empty() {
        return MultiPolygon::new(vec![]);
    }
    a.intersection(b)
}

/// Whether `a` and `b` share more than rounding: an overlap of area over
/// `min_area` whose mean width (area over its box's diagonal) exceeds
/// `lin`. Regions meeting along an edge overlap by a hairline that depends
/// on how the part sits in the world; this says no to it in every pose.
pub fn overlap_beyond(
    a: &MultiPolygon<f64>,
    b: &MultiPolygon<f64>,
    lin: f64,
    min_area: f64,
) -> bool {
    beyond_rounding(&intersect(a, b), lin, min_area)
}

/// Whether a region (an overlap) is more than rounding: area over
/// `min_area` and mean width (area over its box's diagonal) over `lin`.
pub fn beyond_rounding(common: &MultiPolygon<f64>, lin: f64, min_area: f64) -> bool {
    let diagonal =
        geo::BoundingRect::bounding_rect(common).map_or(0.0, |r| r.width().hypot(r.height()));
    let area = common.unsigned_area();
    area > min_area && area > lin * diagonal
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 10 × 4 rectangle with an antenna (through a middle corner) from
    /// its left side to near its right: the same area, the antenna gone
    /// (a straight corner kept),
    /// and the inscribed circle the rectangle's again.
    #[test]
    fn a_spike_is_dropped() {
        let ring = vec![
            (0.0, 0.0),
            (10.0, 0.0),
            (10.0, 4.0),
            (0.0, 4.0),
            (0.0, 2.0),
            (5.0, 2.0),
            (9.0, 2.0),
            (5.0, 2.0),
            (0.0, 2.0),
            (0.0, 0.0),
        ];
        let spiky = MultiPolygon::new(vec![Polygon::new(LineString::from(ring), vec![])]);
        let clean = without_spikes(&spiky);
        assert!((clean.unsigned_area() - 40.0).abs() < 1e-12);
        // Four corners, the straight one at (0, 2) and the closing repeat.
        assert_eq!(
            clean.0[0].exterior().0.len(),
            6,
            "{:?}",
            clean.0[0].exterior()
        );
        assert!(inscribed_radius(&spiky) < 1.5);
        assert!((inscribed_radius(&clean) - 2.0).abs() < 1e-3);
    }

    fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> MultiPolygon<f64> {
        MultiPolygon::new(vec![Polygon::new(
            LineString::from(vec![(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)]),
            vec![],
        )])
    }

    #[test]
    fn regions_meeting_along_an_edge_do_not_overlap() {
        let a = rect(0.0, 0.0, 100.0, 10.0);
        // Rounding leaves a hairline of 1e-7 across a 100 long edge.
        let b = rect(0.0, 10.0 - 1e-7, 100.0, 20.0);
        assert!(!overlap_beyond(&a, &b, 1e-6, 1e-8));
        let c = rect(50.0, 5.0, 150.0, 20.0);
        assert!(overlap_beyond(&a, &c, 1e-6, 1e-8));
    }

    #[test]
    fn widths_and_inscribed_circles() {
        assert!((narrow_width(&rect(0.0, 0.0, 100.0, 2.0)) - 2.0).abs() < 1e-9);
        assert!((narrow_width(&rect(0.0, 0.0, 40.0, 40.0)) - 40.0).abs() < 1e-9);
        // A cross of two 2-wide strips is narrow although its box is wide.
        let cross = rect(0.0, 49.0, 100.0, 51.0).union(&rect(49.0, 0.0, 51.0, 100.0));
        assert!(narrow_width(&cross) < 4.1);
        let r = inscribed_radius(&rect(0.0, 0.0, 80.0, 40.0));
        assert!((r - 20.0).abs() < 0.05, "{r}");
    }

    #[test]
    fn the_widest_of_pieces_spread_far_apart() {
        // Slivers 0.4 wide every 11.3 mm along 140 mm, and one 1.2 wide:
        // a grid over their common box falls between them.
        let mut pieces: Vec<Polygon<f64>> = (0..12)
            .map(|k| {
                rect(11.3 * k as f64, 0.0, 11.3 * k as f64 + 3.0, 0.4)
                    .0
                    .remove(0)
            })
            .collect();
        pieces.push(rect(140.0, 0.0, 143.0, 1.2).0.remove(0));
        let r = inscribed_radius(&MultiPolygon::new(pieces));
        assert!((r - 0.6).abs() < 0.01, "{r}");
    }
}
