//! Faces the removal cannot take exactly (tilted cylinders and cones,
//! tori off the tool axis, free-form faces) become piecewise linear graph
//! pieces of their own triangles, split where their facing turns (issue
//! 37): NIST CTC 03, whose tilted holes refused every plan before, gets a
//! removal that adds up, whose part volume is the tessellation's within
//! the bound the plan reports, and the same plan on a turned copy (the
//! set-up turned with it).

mod common;

use thinwall_removal::Removal;

const CTC_03: &str = "nist/nist_ctc_03_asme1_ap242-e2.stp";

#[test]
fn tilted_holes_get_a_removal_that_adds_up() {
    let (part, r) = common::block_removal(&common::shared_data().join(CTC_03));
    let r = r
        .and_then(Removal::checked)
        .expect("a removal that adds up");
    let m = &r.meshed;
    assert!(!m.faces.is_empty() && m.triangles > 0, "{m:?}");
    assert!(m.deviation_mm > 0.0 && m.deviation_mm <= 0.005, "{m:?}");
    assert!((m.volume_bound_mm3 - m.deviation_mm * m.area_mm2 - m.overlap_mm3).abs() < 1e-9);
    let removed: f64 = r.blocks.iter().map(|b| b.volume).sum::<f64>() + r.sliver_volume;
    assert!(
        (removed - (r.stock_volume - r.part_volume)).abs() <= 1e-6 * r.stock_volume,
        "blocks {removed} against stock − part {}",
        r.stock_volume - r.part_volume
    );
    // The tessellation for pictures is coarser (its own deviation), so the
    // two agree to its precision, not the removal's.
    common::assert_part_volume_is_the_tessellations(&part, &r, 1e-3, "CTC 03");
}

#[test]
fn a_turned_copy_gets_the_same_plan() {
    let text = std::fs::read_to_string(common::shared_data().join(CTC_03)).unwrap();
    let rules = thinwall_plan::RuleSet::default_rules();
    let (_, built) = common::plan_text(&text, [0.0, 0.0, 1.0], &rules);
    let (r, t) = common::rigid_motion(37);
    let (turned_text, _) = common::turned_step(&text, &r, &t);
    let up = r * nalgebra::Vector3::new(0.0, 0.0, 1.0);
    let (_, turned) = common::plan_text(&turned_text, [up.x, up.y, up.z], &rules);
    let (a, b) = (&built.removal, &turned.removal);
    assert!(
        a.unavailable.is_none() && b.unavailable.is_none(),
        "{a:?} {b:?}"
    );
    assert_eq!(a.meshed.faces, b.meshed.faces);
    let bound =
        a.meshed.volume_bound_mm3.max(b.meshed.volume_bound_mm3) + 1e-6 * a.stock_volume_mm3;
    for (x, y, what) in [
        (a.stock_volume_mm3, b.stock_volume_mm3, "stock"),
        (a.part_volume_mm3, b.part_volume_mm3, "part"),
        (a.removed_volume_mm3, b.removed_volume_mm3, "removed"),
    ] {
        assert!(
            (x - y).abs() <= bound,
            "{what}: {x} as built, {y} turned (bound {bound})"
        );
    }
    assert_eq!(
        built.machining_features.len(),
        turned.machining_features.len(),
        "machining features"
    );
}

/// The generated pocketed panels (`fixtures/pockets`): corners where the
/// corner radius and the floor fillet meet are tori about up, or, where
/// the fillet is as large as the corner's offset, spindles OpenCascade
/// writes as surfaces of revolution (meshed; their seam turned away from
/// the face by the reader). Every panel gets a removal that adds up, whose
/// part volume is the tessellation's (`pockets_3`, tori only, was refused
/// as inconsistent until arcs were cut alike by angle: its corner
/// cylinders' top and bottom circles parted in projection).
#[test]
fn pocketed_panels_get_removals_that_add_up() {
    let panels = common::step_files(&common::root().join("fixtures/pockets"));
    let mut planned = Vec::new();
    for path in &panels {
        let (part, r) = common::block_removal(path);
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        let r = r
            .and_then(Removal::checked)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        common::assert_part_volume_is_the_tessellations(&part, &r, 1e-3, &name);
        planned.push(name);
    }
    eprintln!("removals that add up: {planned:?}");
    assert_eq!(planned.len(), panels.len(), "{planned:?}");
    assert!(
        planned.iter().any(|n| n == "pockets_1.step"),
        "a panel with spindle corners"
    );
}
