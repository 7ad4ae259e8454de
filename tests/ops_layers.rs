//! Roughing layers and cutter fields (issue 17, Schuster): a level at
//! every upward flat face, sections that keep every block's area, fields
//! with blank and part contours; hand values on a fixture with two closed
//! pockets.

mod common;

use thinwall_analysis::parallel::Work;

use thinwall_analysis::{Machine, PartAnalysis, Setup};
use thinwall_geom::{Frame, Vector3};
use thinwall_ops::layers::{
    levels, out_of_reach_mm3, roughing_layers, section_area_by_blocks, EdgeKind, LayerOptions,
};
use thinwall_removal::pieces::{Facing, Height};
use thinwall_removal::{frame_of, Removal, RemovalError, StockShape};

fn removal(part: &thinwall_brep::Part) -> Result<Removal, RemovalError> {
    let a = PartAnalysis::new(
        part,
        Setup::new([0.0, 0.0, 1.0], Machine::ThreeAxis).unwrap(),
    );
    let (frame, lo, hi) = frame_of(&a, Vector3::z());
    Removal::new(
        part,
        frame,
        &StockShape::Block { lo, hi },
        &[],
        a.bounding_box().diagonal(),
        Work::serial(),
    )
}

/// The sections at `z` of the blocks bounded by a meshed face, mm².
fn meshed_section_area(r: &Removal, z: f64) -> f64 {
    use thinwall_removal::Bound;
    let meshed = |b: &Bound| match *b {
        Bound::Part(i) => r.meshed.faces.contains(&r.part_pieces[i].step_id),
        Bound::Stock(i) => r.meshed.faces.contains(&r.stock_pieces[i].step_id),
        Bound::Flat(_) => false,
    };
    thinwall_ops::layers::reachable(r)
        .filter(|b| meshed(&b.lower) || meshed(&b.upper))
        .map(|b| geo::Area::unsigned_area(&thinwall_removal::slab::section(r, b, z)))
        .sum()
}

/// `fixtures/access/pockets.step`: a 60 × 40 × 20 block with two closed
/// pockets 10 deep, 10 × 30 and 24 × 30 (the stock is the block itself).
/// With a_p = 4 the levels are 16, 12 and the floors at 10; every layer's
/// section is the two pockets, 300 + 720 = 1020 mm², two fields walled by
/// the part all round; 1020 × 10 = 10,200 mm³ is the removal. A smallest
/// tool of Ø12 cannot enter the 10 mm pocket.
#[test]
fn two_closed_pockets_by_hand() {
    let part = thinwall_step::read_file(common::root().join("fixtures/access/pockets.step"))
        .unwrap()
        .0;
    let r = removal(&part).unwrap();
    let opts = LayerOptions {
        axial_depth_mm: 4.0,
        smallest_tool_mm: 12.0,
        ..Default::default()
    };
    let layers = roughing_layers(&r, &opts);
    let z: Vec<f64> = layers.iter().map(|l| l.z_bottom_mm).collect();
    let want = [16.0, 12.0, 10.0];
    assert_eq!(z.len(), 3, "{z:?}");
    for (got, want) in z.iter().zip(want) {
        assert!((got - want).abs() < 1e-9, "{z:?}");
    }
    assert_eq!(layers[2].floors.len(), 2, "both pocket floors at 10");
    assert!(layers[0].floors.is_empty());
    let mut volume = 0.0;
    for l in &layers {
        assert!(
            (l.area_mm2 - 1020.0).abs() < 1e-6 * 1020.0,
            "{}",
            l.area_mm2
        );
        assert_eq!(l.fields.len(), 2);
        for f in &l.fields {
            assert!(f.islands.is_empty());
            assert!(f.outer.edges.iter().all(|&e| e == EdgeKind::Part));
            let narrow = (f.area_mm2 - 300.0).abs() < 1e-6 * 300.0;
            assert_eq!(f.too_small, narrow, "{f:?}");
            let d = if narrow { 10.0 } else { 24.0 };
            assert!(
                (f.inscribed_diameter_mm - d).abs() < 1e-3 * d,
                "{}",
                f.inscribed_diameter_mm
            );
        }
        volume += l.area_mm2 * (l.z_top_mm - l.z_bottom_mm);
    }
    assert!((volume - 10_200.0).abs() < 1e-6 * 10_200.0, "{volume}");
    assert!((r.removed_volume() - 10_200.0).abs() < 1e-6 * 10_200.0);
}

