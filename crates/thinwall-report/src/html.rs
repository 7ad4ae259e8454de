//! The self-contained HTML report (`--format html -o FILE`): one file that
//! opens from disk with no network. It holds the report's own JSON (the
//! same contract as `--format json`), the tessellated part (and, for a
//! plan or a classification, the volumes), the colour table, the viewer
//! (`assets/report.js`, `assets/report.css`) and three.js (vendored by
//! `scripts/vendor_three.sh`, MIT, licence in `vendor/three/LICENSE`), all
//! inline. The viewer draws the part coloured by feature, lists the
//! features, highlights a feature's faces, draws the connection structure,
//! steps through a plan's machining-feature order and shows a classified
//! volume's closed and open faces (`docs/REPORTS.md`).

use crate::{ClassificationReport, RecognitionReport};
use serde::Serialize;
use std::collections::BTreeMap;
use thinwall_analysis::PartAnalysis;
use thinwall_brep::tessellate::{part_mesh, Mesh};
use thinwall_brep::Part;
use thinwall_plan::Plan;

/// Version tag of the data block inside the page (`<script id="tw-data">`).
pub const HTML_DATA_SCHEMA: &str = "thinwall/html-report/1";

const TEMPLATE: &str = include_str!("../assets/report.html");
const STYLE: &str = include_str!("../assets/report.css");
const APP: &str = include_str!("../assets/report.js");
const THREE: &str = include_str!("../vendor/three/three-bundle.min.js");
const THREE_LICENSE: &str = include_str!("../vendor/three/LICENSE");

/// The triangles of a part (or of a volume) in the page, per face.
#[derive(Clone, Debug, Serialize)]
pub struct Geometry {
    pub faces: Vec<FaceGeometry>,
    /// Every edge as a polyline, flat `x, y, z, x, y, z, …` in mm.
    pub edges: Vec<Vec<f64>>,
}

/// One face: its own points (flat, mm) and triangles (indices into them,
/// counter-clockwise seen from outside the material), or why it has none.
#[derive(Clone, Debug, Serialize)]
pub struct FaceGeometry {
    pub step_id: u64,
    pub body: u32,
    pub surface: &'static str,
    pub points: Vec<f64>,
    pub triangles: Vec<u32>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub issue: Option<String>,
}

/// A removal volume in the page: a plan's machining feature (id `V3`) or a
/// classified volume (its file name).
#[derive(Clone, Debug, Serialize)]
pub struct VolumeGeometry {
    pub id: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub geometry: Option<Geometry>,
    /// Why it is not drawn.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
}

/// What the page shows besides the part.
#[derive(Serialize)]
#[serde(tag = "view", rename_all = "snake_case")]
enum View<'a> {
    Recognition,
    Plan {
        plan: serde_json::Value,
        /// Per set-up after the first (`plan.then`), its features'
        /// volumes (the first set-up's are the page's `volumes`).
        #[serde(skip_serializing_if = "Vec::is_empty")]
        later_volumes: Vec<Vec<VolumeGeometry>>,
    },
    Classification {
        classification: &'a ClassificationReport,
    },
    Access {
        access: &'a crate::access::AccessReport,
    },
    Operations {
        operations: &'a crate::operations::OperationsReport,
    },
}

#[derive(Serialize)]
struct PageData<'a> {
    schema: &'static str,
    title: &'a str,
    /// The set-up's up and the stock axes across it: the view's frame.
    up: [f64; 3],
    across: [[f64; 3]; 2],
    /// The part's diagonal, mm.
    size: f64,
    palette: BTreeMap<String, String>,
    part: Geometry,
    /// The recognition (also under a plan: it names the part's faces).
    #[serde(skip_serializing_if = "Option::is_none")]
    recognition: Option<&'a RecognitionReport>,
    /// With a recognition: the kind of stiffness feature each face of
    /// `part` shows (`svg::face_kinds`, the pictures' one rule).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    face_kinds: Vec<Option<thinwall_analysis::StiffnessKind>>,
    #[serde(flatten)]
    view: View<'a>,
    volumes: Vec<VolumeGeometry>,
}

/// Round to 1e-4 mm: the page's coordinates.
fn round(x: f64) -> f64 {
    (x * 1e4).round() / 1e4
}

/// A mesh as the page's geometry: each face with its own points.
pub fn geometry(part: &Part, mesh: &Mesh) -> Geometry {
    let faces = mesh
        .faces
        .iter()
        .map(|fm| {
            let face = part.face(fm.face);
            let mut local: BTreeMap<u32, u32> = BTreeMap::new();
            let mut points = Vec::new();
            let mut triangles = Vec::with_capacity(fm.triangles.len() * 3);
            for &i in fm.triangles.iter().flatten() {
                let next = local.len() as u32;
                let k = *local.entry(i).or_insert_with(|| {
                    let p = mesh.points[i as usize];
                    points.extend([round(p.x), round(p.y), round(p.z)]);
                    next
                });
                triangles.push(k);
            }
            FaceGeometry {
                step_id: face.step_id,
                body: face.body.0,
                surface: face.surface.kind_name(),
                points,
                triangles,
                issue: fm.issue.clone(),
            }
        })
        .collect();
    let edges = mesh
        .edges
        .iter()
        .map(|ids| {
            ids.iter()
                .flat_map(|&i| {
                    let p = mesh.points[i as usize];
                    [round(p.x), round(p.y), round(p.z)]
                })
                .collect()
        })
        .collect();
    Geometry { faces, edges }
}

