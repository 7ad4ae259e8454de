//! Triangles of a part's faces, for pictures and viewers (issue 15).
//!
//! Every edge is sampled once, to a chordal deviation, and both faces of
//! the edge use those points: the mesh is watertight along edges by
//! construction. Each face's loops are mapped into its parameter plane
//! (a plane's own frame; a cylinder or cone unrolled, angles followed
//! continuously around each loop; a free-form face by point inversion),
//! with interior points on a grid fine enough for the deviation, and
//! triangulated there with spade's constrained Delaunay triangulation;
//! triangles inside the loops (even–odd) are kept and turned to face out
//! of the material.
//!
//! A band of a cylinder or cone bounded by two circles and no seam edge is
//! cut along a line of the surface between the two loops; a face bounded
//! by one loop going around (a sphere's cap, a cone to its apex) is closed
//! along its pole's line. Tori and faces whose loops cannot be mapped are
//! left out, each with the reason (`FaceMesh::issue`).

use crate::model::{Face, FaceId, Part};
use spade::{ConstrainedDelaunayTriangulation, Point2, Triangulation};
use std::f64::consts::TAU;
use thinwall_geom::{NurbsCurve, Point3, Surface, Vector3};

/// The triangles of a part: shared points, triangles per face.
#[derive(Clone, Debug, Default)]
pub struct Mesh {
    pub points: Vec<Point3>,
    pub faces: Vec<FaceMesh>,
    /// Every edge's points, start to end (indices into `points`), by
    /// `EdgeId::index()`: the polylines both its faces use.
    pub edges: Vec<Vec<u32>>,
}

/// One face's triangles (indices into `Mesh::points`, counter-clockwise
/// seen from outside the material), or why it has none; `issue` also
/// says where a face is drawn from a defective outline (a loop the file
/// leaves open).
#[derive(Clone, Debug)]
pub struct FaceMesh {
    pub face: FaceId,
    pub triangles: Vec<[u32; 3]>,
    pub issue: Option<String>,
}

impl Mesh {
    /// Area of one face's triangles, mm².
    pub fn face_area(&self, f: &FaceMesh) -> f64 {
        f.triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| self.points[i as usize]);
                0.5 * (b - a).cross(&(c - a)).norm()
            })
            .sum()
    }
}

/// Largest angle a chord or a triangle may span on a curved edge or
/// surface, radians (with the deviation: small holes stay round).
const MAX_ANGLE: f64 = 0.15;
/// Most segments of one edge and grid lines of one face direction.
const MAX_EDGE_SEGMENTS: usize = 512;
/// A boundary point this close to the axis (relative to the loop's or the
/// sphere's radius) is a cone's apex or a sphere's pole: files place such
/// vertices to their own precision, not on the axis exactly.
const APEX_GAP: f64 = 1e-5;
/// Rows along a cylinder's or cone's generator are this many columns
/// apart: the surface is straight that way.
const GENERATOR_STRETCH: f64 = 4.0;
const MAX_GRID: usize = 200;
/// A cylinder's or cone's triangle may span this many columns across its
/// generator (√2: the chord's sagitta at most twice the column's).
const ONE_COLUMN: f64 = std::f64::consts::SQRT_2;
/// Most cells of one face's grid (columns × rows), and of one direction:
/// a thin blend around a large circle needs many columns and few rows.
const MAX_CELLS: usize = 250_000;
const MAX_LINES: usize = 4096;
/// A face's deviation is at most this part of its smallest radius
/// (`face_deviation`).
const NARROW_FACE: f64 = 0.002;
/// Where the area between a face's boundary curves and their chords is
/// more than this part of the face's area, the face is made finer.
const BOUNDARY_AREA: f64 = 0.004;

/// The chordal deviation of `part_mesh`, relative to the part's size
/// (`Part::size`).
pub const RELATIVE_DEVIATION: f64 = 1e-3;

/// The part's triangles at `RELATIVE_DEVIATION` of its size: the one mesh
/// the pictures, the pages and the accessibility analysis share.
pub fn part_mesh(part: &Part) -> Mesh {
    crate::builds::record(part, crate::builds::Built::Mesh);
    let size = part.size().max(1e-9);
    tessellate(part, RELATIVE_DEVIATION * size)
}

/// Tessellate every face of `part` to within `deviation` mm of its
/// surface (chords of curved edges, triangles across curved faces).
///
/// A face narrower than a few deviations (a thin blend, a long sliver)
/// would get chords as deep as it is wide: where the first pass finds the
/// area between a face's boundary curves and their chords more than
/// `BOUNDARY_AREA` of the face's, that face and its edges are made finer
/// and the part is tessellated again.
pub fn tessellate(part: &Part, deviation: f64) -> Mesh {
    let deviation = deviation.max(1e-9);
    let by_surface: Vec<f64> = part
        .face_ids()
        .map(|f| face_deviation(&part.face(f).surface, deviation))
        .collect();
    let (first, chords) = tessellate_with(part, &by_surface, deviation);
    // Where a face's boundary chords could change its area by more than
    // `BOUNDARY_AREA` of it, the face (and so its edges) gets finer.
    let refined: Vec<f64> = first
        .faces
        .iter()
        .zip(&by_surface)
        .map(|(fm, &d)| {
            let edges = || {
                part.face(fm.face)
                    .loops
                    .iter()
                    .flat_map(|&l| &part.loop_(l).coedges)
                    .map(|ce| chords[ce.edge.index()])
            };
            let bound: f64 = edges().map(|c| c.area).sum();
            let sagitta = edges().map(|c| c.sagitta).fold(0.0, f64::max);
            let area = first.face_area(fm);
            if area > 0.0 && bound > BOUNDARY_AREA * area {
                // The chords as they came (the deviation or the angle
                // bounded them), made as much shallower as needed.
                d.min(sagitta * BOUNDARY_AREA * area / bound).max(1e-9)
            } else {
                d
            }
        })
        .collect();
    if refined == by_surface {
        return first;
    }
    tessellate_with(part, &refined, deviation).0
}

/// Tessellate with a deviation per face (by `FaceId::index()`); an edge is
/// as fine as the finest face it bounds.
/// Also, per edge, how far its chords are off its curve.
fn tessellate_with(
    part: &Part,
    face_deviation: &[f64],
    part_deviation: f64,
) -> (Mesh, Vec<ChordsOff>) {
    let mut edge_deviation = vec![f64::INFINITY; part.edges.len()];
    for f in part.face_ids() {
        for &l in &part.face(f).loops {
            for ce in &part.loop_(l).coedges {
                let d = &mut edge_deviation[ce.edge.index()];
                *d = d.min(face_deviation[f.index()]);
            }
        }
    }
    let mut points: Vec<Point3> = part.vertices.iter().map(|v| v.point).collect();
    let mut chords = vec![ChordsOff::default(); part.edges.len()];
    let edge_points: Vec<Vec<u32>> = part
        .edges
        .iter()
        .zip(&edge_deviation)
        .zip(&mut chords)
        .map(|((e, &deviation), off)| {
            let mut ids = vec![e.start.0];
            if let Some(c) = &e.nurbs {
                let params = interior_params(c, deviation.min(1e9));
                *off = chords_off(c, &params);
                for t in params {
                    ids.push(points.len() as u32);
                    points.push(c.point(t));
                }
            }
            ids.push(e.end.0);
            ids
        })
        .collect();
    let mut mesh = Mesh {
        points,
        faces: Vec::new(),
        edges: Vec::new(),
    };
    for f in part.face_ids() {
        let d = face_deviation[f.index()];
        let fm = face_mesh(
            part,
            f,
            &edge_points,
            (d, Some(part_deviation)),
            &mut mesh.points,
        );
        mesh.faces.push(fm);
    }
    mesh.edges = edge_points;
    (mesh, chords)
}

