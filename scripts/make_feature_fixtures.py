#!/usr/bin/env python3
"""Generate plates with the features a 3-axis set-up from the top does not
finish alone, as CAD users draw them, with their truth: a pocket whose
walls are drafted (1-5 degrees, corner radius R: planes and cones), a hole
through the plate tilted 35-50 degrees off the plate's normal (steep
enough that part of it lies under material from both sides), and a
spherical dimple in the top face. Sizes, angles and places come from a
seeded generator.

Each part is `features_SEED.step` with `features_SEED.truth.json`: the
plate's size, per feature its kind and measures (the tilted hole's axis
`direction`, entry point and diameter), and the part's volume as
OpenCascade computes it (`volume`, mm³: an independent check of the
removal's).

usage: python3 scripts/make_feature_fixtures.py [OUT_DIR [FIRST_SEED [COUNT]]]
       (default fixtures/features, seeds 1..3)
"""
import math, os, random, sys

sys.path.insert(0, os.path.dirname(__file__))
from make_recognition_fixtures import box, cut, write_generated, near, _edge, _face  # noqa: E402
from OCP.BRepAdaptor import BRepAdaptor_Curve  # noqa: E402
from OCP.BRepFilletAPI import BRepFilletAPI_MakeFillet  # noqa: E402
from OCP.BRepGProp import BRepGProp  # noqa: E402
from OCP.BRepOffsetAPI import BRepOffsetAPI_DraftAngle  # noqa: E402
from OCP.BRepPrimAPI import BRepPrimAPI_MakeCylinder, BRepPrimAPI_MakeSphere  # noqa: E402
from OCP.GProp import GProp_GProps  # noqa: E402
from OCP.TopAbs import TopAbs_EDGE, TopAbs_FACE  # noqa: E402
from OCP.TopExp import TopExp_Explorer  # noqa: E402
from OCP.BRepAdaptor import BRepAdaptor_Surface  # noqa: E402
from OCP.GeomAbs import GeomAbs_SurfaceType as T  # noqa: E402
from OCP.gp import gp_Ax2, gp_Dir, gp_Pln, gp_Pnt  # noqa: E402

UP = gp_Dir(0, 0, 1)


def edges(shape):
    e = TopExp_Explorer(shape, TopAbs_EDGE)
    while e.More():
        yield _edge(e.Current())
        e.Next()


def faces(shape):
    e = TopExp_Explorer(shape, TopAbs_FACE)
    while e.More():
        yield _face(e.Current())
        e.Next()


def drafted_pocket_tool(x0, y0, x1, y1, z_floor, z_top, corner, draft_deg):
    """The material a drafted pocket removes: a box from the floor up past
    the top, its vertical edges rounded by `corner`, its side faces drafted
    so the pocket widens upwards (neutral plane the floor)."""
    tool = box(x0, y0, z_floor, x1, y1, z_top + 1.0)
    fil = BRepFilletAPI_MakeFillet(tool)
    for ed in edges(tool):
        a = BRepAdaptor_Curve(ed)
        p, q = a.Value(a.FirstParameter()), a.Value(a.LastParameter())
        if near(p.X(), q.X()) and near(p.Y(), q.Y()):
            fil.Add(corner, ed)
    tool = fil.Shape()
    draft = BRepOffsetAPI_DraftAngle(tool)
    neutral = gp_Pln(gp_Pnt(0, 0, z_floor), UP)
    for f in faces(tool):
        s = BRepAdaptor_Surface(f)
        if s.GetType() == T.GeomAbs_Plane and abs(s.Plane().Axis().Direction().Z()) > 0.5:
            continue  # floor and top
        # Widening upwards: the tool's sides lean out.
        draft.Add(f, UP, -math.radians(draft_deg), neutral)
        if not draft.AddDone():
            raise RuntimeError("draft refused a face")
    draft.Build()
    return draft.Shape()


def volume(shape):
    props = GProp_GProps()
    BRepGProp.VolumeProperties_s(shape, props)
    return props.Mass()


def part(seed):
    rnd = random.Random(seed)
    length = round(rnd.uniform(140.0, 190.0), 2)
    width = round(rnd.uniform(70.0, 100.0), 2)
    t = round(rnd.uniform(14.0, 20.0), 2)
    body = box(0, 0, 0, length, width, t)
    features = []

    # A drafted pocket in the left third.
    depth = round(rnd.uniform(0.4 * t, 0.7 * t), 2)
    corner = round(rnd.uniform(4.0, 8.0), 2)
    draft = round(rnd.uniform(1.0, 5.0), 2)
    px0, py0 = round(rnd.uniform(8.0, 14.0), 2), round(rnd.uniform(8.0, 14.0), 2)
    px1 = round(length / 3 - rnd.uniform(4.0, 8.0), 2)
    py1 = round(width - rnd.uniform(8.0, 14.0), 2)
    body = cut(body, drafted_pocket_tool(px0, py0, px1, py1, t - depth, t, corner, draft))
    features.append({"kind": "drafted_pocket", "floor_box": [px0, py0, t - depth, px1, py1, t],
                     "corner_radius": corner, "draft_deg": draft, "depth": depth})

    # A hole through the plate, tilted about y, in the middle third.
    d = round(rnd.uniform(5.0, 8.0), 2)
    tilt = round(rnd.uniform(35.0, 50.0), 2)
    sign = rnd.choice([-1.0, 1.0])
    a = math.radians(tilt)
    direction = (sign * math.sin(a), 0.0, -math.cos(a))
    cx, cy = round(length / 2, 2), round(rnd.uniform(0.35 * width, 0.65 * width), 2)
    # The axis passes through (cx, cy, t/2); the cylinder runs well past
    # both faces.
    span = 2.0 * t / math.cos(a)
    start = gp_Pnt(cx - direction[0] * span / 2, cy, t / 2 - direction[2] * span / 2)
    hole = BRepPrimAPI_MakeCylinder(gp_Ax2(start, gp_Dir(*direction)), d / 2, span).Shape()
    body = cut(body, hole)
    entry = [cx - direction[0] * (t / 2) / math.cos(a), cy, t]
    features.append({"kind": "tilted_hole", "direction": list(direction), "tilt_deg": tilt,
                     "diameter": d, "entry_point": entry})

    # A spherical dimple in the right third: a cap of depth h.
    rs = round(rnd.uniform(10.0, 20.0), 2)
    h = round(rnd.uniform(2.0, min(6.0, t - 4.0)), 2)
    foot = math.sqrt(rs * rs - (rs - h) ** 2)
    c = (round(rnd.uniform(2 * length / 3 + foot + 3, length - foot - 4), 2),
         round(rnd.uniform(foot + 4, width - foot - 4), 2), t + rs - h)
    body = cut(body, BRepPrimAPI_MakeSphere(gp_Pnt(*c), rs).Shape())
    features.append({"kind": "dimple", "centre": list(c), "radius": rs, "depth": h})

    truth = {"seed": seed, "length": length, "width": width, "thickness": t,
             "features": features, "volume": volume(body)}
    return body, truth


def main():
    write_generated("features", part, "fixtures/features", 3)


if __name__ == "__main__":
    main()
