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

use super::interval::{intersect, length, merge, overlap, subtract, Span};
use super::scene::{blocked, Block};
use super::standing::{by_key, merge_sorted, Key, Standing};
use super::{xy_bounds, Ctx, Judged};
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
    judge_lines(ctx, scene, pf, own, lost_share, true)
}

/// As [`judge`], every obstacle clipped at every line, a standing face's
/// too ([`Standing`] not used): the reference its shortcut must equal.
pub fn judge_clipped(ctx: &Ctx, scene: &super::scene::Scene, pf: &PlanarFace, own: u32) -> Judged {
    judge_lines(ctx, scene, pf, own, f64::INFINITY, false)
}

/// Whether the face stands along the scene's axis, so [`judge`] takes its
/// obstacles' whole spans from [`Standing`].
pub fn stands(ctx: &Ctx, scene: &super::scene::Scene, pf: &PlanarFace) -> bool {
    let side = SideFrame::new(ctx, scene, pf);
    pf.polygon_in(&side.frame)
        .bounding_rect()
        .is_some_and(|r| side.stands(ctx, scene, (r.min().y, r.max().y)))
}

fn judge_lines(
    ctx: &Ctx,
    scene: &super::scene::Scene,
    pf: &PlanarFace,
    own: u32,
    lost_share: f64,
    shortcut: bool,
) -> Judged {
    let side = SideFrame::new(ctx, scene, pf);
    let region = pf.polygon_in(&side.frame);
    let mut out = Judged::default();
    let Some(rect) = region.bounding_rect() else {
        return out;
    };
    let budget = lost_share * region.unsigned_area();
    let (v0, v1) = (rect.min().y, rect.max().y);
    let cands = side.candidates(ctx, scene, own, &rect);
    let standing = shortcut
        .then(|| side.standing(ctx, scene, &cands, (v0, v1)))
        .flatten();
    let obstacles = Obstacles {
        cands: &cands,
        standing: standing.as_ref(),
    };
    let bands = bands(
        &region,
        scene,
        &cands,
        side.z0,
        side.rise,
        ctx.tool.cutting_length,
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
            let line = Line {
                face: &face,
                v,
                weight: wt * half,
            };
            let stop = side.integrate(ctx, scene, &obstacles, &line, &mut blocks, &mut out);
            if k == 1 {
                for (ua, ub) in intersect(&face, &stop) {
                    out.unreachable.push(
                        [(ua, va), (ub, va), (ub, vb), (ua, vb)]
                            .iter()
                            .map(|&(u, v)| side.frame.to_world(&Vector3::new(u, v, 0.0)).into())
                            .collect(),
                    );
                }
            }
        }
    }
    out
}

/// A planar face seen from the side: its frame (x level along the face,
/// z its normal), the level normal the tool's axis sits out along, how the
/// face rises with its `v`, and the level direction in the scene.
struct SideFrame {
    frame: Frame,
    level: Vector3,
    rise: f64,
    /// The frame's x in the scene's plane, unit.
    e2: [f64; 2],
    /// The tool's radius, mm.
    r: f64,
    /// The frame's origin's height in the scene, mm.
    z0: f64,
}

/// The triangles that may stop the tool on a face, highest first, and
/// where the face stands along the axis, the spans each blocks whole.
struct Obstacles<'a> {
    cands: &'a [u32],
    standing: Option<&'a Standing>,
}

/// One level line of the face: its spans, its `v` and its quadrature weight.
struct Line<'a> {
    face: &'a [Span],
    v: f64,
    weight: f64,
}

impl SideFrame {
    fn new(ctx: &Ctx, scene: &super::scene::Scene, pf: &PlanarFace) -> Self {
        let axis = scene.frame.z;
        let n = pf.normal();
        let e = axis.cross(&n).normalize();
        let y = n.cross(&e);
        let frame = Frame {
            origin: pf.frame.origin,
            x: e,
            y,
            z: n,
        };
        let e_local = scene.local_vector(&e);
        let norm = e_local[0].hypot(e_local[1]);
        Self {
            level: (n - axis * n.dot(&axis)).normalize(),
            rise: y.dot(&axis),
            e2: [e_local[0] / norm, e_local[1] / norm],
            r: 0.5 * ctx.tool.diameter,
            z0: scene.local(&frame.origin)[2],
            frame,
        }
    }

    /// The tool's tip touching the face at (`u`, `v`), in the scene.
    fn tip(&self, scene: &super::scene::Scene, u: f64, v: f64) -> [f64; 3] {
        scene.local(&(self.frame.to_world(&Vector3::new(u, v, 0.0)) + self.level * self.r))
    }

