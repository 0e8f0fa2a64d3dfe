"""What kernel parts need from an axis or from the controller, as protocols.

Planning and queueing take an axis as an argument; annotating it with the axis class would make the
modules import each other in a circle (the axis uses them).  Likewise the axis and the synchronous operation
stage keep the controller that created them.  These protocols name only what is used."""
from __future__ import annotations

from typing import Any, Callable, Protocol

from .axis_config import AxisConfig
from .bank import AxisBank
from .io import DigitalInputs, DigitalOutputs


class PlannedAxis(Protocol):
    """An axis as the motion planner sees it (``kernel.motion``)."""

    config: AxisConfig              # the axis configuration in effect
    pto: bool                       # pulse output: start/stop velocity, no jerk limit on every version

    def commanded_velocity(self, velocity: float) -> float: ...

    def position_resolution(self) -> float: ...

    def sw_limits_effective(self) -> bool: ...


class ServoHost(Protocol):
    """The controller as its technology objects see it (``kernel.runtime.Controller``).

    An axis is created by the controller and keeps it as ``axis.ctl``; annotating that with the controller
    class would make ``axis`` and ``runtime`` import each other.  The private fields are the controller's
    bookkeeping that axes update on events (which axes watch inputs, monitor, hold a pulse generator)."""

    time: float                     # virtual time [s]
    servo_cycle: float              # [s]
    mode: str                       # "RUN" or "STOP"
    rules: frozenset[str]           # version rules of the family in force (``kernel.family``)
    bank: AxisBank                  # the arrays of all axes
    inputs: DigitalInputs
    outputs: DigitalOutputs
    plant: Any                      # drives.plant.Plant: the simulated machine around the drives
    retain: dict[str, dict]         # retentive data per axis name
    _input_axes: list[Any]          # axes that watch inputs every servo cycle
    _dirty_axes: set[Any]           # axes whose parameters changed while moving
    _pto_holder: dict[int, Any]     # pulse generator number -> the axis holding it
    _n_fe: int                      # axes with following error monitoring on
    _n_few: int                     # axes that report a following error warning
    _n_pm: int                      # axes in positioning monitoring
    _n_sup: int                     # axes with a superimposed motion part

    def _next_db_number(self) -> int: ...

    def _drive_group(self, spec: Any) -> Any: ...

    def _bind_drive(self, name: str, spec: Any) -> Any: ...

    def _retain_axis(self, axis: Any) -> None: ...

    def on_pre_servo(self, fn: Callable[[float], None]) -> Callable[[float], None]: ...
