"""Enabling and disabling an axis: the power state machine behind the enabling instruction (MC_Power).

S7-1200 V6 §11.1.1 (MC_Power): Enable = TRUE enables the axis - at once without drive feedback, otherwise
once the drive reports ready; StartMode 0 enables a drive axis without position control.  Enable = FALSE
stops the axis by StopMode (0 emergency stop, 1 immediate stop, 2 emergency stop with jerk limit) and then
removes the enable; an axis already stopping goes on stopping.  Only the instruction that enabled an axis
may disable it (16#8202-like rejection for another one).  Several axes on one pulse generator: the first
MC_Power call of an axis takes it over once its holder is disabled (§12.1).  "Remove enable" (§12.8) sets
the setpoint to zero and switches the enable off; the drive stops by itself.

``PowerControl`` is a component of an axis (``axis.power_control``).  The axis keeps the state the rest of
the controller reads (``state``, ``power_owner``, ``stop_mode``, ``position_controlled``); the steps a
family changes (``_disable``, ``_remove_enable``, ``_has_start_mode``, ``_zero_at_enable``, ``_abort_all``)
are called back through the axis so that a family's override wins.
"""
from __future__ import annotations

from typing import Any, Protocol

from . import faults as F
from .axis_config import AxisConfig
from .faults import Fault, Reaction
from .profiles import Planner, Profile

DISABLED, ENABLING, ENABLED, DISABLING = "disabled", "enabling", "enabled", "disabling"
_EPS_T = 1e-9


class PowerHost(Protocol):
    """What the power state machine needs from its axis."""

    ctl: Any                        # the controller: ``mode``, ``bank``, ``_pto_holder``
    index: int
    config: AxisConfig
    drive: Any                      # drives.base.DriveChannel
    drive_io: Any                   # kernel.drive_io.DriveIO
    motion: Any                     # kernel.motion.MotionPlanner
    fault_injection: Any            # kernel.fault_injection.FaultInjection
    profile: Profile
    state: str
    power_owner: Any
    stop_mode: int
    position_controlled: bool
    holding_zero_velocity: bool
    homed: bool
    alarms: list[Fault]
    pto: bool
    sim: bool
    servo: bool
    _after_stop: str | None
    _timers: dict[str, float]

    @property
    def now(self) -> float: ...
    @property
    def sensor_valid(self) -> bool: ...

    def raise_alarm(self, fault: Fault, job: Any = None) -> None: ...
    def _apply_dirty(self, moment: str) -> Fault | None: ...
    def _config_fault(self, apply: bool = False) -> Fault | None: ...
    def _enable(self, start_mode: int) -> None: ...
    def _disable(self, stop_mode: int) -> None: ...
    def _become_enabled(self, t: float) -> None: ...
    def _remove_enable(self, t: float, by_power: bool = False) -> None: ...
    def _has_start_mode(self) -> bool: ...
    def _zero_at_enable(self) -> bool: ...
    def _abort_all(self, t: float) -> None: ...
    def _stop_positioning_monitor(self) -> None: ...
    def _set_loop_flags(self) -> None: ...
    def _schedule(self) -> None: ...
    def _start_profile(self, profile: Profile, plan: Any = None) -> None: ...
    def _state_now(self) -> tuple[float, float, float]: ...


