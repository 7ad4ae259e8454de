#!/usr/bin/env python3
"""Check exported machining-feature volumes from outside, with OpenCascade:
each STEP file in DIR must hold valid closed solids; prints their volume.
Optionally compare with the plan's JSON: each file holds its feature's
solids, of the feature's volume (a feature with a solid that is not written
yet, over a cone, shows as a mismatch).

usage: python3 scripts/check_volumes_occ.py DIR [PLAN.json]
Needs cadquery-ocp-novtk.
"""
import glob, json, os, sys

from OCP.STEPControl import STEPControl_Reader
from OCP.IFSelect import IFSelect_RetDone
from OCP.BRepCheck import BRepCheck_Analyzer
from OCP.GProp import GProp_GProps
from OCP.BRepGProp import BRepGProp


def main():
    d = sys.argv[1]
    want = {}
    if len(sys.argv) > 2:
        plan = json.load(open(sys.argv[2]))
        want = {f["id"]: f["volume_mm3"] for f in plan["machining_features"]}
    bad = 0
    for f in sorted(glob.glob(os.path.join(d, "*.step"))):
        r = STEPControl_Reader()
        assert r.ReadFile(f) == IFSelect_RetDone, f
        r.TransferRoots()
        shape = r.OneShape()
        valid = BRepCheck_Analyzer(shape).IsValid()
        p = GProp_GProps()
        vol = getattr(BRepGProp, "VolumeProperties_s", None) or BRepGProp.VolumeProperties
        vol(shape, p)
        name = os.path.splitext(os.path.basename(f))[0]
        w = want.get(name)
        ok = valid and (w is None or abs(p.Mass() - w) <= 1e-6 * w)
        bad += not ok
        print(f"{name}: valid {valid} volume {p.Mass():.6f}" + (f" want {w:.6f}" if w else "") + ("" if ok else "  MISMATCH"))
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
