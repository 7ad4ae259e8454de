//! Surfaces: the analytic kinds STEP names, and everything else as NURBS.
//!
//! Parametrisations follow ISO 10303-42, so `(u, v)` are right-handed with
//! respect to the surface normal `∂S/∂u × ∂S/∂v` (outward for cylinders,
//! cones, spheres and tori):
//! - cylinder: `S(u,v) = C + r(cos u·x + sin u·y) + v·z`
//! - cone: `S(u,v) = C + (r + v·tan α)(cos u·x + sin u·y) + v·z`
//! - sphere: `S(u,v) = C + R cos v (cos u·x + sin u·y) + R sin v·z`
//! - torus: `S(u,v) = C + (R + r cos v)(cos u·x + sin u·y) + r sin v·z`

use crate::{Frame, NurbsSurface, Point3, Vector3};
use serde::{Deserialize, Serialize};

/// The family of a free-form surface (kept for reports; all evaluate as NURBS).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FreeformKind {
    Bspline,
    Extrusion,
    Revolution,
    Offset,
    Other,
}

/// A surface in model space, mm and radians.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Surface {
    /// Normal = `frame.z`.
    Plane {
        frame: Frame,
    },
    Cylinder {
        frame: Frame,
        radius: f64,
    },
    /// `radius` at `v = 0`, `semi_angle` in radians.
    Cone {
        frame: Frame,
        radius: f64,
        semi_angle: f64,
    },
    Sphere {
        frame: Frame,
        radius: f64,
    },
    Torus {
        frame: Frame,
        major_radius: f64,
        minor_radius: f64,
    },
    Freeform {
        kind: FreeformKind,
        nurbs: NurbsSurface,
    },
    /// A surface the reader could not represent (kept so the face stays).
    Unsupported {
        keyword: String,
    },
}

impl Surface {
    /// The name reports use: `plane`, `cylinder`, `cone`, `sphere`, `torus`,
    /// `bspline`, `extrusion`, `revolution`, `offset`, `other`.
    pub fn kind_name(&self) -> &'static str {
        match self {
            Surface::Plane { .. } => "plane",
            Surface::Cylinder { .. } => "cylinder",
            Surface::Cone { .. } => "cone",
            Surface::Sphere { .. } => "sphere",
            Surface::Torus { .. } => "torus",
            Surface::Freeform { kind, .. } => match kind {
                FreeformKind::Bspline => "bspline",
                FreeformKind::Extrusion => "extrusion",
                FreeformKind::Revolution => "revolution",
                FreeformKind::Offset => "offset",
                FreeformKind::Other => "other",
            },
            Surface::Unsupported { .. } => "unsupported",
        }
    }

    /// The frame of an analytic surface.
    pub fn frame(&self) -> Option<&Frame> {
        match self {
            Surface::Plane { frame }
            | Surface::Cylinder { frame, .. }
            | Surface::Cone { frame, .. }
            | Surface::Sphere { frame, .. }
            | Surface::Torus { frame, .. } => Some(frame),
            Surface::Freeform { .. } | Surface::Unsupported { .. } => None,
        }
    }

    /// The unit surface normal (the parametrisation's sense, before any face
    /// orientation) at a point on or near the surface. `None` where it is
    /// undefined (on an axis, at an apex).
    pub fn normal_at(&self, p: &Point3) -> Option<Vector3> {
        match self {
            Surface::Plane { frame } => Some(frame.z),
            Surface::Cylinder { frame, .. } => {
                let l = frame.to_local(p);
                let radial = Vector3::new(l.x, l.y, 0.0).try_normalize(1e-12)?;
                Some(frame.vector_to_world(&radial))
            }
            Surface::Cone {
                frame, semi_angle, ..
            } => {
                let l = frame.to_local(p);
                let radial = Vector3::new(l.x, l.y, 0.0).try_normalize(1e-12)?;
                let (s, c) = semi_angle.sin_cos();
                let n = radial * c - Vector3::z() * s;
                Some(frame.vector_to_world(&n))
            }
            Surface::Sphere { frame, .. } => (p - frame.origin).try_normalize(1e-12),
            Surface::Torus {
                frame,
                major_radius,
                ..
            } => {
                let l = frame.to_local(p);
                let radial = Vector3::new(l.x, l.y, 0.0).try_normalize(1e-12)?;
                let centre = radial * *major_radius;
                let n = (l - centre).try_normalize(1e-12)?;
                Some(frame.vector_to_world(&n))
            }
            Surface::Freeform { nurbs, .. } => {
                let (u, v, _) = nurbs.invert(p, None);
                nurbs_normal(nurbs, u, v)
            }
            Surface::Unsupported { .. } => None,
        }
    }

    /// A point's parameters on a surface of revolution about `frame.z`:
    /// `(u, v)` as in the module doc. `None` for planes and free-form.
    pub fn revolution_uv(&self, p: &Point3) -> Option<(f64, f64)> {
        let frame = self.frame()?;
        let l = frame.to_local(p);
        let u = l.y.atan2(l.x);
        let rho = l.x.hypot(l.y);
        let v = match self {
            Surface::Cylinder { .. } | Surface::Cone { .. } => l.z,
            Surface::Sphere { .. } => l.z.atan2(rho),
            Surface::Torus { major_radius, .. } => l.z.atan2(rho - major_radius),
            _ => return None,
        };
        Some((u, v))
    }
}

