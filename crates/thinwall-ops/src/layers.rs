//! Roughing layers and cutter fields (Schuster ch. 4–5): z-levels from
//! the stock's top down at the axial depth of cut, plus a level exactly at
//! the height of every flat face of the part facing up (so floors are not
//! left with steps) or down (an undercut's ceiling); per layer the cross-section of the removal region
//! (stock − part, [`thinwall_removal`]) at the layer's bottom, as
//! closed contours split into cutter fields: one outer contour each, its
//! inner contours islands, every contour edge marked as blank (the stock's
//! boundary) or part contour.

use geo::{Area, BoundingRect, Contains, Coord, LineString, MultiPolygon, Point, Polygon, Rect};
use serde::Serialize;
use thinwall_analysis::boolean;
use thinwall_plan::StepLimit;
use thinwall_removal::pieces::{Facing, Height};
use thinwall_removal::{outline, slab, Removal};

/// A plane whose height changes less than this per mm across is flat.
pub const FLAT_SLOPE: f64 = 1e-9;

/// What the layers are cut with.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct LayerOptions {
    /// Depth of cut between levels, mm (the roughing tool's a_p).
    pub axial_depth_mm: f64,
    /// The smallest tool's diameter, mm: a field it cannot enter is too
    /// small.
    pub smallest_tool_mm: f64,
    /// The thin walls standing along up and the deepest layer allowed
    /// over their heights (the step approach: no layer beside a thin wall
    /// deeper than its `h_RF`).
    pub step_limits: Vec<StepLimit>,
}

/// What a contour edge runs along.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum EdgeKind {
    /// The stock's boundary: the tool may come in over it.
    Blank,
    /// The part: the tool must not cut past it.
    Part,
}

/// A closed contour in the removal frame's (x, y), mm, and what each edge
/// (from point i to point i + 1, the last back to the first) runs along.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Contour {
    pub points: Vec<[f64; 2]>,
    pub edges: Vec<EdgeKind>,
}

/// One cutter field: an outer contour and its islands.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CutterField {
    pub outer: Contour,
    pub islands: Vec<Contour>,
    pub area_mm2: f64,
    /// The widest circle inside it, mm.
    pub inscribed_diameter_mm: f64,
    /// Narrower than the smallest tool: no tool enters it.
    pub too_small: bool,
}

impl Contour {
    /// The closed ring of its points.
    pub fn ring(&self) -> LineString<f64> {
        let mut pts: Vec<Coord<f64>> = self
            .points
            .iter()
            .map(|p| Coord { x: p[0], y: p[1] })
            .collect();
        if let Some(&first) = pts.first() {
            pts.push(first);
        }
        LineString::new(pts)
    }
}

impl CutterField {
    /// The field as a polygon, its islands as holes.
    pub fn polygon(&self) -> Polygon<f64> {
        Polygon::new(
            self.outer.ring(),
            self.islands.iter().map(Contour::ring).collect(),
        )
    }
}

/// One roughing layer.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RoughingLayer {
    pub index: usize,
    /// The plan's machining feature it belongs to, when the operations
    /// follow the plan.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub feature: Option<thinwall_plan::VolumeId>,
    pub z_top_mm: f64,
    pub z_bottom_mm: f64,
    /// STEP ids of the part's flat faces facing up at the layer's bottom.
    pub floors: Vec<u64>,
    /// Those faces seen from up (x, y).
    #[serde(skip)]
    pub floor_region: MultiPolygon<f64>,
    /// The removal region's cross-section at the bottom, mm².
    pub area_mm2: f64,
    /// The deepest this layer may be, beside the thin walls whose heights
    /// it crosses (their `h_RF`), mm; none beside no thin wall.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub step_limit_mm: Option<f64>,
    pub fields: Vec<CutterField>,
}

