#!/usr/bin/env python3
"""Generate operations fixtures with known answers (issue 17, docs/OPERATIONS.md):

  pocket_islands.step: a block x -10..110, y -10..90, z 0..20 with a pocket
    x 0..100, y 0..80, 10 deep (floor z 10) whose vertical corners have
    3 mm radii, and two square islands 20 x 20 standing to the top at
    x 23..43 and 57..77, y 30..50: 14 mm apart.
  plain_block.step: a 60 x 40 x 20 block, its own stock: nothing to remove.
  drill_plate.step: a plate x 0..120, y 0..80, z 0..20 with a pocket
    x 10..70, y 10..70, 8 deep (floor z 12) and holes along z:
      Ø6.6 through at (40, 40) in the pocket's floor;
      Ø5 through at (90, 20) and (90, 60) from the top;
      Ø10 blind at (105, 40), 12 deep (bottom z 8, flat);
      Ø3.3 blind at (90, 40), 18 deep (bottom z 2): deeper than 4 Ø, pecked;
      Ø8 through at (20, 20) in the pocket's floor: no drill of the
      default library matches, so the end mills take it.

usage: python3 scripts/make_ops_fixtures.py [OUT_DIR]   (default fixtures/ops)
"""
import os, sys

sys.path.insert(0, os.path.dirname(__file__))
from make_recognition_fixtures import box, cut, fuse, near, write, _edge  # noqa: E402
from OCP.BRepPrimAPI import BRepPrimAPI_MakeCylinder  # noqa: E402
from OCP.gp import gp_Ax2, gp_Pnt, gp_Dir  # noqa: E402
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


def hole_z(x, y, d, z0, z1):
    """A cylinder of diameter d along z from z0 to z1."""
    ax = gp_Ax2(gp_Pnt(x, y, z0), gp_Dir(0, 0, 1))
    return BRepPrimAPI_MakeCylinder(ax, d / 2.0, z1 - z0).Shape()


def drill_plate():
    return cut(
        box(0, 0, 0, 120, 80, 20),
        box(10, 10, 12, 70, 70, 30),
        hole_z(40, 40, 6.6, -1, 13),
        hole_z(90, 20, 5.0, -1, 21),
        hole_z(90, 60, 5.0, -1, 21),
        hole_z(105, 40, 10.0, 8, 21),
        hole_z(90, 40, 3.3, 2, 21),
        hole_z(20, 20, 8.0, -1, 13),
    )


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "fixtures/ops"
    os.makedirs(out, exist_ok=True)
    block = cut(box(-10, -10, 0, 110, 90, 20), rounded_box(0, 0, 10, 100, 80, 30, 3.0))
    part = fuse(block, box(23, 30, 10, 43, 50, 20), box(57, 30, 10, 77, 50, 20))
    write(part, os.path.join(out, "pocket_islands.step"))
    write(box(0, 0, 0, 60, 40, 20), os.path.join(out, "plain_block.step"))
    write(drill_plate(), os.path.join(out, "drill_plate.step"))


if __name__ == "__main__":
    main()
