//! Where a straight line comes within a distance of a convex polygon: the
//! one interval of its parameter (the polygon grown by a disk is convex), and
//! sets of such intervals on a line.

/// `[start, end]` along a line, mm.
pub type Span = (f64, f64);

/// The parameters `s` where `q0 + s·e` (`e` unit) lies closer than `rho` to
/// the convex polygon `pts` (its corners in order, or a segment, or a point).
/// The polygon grown by the disk is convex, so this is one interval: from
/// the first to the last parameter within `rho` of its outline (where the
/// line crosses the inside, it crosses the outline first). Computed in the
/// line's frame (along it, across it), corner disks and edge strips.
pub fn line_near_convex(q0: [f64; 2], e: [f64; 2], pts: &[[f64; 2]], rho: f64) -> Option<Span> {
    if rho <= 0.0 || pts.is_empty() {
        return None;
    }
    let local = |p: [f64; 2]| {
        let w = sub(p, q0);
        [dot(w, e), cross(e, w)]
    };
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    let mut add = |span: Option<Span>| {
        if let Some((a, b)) = span {
            if b > a {
                lo = lo.min(a);
                hi = hi.max(b);
            }
        }
    };
    let n = pts.len();
    for k in 0..n {
        let a = local(pts[k]);
        // The corner's disk.
        let d2 = rho * rho - a[1] * a[1];
        if d2 > 0.0 {
            let h = d2.sqrt();
            add(Some((a[0] - h, a[0] + h)));
        }
        if n > 1 {
            add(strip(a, local(pts[(k + 1) % n]), rho));
        }
    }
    (hi > lo).then_some((lo, hi))
}

