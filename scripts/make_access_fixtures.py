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
  rounded_pocket.step: an 80 x 50 x 20 block with a closed pocket 40 x 30
    (x 10..50, y 10..40), 10 deep, its four upright corners rounded R5, and
    a through hole D8 at (65, 25): the largest tool that reaches the whole
    pocket is D10 (twice the corner radius), the hole's D8.

Harik & Ris's worked case rebuilt (their figures 6 and 10-13 are not in the
text we have: a semi-open planar face with three closed linear edges, so
nine proposed directions, and one obstacle over it):
  bay_with_lip.step: a block x -20..60, y -70..110, z -10..20 with a bay cut
    from z 0 up, whose floor (z 0) is the trapezoid (0,0) (60,-60/sqrt3)
    (60,40+60/sqrt3) (0,40): the back edge x = 0 is closed with both
    neighbours closed, the two side edges at -30 and +30 degrees are closed
    windows, the edge x = 60 is open (the block ends). A lip x 40..50,
    from the lower side wall to y -10, z 4..8, hangs over the floor.

usage: python3 scripts/make_access_fixtures.py [OUT_DIR]   (default fixtures/access)
"""
import math, os, sys

sys.path.insert(0, os.path.dirname(__file__))
from make_recognition_fixtures import box, cut, fuse, write  # noqa: E402
from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeFace, BRepBuilderAPI_MakePolygon  # noqa: E402
from OCP.BRepPrimAPI import BRepPrimAPI_MakePrism  # noqa: E402
from OCP.gp import gp_Ax2, gp_Dir, gp_Pnt, gp_Vec  # noqa: E402
from OCP.BRepAdaptor import BRepAdaptor_Curve  # noqa: E402
from OCP.BRepFilletAPI import BRepFilletAPI_MakeFillet  # noqa: E402
from OCP.BRepPrimAPI import BRepPrimAPI_MakeCylinder  # noqa: E402
from OCP.TopAbs import TopAbs_EDGE  # noqa: E402
from OCP.TopExp import TopExp_Explorer  # noqa: E402
from OCP.TopoDS import TopoDS  # noqa: E402


def prism_z(points, z0, z1):
    """A prism of the polygon `points` (x, y) from z0 to z1."""
    poly = BRepBuilderAPI_MakePolygon()
    for x, y in points:
        poly.Add(gp_Pnt(x, y, z0))
    poly.Close()
    face = BRepBuilderAPI_MakeFace(poly.Wire()).Face()
    return BRepPrimAPI_MakePrism(face, gp_Vec(0, 0, z1 - z0)).Shape()


def bay_with_lip():
    s = 1.0 / math.sqrt(3.0)
    bay = prism_z([(0, 0), (70, -70 * s), (70, 40 + 70 * s), (0, 40)], 0, 30)
    block = cut(box(-20, -70, -10, 60, 110, 20), bay)
    return fuse(block, box(40, -40, 4, 50, -10, 8))


def rounded_pocket():
    cutter = box(10, 10, 10, 50, 40, 30)
    fillet = BRepFilletAPI_MakeFillet(cutter)
    e = TopExp_Explorer(cutter, TopAbs_EDGE)
    while e.More():
        edge = TopoDS.Edge(e.Current())
        c = BRepAdaptor_Curve(edge)
        p, q = c.Value(c.FirstParameter()), c.Value(c.LastParameter())
        if abs(p.X() - q.X()) < 1e-9 and abs(p.Y() - q.Y()) < 1e-9:
            fillet.Add(5.0, edge)
        e.Next()
    hole = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(65, 25, -5), gp_Dir(0, 0, 1)), 4.0, 30).Shape()
    return cut(box(0, 0, 0, 80, 50, 20), fillet.Shape(), hole)


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
    write(bay_with_lip(), os.path.join(out, "bay_with_lip.step"))
    write(rounded_pocket(), os.path.join(out, "rounded_pocket.step"))


if __name__ == "__main__":
    main()
