//! A block cut at given heights, exactly: where a bound is a sloped plane
//! or a half cylinder, the line where it crosses a cut height is straight
//! (a plane's level line; a cylinder's lines parallel to its axis), so the
//! block's cell is clipped by half-planes into the parts that lie above,
//! across and below the cut. A layer then holds exactly the material
//! between its two heights, beside a drafted wall or over a foot fillet
//! too. Cones (level lines are circles) keep their block whole: a cut
//! through one moves to the cone's end.

use super::pieces::Height;
use super::{Block, Bound, Removal};
use geo::{BooleanOps, BoundingRect, Coord, LineString, MultiPolygon, Polygon, Rect};

/// Material between two bounds over a region.
#[derive(Clone, Debug)]
pub struct Slice {
    pub region: MultiPolygon<f64>,
    pub lower: Bound,
    pub upper: Bound,
    pub volume: f64,
}

/// Where a height is below (or above) a level, within a box.
enum Side {
    All,
    Nothing,
    Convex(Vec<Polygon<f64>>),
}

/// The block cut at `cuts` (sorted); slices in order from the bottom. A
/// cut within `tol` of a bound's end is no cut.
pub fn cut(r: &Removal, b: &Block, cuts: &[f64], tol: f64) -> Vec<Slice> {
    let cell = &r.cells[b.cell];
    let (hl, hu) = (r.height_of(&b.lower), r.height_of(&b.upper));
    let (lo_r, hi_r) = (r.bound_range(&b.lower), r.bound_range(&b.upper));
    let exact = |h: &Height| {
        !matches!(
            h,
            Height::Cone { .. } | Height::Revolved { .. } | Height::Facets { .. }
        )
    };
    let cuts: Vec<f64> = cuts
        .iter()
        .copied()
        .filter(|&c| {
            let above_lower = c > if exact(&hl) { lo_r[0] } else { lo_r[1] } + tol;
            let below_upper = c < if exact(&hu) { hi_r[1] } else { hi_r[0] } - tol;
            above_lower && below_upper
        })
        .collect();
    let whole = MultiPolygon::new(vec![cell.poly.clone()]);
    if cuts.is_empty() {
        return vec![Slice {
            region: whole,
            lower: b.lower,
            upper: b.upper,
            volume: b.volume,
        }];
    }
    let bbox = grow(cell.bbox);
    let mut out = Vec::new();
    for i in 0..=cuts.len() {
        let below_c = i.checked_sub(1).map(|k| cuts[k]);
        let above_c = cuts.get(i).copied();
        // Lower end: the cut where the lower bound is under it, else the bound.
        let (under, over) = match below_c {
            None => (Side::Nothing, Side::All),
            Some(c) => (
                side_in(&hl, lo_r, c, bbox, true),
                side_in(&hl, lo_r, c, bbox, false),
            ),
        };
        // Upper end: the cut where the upper bound is over it, else the bound.
        let (u_under, u_over) = match above_c {
            None => (Side::All, Side::Nothing),
            Some(c) => (
                side_in(&hu, hi_r, c, bbox, true),
                side_in(&hu, hi_r, c, bbox, false),
            ),
        };
        let lower_cut = below_c.map(Bound::Flat);
        let upper_cut = above_c.map(Bound::Flat);
        let mut add = |sides: &[&Side], lower: Bound, upper: Bound| {
            let region = clip(&whole, sides);
            if region.0.is_empty() {
                return;
            }
            let volume = region
                .0
                .iter()
                .map(|p| {
                    super::flux::flux(&r.height_of(&upper), p)
                        - super::flux::flux(&r.height_of(&lower), p)
                })
                .sum();
            out.push(Slice {
                region,
                lower,
                upper,
                volume,
            });
        };
        let extra_u = below_c.map(|c| side_in(&hu, hi_r, c, bbox, false));
        let extra_l = above_c.map(|c| side_in(&hl, lo_r, c, bbox, true));
        let all = Side::All;
        if let (Some(lc), Some(uc)) = (lower_cut, upper_cut) {
            add(&[&under, &u_over], lc, uc);
        }
        if let Some(lc) = lower_cut {
            add(
                &[&under, &u_under, extra_u.as_ref().unwrap_or(&all)],
                lc,
                b.upper,
            );
        }
        if let Some(uc) = upper_cut {
            add(
                &[&over, &u_over, extra_l.as_ref().unwrap_or(&all)],
                b.lower,
                uc,
            );
        }
        add(&[&over, &u_under], b.lower, b.upper);
    }
    out
}

