//! The one vocabulary of Thinwall: stiffness feature kinds, machining
//! feature kinds and profiles, volume types, and the typed ids that name
//! features inside the library. Each serialises to the same snake_case
//! strings the JSON contracts use.

use serde::{Deserialize, Deserializer, Serialize, Serializer};
use std::fmt;

/// Defines an enum of names with `ALL`, `name()` and `parse()`; serde uses
/// the same names.
macro_rules! named_enum {
    ($(#[$m:meta])* $vis:vis enum $name:ident { $($(#[$vm:meta])* $v:ident => $s:literal,)+ }) => {
        $(#[$m])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
        $vis enum $name {
            $($(#[$vm])* #[serde(rename = $s)] $v,)+
        }

        impl $name {
            /// Every value, in declaration order.
            pub const ALL: &'static [$name] = &[$($name::$v,)+];

            /// The name used in JSON, TOML and on the command line.
            pub fn name(self) -> &'static str {
                match self {
                    $($name::$v => $s,)+
                }
            }

            /// The value with this name.
            pub fn parse(s: &str) -> Option<Self> {
                Self::ALL.iter().copied().find(|k| k.name() == s)
            }
        }

        impl fmt::Display for $name {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.pad(self.name())
            }
        }
    };
}

named_enum! {
    /// Stiffness feature kinds (DOMAIN.md §1–2).
    pub enum StiffnessKind {
        Web => "web",
        Rib => "rib",
        Flange => "flange",
        Wall => "wall",
        Hole => "hole",
        Cutout => "cutout",
        Notch => "notch",
        /// A blind, not round depression in a wall's side (a wall made
        /// locally thinner).
        Pocket => "pocket",
        Chamfer => "chamfer",
        Fillet => "fillet",
        /// Engraving, embossing or lettering on a face: a detail.
        Engraving => "engraving",
    }
}

impl StiffnessKind {
    /// Web, rib, flange or wall.
    pub fn is_wall(self) -> bool {
        matches!(
            self,
            StiffnessKind::Web | StiffnessKind::Rib | StiffnessKind::Flange | StiffnessKind::Wall
        )
    }

    /// Whether a machining feature of `kind` on the same faces tells the same
    /// story: a hole is a hole, a pocket a pocket or step, a cut-out a slot,
    /// step, passage or pocket, a notch a step or slot, a fillet a fillet, a
    /// chamfer a chamfer. Walls and engravings share faces with anything.
    pub fn agrees_with(self, kind: MachiningKind) -> bool {
        use MachiningKind as M;
        match self {
            StiffnessKind::Web
            | StiffnessKind::Rib
            | StiffnessKind::Flange
            | StiffnessKind::Wall
            | StiffnessKind::Engraving => true,
            StiffnessKind::Hole => kind == M::Hole,
            StiffnessKind::Pocket => matches!(kind, M::Pocket | M::Step),
            StiffnessKind::Cutout => matches!(kind, M::Slot | M::Step | M::Passage | M::Pocket),
            StiffnessKind::Notch => matches!(kind, M::Step | M::Slot),
            StiffnessKind::Fillet => kind == M::Fillet,
            StiffnessKind::Chamfer => kind == M::Chamfer,
        }
    }

    /// Prefix of this kind's feature ids (`R` in `R2`).
    pub fn prefix(self) -> &'static str {
        match self {
            StiffnessKind::Web => "W",
            StiffnessKind::Rib => "R",
            StiffnessKind::Flange => "F",
            StiffnessKind::Wall => "L",
            StiffnessKind::Hole => "H",
            StiffnessKind::Cutout => "C",
            StiffnessKind::Notch => "N",
            StiffnessKind::Pocket => "P",
            StiffnessKind::Chamfer => "CH",
            StiffnessKind::Fillet => "FL",
            StiffnessKind::Engraving => "E",
        }
    }
}

named_enum! {
    /// Conventional machining feature kinds found on a part (DOMAIN.md §6).
    pub enum MachiningKind {
        Hole => "hole",
        Pocket => "pocket",
        Slot => "slot",
        Step => "step",
        Passage => "passage",
        Chamfer => "chamfer",
        Fillet => "fillet",
        /// A ring-shaped groove around a standing core (an O-ring groove).
        Groove => "groove",
        /// A face of the part's envelope to face-mill: the allowance on a
        /// block or blank face above it.
        Face => "face",
        /// A round boss standing above the face around it: the material
        /// to machine away around it.
        Boss => "boss",
    }
}

named_enum! {
    /// The 24 machining feature classes of the MFCAD++ benchmark (Colligan
    /// et al., 2022), by their names in the dataset (its ids in the same
    /// order, 0–23; 24 is stock). `docs/MACHINING.md` gives the mapping.
    pub enum Catalog {
        Chamfer => "chamfer",
        ThroughHole => "through_hole",
        TriangularPassage => "triangular_passage",
        RectangularPassage => "rectangular_passage",
        SixSidesPassage => "6sides_passage",
        TriangularThroughSlot => "triangular_through_slot",
        RectangularThroughSlot => "rectangular_through_slot",
        CircularThroughSlot => "circular_through_slot",
        RectangularThroughStep => "rectangular_through_step",
        TwoSidesThroughStep => "2sides_through_step",
        SlantedThroughStep => "slanted_through_step",
        ORing => "Oring",
        BlindHole => "blind_hole",
        TriangularPocket => "triangular_pocket",
        RectangularPocket => "rectangular_pocket",
        SixSidesPocket => "6sides_pocket",
        CircularEndPocket => "circular_end_pocket",
        RectangularBlindSlot => "rectangular_blind_slot",
        VCircularEndBlindSlot => "v_circular_end_blind_slot",
        HCircularEndBlindSlot => "h_circular_end_blind_slot",
        TriangularBlindStep => "triangular_blind_step",
        CircularBlindStep => "circular_blind_step",
        RectangularBlindStep => "rectangular_blind_step",
        Round => "round",
    }
}

impl Catalog {
    /// The class id in MFCAD++ (0–23).
    pub fn id(self) -> u32 {
        Self::ALL.iter().position(|&c| c == self).unwrap_or(0) as u32
    }
}

named_enum! {
    /// The profile of a machining feature.
    pub enum Profile {
        Rectangular => "rectangular",
        Triangular => "triangular",
        Hexagonal => "hexagonal",
        Circular => "circular",
        Slanted => "slanted",
        TwoSided => "two_sided",
        Free => "free",
        Counterbored => "counterbored",
        Countersunk => "countersunk",
        MultiSegment => "multi_segment",
        /// Straight sides ending in half or quarter circles (an obround
        /// pocket, a slot with a round end).
        CircularEnd => "circular_end",
        /// A concave blend.
        Fillet => "fillet",
        /// A convex blend.
        Round => "round",
    }
}

impl Profile {
    /// The profile of a feature with `n` wall directions (3, 4, 6), else free.
    pub fn of_sides(n: usize) -> Profile {
        match n {
            3 => Profile::Triangular,
            4 => Profile::Rectangular,
            6 => Profile::Hexagonal,
            _ => Profile::Free,
        }
    }
}

named_enum! {
    /// The machining-feature types of a 2.5D removal volume (DOMAIN.md §5.3).
    pub enum VolumeType {
        /// Cylindrical (a round hole is a rectangular one without straight sides).
        Hole => "hole",
        /// All sides closed, bottom closed.
        Pocket => "pocket",
        /// All sides closed, bottom open (a through pocket).
        Passage => "passage",
        /// Three sides closed in a U, one end open.
        BlindSlot => "blind_slot",
        /// Two opposite sides closed.
        ThroughSlot => "through_slot",
        /// Two adjacent sides closed.
        CornerNotch => "corner_notch",
        /// One side, or one connected chain of sides, closed.
        Step => "step",
        /// No side closed, bottom closed.
        Face => "face",
        /// Free-shaped profile (curved sides other than corner radii), all sides closed.
        FreePocket => "free_pocket",
        /// Free-shaped profile, all sides closed, bottom open.
        FreePassage => "free_passage",
        /// Free-shaped profile, some sides closed.
        FreeStep => "free_step",
        /// Matches no type exactly; kept with its adjacency for a user to edit.
        Unknown => "unknown",
    }
}

/// The id of a stiffness feature: its kind and a number, written `R2`, `H1`,
/// `CH3`. Stable within one recognition (numbered by kind, then by smallest
/// face id).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct FeatureId {
    pub kind: StiffnessKind,
    /// From 1.
    pub number: u32,
}

