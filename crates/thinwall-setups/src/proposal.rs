//! Set-ups proposed (issue 37): the fewest ups from which a 3-axis machine
//! reaches stock − part, chosen greedily. The first is the direction the
//! part's planar faces face that reaches the most material
//! ([`crate::choice`]); while material is left that no set-up so far
//! reaches (the residue, [`crate::turn::residue`]), the next is the
//! candidate that leaves the least: the first's opposite, the directions
//! the faces round the residue face (planar normals, axes of cylinders
//! and cones both ways) and the first stock's other axes. Candidates are
//! judged on height maps of the part's mesh ([`crate::heights`]); only the
//! set-ups taken get their exact removal. It stops when the residue is
//! within the removal's tolerance, when no candidate takes more than that,
//! or at [`MOST_SETUPS`]. Every direction comes from the part, so turning
//! the part turns the proposal with it.

use crate::choice::{clean, up_candidates, UpCandidate, SAME_SETUP_COS};
use crate::heights::HeightMap;
use crate::turn::{cut_after, residue, residue_after, residue_tolerance, Residue};
use serde::Serialize;
use std::collections::HashMap;
use thinwall_analysis::PartAnalysis;
use thinwall_geom::{Point3, Vector3};
use thinwall_removal::{Bound, Removal, RemovalError};

/// Set-ups proposed, at most.
pub const MOST_SETUPS: usize = 6;

/// The least share of stock − part a set-up after the first must take.
pub const MIN_SETUP_SHARE: f64 = 1e-4;

/// Candidates tried for each set-up after the first, at most.
pub const MOST_TRIED: usize = 8;

/// A later set-up's candidate.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LaterCandidate {
    /// Which set-up it was tried for (2 for the second, …).
    pub setup: usize,
    pub up: [f64; 3],
    /// What would be left with it, mm³ (none where refused).
    pub residue_mm3: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub refused: Option<String>,
}

/// The set-ups proposed and why.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Proposal {
    /// Their ups, in order.
    pub ups: Vec<[f64; 3]>,
    /// Why each was taken, then what is left.
    pub why: Vec<String>,
    /// The first set-up's candidates, best first.
    pub candidates: Vec<UpCandidate>,
    /// The later set-ups' candidates.
    pub later: Vec<LaterCandidate>,
    /// What no proposed set-up reaches.
    pub residue: Residue,
}

/// One set-up's direction ([`SAME_SETUP_COS`]).
fn same(a: &Vector3, b: &Vector3) -> bool {
    a.dot(b) > SAME_SETUP_COS
}

/// The removals of the set-ups along `ups`, in order (not yet
/// [`crate::turn::in_turn`]); when `proposed`, those [`propose`]s
/// instead and why (`ups[0]` only says why when every candidate is
/// refused).
pub fn setups(
    a: &PartAnalysis,
    ups: &[[f64; 3]],
    proposed: bool,
) -> Result<(Option<Proposal>, Vec<Removal>), RemovalError> {
    let ups: Vec<Vector3> = ups.iter().map(|u| Vector3::from(*u).normalize()).collect();
    if proposed {
        let (proposal, removals) = propose(a);
        if !removals.is_empty() {
            return Ok((Some(proposal), removals));
        }
        return Ok((Some(proposal), crate::turn::removals_along(a, &ups[..1])?));
    }
    Ok((None, crate::turn::removals_along(a, &ups)?))
}

