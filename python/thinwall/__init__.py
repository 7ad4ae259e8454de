"""Thinwall: stiffness features, machining features and machining plans of
thin-walled parts, from STEP.

Each function is one command of the ``thinwall`` command line, its keyword
arguments that command's flags (``tool_diameter=10`` is ``--tool-diameter
10``); each returns a typed result whose ``to_dict()`` is the command line's
JSON. A part is a path, STEP bytes, or a :class:`Part` read once with
:func:`read` and given to several commands. Work runs with the GIL released.

>>> import thinwall
>>> r = thinwall.recognize("fixtures/recognition/rib_grid_panel.step", up=(0, 0, 1))
>>> [f.kind for f in r.stiffness_features][:2]
['web', 'rib']
>>> r.stiffness_features[0].faces[0].occ_index   # the face's index in OpenCascade's order
3
"""
from __future__ import annotations

import json
import os
from typing import Any, Dict, Iterable, Optional, Sequence, Tuple, Union

from . import _native
from ._native import InputError, InternalError, Part, ThinwallError, UsageError
from ._results import (
    Access,
    Classification,
    Face,
    FaceReach,
    Feature,
    Inspection,
    Operations,
    Plan,
    Recognition,
    Record,
    Result,
    WallSizing,
)
from ._words import words

__all__ = [
    "Access", "Classification", "Face", "FaceReach", "Feature", "InputError", "Inspection",
    "InternalError", "Operations", "Part", "Plan", "Recognition", "Record", "Result",
    "ThinwallError", "UsageError", "WallSizing", "access", "classify", "inspect", "operations",
    "palette", "plan", "read", "recognize", "size_wall", "__version__",
]

__version__ = _native.version()


def palette() -> Dict[str, str]:
    """The colours of Thinwall's pictures by name (``stiffness.web``,
    ``machining.hole``, …) as ``#rrggbb``, for a host to colour alike."""
    return _native.palette()

#: What a command takes as its part.
PartLike = Union[Part, str, "os.PathLike[str]", bytes]


def read(source: PartLike, *, name: Optional[str] = None) -> Part:
    """Read a part once (a path, or STEP text as bytes named ``name``) to
    give it to several commands."""
    if isinstance(source, Part):
        return source
    if isinstance(source, (bytes, bytearray, memoryview)):
        return Part.from_bytes(bytes(source), name or "<bytes>")
    if isinstance(source, (str, os.PathLike)):
        return Part.from_path(os.fspath(source))
    raise TypeError(f"a part is a path, bytes or a thinwall.Part, not {type(source).__name__}")


def _on(part: PartLike) -> Tuple[str, Optional[Part]]:
    """The part's word on the command line, and the part when it is read."""
    if isinstance(part, (str, os.PathLike)):
        return os.fspath(part), None
    p = read(part)
    return p.name, p


def _run(command: str, part: Optional[PartLike], options: dict, positional: bool = True) -> Any:
    if part is None:
        return json.loads(_native.run(words(command, [], options)))
    word, read_part = _on(part)
    head = [word] if positional else []
    if not positional:
        options = {"part": word, **options}
    return json.loads(_native.run(words(command, head, options), read_part))


def recognize(part: PartLike, **options: Any) -> Recognition:
    """Stiffness features (webs, ribs, flanges, walls; holes, cut-outs,
    notches, fillets, chamfers), their connections in the set-up, the reach
    of every wall side, and the machining features. Options: ``up``,
    ``machine``, ``tilt_limit``, ``include``, ``exclude``, ``force``,
    ``allowed_deflection``, ``tool_diameter``, ``connect_thick``,
    ``allow_open``, ``stock``, ``stock_offset``, ``cutting_length``,
    ``holder_diameter``, ``no_reach``, ``config``, ``time_limit``."""
    return Recognition(_run("recognize", part, options))


def plan(part: PartLike, **options: Any) -> Plan:
    """The machining plan: sequence constraints, the walls' step approach,
    the removal's machining features. ``up`` may be several ups (set-ups
    in turn); without one the set-ups are proposed. Options as
    :func:`recognize`, and ``rules`` (a TOML file)."""
    return Plan(_run("plan", part, options))


def operations(part: PartLike, **options: Any) -> Operations:
    """Operations of the set-ups: layers, tools, finishing, holes. Options:
    ``up`` (one or several), ``tools``, ``axial_depth``, ``min_share``,
    ``by_feature``, ``both_sides``, ``choose_up``, ``time_limit``."""
    return Operations(_run("operations", part, options))


def access(part: PartLike, **options: Any) -> Access:
    """Reach of every face by a tool and its holder, and flank milling.
    Options: ``up``, ``machine``, ``tilt_limit``, ``tool_diameter``,
    ``cutting_length``, ``holder_diameter``, ``tool_radius``,
    ``threshold``, ``time_limit``."""
    return Access(_run("access", part, options))


def inspect(part: PartLike, **options: Any) -> Inspection:
    """The part's bodies, faces, edges and their convexity."""
    return Inspection(_run("inspect", part, options))


def classify(
    part: PartLike,
    volumes: Iterable[Union[str, "os.PathLike[str]"]],
    *,
    before: Sequence[Tuple[int, int]] = (),
    **options: Any,
) -> Classification:
    """Classify removal volumes (STEP solids, by path) against the part;
    ``before`` pairs ``(a, b)``: volume a is removed before volume b."""
    options = {"volume": [os.fspath(v) for v in volumes], "before": list(before), **options}
    return Classification(_run("classify", part, options, positional=False))


def size_wall(**options: Any) -> WallSizing:
    """A thin wall's machining-feature sizes (B_RF, h_RF, H_RF) by the
    step-approach model: ``length``, ``thickness``, ``height`` (mm),
    ``milling`` ('peripheral' or 'face') and the model's parameters."""
    return WallSizing(_run("size-wall", None, options))
