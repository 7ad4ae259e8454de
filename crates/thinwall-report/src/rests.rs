//! Rests a planner reads as places, not as a line per layer: a field that no
//! tool of the library reaches usually repeats down the layers (a slot
//! narrower than the smallest end mill, a corner sharper than its radius).
//! Rests with the same outline (area to 0.01 mm², centroid to 0.01 mm) are
//! one place, with the layers it repeats on; a summary line counts them.
//! Where a tool would take part of a rest but its share is under the
//! library's minimum, the place says which tool and how much.

use std::fmt::Write;
use thinwall_ops::operations::Rest;

/// One place no tool reaches and the layers (0-based) it repeats on.
#[derive(Clone, Debug, PartialEq)]
pub struct RestPlace {
    pub area_mm2: f64,
    pub width_mm: f64,
    /// The outline's centroid in the removal frame, mm.
    pub at: [f64; 2],
    pub layers: Vec<usize>,
    /// The tool that would take part of it and that part, mm², under the
    /// minimum share.
    pub below_minimum: Option<(String, f64)>,
}

/// A rest's area and centroid (0.01 mm², 0.01 mm) and the share under
/// the minimum (tool, 0.01 mm²).
type PlaceKey = ([i64; 3], Option<(String, i64)>);

/// Rests grouped by outline, in the order they first appear.
pub fn places(rests: &[Rest]) -> Vec<RestPlace> {
    let mut out: Vec<(PlaceKey, RestPlace)> = Vec::new();
    for r in rests {
        let at = centroid(&r.outlines);
        let below = r
            .below_minimum
            .as_ref()
            .map(|b| (b.tool.clone(), b.area_mm2));
        let key = (
            [
                (r.area_mm2 * 100.0).round() as i64,
                (at[0] * 100.0).round() as i64,
                (at[1] * 100.0).round() as i64,
            ],
            below
                .as_ref()
                .map(|b| (b.0.clone(), (b.1 * 100.0).round() as i64)),
        );
        match out.iter_mut().find(|(k, _)| *k == key) {
            Some((_, p)) => p.layers.push(r.layer),
            None => out.push((
                key,
                RestPlace {
                    area_mm2: r.area_mm2,
                    width_mm: r.width_mm,
                    at,
                    layers: vec![r.layer],
                    below_minimum: below,
                },
            )),
        }
    }
    out.into_iter().map(|(_, p)| p).collect()
}

/// The rest lines of a set-up's text: a summary, then one line per place.
/// `min_share_mm2` is the library's minimum share.
pub fn write_rests(s: &mut String, rests: &[Rest], min_share_mm2: f64) {
    if rests.is_empty() {
        return;
    }
    let places = places(rests);
    let layers = {
        let mut l: Vec<usize> = rests.iter().map(|r| r.layer).collect();
        l.sort_unstable();
        l.dedup();
        l.len()
    };
    let total: f64 = rests.iter().map(|r| r.area_mm2).sum();
    let below: f64 = rests
        .iter()
        .filter_map(|r| r.below_minimum.as_ref())
        .map(|b| b.area_mm2)
        .sum();
    let _ = writeln!(
        s,
        "rest: {} field(s) on {} layer(s) in {} place(s), {:.2} mm² of layer area: {:.2} mm² no tool of the library reaches, {:.2} mm² a tool would take but under the minimum share ({:.1} mm² per field and layer)",
        rests.len(),
        layers,
        places.len(),
        total,
        total - below,
        below,
        min_share_mm2
    );
    for p in &places {
        let under = p
            .below_minimum
            .as_ref()
            .map(|(tool, a)| format!("; {tool} would take {a:.2} mm² of it, under the minimum"))
            .unwrap_or_default();
        let _ = writeln!(
            s,
            "  {:.2} mm², {:.2} mm wide, at ({:.2}, {:.2}): layer(s) {}{under}",
            p.area_mm2,
            p.width_mm,
            p.at[0],
            p.at[1],
            ranges(&p.layers)
        );
    }
}

/// Layers 1-based as ranges: `1–3, 5`.
fn ranges(layers: &[usize]) -> String {
    let mut sorted = layers.to_vec();
    sorted.sort_unstable();
    sorted.dedup();
    let mut parts: Vec<String> = Vec::new();
    let mut k = 0;
    while k < sorted.len() {
        let start = sorted[k];
        while k + 1 < sorted.len() && sorted[k + 1] == sorted[k] + 1 {
            k += 1;
        }
        parts.push(if sorted[k] == start {
            format!("{}", start + 1)
        } else {
            format!("{}–{}", start + 1, sorted[k] + 1)
        });
        k += 1;
    }
    parts.join(", ")
}

/// The centroid of outlines (geo's: by area, by length where they enclose
/// none), mm.
fn centroid(outlines: &[Vec<[f64; 2]>]) -> [f64; 2] {
    use geo::Centroid;
    let region = geo::MultiPolygon::new(
        outlines
            .iter()
            .map(|ring| geo::Polygon::new(ring.iter().map(|p| (p[0], p[1])).collect(), vec![]))
            .collect(),
    );
    region.centroid().map_or([0.0, 0.0], |c| [c.x(), c.y()])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(layer: usize, x: f64) -> Rest {
        Rest {
            layer,
            field: 0,
            area_mm2: 1.0,
            width_mm: 1.0,
            outlines: vec![vec![[x, 0.0], [x + 1.0, 0.0], [x + 1.0, 1.0], [x, 1.0]]],
            below_minimum: None,
        }
    }

    #[test]
    fn a_rest_repeated_down_the_layers_is_one_place() {
        let rests = [
            square(0, 0.0),
            square(1, 0.0),
            square(2, 0.0),
            square(4, 0.0),
            square(1, 5.0),
        ];
        let p = places(&rests);
        assert_eq!(p.len(), 2);
        assert_eq!(p[0].layers, vec![0, 1, 2, 4]);
        assert!((p[0].at[0] - 0.5).abs() < 1e-12 && (p[0].at[1] - 0.5).abs() < 1e-12);
        assert_eq!(ranges(&p[0].layers), "1–3, 5");
        let mut s = String::new();
        write_rests(&mut s, &rests, 20.0);
        assert!(
            s.starts_with("rest: 5 field(s) on 4 layer(s) in 2 place(s), 5.00 mm² of layer area: 5.00 mm² no tool"),
            "{s}"
        );
        assert_eq!(s.lines().count(), 3, "{s}");
    }

    #[test]
    fn a_rest_a_tool_would_take_under_the_minimum_says_so_apart() {
        let mut under = square(1, 0.0);
        under.below_minimum = Some(thinwall_ops::rest::BelowMinimum {
            tool: "EM4".into(),
            area_mm2: 0.6,
        });
        let rests = [square(0, 0.0), under];
        let p = places(&rests);
        assert_eq!(p.len(), 2, "{p:?}");
        let mut s = String::new();
        write_rests(&mut s, &rests, 20.0);
        assert!(
            s.contains("1.40 mm² no tool of the library reaches, 0.60 mm² a tool would take"),
            "{s}"
        );
        assert!(
            s.contains("EM4 would take 0.60 mm² of it, under the minimum"),
            "{s}"
        );
    }
}
