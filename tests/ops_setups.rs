//! Set-ups proposed and planned in turn (issue 37), on generated parts
//! with their truth, as built and turned (the set-up turned with the
//! part): a panel pocketed from both sides of its web gets two set-ups from
//! opposite sides with every pocket in the set-up that faces it, a
//! one-sided panel one; a plate with holes across it a set-up along their
//! axis; what the set-ups take adds up to stock − part with no residue.

mod common;

use nalgebra::{Point3, Rotation3, Vector3};
use std::path::Path;
use thinwall_analysis::{PartAnalysis, Setup};
use thinwall_removal::locate::{Locator, Place};
use thinwall_removal::Removal;
use thinwall_setups::proposal::setups;
use thinwall_setups::proposal::Proposal;
use thinwall_setups::turn::{in_turn, residue, residue_tolerance, Judged};

#[derive(serde::Deserialize)]
struct PanelTruth {
    both_sides: bool,
    pockets: Vec<PanelPocket>,
}

#[derive(serde::Deserialize)]
struct PanelPocket {
    side: f64,
    #[serde(rename = "box")]
    bounds: [f64; 6],
    /// A lightening hole's diameter in its floor, centred (0: none).
    hole: f64,
}

impl PanelPocket {
    /// A point of the pocket's material that lies over no lightening hole
    /// (a column through one is open to both sides) and off its floor
    /// fillet: a tenth of its depth in from its open face, half-way
    /// between its wall and the hole (its middle without one).
    fn inside(&self) -> Point3<f64> {
        let b = self.bounds;
        let (cx, cy) = (0.5 * (b[0] + b[3]), 0.5 * (b[1] + b[4]));
        let x = if self.hole > 0.0 {
            0.5 * (b[0] + cx - 0.5 * self.hole)
        } else {
            cx
        };
        let z = if self.side > 0.0 {
            b[2] + 0.9 * (b[5] - b[2])
        } else {
            b[5] - 0.9 * (b[5] - b[2])
        };
        Point3::new(x, cy, z)
    }
}

/// A generated part posed, its set-ups proposed and planned in turn.
struct Posed {
    proposal: Proposal,
    removals: Vec<Removal>,
    /// What later set-ups may cut again, mm³.
    recut: f64,
    /// The proposed ups turned back to the part as built.
    ups: Vec<Vector3<f64>>,
    rot: Rotation3<f64>,
    t: Vector3<f64>,
}

/// The part of `path` posed by `seed`, its set-ups proposed and planned in
/// turn.
fn proposed(path: &Path, seed: Option<u64>) -> Posed {
    let text = common::posed_step(&std::fs::read_to_string(path).unwrap(), seed);
    let (part, _) = thinwall_step::read_bytes(text.as_bytes(), "part.step").unwrap();
    let a = PartAnalysis::new(&part, Setup::default());
    let (proposal, mut removals) = setups(&a, &[[0.0, 0.0, 1.0]], true)
        .unwrap_or_else(|e| panic!("{} {seed:?}: {e}", path.display()));
    let proposal = proposal.expect("proposed");
    let recut = in_turn(&mut removals).iter().sum();
    let (rot, t) = seed.map_or(
        (Rotation3::identity(), Vector3::zeros()),
        common::rigid_motion,
    );
    let ups = proposal
        .ups
        .iter()
        .map(|u| rot.inverse() * Vector3::from(*u))
        .collect();
    Posed {
        proposal,
        removals,
        recut,
        ups,
        rot,
        t,
    }
}

/// `check` on the part of `path` as built and turned by `seed`, each
/// posed and proposed (with its name for messages); the turned copy's
/// ups, turned back, are the built one's.
fn in_both_poses(path: &Path, seed: u64, mut check: impl FnMut(&str, &Posed)) {
    let mut all: Vec<Vec<Vector3<f64>>> = Vec::new();
    for seed in [None, Some(seed)] {
        let posed = proposed(path, seed);
        check(&format!("{} {seed:?}", path.display()), &posed);
        all.push(posed.ups);
    }
    assert_eq!(
        all[0].len(),
        all[1].len(),
        "{}: turned {all:?}",
        path.display()
    );
    for (a, b) in all[0].iter().zip(&all[1]) {
        assert!((a - b).norm() < 1e-9, "{}: turned {all:?}", path.display());
    }
}

/// The truth written beside a generated part.
fn truth_of<T: serde::de::DeserializeOwned>(path: &Path) -> T {
    serde_json::from_str(&std::fs::read_to_string(path.with_extension("truth.json")).unwrap())
        .unwrap()
}

