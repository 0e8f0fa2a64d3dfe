"""The ends of an axis's travel range: hardware limit switches and the measuring range of the actual value.

Hardware limit switches (S7-1200 V6 §5.4.4.3, §12.8 16#8003/16#8004/16#800E): a switch stays actuated
beyond its position, and once it is approached the axis may only move in the free direction.  Reaching one
stops a pulse output axis with the emergency deceleration (it stays enabled) and removes the enable of a
drive axis, whose drive then stops it.  Actual value range (§12.8 16#800B): an absolute encoder that leaves
its measuring range, or a modulo axis whose actual value jumps by more than the modulo length in one cycle
(§5.4.4.2), loses its enable.

``LimitSwitches`` is a component of an axis (``axis.limit_switches``); it reads the inputs only for axes the
controller watches every servo cycle (``kernel.servo_cycle.watch_inputs``).
"""
from __future__ import annotations

from typing import Any, Mapping, Protocol

from ..drives.base import DriveChannel
from ..drives.spec import EncoderKind
from . import faults as F
from .axis_config import AxisConfig
from .faults import Fault, Reaction
from .jobs import Job, JobKind
from .profiles import Profile

SIDES = ("min", "max")


class SwitchBoard(Protocol):
    """The controller as the switches see it: the input image and the setpoint arrays."""

    inputs: Mapping[str, bool]
    bank: Any                       # kernel.bank.AxisBank (``sp_v`` read)


class LimitSwitchHost(Protocol):
    """What the limit switches need from their axis."""

    ctl: SwitchBoard
    index: int                      # the axis's slot in ``ctl.bank``
    config: AxisConfig
    drive: DriveChannel
    state: str                      # "disabled", "enabling", "enabled", "disabling"
    job: Job | None
    pto: bool
    sim: bool
    servo: bool
    alarms: list[Fault]

    def raise_alarm(self, fault: Fault, job: Job | None = None) -> None: ...

    def _homing_hw_limit(self, side: str, t: float) -> bool:
        """Active homing reverses at a limit switch (True: handled, no alarm)."""
        ...


def directions(profile: Profile, p: float, tol: float = 1e-9) -> tuple[bool, bool]:
    """(moves up, moves down) of a profile starting at ``p``."""
    positions = [s.p for s in profile.segments]
    up = max(positions) > p + tol or profile.final.v > 0 or any(s.v > tol for s in profile.segments)
    down = min(positions) < p - tol or profile.final.v < 0 or any(s.v < -tol for s in profile.segments)
    return up, down


