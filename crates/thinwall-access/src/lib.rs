//! Accessibility of a part's faces for a planner (issue 16, started):
//! whether a planar face can be flank milled, by its G-zone (Harik & Ris,
//! DETC2006-99098; `../shared/docs/DOMAIN.md` §6).
//!
//! Per planar face: its edges' sharpness (closed where the neighbour rises
//! above the face's plane: a concave edge, or a tangent one into a concave
//! blend; open otherwise), its nature (closed, open, semi-open), candidate
//! milling directions from its closed edges by the paper's trade rules, the
//! obstacles above it within the tool's reach (the part's material in a
//! slab one tool diameter thick over the face, each face's piece projected
//! as its convex hull: the paper projects bounding shapes), and the G-zone:
//! the L-zones of the directions, in priority order, intersected until the
//! visibility ratio reaches the threshold (95 %).
//!
//! Everything is measured in the face's own plane and reported in 3-D
//! directions: a turned part gives the same faces, ratios and verdicts.

pub mod reach;
pub mod zones;

use geo::{Area, BoundingRect, ConvexHull, Intersects, MultiPoint, MultiPolygon, Point};
use serde::Serialize;
use thinwall_analysis::PartAnalysis;
use thinwall_brep::tessellate::Mesh;
use thinwall_brep::{EdgeId, FaceId};
use thinwall_geom::{CurveKind, Frame, Point3};
use thinwall_graph::Convexity;
use zones::Barrier;

/// Settings of the flank-milling analysis.
#[derive(Clone, Debug, Serialize)]
pub struct FlankOptions {
    /// The tool's diameter, mm: obstacles count up to this far above a face.
    pub tool_diameter: f64,
    /// Widen barriers by the tool's radius across each direction (fig. 15).
    pub tool_radius: bool,
    /// Visibility ratio at which a face is advisable (0.95).
    pub threshold: f64,
}

impl Default for FlankOptions {
    fn default() -> Self {
        Self {
            tool_diameter: 12.0,
            tool_radius: false,
            threshold: 0.95,
        }
    }
}

/// How the part goes on beyond an edge of the face, for a tool lying in
/// the face's plane.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Sharpness {
    /// The neighbour rises above the plane (a concave edge): a wall.
    Closed,
    /// The neighbour falls away (convex): the tool comes in over it.
    Open,
    /// Tangent into a concave blend that rises.
    TangentClosed,
    /// Tangent into a face that does not rise.
    TangentOpen,
}

impl Sharpness {
    fn closed(self) -> bool {
        matches!(self, Sharpness::Closed | Sharpness::TangentClosed)
    }
}

/// A face's nature by its edges.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Nature {
    /// Every edge closed: no way in along the plane.
    Closed,
    /// No edge closed.
    Open,
    SemiOpen,
}

/// One edge of the face.
#[derive(Clone, Debug, Serialize)]
pub struct EdgeAccess {
    pub edge: u64,
    pub sharpness: Sharpness,
}

/// A candidate milling direction (the tool's body comes from outside along
/// it), from an edge by a rule.
#[derive(Clone, Debug, Serialize)]
pub struct Candidate {
    /// Unit, in the face's plane.
    pub direction: [f64; 3],
    /// 1 first.
    pub priority: u8,
    pub rule: &'static str,
    /// The edge proposing it (STEP id).
    pub edge: u64,
    /// mm² of the face this direction alone cannot reach.
    pub l_zone_mm2: f64,
}

/// A direction taken, with the G-zone after it.
#[derive(Clone, Debug, Serialize)]
pub struct Used {
    pub direction: [f64; 3],
    pub l_zone_mm2: f64,
    pub g_zone_mm2: f64,
    pub visibility: f64,
}

