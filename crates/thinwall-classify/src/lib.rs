//! Dedicated classification of machining-feature volumes (DOMAIN.md §5.3,
//! Popma 5.4.2, 6.2.3): each volume must match a type exactly, by its shape
//! (a planar profile swept along the tool direction, top open) and by which
//! of its faces are closed — coinciding over an area with the part, or with
//! a volume not removed before it — and which open.
//!
//! ```no_run
//! # let (part, _) = thinwall_step::read_file("part.step").unwrap();
//! # let (v0, _) = thinwall_step::read_file("v0.step").unwrap();
//! use thinwall_analysis::{PartAnalysis, Setup};
//! use thinwall_classify::{classify, Request, Volume};
//! let a = PartAnalysis::new(&part, Setup::default());
//! let volumes = vec![Volume { name: "v0".into(), part: v0, current: None, up: None }];
//! let r = classify(&Request { part: &a, volumes: &volumes, before: &[], together: &[], priority: vec![] }).unwrap();
//! println!("{}", r[0].kind);
//! ```

mod checks;
mod coincide;
pub(crate) mod index;
mod profile;
pub mod types;

pub use types::*;

use coincide::{coincide, FaceGeom, Tol};
use std::collections::HashSet;
use thinwall_analysis::{PartAnalysis, Setup};
use thinwall_brep::Part;
use thinwall_geom::Vector3;
use thiserror::Error;

/// A volume to classify.
pub struct Volume {
    pub name: String,
    /// The volume as a solid (read from its own STEP file).
    pub part: Part,
    /// Its current type, tried first (re-classification keeps a type that
    /// still fits).
    pub current: Option<VolumeType>,
    /// The direction its tool comes from, when not the set-up's up (a
    /// volume reached from another set-up: a hole through an upright rib).
    pub up: Option<Vector3>,
}

/// What to classify: volumes against the analysed part, in the part's
/// set-up (the tool comes from above: its direction is `−up`).
pub struct Request<'a> {
    pub part: &'a PartAnalysis<'a>,
    pub volumes: &'a [Volume],
    /// `(a, b)`: volume `a` is removed before volume `b`.
    pub before: &'a [(usize, usize)],
    /// `(a, b)`: volumes `a` and `b` are removed together (solids of one
    /// machining feature): a face between them is open for both.
    pub together: &'a [(usize, usize)],
    /// Type order; empty for [`DEFAULT_PRIORITY`].
    pub priority: Vec<VolumeType>,
}

/// A request that cannot be served.
#[derive(Debug, Error, PartialEq)]
pub enum ClassifyError {
    #[error("sequence {before} before {after} names volumes outside 0..{count}")]
    Sequence {
        before: usize,
        after: usize,
        count: usize,
    },
    #[error("volume {volume} cannot be removed before itself")]
    SelfPair { volume: usize },
    #[error("the removal sequence is cyclic: volume {volume} would come before itself")]
    Cycle { volume: usize },
    #[error("volume {volume} has {bodies} bodies; a volume is one solid")]
    MultiBody { volume: usize, bodies: usize },
    #[error("volumes {first} and {second} are the same solid")]
    Duplicate { first: usize, second: usize },
    #[error("volume {volume} is the part itself, not a volume to remove")]
    PartAsVolume { volume: usize },
    #[error("volumes {first} and {second} overlap: a volume is removed once")]
    Overlap { first: usize, second: usize },
}

impl ClassifyError {
    /// A stable machine-readable code for the error kind.
    pub fn code(&self) -> &'static str {
        match self {
            ClassifyError::Sequence { .. } => "sequence",
            ClassifyError::SelfPair { .. } => "self_pair",
            ClassifyError::Cycle { .. } => "cycle",
            ClassifyError::MultiBody { .. } => "multi_body",
            ClassifyError::Duplicate { .. } => "duplicate",
            ClassifyError::PartAsVolume { .. } => "part_as_volume",
            ClassifyError::Overlap { .. } => "overlap",
        }
    }
}

/// One volume face with its role, whether it is closed, what it touches.
pub(crate) struct Judged<'g> {
    pub geom: &'g FaceGeom<'g>,
    pub role: FaceRole,
    pub closed: bool,
    pub touches: Vec<Touch>,
}

