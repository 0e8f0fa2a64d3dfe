"""Homing of the positioning axis (S7-1200 V6 §2.5, §5.4.4.5, §11.1.3): a component the axis owns.

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

``Homing`` keeps the state of homing (the armed passive homing job, the last reference mark; the phase
of active homing is in the job's ``extra``) and reaches the axis only through ``HomingAxis``, so it can
run on any host that offers those few things.
"""
from __future__ import annotations

import math
from typing import Any, Mapping, Protocol

from . import faults as F
from ..drives.spec import EncoderInterface
from .family import DIRECT_HOMING_WHEN_DISABLED
from .faults import Fault, Reaction
from .jobs import Job, JobKind, JobState
from .motion import limits
from .profiles import Limits, Profile
from .protocols import PlannedAxis

#: encoders whose zero marks travel on the bus (an encoder of its own on the bus, the drive's encoder)
_BUS_ENCODERS = (EncoderInterface.PROFIDRIVE, EncoderInterface.DRIVE_TELEGRAM)
_MAX_REPOSITIONS = 4            # attempts to get onto the switch before giving up (16#8009)


class HomingController(Protocol):
    """What homing needs from the controller of its axis."""

    bank: Any                       # the array bank: sp_p, act_p, sp_v, act_v, seg_p, pm_target
    inputs: Mapping[str, bool]      # filtered digital inputs (the homing switches)
    rules: frozenset[str]           # version rules in force (direct homing of a disabled axis)
    _input_axes: list[Any]          # axes that watch their inputs every servo cycle

    def _retain_axis(self, axis: Any) -> None: ...


class HomingAxis(PlannedAxis, Protocol):
    """What homing needs from its axis: configuration, drive, the running job and profile, alarms."""

    ctl: HomingController
    index: int                      # the axis's slot in the array bank
    drive: Any                      # its drive channel: set_actual, zero-mark latch, mechanical_position
    motion: Any                     # its MotionPlanner: planner, stop_with
    profile: Profile
    job: Job | None                 # the running motion job
    state: str                      # "disabled", "enabling", "enabled", "disabling"
    homed: bool
    abs_offset: float               # absolute encoder adjustment (StatusSensor.AbsEncoderOffset)
    alarms: list[Fault]
    sim: bool
    servo: bool
    position_controlled: bool
    _interpolating: bool

    @property
    def now(self) -> float: ...

    @property
    def sensor_valid(self) -> bool: ...

    def _wrap(self, value: float) -> float: ...

    def _state_now(self) -> tuple[float, float, float]: ...

    def _state_at(self, t: float) -> tuple[float, float, float]: ...

    def _start_profile(self, profile: Profile, plan: Any = None) -> None: ...

    def _replan(self) -> None: ...

    def _finish_job(self, job: Job, state: JobState, t: float, fault: Fault | None = None) -> None: ...

    def _start_positioning_monitor(self, job: Job, t: float) -> None: ...

    def _blocking_alarm(self) -> Fault | None: ...

    def _apply_dirty(self, moment: str) -> Fault | None: ...

    def raise_alarm(self, fault: Fault, job: Job | None = None) -> None: ...

    def submit(self, job: Job) -> None: ...