/// The flank-milling verdict of one planar face.
#[derive(Clone, Debug, Serialize)]
pub struct PlanarFaceAccess {
    pub face: u64,
    pub body: u32,
    pub nature: Nature,
    pub area_mm2: f64,
    pub edges: Vec<EdgeAccess>,
    /// Obstacles above the face within the tool's reach.
    pub obstacles: usize,
    /// In the order tried: priority, then the smallest L-zone.
    pub candidates: Vec<Candidate>,
    /// The directions taken until the threshold, each with the G-zone.
    pub used: Vec<Used>,
    /// mm² no direction taken reaches.
    pub g_zone_mm2: f64,
    /// The G-zone's outlines on the face (3-D points, mm), for pictures.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub g_zone: Vec<Vec<[f64; 3]>>,
    /// Reachable area / face area.
    pub visibility: f64,
    pub advisable: bool,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
}

/// The flank-milling verdict of every planar face of the analysed part;
/// `mesh` is the part's tessellation (the obstacles are read from it).
pub fn flank_milling(
    a: &PartAnalysis,
    mesh: &Mesh,
    options: &FlankOptions,
) -> Vec<PlanarFaceAccess> {
    let boxes = mesh_boxes(mesh);
    let planar: Vec<_> = a.planar_faces().collect();
    a.work().map(&planar, |pf| {
        face_access(a, mesh, &boxes, pf.face, &pf.frame, options)
    })
}

/// Each mesh face's box (min, max), to skip faces far from a slab.
fn mesh_boxes(mesh: &Mesh) -> Vec<([f64; 3], [f64; 3])> {
    mesh.faces
        .iter()
        .map(|fm| {
            let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
            for &i in fm.triangles.iter().flatten() {
                let p = mesh.points[i as usize];
                for k in 0..3 {
                    lo[k] = lo[k].min(p[k]);
                    hi[k] = hi[k].max(p[k]);
                }
            }
            (lo, hi)
        })
        .collect()
}

/// One boundary edge in the sketch.
struct SketchEdge {
    edge: EdgeId,
    sharpness: Sharpness,
    line: bool,
    points: Vec<[f64; 2]>,
}

fn face_access(
    a: &PartAnalysis,
    mesh: &Mesh,
    boxes: &[([f64; 3], [f64; 3])],
    f: FaceId,
    frame: &Frame,
    options: &FlankOptions,
) -> PlanarFaceAccess {
    let part = a.part();
    let face = part.face(f);
    let region = a
        .planar(f)
        .map(|p| p.polygon_in(frame))
        .unwrap_or_else(|| MultiPolygon::new(vec![]));
    let area = region.unsigned_area();
    let loops = sketch_edges(a, f, frame);
    let edges: Vec<&SketchEdge> = loops.iter().flatten().collect();
    let closed = edges.iter().filter(|e| e.sharpness.closed()).count();
    let nature = match closed {
        0 => Nature::Open,
        n if n == edges.len() => Nature::Closed,
        _ => Nature::SemiOpen,
    };
    let mut barriers: Vec<Barrier> = edges
        .iter()
        .filter(|e| e.sharpness.closed())
        .flat_map(|e| {
            e.points.windows(2).map(|w| Barrier {
                points: vec![w[0], w[1]],
            })
        })
        .collect();
    let obstacles = obstacles(a, mesh, boxes, f, frame, &region, options.tool_diameter);
    let n_obstacles = obstacles.len();
    barriers.extend(obstacles);
    let radius = if options.tool_radius {
        0.5 * options.tool_diameter
    } else {
        0.0
    };
    let candidates = ranked_candidates(part, &loops, &region, &barriers, radius);
    let to_3d = |r: [f64; 2]| -> [f64; 3] { (frame.x * r[0] + frame.y * r[1]).into() };
    let mut out = PlanarFaceAccess {
        face: face.step_id,
        body: face.body.0,
        nature,
        area_mm2: area,
        edges: edges
            .iter()
            .map(|e| EdgeAccess {
                edge: part.edge(e.edge).step_id,
                sharpness: e.sharpness,
            })
            .collect(),
        obstacles: n_obstacles,
        candidates: candidates
            .iter()
            .map(|(c, _)| Candidate {
                direction: to_3d(c.0),
                priority: c.2,
                rule: c.3,
                edge: part.edge(c.4).step_id,
                l_zone_mm2: c.1,
            })
            .collect(),
        used: Vec::new(),
        g_zone_mm2: area,
        g_zone: Vec::new(),
        visibility: 0.0,
        advisable: false,
        note: None,
    };
    if nature == Nature::Closed {
        out.note = Some("closed face: every edge rises, no way in along its plane".into());
        return out;
    }
    g_zone_into(&mut out, &region, candidates, frame, options);
    out
}

