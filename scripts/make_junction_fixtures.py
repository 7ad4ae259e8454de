#!/usr/bin/env python3
"""Generate parts where round features meet, as NIST FTC 10 has them:

- `boss_and_bar`: a plate with a boss standing on it (a cylinder about z)
  and a round bar leaving the boss sideways (a cylinder about x), the bar's
  root blended into the boss. The blend is a free-form face; its edge on the
  boss turns out round the boss's axis and back (FTC 10's face #1573 and
  its edge #1483).
- `cross_holes`: a block with a bore down through it and a small cross
  hole from a side face into the bore, and a blind drilled hole (a drill
  point) that a second cross hole breaks into. The curves where the cross
  holes meet the bores lie on two cylinders at once.

Every removal of these parts must add up from each of the six axis
directions, as built and turned (`tests/removal_facets.rs` turns them).

usage: python3 scripts/make_junction_fixtures.py [OUT_DIR]
       (default fixtures/junctions)
"""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from make_recognition_fixtures import box, cut, fuse, write, _edge  # noqa: E402
from make_hole_fixtures import union  # noqa: E402
from OCP.BRepFilletAPI import BRepFilletAPI_MakeFillet  # noqa: E402
from OCP.BRepPrimAPI import BRepPrimAPI_MakeCone, BRepPrimAPI_MakeCylinder  # noqa: E402
from OCP.TopAbs import TopAbs_EDGE  # noqa: E402
from OCP.TopExp import TopExp_Explorer  # noqa: E402
from OCP.BRepAdaptor import BRepAdaptor_Curve  # noqa: E402
from OCP.GeomAbs import GeomAbs_Circle, GeomAbs_Line  # noqa: E402
from OCP.gp import gp_Ax2, gp_Dir, gp_Pnt  # noqa: E402


def cylinder(origin, direction, r, length):
    return BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(*origin), gp_Dir(*direction)), r, length).Shape()


def boss_and_bar():
    """Plate 80 x 40 x 4; boss r 8, 24 high at (20, 20); bar r 5 along +x
    from inside the boss at height 14, 40 long; the bar's root on the boss
    blended with r 1.5."""
    plate = box(0, 0, 0, 80, 40, 4)
    boss = cylinder((20, 20, 0), (0, 0, 1), 8.0, 24.0)
    bar = cylinder((20, 20, 14), (1, 0, 0), 5.0, 40.0)
    part = union(plate, boss, bar)
    blend = BRepFilletAPI_MakeFillet(part)
    explorer = TopExp_Explorer(part, TopAbs_EDGE)
    while explorer.More():
        edge = _edge(explorer.Current())
        curve = BRepAdaptor_Curve(edge)
        kind = curve.GetType()
        if kind not in (GeomAbs_Circle, GeomAbs_Line):
            # The curves where the bar meets the boss (not its end circle).
            blend.Add(1.5, edge)
        explorer.Next()
    return blend.Shape()


def cross_holes():
    """Block 60 x 30 x 30: a bore r 3.5 down through it at (15, 15); a
    cross hole r 1.25 along +y from the face y = 0 into the bore at
    height 12; a blind hole r 2.75, 18 deep with a 118 degree drill point
    down from the top at (42, 15), and a cross hole r 1 along -y from the
    face y = 30 into it at height 20."""
    block = box(0, 0, 0, 60, 30, 30)
    bore = cylinder((15, 15, -1), (0, 0, 1), 3.5, 32.0)
    cross = cylinder((15, -1, 12), (0, 1, 0), 1.25, 16.0)
    r, depth = 2.75, 18.0
    point = r / 1.6642795  # tan(59 degrees): the drill point's height
    blind = cylinder((42, 15, 30 - depth), (0, 0, 1), r, depth + 1)
    tip = BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(42, 15, 30 - depth), gp_Dir(0, 0, -1)),
                               r, 0.0, point).Shape()
    cross2 = cylinder((42, 31, 20), (0, -1, 0), 1.0, 16.0)
    return cut(block, bore, cross, fuse(blind, tip), cross2)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "fixtures/junctions"
    os.makedirs(out, exist_ok=True)
    for name, make in [("boss_and_bar", boss_and_bar), ("cross_holes", cross_holes)]:
        shape = make()
        write(shape, os.path.join(out, f"{name}.step"))


if __name__ == "__main__":
    main()
