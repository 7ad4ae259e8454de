//! The part seen from the set-up's up: every face that is not vertical,
//! cut where needed into pieces that are graphs `z = h(x, y)` over their
//! projection, each facing up (material below) or down (material above).
//!
//! Supported: planes at any angle, cylinders whose axis is square to up
//! (foot fillets, holes through upright walls; cut at their silhouettes),
//! cones about an axis along up (countersinks, drafted bosses), tori about
//! an axis along up and spheres, each face within one half (above or below
//! its equator: the corner of a pocket where its corner radius meets its
//! floor fillet, a blended hole edge, a spherical dimple). Vertical
//! faces (planes along up, cylinders about an axis along up) project to
//! curves and carry no volume. Any other surface makes the removal plan
//! unavailable, with the face named.

use super::sample::face_loop_points;
use super::RemovalError;
use geo::{BooleanOps, Coord, LineString, MultiPolygon, Orient, Polygon, Rect};
use std::sync::atomic::{AtomicUsize, Ordering};
use thinwall_analysis::parallel::Work;
use thinwall_brep::{FaceId, Part};
use thinwall_geom::{Frame, Point3, Surface, Vector3};

/// |n·up| below this: the face is vertical (projects to a curve).
const VERTICAL_EPS: f64 = 1e-9;

/// Which side of a piece the material is on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Facing {
    /// Outward normal up: material below.
    Up,
    /// Outward normal down: material above.
    Down,
}

/// A piece's height over the set-up plane, in the removal frame.
///
/// Every variant fills the same seven numbers (`pad` makes up the rest):
/// a value built on the stack is then initialised all through, which
/// valgrind needs to follow optimised code that reads the payload before
/// it branches on the variant.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Height {
    /// `z = z0 + gx·x + gy·y`.
    Plane {
        z0: f64,
        gx: f64,
        gy: f64,
        #[serde(skip)]
        pad: [f64; 4],
    },
    /// Half of a cylinder about a horizontal axis through `(ox, oy, oz)`
    /// along `(ax, ay)`: `z = oz + sign·√(r² − u²)`, `u` across the axis.
    Cylinder {
        o: [f64; 3],
        a: [f64; 2],
        r: f64,
        sign: f64,
    },
    /// A cone about a vertical axis through `(cx, cy)`: `z = z0 + k·ρ`.
    Cone {
        c: [f64; 2],
        z0: f64,
        k: f64,
        #[serde(skip)]
        pad: [f64; 3],
    },
    /// Half of a torus about a vertical axis through `c` (a sphere when
    /// `big_r` is 0): `z = zc + sign·√(r² − (ρ − R)²)`, ρ the distance from
    /// the axis; the upper half (`sign` +1) or the lower one.
    Revolved {
        c: [f64; 2],
        zc: f64,
        big_r: f64,
        r: f64,
        sign: f64,
        #[serde(skip)]
        pad: [f64; 1],
    },
    /// Triangles of a face no other variant takes (a tilted cylinder, a
    /// free-form face), all facing one way: piecewise linear.
    Facets {
        #[serde(serialize_with = "crate::facets::shared")]
        facets: std::sync::Arc<crate::facets::Facets>,
        #[serde(skip)]
        pad: [f64; 6],
    },
}

/// A graph piece of one face.
#[derive(Clone, Debug)]
pub struct Piece {
    pub face: FaceId,
    pub step_id: u64,
    pub facing: Facing,
    pub region: MultiPolygon<f64>,
    pub height: Height,
    pub bbox: Rect<f64>,
    /// Lowest and highest height over the region, mm.
    pub z_range: [f64; 2],
}

/// Every graph piece of `part` in `frame` (z = up): exact where the face
/// is a graph [`face_pieces`] takes, else its triangles at `deviation`
/// ([`facet_pieces`]), each recorded in `meshed`.
pub fn pieces(
    part: &Part,
    frame: &Frame,
    (deviation, work): (f64, Work),
    meshed: &mut Meshed,
) -> Result<Vec<Piece>, RemovalError> {
    let faces: Vec<(usize, FaceId)> = part.face_ids().enumerate().collect();
    // The first face (in the part's order) that fails is the error; past
    // a failure, faces after it are not worth making.
    let failed = AtomicUsize::new(usize::MAX);
    let made = work.map(&faces, |&(k, f)| {
        if k > failed.load(Ordering::Relaxed) {
            return None;
        }
        let made = face_or_facet_pieces(part, f, frame, deviation);
        if made.is_err() {
            failed.fetch_min(k, Ordering::Relaxed);
        }
        Some(made)
    });
    let mut out = Vec::new();
    for ((_, f), m) in faces.into_iter().zip(made) {
        // Faces left unmade follow a failed one, whose error comes first.
        let (p, overlap) = m.expect("a face unmade follows a failure")?;
        if let Some(overlap) = overlap {
            meshed.add(part, f, &p, deviation, overlap);
        }
        out.extend(p);
    }
    Ok(out)
}

/// Face `f`'s exact pieces, or else its triangles' and their overlap in
/// projection (mm³).
fn face_or_facet_pieces(
    part: &Part,
    f: FaceId,
    frame: &Frame,
    deviation: f64,
) -> Result<(Vec<Piece>, Option<f64>), RemovalError> {
    match face_pieces(part, f, frame) {
        Ok(p) => Ok((p, None)),
        Err(RemovalError::UnsupportedFace { step_id, reason }) => {
            let (facets, overlap) = facet_pieces(part, f, frame, deviation).map_err(|why| {
                RemovalError::UnsupportedFace {
                    step_id,
                    reason: format!("{reason}, and its triangles: {why}"),
                }
            })?;
            Ok((facets, Some(overlap)))
        }
        Err(e) => Err(e),
    }
}

/// The faces taken as triangles rather than exactly: which, their area,
/// and the bound on the volume that implies.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize)]
pub struct Meshed {
    /// STEP ids of the meshed faces.
    pub faces: Vec<u64>,
    /// Their triangles' area, mm².
    pub area_mm2: f64,
    /// Triangles' largest distance from their surface, mm.
    pub deviation_mm: f64,
    /// Triangles taken as graph pieces.
    pub triangles: usize,
    /// Where triangles straddling a silhouette overlap their neighbours
    /// in projection: the overlap times the face's height range, mm³.
    pub overlap_mm3: f64,
    /// How far the removal can be off the exact one through them:
    /// deviation × area + the overlaps, mm³.
    pub volume_bound_mm3: f64,
}

