//! Stiffness feature recognition (DOMAIN.md §1–2, Popma 3.2, 4.1, 5.4.1,
//! 6.1.1): walls from opposed planar side faces, their kind in the set-up
//! (web, rib, flange, wall) and thinness by the cantilever model; holes,
//! cut-outs and notches in them; fillets and chamfers on them.
//!
//! Face-pattern recognizers over the analysis context
//! ([`thinwall_analysis::PartAnalysis`]); walls claim their faces first, so
//! a depression never takes a wall's side.
//!
//! ```no_run
//! use thinwall_analysis::{PartAnalysis, Setup};
//! let (part, _) = thinwall_step::read_file("panel.step").unwrap();
//! let a = PartAnalysis::new(&part, Setup::default());
//! let r = thinwall_recognize::recognize(&a, &thinwall_recognize::Config::default());
//! for f in &r.features {
//!     println!("{} {} {:?}", f.id, f.kind, f.thin);
//! }
//! ```

mod assemble;
mod claims;
pub mod config;
pub mod curved;
pub mod deflection;
pub mod depressions;
pub mod details;
pub mod engraving;
pub mod feature;
pub mod junctions;
pub mod offset;
pub mod sizing;
pub mod wall;
pub mod walls;

pub use config::{Config, ConfigError};
pub use curved::MidSurface;
pub use feature::{OtherSide, Plane, StiffnessFeature, WallGeometry};
pub use junctions::Junction;
pub use thinwall_analysis::{FeatureId, StiffnessKind};

use std::collections::BTreeMap;
use thinwall_analysis::PartAnalysis;

/// Everything recognition found.
#[derive(Clone, Debug)]
pub struct Recognition {
    /// Features in report order (by kind, then smallest face id).
    pub features: Vec<StiffnessFeature>,
    /// Wall-to-wall junctions, by index into `features` (walls only).
    pub junctions: Vec<Junction>,
    /// The chosen base of each wall feature (index into `features`).
    pub bases: BTreeMap<usize, usize>,
}

impl Recognition {
    /// The feature with this id.
    pub fn feature(&self, id: FeatureId) -> Option<&StiffnessFeature> {
        self.features.iter().find(|f| f.id == id)
    }
}

/// Recognize the stiffness features of the analysed part in its set-up.
pub fn recognize(a: &PartAnalysis, config: &Config) -> Recognition {
    let walls = walls::find_walls(a, config);
    let up = a.up();
    let heights: Vec<f64> = walls
        .iter()
        .map(|w| w.mid_plane().0.coords.dot(&up))
        .collect();
    let cos_floor = config.thresholds.parallel_angle_deg.to_radians().cos();
    let junctions = junctions::resolve_l_junctions(
        junctions::prefer_floors(junctions::find_junctions(a, &walls), &walls, &up, cos_floor),
        |w| heights[w],
        a.tol().feature,
    );
    let sizes = sizing::size_walls(a, &walls, &junctions, &heights, config);
    let kinds = sizing::kinds(&sizes);
    let thin: Vec<bool> = sizes.iter().map(|s| s.thin).collect();
    let squat: Vec<bool> = sizes.iter().map(|s| s.squat).collect();
    let claims = claims::claim(a, &walls, &thin, &squat, config);
    let mut draft = assemble::walls(a, &walls, &sizes, &kinds, &claims);
    assemble::depressions(a, &mut draft, &walls, &sizes, &claims.depressions, config);
    assemble::details(a, &mut draft, &walls, &sizes, &claims);
    let wall_feature = draft.wall_feature.clone();
    let (features, new_pos) = assemble::number(draft);
    let wall_pos = |w: usize| wall_feature[w].map(|fi| new_pos[fi]);
    let junctions = junctions
        .iter()
        .filter_map(|j| {
            Some(Junction {
                leaf: wall_pos(j.leaf)?,
                base: wall_pos(j.base)?,
                ..j.clone()
            })
        })
        .collect();
    let bases = (0..walls.len())
        .filter_map(|w| Some((wall_pos(w)?, wall_pos(sizes[w].base?)?)))
        .collect();
    Recognition {
        features,
        junctions,
        bases,
    }
}
