//! Regression checks of a user's parts: a recognition report compared with
//! a stored one (`thinwall check`), by what a person cares about —
//! features added or lost, a changed kind, sizes changed beyond a
//! tolerance, thinness, connections.
//!
//! Features are matched by where they are, not by id (ids renumber when a
//! feature appears or goes): a wall by its mid-plane (parallel, offset
//! within half its thickness, then the nearest point), a depression or
//! detail by the wall it is in (matched first) and its sizes. Both reports
//! are read as JSON (`thinwall/recognition`), so an expectation written by
//! an older version still compares as long as it has these fields.

use serde::Serialize;
use serde_json::Value;
use std::collections::BTreeSet;

/// Sizes closer than `absolute_mm + relative × |expected|` are the same.
#[derive(Clone, Copy, Debug)]
pub struct CheckTolerance {
    pub absolute_mm: f64,
    pub relative: f64,
}

impl Default for CheckTolerance {
    fn default() -> Self {
        Self {
            absolute_mm: 0.01,
            relative: 1e-3,
        }
    }
}

/// One difference between the expected recognition and the actual one.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Difference {
    Lost {
        expected: String,
        description: String,
    },
    Added {
        actual: String,
        description: String,
    },
    KindChanged {
        expected: String,
        actual: String,
        from: String,
        to: String,
    },
    SizeChanged {
        expected: String,
        actual: String,
        size: String,
        from: f64,
        to: f64,
    },
    ThinChanged {
        expected: String,
        actual: String,
        from: bool,
        to: bool,
    },
    ConnectionLost {
        connection: String,
    },
    ConnectionAdded {
        connection: String,
    },
}

/// `R2`, or `R2 (now R1)` where it was renumbered.
fn was(expected: &str, actual: &str) -> String {
    match expected == actual {
        true => expected.to_string(),
        false => format!("{expected} (now {actual})"),
    }
}

impl std::fmt::Display for Difference {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Difference::Lost {
                expected,
                description,
            } => {
                write!(f, "lost     {expected}: {description}")
            }
            Difference::Added {
                actual,
                description,
            } => write!(f, "added    {actual}: {description}"),
            Difference::KindChanged {
                expected,
                actual,
                from,
                to,
            } => {
                write!(f, "kind     {}: {from} → {to}", was(expected, actual))
            }
            Difference::SizeChanged {
                expected,
                actual,
                size,
                from,
                to,
            } => write!(
                f,
                "size     {}: {size} {from:.3} → {to:.3} mm",
                was(expected, actual)
            ),
            Difference::ThinChanged {
                expected,
                actual,
                from,
                to,
            } => {
                write!(f, "thin     {}: {from} → {to}", was(expected, actual))
            }
            Difference::ConnectionLost { connection } => {
                write!(f, "lost     connection {connection}")
            }
            Difference::ConnectionAdded { connection } => {
                write!(f, "added    connection {connection}")
            }
        }
    }
}

/// Why two reports cannot be compared.
#[derive(Debug, thiserror::Error, PartialEq)]
#[error("{which} is not a recognition report: {why}")]
pub struct NotAReport {
    pub which: &'static str,
    pub why: String,
}

const SIZES: [&str; 5] = ["thickness", "height", "length", "diameter", "width"];

/// The features of a report, as JSON objects.
fn features<'a>(report: &'a Value, which: &'static str) -> Result<&'a Vec<Value>, NotAReport> {
    report["stiffness_features"].as_array().ok_or(NotAReport {
        which,
        why: "no stiffness_features".into(),
    })
}

fn id(f: &Value) -> String {
    f["id"].as_str().unwrap_or("?").to_string()
}

fn kind(f: &Value) -> String {
    f["kind"].as_str().unwrap_or("?").to_string()
}

