//! Booleans of 2-D regions, and which engine serves which job (the one
//! place that says so; regions are geo `MultiPolygon`s everywhere):
//!
//! | engine | serves |
//! |---|---|
//! | this module: i_overlay 9 directly (`union`, `difference`, `intersection`, `split`, `split_near`, `intersection_near`, `union_all`, `union_tiles`, `wound_region`, `even_odd_region`, `positive_region`) | a meshed face's region and a face's projection whose loops overlap (`thinwall-removal/src/pieces.rs`), reach of floors and their obstacles (`thinwall-access/src/reach/`), rest areas and fields of operations (`thinwall-ops/src/rest.rs`), the removal's cells when a meshed face is among its pieces (`thinwall-removal/src/cells.rs`): unions of many grown triangles and slivers |
//! | geo's `BooleanOps` (i_overlay 4.5 inside geo 0.33) | face regions from loops (`polygon.rs`), wall overlaps of the recognizers (`walls.rs`, `curved.rs`, `offset.rs`), the removal's pieces, cells and cuts (`thinwall-removal`), flank-milling zones (`thinwall-access/src/zones.rs`), the order of operations (`thinwall-ops/src/order.rs`): few operands, made by our own code, whose outputs the snapshots pin |
//!
//! Why two: geo 0.33 pins i_overlay 4.5, whose hole binding panics (an
//! index out of bounds) on some unions the reach layer makes, e.g.
//! slivers folded on themselves from NIST FTC 10 and STC 06
//! (docs/ARCHITECTURE.md's ledger). Moving a job from geo's to this
//! module is a change of output at rounding level, to be made with a
//! snapshot comparison.
//!
//! Every boolean here runs on i_overlay's 64-bit integer grid
//! (`overlay_as::<i64>`): on its default 32-bit grid, near-collinear
//! slivers (a fan at a drill-point cone's apex) snap and split again and
//! again, 0.9 s for a 47-corner ring that takes 77 µs here (the ledger).
//!
//! Each operand must be a valid region (its polygons apart, holes inside
//! their outline): the even-odd rule then fills it whatever the rings'
//! orientation.

use geo::{Coord, LineString, MultiPolygon, Polygon};
use i_overlay::core::fill_rule::FillRule;
use i_overlay::core::overlay_rule::OverlayRule;
use i_overlay::float::single::SingleFloatOverlay;
use i_overlay::i_float::adapter::FloatPointAdapter;

/// i_overlay's shapes: per polygon its rings, outline first, each open.
type Shapes = Vec<Vec<Vec<[f64; 2]>>>;

/// `a ∪ b`.
pub fn union(a: &MultiPolygon<f64>, b: &MultiPolygon<f64>) -> MultiPolygon<f64> {
    apply(a, b, OverlayRule::Union)
}

/// `a − b`.
pub fn difference(a: &MultiPolygon<f64>, b: &MultiPolygon<f64>) -> MultiPolygon<f64> {
    apply(a, b, OverlayRule::Difference)
}

/// `a ∩ b`.
pub fn intersection(a: &MultiPolygon<f64>, b: &MultiPolygon<f64>) -> MultiPolygon<f64> {
    apply(a, b, OverlayRule::Intersect)
}

/// `(a ∩ b, a − b)` from one overlay graph of the two (half the work of
/// the two booleans apart: the segments are split and wound once).
pub fn split(
    a: &MultiPolygon<f64>,
    b: &MultiPolygon<f64>,
) -> (MultiPolygon<f64>, MultiPolygon<f64>) {
    let (sa, sb) = (shapes(a), shapes(b));
    split_shapes(&sa, &sb, None)
}

/// [`split`] of a small `a` by a large region prepared once
/// ([`Near::of`]): the same result, bit for bit, from the region's rings
/// near `a` only.
pub fn split_near(a: &MultiPolygon<f64>, b: &Near) -> (MultiPolygon<f64>, MultiPolygon<f64>) {
    let empty = || MultiPolygon::new(vec![]);
    let Some((sa, sb, grid)) = b.by(a) else {
        return (empty(), empty());
    };
    split_shapes(&sa, &sb, Some(&grid))
}

