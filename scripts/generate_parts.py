#!/usr/bin/env python3
"""Random thin-walled parts with their truth (issue 39, docs/GENERATOR.md).

Every part is drawn the way a CAD user draws it and comes with what it is
made of, in the set-up it is machined in:

  panel: a block pocketed from one side into a grid of cells: a web under
    the pockets, ribs between them, flanges on the edges that keep one
    (random counts, spacings, sizes), pockets drafted 0-5 degrees with
    corner radii (cones when drafted) and floor fillets, lightening holes
    through ribs and the web, cut-outs in flange tops.
  skin: a cylindrical skin of random radius and sector, arched either way,
    with flat stringers standing on its convex or its concave side (the side
    the set-up machines), holes through the skin between them.

Each part is then placed in a random rigid pose (a uniform rotation and a
move) with its set-up's up turned alike. The truth names faces by their
ordinal in OpenCascade's face order (`TopExp::MapShapes`, from 0), which a
rigid move keeps: features (web, rib, flange, hole, cutout; a wall's side
faces, thickness, foot and top thickness when drafted), connections
(base_leaf, crossing) and the blend faces (fillet_faces).

usage: python3 scripts/generate_parts.py [OUT_DIR [FIRST [COUNT]]]
       writes OUT_DIR/gen_SEED.step and OUT_DIR/gen_SEED.truth.json
       (default target/generated, seeds FIRST .. FIRST+COUNT-1 = 1 .. 20)
"""
import math, os, random, sys

from OCP.BRepPrimAPI import BRepPrimAPI_MakeCylinder, BRepPrimAPI_MakeRevol
from OCP.BRepAlgoAPI import BRepAlgoAPI_Cut, BRepAlgoAPI_Fuse
from OCP.BRepFilletAPI import BRepFilletAPI_MakeFillet
from OCP.BRepOffsetAPI import BRepOffsetAPI_DraftAngle
from OCP.BRepBuilderAPI import (BRepBuilderAPI_Transform, BRepBuilderAPI_MakePolygon,
                                BRepBuilderAPI_MakeFace)
from OCP.BRepAdaptor import BRepAdaptor_Surface, BRepAdaptor_Curve
from OCP.BRepGProp import BRepGProp
from OCP.GProp import GProp_GProps
from OCP.GeomAbs import GeomAbs_SurfaceType as S, GeomAbs_CurveType as C
from OCP.ShapeUpgrade import ShapeUpgrade_UnifySameDomain
from OCP.TopAbs import TopAbs_FACE, TopAbs_EDGE, TopAbs_REVERSED
from OCP.TopExp import TopExp, TopExp_Explorer
from OCP.TopoDS import TopoDS
from OCP.gp import gp_Pnt, gp_Dir, gp_Ax1, gp_Ax2, gp_Pln, gp_Trsf, gp_Vec, gp_Quaternion
try:  # OpenCascade 7.x bindings
    from OCP.TopTools import TopTools_ListOfShape, TopTools_IndexedMapOfShape
except ImportError:  # 8.x moved the containers
    from OCP.OCP.collections import List_TopoDS_Shape as TopTools_ListOfShape
    from OCP.OCP.collections import IndexedMap_TopoDS_Shape_TopTools_ShapeMapHasher as TopTools_IndexedMapOfShape

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_recognition_fixtures import box, write_generated  # noqa: E402

_face = getattr(TopoDS, "Face_s", None) or TopoDS.Face
_edge = getattr(TopoDS, "Edge_s", None) or TopoDS.Edge
_map_shapes = getattr(TopExp, "MapShapes_s", None) or TopExp.MapShapes
_surface_props = getattr(BRepGProp, "SurfaceProperties_s", None) or BRepGProp.SurfaceProperties