/// How far an edge's chords are off its curve: the largest sagitta (mm)
/// and the area between them (at most ⅔ × sagitta × chord per chord,
/// mm²).
#[derive(Clone, Copy, Debug, Default)]
struct ChordsOff {
    sagitta: f64,
    area: f64,
}

/// How far a curve's chords at `inner` parameters (and its ends) are off
/// it, the sagitta measured at each chord's middle parameter.
fn chords_off(c: &NurbsCurve, inner: &[f64]) -> ChordsOff {
    let spans = c.spans();
    let (Some(first), Some(last)) = (spans.first(), spans.last()) else {
        return ChordsOff::default();
    };
    let mut ts = vec![first.0];
    ts.extend_from_slice(inner);
    ts.push(last.1);
    let mut off = ChordsOff::default();
    for w in ts.windows(2) {
        let (a, b) = (c.point(w[0]), c.point(w[1]));
        let m = c.point(0.5 * (w[0] + w[1]));
        let chord = b - a;
        let len = chord.norm();
        let sag = if len > 0.0 {
            (m - a).cross(&chord).norm() / len
        } else {
            (m - a).norm()
        };
        off.sagitta = off.sagitta.max(sag);
        off.area += 2.0 / 3.0 * sag * len;
    }
    off
}

/// A face's own deviation: at most a small part of its surface's
/// smallest radius. A blend of radius 0.1 mm along a 60 mm circle is
/// narrower than the part's deviation; chords of that circle within the
/// part's deviation would fold the blend's triangles across it.
fn face_deviation(s: &Surface, deviation: f64) -> f64 {
    let radius = match s {
        Surface::Cylinder { radius, .. } | Surface::Sphere { radius, .. } => *radius,
        Surface::Torus { minor_radius, .. } => *minor_radius,
        _ => return deviation,
    };
    deviation.min(NARROW_FACE * radius).max(1e-9)
}

/// Parameters inside an edge curve where its chords stay within
/// `deviation`: each knot span halved until the chord's midpoint lies
/// that close to the curve.
fn interior_params(c: &NurbsCurve, deviation: f64) -> Vec<f64> {
    if c.degree == 1 && c.is_polynomial() {
        // A polyline: its inner knots are its corners.
        let spans = c.spans();
        return spans.iter().skip(1).map(|s| s.0).collect();
    }
    let spans = c.spans();
    let mut deviation = deviation;
    loop {
        let mut out = Vec::new();
        for (k, (a, b)) in spans.iter().enumerate() {
            if k > 0 {
                out.push(*a);
            }
            split(c, *a, *b, deviation, 0, &mut out);
        }
        // Too many: coarser along the whole edge (never a cut-off tail).
        if out.len() <= MAX_EDGE_SEGMENTS || deviation > 1e6 {
            return out;
        }
        deviation *= 2.0;
    }
}

fn split(c: &NurbsCurve, a: f64, b: f64, deviation: f64, depth: u32, out: &mut Vec<f64>) {
    let (pa, pb) = (c.point(a), c.point(b));
    let m = 0.5 * (a + b);
    // The curve's distance from the chord at a quarter, the middle and
    // three quarters (an S-shaped span passes the chord's middle).
    let off = |t: f64| {
        let p = c.point(t);
        let d = pb - pa;
        let l2 = d.norm_squared();
        if l2 == 0.0 {
            return (p - pa).norm();
        }
        let s = ((p - pa).dot(&d) / l2).clamp(0.0, 1.0);
        (p - (pa + d * s)).norm()
    };
    let worst = off(m).max(off(0.5 * (a + m))).max(off(0.5 * (m + b)));
    // The turn between the two halves: half the arc's angle.
    let pm = c.point(m);
    let (h1, h2) = (pm - pa, pb - pm);
    let turn = h1.angle(&h2);
    let straight_enough = turn.is_nan() || turn <= 0.5 * MAX_ANGLE;
    if (worst <= deviation && straight_enough) || depth >= 9 {
        return;
    }
    split(c, a, m, deviation, depth + 1, out);
    out.push(m);
    split(c, m, b, deviation, depth + 1, out);
}

/// A face's map into its parameter plane and back.
enum Chart<'a> {
    Plane {
        frame: &'a thinwall_geom::Frame,
    },
    /// Unrolled: u = angle × scale, v along the axis; radius r0 + slope·v.
    Revolved {
        frame: &'a thinwall_geom::Frame,
        scale: f64,
        r0: f64,
        slope: f64,
    },
    Freeform {
        nurbs: &'a thinwall_geom::NurbsSurface,
    },
    /// u = longitude × radius, v = latitude × radius.
    Sphere {
        frame: &'a thinwall_geom::Frame,
        radius: f64,
    },
    /// u = angle about the axis × major radius, v = angle about the tube's
    /// circle × minor radius; both unrolled.
    Torus {
        frame: &'a thinwall_geom::Frame,
        major: f64,
        minor: f64,
    },
}

impl Chart<'_> {
    fn of(s: &Surface) -> Option<Chart<'_>> {
        match s {
            Surface::Plane { frame } => Some(Chart::Plane { frame }),
            Surface::Cylinder { frame, radius } => Some(Chart::Revolved {
                frame,
                scale: *radius,
                r0: *radius,
                slope: 0.0,
            }),
            Surface::Cone {
                frame,
                radius,
                semi_angle,
            } => Some(Chart::Revolved {
                frame,
                scale: radius.max(1.0),
                r0: *radius,
                slope: semi_angle.tan(),
            }),
            Surface::Freeform { nurbs, .. } => Some(Chart::Freeform { nurbs }),
            Surface::Sphere { frame, radius } => Some(Chart::Sphere {
                frame,
                radius: *radius,
            }),
            Surface::Torus {
                frame,
                major_radius,
                minor_radius,
            } if *major_radius > 0.0 && *minor_radius > 0.0 => Some(Chart::Torus {
                frame,
                major: *major_radius,
                minor: *minor_radius,
            }),
            _ => None,
        }
    }

    fn periodic(&self) -> Option<f64> {
        match self {
            Chart::Revolved { scale, .. } => Some(TAU * scale),
            Chart::Sphere { radius, .. } => Some(TAU * radius),
            Chart::Torus { major, .. } => Some(TAU * major),
            _ => None,
        }
    }

    /// The period of v, where it has one (a torus's tube).
    fn periodic_v(&self) -> Option<f64> {
        match self {
            Chart::Torus { minor, .. } => Some(TAU * minor),
            _ => None,
        }
    }

    /// Where a face bounded by one loop around the axis closes: the pole
    /// (or apex) on the side `up` (larger v) or below, as v.
    fn cap(&self, up: bool) -> Option<f64> {
        match self {
            Chart::Sphere { radius, .. } => Some(if up { 1.0 } else { -1.0 } * radius * TAU / 4.0),
            Chart::Revolved { r0, slope, .. } if *slope != 0.0 => {
                let apex = -r0 / slope;
                // Only on the side the cone narrows to.
                (up == (apex > 0.0)).then_some(apex)
            }
            _ => None,
        }
    }
}

