//! Engraving, embossing and lettering: shallow groups of many small faces
//! sunk into (or standing on) one host face. Their strokes look like short
//! walls; a planner sees text to engrave with a small tool, not walls.
//!
//! Candidates are small faces (each under `ENGRAVING_FACE_SHARE` of the
//! part's area) that are not sides of a reported wall. Connected groups of
//! them (a letter) that hold a planar face and are shallow along one of
//! their planar faces' normals (≤ `engraving_max_depth_mm`, and ≤ 1 % of
//! the part's diagonal) and wider across than twice that depth are glyphs;
//! glyphs sharing the host face they are cut into are one engraving when
//! there are at least `MIN_GLYPHS` of them with `MIN_FACES` faces in all.

use crate::config::Config;
use std::collections::{BTreeMap, HashSet};
use thinwall_analysis::PartAnalysis;
use thinwall_brep::FaceId;
use thinwall_geom::Vector3;

/// A candidate face is at most this share of the part's whole area.
const ENGRAVING_FACE_SHARE: f64 = 0.005;
/// An engraving is shallow for the part too: at most this share of its
/// bounding-box diagonal deep (a 2 mm deep feature of a 30 mm block is a
/// machining feature, of a 600 mm part lettering).
const ENGRAVING_DEPTH_SHARE: f64 = 0.01;
/// Fewest faces of one glyph.
const MIN_GLYPH_FACES: usize = 3;
/// Fewest glyphs, and faces in all, that make an engraving.
const MIN_GLYPHS: usize = 2;
const MIN_FACES: usize = 10;

/// An engraving found.
#[derive(Clone, Debug)]
pub struct Engraving {
    pub faces: Vec<FaceId>,
    /// Its depth (or height, embossed), mm, and the direction it is measured along.
    pub depth: f64,
    pub direction: Vector3,
    /// Length and width of its extent across that direction, mm.
    pub length: f64,
    pub width: f64,
}

/// Engravings among faces not `taken` (reported walls' sides excluded by
/// the caller).
pub fn engravings(a: &PartAnalysis, taken: &HashSet<FaceId>, config: &Config) -> Vec<Engraving> {
    let total: f64 = a.face_props().iter().map(|p| p.area).sum();
    let small: Vec<FaceId> = a
        .part()
        .face_ids()
        .filter(|f| !taken.contains(f) && a.props(*f).area <= ENGRAVING_FACE_SHARE * total)
        .collect();
    let max_depth = config
        .thresholds
        .engraving_max_depth_mm
        .min(ENGRAVING_DEPTH_SHARE * a.tol().diagonal);
    let mut by_host: BTreeMap<FaceId, Vec<(Vec<FaceId>, f64, Vector3)>> = BTreeMap::new();
    for glyph in a.components(&small, |_, _, _| true) {
        if glyph.len() < MIN_GLYPH_FACES {
            continue;
        }
        let Some((depth, dir)) = shallowest(a, &glyph) else {
            continue;
        };
        let across = a.sizes_across(&glyph, &dir).0;
        if depth > max_depth || across < 2.0 * depth {
            continue;
        }
        if let Some(host) = host_of(a, &glyph) {
            by_host.entry(host).or_default().push((glyph, depth, dir));
        }
    }
    by_host
        .into_values()
        .filter(|g| {
            g.len() >= MIN_GLYPHS && g.iter().map(|x| x.0.len()).sum::<usize>() >= MIN_FACES
        })
        .map(|glyphs| {
            let dir = glyphs[0].2;
            let mut faces: Vec<FaceId> = glyphs.iter().flat_map(|g| g.0.iter().copied()).collect();
            faces.sort();
            let (length, width) = a.sizes_across(&faces, &dir);
            Engraving {
                depth: glyphs.iter().map(|g| g.1).fold(0.0, f64::max),
                direction: dir,
                length,
                width,
                faces,
            }
        })
        .collect()
}

/// The least extent of the faces along one of their planar faces' normals.
fn shallowest(a: &PartAnalysis, faces: &[FaceId]) -> Option<(f64, Vector3)> {
    faces
        .iter()
        .filter_map(|&f| a.planar(f).map(|p| p.normal()))
        .map(|n| {
            let (lo, hi) = a.extent(faces, &n);
            (hi - lo, n)
        })
        .min_by(|x, y| x.0.total_cmp(&y.0))
}

/// The largest face outside the glyph that it meets: the face it is cut
/// into or stands on.
fn host_of(a: &PartAnalysis, glyph: &[FaceId]) -> Option<FaceId> {
    glyph
        .iter()
        .flat_map(|&f| a.graph().neighbours(f).map(|(g, _)| g))
        .filter(|g| glyph.binary_search(g).is_err())
        .max_by(|x, y| a.props(*x).area.total_cmp(&a.props(*y).area))
}
