//! The machine set-up: up direction (tool axis of a 3-axis machine),
//! machine class, and the part's placement on the table.

use serde::{Deserialize, Serialize};
use thinwall_geom::Vector3;
use thiserror::Error;

/// A set-up that cannot be used.
#[derive(Debug, Error, PartialEq)]
pub enum SetupError {
    #[error("up direction {0:?} has no length")]
    ZeroUp([f64; 3]),
    #[error("up direction {0:?} is not three finite numbers")]
    NotFiniteUp([f64; 3]),
    #[error("tilt limit must be within 0..90 degrees, got {0}")]
    TiltLimit(f64),
}

impl SetupError {
    /// A stable machine-readable code for the error kind.
    pub fn code(&self) -> &'static str {
        match self {
            SetupError::ZeroUp(_) => "zero_up",
            SetupError::NotFiniteUp(_) => "not_finite_up",
            SetupError::TiltLimit(_) => "tilt_limit",
        }
    }
}

/// What the machine can do with its tool axis.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "class", rename_all = "snake_case")]
pub enum Machine {
    /// The tool axis is always `up`.
    ThreeAxis,
    /// The tool axis may tilt from `up` by at most `tilt_limit_deg`.
    FiveAxis { tilt_limit_deg: f64 },
}

/// A set-up.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Setup {
    /// Up in machine coordinates (unit).
    pub up: [f64; 3],
    pub machine: Machine,
    /// Part-to-machine rigid placement (row-major 4×4); identity when absent.
    pub placement: Option<[[f64; 4]; 4]>,
}

impl Default for Setup {
    fn default() -> Self {
        Self {
            up: [0.0, 0.0, 1.0],
            machine: Machine::ThreeAxis,
            placement: None,
        }
    }
}

impl Setup {
    /// A set-up with `up` (any length but zero, stored unit) on `machine`,
    /// with no placement.
    pub fn new(up: [f64; 3], machine: Machine) -> Result<Self, SetupError> {
        let s = Self {
            up,
            machine,
            placement: None,
        };
        s.validate()?;
        // Scaled first: a direction such as (1e308, 1e308, 0) has a length
        // past f64's range.
        let largest = up.iter().fold(0.0f64, |m, c| m.max(c.abs()));
        let u = (Vector3::new(up[0], up[1], up[2]) / largest).normalize();
        Ok(Self {
            up: [u.x, u.y, u.z],
            ..s
        })
    }

    /// Reject a zero or non-finite up and a tilt limit outside 0..90°.
    pub fn validate(&self) -> Result<(), SetupError> {
        if self.up.iter().any(|c| !c.is_finite()) {
            return Err(SetupError::NotFiniteUp(self.up));
        }
        let largest = self.up.iter().fold(0.0f64, |m, c| m.max(c.abs()));
        if largest <= 1e-9 {
            return Err(SetupError::ZeroUp(self.up));
        }
        if let Machine::FiveAxis { tilt_limit_deg } = self.machine {
            if !(tilt_limit_deg.is_finite() && (0.0..=90.0).contains(&tilt_limit_deg)) {
                return Err(SetupError::TiltLimit(tilt_limit_deg));
            }
        }
        Ok(())
    }

    /// Up expressed in the part's own coordinates (the placement's rotation
    /// undone), unit length.
    pub fn up_in_part(&self) -> Vector3 {
        let u = Vector3::new(self.up[0], self.up[1], self.up[2]);
        let u = match &self.placement {
            // Rotation is orthonormal: its inverse is its transpose.
            Some(m) => Vector3::new(
                m[0][0] * u.x + m[1][0] * u.y + m[2][0] * u.z,
                m[0][1] * u.x + m[1][1] * u.y + m[2][1] * u.z,
                m[0][2] * u.x + m[1][2] * u.y + m[2][2] * u.z,
            ),
            None => u,
        };
        u.try_normalize(1e-12).unwrap_or_else(Vector3::z)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn placement_turns_up_into_part_coordinates() {
        // The part is turned 90° about z on the table: machine +x is part -y…
        // p_machine = R p_part with R = rot_z(90°): part +x -> machine +y.
        let s = Setup {
            up: [0.0, 1.0, 0.0],
            placement: Some([
                [0.0, -1.0, 0.0, 5.0],
                [1.0, 0.0, 0.0, 0.0],
                [0.0, 0.0, 1.0, 0.0],
                [0.0, 0.0, 0.0, 1.0],
            ]),
            ..Setup::default()
        };
        let u = s.up_in_part();
        assert!((u - Vector3::x()).norm() < 1e-12, "{u}");
        assert!((Setup::default().up_in_part() - Vector3::z()).norm() < 1e-12);
    }

    #[test]
    fn new_normalizes_and_rejects_nonsense() {
        let s = Setup::new([0.0, 0.0, 2.0], Machine::ThreeAxis).unwrap();
        assert_eq!(s.up, [0.0, 0.0, 1.0]);
        let e = Setup::new([0.0, 0.0, 0.0], Machine::ThreeAxis).unwrap_err();
        assert_eq!(e.code(), "zero_up");
        let e = Setup::new(
            [0.0, 0.0, 1.0],
            Machine::FiveAxis {
                tilt_limit_deg: 95.0,
            },
        );
        assert_eq!(e.unwrap_err().code(), "tilt_limit");
    }
}