#: Geometric match of a face to the plane or cylinder it was drawn on, mm.
MATCH = 1e-5
#: Smallest pocket cell: under it a web is no longer thin, mm.
MIN_CELL = 28.0
#: A channel between two ribs narrower than the default tool (Ø12), mm.
NARROW_CELL = (8.0, 11.5)


# ---------------------------------------------------------------- solids

def cylinder(p, d, r, length):
    return BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(*p), gp_Dir(*d)), r, length).Shape()


def shape_list(shapes):
    out = TopTools_ListOfShape()
    for s in shapes:
        out.Append(s)
    return out


def unified(s):
    u = ShapeUpgrade_UnifySameDomain(s, True, True, True)
    u.Build()
    return u.Shape()


def cut_all(base, tools):
    op = BRepAlgoAPI_Cut()
    op.SetArguments(shape_list([base]))
    op.SetTools(shape_list(tools))
    op.Build()
    assert op.IsDone(), "cut failed"
    return unified(op.Shape())


def fuse_all(shapes):
    op = BRepAlgoAPI_Fuse()
    op.SetArguments(shape_list(shapes[:1]))
    op.SetTools(shape_list(shapes[1:]))
    op.Build()
    assert op.IsDone(), "fuse failed"
    return unified(op.Shape())


def edges(shape):
    e = TopExp_Explorer(shape, TopAbs_EDGE)
    while e.More():
        yield _edge(e.Current())
        e.Next()


def faces_of(shape):
    """Faces in OpenCascade's order (`TopExp::MapShapes`)."""
    m = TopTools_IndexedMapOfShape()
    _map_shapes(shape, TopAbs_FACE, m)
    return [_face(m.FindKey(i)) for i in range(1, m.Extent() + 1)]


def pocket_tool(x0, y0, x1, y1, floor, top, corner, draft_deg, fillet):
    """What a pocket removes: the floor's rectangle (x0..x1, y0..y1 at
    `floor`) with `corner` radii, its sides leaning outwards `draft_deg`
    up to `top`, its floor edge blended with `fillet`."""
    s = box(x0, y0, floor, x1, y1, top)
    if corner > 0:
        f = BRepFilletAPI_MakeFillet(s)
        for e in edges(s):
            c = BRepAdaptor_Curve(e)
            if c.GetType() == C.GeomAbs_Line and abs(c.Line().Direction().Z()) > 0.99:
                f.Add(corner, e)
        s = f.Shape()
    if draft_deg > 0:
        d = BRepOffsetAPI_DraftAngle(s)
        neutral = gp_Pln(gp_Pnt(0, 0, floor), gp_Dir(0, 0, 1))
        for face in faces_of(s):
            a = BRepAdaptor_Surface(face)
            if a.GetType() == S.GeomAbs_Plane and abs(a.Plane().Axis().Direction().Z()) > 0.99:
                continue
            d.Add(face, gp_Dir(0, 0, 1), -math.radians(draft_deg), neutral, True)
            assert d.AddDone(), "draft refused a face"
        d.Build()
        assert d.IsDone(), "draft failed"
        s = d.Shape()
    if fillet > 0:
        f = BRepFilletAPI_MakeFillet(s)
        for e in edges(s):
            p0, p1 = end_points(e)
            if abs(p0[2] - floor) < 1e-7 and abs(p1[2] - floor) < 1e-7:
                f.Add(fillet, e)
        s = f.Shape()
    return s


def end_points(e):
    c = BRepAdaptor_Curve(e)
    a, b = c.Value(c.FirstParameter()), c.Value(c.LastParameter())
    return (a.X(), a.Y(), a.Z()), (b.X(), b.Y(), b.Z())


# ---------------------------------------------------------------- face matching

