//! Sequence rules as data: a TOML file a company can edit (`rules/default.toml`
//! holds the five rules of DOMAIN.md §4). Unknown keys, bad values and
//! contradictory rules are errors naming the file, the rule and its line.

use serde::{Deserialize, Serialize};
use thinwall_analysis::StiffnessKind;
use thiserror::Error;

/// The rules shipped with Thinwall.
pub const DEFAULT_RULES: &str = include_str!("../rules/default.toml");

/// What a rule puts between its two features.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Relation {
    /// `first` is machined before `second`.
    Before,
    /// The two are machined together.
    Simultaneous,
}

/// Which of the two goes first in a `before` rule.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum GoesFirst {
    #[default]
    First,
    Second,
}

/// How the two features must be connected (DOMAIN.md §3).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ConnectionCondition {
    #[default]
    Any,
    /// `first` is a leaf of `second` (on it or in it).
    FirstOnSecond,
    /// `second` is a leaf of `first`.
    SecondOnFirst,
    /// They cross.
    Crossing,
    /// No direct connection.
    None,
}

/// Where `first` is against `second` in the set-up (their tops along up).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum HeightCondition {
    #[default]
    Any,
    Higher,
    Lower,
    Level,
}

/// How a rib (`first`) runs on the wall it stands on (`second`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum OrientationCondition {
    #[default]
    Any,
    /// Along the wall, square to the wall's height.
    Horizontal,
    /// Along the wall's height.
    Vertical,
}

/// A rule as written in the file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawRule {
    name: String,
    priority: i64,
    first: Vec<String>,
    second: Vec<String>,
    #[serde(default)]
    connection: ConnectionCondition,
    #[serde(default)]
    height: HeightCondition,
    height_tolerance_mm: Option<f64>,
    #[serde(default)]
    orientation: OrientationCondition,
    orientation_tolerance_deg: Option<f64>,
    max_in_row: Option<usize>,
    relation: Relation,
    goes_first: Option<GoesFirst>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFile {
    rule: Vec<toml::Spanned<RawRule>>,
}

/// A checked rule.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Rule {
    pub name: String,
    /// Higher is tried first.
    pub priority: i64,
    pub first: Vec<StiffnessKind>,
    pub second: Vec<StiffnessKind>,
    pub connection: ConnectionCondition,
    pub height: HeightCondition,
    /// Tops closer than this are level, mm.
    pub height_tolerance_mm: f64,
    pub orientation: OrientationCondition,
    /// Within this of the wall's height direction is vertical, of square
    /// to it horizontal, degrees.
    pub orientation_tolerance_deg: f64,
    /// The rule holds only while the wall carries at most this many ribs
    /// of the same orientation.
    pub max_in_row: Option<usize>,
    pub relation: Relation,
    /// With `before`: which of the two goes first (`first` by default).
    pub goes_first: GoesFirst,
    /// Line of the rule in its file.
    pub line: usize,
}

/// The rules in force, highest priority first.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RuleSet {
    /// Where they came from (a path, or `default`).
    pub source: String,
    pub rules: Vec<Rule>,
}

/// A rule file that cannot be used.
#[derive(Debug, Error, PartialEq)]
pub enum RulesError {
    #[error("{file}: {message}")]
    Toml { file: String, message: String },
    #[error("{file}:{line}: rule '{rule}': {message}")]
    Invalid {
        file: String,
        rule: String,
        line: usize,
        message: String,
    },
}

impl RulesError {
    /// A stable machine-readable code for the error kind.
    pub fn code(&self) -> &'static str {
        match self {
            RulesError::Toml { .. } => "rules.toml",
            RulesError::Invalid { .. } => "rules.invalid",
        }
    }
}

/// Default height tolerance, mm.
const HEIGHT_TOLERANCE_MM: f64 = 0.5;
/// Default orientation tolerance, degrees.
const ORIENTATION_TOLERANCE_DEG: f64 = 30.0;

