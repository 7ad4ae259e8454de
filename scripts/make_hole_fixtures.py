#!/usr/bin/env python3
"""Generate holes as milled parts carry them, with their truth: plain,
countersunk (82, 90 and 100 degrees), counterbored, with a chamfered or a
blended entry, chamfered at the exit, stepped (three diameters), and blind
with a drill point or a flat bottom; in a flat plate (drilled down) and in
an upright wall on a base (drilled across). Diameters and depths come from
a seeded generator.

Each part is `holes_SEED.step` with `holes_SEED.truth.json`: per hole its
entry point (the axis on the entry face), its direction (into the part),
and its stages from the entry down: `entry` (countersink or chamfer:
included angle and diameter at the face; blend: radius), `bores`
(diameter and depth each, widest first), `exit` (a chamfer at a through
hole's far end), and `tip` (`through`, `flat`, or `drill_point` with its
included angle).

usage: python3 scripts/make_hole_fixtures.py [OUT_DIR [FIRST_SEED [COUNT]]]
       (default fixtures/holes, seeds 1..4)
"""
import math, os, random, sys

sys.path.insert(0, os.path.dirname(__file__))
from make_recognition_fixtures import box, cut, fuse, write_generated, _edge  # noqa: E402
from OCP.BRepAdaptor import BRepAdaptor_Curve  # noqa: E402
from OCP.BRepAlgoAPI import BRepAlgoAPI_Fuse  # noqa: E402
from OCP.BRepBuilderAPI import BRepBuilderAPI_Transform  # noqa: E402
from OCP.BRepFilletAPI import BRepFilletAPI_MakeFillet  # noqa: E402
from OCP.BRepPrimAPI import BRepPrimAPI_MakeCone, BRepPrimAPI_MakeCylinder  # noqa: E402
from OCP.GeomAbs import GeomAbs_Circle  # noqa: E402
from OCP.TopAbs import TopAbs_EDGE  # noqa: E402
from OCP.TopExp import TopExp_Explorer  # noqa: E402
from OCP.gp import gp_Ax1, gp_Ax2, gp_Dir, gp_Pnt, gp_Trsf, gp_Vec  # noqa: E402

DOWN = gp_Dir(0, 0, -1)
KINDS = ["plain", "countersink", "counterbore", "chamfer", "blend", "chamfer_exit",
         "stepped", "drill_point", "flat_blind"]


def union(*shapes):
    s = shapes[0]
    for o in shapes[1:]:
        s = BRepAlgoAPI_Fuse(s, o).Shape()
    return s


def cyl(z_top, r, length):
    """A cylinder of radius r down the -z axis from z_top."""
    return BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, z_top), DOWN), r, length).Shape()


def cone(z_top, r_top, r_bottom, h):
    return BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(0, 0, z_top), DOWN), r_top, r_bottom, h).Shape()


