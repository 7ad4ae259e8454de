#!/usr/bin/env python3
"""Generate recognition fixtures: thin-walled parts built with OpenCascade,
each with the stiffness features it must yield.

Expected features name their faces by centroid (mm) so they survive any
STEP id numbering; tests map centroids to the faces Thinwall reads.

usage: python3 scripts/make_recognition_fixtures.py [OUT_DIR [CASE ...]]
       (default fixtures/recognition, every case; naming cases regenerates only those)
"""
import json, math, os, sys

from OCP.BRepPrimAPI import BRepPrimAPI_MakeBox, BRepPrimAPI_MakeCylinder, BRepPrimAPI_MakePrism
from OCP.BRepAlgoAPI import BRepAlgoAPI_Cut, BRepAlgoAPI_Fuse
from OCP.BRepFilletAPI import BRepFilletAPI_MakeFillet, BRepFilletAPI_MakeChamfer
from OCP.BRepBuilderAPI import (BRepBuilderAPI_Transform, BRepBuilderAPI_MakePolygon,
                                BRepBuilderAPI_MakeFace)
from OCP.gp import gp_Pnt, gp_Ax2, gp_Dir, gp_Trsf, gp_Vec, gp_Ax1
from OCP.TopExp import TopExp_Explorer
from OCP.TopAbs import TopAbs_FACE, TopAbs_EDGE
from OCP.TopoDS import TopoDS
from OCP.STEPControl import STEPControl_Writer, STEPControl_AsIs
from OCP.Interface import Interface_Static
from OCP.IFSelect import IFSelect_RetDone
from OCP.GProp import GProp_GProps
from OCP.BRepGProp import BRepGProp
from OCP.BRepAdaptor import BRepAdaptor_Surface, BRepAdaptor_Curve
from OCP.GeomAbs import GeomAbs_SurfaceType as T
from OCP.ShapeUpgrade import ShapeUpgrade_UnifySameDomain

# OpenCascade 7.x's bindings name static methods with `_s`; 8.x does not.
_face = getattr(TopoDS, "Face_s", None) or TopoDS.Face
_edge = getattr(TopoDS, "Edge_s", None) or TopoDS.Edge


def occ_version():
    try:
        import importlib.metadata as md
        return md.version("cadquery-ocp-novtk").rsplit(".", 2)[0]
    except Exception:
        return "7.9"


def box(x0, y0, z0, x1, y1, z1):
    return BRepPrimAPI_MakeBox(gp_Pnt(x0, y0, z0), x1 - x0, y1 - y0, z1 - z0).Shape()


def fuse(*shapes):
    s = shapes[0]
    for o in shapes[1:]:
        s = BRepAlgoAPI_Fuse(s, o).Shape()
    u = ShapeUpgrade_UnifySameDomain(s, True, True, True)
    u.Build()
    return u.Shape()


def cut(a, *tools):
    for t in tools:
        a = BRepAlgoAPI_Cut(a, t).Shape()
    u = ShapeUpgrade_UnifySameDomain(a, True, True, True)
    u.Build()
    return u.Shape()


def hole_y(x, z, d, y0=-50, length=200):
    """A cylinder along +y through (x, y0, z)."""
    return BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y0, z), gp_Dir(0, 1, 0)), d / 2, length).Shape()


def faces(shape):
    out = []
    e = TopExp_Explorer(shape, TopAbs_FACE)
    while e.More():
        f = _face(e.Current())
        p = GProp_GProps()
        BRepGProp.SurfaceProperties_s(f, p)
        c = p.CentreOfMass()
        a = BRepAdaptor_Surface(f)
        kind = {T.GeomAbs_Plane: "plane", T.GeomAbs_Cylinder: "cylinder"}.get(a.GetType(), "other")
        n = None
        if kind == "plane":
            d = a.Plane().Axis().Direction()
            n = [d.X(), d.Y(), d.Z()]
            if f.Orientation() == 1:  # reversed
                n = [-v for v in n]
        out.append({"centroid": [c.X(), c.Y(), c.Z()], "kind": kind, "normal": n, "area": p.Mass()})
        e.Next()
    return out


