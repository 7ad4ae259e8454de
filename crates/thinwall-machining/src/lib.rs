//! Conventional machining features on a part (DOMAIN.md §6: Alpha_1's
//! holes, pockets, slots; Matsuda's milled regions; the MFCAD taxonomy):
//! holes (through, blind, counterbored, countersunk), pockets, slots,
//! steps, passages, chamfers, fillets and rounds.
//!
//! The part is taken as cut from its bounding block: a face lying on one of
//! the block's six planes is **stock**. The other faces are grouped into
//! features: curved faces tangent to two or more faces are blends (fillets
//! and rounds, chained along tangent edges); the rest are joined across
//! concave edges (the inside corners of a depression), the two halves
//! of a hole's cylinder across their tangent seam, and a round end with the
//! plane it runs into; pieces of one feature that a later cut split apart
//! are joined (`fragments`). Each group is typed from
//! which stock planes it opens to and its faces' directions:
//!
//! - a floor facing the only stock plane it opens to: **pocket**;
//! - opening to one stock plane without a floor, or to two opposite ones:
//!   **passage** (through);
//! - opening to two opposite planes and one more: **slot** (through);
//!   to two opposite planes and two more: **step** (through);
//! - to three planes, none opposite: blind **step**; to two: blind **slot**;
//! - one inclined face meeting three or more stock planes: **chamfer**;
//! - concave cylinders: **hole**, through when nothing closes its bottom.
//!
//! Profiles: the number of wall directions (3 triangular, 4 rectangular,
//! 6 hexagonal); a through slot of two faces is triangular (a V); a through
//! step of three faces two-sided, of two faces rectangular when its faces
//! are parallel to the block's, else slanted; a blind step of two faces
//! triangular.

mod blends;
mod boss;
mod catalog;
mod chamfer;
mod closed_slot;
mod facing;
mod fragments;
mod holes;
mod island;
mod options;
mod patterns;
mod shape;
mod solid;
pub mod stock;

pub use blends::takes_blends;
pub use holes::{Bore, HoleEnd, HoleForm, HoleTip};

/// What bounds a feature's largest tool.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ToolBound {
    /// Twice its smallest corner radius.
    CornerRadius,
    /// Its floor's (or cross-section's) widest circle, widened by a floor
    /// fillet a bull-nose's corner sits in.
    Width,
    /// A hole's narrowest bore.
    Bore,
}
pub use options::{MachiningError, Options, StockSpec};
pub use patterns::{hole_patterns, HolePattern, Layout};
pub use stock::Stock;

use geo::{Area, MultiPolygon};
use serde::{Deserialize, Serialize};
use std::collections::BTreeSet;
use thinwall_analysis::polygon::{clearance_radius, inscribed_radius, min_rect_sides};
use thinwall_analysis::{Catalog, FeatureId, MachiningId, MachiningKind, PartAnalysis, Profile};
use thinwall_brep::FaceId;
use thinwall_geom::tolerance::{FEATURE_PARALLEL_DEG, NEAR_PARALLEL_EPS, UNIT_PARALLEL_EPS};
use thinwall_geom::{Surface, Vector3};
use thinwall_graph::Convexity;