def face_info(face):
    """Type, outward plane (normal, offset) or cylinder (axis point,
    direction, radius), centroid and area of a face."""
    a = BRepAdaptor_Surface(face)
    p = GProp_GProps()
    _surface_props(face, p)
    c = p.CentreOfMass()
    info = {"type": a.GetType(), "centroid": (c.X(), c.Y(), c.Z()), "area": p.Mass()}
    if a.GetType() == S.GeomAbs_Plane:
        pl = a.Plane()
        n = pl.Axis().Direction()
        n = [n.X(), n.Y(), n.Z()]
        if face.Orientation() == TopAbs_REVERSED:
            n = [-v for v in n]
        o = pl.Location()
        info["normal"] = n
        info["offset"] = n[0] * o.X() + n[1] * o.Y() + n[2] * o.Z()
    elif a.GetType() == S.GeomAbs_Cylinder:
        cy = a.Cylinder()
        ax = cy.Axis()
        info["axis"] = ((ax.Location().X(), ax.Location().Y(), ax.Location().Z()),
                        (ax.Direction().X(), ax.Direction().Y(), ax.Direction().Z()))
        info["radius"] = cy.Radius()
    return info


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def unit(v):
    n = math.sqrt(dot(v, v))
    return [x / n for x in v]


def on_plane(info, normal, point):
    """The face lies on the plane through `point` with outward `normal`."""
    if "normal" not in info:
        return False
    n = unit(normal)
    return dot(info["normal"], n) > 1 - 1e-9 and abs(info["offset"] - dot(n, point)) < MATCH


def on_cylinder(info, point, direction, radius):
    if "axis" not in info or abs(info["radius"] - radius) > MATCH:
        return False
    (q, d) = info["axis"]
    u = unit(direction)
    if abs(abs(dot(d, u)) - 1) > 1e-9:
        return False
    w = sub(q, point)
    off = sub(w, [dot(w, u) * x for x in u])
    return math.sqrt(dot(off, off)) < MATCH


def inside(info, lo, hi):
    return all(a - MATCH <= c <= b + MATCH for c, a, b in zip(info["centroid"], lo, hi))


class Truth:
    """Features and connections of a part, faces by their ordinal."""

    def __init__(self, shape, up):
        self.shape = shape
        self.infos = [face_info(f) for f in faces_of(shape)]
        self.up = list(up)
        self.features = []
        self.connections = []
        self.taken = set()

    def select(self, pred):
        return [i for i, info in enumerate(self.infos) if pred(info)]

    def wall(self, fid, kind, pred, thickness, foot=None, top=None):
        faces = self.select(pred)
        assert faces, f"{fid}: no side face"
        f = {"id": fid, "kind": kind, "thin": True, "thickness": round(thickness, 9), "side_faces": faces}
        if foot is not None and abs(foot - top) > 1e-9:
            f["thickness_foot"], f["thickness_top"] = round(foot, 9), round(top, 9)
        self.features.append(f)
        self.taken.update(faces)

    def depression(self, fid, kind, pred, wall, **extra):
        faces = self.select(pred)
        assert faces, f"{fid}: no face"
        f = {"id": fid, "kind": kind, "wall": wall, "faces": faces}
        f.update(extra)
        self.features.append(f)
        self.connections.append({"base": wall, "leaf": fid, "kind": "base_leaf"})
        self.taken.update(faces)

    def link(self, base, leaf, kind="base_leaf"):
        self.connections.append({"base": base, "leaf": leaf, "kind": kind})

    def blends(self):
        """Faces no feature names that are neither planes nor the skin's
        cylinders: corner radii, floor fillets and the tori between them."""
        return [i for i, info in enumerate(self.infos)
                if i not in self.taken and info["type"] != S.GeomAbs_Plane]

    def document(self, family, seed, params):
        return {"generator": "thinwall generate_parts 1", "family": family, "seed": seed,
                "up": self.up, "face_count": len(self.infos), "params": params,
                "features": self.features, "connections": self.connections,
                "fillet_faces": self.blends()}


# ---------------------------------------------------------------- panels