/// [`intersection`] of a small `a` with a large region prepared once
/// ([`Near::of`]): the same result, bit for bit, from the region's rings
/// near `a` only.
pub fn intersection_near(a: &MultiPolygon<f64>, b: &Near) -> MultiPolygon<f64> {
    use i_overlay::core::overlay::ShapeType;
    use i_overlay::float::overlay::FloatOverlay;
    let Some((sa, sb, grid)) = b.by(a) else {
        return MultiPolygon::new(vec![]);
    };
    crate::parallel::check_deadline();
    let corners = [grid.min, grid.max];
    let adapter = FloatPointAdapter::<[f64; 2], i64>::with_iter_conservative(corners.iter());
    let capacity = sa.iter().chain(&sb).flatten().map(Vec::len).sum();
    let shapes = FloatOverlay::with_adapter(adapter, capacity)
        .unsafe_add_source(&sa, ShapeType::Subject)
        .unsafe_add_source(&sb, ShapeType::Clip)
        .overlay(OverlayRule::Intersect, FillRule::EvenOdd);
    from_shapes(shapes)
}

/// A large region prepared for booleans with small ones near it: its
/// rings as the overlay takes them, each with its box, and the bounds of
/// all its corners.
pub struct Near {
    bounds: Bounds,
    /// Per polygon, its rings (outline first) and their boxes.
    shapes: Vec<Vec<(Bounds, Vec<[f64; 2]>)>>,
}

impl Near {
    /// `region` prepared (`None` when it has no corners).
    pub fn of(region: &MultiPolygon<f64>) -> Option<Self> {
        let shapes = shapes(region);
        let bounds = Bounds::of_shapes(&shapes)?;
        let boxed = shapes
            .into_iter()
            .map(|rings| {
                rings
                    .into_iter()
                    .filter_map(|r| Some((Bounds::of_ring(&r)?, r)))
                    .collect()
            })
            .collect();
        Some(Near {
            bounds,
            shapes: boxed,
        })
    }

    /// `a`'s shapes, the region's rings whose boxes meet `a`'s (a
    /// polygon whose outline's box misses it goes whole, a hole that
    /// misses it goes from its polygon), and the bounds of both whole
    /// (`None` when `a` is empty). The rings left are the region's own,
    /// and the overlay's integer grid is the one the whole of both would
    /// give (it follows the bounds of all corners), so every segment that
    /// meets `a` is the same on the grid and a boolean of the two near
    /// `a` is the boolean of the whole, bit for bit.
    fn by(&self, a: &MultiPolygon<f64>) -> Option<(Shapes, Shapes, Bounds)> {
        let sa = shapes(a);
        let a_bounds = Bounds::of_shapes(&sa)?;
        let sb: Shapes = self
            .shapes
            .iter()
            .filter(|rings| rings[0].0.meets(&a_bounds))
            .map(|rings| {
                rings
                    .iter()
                    .enumerate()
                    .filter(|(k, (b, _))| *k == 0 || b.meets(&a_bounds))
                    .map(|(_, (_, r))| r.clone())
                    .collect()
            })
            .collect();
        Some((sa, sb, a_bounds.union(&self.bounds)))
    }
}

/// The corners' bounds of a region: the overlay's integer grid is set by
/// them.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Bounds {
    min: [f64; 2],
    max: [f64; 2],
}

impl Bounds {
    /// The bounds of `m`'s corners (`None` when it has none).
    #[cfg(test)]
    fn of(m: &MultiPolygon<f64>) -> Option<Self> {
        Self::of_shapes(&shapes(m))
    }

    fn of_ring(r: &[[f64; 2]]) -> Option<Self> {
        Self::of_points(r.iter())
    }

    fn of_shapes(s: &Shapes) -> Option<Self> {
        Self::of_points(s.iter().flatten().flatten())
    }

