//! Removals made two ways are the same, bit for bit. A removal cut into
//! bands after one made without them (`Removal::with_bands`, what the plan
//! does after the proposal) is the removal made with the bands from the
//! start: the same cells, covers over each, bands and blocks; turned parts
//! too. It refuses a removal that has bands already and another stock. A
//! removal made on threads is the one made on the calling thread.

mod common;

use geo::{Coord, LineString, MultiPolygon, Polygon, Rect};
use thinwall_analysis::parallel::{Budget, Work};
use thinwall_analysis::{PartAnalysis, Setup};
use thinwall_brep::Part;
use thinwall_geom::Vector3;
use thinwall_removal::{frame_of, Removal, StockShape};

/// Exact faces, pockets on both sides of a web with corner radii and floor
/// fillets, holes, cylinders with holes, free-form faces taken as
/// triangles, and turned copies.
const PARTS: [&str; 7] = [
    "ops/pocket_islands.step",
    "pockets/pockets_2.step",
    "holes/holes_2.step",
    "curved/frame_r400_holes.step",
    "curved/frame_r400_holes_turned.step",
    "bulges/bulges_1.step",
    "bulges/bulges_3.step",
];

fn read(name: &str) -> Part {
    let path = common::root().join("fixtures").join(name);
    thinwall_step::read_file(&path).unwrap().0
}

fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Polygon<f64> {
    Rect::new(Coord { x: x0, y: y0 }, Coord { x: x1, y: y1 }).to_polygon()
}

/// Bands over the stock's footprint `lo`–`hi`: its left third, a strip
/// across its middle, and a disc about its centre (a 48-gon).
fn bands(lo: [f64; 3], hi: [f64; 3]) -> Vec<MultiPolygon<f64>> {
    let (w, h) = (hi[0] - lo[0], hi[1] - lo[1]);
    let c = [lo[0] + 0.5 * w, lo[1] + 0.5 * h];
    let r = 0.3 * w.min(h);
    let disc: LineString<f64> = (0..48)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / 48.0;
            (c[0] + r * t.cos(), c[1] + r * t.sin())
        })
        .collect();
    vec![
        MultiPolygon::new(vec![rect(lo[0], lo[1], lo[0] + w / 3.0, hi[1])]),
        MultiPolygon::new(vec![rect(lo[0], c[1] - 0.1 * h, hi[0], c[1] + 0.1 * h)]),
        MultiPolygon::new(vec![Polygon::new(disc, vec![])]),
    ]
}

#[test]
fn bands_cut_after_are_bands_cut_from_the_start() {
    for name in PARTS {
        let part = read(name);
        let a = PartAnalysis::new(&part, Setup::default());
        let size = a.bounding_box().diagonal();
        for up in [[0.0, 0.0, 1.0], [0.0, 0.0, -1.0], [1.0, 0.0, 0.0]] {
            let what = format!("{name} up {up:?}");
            let (frame, lo, hi) = frame_of(&a, up.into());
            let stock = StockShape::Block { lo, hi };
            let bands = bands(lo, hi);
            let Ok(plain) = Removal::new(&part, frame, &stock, &[], size, Work::serial()) else {
                // A direction the removal refuses is refused either way.
                assert!(
                    Removal::new(&part, frame, &stock, &bands, size, Work::serial()).is_err(),
                    "{what}"
                );
                continue;
            };
            let direct = Removal::new(&part, frame, &stock, &bands, size, Work::serial()).unwrap();
            let after = plain
                .with_bands(&part, &stock, &bands, Work::serial())
                .unwrap()
                .unwrap();
            assert!(
                direct.cells.len() > plain.cells.len(),
                "{what}: the bands cut"
            );
            common::assert_same_removal(&direct, &after, &what);
            // Once banded, or for another block, it starts afresh.
            assert!(
                after
                    .with_bands(&part, &stock, &bands, Work::serial())
                    .is_none(),
                "{what}"
            );
            let taller = StockShape::Block {
                lo,
                hi: [hi[0], hi[1], hi[2] + 1.0],
            };
            assert!(
                plain
                    .with_bands(&part, &taller, &bands, Work::serial())
                    .is_none(),
                "{what}"
            );
        }
    }
}

/// A removal made on threads is the one made on the calling thread: the
/// faces' pieces, the cells (each cover's cells cut apart and put back in
/// order), the columns, bit for bit; and a direction the removal refuses
/// is refused for the same face and reason (the first failing face in the
/// part's order, though the faces after it are left unmade). Along the
/// block's axes and a degree off them.
#[test]
fn a_removal_made_on_threads_is_the_one_made_on_one() {
    let budget = Budget::default();
    let threads = Work {
        parallel: true,
        budget: &budget,
    };
    let (mut made, mut refused, mut meshed) = (0, 0, 0);
    let tilt = 1f64.to_radians();
    // The turned frame is along the list; its twin as built is left out.
    for name in PARTS
        .iter()
        .filter(|n| **n != "curved/frame_r400_holes.step")
    {
        let part = read(name);
        let a = PartAnalysis::new(&part, Setup::default());
        let size = a.bounding_box().diagonal();
        for up in [
            Vector3::new(0.0, 0.0, 1.0),
            Vector3::new(0.0, 0.0, -1.0),
            Vector3::new(1.0, 0.0, 0.0),
            Vector3::new(tilt.sin(), 0.0, tilt.cos()),
            Vector3::new(0.0, tilt.sin(), -tilt.cos()),
        ] {
            let what = format!("{name} up {up:?}");
            let (frame, lo, hi) = frame_of(&a, up);
            let stock = StockShape::Block { lo, hi };
            let one = Removal::new(&part, frame, &stock, &[], size, Work::serial());
            let many = Removal::new(&part, frame, &stock, &[], size, threads);
            match (one, many) {
                (Ok(x), Ok(y)) => {
                    common::assert_same_removal(&x, &y, &what);
                    made += 1;
                    meshed += usize::from(!x.meshed.is_empty());
                }
                (Err(x), Err(y)) => {
                    assert_eq!(x.to_string(), y.to_string(), "{what}");
                    refused += 1;
                }
                (x, y) => panic!("{what}: {:?} and {:?}", x.err(), y.err()),
            }
        }
    }
    // Both kinds of face and both outcomes were tried.
    assert!(made >= 20 && meshed >= 2, "{made} made, {meshed} meshed");
    eprintln!("{made} made ({meshed} with triangles), {refused} refused");
}
