#!/usr/bin/env python3
"""Generate curved-wall fixtures (issue 18, docs/RECOGNITION.md "Curved walls").

Each part is a cross-section revolved about the z axis (or a skin with
stringers), written with its expected walls: kind, thin, thickness (mm),
height (mm, from the base's side along the wall's generator), developed
length (mm, along the arc of the mid-surface), side faces by centroid, and
the base-leaf connections between them. Every part is also written turned
37° about (1, 2, 3) and moved, its up and points turned with it.

  frame_r400: a frame segment, web 2 mm (z 0..2) over r 400..480 and 30°,
    flanges 1.6 mm thick and 25 mm tall (z 0..25) on its inner and outer
    curved edges.
  tube_and_boss: a 2 mm plate with a tube Ø40 (1.5 wall, a radial Ø8
    window) standing 28 on it, and a Ø20 boss 15 tall around a Ø10 hole (not a wall).
  frame_r250: a frame segment, web 2.5 mm over r 250..310 and 60°, an outer
    flange 2 mm thick and 30 mm tall standing up and an inner one 2 mm
    thick hanging 20 mm down.
  skin_stringers: a skin 2 mm thick (r 500..502 about the y axis, 40° about
    the top, 300 long) with two straight stringers 1.5 mm thick and 20 mm
    tall inside it, at ±8° from the top, the whole length.
  frame_r400_holes: frame_r400 with a radial Ø10 hole through the outer
    flange (15°, 13 up) and a Ø30 lightening hole through the web (r 440).
  conical_flange: a web 2 mm over r 200..260 and 45° with an outer flange
    1.5 mm thick leaning 15° outwards, 25 mm along its generator from the
    web's underside.

  freeform_rib: a web 2 mm (x 0..200, y 0..100) with a rib 1.5 mm thick
    and 28 mm tall standing on it along an S-shaped curve (a B-spline in
    plan, its two sides the curve's offsets by ±0.75 mm, approximated to
    1e-8 mm): walls between free-form faces that are offsets of each other.

usage: python3 scripts/make_curved_fixtures.py [OUT_DIR]   (default fixtures/curved)
"""
import json, math, os, sys

sys.path.insert(0, os.path.dirname(__file__))
from make_recognition_fixtures import (box, fuse, write, turned, turn_point, turn_dir,  # noqa: E402
                                       occ_version, _face, pick, near)
from OCP.BRepPrimAPI import BRepPrimAPI_MakeRevol  # noqa: E402
from OCP.BRepBuilderAPI import BRepBuilderAPI_MakePolygon, BRepBuilderAPI_MakeFace, BRepBuilderAPI_Transform  # noqa: E402
from OCP.gp import gp_Pnt, gp_Ax1, gp_Dir, gp_Trsf, gp_Vec  # noqa: E402
from OCP.TopExp import TopExp_Explorer  # noqa: E402
from OCP.TopAbs import TopAbs_FACE  # noqa: E402
from OCP.GProp import GProp_GProps  # noqa: E402
from OCP.BRepGProp import BRepGProp, BRepGProp_Face  # noqa: E402
from OCP.BRepAdaptor import BRepAdaptor_Surface  # noqa: E402
from OCP.GeomAbs import GeomAbs_SurfaceType as T, GeomAbs_C2  # noqa: E402


def revolved(points_xz, degrees, start_deg=0.0):
    """The polygon `points_xz` (in the xz plane, x = radius) revolved about z
    from `start_deg` through `degrees`."""
    poly = BRepBuilderAPI_MakePolygon()
    for x, z in points_xz:
        poly.Add(gp_Pnt(x, 0, z))
    poly.Close()
    face = BRepBuilderAPI_MakeFace(poly.Wire()).Face()
    shape = BRepPrimAPI_MakeRevol(face, gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), math.radians(degrees)).Shape()
    if start_deg:
        t = gp_Trsf()
        t.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), math.radians(start_deg))
        shape = BRepBuilderAPI_Transform(shape, t, True).Shape()
    return shape


