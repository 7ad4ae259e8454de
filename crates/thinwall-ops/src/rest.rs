//! Tool selection with rest areas (Matsuda & Kimura §4.3–4.4): per cutter
//! field, the largest end mill that fits, the area it clears (the field
//! opened by its radius: the tool's centre kept a radius off every part
//! contour, free to overhang blank contours), and the rest left for the
//! next smaller tool, down the library. Smaller disks open a superset, so
//! each tool clears what the larger ones left and more; what the smallest
//! leaves is the rest no tool reaches, with its size and outline.
//!
//! Each share is split into Popma's regions (§4.3.4–4.3.5): a boundary
//! region along the product, a full-cut region and a roughing (rest)
//! region, and the field gets its product adjacency class (side, bottom).
//!
//! Disks are 128-gons with their corners on the circle
//! ([`thinwall_access::reach::floor::disk`]): an area bounded by a tool's
//! arc comes out within about 0.1 % of the circle's. Contours are grown by
//! them as strokes ([`thinwall_access::reach::stroke`]): each chain of one
//! kind in one boolean, the same region as a capsule per edge.

use crate::layers::{CutterField, EdgeKind};
use crate::tools::CuttingTool;
use geo::{Area, MultiPolygon};
use serde::Serialize;
use thinwall_access::reach::floor::{disk, opened};
use thinwall_access::reach::stroke::stroked;
use thinwall_analysis::boolean::{difference, intersection, intersection_near, union, Near};
use thinwall_analysis::polygon::without_slivers;

/// One tool's share of a field, and its regions (Popma §4.3.4): the
/// three add up to `cleared_mm2`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ToolShare {
    pub tool: String,
    pub diameter_mm: f64,
    /// What this tool clears that the larger ones left, mm².
    pub cleared_mm2: f64,
    /// Within the finishing stepover of a part contour: down milling,
    /// reduced stepover, mm².
    pub boundary_mm2: f64,
    /// Where the material it meets is at least as wide as the tool but
    /// narrower than d + a_e, so it cuts its full width: reduced depth of
    /// cut, mm².
    pub full_cut_mm2: f64,
    /// The rest of its share, roughing conditions (Popma's rest region),
    /// mm².
    pub roughing_mm2: f64,
    /// Of its share, what lies over a floor of the part (the bottom
    /// layer's finishing pass), mm².
    pub floor_mm2: f64,
    /// Its first share in the field (roughing), or a smaller tool's in
    /// what larger ones left (rest machining, semi-finishing).
    pub first: bool,
}

/// How a tool gets into a field.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Entry {
    /// Over a blank contour, from outside the stock.
    FromOutside,
    /// The field is closed by the part: a ramp or a helix down.
    Ramp,
}

/// Where a field lies against the product (Popma §5.3's product
/// adjacency class): along part contours (`side`), over a floor
/// (`bottom`), both or neither.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Adjacency {
    None,
    Side,
    Bottom,
    SideAndBottom,
}

impl Adjacency {
    /// The class of a place along part contours (`side`) and over a floor
    /// (`bottom`).
    pub fn of(side: bool, bottom: bool) -> Self {
        match (side, bottom) {
            (true, true) => Adjacency::SideAndBottom,
            (true, false) => Adjacency::Side,
            (false, true) => Adjacency::Bottom,
            (false, false) => Adjacency::None,
        }
    }

    pub fn side(self) -> bool {
        matches!(self, Adjacency::Side | Adjacency::SideAndBottom)
    }

    pub fn bottom(self) -> bool {
        matches!(self, Adjacency::Bottom | Adjacency::SideAndBottom)
    }

    /// Both places together.
    pub fn with(self, other: Adjacency) -> Self {
        Adjacency::of(self.side() || other.side(), self.bottom() || other.bottom())
    }
}

/// Part of a field's rest that `tool` would take, left because it is
/// under the minimum share a tool must take to run there.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct BelowMinimum {
    pub tool: String,
    pub area_mm2: f64,
}

