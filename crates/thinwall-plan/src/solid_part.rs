//! truck solids as our [`Part`], directly: the planner's feature solids are
//! classified and drawn without writing them as STEP text and reading them
//! back. truck's topology maps one to one onto ours (a compressed shell is
//! arrays of vertices, edges and faces); its surfaces are planes and NURBS
//! (an extruded arc's rational B-spline is a cylinder, found as the reader
//! finds it), its edge curves lines and NURBS.
//!
//! The ids a STEP file would give are numbered here the way a file numbers
//! its entities: one counter over bodies, shells, faces, edges and
//! vertices, from 1, so every id in a part is distinct.

use thinwall_brep::{
    Body, BodyId, BodyKind, Coedge, Edge, EdgeId, Face, FaceId, Loop, LoopId, Part, Shell, Vertex,
    VertexId,
};
use thinwall_geom::surface::FreeformKind;
use thinwall_geom::{CurveKind, Frame, NurbsCurve, NurbsSurface, Point3, Surface, Vector3};
use truck_modeling::{Curve as TCurve, Solid, Surface as TSurface};

/// Why a truck solid could not be built as a part.
#[derive(Clone, Debug, thiserror::Error, PartialEq)]
pub enum SolidPartError {
    /// A surface or curve kind our B-rep has no form for.
    #[error("solid {solid}: {what} is not supported")]
    Unsupported { solid: String, what: &'static str },
    /// A NURBS whose knots, degree or weights our B-rep refuses.
    #[error("solid {solid}: {what}: {source}")]
    Nurbs {
        solid: String,
        what: &'static str,
        source: thinwall_geom::nurbs::NurbsError,
    },
    /// A plane whose normal or axis is degenerate.
    #[error("solid {solid}: a degenerate plane")]
    DegeneratePlane { solid: String },
}

type Compressed =
    truck_topology::compress::CompressedShell<truck_modeling::Point3, TCurve, TSurface>;

/// Named solids as one part, one body each, in order.
pub fn part_of(solids: &[(String, &Solid)]) -> Result<Part, SolidPartError> {
    let mut b = Builder {
        part: Part::default(),
        next_id: 1,
    };
    for (name, solid) in solids {
        b.add_body(name, solid)?;
    }
    Ok(b.part)
}

struct Builder {
    part: Part,
    next_id: u64,
}

fn point(p: truck_modeling::Point3) -> Point3 {
    Point3::new(p.x, p.y, p.z)
}

fn vector(v: truck_modeling::Vector3) -> Vector3 {
    Vector3::new(v.x, v.y, v.z)
}

impl Builder {
    fn id(&mut self) -> u64 {
        self.next_id += 1;
        self.next_id - 1
    }

    fn add_body(&mut self, name: &str, solid: &Solid) -> Result<(), SolidPartError> {
        let body = BodyId(self.part.bodies.len() as u32);
        let step_id = self.id();
        let mut shells = Vec::new();
        for (k, shell) in solid.compress().boundaries.iter().enumerate() {
            shells.push(Shell {
                step_id: self.id(),
                is_void: k > 0,
                faces: self.add_shell(name, body, shell)?,
            });
        }
        self.part.bodies.push(Body {
            step_id,
            name: name.to_string(),
            kind: BodyKind::ManifoldSolid,
            shells,
            placement: None,
        });
        Ok(())
    }

    /// A shell's faces; its vertices and edges added once each.
    fn add_shell(
        &mut self,
        name: &str,
        body: BodyId,
        shell: &Compressed,
    ) -> Result<Vec<FaceId>, SolidPartError> {
        let first_face = self.part.faces.len() as u32;
        let mut faces = Vec::new();
        for f in &shell.faces {
            let face = FaceId(first_face + faces.len() as u32);
            faces.push(self.add_face(name, body, face, f)?);
        }
        let vertex0 = self.part.vertices.len() as u32;
        for p in &shell.vertices {
            let step_id = self.id();
            self.part.vertices.push(Vertex {
                step_id,
                point: point(*p),
            });
        }
        let edge0 = self.part.edges.len() as u32;
        for e in &shell.edges {
            let (start, end) = (
                VertexId(vertex0 + e.vertices.0 as u32),
                VertexId(vertex0 + e.vertices.1 as u32),
            );
            let edge = self.edge(name, start, end, &e.curve)?;
            self.part.edges.push(edge);
        }
        // The loops were built before the edges: shift their edge indices.
        for &f in &faces {
            for &l in &self.part.faces[f.index()].loops {
                for c in &mut self.part.loops[l.index()].coedges {
                    c.edge = EdgeId(edge0 + c.edge.0);
                }
            }
        }
        Ok(faces)
    }

    /// A face: outward where truck's face is oriented (a truck solid's
    /// faces point out of it), each loop with the face on its left seen
    /// from outside. The loops' edges are indices into the shell's edges.
    fn add_face(
        &mut self,
        name: &str,
        body: BodyId,
        id: FaceId,
        f: &truck_topology::compress::CompressedFace<TSurface>,
    ) -> Result<FaceId, SolidPartError> {
        let step_id = self.id();
        let (surface, turned) = thinwall_geom::surface::analytic_form(surface(name, &f.surface)?);
        let mut loops = Vec::new();
        for wire in &f.boundaries {
            let mut coedges: Vec<Coedge> = wire
                .iter()
                .map(|ce| Coedge {
                    edge: EdgeId(ce.index as u32),
                    forward: ce.orientation == f.orientation,
                })
                .collect();
            if !f.orientation {
                coedges.reverse();
            }
            loops.push(LoopId(self.part.loops.len() as u32));
            self.part.loops.push(Loop {
                face: id,
                // truck marks no bound outer: as in a file of FACE_BOUNDs,
                // the analysis finds the outer one by its extent.
                is_outer: false,
                coedges,
                vertex: None,
            });
        }
        self.part.faces.push(Face {
            step_id,
            name: String::new(),
            body,
            surface,
            same_sense: f.orientation != turned,
            loops,
        });
        Ok(id)
    }