/// Every thin-walled part and recognition fixture: a level at every flat
/// face facing up within the removal, each layer's joined section keeps
/// the area of every block's section (1e-6), its fields add up to it,
/// every contour edge is marked; where every face is flat or vertical the
/// layers stack up to the removal's volume exactly.
#[test]
fn every_thin_walled_part_gets_levels_at_its_floors_and_exact_sections() {
    let (mut prismatic, mut parts, mut unsupported) = (0, 0, 0);
    for path in common::thin_walled_parts() {
        let part = thinwall_step::read_file(&path).unwrap().0;
        // The removal decomposition takes faces that are graphs over the
        // set-up plane; a cylinder tilted to the axis is refused by name.
        let r = match removal(&part) {
            Ok(r) => r,
            Err(e) => {
                assert_eq!(e.code(), "unsupported_face", "{}: {e}", path.display());
                unsupported += 1;
                continue;
            }
        };
        parts += 1;
        let opts = LayerOptions {
            axial_depth_mm: 6.0,
            smallest_tool_mm: 4.0,
            ..Default::default()
        };
        let layers = roughing_layers(&r, &opts);
        let what = path.display().to_string();
        let tol = 1e-6 * r.size;
        let lv = levels(&r, 6.0, tol);
        let (top, bottom) = (
            layers.first().map_or(0.0, |l| l.z_top_mm),
            layers.last().map_or(0.0, |l| l.z_bottom_mm),
        );
        for p in &r.part_pieces {
            if let (Facing::Up, &Height::Plane { z0, gx, gy, .. }) = (p.facing, &p.height) {
                if gx == 0.0 && gy == 0.0 && z0 > bottom + tol && z0 < top - tol {
                    assert!(
                        lv.iter()
                            .any(|l| (l.0 - z0).abs() <= tol && l.1.contains(&p.step_id)),
                        "{what}: no level at face #{} (z {z0})",
                        p.step_id
                    );
                }
            }
        }
        let mut volume = 0.0;
        for l in &layers {
            let blocks = section_area_by_blocks(&r, l.z_bottom_mm + tol);
            // Exact blocks tile the section; a meshed face's blocks may
            // overlap an exact neighbour's (heights crossing within the
            // deviation), never by more than their own sections.
            let overlap = meshed_section_area(&r, l.z_bottom_mm + tol);
            assert!(
                l.area_mm2 <= blocks + 1e-6 * blocks.max(1.0)
                    && l.area_mm2 >= blocks - overlap - 1e-6 * blocks.max(1.0),
                "{what}: layer {} joined {} mm², blocks {blocks}, meshed blocks {overlap}",
                l.index,
                l.area_mm2
            );
            // Every field is a region as the booleans read it: no outline
            // folded over itself (overlapping blocks), so what the tools
            // clear and leave adds up to it.
            for f in &l.fields {
                let field = geo::MultiPolygon::new(vec![f.polygon()]);
                let read =
                    thinwall_analysis::boolean::union(&field, &geo::MultiPolygon::new(vec![]));
                let read = geo::Area::unsigned_area(&read);
                assert!(
                    (read - f.area_mm2).abs() <= 1e-6 * f.area_mm2.max(1.0),
                    "{what}: layer {} field of {} mm² read as {read}",
                    l.index,
                    f.area_mm2
                );
            }
            for f in &l.fields {
                assert_eq!(f.outer.points.len(), f.outer.edges.len(), "{what}");
                assert!(f.area_mm2 > 0.0, "{what}");
            }
            volume += l.area_mm2 * (l.z_top_mm - l.z_bottom_mm);
        }
        let flat_or_vertical = part.face_ids().all(|f| {
            let p = thinwall_brep::props::compute_face_props(&part, f);
            matches!(part.face(f).surface, thinwall_geom::Surface::Plane { .. })
                && p.normal
                    .is_some_and(|n| n.z.abs() < 1e-9 || n.z.abs() > 1.0 - 1e-9)
        });
        if flat_or_vertical && !layers.is_empty() {
            // What lies under the part is another set-up's, not a layer's.
            let removed = r.removed_volume() - out_of_reach_mm3(&r);
            assert!(
                (volume - removed).abs() <= 1e-6 * removed,
                "{what}: layers {volume} mm³, removal {removed}"
            );
            prismatic += 1;
        }
    }
    assert!(prismatic >= 3, "{prismatic}");
    assert!(
        parts >= 4 * unsupported,
        "{parts} parts layered, {unsupported} refused"
    );
}

