//! The part's triangles in a tool axis's frame (`z` along the axis, up),
//! in a hierarchy of boxes by face, and what stops a tool whose tip runs
//! along a level line.

use super::interval::{line_near_convex, point_near_convex, Span};
use super::Tool;
use rstar::primitives::{GeomWithData, Rectangle};
use rstar::{RTree, AABB};
use thinwall_brep::tessellate::Mesh;
use thinwall_geom::{Frame, Point3, Vector3};

/// One triangle of the part, in the axis frame.
pub struct Tri {
    pub p: [[f64; 3]; 3],
    /// The corners' indices into the mesh's points (edges shared by two
    /// triangles share them).
    pub v: [u32; 3],
    /// Index into the mesh's faces.
    pub face: u32,
    /// Of a curved face, or a planar one with a curved edge: its chords
    /// lie up to the tessellation's deviation off the face, so it touches
    /// the tool within a wider tolerance.
    pub tessellated: bool,
    lo: [f64; 3],
    hi: [f64; 3],
}

impl Tri {
    pub fn new(p: [[f64; 3]; 3], v: [u32; 3], face: u32, tessellated: bool) -> Self {
        let mut lo = p[0];
        let mut hi = p[0];
        for q in &p[1..] {
            for c in 0..3 {
                lo[c] = lo[c].min(q[c]);
                hi[c] = hi[c].max(q[c]);
            }
        }
        Self {
            p,
            v,
            face,
            tessellated,
            lo,
            hi,
        }
    }
}

type Boxes = RTree<GeomWithData<Rectangle<[f64; 3]>, u32>>;

/// Triangles in the frame of one tool axis, in a two-level hierarchy of
/// boxes (x, y, z in the frame): the faces', and each face's triangles'
/// (R-trees, `rstar`). A query by footprint and height takes the faces
/// whose box meets it, then their triangles; one that asks which faces
/// stop a tool stops testing a face at its first triangle that does.
pub struct Scene {
    pub frame: Frame,
    pub tris: Vec<Tri>,
    /// The boxes of the mesh's faces (index into the mesh's faces).
    faces: Boxes,
    /// Per face of the mesh, its triangles' boxes (index into `tris`).
    face_tris: Vec<Boxes>,
}

impl Scene {
    /// `frame.z` is the tool axis; the origin near the part keeps the
    /// coordinates small. `curved` tells the mesh's faces whose triangles
    /// only approximate them ([`Tri::tessellated`]).
    pub fn new(mesh: &Mesh, frame: Frame, curved: impl Fn(usize) -> bool) -> Self {
        let mut tris = Vec::new();
        let mut face_tris = Vec::with_capacity(mesh.faces.len());
        let mut face_boxes = Vec::new();
        for (k, fm) in mesh.faces.iter().enumerate() {
            let first = tris.len();
            for t in &fm.triangles {
                let p = t.map(|i| {
                    let l = frame.to_local(&mesh.points[i as usize]);
                    [l.x, l.y, l.z]
                });
                tris.push(Tri::new(p, *t, k as u32, curved(k)));
            }
            let own = &tris[first..];
            let boxes: Vec<_> = own
                .iter()
                .zip(first as u32..)
                .map(|(t, i)| GeomWithData::new(Rectangle::from_corners(t.lo, t.hi), i))
                .collect();
            if let Some(t0) = own.first() {
                let (mut lo, mut hi) = (t0.lo, t0.hi);
                for t in own {
                    for c in 0..3 {
                        lo[c] = lo[c].min(t.lo[c]);
                        hi[c] = hi[c].max(t.hi[c]);
                    }
                }
                face_boxes.push(GeomWithData::new(Rectangle::from_corners(lo, hi), k as u32));
            }
            face_tris.push(RTree::bulk_load(boxes));
        }
        Self {
            frame,
            tris,
            faces: RTree::bulk_load(face_boxes),
            face_tris,
        }
    }

    pub fn local(&self, p: &Point3) -> [f64; 3] {
        let l = self.frame.to_local(p);
        [l.x, l.y, l.z]
    }