class PowerControl:
    """The enable state machine of one axis: disabled -> enabling -> enabled -> disabling -> disabled."""

    def __init__(self, axis: PowerHost):
        self.axis = axis

    def power(self, owner: Any, enable: bool, start_mode: int, stop_mode: int) -> Fault | None:
        """Called by the enabling instruction on every call; returns a rejection or None."""
        ax = self.axis
        if ax.power_owner is not None and ax.power_owner is not owner:
            return F.reject(F.ALREADY_ENABLED) if enable else None
        if enable and ax.ctl.mode != "RUN":
            return F.reject(F.REJECTED, "starting_up")
        no = ax.config.pulse_output.generator if ax.pto else 0
        if no:
            # several axes on one pulse generator: the first MC_Power call of an axis takes the PTO over
            # once the axis holding it is disabled (§12.1)
            holder = ax.ctl._pto_holder.get(no)
            if holder is not ax:
                if holder is not None and holder.state != DISABLED:
                    return F.reject(F.PTO_SWITCH) if enable else None
                ax.ctl._pto_holder[no] = ax
                ax._apply_dirty("enable")
        if enable:
            ax.power_owner = owner
            ax.stop_mode = stop_mode
            if ax.state == DISABLED and not ax.alarms and ax._after_stop is None:
                ax._enable(start_mode)
        elif ax.power_owner is owner:
            if ax.state in (ENABLING, ENABLED):
                ax._disable(stop_mode)
            if ax.state == DISABLED:
                ax.power_owner = None
        return None

    def enable(self, start_mode: int) -> None:
        ax = self.axis
        t = ax.now
        if ax._apply_dirty("enable") is not None:
            return
        bad = ax._config_fault()
        if bad is not None:
            ax.raise_alarm(bad)
            return
        ax.position_controlled = start_mode == 1 or not ax._has_start_mode()
        if bool(ax.ctl.bank.simulated[ax.index]):
            ax._become_enabled(t)          # simulated actual values (axis.simulate_actual): the drive stays off
            return
        if ax.servo and ax.position_controlled and not ax.sensor_valid:
            detail = ax.fault_injection.faults.get("encoder", ("", False))[0]
            ax.raise_alarm(F.alarm(F.ENCODER, detail, Reaction.REMOVE_ENABLE))
            return
        ax.state = ENABLING
        ax.drive.set_enable(True, t)
        ax.drive_io.set_enable_output(True)
        if ax.sim or (not ax.servo and ax.drive_io.ready()):
            ax._become_enabled(t)          # no drive feedback to wait for (§11.1.1, §5.4.3.1)
        else:
            ax._timers["ready"] = t
            ax._schedule()

    def on_ready_timer(self, t: float) -> None:
        """While enabling: the drive reports ready (enabled now) or is asked again next servo cycle."""
        ax = self.axis
        if ax.drive.ready(t) and ax.drive_io.ready():
            ax._become_enabled(t)
        else:
            ax._timers["ready"] = t + ax.ctl.servo_cycle

    def become_enabled(self, t: float) -> None:
        ax = self.axis
        ax.state = ENABLED
        b, i = ax.ctl.bank, ax.index
        if ax._zero_at_enable():
            ax.drive.set_actual(b, 0.0)
            b.act_p[i] = 0.0
            b.sp_p[i] = 0.0
        p = float(b.act_p[i])
        b.sp_p[i], b.sp_v[i], b.sp_a[i] = p, 0.0, 0.0
        ax._set_loop_flags()
        ax._start_profile(Planner.hold(t, p))

    def disable(self, stop_mode: int) -> None:
        ax = self.axis
        t = ax.now
        ax._abort_all(t)
        if ax.state == ENABLING:
            ax._remove_enable(t, by_power=True)
            return
        ax.state = DISABLING
        p, v, a = ax._state_now()
        ax._after_stop = "disable"
        if stop_mode == 1:
            if ax.pto:
                # pulse output stopped within 30 ms (f >= 100 Hz) or up to 1.5 s at 2 Hz (§11.1.1)
                f = abs(v) / ax.config.drive.pulse_length
                duration = 0.03 if f >= 100.0 else (3.0 / f if f > 0 else 0.0)
                plan = ax.motion.ramp_out(t, p, v, duration)
                ax._start_profile(plan.profile, plan)
            else:
                ax._remove_enable(t, by_power=True)
                return
        else:
            plan = ax.motion.stop(t, p, v, a, emergency=True, jerk=stop_mode == 2)
            ax._start_profile(plan.profile, plan)
        if ax.profile.t_end <= t + _EPS_T:
            ax._remove_enable(t, by_power=True)

    def remove_enable(self, t: float, by_power: bool = False) -> None:
        """Setpoint zero and enable off; the drive stops by itself (§12.8 'Remove enable')."""
        ax = self.axis
        ax._after_stop = None
        ax.holding_zero_velocity = False
        ax.drive.set_enable(False, t)
        ax.drive_io.set_enable_output(False)
        ax.state = DISABLED
        ax._stop_positioning_monitor()
        ax._timers.pop("ready", None)
        b, i = ax.ctl.bank, ax.index
        ax._set_loop_flags()
        p = float(b.act_p[i]) if ax.servo else ax._state_now()[0]
        b.sp_v[i] = b.sp_a[i] = 0.0
        ax._start_profile(Planner.hold(t, p))
        if by_power and ax.pto:
            ax.homed = False                     # §2.5: disabling a PTO axis resets "homed"