    fn of_points<'p>(mut it: impl Iterator<Item = &'p [f64; 2]>) -> Option<Self> {
        let first = *it.next()?;
        Some(it.fold(
            Bounds {
                min: first,
                max: first,
            },
            |b, p| Bounds {
                min: [b.min[0].min(p[0]), b.min[1].min(p[1])],
                max: [b.max[0].max(p[0]), b.max[1].max(p[1])],
            },
        ))
    }

    fn union(&self, o: &Bounds) -> Bounds {
        Bounds {
            min: [self.min[0].min(o.min[0]), self.min[1].min(o.min[1])],
            max: [self.max[0].max(o.max[0]), self.max[1].max(o.max[1])],
        }
    }

    fn meets(&self, o: &Bounds) -> bool {
        self.min[0] <= o.max[0]
            && o.min[0] <= self.max[0]
            && self.min[1] <= o.max[1]
            && o.min[1] <= self.max[1]
    }
}

/// `(a ∩ b, a − b)` of shapes, on the integer grid of `grid` when given
/// (else of their corners).
fn split_shapes(
    sa: &Shapes,
    sb: &Shapes,
    grid: Option<&Bounds>,
) -> (MultiPolygon<f64>, MultiPolygon<f64>) {
    use i_overlay::core::extract::BooleanExtractionBuffer;
    use i_overlay::core::overlay::ShapeType;
    use i_overlay::float::overlay::FloatOverlay;
    let empty = || MultiPolygon::new(vec![]);
    if sa.is_empty() {
        return (empty(), empty());
    }
    crate::parallel::check_deadline();
    let mut overlay = match grid {
        None => FloatOverlay::<[f64; 2], i64>::from_subj_and_clip(sa, sb),
        Some(g) => {
            let corners = [g.min, g.max];
            let adapter =
                FloatPointAdapter::<[f64; 2], i64>::with_iter_conservative(corners.iter());
            let capacity = sa.iter().chain(sb).flatten().map(Vec::len).sum();
            FloatOverlay::with_adapter(adapter, capacity)
                .unsafe_add_source(sa, ShapeType::Subject)
                .unsafe_add_source(sb, ShapeType::Clip)
        }
    };
    let Some(graph) = overlay.build_graph_view(FillRule::EvenOdd) else {
        return (empty(), empty());
    };
    let mut buffer = BooleanExtractionBuffer::default();
    let inside = graph.extract_shapes(OverlayRule::Intersect, &mut buffer);
    let outside = graph.extract_shapes(OverlayRule::Difference, &mut buffer);
    (from_shapes(inside), from_shapes(outside))
}

/// The union of polygons that tile a region and barely overlap (a mesh's
/// triangles seen from above), in one sweep with the non-zero rule (each
/// ring counter-clockwise). Where many overlap deeply (grown triangles),
/// [`union_all`]'s pairwise tree is faster.
pub fn union_tiles(tiles: &[Polygon<f64>]) -> MultiPolygon<f64> {
    use geo::Orient;
    let oriented = MultiPolygon::new(
        tiles
            .iter()
            .map(|p| p.orient(geo::orient::Direction::Default))
            .collect(),
    );
    let shapes = shapes(&oriented);
    if shapes.is_empty() {
        return MultiPolygon::new(vec![]);
    }
    crate::parallel::check_deadline();
    let none: Shapes = Vec::new();
    from_shapes(shapes.overlay_as::<i64>(&none, OverlayRule::Subject, FillRule::NonZero))
}

/// The region closed rings wind around (the non-zero rule over all of
/// them as one shape): a patch of triangles' outline, outer rings counter-
/// clockwise and holes clockwise, cleaned of the small self-overlaps its
/// triangles leave along a silhouette.
pub fn wound_region(rings: Vec<Vec<[f64; 2]>>) -> MultiPolygon<f64> {
    filled(rings, FillRule::NonZero)
}

/// The region closed rings cut out of each other (the even-odd rule over
/// all of them as one shape): a face's projection whose loops overlap in
/// projection, ring by ring exclusive or.
pub fn even_odd_region(rings: Vec<Vec<[f64; 2]>>) -> MultiPolygon<f64> {
    filled(rings, FillRule::EvenOdd)
}