impl RuleSet {
    /// The shipped rules.
    pub fn default_rules() -> Self {
        Self::from_toml(DEFAULT_RULES, "default").expect("the shipped rules are valid")
    }

    /// Parse and check a rule file (`file` names it in errors).
    pub fn from_toml(text: &str, file: &str) -> Result<Self, RulesError> {
        let raw: RawFile = toml::from_str(text).map_err(|e| RulesError::Toml {
            file: file.to_string(),
            message: e.to_string().trim_end().to_string(),
        })?;
        let mut rules = Vec::new();
        for spanned in raw.rule {
            let line = 1 + text[..spanned.span().start.min(text.len())]
                .matches('\n')
                .count();
            let rule = check(spanned.into_inner(), line).map_err(|(rule, message)| {
                RulesError::Invalid {
                    file: file.to_string(),
                    rule,
                    line,
                    message,
                }
            })?;
            for other in &rules {
                let other: &Rule = other;
                let clash = if other.name == rule.name {
                    Some(format!("a second rule of this name (line {})", other.line))
                } else if other.priority == rule.priority {
                    Some(format!(
                        "the same priority {} as rule '{}' (line {}): their order would be arbitrary",
                        rule.priority, other.name, other.line
                    ))
                } else {
                    None
                };
                if let Some(message) = clash {
                    return Err(RulesError::Invalid {
                        file: file.to_string(),
                        rule: rule.name,
                        line,
                        message,
                    });
                }
            }
            rules.push(rule);
        }
        if rules.is_empty() {
            return Err(RulesError::Toml {
                file: file.to_string(),
                message: "no [[rule]] in the file".to_string(),
            });
        }
        rules.sort_by_key(|r| std::cmp::Reverse(r.priority));
        Ok(Self {
            source: file.to_string(),
            rules,
        })
    }
}

