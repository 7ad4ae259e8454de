//! A static picture of a recognized part for documents
//! (`thinwall recognize --format svg`): an isometric view along the
//! set-up's stock axes, the part's triangles (`thinwall_brep::tessellate`)
//! shaded and coloured by the kind of stiffness feature each face belongs
//! to, hidden faces removed by drawing far to near (faces turned away are
//! left out; faces cut in small pieces so the order holds), and a legend.
//! No edges are drawn: far-to-near drawing cannot hide an edge just behind
//! a thin wall, and a wrong edge misleads more than none.

use std::collections::{BTreeMap, HashMap};
use std::fmt::Write;
use thinwall_analysis::{PartAnalysis, StiffnessKind};
use thinwall_brep::tessellate::Mesh;
use thinwall_geom::{Point3, Vector3};

/// The kind of feature each face (by step id) belongs to: walls first,
/// then what is in or on them.
pub(crate) fn face_kinds(features: &[crate::FeatureEntry]) -> HashMap<u64, StiffnessKind> {
    let mut m = HashMap::new();
    for pass in [false, true] {
        for f in features.iter().filter(|f| f.feature.kind.is_wall() == pass) {
            let tops = f.feature.top_end_faces.iter().flatten();
            for &s in f.feature.faces.iter().chain(tops) {
                m.insert(s, f.feature.kind);
            }
        }
    }
    m
}

/// The picture, `width` pixels wide.
pub fn picture(
    a: &PartAnalysis,
    mesh: &Mesh,
    features: &[crate::FeatureEntry],
    title: &str,
    width: f64,
) -> String {
    let part = a.part();
    let (e1, e2, up) = view_axes(a);
    // Looking down along −(e1 + e2 + up): the box's iso view.
    let view = -(e1 + e2 + up).normalize();
    let right = up.cross(&view).try_normalize(1e-12).unwrap_or(e1);
    let screen_up = view.cross(&right);
    let to_screen = |p: &Point3| [p.coords.dot(&right), -p.coords.dot(&screen_up)];
    let light = (-view + up * 0.6 + right * 0.3).normalize();
    let kinds = face_kinds(features);
    let size = part.bounding_box().diagonal().max(1e-9);
    let piece = 0.05 * size;
    let mut items: Vec<(f64, String)> = Vec::new();
    let mut used: BTreeMap<&'static str, (usize, [u8; 3])> = BTreeMap::new();
    for fm in &mesh.faces {
        let step = part.face(fm.face).step_id;
        let kind = kinds.get(&step).copied();
        let c = crate::palette::stiffness(kind);
        let name = kind.map_or("other", |k| k.name());
        let entry = used.entry(name).or_insert((0, c));
        entry.0 += 1;
        let pieces = fm.triangles.iter().flat_map(|t| {
            // Small pieces: far-to-near drawing orders large faces badly.
            small_pieces(t.map(|i| mesh.points[i as usize]), piece)
        });
        for [p, q, r] in pieces {
            let n = (q - p).cross(&(r - p));
            let Some(n) = n.try_normalize(1e-300) else {
                continue;
            };
            if n.dot(&view) >= 0.0 {
                continue; // turned away
            }
            let shade = 0.45 + 0.55 * n.dot(&light).abs();
            let fill = c.map(|x| (x as f64 * shade).round().min(255.0) as u8);
            // Seen from above, a floor is never in front of the wall
            // standing on it where the two overlap on the picture: floors
            // go back half a piece, so those behind a wall stay behind it.
            let floor = if n.dot(&up) > 0.5 { 0.5 * piece } else { 0.0 };
            let depth = (p.coords + q.coords + r.coords).dot(&view) / 3.0 + floor;
            let [a, b, cc] = [to_screen(&p), to_screen(&q), to_screen(&r)];
            let hex = format!("#{:02x}{:02x}{:02x}", fill[0], fill[1], fill[2]);
            items.push((
                depth,
                format!(
                    "<polygon points=\"{:.2},{:.2} {:.2},{:.2} {:.2},{:.2}\" fill=\"{hex}\" stroke=\"{hex}\" stroke-width=\"0.4\"/>",
                    a[0], a[1], b[0], b[1], cc[0], cc[1]
                ),
            ));
        }
    }
    // Far first.
    items.sort_by(|x, y| y.0.total_cmp(&x.0));
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in &mesh.points {
        let s = to_screen(p);
        for k in 0..2 {
            lo[k] = lo[k].min(s[k]);
            hi[k] = hi[k].max(s[k]);
        }
    }
    let (w, h) = ((hi[0] - lo[0]).max(1e-9), (hi[1] - lo[1]).max(1e-9));
    let scale = (width - 220.0).max(100.0) / w;
    let height = (h * scale + 40.0).max(40.0 + 22.0 * used.len() as f64);
    let mut s = String::new();
    let _ = writeln!(
        s,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width:.0}\" height=\"{height:.0}\" viewBox=\"0 0 {width:.0} {height:.0}\">"
    );
    let _ = writeln!(s, "<title>{}</title>", escape(title));
    let _ = writeln!(s, "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>");
    let _ = writeln!(
        s,
        "<g transform=\"translate({:.3},{:.3}) scale({scale:.6}) translate({:.3},{:.3})\" stroke-linejoin=\"round\">",
        20.0, 20.0, -lo[0], -lo[1]
    );
    for (_, item) in &items {
        s.push_str(item);
        s.push('\n');
    }
    s.push_str("</g>\n");
    // Legend.
    let x0 = width - 190.0;
    let _ = writeln!(s, "<g font-family=\"sans-serif\" font-size=\"13\">");
    for (k, (name, (count, c))) in used.iter().enumerate() {
        let y = 24.0 + 22.0 * k as f64;
        let _ = writeln!(
            s,
            "<rect x=\"{x0}\" y=\"{:.0}\" width=\"14\" height=\"14\" fill=\"#{:02x}{:02x}{:02x}\" stroke=\"#303030\"/><text x=\"{:.0}\" y=\"{:.0}\">{name} ({count} faces)</text>",
            y - 11.0,
            c[0],
            c[1],
            c[2],
            x0 + 20.0,
            y
        );
    }
    s.push_str("</g>\n</svg>\n");
    s
}

