//! Chamfers: bevel faces replacing an edge between two faces, found before
//! depressions are grouped (a bevel on an inside edge would otherwise join
//! the features on either side of it into one).
//!
//! A planar face is a chamfer when it is one strip (one loop, at least
//! three times longer than wide), its normal bisects the normals of two of
//! its non-parallel planar neighbours met with the same convexity (a
//! symmetric bevel), it is narrower than half the larger of the two (the
//! square root of its area), it is not a hexagon's side, and it
//! does not close with them alone a face it meets (a triangular step's
//! floor); a cone is a chamfer when it joins a plane square to
//! its axis and a coaxial cylinder and is shorter along the axis than the
//! cylinder's radius or is at 45° (a longer, steeper or flatter cone is a
//! countersink, part of its hole),
//! or when it carries a chain of planar bevels round a curved edge. A
//! plane coplanar with a planar bevel it meets smoothly is a piece of it.

use crate::{MachiningFeature, Stock};
use thinwall_analysis::polygon::min_rect_sides;
use thinwall_analysis::{Catalog, MachiningKind, PartAnalysis, Profile};
use thinwall_brep::FaceId;
use thinwall_geom::tolerance::NEAR_PARALLEL_EPS;
use thinwall_geom::{Surface, Vector3};
use thinwall_graph::Convexity;

/// A bevel's normal bisects its neighbours' within this angle, degrees.
const BISECT_DEG: f64 = 0.5;
/// A hexagon side meets its neighbour at 60° within this slack on the
/// cosine (about half a degree).
const HEXAGON_COS_SLACK: f64 = 1e-3;
/// A bevel is narrower than this share of the larger face it joins (the
/// square root of its area).
const NARROWER: f64 = 0.5;
/// A bevel on a cylinder's straight rim meets it and the plane at
/// dihedral angles this close, degrees.
const CHORD_BEVEL_DEG: f64 = 5.0;
/// A bevel strip meets four faces: its two ends and its two sides.
const ENDS_AND_SIDES: usize = 4;
/// A bevel is at least this many times longer than wide (a strip).
const ELONGATED: f64 = 3.0;

/// Whether face `f` is a chamfer (module docs).
pub(crate) fn is_chamfer(a: &PartAnalysis, f: FaceId) -> bool {
    match a.part().face(f).surface {
        Surface::Plane { .. } => {
            is_planar_bevel(a, f) || is_bevel_piece(a, f) || is_curved_edge_bevel(a, f)
        }
        Surface::Cone { .. } => is_conical_bevel(a, f) || is_bevel_corner(a, f),
        _ => false,
    }
}

/// A cone carrying a chain of planar bevels round a curved edge (a
/// chamfered obround rim): tangent to a planar bevel.
pub(crate) fn is_bevel_corner(a: &PartAnalysis, f: FaceId) -> bool {
    matches!(a.part().face(f).surface, Surface::Cone { .. })
        && a.graph().neighbours(f).any(|(g, adj)| {
            adj.convexity == Convexity::Smooth
                && matches!(a.part().face(g).surface, Surface::Plane { .. })
                && is_planar_bevel(a, g)
        })
}

/// A piece of a planar bevel split along a smooth edge (a sliver the
/// modeller left beside it): coplanar with a bevel it meets smoothly.
fn is_bevel_piece(a: &PartAnalysis, f: FaceId) -> bool {
    let Some(n) = a.props(f).normal else {
        return false;
    };
    a.graph().neighbours(f).any(|(g, adj)| {
        adj.convexity == Convexity::Smooth
            && a.props(g)
                .normal
                .is_some_and(|m| n.dot(&m) > 1.0 - NEAR_PARALLEL_EPS)
            && is_planar_bevel(a, g)
    })
}

/// A face's width and length when it is one strip: one loop (holes would
/// make a broad face look narrow by its boundary length), elongated.
fn strip(a: &PartAnalysis, f: FaceId) -> Option<(f64, f64)> {
    let (width, length) = a.strip_width(f);
    (a.part().face(f).loops.len() == 1 && length >= ELONGATED * width).then_some((width, length))
}

