//! Recognition settings: the set-up, the sizing model's parameters and the
//! recognizers' thresholds. Defaults are Popma's (App. A.2) and
//! `DOMAIN.md`; every value can be overridden from a TOML file or flags.

use serde::{Deserialize, Serialize};
use thiserror::Error;

/// Feature kinds a user can include or exclude.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Kind {
    Web,
    Rib,
    Flange,
    Wall,
    Hole,
    Cutout,
    Notch,
    Chamfer,
    Fillet,
}

impl Kind {
    pub const ALL: [Kind; 9] = [
        Kind::Web,
        Kind::Rib,
        Kind::Flange,
        Kind::Wall,
        Kind::Hole,
        Kind::Cutout,
        Kind::Notch,
        Kind::Chamfer,
        Kind::Fillet,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Kind::Web => "web",
            Kind::Rib => "rib",
            Kind::Flange => "flange",
            Kind::Wall => "wall",
            Kind::Hole => "hole",
            Kind::Cutout => "cutout",
            Kind::Notch => "notch",
            Kind::Chamfer => "chamfer",
            Kind::Fillet => "fillet",
        }
    }

    pub fn is_wall(self) -> bool {
        matches!(self, Kind::Web | Kind::Rib | Kind::Flange | Kind::Wall)
    }

    pub fn parse(s: &str) -> Option<Kind> {
        Kind::ALL.into_iter().find(|k| k.name() == s)
    }
}

/// The cantilever model deciding whether a wall is thin (Popma 4.1.2, 6.1.1).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Thinness {
    /// Maximum milling force, N.
    pub force_n: f64,
    /// Young's modulus, N/mm² (aluminium).
    pub youngs_modulus_n_mm2: f64,
    /// Allowed deflection, mm.
    pub allowed_deflection_mm: f64,
    /// Effective length factor: `L_eff = min(L, factor · h)`.
    pub effective_length_factor: f64,
}

impl Default for Thinness {
    fn default() -> Self {
        Self {
            force_n: 200.0,
            youngs_modulus_n_mm2: 70_000.0,
            allowed_deflection_mm: 0.01,
            effective_length_factor: 4.0,
        }
    }
}

/// Recognizer thresholds.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Thresholds {
    /// Angle within which two side faces count as parallel, degrees.
    pub parallel_angle_deg: f64,
    /// A wall's narrowest in-plane width must exceed its thickness times this.
    pub min_width_to_thickness: f64,
    /// Preferred tool diameter, mm (large holes, step separation).
    pub preferred_tool_diameter_mm: f64,
    /// A hole is large when its height exceeds this many tool diameters.
    pub large_hole_factor: f64,
    /// Largest width of a chamfer face, mm.
    pub chamfer_max_width_mm: f64,
}

impl Default for Thresholds {
    fn default() -> Self {
        Self {
            parallel_angle_deg: 0.5,
            min_width_to_thickness: 1.0,
            preferred_tool_diameter_mm: 12.0,
            large_hole_factor: 1.5,
            chamfer_max_width_mm: 10.0,
        }
    }
}

/// Everything recognition needs besides the part.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Config {
    /// The set-up's up direction (tool axis of a 3-axis machine).
    pub up: [f64; 3],
    /// Kinds to report (all when empty).
    pub include: Vec<Kind>,
    /// Kinds never reported.
    pub exclude: Vec<Kind>,
    /// Order in which depression and detail recognizers claim faces
    /// (walls always come first).
    pub priority: Vec<Kind>,
    pub thinness: Thinness,
    pub thresholds: Thresholds,
}

impl Default for Config {
    fn default() -> Self {
        Self {
            up: [0.0, 0.0, 1.0],
            include: Vec::new(),
            exclude: Vec::new(),
            priority: vec![
                Kind::Hole,
                Kind::Cutout,
                Kind::Notch,
                Kind::Fillet,
                Kind::Chamfer,
            ],
            thinness: Thinness::default(),
            thresholds: Thresholds::default(),
        }
    }
}

/// A configuration that cannot be used.
#[derive(Debug, Error)]
pub enum ConfigError {
    #[error("{file}: {message}")]
    Toml { file: String, message: String },
    #[error("invalid setting: {0}")]
    Invalid(String),
}

impl Config {
    /// Parse TOML text (`file` names it in errors) over the defaults.
    pub fn from_toml(text: &str, file: &str) -> Result<Self, ConfigError> {
        let c: Config = toml::from_str(text).map_err(|e| ConfigError::Toml {
            file: file.to_string(),
            message: e.to_string(),
        })?;
        c.validate()?;
        Ok(c)
    }

    /// Reject values the models cannot work with.
    pub fn validate(&self) -> Result<(), ConfigError> {
        let n = (self.up[0].powi(2) + self.up[1].powi(2) + self.up[2].powi(2)).sqrt();
        if !(n.is_finite() && n > 1e-9) {
            return Err(ConfigError::Invalid(format!(
                "up direction {:?} has no length",
                self.up
            )));
        }
        let t = &self.thinness;
        for (name, v) in [
            ("force_n", t.force_n),
            ("youngs_modulus_n_mm2", t.youngs_modulus_n_mm2),
            ("allowed_deflection_mm", t.allowed_deflection_mm),
            ("effective_length_factor", t.effective_length_factor),
            (
                "preferred_tool_diameter_mm",
                self.thresholds.preferred_tool_diameter_mm,
            ),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return Err(ConfigError::Invalid(format!(
                    "{name} must be positive, got {v}"
                )));
            }
        }
        Ok(())
    }

    /// Whether `kind` is to be reported.
    pub fn reports(&self, kind: Kind) -> bool {
        (self.include.is_empty() || self.include.contains(&kind)) && !self.exclude.contains(&kind)
    }

    /// The unit up vector.
    pub fn up_unit(&self) -> thinwall_geom::Vector3 {
        thinwall_geom::Vector3::new(self.up[0], self.up[1], self.up[2]).normalize()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn toml_overrides_defaults_and_rejects_nonsense() {
        let c = Config::from_toml(
            "up = [1.0, 0.0, 0.0]\nexclude = [\"chamfer\"]\n[thinness]\nforce_n = 150.0\n",
            "t.toml",
        )
        .unwrap();
        assert_eq!(c.up, [1.0, 0.0, 0.0]);
        assert_eq!(c.thinness.force_n, 150.0);
        assert_eq!(c.thinness.youngs_modulus_n_mm2, 70_000.0);
        assert!(!c.reports(Kind::Chamfer) && c.reports(Kind::Rib));
        let e = Config::from_toml("[thinness]\nforce_n = -1.0\n", "t.toml").unwrap_err();
        assert!(e.to_string().contains("force_n"));
        let e = Config::from_toml("bogus = 1\n", "bad.toml").unwrap_err();
        assert!(e.to_string().starts_with("bad.toml:"));
        assert!(Config::from_toml("up = [0.0, 0.0, 0.0]\n", "t.toml").is_err());
    }
}