impl FeatureId {
    pub fn new(kind: StiffnessKind, number: u32) -> Self {
        Self { kind, number }
    }

    /// Read `R2`, `CH3`, … back.
    pub fn parse(s: &str) -> Option<Self> {
        // Longest prefix first: `CH` before `C`, `FL` before `F`.
        let mut kinds: Vec<StiffnessKind> = StiffnessKind::ALL.to_vec();
        kinds.sort_by_key(|k| std::cmp::Reverse(k.prefix().len()));
        kinds.into_iter().find_map(|k| {
            let n: u32 = s.strip_prefix(k.prefix())?.parse().ok()?;
            (n > 0 && !s[k.prefix().len()..].starts_with('+')).then(|| Self::new(k, n))
        })
    }
}

impl fmt::Display for FeatureId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(&format!("{}{}", self.kind.prefix(), self.number))
    }
}

impl Serialize for FeatureId {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

impl<'de> Deserialize<'de> for FeatureId {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let s = String::deserialize(d)?;
        FeatureId::parse(&s)
            .ok_or_else(|| serde::de::Error::custom(format!("'{s}' is not a feature id")))
    }
}

/// The id of a machining feature on a part: `M1`, `M2`, … by smallest face id.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Default)]
pub struct MachiningId(pub u32);

