//! Bad input gets a clear error naming the file (and entity where there is
//! one), never a panic.

mod common;

use thinwall_step::{read_bytes, StepError};

fn good() -> String {
    std::fs::read_to_string(common::shared_data().join("thinwall/loose_rib_00.step")).unwrap()
}

fn err(bytes: &[u8]) -> StepError {
    read_bytes(bytes, "bad.step").expect_err("must be rejected")
}

#[test]
fn empty_and_garbage_files_are_syntax_errors() {
    for input in [
        &b""[..],
        b"hello world",
        b"\x00\xff\xfe binary",
        b"ISO-10303-21;",
    ] {
        let e = err(input);
        assert!(matches!(e, StepError::Syntax { .. }), "{e:?}");
        assert!(e.to_string().starts_with("bad.step: "), "{e}");
    }
}

#[test]
fn wrong_header_is_rejected() {
    let text = good().replacen("ISO-10303-21;", "ISO-10303-99;", 1);
    let e = err(text.as_bytes());
    assert!(e.to_string().contains("bad.step"), "{e}");
    let no_schema = good().replacen("FILE_SCHEMA", "FILE_SCHEMX", 1);
    let e = err(no_schema.as_bytes());
    assert!(e.to_string().contains("bad.step"), "{e}");
}

#[test]
fn truncated_files_never_panic() {
    let text = good();
    for frac in [0.1, 0.3, 0.5, 0.7, 0.9, 0.99] {
        let cut = (text.len() as f64 * frac) as usize;
        // A cut file is a syntax error naming the file; a caught panic
        // (`internal`) would be a defect, not an answer.
        let e = err(&text.as_bytes()[..cut]);
        assert!(e.to_string().contains("bad.step"), "{e}");
        assert_ne!(e.code(), "internal", "{frac}: {e}");
        assert!(matches!(e, StepError::Syntax { .. }), "{frac}: {e:?}");
    }
}

/// The assembly fixture with `extra` entities added before `ENDSEC`.
fn assembly_with(extra: &str) -> String {
    let text =
        std::fs::read_to_string(common::root().join("fixtures/bracket_assembly.step")).unwrap();
    let end = text.rfind("ENDSEC;").expect("data section");
    format!("{}{extra}{}", &text[..end], &text[end..])
}

/// A placement of definition #31 (the bracket) inside itself.
fn self_use(id: u64) -> String {
    format!(
        "#{a} = CONTEXT_DEPENDENT_SHAPE_REPRESENTATION(#{b},#{d});\n\
         #{b} = ( REPRESENTATION_RELATIONSHIP('','',#36,#36) \
         REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION(#{c}) SHAPE_REPRESENTATION_RELATIONSHIP() );\n\
         #{c} = ITEM_DEFINED_TRANSFORMATION('','',#11,#15);\n\
         #{d} = PRODUCT_DEFINITION_SHAPE('Placement','',#{e});\n\
         #{e} = NEXT_ASSEMBLY_USAGE_OCCURRENCE('{id}','self','',#31,#31,$);\n",
        a = id,
        b = id + 1,
        c = id + 2,
        d = id + 3,
        e = id + 4
    )
}

#[test]
fn a_definition_that_contains_itself_is_refused_at_once() {
    // Used twice by itself: without a check on the path this is a walk of
    // 2^32 instances; with it, the first repetition is an error.
    let text = assembly_with(&(self_use(5000) + &self_use(5010)));
    let t0 = std::time::Instant::now();
    let e = err(text.as_bytes());
    assert_eq!(e.code(), "cyclic_assembly", "{e}");
    assert!(e.to_string().starts_with("bad.step: "), "{e}");
    assert!(t0.elapsed().as_secs() < 5, "took {:?}", t0.elapsed());
}

#[test]
fn deeply_nested_and_self_referencing_surface_curves_fail_cleanly() {
    let text = good();
    let line = "#26 = SURFACE_CURVE('',#27,(#31,#43),.PCURVE_S1.);";
    assert!(text.contains(line), "fixture text changed upstream");
    // 40 surface curves, each the 3D curve of the one before, over the line.
    let mut chain = String::new();
    for k in 0..40u64 {
        let next = if k == 39 { 27 } else { 90_001 + k };
        chain.push_str(&format!(
            "#{} = SURFACE_CURVE('',#{next},(#31,#43),.PCURVE_S1.);\n",
            90_000 + k
        ));
    }
    let nested = text
        .replacen(
            line,
            "#26 = SURFACE_CURVE('',#90000,(#31,#43),.PCURVE_S1.);",
            1,
        )
        .replacen("ENDSEC;", &format!("{chain}ENDSEC;"), 1);
    let looped = text.replacen(
        line,
        "#26 = SURFACE_CURVE('',#26,(#31,#43),.PCURVE_S1.);",
        1,
    );
    for (what, text) in [("nested", nested), ("self-referencing", looped)] {
        match read_bytes(text.as_bytes(), "bad.step") {
            // Read: the edge is there, its description cut at the nesting bound.
            Ok((part, _)) => {
                let edge = part
                    .edges
                    .iter()
                    .find(|e| e.step_id == 21)
                    .expect("edge #21");
                match &edge.curve {
                    thinwall_geom::CurveKind::Other { keyword } => {
                        assert!(keyword.contains("nested deeper"), "{what}: {keyword}")
                    }
                    other => panic!("{what}: edge #21 read as {other:?}"),
                }
            }
            Err(e) => {
                assert_ne!(e.code(), "internal", "{what}: {e}");
                assert!(e.to_string().starts_with("bad.step: "), "{what}: {e}");
            }
        }
    }
}