/// The unit normal of a NURBS surface at `(u, v)`; falls back to a nearby
/// parameter where the surface is degenerate (a collapsed edge).
pub fn nurbs_normal(s: &NurbsSurface, u: f64, v: f64) -> Option<Vector3> {
    let sp = s.eval(u, v);
    if let Some(n) = sp.du.cross(&sp.dv).try_normalize(1e-14) {
        return Some(n);
    }
    let ((u0, u1), (v0, v1)) = s.domain();
    let eu = (u1 - u0) * 1e-4;
    let ev = (v1 - v0) * 1e-4;
    let uu = if u + eu <= u1 { u + eu } else { u - eu };
    let vv = if v + ev <= v1 { v + ev } else { v - ev };
    let sp = s.eval(uu, vv);
    sp.du.cross(&sp.dv).try_normalize(1e-14)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn analytic_normals_point_outward() {
        let f = Frame::world();
        let cone = Surface::Cone {
            frame: f,
            radius: 2.0,
            semi_angle: std::f64::consts::FRAC_PI_4,
        };
        let n = cone.normal_at(&Point3::new(3.0, 0.0, 1.0)).unwrap();
        let s = std::f64::consts::FRAC_1_SQRT_2;
        assert!((n - Vector3::new(s, 0.0, -s)).norm() < 1e-12);
        let torus = Surface::Torus {
            frame: f,
            major_radius: 10.0,
            minor_radius: 2.0,
        };
        let n = torus.normal_at(&Point3::new(0.0, 10.0, 2.0)).unwrap();
        assert!((n - Vector3::z()).norm() < 1e-12);
        let sphere = Surface::Sphere {
            frame: f,
            radius: 1.0,
        };
        assert!(sphere.normal_at(&Point3::origin()).is_none());
        let cyl = Surface::Cylinder {
            frame: f,
            radius: 1.0,
        };
        assert!(cyl.normal_at(&Point3::new(0.0, 0.0, 5.0)).is_none());
    }

    #[test]
    fn revolution_parameters_follow_iso_10303_42() {
        let sphere = Surface::Sphere {
            frame: Frame::world(),
            radius: 2.0,
        };
        let (u, v) = sphere.revolution_uv(&Point3::new(0.0, 1.0, 1.0)).unwrap();
        assert!((u - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
        assert!((v - std::f64::consts::FRAC_PI_4).abs() < 1e-12);
        let plane = Surface::Plane {
            frame: Frame::world(),
        };
        assert!(plane.revolution_uv(&Point3::origin()).is_none());
    }
}