    pub fn local_vector(&self, v: &Vector3) -> [f64; 3] {
        let l = self.frame.vector_to_local(v);
        [l.x, l.y, l.z]
    }

    /// Triangles whose footprint meets the rectangle `lo..hi` and whose top
    /// is above `zmin`, each once, in index order.
    pub fn near(&self, lo: [f64; 2], hi: [f64; 2], zmin: f64) -> Vec<u32> {
        let envelope = Self::envelope(lo, hi, (zmin, f64::INFINITY));
        let mut out: Vec<u32> = self
            .faces
            .locate_in_envelope_intersecting(&envelope)
            .flat_map(|face| {
                self.face_tris[face.data as usize].locate_in_envelope_intersecting(&envelope)
            })
            .map(|t| t.data)
            .filter(|&k| self.tris[k as usize].hi[2] > zmin)
            .collect();
        out.sort_unstable();
        out
    }

    /// The faces (mesh indices) whose box meets the rectangle `lo..hi`
    /// between the heights (`zmin` exclusive, as [`Scene::near`]) and for
    /// one of whose triangles there `test` holds (each face's triangles
    /// tested until one does), each told to `f` once.
    pub fn faces_where(
        &self,
        lo: [f64; 2],
        hi: [f64; 2],
        (zmin, zmax): (f64, f64),
        mut test: impl FnMut(u32) -> bool,
        mut f: impl FnMut(u32),
    ) {
        let envelope = Self::envelope(lo, hi, (zmin, zmax));
        for face in self.faces.locate_in_envelope_intersecting(&envelope) {
            let hit = self.face_tris[face.data as usize]
                .locate_in_envelope_intersecting(&envelope)
                .any(|t| self.tris[t.data as usize].hi[2] > zmin && test(t.data));
            if hit {
                f(face.data);
            }
        }
    }

    fn envelope(lo: [f64; 2], hi: [f64; 2], (zmin, zmax): (f64, f64)) -> AABB<[f64; 3]> {
        AABB::from_corners([lo[0], lo[1], zmin], [hi[0], hi[1], zmax.min(f64::MAX)])
    }

    /// The height of triangle `k`'s highest corner.
    pub fn top(&self, k: u32) -> f64 {
        self.tris[k as usize].hi[2]
    }

    /// Heights of the corners of `tris`.
    pub fn heights<'a>(&'a self, tris: &'a [u32]) -> impl Iterator<Item = f64> + 'a {
        tris.iter()
            .flat_map(|&k| self.tris[k as usize].p.iter().map(|p| p[2]))
    }
}

/// What stops the tool along a line: the span of the line's parameter,
/// the triangle, and whether the holder (not the cutter) meets it.
#[derive(Clone, Copy, Debug)]
pub struct Block {
    pub span: Span,
    pub tri: u32,
    pub holder: bool,
}

/// The spans a triangle blocks along a line whose tip's foot stays put
/// while its height changes (a face standing along the axis): wholly above
/// the cutting length only the holder meets it, wholly within it only the
/// cutter, and either way the same span at every such height ([`blocked`]
/// for a triangle that is whole there).
#[derive(Clone, Copy, Debug, Default)]
pub struct Whole {
    pub holder: Option<Span>,
    pub cutter: Option<Span>,
}

/// [`Whole`] of each of `cands` along `q0 + s·e` (its height unused).
pub fn whole_spans(
    scene: &Scene,
    cands: &[u32],
    q0: [f64; 3],
    e: [f64; 2],
    tool: &Tool,
    touches: (f64, f64),
) -> Vec<Whole> {
    let (r, big) = (0.5 * tool.diameter, 0.5 * tool.holder_diameter);
    let q = [q0[0], q0[1]];
    cands
        .iter()
        .map(|&k| {
            let t = &scene.tris[k as usize];
            let touch = t.touch(touches);
            let farther = beside(t, q, e);
            if farther(big) {
                return Whole::default();
            }
            let xy = t.p.map(|p| [p[0], p[1]]);
            let rho = r - touch;
            Whole {
                holder: line_near_convex(q, e, &xy, big - touch),
                cutter: (!farther(rho))
                    .then(|| line_near_convex(q, e, &xy, rho))
                    .flatten(),
            }
        })
        .collect()
}

