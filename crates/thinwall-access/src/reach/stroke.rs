//! Polylines grown by the tool's disk, in one boolean: the union of every
//! edge's capsule (the edge grown by the disk), as the region that the
//! convolution of the polyline with the disk winds around positively
//! (Guibas, Ramshaw & Stolfi's convolution; Wein, "Exact and efficient
//! construction of planar Minkowski sums using the convolution method",
//! 2006). A chain is walked there and back, so it encloses nothing of its
//! own; at each corner the disk's corners between the two edges' outward
//! normals are inserted, forwards where the walk turns left (and at the
//! turn-arounds: the caps), backwards where it turns right.
//!
//! Why it is the capsules' union: the capsules' outlines, added up, are
//! the convolution plus one whole disk outline round every inner corner of
//! the chain (at a corner turning by θ the two capsules' half-disks make
//! the convolution's arc of θ forwards, its arc of θ backwards, and one
//! full turn). So a point's winding number is the number of capsules that
//! hold it less the number of corner disks that do; a corner's disk lies
//! in both capsules beside it, so along each run of capsules holding the
//! point there is one corner fewer than capsules: the number is at least 1
//! inside the union and 0 outside. The walk must turn the way the corner
//! does: a corner straight within rounding takes the short way round the
//! disk (a wrong way round is a whole disk wound negatively).
//!
//! Its outline has the disk's corners only where the chain turns, where
//! the capsules' union took a disk's corners per edge: on a contour
//! meshed finely along an arc, hundreds of capsules overlapping deeply,
//! the booleans' slowest input. The region is the same point set; the
//! booleans round it alike (areas equal to about 1e-12 relative).

use geo::MultiPolygon;
use thinwall_analysis::boolean::positive_region;

/// The `chains` (open polylines; a closed ring repeats its first corner at
/// its end) grown by `disk` (convex, counter-clockwise, around the
/// origin, as [`super::disk::disk`] makes it).
pub fn stroked(chains: &[Vec<[f64; 2]>], disk: &[[f64; 2]]) -> MultiPolygon<f64> {
    if disk.len() < 3 {
        return MultiPolygon::new(vec![]);
    }
    let cycles: Vec<Vec<[f64; 2]>> = chains
        .iter()
        .map(|c| there_and_back(c))
        .filter(|c| !c.is_empty())
        .map(|c| convolution(&c, disk))
        .collect();
    positive_region(cycles)
}

/// The chain's corners (repeats dropped) and its inner corners back.
fn there_and_back(chain: &[[f64; 2]]) -> Vec<[f64; 2]> {
    let mut pts: Vec<[f64; 2]> = Vec::with_capacity(2 * chain.len());
    for p in chain {
        if pts.last() != Some(p) {
            pts.push(*p);
        }
    }
    let n = pts.len();
    for k in (1..n.saturating_sub(1)).rev() {
        pts.push(pts[k]);
    }
    pts
}

fn sub(a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
    [a[0] - b[0], a[1] - b[1]]
}

fn add(a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
    [a[0] + b[0], a[1] + b[1]]
}