/// The candidate directions of a face, each once (within 1°), with its
/// L-zone, in the order the G-zone takes them.
fn ranked_candidates(
    part: &thinwall_brep::Part,
    loops: &[Vec<SketchEdge>],
    region: &MultiPolygon<f64>,
    barriers: &[Barrier],
    radius: f64,
) -> Vec<(Proposal, MultiPolygon<f64>)> {
    let area = region.unsigned_area();
    // One direction once (within 1°), with its best priority, then the
    // proposing edge's STEP id: neither face nor edge order decides which
    // stays.
    let mut proposals = candidates(loops, region);
    proposals.sort_by_key(|c| (c.2, part.edge(c.4).step_id, c.5));
    let same = 1.0f64.to_radians().cos();
    let mut kept: Vec<Proposal> = Vec::with_capacity(proposals.len());
    for c in proposals {
        if !kept
            .iter()
            .any(|k| k.0[0] * c.0[0] + k.0[1] * c.0[1] > same)
        {
            kept.push(c);
        }
    }
    // Each candidate's L-zone once: its area orders the candidates, and
    // the G-zone intersects the zones themselves.
    let mut candidates: Vec<(Proposal, MultiPolygon<f64>)> = kept
        .into_iter()
        .map(|mut c| {
            let l = zones::l_zone(region, barriers, c.0, radius);
            c.1 = l.unsigned_area();
            (c, l)
        })
        .collect();
    // Priority, then the smallest L-zone (equal within 1e-6 of the face:
    // rounding must not reorder a turned copy), then the proposing edge
    // and the order of its proposals.
    let grain = 1e-6 * area.max(1e-300);
    let key = |c: &Proposal| {
        (
            c.2,
            (c.1 / grain).round() as i64,
            part.edge(c.4).step_id,
            c.5,
        )
    };
    candidates.sort_by_key(|(c, _)| key(c));
    candidates
}

/// The G-zone of a face that is not closed: the candidates' L-zones taken
/// in order to the threshold (Harik & Ris), its area, rings and visibility.
fn g_zone_into(
    out: &mut PlanarFaceAccess,
    region: &MultiPolygon<f64>,
    candidates: Vec<(Proposal, MultiPolygon<f64>)>,
    frame: &Frame,
    options: &FlankOptions,
) {
    let area = out.area_mm2;
    let to_3d = |r: [f64; 2]| -> [f64; 3] { (frame.x * r[0] + frame.y * r[1]).into() };
    let dirs: Vec<[f64; 2]> = candidates.iter().map(|(c, _)| c.0).collect();
    let l_zones: Vec<MultiPolygon<f64>> = candidates.into_iter().map(|(_, l)| l).collect();
    let (g, steps) = zones::g_zone(region, &l_zones, options.threshold);
    out.used = steps
        .iter()
        .zip(&dirs)
        .map(|(s, &r)| Used {
            direction: to_3d(r),
            l_zone_mm2: s.l_zone,
            g_zone_mm2: s.g_zone,
            visibility: s.visibility,
        })
        .collect();
    // The G-zone lies in the face: more is the booleans' rounding.
    out.g_zone_mm2 = g.unsigned_area().min(area);
    let lift = |c: geo::Coord<f64>| -> [f64; 3] {
        frame
            .to_world(&thinwall_geom::Vector3::new(c.x, c.y, 0.0))
            .into()
    };
    out.g_zone = g
        .iter()
        .flat_map(|p| std::iter::once(p.exterior()).chain(p.interiors()))
        .map(|ring| ring.coords().map(|&c| lift(c)).collect())
        .collect();
    out.visibility = if area > 0.0 {
        1.0 - out.g_zone_mm2 / area
    } else {
        0.0
    };
    out.advisable = out.visibility >= options.threshold;
}

