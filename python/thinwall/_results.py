"""Typed results over the command line's JSON.

A result wraps the JSON document of its command (``to_dict()`` gives it
back, unchanged) and names what a caller reaches for: its features, their
faces. A face is a :class:`Face`: its STEP entity id, its body and its
ordinal in OpenCascade's face order (``occ_index``), read from the
document's ``opencascade_faces``.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Dict, Iterator, List, Optional, Sequence, Tuple


@dataclass(frozen=True)
class Face:
    """A face of the part, as results name it.

    ``occ_index`` is its position in ``TopExp::MapShapes(shape, TopAbs_FACE)``
    over the shape OpenCascade reads from the same file (from 0: FreeCAD's
    ``Shape.Faces[occ_index]``); ``None`` for a part not read from STEP.
    """

    step_id: int
    body: int
    occ_index: Optional[int]


class Faces:
    """The part's faces by (body, STEP id), from ``opencascade_faces``."""

    def __init__(self, doc: Dict[str, Any]):
        self._by_key: Dict[Tuple[int, int], Face] = {}
        self._by_id: Dict[int, Face] = {}
        self.ordered: List[Optional[Face]] = []
        for i, key in enumerate(doc.get("opencascade_faces") or []):
            face = None if key is None else Face(key["step_id"], key["body"], i)
            self.ordered.append(face)
            if face is not None:
                self._by_key[(face.body, face.step_id)] = face
                self._by_id.setdefault(face.step_id, face)

    def get(self, step_id: int, body: Optional[int] = None) -> Face:
        """The face ``step_id`` of ``body`` (the first body holding it when
        the record names no body)."""
        if body is not None:
            found = self._by_key.get((body, step_id))
        else:
            found = self._by_id.get(step_id)
        if found is None:
            return Face(step_id, 0 if body is None else body, None)
        return found


class Record:
    """One object of a result's JSON: its fields as attributes."""

    def __init__(self, data: Dict[str, Any], faces: Faces):
        self._data = data
        self._faces = faces

    def __getattr__(self, name: str) -> Any:
        try:
            return self._data[name]
        except KeyError:
            raise AttributeError(f"{type(self).__name__} has no field '{name}'") from None

    def __getitem__(self, name: str) -> Any:
        return self._data[name]

    def get(self, name: str, default: Any = None) -> Any:
        return self._data.get(name, default)

    def resolve(self, field: str) -> Tuple[Face, ...]:
        """The faces a field of STEP ids names (``faces``, ``side_faces``,
        ``bottom_faces``, …), in its order."""
        body = self._data.get("body")
        return tuple(self._faces.get(i, body) for i in self._data.get(field) or [])

    @property
    def faces(self) -> Tuple[Face, ...]:
        """The faces it is made of."""
        return self.resolve("faces")

    def to_dict(self) -> Dict[str, Any]:
        return self._data

    def __repr__(self) -> str:
        ident = self._data.get("id", "")
        kind = self._data.get("kind", "")
        return f"<{type(self).__name__} {ident} {kind}>".replace("  ", " ")


class Feature(Record):
    """A stiffness feature (web, rib, flange, hole, …) or a machining
    feature (pocket, slot, hole, …, or a plan's removal volume)."""

    def __repr__(self) -> str:
        d = self._data
        bits = [str(d.get("id", "?")), str(d.get("kind", d.get("size_class", "")))]
        if d.get("thickness") is not None:
            bits.append(f"t {d['thickness']:g} mm")
        if d.get("thin") is True:
            bits.append("thin")
        n = len(d.get("faces") or [])
        bits.append(f"{n} face{'s' if n != 1 else ''}")
        return f"<Feature {' '.join(bits)}>"


class FaceReach(Record):
    """How much of a face a tool reaches (``access``)."""

    @property
    def face(self) -> Face:
        return self._faces.get(self._data["face"], self._data.get("body"))

    @property
    def faces(self) -> Tuple[Face, ...]:
        return (self.face,)

    def __repr__(self) -> str:
        d = self._data
        return f"<FaceReach #{d['face']} {d.get('contact', '')} {d.get('fraction', 0):.3f}>"