/// `fixtures/ops/pocket_islands.step` (scripts/make_ops_fixtures.py): a
/// pocket 100 × 80 with 3 mm corner radii and two 20 × 20 islands 14 mm
/// apart, tools {Ø20, Ø12, Ø6}. By hand (docs/OPERATIONS.md):
/// - the field: 100 · 80 − 4 · 3²(1 − π/4) − 2 · 400 = 7192.27 mm²;
/// - Ø20 does not fit between the islands. Its centre reaches (50, 30 − √51)
///   below the gap (10 from both island corners), and as far above it, so
///   it cuts into the gap two circular segments of radius 10 whose chord
///   is the gap's 14 mm: 100 acos(√51/10) − 7√51 = 27.55 mm² each. In each
///   corner it leaves (10² − 3²)(1 − π/4). It leaves 280 − 2 · 27.55 +
///   4 · 91 (1 − π/4) = 302.99 mm²;
/// - Ø12 fits the gap (its centre anywhere on x 49..51) and leaves only the
///   corners: 4 · (6² − 3²)(1 − π/4) = 23.18 mm²;
/// - Ø6 fits the corners' 3 mm radii: nothing is left.
///
/// With 128-gon disks the areas are within 0.3 % of these (and the rest
/// within 0.05 mm²).
#[test]
fn a_pocket_with_islands_takes_three_tools_by_hand() {
    use thinwall_ops::rest::select;
    let part = thinwall_step::read_file(common::root().join("fixtures/ops/pocket_islands.step"))
        .unwrap()
        .0;
    let r = removal(&part).unwrap();
    let layers = roughing_layers(
        &r,
        &LayerOptions {
            axial_depth_mm: 10.0,
            smallest_tool_mm: 6.0,
            ..Default::default()
        },
    );
    assert_eq!(layers.len(), 1, "one layer down to the floor at 10");
    let l = &layers[0];
    assert_eq!(l.fields.len(), 1);
    let field = &l.fields[0];
    assert_eq!(field.islands.len(), 2);
    let k = 1.0 - std::f64::consts::FRAC_PI_4;
    let area = 8000.0 - 4.0 * 9.0 * k - 800.0;
    assert!(
        (field.area_mm2 - area).abs() < 1e-3 * area,
        "{}",
        field.area_mm2
    );
    let lib = thinwall_ops::ToolLibrary::default_tools();
    let mills: Vec<_> = lib
        .end_mills()
        .filter(|t| [20.0, 12.0, 6.0].contains(&t.diameter_mm))
        .collect();
    assert_eq!(mills.len(), 3);
    let picked = select(field, &mills, &layers[0].floor_region, 0.0);
    let names: Vec<&str> = picked.shares.iter().map(|s| s.tool.as_str()).collect();
    assert_eq!(names, ["EM20", "EM12", "EM6"]);
    let segment = 100.0 * (51f64.sqrt() / 10.0).acos() - 7.0 * 51f64.sqrt();
    let left20 = 280.0 - 2.0 * segment + 4.0 * 91.0 * k;
    let left12 = 4.0 * 27.0 * k;
    let want = [area - left20, left20 - left12, left12];
    for (s, w) in picked.shares.iter().zip(want) {
        assert!(
            (s.cleared_mm2 - w).abs() < 3e-3 * w,
            "{}: {} mm², by hand {w}",
            s.tool,
            s.cleared_mm2
        );
    }
    assert!(picked.rest_mm2 < 0.05, "{}", picked.rest_mm2);
    // The shares and the rest make up the field.
    let total: f64 = picked.shares.iter().map(|s| s.cleared_mm2).sum::<f64>() + picked.rest_mm2;
    assert!((total - field.area_mm2).abs() < 1e-6 * field.area_mm2);
}

