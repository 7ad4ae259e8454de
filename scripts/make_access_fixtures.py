#!/usr/bin/env python3
"""Generate accessibility fixtures with known answers (docs/ACCESS.md): a
100 x 60 x 5 plate with a 10 x 10 x 5 block standing on its top at
x 40..50, y 20..30. The plate's top face (5900 mm^2: the block's foot is
not part of it) has the block's four sides as closed edges; a tool lying
on the face is shaded behind the block, by construction:
  coming towards -y (from y = 60): the strip x 40..50, y 0..20  = 200 mm^2
  towards +y: x 40..50, y 30..60 = 300; towards -x: x 0..40, y 20..30 = 400;
  towards +x: x 50..100, y 20..30 = 500.

Reach with obstruction (Ø12 tool, cutting length 36, holder Ø24; hand
values in docs/ACCESS.md):
  two_ribs.step: a 100 x 60 x 10 plate with rib A (x 20..25, to z 50) and
    rib B (x 33..38, to z 30), both the plate's length: the gap is 8 mm.
  pockets.step: a 60 x 40 x 20 block with two closed pockets 10 deep, one
    10 wide (x 10..20) and one 24 wide (x 30..54), both y 5..35.
  overhang.step: a 100 x 60 x 10 plate, a wall x 0..10 to z 50 and a shelf
    from its top x 10..40, z 40..50, over the plate's top face.

usage: python3 scripts/make_access_fixtures.py [OUT_DIR]   (default fixtures/access)
"""
import os, sys

sys.path.insert(0, os.path.dirname(__file__))
from make_recognition_fixtures import box, cut, fuse, write  # noqa: E402


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "fixtures/access"
    os.makedirs(out, exist_ok=True)
    part = fuse(box(0, 0, 0, 100, 60, 5), box(40, 20, 5, 50, 30, 10))
    write(part, os.path.join(out, "plate_with_block.step"))
    ribs = fuse(box(0, 0, 0, 100, 60, 10), box(20, 0, 10, 25, 60, 50), box(33, 0, 10, 38, 60, 30))
    write(ribs, os.path.join(out, "two_ribs.step"))
    pockets = cut(box(0, 0, 0, 60, 40, 20), box(10, 5, 10, 20, 35, 30), box(30, 5, 10, 54, 35, 30))
    write(pockets, os.path.join(out, "pockets.step"))
    shelf = fuse(box(0, 0, 0, 100, 60, 10), box(0, 0, 10, 10, 60, 50), box(10, 0, 40, 40, 60, 50))
    write(shelf, os.path.join(out, "overhang.step"))


if __name__ == "__main__":
    main()
