//! Right-handed orthonormal coordinate frames (STEP's `AXIS2_PLACEMENT_3D`).

use crate::{Point3, Vector3};
use serde::{Deserialize, Serialize};

/// An origin with orthonormal axes `x`, `y`, `z` (right-handed).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Frame {
    pub origin: Point3,
    pub x: Vector3,
    pub y: Vector3,
    pub z: Vector3,
}

impl Frame {
    /// The world frame.
    pub fn world() -> Self {
        Self {
            origin: Point3::origin(),
            x: Vector3::x(),
            y: Vector3::y(),
            z: Vector3::z(),
        }
    }

    /// A frame from an origin, an axis and a reference direction, the STEP
    /// way: `z` = axis, `x` = reference projected orthogonal to `z`. Without a
    /// usable reference an arbitrary perpendicular is taken. `None` for a
    /// zero axis.
    pub fn from_axis(origin: Point3, axis: Vector3, reference: Option<Vector3>) -> Option<Self> {
        let z = axis.try_normalize(1e-12)?;
        let x = reference
            .and_then(|r| (r - z * r.dot(&z)).try_normalize(1e-9))
            .unwrap_or_else(|| any_perpendicular(&z));
        let y = z.cross(&x);
        Some(Self { origin, x, y, z })
    }

    /// Coordinates of `p` in this frame.
    pub fn to_local(&self, p: &Point3) -> Vector3 {
        let d = p - self.origin;
        Vector3::new(d.dot(&self.x), d.dot(&self.y), d.dot(&self.z))
    }

    /// A direction expressed in this frame.
    pub fn vector_to_local(&self, v: &Vector3) -> Vector3 {
        Vector3::new(v.dot(&self.x), v.dot(&self.y), v.dot(&self.z))
    }

    /// The world point with local coordinates `l`.
    pub fn to_world(&self, l: &Vector3) -> Point3 {
        self.origin + self.x * l.x + self.y * l.y + self.z * l.z
    }

    /// A world direction from local components.
    pub fn vector_to_world(&self, l: &Vector3) -> Vector3 {
        self.x * l.x + self.y * l.y + self.z * l.z
    }

    /// This frame moved by a rigid transform given as a 4×4 row-major matrix
    /// (points map as column vectors, `p' = M·p`).
    pub fn transformed(&self, m: &[[f64; 4]; 4]) -> Self {
        Self {
            origin: transform_point(m, &self.origin),
            x: transform_vector(m, &self.x),
            y: transform_vector(m, &self.y),
            z: transform_vector(m, &self.z),
        }
    }
}

/// `p' = M·p` for a row-major 4×4 rigid transform.
pub fn transform_point(m: &[[f64; 4]; 4], p: &Point3) -> Point3 {
    Point3::new(
        m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
        m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
        m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3],
    )
}

/// The rotation part of `M` applied to `v`.
pub fn transform_vector(m: &[[f64; 4]; 4], v: &Vector3) -> Vector3 {
    Vector3::new(
        m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
        m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
        m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z,
    )
}

/// `a·b` for row-major 4×4 matrices.
pub fn compose(a: &[[f64; 4]; 4], b: &[[f64; 4]; 4]) -> [[f64; 4]; 4] {
    let mut m = [[0.0; 4]; 4];
    for (i, row) in m.iter_mut().enumerate() {
        for (j, cell) in row.iter_mut().enumerate() {
            *cell = (0..4).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    m
}

/// The identity transform.
pub const IDENTITY: [[f64; 4]; 4] = [
    [1.0, 0.0, 0.0, 0.0],
    [0.0, 1.0, 0.0, 0.0],
    [0.0, 0.0, 1.0, 0.0],
    [0.0, 0.0, 0.0, 1.0],
];

/// A unit vector perpendicular to the unit vector `z`.
pub fn any_perpendicular(z: &Vector3) -> Vector3 {
    let helper = if z.x.abs() < 0.9 {
        Vector3::x()
    } else {
        Vector3::y()
    };
    (helper - z * helper.dot(z)).normalize()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frame_round_trips_points() {
        let f = Frame::from_axis(
            Point3::new(1.0, 2.0, 3.0),
            Vector3::new(0.0, 0.0, 2.0),
            Some(Vector3::new(1.0, 1.0, 0.5)),
        )
        .unwrap();
        assert!((f.x.norm() - 1.0).abs() < 1e-12);
        assert!(f.x.dot(&f.z).abs() < 1e-12);
        assert!((f.x.cross(&f.y) - f.z).norm() < 1e-12);
        let p = Point3::new(-4.0, 5.0, 0.25);
        let back = f.to_world(&f.to_local(&p));
        assert!((back - p).norm() < 1e-12);
    }

    #[test]
    fn degenerate_axis_is_rejected_and_bad_reference_recovered() {
        assert!(Frame::from_axis(Point3::origin(), Vector3::zeros(), None).is_none());
        let f = Frame::from_axis(Point3::origin(), Vector3::z(), Some(Vector3::z())).unwrap();
        assert!(f.x.dot(&f.z).abs() < 1e-12);
    }

    #[test]
    fn transform_composes() {
        // 90° about z then shift x by 10.
        let rot = [
            [0.0, -1.0, 0.0, 0.0],
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 0.0, 1.0, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ];
        let mut shift = IDENTITY;
        shift[0][3] = 10.0;
        let m = compose(&shift, &rot);
        let p = transform_point(&m, &Point3::new(1.0, 0.0, 0.0));
        assert!((p - Point3::new(10.0, 1.0, 0.0)).norm() < 1e-12);
    }
}
