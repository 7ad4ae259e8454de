//! Static pictures for documents (`--format svg` of `recognize`, `plan`
//! and `classify`): an isometric view along the
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

/// The kind of feature each face of `part` belongs to (by position in
/// `part.face_ids()`), the one rule every picture colours by: what lies in
/// or on the walls first, then the walls over them, so a face a wall and a
/// detail share shows the wall. Faces are matched by body and STEP id
/// (instances of one solid share ids).
pub fn face_kinds(
    part: &thinwall_brep::Part,
    features: &[crate::FeatureEntry],
) -> Vec<Option<StiffnessKind>> {
    let mut m: HashMap<(u32, u64), StiffnessKind> = HashMap::new();
    for pass in [false, true] {
        for f in features.iter().filter(|f| f.feature.kind.is_wall() == pass) {
            let tops = f.feature.top_end_faces.iter().flatten();
            for &s in f.feature.faces.iter().chain(tops) {
                m.insert((f.feature.body, s), f.feature.kind);
            }
        }
    }
    part.face_ids()
        .map(|id| {
            let face = part.face(id);
            m.get(&(face.body.0, face.step_id)).copied()
        })
        .collect()
}

/// Something to draw: a mesh, a colour per face (by position in
/// `mesh.faces`) and an opacity (1 opaque; volumes around a part are drawn
/// see-through).
pub struct Layer<'m> {
    pub mesh: &'m Mesh,
    pub colours: Vec<[u8; 3]>,
    pub opacity: f64,
}

/// A text drawn on top, centred at a point (a feature's number).
pub struct Label {
    pub at: Point3,
    pub text: String,
}

/// A line of the legend.
pub struct Key {
    pub text: String,
    pub colour: [u8; 3],
}

/// The recognition's picture, `width` pixels wide: the part coloured by
/// the kind of stiffness feature of each face.
pub fn picture(
    a: &PartAnalysis,
    features: &[crate::FeatureEntry],
    title: &str,
    width: f64,
) -> String {
    let mesh = a.mesh();
    let (colours, legend) = part_colours(a, mesh, features);
    let layer = Layer {
        mesh,
        colours,
        opacity: 1.0,
    };
    draw(a, &[layer], &[], &legend, title, width)
}

/// Each face's colour by the kind of stiffness feature it belongs to, and
/// the legend of kinds with their face counts.
fn part_colours(
    a: &PartAnalysis,
    mesh: &Mesh,
    features: &[crate::FeatureEntry],
) -> (Vec<[u8; 3]>, Vec<Key>) {
    let kinds = face_kinds(a.part(), features);
    let mut used: BTreeMap<&'static str, (usize, [u8; 3])> = BTreeMap::new();
    let colours = mesh
        .faces
        .iter()
        .map(|fm| {
            let kind = kinds[fm.face.index()];
            let c = crate::palette::stiffness(kind);
            used.entry(kind.map_or("other", |k| k.name()))
                .or_insert((0, c))
                .0 += 1;
            c
        })
        .collect();
    let legend = used
        .into_iter()
        .map(|(name, (count, colour))| Key {
            text: format!("{name} ({count} faces)"),
            colour,
        })
        .collect();
    (colours, legend)
}

/// A plan's picture: the part, and every machining feature's solids
/// see-through in their class's colour, numbered in the plan's order
/// (when there are few enough to read: `MAX_NUMBERS`).
pub fn plan_picture(
    a: &PartAnalysis,
    features: &[crate::FeatureEntry],
    plan: &thinwall_plan::Plan,
    title: &str,
    width: f64,
) -> String {
    let part_mesh = a.mesh();
    let (colours, mut legend) = part_colours(a, part_mesh, features);
    let mut layers = vec![Layer {
        mesh: part_mesh,
        colours,
        opacity: 1.0,
    }];
    let rank: HashMap<&str, usize> = plan
        .feature_sequence
        .order
        .iter()
        .enumerate()
        .map(|(k, id)| (id.as_str(), k + 1))
        .collect();
    let meshes: Vec<(usize, Mesh, [u8; 3])> = plan
        .machining_features
        .iter()
        .filter_map(|f| {
            let part = thinwall_plan::volumes::feature_part(plan, f)?;
            let colour = crate::palette::plan_class(f.size_class.name());
            Some((
                rank.get(f.id.as_str()).copied().unwrap_or(0),
                thinwall_brep::tessellate::part_mesh(&part),
                colour,
            ))
        })
        .collect();
    let numbered = meshes.len() <= MAX_NUMBERS;
    let mut labels = Vec::new();
    for (n, mesh, colour) in &meshes {
        layers.push(Layer {
            mesh,
            colours: vec![*colour; mesh.faces.len()],
            opacity: 0.45,
        });
        if numbered {
            labels.push(Label {
                at: centre(mesh),
                text: n.to_string(),
            });
        }
    }
    for class in ["large", "small", "bulk", "other_setup", "detail"] {
        let count = plan
            .machining_features
            .iter()
            .filter(|f| f.size_class.name() == class)
            .count();
        if count > 0 {
            legend.push(Key {
                text: format!("{} ({count} features)", class.replace('_', " ")),
                colour: crate::palette::plan_class(class),
            });
        }
    }
    draw(a, &layers, &labels, &legend, title, width)
}