/// Whether triangle `t` lies wholly to one side of the line through `q`
/// along `e`, at least the given distance away.
fn beside(t: &Tri, q: [f64; 2], e: [f64; 2]) -> impl Fn(f64) -> bool {
    let off = t.p.map(|p| e[0] * (p[1] - q[1]) - e[1] * (p[0] - q[0]));
    let (least, most) = (
        off[0].min(off[1]).min(off[2]),
        off[0].max(off[1]).max(off[2]),
    );
    move |d: f64| least >= d || most <= -d
}

/// How a triangle meets a tool whose tip is at some height: wholly above
/// the cutting length (only the holder, on the whole triangle), wholly
/// within it (only the cutter, on the whole triangle), or cut by a level
/// ([`blocked`] clips it there; in the first two cases its clip keeps the
/// triangle whole).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Meets {
    Holder,
    Cutter,
    Clipped,
}

impl Tri {
    /// [`Meets`] at tip height `h`, `touch` this triangle's tolerance.
    pub fn meets(&self, h: f64, cutting_length: f64, touch: f64) -> Meets {
        let top = h + cutting_length;
        if self.lo[2] > top + touch {
            Meets::Holder
        } else if self.lo[2] > h + touch && self.hi[2] <= top {
            Meets::Cutter
        } else {
            Meets::Clipped
        }
    }

    /// Material within this of the tool's surface touches it: `exact` for
    /// a planar face's triangle, `tessellated` for one that only
    /// approximates its face.
    pub fn touch(&self, (exact, tessellated): (f64, f64)) -> f64 {
        if self.tessellated {
            tessellated
        } else {
            exact
        }
    }
}

/// Where a tool whose tip centre runs along `q0 + s·e` (`q0[2]` its height,
/// `e` level and unit) would cut into the triangles `cands`: the cutter
/// (radius r, from the tip up to the cutting length) or the holder above
/// it. Material within `touch` of the tool's surface only touches it, a
/// curved face's triangle within `touch_tessellated` (its chords cut
/// inside a concave blend the tool touches).
pub fn blocked(
    scene: &Scene,
    cands: &[u32],
    q0: [f64; 3],
    e: [f64; 2],
    tool: &Tool,
    (exact, touch_tessellated): (f64, f64),
    out: &mut Vec<Block>,
) {
    let h = q0[2];
    let (r, big) = (0.5 * tool.diameter, 0.5 * tool.holder_diameter);
    let top = h + tool.cutting_length;
    let q = [q0[0], q0[1]];
    for &k in cands {
        let t = &scene.tris[k as usize];
        let touch = t.touch((exact, touch_tessellated));
        if t.hi[2] <= h + touch {
            continue;
        }
        // Wholly to one side of the line, farther than the holder's radius.
        let farther = beside(t, q, e);
        if farther(big) {
            continue;
        }
        // Wholly to one side, farther than the cutter's radius: only the
        // holder can meet it.
        let rho = r - touch;
        if !farther(rho) && t.lo[2] <= top {
            let (low, n) = clip(&t.p, h + touch, top);
            if let Some(span) = line_near_convex(q, e, &low[..n], rho) {
                out.push(Block {
                    span,
                    tri: k,
                    holder: false,
                });
            }
        }
        if t.hi[2] > top + touch {
            let (high, n) = clip(&t.p, top + touch, f64::INFINITY);
            if let Some(span) = line_near_convex(q, e, &high[..n], big - touch) {
                out.push(Block {
                    span,
                    tri: k,
                    holder: true,
                });
            }
        }
    }
}

