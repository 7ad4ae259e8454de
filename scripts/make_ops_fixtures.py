#!/usr/bin/env python3
"""Generate operations fixtures with known answers (issue 17, docs/OPERATIONS.md):

  pocket_islands.step: a block x -10..110, y -10..90, z 0..20 with a pocket
    x 0..100, y 0..80, 10 deep (floor z 10) whose vertical corners have
    3 mm radii, and two square islands 20 x 20 standing to the top at
    x 23..43 and 57..77, y 30..50: 14 mm apart.
  plain_block.step: a 60 x 40 x 20 block, its own stock: nothing to remove.

usage: python3 scripts/make_ops_fixtures.py [OUT_DIR]   (default fixtures/ops)
"""
import os, sys

sys.path.insert(0, os.path.dirname(__file__))
from make_recognition_fixtures import box, cut, fuse, near, write, _edge  # noqa: E402
from OCP.BRepFilletAPI import BRepFilletAPI_MakeFillet  # noqa: E402
from OCP.TopExp import TopExp_Explorer  # noqa: E402
from OCP.TopAbs import TopAbs_EDGE  # noqa: E402
from OCP.BRepAdaptor import BRepAdaptor_Curve  # noqa: E402


def rounded_box(x0, y0, z0, x1, y1, z1, r):
    """A box whose four vertical edges are rounded with radius r."""
    b = box(x0, y0, z0, x1, y1, z1)
    fil = BRepFilletAPI_MakeFillet(b)
    e = TopExp_Explorer(b, TopAbs_EDGE)
    while e.More():
        ed = _edge(e.Current())
        a = BRepAdaptor_Curve(ed)
        p0, p1 = a.Value(a.FirstParameter()), a.Value(a.LastParameter())
        if near(p0.X(), p1.X()) and near(p0.Y(), p1.Y()):
            fil.Add(r, ed)
        e.Next()
    return fil.Shape()


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "fixtures/ops"
    os.makedirs(out, exist_ok=True)
    block = cut(box(-10, -10, 0, 110, 90, 20), rounded_box(0, 0, 10, 100, 80, 30, 3.0))
    part = fuse(block, box(23, 30, 10, 43, 50, 20), box(57, 30, 10, 77, 50, 20))
    write(part, os.path.join(out, "pocket_islands.step"))
    write(box(0, 0, 0, 60, 40, 20), os.path.join(out, "plain_block.step"))


if __name__ == "__main__":
    main()
