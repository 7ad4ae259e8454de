//! Every command builds its part's analysis once and meshes it at most
//! once: the study hands the same analysis (and its mesh) to every layer,
//! and no layer builds its own for the part (a plan's volumes get their
//! own). Counted per part by `thinwall_brep::builds`.

use std::path::PathBuf;
use thinwall_analysis::Machine;
use thinwall_brep::builds::{count, Built};
use thinwall_study::*;

fn fixture(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../fixtures")
        .join(name)
}

/// The analyses and meshes `f` built (a fresh study of `part` each time),
/// and its rendering in each of `formats`.
fn counted(
    part: &LoadedPart,
    formats: &[Format],
    f: impl for<'p> Fn(&Study<'p>) -> Rendered<'p>,
) -> (usize, usize) {
    let built = || {
        (
            count(&part.part, Built::Analysis),
            count(&part.part, Built::Mesh),
        )
    };
    let (a0, m0) = built();
    let study = Study::new(part);
    let result = f(&study);
    for &format in formats {
        let text = render(&result, format).unwrap();
        assert!(!text.is_empty());
    }
    let (a1, m1) = built();
    (a1 - a0, m1 - m0)
}

#[test]
fn each_command_builds_the_analysis_and_the_mesh_once() {
    use Format::*;
    let part = LoadedPart::read_file(fixture("recognition/rib_grid_panel.step")).unwrap();
    let setup = setup_of(None, Machine::ThreeAxis).unwrap();

    let inspect_built = counted(&part, &[Text, Json], |s| inspect(s).unwrap().into());
    assert_eq!(inspect_built, (1, 0), "inspect");

    // The CLI's default: reach of wall sides on the mesh.
    let req = RecognizeRequest {
        reach_tool: Some(thinwall_access::reach::Tool::new(12.0)),
        ..Default::default()
    };
    let recognize_built = counted(&part, &[Text, Json, Svg, Html], |s| {
        recognize(s, &req).unwrap().into()
    });
    assert_eq!(
        recognize_built,
        (1, 1),
        "recognize with reach, every format"
    );

    let plan_req = PlanRequest::new(req.clone(), thinwall_plan::RuleSet::default_rules());
    let plan_built = counted(&part, &[Text, Json, Svg, Html], |s| {
        plan(s, &plan_req).unwrap().into()
    });
    assert_eq!(plan_built, (1, 1), "plan, every format");

    let access_req = AccessRequest::new(setup.clone());
    let access_built = counted(&part, &[Text, Json, Html], |s| {
        access(s, &access_req).unwrap().into()
    });
    assert_eq!(access_built, (1, 1), "access, every format");

    for by_feature in [false, true] {
        let mut ops_req = OperationsRequest::new(setup.clone());
        ops_req.by_feature = by_feature;
        let ops = counted(&part, &[Text, Json, Html], |s| {
            operations(s, &ops_req).unwrap().into()
        });
        assert_eq!(ops, (1, 1), "operations (by feature: {by_feature})");
    }

    // Two commands on one study share its analysis and mesh.
    let built = || {
        (
            count(&part.part, Built::Analysis),
            count(&part.part, Built::Mesh),
        )
    };
    let (a0, m0) = built();
    let study = Study::new(&part);
    let planned = plan(&study, &plan_req).unwrap();
    let again = recognize(&study, &req).unwrap();
    assert!(std::sync::Arc::ptr_eq(&planned.outcome, &again.outcome));
    render(&again.into(), Html).unwrap();
    let (a1, m1) = built();
    assert_eq!((a1 - a0, m1 - m0), (1, 1));
}
