"""Values the fuzzer feeds to instruction inputs and tags, and how they are written back as Python source.

Every value of an episode is plain data (numbers, strings, None, lists) or one of the small reference
records below, so that an episode can be printed as a self-contained reproducer script.
"""
from __future__ import annotations

import math
import random
from dataclasses import dataclass
from typing import Any

HUGE_INT = 10 ** 400                 # a Python int beyond the float range (defect 5)


@dataclass(frozen=True)
class Ref:
    """A technology object of the episode, by name (an ``Axis``/``Master``/``Slave``/``Cam`` input)."""
    name: str


@dataclass(frozen=True)
class TagRefSpec:
    """``<axis>.ref(path)``: a VARIANT pointer to a tag (MC_ReadParam/MC_WriteParam ``Parameter``)."""
    name: str
    path: str


@dataclass(frozen=True)
class VarSpec:
    """A typed user program variable of ``plcmotion.s7_1200.variables`` (``Real(1.0)``)."""
    kind: str
    value: Any


def lit(v: Any) -> str:
    """Python source of a value."""
    if isinstance(v, Ref):
        return f"TO[{v.name!r}]"
    if isinstance(v, TagRefSpec):
        return f"TO[{v.name!r}].ref({v.path!r})"
    if isinstance(v, VarSpec):
        return f"variables.{v.kind}({lit(v.value)})"
    if isinstance(v, bool) or v is None or isinstance(v, str):
        return repr(v)
    if isinstance(v, bytearray) and not any(v):
        return f"bytearray({len(v)})"        # an empty ANY area of that length (S7-Technology)
    if isinstance(v, int):
        return "10 ** 400" if v == HUGE_INT else ("-10 ** 400" if v == -HUGE_INT else repr(v))
    if isinstance(v, float):
        if math.isnan(v):
            return "float('nan')"
        if math.isinf(v):
            return "float('inf')" if v > 0 else "-float('inf')"
        return repr(v)
    if isinstance(v, (list, tuple)):
        inner = ", ".join(lit(x) for x in v)
        return f"[{inner}]" if isinstance(v, list) else f"({inner}{',' if len(v) == 1 else ''})"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{lit(k)}: {lit(x)}" for k, x in v.items()) + "}"
    return repr(v)


GARBAGE: tuple[Any, ...] = (float("nan"), float("inf"), -float("inf"), HUGE_INT, -HUGE_INT, None, "abc", [1.0],
                            1e300, -1e300, 1e-300, 0.0, -0.0)


def real(rnd: random.Random, scale: float, *, garbage: float = 0.15, signed: bool = True) -> Any:
    """A REAL input: mostly a plausible number around ``scale``, sometimes garbage."""
    r = rnd.random()
    if r < garbage:
        return rnd.choice(GARBAGE)
    if r < garbage + 0.05:
        return rnd.choice((0.0, -1.0, 1.0, scale, -scale))
    x = rnd.uniform(0.0, 1.5 * scale)
    if rnd.random() < 0.2:
        x = round(x, rnd.choice((0, 1, 3)))
    return -x if signed and rnd.random() < 0.3 else x


def integer(rnd: random.Random, choices: tuple[int, ...], *, garbage: float = 0.1) -> Any:
    """An INT input: one of ``choices`` mostly, otherwise an out-of-range or wrongly typed value."""
    if rnd.random() < garbage:
        return rnd.choice((-1, 99, 32768, 1.0, 2.5, float("nan"), HUGE_INT, None, "1", True))
    return rnd.choice(choices)