def pick(fs, pred):
    got = [f["centroid"] for f in fs if pred(f)]
    assert got, "predicate selected no face"
    return got


def near(a, b, tol=1e-6):
    return abs(a - b) < tol


def n_is(f, v):
    """The face is planar with outward normal `v`."""
    return f["normal"] is not None and all(near(a, b, 1e-6) for a, b in zip(f["normal"], v))


def write(shape, path):
    Interface_Static.SetCVal_s("write.step.schema", "AP214IS")
    w = STEPControl_Writer()
    w.Transfer(shape, STEPControl_AsIs)
    assert w.Write(path) == IFSelect_RetDone


def write_generated(stem, make, default_out, default_count):
    """A generator's command line `[OUT [FIRST [COUNT]]]`: for each seed,
    `make(seed)` -> (shape, truth) written as OUT/STEM_SEED.step and
    OUT/STEM_SEED.truth.json."""
    out = sys.argv[1] if len(sys.argv) > 1 else default_out
    first = int(sys.argv[2]) if len(sys.argv) > 2 else 1
    count = int(sys.argv[3]) if len(sys.argv) > 3 else default_count
    os.makedirs(out, exist_ok=True)
    for seed in range(first, first + count):
        shape, truth = make(seed)
        write(shape, os.path.join(out, f"{stem}_{seed}.step"))
        with open(os.path.join(out, f"{stem}_{seed}.truth.json"), "w") as f:
            json.dump(truth, f, indent=1)
            f.write("\n")


def wall(kind, side_pred, thin=True, thickness=None, fs=None, name=None):
    return {"kind": kind, "thin": thin, "thickness": thickness, "side_faces_at": pick(fs, side_pred), "name": name}


def other(kind, pred, fs, wall_name, **extra):
    d = {"kind": kind, "faces_at": pick(fs, pred), "wall": wall_name}
    d.update(extra)
    return d


def rib_grid_panel(with_y_rib=True):
    """Web 200x150x2, four 1.5 mm flanges 30 high, two ribs along x and one
    along y (1.2 mm, 25 high) crossing, three Ø19 holes (large: over
    18 mm high) in the first x rib and two cut-outs (10 wide, 8 deep) in
    the y=0 flange. Without the y rib: the part a regression check must
    tell apart (make_check_fixtures.py)."""
    L, W, t, H = 200.0, 150.0, 2.0, 30.0
    parts = [box(0, 0, 0, L, W, t),
             box(0, 0, t, L, 1.5, H), box(0, W - 1.5, t, L, W, H),
             box(0, 1.5, t, 1.5, W - 1.5, H), box(L - 1.5, 1.5, t, L, W - 1.5, H),
             box(1.5, 49.4, t, L - 1.5, 50.6, 25), box(1.5, 99.4, t, L - 1.5, 100.6, 25)]
    if with_y_rib:
        parts.append(box(99.4, 1.5, t, 100.6, W - 1.5, 25))
    s = fuse(*parts)
    s = cut(s, hole_y(30, 14, 19.0, 45, 10), hole_y(70, 14, 19.0, 45, 10), hole_y(150, 14, 19.0, 45, 10),
            box(40, -1, 22, 50, 3, H + 1), box(140, -1, 22, 150, 3, H + 1))
    return s


