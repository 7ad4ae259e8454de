//! The one module that talks to step-io: its scene is walked into our
//! [`Part`]. Everything step-io specific (handles, entity keys, raw
//! entities, units) stays in here.

use crate::id_scan;
use crate::references::{self, References};
use crate::{ReadIssue, ReadLimits, ReadReport, StepError};
use std::collections::{HashMap, HashSet};
use step_io::model as m;
use step_io::scene::{
    CurveKind as SCurve, Edge as SEdge, Face as SFace, Scene, Shell as SShell, SurfaceKind,
};
use step_io::{EntityKey, Orientation, StepModel};
use thinwall_brep::{
    Body, BodyId, BodyKind, Coedge, Edge, EdgeId, Face, FaceId, Loop, LoopId, Part, Shell, Units,
    Vertex, VertexId,
};
use thinwall_geom::frame::{compose, transform_point, transform_vector, IDENTITY};
use thinwall_geom::surface::FreeformKind;
use thinwall_geom::{CurveKind, Frame, NurbsCurve, NurbsSurface, Point3, Surface, Vector3};

type Matrix = [[f64; 4]; 4];

/// Deepest assembly nesting followed.
const MAX_ASSEMBLY_DEPTH: usize = 32;
/// Deepest nesting of surface curves followed to their 3D curve.
const MAX_CURVE_NESTING: usize = 16;
/// Read `bytes` (named `file` in messages) into a part, within `limits`.
pub fn read(
    bytes: &[u8],
    file: &str,
    limits: &ReadLimits,
) -> Result<(Part, ReadReport), StepError> {
    // One scan of the text's references serves the cycle check, the end of
    // a truncated file and the dangling references.
    let refs = References::scan(bytes);
    refuse_cycles(&refs, file)?;
    let (model, report) = step_io::read(bytes).map_err(|e| StepError::Syntax {
        file: file.to_string(),
        message: with_truncation(e.to_string(), bytes, &refs),
    })?;
    let mut out = ReadReport {
        entities_read: report.entities_read,
        entities_kept: report.entities_kept,
        ..ReadReport::default()
    };
    for (id, reason) in &report.dropped {
        out.dropped.push(ReadIssue {
            entity: Some(*id),
            message: reason.to_string(),
        });
    }
    for (id, note) in &report.normalized {
        out.repaired.push(ReadIssue {
            entity: Some(*id),
            message: (*note).to_string(),
        });
    }
    for w in &report.parse_warnings {
        out.repaired.push(ReadIssue {
            entity: None,
            message: w.to_string(),
        });
    }
    let dropped: HashSet<u64> = report.dropped.iter().map(|(id, _)| *id).collect();
    let ids = EntityIds::new(bytes, &dropped, &model, file)?;
    let scene = model.scene();
    let mut builder = Builder::new(&scene, &ids, file, &mut out, limits);
    builder.collect_bodies()?;
    let mut part = builder.part;
    part.occ_ordinals = crate::occ_order::ordinals(&refs, &builder.groups, part.faces.len());
    for w in scene.warnings() {
        out.repaired.push(ReadIssue {
            entity: None,
            message: format!("step-io: {w}"),
        });
    }
    for (referrer, missing) in dangling(&refs, &out) {
        out.dropped.push(ReadIssue {
            entity: Some(referrer),
            message: format!("refers to #{missing}, which the file does not define"),
        });
    }
    if part.bodies.is_empty() {
        return Err(no_brep(&model, file, &out));
    }
    crate::sanity::check(&part, file)?;
    Ok((part, out))
}

/// A parse error at the end of the text, with where the text ends (a
/// truncated file is the usual cause).
fn with_truncation(message: String, bytes: &[u8], refs: &References) -> String {
    if !message.contains("end of file") {
        return message;
    }
    let lines = bytes.iter().filter(|b| **b == b'\n').count() + 1;
    let last = refs.last_id();
    match last {
        Some(id) => format!(
            "{message} (the text ends at line {lines}, after entity #{id}: is the file truncated?)"
        ),
        None => format!("{message} (the text ends at line {lines}: is the file truncated?)"),
    }
}

/// Refuse a file whose references (or product usages) go round in a
/// circle before step-io, which follows them recursively, sees it.
fn refuse_cycles(refs: &References, file: &str) -> Result<(), StepError> {
    if let Some(c) = refs.cycle() {
        return Err(StepError::CyclicReference {
            file: file.to_string(),
            entities: references::list(&c),
        });
    }
    if let Some(c) = refs.assembly_cycle() {
        return Err(StepError::CyclicAssembly {
            file: file.to_string(),
            detail: format!("product definitions and usages {}", references::list(&c)),
        });
    }
    Ok(())
}