fn is_planar_bevel(a: &PartAnalysis, f: FaceId) -> bool {
    let (Some(n), Some((width, _))) = (a.props(f).normal, strip(a, f)) else {
        return false;
    };
    let mut planes: Vec<(FaceId, Vector3, Convexity)> = Vec::new();
    for (g, adj) in a.graph().neighbours(f) {
        if let Some(m) = a.props(g).normal {
            if g != f && !planes.iter().any(|(h, ..)| *h == g) {
                planes.push((g, m, adj.convexity));
            }
        }
    }
    let cos = BISECT_DEG.to_radians().cos();
    planes.iter().enumerate().any(|(i, (g, ng, cg))| {
        planes[i + 1..].iter().any(|(h, nh, ch)| {
            let sum = ng + nh;
            cg == ch
                && ng.dot(nh) < 1.0 - NEAR_PARALLEL_EPS
                && sum.norm() > NEAR_PARALLEL_EPS
                && n.dot(&sum.normalize()) > cos
                && (width < NARROWER * a.props(*g).area.sqrt().max(a.props(*h).area.sqrt())
                    || inside_depression(a, f, *cg))
                && !closes_a_floor(a, f, *g, *h)
                && !hexagon_side(&n, ng)
        })
    })
}

/// A planar strip on the straight edge between a plane and a cylinder,
/// along the cylinder's axis (a slot's rim, an inside corner): it has two
/// ends and two sides, both its long edges run along the axis, and it
/// meets the cylinder and the plane with the same convexity at dihedral
/// angles that nearly agree (a symmetric bevel of a curved face is a
/// chord, not a bisector, so they differ by a few degrees); it is narrower
/// than the cylinder's radius.
fn is_curved_edge_bevel(a: &PartAnalysis, f: FaceId) -> bool {
    let (Some(n), Some((width, _))) = (a.props(f).normal, strip(a, f)) else {
        return false;
    };
    if a.graph().neighbours(f).count() != ENDS_AND_SIDES {
        return false;
    }
    // Each side: the face, its convexity and the dihedral angle, degrees.
    let sides: Vec<(FaceId, Convexity, f64)> = a
        .graph()
        .neighbours(f)
        .filter(|(_, adj)| adj.convexity != Convexity::Smooth && adj.edges.len() == 1)
        .map(|(g, adj)| {
            (
                g,
                adj.convexity,
                a.graph().edges[adj.edges[0]].angle_min_deg,
            )
        })
        .collect();
    let along = |h: FaceId, axis: &Vector3| {
        a.planar(h).is_some_and(|p| {
            n.cross(&p.normal())
                .try_normalize(NEAR_PARALLEL_EPS)
                .is_some_and(|e| e.dot(axis).abs() > 1.0 - NEAR_PARALLEL_EPS)
        })
    };
    let bevel_angle =
        |deg: f64| (CHORD_BEVEL_DEG..90.0 - CHORD_BEVEL_DEG).contains(&(deg - 180.0).abs());
    sides.iter().any(|&(g, cg, ag)| {
        let Some(c) = a.cylinder(g).filter(|c| width < c.radius) else {
            return false;
        };
        bevel_angle(ag)
            && sides.iter().any(|&(h, ch, ah)| {
                ch == cg && along(h, &c.axis) && (ag - ah).abs() < CHORD_BEVEL_DEG
            })
    })
}

/// A bevel between two faces it meets concavely that meets every other
/// neighbour concavely too: an inside corner's bevel in a depression, which
/// may be wider than the remnants of the faces it joins.
fn inside_depression(a: &PartAnalysis, f: FaceId, c: Convexity) -> bool {
    c == Convexity::Concave
        && a.graph()
            .neighbours(f)
            .all(|(_, adj)| adj.convexity == Convexity::Concave)
}

/// Whether a face meeting a neighbour at 60° between normals is a side of
/// a hexagon (a six-sided pocket, passage or boss), not a bevel.
fn hexagon_side(n: &Vector3, neighbour: &Vector3) -> bool {
    (n.dot(neighbour) - 0.5).abs() < HEXAGON_COS_SLACK
}

