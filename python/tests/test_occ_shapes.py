"""`thinwall.occ`: a shape in an OpenCascade host, recognized through STEP
written in memory; every feature's face ordinals index the host shape's own
faces (`thinwall.occ.faces(shape)`), checked by geometry against the same
face read back from the STEP text."""
from __future__ import annotations

import math

import pytest

import thinwall
from conftest import FIXTURES, ROOT, OccPart

occ = pytest.importorskip("thinwall.occ")


def _pocketed_block():
    from OCP.BRepAlgoAPI import BRepAlgoAPI_Cut
    from OCP.BRepFilletAPI import BRepFilletAPI_MakeFillet
    from OCP.BRepPrimAPI import BRepPrimAPI_MakeBox, BRepPrimAPI_MakeCylinder
    from OCP.TopAbs import TopAbs_EDGE
    from OCP.TopExp import TopExp_Explorer
    from OCP.TopoDS import TopoDS
    from OCP.gp import gp_Ax2, gp_Dir, gp_Pnt

    block = BRepPrimAPI_MakeBox(120.0, 80.0, 20.0).Shape()
    pocket = BRepPrimAPI_MakeBox(gp_Pnt(10, 10, 4), 100.0, 60.0, 30.0).Shape()
    pocket_f = BRepFilletAPI_MakeFillet(pocket)
    e = TopExp_Explorer(pocket, TopAbs_EDGE)
    while e.More():
        pocket_f.Add(5.0, TopoDS.Edge(e.Current()))
        e.Next()
    cut = BRepAlgoAPI_Cut(block, pocket_f.Shape()).Shape()
    hole = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(60, 40, -1), gp_Dir(0, 0, 1)), 4.0, 10.0).Shape()
    return BRepAlgoAPI_Cut(cut, hole).Shape()


def _two_bodies():
    from OCP.BRep import BRep_Builder
    from OCP.BRepPrimAPI import BRepPrimAPI_MakeBox
    from OCP.TopoDS import TopoDS_Compound
    from OCP.gp import gp_Pnt

    c = TopoDS_Compound()
    b = BRep_Builder()
    b.MakeCompound(c)
    b.Add(c, BRepPrimAPI_MakeBox(50.0, 40.0, 3.0).Shape())
    b.Add(c, BRepPrimAPI_MakeBox(gp_Pnt(0, 60, 0), 50.0, 3.0, 40.0).Shape())
    return c


def _read(rel):
    return OccPart(ROOT / rel).shape


class Wrapped:
    """What CadQuery's and build123d's objects look like: a `wrapped` shape."""

    def __init__(self, shape):
        self.wrapped = shape


SHAPES = {
    "pocketed block with fillets and a hole": _pocketed_block,
    "two bodies": _two_bodies,
    "rib-grid panel read by OpenCascade": lambda: _read("fixtures/recognition/rib_grid_panel.step"),
    "countersunk holes read by OpenCascade": lambda: _read(
        next(str(p.relative_to(ROOT)) for p in FIXTURES if "holes" in str(p))
    ),
    "a wrapped shape (CadQuery, build123d)": lambda: Wrapped(_pocketed_block()),
}


@pytest.mark.parametrize("name", list(SHAPES))
def test_face_ordinals_index_the_host_shapes_faces(tmp_path, name):
    shape = SHAPES[name]()
    faces = occ.faces(shape)
    result = occ.recognize(shape, up=(0, 0, 1))
    assert len(result.occ_faces) == len(faces)
    # The same STEP text read back by OpenCascade: its faces are made from
    # the entities our results name.
    path = tmp_path / "shape.step"
    path.write_bytes(occ.step_bytes(shape))
    back = OccPart(path)
    props = [OccPart.props(f) for f in faces]
    size = max(1.0, max(math.dist(a[1], b[1]) for a in props for b in props))
    named = [f for feature in result for f in feature.faces]
    assert named, "the shape has features"
    for face in named:
        assert back.labels[face.occ_index] == face.step_id
        area, c = props[face.occ_index]
        area_b, c_b = OccPart.props(back.faces[face.occ_index])
        assert abs(area - area_b) <= 1e-6 * size and math.dist(c, c_b) <= 1e-6 * size, face


def test_the_pocket_keeps_its_corner_radius_and_the_hole_its_face():
    shape = _pocketed_block()
    r = occ.recognize(shape, up=(0, 0, 1))
    kinds = sorted(m.kind for m in r.machining_features)
    assert "pocket" in kinds and "hole" in kinds, kinds
    hole = next(m for m in r.machining_features if m.kind == "hole")
    face = occ.faces(shape)[hole.faces[0].occ_index]
    from OCP.BRepAdaptor import BRepAdaptor_Surface
    from OCP.GeomAbs import GeomAbs_Cylinder

    s = BRepAdaptor_Surface(face)
    assert s.GetType() == GeomAbs_Cylinder and abs(s.Cylinder().Radius() - 4.0) < 1e-9


def test_not_a_shape_is_a_type_error():
    with pytest.raises(TypeError):
        occ.part(object())
