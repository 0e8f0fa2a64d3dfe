"""S7-1500 positioning axis and synchronous axis technology objects (S7-1500T V5 §3.1, §6.1, §9.3, §A.1).

They share the kernel's motion with the S7-1200 axis and differ where the S7-1500 does: every job
brings its own dynamics (limited by ``DynamicLimits``), ``MC_Stop`` locks the axis while its Execute is
TRUE, a superimposed motion can run on top of any basic motion, jobs override each other by the tables
of §9.3, and the synchronous axis follows leading values (its ``kernel.follower.Follower``).
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, Mapping

from . import override as O
from . import alarms as A
from . import tags as T
from ...kernel.axis import DISABLED, ENABLING
from ...kernel import faults as F
from ...kernel.faults import Fault, Reaction
from ...kernel.jobs import Job
from ...kernel.layered_axis import LayeredAxis
from ...kernel.leading import AxisLeadingValue
from .parameters import S7_1500
from ...kernel.profiles import INF
from ...kernel.follower import Follower

if TYPE_CHECKING:  # pragma: no cover
    from ...kernel.runtime import Controller

_EPS_T = 1e-9
STOP_MODES = O.STOP_MODES


class PositioningAxis1500(LayeredAxis):
    """Positioning axis technology object of the S7-1500 (TO_PositioningAxis).

    The motion layers (superimposed motion, the MC_Stop lock, the follower of a synchronous axis) are the
    kernel's ``LayeredAxis``; here: the S7-1500 tags, the leading value it provides, WarningWord.X3, the
    MC_Stop modes and the MC_Power stop modes."""

    schema = S7_1500
    _dynamic = T.DYNAMIC
    _dynamic_types = T.TYPES
    _dynamic_aliases: dict[str, str] = {}
    _status_groups = T.GROUPS
    _read_param_tags = frozenset(T.DYNAMIC)
    command_not_accepted = False
    # alarm 533 brakes at a software limit switch with the maximum dynamic values (reaction 2; V5 has no
    # PositionLimits_SW.LimitReachedBehavior, so 0 = maximum dynamics always applies; decisions.md #91)
    sw_limit_max_deceleration = True

    # a leading TO (S7-1500T V5 §3.3): setpoints, actual values and the delayed value (see lv_provider)
    provides_setpoints = True
    provides_actual_values = True
    provides_delayed_values = True

    def __init__(self, ctl: "Controller", name: str, cfg: Mapping[str, Any], **kw: Any):
        self.command_not_accepted = False        # WarningWord.X3: a job was rejected (until MC_Reset)
        super().__init__(ctl, name, cfg, **kw)
        self.lv_provider = AxisLeadingValue(self)        # the leading value it provides (§3.3, §8.1.3)

    # --- the leading value it provides: what followers call (kernel.leading) ---------------------------
    def lv_value(self, mode: str, t: float) -> tuple[float, float, float]:
        return self.lv_provider.lv_value(mode, t)

    def lv_slot(self, mode: str) -> int:
        return self.lv_provider.lv_slot(mode)

    def lv_position_controlled(self) -> bool:
        return self.lv_provider.lv_position_controlled()

    def lv_modulo(self) -> tuple[float, float] | None:
        return self.lv_provider.lv_modulo()

    def leading_value_invalid(self, mode: str) -> str | None:
        return self.lv_provider.leading_value_invalid(mode)

    def provide_leading_value(self, sink: Any) -> None:
        self.lv_provider.provide_leading_value(sink)

    # --- alarms -----------------------------------------------------------------------------------------
    def raise_alarm(self, fault: Fault, job: Job | None = None) -> None:
        """The kernel's fault as the CPU's technology alarm: the axis carries out that alarm's reaction
        (``alarms.ALARMS``; e.g. 601 stops with the maximum dynamic values, 101 removes the enable)."""
        super().raise_alarm(A.enforce(fault), job)

    def acknowledge(self) -> Fault | None:
        """MC_Reset: alarms that need a restart of the technology object stay (StatusWord.X3)."""
        self.command_not_accepted = False
        fatal = [a for a in self.alarms if A.needs_restart(a)]
        persisting = super().acknowledge()
        if fatal:
            self.alarms = fatal + [a for a in self.alarms if a not in fatal]
            return fatal[0]
        return persisting

    def check_start(self, job: Job) -> Fault | None:
        """An absolute positioning of an axis that is not homed is technology alarm 321 (ErrorWord.X3,
        emergency stop ramp; §7.1.1 "Job rejected ... for example, technology object not homed"), not a
        plain rejection (docs/s7_1500/decisions.md #84)."""
        fault = super().check_start(job)
        if fault is not None and fault.kind == F.NOT_HOMED and not fault.ack:
            fault = F.alarm(F.NOT_HOMED, fault.detail, Reaction.EMERGENCY, "the axis is not homed")
            self.raise_alarm(fault)
        return fault

    def note_rejected(self, fault: Fault) -> None:
        """An instruction's job was rejected (not enabled, not homed, MC_Stop lock, ...): §7.1.1 "Job
        rejected" shows WarningWord.X3 (CommandNotAccepted) until MC_Reset (docs/s7_1500/decisions.md)."""
        if not fault.ack:
            self.command_not_accepted = True

    # --- MC_Stop Mode 0 (emergency stop ramp) and 2 (maximum dynamic values), §6.1.5.3 -------------------
    def _plan_stop(self, job: Job, t: float) -> None:
        if job.mode == 0:
            plan = self.motion.stop(t, *self._state_now(), emergency=True, jerk=False)
            self._start_profile(plan.profile, plan)
        else:
            job.extra["max_dynamics"] = True
            self._plan_job(job, t)

    def _replan_stop(self, stop: Job) -> bool:
        if stop.mode == 0 and abs(self._state_now()[1]) > 1e-12:
            # MC_Stop Mode 0 runs down the emergency-stop ramp (§6.1.5.3): a re-plan keeps that ramp, never
            # a stop with the dynamic defaults (fuzz seed 201112)
            self._plan_stop(stop, self.now)
            return True
        return False

    # --- enable / disable (MC_Power StopMode: 0 emergency stop, 1 immediate stop, 2 maximum dynamics) ----
    _enabled_once = False

    def _has_start_mode(self) -> bool:
        """A simulated axis (Simulation.Mode 1) runs as the drive axis it stands for, also without position
        control (StatusWord.X28, §A.1.37); a virtual axis has no drive and stays position-controlled."""
        return self.servo or (self.sim and self.ueff["Simulation.Mode"] == 1 and not self.ueff["VirtualAxis.Mode"])

    def _zero_at_enable(self) -> bool:
        """An unhomed S7-1500 axis counts from the position at its first enable after the technology object
        started (§7.1.2); enabling it again keeps the position, so a follower sees no leading value step
        (§9.1.1: it follows its leading axis after that is enabled again).  docs: issue 8 decision."""
        first = not self._enabled_once
        self._enabled_once = True
        return first and super()._zero_at_enable()

    def _disable(self, stop_mode: int) -> None:
        t = self.now
        self._abort_all(t)
        if self.state == ENABLING:
            self._remove_enable(t, by_power=True)
            return
        self.state = "disabling"
        p, v, a = self._state_now()
        self._after_stop = "disable"
        if stop_mode == 1:
            self._remove_enable(t, by_power=True)
            return
        if stop_mode == 2:
            lim = self._max_dynamics()
            plan_profile = self.motion.stop_with(t, p, v, a, lim)
            self._start_profile(plan_profile)
        else:
            plan = self.motion.stop(t, p, v, a, emergency=True, jerk=False)
            self._start_profile(plan.profile, plan)
        if self.profile.t_end <= t + _EPS_T:
            self._remove_enable(t, by_power=True)

    def reinitialize(self, reason: str) -> None:
        self._enabled_once = False               # a restarted technology object counts anew (§7.1.2)
        self.command_not_accepted = False
        super().reinitialize(reason)


class SynchronousAxis(PositioningAxis1500):
    """Synchronous axis technology object (TO_SynchronousAxis): a positioning axis that can follow a
    leading value (§3.1) - its ``follower`` component.  ``leading_values``: the possible leading values,
    as names or ``(name, "setpoint" | "actual" | "delayed")`` pairs (§6.1.3)."""

    _dynamic = T.SYNC_DYNAMIC
    _dynamic_types = T.SYNC_TYPES
    _status_groups = T.SYNC_GROUPS
    _read_param_tags = frozenset(T.SYNC_DYNAMIC)

    def __init__(self, ctl: "Controller", name: str, cfg: Mapping[str, Any], *, leading_values=(), **kw: Any):
        self.follower: Follower = Follower(self, leading_values, name)
        super().__init__(ctl, name, cfg, **kw)

    # what the synchronous instructions call (s7_1500/sync.py) --------------------------------------------
    @property
    def possible_leading_values(self) -> dict[str, str]:
        return self.follower.possible_leading_values

    def sync_submit(self, job: Job) -> None:
        """Hand a synchronous job to the follower.  MC_CamIn with a cam that is not interpolated is the
        CPU's technology alarm 612 at the following axis (reaction 4 remove enable, ErrorWord.X2); the job
        ends with 16#8001 (docs/s7_1500/decisions.md #62)."""
        self.follower.submit(job)
        fault = job.fault
        if fault is not None and fault.kind == F.CAM_NOT_INTERPOLATED and not fault.ack:
            self.raise_alarm(F.alarm(F.CAM_NOT_INTERPOLATED, "", Reaction.REMOVE_ENABLE,
                                     "the cam used for camming is not interpolated"))

    def phase_shift(self, t: float | None = None) -> float:
        return self.follower.phase_shift(t)

    def covered_phase_shift(self, job: Job) -> float:
        return self.follower.covered_phase_shift(job)

    def set_lv_additive(self, job: Job, p: float, v: float, a: float) -> Fault | None:
        return self.follower.set_lv_additive(job, p, v, a)

    def end_lv_additive(self, job: Job) -> None:
        self.follower.end_lv_additive(job)

    def start_simulation(self, job: Job) -> Fault | None:
        return self.follower.start_simulation(job)

    def end_simulation(self, job: Job) -> None:
        self.follower.end_simulation(job)


__all__ = ["PositioningAxis1500", "SynchronousAxis", "DISABLED", "INF", "math"]
