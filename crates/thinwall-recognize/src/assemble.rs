//! Recognition results as features: walls with their figures and geometry,
//! depressions and details with theirs, numbered by kind and smallest face
//! id, references as typed ids.

use crate::claims::Claims;
use crate::config::Config;
use crate::depressions::{Depression, DepressionKind};
use crate::feature::{Plane, StiffnessFeature, WallGeometry};
use crate::sizing::WallSize;
use crate::walls::Wall;
use std::collections::BTreeMap;
use thinwall_analysis::{measure, FeatureId, PartAnalysis, StiffnessKind};
use thinwall_brep::FaceId;
use thinwall_geom::tolerance::DIRECTION_NORM_MIN;
use thinwall_geom::{Point3, Vector3};

/// Features before numbering, with references by position.
pub struct Draft {
    pub features: Vec<StiffnessFeature>,
    /// Per feature: its base (walls) or the wall it is in or on, by position.
    pub refs: Vec<Option<usize>>,
    /// Per wall: its feature's position, when reported.
    pub wall_feature: Vec<Option<usize>>,
    /// Per feature position: the other walls' positions a pocket's blends
    /// touch (`StiffnessFeature::walls`).
    pub also: BTreeMap<usize, Vec<usize>>,
}

/// The wall features (squat slabs left out: they are bases, not walls).
pub fn walls(
    a: &PartAnalysis,
    walls: &[Wall],
    sizes: &[WallSize],
    kinds: &[StiffnessKind],
    claims: &Claims,
) -> Draft {
    let mut d = Draft {
        features: Vec::new(),
        refs: Vec::new(),
        wall_feature: vec![None; walls.len()],
        also: BTreeMap::new(),
    };
    for (w, wall) in walls.iter().enumerate() {
        if sizes[w].squat {
            continue;
        }
        d.wall_feature[w] = Some(d.features.len());
        d.features
            .push(wall_feature(a, wall, &sizes[w], kinds[w], &claims.rims[w]));
    }
    for (w, &fi) in d.wall_feature.clone().iter().enumerate() {
        if fi.is_some() {
            d.refs.push(sizes[w].base.and_then(|b| d.wall_feature[b]));
        }
    }
    d
}

fn xyz(v: &Vector3) -> [f64; 3] {
    [v.x, v.y, v.z]
}

fn wall_feature(
    a: &PartAnalysis,
    wall: &Wall,
    s: &WallSize,
    kind: StiffnessKind,
    rim: &[FaceId],
) -> StiffnessFeature {
    let sides = [a.step_ids(&wall.sides[0]), a.step_ids(&wall.sides[1])];
    let mut side_faces: Vec<u64> = sides.iter().flatten().copied().collect();
    side_faces.sort();
    let top = a.step_ids(rim);
    let mut faces = side_faces.clone();
    faces.extend(&top);
    faces.sort();
    faces.dedup();
    let (p, n) = wall.mid_plane();
    let mut f = StiffnessFeature::new(kind, faces);
    f.body = a.part().face(wall.sides[0][0]).body.0;
    f.side_faces = Some(side_faces);
    f.sides = Some(sides);
    f.thin = Some(s.thin);
    f.thickness = Some(wall.thickness_range.0);
    if wall.drafted() {
        let (foot, top) = foot_and_top(wall, s, a.tol().feature);
        f.thickness_foot = Some(foot);
        f.thickness_top = Some(top);
    }
    f.height = Some(s.height);
    f.length = Some(s.length);
    f.deflection = Some(s.deflection);
    let t = wall.thickness_range.0;
    f.model_note = crate::deflection::validity_note(t, s.height, s.deflection);
    f.slenderness = Some(if t > 0.0 { s.height / t } else { 0.0 });
    f.other_side = s.other_side.clone();
    f.access_directions = Some([xyz(&wall.normals[0]), xyz(&wall.normals[1])]);
    f.top_end_faces = Some(top);
    match &wall.curved {
        Some(c) => {
            f.mid_surface = Some(c.mid_surface(&wall.region));
            f.access_range = Some(c.access_range(&wall.region));
        }
        None => {
            f.mid_plane = Some(Plane {
                point: [p.x, p.y, p.z],
                normal: xyz(&n),
            });
            f.geometry = Some(geometry(a, wall, s));
        }
    }
    f
}

