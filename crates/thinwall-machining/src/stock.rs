//! The stock a part is cut from: a block whose axes come from the part
//! itself, so that a part turned by any rigid motion is judged alike.
//!
//! The axes are the part's dominant orthogonal planar directions: of all
//! pairs of planar normal directions at right angles, the one whose
//! faces, with those along their cross product, carry the most area (a
//! block's sides outweigh a slanted step); with no such pair, the
//! direction carrying the most area and the long side of the part's
//! minimum rectangle seen along it. A part whose axes are the world's
//! keeps the world's axes exactly (and its bounding box), so axis-aligned
//! parts are measured as before. The block spans the part's extent along
//! each axis.

use thinwall_analysis::PartAnalysis;
use thinwall_brep::FaceId;
use thinwall_geom::tolerance::{FEATURE_PARALLEL_DEG, UNIT_PARALLEL_EPS};
use thinwall_geom::Vector3;

/// Two planar directions within this of a right angle can span the stock
/// (cast and forged parts carry drafts of a degree or two), degrees.
const FRAME_ORTHOGONAL_DEG: f64 = 3.0;
/// Axes within this of the world's are taken as the world's (a drafted part
/// modelled square to the world is cut from a square block), degrees.
const WORLD_SNAP_DEG: f64 = 2.0;

/// The stock block: three axes and the part's extent along each.
pub struct Stock {
    pub axes: [Vector3; 3],
    lo: [f64; 3],
    hi: [f64; 3],
    /// The axes are the world's: faces' and the part's boxes measure them.
    world: bool,
    tol: f64,
    /// The set-up's tool axis, when features are judged in it.
    pub up: Option<Vector3>,
}

impl Stock {
    /// The stock of an analysed part; with the set-up's `up`, one of its
    /// axes is up.
    pub fn of(a: &PartAnalysis, up: Option<Vector3>) -> Self {
        let axes = match up {
            Some(u) => axes_about(a, u),
            None => dominant_axes(a),
        };
        let world = axes == WORLD;
        let (mut lo, mut hi) = ([0.0; 3], [0.0; 3]);
        let all: Vec<FaceId> = a.part().face_ids().collect();
        for k in 0..3 {
            (lo[k], hi[k]) = a.with_bulges(
                &axes[k],
                if world {
                    (a.bounding_box().min[k], a.bounding_box().max[k])
                } else {
                    a.extent(&all, &axes[k])
                },
            );
        }
        Self {
            axes,
            lo,
            hi,
            world,
            tol: a.tol().feature,
            up,
        }
    }

    /// Block plane `sp`'s offset along its outward normal, mm.
    pub fn plane_offset(&self, sp: usize) -> f64 {
        let k = sp / 2;
        if sp % 2 == 1 {
            self.hi[k]
        } else {
            -self.lo[k]
        }
    }

    /// The block plane facing up, if features are judged in a set-up.
    pub fn up_plane(&self) -> Option<usize> {
        let u = self.up?;
        let snap = WORLD_SNAP_DEG.to_radians().cos();
        (0..6).find(|&sp| self.normal(sp).dot(&u) > snap)
    }

    /// The outward normal of block plane `sp` (`2k`: the low side of axis
    /// `k`, `2k + 1` the high side).
    pub fn normal(&self, sp: usize) -> Vector3 {
        let n = self.axes[sp / 2];
        if sp % 2 == 1 {
            n
        } else {
            -n
        }
    }

    /// The block's largest extent along its axes, mm.
    pub fn largest_extent(&self) -> f64 {
        (0..3).map(|k| self.hi[k] - self.lo[k]).fold(0.0, f64::max)
    }

    /// Whether a unit direction is one of the block's axes (either sense).
    pub fn aligned(&self, n: &Vector3) -> bool {
        self.axes
            .iter()
            .any(|ax| n.dot(ax).abs() > 1.0 - UNIT_PARALLEL_EPS)
    }

    /// The block plane a planar face lies on, if any.
    pub fn plane_of(&self, a: &PartAnalysis, f: FaceId) -> Option<usize> {
        let p = a.props(f);
        let n = p.normal?;
        (0..3).find_map(|k| {
            let along = n.dot(&self.axes[k]);
            let (min, max) = if self.world {
                (p.bbox.min[k], p.bbox.max[k])
            } else {
                a.extent(&[f], &self.axes[k])
            };
            let at = |v: f64| (min - v).abs() < self.tol && (max - v).abs() < self.tol;
            if along > 1.0 - UNIT_PARALLEL_EPS && at(self.hi[k]) {
                Some(2 * k + 1)
            } else if along < -1.0 + UNIT_PARALLEL_EPS && at(self.lo[k]) {
                Some(2 * k)
            } else {
                None
            }
        })
    }
}

/// A direction with a canonical sense: its largest component positive.
fn canonical(v: Vector3) -> Vector3 {
    let k = v.iamax();
    if v[k] < 0.0 {
        -v
    } else {
        v
    }
}

