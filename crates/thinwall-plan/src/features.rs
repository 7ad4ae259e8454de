//! The whole removal plan (issue 14): every bit of stock − part belongs to
//! one machining feature. The step-approach layers of the thin walls
//! (`steps`) claim what lies in their boxes, in plan order (an earlier
//! feature keeps an overlap: the owners' sequence priority, §5.4); what
//! is left is bulk, owned by the wall it lies on; what the set-up cannot
//! reach (nothing of it open to up) is a feature for another set-up.
//!
//! The blocks of the decomposition (`removal`) are cut at the layers'
//! heights, so a layer is exactly the removal inside its box: the part is
//! never in a feature, features never overlap, and they add up to stock −
//! part. A cut that would pass through a curved bound (a foot fillet)
//! moves to that bound's end, so a curved piece stays whole (in the layer
//! below).

pub use crate::types::{FeatureClass, FeatureSolid, Piece, RemovalFeature};

use crate::types::{Layer, SizeClass, VolumeId};
use std::collections::{BTreeMap, HashMap};
use thinwall_analysis::FeatureId;
use thinwall_pipeline::Outcome;
use thinwall_removal::{Bound, Removal};

use thinwall_geom::tolerance::{MERGE, SLIVER};

impl FeatureClass {
    pub fn name(self) -> &'static str {
        match self {
            FeatureClass::Large => "large",
            FeatureClass::Small => "small",
            FeatureClass::Bulk => "bulk",
            FeatureClass::OtherSetup => "other_setup",
            FeatureClass::Detail => "detail",
        }
    }
}

/// Assign every removal block to a feature. `layers` in plan order and
/// `layer_band[i]`, the index of layer i's band in the decomposition (none
/// for a layer that is not a prism along up).
#[allow(clippy::too_many_arguments)]
pub fn assign(
    out: &Outcome,
    r: &Removal,
    layers: &[Layer],
    layer_band: &[Option<usize>],
    band_area: &[f64],
    splits: &[crate::types::HoleSplit],
    tol: f64,
) -> (Vec<RemovalFeature>, f64) {
    let details = detail_faces(out, r);
    let halves: HashMap<u64, (FeatureId, f64)> = splits
        .iter()
        .flat_map(|s| s.faces.iter().map(move |&f| (f, (s.hole, s.z))))
        .collect();
    let (by_layer, rest, dropped) = distribute(r, layers, layer_band, &details, &halves, tol);
    let mut feats: Vec<RemovalFeature> = layers
        .iter()
        .zip(by_layer)
        .enumerate()
        .map(|(li, (l, pieces))| layer_feature(l, pieces, band_area[li]))
        .collect();
    let owners = face_owners(out);
    // Bulk from the top down, then the other set-up's. Tops compared in
    // tenths of a micrometre: equal heights stay in key order whatever the
    // rounding of a pose.
    let mut groups: Vec<(BulkKey, Vec<Piece>)> = rest.into_iter().collect();
    let top = |p: &Vec<Piece>| {
        let z = p.iter().map(|q| q.z[1]).fold(f64::NEG_INFINITY, f64::max);
        (z * 1e4).round() as i64
    };
    groups.sort_by(|a, b| b.0 .0.cmp(&a.0 .0).then_with(|| top(&b.1).cmp(&top(&a.1))));
    for ((reachable, claim, [lo, hi], _), pieces) in groups {
        let owner = claim.map(Claim::owner).or_else(|| {
            [lo, hi].iter().find_map(|k| match k {
                Key::Part(step) => owners.get(step).copied(),
                _ => None,
            })
        });
        let mut f = rest_feature(r, reachable, owner, pieces);
        if matches!(claim, Some(Claim::Detail(_))) && reachable {
            f.size_class = FeatureClass::Detail;
        }
        feats.push(f);
    }
    absorb_crumbs(&mut feats, MERGE * r.stock_volume);
    feats.retain(|f| !f.pieces.is_empty() || f.step.is_some());
    renumber(&mut feats);
    for f in &mut feats {
        f.faces = crate::touch::faces_touched(r, &f.pieces, tol);
        f.solids = solids(r, &f.pieces);
    }
    (feats, dropped)
}

