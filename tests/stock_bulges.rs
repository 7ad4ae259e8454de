//! Curved faces that rise above all their edges (issue 37): a half-torus
//! bead on a plate, a spherical dome, a bead hanging from the underside
//! (`scripts/make_bulge_fixtures.py`, with their truth). The stock holds
//! their crests, not only their edges — before, the block stopped at the
//! edges and the removal refused NIST FTC 11 ("the stock does not contain
//! the part"); the dome's column is read where its pole does not touch the
//! stock's top — before, the block over the dome read as empty at the pole
//! and the removal was hundreds of mm³ off. As built and turned, set up
//! from either side; the part's volume is the closed form's to 1e-6.

mod common;

use nalgebra::Vector3;
use thinwall_analysis::parallel::Work;
use thinwall_analysis::{Machine, PartAnalysis, Setup};
use thinwall_machining::stock::Stock;
use thinwall_removal::{frame_of, Removal, StockShape};

#[derive(serde::Deserialize)]
struct Truth {
    length: f64,
    width: f64,
    lo: [f64; 3],
    hi: [f64; 3],
    /// In closed form (the plate, half tori, a spherical cap), mm³.
    volume: f64,
}

fn parts() -> Vec<std::path::PathBuf> {
    common::generated_parts("THINWALL_BULGES_DIR", "bulges")
}

#[test]
fn the_stock_holds_the_crests_and_the_removal_adds_up_in_any_pose() {
    let mut checked = 0;
    for path in parts() {
        let truth: Truth = serde_json::from_str(
            &std::fs::read_to_string(path.with_extension("truth.json")).unwrap(),
        )
        .unwrap();
        let text = std::fs::read_to_string(&path).unwrap();
        for seed in [None, Some(3), Some(17)] {
            for sign in [1.0, -1.0] {
                let what = format!("{} {seed:?} up {sign}", path.display());
                check_pose(&common::posed_step(&text, seed), seed, sign, &truth, &what);
                checked += 1;
            }
        }
    }
    assert!(checked >= 18, "{checked} poses");
}

fn check_pose(text: &str, seed: Option<u64>, sign: f64, truth: &Truth, what: &str) {
    let (part, _) = thinwall_step::read_bytes(text.as_bytes(), "bulges.step").unwrap();
    let (rot, shift) = seed.map_or(
        (nalgebra::Rotation3::identity(), Vector3::zeros()),
        common::rigid_motion,
    );
    let up = rot * Vector3::z() * sign;
    let a = PartAnalysis::new(
        &part,
        Setup::new([up.x, up.y, up.z], Machine::ThreeAxis).unwrap(),
    );
    let size = a.bounding_box().diagonal();
    let tol = 1e-6 * size;
    // Along up: the crests (the truth's z range, moved with the part).
    let (lo, hi) = along(&Stock::of(&a, Some(up)), &up);
    let at = shift.dot(&up);
    let (want_lo, want_hi) = if sign > 0.0 {
        (truth.lo[2] + at, truth.hi[2] + at)
    } else {
        (-truth.hi[2] + at, -truth.lo[2] + at)
    };
    assert!(
        (lo - want_lo).abs() < tol && (hi - want_hi).abs() < tol,
        "{what}: stock along up {lo}..{hi}, crests {want_lo}..{want_hi}"
    );
    // Across: the plate (no bulge reaches past its sides).
    let (frame, slo, shi) = frame_of(&a, up);
    let mut across = [shi[0] - slo[0], shi[1] - slo[1]];
    across.sort_by(|x, y| y.total_cmp(x));
    let mut plate = [truth.length, truth.width];
    plate.sort_by(|x, y| y.total_cmp(x));
    for k in 0..2 {
        assert!(
            (across[k] - plate[k]).abs() < tol,
            "{what}: {across:?} against {plate:?}"
        );
    }
    let r = Removal::new(
        &part,
        frame,
        &StockShape::Block { lo: slo, hi: shi },
        &[],
        size,
        Work::serial(),
    )
    .and_then(Removal::checked)
    .unwrap_or_else(|e| panic!("{what}: {e}"));
    assert!(
        (r.part_volume - truth.volume).abs() < 1e-6 * truth.volume,
        "{what}: part {} against {} in closed form",
        r.part_volume,
        truth.volume
    );
    let stock = (shi[0] - slo[0]) * (shi[1] - slo[1]) * (shi[2] - slo[2]);
    assert!(
        (r.removed_volume() - (stock - r.part_volume)).abs() < 1e-6 * stock,
        "{what}: removed {} of {}",
        r.removed_volume(),
        stock - r.part_volume
    );
}

/// The stock's extent along its axis nearest `up`, seen along `up`.
fn along(stock: &Stock, up: &Vector3<f64>) -> (f64, f64) {
    let k = (0..3)
        .max_by(|&i, &j| {
            stock.axes[i]
                .dot(up)
                .abs()
                .total_cmp(&stock.axes[j].dot(up).abs())
        })
        .unwrap();
    let (lo, hi) = (-stock.plane_offset(2 * k), stock.plane_offset(2 * k + 1));
    if stock.axes[k].dot(up) > 0.0 {
        (lo, hi)
    } else {
        (-hi, -lo)
    }
}
