//! Tool selection with rest areas (Matsuda & Kimura §4.3–4.4): per cutter
//! field, the largest end mill that fits, the area it clears (the field
//! opened by its radius: the tool's centre kept a radius off every part
//! contour, free to overhang blank contours), and the rest left for the
//! next smaller tool, down the library. Smaller disks open a superset, so
//! each tool clears what the larger ones left and more; what the smallest
//! leaves is the rest no tool reaches, with its size and outline.
//!
//! Disks are 128-gons with their corners on the circle
//! ([`thinwall_access::reach::floor::disk`]): an area bounded by a tool's
//! arc comes out within about 0.1 % of the circle's.

use crate::layers::{CutterField, EdgeKind};
use crate::tools::CuttingTool;
use geo::{Area, BooleanOps, MultiPolygon};
use serde::Serialize;
use thinwall_access::reach::floor::{disk, grown, union_all};

/// One tool's share of a field.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ToolShare {
    pub tool: String,
    pub diameter_mm: f64,
    /// What this tool clears that the larger ones left, mm².
    pub cleared_mm2: f64,
}

/// A field's tools, largest first, and what none of them reaches.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct FieldTools {
    pub shares: Vec<ToolShare>,
    /// Left by the smallest tool, mm².
    pub rest_mm2: f64,
    /// Its outlines (x, y in the removal frame), mm.
    pub rest: Vec<Vec<[f64; 2]>>,
    /// The widest piece of the rest, mm (0 when none).
    pub rest_width_mm: f64,
}

/// The field as a polygon, and its part and blank edges as segments.
struct Shape {
    region: MultiPolygon<f64>,
    part: Vec<[[f64; 2]; 2]>,
    blank: Vec<[[f64; 2]; 2]>,
}

fn shape(f: &CutterField) -> Shape {
    let mut part = Vec::new();
    let mut blank = Vec::new();
    for c in std::iter::once(&f.outer).chain(&f.islands) {
        for (seg, kind) in straight_runs(&c.points, &c.edges) {
            match kind {
                EdgeKind::Part => part.push(seg),
                EdgeKind::Blank => blank.push(seg),
            }
        }
    }
    Shape {
        region: MultiPolygon::new(vec![f.polygon()]),
        part,
        blank,
    }
}

/// A closed contour's edges with runs of collinear edges of one kind
/// joined (cell boundaries split a straight contour into many edges; each
/// grown edge costs a boolean): (segment, kind).
fn straight_runs(points: &[[f64; 2]], kinds: &[EdgeKind]) -> Vec<([[f64; 2]; 2], EdgeKind)> {
    let n = points.len();
    if n < 2 {
        return Vec::new();
    }
    let turns = |k: usize| {
        // Whether the contour turns (or changes kind) at point k.
        let (a, b, c) = (points[(k + n - 1) % n], points[k], points[(k + 1) % n]);
        let (u, v) = ([b[0] - a[0], b[1] - a[1]], [c[0] - b[0], c[1] - b[1]]);
        let cross = u[0] * v[1] - u[1] * v[0];
        let dot = u[0] * v[0] + u[1] * v[1];
        let scale = u[0].hypot(u[1]) * v[0].hypot(v[1]);
        kinds[(k + n - 1) % n] != kinds[k] || cross.abs() > 1e-9 * scale || dot <= 0.0
    };
    let corners: Vec<usize> = (0..n).filter(|&k| turns(k)).collect();
    if corners.is_empty() {
        return (0..n)
            .map(|k| ([points[k], points[(k + 1) % n]], kinds[k]))
            .collect();
    }
    (0..corners.len())
        .map(|i| {
            let (a, b) = (corners[i], corners[(i + 1) % corners.len()]);
            ([points[a], points[b]], kinds[a])
        })
        .collect()
}

/// Where a tool of radius `r` clears the field: its centre anywhere in
/// the field or past a blank contour, at least `r` from every part
/// contour; the positions grown back by `r`, within the field.
fn cleared(s: &Shape, r: f64) -> MultiPolygon<f64> {
    let d = disk(r);
    let grow = |segs: &[[[f64; 2]; 2]]| -> Vec<MultiPolygon<f64>> {
        segs.iter()
            .filter_map(|s| grown(s, &d))
            .map(|p| MultiPolygon::new(vec![p]))
            .collect()
    };
    let mut domain = grow(&s.blank);
    domain.push(s.region.clone());
    let free = union_all(domain).difference(&union_all(grow(&s.part)));
    if free.unsigned_area() <= 0.0 {
        return MultiPolygon::new(vec![]);
    }
    let mut pieces = vec![free.clone()];
    for p in &free {
        for ring in std::iter::once(p.exterior()).chain(p.interiors()) {
            let mut pts: Vec<[f64; 2]> = ring.coords().map(|c| [c.x, c.y]).collect();
            pts.pop();
            let kinds = vec![EdgeKind::Part; pts.len()];
            for (seg, _) in straight_runs(&pts, &kinds) {
                if let Some(g) = grown(&seg, &d) {
                    pieces.push(MultiPolygon::new(vec![g]));
                }
            }
        }
    }
    s.region.intersection(&union_all(pieces))
}

/// The area a tool of diameter `d` may seem to clear or leave from its
/// disk being a polygon alone: twice the 128-gon's shortfall of the
/// circle's area (about 4·10⁻⁴ of it). A share or a rest below it is noise,
/// not an operation.
fn noise(d: f64) -> f64 {
    2.0 * 4e-4 * std::f64::consts::PI * (0.5 * d).powi(2)
}

/// The tools for one field: `mills` largest first; a tool that clears
/// nothing new is skipped, and the descent stops once nothing is left
/// (within 1e-9 of the field).
pub fn select(field: &CutterField, mills: &[&CuttingTool]) -> FieldTools {
    let s = shape(field);
    let area = s.region.unsigned_area();
    let tiny = 1e-9 * area.max(1.0);
    let mut shares = Vec::new();
    let mut done = MultiPolygon::new(vec![]);
    let mut done_area = 0.0;
    for t in mills {
        if area - done_area <= tiny {
            break;
        }
        let c = cleared(&s, 0.5 * t.diameter_mm);
        let now = c.unsigned_area().max(done_area);
        // Slivers the larger tools' polygons left count as noise too.
        let first = shares
            .first()
            .map_or(t.diameter_mm, |s: &ToolShare| s.diameter_mm);
        if now - done_area > tiny.max(noise(first)) {
            shares.push(ToolShare {
                tool: t.name.clone(),
                diameter_mm: t.diameter_mm,
                cleared_mm2: now - done_area,
            });
            done = c;
            done_area = now;
        }
    }
    // Measured on the difference itself: the layer check (cleared + rest
    // = section) then compares two booleans, not one number with itself.
    let rest = s.region.difference(&done);
    let rest_mm2 = rest.unsigned_area();
    // Less than the disks' polygon error: no rest worth a word.
    let largest = shares.first().map_or(0.0, |s| s.diameter_mm);
    let tiny = tiny.max(noise(largest));
    FieldTools {
        shares,
        rest_mm2,
        rest_width_mm: if rest_mm2 > tiny {
            2.0 * thinwall_analysis::polygon::inscribed_radius(&rest)
        } else {
            0.0
        },
        rest: if rest_mm2 > tiny {
            rest.iter()
                .map(|p| p.exterior().coords().map(|c| [c.x, c.y]).collect())
                .collect()
        } else {
            Vec::new()
        },
    }
}