/// Dangling references, named only when step-io dropped something because
/// of one.
fn dangling(refs: &References, report: &ReadReport) -> Vec<(u64, u64)> {
    if report
        .dropped
        .iter()
        .any(|d| d.message.contains("dangling"))
    {
        refs.dangling()
    } else {
        Vec::new()
    }
}

fn no_brep(model: &StepModel, file: &str, report: &ReadReport) -> StepError {
    let tessellated = model.all::<m::TessellatedSolid>().len()
        + model.all::<m::TessellatedShell>().len()
        + model.all::<m::TessellatedFace>().len();
    let faces = model.all::<m::AdvancedFace>().len();
    let root_cause = report
        .dropped
        .iter()
        .find(|d| d.message.starts_with("refers to #"))
        .or_else(|| {
            report
                .dropped
                .iter()
                .find(|d| !d.message.starts_with("cascade"))
        })
        .or_else(|| report.dropped.first());
    let detail = if tessellated > 0 {
        format!(
            " (it holds tessellated geometry only: {tessellated} tessellated items; a mesh is not a B-rep)"
        )
    } else if let Some(d) = root_cause.filter(|d| d.message.starts_with("refers to #")) {
        let dangling = report
            .dropped
            .iter()
            .filter(|x| x.message.starts_with("refers to #"))
            .count();
        format!(
            " (#{} {}; {} entities dropped as a consequence)",
            d.entity.unwrap_or(0),
            d.message,
            report.dropped.len() - dangling
        )
    } else if let Some(d) = root_cause {
        format!(
            " ({} entities dropped as unreadable, starting with #{}: {})",
            report.dropped.len(),
            d.entity.unwrap_or(0),
            d.message
        )
    } else if faces > 0 {
        format!(" ({faces} faces, but no solid or closed shell uses them)")
    } else {
        String::new()
    };
    StepError::NoBrep {
        file: file.to_string(),
        detail,
    }
}

/// Arena index → file entity id, for the entity types we report by id.
struct EntityIds {
    by_keyword: HashMap<&'static str, Vec<u64>>,
}

impl EntityIds {
    fn new(
        bytes: &[u8],
        dropped: &HashSet<u64>,
        model: &StepModel,
        file: &str,
    ) -> Result<Self, StepError> {
        let mut by_keyword = id_scan::scan_ids(bytes);
        for v in by_keyword.values_mut() {
            v.retain(|id| !dropped.contains(id));
        }
        let expected = [
            ("ADVANCED_FACE", model.all::<m::AdvancedFace>().len()),
            ("FACE_SURFACE", model.all::<m::FaceSurface>().len()),
            ("EDGE_CURVE", model.all::<m::EdgeCurve>().len()),
            ("VERTEX_POINT", model.all::<m::VertexPoint>().len()),
            (
                "MANIFOLD_SOLID_BREP",
                model.all::<m::ManifoldSolidBrep>().len(),
            ),
            ("BREP_WITH_VOIDS", model.all::<m::BrepWithVoids>().len()),
            ("CLOSED_SHELL", model.all::<m::ClosedShell>().len()),
            ("OPEN_SHELL", model.all::<m::OpenShell>().len()),
            (
                "SHELL_BASED_SURFACE_MODEL",
                model.all::<m::ShellBasedSurfaceModel>().len(),
            ),
        ];
        for (keyword, n) in expected {
            let found = by_keyword.get(keyword).map_or(0, Vec::len);
            if found != n {
                return Err(StepError::IdMismatch {
                    file: file.to_string(),
                    keyword,
                    expected: n,
                    found,
                });
            }
        }
        Ok(Self { by_keyword })
    }

    /// The file id of an entity, 0 when its type is not tracked.
    fn of(&self, key: EntityKey) -> u64 {
        let (kw, i) = match key {
            EntityKey::AdvancedFace(i) => ("ADVANCED_FACE", i.0),
            EntityKey::FaceSurface(i) => ("FACE_SURFACE", i.0),
            EntityKey::EdgeCurve(i) => ("EDGE_CURVE", i.0),
            EntityKey::VertexPoint(i) => ("VERTEX_POINT", i.0),
            EntityKey::ManifoldSolidBrep(i) => ("MANIFOLD_SOLID_BREP", i.0),
            EntityKey::BrepWithVoids(i) => ("BREP_WITH_VOIDS", i.0),
            EntityKey::ClosedShell(i) => ("CLOSED_SHELL", i.0),
            EntityKey::OpenShell(i) => ("OPEN_SHELL", i.0),
            EntityKey::ShellBasedSurfaceModel(i) => ("SHELL_BASED_SURFACE_MODEL", i.0),
            _ => return 0,
        };
        self.by_keyword
            .get(kw)
            .and_then(|v| v.get(i as usize))
            .copied()
            .unwrap_or(0)
    }
}