/// A classification's picture: the part see-through, every volume with
/// its closed faces red and its open faces green, numbered by index.
pub fn classification_picture(
    a: &PartAnalysis,
    report: &crate::ClassificationReport,
    volumes: &[&thinwall_brep::Part],
    title: &str,
    width: f64,
) -> String {
    let part_mesh = a.mesh();
    let mut layers = vec![Layer {
        colours: vec![crate::palette::OTHER; part_mesh.faces.len()],
        mesh: part_mesh,
        opacity: 0.3,
    }];
    let meshes: Vec<Mesh> = volumes
        .iter()
        .map(|p| thinwall_brep::tessellate::part_mesh(p))
        .collect();
    let (closed, open) = (crate::palette::CLOSED, crate::palette::OPEN);
    let mut labels = Vec::new();
    for ((c, part), mesh) in report.volumes.iter().zip(volumes).zip(&meshes) {
        let colours = mesh
            .faces
            .iter()
            .map(|fm| {
                let step = part.face(fm.face).step_id;
                match c.faces.iter().find(|f| f.step_id == step) {
                    Some(f) if f.closed => closed,
                    _ => open,
                }
            })
            .collect();
        layers.push(Layer {
            mesh,
            colours,
            opacity: 0.85,
        });
        labels.push(Label {
            at: centre(mesh),
            text: format!("{} {}", c.index, c.kind.name()),
        });
    }
    let legend = [
        Key {
            text: "closed face".into(),
            colour: closed,
        },
        Key {
            text: "open face".into(),
            colour: open,
        },
        Key {
            text: "part".into(),
            colour: crate::palette::OTHER,
        },
    ];
    draw(a, &layers, &labels, &legend, title, width)
}

/// More numbered volumes than this make an unreadable picture.
const MAX_NUMBERS: usize = 80;