def rib_grid_expected(fs):
    L, W, t, H = 200.0, 150.0, 2.0, 30.0
    def c(f, i):
        return f["centroid"][i]
    e = [
        wall("web", lambda f: (n_is(f, [0, 0, -1]) and near(c(f, 2), 0)) or (n_is(f, [0, 0, 1]) and near(c(f, 2), t)), thickness=2.0, fs=fs, name="W"),
        wall("flange", lambda f: (n_is(f, [0, -1, 0]) and near(c(f, 1), 0)) or (n_is(f, [0, 1, 0]) and near(c(f, 1), 1.5)), thickness=1.5, fs=fs, name="F_y0"),
        wall("flange", lambda f: (n_is(f, [0, 1, 0]) and near(c(f, 1), W)) or (n_is(f, [0, -1, 0]) and near(c(f, 1), W - 1.5)), thickness=1.5, fs=fs, name="F_yW"),
        wall("flange", lambda f: (n_is(f, [-1, 0, 0]) and near(c(f, 0), 0)) or (n_is(f, [1, 0, 0]) and near(c(f, 0), 1.5)), thickness=1.5, fs=fs, name="F_x0"),
        wall("flange", lambda f: (n_is(f, [1, 0, 0]) and near(c(f, 0), L)) or (n_is(f, [-1, 0, 0]) and near(c(f, 0), L - 1.5)), thickness=1.5, fs=fs, name="F_xL"),
        wall("rib", lambda f: (n_is(f, [0, -1, 0]) and near(c(f, 1), 49.4)) or (n_is(f, [0, 1, 0]) and near(c(f, 1), 50.6)), thickness=1.2, fs=fs, name="RX1"),
        wall("rib", lambda f: (n_is(f, [0, -1, 0]) and near(c(f, 1), 99.4)) or (n_is(f, [0, 1, 0]) and near(c(f, 1), 100.6)), thickness=1.2, fs=fs, name="RX2"),
        wall("rib", lambda f: (n_is(f, [-1, 0, 0]) and near(c(f, 0), 99.4)) or (n_is(f, [1, 0, 0]) and near(c(f, 0), 100.6)), thickness=1.2, fs=fs, name="RY"),
    ]
    for x in (30, 70, 150):
        e.append(other("hole", lambda f, x=x: f["kind"] == "cylinder" and near(c(f, 0), x, 1e-3), fs, "RX1", large=True))
    for x0 in (40, 140):
        e.append(other("cutout", lambda f, x0=x0: c(f, 1) < 1.5 + 1e-9 and x0 - 1e-6 <= c(f, 0) <= x0 + 10 + 1e-6 and c(f, 2) > 21.9
                       and f["kind"] == "plane" and not n_is(f, [0, -1, 0]) and not n_is(f, [0, 1, 0]) and not near(c(f, 2), H), fs, "F_y0"))
    return e


def filleted_chamfered_rib():
    """A 120x40x20 block with a 3 mm rib 50 high on it, r2 foot fillets,
    and a 1 mm chamfer on one top edge of the rib."""
    s = fuse(box(0, 0, 0, 120, 40, 20), box(10, 18.5, 20, 110, 21.5, 70))
    fil = BRepFilletAPI_MakeFillet(s)
    ch = None
    e = TopExp_Explorer(s, TopAbs_EDGE)
    while e.More():
        ed = _edge(e.Current())
        a = BRepAdaptor_Curve(ed)
        p0, p1 = a.Value(a.FirstParameter()), a.Value(a.LastParameter())
        if near(p0.Z(), 20) and near(p1.Z(), 20) and near(p0.Y(), p1.Y()) and (near(p0.Y(), 18.5) or near(p0.Y(), 21.5)):
            fil.Add(2.0, ed)
        e.Next()
    s = fil.Shape()
    cm = BRepFilletAPI_MakeChamfer(s)
    e = TopExp_Explorer(s, TopAbs_EDGE)
    while e.More():
        ed = _edge(e.Current())
        a = BRepAdaptor_Curve(ed)
        p0, p1 = a.Value(a.FirstParameter()), a.Value(a.LastParameter())
        if near(p0.Z(), 70) and near(p1.Z(), 70) and near(p0.Y(), 21.5) and near(p1.Y(), 21.5):
            cm.Add(1.0, ed)
        e.Next()
    return cm.Shape()