/// The proposal and the removal of each set-up proposed (none when every
/// candidate was refused: the candidates say why).
pub fn propose(a: &PartAnalysis) -> (Proposal, Vec<Removal>) {
    let mut proposal = Proposal {
        ups: Vec::new(),
        why: Vec::new(),
        candidates: up_candidates(a),
        later: Vec::new(),
        residue: residue(&[]),
    };
    let mut refused = Refused::default();
    let Some(first) = first_setup(a, &mut proposal, &mut refused) else {
        proposal
            .why
            .push("no direction the planar faces face gives a removal".into());
        return (proposal, Vec::new());
    };
    let mut removals = vec![first];
    let tol = residue_tolerance(&removals[0]);
    // A set-up after the first must take more than this: below it, what
    // is left is a residue to name, not a set-up with nothing to cut.
    let worth = tol.max(MIN_SETUP_SHARE * (removals[0].stock_volume - removals[0].part_volume));
    proposal.residue = residue(&removals);
    while proposal.residue.volume_mm3 > tol && removals.len() < MOST_SETUPS {
        let before = proposal.residue.volume_mm3;
        let Some((r, left)) = next_setup(
            a,
            (&mut removals, &mut refused),
            &mut proposal.later,
            (before, worth),
        ) else {
            break;
        };
        let up = clean(&r.frame.z);
        proposal.why.push(format!(
            "then up ({:.3}, {:.3}, {:.3}): it reaches {:.1} mm³ of the {:.1} mm³ the set-ups before left, the most of {} candidate(s) on their height maps",
            up[0],
            up[1],
            up[2],
            proposal.residue.volume_mm3 - left.volume_mm3,
            proposal.residue.volume_mm3,
            proposal.later.iter().filter(|c| c.setup == removals.len() + 1).count()
        ));
        proposal.ups.push(up);
        removals.push(r);
        proposal.residue = left;
    }
    proposal.why.push(left_text(&proposal.residue, tol));
    (proposal, removals)
}

/// The first set-up's exact removal: of the candidates whose height maps
/// reach within their precision of the best ([`near_best`]), the one whose
/// exact removal reaches the most (to rounding; then the larger face on
/// the table); if the removal refuses them all, the next candidates in
/// turn. Those it refuses say why.
fn first_setup(
    a: &PartAnalysis,
    proposal: &mut Proposal,
    refused: &mut Refused,
) -> Option<Removal> {
    let tried = proposal.candidates.len();
    let mut from = 0;
    while from < tried {
        let group = near_best(&proposal.candidates[from..]);
        let mut best: Option<(f64, f64, Removal)> = None;
        for c in &mut proposal.candidates[from..from + group] {
            match refused.removal_along(a, Vector3::from(c.up)) {
                Err(why) => c.refused = Some(why),
                Ok(r) => {
                    let reached: f64 = r
                        .blocks
                        .iter()
                        .filter(|b| b.reachable && !b.cleared)
                        .map(|b| b.volume)
                        .sum();
                    let tie = 1e-6 * r.stock_volume;
                    let better = best.as_ref().is_none_or(|(v, area, _)| {
                        reached > v + tie || (reached >= v - tie && c.facing_area_mm2 > *area)
                    });
                    if better {
                        best = Some((reached, c.facing_area_mm2, r));
                    }
                }
            }
        }
        if let Some((reached, _, r)) = best {
            let up = clean(&r.frame.z);
            proposal.why.push(format!(
                "up ({:.3}, {:.3}, {:.3}): of the {tried} directions the planar faces face, it reaches the most material ({:.1} mm³; {group} near the best on their height maps compared exactly)",
                up[0], up[1], up[2], reached
            ));
            proposal.ups.push(up);
            return Some(r);
        }
        from += group;
    }
    None
}

/// How many of `candidates` (best first on their height maps) reach
/// within the maps' precision of the first: 1 % of its reach and a
/// thousandth of its stock (`tests/ops_setups.rs` holds the maps to that).
fn near_best(candidates: &[UpCandidate]) -> usize {
    let reach = |c: &UpCandidate| c.reachable_mm3.unwrap_or(0.0);
    let Some(first) = candidates.first() else {
        return 0;
    };
    let margin = 0.01 * reach(first) + 1e-3 * first.stock_mm3;
    candidates
        .iter()
        .take_while(|c| reach(c) >= reach(first) - margin)
        .count()
        .max(1)
}

/// What the proposal leaves, in words.
fn left_text(residue: &Residue, tol: f64) -> String {
    if residue.volume_mm3 <= tol {
        format!("every set-up together reaches all of stock − part (within {tol:.3} mm³)")
    } else {
        format!(
            "{:.1} mm³ are left that no set-up reaches, round faces {}",
            residue.volume_mm3,
            residue
                .faces
                .iter()
                .map(|f| format!("#{f}"))
                .collect::<Vec<_>>()
                .join(", ")
        )
    }
}