/// The set-up's stock axes across up and up itself: the frame pictures
/// are drawn in (an isometric view looks down along −(e1 + e2 + up)), so
/// a turned part is drawn the same.
pub fn view_axes(a: &PartAnalysis) -> (Vector3, Vector3, Vector3) {
    let up = a.up();
    let stock = thinwall_machining::stock::Stock::of(a, Some(up));
    let across: Vec<Vector3> = stock
        .axes
        .iter()
        .copied()
        .filter(|x| x.dot(&up).abs() < 0.5)
        .collect();
    match across.as_slice() {
        [x, y, ..] => (*x, *y, up),
        _ => {
            let x = thinwall_geom::frame::any_perpendicular(&up);
            (x, up.cross(&x), up)
        }
    }
}

/// A triangle split in four until its sides are shorter than `longest`.
fn small_pieces(t: [Point3; 3], longest: f64) -> Vec<[Point3; 3]> {
    let side = |a: &Point3, b: &Point3| (b - a).norm();
    let [a, b, c] = t;
    if side(&a, &b).max(side(&b, &c)).max(side(&c, &a)) <= longest {
        return vec![t];
    }
    let mid = |p: &Point3, q: &Point3| Point3::from((p.coords + q.coords) * 0.5);
    let (ab, bc, ca) = (mid(&a, &b), mid(&b, &c), mid(&c, &a));
    [[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]
        .into_iter()
        .flat_map(|x| small_pieces(x, longest))
        .collect()
}

fn escape(t: &str) -> String {
    t.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}
