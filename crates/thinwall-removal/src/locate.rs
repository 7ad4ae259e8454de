//! Where a point of space lies in a removal, and points inside a block:
//! how set-ups along different ups are compared (issue 37). Two removals
//! of one part along different ups cut stock − part into different
//! blocks; whether a block of one was reached by the other is judged at
//! points inside it, each located among the other's blocks.

use crate::inside::PolygonIndex;
use crate::{Grid, Removal};
use geo::{Coord, Intersects, Point};
use thinwall_geom::{Point3, Vector3};

/// Where a point lies in a removal.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Place {
    /// In this block (an index into the removal's blocks).
    Block(usize),
    /// Inside the stock, in no block: part material (or a sliver left out).
    Solid,
    /// Outside the stock.
    Outside,
}

/// Finds the block a point lies in: the cells by a grid over their boxes,
/// then the blocks of the cell by their bounds' heights.
pub struct Locator<'r> {
    removal: &'r Removal,
    grid: Grid,
    /// Per cell, its blocks.
    by_cell: Vec<Vec<usize>>,
    /// The rectangle the cells cover (found once: every cell's box).
    area: geo::Rect<f64>,
    /// Per cell with many corners, its rings' edges filed by height.
    filed: Vec<Option<PolygonIndex>>,
}

/// A cell with more corners than this is tested through its filed edges.
const FILED_CORNERS: usize = 64;

impl<'r> Locator<'r> {
    pub fn new(removal: &'r Removal) -> Self {
        let mut by_cell = vec![Vec::new(); removal.cells.len()];
        for (i, b) in removal.blocks.iter().enumerate() {
            by_cell[b.cell].push(i);
        }
        let area = footprint(removal);
        let grid = Grid::new(area, removal.cells.iter().map(|c| c.bbox), 0.0);
        let filed = removal
            .cells
            .iter()
            .map(|c| {
                let corners = c.poly.exterior().0.len()
                    + c.poly.interiors().iter().map(|h| h.0.len()).sum::<usize>();
                (corners > FILED_CORNERS).then(|| PolygonIndex::new(&c.poly))
            })
            .collect();
        Self {
            removal,
            grid,
            by_cell,
            area,
            filed,
        }
    }

    /// Where world point `p` lies; on a bound, in the block it bounds.
    pub fn place(&self, p: &Point3) -> Place {
        let r = self.removal;
        let l = r.frame.to_local(p);
        let tol = 1e-9 * r.size;
        let area = self.area;
        let (x, y) = (l.x, l.y);
        if x < area.min().x - tol
            || x > area.max().x + tol
            || y < area.min().y - tol
            || y > area.max().y + tol
        {
            return Place::Outside;
        }
        let pt = Point::new(x, y);
        let Some(ci) = self.grid.at(x, y).iter().copied().find(|&ci| {
            inside_box(&r.cells[ci].bbox, x, y)
                && match &self.filed[ci] {
                    Some(index) => index.contains_or_touches(Coord { x, y }),
                    None => r.cells[ci].poly.intersects(&pt),
                }
        }) else {
            return Place::Solid;
        };
        for &bi in &self.by_cell[ci] {
            let b = &r.blocks[bi];
            let lo = r.height_of(&b.lower).at(x, y);
            let hi = r.height_of(&b.upper).at(x, y);
            if l.z >= lo - tol && l.z <= hi + tol {
                return Place::Block(bi);
            }
        }
        if let Some((lo, hi)) = r.block {
            if l.z < lo[2] - tol || l.z > hi[2] + tol {
                return Place::Outside;
            }
        }
        Place::Solid
    }
}

/// Whether (x, y) lies in box `b` or on its sides (a cell's point lies
/// in its box: the box rejects the others before the cell's rings are
/// walked).
fn inside_box(b: &geo::Rect<f64>, x: f64, y: f64) -> bool {
    x >= b.min().x && x <= b.max().x && y >= b.min().y && y <= b.max().y
}

/// The rectangle the removal's cells cover (its arrangement's start).
fn footprint(r: &Removal) -> geo::Rect<f64> {
    let mut lo = Coord {
        x: f64::INFINITY,
        y: f64::INFINITY,
    };
    let mut hi = Coord {
        x: f64::NEG_INFINITY,
        y: f64::NEG_INFINITY,
    };
    for c in &r.cells {
        lo = Coord {
            x: lo.x.min(c.bbox.min().x),
            y: lo.y.min(c.bbox.min().y),
        };
        hi = Coord {
            x: hi.x.max(c.bbox.max().x),
            y: hi.y.max(c.bbox.max().y),
        };
    }
    if lo.x > hi.x {
        return geo::Rect::new(Coord { x: 0.0, y: 0.0 }, Coord { x: 0.0, y: 0.0 });
    }
    geo::Rect::new(lo, hi)
}

/// Corners of a cell toward which sample points are taken, at most.
const SAMPLE_CORNERS: usize = 6;

/// Heights, as fractions of a block's span, at which it is sampled.
const SAMPLE_HEIGHTS: [f64; 3] = [0.25, 0.5, 0.75];

/// Points inside block `bi` of `r`, world coordinates: over its cell's
/// interior point and half-way from it to some of the cell's corners
/// (those inside the cell), at a quarter, half and three quarters of the
/// block's height there. Empty for a block of no thickness.
pub fn samples(r: &Removal, bi: usize) -> Vec<Point3> {
    let b = &r.blocks[bi];
    let cell = &r.cells[b.cell];
    let Some(centre) = geo::InteriorPoint::interior_point(&cell.poly) else {
        return Vec::new();
    };
    let corners = &cell.poly.exterior().0;
    let every = (corners.len() / SAMPLE_CORNERS).max(1);
    let mut columns = vec![centre];
    for v in corners.iter().step_by(every) {
        let p = Point::new(0.5 * (v.x + centre.x()), 0.5 * (v.y + centre.y()));
        if cell.poly.intersects(&p) {
            columns.push(p);
        }
    }
    let tol = 1e-9 * r.size;
    let (lower, upper) = (r.height_of(&b.lower), r.height_of(&b.upper));
    let mut out = Vec::new();
    for c in columns {
        let (lo, hi) = (lower.at(c.x(), c.y()), upper.at(c.x(), c.y()));
        if hi - lo <= tol {
            continue;
        }
        for s in SAMPLE_HEIGHTS {
            let z = lo + s * (hi - lo);
            out.push(r.frame.to_world(&Vector3::new(c.x(), c.y(), z)));
        }
    }
    out
}