/// The convolution of the closed walk `cycle` with `disk`: each edge
/// moved by the disk's corner farthest along the edge's outward (right)
/// normal, joined at each corner by the disk's corners between, walked
/// the way the corner turns (forwards at a turn-around: a cap).
fn convolution(cycle: &[[f64; 2]], disk: &[[f64; 2]]) -> Vec<[f64; 2]> {
    let (n, m) = (cycle.len(), disk.len());
    if n == 1 {
        return disk.iter().map(|&q| add(cycle[0], q)).collect();
    }
    let edge = |i: usize| sub(cycle[(i + 1) % n], cycle[i % n]);
    let normal = |e: [f64; 2]| [e[1], -e[0]];
    let dot = |k: usize, v: [f64; 2]| disk[k % m][0] * v[0] + disk[k % m][1] * v[1];
    // The farthest corner along `v`, climbing from corner `j` (the disk
    // is convex: one hill; from its foot, forwards).
    let farthest = |mut j: usize, v: [f64; 2]| {
        while dot(j + 1, v) > dot(j, v) {
            j = (j + 1) % m;
        }
        while dot(j + m - 1, v) > dot(j, v) {
            j = (j + m - 1) % m;
        }
        j
    };
    let mut j = farthest(0, normal(edge(0)));
    let mut out = Vec::with_capacity(2 * n + m);
    for i in 0..n {
        let q = cycle[(i + 1) % n];
        out.push(add(q, disk[j]));
        let (e_in, e_out) = (edge(i), edge(i + 1));
        let k = farthest(j, normal(e_out));
        let ahead = (k + m - j) % m;
        if ahead == 0 {
            continue;
        }
        let cross = e_in[0] * e_out[1] - e_in[1] * e_out[0];
        let along = e_in[0] * e_out[0] + e_in[1] * e_out[1];
        // The way the corner turns; where that would go more than half
        // round to a corner a step or two the other way, the turn is
        // straight within rounding: the short way.
        let forwards = if cross > 0.0 || (cross == 0.0 && along < 0.0) {
            ahead <= m / 2 + 1
        } else {
            ahead < m / 2 - 1
        };
        let step = if forwards { 1 } else { m - 1 };
        while j != k {
            j = (j + step) % m;
            out.push(add(q, disk[j]));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::super::disk::{disk, grown};
    use super::*;
    use geo::{Area, MultiPolygon};
    use thinwall_analysis::boolean::{difference, union_all};

    fn capsules(chains: &[Vec<[f64; 2]>], d: &[[f64; 2]]) -> MultiPolygon<f64> {
        let mut parts = Vec::new();
        for c in chains {
            if c.len() == 1 {
                parts.extend(grown(c, d).map(|p| MultiPolygon::new(vec![p])));
            }
            for w in c.windows(2) {
                parts.extend(grown(w, d).map(|p| MultiPolygon::new(vec![p])));
            }
        }
        union_all(parts)
    }

    /// Random chains (open, closed, spiky, dense arcs either way, single
    /// points, repeated corners) grown by disks from much smaller to much
    /// larger than their edges: the same region as the capsules' union
    /// (areas within 1e-9, each less the other within 1e-9 of the area).
    #[test]
    fn a_stroke_is_the_union_of_its_capsules() {
        let mut next = super::super::tests::uniform(0x9e37_79b9_7f4a_7c15_u64);
        for trial in 0..120 {
            let r = 0.05 + 6.0 * next() * next();
            let d = disk(r);
            let mut chains = Vec::new();
            for _ in 0..1 + trial % 3 {
                let c: Vec<[f64; 2]> = match trial % 5 {
                    0 => (0..2 + (next() * 8.0) as usize)
                        .map(|_| [20.0 * next(), 20.0 * next()])
                        .collect(),
                    1 | 2 => {
                        // An arc, finely meshed, either way round.
                        let (cx, cy, rad) = (10.0 * next(), 10.0 * next(), 0.5 + 8.0 * next());
                        let (a0, span) = (6.3 * next(), 6.0 * next() - 3.0);
                        let k = 5 + (next() * 150.0) as usize;
                        (0..=k)
                            .map(|i| {
                                let t = a0 + span * i as f64 / k as f64;
                                [cx + rad * t.cos(), cy + rad * t.sin()]
                            })
                            .collect()
                    }
                    3 => {
                        let mut ring: Vec<[f64; 2]> = (0..3 + (next() * 10.0) as usize)
                            .map(|_| [20.0 * next(), 20.0 * next()])
                            .collect();
                        ring.push(ring[0]);
                        ring
                    }
                    _ => {
                        // Axis-aligned with repeats and turn-arounds.
                        let mut p = [0.0, 0.0];
                        let mut c = vec![p];
                        for _ in 0..6 {
                            let k = (next() * 4.0) as usize;
                            let len = if next() < 0.2 { 0.0 } else { 5.0 * next() };
                            p[k % 2] += if k < 2 { len } else { -len };
                            c.push(p);
                        }
                        c
                    }
                };
                chains.push(c);
            }
            if trial % 17 == 0 {
                chains.push(vec![[3.0, 3.0]]);
            }
            let want = capsules(&chains, &d);
            let got = stroked(&chains, &d);
            let a = want.unsigned_area();
            let tol = 1e-9 * a.max(1.0);
            assert!(
                (got.unsigned_area() - a).abs() <= tol,
                "{trial}: {} vs {a}",
                got.unsigned_area()
            );
            assert!(difference(&want, &got).unsigned_area() <= tol, "{trial}");
            assert!(difference(&got, &want).unsigned_area() <= tol, "{trial}");
        }
    }

    /// Chains meshed along a line whose normal lies half-way between two
    /// of the disk's corners, their corners jittered by rounding: a corner
    /// that turns right by 1e-17 may find its farthest disk corner one
    /// step forwards. Walking the way it turns then went all round the
    /// disk (a disk wound negatively: 4 % of an opened floor lost on a
    /// shared thin-walled panel); the short way is right.
    #[test]
    fn a_straight_corner_within_rounding_takes_the_short_way() {
        let mut next = super::super::tests::uniform(0x1234_5678_9abc_def1_u64);
        let d = disk(4.0);
        for k in 0..128 {
            // Normal at the bisector of corners k and k + 1: the line runs
            // a quarter turn on.
            let t = std::f64::consts::TAU * (k as f64 + 0.5) / 128.0 + std::f64::consts::FRAC_PI_2;
            let u = [t.cos(), t.sin()];
            let mut along = 0.0;
            let chain: Vec<[f64; 2]> = (0..40)
                .map(|_| {
                    along += 0.01 + 0.2 * next();
                    let jitter = 1e-15 * (next() - 0.5);
                    [along * u[0] - jitter * u[1], along * u[1] + jitter * u[0]]
                })
                .collect();
            let chains = vec![chain];
            let want = capsules(&chains, &d);
            let got = stroked(&chains, &d);
            let a = want.unsigned_area();
            assert!(
                (got.unsigned_area() - a).abs() <= 1e-9 * a,
                "{k}: {} vs {a}",
                got.unsigned_area()
            );
        }
    }
}
