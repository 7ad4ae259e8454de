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
        // Any outcome but a panic is acceptable; an error must name the file.
        if let Err(e) = read_bytes(&text.as_bytes()[..cut], "bad.step") {
            assert!(e.to_string().contains("bad.step"), "{e}");
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
    assert!(msg.contains("bad.step") && msg.contains('#'), "{msg}");
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
