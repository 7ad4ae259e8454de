"""Every face a result names carries its ordinal in OpenCascade's face
order: on every shared part and fixture, the face OpenCascade numbers with
that ordinal is the one made from the same STEP entity (in the same placed
instance of its body), so its centroid and area are that face's."""
from __future__ import annotations

import math

import pytest

import thinwall
from conftest import FIXTURES, ROOT, SHARED, OccPart

PARTS = FIXTURES + SHARED


def _name(p):
    return str(p.relative_to(ROOT.parent))


def _size(faces):
    lo = [min(c[i] for _, c in faces) for i in range(3)]
    hi = [max(c[i] for _, c in faces) for i in range(3)]
    return max(1.0, math.dist(lo, hi))


@pytest.mark.parametrize("path", PARTS, ids=_name)
def test_each_features_faces_are_the_same_faces_of_the_opencascade_shape(path):
    try:
        result = thinwall.recognize(str(path), no_reach=True, allow_open=True)
    except thinwall.InputError as e:
        # A part Thinwall refuses (tessellated only) has no faces to map.
        assert e.code.startswith("read."), e
        return
    occ = OccPart(path)
    ours = result.occ_faces
    assert len(ours) == len(occ.faces), "OpenCascade numbers another count of faces"
    props = [OccPart.props(f) for f in occ.faces]
    size = _size(props)
    named = {f for feature in result for f in feature.faces}
    inspected = {(r["body"], r["step_id"]): r for r in thinwall.inspect(str(path)).to_dict()["faces"]}
    for face in sorted(named, key=lambda f: f.occ_index):
        i = face.occ_index
        assert occ.labels[i] == face.step_id, (face, occ.labels[i])
        # Among OpenCascade's faces made from this entity (one per placed
        # instance of the body), ours is the one nearest our own centroid.
        same = [k for k, label in enumerate(occ.labels) if label == face.step_id]
        centroid = inspected[(face.body, face.step_id)]["centroid"]
        nearest = min(same, key=lambda k: math.dist(props[k][1], centroid))
        area, c = props[i]
        area_n, c_n = props[nearest]
        assert abs(area - area_n) <= 1e-6 * size and math.dist(c, c_n) <= 1e-6 * size, face