def hole_tool(kind, t, rnd):
    """The material a hole removes, its axis down -z from the entry face
    z = 0 through a wall of thickness t; and its truth stages."""
    d = round(rnd.uniform(4.0, 14.0), 2)
    r, e = d / 2, 1.0  # e: the tool's overshoot beyond the faces
    through = cyl(e, r, t + 2 * e)
    stages = {"entry": None, "bores": [{"diameter": d, "depth": t}], "exit": None,
              "tip": "through"}
    if kind == "countersink":
        angle = rnd.choice([82.0, 90.0, 100.0])
        big = round(d * rnd.uniform(1.6, 2.0), 2)
        k = math.tan(math.radians(angle / 2))
        h = (big / 2 - r) / k
        tool = union(through, cone(e, big / 2 + e * k, r, h + e))
        stages["entry"] = {"kind": "countersink", "angle_deg": angle, "diameter": big}
        stages["bores"][0]["depth"] = t - h
        return tool, stages
    if kind in ("chamfer", "chamfer_exit"):
        # An edge break: radially at most 0.15 of the diameter (Thinwall
        # reads a cone wider than 0.2 of it as a countersink).
        c = round(rnd.uniform(0.05, 0.15) * d, 2)
        if kind == "chamfer":
            tool = union(through, cone(e, r + c + e, r, c + e))
            stages["entry"] = {"kind": "chamfer", "angle_deg": 90.0, "diameter": d + 2 * c}
        else:
            tool = union(through, cone(-t + c, r, r + c + e, c + e))
            stages["exit"] = {"kind": "chamfer", "angle_deg": 90.0, "diameter": d + 2 * c}
        stages["bores"][0]["depth"] = t - c
        return tool, stages
    if kind == "counterbore":
        big = round(d * rnd.uniform(1.5, 1.9), 2)
        depth = round(rnd.uniform(0.25, 0.5) * t, 2)
        tool = union(through, cyl(e, big / 2, depth + e))
        stages["bores"] = [{"diameter": big, "depth": depth}, {"diameter": d, "depth": t - depth}]
        return tool, stages
    if kind == "stepped":
        d2 = round(d * 1.35, 2)
        d3 = round(d * 1.7, 2)
        h3, h2 = round(0.25 * t, 2), round(0.25 * t, 2)
        tool = union(through, cyl(e, d2 / 2, h3 + h2 + e), cyl(e, d3 / 2, h3 + e))
        stages["bores"] = [{"diameter": d3, "depth": h3}, {"diameter": d2, "depth": h2},
                           {"diameter": d, "depth": t - h3 - h2}]
        return tool, stages
    if kind in ("drill_point", "flat_blind"):
        depth = round(rnd.uniform(0.4, 0.7) * t, 2)
        tool = cyl(e, r, depth + e)
        stages["bores"][0]["depth"] = depth
        if kind == "drill_point":
            tip = r / math.tan(math.radians(59.0))
            tool = union(tool, cone(-depth, r, 0.0, tip))
            stages["tip"] = {"drill_point": 118.0}
        else:
            stages["tip"] = "flat"
        return tool, stages
    if kind == "blend":
        stages["entry"] = {"kind": "blend", "radius": round(rnd.uniform(0.5, 1.5), 2)}
    return through, stages


def placed(shape, origin, direction):
    """`shape` built about the -z axis from the origin, moved so its axis
    enters at `origin` along `direction` (down or +y)."""
    t = gp_Trsf()
    if direction == (0.0, 1.0, 0.0):
        t.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0)), math.pi / 2)
    m = gp_Trsf()
    m.SetTranslation(gp_Vec(*origin))
    return BRepBuilderAPI_Transform(shape, m.Multiplied(t), True).Shape()


def blend_entry(part, origin, direction, d, radius):
    """Round the circular edge where a hole of diameter d enters at origin."""
    fil = BRepFilletAPI_MakeFillet(part)
    e = TopExp_Explorer(part, TopAbs_EDGE)
    while e.More():
        ed = _edge(e.Current())
        a = BRepAdaptor_Curve(ed)
        if a.GetType() == GeomAbs_Circle:
            c = a.Circle()
            p = c.Location()
            if abs(c.Radius() - d / 2) < 1e-6 and p.Distance(gp_Pnt(*origin)) < 1e-6:
                fil.Add(radius, ed)
        e.Next()
    return fil.Shape()


def part(seed):
    rnd = random.Random(seed)
    t = round(rnd.uniform(10.0, 20.0), 2)
    pitch = 34.0
    n = len(KINDS)
    upright = seed % 2 == 0
    if upright:
        # A wall t thick, drilled across (+y), standing on a base.
        length, height = pitch * (n + 1), 40.0
        body = fuse(box(0, -30, 0, length, 30 + t, 10), box(0, 0, 10, length, t, 10 + height))
        sites = [((pitch * (i + 1), 0.0, 10 + height / 2), (0.0, 1.0, 0.0)) for i in range(n)]
    else:
        length = pitch * (n + 1)
        body = box(0, 0, 0, length, 40, t)
        sites = [((pitch * (i + 1), 20.0, t), (0.0, 0.0, -1.0)) for i in range(n)]
    holes = []
    blends = []
    for kind, (origin, direction) in zip(KINDS, sites):
        tool, stages = hole_tool(kind, t, rnd)
        body = cut(body, placed(tool, origin, direction))
        if stages["entry"] and stages["entry"]["kind"] == "blend":
            blends.append((origin, direction, stages["bores"][0]["diameter"], stages["entry"]["radius"]))
            stages["bores"][0]["depth"] = t - stages["entry"]["radius"]
        holes.append({"kind": kind, "entry_point": list(origin), "direction": list(direction), **stages})
    for origin, direction, d, radius in blends:
        body = blend_entry(body, origin, direction, d, radius)
    return body, {"seed": seed, "thickness": t, "upright": upright, "holes": holes}


def main():
    write_generated("holes", part, "fixtures/holes", 4)


if __name__ == "__main__":
    main()
