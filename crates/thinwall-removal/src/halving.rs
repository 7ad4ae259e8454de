//! Cutting large work small: a region's corners counted, and a box
//! halved along its longer side (the meshed faces' many-cornered regions
//! are cut over such halves, in the arrangement and in the flux).

use geo::{Coord, MultiPolygon, Rect};

/// How many corners a region's rings have.
pub(crate) fn corners(m: &MultiPolygon<f64>) -> usize {
    m.iter()
        .map(|p| p.exterior().0.len() + p.interiors().iter().map(|r| r.0.len()).sum::<usize>())
        .sum()
}

/// The two halves of a box, across its longer side.
pub(crate) fn halves(rect: &Rect<f64>) -> [Rect<f64>; 2] {
    let (lo, hi) = (rect.min(), rect.max());
    if hi.x - lo.x >= hi.y - lo.y {
        let mid = 0.5 * (lo.x + hi.x);
        [
            Rect::new(lo, Coord { x: mid, y: hi.y }),
            Rect::new(Coord { x: mid, y: lo.y }, hi),
        ]
    } else {
        let mid = 0.5 * (lo.y + hi.y);
        [
            Rect::new(lo, Coord { x: hi.x, y: mid }),
            Rect::new(Coord { x: lo.x, y: mid }, hi),
        ]
    }
}