/// A field's tools, largest first, and what none of them reaches.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct FieldTools {
    pub adjacency: Adjacency,
    pub entry: Entry,
    pub shares: Vec<ToolShare>,
    /// Left by the smallest tool, mm².
    pub rest_mm2: f64,
    /// Its outlines (x, y in the removal frame), mm.
    pub rest: Vec<Vec<[f64; 2]>>,
    /// The widest piece of the rest, mm (0 when none).
    pub rest_width_mm: f64,
    /// Of the rest, what a tool would reach but the share it would take
    /// is under the library's minimum (`min_share_mm2`): that tool.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub below_minimum: Option<BelowMinimum>,
    /// The hole (machining feature id) whose drill takes the whole field
    /// instead of the end mills.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub drilled: Option<String>,
}

impl FieldTools {
    /// A field a drill takes whole: no end mill, no rest.
    pub fn drilled(hole: &str) -> Self {
        Self {
            adjacency: Adjacency::Side,
            entry: Entry::Ramp,
            shares: Vec::new(),
            rest_mm2: 0.0,
            rest: Vec::new(),
            rest_width_mm: 0.0,
            below_minimum: None,
            drilled: Some(hole.to_string()),
        }
    }
}

/// The field as a polygon, and its part and blank contours as chains.
struct Shape {
    region: MultiPolygon<f64>,
    part: Vec<Vec<[f64; 2]>>,
    blank: Vec<Vec<[f64; 2]>>,
}

fn shape(f: &CutterField) -> Shape {
    let mut part = Vec::new();
    let mut blank = Vec::new();
    for c in std::iter::once(&f.outer).chain(&f.islands) {
        for (chain, kind) in chains(&c.points, &c.edges) {
            match kind {
                EdgeKind::Part => part.push(chain),
                EdgeKind::Blank => blank.push(chain),
            }
        }
    }
    Shape {
        region: MultiPolygon::new(vec![f.polygon()]),
        part,
        blank,
    }
}

/// A closed contour's edges (`kinds[k]`: from corner k to k + 1) as
/// chains of one kind, each a maximal run of consecutive edges; a contour
/// of one kind is one chain, closed (its first corner repeated).
fn chains(points: &[[f64; 2]], kinds: &[EdgeKind]) -> Vec<(Vec<[f64; 2]>, EdgeKind)> {
    let n = points.len();
    if n < 2 {
        return Vec::new();
    }
    let Some(start) = (0..n).find(|&k| kinds[k] != kinds[(k + n - 1) % n]) else {
        let mut ring = points.to_vec();
        ring.push(points[0]);
        return vec![(ring, kinds[0])];
    };
    let mut out = Vec::new();
    let mut chain = vec![points[start]];
    for i in 0..n {
        let k = (start + i) % n;
        chain.push(points[(k + 1) % n]);
        if i + 1 == n || kinds[(k + 1) % n] != kinds[k] {
            out.push((
                std::mem::replace(&mut chain, vec![points[(k + 1) % n]]),
                kinds[k],
            ));
        }
    }
    out
}

/// Where a tool of radius `r` clears the field: its centre anywhere in
/// the field or past a blank contour, at least `r` from every part
/// contour; the positions grown back by `r`, within the field.
fn cleared(s: &Shape, r: f64) -> MultiPolygon<f64> {
    let d = disk(r);
    let domain = if s.blank.is_empty() {
        s.region.clone()
    } else {
        union(&s.region, &stroked(&s.blank, &d))
    };
    let free = difference(&domain, &stroked(&s.part, &d));
    if free.unsigned_area() <= 0.0 {
        return MultiPolygon::new(vec![]);
    }
    intersection(&s.region, &opened(&free, &d))
}