#[test]
fn dangling_reference_is_reported_with_the_entity() {
    // Face #17's surface #32 becomes an id the file does not define: the
    // face, its shell and the solid cascade away, and the read says why.
    let text = good().replacen(
        "#17 = ADVANCED_FACE('',(#18),#32,.F.);",
        "#17 = ADVANCED_FACE('',(#18),#99999,.F.);",
        1,
    );
    assert_ne!(text, good(), "fixture text changed upstream");
    let e = err(text.as_bytes());
    assert_eq!(e.code(), "no_brep");
    let msg = e.to_string();
    assert!(
        msg.contains("bad.step")
            && msg.contains("#17 refers to #99999, which the file does not define"),
        "{msg}"
    );
}

#[test]
fn a_missing_face_is_named() {
    // The shell's first face is not in the file at all.
    let text: String = good()
        .lines()
        .filter(|l| !l.starts_with("#17 = ADVANCED_FACE"))
        .map(|l| format!("{l}\n"))
        .collect();
    let e = err(text.as_bytes());
    assert_eq!(e.code(), "no_brep");
    assert!(
        e.to_string()
            .contains("#16 refers to #17, which the file does not define"),
        "{e}"
    );
}

#[test]
fn an_open_shell_read_as_a_solid_is_refused_unless_allowed() {
    // A CLOSED_SHELL missing one of its faces: its neighbours' edges are
    // used once.
    let text = good().replacen(
        "#16 = CLOSED_SHELL('',(#17,#137,",
        "#16 = CLOSED_SHELL('',(#137,",
        1,
    );
    assert_ne!(text, good(), "fixture text changed upstream");
    let (part, _) = read_bytes(text.as_bytes(), "open.step").expect("read as a solid");
    let e =
        thinwall_pipeline::run(&part, None, &thinwall_pipeline::Request::default()).unwrap_err();
    assert_eq!(e.code(), "input.open_shell", "{e}");
    assert!(
        e.to_string().contains("edges are used by one face only"),
        "{e}"
    );
    let allow = thinwall_pipeline::Request {
        allow_open: true,
        ..Default::default()
    };
    let out = thinwall_pipeline::run(&part, None, &allow).unwrap();
    let open: Vec<_> = out
        .warnings
        .iter()
        .filter(|w| w.message.contains("used by one face only"))
        .collect();
    assert!(open.len() >= 4, "{:?}", out.warnings);
    assert!(open.iter().all(|w| w.entity.is_some()));
    // The intact part has no such warning and no free edge.
    let (whole, _) = read_bytes(good().as_bytes(), "good.step").unwrap();
    let out = thinwall_pipeline::run(&whole, None, &Default::default()).unwrap();
    assert!(out
        .warnings
        .iter()
        .all(|w| !w.message.contains("one face only")));
}

#[test]
fn open_shell_where_a_solid_is_expected_is_rejected() {
    let text = good().replacen("#16 = CLOSED_SHELL(", "#16 = OPEN_SHELL(", 1);
    assert_ne!(text, good());
    let e = err(text.as_bytes());
    assert!(
        matches!(e, StepError::OpenShell { .. } | StepError::NoBrep { .. }),
        "{e:?}"
    );
    assert!(e.to_string().contains("bad.step"));
}

#[test]
fn missing_file_is_an_io_error_naming_it() {
    let e = thinwall_step::read_file("/nonexistent/part.step").unwrap_err();
    assert_eq!(e.code(), "io");
    assert!(e.to_string().contains("/nonexistent/part.step"));
}

#[test]
fn a_shell_listing_a_face_twice_counts_it_once_and_says_so() {
    let text = good();
    let (part, _) = read_bytes(text.as_bytes(), "good.step").unwrap();
    let at = text.find("CLOSED_SHELL('',(").expect("a closed shell") + "CLOSED_SHELL('',(".len();
    let first: String = text[at..]
        .chars()
        .take_while(|c| *c != ',' && *c != ')')
        .collect();
    let doubled = format!("{}{first},{}", &text[..at], &text[at..]);
    let (again, report) = read_bytes(doubled.as_bytes(), "twice.step").unwrap();
    assert_eq!(again.faces.len(), part.faces.len());
    assert!(
        report
            .repaired
            .iter()
            .any(|r| r.message.contains("more than once")),
        "{:?}",
        report.repaired
    );
}