/// One face's triangles with its boundary given: `edge_interior(e)` are
/// the points of edge `e` strictly between its start and end vertices,
/// start to end (a caller whose neighbouring pieces use those same points,
/// as the removal's area-keeping samples do, gets no gap along the edge);
/// the face's inside is triangulated to within `deviation` mm. The points
/// (the part's vertices first) and the triangles, counter-clockwise seen
/// from outside the material; or why the face cannot be triangulated.
pub fn face_triangles(
    part: &Part,
    f: FaceId,
    edge_interior: &dyn Fn(crate::EdgeId) -> Vec<Point3>,
    deviation: f64,
) -> Result<(Vec<Point3>, Vec<[u32; 3]>), String> {
    let face = part.face(f);
    let chart = Chart::of(&face.surface)
        .ok_or_else(|| format!("{} faces are not tessellated yet", face.surface.kind_name()))?;
    let mut points: Vec<Point3> = part.vertices.iter().map(|v| v.point).collect();
    let mut edge_points: Vec<Vec<u32>> = vec![Vec::new(); part.edges.len()];
    for &l in &face.loops {
        for ce in &part.loop_(l).coedges {
            let ids = &mut edge_points[ce.edge.index()];
            if !ids.is_empty() {
                continue; // a seam: both its uses share the points
            }
            let e = part.edge(ce.edge);
            ids.push(e.start.0);
            for p in edge_interior(ce.edge) {
                ids.push(points.len() as u32);
                points.push(p);
            }
            ids.push(e.end.0);
        }
    }
    let triangles = triangulate(
        part,
        face,
        &chart,
        &edge_points,
        // A caller's own face (the removal's facets): rows as they were.
        (deviation.max(1e-9), None),
        &mut points,
    )?;
    Ok((points, triangles))
}

/// A face's triangles, or why it has none.
fn face_mesh(
    part: &Part,
    f: FaceId,
    edge_points: &[Vec<u32>],
    deviation: (f64, Option<f64>),
    points: &mut Vec<Point3>,
) -> FaceMesh {
    let face = part.face(f);
    let mut out = FaceMesh {
        face: f,
        triangles: Vec::new(),
        issue: None,
    };
    let Some(chart) = Chart::of(&face.surface) else {
        out.issue = Some(format!(
            "{} faces are not tessellated yet",
            face.surface.kind_name()
        ));
        return out;
    };
    match triangulate(part, face, &chart, edge_points, deviation, points) {
        Ok(t) => {
            out.triangles = t;
            // Drawn, but its outline is the file's: where a loop does not
            // close, the triangles close it with a chord.
            out.issue = open_loop(part, face);
        }
        Err(why) => out.issue = Some(why),
    }
    out
}

/// Where one of the face's loops does not close in the file: an edge
/// ending at another vertex than the next one starts at.
pub fn open_loop(part: &Part, face: &Face) -> Option<String> {
    for &l in &face.loops {
        let coedges = &part.loop_(l).coedges;
        let ends = |k: usize| {
            let ce = &coedges[k];
            let e = part.edge(ce.edge);
            if ce.forward {
                (e.start, e.end)
            } else {
                (e.end, e.start)
            }
        };
        for k in 0..coedges.len() {
            let next = (k + 1) % coedges.len();
            let (end, start) = (ends(k).1, ends(next).0);
            if end != start {
                return Some(format!(
                    "loop does not close in the file: edge #{} ends at vertex #{}, edge #{} starts at vertex #{}",
                    part.edge(coedges[k].edge).step_id,
                    part.vertex(end).step_id,
                    part.edge(coedges[next].edge).step_id,
                    part.vertex(start).step_id
                ));
            }
        }
    }
    None
}

/// The loops of a face as point ids, in order (each edge's points once).
fn loop_ids(part: &Part, face: &Face, edge_points: &[Vec<u32>]) -> Vec<Vec<u32>> {
    face.loops
        .iter()
        .map(|&l| {
            let runs: Vec<Vec<u32>> = part
                .loop_(l)
                .coedges
                .iter()
                .map(|ce| {
                    let mut run = edge_points[ce.edge.index()].clone();
                    if !ce.forward {
                        run.reverse();
                    }
                    run
                })
                .collect();
            let mut ids = Vec::new();
            for (k, run) in runs.iter().enumerate() {
                // A run's last point is the next run's first, but where the
                // file leaves the loop open (`open_loop`).
                let next = &runs[(k + 1) % runs.len()];
                let shared = run.last() == next.first();
                ids.extend(&run[..run.len() - usize::from(shared)]);
            }
            ids
        })
        .filter(|ids: &Vec<u32>| ids.len() >= 2)
        .collect()
}

/// A polygon of the parameter plane, each corner with its point id.
type Ring = Vec<([f64; 2], u32)>;

/// `deviation`: the face's, and the part mesh's (none for a caller's own
/// face: the removal's facets). In the part's mesh a cylinder or cone is
/// in columns only where it can be, and rows along its straight generator
/// are never closer than the part's deviation, whatever its radius.
fn triangulate(
    part: &Part,
    face: &Face,
    chart: &Chart,
    edge_points: &[Vec<u32>],
    (deviation, part_deviation): (f64, Option<f64>),
    points: &mut Vec<Point3>,
) -> Result<Vec<[u32; 3]>, String> {
    let loops = loop_ids(part, face, edge_points);
    if loops.is_empty() {
        return Err("no loop with points".into());
    }
    let mut rings: Vec<Ring> = Vec::new();
    let mut wrapping: Vec<Ring> = Vec::new();
    let mut hint = None;
    for ids in &loops {
        let (ring, turns) = map_loop(chart, ids, points, &mut hint)?;
        if turns == 0 {
            rings.push(ring);
        } else {
            wrapping.push(ring);
        }
    }
    let cut = close_wrapping(face, chart, wrapping, &mut rings, points)?;
    if let Some(period) = chart.periodic() {
        align_turns(&mut rings, period, 0);
    }
    if let Some(period) = chart.periodic_v() {
        align_turns(&mut rings, period, 1);
    }
    let grid = Grid::of(chart, &rings, deviation, part_deviation);
    // A cylinder or cone is straight along its generator: columns alone
    // where their strips come out one column wide, rows where not. Only in
    // the part's mesh: a caller's own faces (the removal's facets, no part
    // deviation) keep their rows.
    let fresh = points.len();
    let columns = grid
        .as_ref()
        .filter(|_| part_deviation.is_some())
        .and_then(|g| g.columns_only(chart));
    if let Some(g) = columns {
        let (tris, steiner) = grid_cdt(chart, rings.clone(), cut, Some(&g), points)?;
        if g.one_column(&tris) {
            return Ok(finish(face, chart, &tris, &steiner, points));
        }
        points.truncate(fresh);
    }
    let (tris, steiner) = grid_cdt(chart, rings, cut, grid.as_ref(), points)?;
    Ok(finish(face, chart, &tris, &steiner, points))
}

