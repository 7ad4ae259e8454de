//! The planner's sequence constraints (issue 13) on the thin-walled parts of
//! `../shared/data/thinwall` and the recognition fixtures: acyclic, top-down
//! except where a higher rule says otherwise, flanges before their walls,
//! depressions with their walls; priorities decide between opposite rules;
//! redundancies and would-be cycles are rejected with their reasons; turned
//! copies (set-up turned alike) get the same plan.

mod common;

use thinwall_analysis::{FeatureId, StiffnessKind};
use thinwall_plan::{Plan, Rejection, Relation, RuleSet};

fn plan_text(text: &str, up: [f64; 3], rules: &RuleSet) -> Plan {
    common::plan_text(text, up, rules).1
}

fn plan_file(path: &std::path::Path, rules: &RuleSet) -> Plan {
    plan_text(
        &std::fs::read_to_string(path).unwrap(),
        [0.0, 0.0, 1.0],
        rules,
    )
}

fn parts() -> Vec<std::path::PathBuf> {
    let mut v = common::step_files(&common::shared_data().join("thinwall"));
    v.extend(common::step_files(
        &std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures/recognition"),
    ));
    v
}

/// Level of each feature in the plan's order.
fn level(p: &Plan, id: FeatureId) -> usize {
    p.order.iter().position(|l| l.contains(&id)).unwrap()
}

#[test]
fn default_rules_give_an_acyclic_top_down_plan_on_every_part() {
    let rules = RuleSet::default_rules();
    let mut checked = 0;
    for path in parts() {
        let p = plan_file(&path, &rules);
        let name = path.display().to_string();
        // Every feature has one level; constraints agree with the levels.
        let placed: usize = p.order.iter().map(Vec::len).sum();
        assert_eq!(placed, p.stiffness_features.len(), "{name}");
        for c in &p.sequence {
            let (a, b) = (level(&p, c.before), level(&p, c.after));
            match c.relation {
                Relation::Before => assert!(a < b, "{name}: {c:?}"),
                Relation::Simultaneous => assert_eq!(a, b, "{name}: {c:?}"),
            }
        }
        for f in &p.stiffness_features {
            let Some(base) = p.connections.iter().find_map(|c| match c {
                thinwall_connect::Connection::BaseLeaf { base, leaf } if *leaf == f.id => {
                    Some(*base)
                }
                _ => None,
            }) else {
                continue;
            };
            match f.kind {
                // A flange precedes the wall it is on.
                StiffnessKind::Flange => {
                    assert!(
                        p.queries.predecessors(base, true).contains(&f.id),
                        "{name}: {} on {base}",
                        f.id
                    )
                }
                // Holes and cut-outs go with their wall.
                StiffnessKind::Hole | StiffnessKind::Cutout => {
                    assert!(
                        p.queries.simultaneous(base).contains(&f.id),
                        "{name}: {} in {base}",
                        f.id
                    )
                }
                _ => {}
            }
        }
        // Top-down: a top-down candidate is enforced, implied already, or
        // rejected only because a higher rule's constraint is in the way.
        for r in p.rejected.iter().filter(|r| r.rule == "top-down") {
            if r.reason != Rejection::Redundant {
                assert!(
                    r.because.iter().any(|c| c.rule != "top-down"),
                    "{name}: {}",
                    r.explanation
                );
            }
        }
        // Every thin wall has sizes; a part with none gets none (an honest
        // empty list, not an error).
        let thin = p
            .stiffness_features
            .iter()
            .filter(|f| f.thin == Some(true) && f.kind.is_wall())
            .count();
        assert_eq!(p.walls.len(), thin, "{name}");
        if name.contains("thick_block") {
            assert!(
                p.walls.is_empty(),
                "{name}: {:?}",
                p.walls.iter().map(|w| w.id).collect::<Vec<_>>()
            );
        }
        checked += 1;
    }
    assert!(checked >= 20, "{checked} parts");
}

/// Two opposite rules on a flange and its wall; the first has priority `a`,
/// the second `b`.
fn opposite_rules(a: i64, b: i64) -> RuleSet {
    let text = format!(
        r#"
[[rule]]
name = "flange-first"
priority = {a}
first = ["flange"]
second = ["web"]
connection = "first_on_second"
relation = "before"

[[rule]]
name = "web-first"
priority = {b}
first = ["web"]
second = ["flange"]
connection = "second_on_first"
relation = "before"
"#
    );
    RuleSet::from_toml(&text, "opposite.toml").unwrap()
}

