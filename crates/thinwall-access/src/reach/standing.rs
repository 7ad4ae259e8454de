//! A face standing along the tool axis (a vertical wall side on three
//! axes): the tool's foot stays put from the face's lowest level line to
//! its highest, only its height changes. A triangle wholly above the
//! cutting length there meets only the holder, one wholly within it only
//! the cutter, and either way on the same span at every such height: found
//! once per face ([`whole_spans`]), kept in the order the lines' blockers
//! are gathered in (face, tool part, start), so a line takes them in order
//! without sorting and only the triangles its two levels cut are clipped.

use super::interval::Span;
use super::scene::{whole_spans, Scene, Whole};
use super::Ctx;

/// A blocker's key: the mesh face and whether the holder meets it.
pub type Key = (u32, bool);

/// Key, then start.
pub fn by_key(x: &(Key, Span), y: &(Key, Span)) -> std::cmp::Ordering {
    x.0.cmp(&y.0).then(x.1 .0.total_cmp(&y.1 .0))
}

/// The whole spans of a standing face's candidate triangles.
pub struct Standing {
    wholes: Vec<Whole>,
    /// (key, span, position in the candidates), by key and start: the
    /// holder's spans.
    holders: Vec<(Key, Span, u32)>,
    /// The cutter's, the same way.
    cutters: Vec<(Key, Span, u32)>,
}

/// Which part of the tool meets a triangle whole at a tip height.
#[derive(PartialEq)]
enum Meets {
    Holder,
    Cutter,
    Clipped,
}

impl Standing {
    /// `cands` seen along `q + s·e` (the tip at any height).
    pub fn new(ctx: &Ctx, scene: &Scene, cands: &[u32], q: [f64; 3], e: [f64; 2]) -> Self {
        let touches = (ctx.touch, ctx.touch_tessellated());
        let wholes = whole_spans(scene, cands, q, e, &ctx.tool, touches);
        let sorted = |pick: fn(&Whole) -> Option<Span>, holder: bool| {
            let mut v: Vec<(Key, Span, u32)> = cands
                .iter()
                .zip(&wholes)
                .enumerate()
                .filter_map(|(i, (&k, w))| {
                    pick(w).map(|s| ((scene.tris[k as usize].face, holder), s, i as u32))
                })
                .collect();
            v.sort_by(|x, y| by_key(&(x.0, x.1), &(y.0, y.1)).then(x.2.cmp(&y.2)));
            v
        };
        let holders = sorted(|w| w.holder, true);
        let cutters = sorted(|w| w.cutter, false);
        Self {
            wholes,
            holders,
            cutters,
        }
    }

    fn part(scene: &Scene, k: u32, h: f64, ctx: &Ctx) -> Meets {
        let touch = scene.tris[k as usize].touch((ctx.touch, ctx.touch_tessellated()));
        let top = h + ctx.tool.cutting_length;
        let (lo, hi) = (scene.bottom(k), scene.top(k));
        if lo > top + touch {
            Meets::Holder
        } else if lo > h + touch && hi <= top {
            Meets::Cutter
        } else {
            Meets::Clipped
        }
    }

    /// At tip height `h`: the whole spans of `cands` (the candidates these
    /// were made of), by key and start; the triangles among `cands[..above]`
    /// that are not whole there go to `clipped`.
    pub fn at(
        &self,
        scene: &Scene,
        cands: &[u32],
        above: usize,
        h: f64,
        ctx: &Ctx,
        clipped: &mut Vec<u32>,
    ) -> Vec<(Key, Span)> {
        debug_assert_eq!(cands.len(), self.wholes.len());
        clipped.extend(
            cands[..above]
                .iter()
                .filter(|&&k| Self::part(scene, k, h, ctx) == Meets::Clipped),
        );
        let pick = |list: &[(Key, Span, u32)], want: Meets| -> Vec<(Key, Span)> {
            list.iter()
                .filter(|x| Self::part(scene, cands[x.2 as usize], h, ctx) == want)
                .map(|x| (x.0, x.1))
                .collect()
        };
        merge_sorted(
            pick(&self.cutters, Meets::Cutter),
            pick(&self.holders, Meets::Holder),
        )
    }
}

/// Two lists sorted [`by_key`] as one.
pub fn merge_sorted(a: Vec<(Key, Span)>, b: Vec<(Key, Span)>) -> Vec<(Key, Span)> {
    if a.is_empty() {
        return b;
    }
    if b.is_empty() {
        return a;
    }
    let mut out = Vec::with_capacity(a.len() + b.len());
    let (mut a, mut b) = (a.into_iter().peekable(), b.into_iter().peekable());
    while let (Some(x), Some(y)) = (a.peek(), b.peek()) {
        if by_key(x, y).is_le() {
            out.extend(a.next());
        } else {
            out.extend(b.next());
        }
    }
    out.extend(a);
    out.extend(b);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_sorted_lists_merge_in_order() {
        let a = vec![((1, false), (0.0, 1.0)), ((2, true), (5.0, 6.0))];
        let b = vec![((1, false), (0.5, 2.0)), ((1, true), (3.0, 4.0))];
        let m = merge_sorted(a.clone(), b.clone());
        let mut want = [a, b].concat();
        want.sort_by(by_key);
        assert_eq!(m, want);
        assert_eq!(merge_sorted(vec![], want.clone()), want);
    }
}
