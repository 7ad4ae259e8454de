//! Stiffness feature recognition (DOMAIN.md §1–2, Popma 3.2, 4.1, 5.4.1,
//! 6.1.1): walls from opposed planar side faces, their kind in the set-up
//! (web, rib, flange, wall) and thinness by the cantilever model; holes,
//! cut-outs and notches in them; fillets and chamfers on them.
//!
//! Face-pattern recognizers over the part and its adjacency graph; walls
//! claim their faces first, so a depression never takes a wall's side.
//!
//! ```no_run
//! let (part, _) = thinwall_step::read_file("panel.step").unwrap();
//! let graph = thinwall_graph::AdjacencyGraph::build(&part, &part.tolerances());
//! let r = thinwall_recognize::recognize(&part, &graph, &thinwall_recognize::Config::default());
//! for f in &r.features {
//!     println!("{} {} {:?}", f.id, f.kind.name(), f.thin);
//! }
//! ```

pub mod config;
pub mod deflection;
pub mod depressions;
pub mod details;
pub mod feature;
pub mod junctions;
pub mod planar;
pub mod walls;

pub use config::{Config, ConfigError, Kind};
pub use feature::{Plane, StiffnessFeature};
pub use junctions::Junction;

use depressions::DepressionKind;
use std::collections::{BTreeMap, HashSet};
use thinwall_brep::{FaceId, Part};
use thinwall_geom::Vector3;
use thinwall_graph::AdjacencyGraph;
use walls::Wall;

/// Everything recognition found.
#[derive(Clone, Debug)]
pub struct Recognition {
    /// Features in report order (walls first, then depressions and details).
    pub features: Vec<StiffnessFeature>,
    /// Wall-to-wall junctions, by index into `features` (walls only).
    pub junctions: Vec<Junction>,
    /// The chosen base of each wall feature (index into `features`).
    pub bases: BTreeMap<usize, usize>,
}

struct WallInfo {
    base: Option<usize>,
    tee: bool,
    height: f64,
    length: f64,
    deflection: f64,
    thin: bool,
    height_dir: Vector3,
}

