//! The topology and geometry arenas of a part.

use serde::{Deserialize, Serialize};
use thinwall_geom::{BoundingBox, CurveKind, NurbsCurve, Point3, Surface, Tolerances, Vector3};

macro_rules! index_type {
    ($($name:ident),*) => {$(
        /// An index into the part's arena of that kind.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
        pub struct $name(pub u32);
        impl $name {
            pub fn index(self) -> usize { self.0 as usize }
        }
    )*};
}
index_type!(BodyId, FaceId, LoopId, EdgeId, VertexId);

/// Length and angle units of the source file; the model itself is always in
/// millimetres and radians.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Units {
    /// The file's length unit name (`millimetre`, `inch`, …).
    pub length: String,
    /// Millimetres per file length unit.
    pub mm_per_unit: f64,
    /// The file's angle unit name (`radian`, `degree`).
    pub angle: String,
    /// Radians per file angle unit.
    pub rad_per_unit: f64,
}

impl Default for Units {
    fn default() -> Self {
        Self {
            length: "millimetre".into(),
            mm_per_unit: 1.0,
            angle: "radian".into(),
            rad_per_unit: 1.0,
        }
    }
}

/// What kind of STEP item a body came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BodyKind {
    /// `MANIFOLD_SOLID_BREP`
    ManifoldSolid,
    /// `BREP_WITH_VOIDS`
    SolidWithVoids,
    /// A `SHELL_BASED_SURFACE_MODEL` whose shells are all closed.
    ClosedSurfaceModel,
}

/// A solid body.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Body {
    /// Entity id of the solid (or surface model).
    pub step_id: u64,
    pub name: String,
    pub kind: BodyKind,
    pub shells: Vec<Shell>,
    /// The product occurrence path placing it, when it came from an assembly.
    pub placement: Option<String>,
}

/// A shell of a body: the outer one, or a cavity.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Shell {
    pub step_id: u64,
    /// A cavity (void) shell.
    pub is_void: bool,
    pub faces: Vec<FaceId>,
}

/// A face: one STEP face.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Face {
    /// Entity id of the `ADVANCED_FACE` (or `FACE_SURFACE`).
    pub step_id: u64,
    pub name: String,
    pub body: BodyId,
    pub surface: Surface,
    /// `true` when the face's outward normal (pointing out of the material)
    /// is the surface's own normal; face, shell and cavity orientations are
    /// all folded in.
    pub same_sense: bool,
    /// Outer loop(s) first. Each loop runs with the face on its left seen
    /// from the outward normal.
    pub loops: Vec<LoopId>,
}

impl Face {
    /// The unit outward normal (out of the material) at a point on or near
    /// the face; none where the surface has none (on an axis, at an apex).
    /// A free-form face's foot point is searched from `hint` (the previous
    /// point's parameters on this face), which is updated.
    pub fn outward_normal(&self, p: &Point3, hint: &mut Option<(f64, f64)>) -> Option<Vector3> {
        let n = match &self.surface {
            Surface::Freeform { nurbs, .. } => {
                let (u, v, _) = nurbs.invert(p, *hint);
                *hint = Some((u, v));
                thinwall_geom::surface::nurbs_normal(nurbs, u, v)?
            }
            s => s.normal_at(p)?,
        };
        Some(if self.same_sense { n } else { -n })
    }
}

/// A face boundary.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Loop {
    pub face: FaceId,
    /// The file marked it `FACE_OUTER_BOUND`.
    pub is_outer: bool,
    pub coedges: Vec<Coedge>,
    /// For a `VERTEX_LOOP` (a cone apex, a sphere pole): its vertex.
    pub vertex: Option<VertexId>,
}

/// One use of an edge by a loop.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Coedge {
    pub edge: EdgeId,
    /// The loop runs along the edge from its start to its end.
    pub forward: bool,
}

/// An edge.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Edge {
    /// Entity id of the `EDGE_CURVE`.
    pub step_id: u64,
    pub start: VertexId,
    pub end: VertexId,
    pub curve: CurveKind,
    /// The exact curve between the vertices, start → end; `None` when the
    /// reader could not derive it (reported as a read issue).
    pub nurbs: Option<NurbsCurve>,
}

/// A vertex.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Vertex {
    /// Entity id of the `VERTEX_POINT`.
    pub step_id: u64,
    pub point: Point3,
}

/// Surface geometry that is not part of any solid (an `OPEN_SHELL` of a
/// surface model beside the solid, as some NIST files carry). Counted and
/// reported, never mixed into the solid's faces, graph or recognition.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Supplemental {
    /// Entity ids of the surface models.
    pub surface_models: Vec<u64>,
    /// Number of faces in them.
    pub face_count: usize,
}

/// Samples per knot span of a curved edge for the part's bounding box.
const BOX_SAMPLES_PER_SPAN: usize = 32;

/// A face as every result names it: its body's index and its STEP id (a
/// body placed twice has the same ids in both).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct FaceKey {
    pub body: u32,
    pub step_id: u64,
}

/// A part: everything read from one STEP file.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Part {
    pub units: Units,
    pub bodies: Vec<Body>,
    pub faces: Vec<Face>,
    pub loops: Vec<Loop>,
    pub edges: Vec<Edge>,
    pub vertices: Vec<Vertex>,
    pub supplemental: Supplemental,
    /// Per face (by [`FaceId`]), its ordinal in the order OpenCascade
    /// numbers the faces of the shape it reads from the same file
    /// (`TopExp::MapShapes(shape, TopAbs_FACE)`, from 0: FreeCAD's
    /// `Shape.Faces`, CadQuery's and pythonOCC's face order). Empty for a
    /// part not read from STEP. Supplemental surface models' faces hold
    /// ordinals too, so an ordinal may be no face's here.
    #[serde(default)]
    pub occ_ordinals: Vec<u32>,
    /// The faces each edge bounds, built on first use ([`Part::edge_faces`]).
    #[serde(skip)]
    pub edge_faces_cache: EdgeFaces,
}

