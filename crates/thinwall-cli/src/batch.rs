//! `thinwall batch`: many parts in parallel, one report each, and a
//! summary. A bad file (unreadable, tessellated only, or one that makes
//! Thinwall fail) is a line of the summary, never the end of the batch.

use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use serde::Serialize;
use std::collections::BTreeMap;
use std::io::IsTerminal;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::Instant;
use thinwall_cli::failure::Failure;
use thinwall_report::expect::{compare, CheckTolerance};

/// One line of the summary (`summary.jsonl`, in the order the parts
/// finish).
#[derive(Debug, Serialize)]
pub struct PartLine {
    pub file: String,
    pub ok: bool,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub report: Option<String>,
    pub faces: usize,
    pub features: BTreeMap<String, usize>,
    pub seconds: f64,
    /// Differences from the expectation (`--expect`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub differences: Option<Vec<String>>,
    /// Why it failed: the error's kind (`usage`, `input`, `internal`,
    /// `differs`) and message.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<(String, String)>,
}

/// What to run.
pub struct Batch {
    pub inputs: Vec<PathBuf>,
    pub out: PathBuf,
    pub jobs: usize,
    pub format: thinwall_study::Format,
    pub expect: Option<PathBuf>,
    pub request: thinwall_study::RecognizeRequest,
}

/// Run the batch; an error (exit 1) when any part failed.
pub fn command(b: Batch) -> Result<(), Failure> {
    if b.inputs.is_empty() {
        return Err(Failure::Usage("no input files".into()));
    }
    std::fs::create_dir_all(&b.out)
        .map_err(|e| Failure::Input(format!("{}: {e}", b.out.display())))?;
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(b.jobs.max(1))
        .build()
        .map_err(|e| Failure::Internal(format!("thread pool: {e}")))?;
    let progress = Progress::new(b.inputs.len());
    let names = report_names(&b.inputs);
    let summary = Summary::create(&b.out)?;
    let t0 = Instant::now();
    let lines: Vec<PartLine> = pool.install(|| {
        // One part a task: parts differ in cost a hundredfold (a few large
        // parts at the end of a list must not all fall to one job).
        b.inputs
            .par_iter()
            .zip(names.par_iter())
            .with_max_len(1)
            .map(|(path, name)| {
                let line = one(&b, path, name);
                summary.append(&line);
                progress.done(&line);
                line
            })
            .collect()
    });
    progress.finish();
    let wall_seconds = t0.elapsed().as_secs_f64();
    summary.finish()?;
    print!("{}", table(&lines));
    let failed = lines.iter().filter(|l| !l.ok).count();
    println!(
        "{} parts, {} failed, {:.2} s with {} job(s); summary in {}",
        lines.len(),
        failed,
        wall_seconds,
        b.jobs.max(1),
        b.out.join("summary.jsonl").display()
    );
    match failed {
        0 => Ok(()),
        n => Err(Failure::Input(format!(
            "{n} of {} parts failed",
            lines.len()
        ))),
    }
}

/// A report name per input: its file stem, numbered where stems repeat.
fn report_names(inputs: &[PathBuf]) -> Vec<String> {
    let mut seen: BTreeMap<String, usize> = BTreeMap::new();
    inputs
        .iter()
        .map(|p| {
            let stem = p
                .file_stem()
                .map_or("part".to_string(), |s| s.to_string_lossy().to_string());
            let n = seen.entry(stem.clone()).or_insert(0);
            *n += 1;
            match *n {
                1 => stem,
                k => format!("{stem}-{k}"),
            }
        })
        .collect()
}

/// One part: recognize, write its report, compare with its expectation.
/// A panic is caught here and becomes an internal failure of that part.
fn one(b: &Batch, path: &Path, name: &str) -> PartLine {
    let t0 = Instant::now();
    let run = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| recognize(b, path, name)));
    let mut line = PartLine {
        file: path.display().to_string(),
        ok: false,
        report: None,
        faces: 0,
        features: BTreeMap::new(),
        seconds: 0.0,
        differences: None,
        error: None,
    };
    match run {
        Ok(Ok(done)) => {
            line.ok = done.differences.as_ref().is_none_or(|d| d.is_empty());
            if !line.ok {
                line.error = Some(("differs".into(), "differs from its expectation".into()));
            }
            line.report = Some(done.report);
            line.faces = done.faces;
            line.features = done.features;
            line.differences = done.differences;
        }
        Ok(Err(f)) => line.error = Some((f.kind().to_string(), f.message().to_string())),
        Err(panic) => {
            let why = panic
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_default();
            line.error = Some(("internal".into(), format!("Thinwall failed: {why}")));
        }
    }
    line.seconds = t0.elapsed().as_secs_f64();
    line
}

struct Done {
    report: String,
    faces: usize,
    features: BTreeMap<String, usize>,
    differences: Option<Vec<String>>,
}

fn recognize(b: &Batch, path: &Path, name: &str) -> Result<Done, Failure> {
    let loaded = thinwall_study::LoadedPart::read_file(path)?;
    let study = crate::limits::study(&loaded).with_parallelism(b.request.parallel);
    let recognized = thinwall_study::recognize(&study, &b.request)?;
    let report = &recognized.report;
    let mut features = BTreeMap::new();
    for f in &report.stiffness_features {
        *features.entry(f.feature.kind.to_string()).or_insert(0) += 1;
    }
    let (json, faces) = (report.to_json(), report.faces.len());
    let text = thinwall_study::render(&recognized.into(), b.format)?;
    let file = b.out.join(format!("{name}.{}", b.format.extension()));
    std::fs::write(&file, &text).map_err(|e| Failure::Input(format!("{}: {e}", file.display())))?;
    let differences = match &b.expect {
        Some(dir) => Some(differences(
            &dir.join(format!("{name}.expect.json")),
            &json,
        )?),
        None => None,
    };
    Ok(Done {
        report: file.display().to_string(),
        faces,
        features,
        differences,
    })
}