/// Recognize the stiffness features of `part` in the set-up of `config`.
pub fn recognize(part: &Part, graph: &AdjacencyGraph, config: &Config) -> Recognition {
    let t0 = std::time::Instant::now();
    let trace = |what: &str| {
        if std::env::var_os("THINWALL_TRACE").is_some() {
            eprintln!("{:>8.3} s  {what}", t0.elapsed().as_secs_f64());
        }
    };
    let up = config.up_unit();
    let bbox = part.bounding_box();
    let tol = thinwall_geom::Tolerances::for_part(bbox.diagonal());
    let slab_tol = (tol.linear * 1000.0).max(1e-3);
    let walls = walls::find_walls(part, config, &tol);
    trace("walls");
    let heights: Vec<f64> = walls
        .iter()
        .map(|w| w.mid_plane().0.coords.dot(&up))
        .collect();
    let diag = bbox.diagonal();
    let junctions = junctions::resolve_l_junctions(
        junctions::find_junctions(part, graph, &walls),
        |w| heights[w],
        1e-6 * diag.max(1.0),
    );

    trace("junctions");
    // Base: the wall a wall meets along its longest foot (ties: the lower).
    let mut info: Vec<WallInfo> = Vec::with_capacity(walls.len());
    for (w, wall) in walls.iter().enumerate() {
        let best = junctions.iter().filter(|j| j.leaf == w).max_by(|a, b| {
            a.length
                .total_cmp(&b.length)
                .then(heights[b.base].total_cmp(&heights[a.base]))
        });
        let (h, l, dir) = match best {
            Some(j) => {
                let base = &walls[j.base];
                let (origin, n) = side_plane(base, j.base_side);
                let pts = wall.outline();
                let h = pts
                    .iter()
                    .map(|p| (p - origin).dot(&n).abs())
                    .fold(0.0, f64::max);
                let along = wall.frame.z.cross(&n);
                let l = match along.try_normalize(1e-6) {
                    Some(a) => walls::extent_along(&pts, &a),
                    None => walls::long_side(&wall.region),
                };
                (h, l, n)
            }
            None => (0.0, 0.0, up),
        };
        info.push(WallInfo {
            base: best.map(|j| j.base),
            tee: best.is_some_and(|j| j.tee),
            height: h,
            length: l,
            deflection: 0.0,
            thin: false,
            height_dir: dir,
        });
    }
    // Walls without a base: webs are measured by their widest cell.
    for w in 0..walls.len() {
        if info[w].base.is_some() {
            continue;
        }
        let leaf_sides: Vec<usize> = junctions
            .iter()
            .filter(|j| j.base == w)
            .map(|j| j.base_side)
            .collect();
        let side = if leaf_sides.iter().filter(|&&s| s == 1).count() > leaf_sides.len() / 2 {
            1
        } else {
            0
        };
        let wall = &walls[w];
        let cells: Vec<geo::MultiPolygon<f64>> = if leaf_sides.is_empty() {
            vec![wall.region.clone()]
        } else {
            wall.sides[side]
                .iter()
                .filter_map(|&f| planar::PlanarFace::new(part, f))
                .map(|p| p.polygon_in(&wall.frame))
                .collect()
        };
        let (mut h, mut l) = (0.0, 0.0);
        for c in &cells {
            let r = planar::inscribed_radius(c);
            if r > h {
                h = r;
                l = walls::long_side(c);
            }
        }
        let in_plane_up = up - wall.frame.z * up.dot(&wall.frame.z);
        info[w].height = h;
        info[w].length = l;
        info[w].height_dir = in_plane_up.try_normalize(1e-6).unwrap_or(wall.frame.x);
    }
    for (w, wall) in walls.iter().enumerate() {
        let i = &mut info[w];
        i.deflection = deflection::deflection_mm(
            wall.thickness,
            i.height,
            i.length.max(i.height),
            &config.thinness,
        );
        i.thin = i.deflection > config.thinness.allowed_deflection_mm;
    }
    trace("thinness");
    // Kinds.
    let kinds: Vec<Kind> = (0..walls.len())
        .map(|w| {
            let thin_leaves = (0..walls.len()).any(|v| info[v].base == Some(w) && info[v].thin);
            if thin_leaves {
                Kind::Web
            } else if info[w].base.is_some() {
                if info[w].tee {
                    Kind::Rib
                } else {
                    Kind::Flange
                }
            } else {
                Kind::Wall
            }
        })
        .collect();

    // Depressions, rims, details.
    let any_side: HashSet<FaceId> = walls
        .iter()
        .flat_map(|w| w.sides.iter().flatten().copied())
        .collect();
    let mut taken: HashSet<FaceId> = any_side.clone();
    let mut deps = Vec::new();
    // Thin walls claim first, then thick ones.
    let mut order: Vec<usize> = (0..walls.len()).collect();
    order.sort_by_key(|&w| (!info[w].thin, w));
    let mut rims: Vec<Vec<FaceId>> = vec![Vec::new(); walls.len()];
    let mut blends = Vec::new();
    let mut chamfers = Vec::new();
    // Depression and detail recognizers claim faces in priority order
    // (walls have claimed their sides already); kinds left out of the
    // priority list run last, in the default order.
    let mut stages: Vec<Kind> = Vec::new();
    for k in config
        .priority
        .iter()
        .chain(Config::default().priority.iter())
    {
        let stage = if *k == Kind::Notch { Kind::Cutout } else { *k };
        if !stage.is_wall() && !stages.contains(&stage) {
            stages.push(stage);
        }
    }
    for stage in stages {
        match stage {
            Kind::Hole => {
                for &w in &order {
                    deps.extend(depressions::holes(
                        part, graph, &walls, w, &mut taken, &any_side, slab_tol,
                    ));
                }
            }
            Kind::Cutout => {
                for &w in &order {
                    let rim =
                        depressions::rim_faces(part, graph, &walls, w, &taken, &any_side, slab_tol);
                    let openings = depressions::edge_openings(part, graph, w, &rim);
                    let used: HashSet<FaceId> = openings
                        .iter()
                        .flat_map(|d| d.faces.iter().copied())
                        .collect();
                    // Blends on the rim (inside corner radii, rounded tops) are details.
                    rims[w] = rim
                        .into_iter()
                        .filter(|f| {
                            !used.contains(f) && !details::is_blend_candidate(part, graph, *f)
                        })
                        .collect();
                    taken.extend(used.iter().copied());
                    taken.extend(rims[w].iter().copied());
                    deps.extend(openings);
                }
            }
            Kind::Fillet => {
                blends = details::blends(part, graph, &taken);
                for b in &blends {
                    taken.extend(b.faces.iter().copied());
                }
            }
            Kind::Chamfer => {
                chamfers =
                    details::chamfers(part, graph, &taken, config.thresholds.chamfer_max_width_mm);
                taken.extend(chamfers.iter().map(|c| c.0));
            }
            _ => {}
        }
        trace(stage.name());
    }
    trace("details");
    // Features: walls first.
    let sid = |fs: &[FaceId]| -> Vec<u64> {
        let mut v: Vec<u64> = fs.iter().map(|&f| part.face(f).step_id).collect();
        v.sort();
        v
    };
    let mut features: Vec<StiffnessFeature> = Vec::new();
    let mut wall_feature: Vec<Option<usize>> = vec![None; walls.len()];
    for (w, wall) in walls.iter().enumerate() {
        if !config.reports(kinds[w]) {
            continue;
        }
        let i = &info[w];
        let sides = [sid(&wall.sides[0]), sid(&wall.sides[1])];
        let mut side_faces: Vec<u64> = sides.iter().flatten().copied().collect();
        side_faces.sort();
        let top = sid(&rims[w]);
        let mut faces = side_faces.clone();
        faces.extend(&top);
        faces.sort();
        let (p, n) = wall.mid_plane();
        let mut f = StiffnessFeature::new(kinds[w], faces);
        f.side_faces = Some(side_faces);
        f.sides = Some(sides);
        f.thin = Some(i.thin);
        f.thickness = Some(wall.thickness);
        f.height = Some(i.height);
        f.length = Some(i.length);
        f.deflection = Some(i.deflection);
        f.slenderness = Some(if wall.thickness > 0.0 {
            i.height / wall.thickness
        } else {
            0.0
        });
        f.mid_plane = Some(Plane {
            point: [p.x, p.y, p.z],
            normal: [n.x, n.y, n.z],
        });
        f.access_directions = Some([
            [wall.normals[0].x, wall.normals[0].y, wall.normals[0].z],
            [wall.normals[1].x, wall.normals[1].y, wall.normals[1].z],
        ]);
        f.top_end_faces = Some(top);
        wall_feature[w] = Some(features.len());
        features.push(f);
    }
    for (w, &fi) in wall_feature.iter().enumerate() {
        if let (Some(fi), Some(b)) = (fi, info[w].base) {
            features[fi].base = wall_feature[b].map(|bf| format!("#{bf}"));
        }
    }
    for d in &deps {
        let kind = match d.kind {
            DepressionKind::Hole { .. } => Kind::Hole,
            DepressionKind::Cutout => Kind::Cutout,
            DepressionKind::Notch => Kind::Notch,
        };
        if !config.reports(kind) {
            continue;
        }
        let mut f = StiffnessFeature::new(kind, sid(&d.faces));
        f.wall = wall_feature[d.wall].map(|i| format!("#{i}"));
        let wall = &walls[d.wall];
        let dir = info[d.wall].height_dir;
        let (lo, hi) = depressions::extent(part, &d.faces, &dir);
        match d.kind {
            DepressionKind::Hole { through } => {
                let diameter = d
                    .faces
                    .iter()
                    .filter_map(|&h| match part.face(h).surface {
                        thinwall_geom::Surface::Cylinder { radius, .. } => Some(2.0 * radius),
                        _ => None,
                    })
                    .fold(None, |m: Option<f64>, x| Some(m.map_or(x, |y| y.max(x))));
                let height = hi - lo;
                let diameter = diameter.unwrap_or(height);
                f.diameter = Some(diameter);
                f.height = Some(height);
                f.through = Some(through);
                f.large = Some(
                    height
                        > config.thresholds.large_hole_factor
                            * config.thresholds.preferred_tool_diameter_mm,
                );
            }
            _ => {
                let top = wall
                    .outline()
                    .iter()
                    .map(|p| p.coords.dot(&dir))
                    .fold(f64::NEG_INFINITY, f64::max);
                f.height = Some((top - lo).max(0.0));
                let along = wall.frame.z.cross(&dir);
                if let Some(a) = along.try_normalize(1e-6) {
                    let (l0, l1) = depressions::extent(part, &d.faces, &a);
                    f.width = Some(l1 - l0);
                }
            }
        }
        features.push(f);
    }
    // The wall a detail sits on: the thin leaf among the walls whose side it touches.
    let wall_of_detail = |faces: &[FaceId]| -> Option<usize> {
        let mut touched: Vec<usize> = Vec::new();
        for &f in faces {
            for (g, _) in graph.neighbours(f) {
                for (w, wall) in walls.iter().enumerate() {
                    if wall.contains_side_face(g).is_some() && !touched.contains(&w) {
                        touched.push(w);
                    }
                }
            }
        }
        touched.sort_by_key(|&w| (!info[w].thin, info[w].base.is_none(), w));
        touched.first().copied()
    };
    if config.reports(Kind::Fillet) {
        for b in &blends {
            let mut f = StiffnessFeature::new(Kind::Fillet, sid(&b.faces));
            f.radius = b.radius;
            f.convex = Some(b.convex);
            f.wall = wall_of_detail(&b.faces)
                .and_then(|w| wall_feature[w])
                .map(|i| format!("#{i}"));
            features.push(f);
        }
    }
    if config.reports(Kind::Chamfer) {
        for (c, width) in &chamfers {
            let mut f = StiffnessFeature::new(Kind::Chamfer, sid(&[*c]));
            f.width = Some(*width);
            f.wall = wall_of_detail(&[*c])
                .and_then(|w| wall_feature[w])
                .map(|i| format!("#{i}"));
            features.push(f);
        }
    }
    // Stable ids: by kind, then by smallest face id; references rewritten.
    let mut order: Vec<usize> = (0..features.len()).collect();
    order.sort_by_key(|&i| {
        (
            features[i].kind,
            features[i].faces.first().copied().unwrap_or(0),
        )
    });
    let mut counters: BTreeMap<&str, usize> = BTreeMap::new();
    let mut new_id = vec![String::new(); features.len()];
    for &i in &order {
        let p = feature::prefix(features[i].kind);
        let n = counters.entry(p).or_insert(0);
        *n += 1;
        new_id[i] = format!("{p}{n}");
    }
    let rename = |r: &Option<String>| -> Option<String> {
        r.as_ref()
            .and_then(|s| s.strip_prefix('#'))
            .and_then(|s| s.parse::<usize>().ok())
            .map(|i| new_id[i].clone())
    };
    for i in 0..features.len() {
        features[i].id = new_id[i].clone();
        features[i].base = rename(&features[i].base);
        features[i].wall = rename(&features[i].wall);
    }
    let mut sorted: Vec<StiffnessFeature> = order.iter().map(|&i| features[i].clone()).collect();
    // Remap junctions and bases to positions in the sorted list.
    let pos_of_old: BTreeMap<usize, usize> = order
        .iter()
        .enumerate()
        .map(|(new, &old)| (old, new))
        .collect();
    let wall_pos = |w: usize| wall_feature[w].and_then(|fi| pos_of_old.get(&fi).copied());
    let junctions_out: Vec<Junction> = junctions
        .iter()
        .filter_map(|j| {
            Some(Junction {
                leaf: wall_pos(j.leaf)?,
                base: wall_pos(j.base)?,
                ..j.clone()
            })
        })
        .collect();
    let bases: BTreeMap<usize, usize> = (0..walls.len())
        .filter_map(|w| Some((wall_pos(w)?, wall_pos(info[w].base?)?)))
        .collect();
    sorted.iter_mut().for_each(|f| f.faces.dedup());
    Recognition {
        features: sorted,
        junctions: junctions_out,
        bases,
    }
}

/// A point on side `s`'s plane of a wall and that side's outward normal.
fn side_plane(wall: &Wall, s: usize) -> (thinwall_geom::Point3, Vector3) {
    if s == 0 {
        (wall.frame.origin, wall.normals[0])
    } else {
        (
            wall.frame.origin - wall.frame.z * wall.thickness,
            wall.normals[1],
        )
    }
}
