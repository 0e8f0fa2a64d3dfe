"""The command table runner (``s7_1200.technology.table_runner.TableRunner``) as a component.

Part (a) drives the runner alone on a small fake host that implements its ``TableHost`` protocol: no
controller, no servo cycle, no instruction - the host records what the runner asks it to plan.  Part (b)
checks how the families attach it: an S7-1200 positioning axis has one (``axis.table_runner``), the S7-1500
axes have none.  Expected values come from S7-1200 Motion Control V6 §6.4.3 (step types, "Complete
command" / "Blend motion"), §11.1.9.1 (MC_CommandTable override response), §9.6 (a bad step ends the
table, the motion goes on) and docs/decisions.md row 41 (a moving axis at the end of the table brakes with
the configured deceleration before Done).
"""
from __future__ import annotations

from types import SimpleNamespace

import pytest

from plcmotion import Controller
from plcmotion.kernel import faults as F
from plcmotion.kernel.jobs import Job, JobKind, JobState
from plcmotion.s7_1200.technology.command_table import CommandTable
from plcmotion.s7_1200.technology.table_runner import TIMER, TableRunner

EMPTY, HALT, REL, ABS, VEL, WAIT = 0, 2, 5, 6, 7, 151
COMPLETE, BLEND = 0, 1
VMAX, VMIN, DEC = 100.0, 1.0, 40.0


class FakeHost:
    """A ``TableHost``: position and velocity are set by the test; plans are recorded, not run."""

    def __init__(self) -> None:
        self.now = 0.0
        self.job: Job | None = None
        self.passive_home: Job | None = None
        self.homed = True
        self.holding_zero_velocity = True
        self.alarms: list[F.Fault] = []
        self.eff = {"DynamicLimits.MaxVelocity": VMAX, "DynamicLimits.MinVelocity": VMIN}
        self.config = SimpleNamespace(
            limits=SimpleNamespace(max_velocity=VMAX, velocity=None, max_acceleration=None, max_deceleration=None,
                                   max_jerk=None, start_stop_velocity=VMIN),
            defaults=SimpleNamespace(acceleration=50.0, deceleration=DEC, emergency_deceleration=500.0,
                                     jerk=float("inf")))
        self.pto = True
        self.motion = self
        self._timers: dict[str, float] = {}
        self._interpolating = False
        self.p = self.v = 0.0
        self.start_fault: F.Fault | None = None
        self.plans: list[tuple[float, Job, bool]] = []     # (time, what to plan, new command)
        self.stops: list = []                               # limits of the stops at the end of a table
        self.monitor_stopped = 0
        self.runner = TableRunner(self)

    # --- the protocol ---------------------------------------------------------------------------------
    def check_start(self, job: Job) -> F.Fault | None:
        return self.start_fault

    def _apply_dirty(self, moment: str) -> F.Fault | None:
        return None

    def _finish_job(self, job: Job, state: JobState, t: float, fault: F.Fault | None = None) -> None:
        job.finish(state, fault)            # like the kernel axis: end it, free the slot, tell its runner
        if job is self.job:
            self.job = None
        if job.kind == self.runner.kind:
            self.runner.release(job)

    def _schedule(self) -> None:
        pass

    def _slice_start(self, t: float) -> float:
        return t

    def _state_at(self, t: float) -> tuple[float, float, float]:
        return self.p, self.v, 0.0

    def _plan_job(self, job: Job, t: float, spec: Job | None = None, *, new_command: bool = True,
                  replan: bool = False) -> bool:
        self.plans.append((t, spec or job, new_command))
        return True

    def _stop_positioning_monitor(self) -> None:
        self.monitor_stopped += 1

    def _start_profile(self, profile, plan=None) -> None:
        self.profile = profile

    def stop_with(self, t, p, v, a, lim):                     # host.motion.stop_with
        self.stops.append(lim)
        return ("stop", t)


def table_job(steps, start: int = 1, end: int | None = None) -> Job:
    table = CommandTable(None, "T", steps)
    return Job(JobKind.TABLE, extra={"table": table, "start": start, "end": len(steps) if end is None else end})


