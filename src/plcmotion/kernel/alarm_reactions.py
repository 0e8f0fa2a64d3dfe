"""The alarms of an axis: an alarm's reaction, acknowledging alarms and restarting the technology object.

S7-1200 V6 §9.6 / §12.8: every technology alarm has a reaction - none (a warning), stop with the current
dynamics, stop with the emergency deceleration, or remove the enable - and ends the job it belongs to
(or, for a family whose manual has it, stop with the configured maximum dynamics).
MC_Reset (§11.1.2) acknowledges the alarms whose cause is gone (a device still faulty keeps its alarm, §12.7;
a configuration error is checked again), and with Restart = TRUE reloads the start values of a disabled
axis (§9.7).  A restart of the technology object (also CPU STOP -> RUN and POWER ON) loses "homed" as §2.5
lists; an absolute encoder keeps its retentive adjustment (§9.4).

``AlarmReactions`` is a component of an axis (``axis.alarm_reactions``).  The alarm list stays on the axis
(``axis.alarms``, read by the tag views and instructions); the steps a family changes (``reinitialize``,
``_abort_all``, ``_remove_enable``) are called back through the axis so that a family's override wins.
"""
from __future__ import annotations

from typing import Any, Protocol

from . import faults as F
from .faults import Fault, Reaction
from .jobs import Job, JobState
from .motion import max_dynamics
from .profiles import Planner, Profile

DISABLED, ENABLING, ENABLED, DISABLING = "disabled", "enabling", "enabled", "disabling"


class AlarmHost(Protocol):
    """What the alarm handling needs from its axis."""

    ctl: Any                        # the controller: ``bank``, ``retain``
    name: str
    index: int
    drive: Any                      # drives.base.DriveChannel
    motion: Any                     # kernel.motion.MotionPlanner
    homing: Any                     # kernel.homing.Homing
    parameters: Any                 # kernel.parameter_store.ParameterStore
    fault_injection: Any            # kernel.fault_injection.FaultInjection
    alarms: list[Fault]
    job: Job | None
    state: str
    power_owner: Any
    busy_commands: set[int]
    homed: bool
    abs_offset: float
    pto: bool
    _interpolating: bool

    @property
    def now(self) -> float: ...

    def _finish_job(self, job: Job, state: JobState, t: float, fault: Fault | None = None) -> None: ...
    def _end_runner_jobs(self, state: JobState, t: float, fault: Fault | None = None) -> None: ...
    def _remove_enable(self, t: float, by_power: bool = False) -> None: ...
    def _abort_all(self, t: float) -> None: ...
    def reinitialize(self, reason: str) -> None: ...
    def absolute_encoder(self) -> bool: ...
    def _config_fault(self, apply: bool = False) -> Fault | None: ...
    def _state_now(self) -> tuple[float, float, float]: ...
    def _start_profile(self, profile: Profile, plan: Any = None) -> None: ...
    def _stop_positioning_monitor(self) -> None: ...
    def _apply_bank_config(self) -> None: ...


class AlarmReactions:
    """Raise, acknowledge and restart for one axis (its alarm list is ``axis.alarms``)."""

    def __init__(self, axis: AlarmHost):
        self.axis = axis

    def raise_alarm(self, fault: Fault, job: Job | None = None) -> None:
        """Note ``fault``, end the job it belongs to and react as it says (§12.8)."""
        ax = self.axis
        t = ax.now
        if fault not in ax.alarms:
            ax.alarms.append(fault)
        victim = job if job is not None else ax.job
        if victim is not None and victim.busy:
            ax._finish_job(victim, JobState.ERROR, t, fault)
        if fault.reaction != Reaction.NONE:
            ax._end_runner_jobs(JobState.ERROR, t, fault)
        if fault.reaction in (Reaction.REMOVE_ENABLE, Reaction.EMERGENCY, Reaction.MAX_DYNAMICS):
            ax.homing.end_passive(JobState.ERROR, fault)
        if ax.state not in (ENABLED, DISABLING, ENABLING):
            return
        if fault.reaction == Reaction.REMOVE_ENABLE:
            ax._remove_enable(t)
        elif fault.reaction in (Reaction.STOP, Reaction.EMERGENCY, Reaction.MAX_DYNAMICS):
            if ax.state == ENABLING:
                ax._remove_enable(t)
                return
            p, v, a = ax._state_now()
            ax._interpolating = False
            if fault.reaction == Reaction.MAX_DYNAMICS:
                ax._start_profile(ax.motion.stop_with(t, p, v, a, max_dynamics(ax)))
            else:
                plan = ax.motion.stop(t, p, v, a, emergency=fault.reaction == Reaction.EMERGENCY,
                                      jerk=fault.reaction == Reaction.STOP)
                ax._start_profile(plan.profile, plan)
            ax._stop_positioning_monitor()

    def acknowledge(self) -> Fault | None:
        """MC_Reset (Restart = FALSE): clear alarms whose cause is gone; returns one that persists."""
        ax = self.axis
        injected = ax.fault_injection
        injected.acknowledge()
        remaining = []
        for fault in ax.alarms:
            if injected.keeps_alarm(fault):            # a device that is still faulty (§12.7)
                remaining.append(fault)
                continue
            if fault.kind == F.CONFIG:
                bad = ax._config_fault(apply=True)
                if bad is not None:
                    remaining.append(bad)
                continue
            if fault.kind == F.DRIVE_NOT_READY and ax.state == ENABLED and not ax.drive.ready(ax.now):
                remaining.append(fault)
                continue
        ax.alarms = remaining
        return remaining[0] if remaining else None

    def restart(self) -> Fault | None:
        """MC_Reset (Restart = TRUE): reload the start values; only while disabled (§9.7, §11.1.2)."""
        ax = self.axis
        if ax.state == DISABLING:
            return F.reject(F.RESTART_IMPOSSIBLE, "not_disabled")
        if ax.power_owner is not None or ax.state != DISABLED:
            return F.reject(F.RESTART_IMPOSSIBLE, "enabled")
        ax.reinitialize("restart")
        return None

    def reinitialize(self, reason: str) -> None:
        """Restart of the technology object with its start values.

        ``reason``: "restart" (MC_Reset Restart = TRUE), "startup" (CPU STOP -> RUN) or "power"
        (POWER OFF -> ON).  "Homed" is lost as §2.5 lists: a PTO axis always, incremental actual values
        on a TO restart or power cycle; an absolute encoder keeps its retentive adjustment (§9.4).
        """
        ax = self.axis
        t = ax.now
        ax._abort_all(t)
        if ax.state != DISABLED:
            ax._remove_enable(t, by_power=True)
        ax.power_owner = None
        ax.parameters.restart()
        ax.alarms.clear()
        ax.busy_commands.clear()
        absolute = ax.absolute_encoder()
        if ax.pto or (not absolute and reason in ("restart", "power")):
            ax.homed = False
        if absolute:
            kept = ax.ctl.retain.get(ax.retain_key, {})
            ax.abs_offset = float(kept.get("AbsEncoderOffset", ax.abs_offset))
            ax.homed = bool(kept.get("HomingDone", ax.homed))
        b, i = ax.ctl.bank, ax.index
        if reason == "power":
            # the actual values start anew: pulse and incremental counters at 0, absolute encoders as is
            ax.drive.set_actual(b, ax.homing.absolute_raw() + ax.abs_offset if absolute else 0.0)
            b.sp_p[i] = b.act_p[i]
            b.sp_v[i] = b.sp_a[i] = 0.0
            ax._start_profile(Planner.hold(t, float(b.sp_p[i])))
        ax._apply_bank_config()
