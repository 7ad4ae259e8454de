//! A face standing along the tool axis (a vertical wall side on three
//! axes): the tool's foot stays put from the face's lowest level line to
//! its highest, only its height changes. A triangle wholly above the
//! cutting length there meets only the holder, one wholly within it only
//! the cutter, and either way on the same span at every such height: found
//! once per face ([`whole_spans`]), kept in the order the lines' blockers
//! are gathered in (face, tool part, start), so a line takes them in order
//! without sorting and only the triangles its two levels cut are clipped.

use super::interval::Span;
use super::scene::{whole_spans, Meets, Scene, Whole};
use super::Ctx;

/// A blocker's key: the mesh face and whether the holder meets it.
pub type Key = (u32, bool);

/// Key, then start.
pub fn by_key(x: &(Key, Span), y: &(Key, Span)) -> std::cmp::Ordering {
    x.0.cmp(&y.0).then(x.1 .0.total_cmp(&y.1 .0))
}

/// The whole spans of a standing face's candidate triangles.
pub struct Standing {
    /// (key, span, triangle), by key, start and triangle: the holder's
    /// spans.
    holders: Vec<(Key, Span, u32)>,
    /// The cutter's, the same way.
    cutters: Vec<(Key, Span, u32)>,
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
                .filter_map(|(&k, w)| {
                    pick(w).map(|s| ((scene.tris[k as usize].face, holder), s, k))
                })
                .collect();
            v.sort_by(|x, y| by_key(&(x.0, x.1), &(y.0, y.1)).then(x.2.cmp(&y.2)));
            v
        };
        Self {
            holders: sorted(|w| w.holder, true),
            cutters: sorted(|w| w.cutter, false),
        }
    }

    /// At tip height `h`: the whole spans, by key and start; the triangles
    /// among `above` (candidates reaching above the tip) that a level cuts
    /// go to `clipped`.
    pub fn at(
        &self,
        scene: &Scene,
        above: &[u32],
        h: f64,
        ctx: &Ctx,
        clipped: &mut Vec<u32>,
    ) -> Vec<(Key, Span)> {
        let touches = (ctx.touch, ctx.touch_tessellated());
        let meets = |k: u32| {
            let t = &scene.tris[k as usize];
            t.meets(h, ctx.tool.cutting_length, t.touch(touches))
        };
        clipped.extend(above.iter().filter(|&&k| meets(k) == Meets::Clipped));
        let pick = |list: &[(Key, Span, u32)], want: Meets| -> Vec<(Key, Span)> {
            list.iter()
                .filter(|x| meets(x.2) == want)
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