def running_move(host: FakeHost) -> Job:
    move = Job(JobKind.VELOCITY, velocity=5.0)
    host.job, host.v = move, 5.0
    return move


def test_s7_1200_table_runner_leading_wait_keeps_the_running_command():
    """§11.1.9.1: the running command is aborted when the first motion step starts, not at the start of
    the table; a Wait step (§6.4.3.2) only waits its Duration."""
    host = FakeHost()
    move = running_move(host)
    job = table_job([{"Type": WAIT, "Duration": 0.5}, {"Type": REL, "Position": 10.0, "Velocity": 20.0}])
    host.runner.start(job)
    assert host.runner.job is job and job.extra["table"].in_use_by is job
    assert host.job is move and move.busy and host.plans == []
    assert host._timers[TIMER] == pytest.approx(0.5) and job.extra["current"] == 1
    host.now = 0.5
    host.runner.on_timer(0.5)
    assert move.state == JobState.ABORTED and host.job is job
    assert not host.holding_zero_velocity and host.monitor_stopped == 1
    (t, spec, new), = host.plans
    assert (t, spec.kind, spec.target, spec.velocity, new) == (0.5, JobKind.RELATIVE, 10.0, 20.0, True)
    assert job.extra["current"] == 2 and job.extra["phase"] == "position"


def test_s7_1200_table_runner_relative_steps_blend_and_count_from_the_previous_target():
    """§6.4.3.2/§6.4.3.6: a relative step counts from the previous positioning's target; "Blend motion"
    arrives with the next step's velocity when it goes on in the same direction, else it stops."""
    host = FakeHost()
    host.p = 2.0
    job = table_job([{"Type": REL, "Position": 10.0, "Velocity": 20.0, "NextStep": BLEND},
                     {"Type": REL, "Position": 5.0, "Velocity": 8.0, "NextStep": BLEND},
                     {"Type": ABS, "Position": 0.0, "Velocity": 30.0},
                     {"Type": EMPTY}])
    host.runner.start(job)
    host.p = 7.5                                           # mid-way: the next target still counts from 12
    host.runner.on_profile_end(job, 1.0)
    host.runner.on_profile_end(job, 2.0)
    targets = [(spec.kind, spec.target, spec.extra.get("end_velocity"), new) for _t, spec, new in host.plans]
    assert targets == [(JobKind.RELATIVE, 12.0, 8.0, True),       # blends into step 2 (same direction)
                       (JobKind.RELATIVE, 17.0, 0.0, False),      # step 3 reverses: stop at 17
                       (JobKind.ABSOLUTE, 0.0, 0.0, False)]
    host.p, host.v = 0.0, 0.0
    host.runner.on_profile_end(job, 3.0)                   # step 4 is Empty: the table ends at standstill
    assert job.state == JobState.DONE and host.runner.job is None and job.extra["table"].in_use_by is None


def test_s7_1200_table_runner_velocity_step_runs_for_its_duration_then_halt():
    """§6.4.3.2: a Velocity set point step lasts Duration (acceleration included); Halt brakes a moving
    axis with the configured deceleration."""
    host = FakeHost()
    job = table_job([{"Type": VEL, "Velocity": -15.0, "Duration": 2.0}, {"Type": HALT}])
    host.runner.start(job)
    (_t, spec, _new), = host.plans
    assert (spec.kind, spec.velocity, host._timers[TIMER]) == (JobKind.VELOCITY, -15.0, 2.0)
    host.v = -15.0
    host.runner.on_timer(2.0)
    assert host.plans[-1][1].kind == JobKind.HALT and job.extra["phase"] == "halt"
    host.v = 0.0
    host.runner.on_profile_end(job, 2.5)
    assert job.state == JobState.DONE and host.job is None and TIMER not in host._timers