impl Meshed {
    /// No face was meshed (the removal is exact).
    pub fn is_empty(&self) -> bool {
        self.faces.is_empty()
    }

    fn add(&mut self, part: &Part, f: FaceId, facets: &[Piece], deviation: f64, overlap: f64) {
        self.faces.push(part.face(f).step_id);
        self.area_mm2 += facets.iter().map(|p| p.facet_area()).sum::<f64>();
        self.deviation_mm = deviation;
        self.triangles += facets
            .iter()
            .map(|p| match &p.height {
                Height::Facets { facets, .. } => facets.len(),
                _ => 0,
            })
            .sum::<usize>();
        self.overlap_mm3 += overlap;
        self.volume_bound_mm3 = self.deviation_mm * self.area_mm2 + self.overlap_mm3;
    }
}

/// A face as graph pieces of its triangles: the watertight tessellation
/// with the removal's own edge points as boundary (so it meets its exact
/// neighbours without a gap), split where its facing turns: a piece per
/// connected patch of the triangles facing up, one per patch of those
/// facing down (triangles standing vertical project to nothing and are
/// left out). A face that curls past vertical and back (a free-form
/// fillet folding over itself) gives two patches facing up, each a graph.
pub fn facet_pieces(
    part: &Part,
    f: FaceId,
    frame: &Frame,
    deviation: f64,
) -> Result<(Vec<Piece>, f64), String> {
    let (points, triangles) = thinwall_brep::tessellate::face_triangles(
        part,
        f,
        &|e| crate::sample::edge_interior_points(part, e),
        deviation,
    )?;
    let local: Vec<[f64; 3]> = points
        .iter()
        .map(|p| {
            let l = frame.to_local(p);
            [l.x, l.y, l.z]
        })
        .collect();
    let step_id = part.face(f).step_id;
    let (mut up, mut down) = (Vec::new(), Vec::new());
    for t in triangles {
        let [a, b, c] = t.map(|i| Vector3::from(local[i as usize]));
        let n = (b - a).cross(&(c - a));
        if n.z.abs() <= VERTICAL_EPS * n.norm() {
            continue;
        }
        if n.z > 0.0 {
            up.push(t);
        } else {
            down.push(t);
        }
    }
    let one_way = up.is_empty() || down.is_empty();
    let mut overlap_volume = 0.0;
    let mut out = Vec::new();
    for (facing, tris) in [(Facing::Up, up), (Facing::Down, down)] {
        let patches = if one_way { vec![tris] } else { patches(&tris) };
        for patch in patches.into_iter().filter(|p| !p.is_empty()) {
            let outline = if one_way {
                Vec::new()
            } else {
                patch_outline(&patch, &local, facing)
            };
            let tris: Vec<[[f64; 3]; 3]> =
                patch.iter().map(|t| t.map(|i| local[i as usize])).collect();
            // A face that faces one way all over is a graph over its own
            // projected loops (the boundary its neighbours share); one that
            // turns is split along its silhouette by its triangles.
            let region = if one_way {
                project(part, f, frame)
            } else {
                let (region, layered) = triangles_region(&tris, outline, deviation)?;
                overlap_volume += layered;
                region
            };
            let height = Height::Facets {
                facets: std::sync::Arc::new(crate::facets::Facets::new(tris)),
                pad: [0.0; 6],
            };
            out.extend(finish(f, step_id, facing, region, height));
        }
    }
    Ok((out, overlap_volume))
}

/// A region without the holes and parts smaller than a square a hundredth
/// of a deviation wide: specks the booleans leave where a fan of sliver
/// triangles meets at a cone's apex.
fn drop_specks(region: MultiPolygon<f64>, deviation: f64) -> MultiPolygon<f64> {
    let speck = (0.01 * deviation).powi(2);
    MultiPolygon::new(
        region
            .0
            .into_iter()
            .filter(|p| crate::moments::area(&Polygon::new(p.exterior().clone(), vec![])) > speck)
            .map(|p| {
                let (outer, holes) = p.into_inner();
                let holes = holes
                    .into_iter()
                    .filter(|h| crate::moments::area(&Polygon::new(h.clone(), vec![])) > speck)
                    .collect();
                Polygon::new(outer, holes)
            })
            .collect(),
    )
}

/// A patch's outline seen from above: its edges that no other triangle of
/// the patch shares, chained into rings running counter-clockwise round
/// the patch (triangles facing down turn the other way in projection, so
/// theirs are reversed).
fn patch_outline(patch: &[[u32; 3]], local: &[[f64; 3]], facing: Facing) -> Vec<Vec<[f64; 2]>> {
    use std::collections::{BTreeMap, HashSet};
    let directed: HashSet<(u32, u32)> = patch
        .iter()
        .flat_map(|t| [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])])
        .collect();
    let mut next: BTreeMap<u32, Vec<u32>> = BTreeMap::new();
    for &(a, b) in &directed {
        if !directed.contains(&(b, a)) {
            next.entry(a).or_default().push(b);
        }
    }
    let mut rings = Vec::new();
    while let Some((&start, _)) = next.iter().find(|(_, v)| !v.is_empty()) {
        let mut ring = vec![start];
        let mut at = start;
        while let Some(b) = next.get_mut(&at).and_then(Vec::pop) {
            if b == start {
                break;
            }
            ring.push(b);
            at = b;
        }
        let mut pts: Vec<[f64; 2]> = ring
            .iter()
            .map(|&i| [local[i as usize][0], local[i as usize][1]])
            .collect();
        if facing == Facing::Down {
            pts.reverse();
        }
        rings.push(pts);
    }
    rings
}

/// Triangles (indices into one point list) grouped into patches that hold
/// together across shared edges.
fn patches(tris: &[[u32; 3]]) -> Vec<Vec<[u32; 3]>> {
    use petgraph::unionfind::UnionFind;
    let mut joined = UnionFind::<usize>::new(tris.len());
    let mut first_at: std::collections::HashMap<(u32, u32), usize> = Default::default();
    for (k, t) in tris.iter().enumerate() {
        for (a, b) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
            match first_at.entry((a.min(b), a.max(b))) {
                std::collections::hash_map::Entry::Occupied(o) => {
                    joined.union(*o.get(), k);
                }
                std::collections::hash_map::Entry::Vacant(v) => {
                    v.insert(k);
                }
            }
        }
    }
    let mut by_root: std::collections::BTreeMap<usize, Vec<[u32; 3]>> = Default::default();
    for (k, t) in tris.iter().enumerate() {
        by_root.entry(joined.find(k)).or_default().push(*t);
    }
    by_root.into_values().collect()
}