/// Placement and unit scaling applied to every coordinate of one body.
#[derive(Clone, Copy)]
struct Place {
    /// Millimetres per file unit.
    scale: f64,
    /// Radians per file angle unit.
    angle: f64,
    matrix: Matrix,
}

impl Place {
    fn point(&self, xyz: &[f64]) -> Option<Point3> {
        if xyz.len() < 3 || xyz.iter().any(|c| !c.is_finite()) {
            return None;
        }
        let p = Point3::new(xyz[0], xyz[1], xyz[2]) * self.scale;
        Some(transform_point(&self.matrix, &p))
    }

    fn vector(&self, v: Vector3) -> Vector3 {
        transform_vector(&self.matrix, &v)
    }
}

struct Builder<'s, 'm> {
    scene: &'s Scene<'m>,
    model: &'m StepModel,
    ids: &'s EntityIds,
    file: &'s str,
    report: &'s mut ReadReport,
    part: Part,
    units: (f64, f64),
    placed: HashSet<(EntityKey, [u64; 12])>,
    limits: &'s ReadLimits,
    /// The solids and surface models placed, for OpenCascade's face order.
    groups: Vec<crate::occ_order::Group>,
    /// Product definitions visited so far (then one per later phase).
    visit: usize,
}

/// The state of an assembly walk: the definitions above the current one,
/// and how many instances have been placed.
#[derive(Default)]
struct Walk {
    ancestors: Vec<EntityKey>,
    instances: usize,
}

fn matrix_key(m: &Matrix) -> [u64; 12] {
    let mut k = [0u64; 12];
    for (i, row) in m.iter().take(3).enumerate() {
        for j in 0..4 {
            k[i * 4 + j] = row[j].to_bits();
        }
    }
    k
}

impl<'s, 'm> Builder<'s, 'm> {
    fn new(
        scene: &'s Scene<'m>,
        ids: &'s EntityIds,
        file: &'s str,
        report: &'s mut ReadReport,
        limits: &'s ReadLimits,
    ) -> Self {
        let units = scene.units();
        let (length_name, mm) = match &units.length {
            Some(u) if u.to_si.is_finite() && u.to_si > 0.0 => (u.name.clone(), u.to_si * 1000.0),
            _ => {
                report.repaired.push(ReadIssue {
                    entity: None,
                    message: "no length unit in the file; millimetres assumed".into(),
                });
                ("millimetre".to_string(), 1.0)
            }
        };
        let (angle_name, rad) = match &units.angle {
            Some(u) if u.to_si.is_finite() && u.to_si > 0.0 => (u.name.clone(), u.to_si),
            _ => ("radian".to_string(), 1.0),
        };
        let part = Part {
            units: Units {
                length: length_name,
                mm_per_unit: mm,
                angle: angle_name,
                rad_per_unit: rad,
            },
            ..Part::default()
        };
        Self {
            scene,
            model: scene.model(),
            ids,
            file,
            report,
            part,
            units: (mm, rad),
            placed: HashSet::new(),
            limits,
            groups: Vec::new(),
            visit: 0,
        }
    }

    fn place(&self, matrix: Matrix) -> Place {
        Place {
            scale: self.units.0,
            angle: self.units.1,
            matrix,
        }
    }

    fn issue(&mut self, entity: Option<u64>, message: impl Into<String>) {
        self.report.repaired.push(ReadIssue {
            entity,
            message: message.into(),
        });
    }

    /// Bodies from the product structure (with placements), then any solid
    /// or surface model it does not reach, in place.
    fn collect_bodies(&mut self) -> Result<(), StepError> {
        let roots: Vec<_> = self.scene.root_definitions().collect();
        let mut walk = Walk::default();
        for def in roots {
            self.visit_definition(def, IDENTITY, def.id().to_string(), &mut walk)?;
        }
        self.visit += 1;
        let mapped: Vec<_> = self.scene.all_mapped_instances().collect();
        for mi in mapped {
            let matrix = match mi.transform().and_then(|t| t.matrix()) {
                Some(mm) => mm,
                None => {
                    self.issue(None, "a MAPPED_ITEM has no usable placement; identity used");
                    IDENTITY
                }
            };
            let matrix = scale_translation(&matrix, self.units.0);
            for solid in mi.solids() {
                self.add_solid(solid, matrix, Some(format!("mapped item {}", mi.name())))?;
            }
            for sm in mi.surface_models() {
                self.add_surface_model(sm, matrix, Some(format!("mapped item {}", mi.name())))?;
            }
        }
        self.visit += 1;
        let solids: Vec<_> = self.scene.all_solids().collect();
        for solid in solids {
            if !self.placed.iter().any(|(k, _)| *k == solid.key()) {
                self.add_solid(solid, IDENTITY, None)?;
            }
        }
        let models: Vec<_> = self.scene.all_surface_models().collect();
        for sm in models {
            if !self.placed.iter().any(|(k, _)| *k == sm.key()) {
                self.add_surface_model(sm, IDENTITY, None)?;
            }
        }
        Ok(())
    }