/// The middle of a mesh's box.
fn centre(mesh: &Mesh) -> Point3 {
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for p in &mesh.points {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    Point3::new(
        0.5 * (lo[0] + hi[0]),
        0.5 * (lo[1] + hi[1]),
        0.5 * (lo[2] + hi[2]),
    )
}

/// The picture of `layers`, `width` pixels wide: an isometric view along
/// the set-up's stock axes, hidden faces removed by drawing far to near,
/// `labels` on top, the legend at the right.
pub fn draw(
    a: &PartAnalysis,
    layers: &[Layer],
    labels: &[Label],
    legend: &[Key],
    title: &str,
    width: f64,
) -> String {
    let iso = Iso::of(a);
    let size = a.part().bounding_box().diagonal().max(1e-9);
    let mut items = iso.pieces(layers, 0.05 * size);
    // Far first.
    items.sort_by(|x, y| y.0.total_cmp(&x.0));
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in layers.iter().flat_map(|l| &l.mesh.points) {
        let s = iso.to_screen(p);
        for k in 0..2 {
            lo[k] = lo[k].min(s[k]);
            hi[k] = hi[k].max(s[k]);
        }
    }
    let (w, h) = ((hi[0] - lo[0]).max(1e-9), (hi[1] - lo[1]).max(1e-9));
    let scale = (width - 220.0).max(100.0) / w;
    let height = (h * scale + 40.0).max(40.0 + 22.0 * legend.len() as f64);
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
    write_labels(&mut s, &iso, labels, lo, scale);
    write_legend(&mut s, legend, width);
    s.push_str("</g>\n</svg>\n");
    s
}

/// The isometric view: looking down along −(e1 + e2 + up) of the set-up's
/// stock axes, with the light.
struct Iso {
    view: Vector3,
    right: Vector3,
    screen_up: Vector3,
    up: Vector3,
    light: Vector3,
}

impl Iso {
    fn of(a: &PartAnalysis) -> Self {
        let (e1, e2, up) = view_axes(a);
        let view = -(e1 + e2 + up).normalize();
        let right = up.cross(&view).try_normalize(1e-12).unwrap_or(e1);
        let screen_up = view.cross(&right);
        let light = (-view + up * 0.6 + right * 0.3).normalize();
        Self {
            view,
            right,
            screen_up,
            up,
            light,
        }
    }

    fn to_screen(&self, p: &Point3) -> [f64; 2] {
        [p.coords.dot(&self.right), -p.coords.dot(&self.screen_up)]
    }

    /// Every triangle facing the eye, cut in pieces of about `piece` mm,
    /// as (depth, SVG polygon).
    fn pieces(&self, layers: &[Layer], piece: f64) -> Vec<(f64, String)> {
        let (view, up, light) = (self.view, self.up, self.light);
        let to_screen = |p: &Point3| self.to_screen(p);
        let mut items: Vec<(f64, String)> = Vec::new();
        for layer in layers {
            let mesh = layer.mesh;
            for (fm, c) in mesh.faces.iter().zip(&layer.colours) {
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
                    // standing on it where the two overlap on the picture:
                    // floors go back half a piece, so those behind a wall stay
                    // behind it.
                    let floor = if n.dot(&up) > 0.5 { 0.5 * piece } else { 0.0 };
                    let depth = (p.coords + q.coords + r.coords).dot(&view) / 3.0 + floor;
                    let [a, b, cc] = [to_screen(&p), to_screen(&q), to_screen(&r)];
                    let hex = crate::palette::hex(fill);
                    // Opaque pieces get a hairline of their own colour to close
                    // the seams; see-through ones none (it would draw the mesh).
                    let style = if layer.opacity < 1.0 {
                        format!("fill-opacity=\"{:.2}\" stroke=\"none\"", layer.opacity)
                    } else {
                        format!("stroke=\"{hex}\" stroke-width=\"0.4\"")
                    };
                    items.push((
                    depth,
                    format!(
                        "<polygon points=\"{:.2},{:.2} {:.2},{:.2} {:.2},{:.2}\" fill=\"{hex}\" {style}/>",
                        a[0], a[1], b[0], b[1], cc[0], cc[1]
                    ),
                ));
                }
            }
        }
        items
    }
}

/// The labels, on top, in picture pixels.
fn write_labels(s: &mut String, iso: &Iso, labels: &[Label], lo: [f64; 2], scale: f64) {
    let _ = writeln!(s, "<g font-family=\"sans-serif\" font-size=\"12\" font-weight=\"bold\" text-anchor=\"middle\">");
    for l in labels {
        let p = iso.to_screen(&l.at);
        let (x, y) = (20.0 + (p[0] - lo[0]) * scale, 20.0 + (p[1] - lo[1]) * scale);
        let w = 8.0 + 7.0 * l.text.chars().count() as f64;
        let _ = writeln!(
            s,
            "<rect x=\"{:.1}\" y=\"{:.1}\" width=\"{w:.0}\" height=\"16\" rx=\"5\" fill=\"white\" stroke=\"#1d232b\"/><text x=\"{x:.1}\" y=\"{:.1}\">{}</text>",
            x - w / 2.0,
            y - 8.0,
            y + 4.0,
            escape(&l.text)
        );
    }
    s.push_str("</g>\n");
}

/// The legend, at the right; its group is closed by the caller.
fn write_legend(s: &mut String, legend: &[Key], width: f64) {
    let x0 = width - 190.0;
    let _ = writeln!(s, "<g font-family=\"sans-serif\" font-size=\"13\">");
    for (k, key) in legend.iter().enumerate() {
        let y = 24.0 + 22.0 * k as f64;
        let _ = writeln!(
            s,
            "<rect x=\"{x0}\" y=\"{:.0}\" width=\"14\" height=\"14\" fill=\"{}\" stroke=\"#303030\"/><text x=\"{:.0}\" y=\"{:.0}\">{}</text>",
            y - 11.0,
            crate::palette::hex(key.colour),
            x0 + 20.0,
            y,
            escape(&key.text)
        );
    }
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
