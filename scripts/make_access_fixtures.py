#!/usr/bin/env python3
"""Generate accessibility fixtures with known answers (docs/ACCESS.md): a
100 x 60 x 5 plate with a 10 x 10 x 5 block standing on its top at
x 40..50, y 20..30. The plate's top face (5900 mm^2: the block's foot is
not part of it) has the block's four sides as closed edges; a tool lying
on the face is shaded behind the block, by construction:
  coming towards -y (from y = 60): the strip x 40..50, y 0..20  = 200 mm^2
  towards +y: x 40..50, y 30..60 = 300; towards -x: x 0..40, y 20..30 = 400;
  towards +x: x 50..100, y 20..30 = 500.

usage: python3 scripts/make_access_fixtures.py [OUT_DIR]   (default fixtures/access)
"""
import os, sys

sys.path.insert(0, os.path.dirname(__file__))
from make_recognition_fixtures import box, fuse, write  # noqa: E402


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "fixtures/access"
    os.makedirs(out, exist_ok=True)
    part = fuse(box(0, 0, 0, 100, 60, 5), box(40, 20, 5, 50, 30, 10))
    write(part, os.path.join(out, "plate_with_block.step"))


if __name__ == "__main__":
    main()
