#!/usr/bin/env python3
"""Generate machining fixtures: a plate with a round boss standing above its
top and a rectangular pocket, the casting envelope it is machined from (the
plate and boss, pocket not yet cut), and a rectangular blank around it; the
Fokker test ribs; ribs with large holes and large cut-outs (Popma §4.1.3);
a rectangular boss with rounded corners on a plate; a pocket with an
island.

usage: python3 scripts/make_machining_fixtures.py [OUT_DIR]
       (default fixtures/machining)
"""
import os, sys

sys.path.insert(0, os.path.dirname(__file__))
from make_recognition_fixtures import box, fuse, cut, write, near, _edge  # noqa: E402
from OCP.BRepAdaptor import BRepAdaptor_Curve  # noqa: E402
from OCP.BRepFilletAPI import BRepFilletAPI_MakeFillet  # noqa: E402
from OCP.TopAbs import TopAbs_EDGE  # noqa: E402
from OCP.TopExp import TopExp_Explorer  # noqa: E402
from OCP.BRepPrimAPI import BRepPrimAPI_MakeCylinder  # noqa: E402
from OCP.gp import gp_Ax2, gp_Dir, gp_Pnt  # noqa: E402


def boss(x, y, z, d, h):
    return BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, z), gp_Dir(0, 0, 1)), d / 2, h).Shape()


def hole_y(x, z, d):
    """A cylinder Ø d across y (through a rib along x), centred at x, z."""
    return BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, -1, z), gp_Dir(0, 1, 0)), d / 2, 102).Shape()


def fillet_edges(shape, radius, keep):
    """Fillet the straight edges of `shape` whose end points `keep` accepts."""
    fil = BRepFilletAPI_MakeFillet(shape)
    e = TopExp_Explorer(shape, TopAbs_EDGE)
    while e.More():
        ed = _edge(e.Current())
        a = BRepAdaptor_Curve(ed)
        if keep(a.Value(a.FirstParameter()), a.Value(a.LastParameter())):
            fil.Add(radius, ed)
        e.Next()
    return fil.Shape()


def rounded_boss_plate():
    """A 40 x 20 boss 15 high on a 100 x 60 x 10 plate, r3 vertical
    corners (no foot fillets: where they meet the corners they make tori,
    which the removal decomposition does not take yet)."""
    boss_box = box(30, 20, 10, 70, 40, 25)
    vertical = lambda p, q: near(p.X(), q.X()) and near(p.Y(), q.Y())  # noqa: E731
    return fuse(box(0, 0, 0, 100, 60, 10), fillet_edges(boss_box, 3.0, vertical))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "fixtures/machining"
    os.makedirs(out, exist_ok=True)
    # Plate 100 x 60 x 20, a boss Ø20 standing 10 on it, a 30 x 20 pocket 8 deep.
    casting = fuse(box(0, 0, 0, 100, 60, 20), boss(30, 30, 20, 20, 10))
    part = cut(casting, box(60, 20, 12, 90, 40, 25))
    write(part, os.path.join(out, "boss_plate.step"))
    write(casting, os.path.join(out, "boss_plate_casting.step"))
    # A blank 5 mm larger on every side, 2 below and 3 above.
    write(box(-5, -5, -2, 105, 65, 33), os.path.join(out, "boss_plate_blank.step"))
    # Fokker test walls: a 120 x 1 rib, 48 and 72 high, on a 10 mm plate.
    for height in (48, 72):
        rib = fuse(box(0, 0, 0, 160, 60, 10), box(20, 29.5, 10, 140, 30.5, 10 + height))
        write(rib, os.path.join(out, f"rib_{height}_on_plate.step"))
    # Popma §4.1.3 on a 10 mm plate 200 x 100: a 1.5 x 72 rib with two large
    # holes, Ø40 and Ø24, centred 50 above its foot (step separation line
    # 70 - 2 x 12 = 46 across both), and a 1.5 x 48 rib with two cut-outs
    # 30 deep from its top (large: deeper than its h_RF of 12), leaving
    # pieces of 30, 60 and 50 mm.
    plate = box(0, 0, 0, 200, 100, 10)
    holed = box(10, 29.25, 10, 190, 30.75, 82)
    for x, d in ((60, 40), (140, 24)):
        holed = cut(holed, hole_y(x, 60, d))
    cut_rib = box(10, 69.25, 10, 190, 70.75, 58)
    for x in (40, 120):
        cut_rib = cut(cut_rib, box(x, 69, 28, x + 20, 71, 60))
    write(fuse(fuse(plate, holed), cut_rib), os.path.join(out, "ribs_with_holes_and_cutouts.step"))
    # Kept apart from the parts the planner's tests sweep: turned, its
    # rounded corners leave the removal decomposition a 0.02 mm3 column
    # (docs/PLANNING.md, known defects).
    os.makedirs(os.path.join(out, "curved_corners"), exist_ok=True)
    write(rounded_boss_plate(), os.path.join(out, "curved_corners", "rounded_boss_plate.step"))
    # A 100 x 60 x 30 block, an 80 x 40 pocket 10 deep, a 20 x 10 island
    # standing in it up to the block's top.
    island = fuse(cut(box(0, 0, 0, 100, 60, 30), box(10, 10, 20, 90, 50, 31)), box(40, 25, 20, 60, 35, 30))
    write(island, os.path.join(out, "island_pocket.step"))


if __name__ == "__main__":
    main()
