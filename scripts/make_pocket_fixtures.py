#!/usr/bin/env python3
"""Generate pocketed panels as aerospace parts are drawn, with their truth:
a plate (a web) with rectangular pockets whose corners have a radius R
(3-12 mm) and whose floors have a fillet r (1-5 mm, r < R: the corner and
the floor fillet meet in a torus), cut from one side or from both sides of
the web, some with a lightening hole through the web in the floor. Sizes,
radii, depths and the layout are drawn from a seeded generator, so a seed
range that was never looked at measures what the recognizer does on parts
it was not tuned to.

Each part is `pockets_SEED.step` with `pockets_SEED.truth.json`: per pocket
its side (+1 cut from the top, -1 from the bottom), its box (x0, y0, z0,
x1, y1, z1, mm: the material it removes), corner radius, floor fillet,
depth and lightening hole diameter (0 for none).

usage: python3 scripts/make_pocket_fixtures.py [OUT_DIR [FIRST_SEED [COUNT]]]
       (default fixtures/pockets, seeds 1..8)
"""
import os, random, sys

sys.path.insert(0, os.path.dirname(__file__))
from make_recognition_fixtures import box, cut, write_generated, near, _edge  # noqa: E402
from OCP.BRepAdaptor import BRepAdaptor_Curve  # noqa: E402
from OCP.BRepFilletAPI import BRepFilletAPI_MakeFillet  # noqa: E402
from OCP.BRepPrimAPI import BRepPrimAPI_MakeCylinder  # noqa: E402
from OCP.TopAbs import TopAbs_EDGE  # noqa: E402
from OCP.TopExp import TopExp_Explorer  # noqa: E402
from OCP.gp import gp_Ax2, gp_Dir, gp_Pnt  # noqa: E402


def edges(shape):
    e = TopExp_Explorer(shape, TopAbs_EDGE)
    while e.More():
        yield _edge(e.Current())
        e.Next()


def ends(ed):
    a = BRepAdaptor_Curve(ed)
    return a.Value(a.FirstParameter()), a.Value(a.LastParameter())


def pocket_tool(x0, y0, x1, y1, z_floor, z_open, side, corner, fillet):
    """The material a pocket removes: a box with vertical edges rounded
    (corner) and the edges round its floor rounded (fillet); `side` +1 opens
    upwards (floor at z_floor), -1 downwards."""
    lo, hi = (z_floor, z_open + 1) if side > 0 else (z_open - 1, z_floor)
    tool = box(x0, y0, lo, x1, y1, hi)
    fil = BRepFilletAPI_MakeFillet(tool)
    for ed in edges(tool):
        p, q = ends(ed)
        if near(p.X(), q.X()) and near(p.Y(), q.Y()):
            fil.Add(corner, ed)
    tool = fil.Shape()
    if fillet > 0:
        fil = BRepFilletAPI_MakeFillet(tool)
        for ed in edges(tool):
            p, q = ends(ed)
            if near(p.Z(), z_floor) and near(q.Z(), z_floor):
                fil.Add(fillet, ed)
        tool = fil.Shape()
    return tool


def hole(x, y, z0, z1, d):
    return BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, z0), gp_Dir(0, 0, 1)), d / 2, z1 - z0).Shape()


def panel(seed):
    """A panel of nx x ny pockets from the top, and for two-sided panels the
    same grid from the bottom, divided by ribs."""
    rnd = random.Random(seed)
    nx, ny = rnd.randint(1, 3), rnd.randint(1, 2)
    both = rnd.random() < 0.5
    web = round(rnd.uniform(1.5, 4.0), 2)
    rib = round(rnd.uniform(2.0, 5.0), 2)
    frame = round(rnd.uniform(4.0, 8.0), 2)
    depth_top = round(rnd.uniform(12.0, 35.0), 2)
    depth_bottom = round(rnd.uniform(10.0, 25.0), 2) if both else 0.0
    cell_x = [round(rnd.uniform(45.0, 110.0), 2) for _ in range(nx)]
    cell_y = [round(rnd.uniform(40.0, 90.0), 2) for _ in range(ny)]
    length = 2 * frame + sum(cell_x) + rib * (nx - 1)
    width = 2 * frame + sum(cell_y) + rib * (ny - 1)
    z_web0 = depth_bottom
    z_web1 = z_web0 + web
    height = z_web1 + depth_top
    part = box(0, 0, 0, length, width, height)
    pockets = []
    y = frame
    for cy in cell_y:
        x = frame
        for cx in cell_x:
            for side in ((1, -1) if both else (1,)):
                corner = round(rnd.uniform(3.0, min(12.0, cx / 3, cy / 3)), 2)
                fillet = round(rnd.uniform(1.0, min(5.0, corner - 0.5)), 2)
                if side > 0:
                    z_floor, z_open, depth = z_web1, height, depth_top
                else:
                    z_floor, z_open, depth = z_web0, 0.0, depth_bottom
                fillet = min(fillet, round(depth / 3, 2))
                tool = pocket_tool(x, y, x + cx, y + cy, z_floor, z_open, side, corner, fillet)
                part = cut(part, tool)
                lo, hi = (z_floor, z_open) if side > 0 else (z_open, z_floor)
                pockets.append({
                    "side": side, "box": [x, y, lo, x + cx, y + cy, hi],
                    "corner_radius": corner, "floor_fillet": fillet, "depth": depth,
                    "hole": 0.0,
                })
            # A lightening hole through the web in the top pocket's floor,
            # clear of its fillets.
            room = min(cx, cy) - 2 * 5.0 - 2 * 2.0
            if rnd.random() < 0.5 and room > 10:
                d = round(rnd.uniform(10.0, min(40.0, room)), 2)
                part = cut(part, hole(x + cx / 2, y + cy / 2, -1, height + 1, d))
                for p in pockets[-(2 if both else 1):]:
                    p["hole"] = d
            x += cx + rib
        y += cy + rib
    truth = {
        "seed": seed, "size": [length, width, height], "web": web,
        "web_z": [z_web0, z_web1], "both_sides": both, "pockets": pockets,
    }
    return part, truth


def main():
    write_generated("pockets", panel, "fixtures/pockets", 8)


if __name__ == "__main__":
    main()
