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

/// A cell whose mean width (2·area / perimeter) is under this fraction of
/// the part's size is a sliver of the 2-D booleans: the booleans round to
/// a grid of about 1e-9 of their inputs' extent, so their decisions there
/// are noise. Cell vertices closer than it are one vertex when a feature's
/// cells are joined into solids.
pub const SLIVER_WIDTH: f64 = 1e-6;

/// Solids whose volumes differ by less than this fraction are equal (up to
/// the sampling of curved edges) when a feature's main solid is chosen.
pub const EQUAL_VOLUME: f64 = 1e-6;