/// What the set-ups take (reachable, not cleared) plus the residue is
/// stock − part, within the removals' precision and what they cut again
/// (`recut`: blocks an earlier set-up along another axis reached in part).
fn assert_adds_up(removals: &[Removal], recut: f64, name: &str) {
    let taken: f64 = removals
        .iter()
        .map(|r| {
            thinwall_ops::layers::reachable(r)
                .map(|b| b.volume)
                .sum::<f64>()
        })
        .sum();
    let left = residue(removals);
    let first = &removals[0];
    let whole = first.stock_volume - first.part_volume;
    let bound = removals
        .iter()
        .map(|r| r.meshed.volume_bound_mm3 + r.sliver_volume)
        .sum::<f64>()
        + 1e-6 * first.stock_volume;
    let once = taken - recut;
    assert!(
        once + left.volume_mm3 <= whole + bound && whole <= taken + left.volume_mm3 + bound,
        "{name}: the set-ups take {taken} mm³ ({recut} perhaps again), {} left, stock − part {whole} (bound {bound})",
        left.volume_mm3
    );
    assert!(
        left.volume_mm3 <= residue_tolerance(first),
        "{name}: {left:?} left"
    );
}

/// Which set-up takes the world point `p`: the first whose removal holds
/// it in a block it reaches and no set-up before took.
fn taken_by(removals: &[Removal], p: &Point3<f64>) -> Option<usize> {
    removals
        .iter()
        .position(|r| match Locator::new(r).place(p) {
            Place::Block(i) => r.blocks[i].reachable && !r.blocks[i].cleared,
            Place::Solid | Place::Outside => false,
        })
}

#[test]
fn every_pocket_is_in_the_set_up_that_faces_it_in_any_pose() {
    let parts = common::generated_parts("THINWALL_POCKETS_DIR", "pockets");
    let (mut two, mut pockets) = (0, 0);
    for (k, path) in parts.iter().enumerate() {
        let truth: PanelTruth = truth_of(path);
        let mut sides = Vec::new();
        for seed in [None, Some(4500 + k as u64)] {
            let name = format!("{} {seed:?}", path.display());
            let Posed {
                proposal,
                removals,
                recut,
                ups,
                rot,
                t,
            } = proposed(path, seed);
            // The ups, as built: along the web's normal.
            let ups: Vec<f64> = ups.iter().map(|u| u.z).collect();
            assert!(
                ups.iter().all(|z| (z.abs() - 1.0).abs() < 1e-9),
                "{name}: {ups:?}"
            );
            assert_eq!(
                ups.len(),
                1 + usize::from(truth.both_sides),
                "{name}: {ups:?}"
            );
            if !truth.both_sides {
                assert!(ups[0] > 0.0, "{name}: the flat underside first");
            }
            assert_eq!(proposal.residue.judged, Judged::Exact, "{name}");
            assert_eq!(recut, 0.0, "{name}");
            assert_adds_up(&removals, recut, &name);
            for p in &truth.pockets {
                let centre = p.inside();
                let at = rot * centre + t;
                let k = taken_by(&removals, &at)
                    .unwrap_or_else(|| panic!("{name}: no set-up takes the pocket at {centre}"));
                assert!(
                    ups[k] * p.side > 0.0,
                    "{name}: the pocket opening to {} is taken from up {}",
                    p.side,
                    ups[k]
                );
                pockets += 1;
            }
            two += usize::from(ups.len() == 2);
            sides.push(ups.iter().map(|z| z.signum()).collect::<Vec<_>>());
        }
        assert_eq!(
            sides[0],
            sides[1],
            "{}: the turned copy's set-ups",
            path.display()
        );
    }
    eprintln!("{} panels as built and turned: {two} with two set-ups, {pockets} pockets each in the set-up facing it", parts.len());
    assert!(two > 0);
}

#[derive(serde::Deserialize)]
struct HolesTruth {
    upright: bool,
    holes: Vec<HoleTruth>,
}

#[derive(serde::Deserialize)]
struct HoleTruth {
    direction: [f64; 3],
}

