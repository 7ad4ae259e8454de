//! Sane numbers at the door: every value of a part the reader returns is
//! finite and inside a documented range, so no NaN or overflow reaches the
//! geometry code above (a coordinate of 1e308 squared is infinite; a knot
//! span of 1e-320 divides to infinity).
//!
//! The reader refuses a part that breaks a bound with
//! [`StepError::BadNumber`], naming the entity (the vertex, edge or face
//! whose geometry holds the value) and what the value is. The bounds:
//!
//! | value                                   | accepted                         |
//! |-----------------------------------------|----------------------------------|
//! | millimetres per file length unit        | 1e-9 ..= 1e9                     |
//! | radians per file angle unit             | 1e-9 ..= 1e9                     |
//! | coordinates, after units and placement  | within ±1e7 mm of the origin     |
//! | radii of circles, cylinders, spheres    | > 0 and ≤ 1e7 mm                 |
//! | cone radius at its frame, torus major   | ≥ 0 and ≤ 1e7 mm                 |
//! | cone semi-angle                         | strictly between 0 and 90°       |
//! | B-spline knots                          | finite, within ±1e9, non-zero spans ≥ 1e-14 of the knot range |
//! | B-spline weights                        | > 0, finite                      |
//! | directions of frames and lines          | finite, non-zero                 |

use crate::StepError;
use thinwall_brep::Part;
use thinwall_geom::{CurveKind, Frame, NurbsCurve, NurbsSurface, Point3, Surface, Vector3};

/// Largest coordinate or radius accepted, mm (ten kilometres).
pub const MAX_LENGTH_MM: f64 = 1e7;
/// Range of a unit's factor (mm per unit, rad per unit).
pub const UNIT_FACTOR: std::ops::RangeInclusive<f64> = 1e-9..=1e9;
/// Largest knot value accepted.
pub const MAX_KNOT: f64 = 1e9;
/// Smallest non-zero knot span, relative to the knot range.
pub const MIN_KNOT_SPAN: f64 = 1e-14;