def rect(x0, z0, x1, z1):
    return [(x0, z0), (x1, z0), (x1, z1), (x0, z1)]


def faces(shape):
    """Every face: centroid, surface type, radius (cylinders) or normal (planes)."""
    out = []
    e = TopExp_Explorer(shape, TopAbs_FACE)
    while e.More():
        f = _face(e.Current())
        p = GProp_GProps()
        BRepGProp.SurfaceProperties_s(f, p)
        c = p.CentreOfMass()
        a = BRepAdaptor_Surface(f)
        d = {"centroid": [c.X(), c.Y(), c.Z()], "area": p.Mass(), "radius": None, "normal": None}
        if a.GetType() == T.GeomAbs_Cylinder:
            d["kind"], d["radius"] = "cylinder", a.Cylinder().Radius()
        elif a.GetType() == T.GeomAbs_Cone:
            d["kind"], d["radius"] = "cone", a.Cone().RefRadius()
        elif a.GetType() == T.GeomAbs_Plane:
            # The outward normal with the face's orientation and a
            # left-handed plane frame (revolved faces have them) both counted.
            g = BRepGProp_Face(f)
            u0, u1, v0, v1 = g.Bounds()
            pnt, n = gp_Pnt(), gp_Vec()
            g.Normal(0.5 * (u0 + u1), 0.5 * (v0 + v1), pnt, n)
            n.Normalize()
            d["kind"], d["normal"] = "plane", [n.X(), n.Y(), n.Z()]
        else:
            d["kind"] = "other"
        out.append(d)
        e.Next()
    return out


def cyl(r):
    return lambda f: f["kind"] == "cylinder" and near(f["radius"], r)


def plane(n, coord=None, axis=2):
    def pred(f):
        if f["kind"] != "plane" or not all(near(a, b) for a, b in zip(f["normal"], n)):
            return False
        return coord is None or near(f["centroid"][axis], coord)
    return pred


def either(*preds):
    return lambda f: any(p(f) for p in preds)


def wall(name, kind, fs, side, thickness, height, length, thin=True):
    return {"name": name, "kind": kind, "thin": thin, "thickness": thickness, "height": height,
            "length": length, "side_faces_at": pick(fs, side)}


def frame_r400():
    a = 30.0
    shape = fuse(revolved(rect(400, 0, 480, 2), a), revolved(rect(478.4, 0, 480, 25), a),
                 revolved(rect(400, 0, 401.6, 25), a))

    def expect(fs):
        arc = math.radians(a)
        return [
            wall("W", "web", fs, either(plane([0, 0, -1]), plane([0, 0, 1], 2.0)), 2.0, None, None),
            wall("O", "flange", fs, either(cyl(480), cyl(478.4)), 1.6, 23.0, 479.2 * arc),
            wall("I", "flange", fs, either(cyl(400), cyl(401.6)), 1.6, 23.0, 400.8 * arc),
        ], [["W", "O"], ["W", "I"]]
    return shape, expect


def frame_r400_holes():
    """frame_r400 with a radial Ø10 hole through the outer flange at 15°,
    13 mm up, and a Ø30 lightening hole through the web at r 440, 15°."""
    from OCP.BRepPrimAPI import BRepPrimAPI_MakeCylinder
    from OCP.gp import gp_Ax2
    from make_recognition_fixtures import cut
    shape, expect_walls = frame_r400()
    a = math.radians(15.0)
    radial = gp_Dir(math.cos(a), math.sin(a), 0)
    flange_hole = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(470 * math.cos(a), 470 * math.sin(a), 13.0), radial), 5.0, 20.0).Shape()
    web_hole = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(440 * math.cos(a), 440 * math.sin(a), -1.0), gp_Dir(0, 0, 1)), 15.0, 4.0).Shape()
    shape = cut(shape, flange_hole, web_hole)

    def expect(fs):
        walls, connections = expect_walls(fs)
        holes = [
            {"wall": "O", "diameter": 10.0, "through": True, "faces_at": pick(fs, cyl(5.0))},
            {"wall": "W", "diameter": 30.0, "through": True, "faces_at": pick(fs, cyl(15.0))},
        ]
        return walls, connections, holes
    return shape, expect