/// The union of triangles' projections, all facing one way, and the
/// volume between the layers where they overlap (mm³); an error where
/// that is more than the deviation allows (the face folds over itself in
/// projection): never a region counted twice beyond the bound.
fn triangles_region(
    tris: &[[[f64; 3]; 3]],
    outline: Vec<Vec<[f64; 2]>>,
    deviation: f64,
) -> Result<(MultiPolygon<f64>, f64), String> {
    let total: f64 = tris.iter().map(crate::fold::flat_area).sum();
    // Through i_overlay 9 (geo's i_overlay 4.5 panics on such input:
    // the ledger): the patch's own outline, not the union of its
    // triangles, whose slivers at an apex cut it into 10^5 corners.
    let region = drop_specks(thinwall_analysis::boolean::wound_region(outline), deviation);
    let union: f64 = region.0.iter().map(crate::moments::area).sum();
    let overlap = (total - union).max(0.0);
    // Overlaps no wider than a chord's sagitta (the deviation) are the
    // tessellation's noise along a silhouette (a tall face standing near
    // vertical overlaps its own rows by slivers), counted into the meshed
    // bound; wider ones holding more than a deviation-thick skin of the
    // triangles between their layers are a face folding over itself.
    if overlap == 0.0 {
        return Ok((region, 0.0));
    }
    let (slivers, folds) = crate::fold::layered_volume(tris, 2.0 * deviation);
    let skin = deviation * tris.iter().map(crate::fold::area).sum::<f64>();
    if folds > skin {
        return Err(format!(
            "a face whose triangles overlap in projection by {overlap:.4} mm² of {total:.4}, \
             {folds:.4} mm³ between their layers, more than a {deviation} mm skin of them \
             ({skin:.4} mm³): it folds over itself"
        ));
    }
    Ok((region, slivers + folds))
}

impl Piece {
    /// The area of a facets piece's triangles themselves (not their
    /// projection), mm²; 0 for other pieces.
    pub fn facet_area(&self) -> f64 {
        match &self.height {
            Height::Facets { facets, .. } => facets.area(),
            _ => 0.0,
        }
    }
}

fn unsupported(part: &Part, f: FaceId, why: &str) -> RemovalError {
    RemovalError::UnsupportedFace {
        step_id: part.face(f).step_id,
        reason: why.to_string(),
    }
}

/// The graph pieces of one face of `part` in `frame` (z = up).
pub fn face_pieces(part: &Part, f: FaceId, frame: &Frame) -> Result<Vec<Piece>, RemovalError> {
    let face = part.face(f);
    let sense = if face.same_sense { 1.0 } else { -1.0 };
    let local = |p: &Point3| frame.to_local(p);
    match &face.surface {
        Surface::Plane { frame: pf } => {
            let n = frame.vector_to_local(&pf.z) * sense;
            if n.z.abs() < VERTICAL_EPS {
                return Ok(vec![]);
            }
            let o = local(&pf.origin);
            // n·(p − o) = 0  ⇒  z = o.z − (n.x (x − o.x) + n.y (y − o.y)) / n.z
            let (gx, gy) = (-n.x / n.z, -n.y / n.z);
            let height = Height::plane(o.z - gx * o.x - gy * o.y, gx, gy);
            let facing = if n.z > 0.0 { Facing::Up } else { Facing::Down };
            let region = project(part, f, frame);
            Ok(finish(f, face.step_id, facing, region, height))
        }
        Surface::Cylinder { frame: cf, radius } => {
            let a = frame.vector_to_local(&cf.z);
            if a.z.abs() > 1.0 - VERTICAL_EPS {
                return Ok(vec![]);
            }
            if a.z.abs() > VERTICAL_EPS {
                return Err(unsupported(part, f, "a cylinder tilted to the tool axis"));
            }
            cylinder_pieces(part, f, frame, cf, *radius, sense)
        }
        Surface::Torus {
            frame: tf,
            major_radius,
            minor_radius,
        } => {
            let a = frame.vector_to_local(&tf.z);
            if a.z.abs() < 1.0 - VERTICAL_EPS {
                return Err(unsupported(
                    part,
                    f,
                    "a torus whose axis is not the tool axis",
                ));
            }
            revolved_piece(
                part,
                f,
                frame,
                &tf.origin,
                *major_radius,
                *minor_radius,
                sense,
            )
        }
        Surface::Sphere { frame: sf, radius } => {
            revolved_piece(part, f, frame, &sf.origin, 0.0, *radius, sense)
        }
        Surface::Cone { frame: cf, .. } => {
            let a = frame.vector_to_local(&cf.z);
            if a.z.abs() < 1.0 - VERTICAL_EPS {
                return Err(unsupported(
                    part,
                    f,
                    "a cone whose axis is not the tool axis",
                ));
            }
            cone_piece(part, f, frame, &face.surface, cf, sense)
        }
        other => Err(unsupported(
            part,
            f,
            &format!(
                "a {} (not yet a graph over the set-up plane)",
                other.kind_name()
            ),
        )),
    }
}

/// Region, bounding box and height range of a finished piece; none when
/// the region is empty.
fn finish(
    f: FaceId,
    step_id: u64,
    facing: Facing,
    region: MultiPolygon<f64>,
    height: Height,
) -> Vec<Piece> {
    use geo::BoundingRect;
    let Some(bbox) = region.bounding_rect() else {
        return vec![];
    };
    let z_range = height.range_over(&region);
    vec![Piece {
        face: f,
        step_id,
        facing,
        region,
        height,
        bbox,
        z_range,
    }]
}

impl Height {
    /// `z = z0 + gx·x + gy·y`.
    pub fn plane(z0: f64, gx: f64, gy: f64) -> Self {
        Height::Plane {
            z0,
            gx,
            gy,
            pad: [0.0; 4],
        }
    }

