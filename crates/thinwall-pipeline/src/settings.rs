//! The settings file of a run (TOML): the set-up's `up` at the top level,
//! beside the recognition settings (`docs/RECOGNITION.md`).

use thinwall_recognize::{Config, ConfigError};

/// A parsed settings file.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Settings {
    /// The set-up's up direction, when the file gives one.
    pub up: Option<[f64; 3]>,
    pub config: Config,
}

impl Settings {
    /// Parse TOML text (`file` names it in errors) over the defaults.
    pub fn from_toml(text: &str, file: &str) -> Result<Self, ConfigError> {
        let mut table: toml::Table = toml::from_str(text).map_err(|e| ConfigError::Toml {
            file: file.to_string(),
            message: e.to_string(),
        })?;
        let up = match table.remove("up") {
            None => None,
            Some(v) => Some(v.try_into::<[f64; 3]>().map_err(|e| ConfigError::Toml {
                file: file.to_string(),
                message: format!("up: {e}"),
            })?),
        };
        Ok(Self {
            up,
            config: Config::from_table(table, file)?,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn up_goes_to_the_setup_and_the_rest_to_recognition() {
        let s = Settings::from_toml(
            "up = [1.0, 0.0, 0.0]\n[thinness]\nforce_n = 150.0\n",
            "t.toml",
        )
        .unwrap();
        assert_eq!(s.up, Some([1.0, 0.0, 0.0]));
        assert_eq!(s.config.thinness.force_n, 150.0);
        let e = Settings::from_toml("up = [1.0, 0.0]\n", "t.toml").unwrap_err();
        assert!(e.to_string().starts_with("t.toml: up"), "{e}");
        let e = Settings::from_toml("bogus = 1\n", "bad.toml").unwrap_err();
        assert!(e.to_string().starts_with("bad.toml:"), "{e}");
        assert_eq!(
            Settings::from_toml("", "t.toml").unwrap(),
            Settings::default()
        );
    }
}
