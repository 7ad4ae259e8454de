//! Set-ups in turn (issue 37): each set-up's stock is what the set-ups
//! before it left. A block of a later set-up's removal is `cleared` when an
//! earlier set-up reached it: exactly for a set-up from the opposite side
//! (the block is open below: nothing of the part between it and that
//! side), else judged at points inside it ([`thinwall_removal::locate`]):
//! every point outside the first set-up's stock or in a block an earlier
//! set-up reaches. What no set-up reaches is the residue, with its volume
//! and the faces round it.

use serde::Serialize;
use thinwall_analysis::PartAnalysis;
use thinwall_geom::tolerance::NEAR_PARALLEL_EPS;
use thinwall_geom::Point3;
use thinwall_geom::Vector3;
use thinwall_removal::locate::{samples, Locator, Place};
use thinwall_removal::{frame_of, Bound, Removal, RemovalError, StockShape};

/// How later set-ups were compared with earlier ones.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Judged {
    /// Every set-up opposite the first, or one set-up: exact.
    Exact,
    /// At points inside the blocks: a block partly reached counts as not
    /// reached (it is machined again), a residue block's volume is taken
    /// in proportion to its points no set-up reaches.
    AtPoints,
}

/// Material no set-up reaches.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Residue {
    pub volume_mm3: f64,
    /// Blocks of the first set-up's removal it lies in.
    pub blocks: usize,
    /// `step_id`s of the part's faces above and below it.
    pub faces: Vec<u64>,
    pub judged: Judged,
}

/// The checked removal of the part's block stock along each of `ups`,
/// in order (not yet [`in_turn`]).
pub fn removals_along(a: &PartAnalysis, ups: &[Vector3]) -> Result<Vec<Removal>, RemovalError> {
    let size = a.bounding_box().diagonal();
    ups.iter()
        .map(|&up| {
            let (frame, lo, hi) = frame_of(a, up);
            Removal::new(
                a.part(),
                frame,
                &StockShape::Block { lo, hi },
                &[],
                size,
                a.work(),
            )?
            .checked()
        })
        .collect()
}

/// Two set-ups from opposite sides.
fn opposite(a: &Removal, b: &Removal) -> bool {
    a.frame.z.dot(&b.frame.z) < -1.0 + NEAR_PARALLEL_EPS
}

/// Whether world point `p` is gone before a set-up: outside the first
/// set-up's stock, or in a block a set-up before reaches.
fn gone(p: &Point3, earlier: &[Removal], at: &[Locator]) -> bool {
    at.iter().enumerate().any(|(j, l)| match l.place(p) {
        Place::Outside => j == 0,
        Place::Block(i) => earlier[j].blocks[i].reachable,
        Place::Solid => false,
    })
}

/// Mark each later removal's blocks that an earlier set-up reached
/// `cleared`, in turn: `removals[0]` is the first set-up's. Returns per
/// set-up the volume of the blocks it reaches that an earlier set-up
/// reached in part (cut whole again: at most that much is air), mm³.
pub fn in_turn(removals: &mut [Removal]) -> Vec<f64> {
    let mut recut = vec![0.0; removals.len()];
    for (k, recut) in recut.iter_mut().enumerate().skip(1) {
        let (earlier, rest) = removals.split_at_mut(k);
        *recut = clear_taken(&mut rest[0], earlier);
    }
    recut
}

/// Mark the blocks of `later` the `earlier` set-ups took whole `cleared`;
/// the volume of those it reaches that they took in part (cut whole
/// again: at most that much is air), mm³.
pub fn clear_taken(later: &mut Removal, earlier: &[Removal]) -> f64 {
    let gone = gone_shares(later, earlier);
    let mut recut = 0.0;
    for (b, g) in later.blocks.iter_mut().zip(gone) {
        b.cleared = g == 1.0;
        if g > 0.0 && g < 1.0 && b.reachable {
            recut += b.volume;
        }
    }
    recut
}

/// Per block of `later`, the share of it the `earlier` set-ups took: 1
/// for a block open below after the opposite side, else the share of its
/// points they reached.
pub fn gone_shares(later: &Removal, earlier: &[Removal]) -> Vec<f64> {
    let at: Vec<Locator> = earlier.iter().map(Locator::new).collect();
    let from_opposite = earlier.iter().any(|e| opposite(e, later));
    (0..later.blocks.len())
        .map(|bi| {
            if from_opposite && later.blocks[bi].open_below {
                return 1.0;
            }
            let points = samples(later, bi);
            let n = points.iter().filter(|p| gone(p, earlier, &at)).count();
            n as f64 / points.len().max(1) as f64
        })
        .collect()
}

/// What set-up `later` cuts after the `earlier` ones: its reachable
/// blocks not wholly taken before, mm³.
pub fn cut_after(later: &Removal, earlier: &[Removal]) -> f64 {
    later
        .blocks
        .iter()
        .zip(gone_shares(later, earlier))
        .filter(|(b, g)| b.reachable && *g < 1.0)
        .map(|(b, _)| b.volume)
        .sum()
}

/// What the first set-up's removal holds that none of `removals` reaches.
pub fn residue(removals: &[Removal]) -> Residue {
    residue_after(removals, None)
}

/// [`residue`] with `also` another set-up's reach besides (a height map's
/// estimate, `HeightMap::reaches` in `heights.rs`).
pub fn residue_after(removals: &[Removal], also: Option<&dyn Fn(&Point3) -> bool>) -> Residue {
    let Some((first, later)) = removals.split_first() else {
        return Residue {
            volume_mm3: 0.0,
            blocks: 0,
            faces: Vec::new(),
            judged: Judged::Exact,
        };
    };
    let from_opposite = later.iter().any(|r| opposite(first, r));
    let others: Vec<&Removal> = later.iter().filter(|r| !opposite(first, r)).collect();
    let at: Vec<Locator> = others.iter().map(|r| Locator::new(r)).collect();
    let reached = |p: &Point3| {
        also.is_some_and(|f| f(p))
            || at.iter().zip(&others).any(|(l, r)| match l.place(p) {
                Place::Block(i) => r.blocks[i].reachable,
                Place::Outside | Place::Solid => false,
            })
    };
    let at_points = !others.is_empty() || also.is_some();
    let (mut volume, mut blocks, mut faces) = (0.0, 0, Vec::new());
    for (bi, b) in first.blocks.iter().enumerate() {
        if b.reachable || (from_opposite && b.open_below) {
            continue;
        }
        let points = samples(first, bi);
        let left = if !at_points || points.is_empty() {
            1.0
        } else {
            points.iter().filter(|p| !reached(p)).count() as f64 / points.len() as f64
        };
        // A block's share under a billionth of the stock is rounding.
        if left * b.volume <= 1e-9 * first.stock_volume {
            continue;
        }
        volume += left * b.volume;
        blocks += 1;
        for bound in [b.lower, b.upper] {
            if let Bound::Part(i) = bound {
                faces.push(first.part_step_id(i));
            }
        }
    }
    faces.sort_unstable();
    faces.dedup();
    Residue {
        volume_mm3: volume,
        blocks,
        faces,
        judged: if at_points {
            Judged::AtPoints
        } else {
            Judged::Exact
        },
    }
}

/// The residue below which a set of set-ups reaches everything: a
/// millionth of the stock, or the first removal's bound through its
/// meshed faces and slivers if larger, mm³.
pub fn residue_tolerance(first: &Removal) -> f64 {
    (1e-6 * first.stock_volume).max(first.meshed.volume_bound_mm3 + first.sliver_volume)
}