/// The levels, top down: every `axial_depth_mm` below the stock's top and
/// every upward flat face's height within the removal, down to its lowest
/// point. Levels closer than `tol` are one (the flat face's wins).
pub fn levels(r: &Removal, axial_depth_mm: f64, tol: f64) -> Vec<(f64, Vec<u64>)> {
    let (mut top, mut bottom) = (f64::NEG_INFINITY, f64::INFINITY);
    for b in reachable(r) {
        top = top.max(r.bound_range(&b.upper)[1]);
        bottom = bottom.min(r.bound_range(&b.lower)[0]);
    }
    if top.is_nan() || bottom.is_nan() || top <= bottom {
        return Vec::new();
    }
    let mut flats: Vec<(f64, Vec<u64>)> = Vec::new();
    for p in &r.part_pieces {
        let Height::Plane { z0, gx, gy, .. } = p.height else {
            continue;
        };
        // Flat within rounding: a turned part's floor has a gradient of
        // 1e-16, not 0.
        if gx.hypot(gy) > FLAT_SLOPE || z0 <= bottom - tol || z0 >= top - tol {
            continue;
        }
        // A flat face facing down (an undercut's ceiling) bounds a layer
        // too, so no layer mixes material above and below it.
        let floor = (p.facing == Facing::Up).then_some(p.step_id);
        match flats.iter_mut().find(|f| (f.0 - z0).abs() <= tol) {
            Some(f) => f.1.extend(floor),
            None => flats.push((z0, floor.into_iter().collect())),
        }
    }
    let mut out = flats;
    let steps = ((top - bottom) / axial_depth_mm).ceil() as usize;
    for k in 1..=steps {
        let z = (top - k as f64 * axial_depth_mm).max(bottom);
        if !out.iter().any(|f| (f.0 - z).abs() <= tol) {
            out.push((z, Vec::new()));
        }
    }
    out.retain(|f| f.0 >= bottom - tol);
    out.sort_by(|a, b| b.0.total_cmp(&a.0));
    for f in &mut out {
        f.1.sort_unstable();
        f.1.dedup();
    }
    out
}

/// The deepest a layer from `top` down to `bottom` may be: the least
/// `h_RF` of the thin walls whose heights it crosses.
pub fn step_limit(limits: &[StepLimit], top: f64, bottom: f64, tol: f64) -> Option<f64> {
    limits
        .iter()
        .filter(|l| l.z_mm[0] < top - tol && l.z_mm[1] > bottom + tol)
        .map(|l| l.depth_mm)
        .min_by(f64::total_cmp)
}

/// `levels` (top down, from `top`) with levels put in so that no layer
/// is deeper than its [`step_limit`]: a layer too deep is cut into equal
/// ones.
pub fn stepped(
    levels: Vec<(f64, Vec<u64>)>,
    top: f64,
    limits: &[StepLimit],
    tol: f64,
) -> Vec<(f64, Vec<u64>)> {
    let mut out = Vec::with_capacity(levels.len());
    let mut above = top;
    for (z, floors) in levels {
        if let Some(depth) = step_limit(limits, above, z, tol) {
            let n = ((above - z - tol) / depth).ceil().max(1.0) as usize;
            for k in 1..n {
                out.push((above - k as f64 * (above - z) / n as f64, Vec::new()));
            }
        }
        out.push((z, floors));
        above = z;
    }
    out
}

/// The roughing layers of the removal `r`.
pub fn roughing_layers(r: &Removal, opts: &LayerOptions) -> Vec<RoughingLayer> {
    let tol = 1e-6 * r.size.max(1.0);
    let Some(top) = reachable(r)
        .map(|b| r.bound_range(&b.upper)[1])
        .max_by(f64::total_cmp)
    else {
        return Vec::new();
    };
    let levels = stepped(
        levels(r, opts.axial_depth_mm, tol),
        top,
        &opts.step_limits,
        tol,
    );
    let footprint = footprint(r);
    let mut out = Vec::with_capacity(levels.len());
    let mut above = top;
    for (index, (z, floors)) in levels.into_iter().enumerate() {
        let polygons = section(r, z + tol);
        let fields: Vec<CutterField> = polygons
            .iter()
            .filter_map(|p| without_slivers(p, tol))
            .map(|p| {
                field(&p, 1e-4 * r.size.max(1.0), opts.smallest_tool_mm, &|q| {
                    !footprint.holds(q)
                })
            })
            .collect();
        let floor_region = MultiPolygon::new(
            r.part_pieces
                .iter()
                .filter(|p| floors.contains(&p.step_id))
                .filter(|p| matches!(p.height, Height::Plane { z0, .. } if (z0 - z).abs() <= tol))
                .flat_map(|p| p.region.0.iter().cloned())
                .collect(),
        );
        out.push(RoughingLayer {
            index,
            feature: None,
            z_top_mm: above,
            z_bottom_mm: z,
            floor_region: thinwall_analysis::boolean::union_all(
                floor_region
                    .into_iter()
                    .map(|p| MultiPolygon::new(vec![p]))
                    .collect(),
            ),
            floors,
            area_mm2: fields.iter().map(|f| f.area_mm2).sum(),
            step_limit_mm: step_limit(&opts.step_limits, above, z, tol),
            fields,
        });
        above = z;
    }
    out
}

