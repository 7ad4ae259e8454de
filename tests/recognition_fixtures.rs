//! Recognition on the fixtures of `scripts/make_recognition_fixtures.py`:
//! every kind and the hard cases (crossing walls, ribs ending on flanges,
//! fillets at the foot, a row of large holes, cut-outs, a notch, a thick
//! wall, a sloped wall, an upright C-frame, a free plate, a turned part).

mod common;

use std::collections::{BTreeSet, HashMap};
use thinwall_recognize::StiffnessKind as Kind;

use common::fixtures::{dir, ids_at, load, our_id, Fixture};

fn check(name: &str) -> Vec<String> {
    let (part, fx, r) = load(name);
    let mut problems = Vec::new();
    let mut ours_of: HashMap<String, String> = HashMap::new();
    let mut matched = BTreeSet::new();
    for e in &fx.features {
        let Some(f) =
            our_id(&part, &r, e).and_then(|id| r.features.iter().find(|f| f.id.to_string() == id))
        else {
            problems.push(format!(
                "{name}: {} {:?} not found with its faces",
                e.kind, e.name
            ));
            continue;
        };
        let is_wall = !e.side_faces_at.is_empty();
        matched.insert(f.id.to_string());
        if let Some(n) = &e.name {
            ours_of.insert(n.clone(), f.id.to_string());
        }
        if f.kind.name() != e.kind {
            problems.push(format!(
                "{name}: {:?} is {} here, expected {}",
                e.name.clone().unwrap_or(f.id.to_string()),
                f.kind.name(),
                e.kind
            ));
        }
        if is_wall && f.thin != Some(e.thin.unwrap_or(true)) {
            problems.push(format!("{name}: {} thin {:?}", f.id, f.thin));
        }
        if let Some(t) = e.thickness {
            if (f.thickness.unwrap_or(0.0) - t).abs() > 1e-6 * t.max(1.0) {
                problems.push(format!(
                    "{name}: {} thickness {:?}, expected {t}",
                    f.id, f.thickness
                ));
            }
        }
        if let Some(l) = e.large {
            if f.large != Some(l) {
                problems.push(format!(
                    "{name}: {} large {:?}, expected {l}",
                    f.id, f.large
                ));
            }
        }
    }
    for e in &fx.features {
        let Some(w) = &e.wall else { continue };
        let want = ids_at(&part, &e.faces_at);
        if let Some(f) = r
            .features
            .iter()
            .find(|f| f.faces.iter().copied().collect::<BTreeSet<_>>() == want)
        {
            if f.wall.map(|x| x.to_string()).as_ref() != ours_of.get(w) {
                problems.push(format!(
                    "{name}: {} {} is in {:?}, expected {w} = {:?}",
                    f.kind.name(),
                    f.id,
                    f.wall,
                    ours_of.get(w)
                ));
            }
        }
    }
    for f in &r.features {
        if f.thin == Some(true) && !matched.contains(&f.id.to_string()) {
            problems.push(format!(
                "{name}: {} {} reported thin, not expected",
                f.kind.name(),
                f.id
            ));
        }
    }
    problems
}

#[test]
fn every_recognition_fixture_yields_its_features() {
    let mut problems = Vec::new();
    let mut kinds = BTreeSet::new();
    let mut n = 0;
    for entry in std::fs::read_dir(dir()).unwrap() {
        let p = entry.unwrap().path();
        let Some(stem) = p
            .file_name()
            .and_then(|s| s.to_str())
            .and_then(|s| s.strip_suffix(".expected.json"))
        else {
            continue;
        };
        let fx: Fixture = serde_json::from_str(&std::fs::read_to_string(&p).unwrap()).unwrap();
        kinds.extend(fx.features.iter().map(|f| f.kind.clone()));
        problems.extend(check(stem));
        n += 1;
    }
    for p in &problems {
        println!("{p}");
    }
    assert!(n >= 7, "{n} fixtures");
    // Every kind has a fixture.
    for k in Kind::ALL {
        assert!(
            kinds.contains(k.name()),
            "no fixture expects a {}",
            k.name()
        );
    }
    assert!(problems.is_empty(), "{} problems", problems.len());
}

#[test]
fn turning_the_part_and_its_up_changes_nothing() {
    let (_, _, a) = load("rib_grid_panel");
    let (_, _, b) = load("rib_grid_panel_turned");
    assert_eq!(a.features.len(), b.features.len());
    for (x, y) in a.features.iter().zip(&b.features) {
        assert_eq!(
            (x.kind, &x.id, x.faces.len(), x.thin),
            (y.kind, &y.id, y.faces.len(), y.thin)
        );
        for (p, q) in [
            (x.thickness, y.thickness),
            (x.height, y.height),
            (x.length, y.length),
            (x.deflection, y.deflection),
            (x.diameter, y.diameter),
        ] {
            match (p, q) {
                (Some(p), Some(q)) => assert!(
                    (p - q).abs() <= 1e-6 * p.abs().max(1.0),
                    "{}: {p} vs {q}",
                    x.id
                ),
                (None, None) => {}
                _ => panic!("{}: {p:?} vs {q:?}", x.id),
            }
        }
    }
}