class LimitSwitches:
    """Hardware limit switches and the actual value range of one axis.

    ``approached``: side ("min"/"max") -> the switch is actuated and active (StatusBits.HWLimitMinActive /
    HWLimitMaxActive).  The input addresses are those of the configuration the axis was created with.
    """

    def __init__(self, axis: LimitSwitchHost):
        self.axis = axis
        c = axis.config
        self.approached = {"min": False, "max": False}
        self.inputs = {"min": c.hardware_limits.min_input, "max": c.hardware_limits.max_input}
        # actual value range checks (§12.8 16#800B): absolute encoders and modulo axes
        self.range_check = axis.servo and (c.drive.encoder.kind is EncoderKind.ABSOLUTE or c.modulo.enabled)
        self._last_mech = axis.drive.mechanical_position()

    @property
    def wired(self) -> bool:
        """A switch input is configured (the axis must be watched every servo cycle)."""
        return any(self.inputs.values())

    # --- hardware limit switches ------------------------------------------------------------------------
    def actuated(self, side: str) -> bool:
        """The input of switch ``side`` shows the level configured as 'approached' (§5.4.4.3 'Select
        level'); a simulated axis has no switches (§5.4.3.1)."""
        address = self.inputs[side]
        ax = self.axis
        if not address or ax.sim:
            return False
        hw = ax.config.hardware_limits
        level = hw.min_active_high if side == "min" else hw.max_active_high
        return ax.ctl.inputs[address] == level

    def check(self, t: float) -> None:
        """Take the switch states of this servo cycle; a switch just approached raises its alarm."""
        active = self.axis.config.hardware_limits.enabled
        approached = self.approached
        before = dict(approached)
        for side in SIDES:
            approached[side] = active and self.actuated(side)
        new = [side for side in SIDES if approached[side] and not before[side]]
        if len(new) == 2:
            self._reached("min", t)          # both at once: the axis cannot be freed (16#800E/16#0044)
        elif new:
            self._reached(new[0], t)

    def _reached(self, side: str, t: float) -> None:
        ax = self.axis
        if ax.state not in ("enabled", "disabling"):
            return
        other = "max" if side == "min" else "min"
        if self.approached[other]:
            ax.raise_alarm(F.alarm(F.HW_LIMIT_FREE, "both", Reaction.REMOVE_ENABLE))
            return
        job = ax.job
        if job is not None and job.busy and job.kind == JobKind.HOME_ACTIVE and ax._homing_hw_limit(side, t):
            return
        v = float(ax.ctl.bank.sp_v[ax.index])
        away = v > 1e-9 if side == "min" else v < -1e-9
        if away:
            # moving out of the switch's direction and yet it was actuated: the switches are swapped
            ax.raise_alarm(F.alarm(F.HW_LIMIT_FREE, "polarity", Reaction.REMOVE_ENABLE))
            return
        reaction = Reaction.EMERGENCY if ax.pto else Reaction.REMOVE_ENABLE
        ax.raise_alarm(F.alarm(F.HW_LIMIT_MIN if side == "min" else F.HW_LIMIT_MAX, "", reaction))

    def direction_fault(self, profile: Profile, p: float) -> Fault | None:
        """A motion from ``p`` into an actuated hardware limit switch is refused (§12.8 16#800E)."""
        lo, hi = self.approached["min"], self.approached["max"]
        if not (lo or hi):
            return None
        if lo and hi:
            return F.alarm(F.HW_LIMIT_FREE, "both", Reaction.REMOVE_ENABLE)
        up, down = directions(profile, p)
        if (lo and down) or (hi and up):
            return F.alarm(F.HW_LIMIT_FREE, "wrong_direction", Reaction.REMOVE_ENABLE)
        return None

    # --- actual value range -----------------------------------------------------------------------------
    def check_range(self) -> None:
        """16#800B: a (non-cyclic) absolute encoder leaves its measuring range; the actual value of a
        modulo axis changes by more than the modulo length in one cycle."""
        ax = self.axis
        mech = ax.drive.mechanical_position()            # coordinate shifts (homing) are no jumps
        jump = abs(mech - self._last_mech)
        self._last_mech = mech
        if ax.alarms and any(a.kind == F.POSITION_RANGE for a in ax.alarms):
            return
        c = ax.config
        if c.modulo.enabled and jump > c.modulo.length:
            ax.raise_alarm(F.alarm(F.POSITION_RANGE, "modulo_jump", Reaction.REMOVE_ENABLE))
            return
        encoder = c.drive.encoder
        if encoder.kind is EncoderKind.ABSOLUTE:
            span = encoder.determinable_revolutions * self._encoder_revolution()
            raw = ax.drive.mechanical_position()
            if raw >= span:
                ax.raise_alarm(F.alarm(F.POSITION_RANGE, "positive", Reaction.REMOVE_ENABLE))
            elif raw < 0.0:
                ax.raise_alarm(F.alarm(F.POSITION_RANGE, "negative", Reaction.REMOVE_ENABLE))

    def _encoder_revolution(self) -> float:
        """Load distance of one encoder revolution (rotary) or the whole range of a linear encoder."""
        encoder = self.axis.config.drive.encoder
        if not encoder.rotary:
            return float("inf")
        return encoder.distance_per_revolution