/// Check one rule; the error is the rule's name and what is wrong.
fn check(raw: RawRule, line: usize) -> Result<Rule, (String, String)> {
    let name = raw.name.clone();
    let fail = |m: String| Err((name.clone(), m));
    if raw.name.trim().is_empty() {
        return fail("empty name".to_string());
    }
    let kinds = |list: &[String], which: &str| -> Result<Vec<StiffnessKind>, String> {
        if list.is_empty() {
            return Err(format!("`{which}` names no kind"));
        }
        list.iter()
            .map(|k| {
                StiffnessKind::parse(k).ok_or_else(|| format!("`{which}`: unknown kind '{k}'"))
            })
            .collect()
    };
    let named = |m: String| (name.clone(), m);
    let first = kinds(&raw.first, "first").map_err(named)?;
    let second = kinds(&raw.second, "second").map_err(named)?;
    let tolerance = |v: Option<f64>, key: &str, default: f64, max: f64| match v {
        Some(t) if !(t.is_finite() && (0.0..=max).contains(&t)) => {
            Err(format!("`{key}` must be within 0..{max}, got {t}"))
        }
        Some(t) => Ok(t),
        None => Ok(default),
    };
    let height_tol = tolerance(
        raw.height_tolerance_mm,
        "height_tolerance_mm",
        HEIGHT_TOLERANCE_MM,
        f64::MAX,
    )
    .map_err(named)?;
    let orient_tol = tolerance(
        raw.orientation_tolerance_deg,
        "orientation_tolerance_deg",
        ORIENTATION_TOLERANCE_DEG,
        45.0,
    )
    .map_err(named)?;
    // Contradictions: conditions that can never hold together, or keys
    // that mean nothing without another.
    let on_wall = matches!(
        raw.connection,
        ConnectionCondition::FirstOnSecond | ConnectionCondition::SecondOnFirst
    );
    if raw.orientation != OrientationCondition::Any
        && raw.connection != ConnectionCondition::FirstOnSecond
    {
        return fail("`orientation` is judged against the wall `first` stands on: it needs connection = \"first_on_second\"".into());
    }
    if raw.height_tolerance_mm.is_some() && raw.height == HeightCondition::Any {
        return fail("`height_tolerance_mm` without a `height` condition".into());
    }
    if raw.orientation_tolerance_deg.is_some() && raw.orientation == OrientationCondition::Any {
        return fail("`orientation_tolerance_deg` without an `orientation` condition".into());
    }
    match raw.max_in_row {
        Some(0) => return fail("`max_in_row` must be 1 or more".into()),
        Some(_) if raw.orientation == OrientationCondition::Any => {
            return fail(
                "`max_in_row` counts ribs of the rule's orientation: it needs `orientation`".into(),
            )
        }
        _ => {}
    }
    if raw.goes_first.is_some() && raw.relation == Relation::Simultaneous {
        return fail("`goes_first` means nothing for a simultaneous rule".into());
    }
    if on_wall && raw.height == HeightCondition::Level {
        return fail("a feature on or in another is never level with it and connected so (height = \"level\" with a base-leaf connection)".into());
    }
    let same_kinds = first == second;
    if same_kinds
        && raw.relation == Relation::Before
        && raw.height == HeightCondition::Any
        && raw.connection == ConnectionCondition::Any
    {
        return fail("`before` between any two features of the same kinds with no condition orders every pair both ways".into());
    }
    Ok(Rule {
        name: raw.name,
        priority: raw.priority,
        first,
        second,
        connection: raw.connection,
        height: raw.height,
        height_tolerance_mm: height_tol,
        orientation: raw.orientation,
        orientation_tolerance_deg: orient_tol,
        max_in_row: raw.max_in_row,
        relation: raw.relation,
        goes_first: raw.goes_first.unwrap_or_default(),
        line,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_shipped_rules_are_the_five_of_domain_4() {
        let r = RuleSet::default_rules();
        let names: Vec<&str> = r.rules.iter().map(|r| r.name.as_str()).collect();
        assert_eq!(
            names,
            [
                "depression-with-its-wall",
                "flange-before-its-wall",
                "horizontal-rib-with-its-wall",
                "vertical-rib-before-its-wall",
                "top-down"
            ]
        );
        assert_eq!(r.rules[0].line, 6);
    }

    fn err(text: &str) -> String {
        RuleSet::from_toml(text, "r.toml").unwrap_err().to_string()
    }

    #[test]
    fn errors_name_the_file_the_rule_and_the_line() {
        let base = "[[rule]]\nname = \"a\"\npriority = 1\nfirst = [\"rib\"]\nsecond = [\"web\"]\nrelation = \"before\"\n";
        assert!(RuleSet::from_toml(base, "r.toml").is_ok());
        let e = err(&format!("{base}colour = \"red\"\n"));
        assert!(e.starts_with("r.toml") && e.contains("colour"), "{e}");
        let e = err(&base.replace("\"web\"", "\"girder\""));
        assert_eq!(e, "r.toml:1: rule 'a': `second`: unknown kind 'girder'");
        let e = err(&base.replace("\"before\"", "\"later\""));
        assert!(e.starts_with("r.toml") && e.contains("later"), "{e}");
        let two = format!("{base}\n[[rule]]\nname = \"b\"\npriority = 1\nfirst = [\"rib\"]\nsecond = [\"web\"]\nrelation = \"before\"\n");
        let e = err(&two);
        assert!(
            e.starts_with("r.toml:8: rule 'b': the same priority 1"),
            "{e}"
        );
        let e = err(&format!("{base}orientation = \"vertical\"\n"));
        assert!(e.contains("first_on_second"), "{e}");
        let e = err(&format!(
            "{base}height_tolerance_mm = -1.0\nheight = \"higher\"\n"
        ));
        assert!(e.contains("height_tolerance_mm"), "{e}");
        assert!(err("").contains("rule"), "an empty file is an error");
    }
}