    /// Place a definition's solids and walk its occurrences, refusing a
    /// definition that contains itself and a walk that places too many.
    fn visit_definition(
        &mut self,
        def: step_io::scene::ProductDef<'s>,
        matrix: Matrix,
        path: String,
        walk: &mut Walk,
    ) -> Result<(), StepError> {
        let depth = walk.ancestors.len();
        if walk.ancestors.contains(&def.key()) {
            return Err(StepError::CyclicAssembly {
                file: self.file.to_string(),
                detail: format!(
                    "product definition '{}' contains itself (path {path})",
                    def.id()
                ),
            });
        }
        walk.instances += 1;
        self.visit += 1;
        if walk.instances > self.limits.max_instances {
            return Err(StepError::TooManyInstances {
                file: self.file.to_string(),
                limit: self.limits.max_instances,
            });
        }
        if depth > MAX_ASSEMBLY_DEPTH {
            self.issue(
                None,
                format!("assembly deeper than {MAX_ASSEMBLY_DEPTH} levels at {path}: not followed"),
            );
            return Ok(());
        }
        let placement = (depth > 0).then(|| path.clone());
        for solid in def.solids() {
            self.add_solid(solid, matrix, placement.clone())?;
        }
        for sm in def.surface_models() {
            self.add_surface_model(sm, matrix, placement.clone())?;
        }
        walk.ancestors.push(def.key());
        for occ in def.occurrences() {
            let Some(child) = occ.definition() else {
                continue;
            };
            let local = match occ.transform().and_then(|t| t.matrix()) {
                Some(mm) => scale_translation(&mm, self.units.0),
                None => {
                    self.issue(
                        None,
                        format!(
                            "occurrence of {} has no usable placement; identity used",
                            child.id()
                        ),
                    );
                    IDENTITY
                }
            };
            let child_path = format!("{path}/{}", child.id());
            self.visit_definition(child, compose(&matrix, &local), child_path, walk)?;
        }
        walk.ancestors.pop();
        Ok(())
    }

    fn add_solid(
        &mut self,
        solid: step_io::scene::Solid<'s>,
        matrix: Matrix,
        placement: Option<String>,
    ) -> Result<(), StepError> {
        if !self.placed.insert((solid.key(), matrix_key(&matrix))) {
            return Ok(());
        }
        let step_id = self.ids.of(solid.key());
        let kind = match solid.key() {
            EntityKey::BrepWithVoids(_) => BodyKind::SolidWithVoids,
            _ => BodyKind::ManifoldSolid,
        };
        let Some((outer, orient)) = solid.outer() else {
            self.issue(Some(step_id), "solid without an outer shell: skipped");
            return Ok(());
        };
        let mut shells = vec![(outer, orient, false)];
        shells.extend(solid.voids().map(|(s, o)| (s, o, true)));
        for (s, _, _) in &shells {
            if !s.is_closed() {
                return Err(StepError::OpenShell {
                    file: self.file.to_string(),
                    solid: step_id,
                    shell: self.ids.of(s.key()),
                });
            }
        }
        let body = Body {
            step_id,
            name: solid.name().to_string(),
            kind,
            shells: Vec::new(),
            placement,
        };
        self.add_body(body, shells, self.place(matrix))
    }

