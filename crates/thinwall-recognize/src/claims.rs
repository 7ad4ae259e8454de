//! Depression and detail recognizers claiming faces in priority order after
//! the walls have claimed their sides: holes, cut-outs and notches (with
//! each wall's rim), fillets, chamfers.

use crate::config::Config;
use crate::depressions::{self, Depression};
use crate::details::{self, Blend};
use crate::engraving::{self, Engraving};
use crate::walls::Wall;
use std::collections::HashSet;
use thinwall_analysis::{PartAnalysis, StiffnessKind};
use thinwall_brep::FaceId;

/// What the depression and detail recognizers found.
#[derive(Default)]
pub struct Claims {
    pub depressions: Vec<Depression>,
    /// Per wall: its top and end faces.
    pub rims: Vec<Vec<FaceId>>,
    pub blends: Vec<Blend>,
    /// Chamfer faces and their widths, mm.
    pub chamfers: Vec<(FaceId, f64)>,
    pub engravings: Vec<Engraving>,
}

/// The recognizer stages in the configured priority; kinds left out of the
/// priority list run last, in the default order (notches come with cut-outs).
fn stages(config: &Config) -> Vec<StiffnessKind> {
    let mut stages: Vec<StiffnessKind> = Vec::new();
    for k in config
        .priority
        .iter()
        .chain(Config::default().priority.iter())
    {
        // Notches come with cut-outs, pockets with holes (the inner loops).
        let stage = match *k {
            StiffnessKind::Notch => StiffnessKind::Cutout,
            StiffnessKind::Pocket => StiffnessKind::Hole,
            other => other,
        };
        if !stage.is_wall() && !stages.contains(&stage) {
            stages.push(stage);
        }
    }
    stages
}

/// Run the stages; engravings first (their strokes are squat slabs, never
/// walls), then the configured ones; thin walls claim before thick ones.
pub fn claim(
    a: &PartAnalysis,
    walls: &[Wall],
    thin: &[bool],
    squat: &[bool],
    config: &Config,
) -> Claims {
    let any_side: HashSet<FaceId> = walls
        .iter()
        .flat_map(|w| w.sides.iter().flatten().copied())
        .collect();
    let wall_sides: HashSet<FaceId> = walls
        .iter()
        .zip(squat)
        .filter(|(_, &s)| !s)
        .flat_map(|(w, _)| w.sides.iter().flatten().copied())
        .collect();
    let mut c = Claims {
        rims: vec![Vec::new(); walls.len()],
        engravings: engraving::engravings(a, &wall_sides, config),
        ..Claims::default()
    };
    let mut taken: HashSet<FaceId> = any_side.clone();
    taken.extend(c.engravings.iter().flat_map(|e| e.faces.iter().copied()));
    let mut order: Vec<usize> = (0..walls.len()).collect();
    order.sort_by_key(|&w| (!thin[w], w));
    for stage in stages(config) {
        match stage {
            StiffnessKind::Hole => {
                for &w in &order {
                    let found = depressions::holes(a, walls, w, &mut taken, &any_side);
                    c.depressions.extend(found);
                }
            }
            StiffnessKind::Cutout => {
                for &w in &order {
                    let openings = cutouts(a, walls, w, &mut taken, &any_side, &mut c.rims[w]);
                    c.depressions.extend(openings);
                }
            }
            StiffnessKind::Fillet => {
                c.blends = details::blends(a, &taken);
                taken.extend(c.blends.iter().flat_map(|b| b.faces.iter().copied()));
            }
            StiffnessKind::Chamfer => {
                let max = config.thresholds.chamfer_max_width_mm;
                c.chamfers = details::chamfers(a, &taken, max);
                taken.extend(c.chamfers.iter().map(|c| c.0));
            }
            _ => {}
        }
    }
    c
}

/// Cut-outs and notches of wall `w` from its rim; the rest of the rim, but
/// its blends (inside corner radii, rounded tops, which are details), is
/// the wall's top and end faces.
fn cutouts(
    a: &PartAnalysis,
    walls: &[Wall],
    w: usize,
    taken: &mut HashSet<FaceId>,
    any_side: &HashSet<FaceId>,
    rim_out: &mut Vec<FaceId>,
) -> Vec<Depression> {
    let rim = depressions::rim_faces(a, &walls[w], taken, any_side);
    let long = thinwall_analysis::polygon::long_side(&walls[w].region);
    let openings = depressions::edge_openings(a, w, &rim, long);
    let used: HashSet<FaceId> = openings
        .iter()
        .flat_map(|d| d.faces.iter().copied())
        .collect();
    *rim_out = rim
        .into_iter()
        .filter(|f| !used.contains(f) && !a.is_blend_candidate(*f))
        .collect();
    taken.extend(used.iter().copied());
    taken.extend(rim_out.iter().copied());
    openings
}
