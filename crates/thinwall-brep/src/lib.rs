//! Thinwall's own read-only B-rep: bodies → shells → faces → loops →
//! coedges → edges → vertices, with geometry, keyed by STEP entity ids.
//!
//! One [`Face`] per STEP face: closed edges and seams are kept as the file
//! has them (nothing is split or healed). The model is built once by a
//! reader (see `thinwall-step`) and never changes afterwards; everything
//! derived (face properties, graphs, features) refers back to it by index
//! and by `step_id`.
//!
//! ```
//! use thinwall_brep::Part;
//! let part = Part::default();
//! assert_eq!(part.solid_face_count(), 0);
//! ```

pub mod builds;
pub mod model;
pub mod param_mesh;
pub mod props;
pub mod tessellate;

pub use model::*;
pub use props::{compute_face_props, FaceProps};
