//! Which faces of a volume coincide over an area with faces of the part or
//! of other volumes (planes by polygon overlap, cylinders by axis, radius
//! and axial overlap).

use crate::FaceRole;
use thinwall_analysis::polygon::{beyond_rounding, intersect};
use thinwall_analysis::{Cylinder, PartAnalysis, PlanarFace};
use thinwall_brep::FaceId;
use thinwall_geom::tolerance::{FEATURE_PARALLEL_DEG, MAX_SIDE_DRAFT_DEG};
use thinwall_geom::{BoundingBox, Vector3};

/// Geometry of one face, prepared once.
pub struct FaceGeom<'a> {
    pub face: FaceId,
    pub step_id: u64,
    pub planar: Option<&'a PlanarFace>,
    pub cylinder: Option<Cylinder>,
    pub bbox: BoundingBox,
    /// A point inside a planar face, found once when first asked.
    inner: std::sync::OnceLock<Option<thinwall_geom::Point3>>,
}

impl<'a> FaceGeom<'a> {
    /// Every face of an analysed part.
    pub fn all(a: &'a PartAnalysis) -> Vec<FaceGeom<'a>> {
        a.part()
            .face_ids()
            .map(|f| {
                let mut bbox = BoundingBox::empty();
                for p in a.boundary_points(f) {
                    bbox.add_point(p);
                }
                FaceGeom {
                    face: f,
                    step_id: a.part().face(f).step_id,
                    planar: a.planar(f),
                    cylinder: a.cylinder(f),
                    bbox,
                    inner: std::sync::OnceLock::new(),
                }
            })
            .collect()
    }

    /// A point inside a planar face (none for other faces), computed once.
    pub fn inner_point(&self) -> Option<thinwall_geom::Point3> {
        *self.inner.get_or_init(|| {
            use geo::InteriorPoint;
            let pf = self.planar?;
            let ip = pf.polygon_in(&pf.frame).interior_point()?;
            Some(pf.frame.to_world(&Vector3::new(ip.x(), ip.y(), 0.0)))
        })
    }

    /// Its role along the tool direction (`−up`).
    pub fn role(&self, up: &Vector3, tol: &Tol) -> FaceRole {
        if let Some(p) = &self.planar {
            let c = p.normal().dot(up);
            if c > tol.cos {
                return FaceRole::Top;
            }
            if c < -tol.cos {
                return FaceRole::Bottom;
            }
            if c.abs() < tol.side_lean {
                return FaceRole::Side;
            }
            return FaceRole::Other;
        }
        if let Some(c) = self.cylinder {
            if c.axis.dot(up).abs() > tol.cos {
                return FaceRole::Side;
            }
        }
        FaceRole::Other
    }

    /// The face's extent along `axis` (over its box corners).
    fn span(&self, axis: &Vector3) -> (f64, f64) {
        let b = &self.bbox;
        (0..8)
            .map(|i| {
                let pick = |k: usize, bit: usize| if i & bit == 0 { b.min[k] } else { b.max[k] };
                Vector3::new(pick(0, 1), pick(1, 2), pick(2, 4)).dot(axis)
            })
            .fold((f64::INFINITY, f64::NEG_INFINITY), |m, x| {
                (m.0.min(x), m.1.max(x))
            })
    }
}

/// The tolerances of coincidence, from the part's.
pub struct Tol {
    pub lin: f64,
    pub cos: f64,
    pub min_area: f64,
    /// Sine of the largest lean of a side (drafted sides are sides).
    pub side_lean: f64,
}

impl Tol {
    pub fn of(a: &PartAnalysis) -> Self {
        Self {
            lin: a.tol().coincidence,
            cos: FEATURE_PARALLEL_DEG.to_radians().cos(),
            min_area: a.tol().min_coincidence_area,
            side_lean: MAX_SIDE_DRAFT_DEG.to_radians().sin(),
        }
    }
}

fn boxes_touch(a: &BoundingBox, b: &BoundingBox, tol: f64) -> bool {
    (0..3).all(|k| a.min[k] <= b.max[k] + tol && b.min[k] <= a.max[k] + tol)
}

/// Whether two faces coincide over an area with opposite outward normals.
pub fn coincide(a: &FaceGeom, b: &FaceGeom, tol: &Tol) -> bool {
    if !boxes_touch(&a.bbox, &b.bbox, tol.lin) {
        return false;
    }
    match (a.planar, b.planar, a.cylinder, b.cylinder) {
        (Some(pa), Some(pb), _, _) => {
            // Facing each other within a side's lean; whether they touch is
            // then a matter of distance over the shared region, so that no
            // angle tips between poses.
            if pa.normal().dot(&pb.normal()) > -(1.0 - tol.side_lean.powi(2)).sqrt() {
                return false;
            }
            if (pb.frame.origin - pa.frame.origin).dot(&pa.normal()).abs() > tol.lin {
                return false;
            }
            let own = pa.polygon_in(&pa.frame);
            let other = pb.polygon_in(&pa.frame);
            let common = intersect(&own, &other);
            // Nearly parallel planes meet only where they are within the
            // tolerance over all the shared region, not along a line where
            // they cross (a side beside a drafted wall).
            beyond_rounding(&common, tol.lin, tol.min_area)
                && common
                    .0
                    .iter()
                    .flat_map(|p| p.exterior().0.iter())
                    .all(|c| {
                        let w = pa.frame.to_world(&Vector3::new(c.x, c.y, 0.0));
                        (w - pb.frame.origin).dot(&pb.normal()).abs() <= tol.lin
                    })
        }
        (_, _, Some(ca), Some(cb)) => {
            if ca.convex == cb.convex
                || (ca.radius - cb.radius).abs() > tol.lin
                || ca.axis.dot(&cb.axis).abs() < tol.cos
            {
                return false;
            }
            let d = cb.origin - ca.origin;
            if (d - ca.axis * d.dot(&ca.axis)).norm() > tol.lin {
                return false;
            }
            // Overlap along the axis.
            let (a0, a1) = a.span(&ca.axis);
            let (b0, b1) = b.span(&ca.axis);
            a1.min(b1) - a0.max(b0) > tol.lin
        }
        _ => false,
    }
}