/// A machining feature on the part.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct MachiningFeature {
    /// `M1`, `M2`, … by smallest face id.
    pub id: MachiningId,
    pub kind: MachiningKind,
    /// The body its faces are on (index into the report's `bodies`).
    pub body: u32,
    /// Opens through the part (no bottom).
    pub through: bool,
    pub profile: Profile,
    /// The MFCAD++ catalogue name (one of its 24 kinds), when it is one.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub catalog: Option<Catalog>,
    /// Unit tool (access) direction, into the part.
    pub direction: [f64; 3],
    /// `step_id`s of all faces it creates, floors included.
    pub faces: Vec<u64>,
    /// Faces facing the access direction (floors).
    pub bottom_faces: Vec<u64>,
    /// The other faces (walls).
    pub side_faces: Vec<u64>,
    /// The walls of islands standing in it (a pocket with islands), among
    /// its side faces; the pocket is typed and measured without them.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub island_faces: Vec<u64>,
    /// Which block planes it opens to, as outward normals.
    pub open_to: Vec<[f64; 3]>,
    /// mm along the direction.
    pub depth: f64,
    /// Profile length and width (minimum rectangle), or hole diameter, mm.
    pub length: f64,
    pub width: f64,
    /// A hole's axis point where the tool enters (its centre on the entry
    /// face), mm.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub centre: Option<[f64; 3]>,
    /// Radii of cylindrical faces (holes, corners, blends), mm.
    pub radii: Vec<f64>,
    /// Its own blends, among its faces: a pocket's corner cylinders, floor
    /// fillets and the tori where they meet; a hole's blended ends.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub blend_faces: Vec<u64>,
    /// Its own cones, among its faces: a hole's countersinks and chamfered
    /// ends.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub chamfer_faces: Vec<u64>,
    /// The smallest radius of the concave corners round its walls along the
    /// tool axis, mm.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub corner_radius: Option<f64>,
    /// Every distinct corner radius, smallest first, mm (more than one
    /// where its corners differ).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub corner_radii: Vec<f64>,
    /// The smallest radius of the fillets round its floor, mm.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub floor_fillet: Option<f64>,
    /// The largest lean of its planar walls from the tool axis, degrees (a
    /// pocket, slot, step or passage with planar walls).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub wall_draft_deg: Option<f64>,
    /// A hole's stages from the entry down: its entry (countersink,
    /// chamfer, blend), bores widest first, exit and tip.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub hole: Option<HoleForm>,
    /// Largest tool diameter that fits the floor (or the cross-section of a
    /// passage or hole) and its corners, mm; absent when there is no floor
    /// to measure. With a floor fillet r, for an end mill whose corner
    /// radius is r (a bull-nose, its corner in the fillet: the floor's
    /// widest circle plus 2r); its corners bound it to 2R. The one answer
    /// the access layer and the operations take (issue 38).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub largest_tool_diameter: Option<f64>,
    /// What bounds `largest_tool_diameter`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tool_bound: Option<ToolBound>,
    /// Whether the set-up's tool (along up, within its tilt limit) reaches
    /// it along its direction; absent when no set-up was given, and for
    /// blends and chamfers.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub reachable: Option<bool>,
    /// The stiffness features sharing a face with it (filled by the
    /// pipeline, which runs both recognizers).
    #[serde(default)]
    pub related: Vec<FeatureId>,
}

impl MachiningFeature {
    /// The MFCAD++ catalogue name of one of its faces (by `step_id`): its
    /// own blends are `round` and its own cones `chamfer` (the catalogue
    /// makes every blend and chamfer a feature of its own), its other faces
    /// its own name.
    pub fn catalog_of_face(&self, step_id: u64) -> Option<Catalog> {
        if self.blend_faces.contains(&step_id) {
            Some(Catalog::Round)
        } else if self.chamfer_faces.contains(&step_id) {
            Some(Catalog::Chamfer)
        } else {
            self.catalog
        }
    }

    /// A feature of `kind` and `profile` on `faces`, entered along `dir`:
    /// every face a side face, no sizes yet (the builders fill them).
    pub(crate) fn on_faces(
        a: &PartAnalysis,
        kind: MachiningKind,
        profile: Profile,
        faces: &[FaceId],
        dir: &Vector3,
    ) -> Self {
        Self {
            id: MachiningId::default(),
            kind,
            body: a.part().face(faces[0]).body.0,
            through: false,
            profile,
            catalog: None,
            direction: [dir.x, dir.y, dir.z],
            faces: a.step_ids(faces),
            bottom_faces: vec![],
            side_faces: a.step_ids(faces),
            island_faces: vec![],
            open_to: vec![],
            depth: 0.0,
            length: 0.0,
            width: 0.0,
            centre: None,
            radii: vec![],
            blend_faces: vec![],
            chamfer_faces: vec![],
            corner_radius: None,
            corner_radii: vec![],
            floor_fillet: None,
            wall_draft_deg: None,
            hole: None,
            largest_tool_diameter: None,
            tool_bound: None,
            reachable: None,
            related: vec![],
        }
    }
}