fn vec3(v: &Value) -> Option<[f64; 3]> {
    let a = v.as_array()?;
    Some([
        a.first()?.as_f64()?,
        a.get(1)?.as_f64()?,
        a.get(2)?.as_f64()?,
    ])
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// A feature in a line: its kind and sizes.
fn describe(f: &Value) -> String {
    let mut s = kind(f);
    for k in SIZES {
        if let Some(x) = f[k].as_f64() {
            s.push_str(&format!(", {k} {x:.2}"));
        }
    }
    if let Some(w) = f["wall"].as_str() {
        s.push_str(&format!(", in {w}"));
    }
    s
}

/// A wall's point half-way between its sides and its normal there: on the
/// mid-plane, or at a curved wall's mid-surface centre.
fn mid(f: &Value) -> Option<([f64; 3], [f64; 3])> {
    let m = &f["mid_plane"];
    if m.is_object() {
        return Some((vec3(&m["point"])?, vec3(&m["normal"])?));
    }
    let s = &f["mid_surface"];
    Some((vec3(&s["centre"])?, vec3(&s["normal"])?))
}

/// How far apart two walls are: offset of one mid-plane point from the
/// other's plane (when parallel), then a little of the in-plane distance.
fn wall_distance(e: &Value, a: &Value) -> Option<f64> {
    let (pe, ne) = mid(e)?;
    let (pa, na) = mid(a)?;
    if dot(ne, na).abs() < 0.9998 {
        return None; // more than about 1° apart
    }
    let d = [pe[0] - pa[0], pe[1] - pa[1], pe[2] - pa[2]];
    let offset = dot(d, na).abs();
    let half = 0.5
        * e["thickness"]
            .as_f64()
            .unwrap_or(0.0)
            .max(a["thickness"].as_f64().unwrap_or(0.0));
    (offset <= half.max(1e-3)).then(|| offset + 1e-3 * dot(d, d).sqrt())
}

/// How different two depressions or details are in size.
fn size_distance(e: &Value, a: &Value) -> f64 {
    SIZES
        .iter()
        .map(|k| match (e[k].as_f64(), a[k].as_f64()) {
            (Some(x), Some(y)) => (x - y).abs(),
            (None, None) => 0.0,
            _ => 1e6,
        })
        .sum()
}

/// Greedy matching by increasing distance; `None` where two cannot match.
fn pair(
    exp: &[usize],
    act: &[usize],
    dist: impl Fn(usize, usize) -> Option<f64>,
) -> Vec<(usize, usize)> {
    let mut cands: Vec<(f64, usize, usize)> = exp
        .iter()
        .flat_map(|&e| act.iter().map(move |&a| (e, a)))
        .filter_map(|(e, a)| dist(e, a).map(|d| (d, e, a)))
        .collect();
    cands.sort_by(|x, y| x.0.total_cmp(&y.0).then((x.1, x.2).cmp(&(y.1, y.2))));
    let (mut used_e, mut used_a) = (BTreeSet::new(), BTreeSet::new());
    let mut out = Vec::new();
    for (_, e, a) in cands {
        if !used_e.contains(&e) && !used_a.contains(&a) {
            used_e.insert(e);
            used_a.insert(a);
            out.push((e, a));
        }
    }
    out
}

/// The differences between an `expected` and an `actual` recognition
/// report, walls first, then what is in or on them, then connections.
pub fn compare(
    expected: &Value,
    actual: &Value,
    tol: CheckTolerance,
) -> Result<Vec<Difference>, NotAReport> {
    let (fe, fa) = (
        features(expected, "the expectation")?,
        features(actual, "the report")?,
    );
    let is_wall = |f: &Value| mid(f).is_some();
    let walls_e: Vec<usize> = (0..fe.len()).filter(|&i| is_wall(&fe[i])).collect();
    let walls_a: Vec<usize> = (0..fa.len()).filter(|&i| is_wall(&fa[i])).collect();
    let mut matched = pair(&walls_e, &walls_a, |e, a| wall_distance(&fe[e], &fa[a]));
    // The rest, within the walls they are in (matched), by size.
    let wall_of = |f: &Value, list: &Vec<Value>| {
        f["wall"]
            .as_str()
            .and_then(|w| list.iter().position(|g| g["id"].as_str() == Some(w)))
    };
    let others_e: Vec<usize> = (0..fe.len()).filter(|&i| !is_wall(&fe[i])).collect();
    let others_a: Vec<usize> = (0..fa.len()).filter(|&i| !is_wall(&fa[i])).collect();
    let wall_map = matched.clone();
    matched.extend(pair(&others_e, &others_a, |e, a| {
        let same_wall = match (wall_of(&fe[e], fe), wall_of(&fa[a], fa)) {
            (Some(we), Some(wa)) => wall_map.contains(&(we, wa)),
            (None, None) => true,
            _ => false,
        };
        (same_wall && kind(&fe[e]) == kind(&fa[a])).then(|| size_distance(&fe[e], &fa[a]))
    }));
    let mut out = Vec::new();
    let (me, ma): (BTreeSet<usize>, BTreeSet<usize>) = (
        matched.iter().map(|m| m.0).collect(),
        matched.iter().map(|m| m.1).collect(),
    );
    for i in (0..fe.len()).filter(|i| !me.contains(i)) {
        out.push(Difference::Lost {
            expected: id(&fe[i]),
            description: describe(&fe[i]),
        });
    }
    for i in (0..fa.len()).filter(|i| !ma.contains(i)) {
        out.push(Difference::Added {
            actual: id(&fa[i]),
            description: describe(&fa[i]),
        });
    }
    let mut pairs = matched.clone();
    pairs.sort();
    for &(e, a) in &pairs {
        let (x, y) = (&fe[e], &fa[a]);
        let names = || (id(x), id(y));
        if kind(x) != kind(y) {
            let (expected, actual) = names();
            out.push(Difference::KindChanged {
                expected,
                actual,
                from: kind(x),
                to: kind(y),
            });
        }
        for k in SIZES {
            if let (Some(from), Some(to)) = (x[k].as_f64(), y[k].as_f64()) {
                if (from - to).abs() > tol.absolute_mm + tol.relative * from.abs() {
                    let (expected, actual) = names();
                    out.push(Difference::SizeChanged {
                        expected,
                        actual,
                        size: k.into(),
                        from,
                        to,
                    });
                }
            }
        }
        if let (Some(from), Some(to)) = (x["thin"].as_bool(), y["thin"].as_bool()) {
            if from != to {
                let (expected, actual) = names();
                out.push(Difference::ThinChanged {
                    expected,
                    actual,
                    from,
                    to,
                });
            }
        }
    }
    connections(expected, actual, fe, fa, &matched, &mut out);
    Ok(out)
}

/// A report's connections as `(kind, ends)`, a crossing's ends sorted.
fn connection_list(report: &Value) -> Vec<(String, Vec<String>)> {
    report["connections"]
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(|c| {
            let k = c["kind"].as_str()?;
            let name = |v: &Value| v.as_str().map(str::to_string);
            let ends: Vec<String> = match k {
                "base_leaf" => vec![name(&c["base"])?, name(&c["leaf"])?],
                _ => c["features"].as_array()?.iter().filter_map(name).collect(),
            };
            Some((k.to_string(), ends))
        })
        .collect()
}

fn label(kind: &str, ends: &[String]) -> String {
    let mut ends = ends.to_vec();
    if kind != "base_leaf" {
        ends.sort();
    }
    format!("{kind} {}", ends.join(" "))
}

/// Connections: an expected one is lost unless the features it joins
/// matched features joined the same way (named as expected, with what
/// became of its ends); an actual one nobody expected is added.
fn connections(
    expected: &Value,
    actual: &Value,
    fe: &[Value],
    fa: &[Value],
    matched: &[(usize, usize)],
    out: &mut Vec<Difference>,
) {
    let now = |name: &str| -> Option<String> {
        let e = fe.iter().position(|f| f["id"].as_str() == Some(name))?;
        matched.iter().find(|m| m.0 == e).map(|m| id(&fa[m.1]))
    };
    let have: BTreeSet<String> = connection_list(actual)
        .iter()
        .map(|(k, ends)| label(k, ends))
        .collect();
    let mut seen = BTreeSet::new();
    for (k, ends) in connection_list(expected) {
        let mapped: Option<Vec<String>> = ends.iter().map(|e| now(e)).collect();
        if let Some(m) = &mapped {
            let l = label(&k, m);
            if have.contains(&l) {
                seen.insert(l);
                continue;
            }
        }
        let fate: Vec<String> = ends
            .iter()
            .filter_map(|e| match now(e) {
                None => Some(format!("{e} lost")),
                Some(n) if n != *e => Some(format!("{e} now {n}")),
                Some(_) => None,
            })
            .collect();
        let mut connection = label(&k, &ends);
        if !fate.is_empty() {
            connection.push_str(&format!(" ({})", fate.join(", ")));
        }
        out.push(Difference::ConnectionLost { connection });
    }
    for l in have.difference(&seen) {
        out.push(Difference::ConnectionAdded {
            connection: l.clone(),
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn rib(id: &str, y: f64, length: f64) -> Value {
        json!({"id": id, "kind": "rib", "thin": true, "thickness": 1.2, "height": 23.0,
               "length": length, "mid_plane": {"point": [100.0, y, 13.0], "normal": [0.0, 1.0, 0.0]}})
    }

    fn report(features: Vec<Value>, connections: Vec<Value>) -> Value {
        json!({"stiffness_features": features, "connections": connections})
    }

    #[test]
    fn renumbered_features_match_by_place_and_changes_are_named() {
        let web = json!({"id": "W1", "kind": "web", "thin": true, "thickness": 2.0, "height": 24.0,
                         "length": 98.0, "mid_plane": {"point": [100.0, 75.0, 1.0], "normal": [0.0, 0.0, 1.0]}});
        let hole = |id: &str, wall: &str| json!({"id": id, "kind": "hole", "wall": wall, "diameter": 19.0, "height": 19.0});
        let conn = |b: &str, l: &str| json!({"kind": "base_leaf", "base": b, "leaf": l});
        let expected = report(
            vec![
                web.clone(),
                rib("R1", 50.0, 197.0),
                rib("R2", 100.0, 197.0),
                hole("H1", "R2"),
            ],
            vec![conn("W1", "R1"), conn("W1", "R2")],
        );
        // R1 gone: R2 is now R1 (with its hole), and a little longer.
        let actual = report(
            vec![web, rib("R1", 100.0, 199.0), hole("H1", "R1")],
            vec![conn("W1", "R1")],
        );
        let d = compare(&expected, &actual, CheckTolerance::default()).unwrap();
        let text: Vec<String> = d.iter().map(|x| x.to_string()).collect();
        assert!(
            d.contains(&Difference::Lost {
                expected: "R1".into(),
                description: "rib, thickness 1.20, height 23.00, length 197.00".into()
            }),
            "{text:?}"
        );
        assert!(
            d.iter().any(
                |x| matches!(x, Difference::SizeChanged { expected, actual, size, .. }
            if expected == "R2" && actual == "R1" && size == "length")
            ),
            "{text:?}"
        );
        assert!(
            d.contains(&Difference::ConnectionLost {
                connection: "base_leaf W1 R1 (R1 lost)".into()
            }),
            "{text:?}"
        );
        // The hole followed its wall: no difference for it.
        assert!(!text.iter().any(|t| t.contains("H1")), "{text:?}");
        assert_eq!(d.len(), 3, "{text:?}");
        // A report against itself: nothing.
        assert!(compare(&expected, &expected, CheckTolerance::default())
            .unwrap()
            .is_empty());
    }

    #[test]
    fn a_file_that_is_not_a_report_is_refused() {
        let e = compare(
            &json!({"x": 1}),
            &report(vec![], vec![]),
            CheckTolerance::default(),
        );
        assert_eq!(e.unwrap_err().which, "the expectation");
    }
}
