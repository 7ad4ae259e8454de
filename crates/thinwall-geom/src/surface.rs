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

/// A NURBS surface that is exactly a piece of a circular cylinder (CAD
/// systems, truck among them, write extruded arcs as rational B-splines):
/// its frame (`z` the axis, origin on it), radius, and whether the
/// surface's normal `∂S/∂u × ∂S/∂v` points away from the axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CylinderFit {
    pub frame: Frame,
    pub radius: f64,
    pub outward: bool,
}

/// A free-form surface that is exactly a cylinder, as one (rational
/// B-splines of extruded arcs: truck builds them so, and so do some CAD
/// systems), and whether its normal turned over doing so; any other surface
/// as it is.
pub fn analytic_form(s: Surface) -> (Surface, bool) {
    if let Surface::Freeform { nurbs, .. } = &s {
        if let Some(fit) = cylinder_of(nurbs, crate::tolerance::FREEFORM_FIT_MM) {
            let cylinder = Surface::Cylinder {
                frame: fit.frame,
                radius: fit.radius,
            };
            return (cylinder, !fit.outward);
        }
    }
    (s, false)
}

/// The cylinder a NURBS surface is, if every point of a 9 × 9 grid over
/// its domain lies within `tol` (mm) of it and one parameter runs straight
/// along its axis.
pub fn cylinder_of(s: &NurbsSurface, tol: f64) -> Option<CylinderFit> {
    const N: usize = 9;
    let ((u0, u1), (v0, v1)) = s.domain();
    let grid: Vec<Vec<crate::nurbs::SurfacePoint>> = (0..N)
        .map(|i| {
            let u = u0 + (u1 - u0) * i as f64 / (N - 1) as f64;
            (0..N)
                .map(|j| s.eval(u, v0 + (v1 - v0) * j as f64 / (N - 1) as f64))
                .collect()
        })
        .collect();
    // The straight parameter: its derivative keeps one direction.
    let straight = |d: &dyn Fn(&crate::nurbs::SurfacePoint) -> Vector3| -> Option<Vector3> {
        let a = d(&grid[0][0]).try_normalize(1e-12)?;
        grid.iter()
            .flatten()
            .all(|p| {
                d(p).try_normalize(1e-12)
                    .is_some_and(|b| a.cross(&b).norm() < 1e-9)
            })
            .then_some(a)
    };
    let (axis, rows): (Vector3, Vec<&crate::nurbs::SurfacePoint>) = match straight(&|p| p.dv) {
        Some(a) => (a, grid.iter().map(|row| &row[0]).collect()),
        None => (straight(&|p| p.du)?, grid[0].iter().collect()),
    };
    // A circle through three points of a section across the axis.
    let flat = |p: &Point3| p.coords - axis * p.coords.dot(&axis);
    let (a, b, c) = (
        flat(&rows[0].point),
        flat(&rows[N / 2].point),
        flat(&rows[N - 1].point),
    );
    let centre = circumcentre(&a, &b, &c)?;
    let radius = (a - centre).norm();
    if radius.is_nan() || radius <= tol {
        return None;
    }
    for p in grid.iter().flatten() {
        if ((flat(&p.point) - centre).norm() - radius).abs() > tol {
            return None;
        }
    }
    let p0 = &grid[0][0];
    let out = flat(&p0.point) - centre;
    let origin = Point3::from(centre + axis * p0.point.coords.dot(&axis));
    Some(CylinderFit {
        frame: Frame {
            origin,
            x: out / radius,
            y: axis.cross(&(out / radius)),
            z: axis,
        },
        radius,
        outward: p0.du.cross(&p0.dv).dot(&out) > 0.0,
    })
}

/// The centre of the circle through three points of a plane.
fn circumcentre(a: &Vector3, b: &Vector3, c: &Vector3) -> Option<Vector3> {
    let (ab, ac) = (b - a, c - a);
    let n = ab.cross(&ac);
    let n2 = n.norm_squared();
    if n2 < 1e-18 * ab.norm_squared() * ac.norm_squared() {
        return None;
    }
    let t = (ac.cross(&n) * ab.norm_squared() + n.cross(&ab) * ac.norm_squared()) / (2.0 * n2);
    Some(a + t)
}

#[cfg(test)]
mod cylinder_tests {
    use super::*;

    /// A quarter of a cylinder of radius `r` about an axis along z through
    /// (1, −2), 5 long, as a quadratic × linear NURBS (rational: exact;
    /// with unit weights: a parabola's extrusion); its normal outward or
    /// not.
    fn quarter(r: f64, outward: bool, rational: bool) -> NurbsSurface {
        let w = if rational {
            std::f64::consts::FRAC_1_SQRT_2
        } else {
            1.0
        };
        let arc = |z: f64| [[r + 1.0, -2.0, z], [r + 1.0, r - 2.0, z], [1.0, r - 2.0, z]];
        let (a, b) = (arc(0.0), arc(5.0));
        let quad = vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0];
        let lin = vec![0.0, 0.0, 1.0, 1.0];
        if outward {
            // u along the arc, v along the axis: ∂u × ∂v points out.
            let pts: Vec<Vec<[f64; 3]>> = (0..3).map(|k| vec![a[k], b[k]]).collect();
            let ws = vec![vec![1.0, 1.0], vec![w, w], vec![1.0, 1.0]];
            NurbsSurface::new(2, 1, quad, lin, &pts, &ws).unwrap()
        } else {
            let pts = vec![a.to_vec(), b.to_vec()];
            let ws = vec![vec![1.0, w, 1.0]; 2];
            NurbsSurface::new(1, 2, lin, quad, &pts, &ws).unwrap()
        }
    }

    #[test]
    fn a_rational_quarter_cylinder_is_found_with_its_normal() {
        for outward in [true, false] {
            let fit = cylinder_of(&quarter(3.0, outward, true), 1e-9).expect("a cylinder");
            assert!((fit.radius - 3.0).abs() < 1e-12);
            assert!(fit.frame.z.cross(&Vector3::z()).norm() < 1e-12);
            let o = fit.frame.origin;
            assert!(
                (o.x - 1.0).abs() < 1e-12 && (o.y + 2.0).abs() < 1e-12,
                "{o:?}"
            );
            assert_eq!(fit.outward, outward);
        }
    }

    #[test]
    fn a_parabolic_extrusion_is_not_a_cylinder() {
        assert!(cylinder_of(&quarter(3.0, true, false), 1e-6).is_none());
    }
}