/// The face's loops as edges in the sketch, each with its sharpness.
fn sketch_edges(a: &PartAnalysis, f: FaceId, frame: &Frame) -> Vec<Vec<SketchEdge>> {
    let part = a.part();
    let graph = a.graph();
    part.face(f)
        .loops
        .iter()
        .map(|&l| {
            part.loop_(l)
                .coedges
                .iter()
                .map(|ce| {
                    let e = part.edge(ce.edge);
                    let attr = &graph.edges[ce.edge.index()];
                    let other = attr.faces.iter().copied().find(|&g| g != f);
                    let sharpness = match attr.convexity {
                        Convexity::Concave => Sharpness::Closed,
                        Convexity::Smooth if other.is_some_and(|g| a.is_concave_blend(g)) => {
                            Sharpness::TangentClosed
                        }
                        Convexity::Smooth => Sharpness::TangentOpen,
                        _ => Sharpness::Open,
                    };
                    let line = matches!(e.curve, CurveKind::Line { .. });
                    let samples = if line { 1 } else { 16 };
                    let points = match &e.nurbs {
                        Some(c) => {
                            let spans = c.spans();
                            let (t0, t1) = (
                                spans.first().map_or(0.0, |s| s.0),
                                spans.last().map_or(1.0, |s| s.1),
                            );
                            (0..=samples)
                                .map(|k| c.point(t0 + (t1 - t0) * k as f64 / samples as f64))
                                .map(|p| to_sketch(frame, &p))
                                .collect()
                        }
                        None => [e.start, e.end]
                            .iter()
                            .map(|&v| to_sketch(frame, &part.vertex(v).point))
                            .collect(),
                    };
                    SketchEdge {
                        edge: ce.edge,
                        sharpness,
                        line,
                        points,
                    }
                })
                .collect()
        })
        .collect()
}

fn to_sketch(frame: &Frame, p: &Point3) -> [f64; 2] {
    let l = frame.to_local(p);
    [l.x, l.y]
}

/// (direction, L-zone area, priority, rule, edge): the paper's trade rules
/// on the closed edges (an open face: across its longest edge, both ways).
/// The last is the proposal's place among its edge's.
type Proposal = ([f64; 2], f64, u8, &'static str, EdgeId, u8);

fn candidates(loops: &[Vec<SketchEdge>], region: &MultiPolygon<f64>) -> Vec<Proposal> {
    let mut out: Vec<Proposal> = Vec::new();
    let push =
        |out: &mut Vec<Proposal>, r: [f64; 2], priority: u8, rule: &'static str, edge: EdgeId| {
            let n = r[0].hypot(r[1]);
            if n < 1e-12 {
                return;
            }
            let r = [r[0] / n, r[1] / n];
            let nth = out.iter().filter(|c| c.4 == edge).count() as u8;
            out.push((r, 0.0, priority, rule, edge, nth));
        };
    for lp in loops {
        let n = lp.len();
        for (k, e) in lp.iter().enumerate() {
            if !e.sharpness.closed() {
                continue;
            }
            let fully =
                lp[(k + n - 1) % n].sharpness.closed() && lp[(k + 1) % n].sharpness.closed();
            if e.line {
                let (p, q) = (e.points[0], e.points[e.points.len() - 1]);
                let t = [q[0] - p[0], q[1] - p[1]];
                let out_normal = outward(region, p, q);
                let (perp, along) = if fully { (1, 3) } else { (2, 4) };
                push(
                    &mut out,
                    out_normal,
                    perp,
                    "perpendicular to a closed linear edge",
                    e.edge,
                );
                if e.sharpness == Sharpness::Closed {
                    push(&mut out, t, along, "along a closed linear edge", e.edge);
                    push(
                        &mut out,
                        [-t[0], -t[1]],
                        along,
                        "along a closed linear edge",
                        e.edge,
                    );
                }
            } else {
                let m = e.points.len() - 1;
                for k in [m / 4, m / 2, 3 * m / 4] {
                    let (p, q) = (e.points[k], e.points[k + 1]);
                    push(
                        &mut out,
                        outward(region, p, q),
                        5,
                        "normal to a closed curved edge",
                        e.edge,
                    );
                }
            }
        }
    }
    if out.is_empty() {
        // An open face: across its longest edge, both ways.
        if let Some(e) = loops
            .iter()
            .flatten()
            .filter(|e| e.points.len() >= 2)
            // Equal lengths (to rounding): the first edge of the file.
            .max_by(|x, y| {
                let (a, b) = (span(x), span(y));
                if (a - b).abs() <= 1e-9 * a.max(b) {
                    y.edge.cmp(&x.edge)
                } else {
                    a.total_cmp(&b)
                }
            })
        {
            let (p, q) = (e.points[0], e.points[e.points.len() - 1]);
            let n = outward(region, p, q);
            push(
                &mut out,
                n,
                9,
                "across the longest edge of an open face",
                e.edge,
            );
            push(
                &mut out,
                [-n[0], -n[1]],
                9,
                "across the longest edge of an open face",
                e.edge,
            );
        }
    }
    out
}