/// Whether two unit normals point the same way.
fn same_direction(a: &Vector3, b: &Vector3) -> bool {
    a.dot(b) > 1.0 - UNIT_PARALLEL_EPS
}

/// A plane: unit normal and offset along it, mm.
pub(crate) type Plane = (Vector3, f64);

/// The plane of a planar face (its outward normal and offset).
pub(crate) fn face_plane(a: &PartAnalysis, f: FaceId) -> Option<Plane> {
    let n = a.props(f).normal?;
    Some((n, n.dot(&a.props(f).centroid.coords)))
}

/// Two planes facing the same way are one within this, mm: ten feature
/// tolerances.
pub(crate) fn plane_tol(a: &PartAnalysis) -> f64 {
    a.tol().feature * 10.0
}

/// Two cylinders (or a cylinder and a point) share an axis line within
/// this, mm: a hundred feature tolerances.
pub(crate) fn axis_tol(a: &PartAnalysis) -> f64 {
    a.tol().feature * 100.0
}

/// Whether two planes are one, facing the same way (within
/// [`plane_tol`]).
pub(crate) fn same_plane(a: &PartAnalysis, (n, o): &Plane, (m, p): &Plane) -> bool {
    same_direction(n, m) && (o - p).abs() < plane_tol(a)
}

/// A lone face at least this share of the block's largest extent long is a
/// side of the part, not a feature.
const PART_SIDE_SHARE: f64 = 0.5;

/// Recognize the machining features of the analysed part, cut from its
/// own block, every block direction a candidate.
pub fn recognize(a: &PartAnalysis) -> Vec<MachiningFeature> {
    recognize_with(a, &Options::default()).unwrap_or_default()
}

/// Recognize the machining features with `opts` (a set-up's tool axis, a
/// stock); an error when the stock is unusable.
pub fn recognize_with(
    a: &PartAnalysis,
    opts: &Options,
) -> Result<Vec<MachiningFeature>, MachiningError> {
    let part = a.part();
    let block = Stock::of(a, opts.up);
    let on_block: Vec<Option<usize>> = part.face_ids().map(|f| block.plane_of(a, f)).collect();
    let as_stock = stock_faces(a, &on_block, &opts.stock)?;
    let mut out = facing::facing_features(a, &block, &on_block, &as_stock, &opts.stock);
    // Faces on the block or the given stock are in no other feature.
    let left: Vec<bool> = part
        .face_ids()
        .map(|f| on_block[f.index()].is_none() && !as_stock[f.index()])
        .collect();
    out.extend(cut_features(a, &block, &on_block, &left));
    let mut out = holes::compound(a, out, opts.up);
    // A feature has a depth and a profile, or it is not a feature (a lone
    // side face seen edge-on, a whole-part face of a casting).
    let least = a.tol().coplanar;
    out.retain(|m| m.length > least && m.width > least && m.depth > least);
    if let Some(up) = opts.up {
        let reach = (opts.tilt_limit_deg + FEATURE_PARALLEL_DEG)
            .to_radians()
            .cos();
        for m in &mut out {
            m.reachable = reachability(m, &up, reach);
        }
    }
    out.sort_by_key(|m| m.faces.first().copied().unwrap_or(0));
    for (i, m) in out.iter_mut().enumerate() {
        m.id = MachiningId(i as u32 + 1);
    }
    Ok(out)
}

/// Whether a tool within the tilt limit of up reaches a feature along its
/// direction; none for blends and chamfers (a profiled cutter follows
/// them from wherever their faces are reached).
fn reachability(m: &MachiningFeature, up: &Vector3, reach: f64) -> Option<bool> {
    if matches!(m.kind, MachiningKind::Fillet | MachiningKind::Chamfer) {
        return None;
    }
    let d = Vector3::new(m.direction[0], m.direction[1], m.direction[2]);
    Some(d.dot(&-up) >= reach || (m.through && d.dot(up) >= reach))
}

