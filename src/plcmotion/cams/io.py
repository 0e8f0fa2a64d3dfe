"""Point-list export and import of cams (S7-1500T V5 §6.2.7).

The cam editor exports a "point list": the cam sampled at 0 to 1E5 (default 360) equally spaced
leading values, optionally with the velocity, acceleration and jerk curves, separated by comma or tab.
The manual does not give the file layout; here it is one header row (``leading,following[,velocity]
[,acceleration][,jerk]``) and one row per sample, numbers written with 17 significant digits so that an
import gives back exactly the exported values.

The import reads such files tolerantly (comma or tab, optional header, blank lines, ``#`` comments,
decimal points) and rejects anything else with the file name and line number: the manual warns that
a corrupt file can make the axes move unexpectedly, so nothing is guessed.
"""
from __future__ import annotations

import math
import os
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from ..kernel.cam import CamCurve

MAX_EXPORT_POINTS = 100_000
DEFAULT_EXPORT_POINTS = 360
DERIVATIVES = ("velocity", "acceleration", "jerk")
_DELIMITERS = {",": ",", "comma": ",", "\t": "\t", "tab": "\t"}


class PointListError(ValueError):
    """A malformed point-list file; ``path`` and ``line`` (1-based, None for the whole file) say where."""

    def __init__(self, path: str, line: int | None, message: str):
        where = f"{path}, line {line}" if line is not None else str(path)
        super().__init__(f"{where}: {message}")
        self.path, self.line = str(path), line


def _curve(cam: Any) -> CamCurve:
    """A CamCurve from a curve, a CamDefinition (``curve()``) or an interpolated cam TO (``curve``)."""
    if isinstance(cam, CamCurve):
        return cam
    c = getattr(cam, "curve", None)
    if callable(c):
        c = c()
    if isinstance(c, CamCurve):
        return c
    if hasattr(cam, "curve"):
        raise ValueError(f"{cam!r} is not interpolated yet (MC_InterpolateCam)")
    raise TypeError(f"expected a CamCurve, a CamDefinition or a cam TO, got {type(cam).__name__}")


def export_points(curve_or_definition: Any, path: str | os.PathLike, n: int = DEFAULT_EXPORT_POINTS,
                  delimiter: str = ",", derivatives: Sequence[str] = DERIVATIVES) -> Path:
    """Write the cam sampled at ``n`` equally spaced leading values from start to end (0..1E5) with a
    header row; ``derivatives``: any of "velocity", "acceleration", "jerk" (derivatives with respect to
    the leading value).  Returns the path."""
    curve = _curve(curve_or_definition)
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not 0 <= n <= MAX_EXPORT_POINTS:
        raise ValueError(f"number of points must be an integer 0..{MAX_EXPORT_POINTS} (§6.2.7), got {n!r}")
    if delimiter not in _DELIMITERS:
        raise ValueError(f"delimiter {delimiter!r}: comma (',') or tab ('\\t') (§6.2.7)")
    sep = _DELIMITERS[delimiter]
    derivatives = tuple(derivatives)
    bad = [d for d in derivatives if d not in DERIVATIVES]
    if bad or len(set(derivatives)) != len(derivatives):
        raise ValueError(f"derivatives: distinct names out of {', '.join(DERIVATIVES)}, got {derivatives!r}")
    xs = np.linspace(curve.start, curve.end, int(n)) if n != 1 else np.array([curve.start])
    values = curve.evaluate(xs, 3)
    cols = [xs, values[0]] + [values[DERIVATIVES.index(d) + 1] for d in derivatives]
    lines = [sep.join(("leading", "following", *derivatives))]
    lines += [sep.join(format(float(c[i]), ".17g") for c in cols) for i in range(len(xs))]
    out = Path(path)
    out.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return out


def _split(line: str) -> list[str]:
    if "\t" in line:
        fields = line.split("\t")
    elif "," in line:
        fields = line.split(",")
    else:
        fields = line.split()
    fields = [f.strip() for f in fields]
    while fields and fields[-1] == "":           # a trailing delimiter
        fields.pop()
    return fields


