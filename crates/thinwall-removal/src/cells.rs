//! The arrangement of projections: the stock's footprint cut by every
//! covering region (a piece's projection, a layer's band) into cells over
//! which the same regions lie. Over one cell, a vertical line meets the
//! same faces in the same order wherever it stands.

use super::flux::area;
use crate::halving::{corners, halves};
use geo::{BooleanOps, BoundingRect, LineString, MultiPolygon, Polygon, Rect};
use thinwall_analysis::boolean::{self, Near};
use thinwall_analysis::parallel::Work;

/// A region that covers part of the plane.
pub struct Cover<'a> {
    pub region: &'a MultiPolygon<f64>,
    pub bbox: Rect<f64>,
    /// Cut through `thinwall_analysis::boolean` (i_overlay 9) rather than
    /// geo's booleans: for the many-cornered regions of meshed faces, on
    /// which geo's i_overlay 4.5 panics (docs/ARCHITECTURE.md's ledger);
    /// the exact pieces keep geo's, whose outputs the snapshots pin.
    pub robust: bool,
}

/// One cell: a polygon and the covers over it (indices into the list
/// given to [`arrange`]).
#[derive(Clone, Debug)]
pub struct Cell {
    pub poly: Polygon<f64>,
    pub bbox: Rect<f64>,
    pub covers: Vec<usize>,
    pub area: f64,
}

fn overlaps(a: &Rect<f64>, b: &Rect<f64>) -> bool {
    a.min().x <= b.max().x
        && b.min().x <= a.max().x
        && a.min().y <= b.max().y
        && b.min().y <= a.max().y
}

/// Cut `start` by every cover in turn. Polygons of area below `min_area`
/// (noise of the booleans) are dropped.
pub fn arrange(start: Polygon<f64>, covers: &[Cover], min_area: f64, work: Work) -> Vec<Cell> {
    arrange_on(vec![cell(start, vec![])], covers, (0, min_area), work)
}

/// `cells`, the arrangement of `covers[..first]`, cut by the covers from
/// `first` on in turn: the arrangement of them all. The cells one cover
/// meets are cut on `work`'s threads (each cut is the cell's alone; the
/// pieces go back in the cells' order, so the result is the same either
/// way).
pub fn arrange_on(
    mut cells: Vec<Cell>,
    covers: &[Cover],
    (first, min_area): (usize, f64),
    work: Work,
) -> Vec<Cell> {
    for (ci, c) in covers.iter().enumerate().skip(first) {
        // A long arrangement (thousands of meshed triangles) stops at the
        // study's time limit.
        thinwall_analysis::parallel::check_deadline();
        // A many-cornered region (a meshed face's outline) is cut into
        // tiles once, so each cell meets only the tiles by it.
        let tiles = (c.robust && corners(c.region) > TILE_CORNERS)
            .then(|| Tiles::of(c.region.clone(), c.bbox, 0));
        let met: Vec<usize> = (0..cells.len())
            .filter(|&k| overlaps(&cells[k].bbox, &c.bbox))
            .collect();
        if met.is_empty() {
            continue;
        }
        // A many-cornered region is cut near each cell only (the same
        // result: `boolean::split_near`).
        let near = match (c.robust, &tiles) {
            (true, None) if corners(c.region) > NEAR_CORNERS => Near::of(c.region),
            _ => None,
        };
        let region = Region {
            tiles: tiles.as_ref(),
            near: near.as_ref(),
        };
        let cut = |&k: &usize| cut_cell(&cells[k], (ci, c), region, min_area);
        let mut cuts = match met.len() >= PARALLEL_CELLS {
            true => work.map(&met, cut),
            false => met.iter().map(cut).collect(),
        }
        .into_iter();
        let mut met = met.into_iter().peekable();
        let mut next = Vec::with_capacity(cells.len() + 4);
        for (k, cl) in cells.into_iter().enumerate() {
            if met.next_if_eq(&k).is_none() {
                next.push(cl);
                continue;
            }
            match cuts.next().expect("one cut per cell met") {
                Some(pieces) => next.extend(pieces),
                None => next.push(cl),
            }
        }
        cells = next;
    }
    cells
}

/// How a cover's region is cut: through its tiles, or near each cell on
/// the grid of its corners' bounds.
#[derive(Clone, Copy)]
struct Region<'t> {
    tiles: Option<&'t Tiles>,
    near: Option<&'t Near>,
}

