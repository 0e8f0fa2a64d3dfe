"""Homing of the positioning axis (S7-1200 V6 §2.5, §5.4.4.5, §11.1.3).

Direct homing (modes 0/1) sets the coordinates at once.  Passive homing (mode 2) watches the homing
switch or the encoder zero mark while other commands move the axis.  Active homing (mode 3) is a motion
job of its own: search the homing switch at the approach velocity, then cross the configured end of the
switch in the homing direction at the referencing velocity (that crossing is the homing event), then
travel the home position offset.  Absolute encoder adjustment (modes 6/7) stores an offset retentively.

Conventions (recorded in docs/decisions.md): the homing direction equals the approach direction
(`Homing.ApproachDirection`); the configured end (`SideInput`: FALSE lower end, TRUE upper end) is
crossed while moving in the homing direction, i.e. it is either the end where the axis enters the switch
or the end where it leaves it.  The homing event assigns ``Position - HomePositionOffset`` to the
position where it happened; the axis then travels to ``Position``.
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

from . import faults as F
from ..drives.spec import EncoderInterface
from .family import DIRECT_HOMING_WHEN_DISABLED
from .faults import Reaction
from .jobs import Job, JobKind, JobState
from .profiles import Limits

if TYPE_CHECKING:  # pragma: no cover
    from .axis import PositioningAxis

#: encoders whose zero marks travel on the bus (an encoder of its own on the bus, the drive's encoder)
_BUS_ENCODERS = (EncoderInterface.PROFIDRIVE, EncoderInterface.DRIVE_TELEGRAM)
_MAX_REPOSITIONS = 4            # attempts to get onto the switch before giving up (16#8009)


class HomingMixin:
    """Mixed into PositioningAxis."""

    #: a simulated axis executes active homing at once, without motion (S7-1200 V6 §5.4.3.1); the S7-1500
    #: runs it as a job that aborts the running motion and brakes the axis first (``_homing_start``)
    _sim_homing_at_once = True

    # --- configuration --------------------------------------------------------------------------------
    def _homing_inputs(self: "PositioningAxis") -> dict[str, str]:
        h = self.config.homing
        return {"active": h.active.input, "passive": h.passive.input}

    def homing_configured(self: "PositioningAxis", mode: int) -> bool:
        """Is the homing method for MC_Home ``mode`` (2 passive, 3 active) configured (§12.8 16#8404/16#0015)?"""
        if self.sim:
            return True                               # simulation homes at once (§5.4.3.1)
        c = self.config
        homing = c.homing.active if mode == 3 else c.homing.passive
        method = homing.mode
        has_input = bool(homing.input)
        # zero marks come with an encoder on the bus (its own telegram or the drive's)
        zero_marks = self.servo and c.drive.encoder.interface in _BUS_ENCODERS
        if method == 2:
            return has_input
        if method == 0:
            return zero_marks
        return zero_marks and has_input

    def absolute_encoder(self: "PositioningAxis") -> bool:
        return (not self.pto) and self.config.drive.encoder.absolute

    def _absolute_raw(self: "PositioningAxis") -> float:
        """Position the absolute encoder reports without adjustment: the machine position in whole increments."""
        q = self.position_resolution()
        return math.floor(self.drive.mechanical_position() / q) * q

    def _cam(self: "PositioningAxis", kind: str) -> bool:
        """Homing switch actuated (filtered input compared with the configured level)."""
        homing = self.config.homing.active if kind == "Active" else self.config.homing.passive
        address = homing.input
        if not address:
            return False
        return self.ctl.inputs[address] == homing.active_high

    # --- direct homing and absolute encoder adjustment ---------------------------------------------------
    def home_direct(self: "PositioningAxis", job: Job) -> None:
        """Mode 0: position := Position; 1: position += Position; 6/7: absolute encoder adjustment."""
        disabled_ok = DIRECT_HOMING_WHEN_DISABLED in self.ctl.rules and not self.pto and job.mode in (0, 1)
        if self.state != "enabled" and not (disabled_ok and self.state == "disabled"):
            job.finish(JobState.ERROR, F.reject(F.NOT_ENABLED))
            return
        if self.job is not None and self.job.busy and self.job.kind == JobKind.HOME_ACTIVE:
            job.finish(JobState.ERROR, F.reject(F.REJECTED, "homing_active"))
            return
        if self.job is not None and self.job.busy and self.job.kind == JobKind.TABLE and job.mode in (0, 1):
            job.finish(JobState.ERROR, F.reject(F.REJECTED, "homing_table"))
            return
        if self.servo and not self.sensor_valid:
            job.finish(JobState.ERROR, F.reject(F.REJECTED, "actual_invalid"))   # StatusSensor.State != 2
            return
        ref = float(self.ctl.bank.sp_p[self.index])   # "current axis position": the Position tag (§12.9.1)
        if job.mode in (0, 7):
            new = self._wrap(job.position)
            delta = new - ref
        else:
            delta = job.position
            new = ref + delta
        if job.mode in (6, 7):
            self.abs_offset += delta
            self.ctl._retain_axis(self)
        self._shift(delta)
        self.homed = True
        if job.mode in (6, 7):
            self.ctl._retain_axis(self)
        self.reference_mark = self._wrap(new)
        job.reference_position = self.reference_mark
        job.finish(JobState.DONE)
        self._replan()

    def _shift(self: "PositioningAxis", delta: float) -> None:
        """Move the coordinate system by ``delta`` (setpoint, actual value, profile, targets)."""
        if delta == 0.0:
            return
        b, i = self.ctl.bank, self.index
        for seg in self.profile.segments:
            seg.p += delta
        b.seg_p[i] += delta
        b.sp_p[i] += delta
        self.drive.set_actual(b, float(b.act_p[i]) + delta if self.servo else float(b.sp_p[i]))
        b.pm_target[i] += delta
        job = self.job
        if job is not None and job.kind != JobKind.ABSOLUTE:
            job.target += delta

    def _set_home(self: "PositioningAxis", latched: float, coordinate: float) -> None:
        """The homing event: the actual position ``latched`` gets ``coordinate`` (homed from now on)."""
        self._shift(coordinate - latched)
        self.homed = True
        self.reference_mark = self._wrap(coordinate)

    # --- MC_Home mode 2 and 3 ----------------------------------------------------------------------------
    def home(self: "PositioningAxis", job: Job) -> None:
        """Start passive (mode 2) or active (mode 3) homing."""
        if self.state != "enabled":
            job.finish(JobState.ERROR, F.reject(F.NOT_ENABLED))
            return
        blocking = self._blocking_alarm()
        if blocking is not None:
            job.finish(JobState.ERROR, blocking)
            return
        if self.servo and not self.sensor_valid:
            job.finish(JobState.ERROR, F.reject(F.REJECTED, "actual_invalid"))
            return
        if self.sim and (job.kind == JobKind.HOME_PASSIVE or self._sim_homing_at_once):
            # simulation: homing is executed at once, without motion (§5.4.3.1)
            if job.kind == JobKind.HOME_ACTIVE and self.job is not None and self.job.busy:
                self._finish_job(self.job, JobState.ABORTED, self.now)
            self._set_home(float(self.ctl.bank.sp_p[self.index]), self._wrap(job.position))
            job.reference_position = self.reference_mark
            job.finish(JobState.DONE)
            self._replan()
            return
        active = self.job if self.job is not None and self.job.busy else None
        if job.kind == JobKind.HOME_PASSIVE:
            if active is not None and active.kind == JobKind.HOME_ACTIVE:
                job.finish(JobState.ERROR, F.reject(F.REJECTED, "homing_active"))
                return
            if active is not None and active.kind == JobKind.TABLE:
                job.finish(JobState.ERROR, F.reject(F.REJECTED, "homing_table"))
                return
            if self.pto and self._apply_dirty("passive_homing") is not None:
                job.finish(JobState.ERROR, self.alarms[-1])
                return
            if self.passive_home is not None and self.passive_home.busy:
                self._finish_job(self.passive_home, JobState.ABORTED, self.now)
            self._arm_passive(job)
            return
        # active homing
        if self.pto and self._apply_dirty("active_homing") is not None:
            job.finish(JobState.ERROR, self.alarms[-1])
            return
        fault = None if self.sim else self._homing_velocity_fault()   # simulation uses no homing velocities
        if fault is not None:
            if fault.kind == F.CONFIG:
                self.raise_alarm(fault)
            else:
                self.raise_alarm(fault)
            job.finish(JobState.ERROR, fault)
            return
        self.submit(job)                      # aborts the running motion and passive homing

    def _homing_velocity_fault(self: "PositioningAxis") -> F.Fault | None:
        """Approach/referencing velocity: 0 is an operating error (16#8011/16#8012), outside the
        start/stop..maximum velocity a configuration error (16#8610/16#8611) (§5.4.4.5, §12.8)."""
        c = self.config
        vmax, vmin = c.limits.max_velocity, c.limits.start_stop_velocity
        for field, v, zero_kind in (("homing.approach_velocity", c.homing.approach_velocity, F.HOMING_APPROACH_ZERO),
                                    ("homing.referencing_velocity", c.homing.referencing_velocity,
                                     F.HOMING_REFERENCING_ZERO)):
            if c.homing.active.mode == 0 and field == "homing.approach_velocity":
                continue                                     # the zero mark search uses only the homing velocity
            path = c.tag_name(field)                         # a configuration fault names the family's tag
            if v <= 0.0:
                return F.alarm(zero_kind, "", Reaction.REMOVE_ENABLE)
            if v > vmax * (1 + 1e-12):
                return F.config_fault(path, "rule:above_max", f"{path} = {v:g} > MaxVelocity {vmax:g}")
            if v < vmin * (1 - 1e-12):
                return F.config_fault(path, "rule:below_start_stop", f"{path} = {v:g} < start/stop velocity {vmin:g}")
        return None

    # --- active homing (a motion job; profiles started here, events from axis and switches) ---------------
    def _homing_start(self: "PositioningAxis", job: Job, t: float) -> None:
        """Called by the axis instead of a motion plan when an active homing job starts."""
        self.homed = False                                  # §2.5: reset at the start of active homing
        if self.sim:
            # S7-1500T V5 §6.1.5.5: active homing aborts the traversing motion (done by the override of
            # submit); a simulated axis has no switch to search: brake to standstill, then home there
            self._homing_phase(job, "simulated", 0.0, t)
            return
        h = self.config.homing
        d = 1.0 if h.approach_positive else -1.0
        upper = h.active.upper_side
        method = h.active.mode
        job.extra.update(d=d, method=method, repositions=0, reversed=False,
                         edge="exit" if upper == (d > 0) else "entry")
        if method == 0:                                     # zero mark only
            self._homing_phase(job, "zero_mark", d * h.referencing_velocity, t)
            self.drive.arm_zero_mark(d)
            return
        if self._cam("Active"):
            self._homing_phase(job, "brake", 0.0, t)        # on the switch already: stop there first
            job.extra["last_dir"] = d
        else:
            self._homing_phase(job, "search", d * h.approach_velocity, t)
            job.extra["last_dir"] = d

    def _homing_phase(self: "PositioningAxis", job: Job, phase: str, velocity: float, t: float) -> None:
        """Enter ``phase``: run at ``velocity`` (0: brake to standstill)."""
        job.extra["phase"] = phase
        if velocity != 0.0:
            job.extra["last_dir"] = 1.0 if velocity > 0 else -1.0
        p, v, a = self._state_now()
        lim = self._homing_limits()
        profile = (self.motion.planner.velocity(t, p, v, a, velocity, lim) if velocity != 0.0
                   else self.motion.stop_with(t, p, v, a, lim))
        self._interpolating = True
        self._start_profile(profile)

    def _homing_limits(self: "PositioningAxis") -> Limits:
        from .motion import limits
        return limits(self)

    def _homing_end(self: "PositioningAxis", job: Job, t: float) -> None:
        """The profile of the current phase has ended (standstill or velocity reached)."""
        phase = job.extra.get("phase")
        if phase == "simulated":
            self._interpolating = False
            self._set_home(self._state_at(t)[0], self._wrap(job.position))
            job.reference_position = self.reference_mark
            self._finish_job(job, JobState.DONE, t)
            return
        h = self.config.homing
        d = job.extra["d"]
        v_ref = h.referencing_velocity
        if phase in ("search", "zero_mark", "final", "leave", "return", "through"):
            return                                          # constant velocity reached: keep going
        if phase == "reverse":
            self._homing_phase(job, "search", -job.extra["search_dir"] * h.approach_velocity, t)
            job.extra["search_dir"] = -job.extra["search_dir"]
            return
        if phase == "brake":
            if job.extra["method"] == 1:
                self._homing_proximity_next(job, t)
                return
            on_cam = self._cam("Active")
            if on_cam:
                if job.extra["edge"] == "exit":
                    self._homing_phase(job, "final", d * v_ref, t)
                else:
                    self._homing_phase(job, "leave", -d * v_ref, t)
                return
            job.extra["repositions"] += 1
            if job.extra["repositions"] > _MAX_REPOSITIONS:
                self.raise_alarm(F.alarm(F.REFERENCE_NOT_FOUND, "", Reaction.EMERGENCY))
                return
            self._homing_phase(job, "return", -job.extra["last_dir"] * v_ref, t)
            return
        if phase == "brake_off":
            if self._cam("Active"):                         # braked back onto the switch: leave again
                self._homing_phase(job, "leave", -d * v_ref, t)
            else:
                self._homing_phase(job, "final", d * v_ref, t)
            return
        if phase in ("offset", "stop"):
            self._interpolating = False
            if self.servo and self.position_controlled:
                self._start_positioning_monitor(job, t)
            else:
                self._finish_job(job, JobState.DONE, t)

    def _homing_check_inputs(self: "PositioningAxis", t: float) -> None:
        """Homing switch edges and zero marks, for the running active or passive homing."""
        job = self.job
        if job is not None and job.busy and job.kind == JobKind.HOME_ACTIVE:
            self._homing_active_inputs(job, t)
        passive = self.passive_home
        if passive is not None and passive.busy:
            self._homing_passive_inputs(passive, t)

    def _homing_active_inputs(self: "PositioningAxis", job: Job, t: float) -> None:
        x = job.extra
        cam = self._cam("Active")
        rising, falling = cam and not x.get("cam", cam), (not cam) and x.get("cam", cam)
        x["cam"] = cam
        phase = x.get("phase")
        latched = self.drive.zero_mark_latched() if x.get("method") in (0, 1) else None
        if latched is not None and phase == "zero_mark":
            self._homing_event(job, latched, t)
            return
        if x["method"] == 1:
            self._homing_proximity_inputs(job, rising, falling, t)
            return
        if phase == "search" and rising:
            self._homing_phase(job, "brake", 0.0, t)
        elif phase == "return" and rising:
            self._homing_phase(job, "brake", 0.0, t)
        elif phase == "final" and x["edge"] == "exit" and falling:
            self._homing_event(job, self._latch_position(), t)
        elif phase == "final" and x["edge"] == "entry" and rising:
            self._homing_event(job, self._latch_position(), t)
        elif phase == "leave" and falling:
            self._homing_phase(job, "brake_off", 0.0, t)

    def _homing_proximity_inputs(self: "PositioningAxis", job: Job, rising: bool, falling: bool, t: float) -> None:
        """ActiveHoming.Mode 1: proximity switch, then the first zero mark after leaving it in d."""
        x = job.extra
        d = x["d"]
        phase = x.get("phase")
        if phase in ("search", "return") and rising:
            if x["last_dir"] == d:
                self._homing_phase(job, "through", d * self.config.homing.referencing_velocity, t)
            else:
                x["phase"] = "cross_back"                   # found from the wrong side: pass it first
        elif phase == "cross_back" and falling:
            self._homing_phase(job, "brake", 0.0, t)
        elif phase == "through" and falling:
            x["phase"] = "zero_mark"
            self.drive.arm_zero_mark(d)

    def _homing_proximity_next(self: "PositioningAxis", job: Job, t: float) -> None:
        d = job.extra["d"]
        v_ref = self.config.homing.referencing_velocity
        if self._cam("Active"):
            self._homing_phase(job, "through", d * v_ref, t)
        else:
            self._homing_phase(job, "return", d * v_ref, t)

    def _homing_hw_limit(self: "PositioningAxis", side: str, t: float) -> bool:
        """A hardware limit switch during active homing: reverse if permitted (True = handled)."""
        job = self.job
        if job is None or job.extra.get("phase") == "simulated":
            return False
        x = job.extra
        toward = (side == "max") == (x.get("last_dir", x["d"]) > 0)
        if not toward or not self.config.homing.auto_reversal or x.get("phase") not in ("search", "return"):
            return False
        if x.get("reversed"):
            # the switch was not found between the limit switches
            self.raise_alarm(F.alarm(F.REFERENCE_NOT_FOUND, "", Reaction.EMERGENCY))
            return True
        x["reversed"] = True
        x["search_dir"] = x.get("last_dir", x["d"])
        self._homing_phase(job, "reverse", 0.0, t)         # brake with the configured deceleration
        return True

    def _latch_position(self: "PositioningAxis") -> float:
        return float(self.ctl.bank.act_p[self.index])

    def _homing_event(self: "PositioningAxis", job: Job, latched: float, t: float) -> None:
        h = self.config.homing
        offset = h.active.home_offset
        target = self._wrap(job.position)
        self.drive.disarm_zero_mark()
        self._set_home(latched, target - offset)
        job.reference_position = self._wrap(target - offset)
        p, v, a = self._state_now()
        if offset != 0.0:
            from .motion import limits
            lim = limits(self, h.referencing_velocity)
            job.extra["phase"] = "offset"
            job.target = target
            self._start_profile(self.motion.planner.position(t, p, v, a, target, lim))
        else:
            job.extra["phase"] = "stop"
            self._start_profile(self.motion.stop_with(t, p, v, a, self._homing_limits()))
        self._interpolating = True

    # --- passive homing ------------------------------------------------------------------------------------
    def _arm_passive(self: "PositioningAxis", job: Job) -> None:
        h = self.config.homing
        d = 1.0 if h.approach_positive else -1.0
        upper = h.passive.upper_side
        method = h.passive.mode
        job.extra.update(d=d, method=method, edge="exit" if upper == (d > 0) else "entry",
                         cam=self._cam("Passive"), left=False)
        self.passive_home = job
        if method == 0:
            self.drive.arm_zero_mark(d)

    def _homing_passive_inputs(self: "PositioningAxis", job: Job, t: float) -> None:
        x = job.extra
        cam = self._cam("Passive")
        rising, falling = cam and not x["cam"], (not cam) and x["cam"]
        x["cam"] = cam
        if x["method"] in (0, 1):
            if x["method"] == 1 and falling and self._moving_direction() == x["d"]:
                self.drive.arm_zero_mark(x["d"])
            latched = self.drive.zero_mark_latched()
            if latched is not None:
                self._passive_event(job, latched, t)
            return
        if not (rising or falling):
            return
        motion = self._moving_direction()
        if motion == 0.0:
            # at standstill the next edge of the switch homes the axis (§5.4.4.5)
            self._passive_event(job, self._latch_position(), t)
            return
        wanted = rising if x["edge"] == "entry" else falling
        if motion == x["d"] and wanted:
            self._passive_event(job, self._latch_position(), t)

    def _moving_direction(self: "PositioningAxis") -> float:
        b, i = self.ctl.bank, self.index
        v = float(b.act_v[i]) if self.servo else float(b.sp_v[i])
        tol = max(self.config.standstill.velocity_threshold if self.servo else 0.0, 1e-9)
        return 1.0 if v > tol else -1.0 if v < -tol else 0.0

    def _passive_event(self: "PositioningAxis", job: Job, latched: float, t: float) -> None:
        self.drive.disarm_zero_mark()
        self._set_home(latched, self._wrap(job.position))
        job.reference_position = self.reference_mark
        self.passive_home = None
        job.finish(JobState.DONE)
        self._replan()