def _number(text: str) -> float | None:
    try:
        return float(text)
    except ValueError:
        return None


#: largest point-list file read [bytes]: an export of MAX_EXPORT_POINTS rows with all derivatives
#: (5 columns of 17 digits) stays below it
MAX_IMPORT_BYTES = 16 * 1024 * 1024
_EXCERPT = 16


def import_points(path: str | os.PathLike, *, require_increasing: bool = True, show_content: bool = True,
                  max_points: int | None = None) -> list[tuple[float, float]]:
    """(leading, following) pairs of a point-list file: comma or tab separated, an optional header row,
    further columns (velocity, ...) checked and ignored, blank lines and lines starting with '#'
    skipped.  Raises PointListError naming the file and line for anything else, and for leading
    values that do not increase (``require_increasing``).

    A message shows at most a short excerpt of a bad field; with ``show_content=False`` (a file named
    by a project, which might be any file) only the line number, field number and the reason.
    ``max_points``: refuse files with more points (checked while reading)."""
    name = str(path)
    try:
        size = os.path.getsize(path)
    except OSError:
        size = 0                                 # let the read below report it
    if size > MAX_IMPORT_BYTES:
        raise PointListError(name, None, f"{size} bytes; a point list has at most {MAX_IMPORT_BYTES} bytes")
    with open(path, "rb") as fh:               # bounded: a device or pipe has no size and may never end
        data = fh.read(MAX_IMPORT_BYTES + 1)
    if len(data) > MAX_IMPORT_BYTES:
        raise PointListError(name, None, f"more than {MAX_IMPORT_BYTES} bytes; a point list has at most "
                                         f"{MAX_IMPORT_BYTES} bytes")
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise PointListError(name, None, f"not a text file ({exc.reason})") from None

    def shown(index: int, field: str) -> str:
        if not show_content:
            return f"field {index + 1}"
        excerpt = field if len(field) <= _EXCERPT else field[:_EXCERPT] + "..."
        return repr(excerpt)
    points: list[tuple[float, float]] = []
    width: int | None = None
    header_allowed = True
    last_line = 0
    for lineno, raw in enumerate(text.splitlines(), 1):
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        fields = _split(line)
        values = [_number(f) for f in fields]
        if header_allowed and all(v is None for v in values):
            header_allowed = False
            width = len(fields)
            continue
        header_allowed = False
        for k, (f, v) in enumerate(zip(fields, values)):
            if v is None:
                hint = " (decimal comma? use a decimal point)" if "," in f else ""
                hint = hint or (" (fields are separated by comma or tab)" if ";" in f else "")
                raise PointListError(name, lineno, f"{shown(k, f)} is not a number{hint}")
            if not math.isfinite(v):
                raise PointListError(name, lineno, f"{shown(k, f)} is not a finite number")
        if len(fields) < 2:
            raise PointListError(name, lineno, f"expected a leading and a following value, got {len(fields)} field(s)")
        if width is None:
            width = len(fields)
        elif len(fields) != width:
            raise PointListError(name, lineno, f"{len(fields)} fields, the file's rows have {width}")
        x, y = values[0], values[1]
        if require_increasing and points and not x > points[-1][0]:  # type: ignore[operator]
            raise PointListError(name, lineno, f"leading value {x!r} does not increase (line {last_line}: "
                                               f"{points[-1][0]!r})")
        if max_points is not None and len(points) >= max_points:
            raise PointListError(name, lineno, f"more than {max_points} points")
        points.append((x, y))  # type: ignore[arg-type]
        last_line = lineno
    if not points:
        raise PointListError(name, None, "no points in the file")
    return points


__all__ = ["DEFAULT_EXPORT_POINTS", "DERIVATIVES", "MAX_EXPORT_POINTS", "MAX_IMPORT_BYTES", "PointListError", "export_points",
           "import_points"]
