//! Every NIST B-rep part through the removal (issue 37): in its default
//! set-up (up +z, the block stock), each part's removal adds up to stock −
//! part, and its part volume is OpenCascade's (BRepGProp over the file's
//! solids, `scripts/check_volumes_occ.py`) within the meshed faces' bound
//! and 3e-6 of it (arcs keep their areas to 2e-7 and their outlines within
//! 5 µm; FTC 11's lettering has edges 0.014 mm off its walls); or it is
//! refused naming a face it cannot take, never a wrong volume; or it runs
//! past a time budget. All twelve add up (CTC 01 took over 400 s and 3 GB
//! while its drill-point cones' outlines had 60k–290k corners; FTC 10 was
//! refused until a blend's edge turning out round a boss and back was cut
//! as a curve, not as a turn, and lenses between two outlines of one
//! circle were told from material).

mod common;

use nalgebra::Vector3;
use std::time::Duration;
use thinwall_analysis::parallel::Work;
use thinwall_analysis::parallel::{Budget, OverBudget};
use thinwall_analysis::{Machine, PartAnalysis, Setup};
use thinwall_removal::{frame_of, Removal, RemovalError, StockShape};

/// OpenCascade 7.9's volume of each part's solids, mm³.
const OCC_VOLUMES: [(&str, f64); 12] = [
    ("nist_ctc_01", 14_644_823.285),
    ("nist_ctc_02", 47_106_842.245),
    ("nist_ctc_03", 332_122.908),
    ("nist_ctc_04", 17_519_780.215),
    ("nist_ctc_05", 12_694_917.588),
    ("nist_ftc_06", 3_323_557.222),
    ("nist_ftc_07", 1_726_244.148),
    ("nist_ftc_10", 188_318.068),
    ("nist_ftc_11", 5_135.058),
    ("nist_stc_06", 3_323_540.520),
    ("nist_stc_07", 1_726_247.281),
    ("nist_stc_08", 503_592.178),
];

/// Seconds a part's removal may take here.
const BUDGET_SECONDS: u64 = 120;

enum Outcome {
    AddsUp,
    Refused,
    OverBudget,
}

#[test]
fn every_nist_part_adds_up_to_opencascades_volume_or_names_why_not() {
    let (mut adds_up, mut refused, mut over) = (0, 0, 0);
    for path in common::step_files(&common::shared_data().join("nist")) {
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        let Some(&(_, occ)) = OCC_VOLUMES.iter().find(|(n, _)| name.starts_with(n)) else {
            continue; // tessellated only (FTC 08): no B-rep
        };
        match removal(&path, occ, &name) {
            Outcome::AddsUp => adds_up += 1,
            Outcome::Refused => refused += 1,
            Outcome::OverBudget => over += 1,
        }
    }
    eprintln!("{adds_up} add up, {refused} refused, {over} over {BUDGET_SECONDS} s");
    assert_eq!(adds_up, 12, "{refused} refused, {over} over the budget");
}

fn removal(path: &std::path::Path, occ: f64, name: &str) -> Outcome {
    let (part, _) = thinwall_step::read_file(path).unwrap();
    let a = PartAnalysis::new(
        &part,
        Setup::new([0.0, 0.0, 1.0], Machine::ThreeAxis).unwrap(),
    );
    let (frame, lo, hi) = frame_of(&a, Vector3::z());
    let size = a.bounding_box().diagonal();
    let budget = Budget::default();
    budget.start(Some(Duration::from_secs(BUDGET_SECONDS)));
    let run = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        Removal::new(
            &part,
            frame,
            &StockShape::Block { lo, hi },
            &[],
            size,
            Work::serial(),
        )
        .and_then(Removal::checked)
    }));
    budget.start(None);
    let r = match run {
        Ok(Ok(r)) => r,
        Ok(Err(e)) => {
            assert!(
                matches!(e, RemovalError::UnsupportedFace { .. }),
                "{name}: {e} (only a face it cannot take may be refused)"
            );
            assert!(e.to_string().starts_with("face #"), "{name}: {e}");
            return Outcome::Refused;
        }
        Err(payload) => {
            assert!(
                payload.downcast_ref::<OverBudget>().is_some(),
                "{name} panicked"
            );
            return Outcome::OverBudget;
        }
    };
    let bound = r.meshed.volume_bound_mm3 + 3e-6 * occ;
    assert!(
        (r.part_volume - occ).abs() <= bound,
        "{name}: part {} against OpenCascade's {occ} (bound {bound})",
        r.part_volume
    );
    let stock = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
    let removed = r.removed_volume() + r.sliver_volume;
    assert!(
        (removed - (stock - r.part_volume)).abs() <= 1e-6 * stock,
        "{name}: removed {removed} of {}",
        stock - r.part_volume
    );
    Outcome::AddsUp
}
