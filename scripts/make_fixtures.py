#!/usr/bin/env python3
"""Generate Thinwall's STEP fixtures and their expected results.

Each fixture is built with OpenCascade (cadquery-ocp-novtk 7.9), written as
STEP, read back, and measured by OpenCascade: face count, surface kinds,
total area, bounding box, voids, bodies. The expected results go beside the
part as `<name>.expected.json`; tests read them and need no Python.

usage: python3 scripts/make_fixtures.py [OUT_DIR]   (default: fixtures/)
"""
import json, math, os, sys

from OCP.BRepPrimAPI import (BRepPrimAPI_MakeBox, BRepPrimAPI_MakeCylinder,
                             BRepPrimAPI_MakeSphere, BRepPrimAPI_MakeCone)
from OCP.BRepAlgoAPI import BRepAlgoAPI_Cut, BRepAlgoAPI_Fuse
from OCP.BRepFilletAPI import BRepFilletAPI_MakeFillet, BRepFilletAPI_MakeChamfer
from OCP.BRepBuilderAPI import BRepBuilderAPI_Transform, BRepBuilderAPI_MakeSolid
from OCP.BRep import BRep_Builder
from OCP.TopoDS import TopoDS, TopoDS_Compound
from OCP.gp import gp_Pnt, gp_Ax2, gp_Dir, gp_Trsf, gp_Vec, gp_Ax1
from OCP.TopExp import TopExp_Explorer
from OCP.TopAbs import TopAbs_FACE, TopAbs_EDGE, TopAbs_SOLID, TopAbs_SHELL
from OCP.STEPControl import STEPControl_Writer, STEPControl_Reader, STEPControl_AsIs
from OCP.Interface import Interface_Static
from OCP.IFSelect import IFSelect_RetDone
from OCP.GProp import GProp_GProps
from OCP.BRepGProp import BRepGProp
from OCP.Bnd import Bnd_Box
from OCP.BRepBndLib import BRepBndLib
from OCP.BRepAdaptor import BRepAdaptor_Surface
from OCP.GeomAbs import GeomAbs_SurfaceType as T

KINDS = {T.GeomAbs_Plane: "plane", T.GeomAbs_Cylinder: "cylinder", T.GeomAbs_Cone: "cone",
         T.GeomAbs_Sphere: "sphere", T.GeomAbs_Torus: "torus"}


def edges_of(shape):
    out = []
    e = TopExp_Explorer(shape, TopAbs_EDGE)
    while e.More():
        out.append(TopoDS.Edge_s(e.Current()))
        e.Next()
    return out


def bracket_with_pocket():
    """A 120x80x30 block: a 60x40x12 pocket from the top, a through hole,
    rounded vertical outer edges, one chamfered top edge."""
    block = BRepPrimAPI_MakeBox(120, 80, 30).Shape()
    fil = BRepFilletAPI_MakeFillet(block)
    for e in edges_of(block):
        from OCP.BRepAdaptor import BRepAdaptor_Curve
        a = BRepAdaptor_Curve(e)
        p0, p1 = a.Value(a.FirstParameter()), a.Value(a.LastParameter())
        if abs(p0.X() - p1.X()) < 1e-9 and abs(p0.Y() - p1.Y()) < 1e-9:  # vertical
            fil.Add(6.0, e)
    shape = fil.Shape()
    pocket = BRepPrimAPI_MakeBox(gp_Pnt(30, 20, 18), 60, 40, 12.0).Shape()
    shape = BRepAlgoAPI_Cut(shape, pocket).Shape()
    hole = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(15, 40, -1), gp_Dir(0, 0, 1)), 5.0, 32).Shape()
    shape = BRepAlgoAPI_Cut(shape, hole).Shape()
    cone = BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(105, 40, 22), gp_Dir(0, 0, 1)), 2.0, 10.0, 8.0001).Shape()
    shape = BRepAlgoAPI_Cut(shape, cone).Shape()
    return shape


def revolved_details():
    """A shaft end: cylinder with a spherical cap, a toroidal groove."""
    shaft = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 10.0, 40.0).Shape()
    cap = BRepPrimAPI_MakeSphere(gp_Pnt(0, 0, 40), 10.0).Shape()
    shape = BRepAlgoAPI_Fuse(shaft, cap).Shape()
    from OCP.BRepPrimAPI import BRepPrimAPI_MakeTorus
    torus = BRepPrimAPI_MakeTorus(gp_Ax2(gp_Pnt(0, 0, 20), gp_Dir(0, 0, 1)), 10.0, 2.0).Shape()
    return BRepAlgoAPI_Cut(shape, torus).Shape()


def block_with_cavity():
    """A 50 mm cube with a closed spherical cavity (BREP_WITH_VOIDS)."""
    box = BRepPrimAPI_MakeBox(50, 50, 50).Shape()
    ball = BRepPrimAPI_MakeSphere(gp_Pnt(25, 25, 25), 10.0).Shape()
    return BRepAlgoAPI_Cut(box, ball).Shape()