def filleted_expected(fs):
    return [
        wall("rib", lambda f: (n_is(f, [0, -1, 0]) and near(f["centroid"][1], 18.5)) or (n_is(f, [0, 1, 0]) and near(f["centroid"][1], 21.5)), thickness=3.0, fs=fs, name="R"),
        other("fillet", lambda f: f["kind"] == "cylinder" and f["centroid"][1] < 20, fs, "R"),
        other("fillet", lambda f: f["kind"] == "cylinder" and f["centroid"][1] > 20, fs, "R"),
        other("chamfer", lambda f: f["kind"] == "plane" and f["normal"] is not None and abs(f["normal"][1]) > 0.5 and abs(f["normal"][2]) > 0.5, fs, "R"),
    ]


def notched_rib():
    """A 3 mm rib 40 high on a block, its top end notched (15 long, 12 deep)."""
    s = fuse(box(0, 0, 0, 120, 40, 20), box(10, 18.5, 20, 110, 21.5, 60))
    return cut(s, box(95, 10, 48, 111, 30, 61))


def notched_expected(fs):
    c = lambda f, i: f["centroid"][i]
    return [
        wall("rib", lambda f: (n_is(f, [0, -1, 0]) and near(c(f, 1), 18.5)) or (n_is(f, [0, 1, 0]) and near(c(f, 1), 21.5)), thickness=3.0, fs=fs, name="R"),
        other("notch", lambda f: (n_is(f, [1, 0, 0]) and near(c(f, 0), 95)) or (n_is(f, [0, 0, 1]) and near(c(f, 2), 48)), fs, "R"),
    ]


def sloped_rib():
    """A 3 mm rib leaning 12° from vertical, 40 high, on a 20 mm block."""
    pts = [(10.0, 20.0), (13.0, 20.0), (13.0 + 40 * math.tan(math.radians(12)), 60.0), (10.0 + 40 * math.tan(math.radians(12)), 60.0)]
    poly = BRepBuilderAPI_MakePolygon()
    for x, z in pts:
        poly.Add(gp_Pnt(x, 0, z))
    poly.Close()
    face = BRepBuilderAPI_MakeFace(poly.Wire()).Face()
    rib = BRepPrimAPI_MakePrism(face, gp_Vec(0, 100, 0)).Shape()
    return fuse(box(0, 0, 0, 40, 100, 20), rib)


def sloped_expected(fs):
    s = math.sin(math.radians(12))
    return [wall("rib", lambda f: f["normal"] is not None and abs(abs(f["normal"][0]) - math.cos(math.radians(12))) < 1e-6
                 and abs(abs(f["normal"][2]) - s) < 1e-6, thickness=3.0 * math.cos(math.radians(12)), fs=fs, name="R")]


def thick_wall():
    """A 20 mm wall 70 high on a 20 mm block: not thin. (It was 40 high
    until issue 11: a slab under 3 t high is a block, not a wall.)"""
    return fuse(box(0, 0, 0, 100, 60, 20), box(0, 20, 20, 100, 40, 90))


def thick_expected(fs):
    return [wall("rib", lambda f: (n_is(f, [0, -1, 0]) and near(f["centroid"][1], 20)) or (n_is(f, [0, 1, 0]) and near(f["centroid"][1], 40)),
                 thin=False, thickness=20.0, fs=fs, name="R")]


def pocketed_rib():
    """An 8 mm rib 60 high on a block, with a blind pocket (30 x 4, 3 deep)
    in one side and a rectangular window (20 x 15) through it."""
    s = fuse(box(0, 0, 0, 200, 60, 20), box(0, 26, 20, 200, 34, 80))
    return cut(s, box(40, 31, 40, 70, 35, 44), box(120, 20, 40, 140, 40, 55))


def pocketed_expected(fs):
    c = lambda f, i: f["centroid"][i]
    inside = lambda f, x0, x1, y0, y1, z0, z1: x0 - 1e-6 <= c(f, 0) <= x1 + 1e-6 and y0 - 1e-6 <= c(f, 1) <= y1 + 1e-6 and z0 - 1e-6 <= c(f, 2) <= z1 + 1e-6
    return [
        wall("rib", lambda f: (n_is(f, [0, -1, 0]) and near(c(f, 1), 26)) or (n_is(f, [0, 1, 0]) and near(c(f, 1), 34)), thickness=8.0, fs=fs, name="R"),
        other("pocket", lambda f: inside(f, 40, 70, 31, 34, 40, 44), fs, "R"),
        other("cutout", lambda f: inside(f, 120, 140, 26, 34, 40, 55), fs, "R"),
    ]