fn grow(r: Rect<f64>) -> Rect<f64> {
    let d = (r.width() + r.height()).max(1.0);
    Rect::new(
        Coord {
            x: r.min().x - d,
            y: r.min().y - d,
        },
        Coord {
            x: r.max().x + d,
            y: r.max().y + d,
        },
    )
}

/// `region` ∩ every side.
fn clip(region: &MultiPolygon<f64>, sides: &[&Side]) -> MultiPolygon<f64> {
    let mut out = region.clone();
    for s in sides {
        match s {
            Side::All => {}
            Side::Nothing => return MultiPolygon::new(vec![]),
            Side::Convex(ps) => {
                if ps.is_empty() {
                    return MultiPolygon::new(vec![]);
                }
                out = out.intersection(&MultiPolygon::new(ps.clone()));
            }
        }
        if out.0.is_empty() {
            break;
        }
    }
    out.0.retain(|p| super::flux::area(p) > 0.0);
    out
}

/// [`side`] of a bound whose heights lie in `range`: a cone, a surface of
/// revolution or facets (no straight level lines) is wholly below or
/// above a cut outside its range ([`cut`] moves any other cut to its
/// end), so the side is all or nothing there.
fn side_in(h: &Height, range: [f64; 2], c: f64, bbox: Rect<f64>, below: bool) -> Side {
    let whole = match h {
        Height::Cone { .. } | Height::Revolved { .. } | Height::Facets { .. } => {
            if c >= range[1] {
                Some(below)
            } else if c < range[0] {
                Some(!below)
            } else {
                None
            }
        }
        _ => None,
    };
    match whole {
        Some(true) => Side::All,
        Some(false) => Side::Nothing,
        None => side(h, c, bbox, below),
    }
}

/// Where `h ≤ c` (`below`) or `h > c` (not `below`), as convex pieces of
/// `bbox`.
fn side(h: &Height, c: f64, bbox: Rect<f64>, below: bool) -> Side {
    match *h {
        Height::Plane { z0, gx, gy, .. } => {
            if gx == 0.0 && gy == 0.0 {
                return if (z0 <= c) == below {
                    Side::All
                } else {
                    Side::Nothing
                };
            }
            // gx·x + gy·y ≤ c − z0
            let (a, b, k) = if below {
                (gx, gy, c - z0)
            } else {
                (-gx, -gy, z0 - c)
            };
            convex(vec![half(bbox, a, b, k)])
        }
        Height::Cylinder { o, a, r, sign } => {
            // u = −a.y (x − ox) + a.x (y − oy); u ≤ t ⟺ −a.y x + a.x y ≤ t + q.
            let q = -a[1] * o[0] + a[0] * o[1];
            let u_le = |t: f64| half(bbox, -a[1], a[0], t + q);
            let u_ge = |t: f64| half(bbox, a[1], -a[0], -t - q);
            let d = if sign > 0.0 { c - o[2] } else { o[2] - c };
            // sign +1: h ≤ c ⟺ √(r² − u²) ≤ d; sign −1: h ≤ c ⟺ √ ≥ d.
            let root_le = if d < 0.0 {
                Side::Nothing
            } else if d >= r {
                Side::All
            } else {
                let w = (r * r - d * d).sqrt();
                convex(vec![u_le(-w), u_ge(w)])
            };
            let root_ge = if d <= 0.0 {
                Side::All
            } else if d > r {
                Side::Nothing
            } else {
                let w = (r * r - d * d).sqrt();
                convex(vec![strip(&u_le(w), &u_ge(-w))])
            };
            match (sign > 0.0, below) {
                (true, true) | (false, false) => root_le,
                (true, false) | (false, true) => root_ge,
            }
        }
        Height::Cone { .. } | Height::Revolved { .. } | Height::Facets { .. } => Side::All,
    }
}

fn convex(ps: Vec<Polygon<f64>>) -> Side {
    Side::Convex(
        ps.into_iter()
            .filter(|p| super::flux::area(p) > 0.0)
            .collect(),
    )
}