/// The rings cut and split for `grid`, and their constrained Delaunay
/// triangles with the grid's interior points.
fn grid_cdt(
    chart: &Chart,
    mut rings: Vec<Ring>,
    cut: Option<(usize, usize)>,
    grid: Option<&Grid>,
    points: &mut Vec<Point3>,
) -> Result<(Vec<PlaneTri>, Vec<[f64; 2]>), String> {
    if let Some(g) = grid {
        g.split_poles(&mut rings);
        if let Some((r, k)) = cut {
            g.split_cut(chart, &mut rings[r], k, points);
        }
    }
    snap(&mut rings);
    let steiner = grid.map_or_else(Vec::new, |g| g.points(&rings));
    let stretch = grid.map_or(1.0, Grid::stretch);
    let tris = cdt(&rings, &steiner, stretch)?;
    Ok((tris, steiner))
}

/// The triangles as point ids, the interior points added to `points`,
/// turned to face out of the material.
fn finish(
    face: &Face,
    chart: &Chart,
    tris: &[PlaneTri],
    steiner: &[[f64; 2]],
    points: &mut Vec<Point3>,
) -> Vec<[u32; 3]> {
    // Interior points become points of the mesh.
    let mut ids: Vec<u32> = Vec::with_capacity(steiner.len());
    for uv in steiner {
        ids.push(points.len() as u32);
        points.push(lift(chart, *uv));
    }
    let (mut out, centres): (Vec<[u32; 3]>, Vec<[f64; 2]>) = tris
        .iter()
        .map(|t| {
            let ids = t.corners.map(|c| match c {
                Corner::Boundary(i) => i,
                Corner::Steiner(j) => ids[j],
            });
            (ids, t.centre)
        })
        .filter(|(t, _)| t[0] != t[1] && t[1] != t[2] && t[0] != t[2])
        .unzip();
    orient_outward(face, chart, points, &mut out, &centres);
    out
}

/// The loops that wrap around the surface closed into one ring pushed on
/// `rings`: a cap to its pole, or the band between two. Returns where the
/// ring is cut open: (ring, corner the cut starts at).
fn close_wrapping(
    face: &Face,
    chart: &Chart,
    mut wrapping: Vec<Ring>,
    rings: &mut Vec<Ring>,
    points: &mut Vec<Point3>,
) -> Result<Option<(usize, usize)>, String> {
    let mut cut = None;
    match wrapping.len() {
        0 => {}
        1 => {
            // A cap: the face lies left of its loop seen from outside;
            // unrolled with the normal towards us, left of a loop going
            // round the positive way is up.
            let ring = &wrapping[0];
            let forward = ring.last().map_or(0.0, |c| c.0[0]) > ring[0].0[0];
            let up = forward == face.same_sense;
            let v = chart
                .cap(up)
                .ok_or_else(|| "one loop goes round a surface with no pole there".to_string())?;
            let pole = points.len() as u32;
            points.push(lift(chart, [ring[0].0[0], v]));
            cut = Some((rings.len(), ring.len()));
            rings.push(cap(ring, v, pole, chart.periodic().unwrap_or(TAU)));
        }
        2 => {
            if let Some(period) = chart.periodic_v() {
                // On a torus the two circles bound two bands: the face's
                // is on the left of the first loop (as for a cap).
                let forward = wrapping[0].last().map_or(0.0, |c| c.0[0]) > wrapping[0][0].0[0];
                let up = forward == face.same_sense;
                let mean = |r: &Ring| r.iter().map(|c| c.0[1]).sum::<f64>() / r.len() as f64;
                let (va, vb) = (mean(&wrapping[0]), mean(&wrapping[1]));
                let turns = if up {
                    ((va - vb) / period).floor() + 1.0
                } else {
                    ((va - vb) / period).ceil() - 1.0
                };
                for c in wrapping[1].iter_mut() {
                    c.0[1] += turns * period;
                }
            }
            cut = Some((rings.len(), wrapping[0].len()));
            rings.push(band(
                &wrapping[0],
                &wrapping[1],
                chart.periodic().unwrap_or(TAU),
            ))
        }
        n => return Err(format!("{n} loop(s) wrap around the surface")),
    }
    Ok(cut)
}

/// The triangles all run one way in the parameter plane; which way is out
/// of the material is decided once for the face, by their 3-D normals
/// against the face's weighted by area (a sliver at a pole has no reliable
/// normal of its own).
///
/// A free-form face's normal is taken at each triangle's centre in its
/// parameter plane (`centres`), where the chart is the surface's own
/// parameters: no point to invert.
fn orient_outward(
    face: &Face,
    chart: &Chart,
    points: &[Point3],
    out: &mut [[u32; 3]],
    centres: &[[f64; 2]],
) {
    let agreement: f64 = out
        .iter()
        .zip(centres)
        .map(|(t, uv)| {
            let [a, b, c] = t.map(|i| points[i as usize]);
            let n = (b - a).cross(&(c - a));
            let outward = match chart {
                Chart::Freeform { nurbs } => {
                    thinwall_geom::surface::nurbs_normal(nurbs, uv[0], uv[1]).map(|o| {
                        if face.same_sense {
                            o
                        } else {
                            -o
                        }
                    })
                }
                _ => {
                    let centre = Point3::from((a.coords + b.coords + c.coords) / 3.0);
                    face.outward_normal(&centre, &mut None)
                }
            };
            outward.map_or(0.0, |o| n.dot(&o))
        })
        .sum();
    if agreement < 0.0 {
        for t in out.iter_mut() {
            t.swap(1, 2);
        }
    }
}

/// A loop in the parameter plane, angles unrolled continuously; with the
/// number of turns it makes around the axis (0 for a closed polygon).
fn map_loop(
    chart: &Chart,
    ids: &[u32],
    points: &[Point3],
    hint: &mut Option<(f64, f64)>,
) -> Result<(Ring, i32), String> {
    let mut ring: Ring = Vec::with_capacity(ids.len());
    // Distances from the axis, for the apex (pole) test.
    let rho: Vec<f64> = match chart {
        Chart::Revolved { frame, .. } | Chart::Sphere { frame, .. } => ids
            .iter()
            .map(|&i| {
                let l = frame.to_local(&points[i as usize]);
                l.x.hypot(l.y)
            })
            .collect(),
        _ => Vec::new(),
    };
    let extent = rho.iter().copied().fold(0.0, f64::max);
    // Angles are followed from point to point, which fails across an apex
    // (the loop may turn by up to half a turn there): start right after
    // one, so the only jump is the loop's closing.
    let start = (0..rho.len())
        .find(|&k| {
            rho[(k + rho.len() - 1) % rho.len()] < APEX_GAP * extent && rho[k] >= APEX_GAP * extent
        })
        .unwrap_or(0);
    let ids: Vec<u32> = ids[start..].iter().chain(&ids[..start]).copied().collect();
    for &i in &ids {
        let uv = chart_uv(chart, &points[i as usize], &ring, extent, hint)?;
        ring.push((uv, i));
    }
    let ring = at_poles(ring);
    let turns = loop_turns(chart, &ring)?;
    Ok((ring, turns))
}