/// A drafted wall's thickness at its foot and at its top, mm: the width of
/// its section normal to the height direction. The top is
/// at the region's highest vertices along the height direction; the foot
/// where the side meets its base's side (through any fillet between them:
/// the side's plane carried down to the base's), or at the region's lowest
/// vertices for a wall without a base. Where several vertices are level
/// (within `tol`), the thinnest of them, so that which corner of a level
/// edge the region's outline lists first does not decide.
fn foot_and_top(wall: &Wall, s: &WallSize, tol: f64) -> (f64, f64) {
    let pts = crate::walls::region_outline(&wall.frame, &wall.region, 0.0);
    let up = &s.height_dir;
    let level = |p: &Point3| p.coords.dot(up);
    let at_level = |h: f64| pts.iter().filter(move |p| (level(p) - h).abs() <= tol);
    let thinnest = |it: &mut dyn Iterator<Item = f64>| {
        it.fold(None, |m: Option<f64>, t| Some(m.map_or(t, |m| m.min(t))))
            .unwrap_or(wall.thickness)
    };
    let (lo, hi) = pts
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(level(p)), hi.max(level(p)))
        });
    // Across the section normal to the height (as a drawing dimensions it).
    let n0 = wall.normals[0];
    let across = (n0 - up * n0.dot(up)).try_normalize(1e-12).unwrap_or(n0);
    let width = |p: &Point3| wall.thickness_along(p, &across);
    let top = thinnest(&mut at_level(hi).map(width));
    let foot = thinnest(&mut at_level(lo).map(|p| match s.foot_plane {
        Some(plane) => width(&down_to(wall, p, plane)),
        None => width(p),
    }));
    (foot, top)
}

/// A point of side 0's plane carried down that plane, across the wall's
/// ridge, to the base's side plane `(origin, normal)`; the point itself
/// where the side runs parallel to the base.
fn down_to(wall: &Wall, p: &Point3, (origin, n): (Point3, Vector3)) -> Point3 {
    // Within side 0's plane, the direction in which the thickness changes.
    let n0 = wall.normals[0];
    let ridge = n0.cross(&wall.normals[1]);
    let Some(across) = n0.cross(&ridge).try_normalize(1e-12) else {
        return *p;
    };
    let rate = across.dot(&n);
    if rate.abs() < 1e-9 {
        return *p;
    }
    p - across * ((p - origin).dot(&n) / rate)
}

/// The wall's region, side polygons and foot line.
fn geometry(a: &PartAnalysis, wall: &Wall, s: &WallSize) -> WallGeometry {
    let side_polygons = [0, 1].map(|k| {
        wall.sides[k]
            .iter()
            .filter_map(|&f| Some((f, a.planar(f)?.polygon_in(&wall.frame))))
            .collect()
    });
    let foot = s.foot_plane.and_then(|(origin, n)| {
        let along = wall.frame.z.cross(&n).try_normalize(DIRECTION_NORM_MIN)?;
        let on_base: Vec<Point3> = wall
            .outline()
            .iter()
            .map(|p| p - n * (p - origin).dot(&n))
            .collect();
        let key = |p: &&Point3| p.coords.dot(&along);
        let lo = on_base.iter().min_by(|x, y| key(x).total_cmp(&key(y)))?;
        let hi = on_base.iter().max_by(|x, y| key(x).total_cmp(&key(y)))?;
        Some([*lo, *hi])
    });
    WallGeometry {
        frame: wall.frame,
        thickness: wall.thickness,
        region: wall.region.clone(),
        side_polygons,
        height_direction: s.height_dir,
        foot,
    }
}