/// A value out of bounds: what it is, the value, and why it is refused.
type Bad = (String, f64, &'static str);

/// Refuse `part` if any of its numbers is out of bounds (first one found, in
/// the order units, vertices, edges, faces).
pub fn check(part: &Part, file: &str) -> Result<(), StepError> {
    let err = |entity: Option<u64>, (what, value, why): Bad| StepError::BadNumber {
        file: file.to_string(),
        entity,
        what,
        value,
        why,
    };
    let u = &part.units;
    for (what, v) in [
        ("the length unit, in mm,", u.mm_per_unit),
        ("the angle unit, in radians,", u.rad_per_unit),
    ] {
        if !UNIT_FACTOR.contains(&v) {
            return Err(err(None, (what.into(), v, "outside 1e-9 ..= 1e9")));
        }
    }
    for v in &part.vertices {
        point(&v.point, "vertex").map_err(|b| err(Some(v.step_id), b))?;
    }
    for e in &part.edges {
        curve(&e.curve)
            .and_then(|()| e.nurbs.as_ref().map_or(Ok(()), nurbs_curve))
            .map_err(|b| err(Some(e.step_id), b))?;
    }
    for f in &part.faces {
        surface(&f.surface).map_err(|b| err(Some(f.step_id), b))?;
    }
    Ok(())
}

fn length(v: f64, what: &str) -> Result<(), Bad> {
    if !v.is_finite() {
        return Err((what.into(), v, "not a finite number"));
    }
    if v.abs() > MAX_LENGTH_MM {
        return Err((what.into(), v, "beyond 1e7 mm"));
    }
    Ok(())
}

fn radius(v: f64, what: &str) -> Result<(), Bad> {
    length(v, what)?;
    if v <= 0.0 {
        return Err((what.into(), v, "not a positive radius"));
    }
    Ok(())
}

fn non_negative(v: f64, what: &str) -> Result<(), Bad> {
    length(v, what)?;
    if v < 0.0 {
        return Err((what.into(), v, "negative"));
    }
    Ok(())
}

fn point(p: &Point3, what: &str) -> Result<(), Bad> {
    p.iter()
        .try_for_each(|c| length(*c, &format!("{what} coordinate")))
}

fn direction(d: &Vector3, what: &str) -> Result<(), Bad> {
    if let Some(c) = d.iter().find(|c| !c.is_finite()) {
        return Err((format!("{what} direction"), *c, "not a finite number"));
    }
    if d.norm() == 0.0 {
        return Err((format!("{what} direction"), 0.0, "of zero length"));
    }
    Ok(())
}

fn frame(f: &Frame, what: &str) -> Result<(), Bad> {
    point(&f.origin, &format!("{what} origin"))?;
    [&f.x, &f.y, &f.z]
        .into_iter()
        .try_for_each(|d| direction(d, what))
}

fn curve(c: &CurveKind) -> Result<(), Bad> {
    match c {
        CurveKind::Line {
            origin,
            direction: d,
        } => {
            point(origin, "line")?;
            direction(d, "line")
        }
        CurveKind::Circle {
            frame: f,
            radius: r,
        } => {
            frame(f, "circle")?;
            radius(*r, "circle radius")
        }
        CurveKind::Ellipse {
            frame: f,
            semi_axis_1,
            semi_axis_2,
        } => {
            frame(f, "ellipse")?;
            radius(*semi_axis_1, "ellipse semi-axis")?;
            radius(*semi_axis_2, "ellipse semi-axis")
        }
        CurveKind::Bspline | CurveKind::Polyline | CurveKind::Other { .. } => Ok(()),
    }
}

fn surface(s: &Surface) -> Result<(), Bad> {
    match s {
        Surface::Plane { frame: f } => frame(f, "plane"),
        Surface::Cylinder {
            frame: f,
            radius: r,
        } => {
            frame(f, "cylinder")?;
            radius(*r, "cylinder radius")
        }
        Surface::Cone {
            frame: f,
            radius: r,
            semi_angle,
        } => {
            frame(f, "cone")?;
            non_negative(*r, "cone radius")?;
            let a = *semi_angle;
            if !(a.is_finite() && a.abs() > 0.0 && a.abs() < std::f64::consts::FRAC_PI_2) {
                return Err(("cone semi-angle".into(), a, "not between 0 and 90°"));
            }
            Ok(())
        }
        Surface::Sphere {
            frame: f,
            radius: r,
        } => {
            frame(f, "sphere")?;
            radius(*r, "sphere radius")
        }
        Surface::Torus {
            frame: f,
            major_radius,
            minor_radius,
        } => {
            frame(f, "torus")?;
            non_negative(*major_radius, "torus major radius")?;
            radius(*minor_radius, "torus minor radius")
        }
        Surface::Freeform { nurbs, .. } => nurbs_surface(nurbs),
        Surface::Unsupported { .. } => Ok(()),
    }
}

fn knots(k: &[f64], what: &str) -> Result<(), Bad> {
    let what = format!("{what} knot");
    if let Some(v) = k.iter().find(|v| !v.is_finite() || v.abs() > MAX_KNOT) {
        return Err((what, *v, "not finite or beyond 1e9"));
    }
    let range = k.last().copied().unwrap_or(0.0) - k.first().copied().unwrap_or(0.0);
    for w in k.windows(2) {
        let span = w[1] - w[0];
        if span < 0.0 {
            return Err((what, w[1], "smaller than the knot before it"));
        }
        if span > 0.0 && span < MIN_KNOT_SPAN * range {
            return Err((
                what,
                w[1],
                "too close to the knot before it (span below 1e-14 of the range)",
            ));
        }
    }
    Ok(())
}

fn weighted(c: &[f64; 4], what: &str) -> Result<(), Bad> {
    let w = c[3];
    if !(w.is_finite() && w > 0.0) {
        return Err((format!("{what} weight"), w, "not positive and finite"));
    }
    point(
        &Point3::new(c[0] / w, c[1] / w, c[2] / w),
        &format!("{what} control point"),
    )
}

fn nurbs_curve(n: &NurbsCurve) -> Result<(), Bad> {
    knots(&n.knots, "curve")?;
    n.control.iter().try_for_each(|c| weighted(c, "curve"))
}

fn nurbs_surface(n: &NurbsSurface) -> Result<(), Bad> {
    knots(&n.knots_u, "surface u")?;
    knots(&n.knots_v, "surface v")?;
    n.control
        .iter()
        .flatten()
        .try_for_each(|c| weighted(c, "surface"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn extreme_and_degenerate_values_are_refused_with_their_reason() {
        assert!(length(1e308, "x").is_err());
        assert!(length(f64::NAN, "x").is_err());
        assert!(length(-9.9e6, "x").is_ok());
        assert_eq!(radius(-1e308, "r").unwrap_err().2, "beyond 1e7 mm");
        assert_eq!(radius(0.0, "r").unwrap_err().2, "not a positive radius");
        assert!(non_negative(0.0, "cone radius").is_ok());
        assert!(knots(&[0.0, 0.0, 1e-320, 1.0, 1.0], "u").is_err());
        assert!(knots(&[0.0, 0.0, 1e308, 1e308], "u").is_err());
        assert!(knots(&[0.0, 0.0, 0.5, 1.0, 1.0], "u").is_ok());
        assert!(knots(&[0.0, 1.0, 0.5], "u").is_err());
        assert!(weighted(&[1.0, 1.0, 1.0, 0.0], "c").is_err());
        assert!(direction(&Vector3::zeros(), "line").is_err());
    }
}