def drafted_prism(y0, foot, top, z0, height, length=200.0):
    """A wall along x whose cross-section tapers symmetrically from `foot`
    (at z0) to `top` (at z0 + height), centred on y0."""
    pts = [(y0 - foot / 2, z0), (y0 + foot / 2, z0), (y0 + top / 2, z0 + height), (y0 - top / 2, z0 + height)]
    poly = BRepBuilderAPI_MakePolygon()
    for y, z in pts:
        poly.Add(gp_Pnt(0, y, z))
    poly.Close()
    face = BRepBuilderAPI_MakeFace(poly.Wire()).Face()
    return BRepPrimAPI_MakePrism(face, gp_Vec(length, 0, 0)).Shape()


DRAFT_H = 30.0


def drafted_panel(deg):
    """A 3 mm web with a drafted rib (4 mm foot) in the middle and a drafted
    flange (3.5 mm foot) on its y = 0 edge, both 30 high, each side leaning
    `deg` towards the other."""
    taper = 2 * DRAFT_H * math.tan(math.radians(deg))
    return fuse(box(0, 0, 0, 200, 100, 3),
                drafted_prism(50, 4.0, 4.0 - taper, 3, DRAFT_H),
                drafted_prism(1.75, 3.5, 3.5 - taper, 3, DRAFT_H))


def thin_top_panel(deg, top=0.9):
    """A 3 mm web with a drafted rib in the middle and a drafted flange on
    its y = 0 edge, both 30 high, each side leaning `deg` towards the other
    down to a `top` mm thin top edge (the foot as thick as the draft
    makes it: 3 mm at 2°, 6.15 mm at 5°)."""
    taper = 2 * DRAFT_H * math.tan(math.radians(deg))
    foot = top + taper
    return fuse(box(0, 0, 0, 200, 100, 3),
                drafted_prism(50, foot, top, 3, DRAFT_H),
                drafted_prism(foot / 2, foot, top, 3, DRAFT_H))


def thin_top_expected(deg, top=0.9):
    def expect(fs):
        c = lambda f, i: f["centroid"][i]
        side = lambda f: f["normal"] is not None and abs(f["normal"][1]) > 0.9 and c(f, 2) > 3 + 1e-6
        return [
            wall("web", lambda f: (n_is(f, [0, 0, -1]) and near(c(f, 2), 0)) or (n_is(f, [0, 0, 1]) and near(c(f, 2), 3)), thickness=3.0, fs=fs, name="W"),
            wall("rib", lambda f: side(f) and 40 < c(f, 1) < 60, thickness=top, fs=fs, name="R"),
            wall("flange", lambda f: side(f) and c(f, 1) < 10, thickness=top, fs=fs, name="F"),
        ]
    return expect


def drafted_expected(deg):
    taper = 2 * DRAFT_H * math.tan(math.radians(deg))

    def expect(fs):
        c = lambda f, i: f["centroid"][i]
        side = lambda f: f["normal"] is not None and abs(f["normal"][1]) > 0.9 and c(f, 2) > 3 + 1e-6
        return [
            wall("web", lambda f: (n_is(f, [0, 0, -1]) and near(c(f, 2), 0)) or (n_is(f, [0, 0, 1]) and near(c(f, 2), 3)), thickness=3.0, fs=fs, name="W"),
            wall("rib", lambda f: side(f) and 45 < c(f, 1) < 55, thickness=4.0 - taper, fs=fs, name="R"),
            wall("flange", lambda f: side(f) and c(f, 1) < 5, thickness=3.5 - taper, fs=fs, name="F"),
        ]
    return expect