/// Which faces are stock: on the block (or none with an allowance), or on
/// the given solid's surface.
fn stock_faces(
    a: &PartAnalysis,
    on_block: &[Option<usize>],
    spec: &StockSpec,
) -> Result<Vec<bool>, MachiningError> {
    match *spec {
        StockSpec::Block => Ok(on_block.iter().map(Option::is_some).collect()),
        StockSpec::Offset(mm) if !(mm.is_finite() && mm >= 0.0) => {
            Err(MachiningError::BadOffset(mm))
        }
        StockSpec::Offset(mm) => Ok(on_block.iter().map(|b| b.is_some() && mm == 0.0).collect()),
        StockSpec::Solid(stock) => solid::faces_on(a, stock),
    }
}

/// Blends, chamfers and depressions among the faces `left`.
fn cut_features(
    a: &PartAnalysis,
    block: &Stock,
    on_block: &[Option<usize>],
    left: &[bool],
) -> Vec<MachiningFeature> {
    let part = a.part();
    let is_left = |f: FaceId| left[f.index()];
    let mut out: Vec<MachiningFeature> = Vec::new();
    // Blends: chains of tangent curved faces.
    let blends: Vec<FaceId> = part
        .face_ids()
        .filter(|&f| is_left(f) && is_blend(a, f) && !chamfer::is_bevel_corner(a, f))
        .collect();
    let chains = a.components(&blends, |_, _, adj| adj.convexity == Convexity::Smooth);
    let mut taken: BTreeSet<FaceId> = blends.iter().copied().collect();
    // Chamfers: chains of bevels.
    let bevels: Vec<FaceId> = part
        .face_ids()
        .filter(|&f| is_left(f) && !taken.contains(&f) && chamfer::is_chamfer(a, f))
        .collect();
    for group in a.components(&bevels, |_, _, adj| adj.convexity == Convexity::Smooth) {
        out.push(chamfer::chamfer_feature(a, block, &group));
    }
    // Bevels in inside corners (between a floor and its wall) still join
    // the faces either side of them, as the corner would.
    let inside_bevels: BTreeSet<FaceId> = bevels
        .iter()
        .copied()
        .filter(|&f| {
            a.graph()
                .neighbours(f)
                .filter(|(_, adj)| adj.convexity == Convexity::Concave)
                .count()
                >= 2
        })
        .collect();
    taken.extend(bevels);
    // Bosses: round convex cylinders standing on a face.
    let candidates: Vec<FaceId> = part
        .face_ids()
        .filter(|f| is_left(*f) && !taken.contains(f))
        .collect();
    for group in boss::boss_groups(a, &candidates) {
        out.push(boss::boss_feature(a, &group));
        taken.extend(group);
    }
    // Prismatic bosses: rings of walls standing on a floor, outside
    // corners between them.
    let candidates: Vec<FaceId> = candidates
        .into_iter()
        .filter(|f| !taken.contains(f))
        .collect();
    // An island in a pocket stays in its pocket's group, but the pocket
    // is typed without it.
    let mut pocket_islands: BTreeSet<FaceId> = BTreeSet::new();
    for island in island::islands(a, &candidates) {
        if island.in_pocket {
            pocket_islands.extend(island.walls);
        } else {
            out.push(island::island_feature(a, &island));
            taken.extend(island.walls);
        }
    }
    // Depressions: concave-connected groups (hole halves across their
    // seam), joined also through the concave blends and bevels between
    // their faces (a filleted pocket's floor and walls are one pocket).
    let connectors: BTreeSet<FaceId> = blends
        .iter()
        .copied()
        .filter(|&f| a.is_concave_blend(f))
        .chain(inside_bevels)
        .collect();
    let rest: Vec<FaceId> = part
        .face_ids()
        .filter(|f| (is_left(*f) && !taken.contains(f)) || connectors.contains(f))
        .collect();
    let groups = depression_groups(a, &rest, &connectors);
    let (found, owned) = depressions(a, block, on_block, groups, &pocket_islands, &chains);
    out.extend(found);
    // Blend chains no depression owns are fillets and rounds of their own.
    for (i, chain) in chains.iter().enumerate() {
        if !owned[i] {
            out.push(blend_feature(a, block, chain));
        }
    }
    out
}

