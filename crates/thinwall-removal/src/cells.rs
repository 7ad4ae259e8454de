//! The arrangement of projections: the stock's footprint cut by every
//! covering region (a piece's projection, a layer's band) into cells over
//! which the same regions lie. Over one cell, a vertical line meets the
//! same faces in the same order wherever it stands.

use super::flux::area;
use geo::{BooleanOps, BoundingRect, MultiPolygon, Polygon, Rect};

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
pub fn arrange(start: Polygon<f64>, covers: &[Cover], min_area: f64) -> Vec<Cell> {
    let mut cells = vec![cell(start, vec![])];
    for (ci, c) in covers.iter().enumerate() {
        // A long arrangement (thousands of meshed triangles) stops at the
        // study's time limit.
        thinwall_analysis::parallel::check_deadline();
        let mut next = Vec::with_capacity(cells.len() + 4);
        for cl in cells.drain(..) {
            if !overlaps(&cl.bbox, &c.bbox) {
                next.push(cl);
                continue;
            }
            let me = MultiPolygon::new(vec![cl.poly.clone()]);
            let inside = match c.robust {
                true => thinwall_analysis::boolean::intersection(&me, c.region),
                false => me.intersection(c.region),
            };
            let inside_area: f64 = inside.0.iter().map(area).sum();
            if inside_area <= min_area {
                next.push(cl);
                continue;
            }
            let outside = match c.robust {
                true => thinwall_analysis::boolean::difference(&me, c.region),
                false => me.difference(c.region),
            };
            let mut covered = cl.covers.clone();
            covered.push(ci);
            for p in inside.0 {
                if area(&p) > min_area {
                    next.push(cell(p, covered.clone()));
                }
            }
            for p in outside.0 {
                if area(&p) > min_area {
                    next.push(cell(p, cl.covers.clone()));
                }
            }
        }
        cells = next;
    }
    cells
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
