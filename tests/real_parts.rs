//! What a planner would not accept, checked on every NIST B-rep part (none
//! of which the rules were tuned on): walls without real extent, features
//! of no size, thin flags outside the model's validity without a note,
//! features spanning bodies.

mod common;

use thinwall_pipeline::{run, Request};

fn nist_parts() -> Vec<std::path::PathBuf> {
    common::step_files(&common::shared_data().join("nist"))
        .into_iter()
        .filter(|f| !f.to_string_lossy().contains("-tg"))
        .collect()
}

#[test]
fn nist_stiffness_features_are_ones_a_planner_would_accept() {
    let mut walls = 0;
    let mut problems = Vec::new();
    for path in nist_parts() {
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        let (part, _) = thinwall_step::read_file(&path).unwrap();
        let out = run(&part, None, &Request::default()).unwrap();
        let least = Request::default().config.thresholds.min_extent_to_thickness;
        for f in &out.recognition.features {
            let id = f.id;
            for (what, v) in [
                ("height", f.height),
                ("length", f.length),
                ("thickness", f.thickness),
                ("diameter", f.diameter),
                ("width", f.width),
                ("radius", f.radius),
            ] {
                if v.is_some_and(|x| !(x > 0.0 && x.is_finite())) {
                    problems.push(format!("{name} {id}: {what} {v:?}"));
                }
            }
            if !f.kind.is_wall() {
                continue;
            }
            walls += 1;
            let t = f.thickness.unwrap();
            if f.height.unwrap() < least * t || f.length.unwrap() < least * t {
                problems.push(format!(
                    "{name} {id}: h {:?} L {:?} under {least} t = {}",
                    f.height,
                    f.length,
                    least * t
                ));
            }
            let (h, d) = (f.height.unwrap(), f.deflection.unwrap());
            let outside = d > thinwall_recognize::deflection::SMALL_DEFLECTION_RATIO * h
                || h / t < thinwall_recognize::deflection::MIN_BEAM_SLENDERNESS;
            if f.thin == Some(true) && outside && f.model_note.is_none() {
                problems.push(format!("{name} {id}: thin outside the model, no note"));
            }
        }
    }
    assert!(problems.is_empty(), "{problems:#?}");
    assert!(walls >= 20, "{walls} walls on the NIST parts");
}

#[test]
fn lettering_is_an_engraving_where_there_is_lettering_and_nowhere_else() {
    let lettered = ["ctc_05", "ftc_06", "ftc_11", "stc_06", "stc_08"];
    let mut parts = nist_parts();
    parts.extend(common::step_files(&common::shared_data().join("thinwall")));
    for path in parts {
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        let (part, _) = thinwall_step::read_file(&path).unwrap();
        let out = run(&part, None, &Request::default()).unwrap();
        let engravings: Vec<_> = out
            .recognition
            .features
            .iter()
            .filter(|f| f.kind == thinwall_recognize::StiffnessKind::Engraving)
            .collect();
        let expected = lettered.iter().any(|l| name.contains(l));
        assert_eq!(!engravings.is_empty(), expected, "{name}: {engravings:?}");
        for e in engravings {
            assert!(
                e.faces.len() >= 10 && e.height.unwrap() > 0.0 && e.height.unwrap() <= 3.0,
                "{name}"
            );
        }
    }
}
