//! The shape of a depression group and its typing: which stock planes it
//! opens to, its planes and cylinders, and from those its kind, whether
//! it goes through, its profile and its catalogue name.

use crate::catalog;
use crate::closed_slot;
use crate::{face_plane, radii, same_direction, same_plane, Plane, Stock};
use std::collections::BTreeSet;
use thinwall_analysis::{Catalog, Cylinder, MachiningKind, PartAnalysis, Profile};
use thinwall_brep::FaceId;
use thinwall_geom::tolerance::NEAR_PARALLEL_EPS;
use thinwall_geom::{Surface, Vector3};
use thinwall_graph::Convexity;

/// A concave cylinder sweeping this much or more is the round end of a
/// slot or pocket (half a circle), not a blend, degrees.
pub(crate) const HALF_SWEEP_DEG: f64 = 150.0;
/// The round ends of a slot along a block edge are quarter circles,
/// within this slack (boundary sampling), degrees.
const QUARTER_DEG: f64 = 90.0;
const QUARTER_SLACK_DEG: f64 = 2.0;
/// Coaxial concave cylinders sweeping this much together are a hole (a
/// full circle less its boundary sampling), degrees.
const FULL_SWEEP_DEG: f64 = 300.0;
/// What is left of a hole that another feature (not a hole) cuts sweeps
/// at least this much: a circular slot's round floor is half a circle at
/// most, degrees.
const CUT_HOLE_SWEEP_DEG: f64 = 200.0;

/// A floor outline filling less of its minimum rectangle than this is a
/// triangle (a right triangle fills ½).
const TRIANGLE_FILL: f64 = 0.6;
/// The profile a ring of walls (or what is left of one where another
/// feature cut it) comes from, by the angles between their normals: six
/// walls at 60° or parallel to each other, or three or more at 60°, 120°
/// or parallel with two meeting at 120° inside, or four with a parallel
/// pair and one at 60°, a hexagon; walls square or parallel only, a
/// rectangle; three walls with no two parallel, a triangle.
pub(crate) fn ring_profile(walls: &[Vector3]) -> Profile {
    let cos = |i: usize, j: usize| walls[i].dot(&walls[j]);
    let pairs = || (0..walls.len()).flat_map(|i| (i + 1..walls.len()).map(move |j| (i, j)));
    let square_or_parallel = pairs().all(|(i, j)| {
        let c = cos(i, j).abs();
        !(NEAR_PARALLEL_EPS..=1.0 - NEAR_PARALLEL_EPS).contains(&c)
    });
    let at_60 = |i: usize, j: usize| (cos(i, j).abs() - 0.5).abs() < NEAR_PARALLEL_EPS.sqrt();
    let sixty = pairs().any(|(i, j)| at_60(i, j));
    // A hexagon's walls are parallel or at 60° to each other, all of them.
    let hexagon_walls =
        pairs().all(|(i, j)| at_60(i, j) || cos(i, j).abs() > 1.0 - NEAR_PARALLEL_EPS);
    let parallel = pairs().any(|(i, j)| cos(i, j) < -1.0 + NEAR_PARALLEL_EPS);
    // Two walls meeting at 120° inside (normals 60° apart): a triangle has
    // no such corner (its three add up to 180°).
    let wide_corner = pairs().any(|(i, j)| (cos(i, j) - 0.5).abs() < NEAR_PARALLEL_EPS.sqrt());
    match walls.len() {
        n if n >= 5 && hexagon_walls => Profile::Hexagonal,
        n if n >= 5 => Profile::Free,
        n if n >= 3 && square_or_parallel => Profile::Rectangular,
        n if n >= 3 && hexagon_walls && wide_corner => Profile::Hexagonal,
        3 if !parallel => Profile::Triangular,
        n if n >= 3 && sixty && parallel => Profile::Hexagonal,
        _ => Profile::Free,
    }
}

/// The profile two walls in a V are left of: a hexagon's where they meet
/// at 120° (normals at 60°), else a triangle's.
fn v_profile(walls: &[Vector3]) -> Profile {
    if (walls[0].dot(&walls[1]) - 0.5).abs() < NEAR_PARALLEL_EPS.sqrt() {
        Profile::Hexagonal
    } else {
        Profile::Triangular
    }
}

/// Whether some pair of the unit normals has a cosine that `holds`.
fn any_pair(normals: &[Vector3], holds: impl Fn(f64) -> bool) -> bool {
    normals
        .iter()
        .enumerate()
        .any(|(i, n)| normals[i + 1..].iter().any(|m| holds(n.dot(m))))
}