/// The region closed rings wind around positively (counter-clockwise, y
/// up), as one shape: a stroke's convolution cycles
/// (`thinwall_access::reach::stroke`), whose loops wind back where the
/// stroke's side is concave.
pub fn positive_region(rings: Vec<Vec<[f64; 2]>>) -> MultiPolygon<f64> {
    filled(rings, FillRule::Positive)
}

/// The region closed rings fill, as one shape, by `rule`.
fn filled(rings: Vec<Vec<[f64; 2]>>, rule: FillRule) -> MultiPolygon<f64> {
    let shape: Vec<Vec<[f64; 2]>> = rings.into_iter().filter(|r| r.len() >= 3).collect();
    if shape.is_empty() {
        return MultiPolygon::new(vec![]);
    }
    crate::parallel::check_deadline();
    let none: Shapes = Vec::new();
    from_shapes(vec![shape].overlay_as::<i64>(&none, OverlayRule::Subject, rule))
}

/// The union of many regions, pairwise up a balanced tree (faster here
/// than one sweep over all of them, whose overlaps run deep).
pub fn union_all(mut parts: Vec<MultiPolygon<f64>>) -> MultiPolygon<f64> {
    if parts.is_empty() {
        return MultiPolygon::new(vec![]);
    }
    while parts.len() > 1 {
        let mut next = Vec::with_capacity(parts.len().div_ceil(2));
        let mut it = parts.into_iter();
        while let Some(a) = it.next() {
            crate::parallel::check_deadline();
            next.push(match it.next() {
                Some(b) => union(&a, &b),
                None => a,
            });
        }
        parts = next;
    }
    parts.pop().unwrap_or_else(|| MultiPolygon::new(vec![]))
}

fn apply(a: &MultiPolygon<f64>, b: &MultiPolygon<f64>, rule: OverlayRule) -> MultiPolygon<f64> {
    let (sa, sb) = (shapes(a), shapes(b));
    if sa.is_empty() && sb.is_empty() {
        return MultiPolygon::new(vec![]);
    }
    from_shapes(sa.overlay_as::<i64>(&sb, rule, FillRule::EvenOdd))
}

fn shapes(m: &MultiPolygon<f64>) -> Shapes {
    m.iter()
        .map(|p| {
            std::iter::once(p.exterior())
                .chain(p.interiors())
                .map(open_ring)
                .filter(|r| r.len() >= 3)
                .collect::<Vec<_>>()
        })
        .filter(|rings| !rings.is_empty())
        .collect()
}

/// A ring's corners without the closing repeat.
fn open_ring(ring: &LineString<f64>) -> Vec<[f64; 2]> {
    let mut pts: Vec<[f64; 2]> = ring.coords().map(|c| [c.x, c.y]).collect();
    if pts.len() > 1 && pts.first() == pts.last() {
        pts.pop();
    }
    pts
}