/// Add the depressions: holes (round, through a wall's side), pockets
/// (blind, not round), cut-outs (through and not round, or from the rim)
/// and notches. A depression of no size (a face flat across the height
/// direction) is not a feature.
pub fn depressions(
    a: &PartAnalysis,
    d: &mut Draft,
    walls: &[Wall],
    sizes: &[WallSize],
    deps: &[Depression],
    config: &Config,
) {
    let least = a.tol().coplanar;
    for dep in deps {
        let Some(wall_feature) = d.wall_feature[dep.wall] else {
            continue; // in a squat slab: a machining feature, not a stiffness one
        };
        let wall = &walls[dep.wall];
        let dir = sizes[dep.wall].height_dir;
        let (lo, hi) = a.extent(&dep.faces, &dir);
        let width = wall
            .frame
            .z
            .cross(&dir)
            .try_normalize(DIRECTION_NORM_MIN)
            .map(|along| {
                let (l0, l1) = a.extent(&dep.faces, &along);
                l1 - l0
            });
        let round = dep
            .faces
            .iter()
            .filter_map(|&h| a.cylinder(h))
            .map(|c| 2.0 * c.radius)
            .fold(None, |m: Option<f64>, x| Some(m.map_or(x, |y| y.max(x))));
        let kind = match (dep.kind, round) {
            (DepressionKind::Hole { .. }, Some(_)) => StiffnessKind::Hole,
            (DepressionKind::Hole { through: true }, None) => StiffnessKind::Cutout,
            (DepressionKind::Hole { through: false }, None) => StiffnessKind::Pocket,
            (DepressionKind::Cutout, _) => StiffnessKind::Cutout,
            (DepressionKind::Notch, _) => StiffnessKind::Notch,
        };
        if hi - lo <= least || width.is_some_and(|w| w <= least) {
            continue;
        }
        let mut f = StiffnessFeature::new(kind, a.step_ids(&dep.faces));
        f.body = a.part().face(dep.faces[0]).body.0;
        if let (StiffnessKind::Hole, Some(diameter)) = (kind, round) {
            let height = hi - lo;
            let t = &config.thresholds;
            f.diameter = Some(diameter);
            f.height = Some(height);
            f.through = Some(matches!(dep.kind, DepressionKind::Hole { through: true }));
            f.large = Some(height > t.large_hole_factor * t.preferred_tool_diameter_mm);
        } else if matches!(dep.kind, DepressionKind::Hole { .. }) {
            // An opening in a side: its extent across the wall's height and
            // along it; a pocket also its depth into the wall.
            f.height = Some(hi - lo);
            f.width = width;
            f.through = Some(kind == StiffnessKind::Cutout);
        } else {
            let (_, top) = measure::extent(&wall.outline(), &dir);
            f.height = Some((top - lo).max(0.0));
            f.width = width;
        }
        d.features.push(f);
        d.refs.push(Some(wall_feature));
    }
}

/// Add fillets and chamfers, each on the thin leaf among the walls whose
/// side it touches.
pub fn details(
    a: &PartAnalysis,
    d: &mut Draft,
    walls: &[Wall],
    sizes: &[WallSize],
    claims: &Claims,
) {
    let mut walls_of_face: BTreeMap<FaceId, Vec<usize>> = BTreeMap::new();
    for (w, wall) in walls.iter().enumerate() {
        for &f in wall.sides.iter().flatten() {
            let list = walls_of_face.entry(f).or_default();
            if !list.contains(&w) {
                list.push(w);
            }
        }
    }
    let walls_of_detail = |faces: &[FaceId]| -> Vec<usize> {
        let mut touched: Vec<usize> = Vec::new();
        for &f in faces {
            for (g, _) in a.graph().neighbours(f) {
                for &w in walls_of_face.get(&g).into_iter().flatten() {
                    if !touched.contains(&w) {
                        touched.push(w);
                    }
                }
            }
        }
        touched.sort_by_key(|&w| (sizes[w].squat, !sizes[w].thin, sizes[w].base.is_none(), w));
        touched
    };
    let wall_of_detail = |faces: &[FaceId]| walls_of_detail(faces).first().copied();
    for b in &claims.blends {
        let mut f = StiffnessFeature::new(StiffnessKind::Fillet, a.step_ids(&b.faces));
        f.body = a.part().face(b.faces[0]).body.0;
        f.radius = b.radius;
        f.convex = Some(b.convex);
        let touched: Vec<usize> = walls_of_detail(&b.faces)
            .into_iter()
            .filter(|&w| d.wall_feature[w].is_some())
            .collect();
        let primary = match pocket_web(a, b, &touched, walls) {
            Some(web) => {
                let mut rest: Vec<usize> = touched.iter().copied().filter(|&w| w != web).collect();
                rest.sort_unstable();
                let pos = d.features.len();
                d.also.insert(
                    pos,
                    rest.iter().filter_map(|&w| d.wall_feature[w]).collect(),
                );
                Some(web)
            }
            None => touched.first().copied(),
        };
        d.features.push(f);
        d.refs.push(primary.and_then(|w| d.wall_feature[w]));
    }
    for e in &claims.engravings {
        let mut f = StiffnessFeature::new(StiffnessKind::Engraving, a.step_ids(&e.faces));
        f.body = a.part().face(e.faces[0]).body.0;
        f.height = Some(e.depth);
        f.length = Some(e.length);
        f.width = Some(e.width);
        d.features.push(f);
        d.refs
            .push(wall_of_detail(&e.faces).and_then(|w| d.wall_feature[w]));
    }
    for (c, width) in &claims.chamfers {
        let mut f = StiffnessFeature::new(StiffnessKind::Chamfer, a.step_ids(&[*c]));
        f.body = a.part().face(*c).body.0;
        f.width = Some(*width);
        d.features.push(f);
        d.refs
            .push(wall_of_detail(&[*c]).and_then(|w| d.wall_feature[w]));
    }
}