/// A boundary point in the chart's parameter plane, its angles unrolled
/// next to the ring's last corners (`extent`: the loop's largest distance
/// from a revolved surface's axis, for the apex test).
fn chart_uv(
    chart: &Chart,
    p: &Point3,
    ring: &Ring,
    extent: f64,
    hint: &mut Option<(f64, f64)>,
) -> Result<[f64; 2], String> {
    let p = *p;
    Ok(match chart {
        Chart::Plane { frame } => {
            let l = frame.to_local(&p);
            [l.x, l.y]
        }
        Chart::Revolved { frame, scale, .. } => {
            let l = frame.to_local(&p);
            let mut a = l.y.atan2(l.x) * scale;
            if let Some(&(prev, _)) = ring.iter().rev().find(|c| c.0[0].is_finite()) {
                let period = TAU * scale;
                a += ((prev[0] - a) / period).round() * period;
            }
            if l.x.hypot(l.y) < APEX_GAP * extent {
                // A cone's apex: no angle of its own (set below).
                a = f64::NAN;
            }
            [a, l.z]
        }
        Chart::Sphere { frame, radius } => {
            let l = frame.to_local(&p);
            let mut a = l.y.atan2(l.x) * radius;
            if let Some(&(prev, _)) = ring.iter().rev().find(|c| c.0[0].is_finite()) {
                let period = TAU * radius;
                a += ((prev[0] - a) / period).round() * period;
            }
            let lat = (l.z / radius).clamp(-1.0, 1.0).asin() * radius;
            if l.x.hypot(l.y) < APEX_GAP * radius {
                // A pole: no longitude of its own (set below).
                a = f64::NAN;
            }
            [a, lat]
        }
        Chart::Torus {
            frame,
            major,
            minor,
        } => {
            let l = frame.to_local(&p);
            let mut a = l.y.atan2(l.x) * major;
            let mut b = l.z.atan2(l.x.hypot(l.y) - major) * minor;
            if let Some(&(prev, _)) = ring.last() {
                let (pa, pb) = (TAU * major, TAU * minor);
                a += ((prev[0] - a) / pa).round() * pa;
                b += ((prev[1] - b) / pb).round() * pb;
            }
            [a, b]
        }
        Chart::Freeform { nurbs } => {
            let (u, v, d) = nurbs.invert(&p, *hint);
            if !(d.is_finite() && u.is_finite() && v.is_finite()) {
                return Err("a boundary point could not be mapped onto the surface".into());
            }
            *hint = Some((u, v));
            [u, v]
        }
    })
}

/// How many times a closed ring of the chart turns around its periodic
/// direction; an error where it goes around a torus's tube.
fn loop_turns(chart: &Chart, ring: &Ring) -> Result<i32, String> {
    if let (Some(period), Some(first), Some(last)) = (chart.periodic_v(), ring.first(), ring.last())
    {
        let closing = first.0[1] + ((last.0[1] - first.0[1]) / period).round() * period;
        if ((closing - first.0[1]) / period).round() != 0.0 {
            return Err("a loop goes around a torus's tube".into());
        }
    }
    let turns = match (chart.periodic(), ring.first(), ring.last()) {
        (Some(period), Some(first), Some(last)) => {
            // Closing the loop: the last step back to the first point.
            let mut closing = first.0[0];
            closing += ((last.0[0] - closing) / period).round() * period;
            ((closing - first.0[0]) / period).round() as i32
        }
        _ => 0,
    };
    Ok(turns)
}

/// A pole has no longitude: it stands on the pole's line twice, at the
/// longitudes of the corners before and after it.
fn at_poles(ring: Ring) -> Ring {
    let n = ring.len();
    if ring.iter().all(|c| c.0[0].is_finite()) || n < 2 {
        return ring;
    }
    let mut out = Ring::with_capacity(n + 2);
    for k in 0..n {
        let c = ring[k];
        if c.0[0].is_finite() {
            out.push(c);
            continue;
        }
        let near = |step: usize| {
            (1..n)
                .map(|j| ring[(k + j * step) % n].0[0])
                .find(|u| u.is_finite())
        };
        let (before, after) = (near(n - 1), near(1));
        for u in [before, after].into_iter().flatten() {
            out.push(([u, c.0[1]], c.1));
        }
    }
    out
}

/// One loop that goes once around, closed along the pole's line: the
/// pole's point at both ends (a triangle fan to it, degenerate on the
/// pole's line).
fn cap(a: &Ring, v: f64, pole: u32, period: f64) -> Ring {
    let start = a[0].0[0];
    let dir = (a.last().map_or(0.0, |c| c.0[0]) - start).signum();
    let mut out: Ring = a.to_vec();
    out.push(([start + dir * period, a[0].0[1]], a[0].1));
    out.push(([start + dir * period, v], pole));
    out.push(([start, v], pole));
    out
}

/// Two loops that each go once around: one polygon, cut along the
/// surface from a point of the first to the point of the second nearest
/// in angle.
fn band(a: &Ring, b: &Ring, period: f64) -> Ring {
    let start = a[0].0[0];
    // b's corner nearest in angle to a's start, b shifted to be near it.
    let (k, shift) = b
        .iter()
        .enumerate()
        .map(|(k, c)| {
            let s = ((start - c.0[0]) / period).round() * period;
            (k, s, (c.0[0] + s - start).abs())
        })
        .min_by(|x, y| x.2.total_cmp(&y.2))
        .map(|(k, s, _)| (k, s))
        .unwrap_or((0, 0.0));
    let dir_a = (a.last().map_or(0.0, |c| c.0[0]) - start).signum();
    let mut out: Ring = a.to_vec();
    // a's start again, one turn on.
    out.push(([start + dir_a * period, a[0].0[1]], a[0].1));
    // b from corner k, once around, starting at the same turn as a's end.
    let n = b.len();
    let b_shift = shift + dir_a * period;
    let mut unrolled: Vec<([f64; 2], u32)> = Vec::with_capacity(n + 1);
    for j in 0..=n {
        let c = &b[(k + j) % n];
        let mut u = c.0[0] + b_shift;
        if let Some(prev) = unrolled.last() {
            u += ((prev.0[0] - u) / period).round() * period;
        }
        unrolled.push(([u, c.0[1]], c.1));
    }
    out.extend(unrolled);
    out
}

