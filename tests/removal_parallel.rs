//! A removal made on threads is the one made on the calling thread: the
//! faces' pieces, the cells (each cover's cells cut apart and put back in
//! order), the blocks and the volumes, bit for bit; and a direction the
//! removal refuses is refused for the same face and reason (the first
//! failing face in the part's order, though the faces after it are left
//! unmade). Exact faces, faces taken as triangles, directions along the
//! block's axes and a degree off them, and turned copies.

mod common;

use thinwall_analysis::parallel::{Budget, Work};
use thinwall_analysis::{PartAnalysis, Setup};
use thinwall_brep::Part;
use thinwall_geom::Vector3;
use thinwall_removal::{frame_of, Removal, StockShape};

const PARTS: [&str; 6] = [
    "ops/pocket_islands.step",
    "pockets/pockets_2.step",
    "holes/holes_2.step",
    "curved/frame_r400_holes_turned.step",
    "bulges/bulges_1.step",
    "bulges/bulges_3.step",
];

fn read(name: &str) -> Part {
    let path = common::root().join("fixtures").join(name);
    thinwall_step::read_file(&path).unwrap().0
}

#[test]
fn a_removal_made_on_threads_is_the_one_made_on_one() {
    let budget = Budget::default();
    let threads = Work {
        parallel: true,
        budget: &budget,
    };
    let (mut made, mut refused, mut meshed) = (0, 0, 0);
    let tilt = 1f64.to_radians();
    for name in PARTS {
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