/// Whether two of the normals face each other (parallel walls).
fn facing_pair(normals: &[Vector3]) -> bool {
    any_pair(normals, |c| c < -1.0 + NEAR_PARALLEL_EPS)
}

/// Whether two of the normals are square to each other.
fn square_pair(normals: &[Vector3]) -> bool {
    any_pair(normals, |c| c.abs() < NEAR_PARALLEL_EPS)
}

/// Whether `n` stands square on every one of `others` it is not.
fn square_to_rest(n: &Vector3, others: &[Vector3]) -> bool {
    others
        .iter()
        .all(|m| same_direction(n, m) || n.dot(m).abs() < NEAR_PARALLEL_EPS)
}

/// A slot through the part typed by its walls: a parallel pair, a
/// rectangle; two walls meeting in a V, a triangle.
fn through_slot(walls: &[Vector3]) -> (MachiningKind, bool, Profile) {
    match (walls.len(), facing_pair(walls)) {
        (_, true) => (MachiningKind::Slot, true, Profile::Rectangular),
        (2, false) => (MachiningKind::Slot, true, Profile::Triangular),
        _ => (MachiningKind::Slot, true, Profile::Free),
    }
}

/// The area of the faces' convex hull over that of its minimum rectangle.
fn fill_ratio(a: &PartAnalysis, faces: &[FaceId]) -> f64 {
    use geo::{Area, ConvexHull};
    let polys: geo::MultiPolygon<f64> = faces
        .iter()
        .filter_map(|&f| a.polygon(f))
        .flat_map(|p| p.0)
        .collect();
    let hull = polys.convex_hull();
    match thinwall_analysis::polygon::min_rect_sides(&hull) {
        Some((long, short)) if long * short > 0.0 => hull.unsigned_area() / (long * short),
        _ => 1.0,
    }
}

/// A lone face on the block's edge is a bevel when at least this many
/// times longer than wide.
const LONE_BEVEL: f64 = 3.0;

/// The typing of a group.
pub(crate) struct Typed {
    pub kind: MachiningKind,
    pub through: bool,
    pub profile: Profile,
    pub catalog: Option<Catalog>,
}

/// Whether walls with these normals (into the void) can close round a
/// floor of normal `n`: seen along it, their directions leave no half-turn
/// free (three walls of a slot, two facing and a back, leave the open end's
/// side).
pub(crate) fn surrounds(walls: &[Vector3], n: &Vector3) -> bool {
    let u = thinwall_geom::frame::any_perpendicular(n);
    let v = n.cross(&u);
    let mut angles: Vec<f64> = walls.iter().map(|w| w.dot(&v).atan2(w.dot(&u))).collect();
    angles.sort_by(f64::total_cmp);
    let (Some(&first), Some(&last)) = (angles.first(), angles.last()) else {
        return false;
    };
    let widest = angles
        .windows(2)
        .map(|p| p[1] - p[0])
        .fold(std::f64::consts::TAU - (last - first), f64::max);
    widest < std::f64::consts::PI - NEAR_PARALLEL_EPS.sqrt()
}

/// Walls of `group` adjacent to wall `w` (sharing an edge).
pub(crate) fn wall_neighbours(a: &PartAnalysis, w: FaceId, walls: &[FaceId]) -> usize {
    a.graph()
        .neighbours(w)
        .filter(|(x, _)| *x != w && walls.contains(x))
        .map(|(x, _)| x)
        .collect::<BTreeSet<FaceId>>()
        .len()
}

/// What typing a depression group needs: the stock planes it opens to,
/// its distinct planes, its concave cylinders.
pub(crate) struct GroupShape<'g> {
    stock: &'g Stock,
    group: &'g [FaceId],
    touched: &'g BTreeSet<usize>,
    /// Distinct planes among the planar faces: normal and offset.
    planes: Vec<(Vector3, f64)>,
    pub(crate) cylinders: Vec<Cylinder>,
    /// The stock plane it is entered from.
    entry: Option<usize>,
}