/// Differences of a report from the expectation at `expect`.
fn differences(expect: &Path, actual: &str) -> Result<Vec<String>, Failure> {
    let text = std::fs::read_to_string(expect)
        .map_err(|e| Failure::Input(format!("{}: {e}", expect.display())))?;
    let e: serde_json::Value = serde_json::from_str(&text)
        .map_err(|e| Failure::Input(format!("{}: not JSON: {e}", expect.display())))?;
    let a: serde_json::Value =
        serde_json::from_str(actual).map_err(|e| Failure::Internal(e.to_string()))?;
    let d = compare(&e, &a, CheckTolerance::default())
        .map_err(|x| Failure::Input(format!("{}: {x}", expect.display())))?;
    Ok(d.iter().map(|x| x.to_string()).collect())
}

/// `summary.jsonl`, a line appended as each part finishes (a batch that
/// is stopped leaves the lines of the parts it finished).
struct Summary {
    path: PathBuf,
    file: Mutex<Result<std::fs::File, String>>,
}

impl Summary {
    fn create(out: &Path) -> Result<Self, Failure> {
        let path = out.join("summary.jsonl");
        let file = std::fs::File::create(&path)
            .map_err(|e| Failure::Input(format!("{}: {e}", path.display())))?;
        Ok(Self {
            path,
            file: Mutex::new(Ok(file)),
        })
    }

    /// Append `line`; the first failure to write is kept for [`finish`].
    fn append(&self, line: &PartLine) {
        let mut file = self.file.lock().unwrap_or_else(|p| p.into_inner());
        if let Ok(f) = file.as_mut() {
            let text = serde_json::to_string(line).unwrap_or_default() + "\n";
            if let Err(e) = f.write_all(text.as_bytes()).and_then(|()| f.flush()) {
                *file = Err(e.to_string());
            }
        }
    }

    fn finish(self) -> Result<(), Failure> {
        match self.file.into_inner().unwrap_or_else(|p| p.into_inner()) {
            Ok(_) => Ok(()),
            Err(e) => Err(Failure::Input(format!("{}: {e}", self.path.display()))),
        }
    }
}

/// The summary as a table: file, faces, features by kind, time, and why
/// a part failed.
fn table(lines: &[PartLine]) -> String {
    use std::fmt::Write;
    let width = lines
        .iter()
        .map(|l| l.file.len())
        .max()
        .unwrap_or(4)
        .clamp(4, 60);
    let mut s = String::new();
    let _ = writeln!(
        s,
        "{:<width$}  {:>6}  {:>8}  features",
        "file", "faces", "seconds"
    );
    for l in lines {
        let file = if l.file.len() > width {
            format!("…{}", &l.file[l.file.len() - (width - 1)..])
        } else {
            l.file.clone()
        };
        let what = match &l.error {
            Some((kind, why)) if kind != "differs" => format!("FAILED ({kind}): {why}"),
            _ => {
                let mut f: Vec<String> =
                    l.features.iter().map(|(k, n)| format!("{n} {k}")).collect();
                if f.is_empty() {
                    f.push("none".into());
                }
                if let Some(d) = l.differences.as_ref().filter(|d| !d.is_empty()) {
                    f.push(format!("DIFFERS: {}", d.join("; ")));
                }
                f.join(", ")
            }
        };
        let _ = writeln!(
            s,
            "{file:<width$}  {:>6}  {:>8.3}  {what}",
            l.faces, l.seconds
        );
    }
    s
}

/// A progress bar on a terminal, plain lines otherwise.
struct Progress {
    bar: Option<ProgressBar>,
    total: usize,
    count: AtomicUsize,
}

impl Progress {
    fn new(total: usize) -> Self {
        let bar = std::io::stderr().is_terminal().then(|| {
            let b = ProgressBar::new(total as u64);
            if let Ok(style) = ProgressStyle::with_template(
                "{bar:40} {pos}/{len} parts, {elapsed} ({eta} left) {msg}",
            ) {
                b.set_style(style);
            }
            b
        });
        Self {
            bar,
            total,
            count: AtomicUsize::new(0),
        }
    }

    fn done(&self, line: &PartLine) {
        let k = self.count.fetch_add(1, Ordering::SeqCst) + 1;
        let state = match &line.error {
            None => "ok".to_string(),
            Some((kind, _)) => kind.clone(),
        };
        match &self.bar {
            Some(b) => {
                b.set_message(format!("{} {state}", line.file));
                b.inc(1);
            }
            None => eprintln!(
                "[{k}/{}] {} {state} {:.2} s",
                self.total, line.file, line.seconds
            ),
        }
    }

    fn finish(&self) {
        if let Some(b) = &self.bar {
            b.finish_and_clear();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn repeated_stems_get_numbered_report_names() {
        let inputs: Vec<PathBuf> = ["a/part.step", "b/part.step", "c/other.stp"]
            .iter()
            .map(PathBuf::from)
            .collect();
        assert_eq!(report_names(&inputs), ["part", "part-2", "other"]);
    }
}