    /// The triangles that may stop the tool anywhere on the face (within
    /// the holder's radius of the tool's line at some height of it),
    /// highest first.
    fn candidates(
        &self,
        ctx: &Ctx,
        scene: &super::scene::Scene,
        own: u32,
        rect: &geo::Rect<f64>,
    ) -> Vec<u32> {
        let tool = &ctx.tool;
        let reach = self.r + 0.5 * tool.holder_diameter;
        let (v0, v1) = (rect.min().y, rect.max().y);
        let corners = [
            (rect.min().x, v0),
            (rect.max().x, v0),
            (rect.max().x, v1),
            (rect.min().x, v1),
        ]
        .map(|(u, v)| self.tip(scene, u, v));
        let (lo, hi) = xy_bounds(&corners, reach);
        let zmin = self.z0 + v0 * self.rise + ctx.touch;
        let mut cands = scene.near(lo, hi, zmin);
        cands.retain(|&k| scene.tris[k as usize].face != own);
        // A corner's offset from the line changes linearly with the
        // height: the two ends bound it.
        let ends = [v0, v1].map(|v| self.tip(scene, 0.0, v));
        let big = 0.5 * tool.holder_diameter;
        let e2 = self.e2;
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
        cands
    }

    /// Where the face stands along the axis (the tool's foot stays put
    /// from its lowest line to its highest): its candidates' whole spans.
    fn standing(
        &self,
        ctx: &Ctx,
        scene: &super::scene::Scene,
        cands: &[u32],
        (v0, v1): (f64, f64),
    ) -> Option<Standing> {
        let a = self.tip(scene, 0.0, v0);
        self.stands(ctx, scene, (v0, v1))
            .then(|| Standing::new(ctx, scene, cands, a, self.e2))
    }

    /// Whether the tool's foot stays within the touching tolerance from
    /// the face's lowest line to its highest.
    fn stands(&self, ctx: &Ctx, scene: &super::scene::Scene, (v0, v1): (f64, f64)) -> bool {
        let (a, b) = (self.tip(scene, 0.0, v0), self.tip(scene, 0.0, v1));
        (a[0] - b[0]).hypot(a[1] - b[1]) <= ctx.touch
    }

    /// Add one level line's area, reached area and blockers to `out`;
    /// returns where the tool is stopped along it.
    fn integrate(
        &self,
        ctx: &Ctx,
        scene: &super::scene::Scene,
        obstacles: &Obstacles,
        line: &Line,
        blocks: &mut Vec<Block>,
        out: &mut Judged,
    ) -> Vec<Span> {
        let p = self.tip(scene, 0.0, line.v);
        let cands = obstacles.cands;
        // Only the triangles reaching above the tip (highest first).
        let above = cands.partition_point(|&k| scene.top(k) > p[2] + ctx.touch);
        let touches = (ctx.touch, ctx.touch_tessellated());
        let mut clipped = Vec::new();
        let whole = match obstacles.standing {
            Some(s) => s.at(scene, &cands[..above], p[2], ctx, &mut clipped),
            None => {
                clipped.extend_from_slice(&cands[..above]);
                Vec::new()
            }
        };
        blocks.clear();
        blocked(scene, &clipped, p, self.e2, &ctx.tool, touches, blocks);
        // Each face's blocks by the cutter or the holder as one set of
        // spans: what it leaves of the line, counted once however finely
        // it is tessellated.
        let mut exact: Vec<(Key, Span)> = blocks
            .iter()
            .map(|b| ((b.tri_face(scene), b.holder), b.span))
            .collect();
        exact.sort_unstable_by(by_key);
        let keyed = merge_sorted(whole, exact);
        let mut all: Vec<Span> = Vec::new();
        for group in keyed.chunk_by(|x, y| x.0 == y.0) {
            let spans = merge(group.iter().map(|g| g.1).collect());
            let lost = overlap(line.face, &spans);
            if lost > 0.0 {
                *out.blockers.entry(group[0].0).or_default() += line.weight * lost;
            }
            all.extend(spans);
        }
        let stop = merge(all);
        out.area += line.weight * length(line.face);
        out.reached += line.weight * length(&subtract(line.face, &stop));
        stop
    }
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
    // Distinct heights first: counting every triangle corner's copy, the
    // coarse merge below was taken or not as rounding put a corner just
    // outside the face, and a kink 0.06 mm up a 36 mm rib went with it.
    let distinct = thin_out(vs, 1e-9 * span);
    let mut out = if distinct.len() > MAX_BANDS {
        thin_out(distinct, span / MAX_BANDS as f64)
    } else {
        distinct
    };
    // The face's top closes the last band, in place of a height just below.
    match out.last_mut() {
        Some(l) if *l >= v1 - 1e-9 * span => *l = v1,
        _ => out.push(v1),
    }
    out
}

/// Sorted values, each kept only more than `gap` above the last one kept.
fn thin_out(vs: Vec<f64>, gap: f64) -> Vec<f64> {
    let mut out: Vec<f64> = Vec::with_capacity(vs.len());
    for v in vs {
        match out.last() {
            Some(&last) if v - last <= gap => {}
            _ => out.push(v),
        }
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