impl<'g> GroupShape<'g> {
    pub(crate) fn new(
        a: &PartAnalysis,
        stock: &'g Stock,
        group: &'g [FaceId],
        touched: &'g BTreeSet<usize>,
    ) -> Self {
        let opposite = opposite_axes(touched);
        let mut planes: Vec<Plane> = Vec::new();
        for &f in group {
            if let Some(q) = face_plane(a, f) {
                if !planes.iter().any(|p| same_plane(a, p, &q)) {
                    planes.push(q);
                }
            }
        }
        let cylinders: Vec<Cylinder> = group
            .iter()
            .filter_map(|&f| a.concave_cylinder(f))
            .collect();
        // The entry: a touched plane not in an opposite pair, facing the
        // same way as a floor if there is one.
        let candidates: Vec<usize> = touched
            .iter()
            .copied()
            .filter(|sp| !opposite.contains(&(sp / 2)))
            .collect();
        // Ranked by whether a face of the group faces it, then by the
        // group's depth seen from it: never by the planes' numbering,
        // which follows the world's axes.
        let facing = envelope_normal(a, group, &planes, &cylinders);
        let rank = |sp: usize| {
            let n = stock.normal(sp);
            let faces_it = planes.iter().any(|(m, _)| same_direction(m, &n))
                || facing.is_some_and(|m| m.dot(&n) > ENVELOPE_FACING);
            let (lo, hi) = a.extent(group, &n);
            (faces_it, hi - lo)
        };
        // In a set-up, from up wherever the group opens there.
        let from_up = stock.up_plane().filter(|sp| touched.contains(sp));
        let entry = from_up.or_else(|| {
            candidates.iter().copied().max_by(|&x, &y| {
                let (fx, dx) = rank(x);
                let (fy, dy) = rank(y);
                fx.cmp(&fy).then(dx.total_cmp(&dy))
            })
        });
        let entry = entry.or_else(|| touched.iter().next().copied());
        // The curved envelope is entered from the block plane it faces
        // (which it may touch along a line only).
        let entry = match facing {
            Some(m) if from_up.is_none() => {
                (0..6).max_by(|&x, &y| m.dot(&stock.normal(x)).total_cmp(&m.dot(&stock.normal(y))))
            }
            _ => entry,
        };
        Self {
            stock,
            group,
            touched,
            planes,
            cylinders,
            entry,
        }
    }

    /// Kind, through, profile and catalogue name.
    pub(crate) fn typing(&self, a: &PartAnalysis) -> Typed {
        if !self.cylinders.is_empty() {
            return self.curved_typing(a);
        }
        let (kind, through, profile) = self.planar_typing(a);
        Typed {
            kind,
            through,
            profile,
            catalog: catalog::planar(kind, through, profile),
        }
    }

    /// Whether the group is what is left of a hole that another hole
    /// crosses: concave cylinders on parallel axes (and the bottom, a plane
    /// square to them, when blind), entered through faces square to them
    /// (the block's, or another feature's floor met at a convex rim), and
    /// along their length meeting (convexly) only other features' faces
    /// parallel to the axis: at least one of them another
    /// hole, or more than half the circle left. A circular slot's edges
    /// meet the block instead, and its arc is half a circle at most.
    /// `round_sweep`: [`Self::round_sweep`].
    fn crossing_holes_piece(&self, a: &PartAnalysis, round_sweep: f64) -> bool {
        let first = self.cylinders[0];
        let tol = crate::axis_tol(a);
        let parallel = |c: &Cylinder| c.axis.dot(&first.axis).abs() > 1.0 - NEAR_PARALLEL_EPS;
        let bottom = |f: FaceId| {
            a.props(f)
                .normal
                .is_some_and(|n| n.dot(&first.axis).abs() > 1.0 - NEAR_PARALLEL_EPS)
        };
        if !self
            .group
            .iter()
            .all(|&f| a.concave_cylinder(f).is_some_and(|c| parallel(&c)) || bottom(f))
        {
            return false;
        }
        let mut other_hole = false;
        for &f in self.group {
            for (g, adj) in a.graph().neighbours(f) {
                if self.group.contains(&g) {
                    continue;
                }
                let across = a.props(g).normal.map(|n| n.dot(&first.axis).abs());
                let on_block = self.stock.plane_of(a, g).is_some();
                let fits = match (a.concave_cylinder(g), across) {
                    // The face it was entered from: the block's, or another
                    // feature's floor met at the rim.
                    (_, Some(c)) if c > 1.0 - NEAR_PARALLEL_EPS => {
                        on_block || adj.convexity == Convexity::Convex
                    }
                    (_, Some(c)) => {
                        c < NEAR_PARALLEL_EPS && !on_block && adj.convexity == Convexity::Convex
                    }
                    (Some(h), None) if parallel(&h) => {
                        other_hole |= !h.coaxial(&first, tol);
                        adj.convexity == Convexity::Convex
                    }
                    (_, None) => false,
                };
                if !fits {
                    return false;
                }
            }
        }
        other_hole || round_sweep >= CUT_HOLE_SWEEP_DEG
    }

    /// Whether the group meets three block planes or more, no two of them
    /// opposite.
    fn corner_only(&self) -> bool {
        self.touched.len() >= 3 && opposite_axes(self.touched).is_empty()
    }

