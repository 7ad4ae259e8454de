"""Thinwall on a shape already in an OpenCascade host (OCP, CadQuery,
build123d, pythonOCC through OCP): the shape is written to STEP in memory
and read from there, so every face a result names carries the ordinal of
that face among the shape's own (``TopExp::MapShapes(shape, TopAbs_FACE)``,
from 0: :func:`faces` lists them in that order).

Needs OpenCascade's Python binding OCP (``pip install cadquery-ocp-novtk``).
"""
from __future__ import annotations

import io
from typing import Any, List

import thinwall

try:
    from OCP.Message import Message, Message_Gravity
    from OCP.STEPControl import STEPControl_AsIs, STEPControl_Writer
    from OCP.IFSelect import IFSelect_RetDone
    from OCP.TopAbs import TopAbs_FACE
    from OCP.TopExp import TopExp
    from OCP.TopoDS import TopoDS, TopoDS_Shape
    from OCP.OCP.collections import (
        IndexedMap_TopoDS_Shape_TopTools_ShapeMapHasher as _ShapeMap,
    )
except ImportError as e:  # pragma: no cover - depends on the environment
    raise ImportError(
        "thinwall.occ needs OpenCascade's Python binding: pip install cadquery-ocp-novtk"
    ) from e


def shape_of(obj: Any) -> TopoDS_Shape:
    """The OCP shape of an OCP shape, a CadQuery Shape or Workplane, or a
    build123d object (their ``wrapped`` shape)."""
    if isinstance(obj, TopoDS_Shape):
        return obj
    if hasattr(obj, "val") and callable(obj.val):  # a CadQuery Workplane
        obj = obj.val()
    wrapped = getattr(obj, "wrapped", None)
    if isinstance(wrapped, TopoDS_Shape):
        return wrapped
    raise TypeError(f"not an OpenCascade shape: {type(obj).__name__}")


def faces(obj: Any) -> List[Any]:
    """The shape's faces in OpenCascade's order: ``faces(shape)[f.occ_index]``
    is the face a result names as ``f``."""
    m = _ShapeMap()
    TopExp.MapShapes_s(shape_of(obj), TopAbs_FACE, m)
    return [TopoDS.Face(m.FindKey(i)) for i in range(1, m.Extent() + 1)]


def _quiet() -> None:
    """OpenCascade's STEP writer prints statistics on stdout unless told."""
    printers = Message.DefaultMessenger_s().Printers()
    for p in printers:
        p.SetTraceLevel(Message_Gravity.Message_Fail)


def step_bytes(obj: Any) -> bytes:
    """The shape as STEP text (AP214, millimetres), written in memory."""
    _quiet()
    writer = STEPControl_Writer()
    if writer.Transfer(shape_of(obj), STEPControl_AsIs) != IFSelect_RetDone:
        raise thinwall.UsageError("OpenCascade could not transfer the shape to STEP")
    buf = io.BytesIO()
    if writer.WriteStream(buf) != IFSelect_RetDone:
        raise thinwall.UsageError("OpenCascade could not write the shape as STEP")
    return buf.getvalue()


def part(obj: Any, name: str = "<shape>") -> thinwall.Part:
    """The shape as a part whose results' face ordinals index
    :func:`faces` of it."""
    read = thinwall.read(step_bytes(obj), name=name)
    expected = len(faces(obj))
    if read.occ_face_count != expected:
        raise thinwall.InputError(
            f"{name}: the shape has {expected} faces, its STEP text {read.occ_face_count}: "
            "its face ordinals would not index the shape's faces"
        )
    return read


def recognize(obj: Any, **options: Any) -> thinwall.Recognition:
    """:func:`thinwall.recognize` of a shape."""
    return thinwall.recognize(part(obj), **options)


def plan(obj: Any, **options: Any) -> thinwall.Plan:
    return thinwall.plan(part(obj), **options)


def operations(obj: Any, **options: Any) -> thinwall.Operations:
    return thinwall.operations(part(obj), **options)


def access(obj: Any, **options: Any) -> thinwall.Access:
    return thinwall.access(part(obj), **options)
