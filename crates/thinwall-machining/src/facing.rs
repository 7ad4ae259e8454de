//! Facing features: the part's faces on its block that are not stock (an
//! allowance on the block, or a blank larger than the part) are faced,
//! one feature per block plane.

use crate::{MachiningFeature, Stock, StockSpec};
use thinwall_analysis::{MachiningKind, PartAnalysis, Profile};
use thinwall_brep::FaceId;
use thinwall_geom::Vector3;

/// One facing feature per block plane holding faces that are not stock;
/// its depth is the allowance (the offset; for a given solid, how far the
/// solid stands off that plane).
pub(crate) fn facing_features(
    a: &PartAnalysis,
    block: &Stock,
    on_block: &[Option<usize>],
    as_stock: &[bool],
    spec: &StockSpec,
) -> Vec<MachiningFeature> {
    let mut out = Vec::new();
    for sp in 0..6 {
        let faces: Vec<FaceId> = a
            .part()
            .face_ids()
            .filter(|f| on_block[f.index()] == Some(sp) && !as_stock[f.index()])
            .collect();
        if faces.is_empty() {
            continue;
        }
        let n = block.normal(sp);
        let depth = match spec {
            StockSpec::Offset(mm) => *mm,
            StockSpec::Solid(stock) => crate::solid::standoff(stock, block, sp),
            StockSpec::Block => 0.0,
        };
        out.push(face_feature(a, &faces, &n, depth));
    }
    out
}

/// Facing `faces` (outward normal `n`) down by `depth` mm.
pub(crate) fn face_feature(
    a: &PartAnalysis,
    faces: &[FaceId],
    n: &Vector3,
    depth: f64,
) -> MachiningFeature {
    let (length, width) = a.sizes_across(faces, n);
    MachiningFeature {
        bottom_faces: a.step_ids(faces),
        side_faces: vec![],
        open_to: vec![[n.x, n.y, n.z]],
        depth,
        length: length.max(width),
        width: width.min(length),
        ..MachiningFeature::on_faces(a, MachiningKind::Face, Profile::Free, faces, &-n)
    }
}