fn span(e: &SketchEdge) -> f64 {
    let (p, q) = (e.points[0], e.points[e.points.len() - 1]);
    (q[0] - p[0]).hypot(q[1] - p[1])
}

/// The normal of segment pq in the plane pointing out of the face (from
/// the face towards the edge).
fn outward(region: &MultiPolygon<f64>, p: [f64; 2], q: [f64; 2]) -> [f64; 2] {
    let t = [q[0] - p[0], q[1] - p[1]];
    let len = t[0].hypot(t[1]).max(1e-300);
    let n = [t[1] / len, -t[0] / len];
    let m = [0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1])];
    let step = 1e-4 * len.max(1e-3);
    let inside = Point::new(m[0] - n[0] * step, m[1] - n[1] * step);
    if region.intersects(&inside) {
        n
    } else {
        [-n[0], -n[1]]
    }
}

/// The part's material above the face (outward side) within `reach`, near
/// it: each other face's triangles cut to the slab, projected, as a convex
/// hull.
#[allow(clippy::too_many_arguments)]
fn obstacles(
    a: &PartAnalysis,
    mesh: &Mesh,
    boxes: &[([f64; 3], [f64; 3])],
    f: FaceId,
    frame: &Frame,
    region: &MultiPolygon<f64>,
    reach: f64,
) -> Vec<Barrier> {
    let Some(rect) = region.bounding_rect() else {
        return Vec::new();
    };
    let slab = Slab {
        frame,
        lo: rect.min(),
        hi: rect.max(),
        eps: 1e-6 * a.bounding_box().diagonal().max(1.0),
        reach,
    };
    let height = |p: &Point3| frame.to_local(p).z;
    let mut out = Vec::new();
    for fm in mesh
        .faces
        .iter()
        .zip(boxes)
        .filter(|(fm, b)| fm.face != f && slab.may_reach(b))
        .map(|(fm, _)| fm)
    {
        // The face's triangles in the slab, grouped where they share a
        // point: each connected piece is an obstacle of its own (a ring's
        // two sides are two obstacles, not one across the face).
        let kept: Vec<(usize, Vec<[f64; 2]>)> = fm
            .triangles
            .iter()
            .enumerate()
            .filter_map(|(k, t)| {
                let tri = t.map(|i| mesh.points[i as usize]);
                let pts: Vec<[f64; 2]> = clip_to_slab(&tri, &height, slab.eps, reach)
                    .iter()
                    .map(|p| to_sketch(frame, p))
                    .filter(|&s| slab.near(s))
                    .collect();
                (!pts.is_empty()).then_some((k, pts))
            })
            .collect();
        for pts in pieces_sharing_points(&fm.triangles, &kept).into_values() {
            let hull = MultiPoint::from(pts).convex_hull();
            let points: Vec<[f64; 2]> = hull.exterior().points().map(|p| [p.x(), p.y()]).collect();
            if !points.is_empty() {
                out.push(Barrier { points });
            }
        }
    }
    out
}

/// The tool's slab over a face: above its plane (beyond `eps`) up to
/// `reach`, within `reach` of its box (`lo`, `hi`) in the sketch.
struct Slab<'a> {
    frame: &'a Frame,
    lo: geo::Coord<f64>,
    hi: geo::Coord<f64>,
    eps: f64,
    reach: f64,
}