/// Per edge, the faces whose loops use it (a cache: any two are equal, so
/// a part compares by its geometry and topology alone).
#[derive(Clone, Debug, Default)]
pub struct EdgeFaces(std::sync::OnceLock<Vec<Vec<FaceId>>>);

impl PartialEq for EdgeFaces {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl Part {
    /// Face `f`'s ordinal in OpenCascade's order ([`Part::occ_ordinals`]),
    /// when the part was read from STEP.
    pub fn occ_ordinal(&self, f: FaceId) -> Option<u32> {
        self.occ_ordinals.get(f.index()).copied()
    }

    /// The part's faces in OpenCascade's order: entry `i` names the face
    /// OpenCascade numbers `i` by its body and STEP id, or is `None` for one
    /// Thinwall does not read as part of a body (a supplemental surface
    /// model's). Empty for a part not read from STEP.
    pub fn occ_faces(&self) -> Vec<Option<FaceKey>> {
        if self.occ_ordinals.is_empty() {
            return Vec::new();
        }
        let n = self.faces.len() + self.supplemental.face_count;
        let mut out = vec![None; n];
        for (f, &o) in self.faces.iter().zip(&self.occ_ordinals) {
            if let Some(slot) = out.get_mut(o as usize) {
                *slot = Some(FaceKey {
                    body: f.body.0,
                    step_id: f.step_id,
                });
            }
        }
        out
    }

    /// The faces whose loops use edge `e` (two on a closed shell; a seam
    /// edge's face once), in face order. Built once per part.
    pub fn edge_faces(&self, e: EdgeId) -> &[FaceId] {
        let map = self.edge_faces_cache.0.get_or_init(|| {
            let mut map = vec![Vec::new(); self.edges.len()];
            for (fi, f) in self.faces.iter().enumerate() {
                for &l in &f.loops {
                    for ce in &self.loop_(l).coedges {
                        let list: &mut Vec<FaceId> = &mut map[ce.edge.index()];
                        if list.last() != Some(&FaceId(fi as u32)) {
                            list.push(FaceId(fi as u32));
                        }
                    }
                }
            }
            map
        });
        map.get(e.index()).map_or(&[], Vec::as_slice)
    }

    pub fn face(&self, id: FaceId) -> &Face {
        &self.faces[id.index()]
    }

    pub fn edge(&self, id: EdgeId) -> &Edge {
        &self.edges[id.index()]
    }

    pub fn vertex(&self, id: VertexId) -> &Vertex {
        &self.vertices[id.index()]
    }

    pub fn loop_(&self, id: LoopId) -> &Loop {
        &self.loops[id.index()]
    }

    /// Ids of every face, in order.
    pub fn face_ids(&self) -> impl Iterator<Item = FaceId> + '_ {
        (0..self.faces.len() as u32).map(FaceId)
    }

    /// Number of faces of the solid bodies.
    pub fn solid_face_count(&self) -> usize {
        self.faces.len()
    }

    /// The first face whose `ADVANCED_FACE` entity id is `step_id`.
    pub fn face_by_step_id(&self, step_id: u64) -> Option<FaceId> {
        self.faces
            .iter()
            .position(|f| f.step_id == step_id)
            .map(|i| FaceId(i as u32))
    }

    /// The bounding box of the vertices and samples of the curved edges
    /// (within ~2e-4 of a circular edge's radius; exact for straight edges).
    /// Interior bulges of curved faces beyond their edges are not included.
    pub fn bounding_box(&self) -> BoundingBox {
        let mut b = BoundingBox::empty();
        self.outline_points(|p| b.add_point(p));
        b
    }

    /// The part's size, mm: twice the largest distance of its vertices and
    /// curved edges' samples from their centroid. A rigid motion keeps it
    /// (the bounding box's diagonal grows by up to √3 as the part turns, and
    /// every tolerance and the tessellation scaled with it: a skin turned
    /// 37° about up was meshed differently and its reach read 0.6 % apart);
    /// for a box it is the diagonal.
    pub fn size(&self) -> f64 {
        let (mut sum, mut n) = (Vector3::zeros(), 0usize);
        self.outline_points(|p| {
            sum += p.coords;
            n += 1;
        });
        if n == 0 {
            return 0.0;
        }
        let centre = Point3::from(sum / n as f64);
        let mut far: f64 = 0.0;
        self.outline_points(|p| far = far.max((p - centre).norm()));
        2.0 * far
    }

    /// Every vertex and the samples of the curved edges, as the bounding
    /// box and the size take them.
    fn outline_points(&self, mut visit: impl FnMut(&Point3)) {
        for v in &self.vertices {
            visit(&v.point);
        }
        for e in &self.edges {
            if let Some(n) = &e.nurbs {
                if n.degree == 1 && n.is_polynomial() {
                    continue; // straight pieces: the vertices bound them
                }
                for (a, bb) in n.spans() {
                    for k in 0..=BOX_SAMPLES_PER_SPAN {
                        visit(&n.point(a + (bb - a) * k as f64 / BOX_SAMPLES_PER_SPAN as f64));
                    }
                }
            }
        }
    }

    /// Tolerances scaled to this part.
    pub fn tolerances(&self) -> Tolerances {
        Tolerances::for_part(self.size())
    }
}