    /// How far round the widest concave cylinder on each of their distinct
    /// axes goes, degrees.
    fn end_sweeps(&self, a: &PartAnalysis) -> Vec<f64> {
        let tol = crate::axis_tol(a);
        let mut ends: Vec<(Cylinder, f64)> = Vec::new();
        for &f in self.group {
            let (Some(c), Some(s)) = (a.concave_cylinder(f), a.cylinder_sweep_deg(f)) else {
                continue;
            };
            match ends.iter_mut().find(|(e, _)| e.coaxial(&c, tol)) {
                Some(end) => end.1 = end.1.max(s),
                None => ends.push((c, s)),
            }
        }
        ends.into_iter().map(|(_, s)| s).collect()
    }

    /// How far round, together, the concave cylinders on the first one's
    /// axis go, degrees.
    fn round_sweep(&self, a: &PartAnalysis) -> f64 {
        let first = self.cylinders[0];
        let tol = crate::axis_tol(a);
        self.group
            .iter()
            .filter(|&&f| {
                a.concave_cylinder(f)
                    .is_some_and(|c| c.coaxial(&first, tol))
            })
            .filter_map(|&f| a.cylinder_sweep_deg(f))
            .sum()
    }

    /// Groups with concave cylinders: holes, O-rings, circular slots,
    /// steps and pocket ends.
    fn curved_typing(&self, a: &PartAnalysis) -> Typed {
        let k = self.curved_facts(a);
        if k.core && k.floor {
            typed(
                MachiningKind::Groove,
                false,
                Profile::Circular,
                Some(Catalog::ORing),
            )
        } else if k.walls.is_empty() {
            self.wallless_typing(a, &k)
        } else {
            self.walled_typing(&k)
        }
    }

    /// What the typing of a group with concave cylinders reads.
    fn curved_facts(&self, a: &PartAnalysis) -> CurvedFacts {
        let first = self.cylinders[0];
        let tol = crate::axis_tol(a);
        let normal_along = |f: FaceId, across: bool| {
            a.props(f).normal.is_some_and(|n| {
                let c = n.dot(&first.axis).abs();
                if across {
                    c > 1.0 - NEAR_PARALLEL_EPS
                } else {
                    c < NEAR_PARALLEL_EPS
                }
            })
        };
        let floor = self.group.iter().any(|&f| normal_along(f, true));
        let walls: Vec<FaceId> = self
            .group
            .iter()
            .copied()
            .filter(|&f| normal_along(f, false))
            .collect();
        let core = self
            .group
            .iter()
            .filter_map(|&f| a.cylinder(f))
            .any(|c| c.convex && c.coaxial(&first, tol));
        let sweeps: Vec<f64> = self
            .group
            .iter()
            .filter(|&&f| a.concave_cylinder(f).is_some())
            .filter_map(|&f| a.cylinder_sweep_deg(f))
            .collect();
        let round_sweep = self.round_sweep(a);
        // A round end another cut split in pieces is one end (each piece
        // may span the whole arc at its own height).
        let ends = self.end_sweeps(a);
        let halves = ends.iter().filter(|&&s| s >= HALF_SWEEP_DEG).count();
        let tangent_wall = walls.iter().any(|&w| {
            a.graph().neighbours(w).any(|(g, adj)| {
                adj.convexity == Convexity::Smooth && a.concave_cylinder(g).is_some()
            })
        });
        // Quarter circles, one of which a chamfer or another cut may have
        // trimmed.
        let quarters = sweeps.iter().all(|&s| s < QUARTER_DEG + QUARTER_SLACK_DEG)
            && sweeps
                .iter()
                .any(|s| (s - QUARTER_DEG).abs() < QUARTER_SLACK_DEG);
        let mut planes: Vec<Plane> = Vec::new();
        for p in walls.iter().filter_map(|&w| face_plane(a, w)) {
            if !planes.iter().any(|q| same_plane(a, q, &p)) {
                planes.push(p);
            }
        }
        CurvedFacts {
            floor,
            wall_planes: planes.len(),
            walls,
            core,
            sweeps,
            round_sweep,
            ends,
            halves,
            tangent_wall,
            quarters,
        }
    }

    /// A half circle through the part (one plane beside it at most, in
    /// pieces or not: where material beyond the edge closed its open side
    /// lower down).
    fn half_through_slot(k: &CurvedFacts) -> Option<Typed> {
        (k.wall_planes <= 1 && !k.floor && k.halves > 0 && k.sweeps.len() == 1).then(|| {
            typed(
                MachiningKind::Slot,
                true,
                Profile::Circular,
                Some(Catalog::CircularThroughSlot),
            )
        })
    }