fn from_shapes(shapes: Shapes) -> MultiPolygon<f64> {
    let ring = |r: Vec<[f64; 2]>| -> LineString<f64> {
        r.into_iter().map(|p| Coord { x: p[0], y: p[1] }).collect()
    };
    MultiPolygon::new(
        shapes
            .into_iter()
            .filter(|s| !s.is_empty())
            .map(|s| {
                let mut rings = s.into_iter();
                let outline = rings
                    .next()
                    .map(ring)
                    .unwrap_or_else(|| LineString::new(vec![]));
                Polygon::new(outline, rings.map(ring).collect())
            })
            .collect(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use geo::{Area, BooleanOps};

    fn square(x: f64, y: f64, s: f64, ccw: bool) -> Polygon<f64> {
        let mut pts = vec![(x, y), (x + s, y), (x + s, y + s), (x, y + s)];
        if !ccw {
            pts.reverse();
        }
        Polygon::new(LineString::from(pts), vec![])
    }

    /// Counter-clockwise rings wind positively, clockwise ones negatively:
    /// a square inside a larger one, each way round.
    #[test]
    fn positive_is_counter_clockwise() {
        let ring = |x: f64, s: f64, ccw: bool| {
            let mut v = vec![[x, x], [x + s, x], [x + s, x + s], [x, x + s]];
            if !ccw {
                v.reverse();
            }
            v
        };
        let area = |rings| positive_region(rings).unsigned_area();
        assert!((area(vec![ring(0.0, 4.0, true)]) - 16.0).abs() < 1e-12);
        assert_eq!(area(vec![ring(0.0, 4.0, false)]), 0.0);
        // Wound twice and once: all of it; once less the inner: a frame.
        let both = area(vec![ring(0.0, 4.0, true), ring(1.0, 1.0, true)]);
        assert!((both - 16.0).abs() < 1e-12);
        let frame = area(vec![ring(0.0, 4.0, true), ring(1.0, 1.0, false)]);
        assert!((frame - 15.0).abs() < 1e-12);
    }

    /// Tiles of either orientation: a 20 × 20 grid of triangles over a
    /// square with a square hole unites to the square less its hole (one
    /// polygon with one hole), and tiles overlapping their neighbours
    /// count their overlap once, as the pairwise union does.
    #[test]
    fn tiles_unite_in_one_sweep() {
        let tri = |a: (f64, f64), b: (f64, f64), c: (f64, f64), ccw: bool| {
            let mut v = vec![a, b, c];
            if !ccw {
                v.reverse();
            }
            Polygon::new(LineString::from(v), vec![])
        };
        let mut tiles = Vec::new();
        for i in 0..20 {
            for j in 0..20 {
                if (8..12).contains(&i) && (8..12).contains(&j) {
                    continue;
                }
                let (x, y) = (i as f64, j as f64);
                tiles.push(tri(
                    (x, y),
                    (x + 1.0, y),
                    (x + 1.0, y + 1.0),
                    (i + j) % 2 == 0,
                ));
                tiles.push(tri((x, y), (x + 1.0, y + 1.0), (x, y + 1.0), true));
            }
        }
        let u = union_tiles(&tiles);
        assert!((u.unsigned_area() - (400.0 - 16.0)).abs() < 1e-9);
        assert_eq!(u.0.len(), 1);
        assert_eq!(u.0[0].interiors().len(), 1);
        let grown: Vec<Polygon<f64>> = (0..10)
            .map(|k| square(k as f64 * 0.5, 0.0, 1.0, k % 2 == 0))
            .collect();
        let pairwise = union_all(
            grown
                .iter()
                .map(|p| MultiPolygon::new(vec![p.clone()]))
                .collect(),
        );
        assert!((union_tiles(&grown).unsigned_area() - pairwise.unsigned_area()).abs() < 1e-9);
        assert!((pairwise.unsigned_area() - 5.5).abs() < 1e-9);
    }

    /// A split is the intersection and the difference, bit for bit; and
    /// the split and the intersection near a small region (the far
    /// polygons and holes of the large one left out) are the whole ones,
    /// bit for bit: over 200 random cells against a field of 60 squares,
    /// some with holes.
    #[test]
    fn a_split_near_is_the_whole_split() {
        let mut seed = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut field = Vec::new();
        for _ in 0..60 {
            let (x, y, s) = (100.0 * next(), 100.0 * next(), 2.0 + 8.0 * next());
            let mut p = square(x, y, s, true);
            if next() < 0.5 {
                p.interiors_push(
                    square(x + 0.3 * s, y + 0.3 * s, 0.4 * s, false)
                        .exterior()
                        .clone(),
                );
            }
            field.push(p);
        }
        let field = union_all(
            field
                .into_iter()
                .map(|p| MultiPolygon::new(vec![p]))
                .collect(),
        );
        let near = Near::of(&field).unwrap();
        let (mut cut, mut left_out) = (0, 0);
        for _ in 0..200 {
            let (x, y, s) = (100.0 * next(), 100.0 * next(), 1.0 + 12.0 * next());
            let n = 3 + (next() * 9.0) as usize;
            let ring: Vec<(f64, f64)> = (0..n)
                .map(|k| {
                    let t = std::f64::consts::TAU * (k as f64 + 0.5 * next()) / n as f64;
                    let r = s * (0.5 + 0.5 * next());
                    (x + r * t.cos(), y + r * t.sin())
                })
                .collect();
            let cell = MultiPolygon::new(vec![Polygon::new(LineString::from(ring), vec![])]);
            let whole = split(&cell, &field);
            assert_eq!(whole.0, intersection(&cell, &field));
            assert_eq!(whole.1, difference(&cell, &field));
            assert_eq!(split_near(&cell, &near), whole);
            assert_eq!(intersection_near(&cell, &near), whole.0);
            cut += usize::from(!whole.0 .0.is_empty() && !whole.1 .0.is_empty());
            let near = Bounds::of(&cell).unwrap();
            left_out += field
                .iter()
                .filter(|p| {
                    !Bounds::of(&MultiPolygon::new(vec![(*p).clone()]))
                        .unwrap()
                        .meets(&near)
                })
                .count();
        }
        assert!(
            cut > 20 && left_out > 1000,
            "{cut} cut, {left_out} polygons left out"
        );
    }

    /// Two overlapping squares and a frame with a hole, in either
    /// orientation: the same areas as geo's booleans.
    #[test]
    fn the_same_areas_as_geo_in_either_orientation() {
        for ccw in [true, false] {
            let a = MultiPolygon::new(vec![square(0.0, 0.0, 4.0, ccw)]);
            let b = MultiPolygon::new(vec![square(2.0, 1.0, 4.0, !ccw)]);
            let hole = square(1.0, 1.0, 2.0, !ccw).exterior().clone();
            let frame = MultiPolygon::new(vec![Polygon::new(
                square(-1.0, -1.0, 6.0, ccw).exterior().clone(),
                vec![hole],
            )]);
            assert!((union(&a, &b).unsigned_area() - 26.0).abs() < 1e-9);
            assert!((intersection(&a, &b).unsigned_area() - 6.0).abs() < 1e-9);
            assert!((difference(&a, &b).unsigned_area() - 10.0).abs() < 1e-9);
            for (x, y) in [(&frame, &b), (&b, &frame), (&a, &frame)] {
                let want = [x.union(y), x.intersection(y), x.difference(y)];
                let got = [union(x, y), intersection(x, y), difference(x, y)];
                for (w, g) in want.iter().zip(&got) {
                    assert!((w.unsigned_area() - g.unsigned_area()).abs() < 1e-9);
                }
            }
        }
    }

    /// Slivers folded on themselves (from joining grown triangles of NIST
    /// FTC 10 seen along +y) on which geo 0.33's union panicked: joined,
    /// within their bounding box (9.0 × 0.03 mm).
    #[test]
    fn folded_slivers_join() {
        let poly = |pts: &[[f64; 2]]| -> Polygon<f64> {
            Polygon::new(
                pts.iter().map(|p| (p[0], p[1])).collect::<Vec<_>>().into(),
                vec![],
            )
        };
        let a = MultiPolygon::new(vec![
            poly(&[
                [-16.01085612169119, 8.992708872091455],
                [-16.01085612169119, 8.970941814613028],
                [-15.510132379742586, 8.992708872091455],
                [-8.499999999912703, 9.000000002813024],
            ]),
            poly(&[
                [-15.009408637793982, 8.992708872091455],
                [-15.009408637793982, 8.970941814613028],
                [-14.508684895845377, 8.992708872091455],
            ]),
            poly(&[
                [-8.499999999912703, 9.000000002813024],
                [-14.508684895845377, 8.992708872091455],
                [-14.007961153896773, 8.992708872091455],
            ]),
        ]);
        let b = MultiPolygon::new(vec![poly(&[
            [-8.500000001139918, 9.000000002813024],
            [-17.513027341313638, 8.992708872091455],
            [-17.012303599365033, 8.992708872091455],
            [-17.012303599365033, 8.970941814613028],
            [-16.51157986486701, 8.992708872091455],
            [-16.010856122918405, 8.992708872091455],
            [-8.500000001139918, 8.999999995362444],
            [-17.005018712230004, 8.992715108227415],
        ])]);
        let u = union(&a, &b).unsigned_area();
        let bbox =
            (17.513027341313638 - 8.499999999912703) * (9.000000002813024 - 8.970941814613028);
        assert!(u > 0.0 && u <= bbox, "{u} of {bbox}");
    }

    /// The outline of a fan of slivers at a drill-point cone's apex, seen
    /// from the side (NIST CTC 01 from −Z): near-collinear edges that the
    /// 32-bit grid splits again and again (0.9 s). The 64-bit grid fills
    /// the same region: one piece, the area the 32-bit grid gives.
    #[test]
    fn a_fan_of_slivers_fills_as_on_the_coarser_grid() {
        let fan: Vec<Vec<[f64; 2]>> = vec![
            vec![
                [30.0, 73.9913938097245],
                [33.01984743937912, 75.99426253981636],
                [32.64236650945673, 75.74390394855489],
                [30.0, 73.9913938097245],
                [31.887404649611952, 75.24318676603191],
                [31.50992371968956, 74.99282817477044],
                [30.0, 73.9913938097245],
                [30.75496185984478, 74.49211099224746],
                [30.377480929922392, 74.24175240098599],
                [30.0, 73.9913938097245],
                [30.416665198314714, 74.24175240098599],
                [30.83333039662943, 74.49211099224746],
                [31.249995594944146, 74.74246958350895],
                [31.666660793258863, 74.99282817477044],
                [32.08332599157358, 75.24318676603191],
                [32.49999118988829, 75.4935453572934],
                [32.91665638820301, 75.74390394855489],
                [33.33332158651773, 75.99426253981636],
                [33.74998678483244, 76.24462113107785],
                [34.166651983147155, 76.49497972233934],
                [34.58331718146187, 76.74533831360081],
                [34.99998237977659, 76.9956969048623],
                [35.4166475780913, 77.24605549612379],
                [35.83331277640602, 77.49641408738526],
                [36.249977974720736, 77.74677267864675],
                [36.666643173035446, 77.99713126990824],
                [37.083308371350164, 78.24748986116971],
                [37.49997356966488, 78.4978484524312],
                [37.9166387679796, 78.74820704369269],
                [38.33330396629431, 78.99856563495416],
                [38.74996916460903, 79.24892422621565],
                [39.166634362923745, 79.49928281747714],
                [39.583299561238455, 79.74964140873861],
                [39.999583570014934, 80.0000000000001],
                [39.98706905192468, 80.0000000000001],
                [39.94248777695873, 80.0000000000001],
                [39.88192866884256, 80.0000000000001],
                [39.789640391493734, 80.0000000000001],
                [39.68161991066778, 80.0000000000001],
                [39.54251341749684, 80.0000000000001],
                [39.38807186024145, 80.0000000000001],
                [39.203486822821, 80.0000000000001],
                [39.00411154575891, 80.0000000000001],
                [38.7758256189037, 80.0000000000001],
            ],
            vec![
                [34.15229022914629, 76.74533831360081],
                [33.774809299223904, 76.49497972233934],
                [30.0, 73.9913938097245],
            ],
        ];
        let area = |m: &MultiPolygon<f64>| geo::Area::unsigned_area(m);
        let fine = wound_region(fan.clone());
        let none: Shapes = Vec::new();
        let coarse = from_shapes(vec![fan].overlay(&none, OverlayRule::Subject, FillRule::NonZero));
        assert_eq!(fine.0.len(), 1);
        assert!(area(&fine) > 0.1, "{}", area(&fine));
        assert!(
            (area(&fine) - area(&coarse)).abs() < 1e-6 * area(&fine),
            "{} {}",
            area(&fine),
            area(&coarse)
        );
    }
}
