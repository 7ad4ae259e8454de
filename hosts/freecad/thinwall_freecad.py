"""Thinwall in FreeCAD: recognize a solid, colour its faces by feature kind,
list its features and connections, select a feature's faces.

FreeCAD numbers a shape's faces as OpenCascade does (``Shape.Faces``), and
every face a Thinwall result names carries that ordinal (``occ_index``), so
the colours land on FreeCAD's own faces without any guessing. The shape is
written to STEP and read by Thinwall; nothing is changed but the object's
colours and two properties (``ThinwallKinds``, ``ThinwallColors``: per
face, the kind that coloured it and its colour), which also hold the result
where no 3D view is (``freecadcmd``).

Used by the macro ``ThinwallFeatures.FCMacro`` (GUI) and by tests
(``python/tests/test_freecad.py``, under ``freecadcmd``).
"""
from __future__ import annotations

import os
import tempfile
from typing import Any, List, Optional, Sequence, Tuple

import thinwall

Colour = Tuple[float, float, float, float]
#: A face no feature lists.
OTHER = "other"


def _rgb(hex_colour: str) -> Colour:
    h = hex_colour.lstrip("#")
    return (int(h[0:2], 16) / 255.0, int(h[2:4], 16) / 255.0, int(h[4:6], 16) / 255.0, 0.0)


def face_kinds(result: "thinwall.Recognition", faces: int) -> List[str]:
    """Per face (FreeCAD's order), the kind that colours it: the last
    stiffness feature listing it (``stiffness.web``), else the last
    machining feature (``machining.hole``), else ``other``."""
    kinds = [OTHER] * faces
    stiff = [False] * faces
    for f in result.stiffness_features:
        for face in f.faces:
            kinds[face.occ_index] = f"stiffness.{f.kind}"
            stiff[face.occ_index] = True
    for f in result.machining_features:
        for face in f.faces:
            if not stiff[face.occ_index]:
                kinds[face.occ_index] = f"machining.{f.kind}"
    return kinds


def colours(kinds: Sequence[str]) -> List[Colour]:
    """Thinwall's picture colours of the kinds (grey for ``other``)."""
    table = thinwall.palette()
    grey = "#cdcdcd"
    return [_rgb(table.get(k, grey)) for k in kinds]


def shape_part(shape: Any) -> "thinwall.Part":
    """A FreeCAD ``Part.Shape`` as a Thinwall part (through a temporary STEP
    file, FreeCAD's own ``exportStep``), its face ordinals FreeCAD's."""
    fd, path = tempfile.mkstemp(suffix=".step")
    os.close(fd)
    try:
        shape.exportStep(path)
        with open(path, "rb") as f:
            part = thinwall.read(f.read(), name="<FreeCAD shape>")
    finally:
        os.unlink(path)
    if part.occ_face_count != len(shape.Faces):
        raise thinwall.InputError(
            f"the shape has {len(shape.Faces)} faces, its STEP text {part.occ_face_count}"
        )
    return part


def recognize_shape(shape: Any, **options: Any) -> "thinwall.Recognition":
    """Recognize a FreeCAD ``Part.Shape``."""
    return thinwall.recognize(shape_part(shape), **options)


def colour_object(obj: Any, result: "thinwall.Recognition") -> List[str]:
    """Colour ``obj``'s faces by feature kind (in the 3D view when there is
    one) and keep the kinds and colours in its properties; the kinds."""
    kinds = face_kinds(result, len(obj.Shape.Faces))
    cols = colours(kinds)
    if "ThinwallKinds" not in obj.PropertiesList:
        obj.addProperty("App::PropertyStringList", "ThinwallKinds", "Thinwall", "Feature kind per face")
        obj.addProperty("App::PropertyColorList", "ThinwallColors", "Thinwall", "Colour per face")
    obj.ThinwallKinds = kinds
    obj.ThinwallColors = cols
    view = getattr(obj, "ViewObject", None)
    if view is not None:
        view.DiffuseColor = cols
    return kinds


def feature_faces(feature: Any) -> List[str]:
    """FreeCAD's names of a feature's faces (``Face1``, …) for selection."""
    return [f"Face{face.occ_index + 1}" for face in feature.faces]


def recognize_object(obj: Any, up: Optional[Sequence[float]] = None, **options: Any) -> "thinwall.Recognition":
    """Recognize a document object's solid, colour it, and return the
    result (``up``: the set-up's tool axis, +Z by default)."""
    if up is not None:
        options["up"] = tuple(up)
    result = recognize_shape(obj.Shape, **options)
    colour_object(obj, result)
    return result