    fn edge(
        &mut self,
        name: &str,
        start: VertexId,
        end: VertexId,
        curve: &TCurve,
    ) -> Result<Edge, SolidPartError> {
        let step_id = self.id();
        let nurbs_error = |source| SolidPartError::Nurbs {
            solid: name.to_string(),
            what: "an edge's curve",
            source,
        };
        let (kind, nurbs) = match curve {
            TCurve::Line(l) => {
                let (origin, direction) = (point(l.0), vector(l.1 - l.0).normalize());
                // The curve is the geometry: its ends are the vertices on it.
                let on_line = |v: VertexId| {
                    let p = self.part.vertices[v.index()].point;
                    let q = origin + direction * (p - origin).dot(&direction);
                    [q.x, q.y, q.z]
                };
                let segment = NurbsCurve::new(
                    1,
                    vec![0.0, 0.0, 1.0, 1.0],
                    &[on_line(start), on_line(end)],
                    &[1.0, 1.0],
                )
                .map_err(nurbs_error)?;
                (CurveKind::Line { origin, direction }, segment)
            }
            TCurve::NurbsCurve(c) => {
                let (points, weights) = cartesian(c.control_points());
                let n = NurbsCurve::new(c.degree(), c.knot_vec().to_vec(), &points, &weights)
                    .map_err(nurbs_error)?;
                (CurveKind::Bspline, n)
            }
            TCurve::BSplineCurve(c) => {
                let points: Vec<[f64; 3]> =
                    c.control_points().iter().map(|p| [p.x, p.y, p.z]).collect();
                let weights = vec![1.0; points.len()];
                let n = NurbsCurve::new(c.degree(), c.knot_vec().to_vec(), &points, &weights)
                    .map_err(nurbs_error)?;
                (CurveKind::Bspline, n)
            }
            TCurve::IntersectionCurve(_) => {
                return Err(SolidPartError::Unsupported {
                    solid: name.to_string(),
                    what: "an intersection curve",
                })
            }
        };
        Ok(Edge {
            step_id,
            start,
            end,
            curve: kind,
            nurbs: Some(nurbs),
        })
    }
}

/// Homogeneous control points as Cartesian points and weights.
fn cartesian(hom: &[truck_modeling::Vector4]) -> (Vec<[f64; 3]>, Vec<f64>) {
    hom.iter()
        .map(|h| ([h.x / h.w, h.y / h.w, h.z / h.w], h.w))
        .unzip()
}

/// A truck surface as ours (a free-form one before it is recognised as a
/// cylinder).
fn surface(name: &str, s: &TSurface) -> Result<Surface, SolidPartError> {
    let nurbs_error = |source| SolidPartError::Nurbs {
        solid: name.to_string(),
        what: "a face's surface",
        source,
    };
    match s {
        TSurface::Plane(p) => Frame::from_axis(
            point(p.origin()),
            vector(p.normal()),
            Some(vector(p.u_axis())),
        )
        .map(|frame| Surface::Plane { frame })
        .ok_or_else(|| SolidPartError::DegeneratePlane {
            solid: name.to_string(),
        }),
        TSurface::NurbsSurface(n) => {
            let (points, weights): (Vec<_>, Vec<_>) =
                n.control_points().iter().map(|row| cartesian(row)).unzip();
            let (ku, kv) = n.knot_vecs();
            let degrees = (n.udegree(), n.vdegree());
            freeform(degrees, (ku, kv), &points, &weights).map_err(nurbs_error)
        }
        TSurface::BSplineSurface(n) => {
            let points: Vec<Vec<[f64; 3]>> = n
                .control_points()
                .iter()
                .map(|row| row.iter().map(|p| [p.x, p.y, p.z]).collect())
                .collect();
            let weights: Vec<Vec<f64>> = points.iter().map(|r| vec![1.0; r.len()]).collect();
            let (ku, kv) = n.knot_vecs();
            let degrees = (n.udegree(), n.vdegree());
            freeform(degrees, (ku, kv), &points, &weights).map_err(nurbs_error)
        }
        TSurface::RevolutedCurve(_) => Err(SolidPartError::Unsupported {
            solid: name.to_string(),
            what: "a surface of revolution",
        }),
    }
}

/// A free-form surface of our B-rep from a NURBS's degrees, knots and
/// `[u][v]` grids of Cartesian points and weights.
fn freeform(
    (du, dv): (usize, usize),
    (ku, kv): (&truck_modeling::KnotVec, &truck_modeling::KnotVec),
    points: &[Vec<[f64; 3]>],
    weights: &[Vec<f64>],
) -> Result<Surface, thinwall_geom::nurbs::NurbsError> {
    let nurbs = NurbsSurface::new(du, dv, ku.to_vec(), kv.to_vec(), points, weights)?;
    Ok(Surface::Freeform {
        kind: FreeformKind::Bspline,
        nurbs,
    })
}