def engraved_plate():
    """A 10 mm plate 300 x 200 with two glyphs, an L and a T, engraved 1 mm
    deep in its top face."""
    glyph_l = fuse(box(100, 90, 9, 102, 105, 11), box(100, 90, 9, 108, 92, 11))
    glyph_t = fuse(box(115, 103, 9, 125, 105, 11), box(119, 90, 9, 121, 105, 11))
    return cut(box(0, 0, 0, 300, 200, 10), glyph_l, glyph_t)


def engraved_expected(fs):
    c = lambda f, i: f["centroid"][i]
    return [
        wall("wall", lambda f: (n_is(f, [0, 0, -1]) and near(c(f, 2), 0)) or (n_is(f, [0, 0, 1]) and near(c(f, 2), 10)), thickness=10.0, fs=fs, name="P"),
        other("engraving", lambda f: 9 - 1e-6 <= c(f, 2) < 10 - 1e-6 and 99 < c(f, 0) < 126 and 89 < c(f, 1) < 106, fs, "P"),
    ]


def flange_cutouts():
    """A 2 mm web 200 x 120 with a 1.6 mm rib and a 1.2 mm flange 30 high
    on its y = 0 edge; three 10 mm cut-outs in the flange, 8, 12 and 8 deep
    (the deep one between the others)."""
    s = fuse(box(0, 0, 0, 200, 120, 2), box(0, 0, 2, 200, 1.2, 30), box(0, 59.2, 2, 200, 60.8, 25))
    return cut(s, box(40, -1, 22, 50, 3, 31), box(95, -1, 18, 105, 3, 31), box(150, -1, 22, 160, 3, 31))


def flange_cutouts_expected(fs):
    c = lambda f, i: f["centroid"][i]
    in_cut = lambda f, x0: x0 - 1e-6 <= c(f, 0) <= x0 + 10 + 1e-6 and c(f, 1) <= 1.2 + 1e-6 and c(f, 2) > 17
    return [
        wall("web", lambda f: (n_is(f, [0, 0, -1]) and near(c(f, 2), 0)) or (n_is(f, [0, 0, 1]) and near(c(f, 2), 2)), thickness=2.0, fs=fs, name="W"),
        wall("flange", lambda f: (n_is(f, [0, -1, 0]) and near(c(f, 1), 0) and c(f, 2) > 2) or (n_is(f, [0, 1, 0]) and near(c(f, 1), 1.2)), thickness=1.2, fs=fs, name="F"),
        wall("rib", lambda f: (n_is(f, [0, -1, 0]) and near(c(f, 1), 59.2)) or (n_is(f, [0, 1, 0]) and near(c(f, 1), 60.8)), thickness=1.6, fs=fs, name="R"),
        other("cutout", lambda f: in_cut(f, 40), fs, "F"),
        other("cutout", lambda f: in_cut(f, 95), fs, "F"),
        other("cutout", lambda f: in_cut(f, 150), fs, "F"),
    ]


def c_frame():
    """An upright C-section frame: 2 mm web (x-z plane) 120 high, 2 mm top
    and bottom flanges 30 wide, two 1.5 mm stiffeners, two Ø30 holes."""
    L = 240.0
    s = fuse(box(0, 0, 0, L, 2, 120), box(0, 0, 0, L, 30, 2), box(0, 0, 118, L, 30, 120),
             box(79.25, 2, 2, 80.75, 30, 118), box(159.25, 2, 2, 160.75, 30, 118))
    return cut(s, hole_y(40, 60, 30.0, -10, 30), hole_y(120, 60, 30.0, -10, 30))