/// Whether `q` lies closer than `rho` to the convex polygon `pts` (its
/// corners in order either way round, or a segment, or a point): inside
/// it, or within `rho` of its outline. [`line_near_convex`] for one point.
pub fn point_near_convex(q: [f64; 2], pts: &[[f64; 2]], rho: f64) -> bool {
    if rho <= 0.0 || pts.is_empty() {
        return false;
    }
    let n = pts.len();
    let (mut left, mut right) = (0, 0);
    let mut near2 = f64::INFINITY;
    for k in 0..n {
        let (a, b) = (pts[k], pts[(k + 1) % n]);
        let (d, w) = (sub(b, a), sub(q, a));
        let side = cross(d, w);
        if side > 0.0 {
            left += 1;
        } else if side < 0.0 {
            right += 1;
        }
        let len2 = dot(d, d);
        let t = if len2 > 0.0 {
            (dot(w, d) / len2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let off = [w[0] - t * d[0], w[1] - t * d[1]];
        near2 = near2.min(dot(off, off));
    }
    // Inside: on one side of every edge (a polygon shrunk to a point or a
    // segment by the clip has no inside).
    let inside = n >= 3 && (left == 0 || right == 0) && left + right > 0;
    inside || near2 < rho * rho
}

/// Where the axis (`across` = 0) passes within `rho` of segment `a`–`b`
/// between its ends, in the line's frame.
fn strip(a: [f64; 2], b: [f64; 2], rho: f64) -> Option<Span> {
    let d = sub(b, a);
    let len2 = dot(d, d);
    if len2 < 1e-300 {
        return None;
    }
    let len = len2.sqrt();
    // Between the ends: 0 < (x − a)·d < |d|², x = (s, 0).
    let between = slab(-dot(a, d), d[0], 0.0, len2);
    // Near the line: |d × (x − a)| < rho·|d|.
    let near = slab(d[1] * a[0] - d[0] * a[1], -d[1], -rho * len, rho * len);
    meet(between, near)
}

fn sub(a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
    [a[0] - b[0], a[1] - b[1]]
}

fn dot(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}

fn cross(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}

/// `lo < a + s·b < hi` as an interval of `s` (all or none when `b` is 0).
fn slab(a: f64, b: f64, lo: f64, hi: f64) -> Option<Span> {
    if b.abs() < 1e-300 {
        return (a > lo && a < hi).then_some((f64::NEG_INFINITY, f64::INFINITY));
    }
    let (s1, s2) = ((lo - a) / b, (hi - a) / b);
    Some((s1.min(s2), s1.max(s2)))
}

fn meet(x: Option<Span>, y: Option<Span>) -> Option<Span> {
    let (x, y) = (x?, y?);
    let (a, b) = (x.0.max(y.0), x.1.min(y.1));
    (b > a).then_some((a, b))
}

/// Sorted, disjoint spans from any.
pub fn merge(mut spans: Vec<Span>) -> Vec<Span> {
    spans.retain(|s| s.1 > s.0);
    // The union is the same whichever of equal starts comes first.
    spans.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
    let mut out: Vec<Span> = Vec::with_capacity(spans.len());
    for s in spans {
        match out.last_mut() {
            Some(last) if s.0 <= last.1 => last.1 = last.1.max(s.1),
            _ => out.push(s),
        }
    }
    out
}

/// `a` (sorted, disjoint) without `b` (sorted, disjoint).
pub fn subtract(a: &[Span], b: &[Span]) -> Vec<Span> {
    let mut out = Vec::new();
    for &(mut s, e) in a {
        for &(bs, be) in b {
            if be <= s || bs >= e {
                continue;
            }
            if bs > s {
                out.push((s, bs));
            }
            s = s.max(be);
            if s >= e {
                break;
            }
        }
        if s < e {
            out.push((s, e));
        }
    }
    out
}

/// `a ∩ b` (both sorted, disjoint).
pub fn intersect(a: &[Span], b: &[Span]) -> Vec<Span> {
    let mut out = Vec::new();
    for &(s, e) in a {
        for &(bs, be) in b {
            let (x, y) = (s.max(bs), e.min(be));
            if y > x {
                out.push((x, y));
            }
        }
    }
    merge(out)
}

/// The length of `a ∩ b` (both sorted, disjoint).
pub fn overlap(a: &[Span], b: &[Span]) -> f64 {
    let (mut i, mut j, mut sum) = (0, 0, 0.0);
    while i < a.len() && j < b.len() {
        let (x, y) = (a[i].0.max(b[j].0), a[i].1.min(b[j].1));
        if y > x {
            sum += y - x;
        }
        if a[i].1 < b[j].1 {
            i += 1;
        } else {
            j += 1;
        }
    }
    sum
}

pub fn length(a: &[Span]) -> f64 {
    a.iter().map(|s| s.1 - s.0).sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_square_grown_by_a_disk() {
        let sq = [[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]];
        // Through the middle: the square and 2 on each side.
        let s = line_near_convex([-50.0, 5.0], [1.0, 0.0], &sq, 2.0).unwrap();
        assert!((s.0 - 48.0).abs() < 1e-12 && (s.1 - 62.0).abs() < 1e-12);
        // Past a corner at 1 below the bottom edge: the strip.
        let s = line_near_convex([-50.0, -1.0], [1.0, 0.0], &sq, 2.0).unwrap();
        assert!((s.0 - (50.0 - 3f64.sqrt())).abs() < 1e-12);
        assert!((s.1 - (60.0 + 3f64.sqrt())).abs() < 1e-12);
        assert!(line_near_convex([-50.0, -2.5], [1.0, 0.0], &sq, 2.0).is_none());
        // A segment (a wall seen from above) and a point.
        let seg = [[0.0, 0.0], [0.0, 10.0]];
        let s = line_near_convex([-5.0, 5.0], [1.0, 0.0], &seg, 1.0).unwrap();
        assert!((s.0 - 4.0).abs() < 1e-12 && (s.1 - 6.0).abs() < 1e-12);
        let s = line_near_convex([0.0, 0.0], [0.0, 1.0], &[[3.0, 4.0]], 5.0).unwrap();
        assert!(s.0.abs() < 1e-12 && (s.1 - 8.0).abs() < 1e-12);
    }

    #[test]
    fn span_sets() {
        let a = merge(vec![(0.0, 2.0), (1.0, 3.0), (5.0, 6.0)]);
        assert_eq!(a, vec![(0.0, 3.0), (5.0, 6.0)]);
        let d = subtract(&a, &[(1.0, 2.0), (5.5, 9.0)]);
        assert_eq!(d, vec![(0.0, 1.0), (2.0, 3.0), (5.0, 5.5)]);
        assert_eq!(length(&d), 2.5);
        assert_eq!(intersect(&a, &[(2.0, 5.5)]), vec![(2.0, 3.0), (5.0, 5.5)]);
        assert_eq!(overlap(&a, &[(2.0, 5.5)]), 1.5);
        assert_eq!(overlap(&[(0.0, 10.0)], &a), 4.0);
        assert_eq!(overlap(&a, &[]), 0.0);
    }

    /// The point test agrees with the line's span at the point (lo < 0 <
    /// hi), away from ties, on random triangles, clipped shapes and
    /// segments either way round.
    #[test]
    fn the_point_test_is_the_line_at_one_point() {
        let mut seed = 7u64;
        let mut rnd = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((seed >> 11) as f64 / (1u64 << 53) as f64) * 20.0 - 10.0
        };
        let mut checked = 0;
        for n in [1usize, 2, 3, 3, 4] {
            for _ in 0..4000 {
                let mut pts: Vec<[f64; 2]> = (0..n).map(|_| [rnd(), rnd()]).collect();
                if n == 4 {
                    // A convex quadrilateral: a square turned and moved.
                    let (c, s, x, y) = (rnd() / 10.0, rnd() / 10.0, rnd(), rnd());
                    pts = [[0.0, 0.0], [3.0, 0.0], [3.0, 2.0], [0.0, 2.0]]
                        .map(|p| [x + c * p[0] - s * p[1], y + s * p[0] + c * p[1]])
                        .to_vec();
                }
                let (q, rho) = ([rnd(), rnd()], rnd().abs() / 2.0);
                let e = [1.0, 0.0];
                let span = line_near_convex(q, e, &pts, rho);
                let by_line = span.is_some_and(|(a, b)| a < 0.0 && b > 0.0);
                let tie = span.is_some_and(|(a, b)| a.abs() < 1e-9 || b.abs() < 1e-9);
                if !tie {
                    assert_eq!(
                        point_near_convex(q, &pts, rho),
                        by_line,
                        "{pts:?} {q:?} {rho}"
                    );
                    checked += 1;
                }
            }
        }
        assert!(checked > 19_000);
        // A triangle meeting a slab at one corner clips to that point thrice.
        let dot3 = [[5.0, 1.0]; 3];
        assert!(!point_near_convex([0.0, 0.0], &dot3, 3.0));
        assert!(point_near_convex([3.0, 0.0], &dot3, 3.0));
    }
}
