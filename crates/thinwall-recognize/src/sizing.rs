//! A wall's figures in the set-up: its base (the wall it meets along its
//! longest foot), height, length and direction of height, the cantilever
//! deflection and thinness; and its kind from those (DOMAIN.md §1–2).

use crate::config::Config;
use crate::deflection::deflection_mm;
use crate::junctions::Junction;
use crate::walls::Wall;
use thinwall_analysis::polygon::{inscribed_radius, long_side};
use thinwall_analysis::{measure, PartAnalysis, StiffnessKind};
use thinwall_geom::tolerance::DIRECTION_NORM_MIN;
use thinwall_geom::{Point3, Vector3};

/// A wall's figures.
#[derive(Clone, Debug)]
pub struct WallSize {
    pub base: Option<usize>,
    pub tee: bool,
    /// mm.
    pub height: f64,
    /// mm.
    pub length: f64,
    pub deflection: f64,
    pub thin: bool,
    /// Unit direction of the height.
    pub height_dir: Vector3,
    /// The foot on the base: the base side's point and outward normal.
    pub foot_plane: Option<(Point3, Vector3)>,
    /// Too squat to be a wall (height or length under
    /// `min_extent_to_thickness` × t): kept as a base for others, never
    /// reported.
    pub squat: bool,
}

/// Size every wall: walls on a base from the base, walls without one (webs)
/// by their widest cell; then their deflection and thinness.
pub fn size_walls(
    a: &PartAnalysis,
    walls: &[Wall],
    junctions: &[Junction],
    heights: &[f64],
    config: &Config,
) -> Vec<WallSize> {
    let mut sizes: Vec<WallSize> = walls
        .iter()
        .enumerate()
        .map(|(w, wall)| on_base(walls, wall, w, junctions, heights, a))
        .collect();
    for (w, wall) in walls.iter().enumerate() {
        if sizes[w].base.is_none() {
            without_base(a, wall, w, junctions, &mut sizes[w]);
        }
    }
    for (wall, s) in walls.iter().zip(&mut sizes) {
        // A drafted wall is judged on its thinnest section (the top, for a
        // wall tapering from its foot): a uniform wall that thin deflects
        // at least as much, so the verdict errs towards support.
        s.deflection = deflection_mm(
            wall.thickness_range.0,
            s.height,
            s.length.max(s.height),
            &config.thinness,
        );
        s.thin = s.deflection > config.thinness.allowed_deflection_mm;
        let least = config.thresholds.min_extent_to_thickness * wall.thickness_range.0;
        s.squat = s.height < least || s.length < least;
    }
    sizes
}

/// Figures of a wall from the wall it meets along its longest foot (ties,
/// within the part's feature tolerance: the lower base, then the thicker,
/// the more substantial of two it meets alike); zero when it meets none.
/// Exact comparisons let rounding in the last digit pick between two bases
/// the leaf meets alike.
fn on_base(
    walls: &[Wall],
    wall: &Wall,
    w: usize,
    junctions: &[Junction],
    heights: &[f64],
    a: &PartAnalysis,
) -> WallSize {
    let (up, tol) = (a.up(), a.tol().feature);
    let order = |x: f64, y: f64| {
        if (x - y).abs() <= tol {
            std::cmp::Ordering::Equal
        } else {
            x.total_cmp(&y)
        }
    };
    let best = junctions.iter().filter(|j| j.leaf == w).max_by(|a, b| {
        order(a.length, b.length)
            .then(order(heights[b.base], heights[a.base]))
            .then(order(walls[a.base].thickness, walls[b.base].thickness))
    });
    let mut size = WallSize {
        base: best.map(|j| j.base),
        tee: best.is_some_and(|j| j.tee),
        height: 0.0,
        length: 0.0,
        deflection: 0.0,
        thin: false,
        height_dir: up,
        foot_plane: None,
        squat: false,
    };
    if let Some(j) = best {
        // A curved base's tangent plane under the leaf's middle.
        let (origin, n) = walls[j.base].side_plane_near(j.base_side, &wall.mid_plane().0);
        let pts = wall.outline();
        let rise = pts
            .iter()
            .map(|p| (p - origin).dot(&n).abs())
            .fold(0.0, f64::max);
        size.height = wall.developed_height(&n).unwrap_or(rise);
        let along = wall.frame.z.cross(&n);
        size.length = match (
            wall.developed_span(&n),
            along.try_normalize(DIRECTION_NORM_MIN),
        ) {
            (Some(developed), _) => developed,
            (None, Some(a)) => measure::span(&pts, &a),
            (None, None) => long_side(&wall.region),
        };
        size.height_dir = n;
        size.foot_plane = Some((origin, n));
    }
    size
}

/// A wall without a base (a web) is measured by its widest cell: the side
/// its leaves stand on (most of them), each face of it a cell.
fn without_base(
    a: &PartAnalysis,
    wall: &Wall,
    w: usize,
    junctions: &[Junction],
    size: &mut WallSize,
) {
    let leaf_sides: Vec<usize> = junctions
        .iter()
        .filter(|j| j.base == w)
        .map(|j| j.base_side)
        .collect();
    let side = usize::from(leaf_sides.iter().filter(|&&s| s == 1).count() > leaf_sides.len() / 2);
    let cells: Vec<geo::MultiPolygon<f64>> = if leaf_sides.is_empty() {
        vec![wall.region.clone()]
    } else if let Some(c) = &wall.curved {
        // Developed, at the mid-surface.
        c.side_polygons[side]
            .iter()
            .map(|(_, p)| p.clone())
            .collect()
    } else {
        wall.sides[side]
            .iter()
            .filter_map(|&f| a.planar(f))
            .map(|p| p.polygon_in(&wall.frame))
            .collect()
    };
    let (mut h, mut l) = (0.0, 0.0);
    for c in &cells {
        let r = inscribed_radius(c);
        if r > h {
            h = r;
            l = long_side(c);
        }
    }
    let up = a.up();
    let in_plane_up = up - wall.frame.z * up.dot(&wall.frame.z);
    size.height = h;
    size.length = l;
    size.height_dir = in_plane_up
        .try_normalize(DIRECTION_NORM_MIN)
        .unwrap_or(wall.frame.x);
}

/// Kinds: a wall carrying thin leaves is a web; a wall on a base is a rib
/// (T-foot) or a flange (L-foot); else a wall.
pub fn kinds(sizes: &[WallSize]) -> Vec<StiffnessKind> {
    (0..sizes.len())
        .map(|w| {
            let thin_leaves = sizes.iter().any(|s| s.base == Some(w) && s.thin);
            if thin_leaves {
                StiffnessKind::Web
            } else if sizes[w].base.is_some() {
                if sizes[w].tee {
                    StiffnessKind::Rib
                } else {
                    StiffnessKind::Flange
                }
            } else {
                StiffnessKind::Wall
            }
        })
        .collect()
}