/// The wall (among `touched`) a pocket's blends `b` are in: a pocket's
/// blends run round its floor (a side of the web, square to up) and round
/// its corners (a cylinder along up) up the walls standing on it, so they
/// are the pocket's, in its web and on its walls, not one arbitrary wall's;
/// none for a fillet along one wall's foot, which keeps that wall.
fn pocket_web(
    a: &PartAnalysis,
    b: &crate::details::Blend,
    touched: &[usize],
    walls: &[Wall],
) -> Option<usize> {
    let up = a.up();
    let along = |v: &thinwall_geom::Vector3| {
        v.dot(&up).abs() > 1.0 - thinwall_geom::tolerance::NEAR_PARALLEL_EPS
    };
    let rounds_a_corner = b.faces.iter().any(|&f| {
        matches!(a.part().face(f).surface, thinwall_geom::Surface::Cylinder { frame, .. } if along(&frame.z))
    });
    if b.convex || touched.len() < 2 || !rounds_a_corner {
        return None;
    }
    let meets = |g: FaceId| {
        b.faces
            .iter()
            .any(|&f| a.graph().neighbours(f).any(|(h, _)| h == g))
    };
    touched.iter().copied().find(|&w| {
        let wall = &walls[w];
        wall.normals
            .iter()
            .zip(&wall.sides)
            .any(|(n, side)| along(n) && side.iter().any(|&g| meets(g)))
    })
}

/// Number the features by kind, then by smallest face id, and sort them so;
/// references become ids. Returns the features and each draft position's
/// new position.
pub fn number(d: Draft) -> (Vec<StiffnessFeature>, Vec<usize>) {
    let Draft {
        mut features,
        refs,
        also,
        ..
    } = d;
    let mut order: Vec<usize> = (0..features.len()).collect();
    order.sort_by_key(|&i| {
        (
            features[i].kind,
            features[i].faces.first().copied().unwrap_or(0),
        )
    });
    let mut counters: BTreeMap<StiffnessKind, u32> = BTreeMap::new();
    let mut ids = vec![FeatureId::new(StiffnessKind::Web, 0); features.len()];
    for &i in &order {
        let n = counters.entry(features[i].kind).or_insert(0);
        *n += 1;
        ids[i] = FeatureId::new(features[i].kind, *n);
    }
    for (i, f) in features.iter_mut().enumerate() {
        f.faces.dedup();
        f.id = ids[i];
        let target = refs[i].map(|r| ids[r]);
        if f.kind.is_wall() {
            f.base = target;
        } else {
            f.wall = target;
        }
        if let Some(others) = also.get(&i) {
            f.walls = target
                .into_iter()
                .chain(others.iter().map(|&r| ids[r]))
                .collect();
        }
    }
    let mut new_pos = vec![0; features.len()];
    for (new, &old) in order.iter().enumerate() {
        new_pos[old] = new;
    }
    let mut slots: Vec<Option<StiffnessFeature>> = features.into_iter().map(Some).collect();
    let sorted = order
        .iter()
        .map(|&i| slots[i].take().expect("each once"))
        .collect();
    (sorted, new_pos)
}
