#!/usr/bin/env python3
"""OpenCascade oracle for Thinwall's reader: per STEP file, the area, centroid
and surface type of every solid face and the convexity (BRepOffset_Analyse)
and midpoint of every edge shared by two faces, plus how long OpenCascade
took to read and to analyse. Faces and edges are keyed by geometry (centroid,
midpoint): OCP's Python binding does not give back STEP entity ids.

Needs `pip install cadquery-ocp-novtk==7.9.3.1.1`. Not used by the test
suite; its output (tests/oracle/*.json) is committed and read by the tests.

usage: occ_oracle.py OUT_DIR FILE...
"""
import json, os, sys, time

from OCP.STEPControl import STEPControl_Reader
from OCP.IFSelect import IFSelect_RetDone
from OCP.TopExp import TopExp_Explorer, TopExp
from OCP.TopAbs import TopAbs_FACE, TopAbs_EDGE, TopAbs_SOLID
from OCP.TopTools import TopTools_IndexedDataMapOfShapeListOfShape
from OCP.BRepGProp import BRepGProp
from OCP.GProp import GProp_GProps
from OCP.BRepOffset import BRepOffset_Analyse
from OCP.ChFiDS import ChFiDS_TypeOfConcavity
from OCP.BRep import BRep_Tool
from OCP.TopoDS import TopoDS

NAMES = {
    ChFiDS_TypeOfConcavity.ChFiDS_Concave: "concave",
    ChFiDS_TypeOfConcavity.ChFiDS_Convex: "convex",
    ChFiDS_TypeOfConcavity.ChFiDS_Tangential: "smooth",
    ChFiDS_TypeOfConcavity.ChFiDS_FreeBound: "free",
    ChFiDS_TypeOfConcavity.ChFiDS_Other: "other",
    ChFiDS_TypeOfConcavity.ChFiDS_Mixed: "mixed",
}


def surface_name(face):
    from OCP.BRepAdaptor import BRepAdaptor_Surface
    from OCP.GeomAbs import GeomAbs_SurfaceType as T
    t = BRepAdaptor_Surface(TopoDS.Face_s(face)).GetType()
    return {T.GeomAbs_Plane: "plane", T.GeomAbs_Cylinder: "cylinder", T.GeomAbs_Cone: "cone",
            T.GeomAbs_Sphere: "sphere", T.GeomAbs_Torus: "torus"}.get(t, "other")


def edge_midpoint(edge):
    from OCP.BRepAdaptor import BRepAdaptor_Curve
    c = BRepAdaptor_Curve(edge)
    p = c.Value(0.5 * (c.FirstParameter() + c.LastParameter()))
    return [p.X(), p.Y(), p.Z()]


def run(path):
    t0 = time.perf_counter()
    reader = STEPControl_Reader()
    if reader.ReadFile(path) != IFSelect_RetDone:
        return {"file": os.path.basename(path), "error": "read failed"}
    reader.TransferRoots()
    shape = reader.OneShape()
    t1 = time.perf_counter()
    # Adjacency: edge -> faces, and convexity.
    emap = TopTools_IndexedDataMapOfShapeListOfShape()
    TopExp.MapShapesAndAncestors_s(shape, TopAbs_EDGE, TopAbs_FACE, emap)
    analyse = BRepOffset_Analyse(shape, 0.01)
    t2 = time.perf_counter()
    faces = []
    exp = TopExp_Explorer(shape, TopAbs_SOLID)
    solid_faces = []
    while exp.More():
        fe = TopExp_Explorer(exp.Current(), TopAbs_FACE)
        while fe.More():
            solid_faces.append(fe.Current())
            fe.Next()
        exp.Next()
    for f in solid_faces:
        props = GProp_GProps()
        BRepGProp.SurfaceProperties_s(f, props)
        c = props.CentreOfMass()
        faces.append({"area": props.Mass(), "centroid": [c.X(), c.Y(), c.Z()],
                      "surface": surface_name(f)})
    edges = []
    for i in range(1, emap.Extent() + 1):
        e = emap.FindKey(i)
        if BRep_Tool.Degenerated_s(TopoDS.Edge_s(e)):
            continue
        kinds = set()
        for interval in analyse.Type(TopoDS.Edge_s(e)):
            kinds.add(NAMES.get(interval.Type(), "other"))
        if emap.FindFromIndex(i).Size() < 2:
            continue
        edges.append({"midpoint": edge_midpoint(TopoDS.Edge_s(e)), "convexity": sorted(kinds)})
    return {
        "file": os.path.basename(path),
        "faces": faces,
        "edges": edges,
        "seconds_read": t1 - t0,
        "seconds_adjacency": t2 - t1,
    }


def main():
    out_dir = sys.argv[1]
    os.makedirs(out_dir, exist_ok=True)
    for path in sys.argv[2:]:
        r = run(path)
        name = os.path.splitext(os.path.basename(path))[0] + ".json"
        with open(os.path.join(out_dir, name), "w") as fh:
            json.dump(r, fh, separators=(",", ":"), sort_keys=True)
        print(f"{r['file']}: {len(r.get('faces', {}))} faces, read {r.get('seconds_read', 0):.3f}s", flush=True)


if __name__ == "__main__":
    main()
