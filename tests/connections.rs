//! Connections and accessibility on the recognition fixtures: crossing
//! ribs, a rib ending on a flange, a flange on a web, a hole in a rib, a
//! fillet on a rib, horizontal flanges on a vertical web, a turned part,
//! and one part in two set-ups.

mod common;

use common::fixtures::{load, load_with_up, names};
use thinwall_connect::{connect, crossing, Connection, Machine, Options, Setup, Structure};
use thinwall_recognize::{FeatureId, StiffnessKind as Kind};

fn fid(s: &str) -> FeatureId {
    FeatureId::parse(s).unwrap_or_else(|| panic!("{s} is not a feature id"))
}

fn structure(
    name: &str,
    up: Option<[f64; 3]>,
) -> (
    Structure,
    std::collections::HashMap<String, String>,
    thinwall_recognize::Recognition,
) {
    let (part, fx, r) = load_with_up(name, up);
    let setup = Setup {
        up: up.unwrap_or(fx.up),
        ..Setup::default()
    };
    let s = connect(&r, &setup, &Options::default());
    s.validate().unwrap_or_else(|e| panic!("{name}: {e}"));
    let ids = names(&part, &fx, &r);
    (s, ids, r)
}

fn has_base_leaf(s: &Structure, base: &str, leaf: &str) -> bool {
    s.connections.contains(&Connection::BaseLeaf {
        base: fid(base),
        leaf: fid(leaf),
    })
}

fn has_crossing(s: &Structure, a: &str, b: &str) -> bool {
    s.connections.contains(&crossing(fid(a), fid(b)))
}

#[test]
fn rib_grid_panel_structure() {
    let (s, n, r) = structure("rib_grid_panel", None);
    let id = |k: &str| n[k].as_str();
    // Flanges on the web, ribs on the web.
    for leaf in ["F_y0", "F_yW", "F_x0", "F_xL", "RX1", "RX2", "RY"] {
        assert!(
            has_base_leaf(&s, id("W"), id(leaf)),
            "W -> {leaf}: {:?}",
            s.connections
        );
    }
    // Crossing ribs, ribs ending on flanges, flanges meeting at corners.
    assert!(has_crossing(&s, id("RX1"), id("RY")) && has_crossing(&s, id("RX2"), id("RY")));
    for (rib, flange) in [
        ("RX1", "F_x0"),
        ("RX1", "F_xL"),
        ("RY", "F_y0"),
        ("RY", "F_yW"),
    ] {
        assert!(has_crossing(&s, id(rib), id(flange)), "{rib} x {flange}");
    }
    assert!(has_crossing(&s, id("F_y0"), id("F_x0")));
    // The holes are leaves of the rib they are in, the cut-outs of their flange.
    for f in r.features.iter().filter(|f| f.kind == Kind::Hole) {
        assert!(has_base_leaf(&s, id("RX1"), &f.id.to_string()));
    }
    for f in r.features.iter().filter(|f| f.kind == Kind::Cutout) {
        assert!(has_base_leaf(&s, id("F_y0"), &f.id.to_string()));
    }
    // Every wall has at most one base and the web none.
    assert_eq!(s.base_of(fid(id("W"))), None);
    // Up +Z: the web's underside faces the table; every other side is reachable.
    let blocked: Vec<(String, usize)> = s
        .access
        .iter()
        .flat_map(|(w, sides)| {
            sides
                .iter()
                .enumerate()
                .filter(|(_, a)| !a.reachable)
                .map(move |(i, _)| (w.to_string(), i))
        })
        .collect();
    assert_eq!(blocked.len(), 1, "{blocked:?}");
    assert_eq!(blocked[0].0, id("W"));
}

#[test]
fn fillet_and_chamfer_on_a_rib_are_its_leaves() {
    let (s, n, r) = structure("filleted_chamfered_rib", None);
    for f in r.features.iter().filter(|f| !f.kind.is_wall()) {
        assert!(
            has_base_leaf(&s, &n["R"], &f.id.to_string()),
            "{} {:?}",
            f.id,
            s.connections
        );
    }
    // The rib stands on a thick block: no base in the structure.
    assert_eq!(s.base_of(fid(&n["R"])), None);
}

#[test]
fn upright_c_frame_web_carries_horizontal_flanges() {
    let (s, n, _) = structure("c_frame", None);
    for leaf in ["FT", "FB", "S1", "S2"] {
        assert!(has_base_leaf(&s, &n["W"], &n[leaf]), "W -> {leaf}");
    }
    for (a, b) in [("S1", "FT"), ("S1", "FB"), ("S2", "FT"), ("S2", "FB")] {
        assert!(has_crossing(&s, &n[a], &n[b]), "{a} x {b}");
    }
    // The top flange's underside faces the table: not reachable with 3 axes.
    let ft = &s.access[&fid(&n["FT"])];
    assert_eq!(ft.iter().filter(|a| !a.reachable).count(), 1);
    assert!(ft.iter().any(|a| a.reason.contains("faces down")));
}

#[test]
fn turned_part_has_the_same_structure() {
    let (a, _, _) = structure("rib_grid_panel", None);
    let (b, _, _) = structure("rib_grid_panel_turned", None);
    assert_eq!(a.connections, b.connections);
    let reach = |s: &Structure| {
        s.access
            .iter()
            .map(|(k, v)| (*k, v[0].reachable, v[1].reachable))
            .collect::<Vec<_>>()
    };
    assert_eq!(reach(&a), reach(&b));
}

#[test]
fn two_setups_of_an_angle_bracket() {
    // Up +Z: the horizontal plate lies on the table and carries the upright one.
    let (z, n, rz) = structure("angle_bracket", Some([0.0, 0.0, 1.0]));
    assert!(has_base_leaf(&z, &n["H"], &n["V"]), "{:?}", z.connections);
    let kind = |r: &thinwall_recognize::Recognition, id: &str| {
        r.features.iter().find(|f| f.id == fid(id)).unwrap().kind
    };
    assert_eq!(kind(&rz, &n["H"]), Kind::Web);
    assert_eq!(kind(&rz, &n["V"]), Kind::Flange);
    // Up +X: the upright plate is now the lower one and becomes the base.
    let (x, n, rx) = structure("angle_bracket", Some([1.0, 0.0, 0.0]));
    assert!(has_base_leaf(&x, &n["V"], &n["H"]), "{:?}", x.connections);
    assert_eq!(kind(&rx, &n["V"]), Kind::Web);
    assert_eq!(kind(&rx, &n["H"]), Kind::Flange);
}

#[test]
fn sloped_rib_undercut_needs_five_axes() {
    let (part, fx, r) = load("sloped_rib");
    let ids = names(&part, &fx, &r);
    let three = connect(&r, &Setup::default(), &Options::default());
    let five = connect(
        &r,
        &Setup {
            machine: Machine::FiveAxis {
                tilt_limit_deg: 15.0,
            },
            ..Setup::default()
        },
        &Options::default(),
    );
    let rib = &fid(&ids["R"]);
    // The leaning rib's lower side overhangs by 12°.
    assert_eq!(three.access[rib].iter().filter(|a| !a.reachable).count(), 1);
    assert!(five.access[rib].iter().all(|a| a.reachable));
}