/// The operations of every thin-walled part: the order never breaks a
/// precedence, has no more tool changes than the plain layer by layer
/// order; in every layer what the rough, semi-finish and wall-finish
/// operations clear plus the rest is the layer's section (1e-6), their
/// regions add up to their areas (a wall finish's all boundary, the others'
/// none), a wall finish follows its tool's roughing of the layer, a floor's finish lies over the layer's floors, and the
/// volumes of the layer's operations add up to its section times its
/// thickness.
#[test]
fn operations_keep_their_order_and_add_up() {
    use thinwall_ops::operations::{operations, Stage};
    let lib = thinwall_ops::ToolLibrary::default_tools();
    let mut parts = common::thin_walled_parts();
    parts.push(common::root().join("fixtures/ops/pocket_islands.step"));
    parts.push(common::root().join("fixtures/ops/drill_plate.step"));
    // Pocketed plates with corner radii and floor fillets, and holes with
    // their countersinks and counterbores: faces across up are meshed.
    parts.extend(common::step_files(&common::root().join("fixtures/pockets")));
    parts.extend(common::step_files(&common::root().join("fixtures/holes")));
    let (mut fewer, mut ran, mut finishes, mut drilled_holes) = (0, 0, 0, 0);
    let (mut wall_finishes, mut meshed) = (0, 0);
    for path in parts {
        let part = thinwall_step::read_file(&path).unwrap().0;
        let Ok(r) = removal(&part).and_then(Removal::checked) else {
            continue;
        };
        meshed += usize::from(!r.meshed.is_empty());
        let a = PartAnalysis::new(
            &part,
            Setup::new([0.0, 0.0, 1.0], Machine::ThreeAxis).unwrap(),
        );
        let holes =
            thinwall_ops::drilling::hole_sites(&common::features_in_setup(&a), &r.frame, &lib);
        drilled_holes += holes.iter().filter(|h| h.drill.is_some()).count();
        let plan = operations(&r, &lib, None, &[], &holes, Work::serial());
        let what = path.display().to_string();
        for op in &plan.operations {
            assert!(
                op.after.iter().all(|&s| s < op.step),
                "{what}: step {}",
                op.step
            );
            assert!(op.time_min.is_finite() && op.time_min >= 0.0, "{what}");
            assert!(op.volume_mm3 >= -1e-9, "{what}: step {}", op.step);
            if let Some(g) = op.regions {
                let sum = g.boundary_mm2 + g.full_cut_mm2 + g.roughing_mm2;
                assert!(
                    (sum - op.area_mm2).abs() <= 1e-6 * op.area_mm2.max(1.0),
                    "{what}: step {}: regions {g:?}, area {}",
                    op.step,
                    op.area_mm2
                );
            }
            assert_eq!(
                op.regions.is_none(),
                matches!(op.stage, Stage::Finish | Stage::Drill)
            );
            // A wall finish is its tool's boundary region alone, after
            // that tool's roughing of the layer where it roughed there.
            if op.stage == Stage::FinishWalls {
                let g = op.regions.unwrap();
                assert!(g.full_cut_mm2 == 0.0 && g.roughing_mm2 == 0.0, "{what}");
                wall_finishes += 1;
                for p in &op.passes {
                    let rough = plan.operations.iter().find(|o| {
                        matches!(o.stage, Stage::Rough | Stage::SemiFinish)
                            && o.tool == op.tool
                            && o.passes.iter().any(|q| q.layer == p.layer)
                    });
                    if let Some(r) = rough {
                        assert!(r.step < op.step, "{what}: step {}", op.step);
                    }
                }
            } else if op.stage.clears() {
                assert!(op.regions.unwrap().boundary_mm2 == 0.0, "{what}");
            }
            // An operation's figures are its passes' added up, its passes
            // in consecutive layers top down.
            if op.stage != Stage::Drill {
                let area: f64 = op.passes.iter().map(|p| p.area_mm2).sum();
                let volume: f64 = op.passes.iter().map(|p| p.volume_mm3).sum();
                assert!((area - op.area_mm2).abs() <= 1e-9 * area.max(1.0));
                assert!((volume - op.volume_mm3).abs() <= 1e-9 * volume.max(1.0));
                assert!(op.passes.windows(2).all(|w| w[0].layer < w[1].layer));
            }
        }
        assert!(plan.tool_changes <= plan.plain_tool_changes, "{what}");
        fewer += usize::from(plan.tool_changes < plan.plain_tool_changes);
        for (k, l) in plan.layers.iter().enumerate() {
            // Every pass in this layer, with its operation's stage.
            let ops = || {
                plan.operations.iter().flat_map(move |o| {
                    o.passes
                        .iter()
                        .filter(move |p| p.layer == k)
                        .map(move |p| (o.stage, p))
                })
            };
            let cleared: f64 = ops()
                .filter(|(s, _)| s.clears())
                .map(|(_, p)| p.area_mm2)
                .sum();
            // Every field's rest, the listed ones and those below the
            // disks' polygon noise alike.
            let rest: f64 = plan.field_tools[k].iter().map(|f| f.rest_mm2).sum();
            let drilled: f64 = l
                .fields
                .iter()
                .zip(&plan.field_tools[k])
                .filter(|(_, ft)| ft.drilled.is_some())
                .map(|(f, _)| f.area_mm2)
                .sum();
            assert!(
                (cleared + rest + drilled - l.area_mm2).abs() <= 1e-6 * l.area_mm2.max(1.0),
                "{what}: layer {k}: {cleared} cleared + {rest} rest + {drilled} drilled, section {}",
                l.area_mm2
            );
            let floor: f64 = ops()
                .filter(|(s, _)| *s == Stage::Finish)
                .map(|(_, p)| p.area_mm2)
                .sum();
            let floors = geo::Area::unsigned_area(&l.floor_region);
            assert!(
                floor <= floors + 1e-6 * floors.max(1.0),
                "{what}: layer {k}"
            );
            finishes += ops().filter(|(s, _)| *s == Stage::Finish).count();
            let volume: f64 = ops().map(|(_, p)| p.volume_mm3).sum();
            let h = l.z_top_mm - l.z_bottom_mm;
            assert!(
                (volume - cleared * h).abs() <= 1e-6 * (cleared * h).max(1.0),
                "{what}: layer {k}: {volume} mm³ in operations, {} cleared",
                cleared * h
            );
        }
        ran += 1;
    }
    assert!(finishes > 0 && wall_finishes > 0 && drilled_holes >= 5);
    eprintln!(
        "OPS {ran} parts ({meshed} with meshed faces), fewer changes on {fewer}, {finishes} floor finishes, {wall_finishes} wall finishes, {drilled_holes} holes drilled"
    );
    assert!(ran >= 38 && meshed >= 8, "{ran} parts, {meshed} meshed");
}

