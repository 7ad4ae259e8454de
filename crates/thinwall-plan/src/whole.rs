//! The whole removal plan: the stock of the set-up, the decomposition of
//! stock − part with the layers' bands, and the features over it.

use crate::features::assign;
use crate::types::Layer;
use crate::types::RemovalFeature;
use crate::types::RemovalSummary;
use geo::{Coord, LineString, MultiPolygon, Orient, Polygon};
use std::collections::BTreeMap;
use thinwall_analysis::{FeatureId, PartAnalysis};
use thinwall_geom::{Frame, Point3, Vector3};
use thinwall_pipeline::Outcome;
use thinwall_removal::{frame_of, Removal, StockShape};

/// The removal plan of `part` with its designed `layers` (plan order).
/// Heights closer than the part's feature tolerance are the same. After
/// the `earlier` set-ups' removals (none: the first set-up), the blocks
/// they took are `cleared` and left out of the features. `this`, the
/// set-up's removal without bands (the proposal's), when in the same
/// frame and stock, is cut by the bands rather than the part
/// decomposed again ([`Removal::with_bands`]: the same result).
pub fn removal_plan(
    a: &PartAnalysis,
    out: &Outcome,
    layers: &[Layer],
    splits: &[crate::types::HoleSplit],
    (this, earlier): (Option<&Removal>, &[Removal]),
) -> (RemovalSummary, Vec<RemovalFeature>, [[f64; 3]; 4]) {
    let part = a.part();
    let up = out.setup.up_in_part();
    let (frame, lo, hi) = frame_of(a, up);
    let size = a.bounding_box().diagonal();
    let tol = a.tol().feature;
    let (stock, name) = StockShape::of(out.request.machining.stock_spec(), lo, hi);
    let frame_out = [
        [frame.origin.x, frame.origin.y, frame.origin.z],
        [frame.x.x, frame.x.y, frame.x.z],
        [frame.y.x, frame.y.y, frame.y.z],
        [frame.z.x, frame.z.y, frame.z.z],
    ];
    let mut notes = Vec::new();
    let (bands, layer_band) = bands(layers, &frame, &mut notes);
    let mut summary = RemovalSummary {
        stock: name,
        notes,
        ..Default::default()
    };
    let reused = this
        .filter(|t| same_bits(&t.frame, &frame) && t.size.to_bits() == size.to_bits())
        .and_then(|t| t.with_bands(part, &stock, &bands, a.work()));
    let made = reused.unwrap_or_else(|| Removal::new(part, frame, &stock, &bands, size, a.work()));
    let mut r = match made.and_then(Removal::checked) {
        Ok(r) => r,
        Err(e) => {
            summary.unavailable = Some(e);
            return (summary, Vec::new(), frame_out);
        }
    };
    // After other set-ups: what they took is no feature of this one.
    if !earlier.is_empty() {
        summary.recut_mm3 = thinwall_setups::turn::clear_taken(&mut r, earlier);
        summary.cleared_before_mm3 = r.cleared_volume();
    }
    let band_area: Vec<f64> = layer_band
        .iter()
        .map(|b| {
            b.map_or(0.0, |k| {
                bands[k].0.iter().map(thinwall_removal::flux::area).sum()
            })
        })
        .collect();
    let (mut feats, slivers) = assign(out, &r, layers, &layer_band, &band_area, splits, tol);
    for f in feats.iter().filter(|f| f.pieces.is_empty()) {
        summary
            .notes
            .push(format!("{}: {}", f.id, f.changes.join("; ")));
    }
    feats.retain(|f| !f.pieces.is_empty());
    summary.slivers_mm3 = slivers + r.sliver_volume;
    summary.stock_volume_mm3 = r.stock_volume;
    summary.part_volume_mm3 = r.part_volume;
    summary.removed_volume_mm3 = feats.iter().map(|f| f.volume_mm3).sum();
    summary.cells = r.cells.len();
    summary.meshed = r.meshed.clone();
    (summary, feats, frame_out)
}

/// One band per wall side with layers (the layers' footprint on the
/// set-up plane), and each layer's band. A layer whose wall does not stand
/// along up is not a prism along up: it gets none, with a note.
fn bands(
    layers: &[Layer],
    frame: &Frame,
    notes: &mut Vec<String>,
) -> (Vec<MultiPolygon<f64>>, Vec<Option<usize>>) {
    let mut by_side: BTreeMap<(FeatureId, u8), usize> = BTreeMap::new();
    let mut out = Vec::new();
    let mut which = Vec::with_capacity(layers.len());
    for l in layers {
        let c: Vec<Vector3> = l
            .corners
            .iter()
            .map(|p| frame.to_local(&Point3::new(p[0], p[1], p[2])))
            .collect();
        // Corners: height-major (0..4 at the foot side, 4..8 above), then
        // along the length (pairs), then across (0 the wall's side, 1 out).
        let upright = |d: Vector3| d.x.abs() + d.y.abs() <= 1e-9 * d.norm().max(1.0);
        let vertical = (0..4).all(|i| upright(c[i + 4] - c[i]));
        // A web's layer: a slab over its strip, a band of its own.
        let flat = (0..8).step_by(2).all(|i| upright(c[i + 1] - c[i]));
        if flat {
            out.push(footprint(&c, [0, 2, 6, 4]));
            which.push(Some(out.len() - 1));
            continue;
        }
        if !vertical {
            notes.push(format!(
                "{} ({} side {}): its wall does not stand along up; its material is in bulk features",
                l.id, l.owner, l.side
            ));
            which.push(None);
            continue;
        }
        let k = *by_side.entry((l.owner, l.side)).or_insert_with(|| {
            out.push(footprint(&c, [0, 1, 3, 2]));
            out.len() - 1
        });
        which.push(Some(k));
    }
    (out, which)
}

/// Four of a box's corners (in the removal frame) as a polygon on the
/// set-up plane.
fn footprint(c: &[Vector3], ring: [usize; 4]) -> MultiPolygon<f64> {
    let mut pts: Vec<Coord<f64>> = ring
        .iter()
        .map(|&i| Coord {
            x: c[i].x,
            y: c[i].y,
        })
        .collect();
    pts.push(pts[0]);
    let poly = Polygon::new(LineString::new(pts), vec![]).orient(geo::orient::Direction::Default);
    MultiPolygon::new(vec![poly])
}

/// Two frames the same bit for bit (a zero's sign too: a removal made in
/// one is then the other's, down to `-0.0` in its output).
fn same_bits(a: &Frame, b: &Frame) -> bool {
    let bits =
        |f: &Frame| [f.origin.coords, f.x, f.y, f.z].map(|v| [v.x, v.y, v.z].map(f64::to_bits));
    bits(a) == bits(b)
}