def tube_and_boss():
    """A 2 mm plate 120 x 80 with a tube (Ø40 outside, 1.5 wall, a Ø8
    window through it) standing 28 on it and a Ø20 boss 15 tall around a
    Ø10 hole: the tube's wall
    goes all the way round (a closed curved wall), the boss's (5 thick
    at radius 7.5) is too tightly curved to be a wall."""
    from OCP.BRepPrimAPI import BRepPrimAPI_MakeCylinder
    from OCP.gp import gp_Ax2
    from make_recognition_fixtures import cut
    z = gp_Dir(0, 0, 1)
    cylinder = lambda x, y, r, z0, h: BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, z0), z), r, h).Shape()
    tube = cut(cylinder(40, 40, 20.0, 1.0, 29.0), cylinder(40, 40, 18.5, 2.0, 40.0))
    boss = cut(cylinder(90, 40, 10.0, 1.0, 16.0), cylinder(90, 40, 5.0, -1.0, 30.0))
    # A radial Ø8 window through the tube: it tells the two round faces'
    # centroids apart, which would otherwise both lie on the axis. (It is
    # read as a cut-out, not a hole, for now: docs/RECOGNITION.md.)
    window = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(40, 40, 16.0), gp_Dir(1, 0, 0)), 4.0, 30.0).Shape()
    shape = cut(fuse(box(0, 0, 0, 120, 80, 2), tube, boss), cylinder(90, 40, 5.0, -1.0, 30.0), window)

    def expect(fs):
        return [
            wall("W", "web", fs, either(plane([0, 0, -1]), plane([0, 0, 1], 2.0)), 2.0, None, None),
            wall("T", "rib", fs, either(cyl(20.0), cyl(18.5)), 1.5, 28.0, 2 * math.pi * 19.25),
        ], [["W", "T"]]
    return shape, expect


def frame_r250():
    a = 60.0
    shape = fuse(revolved(rect(250, 0, 310, 2.5), a, 10.0), revolved(rect(308, 0, 310, 30), a, 10.0),
                 revolved(rect(250, 0, 252, 18), a, 10.0))

    def expect(fs):
        arc = math.radians(a)
        return [
            wall("W", "web", fs, either(plane([0, 0, -1], 0.0), plane([0, 0, 1], 2.5)), 2.5, None, None),
            wall("O", "flange", fs, either(cyl(310), cyl(308)), 2.0, 27.5, 309 * arc),
            wall("I", "flange", fs, either(cyl(250), cyl(252)), 2.0, 15.5, 251 * arc),
        ], [["W", "O"], ["W", "I"]]
    return shape, expect