#[derive(serde::Deserialize)]
struct PanelTruth {
    web_z: [f64; 2],
    both_sides: bool,
    pockets: Vec<PanelPocket>,
}

#[derive(serde::Deserialize)]
struct PanelPocket {
    side: f64,
    hole: f64,
}

/// One generated panel posed by `seed`: the volume a tool along up does
/// not reach, the reachable removal, and per layer under the web's
/// underside (in the removal frame) its area; the lightening holes' area;
/// the bound on volumes (meshed faces) and the part's size.
fn panel_layers(path: &std::path::Path, seed: Option<u64>) -> (f64, f64, Vec<f64>, f64, f64, f64) {
    let truth: PanelTruth =
        serde_json::from_str(&std::fs::read_to_string(path.with_extension("truth.json")).unwrap())
            .unwrap();
    let (rot, t) = seed.map_or(
        (nalgebra::Rotation3::identity(), nalgebra::Vector3::zeros()),
        common::rigid_motion,
    );
    // Turned or not, the removal adds up (its arcs are cut alike in any
    // pose: `sample::turn_points`).
    let (r, frame, size) = posed_removal(path, seed, 1.0);
    let underside = rot * nalgebra::Point3::new(0.0, 0.0, truth.web_z[0]) + t;
    let z_under = frame.to_local(&underside).z;
    let tol = 1e-6 * size;
    let opts = LayerOptions {
        axial_depth_mm: 6.0,
        smallest_tool_mm: 4.0,
        ..Default::default()
    };
    let below: Vec<f64> = roughing_layers(&r, &opts)
        .iter()
        .filter(|l| l.z_top_mm <= z_under + tol)
        .map(|l| l.area_mm2)
        .collect();
    let holes: f64 = truth
        .pockets
        .iter()
        .filter(|p| p.side > 0.0)
        .map(|p| std::f64::consts::PI * p.hole * p.hole / 4.0)
        .sum();
    let out = out_of_reach_mm3(&r);
    assert_eq!(
        out > 0.0,
        truth.both_sides,
        "{} {seed:?}: {out} mm³ out of reach",
        path.display()
    );
    // The removal's own precision (it refuses itself past it).
    let bound = r.meshed.volume_bound_mm3 + 1e-6 * r.stock_volume;
    (out, r.removed_volume() - out, below, holes, bound, size)
}