/// `p` without the slivers the joining of blocks leaves where their
/// sections meet at a slant (a turned part): rings narrower on average
/// than twice `tol` (area below `tol` times the perimeter); none if the
/// outer ring is one.
pub(crate) fn without_slivers(p: &Polygon<f64>, tol: f64) -> Option<Polygon<f64>> {
    use geo::{Euclidean, Length};
    let sliver = |ring: &LineString<f64>| {
        let area = Polygon::new(ring.clone(), vec![]).unsigned_area();
        area < tol * Euclidean.length(ring)
    };
    if sliver(p.exterior()) {
        return None;
    }
    Some(Polygon::new(
        p.exterior().clone(),
        p.interiors()
            .iter()
            .filter(|r| !sliver(r))
            .cloned()
            .collect(),
    ))
}

/// The removal region's cross-section at `z` that a tool along up reaches:
/// every reachable block's, joined where they meet.
pub fn section(r: &Removal, z: f64) -> Vec<Polygon<f64>> {
    let pieces: Vec<Polygon<f64>> = reachable(r)
        .flat_map(|b| slab::section(r, b, z).0)
        .collect();
    join(&pieces, r.size)
}

/// The blocks this set-up cuts: those a tool along up reaches (nothing of
/// the part above them) that no earlier set-up took. What lies under the
/// part (the far side of a double-sided web) is another set-up's, never
/// this one's layers.
pub fn reachable(r: &Removal) -> impl Iterator<Item = &thinwall_removal::Block> {
    r.blocks.iter().filter(|b| b.reachable && !b.cleared)
}

/// The volume of the blocks a tool along up does not reach and no earlier
/// set-up took, mm³: none
/// under [`MERGE`](thinwall_geom::tolerance::MERGE) of the stock's volume
/// (rounding of a turned part's faces, not material).
pub fn out_of_reach_mm3(r: &Removal) -> f64 {
    let v: f64 = r
        .blocks
        .iter()
        .filter(|b| !b.reachable && !b.cleared)
        .map(|b| b.volume)
        .sum();
    if v > thinwall_geom::tolerance::MERGE * r.stock_volume {
        v
    } else {
        0.0
    }
}

/// Sections of blocks joined into one region. Blocks that tile the
/// section share their edges, which cancel ([`outline::union`], exact to
/// the snap). Blocks that overlap (a meshed face's triangles crossing an
/// exact neighbour's height within the deviation; a machining feature's
/// solids meeting a slanted cut) fold that outline over itself, a field no
/// boolean reads as its area: those sections are joined by a boolean
/// union instead.
pub(crate) fn join(pieces: &[Polygon<f64>], size: f64) -> Vec<Polygon<f64>> {
    let joined = outline::union(pieces, JOIN_SNAP * size.max(1.0));
    let region = MultiPolygon::new(joined);
    let shoelace = region.unsigned_area();
    let read = boolean::union(&region, &MultiPolygon::new(vec![])).unsigned_area();
    if (shoelace - read).abs() <= FOLD_SHARE * shoelace.max(1.0) {
        return region.0;
    }
    boolean::union_all(
        pieces
            .iter()
            .map(|p| MultiPolygon::new(vec![p.clone()]))
            .collect(),
    )
    .0
}

/// A joined outline whose area as a boolean reads it differs from its
/// shoelace area by more than this share folds over itself.
const FOLD_SHARE: f64 = 1e-6;