/// The faces whose triangles a tool with its tip centre at `c` would cut
/// into (as [`blocked`] tells at the line's point `c`), pushed on `stops`
/// once each with whether the holder (not the cutter) meets them: the
/// cutter's within its radius, the holder's within its own among the
/// triangles reaching above the cutting length. Each query visits a face
/// once and stops testing it at its first triangle that stops the tool.
pub fn point_stops(
    scene: &Scene,
    c: [f64; 3],
    tool: &Tool,
    touch: f64,
    stops: &mut Vec<(u32, bool)>,
) {
    let h = c[2];
    let (r, big) = (0.5 * tool.diameter, 0.5 * tool.holder_diameter);
    let top = h + tool.cutting_length;
    let q = [c[0], c[1]];
    let mut near = |rho: f64, lo: f64, hi: f64, holder: bool| {
        let (a, b) = ([q[0] - rho, q[1] - rho], [q[0] + rho, q[1] + rho]);
        scene.faces_where(
            a,
            b,
            (lo, hi),
            |k| {
                let (part, n) = clip(&scene.tris[k as usize].p, lo, hi);
                point_near_convex(q, &part[..n], rho - touch)
            },
            |face| {
                if !stops.contains(&(face, holder)) {
                    stops.push((face, holder));
                }
            },
        );
    };
    near(r, h + touch, top, false);
    near(big, top + touch, f64::INFINITY, true);
}

/// Corners a triangle cut by two levels can have.
const MOST_CORNERS: usize = 5;

/// A clipped triangle's corners, each with the edge from it to the next
/// (see [`clip_tagged`]), on the stack.
type Corners = [([f64; 3], Option<u8>); MOST_CORNERS];

/// The triangle's part with `lo < z ≤ hi`, its corners seen from above:
/// the first `n` of the array.
pub(super) fn clip(tri: &[[f64; 3]; 3], lo: f64, hi: f64) -> ([[f64; 2]; MOST_CORNERS], usize) {
    let mut out = [[0.0; 2]; MOST_CORNERS];
    if tri.iter().all(|p| p[2] > lo && p[2] <= hi) {
        for (o, p) in out.iter_mut().zip(tri) {
            *o = [p[0], p[1]];
        }
        return (out, 3);
    }
    let (corners, n) = clip_corners(tri, lo, hi);
    for (o, (p, _)) in out.iter_mut().zip(&corners[..n]) {
        *o = [p[0], p[1]];
    }
    (out, n)
}

/// The triangle's part with `lo < z ≤ hi` as a polygon, each corner with
/// the edge of the triangle that the polygon's edge from it to the next
/// corner lies on (`Some(k)`: from corner `k` to `k + 1`), or `None` where
/// that edge runs along a cut. A point where a cut crosses an edge is
/// computed from the edge's lower end (then by coordinates), so the two
/// triangles sharing an edge cut it at the same point.
pub(super) fn clip_tagged(tri: &[[f64; 3]; 3], lo: f64, hi: f64) -> Vec<([f64; 3], Option<u8>)> {
    let (corners, n) = clip_corners(tri, lo, hi);
    corners[..n].to_vec()
}

fn clip_corners(tri: &[[f64; 3]; 3], lo: f64, hi: f64) -> (Corners, usize) {
    let mut poly: Corners = [([0.0; 3], None); MOST_CORNERS];
    for k in 0..3 {
        poly[k] = (tri[k], Some(k as u8));
    }
    let mut n = 3;
    for (limit, above) in [(lo, true), (hi, false)] {
        if !limit.is_finite() {
            continue;
        }
        let inside = |p: &[f64; 3]| if above { p[2] > limit } else { p[2] <= limit };
        let mut next: Corners = [([0.0; 3], None); MOST_CORNERS];
        let mut m = 0;
        // A plane cuts a convex polygon at two points at most: one corner
        // more each time (the guard only keeps rounding from panicking).
        let mut put = |corner| {
            if m < MOST_CORNERS {
                next[m] = corner;
                m += 1;
            }
        };
        for k in 0..n {
            let ((p, tag), (q, _)) = (poly[k], poly[(k + 1) % n]);
            let (ip, iq) = (inside(&p), inside(&q));
            if ip {
                put((p, tag));
            }
            if ip != iq {
                // Leaving: the edge from the crossing runs along the cut.
                put((crossing(&p, &q, limit), if ip { None } else { tag }));
            }
        }
        (poly, n) = (next, m);
        if n == 0 {
            break;
        }
    }
    (poly, n)
}