/// Loops unrolled one by one may land a turn apart: each hole of a face
/// is moved by whole turns to lie within its outer loop's span of angle
/// (parameter `k`: 0 for u, 1 for v).
fn align_turns(rings: &mut [Ring], period: f64, k: usize) {
    // The outer loop: the widest (a file's loops need not come outer first).
    let span = |r: &Ring| {
        let (lo, hi) = r
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), c| {
                (l.min(c.0[k]), h.max(c.0[k]))
            });
        (lo, hi - lo)
    };
    let Some(outer) =
        (0..rings.len()).max_by(|&a, &b| span(&rings[a]).1.total_cmp(&span(&rings[b]).1))
    else {
        return;
    };
    let lo = span(&rings[outer]).0;
    for (j, r) in rings.iter_mut().enumerate() {
        if j == outer {
            continue;
        }
        let mid = r.iter().map(|c| c.0[k]).sum::<f64>() / r.len().max(1) as f64;
        let shift = ((lo - mid) / period).ceil() * period;
        for c in r.iter_mut() {
            c.0[k] += shift;
        }
    }
}

/// Parameters rounded to 1e-9 of the rings' extent:
/// points of one straight boundary (a circle of a cylinder unrolled) are
/// then exactly in line, and the triangulation makes no sliver across
/// them from rounding.
fn snap(rings: &mut [Ring]) {
    let extent = rings
        .iter()
        .flatten()
        .fold(0.0f64, |m, c| m.max(c.0[0].abs()).max(c.0[1].abs()))
        .max(1.0);
    let grid = 1e-9 * extent;
    for c in rings.iter_mut().flatten() {
        for k in 0..2 {
            c.0[k] = (c.0[k] / grid).round() * grid;
        }
    }
}

/// Cells of a free-form face's parameter box fine enough for
/// `deviation`: the surface sampled on a coarse grid (four samples per
/// knot span, at least 16), the largest second difference along each
/// direction (the sagitta of a chord over two samples) scaled to the cell
/// size whose chords stay within `deviation` (a sagitta grows with the
/// square of the chord).
fn freeform_cells(
    nurbs: &thinwall_geom::NurbsSurface,
    lo: [f64; 2],
    hi: [f64; 2],
    deviation: f64,
) -> (usize, usize) {
    let spans = |knots: &[f64], a: f64, b: f64| {
        let mut inner: Vec<f64> = knots.iter().copied().filter(|&k| k > a && k < b).collect();
        inner.dedup();
        inner.len() + 1
    };
    let nu = (4 * spans(&nurbs.knots_u, lo[0], hi[0])).clamp(16, MAX_GRID);
    let nv = (4 * spans(&nurbs.knots_v, lo[1], hi[1])).clamp(16, MAX_GRID);
    let at = |i: usize, j: usize| {
        let u = lo[0] + (hi[0] - lo[0]) * i as f64 / nu as f64;
        let v = lo[1] + (hi[1] - lo[1]) * j as f64 / nv as f64;
        nurbs.eval(u, v).point
    };
    let grid: Vec<Vec<Point3>> = (0..=nu)
        .map(|i| (0..=nv).map(|j| at(i, j)).collect())
        .collect();
    let (mut su, mut sv) = (0.0f64, 0.0f64);
    for i in 0..=nu {
        for j in 0..=nv {
            if i > 0 && i < nu {
                let d = grid[i - 1][j].coords - 2.0 * grid[i][j].coords + grid[i + 1][j].coords;
                su = su.max(0.5 * d.norm());
            }
            if j > 0 && j < nv {
                let d = grid[i][j - 1].coords - 2.0 * grid[i][j].coords + grid[i][j + 1].coords;
                sv = sv.max(0.5 * d.norm());
            }
        }
    }
    // Chords over two samples have sagitta `sag`; over one cell of n,
    // sag · (samples / 2n)².
    let cells = |sag: f64, samples: usize| {
        ((0.5 * samples as f64 * (sag / deviation).sqrt()).ceil() as usize).max(samples / 2)
    };
    (cells(su, nu), cells(sv, nv))
}

/// Columns and rows within `MAX_LINES` each and `MAX_CELLS` together,
/// both scaled alike where they are not.
fn cap_cells(nu: usize, nv: usize) -> (usize, usize) {
    let (nu, nv) = (nu.clamp(1, MAX_LINES), nv.clamp(1, MAX_LINES));
    let cells = (nu * nv) as f64;
    if cells <= MAX_CELLS as f64 {
        return (nu, nv);
    }
    let k = (MAX_CELLS as f64 / cells).sqrt();
    (
        ((nu as f64 * k).floor() as usize).max(1),
        ((nv as f64 * k).floor() as usize).max(1),
    )
}

/// The angle of an arc of radius `r` whose chord stays within `deviation`
/// (the sagitta r(1 − cos(θ/2))), at most `MAX_ANGLE`.
fn arc_step(deviation: f64, r: f64) -> f64 {
    (2.0 * (1.0 - (deviation / r).min(1.0)).acos()).min(MAX_ANGLE)
}

/// The parameter box of a face's rings and its columns and rows: fine
/// enough for `deviation` (none on a plane).
struct Grid {
    lo: [f64; 2],
    hi: [f64; 2],
    nu: usize,
    nv: usize,
}

impl Grid {
    /// `part_deviation`: the part mesh's, which rows along a straight
    /// generator never come closer than (none for a caller's own face).
    fn of(
        chart: &Chart,
        rings: &[Ring],
        deviation: f64,
        part_deviation: Option<f64>,
    ) -> Option<Grid> {
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for c in rings.iter().flatten() {
            for k in 0..2 {
                lo[k] = lo[k].min(c.0[k]);
                hi[k] = hi[k].max(c.0[k]);
            }
        }
        let (nu, nv) = match chart {
            Chart::Plane { .. } => return None,
            Chart::Revolved {
                scale, r0, slope, ..
            } => {
                // The sagitta of an arc of angle θ is r(1 − cos(θ/2)); rows
                // along the generator keep triangles from spanning more than
                // a column's angle.
                let r = (r0 + slope * lo[1]).abs().max((r0 + slope * hi[1]).abs());
                let step = arc_step(deviation, r.max(1e-9)) * scale;
                (
                    ((hi[0] - lo[0]) / step.max(1e-9)).ceil() as usize,
                    ((hi[1] - lo[1])
                        / (GENERATOR_STRETCH * step)
                            .max(part_deviation.unwrap_or(0.0))
                            .max(1e-9))
                    .ceil() as usize,
                )
            }
            Chart::Torus { major, minor, .. } => {
                let (su, sv) = (
                    arc_step(deviation, major + minor) * major,
                    arc_step(deviation, *minor) * minor,
                );
                (
                    ((hi[0] - lo[0]) / su.max(1e-9)).ceil() as usize,
                    ((hi[1] - lo[1]) / sv.max(1e-9)).ceil() as usize,
                )
            }
            Chart::Freeform { nurbs } => freeform_cells(nurbs, lo, hi, deviation),
            Chart::Sphere { radius, .. } => {
                let angle = arc_step(deviation, *radius);
                let step = (angle * radius).max(1e-9);
                (
                    ((hi[0] - lo[0]) / step).ceil() as usize,
                    ((hi[1] - lo[1]) / step).ceil() as usize,
                )
            }
        };
        Some(Grid {
            lo,
            hi,
            nu: cap_cells(nu, nv).0,
            nv: cap_cells(nu, nv).1,
        })
    }

