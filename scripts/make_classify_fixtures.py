#!/usr/bin/env python3
"""Fixtures for the dedicated classification of volumes: a 100x80x40 blank
minus the volumes (so each fits exactly), the volumes as their own STEP
files, and the expected classification; each case also turned (part,
volumes and up together).

usage: python3 scripts/make_classify_fixtures.py [OUT_DIR]   (default fixtures/classify)
"""
import json, math, os, sys

from OCP.BRepPrimAPI import BRepPrimAPI_MakeBox, BRepPrimAPI_MakeCylinder
from OCP.BRepAlgoAPI import BRepAlgoAPI_Cut, BRepAlgoAPI_Fuse
from OCP.BRepBuilderAPI import BRepBuilderAPI_Transform
from OCP.gp import gp_Pnt, gp_Ax2, gp_Dir, gp_Trsf, gp_Vec, gp_Ax1
from OCP.STEPControl import STEPControl_Writer, STEPControl_AsIs
from OCP.Interface import Interface_Static
from OCP.IFSelect import IFSelect_RetDone
from OCP.ShapeUpgrade import ShapeUpgrade_UnifySameDomain


def box(x0, y0, z0, x1, y1, z1):
    return BRepPrimAPI_MakeBox(gp_Pnt(x0, y0, z0), x1 - x0, y1 - y0, z1 - z0).Shape()


def cyl(x, y, z0, z1, r):
    return BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, z0), gp_Dir(0, 0, 1)), r, z1 - z0).Shape()


def unify(s):
    u = ShapeUpgrade_UnifySameDomain(s, True, True, True)
    u.Build()
    return u.Shape()


def fuse(a, b):
    return unify(BRepAlgoAPI_Fuse(a, b).Shape())


def write(shape, path):
    Interface_Static.SetCVal_s("write.step.schema", "AP214IS")
    w = STEPControl_Writer()
    w.Transfer(shape, STEPControl_AsIs)
    assert w.Write(path) == IFSelect_RetDone, path


def blank_minus(volumes, extra_cut=None):
    part = box(0, 0, 0, 100, 80, 40)
    for v in (extra_cut or volumes):
        part = BRepAlgoAPI_Cut(part, v).Shape()
    return unify(part)


def cases():
    pocket = box(30, 20, 25, 70, 60, 40)
    yield "pocket", [pocket], [], [("pocket", "side_and_bottom", False)], None
    yield "passage", [box(30, 20, 0, 70, 60, 40)], [], [("passage", "side", True)], None
    yield "blind_slot", [box(0, 30, 30, 60, 50, 40)], [], [("blind_slot", "side_and_bottom", False)], None
    yield "through_slot", [box(0, 30, 30, 100, 50, 40)], [], [("through_slot", "side_and_bottom", False)], None
    yield "corner_notch", [box(70, 60, 30, 100, 80, 40)], [], [("corner_notch", "side_and_bottom", False)], None
    yield "step", [box(80, 0, 30, 100, 80, 40)], [], [("step", "side_and_bottom", False)], None
    yield "face", [box(0, 0, 35, 100, 80, 40)], [], [("face", "bottom", False)], None
    yield "hole", [cyl(50, 40, 20, 40, 6)], [], [("hole", "side_and_bottom", False)], None
    free = fuse(box(30, 20, 25, 70, 60, 40), cyl(65, 40, 25, 40, 25))
    yield "free_pocket", [free], [], [("free_pocket", "side_and_bottom", False)], None
    free_through = fuse(box(30, 20, 0, 70, 60, 40), cyl(65, 40, 0, 40, 25))
    yield "free_passage", [free_through], [], [("free_passage", "side", True)], None
    # A step at the x=100 edge whose closed side bulges into the part as an arc.
    free_edge = fuse(box(80, 0, 30, 100, 80, 40), cyl(80, 40, 30, 40, 15))
    yield "free_step", [free_edge], [], [("free_step", "side_and_bottom", False)], None
    # Upper removed before lower: the upper sees the lower (not yet removed)
    # as a closed bottom; the lower sees the upper as an open top.
    yield "stacked", [box(30, 20, 30, 70, 60, 40), box(30, 20, 20, 70, 60, 30)], [(0, 1)], \
        [("pocket", "side", False), ("pocket", "side_and_bottom", False)], None
    # Side by side, 0 before 1: 0 sees 1 as a closed side (a pocket); 1 sees
    # 0 as open (a blind slot).
    yield "facing", [box(20, 20, 30, 50, 60, 40), box(50, 20, 30, 80, 60, 40)], [(0, 1)], \
        [("pocket", "side_and_bottom", False), ("blind_slot", "side_and_bottom", False)], None
    stepped = fuse(box(30, 20, 30, 70, 60, 40), box(30, 20, 25, 50, 60, 30))
    yield "stepped_bottom", [stepped], [], [("unknown", "side_and_bottom", False)], None
    # The part has a 15 deep pocket; the volume goes 20 deep: it overlaps material.
    yield "overlap", [box(30, 20, 20, 70, 60, 40)], [], [("unknown", "side", False)], [box(30, 20, 25, 70, 60, 40)]


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "fixtures/classify"
    t = gp_Trsf()
    t.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(2, -1, 3)), math.radians(29))
    t2 = gp_Trsf()
    t2.SetTranslation(gp_Vec(-40, 70, 15))
    t2.Multiply(t)
    up = gp_Dir(0, 0, 1).Transformed(t2)
    for name, vols, before, expected, extra in cases():
        for turned in (False, True):
            d = os.path.join(out, name + ("_turned" if turned else ""))
            os.makedirs(d, exist_ok=True)
            part = blank_minus(vols, extra)
            shapes = [part] + vols
            if turned:
                shapes = [BRepBuilderAPI_Transform(s, t2, True).Shape() for s in shapes]
            write(shapes[0], os.path.join(d, "part.step"))
            for i, v in enumerate(shapes[1:]):
                write(v, os.path.join(d, f"v{i}.step"))
            doc = {
                "up": [up.X(), up.Y(), up.Z()] if turned else [0, 0, 1],
                "before": [list(b) for b in before],
                "volumes": [{"file": f"v{i}.step", "type": e[0], "product_adjacency": e[1], "bottom_open": e[2]}
                            for i, e in enumerate(expected)],
                "source": "scripts/make_classify_fixtures.py (OpenCascade 7.9)",
            }
            json.dump(doc, open(os.path.join(d, "expected.json"), "w"), indent=1)
        print(name)


if __name__ == "__main__":
    main()