/// Generated pocketed panels (issue 37/38: pockets on both sides of a
/// web), as built and turned: what lies under the web is left to another
/// set-up (a volume, for panels pocketed from both sides only); no layer
/// under the web's underside cuts more than the lightening holes through
/// it; the removal adds up in either pose, and the turned copy leaves and
/// layers the same volumes (within each removal's precision).
#[test]
fn a_set_up_layers_only_what_its_up_reaches_in_any_pose() {
    let parts = common::generated_parts("THINWALL_POCKETS_DIR", "pockets");
    let (mut two_sided, mut layers_below) = (0, 0);
    for (k, path) in parts.iter().enumerate() {
        let poses = [
            ("as built", panel_layers(path, None)),
            ("turned", panel_layers(path, Some(4100 + k as u64))),
        ];
        for (pose, (out, _, below, holes, _, size)) in &poses {
            for area in below {
                // The stock box fits a turned part to rounding: a band of
                // that width (1e-6 × size) along its outline may remain.
                let noise = 4.0 * 1e-6 * size * size;
                assert!(
                    *area <= holes + 1e-6 * holes.max(1.0) + noise,
                    "{} {pose}: a layer under the web cuts {area} mm², the holes through it {holes}",
                    path.display()
                );
                layers_below += 1;
            }
            two_sided += usize::from(*out > 0.0);
        }
        let [(_, built), (_, turned)] = &poses;
        // The split between this set-up and another does not depend on
        // the pose beyond each removal's precision.
        let bound = built.4 + turned.4;
        assert!(
            (built.0 - turned.0).abs() <= bound && (built.1 - turned.1).abs() <= bound,
            "{}: out of reach {} / {}, reachable {} / {} (bound {bound})",
            path.display(),
            built.0,
            turned.0,
            built.1,
            turned.1
        );
    }
    eprintln!(
        "{} panels as built and turned: {two_sided} poses leave material to another set-up, \
         {layers_below} layers under a web",
        parts.len()
    );
    assert!(two_sided > 0);
}