/// The regions of tool `t`'s share (Popma §4.3.4), what its opening `c`
/// clears beyond `done` (the larger tools'): along the part contours
/// within the finishing stepover (boundary); then where part contours on
/// both sides leave the tool one pass at most, so it engages (nearly) its
/// full width: what a disk a stepover wider (d + a_e) cannot reach,
/// between walls closer than that and in the corners it cleans (full
/// cut); the rest is roughing. Returns the boundary and full-cut areas,
/// mm².
///
/// Measured as differences of areas, each an opening intersected with the
/// band or with band ∪ wider opening: a boolean between two openings
/// (their outlines run along the same walls, with tens of thousands of
/// points) is what slows `i_overlay` down badly.
fn regions(
    s: &Shape,
    c: &MultiPolygon<f64>,
    done: &MultiPolygon<f64>,
    t: &CuttingTool,
) -> (f64, f64) {
    let u = stroked(&s.part, &disk(t.finish_radial_depth_mm));
    let wide = cleared(s, 0.5 * (t.diameter_mm + t.radial_depth_mm));
    let v = union(&u, &wide);
    let within = |m: &MultiPolygon<f64>, x: &MultiPolygon<f64>| {
        if m.0.is_empty() || x.0.is_empty() {
            0.0
        } else {
            intersection(m, x).unsigned_area()
        }
    };
    let boundary = within(c, &u) - within(done, &u);
    let outside_v = |m: &MultiPolygon<f64>| m.unsigned_area() - within(m, &v);
    let full_cut = outside_v(c) - outside_v(done);
    (boundary.max(0.0), full_cut.max(0.0))
}

/// The area a tool of diameter `d` may seem to clear or leave from its
/// disk being a polygon alone: twice the 128-gon's shortfall of the
/// circle's area (about 4·10⁻⁴ of it). A share or a rest below it is noise,
/// not an operation.
pub(crate) fn noise(d: f64) -> f64 {
    2.0 * 4e-4 * std::f64::consts::PI * (0.5 * d).powi(2)
}

/// The tools for one field: `mills` largest first; a tool that clears
/// nothing new is skipped, and the descent stops once nothing is left
/// (within 1e-9 of the field). A tool whose share would be under
/// `min_share_mm2` does not run there: the next smaller tool takes that
/// share with its own, and what the last such tool would take is left as
/// rest below the minimum.
/// `floor` is the part's floors at the layer's bottom (x, y), for the
/// bottom adjacency and each share's floor area.
pub fn select(
    field: &CutterField,
    mills: &[&CuttingTool],
    floor: &MultiPolygon<f64>,
    min_share_mm2: f64,
) -> FieldTools {
    open(field, mills, min_share_mm2).on(Near::of(floor).as_ref())
}

/// What the mills clear of one field, whatever lies under it: the part of
/// [`select`] that only the field's contours decide (a pocket's layers
/// share one section, so this is worked out once per distinct field).
pub struct Opened {
    region: MultiPolygon<f64>,
    tiny: f64,
    /// The smallest mill's polygon noise: a floor under it is no floor.
    floor_noise: f64,
    side: bool,
    entry: Entry,
    /// Each tool's share (its floor area not yet known) and its opening.
    shares: Vec<(ToolShare, MultiPolygon<f64>)>,
    below: Option<BelowMinimum>,
    rest_mm2: f64,
    rest_width_mm: f64,
    rest: Vec<Vec<[f64; 2]>>,
}

