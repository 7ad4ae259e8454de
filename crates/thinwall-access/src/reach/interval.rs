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
    spans.sort_by(|a, b| a.0.total_cmp(&b.0));
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
    }
}