/// A recognition report as a page.
pub fn recognition_page(title: &str, a: &PartAnalysis, report: &RecognitionReport) -> String {
    page(title, a, Some(report), View::Recognition, Vec::new())
}

/// A plan as a page: the part coloured by the recognition, every machining
/// feature's solids numbered in the plan's order.
pub fn plan_page(title: &str, a: &PartAnalysis, report: &RecognitionReport, plan: &Plan) -> String {
    let volumes = plan_volumes(plan);
    let later_volumes = plan.then.iter().map(plan_volumes).collect();
    let plan = serde_json::to_value(plan).unwrap_or(serde_json::Value::Null);
    page(
        title,
        a,
        Some(report),
        View::Plan {
            plan,
            later_volumes,
        },
        volumes,
    )
}

/// One set-up's machining features as pictures (a note where its solids
/// are not written yet).
fn plan_volumes(plan: &Plan) -> Vec<VolumeGeometry> {
    plan.machining_features
        .iter()
        .map(|f| match thinwall_plan::volumes::feature_part(plan, f) {
            Some(p) => VolumeGeometry {
                id: f.id.to_string(),
                geometry: Some(geometry(&p, &part_mesh(&p))),
                note: None,
            },
            None => VolumeGeometry {
                id: f.id.to_string(),
                geometry: None,
                note: Some("its solids (over a cone) are not written yet".to_string()),
            },
        })
        .collect()
}

/// A classification as a page: the part, and every volume (`volumes`, in
/// the report's order) with its closed and open faces.
pub fn classification_page(
    title: &str,
    a: &PartAnalysis,
    report: &ClassificationReport,
    volumes: &[&Part],
) -> String {
    let volumes = report
        .volumes
        .iter()
        .zip(volumes)
        .map(|(c, p)| VolumeGeometry {
            id: c.name.clone(),
            geometry: Some(geometry(p, &part_mesh(p))),
            note: None,
        })
        .collect();
    page(
        title,
        a,
        None,
        View::Classification {
            classification: report,
        },
        volumes,
    )
}

/// An accessibility report as a page: planar faces coloured by how much
/// of them flank milling reaches, the G-zones drawn, the directions used.
pub fn access_page(title: &str, a: &PartAnalysis, report: &crate::access::AccessReport) -> String {
    page(title, a, None, View::Access { access: report }, Vec::new())
}

/// An operations report as a page: the operations in order, each drawn
/// as its passes' cutter fields at their levels over the part.
pub fn operations_page(
    title: &str,
    a: &PartAnalysis,
    report: &crate::operations::OperationsReport,
) -> String {
    page(
        title,
        a,
        None,
        View::Operations { operations: report },
        Vec::new(),
    )
}

fn page(
    title: &str,
    a: &PartAnalysis,
    recognition: Option<&RecognitionReport>,
    view: View<'_>,
    volumes: Vec<VolumeGeometry>,
) -> String {
    let part = a.part();
    let (e1, e2, up) = crate::svg::view_axes(a);
    let data = PageData {
        schema: HTML_DATA_SCHEMA,
        title,
        up: up.into(),
        across: [e1.into(), e2.into()],
        size: part.bounding_box().diagonal(),
        palette: crate::palette::table(),
        part: geometry(part, a.mesh()),
        face_kinds: recognition
            .map(|r| crate::svg::face_kinds(part, &r.stiffness_features))
            .unwrap_or_default(),
        recognition,
        view,
        volumes,
    };
    let json = serde_json::to_string(&data).unwrap_or_else(|_| "null".to_string());
    fill(title, &json)
}

/// The template with its parts inline, each placeholder of the template
/// filled once. Text inside `<script>` must not end it: in JSON every `<`
/// is written `\u003c`; in the scripts `</script` is written `<\/script`
/// (the same string in JS), and `<!--` may not occur (checked by a test).
fn fill(title: &str, json: &str) -> String {
    let script_safe = |s: &str| s.replace("</script", "<\\/script");
    let licence = THREE_LICENSE.replace("*/", "* /");
    let mut out = String::with_capacity(TEMPLATE.len() + THREE.len() + json.len() + APP.len());
    let mut rest = TEMPLATE;
    while let Some(at) = rest.find("{{") {
        out.push_str(&rest[..at]);
        let Some(end) = rest[at..].find("}}") else {
            break;
        };
        match &rest[at + 2..at + end] {
            "TITLE" => out.push_str(&escape(title)),
            "STYLE" => out.push_str(STYLE),
            "THREE_LICENSE" => out.push_str(&licence),
            "THREE" => out.push_str(&script_safe(THREE)),
            "APP" => out.push_str(&script_safe(APP)),
            "DATA" => out.push_str(&json.replace('<', "\\u003c")),
            other => out.push_str(other),
        }
        rest = &rest[at + end + 2..];
    }
    out.push_str(rest);
    out
}

fn escape(t: &str) -> String {
    t.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// The page's data block, read back (for tests and tools).
pub fn data_of(page: &str) -> Option<serde_json::Value> {
    let start = page.find("<script type=\"application/json\" id=\"tw-data\">")?;
    let body = &page[start..];
    let open = body.find('>')? + 1;
    let close = body.find("</script>")?;
    serde_json::from_str(&body[open..close]).ok()
}
