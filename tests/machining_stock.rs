//! Machining features against a stock and in a set-up, on a generated plate
//! with a round boss standing on its top and a rectangular pocket
//! (`scripts/make_machining_fixtures.py`): the default block, a casting
//! envelope, a larger blank, a uniform allowance, errors, reach from up,
//! and the same answers on turned copies.

mod common;

use thinwall_analysis::{MachiningKind, PartAnalysis, Setup};
use thinwall_geom::Vector3;
use thinwall_machining::{recognize_with, MachiningError, Options, StockSpec};

fn fixture(name: &str) -> String {
    common::machining_fixture(name)
}

fn read(text: &str) -> thinwall_brep::Part {
    thinwall_step::read_bytes(text.as_bytes(), "part.step")
        .unwrap()
        .0
}

/// Kind, depth, length × width of each feature, sorted.
fn summary(part: &thinwall_brep::Part, opts: &Options) -> Vec<String> {
    let a = PartAnalysis::new(part, Setup::default());
    let mut v: Vec<String> = recognize_with(&a, opts)
        .unwrap()
        .iter()
        .map(|m| {
            format!(
                "{} {} depth {:.2} {:.2} x {:.2} reach {:?}",
                m.kind, m.profile, m.depth, m.length, m.width, m.reachable
            )
        })
        .collect();
    v.sort();
    v
}

#[test]
fn the_block_gives_boss_the_face_round_it_and_pocket() {
    let part = read(&fixture("boss_plate.step"));
    assert_eq!(
        summary(&part, &Options::default()),
        [
            "boss circular depth 10.00 20.00 x 20.00 reach None",
            "face free depth 10.00 100.00 x 60.00 reach None",
            "pocket rectangular depth 8.00 30.00 x 20.00 reach None",
        ]
    );
    // The boss: its cap centre, the tool coming down its axis.
    let a = PartAnalysis::new(&part, Setup::default());
    let m = recognize_with(&a, &Options::default()).unwrap();
    let boss = m.iter().find(|m| m.kind == MachiningKind::Boss).unwrap();
    let c = boss.centre.unwrap();
    assert!((c[0] - 30.0).abs() < 1e-6 && (c[1] - 30.0).abs() < 1e-6 && (c[2] - 30.0).abs() < 1e-6);
    assert_eq!(boss.direction, [0.0, 0.0, -1.0]);
}

#[test]
fn a_casting_envelope_leaves_only_what_is_machined() {
    let part = read(&fixture("boss_plate.step"));
    let casting = read(&fixture("boss_plate_casting.step"));
    let opts = Options {
        stock: StockSpec::Solid(&casting),
        ..Options::default()
    };
    assert_eq!(
        summary(&part, &opts),
        ["pocket rectangular depth 8.00 30.00 x 20.00 reach None"]
    );
}

#[test]
fn a_blank_and_an_allowance_face_the_envelope() {
    let part = read(&fixture("boss_plate.step"));
    let blank = read(&fixture("boss_plate_blank.step"));
    let with_blank = summary(
        &part,
        &Options {
            stock: StockSpec::Solid(&blank),
            ..Options::default()
        },
    );
    let faced: Vec<&String> = with_blank
        .iter()
        .filter(|s| s.starts_with("face"))
        .collect();
    // The blank stands 5 mm off the four sides, 2 below, 3 above the cap;
    // round the boss the plate's top is 10 below the cap.
    let depths: Vec<&str> = faced.iter().map(|s| &s[16..20]).collect();
    assert_eq!(
        depths,
        ["10.0", "2.00", "3.00", "5.00", "5.00", "5.00", "5.00"],
        "{faced:?}"
    );
    let with_offset = summary(
        &part,
        &Options {
            stock: StockSpec::Offset(1.5),
            ..Options::default()
        },
    );
    assert_eq!(
        with_offset
            .iter()
            .filter(|s| s.contains("depth 1.50"))
            .count(),
        6
    );
    assert_eq!(with_offset.len(), with_blank.len());
}

#[test]
fn an_unusable_stock_is_a_typed_error() {
    let part = read(&fixture("boss_plate.step"));
    let a = PartAnalysis::new(&part, Setup::default());
    let bad = Options {
        stock: StockSpec::Offset(-1.0),
        ..Options::default()
    };
    assert_eq!(recognize_with(&a, &bad).unwrap_err().code(), "bad_offset");
    let shifted = common::turned_step(
        &fixture("boss_plate_casting.step"),
        &nalgebra::Rotation3::identity(),
        &nalgebra::Vector3::new(50.0, 0.0, 0.0),
    )
    .0;
    let shifted = read(&shifted);
    let off = Options {
        stock: StockSpec::Solid(&shifted),
        ..Options::default()
    };
    match recognize_with(&a, &off) {
        Err(MachiningError::StockTooSmall { by }) => assert!((by - 50.0).abs() < 1e-6),
        other => panic!("{other:?}"),
    }
}

#[test]
fn reach_is_judged_from_up() {
    let part = read(&fixture("boss_plate.step"));
    let from = |up: Vector3| {
        summary(
            &part,
            &Options {
                up: Some(up),
                ..Options::default()
            },
        )
    };
    let down = from(Vector3::z());
    assert!(down.iter().all(|s| s.ends_with("Some(true)")), "{down:?}");
    // Upside down, nothing on the top is reached.
    let upside_down = from(-Vector3::z());
    assert!(
        upside_down.iter().all(|s| s.ends_with("Some(false)")),
        "{upside_down:?}"
    );
}

#[test]
fn turned_part_stock_and_set_up_give_the_same_features() {
    let (r, t) = common::rigid_motion(11);
    let turn = |name: &str| read(&common::turned_step(&fixture(name), &r, &t).0);
    let (part, casting, blank) = (
        read(&fixture("boss_plate.step")),
        read(&fixture("boss_plate_casting.step")),
        read(&fixture("boss_plate_blank.step")),
    );
    let (tpart, tcasting, tblank) = (
        turn("boss_plate.step"),
        turn("boss_plate_casting.step"),
        turn("boss_plate_blank.step"),
    );
    let up = Vector3::z();
    let tup = r * up;
    for (stock, tstock) in [
        (StockSpec::Block, StockSpec::Block),
        (StockSpec::Solid(&casting), StockSpec::Solid(&tcasting)),
        (StockSpec::Solid(&blank), StockSpec::Solid(&tblank)),
        (StockSpec::Offset(1.5), StockSpec::Offset(1.5)),
    ] {
        let opts = Options {
            up: Some(up),
            stock,
            ..Options::default()
        };
        let topts = Options {
            up: Some(tup),
            stock: tstock,
            ..Options::default()
        };
        assert_eq!(summary(&tpart, &topts), summary(&part, &opts));
    }
}