#[test]
fn the_higher_rule_wins_and_swapping_priorities_flips_it() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("fixtures/recognition/rib_grid_panel.step");
    for (a, b, winner, loser) in [
        (2, 1, "flange-first", "web-first"),
        (1, 2, "web-first", "flange-first"),
    ] {
        let p = plan_file(&path, &opposite_rules(a, b));
        assert!(!p.sequence.is_empty());
        assert!(
            p.sequence.iter().all(|c| c.rule == winner),
            "{:?}",
            p.sequence
        );
        assert_eq!(p.rejected.len(), p.sequence.len());
        for r in &p.rejected {
            assert_eq!(r.rule, loser);
            assert_eq!(r.reason, Rejection::Cycle, "{}", r.explanation);
            assert_eq!(r.because.len(), 1);
            assert_eq!(r.because[0].rule, winner);
            assert!(
                r.explanation.contains("would close a cycle"),
                "{}",
                r.explanation
            );
        }
    }
}

#[test]
fn goes_first_second_is_the_same_as_swapping_the_kinds() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("fixtures/recognition/rib_grid_panel.step");
    let swapped = RuleSet::from_toml(
        "[[rule]]\nname = \"w\"\npriority = 1\nfirst = [\"web\"]\nsecond = [\"flange\"]\nconnection = \"second_on_first\"\nrelation = \"before\"\ngoes_first = \"second\"\n",
        "s.toml",
    )
    .unwrap();
    let p = plan_file(&path, &swapped);
    let q = plan_file(&path, &opposite_rules(2, 1));
    let pairs = |p: &Plan| {
        p.sequence
            .iter()
            .map(|c| (c.before, c.after))
            .collect::<Vec<_>>()
    };
    assert_eq!(pairs(&p), pairs(&q));
    assert!(p
        .sequence
        .iter()
        .all(|c| c.before.kind == StiffnessKind::Flange));
}

#[test]
fn redundancy_and_a_would_be_cycle_are_rejected_with_their_chains() {
    let rules = RuleSet::default_rules();
    let fixtures = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures/recognition");
    // Rib grid: a flange before the web, then top-down says so again.
    let p = plan_file(&fixtures.join("rib_grid_panel.step"), &rules);
    let redundant = p
        .rejected
        .iter()
        .find(|r| r.reason == Rejection::Redundant)
        .expect("a redundant candidate");
    assert_eq!(redundant.rule, "top-down");
    assert!(
        redundant.explanation.contains("already precedes"),
        "{}",
        redundant.explanation
    );
    // C frame: the web stands above its lower flange, but the flange goes
    // first: top-down would close a cycle.
    let p = plan_file(&fixtures.join("c_frame.step"), &rules);
    let cycle = p
        .rejected
        .iter()
        .find(|r| r.reason == Rejection::Cycle)
        .expect("a would-be cycle");
    assert_eq!(cycle.rule, "top-down");
    assert_eq!(cycle.because[0].rule, "flange-before-its-wall");
}

#[test]
fn queries_answer_direct_and_indirect() {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures/recognition/c_frame.step");
    let p = plan_file(&path, &RuleSet::default_rules());
    let id = |s: &str| FeatureId::parse(s).unwrap();
    // F2 before F1 before W1 before the ribs.
    assert!(p.queries.successors(id("F2"), false).contains(&id("F1")));
    assert!(!p.queries.successors(id("F2"), false).contains(&id("R1")));
    assert!(p.queries.successors(id("F2"), true).contains(&id("R1")));
    assert!(p.queries.predecessors(id("R1"), true).contains(&id("F2")));
    assert_eq!(p.queries.simultaneous(id("W1")), vec![id("H1"), id("H2")]);
}

#[test]
fn a_turned_part_and_set_up_get_the_same_plan() {
    let rules = RuleSet::default_rules();
    for name in ["rib_grid_panel", "c_frame", "flange_cutouts"] {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join(format!("fixtures/recognition/{name}.step"));
        let text = std::fs::read_to_string(&path).unwrap();
        let (r, t) = common::rigid_motion(5);
        let (turned, _) = common::turned_step(&text, &r, &t);
        let up = r * nalgebra::Vector3::z();
        let a = plan_text(&text, [0.0, 0.0, 1.0], &rules);
        let b = plan_text(&turned, [up.x, up.y, up.z], &rules);
        assert_eq!(a.sequence, b.sequence, "{name}");
        assert_eq!(a.rejected, b.rejected, "{name}");
        assert_eq!(a.order, b.order, "{name}");
    }
}

/// The number of a layer id (`V12` → 12).
fn layer_number(id: &str) -> usize {
    id[1..].parse().unwrap()
}