/// Whether bevel candidate `f` between `g` and `h` bounds, with them only,
/// a face it meets: a triangular step's floor (a bevel's end faces go on
/// beyond it).
fn closes_a_floor(a: &PartAnalysis, f: FaceId, g: FaceId, h: FaceId) -> bool {
    a.graph().neighbours(f).any(|(e, adj)| {
        adj.convexity == Convexity::Concave
            && e != g
            && e != h
            && a.graph()
                .neighbours(e)
                .all(|(x, _)| x == f || x == g || x == h)
    })
}

fn is_conical_bevel(a: &PartAnalysis, f: FaceId) -> bool {
    let Surface::Cone {
        frame, semi_angle, ..
    } = a.part().face(f).surface
    else {
        return false;
    };
    let axis = frame.z;
    let square_plane = a.graph().neighbours(f).any(|(g, _)| {
        a.props(g)
            .normal
            .is_some_and(|m| m.dot(&axis).abs() > 1.0 - NEAR_PARALLEL_EPS)
    });
    let (lo, hi) = a.extent(&[f], &axis);
    let cylinder = a.graph().neighbours(f).find_map(|(g, _)| {
        a.cylinder(g).filter(|c| {
            c.axis.dot(&axis).abs() > 1.0 - NEAR_PARALLEL_EPS
                && (c.origin - frame.origin).cross(&axis).norm() < crate::axis_tol(a)
        })
    });
    // A symmetric bevel (45°) of any size is a chamfer; a steeper or
    // flatter cone only when short (else a countersink).
    let symmetric = (semi_angle.to_degrees() - 45.0).abs() < BISECT_DEG;
    square_plane && cylinder.is_some_and(|c| symmetric || hi - lo < c.radius)
}

/// How deep a chamfer reaches, mm: along `dir` (a chain round a curve, a
/// cone: along its axis); one flat bevel, which has no extent along its
/// own normal, reaches its leg along the block axis nearest that normal:
/// its `width` across, times the sine of its angle to that axis.
fn leg(a: &PartAnalysis, stock: &Stock, group: &[FaceId], dir: &Vector3, width: f64) -> f64 {
    let (lo, hi) = a.extent(group, dir);
    let along = if hi.is_finite() { hi - lo } else { 0.0 };
    if along > a.tol().coplanar {
        return along;
    }
    let nearest = stock
        .axes
        .iter()
        .map(|ax| ax.dot(dir).abs())
        .fold(0.0, f64::max);
    width * (1.0 - nearest * nearest).max(0.0).sqrt()
}

/// A chamfer feature: a chain of bevel faces, its long and short sides.
pub(crate) fn chamfer_feature(
    a: &PartAnalysis,
    stock: &Stock,
    group: &[FaceId],
) -> MachiningFeature {
    let normal: Vector3 = group
        .iter()
        .filter_map(|&f| a.props(f).normal)
        .fold(Vector3::zeros(), |s, n| s + n);
    let dir = (-normal).try_normalize(1e-12).unwrap_or(-stock.axes[2]);
    // A lone planar bevel: its own long and short sides. A chain or a
    // conical bevel: its longest extent along the stock's axes (a ring's
    // diameter, not its developed length) and its widest strip.
    let sides = (group.len() == 1)
        .then(|| a.polygon(group[0]).and_then(|p| min_rect_sides(&p)))
        .flatten();
    let (length, width) = sides.unwrap_or_else(|| {
        let width = group
            .iter()
            .map(|&f| a.strip_width(f).0)
            .fold(0.0, f64::max);
        let length = stock
            .axes
            .iter()
            .map(|ax| {
                let (lo, hi) = a.extent(group, ax);
                hi - lo
            })
            .fold(0.0, f64::max);
        (length, width)
    });
    MachiningFeature {
        catalog: Some(Catalog::Chamfer),
        depth: leg(a, stock, group, &dir, width.min(length)),
        length: length.max(width),
        width: width.min(length),
        ..MachiningFeature::on_faces(a, MachiningKind::Chamfer, Profile::Slanted, group, &dir)
    }
}