    /// `z = z0 + k·ρ` about `(c[0], c[1])`.
    pub fn cone(c: [f64; 2], z0: f64, k: f64) -> Self {
        Height::Cone {
            c,
            z0,
            k,
            pad: [0.0; 3],
        }
    }

    /// `z = zc + sign·√(r² − (ρ − R)²)` about `c`.
    pub fn revolved(c: [f64; 2], zc: f64, big_r: f64, r: f64, sign: f64) -> Self {
        Height::Revolved {
            c,
            zc,
            big_r,
            r,
            sign,
            pad: [0.0; 1],
        }
    }

    /// Distance across a cylinder's axis (0 for the others).
    pub fn across(&self, x: f64, y: f64) -> f64 {
        match *self {
            Height::Cylinder { o, a, .. } => (x - o[0]) * (-a[1]) + (y - o[1]) * a[0],
            _ => 0.0,
        }
    }

    /// The height at `(x, y)`, mm.
    pub fn at(&self, x: f64, y: f64) -> f64 {
        match *self {
            Height::Plane { z0, gx, gy, .. } => z0 + gx * x + gy * y,
            Height::Cylinder { o, r, sign, .. } => {
                let u = self.across(x, y).clamp(-r, r);
                o[2] + sign * (r * r - u * u).max(0.0).sqrt()
            }
            Height::Cone { c, z0, k, .. } => z0 + k * (x - c[0]).hypot(y - c[1]),
            Height::Revolved {
                c,
                zc,
                big_r,
                r,
                sign,
                ..
            } => {
                let d = (x - c[0]).hypot(y - c[1]) - big_r;
                zc + sign * (r * r - d * d).max(0.0).sqrt()
            }
            Height::Facets { ref facets, .. } => facets.at(x, y),
        }
    }

    /// The height at `(u, s)` across and along a horizontal axis through
    /// `o` along `a` (the frame's x, y of that point).
    pub fn at_us(&self, o: &[f64; 3], a: &[f64; 2], u: f64, s: f64) -> f64 {
        self.at(o[0] + a[0] * s - a[1] * u, o[1] + a[1] * s + a[0] * u)
    }

    /// The lowest and highest height over a region: at its corners, and
    /// at a half cylinder's crest where the region spans the axis.
    pub fn range_over(&self, region: &MultiPolygon<f64>) -> [f64; 2] {
        if let Height::Facets { facets, .. } = self {
            return facets.range_over(region);
        }
        if let Height::Revolved {
            c,
            zc,
            big_r,
            r,
            sign,
            ..
        } = *self
        {
            return revolved_range(region, c, zc, big_r, r, sign);
        }
        let corners = || region.0.iter().flat_map(|p| p.exterior().0.iter());
        let mut z = [f64::INFINITY, f64::NEG_INFINITY];
        for c in corners() {
            let v = self.at(c.x, c.y);
            z = [z[0].min(v), z[1].max(v)];
        }
        if let Height::Cylinder { o, sign, r, .. } = *self {
            // The crest, where one polygon reaches across the axis (a region
            // of two strips either side of it does not).
            let spans = region.0.iter().any(|p| {
                let (lo, hi) = p
                    .exterior()
                    .0
                    .iter()
                    .map(|c| self.across(c.x, c.y))
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), u| {
                        (lo.min(u), hi.max(u))
                    });
                lo <= 0.0 && hi >= 0.0
            });
            if spans {
                let crest = o[2] + sign * r;
                z = [z[0].min(crest), z[1].max(crest)];
            }
        }
        z
    }
}

/// A face's loops projected on the frame's xy plane.
fn project(part: &Part, f: FaceId, frame: &Frame) -> MultiPolygon<f64> {
    let rings: Vec<LineString<f64>> = face_loop_points(part, f)
        .iter()
        .map(|pts| {
            ring(pts.iter().map(|p| {
                let l = frame.to_local(p);
                (l.x, l.y)
            }))
        })
        .collect();
    polygon_of_rings(rings)
}

/// A closed ring from points.
pub fn ring(pts: impl Iterator<Item = (f64, f64)>) -> LineString<f64> {
    let mut cs: Vec<Coord<f64>> = pts.map(|(x, y)| Coord { x, y }).collect();
    if let Some(&c) = cs.first() {
        cs.push(c);
    }
    LineString::new(cs)
}

/// The region of a face's rings (even-odd: the largest ring outside, the
/// others cut out), as a valid polygon. The common case — every other
/// ring inside the largest and apart from each other, holes of a face —
/// is built directly; anything else by the even-odd rule over all rings.
fn polygon_of_rings(rings: Vec<LineString<f64>>) -> MultiPolygon<f64> {
    use geo::{Area, Contains};
    let mut order: Vec<(f64, LineString<f64>)> = rings
        .into_iter()
        .map(|r| (Polygon::new(r.clone(), vec![]).unsigned_area(), r))
        .collect();
    order.sort_by(|a, b| b.0.total_cmp(&a.0));
    let Some((_, outer)) = order.first() else {
        return MultiPolygon::new(vec![]);
    };
    let outer_poly = Polygon::new(outer.clone(), vec![]);
    let nested = order[1..].iter().all(|(_, r)| {
        r.0.first()
            .is_some_and(|c| outer_poly.contains(&geo::Point::from(*c)))
    });
    if nested && (order.len() <= 2 || holes_apart(&order[1..])) {
        let holes = order[1..].iter().map(|(_, r)| r.clone()).collect();
        let p = Polygon::new(outer.clone(), holes).orient(geo::orient::Direction::Default);
        return MultiPolygon::new(vec![p]);
    }
    // Through i_overlay 9: geo's xor (i_overlay 4.5) panics on the loops
    // of some faces seen along a tilted up (NIST FTC 07 tilted 1°).
    thinwall_analysis::boolean::even_odd_region(
        order
            .into_iter()
            .map(|(_, r)| {
                let mut pts: Vec<[f64; 2]> = r.0.iter().map(|c| [c.x, c.y]).collect();
                if pts.len() > 1 && pts.first() == pts.last() {
                    pts.pop();
                }
                pts
            })
            .collect(),
    )
}

