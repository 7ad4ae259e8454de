//! Reach of a planar face the tool meets with its side or the corner of its
//! end (a wall side, an inclined face): the tool touching a point has its
//! tip at the point's height and its axis one radius out along the face's
//! level normal, so along each level line of the face the tool's positions
//! form a line, and what stops it there is a set of exact intervals. The
//! reachable area is integrated over the face's height, band by band
//! between the heights where what stops the tool can change (corners of the
//! obstacles, and those corners less the cutting length): within a band the
//! reached length is smooth, and three Gauss–Legendre lines integrate it (a
//! constant or linear length exactly).

use super::interval::{intersect, length, merge, subtract, Span};
use super::scene::{blocked, Block};
use super::{Ctx, Judged};
use geo::{Area, BoundingRect, MultiPolygon};
use thinwall_analysis::PlanarFace;
use thinwall_geom::{Frame, Vector3};

/// Bands per face, at most (a curved neighbour has many corner heights).
const MAX_BANDS: usize = 200;

/// Gauss–Legendre nodes and weights on [−1, 1] (three points); the middle
/// one draws the unreachable region.
const GAUSS: [(f64, f64); 3] = [
    (-0.774_596_669_241_483_4, 5.0 / 9.0),
    (0.0, 8.0 / 9.0),
    (0.774_596_669_241_483_4, 5.0 / 9.0),
];

pub fn judge(ctx: &Ctx, scene: &super::scene::Scene, pf: &PlanarFace, own: u32) -> Judged {
    judge_within(ctx, scene, pf, own, f64::INFINITY)
}

/// As [`judge`], but stopping (`cut_short`) after the first band that
/// brings the area lost above the share `lost_share` of the face's.
pub fn judge_within(
    ctx: &Ctx,
    scene: &super::scene::Scene,
    pf: &PlanarFace,
    own: u32,
    lost_share: f64,
) -> Judged {
    let axis = scene.frame.z;
    let n = pf.normal();
    let e = axis.cross(&n).normalize();
    let y = n.cross(&e);
    let level: Vector3 = (n - axis * n.dot(&axis)).normalize();
    let rise = y.dot(&axis);
    let frame = Frame {
        origin: pf.frame.origin,
        x: e,
        y,
        z: n,
    };
    let region = pf.polygon_in(&frame);
    let mut out = Judged::default();
    let Some(rect) = region.bounding_rect() else {
        return out;
    };
    let budget = lost_share * region.unsigned_area();
    let tool = &ctx.tool;
    let r = 0.5 * tool.diameter;
    let reach = r + 0.5 * tool.holder_diameter;
    let z0 = scene.local(&frame.origin)[2];
    let (v0, v1) = (rect.min().y, rect.max().y);
    // The triangles that may stop the tool anywhere on the face.
    let corners = [
        (rect.min().x, v0),
        (rect.max().x, v0),
        (rect.max().x, v1),
        (rect.min().x, v1),
    ]
    .map(|(u, v)| {
        let p = frame.to_world(&Vector3::new(u, v, 0.0)) + level * r;
        scene.local(&p)
    });
    let lo = [
        corners.iter().map(|c| c[0]).fold(f64::INFINITY, f64::min) - reach,
        corners.iter().map(|c| c[1]).fold(f64::INFINITY, f64::min) - reach,
    ];
    let hi = [
        corners
            .iter()
            .map(|c| c[0])
            .fold(f64::NEG_INFINITY, f64::max)
            + reach,
        corners
            .iter()
            .map(|c| c[1])
            .fold(f64::NEG_INFINITY, f64::max)
            + reach,
    ];
    let zmin = z0 + v0 * rise + ctx.touch;
    let mut cands = scene.near(lo, hi, zmin);
    cands.retain(|&k| scene.tris[k as usize].face != own);
    let e_local = scene.local_vector(&e);
    let e2 = [e_local[0], e_local[1]];
    let norm = e2[0].hypot(e2[1]);
    let e2 = [e2[0] / norm, e2[1] / norm];
    // Keep the triangles within the holder's radius of the tool's line at
    // some height of the face (a corner's offset from the line changes
    // linearly with the height: the two ends bound it).
    let ends =
        [v0, v1].map(|v| scene.local(&(frame.to_world(&Vector3::new(0.0, v, 0.0)) + level * r)));
    let big = 0.5 * tool.holder_diameter;
    cands.retain(|&k| {
        let t = &scene.tris[k as usize];
        let offs = ends.iter().flat_map(|q| {
            t.p.iter()
                .map(move |p| e2[0] * (p[1] - q[1]) - e2[1] * (p[0] - q[0]))
        });
        let (lo, hi) = offs.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), d| {
            (a.min(d), b.max(d))
        });
        lo < big && hi > -big
    });
    // Highest first: a line skips the triangles below its tip at once.
    cands.sort_by(|&x, &y| scene.top(y).total_cmp(&scene.top(x)).then(x.cmp(&y)));
    let bands = bands(
        &region,
        scene,
        &cands,
        z0,
        rise,
        tool.cutting_length,
        (v0, v1),
    );
    let mut blocks: Vec<Block> = Vec::new();
    for w in bands.windows(2) {
        thinwall_analysis::parallel::check_deadline();
        if out.area - out.reached > budget {
            out.cut_short = true;
            return out;
        }
        let (va, vb) = (w[0], w[1]);
        let half = 0.5 * (vb - va);
        for (k, (x, wt)) in GAUSS.iter().enumerate() {
            let v = va + half * (1.0 + x);
            let face = row(&region, v);
            if face.is_empty() {
                continue;
            }
            let p = scene.local(&(frame.to_world(&Vector3::new(0.0, v, 0.0)) + level * r));
            // Only the triangles reaching above the tip (highest first).
            let above = cands.partition_point(|&k| scene.top(k) > p[2] + ctx.touch);
            blocks.clear();
            blocked(
                scene,
                &cands[..above],
                p,
                e2,
                tool,
                (ctx.touch, ctx.touch_tessellated()),
                &mut blocks,
            );
            let stop = merge(blocks.iter().map(|b| b.span).collect());
            let weight = wt * half;
            out.area += weight * length(&face);
            out.reached += weight * length(&subtract(&face, &stop));
            for b in &blocks {
                let lost = length(&intersect(&face, &[b.span]));
                if lost > 0.0 {
                    *out.blockers
                        .entry((b.tri_face(scene), b.holder))
                        .or_default() += weight * lost;
                }
            }
            if k == 1 {
                for (ua, ub) in intersect(&face, &stop) {
                    out.unreachable.push(
                        [(ua, va), (ub, va), (ub, vb), (ua, vb)]
                            .iter()
                            .map(|&(u, v)| frame.to_world(&Vector3::new(u, v, 0.0)).into())
                            .collect(),
                    );
                }
            }
        }
    }
    out
}

