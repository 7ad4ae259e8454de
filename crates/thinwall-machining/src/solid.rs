//! A given stock solid (a blank, a casting envelope): which of the part's
//! faces lie on its surface (as-stock faces, not machined) and how far it
//! stands off each block plane.

use crate::{MachiningError, Stock};
use thinwall_analysis::measure::boundary_points;
use thinwall_analysis::PartAnalysis;
use thinwall_brep::Part;
use thinwall_geom::{Point3, Surface, Vector3};

/// A stock face's surface, as far as it can be matched: a plane with its
/// outward normal, or a cylinder.
enum StockSurface {
    Plane {
        origin: Point3,
        normal: Vector3,
    },
    Cylinder {
        origin: Point3,
        axis: Vector3,
        radius: f64,
    },
}

impl StockSurface {
    fn distance(&self, p: &Point3) -> f64 {
        match self {
            StockSurface::Plane { origin, normal } => (p - origin).dot(normal).abs(),
            StockSurface::Cylinder {
                origin,
                axis,
                radius,
            } => {
                let d = p - origin;
                ((d - axis * d.dot(axis)).norm() - radius).abs()
            }
        }
    }
}

fn surfaces(stock: &Part) -> Vec<StockSurface> {
    stock
        .faces
        .iter()
        .filter_map(|f| match f.surface {
            Surface::Plane { frame } => Some(StockSurface::Plane {
                origin: frame.origin,
                normal: if f.same_sense { frame.z } else { -frame.z },
            }),
            Surface::Cylinder { frame, radius } => Some(StockSurface::Cylinder {
                origin: frame.origin,
                axis: frame.z,
                radius,
            }),
            _ => None,
        })
        .collect()
}

/// Which of the part's faces lie on the stock's surface: every boundary
/// sample within tolerance of one stock face's surface (planes facing the
/// same way). An error when the stock is empty or does not contain the
/// part.
pub(crate) fn faces_on(a: &PartAnalysis, stock: &Part) -> Result<Vec<bool>, MachiningError> {
    if stock.faces.is_empty() {
        return Err(MachiningError::EmptyStock);
    }
    let tol = a.tol().feature * 100.0;
    let (pb, sb) = (a.bounding_box(), stock.bounding_box());
    let by = (0..3)
        .map(|k| (sb.min[k] - pb.min[k]).max(pb.max[k] - sb.max[k]))
        .fold(0.0, f64::max);
    if by > tol {
        return Err(MachiningError::StockTooSmall { by });
    }
    let surfaces = surfaces(stock);
    Ok(a.part()
        .face_ids()
        .map(|f| {
            let pts = a.boundary_points(f);
            let normal = a.props(f).normal;
            !pts.is_empty()
                && surfaces.iter().any(|s| {
                    let facing = match (s, normal) {
                        (StockSurface::Plane { normal: m, .. }, Some(n)) => n.dot(m) > 0.0,
                        (StockSurface::Plane { .. }, None) => false,
                        (StockSurface::Cylinder { .. }, _) => normal.is_none(),
                    };
                    facing && pts.iter().all(|p| s.distance(p) < tol)
                })
        })
        .collect())
}

/// How far the stock stands off block plane `sp` (outwards), mm.
pub(crate) fn standoff(stock: &Part, block: &Stock, sp: usize) -> f64 {
    let n = block.normal(sp);
    let far = stock
        .face_ids()
        .flat_map(|f| boundary_points(stock, f))
        .map(|p| p.coords.dot(&n))
        .fold(f64::NEG_INFINITY, f64::max);
    (far - block.plane_offset(sp)).max(0.0)
}