def cells(rnd, length, start, end, foot, most):
    """Random rib centre lines across `length`: the pockets' floor edges
    (from `start`, the first wall's inner foot or past the edge, to `end`)
    split into cells at least MIN_CELL wide by ribs `foot` thick at their
    foot; one time in four, one cell between two ribs is a channel
    NARROW_CELL wide, narrower than the tool. Returns (rib centres, cells
    as (lo, hi) at the floor)."""
    room = end - start
    n = max(0, min(most, int((room + foot) // (MIN_CELL + foot)) - 1))
    n = rnd.randint(0, n)
    slack = room - (n + 1) * MIN_CELL - n * foot
    shares = sorted(rnd.uniform(0, slack) for _ in range(n + 1))
    widths, prev = [], 0.0
    for s in shares[:-1] + [slack]:
        widths.append(MIN_CELL + s - prev)
        prev = s
    if n >= 2 and rnd.random() < 0.25:
        k = rnd.randint(1, n - 1)
        narrow = rnd.uniform(*NARROW_CELL)
        widths[k + 1] += widths[k] - narrow
        widths[k] = narrow
    ribs, spans, at = [], [], start
    for i, w in enumerate(widths):
        spans.append((at, at + w))
        at += w
        if i < n:
            ribs.append(at + foot / 2)
            at += foot
    return ribs, spans


def panel(rnd):
    """A block pocketed from +z into a grid of cells; truth in the block's frame."""
    L, W = rnd.uniform(120, 280), rnd.uniform(90, 200)
    tw, h = rnd.uniform(1.5, 2.5), rnd.uniform(14, 40)
    draft = rnd.choice([0.0, 0.0, rnd.uniform(0.5, 5.0)])
    taper = h * math.tan(math.radians(draft))
    rib_top, fl_top = rnd.uniform(0.8, 2.5), rnd.uniform(1.0, 2.5)
    rib_foot, fl_foot = rib_top + 2 * taper, fl_top + taper
    flanged = {e: rnd.random() < 0.75 for e in ("x0", "x1", "y0", "y1")}
    ext = 12.0  # how far an open pocket runs past the block's edge
    x_lo = fl_foot if flanged["x0"] else -ext
    x_hi = L - fl_foot if flanged["x1"] else L + ext
    y_lo = fl_foot if flanged["y0"] else -ext
    y_hi = W - fl_foot if flanged["y1"] else W + ext
    xs, xcells = cells(rnd, L, x_lo, x_hi, rib_foot, 4)   # ribs along y at x = xs
    ys, ycells = cells(rnd, W, y_lo, y_hi, rib_foot, 3)   # ribs along x at y = ys
    smallest = min(min(b - a for a, b in xcells), min(b - a for a, b in ycells))
    corner = rnd.choice([0.0, rnd.uniform(1.5, min(8.0, smallest / 2 - 2))])
    fillet = rnd.choice([0.0, rnd.uniform(0.5, min(3.0, 0.3 * smallest))])
    if corner > 0:
        fillet = min(fillet, 0.8 * corner)
    top = tw + h
    tools = [pocket_tool(a, c, b, d, tw, top + 2, corner, draft, fillet)
             for a, b in xcells for c, d in ycells]
    params = {"length": L, "width": W, "web": tw, "height": h, "draft_deg": draft,
              "rib_top": rib_top, "rib_foot": rib_foot, "flange_top": fl_top,
              "flange_foot": fl_foot, "flanges": flanged, "corner_radius": corner,
              "floor_fillet": fillet, "ribs_x": xs, "ribs_y": ys}
    cutters, plan = panel_depressions(rnd, xs, ys, xcells, ycells, flanged, params)
    shape = cut_all(box(0, 0, 0, L, W, top), tools + cutters)
    t = Truth(shape, (0, 0, 1))
    panel_walls(t, params)
    panel_depression_truth(t, plan, params)
    return t, params


def panel_depressions(rnd, xs, ys, xcells, ycells, flanged, p):
    """Lightening holes through ribs and the web, cut-outs in flange tops:
    their tools and what the truth needs to find their faces."""
    tw, h, rf, rc = p["web"], p["height"], p["floor_fillet"], p["corner_radius"]
    tools, plan = [], []
    clear = (h - rf) / 2 - 1.5
    for axis, ribs, spans in (("y", xs, ycells), ("x", ys, xcells)):
        for i, c in enumerate(ribs):
            if rnd.random() < 0.5 or clear < 2.5:
                continue
            a, b = rnd.choice(spans)
            a, b = max(a, 0.0), min(b, p["length"] if axis == "x" else p["width"])
            most = min(clear, (b - a) / 2 - rc - 3)
            if most < 2.0:
                continue
            r = rnd.uniform(2.0, most)
            s = rnd.uniform(a + rc + r + 2, b - rc - r - 2)
            z = tw + rf + (h - rf) / 2
            half = p["rib_foot"] / 2 + 1
            if axis == "y":   # a rib along y at x = c: the hole along x
                tools.append(cylinder((c - half, s, z), (1, 0, 0), r, 2 * half))
                plan.append(("hole", f"RY{i + 1}", (c, s, z), (1, 0, 0), r))
            else:
                tools.append(cylinder((s, c - half, z), (0, 1, 0), r, 2 * half))
                plan.append(("hole", f"RX{i + 1}", (s, c, z), (0, 1, 0), r))
    for a, b in xcells:
        for c, d in ycells:
            lo, hi = max(a, 0), min(b, p["length"])
            lo2, hi2 = max(c, 0), min(d, p["width"])
            room = min(hi - lo, hi2 - lo2) / 2 - rf - 3
            if rnd.random() < 0.25 and room > 2.5:
                r = rnd.uniform(2.0, min(room, 12.0))
                x, y = (lo + hi) / 2, (lo2 + hi2) / 2
                tools.append(cylinder((x, y, -1), (0, 0, 1), r, tw + 2))
                plan.append(("hole", "W", (x, y, 0), (0, 0, 1), r))
    for edge in ("x0", "x1", "y0", "y1"):
        if not flanged[edge] or rnd.random() < 0.5:
            continue
        spans = ycells if edge[0] == "x" else xcells
        lo, hi = rnd.choice(spans)
        lo, hi = max(lo, 0), min(hi, p["width"] if edge[0] == "x" else p["length"])
        room = hi - lo - 2 * rc - 6
        if room < 4:
            continue
        width = rnd.uniform(4, min(15, room))
        at = rnd.uniform(lo + rc + 3, hi - rc - 3 - width)
        # At the flange's end where the pockets run out past the block's
        # edge (no flange across it), one time in three: open at that end.
        ends = open_ends(edge, flanged, p)
        if ends and rnd.random() < 1 / 3:
            at = -1.0 if rnd.choice(ends) == "lo" else ends_length(edge, p) + 1 - width
        depth = rnd.uniform(3, min(0.45 * h, h - rf - 3))
        tools.append(notch_tool(edge, at, width, depth, p))
        plan.append(("cutout", "F" + edge.upper(), edge, at, width, depth))
    return tools, plan


def ends_length(edge, p):
    """The length of the block's edge a flange runs along."""
    return p["width"] if edge[0] == "x" else p["length"]


def open_ends(edge, flanged, p):
    """The ends ("lo", "hi") of a flange along `edge` with no flange across them."""
    across = ("y0", "y1") if edge[0] == "x" else ("x0", "x1")
    return [end for end, e in zip(("lo", "hi"), across) if not flanged[e]]


def notch_tool(edge, at, width, depth, p):
    top, foot = p["web"] + p["height"], p["flange_foot"]
    if edge[0] == "y":
        y0 = -1 if edge == "y0" else p["width"] - foot - 1
        return box(at, y0, top - depth, at + width, y0 + foot + 2, top + 1)
    x0 = -1 if edge == "x0" else p["length"] - foot - 1
    return box(x0, at, top - depth, x0 + foot + 2, at + width, top + 1)


def panel_walls(t, p):
    """Web, flanges and ribs with their side planes; their connections."""
    L, W, tw, h = p["length"], p["width"], p["web"], p["height"]
    d = math.radians(p["draft_deg"])
    cs, sn = math.cos(d), math.sin(d)
    t.wall("W", "web", lambda f: on_plane(f, (0, 0, -1), (0, 0, 0)) or on_plane(f, (0, 0, 1), (0, 0, tw)), tw)
    fl = {}
    for e, out, inner, at in (("x0", (-1, 0, 0), (cs, 0, sn), 0.0), ("x1", (1, 0, 0), (-cs, 0, sn), L),
                              ("y0", (0, -1, 0), (0, cs, sn), 0.0), ("y1", (0, 1, 0), (0, -cs, sn), W)):
        if not p["flanges"][e]:
            continue
        fid = "F" + e.upper()
        axis = 0 if e[0] == "x" else 1
        edge_pt = [0.0, 0.0, tw]
        edge_pt[axis] = at
        foot_pt = list(edge_pt)
        foot_pt[axis] = at + (p["flange_foot"] if at == 0 else -p["flange_foot"])
        t.wall(fid, "flange",
               lambda f, out=out, ep=edge_pt, inner=inner, fp=foot_pt: on_plane(f, out, ep) or on_plane(f, inner, fp),
               p["flange_top"], p["flange_foot"], p["flange_top"])
        t.link("W", fid)
        fl[e] = fid
    for a in ("x0", "x1"):
        for b in ("y0", "y1"):
            if a in fl and b in fl:
                t.link(fl[a], fl[b], "crossing")
    half = p["rib_foot"] / 2
    for i, x in enumerate(p["ribs_x"]):
        rid = f"RY{i + 1}"
        t.wall(rid, "rib", lambda f, x=x: on_plane(f, (cs, 0, sn), (x + half, 0, tw)) or on_plane(f, (-cs, 0, sn), (x - half, 0, tw)),
               p["rib_top"], p["rib_foot"], p["rib_top"])
        t.link("W", rid)
        for e in ("y0", "y1"):
            if e in fl:
                t.link(rid, fl[e], "crossing")
    for j, y in enumerate(p["ribs_y"]):
        rid = f"RX{j + 1}"
        t.wall(rid, "rib", lambda f, y=y: on_plane(f, (0, cs, sn), (0, y + half, tw)) or on_plane(f, (0, -cs, sn), (0, y - half, tw)),
               p["rib_top"], p["rib_foot"], p["rib_top"])
        t.link("W", rid)
        for e in ("x0", "x1"):
            if e in fl:
                t.link(rid, fl[e], "crossing")
        for i in range(len(p["ribs_x"])):
            t.link(f"RY{i + 1}", rid, "crossing")


def panel_depression_truth(t, plan, p):
    top = p["web"] + p["height"]
    n_hole = n_cut = 0
    for item in plan:
        if item[0] == "hole":
            _, wall, at, axis, r = item
            n_hole += 1
            t.depression(f"H{n_hole}", "hole", lambda f, at=at, axis=axis, r=r: on_cylinder(f, at, axis, r),
                         wall, diameter=round(2 * r, 9))
        else:
            _, wall, edge, at, width, depth = item
            n_cut += 1
            foot = p["flange_foot"]
            if edge[0] == "y":
                y0 = 0 if edge == "y0" else p["width"] - foot
                lo, hi = (at, y0, top - depth), (at + width, y0 + foot, top)
                sides = lambda f, at=at, w=width: on_plane(f, (1, 0, 0), (at, 0, 0)) or on_plane(f, (-1, 0, 0), (at + w, 0, 0))
            else:
                x0 = 0 if edge == "x0" else p["length"] - foot
                lo, hi = (x0, at, top - depth), (x0 + foot, at + width, top)
                sides = lambda f, at=at, w=width: on_plane(f, (0, 1, 0), (0, at, 0)) or on_plane(f, (0, -1, 0), (0, at + w, 0))
            floor = lambda f, z=top - depth: on_plane(f, (0, 0, 1), (0, 0, z))
            # Open at the flange's end: a side notch at a wall end (DOMAIN.md §2.2).
            at_end = at < 0 or at + width > ends_length(edge, p)
            t.depression(f"C{n_cut}", "notch" if at_end else "cutout",
                         lambda f, lo=lo, hi=hi, s=sides, fl=floor: inside(f, lo, hi) and (s(f) or fl(f)),
                         wall, depth=round(depth, 9))


# ---------------------------------------------------------------- skins

def about_x(degrees):
    t = gp_Trsf()
    t.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0)), math.radians(degrees))
    return t


