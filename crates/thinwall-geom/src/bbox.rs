//! Axis-aligned bounding boxes.

use crate::Point3;
use serde::{Deserialize, Serialize};

/// An axis-aligned box, mm. An empty box has `min > max`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct BoundingBox {
    pub min: [f64; 3],
    pub max: [f64; 3],
}

impl Default for BoundingBox {
    fn default() -> Self {
        Self::empty()
    }
}

impl BoundingBox {
    /// The box holding nothing.
    pub fn empty() -> Self {
        Self {
            min: [f64::INFINITY; 3],
            max: [f64::NEG_INFINITY; 3],
        }
    }

    pub fn is_empty(&self) -> bool {
        (0..3).any(|i| self.min[i] > self.max[i])
    }

    /// Grow to hold `p` (non-finite points are ignored).
    pub fn add_point(&mut self, p: &Point3) {
        if !(p.x.is_finite() && p.y.is_finite() && p.z.is_finite()) {
            return;
        }
        for i in 0..3 {
            self.min[i] = self.min[i].min(p[i]);
            self.max[i] = self.max[i].max(p[i]);
        }
    }

    /// Grow to hold `other`.
    pub fn add_box(&mut self, other: &BoundingBox) {
        for i in 0..3 {
            self.min[i] = self.min[i].min(other.min[i]);
            self.max[i] = self.max[i].max(other.max[i]);
        }
    }

    /// Edge lengths, mm (zeros for an empty box).
    pub fn size(&self) -> [f64; 3] {
        if self.is_empty() {
            return [0.0; 3];
        }
        [
            self.max[0] - self.min[0],
            self.max[1] - self.min[1],
            self.max[2] - self.min[2],
        ]
    }

    /// Length of the diagonal, mm.
    pub fn diagonal(&self) -> f64 {
        let s = self.size();
        (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]).sqrt()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn box_grows_and_measures() {
        let mut b = BoundingBox::empty();
        assert!(b.is_empty());
        assert_eq!(b.diagonal(), 0.0);
        b.add_point(&Point3::new(0.0, 0.0, 0.0));
        b.add_point(&Point3::new(3.0, 4.0, 0.0));
        b.add_point(&Point3::new(f64::NAN, 1.0, 1.0));
        assert!(!b.is_empty());
        assert_eq!(b.size(), [3.0, 4.0, 0.0]);
        assert!((b.diagonal() - 5.0).abs() < 1e-12);
    }
}
