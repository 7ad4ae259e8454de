//! Whether a face's triangles of one facing fold over themselves: where
//! two of them overlap in projection, how far apart they stand there.
//!
//! Triangles along a silhouette, standing near vertical, overlap their
//! neighbours by slivers at one height (the tessellation's noise); a face
//! that curls over itself overlaps in layers. The volume between the
//! layers over the overlaps tells them apart.

use rstar::{primitives::GeomWithData, primitives::Rectangle, RTree, AABB};

/// The volume between layers where pairs of triangles overlap in
/// projection (`∑ area × |Δz|`, each overlap's heights taken at its
/// centroid), mm³: `(slivers, folds)`, the overlaps no wider than `narrow`
/// (mm, by twice area over perimeter) apart from the wider ones.
pub fn layered_volume(tris: &[[[f64; 3]; 3]], narrow: f64) -> (f64, f64) {
    let boxes: Vec<GeomWithData<Rectangle<[f64; 2]>, usize>> = tris
        .iter()
        .enumerate()
        .map(|(k, t)| {
            let (lo, hi) = flat_box(t);
            GeomWithData::new(Rectangle::from_corners(lo, hi), k)
        })
        .collect();
    let tree = RTree::bulk_load(boxes);
    let (mut slivers, mut folds) = (0.0, 0.0);
    for (i, t) in tris.iter().enumerate() {
        let (lo, hi) = flat_box(t);
        for other in tree.locate_in_envelope_intersecting(&AABB::from_corners(lo, hi)) {
            let j = other.data;
            if j <= i {
                continue;
            }
            let common = clip(&ccw(t), &ccw(&tris[j]));
            let (area, c) = area_centroid(&common);
            if area <= 0.0 {
                continue;
            }
            let volume = area * (height(t, c) - height(&tris[j], c)).abs();
            if 2.0 * area <= narrow * perimeter(&common) {
                slivers += volume;
            } else {
                folds += volume;
            }
        }
    }
    (slivers, folds)
}

fn perimeter(poly: &[[f64; 2]]) -> f64 {
    (0..poly.len())
        .map(|k| {
            let (p, q) = (poly[k], poly[(k + 1) % poly.len()]);
            (q[0] - p[0]).hypot(q[1] - p[1])
        })
        .sum()
}

/// A triangle's own area (not its projection's), mm².
pub fn area(t: &[[f64; 3]; 3]) -> f64 {
    let n = crate::facets::normal(t);
    0.5 * n[0].hypot(n[1]).hypot(n[2])
}

/// A triangle's projection's area, mm².
pub fn flat_area(t: &[[f64; 3]; 3]) -> f64 {
    let [a, b, c] = *t;
    0.5 * cross([a[0], a[1]], [b[0], b[1]], [c[0], c[1]]).abs()
}

fn flat_box(t: &[[f64; 3]; 3]) -> ([f64; 2], [f64; 2]) {
    let lo = [0, 1].map(|k| t.iter().map(|p| p[k]).fold(f64::INFINITY, f64::min));
    let hi = [0, 1].map(|k| t.iter().map(|p| p[k]).fold(f64::NEG_INFINITY, f64::max));
    (lo, hi)
}

/// A triangle's projection, counter-clockwise.
fn ccw(t: &[[f64; 3]; 3]) -> Vec<[f64; 2]> {
    let mut p: Vec<[f64; 2]> = t.iter().map(|q| [q[0], q[1]]).collect();
    if cross(p[0], p[1], p[2]) < 0.0 {
        p.swap(1, 2);
    }
    p
}

fn cross(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

/// The part of convex polygon `subject` inside convex counter-clockwise
/// polygon `by` (Sutherland–Hodgman).
fn clip(subject: &[[f64; 2]], by: &[[f64; 2]]) -> Vec<[f64; 2]> {
    let mut out = subject.to_vec();
    for k in 0..by.len() {
        let (a, b) = (by[k], by[(k + 1) % by.len()]);
        let input = std::mem::take(&mut out);
        for m in 0..input.len() {
            let (p, q) = (input[m], input[(m + 1) % input.len()]);
            let (sp, sq) = (cross(a, b, p), cross(a, b, q));
            if sp >= 0.0 {
                out.push(p);
            }
            if (sp >= 0.0) != (sq >= 0.0) {
                let s = sp / (sp - sq);
                out.push([p[0] + (q[0] - p[0]) * s, p[1] + (q[1] - p[1]) * s]);
            }
        }
        if out.is_empty() {
            break;
        }
    }
    out
}

fn area_centroid(poly: &[[f64; 2]]) -> (f64, [f64; 2]) {
    let (a, mx, my) = crate::clip::moments(poly);
    if a.abs() < 0.5e-300 {
        return (0.0, [0.0, 0.0]);
    }
    (a.abs(), [mx / a, my / a])
}

/// The height of a triangle's plane over point `c`.
fn height(t: &[[f64; 3]; 3], c: [f64; 2]) -> f64 {
    let (a, n) = (t[0], crate::facets::normal(t));
    if n[2].abs() < 1e-300 {
        return a[2];
    }
    a[2] - (n[0] * (c[0] - a[0]) + n[1] * (c[1] - a[1])) / n[2]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn layers_apart_hold_volume_and_neighbours_hold_none() {
        // Two triangles sharing an edge: no overlap.
        let a = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
        let b = [[1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]];
        assert_eq!(layered_volume(&[a, b], 0.01), (0.0, 0.0));
        // The same triangle 2 above: its whole area (0.5) twice apart, a
        // fold (it is wider than 0.01).
        let up = a.map(|p| [p[0], p[1], p[2] + 2.0]);
        let (slivers, folds) = layered_volume(&[a, up], 0.01);
        assert!(slivers == 0.0 && (folds - 1.0).abs() < 1e-12);
        // Shifted by half its width: they share a triangle of area 1/8,
        // 3 apart.
        let shifted = a.map(|p| [p[0] + 0.5, p[1], p[2] + 3.0]);
        assert!((layered_volume(&[a, shifted], 0.01).1 - 3.0 / 8.0).abs() < 1e-12);
        // Shifted by all but 0.001 of its width: a sliver.
        let sliver = a.map(|p| [p[0] + 0.999, p[1], p[2] + 3.0]);
        let (slivers, folds) = layered_volume(&[a, sliver], 0.01);
        assert!(
            folds == 0.0 && slivers > 0.0 && slivers < 3.0 * 0.001,
            "{slivers}"
        );
    }
}
