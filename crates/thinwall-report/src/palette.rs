//! The colours of the pictures (SVG and HTML): one per kind of stiffness
//! feature, per kind of machining feature, per class of plan feature and
//! per face state of a classified volume, so every view colours alike.

use std::collections::BTreeMap;
use thinwall_analysis::{MachiningKind, StiffnessKind};

/// Faces of no feature, or shared by several.
pub const OTHER: [u8; 3] = [205, 205, 205];

/// Fill colour of a stiffness kind (and of faces of no feature).
pub fn stiffness(kind: Option<StiffnessKind>) -> [u8; 3] {
    use StiffnessKind as K;
    match kind {
        Some(K::Web) => [120, 170, 220],
        Some(K::Rib) => [240, 150, 60],
        Some(K::Flange) => [90, 180, 110],
        Some(K::Wall) => [160, 120, 200],
        Some(K::Hole) => [210, 60, 60],
        Some(K::Cutout) => [200, 80, 170],
        Some(K::Notch) => [150, 100, 60],
        Some(K::Pocket) => [230, 210, 80],
        Some(K::Chamfer) => [60, 190, 200],
        Some(K::Fillet) => [170, 180, 200],
        Some(K::Engraving) => [60, 60, 60],
        None => OTHER,
    }
}

/// Fill colour of a machining kind.
pub fn machining(kind: MachiningKind) -> [u8; 3] {
    use MachiningKind as K;
    match kind {
        K::Hole => [210, 60, 60],
        K::Pocket => [230, 190, 60],
        K::Slot => [80, 150, 230],
        K::Step => [100, 190, 120],
        K::Passage => [200, 80, 170],
        K::Chamfer => [60, 190, 200],
        K::Fillet => [170, 180, 200],
        K::Groove => [150, 100, 60],
        K::Face => [150, 150, 150],
        K::Boss => [240, 130, 90],
    }
}

/// A classified volume's closed and open faces.
pub const CLOSED: [u8; 3] = [220, 60, 50];
pub const OPEN: [u8; 3] = [90, 200, 110];

/// A plan feature's class (`large`, `small`, `bulk`, `other_setup`,
/// `detail`).
pub fn plan_class(class: &str) -> [u8; 3] {
    match class {
        "large" => [70, 130, 230],
        "small" => [120, 200, 240],
        "bulk" => [180, 180, 120],
        "other_setup" => [230, 120, 200],
        "detail" => [60, 190, 200],
        _ => OTHER,
    }
}

/// `#rrggbb`.
pub fn hex(c: [u8; 3]) -> String {
    format!("#{:02x}{:02x}{:02x}", c[0], c[1], c[2])
}

/// Every colour by name, for the HTML viewer: `stiffness.web`,
/// `machining.hole`, `plan.large`, `volume.closed`, …
pub fn table() -> BTreeMap<String, String> {
    let mut m = BTreeMap::new();
    for k in StiffnessKind::ALL {
        m.insert(format!("stiffness.{}", k.name()), hex(stiffness(Some(*k))));
    }
    for k in MachiningKind::ALL {
        m.insert(format!("machining.{}", k.name()), hex(machining(*k)));
    }
    let named: [(&str, [u8; 3]); 25] = [
        ("ops.rough", [60, 120, 215]),
        ("ops.semi_finish", [150, 90, 200]),
        ("ops.finish_walls", [40, 160, 170]),
        ("ops.finish", [60, 170, 110]),
        ("ops.drill", [220, 120, 40]),
        ("ops.finish_radii", [200, 60, 120]),
        ("access.advisable", [90, 190, 110]),
        ("reach.whole", [90, 190, 110]),
        ("reach.most", [190, 200, 80]),
        ("reach.part", [240, 150, 60]),
        ("reach.none", [215, 70, 60]),
        ("access.partial", [240, 170, 60]),
        ("access.blocked", [215, 70, 60]),
        ("access.closed", [120, 120, 130]),
        ("other", OTHER),
        ("selected", [255, 60, 30]),
        ("plan.large", plan_class("large")),
        ("plan.small", plan_class("small")),
        ("plan.bulk", plan_class("bulk")),
        ("plan.other_setup", plan_class("other_setup")),
        ("plan.detail", plan_class("detail")),
        ("plan.current", [255, 120, 0]),
        ("volume.closed", CLOSED),
        ("volume.open", OPEN),
        ("volume.touched", [250, 200, 40]),
    ];
    for (n, c) in named {
        m.insert(n.to_string(), hex(c));
    }
    m
}