/// The sum of every reachable block's cross-section at `z`, mm² (the
/// joined section must keep it).
pub fn section_area_by_blocks(r: &Removal, z: f64) -> f64 {
    reachable(r)
        .map(|b| slab::section(r, b, z).unsigned_area())
        .sum()
}

/// Where the stock is, seen from up: the block's rectangle, or a given
/// solid's pieces.
enum Footprint {
    Rect(Rect<f64>),
    Pieces(Vec<MultiPolygon<f64>>),
}

fn footprint(r: &Removal) -> Footprint {
    if r.stock_pieces.is_empty() {
        let cells = MultiPolygon::new(r.cells.iter().map(|c| c.poly.clone()).collect());
        Footprint::Rect(cells.bounding_rect().unwrap_or(Rect::new(
            Coord { x: 0.0, y: 0.0 },
            Coord { x: 0.0, y: 0.0 },
        )))
    } else {
        Footprint::Pieces(r.stock_pieces.iter().map(|p| p.region.clone()).collect())
    }
}

impl Footprint {
    fn holds(&self, q: Coord<f64>) -> bool {
        match self {
            Footprint::Rect(rect) => {
                q.x > rect.min().x && q.x < rect.max().x && q.y > rect.min().y && q.y < rect.max().y
            }
            Footprint::Pieces(ps) => ps.iter().any(|p| p.contains(&Point::from(q))),
        }
    }
}

/// The cutter field of polygon `p`: a contour is blank where the point
/// just across it (`step` away) is `blank`, else part. An edge may be
/// both (a flange's side with a cut-out of an earlier feature in it): it
/// is split where its kind changes (sampled every half of the smallest
/// tool, the change found by bisection), after collinear vertices are
/// dropped, so the split lies where the geometry says, wherever the
/// polygon's vertices happen to be.
pub(crate) fn field(
    p: &Polygon<f64>,
    step: f64,
    smallest: f64,
    blank: &dyn Fn(Coord<f64>) -> bool,
) -> CutterField {
    let contour = |ring: &LineString<f64>| {
        let pts = without_collinear(ring);
        let n = pts.len();
        let mut points = Vec::new();
        let mut edges = Vec::new();
        for k in 0..n {
            let (a, b) = (pts[k], pts[(k + 1) % n]);
            for (start, kind) in edge_kinds(p, a, b, step, 0.5 * smallest, blank) {
                points.push([start.x, start.y]);
                edges.push(kind);
            }
        }
        Contour { points, edges }
    };
    let region = MultiPolygon::new(vec![p.clone()]);
    let inscribed = 2.0 * thinwall_analysis::polygon::inscribed_radius(&region);
    CutterField {
        outer: contour(p.exterior()),
        islands: p.interiors().iter().map(contour).collect(),
        area_mm2: p.unsigned_area(),
        inscribed_diameter_mm: inscribed,
        too_small: inscribed < smallest,
    }
}

/// A ring's vertices (not closed) without those where it runs straight on.
fn without_collinear(ring: &LineString<f64>) -> Vec<Coord<f64>> {
    let mut pts: Vec<Coord<f64>> = ring.0.clone();
    if pts.len() > 1 && pts.first() == pts.last() {
        pts.pop();
    }
    let n = pts.len();
    if n < 4 {
        return pts;
    }
    let straight = |k: usize| {
        let (a, b, c) = (pts[(k + n - 1) % n], pts[k], pts[(k + 1) % n]);
        let (u, v) = (b - a, c - b);
        let cross = u.x * v.y - u.y * v.x;
        let dot = u.x * v.x + u.y * v.y;
        let scale = u.x.hypot(u.y) * v.x.hypot(v.y);
        cross.abs() <= COLLINEAR * scale && dot > 0.0
    };
    let keep: Vec<Coord<f64>> = (0..n).filter(|&k| !straight(k)).map(|k| pts[k]).collect();
    if keep.len() >= 3 {
        keep
    } else {
        pts
    }
}