def skin_stringers():
    """The skin about the y axis: the profile revolved about z, then turned
    so z goes to y (the skin's top at +z)."""
    half = 20.0
    skin = revolved(rect(500, 0, 502, 300), 2 * half, 90.0 - half)
    parts = [skin]
    for deg in (-8.0, 8.0):
        # A stringer in the xy plane about the radial direction at 90° + deg,
        # from r 480 into the skin.
        s = box(-0.75, 480.0, 0.0, 0.75, 500.5, 300.0)
        t = gp_Trsf()
        t.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), math.radians(deg))
        parts.append(BRepBuilderAPI_Transform(s, t, True).Shape())
    shape = fuse(*parts)
    # Axis z -> y: turn -90° about x (z to y, y to -z) then flip so the
    # skin's top (+y before) is +z.
    t = gp_Trsf()
    t.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0)), math.radians(90.0))
    shape = BRepBuilderAPI_Transform(shape, t, True).Shape()

    def expect(fs):
        def stringer_side(sign):
            # Side planes of the stringer at +-8° about the top: normals
            # (+-cos, 0, sin) turned; pick by centroid angle.
            def pred(f):
                if f["kind"] != "plane":
                    return False
                x, _, z = f["centroid"]
                ang = math.degrees(math.atan2(x, z))
                n = f["normal"]
                return abs(ang - sign * 8.0) < 0.2 and abs(n[1]) < 1e-9 and abs(n[0]) > 0.9
            return pred
        return [
            wall("S", "web", fs, either(cyl(500), cyl(502)), 2.0, None, None),
            wall("A", "rib", fs, stringer_side(-1), 1.5, 20.0, 300.0),
            wall("B", "rib", fs, stringer_side(1), 1.5, 20.0, 300.0),
        ], [["S", "A"], ["S", "B"]]
    return shape, expect


def conical_flange():
    a, lean, thick, slant = 45.0, math.radians(15.0), 1.5, 25.0
    w = thick / math.cos(lean)
    top = (260 + slant * math.sin(lean), slant * math.cos(lean))
    flange = [(260 - w, 0.0), (260.0, 0.0), top, (top[0] - w, top[1])]
    shape = fuse(revolved(rect(200, 0, 260, 2), a), revolved(flange, a))

    def expect(fs):
        # Height along the generator: the region where both sides face each
        # other, from the inner side's foot on the web (z 2) to its top.
        height = (top[1] - 2.0) / math.cos(lean)
        # Developed length: the arc of the mid-surface at the region's
        # centre (half-way up the inner side, moved half the thickness
        # along the normal, which leans down by the lean angle).
        zm = 0.5 * (2.0 + top[1]) - 0.5 * thick * math.sin(lean)
        r_mid = 260 - 0.5 * w + zm * math.tan(lean)
        return [
            wall("W", "web", fs, either(plane([0, 0, -1]), plane([0, 0, 1], 2.0)), 2.0, None, None),
            wall("F", "flange", fs, lambda f: f["kind"] == "cone", thick, height, r_mid * math.radians(a)),
        ], [["W", "F"]]
    return shape, expect


def s_curve():
    """The rib's mid-curve in plan: a B-spline through an S."""
    from OCP.OCP.collections import Array1_gp_Pnt
    from OCP.GeomAPI import GeomAPI_PointsToBSpline
    pts = Array1_gp_Pnt(1, 9)
    for i in range(9):
        x = 30.0 + 140.0 * i / 8
        pts.SetValue(i + 1, gp_Pnt(x, 50.0 + 18.0 * math.sin(2 * math.pi * (x - 30.0) / 140.0), 0.0))
    return GeomAPI_PointsToBSpline(pts, 3, 8, GeomAbs_C2, 1e-9).Curve()


def offset_curve(c, d, n=600):
    """The plan curve `c` offset by `d` to its left, as a B-spline through
    `n` points of the exact offset (within 1e-8 mm)."""
    from OCP.OCP.collections import Array1_gp_Pnt
    from OCP.GeomAPI import GeomAPI_PointsToBSpline
    t0, t1 = c.FirstParameter(), c.LastParameter()
    pts = Array1_gp_Pnt(1, n)
    for i in range(n):
        t = t0 + (t1 - t0) * i / (n - 1)
        p, v = gp_Pnt(), gp_Vec()
        c.D1(t, p, v)
        l = math.hypot(v.X(), v.Y())
        pts.SetValue(i + 1, gp_Pnt(p.X() - d * v.Y() / l, p.Y() + d * v.X() / l, 0.0))
    return GeomAPI_PointsToBSpline(pts, 3, 8, GeomAbs_C2, 1e-8).Curve()