/// [`select`]'s descent down the mills, before any floor.
pub fn open(field: &CutterField, mills: &[&CuttingTool], min_share_mm2: f64) -> Opened {
    let s = shape(field);
    let area = s.region.unsigned_area();
    let tiny = 1e-9 * area.max(1.0);
    let mut shares: Vec<(ToolShare, MultiPolygon<f64>)> = Vec::new();
    let mut done = MultiPolygon::new(vec![]);
    let mut done_area = 0.0;
    let mut below: Option<BelowMinimum> = None;
    for t in mills {
        if area - done_area <= tiny {
            break;
        }
        let c = cleared(&s, 0.5 * t.diameter_mm);
        let now = c.unsigned_area().max(done_area);
        // Slivers the larger tools' polygons left count as noise too.
        let first = shares.first().map_or(t.diameter_mm, |s| s.0.diameter_mm);
        let cleared_mm2 = now - done_area;
        if cleared_mm2 <= tiny.max(noise(first)) {
            continue;
        }
        if cleared_mm2 < min_share_mm2 {
            below = Some(BelowMinimum {
                tool: t.name.clone(),
                area_mm2: cleared_mm2,
            });
            continue;
        }
        below = None;
        let share = share(&s, &c, &done, t, cleared_mm2, shares.is_empty());
        shares.push((share, c.clone()));
        done = c;
        done_area = now;
    }
    // Measured on the difference itself: the layer check (cleared + rest
    // = section) then compares two booleans, not one number with itself.
    let rest = difference(&s.region, &done);
    let rest_mm2 = rest.unsigned_area();
    // Less than the disks' polygon error: no rest worth a word (a field
    // no tool enters: the smallest tool's).
    let largest = shares
        .first()
        .map(|s| s.0.diameter_mm)
        .or_else(|| mills.last().map(|t| t.diameter_mm))
        .unwrap_or(0.0);
    let worth = rest_mm2 > tiny.max(noise(largest));
    // Slivers of no area along a contour and zero-width spikes are no
    // rest, and would cut its inscribed width short.
    let rest = without_slivers(&rest, tiny);
    Opened {
        tiny,
        floor_noise: mills.last().map_or(0.0, |t| noise(t.diameter_mm)),
        side: !s.part.is_empty(),
        entry: if s.blank.is_empty() {
            Entry::Ramp
        } else {
            Entry::FromOutside
        },
        shares,
        below,
        rest_mm2,
        rest_width_mm: if worth {
            2.0 * thinwall_analysis::polygon::inscribed_radius(&rest)
        } else {
            0.0
        },
        rest: if worth {
            rest.iter()
                .map(|p| p.exterior().coords().map(|c| [c.x, c.y]).collect())
                .collect()
        } else {
            Vec::new()
        },
        region: s.region,
    }
}

impl Opened {
    /// The field's tools over `floor` (the part's floors at the layer's
    /// bottom, x, y, prepared once per layer; `None`: no floor): each
    /// share's floor area and the bottom adjacency. The floors near the
    /// field are all that is cut (`boolean::intersection_near`: the same
    /// result), so a layer's many fields over many floors cost no more
    /// than each field's own.
    pub fn on(&self, floor: Option<&Near>) -> FieldTools {
        let floor = match floor {
            Some(f) => intersection_near(&self.region, f),
            None => MultiPolygon::new(vec![]),
        };
        let over = |c: &MultiPolygon<f64>| {
            if c.0.is_empty() || floor.0.is_empty() {
                0.0
            } else {
                intersection(c, &floor).unsigned_area()
            }
        };
        let mut below_done = 0.0;
        let shares = self
            .shares
            .iter()
            .map(|(s, c)| {
                let here = over(c);
                let floor_mm2 = (here - below_done).max(0.0);
                below_done = here;
                ToolShare {
                    floor_mm2,
                    ..s.clone()
                }
            })
            .collect();
        // A floor that only touches the field along an edge leaves a
        // sliver of the booleans' rounding: under the smallest mill's
        // polygon noise it is no floor.
        let bottom = floor.unsigned_area() > self.tiny.max(self.floor_noise);
        FieldTools {
            adjacency: Adjacency::of(self.side, bottom),
            entry: self.entry,
            shares,
            rest_mm2: self.rest_mm2,
            rest_width_mm: self.rest_width_mm,
            rest: self.rest.clone(),
            below_minimum: self.below.clone(),
            drilled: None,
        }
    }
}