/// The part of `bbox` where `a·x + b·y ≤ k` (Sutherland–Hodgman on its
/// four corners).
fn half(bbox: Rect<f64>, a: f64, b: f64, k: f64) -> Polygon<f64> {
    let pts: Vec<Coord<f64>> = bbox.to_polygon().exterior().0[..4].to_vec();
    Polygon::new(LineString::new(clip_ring(&pts, a, b, k)), vec![])
}

fn clip_ring(pts: &[Coord<f64>], a: f64, b: f64, k: f64) -> Vec<Coord<f64>> {
    let f = |p: &Coord<f64>| a * p.x + b * p.y - k;
    let mut out = Vec::new();
    for i in 0..pts.len() {
        let (p, q) = (pts[i], pts[(i + 1) % pts.len()]);
        let (fp, fq) = (f(&p), f(&q));
        if fp <= 0.0 {
            out.push(p);
        }
        if (fp < 0.0 && fq > 0.0) || (fp > 0.0 && fq < 0.0) {
            let t = fp / (fp - fq);
            out.push(Coord {
                x: p.x + (q.x - p.x) * t,
                y: p.y + (q.y - p.y) * t,
            });
        }
    }
    if let Some(&c) = out.first() {
        out.push(c);
    }
    out
}

/// The intersection of two convex polygons made by `half` (clip one's
/// ring by the other's edges).
fn strip(p: &Polygon<f64>, q: &Polygon<f64>) -> Polygon<f64> {
    let mut ring: Vec<Coord<f64>> = p.exterior().0.clone();
    ring.pop();
    let qs = &q.exterior().0;
    // q is counter-clockwise or clockwise: orient each edge's inside by
    // the mean of q's corners (inside a convex polygon).
    if qs.len() < 2 {
        return Polygon::new(LineString::new(vec![]), vec![]);
    }
    let corners = &qs[..qs.len() - 1];
    let cen = Coord {
        x: corners.iter().map(|c| c.x).sum::<f64>() / corners.len() as f64,
        y: corners.iter().map(|c| c.y).sum::<f64>() / corners.len() as f64,
    };
    for w in qs.windows(2) {
        let (s, e) = (w[0], w[1]);
        // Line through s, e: n·x ≤ n·s with n pointing away from the centre.
        let mut n = (e.y - s.y, -(e.x - s.x));
        if n.0 * (cen.x - s.x) + n.1 * (cen.y - s.y) > 0.0 {
            n = (-n.0, -n.1);
        }
        if ring.len() < 3 {
            break;
        }
        let mut r2 = clip_ring(&ring, n.0, n.1, n.0 * s.x + n.1 * s.y);
        r2.pop();
        ring = r2;
    }
    if let Some(&c) = ring.first() {
        ring.push(c);
    }
    Polygon::new(LineString::new(ring), vec![])
}

/// The block's cross-section at height `z`: where its lower bound lies at
/// or below `z` and its upper bound above it (exact for planes and
/// cylinders; a cone's bound counts as crossing its whole cell, as in
/// [`cut`]).
pub fn section(r: &Removal, b: &Block, z: f64) -> MultiPolygon<f64> {
    let cell = &r.cells[b.cell];
    let (lo_r, hi_r) = (r.bound_range(&b.lower), r.bound_range(&b.upper));
    if z < lo_r[0] || z >= hi_r[1] {
        return MultiPolygon::new(vec![]);
    }
    let (hl, hu) = (r.height_of(&b.lower), r.height_of(&b.upper));
    let whole = MultiPolygon::new(vec![cell.poly.clone()]);
    between(&whole, &hl, &hu, z)
}

/// Where `region` lies between the heights `lower` (at or below `z`) and
/// `upper` (above it): the cross-section at `z` of the solid they bound
/// over it (a machining feature's solid), exact for planes and cylinders.
pub fn between(
    region: &MultiPolygon<f64>,
    lower: &Height,
    upper: &Height,
    z: f64,
) -> MultiPolygon<f64> {
    let Some(bbox) = region.bounding_rect() else {
        return MultiPolygon::new(vec![]);
    };
    let bbox = grow(bbox);
    clip(
        region,
        &[&side(lower, z, bbox, true), &side(upper, z, bbox, false)],
    )
}