/// A region with more corners than this is cut near each cell only.
const NEAR_CORNERS: usize = 8;

/// Cells a cover meets, at least, to cut them on several threads.
const PARALLEL_CELLS: usize = 4;

/// Cell `cl` cut by cover `ci`: its pieces inside the cover and outside,
/// or `None` when the cover leaves it whole (no more than `min_area` of it
/// inside).
fn cut_cell(
    cl: &Cell,
    (ci, c): (usize, &Cover),
    Region {
        tiles,
        near: bounds,
    }: Region,
    min_area: f64,
) -> Option<Vec<Cell>> {
    // A cell with many holes (a rib grid's top) meets a cover through the
    // holes by it only: the others lie outside the cover's box, so they
    // change neither part, and go back into the piece around them after.
    let (near, far) = by_the_box(&cl.poly, &c.bbox);
    let me = MultiPolygon::new(vec![near]);
    let local;
    let region = match tiles {
        Some(t) => {
            local = t.near(&cl.bbox);
            &local
        }
        None => c.region,
    };
    let (inside, outside) = match (c.robust, bounds) {
        (true, Some(b)) => {
            let (i, o) = boolean::split_near(&me, b);
            (i, Some(o))
        }
        (true, None) => {
            let (i, o) = boolean::split(&me, region);
            (i, Some(o))
        }
        (false, _) => (me.intersection(region), None),
    };
    let inside_area: f64 = inside.0.iter().map(area).sum();
    if inside_area <= min_area {
        return None;
    }
    let outside = outside.unwrap_or_else(|| me.difference(region));
    let outside = match with_holes(outside, &far) {
        Some(o) => o,
        // A hole found no piece around it (a boolean's noise): the whole
        // cell, as without the shortcut.
        None => {
            let whole = MultiPolygon::new(vec![cl.poly.clone()]);
            match c.robust {
                true => boolean::difference(&whole, region),
                false => whole.difference(region),
            }
        }
    };
    let mut covered = cl.covers.clone();
    covered.push(ci);
    let inside = inside.0.into_iter().map(|p| (p, covered.clone()));
    let outside = outside.0.into_iter().map(|p| (p, cl.covers.clone()));
    Some(
        inside
            .chain(outside)
            .filter(|(p, _)| area(p) > min_area)
            .map(|(p, covers)| cell(p, covers))
            .collect(),
    )
}

/// A cell with more holes than this meets a cover through the holes by the
/// cover's box only ([`by_the_box`]).
const NEAR_HOLES: usize = 16;

/// `poly` with only the holes whose boxes meet `b` (all of them when it
/// has few), and the others.
fn by_the_box(poly: &Polygon<f64>, b: &Rect<f64>) -> (Polygon<f64>, Vec<LineString<f64>>) {
    if poly.interiors().len() <= NEAR_HOLES {
        return (poly.clone(), Vec::new());
    }
    let (near, far): (Vec<_>, Vec<_>) = poly
        .interiors()
        .iter()
        .cloned()
        .partition(|h| h.bounding_rect().is_some_and(|r| overlaps(&r, b)));
    (Polygon::new(poly.exterior().clone(), near), far)
}

/// `pieces` with each of `far` (holes clear of what cut them) back in the
/// piece whose outline surrounds it; `None` when one has no such piece.
fn with_holes(mut pieces: MultiPolygon<f64>, far: &[LineString<f64>]) -> Option<MultiPolygon<f64>> {
    use geo::Contains;
    if far.is_empty() {
        return Some(pieces);
    }
    let outlines: Vec<Polygon<f64>> = pieces
        .0
        .iter()
        .map(|q| Polygon::new(q.exterior().clone(), vec![]))
        .collect();
    for hole in far {
        let at = geo::Point::from(*hole.0.first()?);
        let home = outlines.iter().position(|o| o.contains(&at))?;
        pieces.0[home].interiors_push(hole.clone());
    }
    Some(pieces)
}

/// A region with more corners than this is cut into tiles before cells
/// meet it.
const TILE_CORNERS: usize = 2048;

/// Halvings of a region's box into tiles, at most.
const MAX_TILE_DEPTH: usize = 16;

