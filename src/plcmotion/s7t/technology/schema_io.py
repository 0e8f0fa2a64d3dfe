"""Axis tags the basic-function FBs need beyond the core schema (S7-Technology V4.1 §6.7.5, §9.4), kept in
their own module so the schema and its builder stay one list each.

* ``override.acceleration`` (parameter 4141): acceleration / deceleration override [%] 1.0 ... 1000.0,
  effective immediately; every motion's acceleration and deceleration (not an emergency stop) is scaled by
  it, within the axis's maximum values (§6.7.5 example "Override").
"""
from __future__ import annotations

from ...kernel.schema import REAL, WP, Param

IMMEDIATELY = (10,)          # the schema's "Immediately" effect code: the next IPO cycle

IO_PARAMS: list[Param] = [
    Param("override.acceleration", REAL, 100.0, WP, IMMEDIATELY, 1.0, 1000.0,
          doc="acceleration and deceleration override [%] (number 4141)"),
]

__all__ = ["IO_PARAMS"]
