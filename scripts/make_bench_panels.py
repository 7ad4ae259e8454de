#!/usr/bin/env python3
"""Rib-grid panels for the recognition benchmark: a slab with k×k pockets
cut in one boolean (web 2 mm, ribs 1.2 mm, pockets 30 mm), about 5·k² faces.
Written to OUT_DIR (default target/bench-panels), never committed.

usage: python3 scripts/make_bench_panels.py [OUT_DIR] [K ...]   (default K: 14 45)
       then five instances of the k=45 panel in one assembly (~50k faces):
       OpenCascade's boolean does not finish a 10,000-pocket cut in 30 min here.
"""
import os, sys, time
from OCP.BRepPrimAPI import BRepPrimAPI_MakeBox
from OCP.BRepAlgoAPI import BRepAlgoAPI_Cut
try:  # OpenCascade 7.x bindings
    from OCP.TopTools import TopTools_ListOfShape
except ImportError:  # 8.x moved the shape list
    from OCP.collections import List_TopoDS_Shape as TopTools_ListOfShape
from OCP.gp import gp_Pnt
from OCP.STEPControl import STEPControl_Writer, STEPControl_AsIs
from OCP.TopExp import TopExp_Explorer
from OCP.TopAbs import TopAbs_FACE


def panel(k, cell=30.0, rib=1.2, web=2.0, height=25.0):
    size = k * cell + rib
    slab = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), size, size, height).Shape()
    tools = TopTools_ListOfShape()
    for i in range(k):
        for j in range(k):
            x, y = rib + i * cell, rib + j * cell
            tools.Append(BRepPrimAPI_MakeBox(gp_Pnt(x, y, web), cell - rib, cell - rib, height).Shape())
    args = TopTools_ListOfShape()
    args.Append(slab)
    op = BRepAlgoAPI_Cut()
    op.SetArguments(args)
    op.SetTools(tools)
    op.SetRunParallel(True)
    op.Build()
    return op.Shape()


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "target/bench-panels"
    ks = [int(a) for a in sys.argv[2:]] or [14, 45]
    os.makedirs(out, exist_ok=True)
    for k in ks:
        t0 = time.time()
        s = panel(k)
        n = 0
        e = TopExp_Explorer(s, TopAbs_FACE)
        while e.More():
            n += 1
            e.Next()
        w = STEPControl_Writer()
        w.Transfer(s, STEPControl_AsIs)
        path = os.path.join(out, f"rib_grid_{n}_faces.step")
        w.Write(path)
        print(f"k={k}: {n} faces, {time.time() - t0:.1f} s -> {path}", flush=True)


def assembly_of(path, copies, out_path, spacing=1500.0):
    """`copies` placed instances of the part in `path`, side by side along x,
    written as one assembly STEP (for face counts booleans cannot reach)."""
    import math
    from OCP.STEPControl import STEPControl_Reader
    from OCP.TDocStd import TDocStd_Document
    from OCP.TCollection import TCollection_ExtendedString
    from OCP.XCAFDoc import XCAFDoc_DocumentTool
    from OCP.STEPCAFControl import STEPCAFControl_Writer
    from OCP.TopLoc import TopLoc_Location
    from OCP.gp import gp_Trsf, gp_Vec
    r = STEPControl_Reader()
    r.ReadFile(path)
    r.TransferRoots()
    shape = r.OneShape()
    doc = TDocStd_Document(TCollection_ExtendedString("XmlOcaf"))
    tool = XCAFDoc_DocumentTool.ShapeTool_s(doc.Main())
    asm = tool.NewShape()
    part = tool.AddShape(shape, False)
    for i in range(copies):
        t = gp_Trsf()
        t.SetTranslation(gp_Vec(i * spacing, 0, 0))
        tool.AddComponent(asm, part, TopLoc_Location(t))
    tool.UpdateAssemblies()
    w = STEPCAFControl_Writer()
    w.Transfer(doc, STEPControl_AsIs)
    w.Write(out_path)


if __name__ == "__main__":
    main()
    out = sys.argv[1] if len(sys.argv) > 1 else "target/bench-panels"
    big = sorted((p for p in os.listdir(out) if p.startswith("rib_grid_") and "x5" not in p),
                 key=lambda p: int(p.split("_")[2]))[-1]
    n = int(big.split("_")[2])
    assembly_of(os.path.join(out, big), 5, os.path.join(out, f"rib_grid_{5 * n}_faces_x5.step"))
    print("assembly of 5 ×", big)