def c_frame_expected(fs):
    c = lambda f, i: f["centroid"][i]
    return [
        wall("web", lambda f: (n_is(f, [0, -1, 0]) and near(c(f, 1), 0)) or (n_is(f, [0, 1, 0]) and near(c(f, 1), 2)), thickness=2.0, fs=fs, name="W"),
        wall("flange", lambda f: (n_is(f, [0, 0, 1]) and near(c(f, 2), 120)) or (n_is(f, [0, 0, -1]) and near(c(f, 2), 118)), thickness=2.0, fs=fs, name="FT"),
        wall("flange", lambda f: (n_is(f, [0, 0, -1]) and near(c(f, 2), 0)) or (n_is(f, [0, 0, 1]) and near(c(f, 2), 2)), thickness=2.0, fs=fs, name="FB"),
        wall("rib", lambda f: (n_is(f, [-1, 0, 0]) and near(c(f, 0), 79.25)) or (n_is(f, [1, 0, 0]) and near(c(f, 0), 80.75)), thickness=1.5, fs=fs, name="S1"),
        wall("rib", lambda f: (n_is(f, [-1, 0, 0]) and near(c(f, 0), 159.25)) or (n_is(f, [1, 0, 0]) and near(c(f, 0), 160.75)), thickness=1.5, fs=fs, name="S2"),
        other("hole", lambda f: f["kind"] == "cylinder" and near(c(f, 0), 40, 1e-3), fs, "W", large=True),
        other("hole", lambda f: f["kind"] == "cylinder" and near(c(f, 0), 120, 1e-3), fs, "W", large=True),
    ]


def thin_plate():
    """A free 2 mm plate: a thin wall with nothing to stand on."""
    return box(0, 0, 0, 120, 80, 2)


def plate_expected(fs):
    return [wall("wall", lambda f: f["normal"] is not None and abs(f["normal"][2]) > 0.99, thickness=2.0, fs=fs, name="P")]


def angle_bracket():
    """Two 2 mm plates in an L: 100x80 on the table, 80 high standing at x=0."""
    return fuse(box(0, 0, 0, 100, 80, 2), box(0, 0, 2, 2, 80, 80))


def bracket_expected(fs):
    c = lambda f, i: f["centroid"][i]
    return [
        wall("web", lambda f: (n_is(f, [0, 0, -1]) and near(c(f, 2), 0)) or (n_is(f, [0, 0, 1]) and near(c(f, 2), 2)), thickness=2.0, fs=fs, name="H"),
        wall("flange", lambda f: (n_is(f, [-1, 0, 0]) and near(c(f, 0), 0)) or (n_is(f, [1, 0, 0]) and near(c(f, 0), 2)), thickness=2.0, fs=fs, name="V"),
    ]


def turned(shape, up_axis=(1, 2, 3), degrees=37.0):
    t = gp_Trsf()
    t.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(*up_axis)), math.radians(degrees))
    t2 = gp_Trsf()
    t2.SetTranslation(gp_Vec(100, -50, 25))
    t2.Multiply(t)
    return BRepBuilderAPI_Transform(shape, t2, True).Shape(), t2


def turn_point(t, p):
    q = gp_Pnt(*p).Transformed(t)
    return [q.X(), q.Y(), q.Z()]


def turn_dir(t, v):
    d = gp_Dir(*v).Transformed(t)
    return [d.X(), d.Y(), d.Z()]


