//! Geometry at the bottom of Thinwall: coordinate frames, analytic and NURBS
//! curves and surfaces, Gauss quadrature, bounding boxes and the named
//! tolerances every layer above uses.
//!
//! Everything here is pure computation on `f64` in millimetres and radians:
//! no I/O, no topology. Points are [`Point3`], directions [`Vector3`]
//! (nalgebra).
//!
//! ```
//! use thinwall_geom::{Frame, Surface, Point3};
//! let cyl = Surface::Cylinder { frame: Frame::world(), radius: 5.0 };
//! let n = cyl.normal_at(&Point3::new(5.0, 0.0, 3.0)).unwrap();
//! assert!((n.x - 1.0).abs() < 1e-12);
//! ```

pub mod bbox;
pub mod curve;
pub mod frame;
pub mod nurbs;
pub mod quadrature;
pub mod surface;
pub mod tolerance;

pub use bbox::BoundingBox;
pub use curve::CurveKind;
pub use frame::Frame;
pub use nurbs::{NurbsCurve, NurbsSurface};
pub use surface::Surface;
pub use tolerance::{PartTolerances, Tolerances};

/// A point in model space, millimetres.
pub type Point3 = nalgebra::Point3<f64>;
/// A direction or displacement in model space.
pub type Vector3 = nalgebra::Vector3<f64>;
