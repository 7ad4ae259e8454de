//! Reach of a curved face, judged at the middle of each of its triangles,
//! long ones in pieces ([`Samples`]; weighted by the piece's area): the
//! tool touches the point with its
//! end where the face is square to the axis, with the corner of its end
//! elsewhere (its axis one radius out along the level normal), and must not
//! cut into any material, the face's own included (a flat end mill cannot
//! touch the bottom of a bowl narrower than itself). The face's direction
//! at a triangle is the surface's outward normal at its middle, where the
//! surface has one: a sliver at a seam, its corners on the arc at
//! different heights, leans off the true direction (NIST CTC 02's Ø10.1
//! bores had two such triangles facing down, away from every tool).

use super::scene::{point_stops, Scene};
use super::{Ctx, Judged, FLOOR_COS, UNDERCUT_SIN};
use thinwall_brep::tessellate::Mesh;
use thinwall_brep::Face;
use thinwall_geom::{Point3, Vector3};

/// Where a curved face is judged: its triangles, a long one cut into
/// pieces at most `spacing` long (a sliver's slices, [`split`]), each
/// with the surface's outward
/// direction (world, unit) at its middle, where the surface has one, else
/// the piece's own. Found once per face: every axis and every tool size
/// judges the same pieces. A cylinder's triangles run the whole length of
/// the face (the strips between generator lines are flat): judged at their
/// middles only, a 143 mm blend would be judged at one point per column.
#[derive(Default)]
pub struct Samples {
    pub tris: Vec<[Point3; 3]>,
    pub normals: Vec<Vector3>,
}

/// A piece longer than this many times its width is sliced (down to the
/// spacing).
const ASPECT: f64 = 4.0;

impl Samples {
    /// Face `own` (mesh index, B-rep face `face`), pieces at most
    /// `spacing` mm long unless no longer than `ASPECT` widths.
    pub fn of(face: &Face, mesh: &Mesh, own: u32, spacing: f64) -> Self {
        let mut tris = Vec::new();
        for t in &mesh.faces[own as usize].triangles {
            split(t.map(|i| mesh.points[i as usize]), spacing, &mut tris);
        }
        let mut hint = None;
        let normals = tris
            .iter()
            .map(|[a, b, c]| {
                let mid = Point3::from((a.coords + b.coords + c.coords) / 3.0);
                face.outward_normal(&mid, &mut hint).unwrap_or_else(|| {
                    (b - a)
                        .cross(&(c - a))
                        .try_normalize(0.0)
                        .unwrap_or_else(Vector3::zeros)
                })
            })
            .collect();
        Self { tris, normals }
    }

    /// Piece `k`'s area, mm².
    pub fn area(&self, k: u32) -> f64 {
        let [a, b, c] = self.tris[k as usize];
        0.5 * (b - a).cross(&(c - a)).norm()
    }

    pub fn len(&self) -> usize {
        self.tris.len()
    }

    pub fn is_empty(&self) -> bool {
        self.tris.is_empty()
    }

    /// The pieces as outlines.
    pub fn outlines(&self, some: impl Iterator<Item = u32>) -> Vec<Vec<[f64; 3]>> {
        some.map(|k| self.tris[k as usize].iter().map(|&p| p.into()).collect())
            .collect()
    }
}

/// `t` pushed on `out`, or where its longest side is longer than
/// `spacing` and than `ASPECT` times its width (a sliver along a
/// generator), sliced parallel to its shortest side into pieces at most
/// `spacing` long: two triangles a slice, the corners' order kept (the
/// pieces face as `t` does).
fn split(t: [Point3; 3], spacing: f64, out: &mut Vec<[Point3; 3]>) {
    let side = |k: usize| (t[(k + 1) % 3] - t[k]).norm();
    let long = side(0).max(side(1)).max(side(2));
    let width = (t[1] - t[0]).cross(&(t[2] - t[0])).norm() / long.max(1e-300);
    if !(long > spacing && long > ASPECT * width) {
        out.push(t);
        return;
    }
    let k = (0..3)
        .min_by(|&x, &y| side(x).total_cmp(&side(y)))
        .unwrap_or(0);
    let (p, q, r) = (t[k], t[(k + 1) % 3], t[(k + 2) % 3]);
    let m = ((long / spacing).ceil() as usize).clamp(1, MAX_SLICES);
    let at = |a: Point3, s: f64| a + (r - a) * s;
    for i in 0..m {
        let (s0, s1) = (i as f64 / m as f64, (i + 1) as f64 / m as f64);
        let (p0, q0, p1, q1) = (at(p, s0), at(q, s0), at(p, s1), at(q, s1));
        out.push([p0, q0, q1]);
        if i + 1 < m {
            out.push([p0, q1, p1]);
        }
    }
}