/// Whether rings' boxes are pairwise apart (then no ring holds another).
fn holes_apart(rings: &[(f64, LineString<f64>)]) -> bool {
    use geo::BoundingRect;
    let mut boxes: Vec<Rect<f64>> = rings
        .iter()
        .filter_map(|(_, r)| r.bounding_rect())
        .collect();
    boxes.sort_by(|a, b| a.min().x.total_cmp(&b.min().x));
    for (i, a) in boxes.iter().enumerate() {
        for b in &boxes[i + 1..] {
            if b.min().x > a.max().x {
                break;
            }
            if b.min().y <= a.max().y && a.min().y <= b.max().y {
                return false;
            }
        }
    }
    true
}

/// A cylinder about a horizontal axis: its region in (θ, s) (θ about the
/// axis from the horizontal, s along it), cut into the half facing up and
/// the half facing down, each mapped onto the plane.
fn cylinder_pieces(
    part: &Part,
    f: FaceId,
    frame: &Frame,
    cf: &Frame,
    r: f64,
    sense: f64,
) -> Result<Vec<Piece>, RemovalError> {
    use std::f64::consts::PI;
    let o = frame.to_local(&cf.origin);
    let a3 = frame.vector_to_local(&cf.z);
    let a = [a3.x, a3.y];
    let an = (a[0] * a[0] + a[1] * a[1]).sqrt();
    let a = [a[0] / an, a[1] / an];
    let b = [-a[1], a[0]];
    let to_ts = |p: &Point3| {
        let l = frame.to_local(p);
        let (dx, dy, dz) = (l.x - o.x, l.y - o.y, l.z - o.z);
        let s = dx * a[0] + dy * a[1];
        let u = dx * b[0] + dy * b[1];
        (dz.atan2(u), s)
    };
    let (wrapped, open) = unrolled_loops(&face_loop_points(part, f), to_ts);
    let region = match wrapped.len() {
        0 => open_region(&open),
        2 => tube_region(&wrapped, &open),
        _ => {
            return Err(unsupported(
                part,
                f,
                "a cylinder whose loops wind around it other than as a tube",
            ))
        }
    };
    // Facing up where sense·sin θ > 0 (the outward normal is sense·radial).
    let (slo, shi) = s_range(&region);
    let mut out = Vec::new();
    for (half, sign) in [(0.0, 1.0), (PI, -1.0)] {
        let part_region = region.intersection(&half_turns(half, slo, shi));
        if part_region.0.is_empty() {
            continue;
        }
        let planar = map_region(&part_region, |t: f64, s: f64| {
            let u = r * t.cos();
            (o.x + a[0] * s + b[0] * u, o.y + a[1] * s + b[1] * u)
        });
        let facing = if sense * sign > 0.0 {
            Facing::Up
        } else {
            Facing::Down
        };
        out.extend(finish(
            f,
            part.face(f).step_id,
            facing,
            planar,
            Height::Cylinder {
                o: [o.x, o.y, o.z],
                a,
                r,
                sign,
            },
        ));
    }
    Ok(out)
}

/// A loop's points as (θ, s) unrolled without jumps, split into the loops
/// that wind once around the axis and those that do not.
type Unrolled = Vec<Vec<(f64, f64)>>;
fn unrolled_loops(
    loops: &[Vec<Point3>],
    to_ts: impl Fn(&Point3) -> (f64, f64),
) -> (Unrolled, Unrolled) {
    use std::f64::consts::{PI, TAU};
    let mut wrapped = Vec::new();
    let mut open = Vec::new();
    for lp in loops {
        let mut pts: Vec<(f64, f64)> = Vec::with_capacity(lp.len());
        for p in lp {
            let (mut t, s) = to_ts(p);
            if let Some(&(prev, _)) = pts.last() {
                while t - prev > PI {
                    t -= TAU;
                }
                while t - prev < -PI {
                    t += TAU;
                }
            }
            pts.push((t, s));
        }
        let turn = pts.last().unwrap().0 - pts[0].0 + wrap_step(pts[0].0 - pts.last().unwrap().0);
        if turn.abs() > PI {
            wrapped.push(pts);
        } else {
            open.push(pts);
        }
    }
    (wrapped, open)
}

/// The (θ, s) region of loops none of which winds around: every loop
/// shifted next to the first one's mean angle.
fn open_region(open: &[Vec<(f64, f64)>]) -> MultiPolygon<f64> {
    use std::f64::consts::TAU;
    let mean = |p: &Vec<(f64, f64)>| p.iter().map(|q| q.0).sum::<f64>() / p.len() as f64;
    let m0 = open.first().map(mean).unwrap_or(0.0);
    let rings = open
        .iter()
        .map(|p| {
            let k = ((m0 - mean(p)) / TAU).round() * TAU;
            ring(p.iter().map(|q| (q.0 + k, q.1)))
        })
        .collect();
    polygon_of_rings(rings)
}

/// A tube: the strip between the two wrapping loops over one turn, less
/// the loops that do not wind around (holes in it). Each wrapping loop is
/// followed in its own order (it need not be a graph over θ: a loop may
/// run along the axis, as where a cut-out bites into the tube's end) and
/// repeated over neighbouring turns; the band between the two repeated
/// paths is clipped to θ ∈ [0, 2π].
fn tube_region(wrapped: &[Vec<(f64, f64)>], open: &[Vec<(f64, f64)>]) -> MultiPolygon<f64> {
    use std::f64::consts::TAU;
    let (p0, p1) = (turns_path(&wrapped[0]), turns_path(&wrapped[1]));
    let (slo, shi) = wrapped
        .iter()
        .flatten()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |m, q| {
            (m.0.min(q.1), m.1.max(q.1))
        });
    let band = polygon_of_rings(vec![ring(p0.into_iter().chain(p1.into_iter().rev()))]);
    let window = Rect::new(
        Coord {
            x: 0.0,
            y: slo - 1.0,
        },
        Coord {
            x: TAU,
            y: shi + 1.0,
        },
    );
    let mut region = band.intersection(&MultiPolygon::new(vec![window.to_polygon()]));
    for p in open {
        let mean = p.iter().map(|q| q.0).sum::<f64>() / p.len() as f64;
        let k = (-mean / TAU).floor();
        for shift in [k - 1.0, k, k + 1.0] {
            let hole = MultiPolygon::new(vec![Polygon::new(
                ring(p.iter().map(|q| (q.0 + shift * TAU, q.1))),
                vec![],
            )]);
            region = region.difference(&hole);
        }
    }
    region
}