class Result:
    """A command's result: its JSON document, typed access to its parts."""

    #: The document's list that iteration goes over.
    _items: Sequence[str] = ()
    _record = Record

    def __init__(self, doc: Dict[str, Any]):
        self._doc = doc
        self._index = Faces(doc)

    def to_dict(self) -> Dict[str, Any]:
        """The command line's JSON document (its contract, `docs/schema`)."""
        return self._doc

    @property
    def schema(self) -> str:
        return self._doc.get("schema", "")

    @property
    def occ_faces(self) -> List[Optional[Face]]:
        """The part's faces in OpenCascade's order (``None`` where a face is
        a supplemental surface model's)."""
        return self._index.ordered

    def face(self, step_id: int, body: Optional[int] = None) -> Face:
        return self._index.get(step_id, body)

    def _records(self, key: str, cls: type = Record) -> List[Any]:
        return [cls(d, self._index) for d in self._doc.get(key) or []]

    def __iter__(self) -> Iterator[Any]:
        for key in self._items:
            yield from self._records(key, self._record)

    def __len__(self) -> int:
        return sum(len(self._doc.get(k) or []) for k in self._items)

    @property
    def faces(self) -> Tuple[Face, ...]:
        """Every face the result's items name, each once, in item order."""
        seen: Dict[Face, None] = {}
        for item in self:
            for f in item.faces:
                seen.setdefault(f, None)
        return tuple(seen)

    def _title(self) -> str:
        return str(self._doc.get("part") or self._doc.get("file") or "")

    def __repr__(self) -> str:
        return f"<{type(self).__name__} {self._title()!r}: {len(self)} items>"


def _count_by_kind(items: List[Record]) -> str:
    counts: Dict[str, int] = {}
    for f in items:
        k = str(f.get("kind", "?"))
        counts[k] = counts.get(k, 0) + 1
    return ", ".join(f"{k} {n}" for k, n in sorted(counts.items()))


class Recognition(Result):
    """``recognize``: stiffness features, connections, machining features.
    Iterating gives the stiffness features, then the machining features."""

    _items = ("stiffness_features", "machining_features")
    _record = Feature

    @property
    def stiffness_features(self) -> List[Feature]:
        return self._records("stiffness_features", Feature)

    @property
    def machining_features(self) -> List[Feature]:
        return self._records("machining_features", Feature)

    @property
    def connections(self) -> List[Dict[str, Any]]:
        return list(self._doc.get("connections") or [])

    def _title(self) -> str:
        return str(self._doc.get("part", {}).get("file", ""))

    def __repr__(self) -> str:
        s, m = self.stiffness_features, self.machining_features
        return (
            f"<Recognition {self._title()!r}: {len(s)} stiffness features ({_count_by_kind(s)}), "
            f"{len(m)} machining features ({_count_by_kind(m)})>"
        )

    def __str__(self) -> str:
        lines = [repr(self)]
        lines += [f"  {f!r}" for f in self]
        lines += [f"  {_connection(c)}" for c in self.connections]
        return "\n".join(lines)


def _connection(c: Dict[str, Any]) -> str:
    if c.get("kind") == "base_leaf":
        return f"{c['leaf']} on {c['base']}"
    if c.get("kind") == "crossing":
        return " crosses ".join(c.get("features", []))
    return str(c)


class Plan(Result):
    """``plan``: the stiffness features' sequence, the walls' step approach,
    the removal's machining features. Iterating gives the machining
    features (removal volumes)."""

    _items = ("machining_features",)
    _record = Feature

    @property
    def machining_features(self) -> List[Feature]:
        return self._records("machining_features", Feature)

    @property
    def stiffness_features(self) -> List[Record]:
        return self._records("stiffness_features")


class Access(Result):
    """``access``: every face's reach; iterating gives the faces."""

    _items = ("faces",)
    _record = FaceReach


class Operations(Result):
    """``operations``: iterating gives the first set-up's operations."""

    def __iter__(self) -> Iterator[Record]:
        for d in (self._doc.get("setup") or {}).get("operations") or []:
            yield Record(d, self._index)

    def __len__(self) -> int:
        return len((self._doc.get("setup") or {}).get("operations") or [])


class Classification(Result):
    """``classify``: iterating gives the volumes' classifications."""

    _items = ("volumes",)


class Inspection(Result):
    """``inspect``: the part's bodies, faces and edges; iterating gives the
    faces."""

    _items = ("faces",)

    def __iter__(self) -> Iterator[Record]:
        for d in self._doc.get("faces") or []:
            yield _FaceRecord(d, self._index)


class _FaceRecord(Record):
    @property
    def faces(self) -> Tuple[Face, ...]:
        return (self._faces.get(self._data["step_id"], self._data.get("body")),)


class WallSizing(Result):
    """``size_wall``: a thin wall's machining-feature sizes."""

    def __len__(self) -> int:
        return 0

    def __repr__(self) -> str:
        return f"<WallSizing {self._doc}>"