/// Most slices of one triangle.
const MAX_SLICES: usize = 4096;

/// A curved face, at its [`Samples`].
pub fn judge(ctx: &Ctx, scene: &Scene, samples: &Samples) -> Judged {
    let n = samples.len() as u32;
    judge_some(ctx, scene, samples, 0..n, f64::INFINITY)
}

/// As [`judge`], at the pieces `some` of the face only (indices into
/// its samples, in the order given; `area` is theirs), stopping
/// (`cut_short`) once more than `lost_mm2` is lost. A larger tool in the
/// same proportions stops wherever a smaller one does: touching the same
/// point, its cutter's and its holder's disks hold the smaller tool's
/// (they touch at the point, and the holder grows with the cutter). So a
/// search over tool sizes judges, below a size that failed, only the
/// triangles that size left (`Judged::lost`).
pub fn judge_some(
    ctx: &Ctx,
    scene: &Scene,
    samples: &Samples,
    some: impl Iterator<Item = u32>,
    lost_mm2: f64,
) -> Judged {
    let tool = &ctx.tool;
    let r = 0.5 * tool.diameter;
    let mut out = Judged::default();
    let mut stops: Vec<(u32, bool)> = Vec::new();
    for k in some {
        thinwall_analysis::parallel::check_deadline();
        if out.area - out.reached > lost_mm2 {
            out.cut_short = true;
            return out;
        }
        let [a, b, c] = samples.tris[k as usize];
        let area = samples.area(k);
        if area <= 0.0 {
            continue;
        }
        out.area += area;
        let mid = Point3::from((a.coords + b.coords + c.coords) / 3.0);
        let p = scene.local(&mid);
        let n = scene.local_vector(&samples.normals[k as usize]);
        if n[2] < -UNDERCUT_SIN {
            out.away += area;
            out.lost.push(k);
            out.unreachable.push(vec![a.into(), b.into(), c.into()]);
            continue;
        }
        let level = n[0].hypot(n[1]);
        let centre = if n[2] >= FLOOR_COS || level < 1e-12 {
            p
        } else {
            [p[0] + r * n[0] / level, p[1] + r * n[1] / level, p[2]]
        };
        stops.clear();
        point_stops(scene, centre, tool, ctx.touch_curved, &mut stops);
        if stops.is_empty() {
            out.reached += area;
            continue;
        }
        out.unreachable.push(vec![a.into(), b.into(), c.into()]);
        out.lost.push(k);
        for key in &stops {
            *out.blockers.entry(*key).or_default() += area;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn area(t: &[Point3; 3]) -> f64 {
        0.5 * (t[1] - t[0]).cross(&(t[2] - t[0])).norm()
    }

    /// A strip between two generator lines, 100 mm long and 0.05 mm wide,
    /// comes out in 2 × 34 − 1 slices at most 3 mm long, of its area and
    /// facing its way; a short or a fat triangle stays whole.
    #[test]
    fn a_sliver_is_sliced_along_its_length() {
        let t = [
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(0.05, 0.0, 0.0),
            Point3::new(0.0, 0.0, 100.0),
        ];
        let mut out = Vec::new();
        split(t, 3.0, &mut out);
        assert_eq!(out.len(), 2 * 34 - 1);
        let normal = |t: &[Point3; 3]| (t[1] - t[0]).cross(&(t[2] - t[0]));
        let total: f64 = out.iter().map(area).sum();
        assert!((total - area(&t)).abs() < 1e-12, "{total}");
        for piece in &out {
            let long = (0..3)
                .map(|k| (piece[(k + 1) % 3] - piece[k]).norm())
                .fold(0.0, f64::max);
            assert!(long <= 3.0 + 1e-9, "{long}");
            assert!(normal(piece).dot(&normal(&t)) > 0.0);
        }
        for whole in [
            [t[0], t[1], Point3::new(0.0, 0.0, 2.0)],
            [
                t[0],
                Point3::new(40.0, 0.0, 0.0),
                Point3::new(0.0, 0.0, 30.0),
            ],
        ] {
            let mut out = Vec::new();
            split(whole, 3.0, &mut out);
            assert_eq!(out, vec![whole]);
        }
    }
}