/// A region cut by halving its box until each tile has few corners: the
/// tiles partition it, so its part in any box is the tiles by that box
/// (they touch only along the cuts).
enum Tiles {
    Leaf(Rect<f64>, MultiPolygon<f64>),
    Split(Box<Tiles>, Box<Tiles>),
}

impl Tiles {
    fn of(region: MultiPolygon<f64>, rect: Rect<f64>, depth: usize) -> Self {
        if corners(&region) <= TILE_CORNERS / 4 || depth >= MAX_TILE_DEPTH {
            return Tiles::Leaf(rect, region);
        }
        let [a, b] = halves(&rect);
        let half = |r: Rect<f64>| {
            let part = thinwall_analysis::boolean::intersection(
                &region,
                &MultiPolygon::new(vec![r.to_polygon()]),
            );
            Box::new(Tiles::of(part, r, depth + 1))
        };
        Tiles::Split(half(a), half(b))
    }

    /// The region's polygons in the tiles whose boxes meet `b`.
    fn near(&self, b: &Rect<f64>) -> MultiPolygon<f64> {
        let mut out = Vec::new();
        self.collect(b, &mut out);
        MultiPolygon::new(out)
    }

    fn collect(&self, b: &Rect<f64>, out: &mut Vec<Polygon<f64>>) {
        match self {
            Tiles::Leaf(r, m) => {
                if overlaps(r, b) {
                    out.extend(m.0.iter().cloned());
                }
            }
            Tiles::Split(x, y) => {
                x.collect(b, out);
                y.collect(b, out);
            }
        }
    }
}

fn cell(poly: Polygon<f64>, covers: Vec<usize>) -> Cell {
    let bbox = poly.bounding_rect().expect("a cell has points");
    let area = area(&poly);
    Cell {
        poly,
        bbox,
        covers,
        area,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use geo::{Area, LineString};

    /// A disc of 6000 corners with a hole, tiled: over any small box its
    /// tiles hold what the whole region holds there, and an arrangement
    /// cut by it robustly (tiled) gives the cells of one cut by the whole.
    #[test]
    fn tiles_hold_the_region_by_any_box() {
        let ring = |r: f64, k: usize, ccw: bool| {
            let mut v: Vec<(f64, f64)> = (0..k)
                .map(|t| {
                    let a = std::f64::consts::TAU * t as f64 / k as f64;
                    (r * a.cos(), r * a.sin())
                })
                .collect();
            if !ccw {
                v.reverse();
            }
            v.push(v[0]);
            LineString::from(v)
        };
        let region = MultiPolygon::new(vec![Polygon::new(
            ring(10.0, 6000, true),
            vec![ring(4.0, 3000, false)],
        )]);
        let bbox = region.bounding_rect().unwrap();
        let tiles = Tiles::of(region.clone(), bbox, 0);
        assert!(matches!(tiles, Tiles::Split(..)));
        for (x, y, s) in [
            (-10.0, -10.0, 20.0),
            (3.0, 0.5, 2.0),
            (-9.9, -1.0, 1.5),
            (0.0, 0.0, 0.1),
        ] {
            let b = Rect::new((x, y), (x + s, y + s));
            let cellp = MultiPolygon::new(vec![b.to_polygon()]);
            let whole = thinwall_analysis::boolean::intersection(&cellp, &region).unsigned_area();
            let local =
                thinwall_analysis::boolean::intersection(&cellp, &tiles.near(&b)).unsigned_area();
            assert!(
                (whole - local).abs() <= 1e-9 * (s * s),
                "{x} {y}: {whole} {local}"
            );
        }
        let start = Rect::new((-12.0, -12.0), (12.0, 12.0)).to_polygon();
        let band = MultiPolygon::new(vec![Rect::new((-12.0, -1.0), (12.0, 1.0)).to_polygon()]);
        let cover = |region, robust| Cover {
            region,
            bbox: region.bounding_rect().unwrap(),
            robust,
        };
        let cells = arrange(
            start,
            &[cover(&band, true), cover(&region, true)],
            1e-9,
            Work::serial(),
        );
        let covered: f64 = cells
            .iter()
            .filter(|c| c.covers.contains(&1))
            .map(|c| c.area)
            .sum();
        assert!((covered - region.unsigned_area()).abs() < 1e-9 * region.unsigned_area());
        assert_eq!(cells.iter().filter(|c| c.covers == vec![0, 1]).count(), 2);
    }
}
