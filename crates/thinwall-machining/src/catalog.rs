//! The MFCAD++ catalogue name of a typed feature (`docs/MACHINING.md`).

use thinwall_analysis::{Catalog, MachiningKind, Profile};

/// The catalogue name of a feature with planar faces only, if it is one
/// of the catalogue's kinds (curved ones are named where they are typed).
pub(crate) fn planar(kind: MachiningKind, through: bool, profile: Profile) -> Option<Catalog> {
    use Catalog as C;
    use MachiningKind as K;
    use Profile as P;
    Some(match (kind, through, profile) {
        (K::Chamfer, _, _) => C::Chamfer,
        (K::Passage, true, P::Triangular) => C::TriangularPassage,
        (K::Passage, true, P::Rectangular) => C::RectangularPassage,
        (K::Passage, true, P::Hexagonal) => C::SixSidesPassage,
        (K::Slot, true, P::Triangular) => C::TriangularThroughSlot,
        (K::Slot, true, P::Rectangular) => C::RectangularThroughSlot,
        (K::Step, true, P::Rectangular) => C::RectangularThroughStep,
        (K::Step, true, P::TwoSided) => C::TwoSidesThroughStep,
        (K::Step, true, P::Slanted) => C::SlantedThroughStep,
        (K::Pocket, false, P::Triangular) => C::TriangularPocket,
        (K::Pocket, false, P::Rectangular) => C::RectangularPocket,
        (K::Pocket, false, P::Hexagonal) => C::SixSidesPocket,
        (K::Slot, false, P::Rectangular) => C::RectangularBlindSlot,
        (K::Step, false, P::Triangular) => C::TriangularBlindStep,
        (K::Step, false, P::Rectangular) => C::RectangularBlindStep,
        _ => return None,
    })
}
