//! Reach of a curved face, judged at the middle of each of its triangles
//! (weighted by the triangle's area): the tool touches the point with its
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

/// The outward direction (world, unit) of face `own` (mesh index, B-rep
/// face `face`) at each of its triangles: the surface's at the triangle's
/// middle, else the triangle's own. Found once per face: every axis and
/// every tool size judges the same triangles.
pub fn normals(face: &Face, mesh: &Mesh, own: u32) -> Vec<Vector3> {
    let mut hint = None;
    mesh.faces[own as usize]
        .triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|i| mesh.points[i as usize]);
            let mid = Point3::from((a.coords + b.coords + c.coords) / 3.0);
            face.outward_normal(&mid, &mut hint).unwrap_or_else(|| {
                (b - a)
                    .cross(&(c - a))
                    .try_normalize(0.0)
                    .unwrap_or_else(Vector3::zeros)
            })
        })
        .collect()
}

/// Face `own` (mesh index), its triangles' [`normals`] given.
pub fn judge(ctx: &Ctx, scene: &Scene, mesh: &Mesh, normals: &[Vector3], own: u32) -> Judged {
    let n = mesh.faces[own as usize].triangles.len() as u32;
    judge_some(ctx, scene, mesh, normals, own, 0..n, f64::INFINITY)
}

/// As [`judge`], at the triangles `some` of the face only (indices into
/// its triangles, in the order given; `area` is theirs), stopping
/// (`cut_short`) once more than `lost_mm2` is lost. A larger tool in the
/// same proportions stops wherever a smaller one does: touching the same
/// point, its cutter's and its holder's disks hold the smaller tool's
/// (they touch at the point, and the holder grows with the cutter). So a
/// search over tool sizes judges, below a size that failed, only the
/// triangles that size left (`Judged::lost`).
pub fn judge_some(
    ctx: &Ctx,
    scene: &Scene,
    mesh: &Mesh,
    normals: &[Vector3],
    own: u32,
    some: impl Iterator<Item = u32>,
    lost_mm2: f64,
) -> Judged {
    let tool = &ctx.tool;
    let r = 0.5 * tool.diameter;
    let tris = &mesh.faces[own as usize].triangles;
    let mut out = Judged::default();
    let mut stops: Vec<(u32, bool)> = Vec::new();
    for k in some {
        thinwall_analysis::parallel::check_deadline();
        if out.area - out.reached > lost_mm2 {
            out.cut_short = true;
            return out;
        }
        let [a, b, c] = tris[k as usize].map(|i| mesh.points[i as usize]);
        let n = (b - a).cross(&(c - a));
        let area = 0.5 * n.norm();
        if area <= 0.0 {
            continue;
        }
        out.area += area;
        let mid = Point3::from((a.coords + b.coords + c.coords) / 3.0);
        let p = scene.local(&mid);
        let n = scene.local_vector(&normals[k as usize]);
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
        point_stops(scene, centre, tool, ctx.touch_curved, |k, holder| {
            let key = (scene.tris[k as usize].face, holder);
            if !stops.contains(&key) {
                stops.push(key);
            }
        });
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