/// Every block cut at the heights of the layers over it, each piece given
/// to the first of those layers (plan order) that holds it, the rest
/// grouped for bulk and other set-up features; with the total of the
/// slivers left out (pieces under [`SLIVER`] of the stock).
#[allow(clippy::type_complexity)]
fn distribute(
    r: &Removal,
    layers: &[Layer],
    layer_band: &[Option<usize>],
    details: &HashMap<u64, (FeatureId, f64)>,
    halves: &HashMap<u64, (FeatureId, f64)>,
    tol: f64,
) -> (Vec<Vec<Piece>>, BTreeMap<BulkKey, Vec<Piece>>, f64) {
    let negligible = SLIVER * r.stock_volume;
    let mut dropped = 0.0;
    let mut by_layer: Vec<Vec<Piece>> = vec![Vec::new(); layers.len()];
    // Layers per band, in plan order.
    let mut by_band: Vec<Vec<usize>> = Vec::new();
    for (i, b) in layer_band.iter().enumerate() {
        if let Some(k) = *b {
            if by_band.len() <= k {
                by_band.resize(k + 1, Vec::new());
            }
            by_band[k].push(i);
        }
    }
    let mut rest: BTreeMap<BulkKey, Vec<Piece>> = BTreeMap::new();
    // A block an earlier set-up took is no feature of this one.
    for b in r.blocks.iter().filter(|b| !b.cleared) {
        let mut covering: Vec<usize> = r.cell_bands[b.cell]
            .iter()
            .flat_map(|&k| by_band.get(k).into_iter().flatten().copied())
            .collect();
        covering.sort_unstable();
        // Over a chamfer: its material, up to its top, is its own.
        let detail = match b.lower {
            Bound::Part(i) => details.get(&r.part_step_id(i)).copied(),
            _ => None,
        };
        // In a large hole its wall's step separation line crosses: the
        // halves above and below it are features of their own.
        let half = [b.lower, b.upper].iter().find_map(|bound| match *bound {
            Bound::Part(i) => halves.get(&r.part_step_id(i)).copied(),
            _ => None,
        });
        let cuts = covering
            .iter()
            .map(|&i| layers[i].cut_heights)
            .chain(detail.map(|(_, top)| [top, top]))
            .chain(half.map(|(_, z)| [z, z]));
        for piece in split(r, b, cuts, tol) {
            if piece.volume.abs() <= negligible {
                dropped += piece.volume;
                continue;
            }
            let mid = 0.5 * (piece.z[0] + piece.z[1]);
            if let Some((id, _)) = detail.filter(|&(_, top)| mid < top) {
                rest.entry(claimed(b.reachable, Claim::Detail(id)))
                    .or_default()
                    .push(piece);
                continue;
            }
            let owner = covering.iter().copied().find(|&i| {
                let z = layers[i].cut_heights;
                b.reachable && mid >= z[0] - tol && mid <= z[1] + tol
            });
            match owner {
                Some(i) => by_layer[i].push(piece),
                None => {
                    let k = match half {
                        Some((hole, z)) => claimed(
                            b.reachable,
                            match mid > z {
                                true => Claim::HoleAbove(hole),
                                false => Claim::HoleBelow(hole),
                            },
                        ),
                        None => (
                            b.reachable,
                            None,
                            [key(r, &b.lower), key(r, &b.upper)],
                            [key(r, &piece.lower), key(r, &piece.upper)],
                        ),
                    };
                    rest.entry(k).or_default().push(piece)
                }
            }
        }
    }
    (by_layer, rest, dropped)
}

