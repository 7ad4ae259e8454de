//! A wall's figures in the set-up: its base (the wall it meets along its
//! longest foot), height, length and direction of height, the cantilever
//! deflection and thinness; and its kind from those (DOMAIN.md §1–2).

use crate::config::Config;
use crate::deflection::deflection_mm;
use crate::feature::OtherSide;
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
    /// A wall through its base: its figures on the base's other side
    /// (`height` and the rest are on the side this set-up machines).
    pub other_side: Option<OtherSide>,
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
        let t = wall.thickness_range.0;
        let deflection = |h: f64| deflection_mm(t, h, s.length.max(h), &config.thinness);
        let allowed = config.thinness.allowed_deflection_mm;
        s.deflection = deflection(s.height);
        if let Some(o) = &mut s.other_side {
            o.deflection = deflection(o.height);
            o.thin = o.deflection > allowed;
            o.slenderness = if t > 0.0 { o.height / t } else { 0.0 };
        }
        // Thin where it needs support on either side of its base.
        s.thin = s.deflection > allowed || s.other_side.as_ref().is_some_and(|o| o.thin);
        let least = config.thresholds.min_extent_to_thickness * wall.thickness_range.0;
        // A wall through its base is squat only where it is on both sides.
        let tallest = s
            .other_side
            .as_ref()
            .map_or(s.height, |o| o.height.max(s.height));
        s.squat = tallest < least || s.length < least;
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
        other_side: None,
    };
    if let Some(j) = best {
        let pts = wall.outline();
        let (side, other) = if j.through {
            let (side, other) = through_sides(&walls[j.base], wall, &up);
            (side, Some(other))
        } else {
            (j.base_side, None)
        };
        // A curved base's tangent plane under the leaf's middle.
        let (origin, n) = walls[j.base].side_plane_near(side, &wall.mid_plane().0);
        size.height = match &other {
            // On this side of the base only.
            Some(_) => rise_above((origin, n), &pts),
            None => wall.developed_height(&n).unwrap_or_else(|| {
                pts.iter()
                    .map(|p| (p - origin).dot(&n).abs())
                    .fold(0.0, f64::max)
            }),
        };
        size.other_side = other.map(|(other_side, height)| OtherSide {
            base_faces: a.step_ids(&walls[j.base].sides[other_side]),
            height,
            deflection: 0.0,
            slenderness: 0.0,
            thin: false,
        });
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

/// How far the points rise above a plane (a point on it and its outward
/// normal), mm: none below it count.
fn rise_above((origin, n): (Point3, Vector3), pts: &[Point3]) -> f64 {
    pts.iter().map(|p| (p - origin).dot(&n)).fold(0.0, f64::max)
}

/// A wall through `base`: the base's side this set-up machines — the one
/// facing up most, or where both face alike (a vertical base) the one the
/// wall rises higher above (side 0 at a tie) — and the other side with the
/// wall's height above it, mm.
fn through_sides(base: &Wall, wall: &Wall, up: &Vector3) -> (usize, (usize, f64)) {
    let pts = wall.outline();
    let mid = wall.mid_plane().0;
    let rise = |t: usize| rise_above(base.side_plane_near(t, &mid), &pts);
    let facing = |t: usize| base.side_plane_near(t, &mid).1.dot(up);
    let side = if (facing(0) - facing(1)).abs() > thinwall_geom::tolerance::NEAR_PARALLEL_EPS {
        usize::from(facing(1) > facing(0))
    } else {
        usize::from(rise(1) > rise(0) + thinwall_geom::tolerance::SAME_LENGTH_MM)
    };
    (side, (1 - side, rise(1 - side)))
}

/// A wall without a base (a web) is measured by its widest cell: the side
/// its leaves stand on (most of them; both sides of a web that walls run
/// through), each face of it a cell.
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
    let majority =
        usize::from(leaf_sides.iter().filter(|&&s| s == 1).count() > leaf_sides.len() / 2);
    let through = junctions.iter().any(|j| j.base == w && j.through);
    let sides: Vec<usize> = if through { vec![0, 1] } else { vec![majority] };
    let cells: Vec<geo::MultiPolygon<f64>> = if leaf_sides.is_empty() {
        vec![wall.region.clone()]
    } else if let Some(c) = &wall.curved {
        // Developed, at the mid-surface; a face whose holes all go
        // through the web without them (as below).
        sides
            .iter()
            .flat_map(|&s| c.side_polygons[s].iter())
            .map(|(f, p)| {
                let openings = a.openings(*f);
                if !openings.is_empty() && openings.iter().all(|&o| o) {
                    without_holes(p)
                } else {
                    p.clone()
                }
            })
            .collect()
    } else {
        // A cell's holes through the web support nothing: the span runs
        // to the walls around it (DOMAIN.md §2.1), as if they were not
        // there, and its figure does not hang on how a search skirts them.
        sides
            .iter()
            .flat_map(|&s| wall.sides[s].iter())
            .filter_map(|&f| a.loops_without_openings(f))
            .map(|loops| thinwall_analysis::polygon::project_loops(&loops, &wall.frame))
            .collect()
    };
    // The widest cell; among cells as wide (a 30 x 30 and a 30 x 40
    // pocket), the shortest, which deflects most: never the face order's
    // or the pose's rounding.
    let tie = a.tol().feature;
    let (mut h, mut l) = (0.0, 0.0);
    for c in &cells {
        let r = inscribed_radius(c);
        if r > h + tie {
            (h, l) = (r, long_side(c));
        } else if r >= h - tie {
            let side = long_side(c);
            if side < l {
                (h, l) = (h.max(r), side);
            }
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

fn without_holes(p: &geo::MultiPolygon<f64>) -> geo::MultiPolygon<f64> {
    geo::MultiPolygon::new(
        p.0.iter()
            .map(|q| geo::Polygon::new(q.exterior().clone(), vec![]))
            .collect(),
    )
}

/// Kinds: a wall carrying thin leaves, one that walls run through (an
/// I-section's web) or one squat walls stand on (a pocket's floor inside
/// a squat rim) is a web; a wall on a base
/// is a rib (T-foot) or a flange (L-foot); else a wall.
pub fn kinds(sizes: &[WallSize]) -> Vec<StiffnessKind> {
    (0..sizes.len())
        .map(|w| {
            let carries = sizes
                .iter()
                .any(|s| s.base == Some(w) && (s.thin || s.other_side.is_some() || s.squat));
            if carries {
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
