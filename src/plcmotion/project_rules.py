"""Limits and value rules of project files that are checked before any object is built.

A project file is input like any other: a 50 MB file or a cam with a million points must give a clear
message at once, not minutes of work and gigabytes of memory.  The limits are far above what a real
machine needs and are checked on the parsed document before technology objects are created:

* ``MAX_FILE_BYTES``, ``MAX_LINES``: size of the project file (checked before parsing).
* ``MAX_OBJECTS``: technology objects of all kinds (axes, encoders, proxies, cams, command tables).
* ``MAX_LIST``: length of any other list (trace signals, leading values, segments of a file).
* ``MAX_DEPTH``: nesting of tables and lists (a tag path has at most four levels).
* cams: at most 1000 points and 50 segments (S7-1500T V5 §6.2.5.7); command tables: 32 steps
  (S7-1200 V6 §12.10.8.1).

The cam rules: every value a finite number within +-1.0E12 (the LREAL range of the cam tags), the
points in strictly increasing leading value.  The manual lets a later point with the same leading
value win (§6.2.5.7), but in a file that only hides a typing error, so a file must not rely on it;
a segment needs xmax > xmin.
"""
from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any, Iterator

from .kernel.cam import MAX_POINTS as MAX_CAM_POINTS
from .kernel.cam import MAX_SEGMENTS as MAX_CAM_SEGMENTS

MAX_FILE_BYTES = 2 * 1024 * 1024
MAX_LINES = 50_000             # tomllib needs some microseconds per line: bounds the parse to about a second
MAX_OBJECTS = 1000
MAX_LIST = 4096
MAX_DEPTH = 12
CAM_LIMIT = 1.0e12
OBJECT_SECTIONS = ("axes", "cams", "command_tables")


def _number(v: Any) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def size_problems(doc: Mapping[str, Any]) -> list[tuple[str, str]]:
    """``(key, message)`` for every limit the parsed document exceeds (cheap: one walk, no objects)."""
    problems: list[tuple[str, str]] = []
    objects = sum(len(doc[s]) for s in OBJECT_SECTIONS if isinstance(doc.get(s), dict))
    if objects > MAX_OBJECTS:
        problems.append((", ".join(OBJECT_SECTIONS),
                         f"{objects} technology objects; allowed: at most {MAX_OBJECTS} in one project"))
    for key, depth, value in _walk(doc):
        if depth > MAX_DEPTH:
            problems.append((key, f"nested {depth} levels deep; allowed: at most {MAX_DEPTH}"))
            break
        if isinstance(value, list) and len(value) > MAX_LIST:
            problems.append((key, f"a list of {len(value)} items; allowed: at most {MAX_LIST}"))
    return problems


def _walk(doc: Mapping[str, Any]) -> Iterator[tuple[str, int, Any]]:
    """``(key path, depth, value)`` of every table and list, iteratively (no recursion limit)."""
    stack: list[tuple[str, int, Any]] = [("", 0, doc)]
    while stack:
        key, depth, value = stack.pop()
        yield key, depth, value
        if depth > MAX_DEPTH:
            continue
        if isinstance(value, Mapping):
            stack.extend((f"{key}.{k}" if key else str(k), depth + 1, v) for k, v in value.items()
                         if isinstance(v, (Mapping, list)))
        elif isinstance(value, list) and len(value) <= MAX_LIST:
            stack.extend((f"{key}[{i}]", depth + 1, v) for i, v in enumerate(value) if isinstance(v, (Mapping, list)))


def point_problem(points: list[Any]) -> tuple[int | None, str] | None:
    """The first point that breaks the cam rules as ``(index, allowed)`` (0-based; None: the number of
    points), else None."""
    if len(points) > MAX_CAM_POINTS:
        return None, f"at most {MAX_CAM_POINTS} points in a cam (S7-1500T V5 §6.2.5.7)"
    last = -math.inf
    for i, p in enumerate(points):
        if not (isinstance(p, (list, tuple)) and len(p) == 2 and all(_number(v) for v in p)):
            return i, "an [x, y] pair of numbers"
        x, y = p
        if not (abs(x) <= CAM_LIMIT and abs(y) <= CAM_LIMIT):     # False for nan and inf, exact for 10**400
            return i, f"finite numbers within +-{CAM_LIMIT:g}"
        if not x > last:
            return i, (f"a leading value above the one before ({last!r}): points in strictly increasing leading "
                       f"value, each leading value once")
        last = x
    return None


def segment_problem(segments: list[Any], fields: tuple[str, ...]) -> tuple[int | None, str] | None:
    """The first segment that breaks the cam rules as ``(index, allowed)`` (None: the number), else None."""
    if len(segments) > MAX_CAM_SEGMENTS:
        return None, f"at most {MAX_CAM_SEGMENTS} segments in a cam (S7-1500T V5 §6.2.5.7)"
    for i, sg in enumerate(segments):
        if not isinstance(sg, dict) or not set(sg) <= set(fields):
            return i, "a table with " + ", ".join(fields)
        if not all(_number(v) and abs(v) <= CAM_LIMIT for v in sg.values()):
            return i, f"finite numbers within +-{CAM_LIMIT:g}"
        if not sg.get("xmax", 0.0) > sg.get("xmin", 0.0):
            return i, "xmax greater than xmin"
    return None


__all__ = ["MAX_CAM_POINTS", "MAX_CAM_SEGMENTS", "MAX_DEPTH", "MAX_FILE_BYTES", "MAX_LINES", "MAX_LIST", "MAX_OBJECTS",
           "point_problem", "segment_problem", "size_problems"]