/// A layer as a feature: its pieces, and what interference did to its box
/// (`band_area` × its cut heights).
fn layer_feature(l: &Layer, pieces: Vec<Piece>, band_area: f64) -> RemovalFeature {
    let volume: f64 = pieces.iter().map(|p| p.volume).sum();
    let box_volume = band_area * (l.cut_heights[1] - l.cut_heights[0]);
    let mut changes = Vec::new();
    if pieces.is_empty() {
        changes.push(
            "vanished: nothing to remove in its box (outside the stock, or the part and earlier features fill it)"
                .to_string(),
        );
    } else if (box_volume - volume).abs() > 1e-6 * box_volume {
        changes.push(format!(
            "{:.1} mm³ of its {:.1} mm³ box is part material or an earlier feature's",
            box_volume - volume,
            box_volume
        ));
    }
    RemovalFeature {
        id: l.id.clone(),
        owner: Some(l.owner),
        side: Some(l.side),
        step: Some(l.step),
        size_class: match l.size_class {
            SizeClass::Large => FeatureClass::Large,
            SizeClass::Small => FeatureClass::Small,
        },
        z_range: z_range(&pieces, l.cut_heights),
        volume_mm3: volume,
        box_volume_mm3: Some(box_volume),
        faces: Vec::new(),
        reachable: true,
        access: None,
        changes,
        pieces,
        solids: Vec::new(),
        classification: None,
    }
}

/// A bulk or other-set-up feature (numbered later, by `renumber`).
fn rest_feature(
    r: &Removal,
    reachable: bool,
    owner: Option<FeatureId>,
    pieces: Vec<Piece>,
) -> RemovalFeature {
    let access = (!reachable).then(|| access_of(r, &pieces)).flatten();
    RemovalFeature {
        id: VolumeId::default(),
        owner,
        side: None,
        step: None,
        size_class: if reachable {
            FeatureClass::Bulk
        } else {
            FeatureClass::OtherSetup
        },
        z_range: z_range(&pieces, [0.0, 0.0]),
        volume_mm3: pieces.iter().map(|p| p.volume).sum(),
        box_volume_mm3: None,
        faces: Vec::new(),
        reachable,
        access,
        changes: Vec::new(),
        pieces,
        solids: Vec::new(),
        classification: None,
    }
}

/// Bulk pieces group by reachability, the feature that claims them, the
/// block's bounds (what they lie on and under) and their own ends.
type BulkKey = (bool, Option<Claim>, [Key; 2], [Key; 2]);

/// Material a feature of its own claims: a chamfer's, up to its top; a
/// large hole's, above or below its wall's step separation line.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Claim {
    Detail(FeatureId),
    HoleAbove(FeatureId),
    HoleBelow(FeatureId),
}

/// A claimed feature's key: all its pieces in one feature, whatever they
/// lie on.
fn claimed(reachable: bool, c: Claim) -> BulkKey {
    let any = [Key::Flat(0); 2];
    (reachable, Some(c), any, any)
}

impl Claim {
    fn owner(self) -> FeatureId {
        match self {
            Claim::Detail(id) | Claim::HoleAbove(id) | Claim::HoleBelow(id) => id,
        }
    }
}

/// The chamfers' faces (step id) with their chamfer and its top (the
/// highest point of its faces along up, in the removal frame), mm.
fn detail_faces(out: &Outcome, r: &Removal) -> HashMap<u64, (FeatureId, f64)> {
    let chamfers: Vec<_> = out
        .recognition
        .features
        .iter()
        .filter(|f| f.kind == thinwall_analysis::StiffnessKind::Chamfer)
        .collect();
    let mut m = HashMap::new();
    for c in chamfers {
        let top = r
            .part_pieces
            .iter()
            .filter(|p| c.faces.contains(&p.step_id))
            .map(|p| p.z_range[1])
            .fold(f64::NEG_INFINITY, f64::max);
        if top.is_finite() {
            for &s in &c.faces {
                m.insert(s, (c.id, top));
            }
        }
    }
    m
}

/// A bound as a grouping key: a part face, a stock face, or a height in
/// nanometres.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Key {
    Part(u64),
    Stock(u64),
    Flat(i64),
}