def turned(shape):
    """The same shape under a rigid rotation (37° about (1,2,3)) and shift."""
    t = gp_Trsf()
    t.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 2, 3)), math.radians(37))
    t2 = gp_Trsf()
    t2.SetTranslation(gp_Vec(100, -50, 25))
    t2.Multiply(t)
    return BRepBuilderAPI_Transform(shape, t2, True).Shape()


def write(shape, path, unit="MM"):
    Interface_Static.SetCVal_s("write.step.unit", unit)
    Interface_Static.SetCVal_s("write.step.schema", "AP214IS")
    w = STEPControl_Writer()
    w.Transfer(shape, STEPControl_AsIs)
    assert w.Write(path) == IFSelect_RetDone, path
    Interface_Static.SetCVal_s("write.step.unit", "MM")


def write_assembly(shape, path):
    """Two placed instances of one part in an XCAF assembly."""
    from OCP.TDocStd import TDocStd_Document
    from OCP.TCollection import TCollection_ExtendedString
    from OCP.XCAFDoc import XCAFDoc_DocumentTool
    from OCP.STEPCAFControl import STEPCAFControl_Writer
    from OCP.TopLoc import TopLoc_Location
    doc = TDocStd_Document(TCollection_ExtendedString("XmlOcaf"))
    tool = XCAFDoc_DocumentTool.ShapeTool_s(doc.Main())
    asm = tool.NewShape()
    part = tool.AddShape(shape, False)
    for dx, angle in ((0.0, 0.0), (200.0, 90.0)):
        t = gp_Trsf()
        t.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), math.radians(angle))
        t2 = gp_Trsf()
        t2.SetTranslation(gp_Vec(dx, 0, 0))
        t2.Multiply(t)
        tool.AddComponent(asm, part, TopLoc_Location(t2))
    tool.UpdateAssemblies()
    w = STEPCAFControl_Writer()
    w.Transfer(doc, STEPControl_AsIs)
    assert w.Write(path) == IFSelect_RetDone


def measure(path):
    r = STEPControl_Reader()
    assert r.ReadFile(path) == IFSelect_RetDone
    r.TransferRoots()
    shape = r.OneShape()
    kinds, area, faces, solids, shells = {}, 0.0, 0, 0, 0
    ex = TopExp_Explorer(shape, TopAbs_SOLID)
    while ex.More():
        solids += 1
        sh = TopExp_Explorer(ex.Current(), TopAbs_SHELL)
        while sh.More():
            shells += 1
            sh.Next()
        fe = TopExp_Explorer(ex.Current(), TopAbs_FACE)
        while fe.More():
            f = TopoDS.Face_s(fe.Current())
            k = KINDS.get(BRepAdaptor_Surface(f).GetType(), "other")
            kinds[k] = kinds.get(k, 0) + 1
            p = GProp_GProps()
            BRepGProp.SurfaceProperties_s(f, p)
            area += p.Mass()
            faces += 1
            fe.Next()
        ex.Next()
    box = Bnd_Box()
    BRepBndLib.AddOptimal_s(shape, box, False, False)
    xmin, ymin, zmin, xmax, ymax, zmax = box.Get()
    return {"bodies": solids, "shells": shells, "faces": faces, "face_counts": kinds,
            "total_area_mm2": area, "bbox_min": [xmin, ymin, zmin], "bbox_max": [xmax, ymax, zmax]}


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "fixtures"
    os.makedirs(out, exist_ok=True)
    bracket = bracket_with_pocket()
    parts = {
        "bracket_with_pocket": (bracket, "MM", "block with pocket, through hole, countersink cone, rounded corners"),
        "bracket_turned": (turned(bracket), "MM", "the bracket under a rigid rotation and shift"),
        "bracket_inch": (bracket, "INCH", "the bracket written in inches"),
        "revolved_details": (revolved_details(), "MM", "cylinder, spherical cap, toroidal groove"),
        "block_with_cavity": (block_with_cavity(), "MM", "cube with a closed spherical cavity"),
    }
    for name, (shape, unit, about) in parts.items():
        path = os.path.join(out, name + ".step")
        write(shape, path, unit)
        m = measure(path)
        m.update({"part": name + ".step", "about": about, "unit": unit,
                  "source": "scripts/make_fixtures.py (OpenCascade 7.9)"})
        json.dump(m, open(os.path.join(out, name + ".expected.json"), "w"), indent=1, sort_keys=True)
        print(name, m["faces"], "faces", round(m["total_area_mm2"], 3), "mm2")
    path = os.path.join(out, "bracket_assembly.step")
    write_assembly(bracket, path)
    m = measure(path)
    m.update({"part": "bracket_assembly.step", "about": "two placed instances of the bracket (second turned 90° about z, shifted 200 mm in x)",
              "unit": "MM", "source": "scripts/make_fixtures.py (OpenCascade 7.9)"})
    json.dump(m, open(os.path.join(out, "bracket_assembly.expected.json"), "w"), indent=1, sort_keys=True)
    print("bracket_assembly", m["bodies"], "bodies", m["faces"], "faces")


if __name__ == "__main__":
    main()
