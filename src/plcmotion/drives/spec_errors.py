"""Configuration errors of drive specifications: which field, which value, what is allowed."""
from __future__ import annotations

import math
from typing import Any


class DriveSpecError(ValueError):
    """A drive, plant or valve specification with a value outside its range: ``field`` names the parameter
    (``CylinderSpec.area_b``), ``value`` the bad value, and the message the allowed range."""

    def __init__(self, field: str, value: Any, allowed: str):
        self.field, self.value, self.allowed = field, value, allowed
        super().__init__(f"{field} = {value!r}: {allowed}")


def finite(field: str, value: Any) -> float:
    """``value`` as a finite float, or a :class:`DriveSpecError` naming ``field``."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise DriveSpecError(field, value, "must be a number")
    x = float(value)
    if not math.isfinite(x):
        raise DriveSpecError(field, value, "must be a finite number")
    return x


__all__ = ["DriveSpecError", "finite"]