    /// Concave cylinders with no wall square to their axis: holes, slots
    /// and steps.
    fn wallless_typing(&self, a: &PartAnalysis, k: &CurvedFacts) -> Typed {
        use Catalog as C;
        use MachiningKind::*;
        let (floor, half) = (k.floor, k.halves > 0);
        if k.round_sweep >= FULL_SWEEP_DEG {
            let (kind, through, profile) = hole_typing(a, self.group, &self.cylinders);
            let name = match (through, profile) {
                (true, Profile::Circular) => Some(C::ThroughHole),
                (false, Profile::Circular) => Some(C::BlindHole),
                _ => None,
            };
            typed(kind, through, profile, name)
        } else if self.crossing_holes_piece(a, k.round_sweep) {
            let name = if floor { C::BlindHole } else { C::ThroughHole };
            typed(Hole, !floor, Profile::Circular, Some(name))
        } else if let Some(t) = Self::half_through_slot(k) {
            t
        } else if !floor && self.touched.is_empty() {
            // Both ends cut away by other features and no floor: what is
            // left of a hole through the part (a slot through it opens
            // onto the block).
            typed(Hole, true, Profile::Circular, Some(C::ThroughHole))
        } else if !floor && !half && self.corner_only() {
            // A quarter circle meeting block planes square to each other
            // only (the top and a corner's two sides), its floor cut away
            // by another feature: a step round a corner.
            typed(Step, false, Profile::Circular, Some(C::CircularBlindStep))
        } else if !floor {
            typed(Slot, true, Profile::Circular, None)
        } else {
            let name = (!half).then_some(C::CircularBlindStep);
            typed(Step, false, Profile::Circular, name)
        }
    }

    /// Concave cylinders beside walls square to their axis: slots, steps
    /// and pockets with round ends.
    fn walled_typing(&self, k: &CurvedFacts) -> Typed {
        use Catalog as C;
        use MachiningKind::*;
        let (floor, halves, ends) = (k.floor, k.halves, &k.ends);
        let (walls, tangent_wall, quarters) = (&k.walls, k.tangent_wall, k.quarters);
        if let Some(t) = Self::half_through_slot(k) {
            t
        } else if !floor && walls.len() == 1 && tangent_wall && quarters {
            // Quarter circles either side of one face they run into, their
            // axes along it: the same slot lying on its side.
            typed(
                Slot,
                false,
                Profile::CircularEnd,
                Some(C::HCircularEndBlindSlot),
            )
        } else if !floor {
            typed(Slot, true, Profile::CircularEnd, None)
        } else if halves >= 1 && ends.len() >= 2 {
            // Two round ends (one may be cut short by another feature).
            typed(
                Pocket,
                false,
                Profile::CircularEnd,
                Some(C::CircularEndPocket),
            )
        } else if halves == 1 {
            typed(
                Slot,
                false,
                Profile::CircularEnd,
                Some(C::VCircularEndBlindSlot),
            )
        } else if !tangent_wall {
            // A quarter circle in a corner whose other walls meet it at an
            // angle (cut by another feature), not a slot's ends running
            // into its back wall.
            typed(Step, false, Profile::Circular, Some(C::CircularBlindStep))
        } else if quarters {
            // Quarter circles at its ends: half an obround, cut lengthwise
            // by the side it opens to.
            typed(
                Slot,
                false,
                Profile::CircularEnd,
                Some(C::HCircularEndBlindSlot),
            )
        } else if self.touched.len() >= 2 {
            // An end cut short by another feature, open to a second block
            // face: what is left of a slot with a round end.
            typed(
                Slot,
                false,
                Profile::CircularEnd,
                Some(C::VCircularEndBlindSlot),
            )
        } else {
            // Ends cut short by another feature: what is left of a pocket.
            typed(
                Pocket,
                false,
                Profile::CircularEnd,
                Some(C::CircularEndPocket),
            )
        }
    }