fn key(r: &Removal, b: &Bound) -> Key {
    match *b {
        Bound::Part(i) => Key::Part(r.part_step_id(i)),
        Bound::Stock(i) => Key::Stock(r.stock_pieces[i].face.index() as u64),
        Bound::Flat(z) => Key::Flat((z * 1e6).round() as i64),
    }
}

fn z_range(pieces: &[Piece], empty: [f64; 2]) -> [f64; 2] {
    if pieces.is_empty() {
        return empty;
    }
    pieces
        .iter()
        .fold([f64::INFINITY, f64::NEG_INFINITY], |z, p| {
            [z[0].min(p.z[0]), z[1].max(p.z[1])]
        })
}

/// Stiffness feature per face: walls first (their sides, tops and ends),
/// then the rest.
fn face_owners(out: &Outcome) -> HashMap<u64, FeatureId> {
    let mut m = HashMap::new();
    for pass in [true, false] {
        for f in out
            .recognition
            .features
            .iter()
            .filter(|f| f.kind.is_wall() == pass)
        {
            let tops = f.top_end_faces.iter().flatten();
            for s in f.faces.iter().chain(tops) {
                m.entry(*s).or_insert(f.id);
            }
        }
    }
    m
}

/// A block cut at the given heights (`removal::slab`), as pieces with
/// their lowest and highest points.
fn split(
    r: &Removal,
    b: &thinwall_removal::Block,
    ranges: impl Iterator<Item = [f64; 2]>,
    tol: f64,
) -> Vec<Piece> {
    let mut cuts: Vec<f64> = ranges.flat_map(|z| z.into_iter()).collect();
    cuts.sort_by(f64::total_cmp);
    cuts.dedup_by(|a, b| (*a - *b).abs() <= tol);
    thinwall_removal::slab::cut(r, b, &cuts, tol)
        .into_iter()
        .map(|s| {
            let z = [
                r.height_range(&s.lower, &s.region)[0],
                r.height_range(&s.upper, &s.region)[1],
            ];
            Piece {
                cell: b.cell,
                region: s.region,
                lower: s.lower,
                upper: s.upper,
                z,
                volume: s.volume,
                block: [b.lower, b.upper],
            }
        })
        .collect()
}

/// The way into a region the set-up does not reach: along the axis of a
/// cylinder bounding it (a hole through an upright wall), or from below
/// when it opens on the stock's bottom.
fn access_of(r: &Removal, pieces: &[Piece]) -> Option<[f64; 3]> {
    for p in pieces {
        for b in [p.lower, p.upper] {
            if let Some(d) = r.cylinder_axis(&b) {
                return Some([d.x, d.y, d.z]);
            }
        }
    }
    let bottom = r.stock_bottom();
    if pieces.iter().all(|p| p.lower == Bound::Flat(bottom)) {
        let d = -r.frame.z;
        return Some([d.x, d.y, d.z]);
    }
    None
}