/// A loop that winds once around, unrolled, as a path of increasing turn
/// over five turns (two before its own, two after): wide enough to cover
/// θ ∈ [0, 2π] from wherever it starts.
fn turns_path(loop_: &[(f64, f64)]) -> Vec<(f64, f64)> {
    use std::f64::consts::TAU;
    let mut pts = loop_.to_vec();
    let turn = pts[pts.len() - 1].0 - pts[0].0 + wrap_step(pts[0].0 - pts[pts.len() - 1].0);
    if turn < 0.0 {
        pts.reverse();
    }
    let mut path = Vec::with_capacity(5 * pts.len() + 1);
    for k in -2..=2 {
        path.extend(pts.iter().map(|q| (q.0 + TAU * k as f64, q.1)));
    }
    path.push((pts[0].0 + 3.0 * TAU, pts[0].1));
    path
}

/// The half turns θ ∈ [half + 2πk, half + 2πk + π] for k in −2..=2, over
/// s ∈ [slo − 1, shi + 1].
fn half_turns(half: f64, slo: f64, shi: f64) -> MultiPolygon<f64> {
    use std::f64::consts::{PI, TAU};
    let mut clip = MultiPolygon::new(vec![]);
    for k in -2..=2 {
        let t0 = half + TAU * k as f64;
        clip.0.push(
            Rect::new(
                Coord {
                    x: t0,
                    y: slo - 1.0,
                },
                Coord {
                    x: t0 + PI,
                    y: shi + 1.0,
                },
            )
            .to_polygon(),
        );
    }
    clip
}

/// A (θ, s) region mapped onto the plane by `map`, oriented.
fn map_region(
    region: &MultiPolygon<f64>,
    map: impl Fn(f64, f64) -> (f64, f64),
) -> MultiPolygon<f64> {
    let m = |ls: &LineString<f64>| {
        LineString::new(
            ls.0.iter()
                .map(|c| {
                    let (x, y) = map(c.x, c.y);
                    Coord { x, y }
                })
                .collect(),
        )
    };
    MultiPolygon::new(
        region
            .0
            .iter()
            .map(|p| {
                Polygon::new(m(p.exterior()), p.interiors().iter().map(m).collect())
                    .orient(geo::orient::Direction::Default)
            })
            .collect(),
    )
}

/// The signed step from `d` to the nearest equivalent angle in (−π, π].
fn wrap_step(d: f64) -> f64 {
    use std::f64::consts::{PI, TAU};
    let mut d = d;
    while d > PI {
        d -= TAU;
    }
    while d <= -PI {
        d += TAU;
    }
    d
}

fn s_range(region: &MultiPolygon<f64>) -> (f64, f64) {
    region
        .0
        .iter()
        .flat_map(|p| p.exterior().0.iter())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), c| {
            (lo.min(c.y), hi.max(c.y))
        })
}

