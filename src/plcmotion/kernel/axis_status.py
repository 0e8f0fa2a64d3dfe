"""The status of an axis in motion-control terms, computed when read: what the families' status tags show.

Each family names these values its own way (S7-1200 ``StatusBits.StandStill``, S7-1500 ``StatusWord.X7``)
and maps them in its tag table; the functions here read the array bank, the alarms and the typed
configuration, never a tag path.  Nothing is copied per servo cycle.
"""
from __future__ import annotations

from typing import Any, Protocol

from . import faults as F


class StatusHost(Protocol):
    """What the status functions read of an axis."""

    ctl: Any
    index: int
    config: Any
    alarms: list
    state: str
    servo: bool
    pto: bool
    sensor_valid: bool
    drive: Any
    holding_zero_velocity: bool

    @property
    def now(self) -> float: ...

    def _wrap(self, value: float) -> float: ...

    def sw_limits_effective(self) -> bool: ...

    def communication_ok(self, what: str) -> bool: ...


def position(ax: StatusHost) -> float:
    """Setpoint position (within the modulo range)."""
    return ax._wrap(float(ax.ctl.bank.sp_p[ax.index]))


def velocity(ax: StatusHost) -> float:
    return float(ax.ctl.bank.sp_v[ax.index])


def acceleration(ax: StatusHost) -> float:
    return float(ax.ctl.bank.sp_a[ax.index])


def actual_position(ax: StatusHost) -> float:
    return ax._wrap(float(ax.ctl.bank.act_p[ax.index]))


def actual_velocity(ax: StatusHost) -> float:
    return float(ax.ctl.bank.act_v[ax.index])


def drive_in_operation(ax: StatusHost) -> bool:
    """The drive is enabled and reports ready."""
    return ax.state in ("enabled", "disabling") and ax.drive.ready(ax.now)


def drive_communication_ok(ax: StatusHost) -> bool:
    return ax.communication_ok("drive")


def encoder_communication_ok(ax: StatusHost) -> bool:
    return ax.communication_ok("encoder")


def communication_fault(ax: StatusHost) -> bool:
    """A drive or an encoder on the bus failed or lost its sign of life (S7-1200 V6 §12.8 16#800C/16#003E,
    16#003F, 16#800A/16#0040, 16#0041: ErrorBits.CommunicationFault, S7-1500 ErrorWord.X7)."""
    return any(a.kind in (F.DRIVE_ALARM, F.ENCODER) and a.detail in ("station", "sign_of_life") for a in ax.alarms)


def software_limit_active(ax: StatusHost, side: str) -> bool:
    """The setpoint stands at or beyond the software limit switch ``side`` ("min" or "max") while the
    switches act."""
    if not ax.sw_limits_effective():
        return False
    p = float(ax.ctl.bank.sp_p[ax.index])
    limits = ax.config.software_limits
    if side == "min":
        return p <= limits.minimum
    return p >= limits.maximum


def accel_state(ax: StatusHost) -> int:
    """+1 accelerating, -1 decelerating, 0 constant velocity or standstill (setpoint)."""
    b, i = ax.ctl.bank, ax.index
    v, a = float(b.sp_v[i]), float(b.sp_a[i])
    if abs(a) <= 1e-9 * max(1.0, ax.config.defaults.acceleration):
        return 0
    return 1 if a * v > 0 or v == 0.0 else -1


def accelerating(ax: StatusHost) -> bool:
    return accel_state(ax) > 0


def decelerating(ax: StatusHost) -> bool:
    return accel_state(ax) < 0


def standstill(ax: StatusHost) -> bool:
    """A drive with position control: the standstill monitor; otherwise the setpoint velocity is zero."""
    b, i = ax.ctl.bank, ax.index
    if ax.servo:
        return bool(b.standstill[i])
    return float(b.sp_v[i]) == 0.0