    /// Groups of planar faces only: typed by their floor (a face every
    /// other face stands square on) and their walls, not by the stock
    /// planes they reach (a feature cut into another one's face reaches
    /// none).
    fn planar_typing(&self, a: &PartAnalysis) -> (MachiningKind, bool, Profile) {
        use MachiningKind::*;
        use Profile as P;
        // One strip of a face meeting three block planes: a bevel on the
        // block's edge (a broad face there is the part's own side).
        if self.planes.is_empty() {
            // Convex curved faces only (a frame's outer flange, a skin's
            // outside): the part's curved envelope under the block.
            return (Face, false, P::Free);
        }
        let (width, length) = a.strip_width(self.group[0]);
        if self.group.len() == 1 && self.touched.len() >= 3 && length >= LONE_BEVEL * width {
            return (Chamfer, false, P::Slanted);
        }
        let floor = self.floor(a);
        let on_floor = |n: &Vector3| floor.is_some_and(|(m, _)| same_direction(n, &m));
        let walls: Vec<Vector3> = self
            .planes
            .iter()
            .filter(|p| !on_floor(&p.0))
            .map(|p| p.0)
            .collect();
        let w = walls.len();
        let parallel = facing_pair(&walls);
        let square = square_pair(&walls);
        let wall_faces: Vec<FaceId> = self
            .group
            .iter()
            .copied()
            .filter(|&f| a.props(f).normal.is_some_and(|n| !on_floor(&n)))
            .collect();
        let closed = w >= 3
            && floor.is_none_or(|(n, _)| surrounds(&walls, &n))
            && wall_faces
                .iter()
                .all(|&f| wall_neighbours(a, f, &wall_faces) >= 2);
        let sides = ring_profile(&walls);
        match floor {
            // A blind slot whose open end material beyond closed lower
            // down (module `closed_slot`): four walls, one of them never
            // meeting the face it was entered from.
            Some(_) if closed && w == 4 && self.closed_lower(a, &wall_faces) => {
                (Slot, false, P::Rectangular)
            }
            Some(_) if closed => (Pocket, false, sides),
            // One wall: square to the stock, a step along a whole edge;
            // else a triangle in a corner or a slanted step, by the floor.
            Some(_) if w == 1 && self.stock.aligned(&walls[0]) => (Step, true, P::Rectangular),
            Some((n, fill)) if w == 1 => match self.wall_ends(a, &wall_faces, &n) {
                Some(true) => (Step, true, P::Slanted),
                Some(false) => (Step, false, P::Triangular),
                None if fill < TRIANGLE_FILL => (Step, false, P::Triangular),
                None => (Step, true, P::Slanted),
            },
            Some(_) if w == 2 && parallel => (Slot, true, P::Rectangular),
            Some(_) if w == 2 && square => (Step, false, P::Rectangular),
            // Two walls, one square to the block and one across a corner:
            // a triangle in a corner beside another cut's wall (a
            // two-sided step's walls meet in a V, neither square).
            Some(_)
                if w == 2 && (self.stock.aligned(&walls[0]) != self.stock.aligned(&walls[1])) =>
            {
                (Step, false, P::Triangular)
            }
            // Two walls in a V opening onto no block plane at all (a
            // two-sided step opens onto the block's sides): what other
            // cuts left of a pocket, a hexagon's where they meet at 120°.
            Some(_) if w == 2 && self.touched.is_empty() => (Pocket, false, v_profile(&walls)),
            Some(_) if w == 2 => (Step, true, P::TwoSided),
            // Two sides and a back: a slot, unless it opens to three stock
            // planes (a notch through a corner: a step).
            Some(_) if w == 3 && parallel && square && self.touched.len() >= 3 => {
                (Step, false, P::Rectangular)
            }
            Some(_) if w == 3 && parallel && square && self.opens_at_end(a, &walls) => {
                (Slot, false, P::Rectangular)
            }
            Some(_) if w == 3 && parallel && square => (Pocket, false, P::Rectangular),
            Some(_) => (Pocket, false, sides),
            // A ring of walls (or what is left of one where another cut
            // split a wall): a passage, unless a slot closed lower down.
            None if w >= 3 => {
                match closed_slot::slot_walls(a, self.group, &self.planes, &wall_faces) {
                    Some(rest) => through_slot(&rest),
                    None => (Passage, true, sides),
                }
            }
            None if w == 2 && parallel => (Slot, true, P::Rectangular),
            None if w == 2 => (Slot, true, P::Triangular),
            None => (Slot, true, P::Free),
        }
    }

    /// What the ends of a lone inclined wall on a floor `n` meet: block
    /// faces square to the floor. Two of them facing opposite
    /// ways, the wall runs across from side to side (a slanted step along
    /// a whole edge): true; two square to each other, it cuts a corner (a
    /// triangular step): false; neither, none.
    fn wall_ends(&self, a: &PartAnalysis, walls: &[FaceId], n: &Vector3) -> Option<bool> {
        let sides: Vec<Vector3> = walls
            .iter()
            .flat_map(|&w| a.graph().neighbours(w))
            .filter_map(|(g, _)| self.stock.plane_of(a, g))
            .map(|sp| self.stock.normal(sp))
            .filter(|m| m.dot(n).abs() < NEAR_PARALLEL_EPS)
            .collect();
        if facing_pair(&sides) {
            Some(true)
        } else if square_pair(&sides) {
            Some(false)
        } else {
            None
        }
    }

