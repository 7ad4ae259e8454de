//! One analysis of a part that every recognizer, the classifier and the
//! planners read: the part and its set-up, the adjacency graph, every face's
//! properties, the planar faces' polygons, boundary samples, the tolerances
//! scaled to the part, blend and chamfer candidates, concave cylinders, and
//! the geometric helpers they share (extents, minimum rectangles, inscribed
//! circles, components over filtered graph views). Built once; costly pieces
//! are computed on first use and kept.
//!
//! It also holds the one set-up type ([`Setup`]) and the one feature
//! vocabulary ([`vocabulary`]).
//!
//! ```no_run
//! use thinwall_analysis::{PartAnalysis, Setup};
//! let (part, _) = thinwall_step::read_file("panel.step").unwrap();
//! let a = PartAnalysis::new(&part, Setup::default());
//! for f in part.face_ids() {
//!     println!("{} mm², planar: {}", a.props(f).area, a.planar(f).is_some());
//! }
//! ```

pub mod boolean;
pub mod components;
mod extreme;
pub mod measure;
pub mod min_rect;
pub mod parallel;
pub mod polygon;
pub mod setup;
pub mod vocabulary;

pub use polygon::{FaceLoops, PlanarFace};
pub use setup::{Machine, Setup, SetupError};
pub use vocabulary::{
    Catalog, FeatureId, MachiningId, MachiningKind, Profile, StiffnessKind, VolumeType,
};

use geo::MultiPolygon;
use std::borrow::Cow;
use std::collections::BTreeSet;
use std::sync::OnceLock;
use thinwall_brep::tessellate::Mesh;
use thinwall_brep::{compute_face_props, FaceId, FaceProps, Part};
use thinwall_geom::{BoundingBox, PartTolerances, Point3, Surface, Vector3};
use thinwall_graph::{Adjacency, AdjacencyGraph, Convexity};

/// Where a warning comes from.
#[derive(
    Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, serde::Serialize, serde::Deserialize,
)]
#[serde(rename_all = "snake_case")]
pub enum WarningSource {
    /// The reader dropped or repaired something.
    Read,
    /// A figure could not be computed exactly (an area, a boundary off its surface).
    Geometry,
    /// The solid is not closed or not a manifold, or an edge could not be judged.
    Topology,
}

/// Something a user should know about the part, with the entity it concerns.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Warning {
    pub source: WarningSource,
    /// The STEP entity id, where there is one.
    pub entity: Option<u64>,
    pub message: String,
}

/// A cylinder face: a point on its axis, the axis, the radius.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cylinder {
    pub origin: Point3,
    pub axis: Vector3,
    pub radius: f64,
    /// Its outward normal points away from the axis (a boss, not a hole).
    pub convex: bool,
}

impl Cylinder {
    /// Same axis line (either direction), within `tol` mm.
    pub fn coaxial(&self, other: &Cylinder, tol: f64) -> bool {
        let d = other.origin - self.origin;
        self.axis.dot(&other.axis).abs() > 1.0 - thinwall_geom::tolerance::UNIT_PARALLEL_EPS
            && (d - self.axis * d.dot(&self.axis)).norm() < tol
    }
}

/// The analysis of one part in one set-up.
pub struct PartAnalysis<'a> {
    part: &'a Part,
    graph: Cow<'a, AdjacencyGraph>,
    setup: Setup,
    bbox: BoundingBox,
    tol: PartTolerances,
    props: OnceLock<Vec<FaceProps>>,
    boundary: OnceLock<Vec<Vec<Point3>>>,
    planar: OnceLock<Vec<Option<PlanarFace>>>,
    smooth_degree: OnceLock<Vec<usize>>,
    mesh: OnceLock<Mesh>,
    parallel: bool,
    budget: parallel::Budget,
}

impl<'a> PartAnalysis<'a> {
    /// Analyse `part` in `setup`, building its adjacency graph.
    pub fn new(part: &'a Part, setup: Setup) -> Self {
        let graph = AdjacencyGraph::build(part, &part.tolerances());
        Self::from_parts(part, Cow::Owned(graph), setup)
    }

    /// Analyse `part` with a graph already built for it (a host keeps one
    /// per loaded part).
    pub fn with_graph(part: &'a Part, graph: &'a AdjacencyGraph, setup: Setup) -> Self {
        Self::from_parts(part, Cow::Borrowed(graph), setup)
    }