/// The faces `rest` in concave-connected groups, joined also through the
/// `connectors` (concave blends and inside bevels, left out of the groups),
/// coaxial concave cylinders and round ends with the walls they run into.
fn depression_groups(
    a: &PartAnalysis,
    rest: &[FaceId],
    connectors: &BTreeSet<FaceId>,
) -> Vec<Vec<FaceId>> {
    let tol = a.tol().feature;
    let joined = |f: FaceId, g: FaceId, adj: &thinwall_graph::Adjacency| {
        adj.convexity == Convexity::Concave
            || (adj.convexity == Convexity::Smooth
                && (connectors.contains(&f) || connectors.contains(&g)))
            || (adj.convexity == Convexity::Smooth
                && matches!((a.concave_cylinder(f), a.concave_cylinder(g)),
                    (Some(x), Some(y)) if x.coaxial(&y, tol * 100.0)))
            // A round end and the wall it runs into (its floor cut away).
            || (adj.convexity == Convexity::Smooth
                && (a.concave_cylinder(f).is_some() && a.planar(g).is_some()
                    || a.concave_cylinder(g).is_some() && a.planar(f).is_some()))
    };
    a.components(rest, joined)
        .into_iter()
        .map(|mut g| {
            g.retain(|f| !connectors.contains(f));
            g
        })
        .filter(|g| !g.is_empty())
        .collect()
}

/// One machining feature per group (pieces another cut split joined): a
/// lone planar face, or a depression typed without its pocket's islands,
/// with the blend chains it owns (`blends`); and which chains were owned.
fn depressions(
    a: &PartAnalysis,
    block: &Stock,
    on_block: &[Option<usize>],
    groups: Vec<Vec<FaceId>>,
    pocket_islands: &BTreeSet<FaceId>,
    chains: &[Vec<FaceId>],
) -> (Vec<MachiningFeature>, Vec<bool>) {
    let mut out = Vec::new();
    let mut owned = vec![false; chains.len()];
    for group in fragments::join_pieces(a, groups) {
        let touched: BTreeSet<usize> = group
            .iter()
            .flat_map(|&f| a.graph().neighbours(f))
            .filter_map(|(h, _)| on_block[h.index()])
            .collect();
        if one_plane(a, &group) {
            out.extend(lone_face(a, block, &group, &touched));
            continue;
        }
        let mut m = depression_feature(a, block, &group, &touched, pocket_islands);
        let mine: Vec<usize> = blends::own_chains(a, chains, &group)
            .into_iter()
            .filter(|&i| !owned[i])
            .collect();
        let blend_faces: Vec<FaceId> = mine.iter().flat_map(|&i| chains[i].clone()).collect();
        blends::attach(a, &mut m, &group, &blend_faces);
        if !m.blend_faces.is_empty() {
            for i in mine {
                owned[i] = true;
            }
        }
        out.push(m);
    }
    (out, owned)
}

/// Whether a group is planar faces on one plane (one face, or pieces of
/// one that another feature split).
fn one_plane(a: &PartAnalysis, group: &[FaceId]) -> bool {
    let plane = |f: FaceId| a.planar(f).and_then(|_| face_plane(a, f));
    let Some(first) = plane(group[0]) else {
        return false;
    };
    group
        .iter()
        .all(|&f| plane(f).is_some_and(|q| same_plane(a, &first, &q)))
}

/// A lone planar face (no walls meet it along concave edges), or the
/// pieces of one: facing a block plane below it, a face to mill down (the
/// material above it, as round a boss); else a bevel on the block's edge,
/// or, spanning half the part or more, a side of a part not cut from a
/// block (no feature), or typed as any group.
fn lone_face(
    a: &PartAnalysis,
    block: &Stock,
    faces: &[FaceId],
    touched: &BTreeSet<usize>,
) -> Option<MachiningFeature> {
    let f = faces[0];
    let n = a.props(f).normal?;
    let offset = n.dot(&a.props(f).centroid.coords);
    let facing = (0..6).find(|&sp| same_direction(&block.normal(sp), &n));
    if let Some(sp) = facing {
        let depth = block.plane_offset(sp) - offset;
        if depth > a.tol().coplanar {
            return Some(facing::face_feature(a, faces, &n, depth));
        }
    }
    let feature = depression_feature(a, block, faces, touched, &BTreeSet::new());
    let side = feature.kind != MachiningKind::Chamfer
        && feature.length >= PART_SIDE_SHARE * block.largest_extent();
    (!side).then_some(feature)
}