impl fmt::Display for MachiningId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(&format!("M{}", self.0))
    }
}

impl Serialize for MachiningId {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

impl<'de> Deserialize<'de> for MachiningId {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let s = String::deserialize(d)?;
        s.strip_prefix('M')
            .and_then(|n| n.parse().ok())
            .map(MachiningId)
            .ok_or_else(|| serde::de::Error::custom(format!("'{s}' is not a machining id")))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn catalogue_ids_are_mfcadpp_class_ids() {
        assert_eq!(Catalog::ALL.len(), 24);
        assert_eq!(Catalog::Chamfer.id(), 0);
        assert_eq!(Catalog::ORing.id(), 11);
        assert_eq!(Catalog::ORing.name(), "Oring");
        assert_eq!(Catalog::SixSidesPocket.name(), "6sides_pocket");
        assert_eq!(Catalog::RectangularBlindStep.id(), 22);
        assert_eq!(Catalog::Round.id(), 23);
        // The JSON schema lists the same names, in the same order.
        let schema = include_str!("../../../docs/schema/recognition.schema.json");
        let mut at = schema.find("\"catalog\"").expect("catalog in the schema");
        for c in Catalog::ALL {
            let quoted = format!("\"{}\"", c.name());
            at += schema[at..]
                .find(&quoted)
                .unwrap_or_else(|| panic!("{quoted} not in the schema, in order"));
        }
    }

    #[test]
    fn names_round_trip_and_ids_read_back() {
        for k in StiffnessKind::ALL {
            assert_eq!(StiffnessKind::parse(k.name()), Some(*k));
            let id = FeatureId::new(*k, 12);
            assert_eq!(FeatureId::parse(&id.to_string()), Some(id));
        }
        assert_eq!(
            FeatureId::parse("CH3").unwrap().kind,
            StiffnessKind::Chamfer
        );
        assert_eq!(FeatureId::parse("C3").unwrap().kind, StiffnessKind::Cutout);
        assert_eq!(FeatureId::parse("FL1").unwrap().kind, StiffnessKind::Fillet);
        assert!(FeatureId::parse("R0").is_none() && FeatureId::parse("X1").is_none());
        assert!(FeatureId::parse("R+1").is_none());
        assert_eq!(VolumeType::parse("blind_slot"), Some(VolumeType::BlindSlot));
        assert_eq!(
            serde_json::to_string(&Profile::TwoSided).unwrap(),
            "\"two_sided\""
        );
        let id: FeatureId = serde_json::from_str("\"FL2\"").unwrap();
        assert_eq!(serde_json::to_string(&id).unwrap(), "\"FL2\"");
        assert_eq!(MachiningId(7).to_string(), "M7");
        // Widths pad, as in the text tables.
        assert_eq!(
            format!("{:<4}|", FeatureId::new(StiffnessKind::Rib, 2)),
            "R2  |"
        );
        assert_eq!(format!("{:<6}|", StiffnessKind::Rib), "rib   |");
    }
}