/// Tool `t`'s share of the field `s`: what its opening `c` adds to `done`
/// (`cleared_mm2`), split into Popma's regions; its floor area comes with
/// the layer ([`Opened::on`]).
fn share(
    s: &Shape,
    c: &MultiPolygon<f64>,
    done: &MultiPolygon<f64>,
    t: &CuttingTool,
    cleared_mm2: f64,
    first: bool,
) -> ToolShare {
    let (boundary, full_cut) = regions(s, c, done, t);
    let full_cut = full_cut.min(cleared_mm2 - boundary).max(0.0);
    let boundary = boundary.min(cleared_mm2);
    ToolShare {
        tool: t.name.clone(),
        diameter_mm: t.diameter_mm,
        cleared_mm2,
        boundary_mm2: boundary,
        full_cut_mm2: full_cut,
        roughing_mm2: (cleared_mm2 - boundary - full_cut).max(0.0),
        floor_mm2: 0.0,
        first,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::layers::Contour;
    use crate::tools::ToolLibrary;

    /// A straight channel 200 long between two part walls `width` apart,
    /// open (blank) at both ends.
    fn channel(width: f64) -> CutterField {
        CutterField {
            outer: Contour {
                points: vec![[0.0, 0.0], [200.0, 0.0], [200.0, width], [0.0, width]],
                edges: vec![
                    EdgeKind::Part,
                    EdgeKind::Blank,
                    EdgeKind::Part,
                    EdgeKind::Blank,
                ],
            },
            islands: Vec::new(),
            area_mm2: 200.0 * width,
            inscribed_diameter_mm: width,
            too_small: false,
        }
    }

    /// A square's edges part, part, blank, part come out as one part
    /// chain of three edges (round the corner where the contour starts)
    /// and one blank edge; a contour of one kind is one closed chain.
    #[test]
    fn a_contour_splits_into_chains_of_one_kind() {
        use EdgeKind::{Blank, Part};
        let sq = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let got = chains(&sq, &[Part, Part, Blank, Part]);
        assert_eq!(got.len(), 2);
        assert_eq!(got[0].1, Blank);
        assert_eq!(got[0].0, vec![sq[2], sq[3]]);
        assert_eq!(got[1].1, Part);
        assert_eq!(got[1].0, vec![sq[3], sq[0], sq[1], sq[2]]);
        let ring = chains(&sq, &[Part; 4]);
        assert_eq!(ring, vec![(vec![sq[0], sq[1], sq[2], sq[3], sq[0]], Part)]);
        assert!(chains(&sq[..1], &[Part]).is_empty());
    }

    /// Ø20 with a_e 12 and a finishing stepover of 2: in a channel 25 wide
    /// (narrower than 20 + 12) everything off the walls' 2 mm bands is a
    /// full cut, 4200 mm², but at the open ends, where a disk of radius 16
    /// centred outside (16 from the walls' ends, so 9.99 before the
    /// entrance) reaches in: at most a segment of 16² acos(9.99/16) −
    /// 9.99 · 12.5 = 104.7 mm² each. In a channel 40 wide nothing is a full
    /// cut (no corners). The bands are 2 × 200 × 2 = 800 mm² either way;
    /// the field is open, so the tool comes in from outside; the walls make
    /// it side adjacent.
    #[test]
    fn a_channel_narrower_than_the_tool_and_a_stepover_is_a_full_cut() {
        let lib = ToolLibrary::default_tools();
        let em20 = lib.tools.iter().find(|t| t.name == "EM20").unwrap();
        assert_eq!(em20.radial_depth_mm, 12.0);
        assert!((em20.finish_radial_depth_mm - 2.0).abs() < 1e-12);
        let none = MultiPolygon::new(vec![]);
        for (width, full_cut, ends) in [(25.0, 4200.0, 2.0 * 104.7), (40.0, 0.0, 0.0)] {
            let ft = select(&channel(width), &[em20], &none, 0.0);
            assert_eq!(ft.shares.len(), 1);
            let s = &ft.shares[0];
            assert!((s.cleared_mm2 - 200.0 * width).abs() < 1e-6, "{s:?}");
            assert!((s.boundary_mm2 - 800.0).abs() < 1e-6, "{s:?}");
            assert!(
                s.full_cut_mm2 <= full_cut + 1e-6 && s.full_cut_mm2 >= full_cut - ends - 1e-6,
                "{s:?}"
            );
            let roughing = 200.0 * width - 800.0 - s.full_cut_mm2;
            assert!((s.roughing_mm2 - roughing).abs() < 1e-6, "{s:?}");
            assert_eq!(s.floor_mm2, 0.0);
            assert!(s.first);
            assert_eq!(ft.adjacency, Adjacency::Side);
            assert_eq!(ft.entry, Entry::FromOutside);
        }
    }

    /// A closed square pocket over a floor: side and bottom adjacent, a
    /// ramp in, and the floor under the whole share.
    #[test]
    fn a_closed_field_over_a_floor_is_entered_by_a_ramp() {
        let lib = ToolLibrary::default_tools();
        let em20 = lib.tools.iter().find(|t| t.name == "EM20").unwrap();
        let mut f = channel(60.0);
        f.outer.points = vec![[0.0, 0.0], [60.0, 0.0], [60.0, 60.0], [0.0, 60.0]];
        f.outer.edges = vec![EdgeKind::Part; 4];
        f.area_mm2 = 3600.0;
        let floor = MultiPolygon::new(vec![f.polygon()]);
        let ft = select(&f, &[em20], &floor, 0.0);
        assert_eq!(ft.adjacency, Adjacency::SideAndBottom);
        assert_eq!(ft.entry, Entry::Ramp);
        let s = &ft.shares[0];
        assert!((s.floor_mm2 - s.cleared_mm2).abs() < 1e-6);
        // The Ø20 leaves its four corners, 10² (1 − π/4) each (the
        // 128-gon within 0.1 %).
        let corners = 4.0 * 100.0 * (1.0 - std::f64::consts::FRAC_PI_4);
        assert!(
            (ft.rest_mm2 - corners).abs() < 1e-3 * 3600.0,
            "{}",
            ft.rest_mm2
        );
        let sum = s.boundary_mm2 + s.full_cut_mm2 + s.roughing_mm2;
        assert!((sum - s.cleared_mm2).abs() < 1e-9 * 3600.0);
    }

    /// One opening serves every layer of the field: over no floor, half
    /// a floor and the whole, each share's floor area and the bottom
    /// adjacency follow the floor (over the whole floor, every share lies
    /// over it).
    #[test]
    fn an_opened_field_over_any_floor_is_the_field_selected_over_it() {
        let lib = ToolLibrary::default_tools();
        let mills: Vec<&CuttingTool> = lib.end_mills().collect();
        let mut f = channel(60.0);
        f.outer.points = vec![[0.0, 0.0], [60.0, 0.0], [60.0, 60.0], [0.0, 60.0]];
        f.outer.edges = vec![
            EdgeKind::Part,
            EdgeKind::Blank,
            EdgeKind::Part,
            EdgeKind::Part,
        ];
        f.area_mm2 = 3600.0;
        let opened = open(&f, &mills, 0.0);
        let half = geo::Rect::new((0.0, 0.0), (30.0, 60.0)).to_polygon();
        let floors = [
            MultiPolygon::new(vec![]),
            MultiPolygon::new(vec![half]),
            MultiPolygon::new(vec![f.polygon()]),
        ];
        let mut floor_areas = Vec::new();
        for floor in &floors {
            let on = opened.on(Near::of(floor).as_ref());
            assert_eq!(on.adjacency.bottom(), !floor.0.is_empty());
            floor_areas.push(on.shares.iter().map(|s| s.floor_mm2).sum::<f64>());
        }
        assert_eq!(floor_areas[0], 0.0);
        // The rest lies in the corners the part closes, both in the left
        // half (the right edge is blank: the tool overhangs it).
        assert!(
            (floor_areas[1] - 1800.0 + opened.rest_mm2).abs() < 1e-6,
            "{floor_areas:?}"
        );
        assert!(
            (floor_areas[2] - 3600.0 + opened.rest_mm2).abs() < 1e-6,
            "{floor_areas:?}"
        );
        let whole = opened.on(Near::of(&floors[2]).as_ref());
        assert!(whole.shares.len() > 1);
        for s in &whole.shares {
            assert!((s.floor_mm2 - s.cleared_mm2).abs() < 1e-6, "{s:?}");
        }
    }
}