/// Classify every volume of the request.
pub fn classify(req: &Request) -> Result<Vec<Classification>, ClassifyError> {
    checks::sequence(req.before, req.volumes.len())?;
    let up = req.part.up();
    let priority = if req.priority.is_empty() {
        DEFAULT_PRIORITY.to_vec()
    } else {
        req.priority.clone()
    };
    let tol = Tol::of(req.part);
    let part_faces = FaceGeom::all(req.part);
    // Volumes are parts of their own, analysed in the same set-up.
    let analyses: Vec<PartAnalysis> = req
        .volumes
        .iter()
        .map(|v| {
            PartAnalysis::new(&v.part, Setup::clone(req.part.setup()))
                .with_parallelism(req.part.is_parallel())
        })
        .collect();
    checks::volumes(req.part, req.volumes, &analyses)?;
    let work = req.part.work();
    let vol_faces: Vec<Vec<FaceGeom>> = analyses.iter().map(FaceGeom::all).collect();
    checks::overlaps(&vol_faces, &up, &tol)?;
    let near = Near::new(&part_faces, &vol_faces, tol.lin);
    let mut preds: Vec<HashSet<usize>> = vec![HashSet::new(); req.volumes.len()];
    for &(a, b) in req.before {
        preds[b].insert(a);
    }
    for &(a, b) in req.together {
        if a.max(b) >= req.volumes.len() {
            return Err(ClassifyError::Sequence {
                before: a,
                after: b,
                count: req.volumes.len(),
            });
        }
        preds[b].insert(a);
        preds[a].insert(b);
    }
    // Each volume is judged against the part and the others alone: on the
    // part's threads, in the volumes' order.
    let order: Vec<usize> = (0..req.volumes.len()).collect();
    Ok(work.map(&order, |&vi| {
        let vol = &req.volumes[vi];
        let predecessors = &preds[vi];
        let up = vol
            .up
            .and_then(|u| u.try_normalize(thinwall_geom::tolerance::DIRECTION_NORM_MIN))
            .unwrap_or(up);
        let faces: Vec<Judged> = vol_faces[vi]
            .iter()
            .map(|g| {
                judge(
                    g,
                    vi,
                    &near,
                    &part_faces,
                    &vol_faces,
                    predecessors,
                    &up,
                    &tol,
                )
            })
            .collect();
        let ctx = profile::Context {
            vol,
            analysis: &analyses[vi],
            part: req.part,
            part_faces: &part_faces,
            part_index: &near.part,
            up: &up,
            tol: &tol,
        };
        profile::shape(&ctx, vi, faces, &priority)
    }))
}

/// The part's and the volumes' faces indexed by their boxes.
struct Near {
    part: index::BoxIndex,
    volumes: index::BoxIndex,
    /// Per indexed volume face: (volume, face).
    owner: Vec<(usize, usize)>,
}

impl Near {
    fn new(part_faces: &[FaceGeom], vol_faces: &[Vec<FaceGeom>], grow: f64) -> Self {
        let boxes: Vec<_> = part_faces.iter().map(|g| g.bbox).collect();
        let mut owner = Vec::new();
        let mut vboxes = Vec::new();
        for (vi, faces) in vol_faces.iter().enumerate() {
            for (fi, g) in faces.iter().enumerate() {
                owner.push((vi, fi));
                vboxes.push(g.bbox);
            }
        }
        Self {
            part: index::BoxIndex::new(&boxes, grow),
            volumes: index::BoxIndex::new(&vboxes, grow),
            owner,
        }
    }
}

/// A volume face's role, what it coincides with, and whether that closes it.
#[allow(clippy::too_many_arguments)]
fn judge<'g>(
    g: &'g FaceGeom<'g>,
    vi: usize,
    near: &Near,
    part_faces: &[FaceGeom],
    vol_faces: &[Vec<FaceGeom>],
    predecessors: &HashSet<usize>,
    up: &Vector3,
    tol: &Tol,
) -> Judged<'g> {
    let mut touches = Vec::new();
    let mut closed = false;
    for p in near.part.near(&g.bbox).into_iter().map(|i| &part_faces[i]) {
        if coincide(g, p, tol) {
            touches.push(Touch::Part { step_id: p.step_id });
            closed = true;
        }
    }
    for (wi, fi) in near
        .volumes
        .near(&g.bbox)
        .into_iter()
        .map(|k| near.owner[k])
    {
        if wi == vi {
            continue;
        }
        let h = &vol_faces[wi][fi];
        if coincide(g, h, tol) {
            touches.push(Touch::Volume {
                index: wi,
                step_id: h.step_id,
            });
            if !predecessors.contains(&wi) {
                closed = true;
            }
        }
    }
    Judged {
        geom: g,
        role: g.role(up, tol),
        closed,
        touches,
    }
}
