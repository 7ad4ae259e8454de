//! A recognition written in the format asked for: the one place `recognize`
//! and `batch` turn a report into text, JSON, a picture or a page.

use thinwall_brep::Part;
use thinwall_pipeline::Outcome;
use thinwall_report::RecognitionReport;

/// The formats of a recognition.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum RecognitionFormat {
    Text,
    Json,
    /// An isometric picture, faces coloured by feature kind, with a legend.
    Svg,
    /// One self-contained page: a 3D view, the features, the connections.
    Html,
}

impl RecognitionFormat {
    /// The file extension of a report in this format.
    pub fn extension(self) -> &'static str {
        match self {
            RecognitionFormat::Text => "txt",
            RecognitionFormat::Json => "json",
            RecognitionFormat::Svg => "svg",
            RecognitionFormat::Html => "html",
        }
    }
}

/// The report of `part`'s recognition in `format`, titled `title`.
pub fn recognition(
    format: RecognitionFormat,
    part: &Part,
    outcome: &Outcome,
    report: &RecognitionReport,
    title: &str,
) -> String {
    match format {
        RecognitionFormat::Text => report.to_text(),
        RecognitionFormat::Json => report.to_json(),
        RecognitionFormat::Svg => {
            let a = thinwall_analysis::PartAnalysis::new(part, outcome.setup.clone());
            let mesh = thinwall_brep::tessellate::part_mesh(part);
            thinwall_report::svg::picture(&a, &mesh, &report.stiffness_features, title, 1000.0)
        }
        RecognitionFormat::Html => {
            let a = thinwall_analysis::PartAnalysis::new(part, outcome.setup.clone());
            thinwall_report::html::recognition_page(title, &a, report)
        }
    }
}