/// Pieces of a section are joined where their vertices lie within this
/// share of the part's size: cells cut apart by the removal meet again to
/// its rounding (2.5e-7 mm apart on a 200 mm part turned by a rigid
/// motion; at 1e-9 they stayed two fields with a "part" edge between).
pub(crate) const JOIN_SNAP: f64 = 1e-7;

/// Vertices whose edges turn by less than this (the sine of the angle)
/// run straight on.
const COLLINEAR: f64 = 1e-9;

/// Bisection steps locating where an edge's kind changes (2⁻⁴⁰ of a
/// sample spacing).
const KIND_BISECTIONS: usize = 40;

/// The kinds along edge `a`→`b` of polygon `p`: each sub-edge's start and
/// kind, in order.
fn edge_kinds(
    p: &Polygon<f64>,
    a: Coord<f64>,
    b: Coord<f64>,
    step: f64,
    spacing: f64,
    blank: &dyn Fn(Coord<f64>) -> bool,
) -> Vec<(Coord<f64>, EdgeKind)> {
    let d = b - a;
    let len = d.x.hypot(d.y).max(1e-300);
    let normal = Coord {
        x: d.y / len * step,
        y: -d.x / len * step,
    };
    let mid = a + d * 0.5;
    // Away from the field: the side the middle's neighbour is not in.
    let away = if p.contains(&Point::from(mid + normal)) {
        -1.0
    } else {
        1.0
    };
    let kind_at = |t: f64| {
        if blank(a + d * t + normal * away) {
            EdgeKind::Blank
        } else {
            EdgeKind::Part
        }
    };
    let n = ((len / spacing.max(1e-9)).ceil() as usize).clamp(1, MAX_EDGE_SAMPLES);
    let ts: Vec<f64> = (0..n).map(|k| (k as f64 + 0.5) / n as f64).collect();
    let kinds: Vec<EdgeKind> = ts.iter().map(|&t| kind_at(t)).collect();
    let mut out = vec![(a, kinds[0])];
    for k in 1..n {
        if kinds[k] == kinds[k - 1] {
            continue;
        }
        let (mut lo, mut hi) = (ts[k - 1], ts[k]);
        for _ in 0..KIND_BISECTIONS {
            let m = 0.5 * (lo + hi);
            if kind_at(m) == kinds[k - 1] {
                lo = m;
            } else {
                hi = m;
            }
        }
        out.push((a + d * (0.5 * (lo + hi)), kinds[k]));
    }
    out
}

/// Most samples along one contour edge.
const MAX_EDGE_SAMPLES: usize = 1024;

#[cfg(test)]
mod tests {
    use super::*;

    fn square(extra_vertex: bool) -> Polygon<f64> {
        // 10 x 10; the bottom edge optionally split at x = 3 (collinear).
        let mut ring = vec![(0.0, 0.0)];
        if extra_vertex {
            ring.push((3.0, 0.0));
        }
        ring.extend([(10.0, 0.0), (10.0, 10.0), (0.0, 10.0), (0.0, 0.0)]);
        Polygon::new(LineString::from(ring), vec![])
    }

    /// Below the bottom edge, air only for x < 6.5 (an earlier feature);
    /// everywhere else beyond the square, part.
    fn blank(q: Coord<f64>) -> bool {
        q.y < 0.0 && q.x < 6.5
    }

    #[test]
    fn an_edge_that_is_part_and_blank_is_split_where_the_air_ends() {
        for extra in [false, true] {
            let f = field(&square(extra), 1e-3, 4.0, &blank);
            let c = &f.outer;
            // Collinear vertices dropped: 4 corners plus the split at 6.5.
            assert_eq!(c.points.len(), 5, "{:?}", c.points);
            let split = c
                .points
                .iter()
                .position(|p| p[1] == 0.0 && p[0] > 0.0 && p[0] < 10.0)
                .unwrap();
            assert!((c.points[split][0] - 6.5).abs() < 1e-9, "{:?}", c.points);
            // Blank from the corner to 6.5, part from there on.
            assert_eq!(c.edges[split - 1], EdgeKind::Blank);
            assert_eq!(c.edges[split], EdgeKind::Part);
            assert_eq!(c.edges.iter().filter(|&&k| k == EdgeKind::Blank).count(), 1);
        }
    }
}