    /// The same columns without rows, on a cylinder or cone: its strips
    /// between two generator lines are flat, however long.
    fn columns_only(&self, chart: &Chart) -> Option<Grid> {
        (matches!(chart, Chart::Revolved { .. }) && self.nv > 1).then_some(Grid { nv: 1, ..*self })
    }

    /// Whether no triangle spans more than `ONE_COLUMN` columns across
    /// the generator (its chord then stays within twice the deviation).
    fn one_column(&self, tris: &[PlaneTri]) -> bool {
        let du = (self.hi[0] - self.lo[0]) / self.nu.max(1) as f64;
        tris.iter().all(|t| t.u_span <= ONE_COLUMN * du)
    }

    /// Rows over columns apart: the triangulation shortens v by this, so
    /// the grid is square there and Delaunay triangles join neighbours
    /// (rows along a cylinder are several columns apart; a torus's tube
    /// is much finer than its sweep in parameter units).
    fn stretch(&self) -> f64 {
        let du = (self.hi[0] - self.lo[0]) / self.nu as f64;
        let dv = (self.hi[1] - self.lo[1]) / self.nv as f64;
        if du > 0.0 && dv > 0.0 {
            dv / du
        } else {
            1.0
        }
    }

    fn u(&self, i: usize) -> f64 {
        self.lo[0] + (self.hi[0] - self.lo[0]) * i as f64 / self.nu as f64
    }

    /// A pole's (apex's) line runs along u with one point id: it gets a
    /// corner at every column, so the triangles at the pole fan out
    /// column by column instead of reaching across the face (those would
    /// land on top of each other, the pole being one point).
    fn split_poles(&self, rings: &mut [Ring]) {
        for r in rings.iter_mut() {
            let mut out: Ring = Vec::with_capacity(r.len());
            for k in 0..r.len() {
                let (a, b) = (r[k], r[(k + 1) % r.len()]);
                out.push(a);
                if a.1 != b.1 || a.0[1] != b.0[1] {
                    continue;
                }
                let (lo, hi) = (a.0[0].min(b.0[0]), a.0[0].max(b.0[0]));
                let mut cols: Vec<f64> = (0..=self.nu)
                    .map(|i| self.u(i))
                    .filter(|&u| u > lo && u < hi)
                    .collect();
                if b.0[0] < a.0[0] {
                    cols.reverse();
                }
                out.extend(cols.into_iter().map(|u| ([u, a.0[1]], a.1)));
            }
            *r = out;
        }
    }

    /// A band or a cap is cut open along a line of the surface, which the
    /// ring runs twice: from corner `k` to the next, and back along the
    /// closing side one turn over. Both get a corner at every row (the
    /// same new points), so no triangle spans the cut's whole length.
    fn split_cut(&self, chart: &Chart, ring: &mut Ring, k: usize, points: &mut Vec<Point3>) {
        let n = ring.len();
        if k + 1 >= n {
            return;
        }
        let (p, q) = (ring[k].0, ring[k + 1].0);
        let row = (self.hi[1] - self.lo[1]) / self.nv.max(1) as f64;
        let m = ((q[1] - p[1]).abs() / row.max(1e-12)).ceil() as usize;
        if m < 2 {
            return;
        }
        let along: Vec<([f64; 2], u32)> = (1..m)
            .map(|j| {
                let t = j as f64 / m as f64;
                let uv = [p[0] + (q[0] - p[0]) * t, p[1] + (q[1] - p[1]) * t];
                points.push(lift(chart, uv));
                (uv, points.len() as u32 - 1)
            })
            .collect();
        // The closing side: the same line one turn back, the other way.
        let shift = ring[0].0[0] - ring[k].0[0];
        let back: Vec<([f64; 2], u32)> = along
            .iter()
            .rev()
            .map(|&(uv, id)| ([uv[0] + shift, uv[1]], id))
            .collect();
        ring.extend(back);
        ring.splice(k + 1..k + 1, along);
    }

    /// Interior points, strictly inside the rings and clear of them
    /// ([`Bands`]: the sides near each point only).
    fn points(&self, rings: &[Ring]) -> Vec<[f64; 2]> {
        let (lo, hi, nu, nv) = (self.lo, self.hi, self.nu, self.nv);
        let bands = Bands::of(rings, 1e-6 * (hi[1] - lo[1] + hi[0] - lo[0]));
        let mut out = Vec::new();
        for i in 1..nu {
            for j in 0..=nv {
                let u = self.u(i);
                let v = lo[1] + (hi[1] - lo[1]) * j as f64 / nv.max(1) as f64;
                // Strictly inside, away from the boundary.
                if bands.inside([u, v]) && bands.clear_of([u, v]) {
                    out.push([u, v]);
                }
            }
        }
        out
    }
}

/// The sides of the rings, each corner to the next.
fn sides(rings: &[Ring]) -> impl Iterator<Item = ([f64; 2], [f64; 2])> + '_ {
    rings
        .iter()
        .flat_map(|r| (0..r.len()).map(move |i| (r[i].0, r[(i + 1) % r.len()].0)))
}

/// Even–odd: whether `p` lies inside the rings.
#[cfg(test)]
fn inside(rings: &[Ring], p: [f64; 2]) -> bool {
    odd_crossings(sides(rings), p)
}

/// Even–odd over `sides`: an odd number of them cross the level of `p`
/// past it.
fn odd_crossings(sides: impl Iterator<Item = ([f64; 2], [f64; 2])>, p: [f64; 2]) -> bool {
    let mut odd = false;
    for (a, b) in sides {
        if (a[1] > p[1]) != (b[1] > p[1]) {
            let x = a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
            if x > p[0] {
                odd = !odd;
            }
        }
    }
    odd
}

/// The rings' sides filed in bands of v (each where it comes within
/// `gap` of the band), so a point is tested against the sides of its band
/// only: the same decisions as against every side (a side outside the
/// band can neither cross the point's level nor come within `gap`).
struct Bands {
    lo: f64,
    step: f64,
    gap: f64,
    sides: Vec<Vec<([f64; 2], [f64; 2])>>,
}

