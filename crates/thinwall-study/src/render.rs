//! Every result written in the format asked for: the one place a use
//! case's result becomes text, JSON, a picture or a page.

use crate::usecase::{Accessed, Classified, Inspected, Operated, Planned, Recognized};
use crate::StudyError;

/// The output formats. Not every result has every format: [`render`]
/// refuses one it has not ([`Rendered::formats`] says which it has).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Text,
    Json,
    /// An isometric picture with a legend.
    Svg,
    /// One self-contained page with a 3D view.
    Html,
}

impl Format {
    pub const ALL: [Format; 4] = [Format::Text, Format::Json, Format::Svg, Format::Html];

    pub fn name(self) -> &'static str {
        match self {
            Format::Text => "text",
            Format::Json => "json",
            Format::Svg => "svg",
            Format::Html => "html",
        }
    }

    /// The file extension of a report in this format.
    pub fn extension(self) -> &'static str {
        match self {
            Format::Text => "txt",
            other => other.name(),
        }
    }
}

impl std::str::FromStr for Format {
    type Err = StudyError;
    fn from_str(s: &str) -> Result<Self, StudyError> {
        Format::ALL
            .into_iter()
            .find(|f| f.name() == s)
            .ok_or_else(|| StudyError::invalid("format", format!("'{s}' is not a format")))
    }
}

/// A result of any use case (made once per command: its size is no cost).
#[allow(clippy::large_enum_variant)]
pub enum Rendered<'p> {
    Inspected(Inspected<'p>),
    Recognized(Recognized<'p>),
    Planned(Planned<'p>),
    Accessed(Accessed<'p>),
    Operated(Operated<'p>),
    Classified(Classified<'p>),
    Sized(thinwall_plan::Sizes),
}

impl Rendered<'_> {
    /// The formats this result can be written in.
    pub fn formats(&self) -> &'static [Format] {
        use Format::*;
        match self {
            Rendered::Inspected(_) | Rendered::Sized(_) => &[Text, Json],
            Rendered::Accessed(_) | Rendered::Operated(_) => &[Text, Json, Html],
            _ => &[Text, Json, Svg, Html],
        }
    }
}

macro_rules! from_result {
    ($($v:ident),*) => {$(
        impl<'p> From<$v<'p>> for Rendered<'p> {
            fn from(r: $v<'p>) -> Self {
                Rendered::$v(r)
            }
        }
    )*};
}
from_result!(Inspected, Recognized, Planned, Accessed, Operated, Classified);

impl From<thinwall_plan::Sizes> for Rendered<'_> {
    fn from(s: thinwall_plan::Sizes) -> Self {
        Rendered::Sized(s)
    }
}

/// `result` in `format`; an error when the result has no such format.
pub fn render(result: &Rendered, format: Format) -> Result<String, StudyError> {
    if !result.formats().contains(&format) {
        return Err(StudyError::invalid(
            "format",
            format!("'{}' is not a format of this result", format.name()),
        ));
    }
    Ok(match result {
        Rendered::Inspected(r) => {
            text_or_json(format, || r.report.to_text(), || r.report.to_json())
        }
        Rendered::Recognized(r) => recognition(r, format),
        Rendered::Planned(r) => plan(r, format),
        Rendered::Accessed(r) => match format {
            Format::Html => {
                let title = format!("Access: {}", r.report.part);
                thinwall_report::html::access_page(&title, &r.at.analysis, &r.report)
            }
            _ => text_or_json(format, || r.report.to_text(), || r.report.to_json()),
        },
        Rendered::Operated(r) => match format {
            Format::Html => {
                let title = format!("Operations: {}", r.report.part);
                thinwall_report::html::operations_page(&title, &r.at.analysis, &r.report)
            }
            _ => text_or_json(format, || r.report.to_text(), || r.report.to_json()),
        },
        Rendered::Classified(r) => classification(r, format),
        Rendered::Sized(s) => text_or_json(
            format,
            || s.to_text(),
            || serde_json::to_string_pretty(s).expect("sizes serialise") + "\n",
        ),
    })
}

fn text_or_json(
    format: Format,
    text: impl FnOnce() -> String,
    json: impl FnOnce() -> String,
) -> String {
    match format {
        Format::Json => json(),
        _ => text(),
    }
}

fn recognition(r: &Recognized, format: Format) -> String {
    let a = &r.at.analysis;
    let title = &r.report.part.file;
    match format {
        Format::Text => r.report.to_text(),
        Format::Json => r.report.to_json(),
        Format::Svg => {
            thinwall_report::svg::picture(a, &r.report.stiffness_features, title, 1000.0)
        }
        Format::Html => thinwall_report::html::recognition_page(title, a, &r.report),
    }
}

fn plan(r: &Planned, format: Format) -> String {
    let a = &r.at.analysis;
    match format {
        Format::Text => thinwall_report::plan::to_text(&r.plan),
        Format::Json => thinwall_report::plan::to_json(&r.plan),
        Format::Svg | Format::Html => {
            let report = thinwall_report::recognition_report(&r.plan.file, a.part(), &r.outcome);
            let title = format!("Plan: {}", r.plan.file);
            match format {
                Format::Svg => thinwall_report::svg::plan_picture(
                    a,
                    &report.stiffness_features,
                    &r.plan,
                    &title,
                    1000.0,
                ),
                _ => thinwall_report::html::plan_page(&title, a, &report, &r.plan),
            }
        }
    }
}

fn classification(r: &Classified, format: Format) -> String {
    let a = &r.at.analysis;
    match format {
        Format::Text => r.report.to_text(),
        Format::Json => r.report.to_json(),
        Format::Svg | Format::Html => {
            let parts: Vec<&thinwall_brep::Part> = r.volumes.iter().map(|v| &v.part).collect();
            let title = format!("Classification: {}", r.report.part);
            match format {
                Format::Svg => thinwall_report::svg::classification_picture(
                    a, &r.report, &parts, &title, 1000.0,
                ),
                _ => thinwall_report::html::classification_page(&title, a, &r.report, &parts),
            }
        }
    }
}
