"""What kernel parts need from an axis, as protocols.

Planning and queueing take an axis as an argument; annotating it with the axis class would make the
modules import each other in a circle (the axis uses them).  These protocols name only what is used."""
from __future__ import annotations

from typing import Protocol

from .axis_config import AxisConfig


class PlannedAxis(Protocol):
    """An axis as the motion planner sees it (``kernel.motion``)."""

    config: AxisConfig              # the axis configuration in effect
    pto: bool                       # pulse output: start/stop velocity, no jerk limit on every version

    def commanded_velocity(self, velocity: float) -> float: ...

    def position_resolution(self) -> float: ...

    def sw_limits_effective(self) -> bool: ...