impl Bands {
    fn of(rings: &[Ring], gap: f64) -> Bands {
        let all: Vec<([f64; 2], [f64; 2])> = sides(rings).collect();
        let (lo, hi) = all
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), s| {
                (l.min(s.0[1]).min(s.1[1]), h.max(s.0[1]).max(s.1[1]))
            });
        let n = ((all.len() as f64).sqrt().ceil() as usize).max(1);
        let step = ((hi - lo) / n as f64).max(f64::MIN_POSITIVE);
        let mut bands = Bands {
            lo,
            step,
            gap,
            sides: vec![Vec::new(); n],
        };
        for s in all {
            let (a, b) = (
                bands.band(s.0[1].min(s.1[1]) - gap),
                bands.band(s.0[1].max(s.1[1]) + gap),
            );
            for band in &mut bands.sides[a..=b] {
                band.push(s);
            }
        }
        bands
    }

    fn band(&self, v: f64) -> usize {
        let k = ((v - self.lo) / self.step).floor();
        if k.is_finite() && k > 0.0 {
            (k as usize).min(self.sides.len() - 1)
        } else {
            0
        }
    }

    fn near(&self, p: [f64; 2]) -> &[([f64; 2], [f64; 2])] {
        if self.sides.is_empty() || p[1].is_nan() {
            return &[];
        }
        &self.sides[self.band(p[1])]
    }

    fn inside(&self, p: [f64; 2]) -> bool {
        odd_crossings(self.near(p).iter().copied(), p)
    }

    /// Farther than the gap from every side ([`side_clear`]).
    fn clear_of(&self, p: [f64; 2]) -> bool {
        self.near(p)
            .iter()
            .all(|&(a, b)| side_clear(a, b, p, self.gap))
    }
}

/// Whether `p` lies farther than `gap` from the side `a`–`b`.
fn side_clear(a: [f64; 2], b: [f64; 2], p: [f64; 2], gap: f64) -> bool {
    let d = [b[0] - a[0], b[1] - a[1]];
    let l2 = d[0] * d[0] + d[1] * d[1];
    let t = if l2 > 0.0 {
        (((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let q = [a[0] + d[0] * t - p[0], a[1] + d[1] * t - p[1]];
    q[0].hypot(q[1]) > gap
}

#[derive(Clone, Copy)]
enum Corner {
    Boundary(u32),
    Steiner(usize),
}

/// A triangle of the parameter plane: its corners and how far it spans
/// along u.
struct PlaneTri {
    corners: [Corner; 3],
    u_span: f64,
    /// The middle of its corners' parameters.
    centre: [f64; 2],
}

/// Constrained Delaunay triangles of the rings (and interior points)
/// whose centres lie inside.
fn cdt(rings: &[Ring], steiner: &[[f64; 2]], stretch: f64) -> Result<Vec<PlaneTri>, String> {
    // Triangulated with v shortened `stretch` times (`Grid::stretch`).
    let at = |uv: &[f64; 2]| crate::param_mesh::spade_point(uv[0], uv[1] / stretch);
    let mut t: ConstrainedDelaunayTriangulation<Point2<f64>> = Default::default();
    let mut corner_of = std::collections::HashMap::new();
    for r in rings {
        let mut handles = Vec::with_capacity(r.len());
        for (uv, id) in r {
            if !(uv[0].is_finite() && uv[1].is_finite()) {
                return Err("a boundary point has no parameters".into());
            }
            let h = t
                .insert(at(uv))
                .map_err(|e| format!("triangulation refused a point: {e:?}"))?;
            corner_of.entry(h).or_insert(Corner::Boundary(*id));
            handles.push(h);
        }
        for i in 0..handles.len() {
            let (a, b) = (handles[i], handles[(i + 1) % handles.len()]);
            if a != b && !t.exists_constraint(a, b) {
                t.try_add_constraint(a, b);
            }
        }
    }
    for (j, uv) in steiner.iter().enumerate() {
        let h = t
            .insert(at(uv))
            .map_err(|e| format!("triangulation refused a point: {e:?}"))?;
        corner_of.entry(h).or_insert(Corner::Steiner(j));
    }
    let bands = Bands::of(rings, 0.0);
    let mut out = Vec::new();
    for f in t.inner_faces() {
        let vs = f.vertices();
        let c = vs.map(|v| {
            let p = v.position();
            [p.x, p.y * stretch]
        });
        let centre = [
            (c[0][0] + c[1][0] + c[2][0]) / 3.0,
            (c[0][1] + c[1][1] + c[2][1]) / 3.0,
        ];
        if !bands.inside(centre) {
            continue;
        }
        let corners: Option<Vec<Corner>> = vs
            .iter()
            .map(|v| corner_of.get(&v.fix()).copied())
            .collect();
        if let Some(cs) = corners {
            let us = c.map(|p| p[0]);
            out.push(PlaneTri {
                corners: [cs[0], cs[1], cs[2]],
                u_span: us[0].max(us[1]).max(us[2]) - us[0].min(us[1]).min(us[2]),
                centre,
            });
        }
    }
    Ok(out)
}

/// The surface point at parameters `uv`.
fn lift(chart: &Chart, uv: [f64; 2]) -> Point3 {
    match chart {
        Chart::Plane { frame } => frame.to_world(&Vector3::new(uv[0], uv[1], 0.0)),
        Chart::Revolved {
            frame,
            scale,
            r0,
            slope,
        } => {
            let (a, r) = (uv[0] / scale, r0 + slope * uv[1]);
            frame.to_world(&Vector3::new(r * a.cos(), r * a.sin(), uv[1]))
        }
        Chart::Freeform { nurbs } => nurbs.eval(uv[0], uv[1]).point,
        Chart::Torus {
            frame,
            major,
            minor,
        } => {
            let (a, b) = (uv[0] / major, uv[1] / minor);
            let rho = major + minor * b.cos();
            frame.to_world(&Vector3::new(rho * a.cos(), rho * a.sin(), minor * b.sin()))
        }
        Chart::Sphere { frame, radius } => {
            let (a, b) = (uv[0] / radius, uv[1] / radius);
            frame.to_world(&Vector3::new(
                radius * b.cos() * a.cos(),
                radius * b.cos() * a.sin(),
                radius * b.sin(),
            ))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Random rings: a star-shaped outline with a hole.
    fn rings(seed: &mut u64) -> Vec<Ring> {
        let mut rnd = || {
            *seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (*seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut ring = |n: usize, r: f64| -> Ring {
            (0..n)
                .map(|i| {
                    let a = std::f64::consts::TAU * i as f64 / n as f64;
                    let rr = r * (0.6 + 0.4 * rnd());
                    ([rr * a.cos(), rr * a.sin()], i as u32)
                })
                .collect()
        };
        vec![ring(60, 10.0), ring(12, 2.0)]
    }

    #[test]
    fn bands_decide_as_every_side_does() {
        let mut seed = 11u64;
        let (mut checked, mut near) = (0, 0);
        for _ in 0..20 {
            let rs = rings(&mut seed);
            let gap = 0.3;
            let bands = Bands::of(&rs, gap);
            for j in 0..=40 {
                for i in 0..=80 {
                    let p = [-10.0 + 0.25 * i as f64, -10.0 + 0.5 * j as f64 + 0.013];
                    assert_eq!(bands.inside(p), inside(&rs, p), "{p:?}");
                    let every = sides(&rs).all(|(a, b)| side_clear(a, b, p, gap));
                    assert_eq!(bands.clear_of(p), every, "{p:?}");
                    near += usize::from(!every);
                    checked += 1;
                }
            }
        }
        assert!(
            checked > 60_000 && near > 1000,
            "{checked} points, {near} near a side"
        );
    }
}
