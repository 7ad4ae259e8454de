//! Reach of a curved face, judged at the middle of each of its triangles
//! (weighted by the triangle's area): the tool touches the point with its
//! end where the face is square to the axis, with the corner of its end
//! elsewhere (its axis one radius out along the level normal), and must not
//! cut into any material, the face's own included (a flat end mill cannot
//! touch the bottom of a bowl narrower than itself).

use super::scene::{blocked, Block, Scene};
use super::{Ctx, Judged, FLOOR_COS, UNDERCUT_SIN};
use thinwall_brep::tessellate::Mesh;
use thinwall_geom::Point3;

pub fn judge(ctx: &Ctx, scene: &Scene, mesh: &Mesh, own: u32) -> Judged {
    let tool = &ctx.tool;
    let r = 0.5 * tool.diameter;
    let reach = 0.5 * tool.holder_diameter;
    let mut out = Judged::default();
    let mut blocks: Vec<Block> = Vec::new();
    for t in &mesh.faces[own as usize].triangles {
        let [a, b, c] = t.map(|i| mesh.points[i as usize]);
        let n = (b - a).cross(&(c - a));
        let area = 0.5 * n.norm();
        if area <= 0.0 {
            continue;
        }
        out.area += area;
        let mid = Point3::from((a.coords + b.coords + c.coords) / 3.0);
        let p = scene.local(&mid);
        let n = scene.local_vector(&(n / (2.0 * area)));
        if n[2] < -UNDERCUT_SIN {
            out.away += area;
            out.unreachable.push(vec![a.into(), b.into(), c.into()]);
            continue;
        }
        let level = n[0].hypot(n[1]);
        let centre = if n[2] >= FLOOR_COS || level < 1e-12 {
            p
        } else {
            [p[0] + r * n[0] / level, p[1] + r * n[1] / level, p[2]]
        };
        let lo = [centre[0] - reach, centre[1] - reach];
        let hi = [centre[0] + reach, centre[1] + reach];
        let cands = scene.near(lo, hi, centre[2] + ctx.touch_curved);
        blocks.clear();
        blocked(
            scene,
            &cands,
            centre,
            [1.0, 0.0],
            tool,
            ctx.touch_curved,
            &mut blocks,
        );
        let hits: Vec<&Block> = blocks
            .iter()
            .filter(|b| b.span.0 < 0.0 && b.span.1 > 0.0)
            .collect();
        if hits.is_empty() {
            out.reached += area;
            continue;
        }
        out.unreachable.push(vec![a.into(), b.into(), c.into()]);
        let mut seen: Vec<(u32, bool)> = Vec::new();
        for h in hits {
            let key = (scene.tris[h.tri as usize].face, h.holder);
            if !seen.contains(&key) {
                seen.push(key);
                *out.blockers.entry(key).or_default() += area;
            }
        }
    }
    out
}
