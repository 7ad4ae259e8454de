//! What a classification request must satisfy before any volume is typed:
//! a removal sequence over existing volumes without self-pairs or cycles,
//! single-body volumes, no volume twice, none that is the part itself, and
//! no two that overlap.

use crate::coincide::{FaceGeom, Tol};
use crate::{ClassifyError, FaceRole, Volume};
use geo::MultiPolygon;
use petgraph::graph::DiGraph;
use thinwall_analysis::polygon::overlap_beyond;
use thinwall_analysis::PartAnalysis;
use thinwall_geom::{Frame, Vector3};

/// The removal sequence: indices in range, no self-pair, no cycle.
pub fn sequence(before: &[(usize, usize)], count: usize) -> Result<(), ClassifyError> {
    for &(a, b) in before {
        if a >= count || b >= count {
            return Err(ClassifyError::Sequence {
                before: a,
                after: b,
                count,
            });
        }
        if a == b {
            return Err(ClassifyError::SelfPair { volume: a });
        }
    }
    let mut g = DiGraph::<usize, ()>::new();
    let nodes: Vec<_> = (0..count).map(|i| g.add_node(i)).collect();
    for &(a, b) in before {
        g.add_edge(nodes[a], nodes[b], ());
    }
    if let Err(cycle) = petgraph::algo::toposort(&g, None) {
        return Err(ClassifyError::Cycle {
            volume: g[cycle.node_id()],
        });
    }
    Ok(())
}

/// A face's signature for comparing solids: surface kind, area and
/// centroid, rounded to the tolerance.
/// A solid's faces, rounded: kind, √area and centroid.
type Signature = Vec<(String, i64, [i64; 3])>;

fn signature(a: &PartAnalysis, tol: f64) -> Signature {
    let q = |x: f64| (x / tol).round() as i64;
    let mut v: Vec<_> = a
        .part()
        .face_ids()
        .map(|f| {
            let p = a.props(f);
            (
                a.part().face(f).surface.kind_name().to_string(),
                q(p.area.sqrt()),
                [q(p.centroid.x), q(p.centroid.y), q(p.centroid.z)],
            )
        })
        .collect();
    v.sort();
    v
}

/// Each volume is one body, appears once, and is not the part.
pub fn volumes(
    part: &PartAnalysis,
    volumes: &[Volume],
    analyses: &[PartAnalysis],
) -> Result<(), ClassifyError> {
    for (i, v) in volumes.iter().enumerate() {
        if v.part.bodies.len() != 1 {
            return Err(ClassifyError::MultiBody {
                volume: i,
                bodies: v.part.bodies.len(),
            });
        }
    }
    // Rounded to a thousandth of a millimetre: the same solid written twice.
    let tol = 1e-3;
    let of_part = signature(part, tol);
    let sigs: Vec<_> = analyses.iter().map(|a| signature(a, tol)).collect();
    let mut first: std::collections::HashMap<&Signature, usize> = std::collections::HashMap::new();
    for (i, s) in sigs.iter().enumerate() {
        if *s == of_part {
            return Err(ClassifyError::PartAsVolume { volume: i });
        }
        if let Some(&j) = first.get(s) {
            return Err(ClassifyError::Duplicate {
                first: j,
                second: i,
            });
        }
        first.insert(s, i);
    }
    Ok(())
}

/// A 2.5D volume's top profile (in the first top face's frame) and height range.
struct Prism {
    frame: Frame,
    profile: MultiPolygon<f64>,
    low: f64,
    high: f64,
}

fn prism(faces: &[FaceGeom], up: &Vector3, tol: &Tol) -> Option<Prism> {
    let height = |g: &FaceGeom| g.planar.map(|p| p.frame.origin.coords.dot(up));
    let tops: Vec<&FaceGeom> = faces
        .iter()
        .filter(|g| g.role(up, tol) == FaceRole::Top)
        .collect();
    let bottoms: Vec<f64> = faces
        .iter()
        .filter(|g| g.role(up, tol) == FaceRole::Bottom)
        .filter_map(height)
        .collect();
    let frame = tops.first()?.planar?.frame;
    let profile = MultiPolygon::new(
        tops.iter()
            .filter_map(|g| g.planar)
            .flat_map(|p| p.polygon_in(&frame).0)
            .collect(),
    );
    let high = tops
        .iter()
        .filter_map(|g| height(g))
        .fold(f64::NEG_INFINITY, f64::max);
    let low = bottoms.into_iter().fold(f64::INFINITY, f64::min);
    (low < high).then_some(Prism {
        frame,
        profile,
        low,
        high,
    })
}

/// No two 2.5D volumes share material: their profiles overlap over an
/// area while their height ranges overlap over more than the tolerance.
pub fn overlaps(vol_faces: &[Vec<FaceGeom>], up: &Vector3, tol: &Tol) -> Result<(), ClassifyError> {
    let prisms: Vec<Option<Prism>> = vol_faces.iter().map(|f| prism(f, up, tol)).collect();
    // Boxes first: two volumes apart need no polygon overlap.
    let boxes: Vec<thinwall_geom::BoundingBox> = vol_faces
        .iter()
        .map(|f| {
            let mut b = thinwall_geom::BoundingBox::empty();
            for g in f {
                let (lo, hi) = (g.bbox.min, g.bbox.max);
                b.add_point(&thinwall_geom::Point3::new(lo[0], lo[1], lo[2]));
                b.add_point(&thinwall_geom::Point3::new(hi[0], hi[1], hi[2]));
            }
            b
        })
        .collect();
    let apart = |i: usize, j: usize| {
        let (a, b) = (&boxes[i], &boxes[j]);
        (0..3).any(|k| a.min[k] >= b.max[k] - tol.lin || b.min[k] >= a.max[k] - tol.lin)
    };
    // Pairs by an index of the boxes: all pairs of a plan's thousands of
    // volumes were a quadratic pass.
    let index = crate::index::BoxIndex::new(&boxes, 0.0);
    for (i, a) in prisms.iter().enumerate() {
        for j in index.near(&boxes[i]).into_iter().filter(|&j| j > i) {
            let (Some(a), Some(b)) = (a, &prisms[j]) else {
                continue;
            };
            if a.high.min(b.high) - a.low.max(b.low) <= tol.lin || apart(i, j) {
                continue;
            }
            let b_in_a = MultiPolygon::new(
                b.profile
                    .0
                    .iter()
                    .map(|p| {
                        use geo::MapCoords;
                        p.map_coords(|c| {
                            let w = b.frame.to_world(&Vector3::new(c.x, c.y, 0.0));
                            let l = a.frame.to_local(&w);
                            geo::Coord { x: l.x, y: l.y }
                        })
                    })
                    .collect(),
            );
            // Material shared over more than the tolerance.
            if overlap_beyond(&a.profile, &b_in_a, tol.lin, tol.min_area) {
                return Err(ClassifyError::Overlap {
                    first: i,
                    second: j,
                });
            }
        }
    }
    Ok(())
}