class Homing:
    """MC_Home of one axis: direct, passive and active homing and the absolute encoder adjustment.

    ``at_once_in_simulation``: a simulated axis executes active homing at once, without motion (S7-1200
    V6 §5.4.3.1); False: it runs as a job that aborts the running motion and brakes the axis first, then
    homes at standstill (S7-1500T V5 §6.1.5.5).
    """

    #: an axis kind without homing has :class:`NoHoming` instead
    available = True

    def __init__(self, axis: HomingAxis, *, at_once_in_simulation: bool = True):
        self.axis = axis
        self.at_once_in_simulation = at_once_in_simulation
        self.passive: Job | None = None             # armed passive homing (MC_Home mode 2)
        self.reference_mark = 0.0                   # the position the axis was homed to last

    # --- configuration --------------------------------------------------------------------------------
    def inputs(self) -> dict[str, str]:
        """Input addresses of the active and the passive homing switch ("" none)."""
        h = self.axis.config.homing
        return {"active": h.active.input, "passive": h.passive.input}

    def configured(self, mode: int) -> bool:
        """Is the homing method for MC_Home ``mode`` (2 passive, 3 active) configured (§12.8 16#8404/16#0015)?"""
        a = self.axis
        if a.sim:
            return True                               # simulation homes at once (§5.4.3.1)
        c = a.config
        homing = c.homing.active if mode == 3 else c.homing.passive
        method = homing.mode
        has_input = bool(homing.input)
        # zero marks come with an encoder on the bus (its own telegram or the drive's)
        zero_marks = a.servo and c.drive.encoder.interface in _BUS_ENCODERS
        if method == 2:
            return has_input
        if method == 0:
            return zero_marks
        return zero_marks and has_input

    def absolute_encoder(self) -> bool:
        a = self.axis
        return (not a.pto) and a.config.drive.encoder.absolute

    def absolute_raw(self) -> float:
        """Position the absolute encoder reports without adjustment: the machine position in whole increments."""
        a = self.axis
        q = a.position_resolution()
        return math.floor(a.drive.mechanical_position() / q) * q

    def _cam(self, kind: str) -> bool:
        """Homing switch actuated (filtered input compared with the configured level)."""
        c = self.axis.config
        homing = c.homing.active if kind == "Active" else c.homing.passive
        address = homing.input
        if not address:
            return False
        return self.axis.ctl.inputs[address] == homing.active_high

    # --- direct homing and absolute encoder adjustment ---------------------------------------------------
    def home_direct(self, job: Job) -> None:
        """Mode 0: position := Position; 1: position += Position; 6/7: absolute encoder adjustment."""
        a = self.axis
        disabled_ok = DIRECT_HOMING_WHEN_DISABLED in a.ctl.rules and not a.pto and job.mode in (0, 1)
        if a.state != "enabled" and not (disabled_ok and a.state == "disabled"):
            job.finish(JobState.ERROR, F.reject(F.NOT_ENABLED))
            return
        if a.job is not None and a.job.busy and a.job.kind == JobKind.HOME_ACTIVE:
            job.finish(JobState.ERROR, F.reject(F.REJECTED, "homing_active"))
            return
        if a.job is not None and a.job.busy and a.job.kind == JobKind.TABLE and job.mode in (0, 1):
            job.finish(JobState.ERROR, F.reject(F.REJECTED, "homing_table"))
            return
        if a.servo and not a.sensor_valid:
            job.finish(JobState.ERROR, F.reject(F.REJECTED, "actual_invalid"))   # StatusSensor.State != 2
            return
        ref = float(a.ctl.bank.sp_p[a.index])   # "current axis position": the Position tag (§12.9.1)
        if job.mode in (0, 7):
            new = a._wrap(job.position)
            delta = new - ref
        else:
            delta = job.position
            new = ref + delta
        if job.mode in (6, 7):
            a.abs_offset += delta
            a.ctl._retain_axis(a)
        self._shift(delta)
        a.homed = True
        if job.mode in (6, 7):
            a.ctl._retain_axis(a)
        self.reference_mark = a._wrap(new)
        job.reference_position = self.reference_mark
        job.finish(JobState.DONE)
        a._replan()

    def drive_homed(self, position: float) -> None:
        """The drive homed itself (a homing run in the drive, e.g. CiA 402 homing mode) and its actual value
        reads ``position`` now: the coordinates follow that value, the axis is homed and the reference mark
        is there.  Every family's homing status is ``axis.homed``."""
        a = self.axis
        b, i = a.ctl.bank, a.index
        self._shift(position - float(b.act_p[i]))
        a.homed = True
        self.reference_mark = a._wrap(position)
        a.ctl._retain_axis(a)
        a._replan()

    def _shift(self, delta: float) -> None:
        """Move the coordinate system by ``delta`` (setpoint, actual value, profile, targets)."""
        if delta == 0.0:
            return
        a = self.axis
        b, i = a.ctl.bank, a.index
        for seg in a.profile.segments:
            seg.p += delta
        b.seg_p[i] += delta
        b.sp_p[i] += delta
        a.drive.set_actual(b, float(b.act_p[i]) + delta if a.servo else float(b.sp_p[i]))
        b.pm_target[i] += delta
        job = a.job
        if job is not None and job.kind != JobKind.ABSOLUTE:
            job.target += delta

    def _set_home(self, latched: float, coordinate: float) -> None:
        """The homing event: the actual position ``latched`` gets ``coordinate`` (homed from now on)."""
        a = self.axis
        self._shift(coordinate - latched)
        a.homed = True
        self.reference_mark = a._wrap(coordinate)

    # --- MC_Home mode 2 and 3 ----------------------------------------------------------------------------
    def home(self, job: Job) -> None:
        """Start passive (mode 2) or active (mode 3) homing."""
        a = self.axis
        if a.state != "enabled":
            job.finish(JobState.ERROR, F.reject(F.NOT_ENABLED))
            return
        blocking = a._blocking_alarm()
        if blocking is not None:
            job.finish(JobState.ERROR, blocking)
            return
        if a.servo and not a.sensor_valid:
            job.finish(JobState.ERROR, F.reject(F.REJECTED, "actual_invalid"))
            return
        if a.sim and (job.kind == JobKind.HOME_PASSIVE or self.at_once_in_simulation):
            # simulation: homing is executed at once, without motion (§5.4.3.1)
            if job.kind == JobKind.HOME_ACTIVE and a.job is not None and a.job.busy:
                a._finish_job(a.job, JobState.ABORTED, a.now)
            self._set_home(float(a.ctl.bank.sp_p[a.index]), a._wrap(job.position))
            job.reference_position = self.reference_mark
            job.finish(JobState.DONE)
            a._replan()
            return
        active = a.job if a.job is not None and a.job.busy else None
        if job.kind == JobKind.HOME_PASSIVE:
            if active is not None and active.kind == JobKind.HOME_ACTIVE:
                job.finish(JobState.ERROR, F.reject(F.REJECTED, "homing_active"))
                return
            if active is not None and active.kind == JobKind.TABLE:
                job.finish(JobState.ERROR, F.reject(F.REJECTED, "homing_table"))
                return
            if a.pto and a._apply_dirty("passive_homing") is not None:
                job.finish(JobState.ERROR, a.alarms[-1])
                return
            if self.passive is not None and self.passive.busy:
                a._finish_job(self.passive, JobState.ABORTED, a.now)
            self._arm_passive(job)
            return
        # active homing
        if a.pto and a._apply_dirty("active_homing") is not None:
            job.finish(JobState.ERROR, a.alarms[-1])
            return
        fault = None if a.sim else self._velocity_fault()   # simulation uses no homing velocities
        if fault is not None:
            a.raise_alarm(fault)
            job.finish(JobState.ERROR, fault)
            return
        a.submit(job)                         # aborts the running motion and passive homing

    def _velocity_fault(self) -> F.Fault | None:
        """Approach/referencing velocity: 0 is an operating error (16#8011/16#8012), outside the
        start/stop..maximum velocity a configuration error (16#8610/16#8611) (§5.4.4.5, §12.8)."""
        c = self.axis.config
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

    # --- passive homing as seen by the other jobs ----------------------------------------------------------
    @property
    def passive_busy(self) -> bool:
        """Passive homing is armed (StatusBits.HomingCommand of the S7-1200 counts it)."""
        return self.passive is not None and self.passive.busy

    def end_passive(self, state: JobState, fault: Fault | None = None) -> None:
        """End an armed passive homing (aborted by another job, error at an alarm, cancelled)."""
        passive = self.passive
        if passive is not None:
            self.axis._finish_job(passive, state, self.axis.now, fault)
        self.passive = None

    # --- active homing (a motion job; profiles started here, events from axis and switches) ---------------
    def start_active(self, job: Job, t: float) -> None:
        """The axis has made the active homing ``job`` its running job: watch the inputs every servo
        cycle (switch edges, zero marks) and start the first phase instead of a motion plan."""
        a = self.axis
        if not a.sim and a not in a.ctl._input_axes:      # a simulated axis has no switch to watch
            a.ctl._input_axes.append(a)
        self._start(job, t)

    def _start(self, job: Job, t: float) -> None:
        a = self.axis
        a.homed = False                                     # §2.5: reset at the start of active homing
        if a.sim:
            # S7-1500T V5 §6.1.5.5: active homing aborts the traversing motion (done by the override of
            # submit); a simulated axis has no switch to search: brake to standstill, then home there
            self._phase(job, "simulated", 0.0, t)
            return
        h = a.config.homing
        d = 1.0 if h.approach_positive else -1.0
        upper = h.active.upper_side
        method = h.active.mode
        job.extra.update(d=d, method=method, repositions=0, reversed=False,
                         edge="exit" if upper == (d > 0) else "entry")
        if method == 0:                                     # zero mark only
            self._phase(job, "zero_mark", d * h.referencing_velocity, t)
            a.drive.arm_zero_mark(d)
            return
        if self._cam("Active"):
            self._phase(job, "brake", 0.0, t)               # on the switch already: stop there first
            job.extra["last_dir"] = d
        else:
            self._phase(job, "search", d * h.approach_velocity, t)
            job.extra["last_dir"] = d

    def _phase(self, job: Job, phase: str, velocity: float, t: float) -> None:
        """Enter ``phase``: run at ``velocity`` (0: brake to standstill)."""
        a = self.axis
        job.extra["phase"] = phase
        if velocity != 0.0:
            job.extra["last_dir"] = 1.0 if velocity > 0 else -1.0
        p, v, acc = a._state_now()
        lim = self._limits()
        profile = (a.motion.planner.velocity(t, p, v, acc, velocity, lim) if velocity != 0.0
                   else a.motion.stop_with(t, p, v, acc, lim))
        a._interpolating = True
        a._start_profile(profile)

    def _limits(self) -> Limits:
        return limits(self.axis)

    def on_profile_end(self, job: Job, t: float) -> None:
        """The profile of the current phase of active homing has ended (standstill or velocity reached)."""
        a = self.axis
        phase = job.extra.get("phase")
        if phase == "simulated":
            a._interpolating = False
            self._set_home(a._state_at(t)[0], a._wrap(job.position))
            job.reference_position = self.reference_mark
            a._finish_job(job, JobState.DONE, t)
            return
        h = a.config.homing
        d = job.extra["d"]
        v_ref = h.referencing_velocity
        if phase in ("search", "zero_mark", "final", "leave", "return", "through"):
            return                                          # constant velocity reached: keep going
        if phase == "reverse":
            self._phase(job, "search", -job.extra["search_dir"] * h.approach_velocity, t)
            job.extra["search_dir"] = -job.extra["search_dir"]
            return
        if phase == "brake":
            if job.extra["method"] == 1:
                self._proximity_next(job, t)
                return
            on_cam = self._cam("Active")
            if on_cam:
                if job.extra["edge"] == "exit":
                    self._phase(job, "final", d * v_ref, t)
                else:
                    self._phase(job, "leave", -d * v_ref, t)
                return
            job.extra["repositions"] += 1
            if job.extra["repositions"] > _MAX_REPOSITIONS:
                a.raise_alarm(F.alarm(F.REFERENCE_NOT_FOUND, "", Reaction.EMERGENCY))
                return
            self._phase(job, "return", -job.extra["last_dir"] * v_ref, t)
            return
        if phase == "brake_off":
            if self._cam("Active"):                         # braked back onto the switch: leave again
                self._phase(job, "leave", -d * v_ref, t)
            else:
                self._phase(job, "final", d * v_ref, t)
            return
        if phase in ("offset", "stop"):
            a._interpolating = False
            if a.servo and a.position_controlled:
                a._start_positioning_monitor(job, t)
            else:
                a._finish_job(job, JobState.DONE, t)

    def check_inputs(self, t: float) -> None:
        """Homing switch edges and zero marks, for the running active or passive homing."""
        job = self.axis.job
        if job is not None and job.busy and job.kind == JobKind.HOME_ACTIVE:
            self._active_inputs(job, t)
        passive = self.passive
        if passive is not None and passive.busy:
            self._passive_inputs(passive, t)

    def _active_inputs(self, job: Job, t: float) -> None:
        x = job.extra
        cam = self._cam("Active")
        rising, falling = cam and not x.get("cam", cam), (not cam) and x.get("cam", cam)
        x["cam"] = cam
        phase = x.get("phase")
        latched = self.axis.drive.zero_mark_latched() if x.get("method") in (0, 1) else None
        if latched is not None and phase == "zero_mark":
            self._event(job, latched, t)
            return
        if x["method"] == 1:
            self._proximity_inputs(job, rising, falling, t)
            return
        if phase == "search" and rising:
            self._phase(job, "brake", 0.0, t)
        elif phase == "return" and rising:
            self._phase(job, "brake", 0.0, t)
        elif phase == "final" and x["edge"] == "exit" and falling:
            self._event(job, self._latch_position(), t)
        elif phase == "final" and x["edge"] == "entry" and rising:
            self._event(job, self._latch_position(), t)
        elif phase == "leave" and falling:
            self._phase(job, "brake_off", 0.0, t)

    def _proximity_inputs(self, job: Job, rising: bool, falling: bool, t: float) -> None:
        """ActiveHoming.Mode 1: proximity switch, then the first zero mark after leaving it in d."""
        x = job.extra
        d = x["d"]
        phase = x.get("phase")
        if phase in ("search", "return") and rising:
            if x["last_dir"] == d:
                self._phase(job, "through", d * self.axis.config.homing.referencing_velocity, t)
            else:
                x["phase"] = "cross_back"                   # found from the wrong side: pass it first
        elif phase == "cross_back" and falling:
            self._phase(job, "brake", 0.0, t)
        elif phase == "through" and falling:
            x["phase"] = "zero_mark"
            self.axis.drive.arm_zero_mark(d)

    def _proximity_next(self, job: Job, t: float) -> None:
        d = job.extra["d"]
        v_ref = self.axis.config.homing.referencing_velocity
        if self._cam("Active"):
            self._phase(job, "through", d * v_ref, t)
        else:
            self._phase(job, "return", d * v_ref, t)

    def hw_limit(self, side: str, t: float) -> bool:
        """A hardware limit switch during active homing: reverse if permitted (True = handled)."""
        a = self.axis
        job = a.job
        if job is None or job.extra.get("phase") == "simulated":
            return False
        x = job.extra
        toward = (side == "max") == (x.get("last_dir", x["d"]) > 0)
        if not toward or not a.config.homing.auto_reversal or x.get("phase") not in ("search", "return"):
            return False
        if x.get("reversed"):
            # the switch was not found between the limit switches
            a.raise_alarm(F.alarm(F.REFERENCE_NOT_FOUND, "", Reaction.EMERGENCY))
            return True
        x["reversed"] = True
        x["search_dir"] = x.get("last_dir", x["d"])
        self._phase(job, "reverse", 0.0, t)                 # brake with the configured deceleration
        return True

    def _latch_position(self) -> float:
        a = self.axis
        return float(a.ctl.bank.act_p[a.index])

    def _event(self, job: Job, latched: float, t: float) -> None:
        a = self.axis
        h = a.config.homing
        offset = h.active.home_offset
        target = a._wrap(job.position)
        a.drive.disarm_zero_mark()
        self._set_home(latched, target - offset)
        job.reference_position = a._wrap(target - offset)
        p, v, acc = a._state_now()
        if offset != 0.0:
            lim = limits(a, h.referencing_velocity)
            job.extra["phase"] = "offset"
            job.target = target
            a._start_profile(a.motion.planner.position(t, p, v, acc, target, lim))
        else:
            job.extra["phase"] = "stop"
            a._start_profile(a.motion.stop_with(t, p, v, acc, self._limits()))
        a._interpolating = True

    # --- passive homing ------------------------------------------------------------------------------------
    def _arm_passive(self, job: Job) -> None:
        a = self.axis
        h = a.config.homing
        d = 1.0 if h.approach_positive else -1.0
        upper = h.passive.upper_side
        method = h.passive.mode
        job.extra.update(d=d, method=method, edge="exit" if upper == (d > 0) else "entry",
                         cam=self._cam("Passive"), left=False)
        self.passive = job
        if method == 0:
            a.drive.arm_zero_mark(d)

    def _passive_inputs(self, job: Job, t: float) -> None:
        x = job.extra
        cam = self._cam("Passive")
        rising, falling = cam and not x["cam"], (not cam) and x["cam"]
        x["cam"] = cam
        if x["method"] in (0, 1):
            drive = self.axis.drive
            if x["method"] == 1 and falling and self._moving_direction() == x["d"]:
                drive.arm_zero_mark(x["d"])
            latched = drive.zero_mark_latched()
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

    def _moving_direction(self) -> float:
        a = self.axis
        b, i = a.ctl.bank, a.index
        v = float(b.act_v[i]) if a.servo else float(b.sp_v[i])
        tol = max(a.config.standstill.velocity_threshold if a.servo else 0.0, 1e-9)
        return 1.0 if v > tol else -1.0 if v < -tol else 0.0

    def _passive_event(self, job: Job, latched: float, t: float) -> None:
        a = self.axis
        a.drive.disarm_zero_mark()
        self._set_home(latched, a._wrap(job.position))
        job.reference_position = self.reference_mark
        self.passive = None
        job.finish(JobState.DONE)
        a._replan()