/// A cone about a vertical axis: one piece, its height linear in the
/// distance to the axis.
/// The height range of a revolved half over a region: its height falls as
/// |ρ − R| grows, so the extremes are at the region's nearest and farthest
/// distances from the axis (the nearest on an edge, or 0 where the region
/// holds the axis) and at ρ = R where the region spans it.
fn revolved_range(
    region: &MultiPolygon<f64>,
    c: [f64; 2],
    zc: f64,
    big_r: f64,
    r: f64,
    sign: f64,
) -> [f64; 2] {
    use geo::Contains;
    let (mut near, mut far) = (f64::INFINITY, 0.0f64);
    for p in &region.0 {
        for ring in std::iter::once(p.exterior()).chain(p.interiors()) {
            for w in ring.0.windows(2) {
                let (a, b) = (
                    (w[0].x - c[0], w[0].y - c[1]),
                    (w[1].x - c[0], w[1].y - c[1]),
                );
                far = far.max(a.0.hypot(a.1));
                let (dx, dy) = (b.0 - a.0, b.1 - a.1);
                let len2 = dx * dx + dy * dy;
                let t = if len2 > 0.0 {
                    (-(a.0 * dx + a.1 * dy) / len2).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                near = near.min((a.0 + t * dx).hypot(a.1 + t * dy));
            }
        }
    }
    if region.contains(&geo::Point::new(c[0], c[1])) {
        near = 0.0;
    }
    if !near.is_finite() {
        return [zc, zc];
    }
    let z = |d: f64| zc + sign * (r * r - d * d).max(0.0).sqrt();
    let d_far = (near - big_r).abs().max((far - big_r).abs());
    let d_near = if near <= big_r && big_r <= far {
        0.0
    } else {
        (near - big_r).abs().min((far - big_r).abs())
    };
    let (a, b) = (z(d_far), z(d_near));
    [a.min(b), a.max(b)]
}

/// Whether a face of a torus or sphere whose boundary lies in one half
/// (`sign`) still reaches across the equator: a cap or zone bounded by
/// circles of latitude only (a dome over a circle below the equator has
/// the same boundary as the bowl under it). Each loop that is a circle of
/// latitude says which way the face goes from it — the loop runs with the
/// face on its left seen from the outward normal, `sense` times the
/// surface's, which at the loop points up the meridian when it turns
/// counter-clockwise seen from above on the tube's outer side (ρ > R).
/// The face goes on past the farthest such circle toward the equator
/// unless another circle beyond it turns it back.
fn crosses_equator(
    loops: &[Vec<Point3>],
    frame: &Frame,
    o: &Vector3,
    big_r: f64,
    sign: f64,
    sense: f64,
    tol: f64,
) -> bool {
    // (height of the circle, whether the face goes up from it)
    let mut circles: Vec<(f64, bool)> = Vec::new();
    for c in loops.iter().filter_map(|l| latitude(l, frame, o, tol)) {
        let outer = if c.rho >= big_r { 1.0 } else { -1.0 };
        circles.push((c.z, sense * c.turn.signum() * outer > 0.0));
    }
    // In the upper half the face must not go down past its lowest circle
    // without a circle below turning it back; in the lower half, up.
    let toward_equator = |&(z, up): &(f64, bool)| {
        let goes = if sign > 0.0 { !up } else { up };
        goes && !circles.iter().any(|&(z2, up2)| {
            if sign > 0.0 {
                z2 < z - tol && up2
            } else {
                z2 > z + tol && !up2
            }
        })
    };
    circles.iter().any(toward_equator)
}

/// A sphere face across its equator bounded by circles of latitude only (a
/// dome over a circle below its equator, a zone, a ball): split at the
/// equator into its upper and lower halves, each over the annulus (or disk)
/// between its boundary circle's projection and the equator's. Any other
/// boundary is refused by name.
#[allow(clippy::too_many_arguments)]
fn sphere_zone(
    part: &Part,
    f: FaceId,
    frame: &Frame,
    o: &Vector3,
    r: f64,
    sense: f64,
    loops: &[Vec<Point3>],
    tol: f64,
) -> Result<Vec<Piece>, RemovalError> {
    let refuse = || {
        unsupported(
            part,
            f,
            "a sphere face across its equator not bounded by circles of latitude",
        )
    };
    // Each loop: its ring in the plane, and whether it bounds the upper
    // half from above (the face goes down from it) or the lower from below.
    let (mut top, mut bottom) = (None, None);
    for l in loops {
        let c = latitude(l, frame, o, tol).ok_or_else(refuse)?;
        let up = sense * c.turn.signum() > 0.0;
        let slot = match (up, c.z > o.z) {
            (false, true) => &mut top,
            (true, false) => &mut bottom,
            _ => return Err(refuse()),
        };
        if slot.replace(c.ring).is_some() {
            return Err(refuse());
        }
    }
    let equator = ring(circle_points(o.x, o.y, r));
    let half = |cap: Option<LineString<f64>>, sign: f64| {
        let mut rings = vec![equator.clone()];
        rings.extend(cap);
        let facing = if sign * sense > 0.0 {
            Facing::Up
        } else {
            Facing::Down
        };
        finish(
            f,
            part.face(f).step_id,
            facing,
            polygon_of_rings(rings),
            Height::revolved([o.x, o.y], o.z, 0.0, r, sign),
        )
    };
    let mut out = half(top, 1.0);
    out.extend(half(bottom, -1.0));
    Ok(out)
}

/// A circle about `(cx, cy)` as points whose polygon keeps the circle's
/// area (chords with their midpoints pushed out by 4/3 of the sagitta,
/// as `sample.rs` does for edges: 64 chords).
fn circle_points(cx: f64, cy: f64, r: f64) -> impl Iterator<Item = (f64, f64)> {
    const CHORDS: usize = 64;
    let step = std::f64::consts::TAU / CHORDS as f64;
    (0..2 * CHORDS).map(move |k| {
        let t = 0.5 * step * k as f64;
        let rr = if k % 2 == 0 {
            r
        } else {
            // The chord's midpoint pushed out by 4/3 of the sagitta.
            let mid = r * (0.5 * step).cos();
            mid + (r - mid) * 4.0 / 3.0
        };
        (cx + rr * t.cos(), cy + rr * t.sin())
    })
}

/// A loop that is a circle of latitude about the vertical axis through
/// `o`: its height, its ring in the plane, its mean distance from the axis
/// and its turn (signed area, counter-clockwise seen from above positive).
struct Latitude {
    z: f64,
    ring: LineString<f64>,
    rho: f64,
    turn: f64,
}

/// The loop as a circle of latitude, if all its points share a height.
fn latitude(l: &[Point3], frame: &Frame, o: &Vector3, tol: f64) -> Option<Latitude> {
    use geo::Area;
    let local: Vec<Vector3> = l.iter().map(|p| frame.to_local(p)).collect();
    let n = local.len().max(1) as f64;
    let z = local.iter().map(|p| p.z).sum::<f64>() / n;
    if local.iter().any(|p| (p.z - z).abs() > tol) {
        return None;
    }
    let rho = local
        .iter()
        .map(|p| (p.x - o.x).hypot(p.y - o.y))
        .sum::<f64>()
        / n;
    let ring = ring(local.iter().map(|p| (p.x, p.y)));
    let turn = Polygon::new(ring.clone(), vec![]).signed_area();
    Some(Latitude { z, ring, rho, turn })
}

/// A torus about a vertical axis (or a sphere, `big_r` 0) whose face lies
/// within one half, above or below its equator: one graph piece over the
/// projection of its loops.
fn revolved_piece(
    part: &Part,
    f: FaceId,
    frame: &Frame,
    centre: &Point3,
    big_r: f64,
    r: f64,
    sense: f64,
) -> Result<Vec<Piece>, RemovalError> {
    let o = frame.to_local(centre);
    let loops = face_loop_points(part, f);
    let tol = 1e-6 * r.max(1.0);
    let (mut above, mut below) = (false, false);
    for p in loops.iter().flatten() {
        let dz = frame.to_local(p).z - o.z;
        above |= dz > tol;
        below |= dz < -tol;
    }
    let sign = match (above, below) {
        (true, false) => 1.0,
        (false, true) => -1.0,
        (true, true) if big_r == 0.0 => {
            return sphere_zone(part, f, frame, &o, r, sense, &loops, tol);
        }
        (true, true) => {
            return Err(unsupported(
                part,
                f,
                "a torus face across its equator (not split there yet)",
            ))
        }
        // Bounded by its equator (a hemisphere, a torus's upper or lower
        // band): the outermost loop runs with the face on its left seen
        // from the outward normal, which there is `sense` times the
        // radial direction, so the face is above the loop when the loop
        // turns counter-clockwise seen from above for sense +1.
        (false, false) => {
            let turn = loops
                .iter()
                .filter_map(|l| latitude(l, frame, &o, tol))
                .map(|c| c.turn)
                .max_by(|a, b| a.abs().total_cmp(&b.abs()))
                .unwrap_or(0.0);
            if turn == 0.0 {
                return Err(unsupported(
                    part,
                    f,
                    "a torus or sphere face without a boundary",
                ));
            }
            sense * turn.signum()
        }
    };
    if crosses_equator(&loops, frame, &o, big_r, sign, sense, tol) {
        if big_r == 0.0 {
            return sphere_zone(part, f, frame, &o, r, sense, &loops, tol);
        }
        return Err(unsupported(
            part,
            f,
            "a torus face across its equator (not split there yet)",
        ));
    }
    // The surface's normal points away from the tube's centre line: up on
    // the upper half.
    let facing = if sign * sense > 0.0 {
        Facing::Up
    } else {
        Facing::Down
    };
    let region = project(part, f, frame);
    Ok(finish(
        f,
        part.face(f).step_id,
        facing,
        region,
        Height::revolved([o.x, o.y], o.z, big_r, r, sign),
    ))
}

fn cone_piece(
    part: &Part,
    f: FaceId,
    frame: &Frame,
    surface: &Surface,
    cf: &Frame,
    sense: f64,
) -> Result<Vec<Piece>, RemovalError> {
    let Surface::Cone {
        radius, semi_angle, ..
    } = surface
    else {
        unreachable!("cone_piece is called on cones")
    };
    let o = frame.to_local(&cf.origin);
    let dir = frame.vector_to_local(&cf.z).z.signum();
    let tan = semi_angle.tan();
    if tan.abs() < 1e-12 {
        return Err(unsupported(part, f, "a cone of zero angle"));
    }
    // ρ = radius + v·tan, z = o.z + dir·v.
    let k = dir / tan;
    let z0 = o.z - k * radius;
    let region = project(part, f, frame);
    // Facing from the outward normal at a boundary point.
    let loops = face_loop_points(part, f);
    let p = loops
        .first()
        .and_then(|l| l.first())
        .ok_or_else(|| unsupported(part, f, "a cone face without a boundary"))?;
    let n = surface
        .normal_at(p)
        .ok_or_else(|| unsupported(part, f, "a cone face on its apex"))?;
    let nz = frame.vector_to_local(&n).z * sense;
    let facing = if nz > 0.0 { Facing::Up } else { Facing::Down };
    Ok(finish(
        f,
        part.face(f).step_id,
        facing,
        region,
        Height::cone([o.x, o.y], z0, k),
    ))
}

/// A vertical face seen from up: its loops' projections (curves), the
/// heights it spans.
#[derive(Clone, Debug)]
pub struct Vertical {
    pub step_id: u64,
    /// How far its edges lie off its surface, at most, mm.
    pub gap: f64,
    pub segments: Vec<[(f64, f64); 2]>,
    pub bbox: Rect<f64>,
    pub z: [f64; 2],
}

/// Every face that projects to a curve (planes along up, cylinders about
/// an axis along up).
pub fn vertical_faces(part: &Part, frame: &Frame) -> Vec<Vertical> {
    let mut out = Vec::new();
    for f in part.face_ids() {
        let face = part.face(f);
        if !is_vertical(&face.surface, frame) {
            continue;
        }
        let mut segments = Vec::new();
        let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
        let loops = face_loop_points(part, f);
        let gap = edge_gap(part, f).max(outline_gap(&face.surface, &loops));
        for lp in loops {
            let pts: Vec<_> = lp.iter().map(|p| frame.to_local(p)).collect();
            for (i, p) in pts.iter().enumerate() {
                let q = pts[(i + 1) % pts.len()];
                segments.push([(p.x, p.y), (q.x, q.y)]);
                for k in 0..3 {
                    lo[k] = lo[k].min(p[k]);
                    hi[k] = hi[k].max(p[k]);
                }
            }
        }
        if segments.is_empty() {
            continue;
        }
        out.push(Vertical {
            step_id: face.step_id,
            gap,
            segments,
            bbox: Rect::new(Coord { x: lo[0], y: lo[1] }, Coord { x: hi[0], y: hi[1] }),
            z: [lo[2], hi[2]],
        });
    }
    out
}

/// Whether a surface projects to a curve along `frame.z` (a plane along
/// up, a cylinder about an axis along up).
fn is_vertical(s: &Surface, frame: &Frame) -> bool {
    match s {
        Surface::Plane { frame: pf } => frame.vector_to_local(&pf.z).z.abs() < VERTICAL_EPS,
        Surface::Cylinder { frame: cf, .. } => {
            frame.vector_to_local(&cf.z).z.abs() > 1.0 - VERTICAL_EPS
        }
        _ => false,
    }
}

/// How far a vertical face's sampled outlines lie off its surface, at
/// their points and their chords' middles, mm. Two edges of one wall cut
/// differently (a cross hole's rim on a plane, cut round its own axis, and
/// where it meets a bore, cut round the bore's; a drill's rim and the
/// curves where cross holes break into its wall) project onto polygons
/// that part by up to this twice: thin lenses whose columns see one
/// face's edge and not the other's.
fn outline_gap(surface: &Surface, loops: &[Vec<Point3>]) -> f64 {
    let off = |p: &Point3| surface_off(surface, p);
    loops
        .iter()
        .flat_map(|lp| {
            (0..lp.len()).map(move |i| {
                let (p, q) = (lp[i], lp[(i + 1) % lp.len()]);
                off(&p).max(off(&Point3::from((p.coords + q.coords) * 0.5)))
            })
        })
        .fold(0.0, f64::max)
}

/// A point's distance off a plane or a cylinder (0 for other surfaces), mm.
fn surface_off(surface: &Surface, p: &Point3) -> f64 {
    match surface {
        Surface::Plane { frame: pf } => (p - pf.origin).dot(&pf.z).abs(),
        Surface::Cylinder { frame: cf, radius } => {
            let l = p - cf.origin;
            ((l - cf.z * l.dot(&cf.z)).norm() - radius).abs()
        }
        _ => 0.0,
    }
}

/// How far a vertical face's edges lie off its surface, at most, mm: the
/// file's own gaps (an edge approximated by a B-spline, a vertex off its
/// line), taken on the edges' curves. The wall's top and bottom outlines
/// then part by up to twice this, and a column between them crosses the
/// part's faces out of turn.
fn edge_gap(part: &Part, f: FaceId) -> f64 {
    let surface = &part.face(f).surface;
    let off = |p: &Point3| surface_off(surface, p);
    let mut gap: f64 = 0.0;
    for &l in &part.face(f).loops {
        for ce in &part.loop_(l).coedges {
            let Some(c) = &part.edge(ce.edge).nurbs else {
                continue;
            };
            for (a, b) in c.spans() {
                for k in 0..=GAP_SAMPLES_PER_SPAN {
                    let t = a + (b - a) * k as f64 / GAP_SAMPLES_PER_SPAN as f64;
                    gap = gap.max(off(&c.point(t)));
                }
            }
        }
    }
    gap
}

/// Points per knot span at which an edge's distance off its face is taken.
const GAP_SAMPLES_PER_SPAN: usize = 8;
