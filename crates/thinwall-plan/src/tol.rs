//! The planner's tolerances, in one place. Lengths are in mm; fractions are
//! of the quantity named (the part's size, the stock's volume).

/// Lengths closer than this are equal when sizes and layer heights are
/// compared: a wall measured on a turned part is its height up to the
/// rounding of the turn, and a comparison at a boundary must not tip.
pub const SAME_LENGTH_MM: f64 = 1e-6;

/// A piece under this fraction of the stock's volume is a sliver of the
/// 2-D booleans (edges that coincide up to rounding), not material.
pub const SLIVER: f64 = 1e-9;

/// A bulk or other-set-up feature under this fraction of the stock's
/// volume (a skim of a hundredth of a millimetre left by a drafted wall's
/// top) joins the feature above or below it in its column.
pub const MERGE: f64 = 1e-6;

/// The removal's sliver width (`thinwall_removal`, its home).
pub use thinwall_removal::SLIVER_WIDTH;

/// Solids whose volumes differ by less than this fraction are equal (up to
/// the sampling of curved edges) when a feature's main solid is chosen.
pub const EQUAL_VOLUME: f64 = 1e-6;