impl Block {
    fn tri_face(&self, scene: &super::scene::Scene) -> u32 {
        scene.tris[self.tri as usize].face
    }
}

/// The heights (as the face's `v`) where what the tool meets may change:
/// the face's corners, the obstacles' corners and those less the cutting
/// length; at most `MAX_BANDS` bands.
fn bands(
    region: &MultiPolygon<f64>,
    scene: &super::scene::Scene,
    cands: &[u32],
    z0: f64,
    rise: f64,
    cutting: f64,
    (v0, v1): (f64, f64),
) -> Vec<f64> {
    let mut vs: Vec<f64> = region
        .iter()
        .flat_map(|p| std::iter::once(p.exterior()).chain(p.interiors()))
        .flat_map(|ring| ring.coords().map(|c| c.y))
        .collect();
    for z in scene.heights(cands) {
        vs.push((z - z0) / rise);
        vs.push((z - cutting - z0) / rise);
    }
    vs.push(v0);
    vs.push(v1);
    vs.retain(|v| *v >= v0 && *v <= v1);
    vs.sort_by(f64::total_cmp);
    let span = (v1 - v0).max(1e-300);
    let min_gap = if vs.len() > MAX_BANDS {
        span / MAX_BANDS as f64
    } else {
        1e-9 * span
    };
    let mut out: Vec<f64> = Vec::with_capacity(vs.len().min(MAX_BANDS + 2));
    for v in vs {
        match out.last() {
            Some(&last) if v - last <= min_gap => {}
            _ => out.push(v),
        }
    }
    if out.last().is_some_and(|&l| l < v1) {
        out.push(v1);
    }
    out
}

/// The face's spans along its level line at height `v`.
pub fn row(region: &MultiPolygon<f64>, v: f64) -> Vec<Span> {
    let mut xs: Vec<f64> = Vec::new();
    for ring in region
        .iter()
        .flat_map(|p| std::iter::once(p.exterior()).chain(p.interiors()))
    {
        for l in ring.lines() {
            let (p, q) = (l.start, l.end);
            if (p.y <= v) != (q.y <= v) {
                xs.push(p.x + (v - p.y) * (q.x - p.x) / (q.y - p.y));
            }
        }
    }
    xs.sort_by(f64::total_cmp);
    merge(xs.chunks_exact(2).map(|c| (c[0], c[1])).collect())
}