/// The part's dominant orthogonal planar directions (module docs).
fn dominant_axes(a: &PartAnalysis) -> [Vector3; 3] {
    let cos = FEATURE_PARALLEL_DEG.to_radians().cos();
    let clusters = normal_clusters(a, |_| true);
    let sin = FRAME_ORTHOGONAL_DEG.to_radians().sin();
    let area_along = |d: &Vector3| -> f64 {
        clusters
            .iter()
            .filter(|(c, _)| c.dot(d).abs() > cos)
            .map(|c| c.1)
            .sum()
    };
    let mut pairs: Vec<(f64, Vector3, Vector3)> = Vec::new();
    for (i, (ci, ai)) in clusters.iter().enumerate() {
        for (cj, aj) in clusters.iter().skip(i + 1) {
            if ci.dot(cj).abs() >= sin {
                continue;
            }
            let score = ai + aj + area_along(&ci.cross(cj).normalize());
            let (d1, d2) = if ai >= aj { (*ci, *cj) } else { (*cj, *ci) };
            pairs.push((score, d1, canonical(d2 - d1 * d2.dot(&d1)).normalize()));
        }
    }
    let (d1, d2) = match best_pair(a, &pairs) {
        Some((d1, d2)) => (d1, d2),
        None => {
            let Some(d1) = clusters
                .iter()
                .max_by(|x, y| x.1.total_cmp(&y.1))
                .map(|c| c.0)
            else {
                return WORLD;
            };
            (d1, across(a, &d1))
        }
    };
    snap_to_world([d1, d2, canonical(d1.cross(&d2).normalize())])
}

/// Pairs scoring within this share of the best tie (a symmetric part's
/// mirror-image directions carry equal area up to rounding, which differs
/// with the pose).
const SCORE_TIE: f64 = 1e-6;

/// The best-scoring pair of directions; ties (within [`SCORE_TIE`]) go to
/// the smaller block, then to the first (a mirror image of the other: the
/// features come out mirrored, alike in size).
fn best_pair(a: &PartAnalysis, pairs: &[(f64, Vector3, Vector3)]) -> Option<(Vector3, Vector3)> {
    let top = pairs.iter().map(|p| p.0).fold(f64::NEG_INFINITY, f64::max);
    let all: Vec<FaceId> = a.part().face_ids().collect();
    let volume = |d1: &Vector3, d2: &Vector3| -> f64 {
        [*d1, *d2, d1.cross(d2)]
            .iter()
            .map(|ax| {
                let (lo, hi) = a.extent(&all, ax);
                hi - lo
            })
            .product()
    };
    let tied: Vec<&(f64, Vector3, Vector3)> = pairs
        .iter()
        .filter(|p| p.0 >= top - SCORE_TIE * top.abs())
        .collect();
    if tied.len() == 1 {
        return Some((tied[0].1, tied[0].2));
    }
    let volumes: Vec<f64> = tied.iter().map(|p| volume(&p.1, &p.2)).collect();
    let least = volumes.iter().copied().fold(f64::INFINITY, f64::min);
    tied.iter()
        .zip(&volumes)
        .find(|(_, &v)| v <= least * (1.0 + SCORE_TIE))
        .map(|(p, _)| (p.1, p.2))
}

const WORLD: [Vector3; 3] = [
    Vector3::new(1.0, 0.0, 0.0),
    Vector3::new(0.0, 1.0, 0.0),
    Vector3::new(0.0, 0.0, 1.0),
];

/// Axes that are the world's (in any order and sense, within the snap
/// angle) are the world's, exactly.
fn snap_to_world(axes: [Vector3; 3]) -> [Vector3; 3] {
    let snap = WORLD_SNAP_DEG.to_radians().cos();
    if axes
        .iter()
        .all(|ax| WORLD.iter().any(|w| ax.dot(w).abs() > snap))
    {
        WORLD
    } else {
        axes
    }
}

/// Planar normal directions (canonical sense) of the faces `keep` admits,
/// merged within the feature-parallel angle, with the area each carries.
fn normal_clusters(a: &PartAnalysis, keep: impl Fn(&Vector3) -> bool) -> Vec<(Vector3, f64)> {
    let cos = FEATURE_PARALLEL_DEG.to_radians().cos();
    let mut clusters: Vec<(Vector3, f64)> = Vec::new();
    for f in a.part().face_ids() {
        let Some(n) = a.props(f).normal.filter(|n| keep(n)) else {
            continue;
        };
        let area = a.props(f).area;
        match clusters.iter_mut().find(|(c, _)| c.dot(&n).abs() > cos) {
            Some(c) => c.1 += area,
            None => clusters.push((canonical(n), area)),
        }
    }
    clusters
}

/// Axes with `up` as one: up, the planar direction square to it carrying
/// the most area (or the long side of the part seen from up), and their
/// cross product; the world's when all three are within the snap angle of
/// the world's.
fn axes_about(a: &PartAnalysis, up: Vector3) -> [Vector3; 3] {
    let sin = FRAME_ORTHOGONAL_DEG.to_radians().sin();
    let d2 = normal_clusters(a, |n| n.dot(&up).abs() < sin)
        .iter()
        .max_by(|x, y| x.1.total_cmp(&y.1))
        .map_or_else(|| across(a, &up), |c| c.0);
    let d2 = canonical((d2 - up * d2.dot(&up)).normalize());
    snap_to_world([up, d2, canonical(up.cross(&d2).normalize())])
}

/// The long side of the part's minimum rectangle seen along `d1`.
fn across(a: &PartAnalysis, d1: &Vector3) -> Vector3 {
    let all: Vec<FaceId> = a.part().face_ids().collect();
    let (u, v, pts) = a.points_across(&all, d1);
    let dir = thinwall_analysis::min_rect::min_rect(&geo::MultiPoint::from(pts))
        .filter(|r| r.long > 0.0)
        .and_then(|r| (u * r.long_dir[0] + v * r.long_dir[1]).try_normalize(1e-12));
    canonical(dir.unwrap_or(u))
}