/// A feature's pieces merged into solids: pieces between the same two
/// bounds are one region (their cells' union), one solid per polygon.
fn solids(r: &Removal, pieces: &[Piece]) -> Vec<FeatureSolid> {
    use geo::Orient;
    // Grouped by their bounds as keys: cut heights equal up to rounding
    // (a pose) are one height.
    let mut groups: Vec<([Key; 2], [Bound; 2], Vec<usize>)> = Vec::new();
    for (i, p) in pieces.iter().enumerate() {
        let k = [key(r, &p.lower), key(r, &p.upper)];
        match groups.iter_mut().find(|g| g.0 == k) {
            Some(g) => g.2.push(i),
            None => groups.push((k, [p.lower, p.upper], vec![i])),
        }
    }
    let mut out = Vec::new();
    for (_, [lo, hi], members) in groups {
        // Cells meet along edges computed twice by separate booleans: they
        // are joined by their shared edges, the same way in every pose.
        let cells: Vec<geo::Polygon<f64>> = members
            .iter()
            .flat_map(|&i| pieces[i].region.0.iter().cloned())
            .collect();
        let region = thinwall_removal::outline::union(
            &cells,
            thinwall_geom::tolerance::SLIVER_WIDTH * r.size,
        );
        let (lower, upper) = (r.height_of(&lo), r.height_of(&hi));
        let sliver = SLIVER * r.stock_volume.cbrt().powi(2);
        for poly in region {
            // Unions of cells cut by separate booleans leave slivers and
            // hairline holes where shared edges differ by rounding.
            if thinwall_removal::flux::area(&poly) <= sliver {
                continue;
            }
            let (ext, holes) = poly.into_inner();
            let holes = holes
                .into_iter()
                .filter(|h| {
                    thinwall_removal::flux::area(&geo::Polygon::new(h.clone(), vec![])) > sliver
                })
                .collect();
            let poly = geo::Polygon::new(ext, holes).orient(geo::orient::Direction::Default);
            let volume_mm3 = thinwall_removal::flux::flux(&upper, &poly)
                - thinwall_removal::flux::flux(&lower, &poly);
            let ring = |ls: &geo::LineString<f64>| {
                let mut v: Vec<[f64; 2]> = ls.0.iter().map(|c| [c.x, c.y]).collect();
                v.pop();
                v
            };
            let mut rings = vec![ring(poly.exterior())];
            rings.extend(poly.interiors().iter().map(ring));
            out.push(FeatureSolid {
                rings,
                lower: lower.clone(),
                upper: upper.clone(),
                volume_mm3,
            });
        }
    }
    out
}

/// Tiny bulk features join a neighbour in their column (the feature whose
/// piece ends where theirs begins, or begins where theirs ends).
fn absorb_crumbs(feats: &mut [RemovalFeature], limit: f64) {
    use std::collections::HashMap;
    let key = |cell: usize, b: &Bound| (cell, b.id());
    // Where the pieces of the features large enough to host end and begin.
    let mut ends: HashMap<(usize, thinwall_removal::BoundId), usize> = HashMap::new();
    for (j, f) in feats.iter().enumerate() {
        if f.volume_mm3 < limit && f.step.is_none() {
            continue;
        }
        for q in &f.pieces {
            ends.entry(key(q.cell, &q.upper)).or_insert(j);
            ends.entry(key(q.cell, &q.lower)).or_insert(j);
        }
    }
    for i in 0..feats.len() {
        let f = &feats[i];
        if f.step.is_some() || f.volume_mm3 >= limit || f.pieces.is_empty() {
            continue;
        }
        let mut keep = Vec::new();
        for p in std::mem::take(&mut feats[i].pieces) {
            let host = [key(p.cell, &p.lower), key(p.cell, &p.upper)]
                .iter()
                .filter_map(|k| ends.get(k).copied())
                .find(|&j| j != i && feats[j].reachable == feats[i].reachable);
            match host {
                Some(j) => {
                    feats[j].volume_mm3 += p.volume;
                    feats[j].z_range = [
                        feats[j].z_range[0].min(p.z[0]),
                        feats[j].z_range[1].max(p.z[1]),
                    ];
                    feats[j].pieces.push(p);
                }
                None => keep.push(p),
            }
        }
        feats[i].volume_mm3 = keep.iter().map(|p| p.volume).sum();
        feats[i].pieces = keep;
    }
}

/// Bulk and other-set-up ids numbered again in order after merging.
fn renumber(feats: &mut [RemovalFeature]) {
    let (mut nb, mut nx, mut nd) = (0, 0, 0);
    for f in feats.iter_mut() {
        match f.size_class {
            FeatureClass::Bulk => {
                nb += 1;
                f.id = VolumeId::new('B', nb);
            }
            FeatureClass::OtherSetup => {
                nx += 1;
                f.id = VolumeId::new('X', nx);
            }
            FeatureClass::Detail => {
                nd += 1;
                f.id = VolumeId::new('D', nd);
            }
            _ => {}
        }
    }
}
