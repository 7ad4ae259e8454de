//! Reach of a floor (a planar face square to the tool axis), which the tool
//! meets with its end: a point is reached when some free position of the
//! tool's axis lies within one radius of it. The free positions are the
//! plane less every obstacle grown by the cutter's radius (material above
//! the floor within the cutting length) or the holder's (above that); the
//! reached floor is the free positions grown again by the radius (a
//! morphological opening). Disks are 128-gons with their corners on the
//! circle, one on the face's own x axis: a straight boundary square to the
//! face's axes comes out exact (others within 3·10⁻⁴ of the radius), a
//! sharp inner corner's uncut area r²(1 − π/4) 0.15 % high.

pub use super::disk::{disk, grown};
use super::obstacle::Obstacle;
use super::scene::{clip_tagged, Scene};
use super::stroke::stroked;
use super::window::Window;
use super::{xy_bounds, Ctx, Judged};
use geo::Rect;
use geo::{Area, BoundingRect, Coord, MultiPolygon};
use std::collections::BTreeMap;
use thinwall_analysis::boolean::{difference, intersection, union, union_all};
use thinwall_analysis::polygon::without_slivers;
use thinwall_analysis::PlanarFace;
use thinwall_geom::{Frame, Vector3};

/// `named`: also which obstacles stop the tool, and how much (the
/// largest-tool search needs only the fraction).
pub fn judge(ctx: &Ctx, scene: &Scene, pf: &PlanarFace, own: u32, named: bool) -> Judged {
    let axis = scene.frame.z;
    let Some(frame) = Frame::from_axis(pf.frame.origin, axis, Some(pf.frame.x)) else {
        return Judged::default();
    };
    let region = pf.polygon_in(&frame);
    let area = region.unsigned_area();
    let Some(rect) = region.bounding_rect() else {
        return Judged::default();
    };
    let r = 0.5 * ctx.tool.diameter;
    let small_disk = disk(r);
    let groups = grown_obstacles(ctx, scene, &frame, &region, own);
    let stopped = union_all(groups.iter().map(|(_, g)| g.clone()).collect());
    let margin = 1.01 * r + 1e-6;
    let frame_box = Rect::new(
        Coord {
            x: rect.min().x - margin,
            y: rect.min().y - margin,
        },
        Coord {
            x: rect.max().x + margin,
            y: rect.max().y + margin,
        },
    );
    let free = difference(&MultiPolygon::new(vec![frame_box.to_polygon()]), &stopped);
    let reached = intersection(&region, &opened(&free, &small_disk));
    // Slivers of no area along the floor's edges are nothing lost.
    let lost = without_slivers(&difference(&region, &reached), 1e-9 * area);
    let mut out = Judged {
        area,
        reached: reached.unsigned_area().min(area),
        ..Judged::default()
    };
    if named && area - out.reached > 1e-9 * area {
        out.blockers = blockers(&groups, &lost);
        out.unreachable = lost
            .iter()
            .flat_map(|p| std::iter::once(p.exterior()).chain(p.interiors()))
            .map(|ring| {
                ring.coords()
                    .map(|c| frame.to_world(&Vector3::new(c.x, c.y, 0.0)).into())
                    .collect()
            })
            .collect();
    }
    out
}

/// The material above the floor (`frame`: the floor's plane) grown by the
/// cutter's disk within the cutting length and by the holder's above it,
/// per face of the part and holder flag, in the floor's plane.
fn grown_obstacles(
    ctx: &Ctx,
    scene: &Scene,
    frame: &Frame,
    region: &MultiPolygon<f64>,
    own: u32,
) -> Vec<((u32, bool), MultiPolygon<f64>)> {
    let tool = &ctx.tool;
    let r = 0.5 * tool.diameter;
    let big = 0.5 * tool.holder_diameter;
    let corners: Vec<[f64; 3]> = region
        .iter()
        .flat_map(|p| p.exterior().coords().copied().collect::<Vec<_>>())
        .map(|c| scene.local(&frame.to_world(&Vector3::new(c.x, c.y, 0.0))))
        .collect();
    let h = corners
        .iter()
        .map(|c| c[2])
        .fold(f64::NEG_INFINITY, f64::max);
    let (lo, hi) = xy_bounds(&corners, r + big);
    let to_face = |p: [f64; 2]| -> [f64; 2] {
        let w = scene.frame.to_world(&Vector3::new(p[0], p[1], h));
        let l = frame.to_local(&w);
        [l.x, l.y]
    };
    let (small_disk, holder_disk) = (disk(r), disk(big));
    // Tessellated material touches within its own tolerance.
    let slack = ctx.touch_tessellated();
    let (small_tess, holder_tess) = (disk((r - slack).max(0.0)), disk((big - slack).max(0.0)));
    let mut obstacles: BTreeMap<(u32, bool), Obstacle> = BTreeMap::new();
    let top = h + tool.cutting_length;
    for k in scene.near(lo, hi, h + ctx.touch) {
        let t = &scene.tris[k as usize];
        if t.face == own {
            continue;
        }
        for (holder, a, b) in [
            (false, h + ctx.touch, top),
            (true, top + ctx.touch, f64::INFINITY),
        ] {
            let clipped = clip_tagged(&t.p, a, b);
            if !clipped.is_empty() {
                obstacles
                    .entry((t.face, holder))
                    .or_default()
                    .push(t, clipped, to_face);
            }
        }
    }
    // Only material within both radii of the floor stops a position the
    // floor is reached from.
    let window = Window::of(region);
    obstacles
        .into_iter()
        .filter_map(|((face, holder), mut ob)| {
            let reach = if holder { big } else { r };
            ob.retain(|corners| window.near(corners, reach + r));
            if ob.is_empty() {
                return None;
            }
            let d = match (holder, ob.tessellated) {
                (false, false) => &small_disk,
                (false, true) => &small_tess,
                (true, false) => &holder_disk,
                (true, true) => &holder_tess,
            };
            Some(((face, holder), ob.grown(d)))
        })
        .collect()
}

/// The positions `free` grown by `disk`: the points the tool's end covers
/// from them (free positions, and their outline grown).
pub fn opened(free: &MultiPolygon<f64>, disk: &[[f64; 2]]) -> MultiPolygon<f64> {
    let rings: Vec<Vec<[f64; 2]>> = free
        .iter()
        .flat_map(|poly| std::iter::once(poly.exterior()).chain(poly.interiors()))
        .map(|ring| ring.coords().map(|c| [c.x, c.y]).collect())
        .collect();
    union(free, &stroked(&rings, disk))
}

/// Which obstacles stop the tool on the `lost` floor: every one whose
/// grown shape covers some of it, with the area it covers (overlapping).
/// Naming only the obstacles that stop the tool alone does not work face
/// by face: a rib's top and its sides each cover what the others do, so
/// none gains alone.
fn blockers(
    groups: &[((u32, bool), MultiPolygon<f64>)],
    lost: &MultiPolygon<f64>,
) -> BTreeMap<(u32, bool), f64> {
    groups
        .iter()
        .map(|(key, g)| (*key, intersection(lost, g).unsigned_area()))
        .filter(|(_, a)| *a > 0.0)
        .collect()
}