def freeform_rib():
    from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge, BRepBuilderAPI_MakeWire
    from OCP.BRepPrimAPI import BRepPrimAPI_MakePrism
    from OCP.GCPnts import GCPnts_AbscissaPoint
    from OCP.GeomAdaptor import GeomAdaptor_Curve
    c = s_curve()
    left, right = offset_curve(c, 0.75), offset_curve(c, -0.75)
    e = lambda *a: BRepBuilderAPI_MakeEdge(*a).Edge()
    lp0, lp1 = left.Value(left.FirstParameter()), left.Value(left.LastParameter())
    rp0, rp1 = right.Value(right.FirstParameter()), right.Value(right.LastParameter())
    w = BRepBuilderAPI_MakeWire()
    for edge in (e(left), e(lp1, rp1), e(right), e(rp0, lp0)):
        w.Add(edge)
    plan = BRepBuilderAPI_MakeFace(w.Wire()).Face()
    rib = BRepPrimAPI_MakePrism(plan, gp_Vec(0, 0, 30)).Shape()
    shape = fuse(box(0, 0, 0, 200, 100, 2), rib)
    length = GCPnts_AbscissaPoint.Length_s(GeomAdaptor_Curve(c), 1e-10)

    def expect(fs):
        return [
            wall("W", "web", fs, either(plane([0, 0, -1]), plane([0, 0, 1], 2.0)), 2.0, None, None),
            wall("R", "rib", fs, lambda f: f["kind"] == "other" and f["centroid"][2] > 2.0, 1.5, 28.0, length),
        ], [["W", "R"]]
    return shape, expect


CASES = {
    "frame_r400": (frame_r400, "frame segment: 2 mm web r 400..480 over 30°, 1.6 mm flanges 25 mm tall on both curved edges"),
    "frame_r400_holes": (frame_r400_holes, "frame_r400 with a radial Ø10 hole through the outer flange and a Ø30 hole through the web"),
    "tube_and_boss": (tube_and_boss, "2 mm plate with a 1.5 mm tube Ø40 standing 28 on it and a Ø20 boss around a Ø10 hole"),
    "frame_r250": (frame_r250, "frame segment: 2.5 mm web r 250..310 over 60°, outer flange 30 tall, inner 18, both 2 mm"),
    "skin_stringers": (skin_stringers, "curved skin 2 mm (r 500) with two straight 1.5 mm stringers 20 tall inside"),
    "freeform_rib": (freeform_rib, "2 mm web with a 1.5 mm rib 28 tall along an S-curve: free-form sides, offsets of each other"),
    "conical_flange": (conical_flange, "2 mm web r 200..260 over 45° with a 1.5 mm conical flange leaning 15° outwards"),
}


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "fixtures/curved"
    os.makedirs(out, exist_ok=True)
    for name, (build, about) in CASES.items():
        shape, expect = build()
        features, connections, *holes = expect(faces(shape))
        holes = holes[0] if holes else []
        for turn in (False, True):
            s, doc_name, up = shape, name, [0, 0, 1]
            feats = json.loads(json.dumps(features))
            if turn:
                s, t = turned(shape)
                doc_name, up = name + "_turned", turn_dir(t, (0, 0, 1))
                for f in feats:
                    f["side_faces_at"] = [turn_point(t, p) for p in f["side_faces_at"]]
            hs = json.loads(json.dumps(holes))
            if turn:
                for h in hs:
                    h["faces_at"] = [turn_point(t, p) for p in h["faces_at"]]
            write(s, os.path.join(out, doc_name + ".step"))
            doc = {"part": doc_name + ".step", "about": about + ("; turned 37° about (1,2,3) and moved" if turn else ""),
                   "up": up, "features": feats, "connections": connections, "holes": hs,
                   "source": f"scripts/make_curved_fixtures.py (OpenCascade {occ_version()})"}
            json.dump(doc, open(os.path.join(out, doc_name + ".expected.json"), "w"), indent=1)
            print(doc_name, len(feats), "walls")


if __name__ == "__main__":
    main()