class NoHoming:
    """The homing part of an axis kind that has no homing (a speed-controlled axis, say): the same interface
    as :class:`Homing`, so the axis core needs no special case, and every homing request is refused as a
    function this kind of technology object does not have."""

    available = False
    passive: Job | None = None
    reference_mark = 0.0

    def __init__(self, axis: HomingAxis, **_: Any):
        self.axis = axis

    def inputs(self) -> dict[str, str]:
        return {"active": "", "passive": ""}

    def configured(self, mode: int) -> bool:
        return False

    def absolute_encoder(self) -> bool:
        return False

    def absolute_raw(self) -> float:
        return 0.0

    def _refuse(self, job: Job) -> None:
        job.finish(JobState.ERROR, F.reject(F.NOT_AVAILABLE, "homing"))

    def home(self, job: Job) -> None:
        self._refuse(job)

    def home_direct(self, job: Job) -> None:
        self._refuse(job)

    def start_active(self, job: Job, t: float) -> None:     # not reached: check_start refuses the job
        self.axis._finish_job(job, JobState.ERROR, t, F.reject(F.NOT_AVAILABLE, "homing"))

    def end_passive(self, state: JobState, fault: Fault | None = None) -> None:
        return None

    def drive_homed(self, position: float) -> None:
        return None                 # an axis kind without homing has no "homed" to set

    def on_profile_end(self, job: Job, t: float) -> None:
        return None

    def check_inputs(self, t: float) -> None:
        return None

    def hw_limit(self, side: str, t: float) -> bool:
        return False
