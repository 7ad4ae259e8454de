//! The largest tool (the run's proportions) that reaches a whole face on
//! one axis: the run's own tool brackets it, doubling up or halving down
//! until the answer changes, then bisection in proportion.
//!
//! A larger tool in the same proportions stops wherever a smaller one does
//! (see [`sampled::judge_some`]), and the search leans on that twice: a
//! side's or curved face's judgement stops as soon as more than the
//! allowance is lost, and below a size that failed, a curved face is
//! judged again only at the triangles that size left.

use super::sampled::Samples;
use super::scene::Scene;
use super::{bore, contact, floor, sampled, side, Contact, Ctx, Judged, WHOLE_SHARE};
use thinwall_analysis::PartAnalysis;
use thinwall_brep::tessellate::Mesh;

/// Smallest tool the largest-tool search tries, mm.
pub const SMALLEST_TOOL: f64 = 0.5;

/// The largest-tool search stops when the sizes that reach the face whole
/// and that do not are this close (relative), or 0.01 mm apart.
pub const TOOL_PRECISION: f64 = 0.005;

/// The largest tool (the run's proportions) that reaches the whole face
/// `own` on the scene's axis, within [`TOOL_PRECISION`]: the run's own
/// tool (`given`: its judgement on this axis) brackets it, doubling up (to
/// twice the face's size) or halving down until the answer changes, then
/// bisecting in proportion. Down, the smallest tool ([`SMALLEST_TOOL`]) is
/// tried first: a face it cannot reach whole has no answer, found in one
/// judgement rather than a halving each. A concave cylinder around the
/// axis ([`bore`]) is tried at its own diameter first: no wider tool
/// reaches it, so a bore reached whole at its size is answered exactly.
/// The result is always a size judged whole.
pub fn largest_tool(
    a: &PartAnalysis,
    mesh: &Mesh,
    ctx: &Ctx,
    scene: &Scene,
    own: u32,
    samples: &Samples,
    given: &Judged,
) -> Option<f64> {
    let f = mesh.faces[own as usize].face;
    let mut judge = WholeJudge::new(a, mesh, ctx, scene, own, samples);
    let mut limit = 2.0 * a.props(f).bbox.diagonal().max(SMALLEST_TOOL);
    if let Some(b) = judge.bound {
        if b < SMALLEST_TOOL {
            return None;
        }
        if judge.whole(b) {
            return Some(b);
        }
        limit = limit.min(b);
    }
    let size = ctx.tool.diameter.clamp(SMALLEST_TOOL, limit);
    // The run's own tool was judged already, unless clamped.
    let given_reaches = if size == ctx.tool.diameter {
        let whole = given.fraction() >= 1.0 - WHOLE_SHARE;
        if !whole {
            judge.failed = Some((size, given.lost.clone()));
        }
        whole
    } else {
        judge.whole(size)
    };
    let (mut lo, mut hi) = if given_reaches {
        // Up: the first size that fails bounds it.
        let mut lo = size;
        loop {
            if lo >= limit {
                return Some(limit);
            }
            let next = (2.0 * lo).min(limit);
            if !judge.whole(next) {
                break (lo, next);
            }
            lo = next;
        }
    } else {
        // Down: none when the smallest fails (a sharp inside corner
        // larger than the allowance); else the first size that reaches it
        // whole bounds it.
        if size <= SMALLEST_TOOL || !judge.whole(SMALLEST_TOOL) {
            return None;
        }
        let mut hi = size;
        loop {
            let next = 0.5 * hi;
            if next <= SMALLEST_TOOL {
                break (SMALLEST_TOOL, hi);
            }
            if judge.whole(next) {
                break (next, hi);
            }
            hi = next;
        }
    };
    while hi / lo > 1.0 + TOOL_PRECISION && hi - lo > 0.01 {
        let mid = (lo * hi).sqrt();
        if judge.whole(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(lo)
}

/// Judges one face whole or not at one tool size after another,
/// remembering what a failed size left.
struct WholeJudge<'a> {
    a: &'a PartAnalysis<'a>,
    mesh: &'a Mesh,
    ctx: &'a Ctx,
    scene: &'a Scene,
    own: u32,
    /// A curved face: where it is judged.
    samples: &'a Samples,
    /// A curved face: the smallest size found to fail, and every sample
    /// it left.
    failed: Option<(f64, Vec<u32>)>,
    /// A curved face: samples that stopped some size.
    hints: Vec<u32>,
    /// A curved face: its triangles' area, mm².
    area: f64,
    /// A concave cylinder around the axis: its diameter, mm.
    bound: Option<f64>,
    /// Sizes judged, and whether whole.
    known: Vec<(f64, bool)>,
}

impl<'a> WholeJudge<'a> {
    fn new(
        a: &'a PartAnalysis<'a>,
        mesh: &'a Mesh,
        ctx: &'a Ctx,
        scene: &'a Scene,
        own: u32,
        samples: &'a Samples,
    ) -> Self {
        Self {
            a,
            mesh,
            ctx,
            scene,
            own,
            samples,
            failed: None,
            hints: Vec::new(),
            area: mesh.face_area(&mesh.faces[own as usize]),
            bound: bore::limit(a, scene, mesh.faces[own as usize].face),
            known: Vec::new(),
        }
    }

    /// Whether the tool of diameter `d` reaches the face whole (each
    /// size judged once).
    fn whole(&mut self, d: f64) -> bool {
        if let Some(&(_, w)) = self.known.iter().find(|k| k.0 == d) {
            return w;
        }
        let w = self.judge(d);
        self.known.push((d, w));
        w
    }

    fn judge(&mut self, d: f64) -> bool {
        self.a.work().check();
        let ctx = Ctx {
            tool: self.ctx.tool.scaled(d),
            touch: self.ctx.touch,
            touch_curved: self.ctx.touch_curved,
        };
        let f = self.mesh.faces[self.own as usize].face;
        let j = match contact(self.a, self.scene, f) {
            None => return false,
            Some((Contact::Floor, Some(pf))) => floor::judge(&ctx, self.scene, pf, self.own, false),
            Some((Contact::Side, Some(pf))) => {
                side::judge_within(&ctx, self.scene, pf, self.own, WHOLE_SHARE)
            }
            Some(_) if self.bound.is_some_and(|b| bore::too_wide(&ctx, b)) => return false,
            Some(_) => return self.curved_whole(&ctx, d),
        };
        !j.cut_short && j.fraction() >= 1.0 - WHOLE_SHARE
    }

    /// A curved face: below the smallest size that failed whole, only the
    /// triangles it left can stop the tool; those that stopped any size
    /// are judged first, and the judgement stops once the allowance is
    /// lost.
    fn curved_whole(&mut self, ctx: &Ctx, d: f64) -> bool {
        let tris = self.samples.len();
        let mut order: Vec<u32> = match &self.failed {
            Some((size, left)) if d <= *size => left.clone(),
            _ => (0..tris as u32).collect(),
        };
        let mut hinted = vec![false; tris];
        for &k in &self.hints {
            hinted[k as usize] = true;
        }
        // Stable: hinted first, each part in its own order.
        order.sort_by_key(|&k| !hinted[k as usize]);
        let budget = WHOLE_SHARE * self.area;
        let j = sampled::judge_some(ctx, self.scene, self.samples, order.into_iter(), budget);
        for &k in &j.lost {
            if !hinted[k as usize] {
                self.hints.push(k);
            }
        }
        let whole = !j.cut_short && j.area - j.reached <= budget;
        // Judged to the end and failed: every triangle it leaves is known.
        if !whole && !j.cut_short && self.failed.as_ref().is_none_or(|(size, _)| d < *size) {
            self.failed = Some((d, j.lost));
        }
        whole
    }
}
