//! Set-ups proposed (issue 37): the fewest ups from which a 3-axis machine
//! reaches stock − part, chosen greedily. The first is the direction the
//! part's planar faces face that reaches the most material
//! ([`crate::choice`]); while material is left that no set-up so far
//! reaches (the residue, [`crate::sequence::residue`]), the next is the
//! candidate that leaves the least: the first's opposite, the directions
//! the faces round the residue face (planar normals, axes of cylinders
//! and cones both ways) and the first stock's other axes. It stops when the
//! residue is within the removal's tolerance, when no candidate takes
//! more than that, or at [`MOST_SETUPS`]. Every direction comes from the
//! part, so turning the part turns the proposal with it.

use crate::choice::{ranked, UpCandidate, SAME_SETUP_COS};
use crate::sequence::{residue, residue_tolerance, Residue};
use serde::Serialize;
use thinwall_analysis::PartAnalysis;
use thinwall_geom::Vector3;
use thinwall_removal::{Bound, Removal, RemovalError};

/// Set-ups proposed, at most.
pub const MOST_SETUPS: usize = 6;

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

fn arr(v: &Vector3) -> [f64; 3] {
    // + 0.0: no negative zeros in the report.
    [v.x + 0.0, v.y + 0.0, v.z + 0.0]
}

/// One set-up's direction ([`SAME_SETUP_COS`]).
fn same(a: &Vector3, b: &Vector3) -> bool {
    a.dot(b) > SAME_SETUP_COS
}

/// The removals of the set-ups along `ups`, in order (not yet
/// [`crate::sequence::in_turn`]); when `proposed`, those [`propose`]s
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
        return Ok((
            Some(proposal),
            crate::sequence::removals_along(a, &ups[..1])?,
        ));
    }
    Ok((None, crate::sequence::removals_along(a, &ups)?))
}

/// The proposal and the removal of each set-up proposed (none when every
/// candidate was refused: the candidates say why).
pub fn propose(a: &PartAnalysis) -> (Proposal, Vec<Removal>) {
    let ranked = ranked(a);
    let candidates: Vec<UpCandidate> = ranked.iter().map(|(c, _)| c.clone()).collect();
    let mut proposal = Proposal {
        ups: Vec::new(),
        why: Vec::new(),
        candidates,
        later: Vec::new(),
        residue: residue(&[]),
    };
    // The other candidates' removals serve the later set-ups' tries.
    let mut built: Vec<Removal> = Vec::new();
    let mut first = None;
    for (_, r) in ranked {
        match (first.is_none(), r) {
            (true, Some(r)) => first = Some(r),
            (false, Some(r)) => built.push(r),
            (_, None) => {}
        }
    }
    let Some(first) = first else {
        proposal
            .why
            .push("no direction the planar faces face gives a removal".into());
        return (proposal, Vec::new());
    };
    let up = arr(&first.frame.z);
    proposal.why.push(format!(
        "up ({:.3}, {:.3}, {:.3}): of the {} directions the planar faces face, it reaches the most material ({:.1} mm³)",
        up[0],
        up[1],
        up[2],
        proposal.candidates.len(),
        proposal.candidates[0].reachable_mm3.unwrap_or(0.0)
    ));
    proposal.ups.push(up);
    let mut removals = vec![first];
    let tol = residue_tolerance(&removals[0]);
    proposal.residue = residue(&removals);
    while proposal.residue.volume_mm3 > tol && removals.len() < MOST_SETUPS {
        let tries = Tries {
            built: &mut built,
            later: &mut proposal.later,
            tol,
        };
        let Some((r, left)) = next_setup(a, &mut removals, tries) else {
            break;
        };
        if proposal.residue.volume_mm3 - left.volume_mm3 <= tol {
            break;
        }
        let up = arr(&r.frame.z);
        proposal.why.push(format!(
            "then up ({:.3}, {:.3}, {:.3}): it reaches {:.1} mm³ of the {:.1} mm³ the set-ups before left, {} candidate(s) tried",
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

/// How the next set-up is tried: removals built already (taken from here
/// and put back when not chosen), the record of candidates, and the
/// residue that counts as nothing.
struct Tries<'t> {
    built: &'t mut Vec<Removal>,
    later: &'t mut Vec<LaterCandidate>,
    tol: f64,
}

impl Tries<'_> {
    /// The removal along `d`: built already, or now.
    fn removal(&mut self, a: &PartAnalysis, d: Vector3) -> Result<Removal, String> {
        match self.built.iter().position(|r| same(&r.frame.z, &d)) {
            Some(k) => Ok(self.built.swap_remove(k)),
            None => crate::choice::removal_along(a, d),
        }
    }
}

/// The best next set-up after `removals` and what it leaves (the first
/// candidate that leaves no more than the tolerance, else the one that
/// leaves the least); each candidate tried is recorded.
fn next_setup(
    a: &PartAnalysis,
    removals: &mut Vec<Removal>,
    mut tries: Tries<'_>,
) -> Option<(Removal, Residue)> {
    let setup = removals.len() + 1;
    let mut best: Option<(Removal, Residue)> = None;
    for d in next_directions(a, removals) {
        let r = match tries.removal(a, d) {
            Err(why) => {
                tries.later.push(LaterCandidate {
                    setup,
                    up: arr(&d),
                    residue_mm3: None,
                    refused: Some(why),
                });
                continue;
            }
            Ok(r) => r,
        };
        removals.push(r);
        let left = residue(removals);
        let r = removals.pop().expect("just pushed");
        tries.later.push(LaterCandidate {
            setup,
            up: arr(&d),
            residue_mm3: Some(left.volume_mm3),
            refused: None,
        });
        if best
            .as_ref()
            .is_some_and(|(_, b)| b.volume_mm3 <= left.volume_mm3)
        {
            tries.built.push(r);
            continue;
        }
        let done = left.volume_mm3 <= tries.tol;
        if let Some((old, _)) = best.replace((r, left)) {
            tries.built.push(old);
        }
        if done {
            break;
        }
    }
    best
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
