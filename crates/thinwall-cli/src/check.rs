//! `thinwall check`: a part's recognition against a stored one.

use std::path::Path;
use thinwall_cli::failure::Failure;
use thinwall_report::expect::{compare, CheckTolerance};

/// The part's recognition report as JSON text.
pub fn recognition_json(
    part: &Path,
    request: &thinwall_study::RecognizeRequest,
) -> Result<String, Failure> {
    let loaded = thinwall_study::LoadedPart::read_file(part)?;
    let study = crate::limits::study(&loaded);
    Ok(thinwall_study::recognize(&study, request)?.report.to_json())
}

/// Compare (or with `update`, store) and print the differences; an error
/// (exit 1) when there are any.
pub fn command(
    part: &Path,
    expect: &Path,
    update: bool,
    tol: CheckTolerance,
    request: thinwall_study::RecognizeRequest,
) -> Result<(), Failure> {
    if !(tol.absolute_mm >= 0.0 && tol.relative >= 0.0) {
        return Err(Failure::Usage("tolerances must be 0 or more".into()));
    }
    let actual = recognition_json(part, &request)?;
    if update {
        std::fs::write(expect, &actual)
            .map_err(|e| Failure::Input(format!("{}: {e}", expect.display())))?;
        println!(
            "{}: expectation written to {}",
            part.display(),
            expect.display()
        );
        return Ok(());
    }
    let text = std::fs::read_to_string(expect)
        .map_err(|e| Failure::Input(format!("{}: {e}", expect.display())))?;
    let parse = |t: &str, what: &Path| {
        serde_json::from_str::<serde_json::Value>(t)
            .map_err(|e| Failure::Input(format!("{}: not JSON: {e}", what.display())))
    };
    let (e, a) = (parse(&text, expect)?, parse(&actual, part)?);
    let diffs =
        compare(&e, &a, tol).map_err(|x| Failure::Input(format!("{}: {x}", expect.display())))?;
    if diffs.is_empty() {
        println!("{}: as expected ({})", part.display(), expect.display());
        return Ok(());
    }
    println!(
        "{}: {} difference(s) from {}",
        part.display(),
        diffs.len(),
        expect.display()
    );
    for d in &diffs {
        println!("  {d}");
    }
    Err(Failure::Input(format!(
        "{}: {} difference(s) from the expectation",
        part.display(),
        diffs.len()
    )))
}