def write_turned(out, name, shape):
    """`name`_turned: the part turned 37° about (1,2,3) and moved, its
    expected features' points and up turned with it."""
    shape, t = turned(shape)
    write(shape, os.path.join(out, name + "_turned.step"))
    base = json.load(open(os.path.join(out, name + ".expected.json")))
    for f in base["features"]:
        for key in ("side_faces_at", "faces_at"):
            if key in f:
                f[key] = [turn_point(t, p) for p in f[key]]
    base.update({"part": name + "_turned.step", "up": turn_dir(t, (0, 0, 1)),
                 "about": base["about"] + "; turned 37° about (1,2,3) and moved, up turned with it"})
    json.dump(base, open(os.path.join(out, name + "_turned.expected.json"), "w"), indent=1)
    print(name + "_turned")


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "fixtures/recognition"
    only = set(sys.argv[2:])
    os.makedirs(out, exist_ok=True)
    cases = {
        "rib_grid_panel": (rib_grid_panel, rib_grid_expected, "web, four flanges, crossing ribs, ribs ending on flanges, a row of large holes, cut-outs, a corner notch"),
        "filleted_chamfered_rib": (filleted_chamfered_rib, filleted_expected, "a rib meeting its base through r2 fillets, with a chamfered top edge"),
        "sloped_rib": (sloped_rib, sloped_expected, "a rib leaning 12° from vertical"),
        "notched_rib": (notched_rib, notched_expected, "a rib with a notch at its top end"),
        "thick_wall": (thick_wall, thick_expected, "a 20 mm wall: not thin"),
        "flange_cutouts": (flange_cutouts, flange_cutouts_expected, "a rib and a flange on a web, three cut-outs in the flange (8, 12 and 8 deep)"),
        "engraved_plate": (engraved_plate, engraved_expected, "a plate with two glyphs engraved 1 mm deep: lettering, not walls"),
        "drafted_05": (lambda: drafted_panel(0.5), drafted_expected(0.5), "a drafted rib and flange, 0.5° per side"),
        "drafted_1": (lambda: drafted_panel(1.0), drafted_expected(1.0), "a drafted rib and flange, 1° per side"),
        "drafted_2": (lambda: drafted_panel(2.0), drafted_expected(2.0), "a drafted rib and flange, 2° per side"),
        "drafted_thin_2": (lambda: thin_top_panel(2.0), thin_top_expected(2.0), "a drafted rib and flange, 2° per side, 3 mm at the foot and 0.9 mm at the top"),
        "drafted_thin_5": (lambda: thin_top_panel(5.0), thin_top_expected(5.0), "a drafted rib and flange, 5° per side, 6.15 mm at the foot and 0.9 mm at the top"),
        "pocketed_rib": (pocketed_rib, pocketed_expected, "a rib with a blind pocket in one side and a rectangular window through it"),
        "c_frame": (c_frame, c_frame_expected, "an upright C-section frame with stiffeners and large holes in the web"),
        "thin_plate": (thin_plate, plate_expected, "a free 2 mm plate: a thin wall standing on nothing"),
        "angle_bracket": (angle_bracket, bracket_expected, "two 2 mm plates in an L; with up +Z the horizontal one is the base"),
    }
    for name, (build, expect, about) in cases.items():
        if only and name not in only:
            continue
        shape = build()
        fs = faces(shape)
        expected = expect(fs)
        write(shape, os.path.join(out, name + ".step"))
        doc = {"part": name + ".step", "about": about, "up": [0, 0, 1], "features": expected,
               "source": f"scripts/make_recognition_fixtures.py (OpenCascade {occ_version()})"}
        json.dump(doc, open(os.path.join(out, name + ".expected.json"), "w"), indent=1)
        print(name, len(fs), "faces,", len(expected), "features")
    for base_name, build in [("flange_cutouts", flange_cutouts), ("drafted_05", lambda: drafted_panel(0.5)), ("drafted_1", lambda: drafted_panel(1.0)),
                             ("drafted_2", lambda: drafted_panel(2.0)), ("drafted_thin_2", lambda: thin_top_panel(2.0)),
                             ("drafted_thin_5", lambda: thin_top_panel(5.0))]:
        if only and base_name + "_turned" not in only:
            continue
        write_turned(out, base_name, build())
    if only and "rib_grid_panel_turned" not in only:
        return
    # The panel turned out of axis alignment, its up turned with it.
    shape, t = turned(rib_grid_panel())
    write(shape, os.path.join(out, "rib_grid_panel_turned.step"))
    base = json.load(open(os.path.join(out, "rib_grid_panel.expected.json")))
    for f in base["features"]:
        for key in ("side_faces_at", "faces_at"):
            if key in f:
                f[key] = [turn_point(t, p) for p in f[key]]
    base.update({"part": "rib_grid_panel_turned.step", "up": turn_dir(t, (0, 0, 1)),
                 "about": "rib_grid_panel turned 37° about (1,2,3) and moved; up turned with it"})
    json.dump(base, open(os.path.join(out, "rib_grid_panel_turned.expected.json"), "w"), indent=1)
    print("rib_grid_panel_turned")


if __name__ == "__main__":
    main()