def test_s7_1200_table_runner_end_of_table_while_moving_brakes_then_done():
    """docs/decisions.md row 41: at the end of the table a moving axis is braked with the configured
    deceleration; the table is Done at standstill (§9.5.2)."""
    host = FakeHost()
    job = table_job([{"Type": VEL, "Velocity": 10.0, "Duration": 1.0}])
    host.runner.start(job)
    host.v = 10.0
    host.runner.on_timer(1.0)
    (lim,) = host.stops
    assert lim.deceleration == DEC and job.busy and job.extra["phase"] == "final_stop" and host._interpolating
    host.v = 0.0
    host.runner.on_profile_end(job, 1.25)
    assert job.state == JobState.DONE and host.runner.job is None


def test_s7_1200_table_runner_bad_step_ends_the_table_motion_continues():
    """§9.6, §12.8 16#8702: a step with a velocity above MaxVelocity ends the table with a configuration
    error of the command table; the motion of the axis goes on (it is not stopped)."""
    host = FakeHost()
    job = table_job([{"Type": VEL, "Velocity": 10.0, "Duration": 1.0},
                     {"Type": REL, "Position": 5.0, "Velocity": 2 * VMAX}])
    host.runner.start(job)
    host.v = 10.0
    host.runner.on_timer(1.0)
    assert job.state == JobState.ERROR and (job.fault.kind, job.fault.detail) == (F.TABLE_CONFIG, "Velocity:above_max")
    assert host.job is None and host.runner.job is None and host.stops == [] and len(host.plans) == 1


def test_s7_1200_table_runner_absolute_step_needs_a_homed_axis():
    """§11.1.9.1, §12.8 16#8204: a Positioning Absolute step needs a homed axis."""
    host = FakeHost()
    host.homed = False
    job = table_job([{"Type": ABS, "Position": 5.0, "Velocity": 10.0}])
    host.runner.start(job)
    assert job.state == JobState.ERROR and job.fault.kind == F.NOT_HOMED and host.plans == []


def test_s7_1200_table_runner_start_is_rejected_like_a_motion_command():
    """§11.1.9.1 requirements: the axis's start checks apply (e.g. 16#8200 not enabled); a running passive
    homing rejects the table (§12.8 16#8207 / 16#0018)."""
    host = FakeHost()
    host.start_fault = F.reject(F.NOT_ENABLED)
    job = table_job([{"Type": REL, "Position": 5.0, "Velocity": 10.0}])
    host.runner.start(job)
    assert job.state == JobState.ERROR and job.fault.kind == F.NOT_ENABLED and host.runner.job is None
    host.start_fault = None
    host.passive_home = Job(JobKind.HOME_PASSIVE, mode=2)
    job = table_job([{"Type": REL, "Position": 5.0, "Velocity": 10.0}])
    host.runner.start(job)
    assert job.state == JobState.ERROR and (job.fault.kind, job.fault.detail) == (F.REJECTED, "table_homing")


def test_s7_1200_table_runner_new_table_replaces_one_still_waiting():
    """§11.1.9.1: a new MC_CommandTable aborts a table that waits in a Wait step before taking over."""
    host = FakeHost()
    first = table_job([{"Type": WAIT, "Duration": 1.0}, {"Type": REL, "Position": 5.0, "Velocity": 10.0}])
    host.runner.start(first)
    second = table_job([{"Type": WAIT, "Duration": 0.2}])
    host.runner.start(second)
    assert first.state == JobState.ABORTED and host.runner.job is second and host._timers[TIMER] == 0.2


# --- (b) the families attach the runner to their axes ---------------------------------------------------------
def test_s7_1200_table_runner_is_attached_to_s7_1200_axes_only():
    """MC_CommandTable exists in S7-1200 V6 §11.1.9 only: an S7-1200 positioning axis has a runner for
    table jobs, the S7-1500 positioning and synchronous axes have none."""
    ax = Controller().add_positioning_axis("A")
    assert isinstance(ax.table_runner, TableRunner) and ax.table_runner.axis is ax
    assert ax.runners == {JobKind.TABLE: ax.table_runner}
    for family in ("S7-1500", "S7-1500T"):
        ctl = Controller(family=family)
        axes = [ctl.add_positioning_axis("P")]
        if family == "S7-1500T":
            axes.append(ctl.add_synchronous_axis("S", leading_values=["P"]))
        for axis in axes:
            assert getattr(axis, "table_runner", None) is None and axis.runners == {}