/// A curved face tangent to two or more faces, but not a hole's cylinder
/// whose tangent neighbours are all hole cylinders (its other half).
pub(crate) fn is_blend(a: &PartAnalysis, f: FaceId) -> bool {
    if a.cylinder_sweep_deg(f)
        .is_some_and(|s| s >= shape::HALF_SWEEP_DEG && a.concave_cylinder(f).is_some())
    {
        return false;
    }
    if a.concave_cylinder(f).is_some()
        && a.graph()
            .neighbours(f)
            .all(|(g, adj)| adj.convexity != Convexity::Smooth || a.concave_cylinder(g).is_some())
    {
        return false;
    }
    let curved = !matches!(a.part().face(f).surface, Surface::Plane { .. });
    curved && a.smooth_degree(f) >= 2
}

/// Radii closer than this are one radius, mm.
pub(crate) const SAME_RADIUS_MM: f64 = 1e-9;

pub(crate) fn radii(a: &PartAnalysis, fs: &[FaceId]) -> Vec<f64> {
    let mut r: Vec<f64> = fs.iter().filter_map(|&f| a.blend_radius(f)).collect();
    r.sort_by(f64::total_cmp);
    r.dedup_by(|a, b| (*a - *b).abs() < SAME_RADIUS_MM);
    r
}

/// A blend chain: its radius (smallest) as depth, its length and width as
/// sizes.
fn blend_feature(a: &PartAnalysis, stock: &Stock, group: &[FaceId]) -> MachiningFeature {
    let convex = a.part().face(group[0]).same_sense;
    let dir = a.props(group[0]).axis.map_or(Vector3::z(), |ax| ax.1);
    let radii_v = radii(a, group);
    let along = |d: &Vector3| {
        let (lo, hi) = a.extent(group, d);
        if hi.is_finite() {
            hi - lo
        } else {
            0.0
        }
    };
    // Its length: the longest extent of the chain (along the stock's axes
    // and its own axis); its width: the developed arc, area over length,
    // never more than the length.
    let [x, y, z] = stock.axes;
    let length = [x, y, z, dir].iter().map(along).fold(0.0, f64::max);
    let area: f64 = group.iter().map(|&f| a.props(f).area).sum();
    let arc = if length > 0.0 { area / length } else { 0.0 };
    let profile = if convex {
        Profile::Round
    } else {
        Profile::Fillet
    };
    MachiningFeature {
        catalog: Some(Catalog::Round),
        depth: radii_v.first().copied().unwrap_or(0.0),
        length,
        width: arc.min(length),
        radii: radii_v,
        ..MachiningFeature::on_faces(a, MachiningKind::Fillet, profile, group, &dir)
    }
}

/// The largest tool that fits: a hole's diameter, or twice the inscribed
/// radius of the floor.
fn largest_tool(
    a: &PartAnalysis,
    kind: MachiningKind,
    radii: &[f64],
    bottom: &[FaceId],
) -> Option<f64> {
    if kind == MachiningKind::Hole {
        return radii.first().map(|r| 2.0 * r);
    }
    if bottom.is_empty() {
        return None;
    }
    let floors: MultiPolygon<f64> = MultiPolygon::new(
        bottom
            .iter()
            .filter_map(|&f| a.polygon(f))
            .flat_map(|p| p.0)
            .collect(),
    );
    if floors.unsigned_area() <= 0.0 {
        return None;
    }
    // Each floor in its own frame: the largest disk centred on it that
    // crosses none of its walls (the tool may overhang its open edges,
    // where it drops away, as a cut-out through a flange); the tool that
    // reaches every floor is no wider than the least of them.
    let radius = bottom
        .iter()
        .filter_map(|&f| {
            let floor = a.polygon(f)?;
            let walls = floor_walls(a, f);
            let clear = clearance_radius(&floor, &walls);
            Some(if clear.is_finite() {
                clear
            } else {
                inscribed_radius(&floor)
            })
        })
        .fold(f64::INFINITY, f64::min);
    radius.is_finite().then_some(2.0 * radius)
}

