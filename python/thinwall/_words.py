"""Keyword arguments to the command line's words.

Each keyword is the flag of the same name (``tool_diameter`` is
``--tool-diameter``), so the command line's parser and rules decide what a
value means and which values are wrong: the same value gives the same
result, or the same error, through the CLI, the C ABI and here.
"""
from __future__ import annotations

import os
from typing import Any, Iterable, List

#: Keywords that would change the command line's output, not the question.
RESERVED = ("format", "output", "o", "verbose")


def _number(v: Any) -> str:
    if isinstance(v, bool):
        raise TypeError(f"expected a number, got {v!r}")
    return repr(float(v)) if isinstance(v, float) else str(v)


def _vector(v: Any) -> str:
    if isinstance(v, str):
        return v
    items = list(v)
    return ",".join(_number(x) for x in items)


def _is_vector(v: Any) -> bool:
    return (
        isinstance(v, (tuple, list))
        and len(v) == 3
        and all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in v)
    )


def flag_words(name: str, value: Any) -> List[str]:
    """The words of one keyword argument (none for ``None`` or ``False``)."""
    if name in RESERVED:
        raise TypeError(f"'{name}' is not an argument here: results are always the JSON contract")
    flag = "--" + name.replace("_", "-")
    if value is None or value is False:
        return []
    if value is True:
        return [flag]
    if isinstance(value, (str, os.PathLike)):
        return [f"{flag}={os.fspath(value)}"]
    if isinstance(value, (int, float)):
        return [f"{flag}={_number(value)}"]
    if _is_vector(value):
        return [f"{flag}={_vector(value)}"]
    if name in ("include", "exclude"):
        return [f"{flag}={','.join(str(k) for k in value)}"]
    if name == "before":
        return [f"{flag}={a}:{b}" for a, b in value]
    if isinstance(value, (tuple, list)):
        # Repeated flags: several ups (set-ups in turn), several volumes.
        out: List[str] = []
        for item in value:
            out += flag_words(name, item)
        return out
    raise TypeError(f"{name}: cannot pass {type(value).__name__} {value!r}")


def words(command: str, positional: Iterable[str], options: dict) -> List[str]:
    """``command``, its positional words, then every option's flag."""
    out = [command, *positional]
    for name, value in options.items():
        out += flag_words(name, value)
    return out
