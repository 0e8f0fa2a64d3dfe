"""Positioning axis technology object: enable state machine, jobs, alarms, homing, configuration.

The axis owns one slot in the controller's array bank.  The servo cycle evaluates its active profile
segment; the axis itself only runs when an event is due (segment end, milestone, timer) or when an
instruction hands it a job.  Behaviour follows S7-1200 Motion Control V6 (section numbers in comments).
"""
from __future__ import annotations

import math
from typing import Any, Iterator, Mapping

from . import faults as F
from . import schema as P
from .family import PULSE_SLICE_TIME
from .faults import Fault, Reaction
from .jobs import MOTION_KINDS, POSITIONING_KINDS, Job, JobKind, JobState
from .axis_queue import BufferMode, axis_queue
from .policy import ABORT, PLCOPEN, SUPERIMPOSED_SLOT, Activity, OverridePolicy, Reject
from .motion import DirectionFault, MotionPlanner, Plan, limits, modulo_target, wrap
from .profiles import Planner, PlanningError, Profile, velocity_reach
from .parameter_store import ParameterStore
from .axis_config import AxisConfig
from ..drives.spec import ActuatorKind
from .drive_io import DriveIO
from .errors import ConfigurationError  # noqa: F401 - kernel.axis.ConfigurationError is public
from .fault_injection import FaultInjection
from .homing import Homing
from .job_runner import JobRunner
from .limit_switches import LimitSwitches
from .protocols import ServoHost
from .tag_views import TagViews

DISABLED, ENABLING, ENABLED, DISABLING = "disabled", "enabling", "enabled", "disabling"
_EPS_T = 1e-9

#: §12.8 16#8202: simultaneously active commands per axis
MAX_COMMANDS_PTO, MAX_COMMANDS_SERVO = 200, 100


