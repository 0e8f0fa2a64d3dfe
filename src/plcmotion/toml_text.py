"""Values and keys of a TOML file shown as the file spells them, for one-line problem messages."""
from __future__ import annotations

import difflib
import json
import math
import re
from collections.abc import Iterator, Mapping
from typing import Any

MAX_SHOWN = 80


def toml_value(value: Any) -> str:
    """``value`` in TOML spelling (``true``, ``"text"``, ``[1, 2]``), shortened when it is long."""
    text = _toml(value)
    return text if len(text) <= MAX_SHOWN else text[:MAX_SHOWN - 3] + "..."


def _toml(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return quoted(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, list):
        return "[" + ", ".join(_toml(v) for v in value) + "]"
    if isinstance(value, Mapping):
        if not value:
            return "{}"
        return "{ " + ", ".join(f"{key(k)} = {_toml(v)}" for k, v in value.items()) + " }"
    if hasattr(value, "isoformat"):          # TOML dates and times
        return value.isoformat()
    return str(value)


def key(name: str) -> str:
    """A key of a key path: bare when it is an identifier-like name, quoted otherwise."""
    return name if re.fullmatch(r"[A-Za-z0-9_\-\[\]]+", name) else quoted(name)


def quoted(text: str) -> str:
    """A TOML basic string; characters that are not printable (line breaks such as U+0085 or U+2028,
    bidi controls) are escaped so that a message stays one readable line."""
    return "".join(c if c.isprintable() or c == " " else f"\\u{ord(c):04x}" if ord(c) < 0x10000
                   else f"\\U{ord(c):08x}" for c in json.dumps(text, ensure_ascii=False))


class Shown:
    """A value whose ``repr`` is its TOML spelling, so ``Issue.message`` shows what the file says."""

    def __init__(self, value: Any):
        self.value = value

    def __repr__(self) -> str:
        return toml_value(self.value)


def leaves(table: Mapping[str, Any], prefix: str = "") -> Iterator[tuple[str, Any]]:
    """``(dotted path, value)`` of every value that is not a table, and of every empty table, in file
    order (duplicates kept)."""
    for name, value in table.items():
        path = f"{prefix}.{name}" if prefix else str(name)
        if isinstance(value, Mapping) and value:
            yield from leaves(value, path)
        else:
            yield path, value


def near(word: str, known: list[str] | tuple[str, ...]) -> str:
    close = difflib.get_close_matches(word, known, n=3, cutoff=0.6)
    return "did you mean " + " or ".join(close) + "?" if close else "allowed: " + ", ".join(known)


__all__ = ["MAX_SHOWN", "Shown", "key", "leaves", "near", "quoted", "toml_value"]
