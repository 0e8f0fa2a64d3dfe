"""Digital signals of an axis: drive enable output, drive ready input, hardware limit switches.

S7-1200 V6 §5.4.3.2 (enable/ready), §2.3 and §5.4.4.3 (hardware limit switches), §12.8 16#8000,
16#8003/16#8004, 16#800E.  A hardware limit switch stays actuated beyond its position; once it is
approached the axis may only move in the free direction.  Reaction: a PTO axis brakes with the emergency
deceleration and stays enabled, a PROFIdrive/analog axis loses its enable and the drive stops it.
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from ..drives.spec import EncoderKind
from . import faults as F
from .faults import Reaction
from .jobs import JobKind

if TYPE_CHECKING:  # pragma: no cover
    from .axis import PositioningAxis
    from .profiles import Profile

_SIDES = ("min", "max")


def directions(profile: "Profile", p: float, tol: float = 1e-9) -> tuple[bool, bool]:
    """(moves up, moves down) of a profile starting at ``p``."""
    positions = [s.p for s in profile.segments]
    up = max(positions) > p + tol or profile.final.v > 0 or any(s.v > tol for s in profile.segments)
    down = min(positions) < p - tol or profile.final.v < 0 or any(s.v < -tol for s in profile.segments)
    return up, down


class SwitchesMixin:
    """Mixed into PositioningAxis."""

    def _setup_io(self: "PositioningAxis") -> None:
        c = self.config
        self.hw_approached = {"min": False, "max": False}
        self._hw_input = {"min": c.hardware_limits.min_input, "max": c.hardware_limits.max_input}
        self._ready_input = c.signals.ready_input
        self._enable_output = c.signals.enable_output
        if self._enable_output:
            self.ctl.outputs[self._enable_output] = False
        # in simulation (Simulation.Mode = 1) switches and drive feedback have no effect (§5.4.3.1)
        uses_inputs = any(self._hw_input.values()) or self._ready_input or any(self._homing_inputs().values())
        # actual value range checks (§12.8 16#800B): absolute encoders and modulo axes
        self._range_check = self.servo and (c.drive.encoder.kind is EncoderKind.ABSOLUTE or c.modulo.enabled)
        self._last_mech = self.drive.mechanical_position()
        if (uses_inputs or self._range_check) and not self.sim and self not in self.ctl._input_axes:
            self.ctl._input_axes.append(self)

    # --- signals ---------------------------------------------------------------------------------------
    def _switch_actuated(self: "PositioningAxis", side: str) -> bool:
        address = self._hw_input[side]
        if not address or self.sim:
            return False
        hw = self.config.hardware_limits
        level = hw.min_active_high if side == "min" else hw.max_active_high
        return self.ctl.inputs[address] == level

    def drive_ready_signal(self: "PositioningAxis") -> bool:
        """'Drive ready' as the controller sees it (True when no ready input is configured)."""
        if not self._ready_input or self.sim:
            return True
        return self.ctl.inputs[self._ready_input]

    def _set_enable_output(self: "PositioningAxis", on: bool) -> None:
        if self._enable_output:
            self.ctl.outputs[self._enable_output] = on

    # --- cyclic check (only axes that use inputs) ------------------------------------------------------
    def _check_inputs(self: "PositioningAxis", t: float) -> None:
        if self._ready_input and self.state in ("enabled", "disabling") and not self.drive_ready_signal():
            self.raise_alarm(F.alarm(F.DRIVE_NOT_READY, "", Reaction.REMOVE_ENABLE))
        active = self.config.hardware_limits.enabled
        before = dict(self.hw_approached)
        for side in _SIDES:
            self.hw_approached[side] = active and self._switch_actuated(side)
        new = [side for side in _SIDES if self.hw_approached[side] and not before[side]]
        if len(new) == 2:
            self._on_hw_limit("min", t)          # both at once: the axis cannot be freed (16#800E/16#0044)
        elif new:
            self._on_hw_limit(new[0], t)
        self._homing_check_inputs(t)
        if self._range_check:
            self._check_actual_range()

    def _check_actual_range(self: "PositioningAxis") -> None:
        """16#800B: a (non-cyclic) absolute encoder leaves its measuring range; the actual value of a
        modulo axis changes by more than the modulo length in one cycle."""
        mech = self.drive.mechanical_position()          # coordinate shifts (homing) are no jumps
        jump = abs(mech - self._last_mech)
        self._last_mech = mech
        if self.alarms and any(a.kind == F.POSITION_RANGE for a in self.alarms):
            return
        c = self.config
        if c.modulo.enabled and jump > c.modulo.length:
            self.raise_alarm(F.alarm(F.POSITION_RANGE, "modulo_jump", Reaction.REMOVE_ENABLE))
            return
        encoder = c.drive.encoder
        if encoder.kind is EncoderKind.ABSOLUTE:
            span = encoder.determinable_revolutions * self._encoder_revolution()
            raw = self.drive.mechanical_position()
            if raw >= span:
                self.raise_alarm(F.alarm(F.POSITION_RANGE, "positive", Reaction.REMOVE_ENABLE))
            elif raw < 0.0:
                self.raise_alarm(F.alarm(F.POSITION_RANGE, "negative", Reaction.REMOVE_ENABLE))

    def _encoder_revolution(self: "PositioningAxis") -> float:
        """Load distance of one encoder revolution (rotary) or the whole range of a linear encoder."""
        encoder = self.config.drive.encoder
        if not encoder.rotary:
            return float("inf")
        return encoder.distance_per_revolution

    def _on_hw_limit(self: "PositioningAxis", side: str, t: float) -> None:
        if self.state not in ("enabled", "disabling"):
            return
        other = "max" if side == "min" else "min"
        if self.hw_approached[other]:
            self.raise_alarm(F.alarm(F.HW_LIMIT_FREE, "both", Reaction.REMOVE_ENABLE))
            return
        job = self.job
        if job is not None and job.busy and job.kind == JobKind.HOME_ACTIVE and self._homing_hw_limit(side, t):
            return
        v = float(self.ctl.bank.sp_v[self.index])
        away = v > 1e-9 if side == "min" else v < -1e-9
        if away:
            # moving out of the switch's direction and yet it was actuated: the switches are swapped
            self.raise_alarm(F.alarm(F.HW_LIMIT_FREE, "polarity", Reaction.REMOVE_ENABLE))
            return
        reaction = Reaction.EMERGENCY if self.pto else Reaction.REMOVE_ENABLE
        self.raise_alarm(F.alarm(F.HW_LIMIT_MIN if side == "min" else F.HW_LIMIT_MAX, "", reaction))

    def _hw_direction_fault(self: "PositioningAxis", profile: "Profile", p: float) -> F.Fault | None:
        """A motion into an actuated hardware limit switch is refused (§12.8 16#800E)."""
        if not (self.hw_approached["min"] or self.hw_approached["max"]):
            return None
        if self.hw_approached["min"] and self.hw_approached["max"]:
            return F.alarm(F.HW_LIMIT_FREE, "both", Reaction.REMOVE_ENABLE)
        up, down = directions(profile, p)
        if (self.hw_approached["min"] and down) or (self.hw_approached["max"] and up):
            return F.alarm(F.HW_LIMIT_FREE, "wrong_direction", Reaction.REMOVE_ENABLE)
        return None