def turned_dir(t, v):
    d = gp_Dir(*v).Transformed(t)
    return (d.X(), d.Y(), d.Z())


def moved(shape, t):
    return BRepBuilderAPI_Transform(shape, t, True).Shape()


def skin(rnd):
    """A cylindrical skin about the x axis (radius `radius` to `radius` +
    `skin`, a sector centred on +z) with flat stringers standing radially
    on its outer (convex) or inner (concave) side, the side the set-up
    machines; holes through the skin between them."""
    R, ts, length = rnd.uniform(250, 800), rnd.uniform(1.5, 3.0), rnd.uniform(150, 300)
    arc = rnd.uniform(120, min(400, R * math.radians(60)))
    span = math.degrees(arc / R)
    outside = rnd.random() < 0.5
    hs, tst = rnd.uniform(12, 35), rnd.uniform(1.0, 2.5)
    poly = BRepBuilderAPI_MakePolygon()
    for x, z in ((0, R), (length, R), (length, R + ts), (0, R + ts)):
        poly.Add(gp_Pnt(x, 0, z))
    poly.Close()
    face = BRepBuilderAPI_MakeFace(poly.Wire()).Face()
    body = BRepPrimAPI_MakeRevol(face, gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0)), math.radians(span)).Shape()
    body = moved(body, about_x(-span / 2))
    # Stringer angles: at least 30 mm of arc apart and 15 mm from the ends.
    gap_deg, edge_deg = math.degrees(30 / R), math.degrees(15 / R)
    most = int((span - 2 * edge_deg) // gap_deg) + 1
    n = rnd.randint(1, max(1, min(4, most)))
    angles = spread(rnd, -span / 2 + edge_deg, span / 2 - edge_deg, n, gap_deg)
    z0, z1 = (R + ts / 2, R + ts + hs) if outside else (R - hs, R + ts / 2)
    parts = [body] + [moved(box(0, -tst / 2, z0, length, tst / 2, z1), about_x(a)) for a in angles]
    holes = skin_holes(rnd, angles, span, R, ts, length)
    shape = fuse_all(parts)
    if holes:
        shape = cut_all(shape, [h[0] for h in holes])
    t = Truth(shape, (0, 0, 1) if outside else (0, 0, -1))
    x_axis = ((0, 0, 0), (1, 0, 0))
    t.wall("W", "web", lambda f: on_cylinder(f, *x_axis, R) or on_cylinder(f, *x_axis, R + ts), ts)
    for i, a in enumerate(angles):
        n = turned_dir(about_x(a), (0, 1, 0))
        t.wall(f"S{i + 1}", "rib", lambda f, n=n: on_plane(f, n, [v * tst / 2 for v in n])
               or on_plane(f, [-v for v in n], [-v * tst / 2 for v in n]), tst)
        t.link("W", f"S{i + 1}")
    for k, (_, at, d, r) in enumerate(holes):
        t.depression(f"H{k + 1}", "hole", lambda f, at=at, d=d, r=r: on_cylinder(f, at, d, r), "W",
                     diameter=round(2 * r, 9))
    params = {"radius": R, "skin": ts, "length": length, "span_deg": span, "stringers_outside": outside,
              "stringer_height": hs, "stringer": tst, "stringer_deg": angles}
    return t, params


def spread(rnd, lo, hi, n, gap):
    """`n` sorted values in lo..hi at least `gap` apart."""
    slack = (hi - lo) - (n - 1) * gap
    cuts = sorted(rnd.uniform(0, slack) for _ in range(n))
    return [lo + c + i * gap for i, c in enumerate(cuts)]


def skin_holes(rnd, angles, span, R, ts, length):
    """Radial holes through the skin, in the middle of the bays between
    stringers (and the sector's ends) that have room."""
    edges = [-span / 2] + angles + [span / 2]
    out = []
    for a, b in zip(edges, edges[1:]):
        room = min(math.radians(b - a) * R / 2, length / 2) - 8
        if room < 3 or rnd.random() < 0.5:
            continue
        r = rnd.uniform(2.5, min(room, 15))
        mid = (a + b) / 2
        x = rnd.uniform(r + 10, length - r - 10)
        d = turned_dir(about_x(mid), (0, 0, 1))
        at = (x, 0.0, 0.0)
        start = tuple(at[i] + d[i] * (R - 2) for i in range(3))
        out.append((cylinder(start, d, r, ts + 4), at, d, r))
    return out


# ---------------------------------------------------------------- poses and parts

def random_pose(rnd):
    """A uniform random rotation and a move within 300 mm."""
    q = [rnd.gauss(0, 1) for _ in range(4)]
    n = math.sqrt(dot(q, q))
    t = gp_Trsf()
    t.SetRotation(gp_Quaternion(*(v / n for v in q)))
    m = gp_Trsf()
    m.SetTranslation(gp_Vec(*(rnd.uniform(-300, 300) for _ in range(3))))
    m.Multiply(t)
    return m


def posed(shape, up, trsf):
    """The part moved by `trsf` and its up turned alike; its faces keep
    their order (checked by their centroids)."""
    moved = BRepBuilderAPI_Transform(shape, trsf, True).Shape()
    before = [face_info(f)["centroid"] for f in faces_of(shape)]
    after = [face_info(f)["centroid"] for f in faces_of(moved)]
    assert len(before) == len(after), "a move changed the face count"
    for b, a in zip(before, after):
        q = gp_Pnt(*b).Transformed(trsf)
        assert abs(q.X() - a[0]) + abs(q.Y() - a[1]) + abs(q.Z() - a[2]) < 1e-6, "a move reordered faces"
    d = gp_Dir(*up).Transformed(trsf)
    return moved, [d.X(), d.Y(), d.Z()]


FAMILIES = {"panel": panel, "skin": skin}


def drawn(seed):
    """Part `seed` in the frame it was drawn in and turned into its random
    pose: ((shape, truth document), (turned shape, its truth document)),
    drawn once."""
    rnd = random.Random(seed)
    family = sorted(FAMILIES)[seed % len(FAMILIES)]
    truth, params = FAMILIES[family](rnd)
    doc = truth.document(family, seed, params)
    trsf = random_pose(rnd)
    shape, up = posed(truth.shape, truth.up, trsf)
    v = trsf.TranslationPart()
    turned = dict(doc, up=up, pose={"rotation": [[trsf.Value(i, j) for j in (1, 2, 3)] for i in (1, 2, 3)],
                                    "translation": [v.X(), v.Y(), v.Z()]})
    return (truth.shape, doc), (shape, turned)


def part(seed, turned=True):
    """Part `seed`: (shape, truth document). `turned` places it in its
    random pose; otherwise it stays in the frame it was drawn in."""
    flat, moved = drawn(seed)
    return moved if turned else flat


def main():
    write_generated("gen", part, "target/generated", 20)


if __name__ == "__main__":
    main()