    fn add_surface_model(
        &mut self,
        sm: step_io::scene::SurfaceModel<'s>,
        matrix: Matrix,
        placement: Option<String>,
    ) -> Result<(), StepError> {
        if !self.placed.insert((sm.key(), matrix_key(&matrix))) {
            return Ok(());
        }
        let shells: Vec<_> = sm.shells().collect();
        let step_id = self.ids.of(sm.key());
        if !shells.is_empty() && shells.iter().all(|(s, _)| s.is_closed()) {
            let body = Body {
                step_id,
                name: sm.name().to_string(),
                kind: BodyKind::ClosedSurfaceModel,
                shells: Vec::new(),
                placement,
            };
            let shells = shells.into_iter().map(|(s, o)| (s, o, false)).collect();
            self.add_body(body, shells, self.place(matrix))
        } else {
            let count = shells.iter().map(|(s, _)| s.faces().count()).sum::<usize>();
            self.part.supplemental.surface_models.push(step_id);
            self.part.supplemental.face_count += count;
            self.groups.push(crate::occ_order::Group {
                visit: self.visit,
                item: step_id,
                first: None,
                count,
            });
            Ok(())
        }
    }

    fn add_body(
        &mut self,
        mut body: Body,
        shells: Vec<(SShell<'s>, Orientation, bool)>,
        place: Place,
    ) -> Result<(), StepError> {
        let adding: usize = shells.iter().map(|(s, _, _)| s.faces().count()).sum();
        if self.part.faces.len() + adding > self.limits.max_faces {
            return Err(StepError::BudgetExceeded {
                file: self.file.to_string(),
                what: "the faces placed (instances × their faces)",
                limit: self.limits.max_faces as u64,
            });
        }
        let body_id = BodyId(self.part.bodies.len() as u32);
        let first = self.part.faces.len();
        let mut edges: HashMap<EntityKey, EdgeId> = HashMap::new();
        let mut vertices: HashMap<EntityKey, VertexId> = HashMap::new();
        let mut seen: HashSet<EntityKey> = HashSet::new();
        for (shell, orient, is_void) in shells {
            let mut faces = Vec::new();
            for face in shell.faces() {
                if !seen.insert(face.key()) {
                    let (shell_id, face_id) = (self.ids.of(shell.key()), self.ids.of(face.key()));
                    self.issue(
                        Some(shell_id),
                        format!("shell lists face #{face_id} more than once: counted once"),
                    );
                    continue;
                }
                let flip = orient == Orientation::Reversed;
                let id = self.add_face(face, body_id, flip, &place, &mut edges, &mut vertices);
                faces.push(id);
            }
            body.shells.push(Shell {
                step_id: self.ids.of(shell.key()),
                is_void,
                faces,
            });
        }
        self.groups.push(crate::occ_order::Group {
            visit: self.visit,
            item: body.step_id,
            first: Some(first),
            count: self.part.faces.len() - first,
        });
        self.part.bodies.push(body);
        Ok(())
    }

    fn add_face(
        &mut self,
        face: SFace<'s>,
        body: BodyId,
        shell_flipped: bool,
        place: &Place,
        edges: &mut HashMap<EntityKey, EdgeId>,
        vertices: &mut HashMap<EntityKey, VertexId>,
    ) -> FaceId {
        let face_id = FaceId(self.part.faces.len() as u32);
        let step_id = self.ids.of(face.key());
        let (surface, turned) =
            thinwall_geom::surface::analytic_form(self.surface(face, place, step_id));
        let same_sense = ((face.orientation() == Orientation::Forward) != shell_flipped) != turned;
        let mut loops = Vec::new();
        let mut bounds: Vec<_> = face.bounds().collect();
        // Outer bounds first.
        bounds.sort_by_key(|b| !b.is_outer());
        for bound in bounds {
            let reversed = bound.orientation() == Orientation::Reversed;
            let mut coedges = Vec::new();
            for (edge, o) in bound.oriented_edges() {
                let Some(eid) = self.edge(edge, place, edges, vertices) else {
                    continue;
                };
                coedges.push(Coedge {
                    edge: eid,
                    forward: (o == Orientation::Forward) != reversed,
                });
            }
            if reversed {
                coedges.reverse();
            }
            let vertex = bound.vertex().and_then(|v| self.vertex(v, place, vertices));
            let loop_id = LoopId(self.part.loops.len() as u32);
            self.part.loops.push(Loop {
                face: face_id,
                is_outer: bound.is_outer(),
                coedges,
                vertex,
            });
            loops.push(loop_id);
        }
        self.part.faces.push(Face {
            step_id,
            name: face.name().to_string(),
            body,
            surface,
            same_sense,
            loops,
        });
        face_id
    }

    fn vertex(
        &mut self,
        v: step_io::scene::Vertex<'s>,
        place: &Place,
        vertices: &mut HashMap<EntityKey, VertexId>,
    ) -> Option<VertexId> {
        if let Some(id) = vertices.get(&v.key()) {
            return Some(*id);
        }
        let step_id = self.ids.of(v.key());
        let Some(point) = v.point().and_then(|p| place.point(&p.xyz())) else {
            self.issue(Some(step_id), "vertex without a usable point: dropped");
            return None;
        };
        let id = VertexId(self.part.vertices.len() as u32);
        self.part.vertices.push(Vertex { step_id, point });
        vertices.insert(v.key(), id);
        Some(id)
    }

    fn edge(
        &mut self,
        edge: SEdge<'s>,
        place: &Place,
        edges: &mut HashMap<EntityKey, EdgeId>,
        vertices: &mut HashMap<EntityKey, VertexId>,
    ) -> Option<EdgeId> {
        if let Some(id) = edges.get(&edge.key()) {
            return Some(*id);
        }
        let step_id = self.ids.of(edge.key());
        let (Some(sv), Some(ev)) = (edge.start(), edge.end()) else {
            self.issue(
                Some(step_id),
                "edge without vertices: dropped from its loop",
            );
            return None;
        };
        let start = self.vertex(sv, place, vertices)?;
        let end = self.vertex(ev, place, vertices)?;
        let nurbs = edge.to_nurbs().and_then(|n| {
            let mut c = NurbsCurve::new(n.degree, n.knots, &n.control_points, &n.weights).ok()?;
            c.map_points(|p| place.point(&[p.x, p.y, p.z]).unwrap_or(p));
            Some(c)
        });
        let curve = self.curve_kind(edge.curve(), place, 0);
        // step-io returns a closed edge (start = end vertex) as its whole
        // curve in the curve's own direction, even when the edge runs
        // against it.
        let conic = matches!(curve, CurveKind::Circle { .. } | CurveKind::Ellipse { .. });
        let nurbs = match nurbs {
            // A circle or ellipse is built from its vertices in equal pieces
            // of at most a quarter turn: step-io's arc has its knots where
            // the curve's own parametrisation puts them (a closed one even
            // starts at the curve's origin, not at the vertex), so the same
            // arc written from another reference direction (a part turned,
            // or written by another system) was sampled at other points.
            Some(n) if conic => self
                .conic_arc(&curve, start, end, edge.same_sense())
                .or(Some(if start == end && !edge.same_sense() {
                    n.reversed()
                } else {
                    n
                })),
            Some(n) => Some(n),
            None => {
                let arc = self.conic_arc(&curve, start, end, edge.same_sense());
                if arc.is_some() {
                    self.issue(
                        Some(step_id),
                        format!(
                            "{} edge built by Thinwall (step-io could not convert it)",
                            curve.name()
                        ),
                    );
                } else {
                    self.issue(
                        Some(step_id),
                        "edge curve could not be evaluated; treated as missing",
                    );
                }
                arc
            }
        };
        let nurbs = match (&curve, nurbs) {
            // The curve is the geometry: a vertex off its line is a gap for
            // the vertex tolerance to cover, not a bend of the edge (as
            // OpenCascade reads it too). step-io spans vertex to vertex.
            (CurveKind::Line { origin, direction }, Some(_)) => {
                let on_line = |v: VertexId| {
                    let p = self.part.vertex(v).point;
                    let t = (p - origin).dot(direction);
                    let q = origin + direction * t;
                    [q.x, q.y, q.z]
                };
                NurbsCurve::new(
                    1,
                    vec![0.0, 0.0, 1.0, 1.0],
                    &[on_line(start), on_line(end)],
                    &[1.0, 1.0],
                )
                .ok()
            }
            (_, n) => n,
        };
        let id = EdgeId(self.part.edges.len() as u32);
        self.part.edges.push(Edge {
            step_id,
            start,
            end,
            curve,
            nurbs,
        });
        edges.insert(edge.key(), id);
        Some(id)
    }

    /// The arc of a circle or ellipse edge between its vertices; with
    /// `same_sense` it runs the way the curve is parametrised.
    fn conic_arc(
        &self,
        curve: &CurveKind,
        start: VertexId,
        end: VertexId,
        same_sense: bool,
    ) -> Option<NurbsCurve> {
        let (frame, a, b) = match curve {
            CurveKind::Circle { frame, radius } => (frame, *radius, *radius),
            CurveKind::Ellipse {
                frame,
                semi_axis_1,
                semi_axis_2,
            } => (frame, *semi_axis_1, *semi_axis_2),
            _ => return None,
        };
        let angle = |v: VertexId| {
            let l = frame.to_local(&self.part.vertex(v).point);
            (l.y / b).atan2(l.x / a)
        };
        let (t0, t1) = (angle(start), angle(end));
        let tau = std::f64::consts::TAU;
        let mut sweep = (t1 - t0).rem_euclid(tau);
        if start == end || sweep < 1e-12 {
            sweep = tau;
        }
        if !same_sense {
            sweep -= tau;
            if sweep.abs() < 1e-12 {
                sweep = -tau;
            }
        }
        NurbsCurve::ellipse_arc(frame, a, b, t0, sweep)
    }

    /// The analytic description of an edge curve; surface curves are
    /// followed to their 3D curve at most `MAX_CURVE_NESTING` deep (a file
    /// may nest them, or make one refer to itself).
    fn curve_kind(
        &self,
        curve: step_io::scene::Curve<'s>,
        place: &Place,
        depth: usize,
    ) -> CurveKind {
        if depth > MAX_CURVE_NESTING {
            return CurveKind::Other {
                keyword: format!("SURFACE_CURVE nested deeper than {MAX_CURVE_NESTING}"),
            };
        }
        let kind = curve.kind();
        match kind {
            SCurve::SurfaceCurve(_)
            | SCurve::SeamCurve(_)
            | SCurve::BoundedSurfaceCurve(_)
            | SCurve::IntersectionCurve(_) => match curve.curve_3d() {
                Some(c3) => self.curve_kind(c3, place, depth + 1),
                None => CurveKind::Other {
                    keyword: "SURFACE_CURVE".into(),
                },
            },
            SCurve::Line(l) => {
                let origin = self.point_ref(&l.pnt, place);
                let dir = match &l.dir {
                    m::VectorRef::Vector(v) => self.direction_ref(&self.model[*v].orientation),
                    m::VectorRef::Complex(_) => None,
                };
                match (origin, dir) {
                    (Some(origin), Some(d)) => CurveKind::Line {
                        origin,
                        direction: place.vector(d).normalize(),
                    },
                    _ => CurveKind::Other {
                        keyword: "LINE".into(),
                    },
                }
            }
            SCurve::Circle(c) => match self.frame2(&c.position, place) {
                Some(frame) => CurveKind::Circle {
                    frame,
                    radius: c.radius * place.scale,
                },
                None => CurveKind::Other {
                    keyword: "CIRCLE".into(),
                },
            },
            SCurve::Ellipse(e) => match self.frame2(&e.position, place) {
                Some(frame) => CurveKind::Ellipse {
                    frame,
                    semi_axis_1: e.semi_axis_1 * place.scale,
                    semi_axis_2: e.semi_axis_2 * place.scale,
                },
                None => CurveKind::Other {
                    keyword: "ELLIPSE".into(),
                },
            },
            SCurve::BSpline(_)
            | SCurve::BSplineWithKnots(_)
            | SCurve::QuasiUniform(_)
            | SCurve::Uniform(_)
            | SCurve::Bezier(_) => CurveKind::Bspline,
            SCurve::Polyline(_) => CurveKind::Polyline,
            SCurve::Trimmed(_) => CurveKind::Other {
                keyword: "TRIMMED_CURVE".into(),
            },
            SCurve::Composite(_) => CurveKind::Other {
                keyword: "COMPOSITE_CURVE".into(),
            },
            SCurve::Parabola(_) => CurveKind::Other {
                keyword: "PARABOLA".into(),
            },
            SCurve::Hyperbola(_) => CurveKind::Other {
                keyword: "HYPERBOLA".into(),
            },
            SCurve::Other(k) => CurveKind::Other {
                keyword: k.to_string(),
            },
            _ => CurveKind::Other {
                keyword: "CURVE".into(),
            },
        }
    }

    fn point_ref(&self, r: &m::CartesianPointRef, place: &Place) -> Option<Point3> {
        match r {
            m::CartesianPointRef::CartesianPoint(id) => place.point(&self.model[*id].coordinates),
            _ => None,
        }
    }

    fn direction_ref(&self, r: &m::DirectionRef) -> Option<Vector3> {
        match r {
            m::DirectionRef::Direction(id) => {
                let d = &self.model[*id].direction_ratios;
                (d.len() == 3 && d.iter().all(|c| c.is_finite()))
                    .then(|| Vector3::new(d[0], d[1], d[2]))
            }
            m::DirectionRef::Complex(_) => None,
        }
    }

    fn frame3(&self, r: &m::Axis2Placement3dRef, place: &Place) -> Option<Frame> {
        let m::Axis2Placement3dRef::Axis2Placement3d(id) = r;
        let a = &self.model[*id];
        let origin = self.point_ref(&a.location, place)?;
        let axis = a
            .axis
            .as_ref()
            .and_then(|d| self.direction_ref(d))
            .unwrap_or_else(Vector3::z);
        let reference = a.ref_direction.as_ref().and_then(|d| self.direction_ref(d));
        Frame::from_axis(
            origin,
            place.vector(axis),
            reference.map(|r| place.vector(r)),
        )
    }

    fn frame2(&self, r: &m::Axis2PlacementRef, place: &Place) -> Option<Frame> {
        match r {
            m::Axis2PlacementRef::Axis2Placement3d(id) => {
                self.frame3(&m::Axis2Placement3dRef::Axis2Placement3d(*id), place)
            }
            m::Axis2PlacementRef::Axis2Placement2d(_) => None,
        }
    }

    fn surface(&mut self, face: SFace<'s>, place: &Place, face_id: u64) -> Surface {
        let s = face.surface();
        let analytic = match s.kind() {
            SurfaceKind::Plane(p) => self
                .frame3(&p.position, place)
                .map(|frame| Surface::Plane { frame }),
            SurfaceKind::Cylindrical(c) => {
                self.frame3(&c.position, place)
                    .map(|frame| Surface::Cylinder {
                        frame,
                        radius: c.radius * place.scale,
                    })
            }
            SurfaceKind::Conical(c) => self.frame3(&c.position, place).map(|frame| Surface::Cone {
                frame,
                radius: c.radius * place.scale,
                semi_angle: c.semi_angle * place.angle,
            }),
            SurfaceKind::Spherical(c) => {
                self.frame3(&c.position, place)
                    .map(|frame| Surface::Sphere {
                        frame,
                        radius: c.radius * place.scale,
                    })
            }
            SurfaceKind::Toroidal(t) => {
                self.frame3(&t.position, place).map(|frame| Surface::Torus {
                    frame,
                    major_radius: t.major_radius * place.scale,
                    minor_radius: t.minor_radius * place.scale,
                })
            }
            _ => None,
        };
        if let Some(a) = analytic {
            return a;
        }
        let kind = match s.kind() {
            SurfaceKind::BSpline(_)
            | SurfaceKind::BSplineWithKnots(_)
            | SurfaceKind::QuasiUniform(_)
            | SurfaceKind::Uniform(_)
            | SurfaceKind::Bezier(_) => FreeformKind::Bspline,
            SurfaceKind::LinearExtrusion(_) => FreeformKind::Extrusion,
            SurfaceKind::Revolution(_) => FreeformKind::Revolution,
            SurfaceKind::Offset(_) => FreeformKind::Offset,
            _ => FreeformKind::Other,
        };
        let keyword = s
            .key()
            .keyword()
            .unwrap_or("complex B-spline surface")
            .to_string();
        let revolved = matches!(s.kind(), SurfaceKind::Revolution(_));
        let nurbs = face.to_nurbs().and_then(|mut n| {
            if revolved {
                let boundary = boundary_points(face);
                crate::seam::away_from(
                    &n.knots_u,
                    &mut n.control_points,
                    &mut n.weights,
                    &boundary,
                );
            }
            let mut ns = NurbsSurface::new(
                n.degree_u,
                n.degree_v,
                n.knots_u,
                n.knots_v,
                &n.control_points,
                &n.weights,
            )
            .ok()?;
            ns.map_points(|p| place.point(&[p.x, p.y, p.z]).unwrap_or(p));
            Some(ns)
        });
        match nurbs {
            Some(nurbs) => Surface::Freeform { kind, nurbs },
            None => {
                self.issue(
                    Some(face_id),
                    format!("surface {keyword} could not be converted; face kept without geometry"),
                );
                Surface::Unsupported { keyword }
            }
        }
    }
}

/// Points on a face's boundary, in file coordinates: its edges' vertices
/// and the middles of their curves.
fn boundary_points(face: SFace<'_>) -> Vec<[f64; 3]> {
    let mut out = Vec::new();
    for bound in face.bounds() {
        for (edge, _) in bound.oriented_edges() {
            for v in [edge.start(), edge.end()].into_iter().flatten() {
                out.extend(v.point().map(|p| p.xyz()));
            }
            if let Some(c) = edge.to_nurbs().and_then(|n| {
                NurbsCurve::new(n.degree, n.knots, &n.control_points, &n.weights).ok()
            }) {
                let (a, b) = c.domain();
                let m = c.point(0.5 * (a + b));
                out.push([m.x, m.y, m.z]);
            }
        }
    }
    out
}

/// A placement matrix read in file units, with its translation scaled to mm.
fn scale_translation(m: &Matrix, scale: f64) -> Matrix {
    let mut out = *m;
    for row in out.iter_mut().take(3) {
        row[3] *= scale;
    }
    out
}