/// Where the segment `p`–`q` crosses the level `z`, computed the same way
/// whichever end comes first.
fn crossing(p: &[f64; 3], q: &[f64; 3], z: f64) -> [f64; 3] {
    let key = |a: &[f64; 3]| (a[2], a[0], a[1]);
    let (a, b) = if key(p).partial_cmp(&key(q)) == Some(std::cmp::Ordering::Greater) {
        (q, p)
    } else {
        (p, q)
    };
    let t = (z - a[2]) / (b[2] - a[2]);
    [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, z]
}

#[cfg(test)]
mod tests {
    use super::*;
    use thinwall_brep::tessellate::FaceMesh;
    use thinwall_brep::FaceId;

    /// Random triangles in a dozen faces (some empty), queried by random
    /// boxes and height bands: `near` is every triangle a brute force
    /// finds, and `faces_where` every face with a triangle there passing
    /// the test (here: a corner within the box).
    #[test]
    fn the_hierarchy_finds_what_brute_force_does() {
        let mut next = super::super::tests::uniform(0x5eed_1234_abcd_0007);
        let mut points = Vec::new();
        let mut faces = Vec::new();
        for f in 0..12u32 {
            let mut triangles = Vec::new();
            let (cx, cy, cz) = (100.0 * next(), 100.0 * next(), 50.0 * next());
            for _ in 0..(f % 4) * 15 {
                let base = points.len() as u32;
                for _ in 0..3 {
                    points.push(Point3::new(
                        cx + 20.0 * next(),
                        cy + 20.0 * next(),
                        cz + 20.0 * next(),
                    ));
                }
                triangles.push([base, base + 1, base + 2]);
            }
            faces.push(FaceMesh {
                face: FaceId(f),
                triangles,
                issue: None,
            });
        }
        let mesh = Mesh {
            points,
            faces,
            edges: Vec::new(),
        };
        let scene = Scene::new(&mesh, Frame::world(), |_| false);
        for _ in 0..300 {
            let lo = [120.0 * next() - 10.0, 120.0 * next() - 10.0];
            let hi = [lo[0] + 30.0 * next(), lo[1] + 30.0 * next()];
            let zmin = 70.0 * next() - 5.0;
            let zmax = if next() < 0.3 {
                f64::INFINITY
            } else {
                zmin + 30.0 * next()
            };
            let meets = |t: &Tri| {
                t.hi[0] >= lo[0]
                    && t.lo[0] <= hi[0]
                    && t.hi[1] >= lo[1]
                    && t.lo[1] <= hi[1]
                    && t.hi[2] > zmin
                    && t.lo[2] <= zmax
            };
            if zmax.is_infinite() {
                let want: Vec<u32> = (0..scene.tris.len() as u32)
                    .filter(|&k| meets(&scene.tris[k as usize]))
                    .collect();
                assert_eq!(scene.near(lo, hi, zmin), want);
            }
            let inside = |k: u32| {
                scene.tris[k as usize]
                    .p
                    .iter()
                    .any(|p| p[0] >= lo[0] && p[0] <= hi[0] && p[1] >= lo[1] && p[1] <= hi[1])
            };
            let mut want_faces: Vec<u32> = (0..12)
                .filter(|&f| {
                    (0..scene.tris.len() as u32).any(|k| {
                        let t = &scene.tris[k as usize];
                        t.face == f && meets(t) && inside(k)
                    })
                })
                .collect();
            let mut got = Vec::new();
            scene.faces_where(lo, hi, (zmin, zmax), inside, |f| got.push(f));
            got.sort_unstable();
            want_faces.sort_unstable();
            assert_eq!(got, want_faces);
        }
    }
}