    /// Whether a blind slot (two facing walls and a back) opens at its
    /// end: some face beyond it, met at a convex edge, faces the way the
    /// back wall does (the side of the face it was cut from).
    fn opens_at_end(&self, a: &PartAnalysis, walls: &[Vector3]) -> bool {
        let Some(back) = walls.iter().find(|n| square_to_rest(n, walls)) else {
            return true;
        };
        self.group.iter().any(|&f| {
            a.graph().neighbours(f).any(|(g, adj)| {
                adj.convexity == Convexity::Convex
                    && !self.group.contains(&g)
                    && a.props(g).normal.is_some_and(|m| same_direction(&m, back))
            })
        })
    }

    /// Whether the ring of `walls` is a slot closed lower down: its other
    /// walls two facing ones and a back.
    fn closed_lower(&self, a: &PartAnalysis, walls: &[FaceId]) -> bool {
        closed_slot::slot_walls(a, self.group, &self.planes, walls)
            .is_some_and(|rest| rest.len() == 3 && facing_pair(&rest) && square_pair(&rest))
    }

    /// The floor: a plane every other plane of the group stands square on
    /// (preferring one square to the stock and facing a stock plane the
    /// group reaches), with how well its outline fills its minimum
    /// rectangle (a triangle ½, a rectangle 1).
    fn floor(&self, a: &PartAnalysis) -> Option<(Vector3, f64)> {
        if self.planes.len() < 2 {
            return None;
        }
        let normals: Vec<Vector3> = self.planes.iter().map(|p| p.0).collect();
        let candidates = self
            .planes
            .iter()
            .filter(|(n, _)| square_to_rest(n, &normals));
        let rank = |n: &Vector3| {
            let faces_entry = self
                .touched
                .iter()
                .any(|&sp| same_direction(n, &self.stock.normal(sp)));
            (self.stock.aligned(n), faces_entry)
        };
        let (n, _) = candidates.max_by_key(|(n, _)| rank(n))?;
        let faces: Vec<FaceId> = self
            .group
            .iter()
            .copied()
            .filter(|&f| a.props(f).normal.is_some_and(|m| same_direction(n, &m)))
            .collect();
        Some((*n, fill_ratio(a, &faces)))
    }

    /// Into the part from the entry plane (holes: along the axis).
    /// With no entry: into its largest planar face (a lone face seen
    /// square on has no depth), never a world axis.
    pub(crate) fn direction(&self, a: &PartAnalysis) -> Vector3 {
        if let Some(c) = self.cylinders.first() {
            match self.entry {
                Some(sp) if self.stock.normal(sp).dot(&c.axis) > 0.0 => -c.axis,
                _ => c.axis,
            }
        } else if let Some(sp) = self.entry {
            -self.stock.normal(sp)
        } else {
            self.group
                .iter()
                .filter_map(|&f| a.props(f).normal.map(|n| (n, a.props(f).area)))
                .max_by(|x, y| x.1.total_cmp(&y.1))
                .map_or(-self.stock.axes[2], |(n, _)| -n)
        }
    }
}

/// The block axes whose two planes the group both reaches.
fn opposite_axes(touched: &BTreeSet<usize>) -> Vec<usize> {
    (0..3)
        .filter(|k| touched.contains(&(2 * k)) && touched.contains(&(2 * k + 1)))
        .collect()
}

/// A group of convex curved faces only faces the block plane within this
/// cosine of its mean outward normal (its entry).
const ENVELOPE_FACING: f64 = 0.5;

/// The mean outward normal (area-weighted, at each face's centroid) of a
/// group with no planes and no concave cylinders: convex curved faces, the
/// part's envelope. `None` for any other group.
fn envelope_normal(
    a: &PartAnalysis,
    group: &[FaceId],
    planes: &[(Vector3, f64)],
    cylinders: &[Cylinder],
) -> Option<Vector3> {
    if !planes.is_empty() || !cylinders.is_empty() {
        return None;
    }
    let mut sum = Vector3::zeros();
    for &f in group {
        let face = a.part().face(f);
        let p = a.props(f);
        let n = face.surface.normal_at(&p.centroid)?;
        sum += if face.same_sense { n } else { -n } * p.area;
    }
    sum.try_normalize(1e-12)
}