/// Plates with holes: flat ones get one set-up (along the holes), upright
/// ones (holes across the part's height) a set-up along the holes' axis
/// after the first, judged at points (not opposite the first): nothing is
/// left, as built and turned.
#[test]
fn holes_across_the_part_get_a_set_up_along_them_in_any_pose() {
    let parts = common::generated_parts("THINWALL_HOLES_DIR", "holes");
    let mut along = 0;
    for (k, path) in parts.iter().enumerate() {
        let truth: HolesTruth = truth_of(path);
        let axis = Vector3::from(truth.holes[0].direction);
        in_both_poses(path, 4600 + k as u64, |name, posed| {
            let ups = &posed.ups;
            let on_axis = ups.iter().any(|u| u.dot(&axis).abs() > 1.0 - 1e-9);
            assert!(on_axis, "{name}: no set-up along the holes: {ups:?}");
            if truth.upright {
                assert!(ups.len() >= 2, "{name}: {ups:?}");
                along += 1;
            }
            assert_adds_up(&posed.removals, posed.recut, name);
            eprintln!(
                "{name}: {} set-up(s), {:.1} mm³ perhaps cut again",
                ups.len(),
                posed.recut
            );
        });
    }
    assert!(along > 0);
}

#[derive(serde::Deserialize)]
struct FeaturesTruth {
    features: Vec<FeatureTruth>,
    volume: f64,
}

#[derive(serde::Deserialize)]
struct FeatureTruth {
    kind: String,
    #[serde(default)]
    direction: Option<[f64; 3]>,
}

/// Plates with a drafted pocket (cones at its corners), a hole tilted
/// 35–50° (part of it under material from both sides) and a spherical
/// dimple (`scripts/make_feature_fixtures.py`), as built and turned: two
/// set-ups, the first along the plate's normal, the second along the tilted
/// hole's axis; nothing left; the removal's part volume is OpenCascade's
/// within its bound, and the set-ups' volumes add up to stock − part.
#[test]
fn a_tilted_hole_gets_a_set_up_along_it_in_any_pose() {
    let parts = common::generated_parts("THINWALL_FEATURES_DIR", "features");
    assert!(!parts.is_empty());
    for (k, path) in parts.iter().enumerate() {
        let truth: FeaturesTruth = truth_of(path);
        let hole = truth
            .features
            .iter()
            .find(|f| f.kind == "tilted_hole")
            .and_then(|f| f.direction)
            .expect("a tilted hole");
        let axis = Vector3::from(hole);
        in_both_poses(path, 4700 + k as u64, |name, posed| {
            let ups = &posed.ups;
            assert_eq!(ups.len(), 2, "{name}: {ups:?}");
            assert!(ups[0].z > 1.0 - 1e-9, "{name}: first {:?}", ups[0]);
            assert!(
                ups[1].dot(&axis).abs() > 1.0 - 1e-9,
                "{name}: second {:?}",
                ups[1]
            );
            let first = &posed.removals[0];
            let bound = first.meshed.volume_bound_mm3 + 1e-6 * first.stock_volume;
            assert!(
                (first.part_volume - truth.volume).abs() <= bound,
                "{name}: part volume {} against OpenCascade's {} (bound {bound})",
                first.part_volume,
                truth.volume
            );
            assert_adds_up(&posed.removals, posed.recut, name);
        });
    }
}

/// The height maps the candidates are ranked on (`heights.rs`) against the
/// exact removal, on the generated panels and feature plates: what each
/// candidate up reaches within 1 % of stock − part and a thousandth of the
/// stock (a square's width along the walls).
#[test]
fn height_maps_estimate_what_an_up_reaches() {
    let mut parts = common::generated_parts("THINWALL_POCKETS_DIR", "pockets");
    parts.extend(common::generated_parts("THINWALL_FEATURES_DIR", "features"));
    let mut compared = 0;
    for path in &parts {
        let (part, _) = thinwall_step::read_file(path).unwrap();
        let a = PartAnalysis::new(&part, Setup::default());
        for c in thinwall_setups::choice::up_candidates(&a) {
            let up = nalgebra::Vector3::from(c.up);
            let r = &thinwall_setups::turn::removals_along(&a, &[up]).unwrap()[0];
            let exact: f64 = thinwall_ops::layers::reachable(r).map(|b| b.volume).sum();
            let whole = r.stock_volume - r.part_volume;
            let estimate = c.reachable_mm3.unwrap();
            assert!(
                (estimate - exact).abs() <= 0.01 * whole + 1e-3 * r.stock_volume,
                "{} up {:?}: {estimate} mm³ on the map, {exact} exactly (of {whole})",
                path.display(),
                c.up
            );
            compared += 1;
        }
    }
    assert!(compared > 0);
}