class PositioningAxis(TagViews):
    """Positioning axis technology object (TO_PositioningAxis)."""

    #: a simulated axis executes active homing at once, without motion (S7-1200 V6 §5.4.3.1)
    _sim_homing_at_once = True

    #: how this kind of technology object names and checks its configuration tags (the family's class says)
    schema: P.AxisSchema

    def __init__(self, ctl: ServoHost, name: str, cfg: Mapping[str, Any], *, db_number: int | None = None):
        self.ctl = ctl
        self.name = name
        self.db_number = db_number if db_number is not None else ctl._next_db_number()
        self.config: AxisConfig                       # the tag values in effect, typed: what the kernel reads
        self.parameters = ParameterStore(self, self.schema, cfg)     # the family's tags: written, in effect
        spec = self.config.drive
        self.pto = spec.actuator is ActuatorKind.PULSE
        self.sim = spec.actuator is ActuatorKind.IDEAL
        self.servo = not self.pto and not self.sim
        self.index = ctl.bank.add()
        t = ctl.time
        self.drive = ctl._drive_group(spec.actuator.value).add(self.index, spec, ctl.servo_cycle, t)
        self.motion = MotionPlanner(self)
        self.homing = Homing(self, at_once_in_simulation=self._sim_homing_at_once)

        self.state = DISABLED
        self.homed = False
        self.position_controlled = True
        self.alarms: list[Fault] = []
        self.job: Job | None = None                   # active motion job
        #: the family's override rules: what a new job does to what runs (kernel/policy.py)
        self.policy: OverridePolicy = ctl._family.policy or PLCOPEN
        self.queue = axis_queue(self, self.policy.queue_depth)   # jobs waiting behind it (PLCopen BufferMode)
        self.runners: dict[JobKind, JobRunner] = {}   # components running kinds of jobs of a family
        self.power_owner: Any = None
        self.stop_mode = 0
        self.busy_commands: set[int] = set()          # id() of instructions with Busy = TRUE
        self.max_commands = MAX_COMMANDS_PTO if self.pto else MAX_COMMANDS_SERVO
        self._after_stop: str | None = None           # "disable" while a disabling stop runs
        self._pm_job: Job | None = None               # job waiting for positioning monitoring
        self._plan: Plan | None = None
        self._interpolating = False                   # the profile of the active job has not ended yet
        self.profile: Profile = Planner.hold(t, 0.0)
        self._seg = 0
        self._pending: dict[str, float] = {}
        self._timers: dict[str, float] = {}
        self.last_internal_error: str | None = None
        self.holding_zero_velocity = False            # standstill reached by MC_MoveVelocity(Velocity=0)
        self.abs_offset = 0.0                         # StatusSensor.AbsEncoderOffset (retentive)
        self.fault_injection = FaultInjection(self)   # injected faults of the simulated devices

        b = ctl.bank
        i = self.index
        x0 = spec.plant.initial_position if self.servo else 0.0
        b.act_p[i] = b.sp_p[i] = x0
        b.servo[i] = self.servo
        b.follow_act[i] = self.servo
        self._apply_bank_config()
        if self.absolute_encoder():
            # an absolute encoder gives its position at once; the adjustment (modes 6/7) is retentive
            kept = ctl.retain.get(name, {})
            self.abs_offset = float(kept.get("AbsEncoderOffset", 0.0))
            self.homed = bool(kept.get("HomingDone", False))
            self.drive.set_actual(b, self.homing.absolute_raw() + self.abs_offset)
            b.sp_p[i] = b.act_p[i]
        self.drive_io = DriveIO(self)                 # enable output, ready input
        self.limit_switches = LimitSwitches(self)     # hardware limit switches, actual value range
        self._watch_inputs()
        if not self.sim:
            ctl.plant.wire_axis(spec.plant, self.drive, t)
        self._start_profile(Planner.hold(t, float(b.sp_p[i])))

    # ------------------------------------------------------------------------------------------------
    # configuration tags: the parameter store (``self.parameters``) under the names the instructions use
    @property
    def cfg(self) -> dict[str, Any]:
        """Tag values as written (work memory)."""
        return self.parameters.values

    @property
    def load_cfg(self) -> dict[str, Any]:
        """Start values (load memory), used by a restart."""
        return self.parameters.start

    @property
    def eff(self) -> dict[str, Any]:
        """Tag values in effect (the family's names)."""
        return self.parameters.effective

    ueff = eff

    def _apply_dirty(self, moment: str) -> Fault | None:
        return self.parameters.apply(moment)

    def _config_fault(self, apply: bool = False) -> Fault | None:
        return self.parameters.config_fault(apply)

    def tag_access(self, path: str) -> str:
        return self.parameters.access(path)

    def write_tag(self, path: str, value: Any, *, via_write_param: bool = False) -> None:
        self.parameters.write(path, value, via_write_param=via_write_param)

    # ------------------------------------------------------------------------------------------------
    # small helpers
    def __repr__(self) -> str:
        return f"<PositioningAxis {self.name} {self.state}>"

    @property
    def now(self) -> float:
        return self.ctl.time

    def _state_now(self) -> tuple[float, float, float]:
        """Setpoint (position, velocity, acceleration) at the controller's current time.

        Taken from the profile, not from the last cycle's arrays: inside a servo cycle's event handling
        the time has already advanced.  An axis whose setpoint follows its actual value (disabled or not
        position-controlled) starts from the actual position.
        """
        return self._state_at(self.ctl.time)

    def _state_at(self, t: float) -> tuple[float, float, float]:
        p, v, a = self.profile.at(t)
        b, i = self.ctl.bank, self.index
        if b.follow_act[i]:
            p = float(b.act_p[i])
        return p, v, a

    @property
    def activated(self) -> bool:
        """StatusBits.Activated: the axis holds its pulse generator (always for an own one, §12.1)."""
        no = self.config.pulse_output.generator if self.pto else 0
        return not no or self.ctl._pto_holder.get(no) is self

    def pto_used_by_other(self) -> bool:
        """ErrorBits.HWUsed: another enabled axis holds the pulse generator of this axis (§12.1)."""
        no = self.config.pulse_output.generator if self.pto else 0
        holder = self.ctl._pto_holder.get(no) if no else None
        return holder is not None and holder is not self and holder.state != DISABLED

    def sw_limits_effective(self) -> bool:
        """SW limit switches act only on a homed, non-modulo axis (§2.3; modulo: see docs/decisions)."""
        c = self.config
        return c.software_limits.enabled and self.homed and not c.modulo.enabled

    def position_resolution(self) -> float:
        """Smallest position step of the axis: one pulse (PTO), one encoder increment (servo)."""
        c = self.config
        if self.pto:
            return c.drive.pulse_length
        if self.servo:
            return c.drive.encoder.increment
        return 1e-9 * max(1.0, abs(c.software_limits.maximum), abs(c.software_limits.minimum))

    def commanded_velocity(self, velocity: float) -> float:
        """A commanded velocity with the velocity override applied (S7-1500 ``Override.Velocity``)."""
        override = self.config.defaults.velocity_override
        return velocity if override is None else velocity * override / 100.0

    def _wrap(self, value: float) -> float:
        m = self.config.modulo
        if m.enabled:
            return wrap(value, m.start, m.length)
        return value

    def _apply_bank_config(self) -> None:
        b, i, c = self.ctl.bank, self.index, self.config
        b.kv[i] = c.position_control.kv
        b.kpc[i] = c.position_control.precontrol / 100.0
        fe = c.following_error
        fmin, fmax, vmin = fe.min_value, fe.max_value, fe.min_velocity
        vmax = c.limits.max_velocity
        b.fe_min[i] = fmin
        b.fe_max[i] = max(fmax, fmin)
        b.fe_vmin[i] = vmin
        b.fe_slope[i] = (fmax - fmin) / (vmax - vmin) if vmax > vmin else 0.0
        b.pm_window[i] = c.positioning.window
        b.pm_dwell[i] = c.positioning.min_dwell_time
        b.ss_threshold[i] = c.standstill.velocity_threshold
        b.ss_dwell[i] = c.standstill.min_dwell_time
        self.drive.reconfigure(c.drive)
        self._set_loop_flags()

    def _set_loop_flags(self) -> None:
        b, i = self.ctl.bank, self.index
        on = self.state in (ENABLED, DISABLING) and self.servo
        closed = on and self.position_controlled
        b.closed_loop[i] = closed
        b.follow_act[i] = self.servo and not closed
        fe = closed and self.config.following_error.enabled
        if fe != b.fe_on[i]:
            b.fe_on[i] = fe
            self.ctl._n_fe += 1 if fe else -1

    # ------------------------------------------------------------------------------------------------
    # profile and events
    def _start_profile(self, profile: Profile, plan: Plan | None = None) -> None:
        self.profile = profile
        self._plan = plan
        self._seg = 0
        self._pending = dict(profile.milestones)
        self._pending.pop("reached", None)
        self._pending["end"] = profile.t_end
        if plan is not None:
            if plan.reach_time is not None and plan.reach_time < profile.t_end - _EPS_T:
                self._pending["reached"] = plan.reach_time
            if plan.cross_time is not None:
                self._pending["cross"] = plan.cross_time
        self._load_segment()
        self._schedule()

    def _load_segment(self) -> None:
        seg = self.profile.segments[self._seg]
        b, i = self.ctl.bank, self.index
        b.seg_t[i], b.seg_p[i], b.seg_v[i], b.seg_a[i], b.seg_j[i] = seg.t, seg.p, seg.v, seg.a, seg.j

    def _schedule(self) -> None:
        nxt = self.profile.end_of(self._seg)
        for tm in self._pending.values():
            nxt = min(nxt, tm)
        for tm in self._timers.values():
            nxt = min(nxt, tm)
        self.ctl.bank.next_event[self.index] = nxt

    def _on_event(self, t: float) -> None:
        """Something of this axis is due at servo time ``t`` (called before the setpoint is evaluated)."""
        for _ in range(64):
            prof = self.profile
            while prof.end_of(self._seg) <= t + _EPS_T:
                self._seg += 1
            self._load_segment()
            due = sorted((tm, name) for name, tm in self._pending.items() if tm <= t + _EPS_T)
            timers = [name for name, tm in self._timers.items() if tm <= t + _EPS_T]
            if not due and not timers:
                break
            for name in timers:
                del self._timers[name]
                self._on_timer(name, t)
            for _tm, name in due:
                if self.profile is prof and name in self._pending:
                    del self._pending[name]
                    self._on_milestone(name, t)
        self.queue.poll()
        self._schedule()

    def _on_timer(self, name: str, t: float) -> None:
        for runner in self.runners.values():
            if name == runner.timer:
                runner.on_timer(t)
                return
        if name == "ready" and self.state == ENABLING:
            if self.drive.ready(t) and self.drive_io.ready():
                self._become_enabled(t)
            else:
                self._timers["ready"] = t + self.ctl.servo_cycle

    def _on_milestone(self, name: str, t: float) -> None:
        job = self.job
        plan = self._plan
        if name == "reached":
            if job is not None and job.busy and job.kind in (JobKind.VELOCITY, JobKind.JOG):
                job.in_velocity = job.reached_once = True
            return
        if name == "cross":
            side = plan.limit_side if plan else "max"
            reaction = Reaction.REMOVE_ENABLE if self.servo else Reaction.NONE
            if not self.servo:
                self._after_stop = "remove_enable"     # PTO: enable removed once the ramp has stopped
            self.raise_alarm(F.alarm(F.SW_LIMIT_MAX if side == "max" else F.SW_LIMIT_MIN, "exceeded", reaction))
            return
        if name != "end":
            return
        if job is not None and job.busy and job.kind == JobKind.HOME_ACTIVE:
            self.homing.on_profile_end(job, t)
            return
        runner = self.runners.get(job.kind) if job is not None and job.busy else None
        if runner is not None and not (plan and plan.limit_side):
            runner.on_profile_end(job, t)
            return
        if plan is not None and plan.override_hold:
            return                                 # positioning waits for the override to rise again
        self._interpolating = False
        if plan is not None and plan.limit_side and plan.limit_detail != "exceeded":
            kind = F.SW_LIMIT_MAX if plan.limit_side == "max" else F.SW_LIMIT_MIN
            self.raise_alarm(F.alarm(kind, plan.limit_detail))
        elif job is not None and job.busy:
            if job.kind in (JobKind.VELOCITY, JobKind.JOG):
                if (job.velocity == 0.0 and not job.extra.get("hold_zero")) or job.jog_released:
                    job.in_velocity = True
                    # §11.1.7: after MC_MoveVelocity(0) ConstantVelocity is shown at standstill
                    self.holding_zero_velocity = job.kind == JobKind.VELOCITY
                    self._finish_job(job, JobState.DONE, t)
                else:
                    job.in_velocity = job.reached_once = True
            elif job.kind in (JobKind.ABSOLUTE, JobKind.RELATIVE, JobKind.HALT):
                if self.servo and self.position_controlled:
                    self._start_positioning_monitor(job, t)
                else:
                    self._finish_job(job, JobState.DONE, t)
        if self._after_stop is not None and self.profile.final.v == 0.0:
            self._remove_enable(t, by_power=self._after_stop == "disable")

    def _finish_job(self, job: Job, state: JobState, t: float, fault: Fault | None = None) -> None:
        job.finish(state, fault)
        if job is self.job:
            self.job = None
        runner = self.runners.get(job.kind)
        if runner is not None:
            runner.release(job)
        if self._pm_job is job:
            self._stop_positioning_monitor()
        self.queue.finished(job)

    def attach_runner(self, runner: JobRunner) -> JobRunner:
        """A family's component runs the jobs of ``runner.kind`` on this axis (``kernel.job_runner``)."""
        self.runners[runner.kind] = runner
        return runner

    def _end_runner_jobs(self, state: JobState, t: float, fault: Fault | None = None) -> None:
        """End the runners' jobs, also those that have not taken the axis over yet."""
        for runner in self.runners.values():
            job = runner.job
            if job is not None and job.busy:
                self._finish_job(job, state, t, fault)

    # ------------------------------------------------------------------------------------------------
    # positioning monitoring (§5.4.4.6), following error, from the vectorised monitors
    def _start_positioning_monitor(self, job: Job, t: float) -> None:
        b, i = self.ctl.bank, self.index
        b.pm_target[i] = self.profile.final.p
        b.pm_deadline[i] = t + self.config.positioning.tolerance_time
        b.pm_in_since[i] = math.nan
        if not b.pm_on[i]:
            b.pm_on[i] = True
            self.ctl._n_pm += 1
        self._pm_job = job

    def _stop_positioning_monitor(self) -> None:
        b, i = self.ctl.bank, self.index
        if b.pm_on[i]:
            b.pm_on[i] = False
            self.ctl._n_pm -= 1
        self._pm_job = None

    def _on_positioned(self, t: float) -> None:
        job = self._pm_job
        self._stop_positioning_monitor()
        if job is not None and job.busy:
            self._finish_job(job, JobState.DONE, t)

    def _on_positioning_fault(self, t: float, detail: str) -> None:
        job = self._pm_job
        self._stop_positioning_monitor()
        self.raise_alarm(F.alarm(F.POSITIONING, detail, Reaction.REMOVE_ENABLE), job=job)

    def _internal_error(self, exc: BaseException) -> None:
        """A defect in the kernel while handling this axis: stop it (16#8FFF) and keep the details."""
        import traceback

        self.last_internal_error = "".join(traceback.format_exception(exc))
        self.raise_alarm(F.alarm(F.INTERNAL, "", Reaction.REMOVE_ENABLE, f"{type(exc).__name__}: {exc}"))

    def _on_following_error(self, t: float) -> None:
        self.raise_alarm(F.alarm(F.FOLLOWING_ERROR, "", Reaction.REMOVE_ENABLE))

    # ------------------------------------------------------------------------------------------------
    # inputs watched every servo cycle: drive ready, limit switches, homing inputs, actual value range
    def _watch_inputs(self) -> None:
        """Have the controller watch this axis's inputs every servo cycle if it has any to watch; in
        simulation (Simulation.Mode = 1) switches and drive feedback have no effect (§5.4.3.1)."""
        h = self.config.homing
        uses_inputs = (self.limit_switches.wired or self.drive_io.ready_input
                       or h.active.input or h.passive.input)
        if (uses_inputs or self.limit_switches.range_check) and not self.sim and self not in self.ctl._input_axes:
            self.ctl._input_axes.append(self)

    def _check_inputs(self, t: float) -> None:
        self.drive_io.check()
        self.limit_switches.check(t)
        self._homing_check_inputs(t)
        if self.limit_switches.range_check:
            self.limit_switches.check_range()

    @property
    def hw_approached(self) -> dict[str, bool]:
        """Side ("min"/"max") -> its hardware limit switch is approached (StatusBits.HWLimit*Active)."""
        return self.limit_switches.approached

    # the public fault injection API (docs/fault_injection.md), kept by ``self.fault_injection``
    def inject_fault(self, kind: str, detail: str = "", *, persistent: bool = False) -> None:
        """Let a simulated device of the axis fail (see ``FaultInjection.inject``)."""
        self.fault_injection.inject(kind, detail, persistent=persistent)

    def clear_fault(self, kind: str | None = None) -> None:
        """Remove the cause of an injected fault, or of all (see ``FaultInjection.clear``)."""
        self.fault_injection.clear(kind)

    def disturb_load(self, *, jump: float = 0.0, force: float | None = None, blocked: bool | None = None) -> None:
        """Disturb the load of the simulated drive (see ``FaultInjection.disturb_load``)."""
        self.fault_injection.disturb_load(jump=jump, force=force, blocked=blocked)

    def communication_ok(self, device: str) -> bool:
        """StatusDrive/StatusSensor.CommunicationOK of ``device`` ("drive" or "encoder")."""
        return self.fault_injection.communication_ok(device)

    @property
    def sensor_valid(self) -> bool:
        """StatusSensor.State = 2: actual values valid (no encoder fault pending)."""
        return self.fault_injection.sensor_valid

    # ------------------------------------------------------------------------------------------------
    # enable / disable (MC_Power, §11.1.1)
    def power(self, owner: Any, enable: bool, start_mode: int, stop_mode: int) -> Fault | None:
        """Called by the enabling instruction on every call; returns a rejection or None."""
        if self.power_owner is not None and self.power_owner is not owner:
            return F.reject(F.ALREADY_ENABLED) if enable else None
        if enable and self.ctl.mode != "RUN":
            return F.reject(F.REJECTED, "starting_up")
        no = self.config.pulse_output.generator if self.pto else 0
        if no:
            # several axes on one pulse generator: the first MC_Power call of an axis takes the PTO over
            # once the axis holding it is disabled (§12.1)
            holder = self.ctl._pto_holder.get(no)
            if holder is not self:
                if holder is not None and holder.state != DISABLED:
                    return F.reject(F.PTO_SWITCH) if enable else None
                self.ctl._pto_holder[no] = self
                self._apply_dirty("enable")
        if enable:
            self.power_owner = owner
            self.stop_mode = stop_mode
            if self.state == DISABLED and not self.alarms and self._after_stop is None:
                self._enable(start_mode)
        elif self.power_owner is owner:
            if self.state in (ENABLING, ENABLED):
                self._disable(stop_mode)
            if self.state == DISABLED:
                self.power_owner = None
        return None

    def _enable(self, start_mode: int) -> None:
        t = self.now
        if self._apply_dirty("enable") is not None:
            return
        bad = self._config_fault()
        if bad is not None:
            self.raise_alarm(bad)
            return
        self.position_controlled = start_mode == 1 or not self._has_start_mode()
        if self.servo and self.position_controlled and not self.sensor_valid:
            detail = self.fault_injection.faults.get("encoder", ("", False))[0]
            self.raise_alarm(F.alarm(F.ENCODER, detail, Reaction.REMOVE_ENABLE))
            return
        self.state = ENABLING
        self.drive.set_enable(True, t)
        self.drive_io.set_enable_output(True)
        if self.sim or (not self.servo and self.drive_io.ready()):
            self._become_enabled(t)          # no drive feedback to wait for (§11.1.1, §5.4.3.1)
        else:
            self._timers["ready"] = t
            self._schedule()

    def _has_start_mode(self) -> bool:
        """Whether MC_Power StartMode 0 (without position control) applies: drive axes (§11.1.1)."""
        return self.servo

    def _zero_at_enable(self) -> bool:
        """An axis that is not homed counts from the position at every enable (S7-1200 V6 §12.9.1)."""
        return not self.homed and not self.absolute_encoder()

    def _become_enabled(self, t: float) -> None:
        self.state = ENABLED
        b, i = self.ctl.bank, self.index
        if self._zero_at_enable():
            self.drive.set_actual(b, 0.0)
            b.act_p[i] = 0.0
            b.sp_p[i] = 0.0
        p = float(b.act_p[i])
        b.sp_p[i], b.sp_v[i], b.sp_a[i] = p, 0.0, 0.0
        self._set_loop_flags()
        self._start_profile(Planner.hold(t, p))

    def _disable(self, stop_mode: int) -> None:
        t = self.now
        self._abort_all(t)
        if self.state == ENABLING:
            self._remove_enable(t, by_power=True)
            return
        self.state = DISABLING
        p, v, a = self._state_now()
        self._after_stop = "disable"
        if stop_mode == 1:
            if self.pto:
                # pulse output stopped within 30 ms (f >= 100 Hz) or up to 1.5 s at 2 Hz (§11.1.1)
                f = abs(v) / self.config.drive.pulse_length
                duration = 0.03 if f >= 100.0 else (3.0 / f if f > 0 else 0.0)
                plan = self.motion.ramp_out(t, p, v, duration)
                self._start_profile(plan.profile, plan)
            else:
                self._remove_enable(t, by_power=True)
                return
        else:
            plan = self.motion.stop(t, p, v, a, emergency=True, jerk=stop_mode == 2)
            self._start_profile(plan.profile, plan)
        if self.profile.t_end <= t + _EPS_T:
            self._remove_enable(t, by_power=True)

    def _remove_enable(self, t: float, by_power: bool = False) -> None:
        """Setpoint zero and enable off; the drive stops by itself (§12.8 'Remove enable')."""
        self._after_stop = None
        self.holding_zero_velocity = False
        self.drive.set_enable(False, t)
        self.drive_io.set_enable_output(False)
        self.state = DISABLED
        self._stop_positioning_monitor()
        self._timers.pop("ready", None)
        b, i = self.ctl.bank, self.index
        self._set_loop_flags()
        p = float(b.act_p[i]) if self.servo else self._state_now()[0]
        b.sp_v[i] = b.sp_a[i] = 0.0
        self._start_profile(Planner.hold(t, p))
        if by_power and self.pto:
            self.homed = False                     # §2.5: disabling a PTO axis resets "homed"

    def _abort_all(self, t: float) -> None:
        for job in (self.job, self.homing.passive):
            if job is not None and job.busy:
                self._finish_job(job, JobState.ABORTED, t)
        self._end_runner_jobs(JobState.ABORTED, t)
        self.job = None
        self.homing.passive = None

    # ------------------------------------------------------------------------------------------------
    # homing (kernel/homing.py, ``self.homing``): delegations for the instructions, the runtime, the tag
    # views and the command table (public names) and for the limit switches (``_homing_*``)
    def home(self, job: Job) -> None:
        self.homing.home(job)

    def home_direct(self, job: Job) -> None:
        self.homing.home_direct(job)

    def homing_configured(self, mode: int) -> bool:
        return self.homing.configured(mode)

    def absolute_encoder(self) -> bool:
        return self.homing.absolute_encoder()

    @property
    def passive_home(self) -> Job | None:
        return self.homing.passive

    @passive_home.setter
    def passive_home(self, job: Job | None) -> None:
        self.homing.passive = job

    def _homing_inputs(self) -> dict[str, str]:
        return self.homing.inputs()

    def _homing_check_inputs(self, t: float) -> None:
        self.homing.check_inputs(t)

    def _homing_hw_limit(self, side: str, t: float) -> bool:
        return self.homing.hw_limit(side, t)

    # ------------------------------------------------------------------------------------------------
    # alarms (§9.6, §12.8)
    def raise_alarm(self, fault: Fault, job: Job | None = None) -> None:
        t = self.now
        if fault not in self.alarms:
            self.alarms.append(fault)
        victim = job if job is not None else self.job
        if victim is not None and victim.busy:
            self._finish_job(victim, JobState.ERROR, t, fault)
        if fault.reaction != Reaction.NONE:
            self._end_runner_jobs(JobState.ERROR, t, fault)
        if fault.reaction in (Reaction.REMOVE_ENABLE, Reaction.EMERGENCY):
            self.homing.end_passive(JobState.ERROR, fault)
        if self.state not in (ENABLED, DISABLING, ENABLING):
            return
        if fault.reaction == Reaction.REMOVE_ENABLE:
            self._remove_enable(t)
        elif fault.reaction in (Reaction.STOP, Reaction.EMERGENCY):
            if self.state == ENABLING:
                self._remove_enable(t)
                return
            p, v, a = self._state_now()
            plan = self.motion.stop(t, p, v, a, emergency=fault.reaction == Reaction.EMERGENCY,
                                    jerk=fault.reaction == Reaction.STOP)
            self._interpolating = False
            self._start_profile(plan.profile, plan)
            self._stop_positioning_monitor()

    def acknowledge(self) -> Fault | None:
        """MC_Reset (Restart = FALSE): clear alarms whose cause is gone; returns one that persists."""
        injected = self.fault_injection
        injected.acknowledge()
        remaining = []
        for fault in self.alarms:
            if injected.keeps_alarm(fault):            # a device that is still faulty (§12.7)
                remaining.append(fault)
                continue
            if fault.kind == F.CONFIG:
                bad = self._config_fault(apply=True)
                if bad is not None:
                    remaining.append(bad)
                continue
            if fault.kind == F.DRIVE_NOT_READY and self.state == ENABLED and not self.drive.ready(self.now):
                remaining.append(fault)
                continue
        self.alarms = remaining
        return remaining[0] if remaining else None

    def restart(self) -> Fault | None:
        """MC_Reset (Restart = TRUE): reload the start values; only while disabled (§9.7, §11.1.2)."""
        if self.state == DISABLING:
            return F.reject(F.RESTART_IMPOSSIBLE, "not_disabled")
        if self.power_owner is not None or self.state != DISABLED:
            return F.reject(F.RESTART_IMPOSSIBLE, "enabled")
        self.reinitialize("restart")
        return None

    def reinitialize(self, reason: str) -> None:
        """Restart of the technology object with its start values.

        ``reason``: "restart" (MC_Reset Restart = TRUE), "startup" (CPU STOP -> RUN) or "power"
        (POWER OFF -> ON).  "Homed" is lost as §2.5 lists: a PTO axis always, incremental actual values
        on a TO restart or power cycle; an absolute encoder keeps its retentive adjustment (§9.4).
        """
        t = self.now
        self._abort_all(t)
        if self.state != DISABLED:
            self._remove_enable(t, by_power=True)
        self.power_owner = None
        self.parameters.restart()
        self.alarms.clear()
        self.busy_commands.clear()
        absolute = self.absolute_encoder()
        if self.pto or (not absolute and reason in ("restart", "power")):
            self.homed = False
        if absolute:
            kept = self.ctl.retain.get(self.name, {})
            self.abs_offset = float(kept.get("AbsEncoderOffset", self.abs_offset))
            self.homed = bool(kept.get("HomingDone", self.homed))
        b, i = self.ctl.bank, self.index
        if reason == "power":
            # the actual values start anew: pulse and incremental counters at 0, absolute encoders as is
            self.drive.set_actual(b, self.homing.absolute_raw() + self.abs_offset if absolute else 0.0)
            b.sp_p[i] = b.act_p[i]
            b.sp_v[i] = b.sp_a[i] = 0.0
            self._start_profile(Planner.hold(t, float(b.sp_p[i])))
        self._apply_bank_config()

    # ------------------------------------------------------------------------------------------------
    # jobs
    def check_start(self, job: Job) -> Fault | None:
        """Conditions every motion job needs (§11.1 'Requirements', §12.8 16#82xx)."""
        if self.ctl.mode != "RUN":
            return F.reject(F.REJECTED, "starting_up")    # STOP/STARTUP: no motion jobs (§2.2.7.4)
        if self.pto_used_by_other():
            return F.reject(F.HW_USED)
        if not self.activated:
            return F.reject(F.NOT_ACTIVATED)                # shared PTO not yet taken over (§12.1)
        if self.state != ENABLED:
            return F.reject(F.NOT_ENABLED)
        blocking = self._blocking_alarm()
        if blocking is not None:
            return blocking
        if len(self.busy_commands) >= self.max_commands:
            return F.reject(F.TOO_MANY_COMMANDS)
        if job.kind == JobKind.ABSOLUTE and not self.homed:
            return F.reject(F.NOT_HOMED)
        needs_control = job.kind in POSITIONING_KINDS or job.kind == JobKind.HOME_ACTIVE or (
            job.kind in (JobKind.VELOCITY, JobKind.JOG) and job.position_controlled)
        if self.servo and needs_control and not self.sensor_valid:
            return F.reject(F.REJECTED, "position_control_required")   # §12.7: invalid actual values
        return None

    def _blocking_alarm(self) -> Fault | None:
        """A pending alarm that keeps new jobs from starting (S7-1200: every alarm, §9.3)."""
        if self.alarms:
            first = self.alarms[0]
            return Fault(F.PENDING_ALARM, first.kind + "/" + first.detail, False, text=str(first))
        return None

    def submit(self, job: Job, buffer_mode: BufferMode = BufferMode.ABORTING) -> None:
        """Hand a job to the axis (MC_Halt, MC_Move*, MC_Stop, MC_MoveSuperimposed, active homing): every job
        goes through the queue (``self.queue``); Aborting starts it at once (``start_job``), the other buffer
        modes let it wait behind the running job."""
        self.queue.submit(job, buffer_mode)

    def start_job(self, job: Job) -> None:
        """Start ``job`` now (the queue's take-over, Aborting): the start conditions, then the family's
        policy decides what the job does to every running activity - end it aborted, let it go on, or
        refuse the new job (kernel/policy.py) - and the job takes the axis (or its superimposed slot)."""
        fault = self.check_start(job)
        if fault is not None:
            job.finish(JobState.ERROR, fault)
            return
        t = self.now
        if self.pto and self._apply_dirty("command") is not None:
            job.finish(JobState.ERROR, self.alarms[-1])
            return
        policy = self.policy
        new = policy.classify(job)
        if policy.slot(new) == SUPERIMPOSED_SLOT:
            self._start_superimposed_job(job)
            return
        for activity in self._activities():
            if activity.job is job:
                continue
            answer = policy.decide(new, job, activity)
            if isinstance(answer, Reject):
                job.finish(JobState.ERROR, answer.fault())
                return
        if not policy.plan_after_override and not self._resolve_target(job):
            return
        self._override(new, t, job)
        if policy.plan_after_override and not self._resolve_target(job):
            return
        self.holding_zero_velocity = False
        self._stop_positioning_monitor()
        self._begin(job, t)

    def _activities(self) -> Iterator[Activity]:
        """What runs on the axis that a new job may end, in the order it is ended; lazy, so that each one
        is looked at after the one before has been ended (ending a job can end others with it)."""
        classify = self.policy.classify
        run = self.job
        if run is not None and run.busy:
            yield Activity(classify(run), run, lambda t: self._finish_job(run, JobState.ABORTED, t))
        for runner in self.runners.values():
            waiting = runner.job
            if waiting is not None and waiting.busy:            # a program that has not taken over yet
                yield Activity(classify(waiting), waiting,
                               lambda t, w=waiting: self._finish_job(w, JobState.ABORTED, t))
        passive = self.homing.passive
        if passive is not None and passive.busy:
            yield Activity(classify(passive), passive, lambda t: self.homing.end_passive(JobState.ABORTED))

    def _override(self, new: str, t: float, new_job: Job | None) -> None:
        """End every running activity that a new job of class ``new`` aborts (the family's policy)."""
        policy = self.policy
        for activity in self._activities():
            if activity.job is not None and activity.job is new_job:
                continue
            if policy.decide(new, new_job, activity) is ABORT:
                activity.end(t)

    def _resolve_target(self, job: Job) -> bool:
        """The absolute target of a positioning from the state at its start (False: the job was refused)."""
        p, v, a = self._start_state(self.now)
        if job.kind == JobKind.RELATIVE:
            job.target = job.extra.pop("relative_base", p) + job.position
            if abs(job.target) > P.E12:
                job.finish(JobState.ERROR, F.reject(F.REJECTED, "numeric_limit"))
                return False
        elif job.kind == JobKind.ABSOLUTE:
            job.target = self._absolute_target(job, p, v, a)
        elif job.kind == JobKind.VELOCITY and job.current:
            job.velocity = v
        return True

    def _begin(self, job: Job, t: float) -> None:
        """The job takes the axis over: position control as it needs, then homing or its motion plan."""
        self.job = job
        if job.kind in self.policy.position_control:
            self._set_position_control(True)
        elif job.kind in (JobKind.VELOCITY, JobKind.JOG):
            self._set_position_control(job.position_controlled)
        if job.kind == JobKind.HOME_ACTIVE:
            self.homing.start_active(job, t)
            return
        if self._plan_job(job, t):
            self._note_limits(self.motion.last_limits, job)

    def _start_superimposed_job(self, job: Job) -> None:
        """A job in the superimposed slot: it adds to whatever runs and replaces a running superimposed job."""
        start = getattr(self, "start_superimposed", None)
        if start is None:
            job.finish(JobState.ERROR, F.reject(F.NOT_AVAILABLE, job.kind.value))
            return
        lim = limits(self, job.velocity, job=job)
        self._note_limits(lim)
        start(job, lim)

    def _note_limits(self, lim: Any, job: Job | None = None) -> None:
        """A family hook: the dynamics of a job were planned within ``lim`` (some families warn when a job's
        values were cut to the limits)."""
        return None

    def _absolute_target(self, job: Job, p: float, v: float, a: float) -> float:
        if self.config.modulo.enabled:
            lim = limits(self, job.velocity)
            return modulo_target(self, job.position, job.direction, math.copysign(1.0, job.extra.get("sign", 1.0)),
                                 p, v, a, lim, self.motion.planner)
        return job.position

    def _plan_job(self, job: Job, t: float, spec: Job | None = None, *, new_command: bool = True,
                  replan: bool = False) -> bool:
        """Plan and start the motion of ``job`` (or of ``spec``, a step of ``job`` planned by a runner).

        A new command on a PTO axis starts at the next segment boundary (V7 PTOSliceTime).  Faults found
        while planning end ``job``.  Returns whether the motion started.
        """
        t_plan = self._slice_start(t) if new_command else t
        p, v, a = self._start_state(t_plan)
        try:
            # a re-plan may use the velocities the running plan reaches anyway (no jerk above the limit
            # to avoid an overshoot the old plan had too)
            reach = velocity_reach(self.profile, t_plan) if replan else None
            plan = self.motion.plan(spec or job, t_plan, p, v, a, replan=replan, reach=reach)
        except DirectionFault as exc:
            self.raise_alarm(F.alarm(F.DIRECTION, exc.detail, Reaction.STOP), job=job)
            return False
        except PlanningError as exc:
            self.raise_alarm(F.alarm(F.INTERNAL, "planning", Reaction.EMERGENCY, str(exc)), job=job)
            return False
        fault = self.limit_switches.direction_fault(plan.profile, p)
        if fault is not None:
            self.raise_alarm(fault, job=job)
            return False
        if t_plan != t:
            # the running profile goes on until the next PTO segment boundary (V7 Actor.PTOSliceTime)
            plan.profile.segments[:0] = [seg for seg in self.profile.segments if seg.t < t_plan]
        self._interpolating = True
        self._start_profile(plan.profile, plan)
        self._planned = (t_plan, self.profile, (p, v, a))
        return True

    _planned: tuple[float, Profile, tuple[float, float, float]] | None = None

    def _start_state(self, t: float) -> tuple[float, float, float]:
        """The state a plan for time ``t`` starts from: the setpoint at ``t``, but when a job planned for the
        same instant still holds the axis (it never ran a servo cycle: two jobs in one application cycle),
        the acceleration that plan started from, not the step a Jerk-0 profile makes at its start.  Only
        where position and velocity agree: anything that moved the profile in between (a coordinate shift,
        a velocity step) leaves the setpoint as it is."""
        p, v, a = self._state_at(t)
        planned = self._planned
        if planned is not None and planned[0] == t and planned[1] is self.profile and planned[2][:2] == (p, v):
            a = planned[2][2]
        return p, v, a

    def _slice_start(self, t: float) -> float:
        """When a new command takes effect: at once, or on a PTO at the next segment boundary."""
        if not self.pto or PULSE_SLICE_TIME not in self.ctl.rules:
            return t
        period = self.config.pulse_output.slice_time
        if period <= self.ctl.servo_cycle * (1 + 1e-9):
            return t
        k = math.ceil(t / period - 1e-9)
        return max(t, k * period)

    def _set_position_control(self, on: bool) -> None:
        if not self._has_start_mode() or on == self.position_controlled:
            return
        self.position_controlled = on
        self._set_loop_flags()

    def _replan(self) -> None:
        """Re-plan the running motion from the current state (parameter change, coordinate shift)."""
        job = self.job
        t = self.now
        if job is not None and job.busy and (job.kind == JobKind.HOME_ACTIVE or job.kind in self.runners):
            return                                          # homing and runners plan their own steps
        if job is not None and job.busy and job.kind in MOTION_KINDS and self._interpolating:
            self._plan_job(job, t, replan=True)
        elif self.sw_limits_effective() and self.state in (ENABLED, DISABLING):
            p, v, a = self._state_now()
            if abs(v) > 1e-12:
                # an internal stop in force (error reaction, disabling) keeps its ramp: the emergency ramp
                # has no jerk limit and its own deceleration (S7-1200 V6 §12.8; fuzz seed 124621)
                running = self._plan.stop if self._plan is not None else None
                emergency, jerk = running if running is not None else (False, True)
                plan = self.motion.stop(t, p, v, a, emergency=emergency, jerk=jerk)
                self._start_profile(plan.profile, plan)

    def release_jog(self, job: Job) -> None:
        """Jog input released: brake with the configured deceleration (§11.1.8)."""
        if job is not self.job or not job.busy or job.jog_released:
            return
        job.jog_released = True
        job.in_velocity = False
        if self.pto:
            self._apply_dirty("jog_stop")
            if not job.busy:
                return
        self._plan_job(job, self.now)

    def change_jog_velocity(self, job: Job, velocity: float) -> None:
        """MC_MoveJog takes a new Velocity while the jog input is TRUE (§9.3)."""
        if job is not self.job or not job.busy or job.jog_released or velocity == job.velocity:
            return
        job.velocity = velocity
        job.in_velocity = False
        self._plan_job(job, self.now)