/// The directions the removal refused, and why. The removal along a
/// direction depends on the part and the direction alone, so one refused
/// is refused again when a later set-up's candidates bring it back (NIST
/// FTC 07: a direction 1° off −Z, 6.3 s each time).
#[derive(Default)]
struct Refused(HashMap<[u64; 3], String>);

impl Refused {
    /// [`crate::choice::removal_along`], or the reason it gave before.
    fn removal_along(&mut self, a: &PartAnalysis, up: Vector3) -> Result<Removal, String> {
        let key = [up.x.to_bits(), up.y.to_bits(), up.z.to_bits()];
        if let Some(why) = self.0.get(&key) {
            return Err(why.clone());
        }
        let made = crate::choice::removal_along(a, up);
        if let Err(why) = &made {
            self.0.insert(key, why.clone());
        }
        made
    }
}

/// Exact removals tried for one set-up, at most: the candidates best on
/// their height maps first, until one takes more than the tolerance.
const MOST_EXACT_TRIES: usize = 3;

/// The next set-up after `removals` and what it leaves: the candidates
/// ranked by what they would leave on their height maps (each recorded in
/// `later`), then the first of the best whose exact removal takes more
/// than `worth` of the `before` mm³ left.
fn next_setup(
    a: &PartAnalysis,
    (removals, refused): (&mut Vec<Removal>, &mut Refused),
    later: &mut Vec<LaterCandidate>,
    (before, worth): (f64, f64),
) -> Option<(Removal, Residue)> {
    let setup = removals.len() + 1;
    let dirs = next_directions(a, removals);
    let done: &[Removal] = removals;
    let lefts = a.work().map(&dirs, |&d| {
        let map = HeightMap::along(a, d);
        let reaches = |p: &Point3| map.reaches(p);
        residue_after(done, Some(&reaches)).volume_mm3
    });
    let mut ranked: Vec<(f64, Vector3)> = lefts.into_iter().zip(dirs).collect();
    later.extend(ranked.iter().map(|&(left, d)| LaterCandidate {
        setup,
        up: clean(&d),
        residue_mm3: Some(left),
        refused: None,
    }));
    ranked.sort_by(|x, y| x.0.total_cmp(&y.0));
    for (_, d) in ranked.into_iter().take(MOST_EXACT_TRIES) {
        let r = match refused.removal_along(a, d) {
            Ok(r) => r,
            Err(why) => {
                if let Some(c) = later.iter_mut().rev().find(|c| c.up == clean(&d)) {
                    c.refused = Some(why);
                }
                continue;
            }
        };
        removals.push(r);
        let left = residue(removals);
        let r = removals.pop().expect("just pushed");
        // It must also have something of its own to cut: points judged in
        // two frames can credit it with material whose blocks here were
        // all but wholly taken before.
        if before - left.volume_mm3 > worth && cut_after(&r, removals) > worth {
            return Some((r, left));
        }
    }
    None
}

/// Candidate ups after `removals`: the first's opposite, the directions
/// the faces round the residue face, the first stock's other axes; none
/// already taken, at most [`MOST_TRIED`].
fn next_directions(a: &PartAnalysis, removals: &[Removal]) -> Vec<Vector3> {
    let first = &removals[0];
    let mut dirs = vec![-first.frame.z];
    for b in first.blocks.iter().filter(|b| !b.reachable) {
        for bound in [b.lower, b.upper] {
            let Bound::Part(i) = bound else { continue };
            let p = a.props(first.part_pieces[i].face);
            if let Some(n) = p.normal {
                dirs.push(n);
            }
            if let Some((_, axis)) = p.axis {
                dirs.push(axis);
                dirs.push(-axis);
            }
        }
    }
    let f = &first.frame;
    dirs.extend([f.x, -f.x, f.y, -f.y]);
    let mut out: Vec<Vector3> = Vec::new();
    for d in dirs {
        let taken = removals.iter().any(|r| same(&r.frame.z, &d));
        if !taken && !out.iter().any(|o| same(o, &d)) && d.norm() > 0.5 {
            out.push(d.normalize());
        }
    }
    out.truncate(MOST_TRIED);
    out
}