    fn from_parts(part: &'a Part, graph: Cow<'a, AdjacencyGraph>, setup: Setup) -> Self {
        let bbox = part.bounding_box();
        thinwall_brep::builds::record(part, thinwall_brep::builds::Built::Analysis);
        Self {
            part,
            graph,
            setup,
            tol: PartTolerances::for_diagonal(part.size()),
            bbox,
            props: OnceLock::new(),
            boundary: OnceLock::new(),
            planar: OnceLock::new(),
            smooth_degree: OnceLock::new(),
            mesh: OnceLock::new(),
            parallel: true,
            budget: parallel::Budget::default(),
        }
    }

    /// Whether costly pieces (face properties) are computed on rayon's
    /// worker threads (the default) or on the calling thread only. The
    /// results are the same either way.
    pub fn with_parallelism(mut self, parallel: bool) -> Self {
        self.parallel = parallel;
        self
    }

    /// Whether work on this analysis may use rayon's worker threads.
    pub fn is_parallel(&self) -> bool {
        self.parallel
    }

    /// The deadline of the work running now on this analysis.
    pub fn budget(&self) -> &parallel::Budget {
        &self.budget
    }

    /// How work on this analysis runs: in parallel or not, within its
    /// budget.
    pub fn work(&self) -> parallel::Work<'_> {
        parallel::Work {
            parallel: self.parallel,
            budget: &self.budget,
        }
    }

    pub fn part(&self) -> &'a Part {
        self.part
    }

    pub fn graph(&self) -> &AdjacencyGraph {
        &self.graph
    }

    pub fn setup(&self) -> &Setup {
        &self.setup
    }

    /// Up in the part's own coordinates (unit).
    pub fn up(&self) -> Vector3 {
        self.setup.up_in_part()
    }

    pub fn bounding_box(&self) -> &BoundingBox {
        &self.bbox
    }

    /// The tolerances in force for this part.
    pub fn tol(&self) -> &PartTolerances {
        &self.tol
    }

    /// The part's triangles ([`thinwall_brep::tessellate::part_mesh`]),
    /// made on first use: the one mesh reach, access, the pictures and the
    /// pages share.
    pub fn mesh(&self) -> &Mesh {
        self.mesh
            .get_or_init(|| thinwall_brep::tessellate::part_mesh(self.part))
    }

    /// Every face's properties, by `face.index()` (computed on first use,
    /// faces in parallel: free-form faces are the costly part; each face's
    /// result does not depend on the others or on the thread).
    pub fn face_props(&self) -> &[FaceProps] {
        self.props.get_or_init(|| {
            let ids: Vec<FaceId> = self.part.face_ids().collect();
            self.work().map(&ids, |&f| compute_face_props(self.part, f))
        })
    }

    /// The face properties, computed if they were not yet.
    pub fn into_face_props(self) -> Vec<FaceProps> {
        self.face_props();
        self.props.into_inner().unwrap_or_default()
    }

    pub fn props(&self, f: FaceId) -> &FaceProps {
        &self.face_props()[f.index()]
    }

    /// Sample points on a face's boundary ([`measure::boundary_points`]).
    pub fn boundary_points(&self, f: FaceId) -> &[Point3] {
        &self.boundary.get_or_init(|| {
            self.part
                .face_ids()
                .map(|f| measure::boundary_points(self.part, f))
                .collect()
        })[f.index()]
    }

    /// Lowest and highest extent of faces' boundaries along `dir`, mm.
    pub fn extent(&self, faces: &[FaceId], dir: &Vector3) -> (f64, f64) {
        measure::extent(faces.iter().flat_map(|&f| self.boundary_points(f)), dir)
    }

    /// Faces' boundary samples seen along `dir`: the 2-D points in the plane
    /// across it, with that plane's axes `u`, `v` (`u × v = dir`).
    pub fn points_across(
        &self,
        faces: &[FaceId],
        dir: &Vector3,
    ) -> (Vector3, Vector3, Vec<geo::Point<f64>>) {
        let u = thinwall_geom::frame::any_perpendicular(dir);
        let v = dir.cross(&u);
        let pts = faces
            .iter()
            .flat_map(|&f| self.boundary_points(f))
            .map(|p| geo::Point::new(p.coords.dot(&u), p.coords.dot(&v)))
            .collect();
        (u, v, pts)
    }

    /// Long and short side of the minimum rectangle around faces seen along
    /// `dir` (independent of how the part sits in the world), mm.
    pub fn sizes_across(&self, faces: &[FaceId], dir: &Vector3) -> (f64, f64) {
        let (_, _, pts) = self.points_across(faces, dir);
        polygon::min_rect_sides(&geo::MultiPoint::from(pts)).unwrap_or((0.0, 0.0))
    }

    /// A planar face with its loops, or `None` for a curved face.
    pub fn planar(&self, f: FaceId) -> Option<&PlanarFace> {
        self.planar.get_or_init(|| {
            self.part
                .face_ids()
                .map(|f| PlanarFace::new(self.part, f))
                .collect()
        })[f.index()]
        .as_ref()
    }

    /// Every planar face, in face order.
    pub fn planar_faces(&self) -> impl Iterator<Item = &PlanarFace> {
        self.part.face_ids().filter_map(|f| self.planar(f))
    }

    /// A planar face's polygon in its own plane frame.
    pub fn polygon(&self, f: FaceId) -> Option<MultiPolygon<f64>> {
        self.planar(f).map(|p| p.polygon_in(&p.frame))
    }

    /// Number of distinct faces meeting `f` along smooth (tangent) edges.
    pub fn smooth_degree(&self, f: FaceId) -> usize {
        self.smooth_degree.get_or_init(|| {
            self.part
                .face_ids()
                .map(|f| {
                    self.graph
                        .neighbours(f)
                        .filter(|(_, a)| a.convexity == Convexity::Smooth)
                        .map(|(g, _)| g)
                        .collect::<BTreeSet<FaceId>>()
                        .len()
                })
                .collect()
        })[f.index()]
    }

    /// Face `f`'s loops with its openings dropped: an inner loop along
    /// which every neighbour meets it at a convex edge (a hole through a
    /// web drops away on every side) is no boundary that supports it or
    /// stops a tool. `None` for a face that is not planar.
    pub fn loops_without_openings(&self, f: FaceId) -> Option<polygon::FaceLoops> {
        let mut loops = self.planar(f)?.loops.clone();
        let openings = self.openings(f);
        if openings.len() == loops.inner.len() {
            let mut keep = openings.iter().map(|o| !o);
            loops.inner.retain(|_| keep.next().unwrap_or(true));
        }
        Some(loops)
    }

    /// Per inner loop of face `f` (in the face's order): whether it is an
    /// opening, every edge of it convex.
    pub fn openings(&self, f: FaceId) -> Vec<bool> {
        let convex: std::collections::HashSet<thinwall_brep::EdgeId> = self
            .graph
            .neighbours(f)
            .filter(|(_, a)| a.convexity == Convexity::Convex)
            .flat_map(|(_, a)| a.edges.iter().map(|&e| self.graph.edges[e].edge))
            .collect();
        let outer = polygon::outer_loops(self.part, f);
        self.part
            .face(f)
            .loops
            .iter()
            .zip(&outer)
            .filter(|(_, &o)| !o)
            .map(|(&l, _)| {
                let lp = self.part.loop_(l);
                !lp.coedges.is_empty() && lp.coedges.iter().all(|ce| convex.contains(&ce.edge))
            })
            .collect()
    }

    /// A face that may be a blend: a cylinder, cone (a drafted pocket's
    /// corner radius), torus, sphere or free-form face tangent to two or
    /// more faces.
    pub fn is_blend_candidate(&self, f: FaceId) -> bool {
        let curved = matches!(
            self.part.face(f).surface,
            Surface::Cylinder { .. }
                | Surface::Cone { .. }
                | Surface::Torus { .. }
                | Surface::Sphere { .. }
                | Surface::Freeform { .. }
        );
        curved && self.smooth_degree(f) >= 2
    }

    /// The radius a blend face rounds with (cylinder, sphere, torus minor).
    pub fn blend_radius(&self, f: FaceId) -> Option<f64> {
        match self.part.face(f).surface {
            Surface::Cylinder { radius, .. } | Surface::Sphere { radius, .. } => Some(radius),
            Surface::Torus { minor_radius, .. } => Some(minor_radius),
            _ => None,
        }
    }

    /// A cylinder face, either sense.
    pub fn cylinder(&self, f: FaceId) -> Option<Cylinder> {
        let face = self.part.face(f);
        match face.surface {
            Surface::Cylinder { frame, radius } => Some(Cylinder {
                origin: frame.origin,
                axis: frame.z,
                radius,
                convex: face.same_sense,
            }),
            _ => None,
        }
    }

    /// The angle a cylinder face sweeps around its axis, degrees: 360 less
    /// the widest gap between its boundary samples' angles (a full
    /// cylinder comes out a little under 360, by its sampling).
    pub fn cylinder_sweep_deg(&self, f: FaceId) -> Option<f64> {
        let c = self.cylinder(f)?;
        let u = thinwall_geom::frame::any_perpendicular(&c.axis);
        let v = c.axis.cross(&u);
        let mut angles: Vec<f64> = self
            .boundary_points(f)
            .iter()
            .filter_map(|p| {
                let d = p - c.origin;
                let r = d - c.axis * d.dot(&c.axis);
                (r.norm() > 0.5 * c.radius).then(|| r.dot(&v).atan2(r.dot(&u)).to_degrees())
            })
            .collect();
        angles.sort_by(f64::total_cmp);
        let (first, last) = (*angles.first()?, *angles.last()?);
        let widest = angles
            .windows(2)
            .map(|w| w[1] - w[0])
            .fold(360.0 - (last - first), f64::max);
        Some(360.0 - widest)
    }

    /// A concave cylinder (outward normal towards its axis): a hole's wall,
    /// an inside corner radius.
    pub fn concave_cylinder(&self, f: FaceId) -> Option<Cylinder> {
        self.cylinder(f).filter(|c| !c.convex)
    }

    /// A cylinder, cone or torus whose outward normal points towards its
    /// axis (a concave blend between walls; a cone where they are drafted).
    pub fn is_concave_blend(&self, f: FaceId) -> bool {
        let face = self.part.face(f);
        matches!(
            face.surface,
            Surface::Cylinder { .. } | Surface::Cone { .. } | Surface::Torus { .. }
        ) && !face.same_sense
    }

    /// A planar face meeting two or more neighbours at convex edges with an
    /// obtuse interior angle (100°–170°): it may be a chamfer.
    pub fn is_chamfer_candidate(&self, f: FaceId) -> bool {
        if self.planar(f).is_none() {
            return false;
        }
        let bevels = self
            .graph
            .neighbours(f)
            .filter(|(_, a)| {
                a.convexity == Convexity::Convex
                    && a.edges.iter().all(|&e| {
                        let ea = &self.graph.edges[e];
                        ea.angle_min_deg > 100.0 && ea.angle_max_deg < 170.0
                    })
            })
            .count();
        bevels >= 2
    }

    /// Width and length of a narrow face: its area over half its boundary
    /// length, and that half length, mm.
    pub fn strip_width(&self, f: FaceId) -> (f64, f64) {
        let half = self
            .boundary_points(f)
            .windows(2)
            .map(|w| (w[1] - w[0]).norm())
            .sum::<f64>()
            .max(1e-9)
            / 2.0;
        (self.props(f).area / half, half)
    }

    /// Faces reachable from `seeds` ([`components::reachable`]).
    pub fn reachable(
        &self,
        seeds: impl IntoIterator<Item = FaceId>,
        node_ok: impl Fn(FaceId) -> bool,
        arc_ok: impl Fn(FaceId, FaceId, &Adjacency) -> bool,
    ) -> BTreeSet<FaceId> {
        components::reachable(&self.graph, seeds, node_ok, arc_ok)
    }

    /// Groups of `members` joined by accepted arcs ([`components::components`]).
    pub fn components(
        &self,
        members: &[FaceId],
        arc_ok: impl Fn(FaceId, FaceId, &Adjacency) -> bool,
    ) -> Vec<Vec<FaceId>> {
        components::components(&self.graph, members, arc_ok)
    }

    /// What the analysis found questionable: faces whose properties are
    /// approximate, edges used by one face only (an open shell), by three
    /// or more, or along which no normal could be evaluated.
    pub fn warnings(&self) -> Vec<Warning> {
        let mut out: Vec<Warning> = self
            .part
            .face_ids()
            .flat_map(|f| {
                let id = self.part.face(f).step_id;
                self.props(f).warnings.iter().map(move |m| Warning {
                    source: WarningSource::Geometry,
                    entity: Some(id),
                    message: format!("face #{id}: {m}"),
                })
            })
            .collect();
        for e in &self.graph.edges {
            let what = match e.convexity {
                Convexity::Free => "is used by one face only: the shell is open there",
                Convexity::NonManifold => "is used by three or more faces: not a manifold solid",
                Convexity::Unknown => "has no surface normal that could be evaluated along it",
                _ => continue,
            };
            out.push(Warning {
                source: WarningSource::Topology,
                entity: Some(e.step_id),
                message: format!("edge #{} {what}", e.step_id),
            });
        }
        out
    }

    /// Edges used by one face only (the solid's shell is open there).
    pub fn free_edges(&self) -> Vec<u64> {
        self.graph
            .edges
            .iter()
            .filter(|e| e.convexity == Convexity::Free)
            .map(|e| e.step_id)
            .collect()
    }

    /// `step_id`s of faces, sorted.
    pub fn step_ids(&self, faces: &[FaceId]) -> Vec<u64> {
        let mut v: Vec<u64> = faces.iter().map(|&f| self.part.face(f).step_id).collect();
        v.sort();
        v
    }
}