/// One generated panel posed by `seed`, its removal with up along the
/// panel's +z turned (`sign` 1) or against it (−1), checked; the frame.
fn posed_removal(path: &std::path::Path, seed: Option<u64>, sign: f64) -> (Removal, Frame, f64) {
    let text = common::posed_step(&std::fs::read_to_string(path).unwrap(), seed);
    let (part, _) = thinwall_step::read_bytes(text.as_bytes(), "panel.step").unwrap();
    let (rot, _) = seed.map_or(
        (nalgebra::Rotation3::identity(), nalgebra::Vector3::zeros()),
        common::rigid_motion,
    );
    let up = rot * Vector3::z() * sign;
    let a = PartAnalysis::new(
        &part,
        Setup::new([up.x, up.y, up.z], Machine::ThreeAxis).unwrap(),
    );
    let (frame, lo, hi) = frame_of(&a, up);
    let size = a.bounding_box().diagonal();
    let r = Removal::new(
        &part,
        frame,
        &StockShape::Block { lo, hi },
        &[],
        size,
        Work::serial(),
    )
    .and_then(Removal::checked)
    .unwrap_or_else(|e| panic!("{} {seed:?} up {sign}: {e}", path.display()));
    (r, frame, size)
}

/// Both sides of the generated panels, one set-up after the other (issue
/// 37), as built and turned: the set-up from the opposite side, after the
/// first, cuts what the first could not reach under the web (what it left
/// = what the second cuts + what neither reaches, within both removals'
/// precision; neither leaves nothing on these panels); the first
/// side's pockets and through columns (lightening holes) are gone, so the
/// second side's layers stop at the web's underside.
#[test]
fn the_opposite_side_cuts_what_the_first_left_in_any_pose() {
    let parts = common::generated_parts("THINWALL_POCKETS_DIR", "pockets");
    let (mut sides, mut layers) = (0, 0);
    for (k, path) in parts.iter().enumerate() {
        let truth: PanelTruth = serde_json::from_str(
            &std::fs::read_to_string(path.with_extension("truth.json")).unwrap(),
        )
        .unwrap();
        for seed in [None, Some(4200 + k as u64)] {
            let (first, _, size) = posed_removal(path, seed, 1.0);
            let (second, frame, _) = posed_removal(path, seed, -1.0);
            let second = second.after_opposite();
            let cut: f64 = thinwall_ops::layers::reachable(&second)
                .map(|b| b.volume)
                .sum();
            let (left, neither) = (out_of_reach_mm3(&first), out_of_reach_mm3(&second));
            let bound = first.meshed.volume_bound_mm3
                + second.meshed.volume_bound_mm3
                + 1e-6 * (first.stock_volume + second.stock_volume);
            let name = format!("{} {seed:?}", path.display());
            assert_eq!(neither, 0.0, "{name}: neither side reaches {neither} mm³");
            assert!(
                (left - cut).abs() <= bound,
                "{name}: the first left {left} mm³, the second cuts {cut} (bound {bound})"
            );
            // A turned one-sided panel leaves rounding, not material.
            let cuts = cut > thinwall_geom::tolerance::MERGE * second.stock_volume;
            assert_eq!(
                cuts, truth.both_sides,
                "{name}: the second side cuts {cut} mm³"
            );
            // The second side stops at the web's underside: beyond it all
            // was the first side's (the lightening holes too).
            let (rot, t) = seed.map_or(
                (nalgebra::Rotation3::identity(), nalgebra::Vector3::zeros()),
                common::rigid_motion,
            );
            let underside = rot * nalgebra::Point3::new(0.0, 0.0, truth.web_z[0]) + t;
            let z_under = frame.to_local(&underside).z;
            let opts = LayerOptions {
                axial_depth_mm: 6.0,
                smallest_tool_mm: 4.0,
                ..Default::default()
            };
            for l in roughing_layers(&second, &opts) {
                if l.area_mm2 > 4.0 * 1e-6 * size * size {
                    assert!(
                        l.z_bottom_mm >= z_under - 1e-6 * size,
                        "{name}: the second side cuts {} mm² down to {}, beyond the web's underside at {z_under}",
                        l.area_mm2,
                        l.z_bottom_mm
                    );
                    layers += 1;
                }
            }
            sides += usize::from(cuts);
        }
    }
    eprintln!(
        "{} panels as built and turned: {sides} second sides with material to cut, in {layers} layers, none beyond the web",
        parts.len()
    );
    assert!(sides > 0);
}