/// The walls of floor `f`: every edge but a convex one (a face rises
/// there, or a fillet blends into one; only where the floor drops away is
/// it open), as polylines in its frame (the frame of
/// `PartAnalysis::polygon`).
fn floor_walls(a: &PartAnalysis, f: FaceId) -> Vec<geo::LineString<f64>> {
    let g = a.graph();
    let mut out = Vec::new();
    if let Some(p) = a.planar(f) {
        for (_, adj) in g.neighbours(f) {
            for &k in &adj.edges {
                let e = &g.edges[k];
                if e.convexity == Convexity::Convex {
                    continue;
                }
                let pts = thinwall_analysis::polygon::edge_points(a.part(), e.edge);
                out.push(geo::LineString::from(
                    pts.iter()
                        .map(|q| {
                            let l = p.frame.to_local(q);
                            (l.x, l.y)
                        })
                        .collect::<Vec<_>>(),
                ));
            }
        }
    }
    out
}

fn depression_feature(
    a: &PartAnalysis,
    stock: &Stock,
    whole: &[FaceId],
    touched: &BTreeSet<usize>,
    islands: &BTreeSet<FaceId>,
) -> MachiningFeature {
    // Typed and measured without the islands standing in it (their floor
    // is in the group, so something is left).
    let (island_walls, group): (Vec<FaceId>, Vec<FaceId>) =
        whole.iter().partition(|f| islands.contains(f));
    let group = if group.is_empty() { whole } else { &group };
    let shape = shape::GroupShape::new(a, stock, group, touched);
    let shape::Typed {
        kind,
        through,
        profile,
        catalog,
    } = shape.typing(a);
    let dir = shape.direction(a);
    let (bottom, sides): (Vec<FaceId>, Vec<FaceId>) = group.iter().partition(|&&f| {
        a.props(f)
            .normal
            .is_some_and(|n| n.dot(&-dir) > 1.0 - NEAR_PARALLEL_EPS)
    });
    let (lo, hi) = a.extent(group, &dir);
    let radii_v = radii(a, group);
    // A hole's profile is its widest concave cylinder: its true diameter,
    // not the extent of boundary samples.
    let hole_diameter = shape
        .cylinders
        .iter()
        .map(|c| 2.0 * c.radius)
        .fold(0.0, f64::max);
    let (length, width) = if kind == MachiningKind::Hole && hole_diameter > 0.0 {
        (hole_diameter, hole_diameter)
    } else if kind == MachiningKind::Chamfer {
        // A chamfer is one inclined face: its own long and short sides.
        a.polygon(group[0])
            .and_then(|p| min_rect_sides(&p))
            .unwrap_or_else(|| a.sizes_across(group, &dir))
    } else {
        a.sizes_across(group, &dir)
    };
    let largest = largest_tool(a, kind, &radii_v, &bottom);
    MachiningFeature {
        through,
        catalog,
        bottom_faces: a.step_ids(&bottom),
        side_faces: a.step_ids(&[&sides[..], &island_walls].concat()),
        island_faces: a.step_ids(&island_walls),
        open_to: touched
            .iter()
            .map(|&sp| {
                let n = stock.normal(sp);
                [n.x, n.y, n.z]
            })
            .collect(),
        depth: if hi.is_finite() { hi - lo } else { 0.0 },
        length,
        width,
        centre: (kind == MachiningKind::Hole)
            .then(|| shape.cylinders.first())
            .flatten()
            .map(|c| {
                let p = c.origin + dir * (lo - c.origin.coords.dot(&dir));
                [p.x, p.y, p.z]
            }),
        largest_tool_diameter: largest,
        tool_bound: largest.map(|_| {
            if kind == MachiningKind::Hole {
                ToolBound::Bore
            } else {
                ToolBound::Width
            }
        }),
        radii: radii_v,
        ..MachiningFeature::on_faces(a, kind, profile, whole, &dir)
    }
}