#[test]
fn step_layers_follow_size_wall_on_the_fokker_ribs() {
    let rules = RuleSet::default_rules();
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures/machining");
    for (height, big) in [(48.0, 48.0), (72.0, 36.0)] {
        let p = plan_file(&dir.join(format!("rib_{height}_on_plate.step")), &rules);
        let sizes = thinwall_plan::size_wall(
            &thinwall_plan::WallDimensions {
                length: 120.0,
                thickness: 1.0,
                height,
            },
            &thinwall_plan::SizingParameters::defaults(thinwall_plan::Milling::Peripheral),
        )
        .unwrap();
        assert_eq!(sizes.big_h, big);
        let layers = &p.layers;
        let large: Vec<f64> = layers
            .iter()
            .filter(|l| l.size_class == thinwall_plan::steps::SizeClass::Large)
            .map(|l| l.height)
            .collect();
        let small: Vec<f64> = layers
            .iter()
            .filter(|l| l.size_class == thinwall_plan::steps::SizeClass::Small)
            .map(|l| l.height)
            .collect();
        assert!(
            large.iter().all(|&h| (h - sizes.big_h).abs() < 1e-6),
            "{large:?}"
        );
        assert!(
            small.iter().all(|&h| (h - sizes.h).abs() < 1e-6),
            "{small:?}"
        );
        assert!((large.iter().sum::<f64>() - height).abs() < 1e-6);
        assert!((small.iter().sum::<f64>() - height).abs() < 1e-6);
        assert!(layers
            .iter()
            .all(|l| (l.width - sizes.b).abs() < 1e-9 && (l.length - 120.0).abs() < 1e-6));
        // The large layer first, each small layer only once the large one
        // beside it is down to its depth (fig. 4.1).
        assert_eq!(layers[0].size_class, thinwall_plan::steps::SizeClass::Large);
        for (i, l) in layers.iter().enumerate() {
            if l.size_class == thinwall_plan::steps::SizeClass::Small {
                let deepest_large = layers[..i]
                    .iter()
                    .filter(|x| x.size_class == thinwall_plan::steps::SizeClass::Large)
                    .map(|x| x.from_foot[0])
                    .fold(f64::INFINITY, f64::min);
                assert!(l.from_foot[0] >= deepest_large - 1e-9, "{l:?}");
            }
        }
    }
}

#[test]
fn every_sized_wall_is_covered_on_both_sides_in_a_valid_order() {
    let rules = RuleSet::default_rules();
    for path in parts() {
        let p = plan_file(&path, &rules);
        let name = path.display().to_string();
        for w in p
            .walls
            .iter()
            .filter(|w| w.sizes.thin && w.kind != StiffnessKind::Web)
        {
            let height = w.sizes.wall.height;
            for side in 0..2u8 {
                let covered: f64 = p
                    .layers
                    .iter()
                    .filter(|l| l.owner == w.id && l.side == side)
                    .map(|l| l.height)
                    .sum();
                assert!(
                    (covered - height).abs() < 1e-3 * height.max(1.0),
                    "{name}: {} side {side}: {covered} of {height}",
                    w.id
                );
            }
        }
        for c in &p.layer_sequence {
            assert!(
                layer_number(&c.before) < layer_number(&c.after),
                "{name}: {c:?}"
            );
        }
    }
}

#[test]
fn a_turned_part_gets_the_same_layers() {
    let rules = RuleSet::default_rules();
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("fixtures/recognition/flange_cutouts.step");
    let text = std::fs::read_to_string(&path).unwrap();
    let (r, t) = common::rigid_motion(9);
    let (turned, _) = common::turned_step(&text, &r, &t);
    let up = r * nalgebra::Vector3::z();
    let a = plan_text(&text, [0.0, 0.0, 1.0], &rules);
    let b = plan_text(&turned, [up.x, up.y, up.z], &rules);
    assert!(!a.layers.is_empty());
    let key = |p: &Plan| -> Vec<String> {
        p.layers
            .iter()
            .map(|l| {
                format!(
                    "{} {} {} {:?} {} {:.6} {:.6} {:.6} {:.6} z {:.6}",
                    l.id,
                    l.owner,
                    l.side,
                    l.size_class,
                    l.step,
                    l.from_foot[0],
                    l.from_foot[1],
                    l.width,
                    l.length,
                    l.z_range[1] - l.z_range[0]
                )
            })
            .collect()
    };
    assert_eq!(key(&a), key(&b));
    assert_eq!(a.layer_sequence, b.layer_sequence);
}
