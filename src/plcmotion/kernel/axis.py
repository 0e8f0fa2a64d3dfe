"""Positioning axis technology object: configuration, profile and events, and the components it owns.

The axis owns one slot in the controller's array bank and its abilities as components: enabling
(``power_control``, kernel/power.py), starting and re-planning jobs (``job_start``, kernel/job_start.py),
positioning monitoring (``positioning_monitor``), alarm reactions and MC_Reset (``alarm_reactions``), homing,
limit switches, drive signals.  The axis keeps one-line delegations for the methods that instructions, the
runtime, other components or a family's subclass call or override.  The servo cycle evaluates its active
profile segment; the axis itself only runs when an event is due (segment end, milestone, timer) or when an
instruction hands it a job.  Behaviour follows S7-1200 Motion Control V6 (section numbers in comments).
"""
from __future__ import annotations

import math
from typing import Any, Iterator, Mapping

from . import faults as F
from . import schema as P
from .faults import Fault, Reaction
from .jobs import Job, JobKind, JobState
from .axis_queue import BufferMode, axis_queue
from .policy import PLCOPEN, Activity, OverridePolicy
from .motion import MotionPlanner, Plan, wrap
from .profiles import Planner, Profile
from .parameter_store import ParameterStore
from .alarm_reactions import AlarmReactions
from .axis_config import AxisConfig
from ..drives.spec import ActuatorKind
from .drive_io import DriveIO
from .errors import ConfigurationError  # noqa: F401 - kernel.axis.ConfigurationError is public
from .fault_injection import FaultInjection
from .homing import Homing
from .job_runner import JobRunner
from .job_start import JobStart
from .limit_switches import LimitSwitches
from .positioning_monitor import PositioningMonitor
from .power import DISABLED, DISABLING, ENABLED, ENABLING, PowerControl
from .protocols import ServoHost
from .tag_views import TagViews

_EPS_T = 1e-9

#: §12.8 16#8202: simultaneously active commands per axis
MAX_COMMANDS_PTO, MAX_COMMANDS_SERVO = 200, 100


