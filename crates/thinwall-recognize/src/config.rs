//! Recognition settings: the set-up, the sizing model's parameters and the
//! recognizers' thresholds. Defaults are Popma's (App. A.2) and
//! `DOMAIN.md`; every value can be overridden from a TOML file or flags.

use serde::{Deserialize, Serialize};
use thinwall_analysis::StiffnessKind as Kind;
use thiserror::Error;

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
    /// Largest draft of a wall's side, degrees: sides leaning towards each
    /// other by up to this each still make a wall (0 for none).
    pub max_draft_deg: f64,
    /// A wall's narrowest in-plane width must exceed its thickness times this.
    pub min_width_to_thickness: f64,
    /// A wall's height and length must each be at least its thickness times
    /// this; a squatter slab (a clamping block, a letter stroke) is material
    /// a wall may stand on, not a wall itself.
    pub min_extent_to_thickness: f64,
    /// Preferred tool diameter, mm (large holes, step separation).
    pub preferred_tool_diameter_mm: f64,
    /// A hole is large when its height exceeds this many tool diameters.
    pub large_hole_factor: f64,
    /// Largest width of a chamfer face, mm.
    pub chamfer_max_width_mm: f64,
    /// Deepest engraving (or highest embossing) recognized as lettering, mm.
    pub engraving_max_depth_mm: f64,
}

impl Default for Thresholds {
    fn default() -> Self {
        Self {
            parallel_angle_deg: 0.3,
            max_draft_deg: 5.0,
            min_width_to_thickness: 1.0,
            min_extent_to_thickness: 3.0,
            preferred_tool_diameter_mm: 12.0,
            large_hole_factor: 1.5,
            chamfer_max_width_mm: 10.0,
            engraving_max_depth_mm: 3.0,
        }
    }
}

/// Everything recognition needs besides the part and its set-up (which
/// the analysis context holds).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Config {
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
#[derive(Debug, Error, PartialEq)]
pub enum ConfigError {
    #[error("{file}: {message}")]
    Toml { file: String, message: String },
    #[error("invalid setting: {name} must be a positive finite number, got {value}")]
    NotPositive { name: &'static str, value: f64 },
    #[error("invalid setting: {name} must be below {limit}, got {value}")]
    TooLarge {
        name: &'static str,
        value: f64,
        limit: f64,
    },
    #[error("invalid setting: {kind} is both included and excluded")]
    IncludedAndExcluded { kind: Kind },
}

impl ConfigError {
    /// A stable machine-readable code for the error kind.
    pub fn code(&self) -> &'static str {
        match self {
            ConfigError::Toml { .. } => "config_file",
            ConfigError::NotPositive { .. } => "not_positive",
            ConfigError::TooLarge { .. } => "too_large",
            ConfigError::IncludedAndExcluded { .. } => "included_and_excluded",
        }
    }
}

impl Config {
    /// Parse TOML text (`file` names it in errors) over the defaults.
    pub fn from_toml(text: &str, file: &str) -> Result<Self, ConfigError> {
        let table: toml::Table = toml::from_str(text).map_err(|e| ConfigError::Toml {
            file: file.to_string(),
            message: e.to_string(),
        })?;
        Self::from_table(table, file)
    }

    /// Settings from an already parsed TOML table (`file` names it in errors).
    pub fn from_table(table: toml::Table, file: &str) -> Result<Self, ConfigError> {
        let c = Config::deserialize(table).map_err(|e| ConfigError::Toml {
            file: file.to_string(),
            message: e.to_string(),
        })?;
        c.validate()?;
        Ok(c)
    }

    /// Reject values the models cannot work with.
    pub fn validate(&self) -> Result<(), ConfigError> {
        let (t, h) = (&self.thinness, &self.thresholds);
        for (name, value) in [
            ("force_n", t.force_n),
            ("youngs_modulus_n_mm2", t.youngs_modulus_n_mm2),
            ("allowed_deflection_mm", t.allowed_deflection_mm),
            ("effective_length_factor", t.effective_length_factor),
            ("parallel_angle_deg", h.parallel_angle_deg),
            ("min_width_to_thickness", h.min_width_to_thickness),
            ("min_extent_to_thickness", h.min_extent_to_thickness),
            ("preferred_tool_diameter_mm", h.preferred_tool_diameter_mm),
            ("large_hole_factor", h.large_hole_factor),
            ("chamfer_max_width_mm", h.chamfer_max_width_mm),
            ("engraving_max_depth_mm", h.engraving_max_depth_mm),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(ConfigError::NotPositive { name, value });
            }
        }
        if !(h.max_draft_deg.is_finite() && (0.0..=15.0).contains(&h.max_draft_deg)) {
            return Err(ConfigError::TooLarge {
                name: "max_draft_deg",
                value: h.max_draft_deg,
                limit: 15.0,
            });
        }
        if h.parallel_angle_deg >= 45.0 {
            return Err(ConfigError::TooLarge {
                name: "parallel_angle_deg",
                value: h.parallel_angle_deg,
                limit: 45.0,
            });
        }
        if let Some(&kind) = self.include.iter().find(|k| self.exclude.contains(k)) {
            return Err(ConfigError::IncludedAndExcluded { kind });
        }
        Ok(())
    }

    /// Whether `kind` is to be reported.
    pub fn reports(&self, kind: Kind) -> bool {
        (self.include.is_empty() || self.include.contains(&kind)) && !self.exclude.contains(&kind)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn toml_overrides_defaults_and_rejects_nonsense() {
        let c = Config::from_toml(
            "exclude = [\"chamfer\"]\n[thinness]\nforce_n = 150.0\n",
            "t.toml",
        )
        .unwrap();
        assert_eq!(c.thinness.force_n, 150.0);
        assert_eq!(c.thinness.youngs_modulus_n_mm2, 70_000.0);
        assert!(!c.reports(Kind::Chamfer) && c.reports(Kind::Rib));
        let e = Config::from_toml("[thinness]\nforce_n = -1.0\n", "t.toml").unwrap_err();
        assert!(e.to_string().contains("force_n"));
        assert_eq!(e.code(), "not_positive");
        let e = Config::from_toml("bogus = 1\n", "bad.toml").unwrap_err();
        assert!(e.to_string().starts_with("bad.toml:"));
        // `up` belongs to the set-up, not to recognition settings.
        assert_eq!(
            Config::from_toml("up = [0.0, 0.0, 1.0]\n", "t.toml")
                .unwrap_err()
                .code(),
            "config_file"
        );
        for bad in [
            "[thresholds]\nparallel_angle_deg = -1.0\n",
            "[thresholds]\nchamfer_max_width_mm = -5.0\n",
            "[thinness]\nforce_n = inf\n",
        ] {
            let e = Config::from_toml(bad, "t.toml").unwrap_err();
            assert_eq!(e.code(), "not_positive", "{bad}");
        }
        let e = Config::from_toml("[thresholds]\nparallel_angle_deg = 60.0\n", "t.toml");
        assert_eq!(e.unwrap_err().code(), "too_large");
        let both = "include = [\"hole\"]\nexclude = [\"hole\"]\n";
        let e = Config::from_toml(both, "t.toml").unwrap_err();
        assert_eq!(e.code(), "included_and_excluded");
    }
}