impl Slab<'_> {
    /// A sketch point within reach of the face's box.
    fn near(&self, p: [f64; 2]) -> bool {
        let (lo, hi, reach) = (self.lo, self.hi, self.reach);
        p[0] >= lo.x - reach && p[0] <= hi.x + reach && p[1] >= lo.y - reach && p[1] <= hi.y + reach
    }

    /// A face whose box lies wholly below the slab, above it or beside the
    /// face's reach cannot give an obstacle.
    fn may_reach(&self, (lo3, hi3): &([f64; 3], [f64; 3])) -> bool {
        if lo3[0] > hi3[0] {
            return false;
        }
        let (mut l, mut h) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
        for c in 0..8 {
            let p = Point3::new(
                if c & 1 == 0 { lo3[0] } else { hi3[0] },
                if c & 2 == 0 { lo3[1] } else { hi3[1] },
                if c & 4 == 0 { lo3[2] } else { hi3[2] },
            );
            let q = self.frame.to_local(&p);
            for (k, v) in [q.x, q.y, q.z].into_iter().enumerate() {
                l[k] = l[k].min(v);
                h[k] = h[k].max(v);
            }
        }
        let (lo, hi, reach) = (self.lo, self.hi, self.reach);
        h[2] > self.eps
            && l[2] <= reach
            && h[0] >= lo.x - reach
            && l[0] <= hi.x + reach
            && h[1] >= lo.y - reach
            && l[1] <= hi.y + reach
    }
}

/// The kept triangles' sketch points grouped where the triangles share a
/// mesh point (union–find over `kept`), keyed by each group's root.
fn pieces_sharing_points(
    triangles: &[[u32; 3]],
    kept: &[(usize, Vec<[f64; 2]>)],
) -> std::collections::BTreeMap<usize, Vec<Point<f64>>> {
    let mut group: Vec<usize> = (0..kept.len()).collect();
    fn root(g: &mut [usize], mut i: usize) -> usize {
        while g[i] != i {
            g[i] = g[g[i]];
            i = g[i];
        }
        i
    }
    let mut by_point: std::collections::HashMap<u32, usize> = std::collections::HashMap::new();
    for (j, (k, _)) in kept.iter().enumerate() {
        for &p in &triangles[*k] {
            if let Some(&other) = by_point.get(&p) {
                let (a, b) = (root(&mut group, j), root(&mut group, other));
                group[a] = b;
            } else {
                by_point.insert(p, j);
            }
        }
    }
    let mut pieces: std::collections::BTreeMap<usize, Vec<Point<f64>>> = Default::default();
    for (j, (_, pts)) in kept.iter().enumerate() {
        let r = root(&mut group, j);
        pieces
            .entry(r)
            .or_default()
            .extend(pts.iter().map(|p| Point::new(p[0], p[1])));
    }
    pieces
}

/// A triangle's part between heights `lo` and `hi` (exclusive of the face's
/// own plane), as its corner points.
fn clip_to_slab(
    tri: &[Point3; 3],
    height: &impl Fn(&Point3) -> f64,
    lo: f64,
    hi: f64,
) -> Vec<Point3> {
    let mut poly: Vec<Point3> = tri.to_vec();
    for (limit, keep_above) in [(lo, true), (hi, false)] {
        let inside = |p: &Point3| {
            let h = height(p);
            if keep_above {
                h > limit
            } else {
                h <= limit
            }
        };
        let mut next = Vec::with_capacity(poly.len() + 2);
        for k in 0..poly.len() {
            let (p, q) = (poly[k], poly[(k + 1) % poly.len()]);
            let (ip, iq) = (inside(&p), inside(&q));
            if ip {
                next.push(p);
            }
            if ip != iq {
                let (hp, hq) = (height(&p), height(&q));
                let t = (limit - hp) / (hq - hp);
                next.push(Point3::from(p.coords + (q - p) * t));
            }
        }
        poly = next;
        if poly.is_empty() {
            break;
        }
    }
    poly
}
