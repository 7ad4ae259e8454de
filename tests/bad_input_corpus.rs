//! A corpus of mutated real files (tests/common/mutate.rs): every class of
//! bad input ends with a typed error of the input kind (the class's own
//! code where it decides one: `read.cyclic_reference`, `read.bad_number`,
//! …) or is read and then recognized, planned and given operations without
//! a failure of Thinwall's own. A panic, a stack overflow (which kills this
//! test) or an internal error counts as a failure.
//!
//! CI runs it on three bases; `THINWALL_LONG=1` runs every shared
//! thin-walled part and NIST part as a base (the long run).

mod common;

use common::mutate::{assembly_corpus, corpus, Mutant};
use thinwall_study::{ErrorKind, LoadedPart, Study, StudyError};

fn bases() -> Vec<std::path::PathBuf> {
    let data = common::shared_data();
    if std::env::var_os("THINWALL_LONG").is_some() {
        let mut v = common::step_files(&data.join("thinwall"));
        v.extend(common::step_files(&data.join("nist")));
        v
    } else {
        vec![
            data.join("thinwall/loose_rib_00.step"),
            data.join("thinwall/filleted_rib_04.step"),
            common::root().join("fixtures/bracket_assembly.step"),
        ]
    }
}

fn mutants() -> Vec<Mutant> {
    let mut all = Vec::new();
    for path in bases() {
        // Only parts that read: a mutation of a file that is refused as it
        // is (NIST FTC 08 holds a mesh only) shows nothing.
        if thinwall_step::read_file(&path).is_err() {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        let base = path.file_stem().unwrap().to_string_lossy().to_string();
        all.extend(corpus(&base, &text));
    }
    let assembly =
        std::fs::read_to_string(common::root().join("fixtures/bracket_assembly.step")).unwrap();
    all.extend(assembly_corpus("bracket_assembly", &assembly, 15, 20_000));
    all
}

/// What went wrong with one mutant, if anything, and whether it was read.
fn judge(m: &Mutant) -> (bool, Option<String>) {
    let read = LoadedPart::read_bytes(&m.bytes, &m.name);
    let ok = read.is_ok();
    (ok, judge_read(m, read))
}

fn judge_read(m: &Mutant, read: Result<LoadedPart, StudyError>) -> Option<String> {
    let bad = |e: &StudyError| e.kind() == ErrorKind::Internal;
    let loaded = match read {
        Err(e) => {
            if bad(&e) {
                return Some(format!("internal error on reading: {e}"));
            }
            if !e.to_string().starts_with(&m.name) {
                return Some(format!("the message does not name the file: {e}"));
            }
            return match m.expect {
                Some(code) if e.code() != format!("read.{code}") => {
                    Some(format!("expected read.{code}, got {}: {e}", e.code()))
                }
                _ => None,
            };
        }
        Ok(loaded) => loaded,
    };
    if let Some(code) = m.expect {
        return Some(format!(
            "read, although it should be refused with read.{code}"
        ));
    }
    let study = Study::new(&loaded).with_parallelism(false);
    let recognized = thinwall_study::recognize(&study, &Default::default()).err();
    let plan = thinwall_study::plan(
        &study,
        &thinwall_study::PlanRequest::new(
            Default::default(),
            thinwall_plan::RuleSet::default_rules(),
        ),
    )
    .err();
    let setup = thinwall_analysis::Setup::default();
    let ops =
        thinwall_study::operations(&study, &thinwall_study::OperationsRequest::new(setup)).err();
    [recognized, plan, ops]
        .into_iter()
        .flatten()
        .find(bad)
        .map(|e| format!("internal error: {e}"))
}

#[test]
fn every_mutated_file_ends_with_a_typed_error_or_a_result_never_a_panic() {
    let all = mutants();
    assert!(all.len() >= 60, "{} mutants", all.len());
    let judged: Vec<(bool, Option<String>)> = all.iter().map(judge).collect();
    let read = judged.iter().filter(|j| j.0).count();
    eprintln!(
        "{} mutated files, {read} of them read and run through every command",
        all.len()
    );
    let failures: Vec<String> = all
        .iter()
        .zip(judged)
        .filter_map(|(m, (_, why))| why.map(|why| format!("{} ({}): {why}", m.name, m.class)))
        .collect();
    assert!(
        failures.is_empty(),
        "{} of {} mutated files went wrong:\n{}",
        failures.len(),
        all.len(),
        failures.join("\n")
    );
}

#[test]
fn every_class_of_the_corpus_is_made() {
    let all = mutants();
    for class in [
        "unit_self",
        "unit_pair",
        "unit_factor",
        "vertex_coordinate",
        "radius",
        "knot",
        "truncated",
        "garbage",
        "rootless_cycle",
        "amplifying_tree",
        "mapped_items",
    ] {
        assert!(
            all.iter().any(|m| m.class == class),
            "no {class} mutant made"
        );
    }
}