/// Choosing the set-up (issue 37) on the generated panels, as built and
/// turned: the chosen up is the one a planner would take first — the side
/// the pockets open to on a one-sided panel, on a two-sided one the side
/// (of the two the web faces) from which more is reachable — and a turned
/// copy chooses the same up turned with it.
#[test]
fn the_chosen_up_is_the_pockets_side_in_any_pose() {
    let parts = common::generated_parts("THINWALL_POCKETS_DIR", "pockets");
    for (k, path) in parts.iter().enumerate() {
        let truth: PanelTruth = serde_json::from_str(
            &std::fs::read_to_string(path.with_extension("truth.json")).unwrap(),
        )
        .unwrap();
        let mut chosen = Vec::new();
        for seed in [None, Some(4300 + k as u64)] {
            let text = common::posed_step(&std::fs::read_to_string(path).unwrap(), seed);
            let (part, _) = thinwall_step::read_bytes(text.as_bytes(), "panel.step").unwrap();
            let a = PartAnalysis::new(&part, Setup::default());
            let c = thinwall_setups::choice::up_candidates(&a);
            let rot = seed.map_or(nalgebra::Rotation3::identity(), |s| {
                common::rigid_motion(s).0
            });
            let back = rot.inverse() * Vector3::from(c[0].up);
            let name = format!("{} {seed:?}", path.display());
            assert!(back.z.abs() > 1.0 - 1e-9, "{name}: chose {:?}", c[0].up);
            if !truth.both_sides {
                assert!(back.z > 0.0, "{name}: chose the flat underside");
            }
            // The chosen up reaches at least as much as any other tried.
            let best = c[0].reachable_mm3.unwrap();
            assert!(c
                .iter()
                .all(|x| x.reachable_mm3.unwrap_or(0.0) <= best + 1e-6 * best));
            chosen.push(back.z.signum());
        }
        assert_eq!(
            chosen[0],
            chosen[1],
            "{}: the turned copy chose another side",
            path.display()
        );
    }
}

/// NIST FTC 07 (milled from its side): of the ups its faces face (faces
/// drafted a degree off the block's sides join them: no two candidates
/// within 5°), the chosen one reaches most of stock − part (the default +Z
/// leaves most of it under the part); a candidate is reached or refused.
#[test]
fn a_real_part_gets_the_up_that_reaches_most() {
    let path = common::shared_data().join("nist/nist_ftc_07_asme1_ap242-e2.stp");
    let part = thinwall_step::read_file(&path).unwrap().0;
    let a = PartAnalysis::new(&part, Setup::default());
    let c = thinwall_setups::choice::up_candidates(&a);
    assert!(c.len() >= 2 && c.len() <= thinwall_setups::choice::MOST_CANDIDATES);
    for (i, x) in c.iter().enumerate() {
        for y in &c[i + 1..] {
            let cos = Vector3::from(x.up).dot(&Vector3::from(y.up));
            assert!(cos < thinwall_setups::choice::SAME_SETUP_COS, "{x:?} {y:?}");
        }
    }
    let best = &c[0];
    let (reached, left) = (best.reachable_mm3.unwrap(), best.out_of_reach_mm3.unwrap());
    assert!(reached > 0.8 * (reached + left), "{best:?}");
    for x in &c[1..] {
        assert!(x.reachable_mm3.unwrap_or(0.0) <= reached, "{x:?}");
        assert!(x.reachable_mm3.is_some() != x.refused.is_some(), "{x:?}");
    }
}