class PositioningAxis(TagViews):
    """Positioning axis technology object (TO_PositioningAxis)."""

    #: the axis reports a following error above ``FollowingErrorMonitoring.warning_level`` to
    #: ``_on_following_warning`` (a family that has such a message sets it)
    reports_following_warning = False
    #: the homing part of this axis kind (``kernel.homing.NoHoming`` for a kind without homing)
    homing_class: type = Homing

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
        self.drive = ctl._drive_group(spec).add(self.index, spec, ctl.servo_cycle, t)
        self.motion = MotionPlanner(self)
        self.homing = self.homing_class(self, at_once_in_simulation=self._sim_homing_at_once)

        self.state = DISABLED
        self.homed = False
        self.position_controlled = True
        self.alarms: list[Fault] = []
        self.alarm_reactions = AlarmReactions(self)    # reactions, MC_Reset, restart (§9.6, §12.8)
        self.job: Job | None = None                   # active motion job
        #: the family's override rules: what a new job does to what runs (kernel/policy.py)
        self.policy: OverridePolicy = ctl._family.policy or PLCOPEN
        self.queue = axis_queue(self, self.policy.queue_depth)   # jobs waiting behind it (PLCopen BufferMode)
        self.runners: dict[JobKind, JobRunner] = {}   # components running kinds of jobs of a family
        self.job_start = JobStart(self)                # check, override, target and plan of a new job
        self.power_owner: Any = None
        self.power_control = PowerControl(self)        # enable / disable (MC_Power, §11.1.1)
        if type(self).power is PositioningAxis.power:
            # MC_Power calls axis.power every application cycle for every axis: bind the component's method
            # directly so the hot call costs no hand-over frame (a family class that overrides power keeps it)
            self.power = self.power_control.power
        self.stop_mode = 0
        self.busy_commands: set[int] = set()          # id() of instructions with Busy = TRUE
        self.max_commands = MAX_COMMANDS_PTO if self.pto else MAX_COMMANDS_SERVO
        self._after_stop: str | None = None           # "disable" while a disabling stop runs
        self.positioning_monitor = PositioningMonitor(self)   # the end of a positioning (§5.4.4.6)
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
        self.drive.attach(self.fault_injection)        # and the faults a drive on a bus reports itself

        b = ctl.bank
        i = self.index
        x0 = spec.plant.initial_position if self.servo else 0.0
        b.act_p[i] = b.sp_p[i] = x0
        b.servo[i] = self.servo
        self._set_follow_act(self.servo)
        self._apply_bank_config()
        if self.absolute_encoder():
            # an absolute encoder gives its position at once; the adjustment (modes 6/7) is retentive
            kept = ctl.retain.get(self.retain_key, {})
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

    def simulate_actual(self, on: bool) -> None:
        """``on``: from the next servo cycle the actual values are the setpoints (following error 0) while the
        drive, not enabled, stands still - a simulation mode that runs the program without moving the
        machine; off: the drive's actual values again (the axis sees where the machine really is)."""
        b, i = self.ctl.bank, self.index
        if bool(b.simulated[i]) != on:
            b.simulated[i] = on
            self.ctl._n_sim += 1 if on else -1

    @property
    def retain_key(self) -> str:
        """Under which name the controller keeps this axis's retentive data (absolute encoder adjustment):
        the axis name; a family whose axes switch between several encoders names the encoder in force."""
        return self.name

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
        return c.software_limits.enabled and (self.homed or not c.homing.required) and not c.modulo.enabled

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
        warn = c.following_error.warning_level if self.reports_following_warning else None
        level = math.inf if warn is None else warn / 100.0
        if math.isinf(level) != math.isinf(b.fe_warn[i]):
            self.ctl._n_few += -1 if math.isinf(level) else 1
        b.fe_warn[i] = level
        b.pm_window[i] = c.positioning.window
        b.pm_dwell[i] = c.positioning.min_dwell_time
        b.ss_threshold[i] = c.standstill.velocity_threshold
        b.ss_dwell[i] = c.standstill.min_dwell_time
        self.drive.reconfigure(c.drive)
        self._set_loop_flags()

    def _set_follow_act(self, follow: bool) -> None:
        b, i = self.ctl.bank, self.index
        if follow != b.follow_act[i]:
            b.follow_act[i] = follow
            b.n_follow += 1 if follow else -1

    def _set_loop_flags(self) -> None:
        b, i = self.ctl.bank, self.index
        on = self.state in (ENABLED, DISABLING) and self.servo
        closed = on and self.position_controlled
        if closed != b.closed_loop[i]:
            b.closed_loop[i] = closed
            b.n_closed += 1 if closed else -1          # counted: the servo cycle skips uniform masks
        self._set_follow_act(self.servo and not closed)
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
            self.power_control.on_ready_timer(t)

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
        if self.positioning_monitor.job is job:
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
        self.positioning_monitor.start(job, t)

    def _stop_positioning_monitor(self) -> None:
        self.positioning_monitor.stop()

    def _on_positioned(self, t: float) -> None:
        self.positioning_monitor.on_positioned(t)

    def _on_positioning_fault(self, t: float, detail: str) -> None:
        self.positioning_monitor.on_fault(t, detail)

    def _internal_error(self, exc: BaseException) -> None:
        """A defect in the kernel while handling this axis: stop it (16#8FFF) and keep the details."""
        import traceback

        self.last_internal_error = "".join(traceback.format_exception(exc))
        self.raise_alarm(F.alarm(F.INTERNAL, "", Reaction.REMOVE_ENABLE, f"{type(exc).__name__}: {exc}"))

    def _on_following_error(self, t: float) -> None:
        self.raise_alarm(F.alarm(F.FOLLOWING_ERROR, "", Reaction.REMOVE_ENABLE))

    def _on_following_warning(self, t: float) -> None:
        """The following error rose above its warning level (only when ``reports_following_warning``)."""

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
        return self.power_control.power(owner, enable, start_mode, stop_mode)

    def _enable(self, start_mode: int) -> None:
        self.power_control.enable(start_mode)

    def _has_start_mode(self) -> bool:
        """Whether MC_Power StartMode 0 (without position control) applies: drive axes (§11.1.1)."""
        return self.servo

    def _zero_at_enable(self) -> bool:
        """An axis that is not homed counts from the position at every enable (S7-1200 V6 §12.9.1)."""
        return not self.homed and not self.absolute_encoder()

    def _become_enabled(self, t: float) -> None:
        self.power_control.become_enabled(t)

    def _disable(self, stop_mode: int) -> None:
        self.power_control.disable(stop_mode)

    def _remove_enable(self, t: float, by_power: bool = False) -> None:
        self.power_control.remove_enable(t, by_power)

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
        self.alarm_reactions.raise_alarm(fault, job)

    def acknowledge(self) -> Fault | None:
        """MC_Reset (Restart = FALSE): clear alarms whose cause is gone; returns one that persists."""
        return self.alarm_reactions.acknowledge()

    def restart(self) -> Fault | None:
        """MC_Reset (Restart = TRUE): reload the start values; only while disabled (§9.7, §11.1.2)."""
        return self.alarm_reactions.restart()

    def reinitialize(self, reason: str) -> None:
        """Restart of the technology object with its start values: "restart" (MC_Reset Restart = TRUE),
        "startup" (CPU STOP -> RUN) or "power" (POWER OFF -> ON)."""
        self.alarm_reactions.reinitialize(reason)

    # ------------------------------------------------------------------------------------------------
    # jobs
    def check_start(self, job: Job) -> Fault | None:
        """Conditions every motion job needs (§11.1 'Requirements', §12.8 16#82xx)."""
        return self.job_start.check_start(job)

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
        """Start ``job`` now (the queue's take-over, Aborting): start conditions, the family's override
        policy, then the job takes the axis (``kernel.job_start``)."""
        self.job_start.start_job(job)

    def _activities(self) -> Iterator[Activity]:
        """What runs on the axis that a new job may end, in the order it is ended (lazy)."""
        return self.job_start.activities()

    def _override(self, new: str, t: float, new_job: Job | None) -> None:
        self.job_start.override(new, t, new_job)

    def _begin(self, job: Job, t: float) -> None:
        self.job_start.begin(job, t)

    def _note_limits(self, lim: Any, job: Job | None = None) -> None:
        """A family hook: the dynamics of a job were planned within ``lim`` (some families warn when a job's
        values were cut to the limits)."""
        return None

    def _plan_job(self, job: Job, t: float, spec: Job | None = None, *, new_command: bool = True,
                  replan: bool = False) -> bool:
        """Plan and start the motion of ``job`` (or of ``spec``); returns whether the motion started."""
        return self.job_start.plan_job(job, t, spec, new_command=new_command, replan=replan)

    def _slice_start(self, t: float) -> float:
        return self.job_start.slice_start(t)

    def _set_position_control(self, on: bool) -> None:
        if not self._has_start_mode() or on == self.position_controlled:
            return
        self.position_controlled = on
        self._set_loop_flags()

    def _replan(self) -> None:
        """Re-plan the running motion from the current state (parameter change, coordinate shift)."""
        self.job_start.replan()

    def release_jog(self, job: Job) -> None:
        """Jog input released: brake with the configured deceleration (§11.1.8)."""
        self.job_start.release_jog(job)

    def change_jog_velocity(self, job: Job, velocity: float) -> None:
        """MC_MoveJog takes a new Velocity while the jog input is TRUE (§9.3)."""
        self.job_start.change_jog_velocity(job, velocity)