/// Holes: concave cylinders. Blind when a face closes the far end: a plane
/// across the axis, or a drill point (cone, sphere) there.
fn hole_typing(
    a: &PartAnalysis,
    group: &[FaceId],
    cylinders: &[Cylinder],
) -> (MachiningKind, bool, Profile) {
    let part = a.part();
    let tol = a.tol().feature;
    let axis = cylinders[0].axis;
    let (lo, hi) = a.extent(group, &axis);
    let at_end = |f: FaceId| {
        let (x, y) = a.extent(&[f], &axis);
        (x - lo).abs() < tol * 100.0 || (y - hi).abs() < tol * 100.0
    };
    let closes = |f: FaceId| {
        let face = part.face(f);
        match face.surface {
            Surface::Plane { .. } => {
                a.props(f)
                    .normal
                    .is_some_and(|n| n.dot(&axis).abs() > 1.0 - NEAR_PARALLEL_EPS)
                    && at_end(f)
                    && face.loops.len() == 1
            }
            // A drill point: at the far end, coming to a tip (a vertex
            // loop) or a single boundary.
            Surface::Cone { .. } | Surface::Sphere { .. } => {
                at_end(f)
                    && (face.loops.len() == 1
                        || face.loops.iter().any(|&l| part.loop_(l).vertex.is_some()))
            }
            _ => false,
        }
    };
    let bottom = group.iter().any(|&f| closes(f));
    let distinct_r = radii(a, group).len();
    let cone = group
        .iter()
        .any(|&f| matches!(part.face(f).surface, Surface::Cone { .. }));
    let profile = if cone && distinct_r >= 1 {
        Profile::Countersunk
    } else if distinct_r == 2 {
        Profile::Counterbored
    } else if distinct_r > 2 {
        Profile::MultiSegment
    } else {
        Profile::Circular
    };
    (MachiningKind::Hole, !bottom, profile)
}

/// What the typing of a group with concave cylinders reads.
struct CurvedFacts {
    /// A face square to the first cylinder's axis.
    floor: bool,
    /// Faces along the axis (planar walls).
    walls: Vec<FaceId>,
    /// The distinct planes of the walls.
    wall_planes: usize,
    /// A convex cylinder coaxial with the first (an O-ring's core).
    core: bool,
    /// Every concave cylinder's sweep, degrees.
    sweeps: Vec<f64>,
    /// The sweep of the cylinders coaxial with the first, degrees.
    round_sweep: f64,
    /// The sweeps of the round ends, degrees.
    ends: Vec<f64>,
    /// Round ends of at least half a circle.
    halves: usize,
    /// A wall meets a concave cylinder tangentially.
    tangent_wall: bool,
    /// Every cylinder a quarter circle at most, one of them a quarter.
    quarters: bool,
}

fn typed(kind: MachiningKind, through: bool, profile: Profile, catalog: Option<Catalog>) -> Typed {
    Typed {
        kind,
        through,
        profile,
        catalog,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f64, y: f64, z: f64) -> Vector3 {
        Vector3::new(x, y, z).normalize()
    }

    /// A rectangle's four walls and a triangle's three close round a
    /// floor; a blind slot's two facing walls and back leave its open end,
    /// as do two walls of a corner. The floor's own turn does not matter.
    #[test]
    fn walls_surround_a_floor_only_when_no_half_turn_is_free() {
        let s = 0.75_f64.sqrt();
        for n in [v(0.0, 0.0, 1.0), v(0.3, -0.2, 0.9)] {
            let u = thinwall_geom::frame::any_perpendicular(&n);
            let (u, w) = (u, n.cross(&u));
            let t = |ws: Vec<Vector3>| {
                ws.into_iter()
                    .map(|x| u * x.x + w * x.y + n * x.z)
                    .collect::<Vec<_>>()
            };
            let rect = t(vec![
                v(1.0, 0.0, 0.0),
                v(-1.0, 0.0, 0.0),
                v(0.0, 1.0, 0.0),
                v(0.0, -1.0, 0.0),
            ]);
            let tri = t(vec![v(1.0, 0.0, 0.0), v(-0.5, s, 0.0), v(-0.5, -s, 0.0)]);
            let slot = t(vec![v(0.0, 1.0, 0.0), v(0.0, -1.0, 0.0), v(1.0, 0.0, 0.0)]);
            let corner = t(vec![v(1.0, 0.0, 0.0), v(0.0, 1.0, 0.0)]);
            assert!(surrounds(&rect, &n));
            assert!(surrounds(&tri, &n));
            assert!(!surrounds(&slot, &n));
            assert!(!surrounds(&corner, &n));
            assert!(!surrounds(&[], &n));
        }
    }
}
