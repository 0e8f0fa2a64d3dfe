"""Per-axis job queue with the PLCopen buffer modes, at kernel level (no dialect).

Expected values come from PLCopen Motion Control Part 1 (BufferMode, "Active"), the S7-Technology V4.1
MC_MoveAbsolute examples "Append motion" / "Overlay motion 1-3" and kinematics (v^2 = v0^2 + 2 a s), never
from the code under test.
"""
from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from plcmotion import Controller
from plcmotion.kernel import faults as F
from plcmotion.kernel.job_queue import BufferMode, JobQueue, transition_velocity
from plcmotion.kernel.jobs import Job, JobKind, JobState

ACC = 10.0            # S7-Technology examples: Acceleration = Deceleration = 10
DT = 0.001            # servo cycle of Controller()


# --- the rules as a pure component --------------------------------------------------------------------------
@pytest.mark.parametrize("mode, v1, v2, expected", [
    (BufferMode.BLENDING_LOW, 50.0, 30.0, 30.0), (BufferMode.BLENDING_LOW, 50.0, 70.0, 50.0),
    (BufferMode.BLENDING_PREVIOUS, 50.0, 30.0, 50.0), (BufferMode.BLENDING_PREVIOUS, 50.0, 70.0, 50.0),
    (BufferMode.BLENDING_NEXT, 50.0, 30.0, 30.0), (BufferMode.BLENDING_NEXT, 50.0, 70.0, 70.0),
    (BufferMode.BLENDING_HIGH, 50.0, 30.0, 50.0), (BufferMode.BLENDING_HIGH, 50.0, 70.0, 70.0),
    (BufferMode.BUFFERED, 50.0, 70.0, 0.0), (BufferMode.ABORTING, 50.0, 70.0, 0.0),
])
def test_kernel_transition_velocity_follows_plcopen_table(mode, v1, v2, expected):
    assert transition_velocity(mode, v1, v2, reverses=False) == expected
    assert transition_velocity(mode, v1, v2, reverses=True) == 0.0       # reversal: standstill at the target


def test_kernel_buffer_mode_numbers_are_plcopen_order():
    assert [m.name for m in BufferMode] == ["ABORTING", "BUFFERED", "BLENDING_LOW", "BLENDING_PREVIOUS",
                                            "BLENDING_NEXT", "BLENDING_HIGH"]
    assert [int(m) for m in BufferMode] == [0, 1, 2, 3, 4, 5]


class FakeAxis:
    """A QueueOwner that runs one job at a time like an axis: starting a job aborts the running one."""

    def __init__(self, depth: int = 1):
        self.queue = JobQueue(self, depth)
        self.job: Job | None = None
        self.log: list[tuple] = []
        self.refuse: set[int] = set()          # id() of jobs that fail when they start
        self.blends: list[tuple[Job, Job, float]] = []
        self.passed = False

    # QueueOwner
    def running_job(self):
        return self.job if self.job is not None and self.job.busy else None

    def admit(self, job):
        return None

    def take_over(self, job, after=None):
        if id(job) in self.refuse:
            job.finish(JobState.ERROR, F.reject(F.NOT_HOMED))
            return
        old = self.job
        self.job = job
        self.log.append(("start", job))
        if old is not None and old.busy:
            self.finish(old, JobState.ABORTED)

    def finish(self, job, state):
        job.finish(state)
        if job is self.job:
            self.job = None
        self.log.append((state.name, job))
        self.queue.finished(job)

    def commanded_speed(self, job):
        return abs(job.velocity)

    def reverses(self, running, job):
        return job.position * (running.position or 1.0) < 0

    def plan_blend(self, running, job, speed):
        self.blends.append((running, job, speed))
        return speed

    def passed_target(self, job):
        return self.passed

    def settle(self):
        self.log.append(("settle", None))


def move(distance=100.0, velocity=50.0, kind=JobKind.RELATIVE):
    return Job(kind, position=distance, velocity=velocity)


def test_kernel_buffered_job_is_busy_not_active_until_the_running_one_is_done():
    ax = FakeAxis()
    j1, j2 = move(), move()
    ax.queue.submit(j1, BufferMode.BUFFERED)          # nothing runs: starts at once
    assert j1.active and ax.job is j1
    ax.queue.submit(j2, BufferMode.BUFFERED)
    assert j2.busy and not j2.active and ax.queue.pending == (j2,)
    assert ax.job is j1 and j1.active
    ax.finish(j1, JobState.DONE)
    # Done of the first and start of the second in the same step, in this order
    assert ax.log[-2:] == [("DONE", j1), ("start", j2)]
    assert j2.active and ax.queue.pending == ()


def test_kernel_aborting_job_aborts_running_and_waiting_jobs():
    ax = FakeAxis(depth=2)
    j1, j2, j3, j4 = move(), move(), move(), move()
    ax.queue.submit(j1)
    ax.queue.submit(j2, BufferMode.BUFFERED)
    ax.queue.submit(j3, BufferMode.BLENDING_LOW)
    ax.queue.submit(j4, BufferMode.ABORTING)
    assert j1.state == j2.state == j3.state == JobState.ABORTED
    assert not j2.pending and not j3.pending
    assert j4.active and ax.queue.pending == ()


def test_kernel_full_queue_rejects_and_the_running_job_goes_on():
    ax = FakeAxis(depth=1)
    j1, j2, j3 = move(), move(), move()
    ax.queue.submit(j1)
    ax.queue.submit(j2, BufferMode.BUFFERED)
    ax.queue.submit(j3, BufferMode.BUFFERED)
    assert j3.state == JobState.ERROR and j3.fault.kind == F.QUEUE_FULL and not j3.fault.ack
    assert j1.active and j2.busy and ax.queue.pending == (j2,)
    deeper = FakeAxis(depth=2)
    k = [move() for _ in range(3)]
    for job in k:
        deeper.queue.submit(job, BufferMode.BUFFERED)
    assert deeper.queue.pending == (k[1], k[2])
    deeper.finish(k[0], JobState.DONE)
    deeper.finish(k[1], JobState.DONE)
    assert [e[0] for e in deeper.log] == ["start", "DONE", "start", "DONE", "start"]
    assert k[2].active


def test_kernel_depth_zero_buffers_nothing():
    ax = FakeAxis(depth=0)
    j1, j2 = move(), move()
    ax.queue.submit(j1)
    ax.queue.submit(j2, BufferMode.BUFFERED)
    assert j2.fault.kind == F.QUEUE_FULL and j1.active


def test_kernel_buffered_after_velocity_job_starts_at_in_velocity():
    ax = FakeAxis()
    vel = Job(JobKind.VELOCITY, velocity=20.0)
    j2 = move()
    ax.queue.submit(vel)
    ax.queue.submit(j2, BufferMode.BUFFERED)
    ax.queue.poll()
    assert j2.pending                                 # still accelerating
    vel.in_velocity = True
    ax.queue.poll()
    assert j2.active
    assert vel.state == JobState.ABORTED              # a continuous motion has no Done (PLCopen)


def test_kernel_velocity_job_at_its_velocity_is_taken_over_at_once():
    ax = FakeAxis()
    vel = Job(JobKind.VELOCITY, velocity=20.0)
    ax.queue.submit(vel)
    vel.in_velocity = True
    j2 = move()
    ax.queue.submit(j2, BufferMode.BLENDING_HIGH)     # no target to blend at: behaves as buffered
    assert j2.active and vel.state == JobState.ABORTED and ax.blends == []


def test_kernel_failing_running_job_aborts_the_waiting_ones():
    ax = FakeAxis()
    j1, j2 = move(), move()
    ax.queue.submit(j1)
    ax.queue.submit(j2, BufferMode.BUFFERED)
    ax.finish(j1, JobState.ERROR)
    assert j2.state == JobState.ABORTED and ax.job is None


def test_kernel_job_that_cannot_start_ends_with_its_fault_and_its_followers_are_aborted():
    ax = FakeAxis(depth=2)
    j1, j2, j3 = move(), move(), move()
    ax.refuse.add(id(j2))
    for job in (j1, j2, j3):
        ax.queue.submit(job, BufferMode.BUFFERED)
    ax.finish(j1, JobState.DONE)
    assert j1.state == JobState.DONE
    assert j2.state == JobState.ERROR and j2.fault.kind == F.NOT_HOMED
    assert j3.state == JobState.ABORTED
    assert ("settle", None) in ax.log                 # nothing controls the axis: a blend tail is braked


def test_kernel_nothing_waits_behind_a_job_without_a_defined_end():
    ax = FakeAxis()
    jog = Job(JobKind.JOG, velocity=10.0)
    ax.queue.submit(jog)
    j2 = move()
    ax.queue.submit(j2, BufferMode.BUFFERED)
    assert j2.state == JobState.ERROR and j2.fault.kind == F.NOT_APPENDABLE and jog.active


def test_kernel_blending_asks_for_the_transition_velocity_of_its_mode():
    ax = FakeAxis()
    j1, j2 = move(1000.0, 50.0), move(500.0, 30.0)
    ax.queue.submit(j1)
    ax.queue.submit(j2, BufferMode.BLENDING_HIGH)
    assert ax.blends == [(j1, j2, 50.0)]
    ax.passed = True                                  # the running positioning passes its target
    ax.queue.poll()
    assert j1.state == JobState.DONE and j2.active
    assert ax.log[-2:] == [("DONE", j1), ("start", j2)]


def test_kernel_reversing_blend_plans_no_motion_through_the_target():
    ax = FakeAxis()
    j1, j2 = move(1000.0, 50.0), move(-300.0, 30.0)
    ax.queue.submit(j1)
    ax.queue.submit(j2, BufferMode.BLENDING_HIGH)
    assert ax.blends == []                           # transition velocity 0: the axis stops at the target


def test_kernel_cancelling_the_waiting_blend_replans_the_running_positioning_to_stop():
    ax = FakeAxis()
    j1, j2 = move(1000.0, 50.0), move(500.0, 30.0)
    ax.queue.submit(j1)
    ax.queue.submit(j2, BufferMode.BLENDING_LOW)
    ax.queue.abort_all()
    assert j2.state == JobState.ABORTED and ax.blends[-1] == (j1, None, 0.0) and j1.active


def test_kernel_family_transition_velocity_replaces_the_plcopen_choice():
    ax = FakeAxis()
    j1, j2 = move(1000.0, 50.0), move(500.0, 30.0)
    ax.queue.submit(j1)
    ax.queue.submit(j2, BufferMode.BLENDING_PREVIOUS, transition_velocity=12.5)   # Pilz "End velocity"
    assert ax.blends == [(j1, j2, 12.5)]


# --- on a real axis ---------------------------------------------------------------------------------------------
def sim_axis(jerk: float | None = None, **extra):
    """A simulated axis (setpoint = actual) with the S7-Technology example dynamics; trapezoidal unless ``jerk``."""
    ctl = Controller()
    params = {"Actor.Type": 1, "Simulation.Mode": 1, "DynamicDefaults.Acceleration": ACC,
              "DynamicDefaults.Deceleration": ACC, "DynamicLimits.MaxVelocity": 100.0,
              "DynamicDefaults.Jerk": jerk if jerk is not None else 0.0}
    params.update(extra)
    axis = ctl.add_positioning_axis("Axis_1", params)
    assert axis.power(object(), True, 1, 0) is None
    ctl.run(0.02)
    assert axis.state == "enabled"
    return ctl, axis


class Recorder:
    """Setpoint samples of every servo cycle and the first sample at or beyond a position."""

    def __init__(self, ctl, axis):
        self.b, self.i = ctl.bank, axis.index
        self.samples: list[tuple[float, float, float]] = []
        ctl.on_post_servo(self)

    def __call__(self, t):
        self.samples.append((t, float(self.b.sp_p[self.i]), float(self.b.sp_v[self.i])))

    def crossing(self, x: float, sign: float = 1.0):
        for k in range(1, len(self.samples)):
            if (self.samples[k - 1][1] - x) * sign < 0 <= (self.samples[k][1] - x) * sign:
                return self.samples[k]
        raise AssertionError(f"{x} never passed")


def position(ctl, axis):
    return float(ctl.bank.sp_p[axis.index])


def velocity(ctl, axis):
    return float(ctl.bank.sp_v[axis.index])


def test_kernel_buffered_moves_run_back_to_back_and_end_done_in_order():
    """S7-Technology MC_MoveAbsolute "Append motion": the axis stops at 1000 (Done_1), the second job starts
    without gap from standstill and ends Done at 1500; Busy_2 from the start, not Active before."""
    ctl, axis = sim_axis()
    j1 = Job(JobKind.RELATIVE, position=1000.0, velocity=50.0)
    j2 = Job(JobKind.RELATIVE, position=500.0, velocity=50.0)
    axis.submit(j1)
    ctl.run(5.0)
    axis.submit(j2, BufferMode.BUFFERED)
    assert j2.busy and not j2.active and j1.active
    states = []
    ctl.on_post_servo(lambda t: states.append((t, j1.state, j2.active, position(ctl, axis), velocity(ctl, axis))))
    ctl.run_until(lambda: not j2.busy, 120.0)
    assert j1.state == j2.state == JobState.DONE
    first = next(k for k, s in enumerate(states) if s[2])               # first cycle with job 2 active
    _t, s1, _, p, v = states[first]
    assert s1 == JobState.DONE                                          # handover in the cycle of Done 1 ...
    assert all(s[1] == JobState.BUSY and not s[2] for s in states[:first])
    assert p == pytest.approx(1000.0, abs=1e-9) and v == pytest.approx(0.0, abs=1e-9)   # ... at standstill
    assert position(ctl, axis) == pytest.approx(1500.0, abs=1e-9)
    # no gap: the axis leaves 1000 in the cycle after the handover
    assert states[first + 1][3] > 1000.0


@pytest.mark.parametrize("mode", [BufferMode.BLENDING_LOW, BufferMode.BLENDING_PREVIOUS,
                                  BufferMode.BLENDING_NEXT, BufferMode.BLENDING_HIGH])
@pytest.mark.parametrize("v2", [30.0, 70.0])
@pytest.mark.parametrize("jerk", [None, 40.0])
def test_kernel_blend_passes_the_first_target_at_the_transition_velocity(mode, v2, jerk):
    """S7-Technology "Overlay motion 1/2" generalised to the four PLCopen blending modes: the first target
    (1000) is passed without stopping at min / previous / next / max of 50 and v2; job 1 is Done there."""
    ctl, axis = sim_axis(jerk)
    j1 = Job(JobKind.RELATIVE, position=1000.0, velocity=50.0)
    j2 = Job(JobKind.RELATIVE, position=500.0, velocity=v2)
    axis.submit(j1)
    ctl.run(5.0)
    axis.submit(j2, mode)
    rec = Recorder(ctl, axis)
    seen = []
    ctl.on_post_servo(lambda t: seen.append((t, j1.state, j2.active)))
    ctl.run_until(lambda: not j2.busy, 120.0)
    expected = {BufferMode.BLENDING_LOW: min(50.0, v2), BufferMode.BLENDING_PREVIOUS: 50.0,
                BufferMode.BLENDING_NEXT: v2, BufferMode.BLENDING_HIGH: max(50.0, v2)}[mode]
    t, _p, v = rec.crossing(1000.0)
    # the velocity changes by at most ACC * DT within the cycle of the crossing
    assert v == pytest.approx(expected, abs=ACC * DT + 1e-6)
    at = next(s for s in seen if s[0] == t)
    assert at[1] == JobState.DONE and at[2]          # Done of job 1 and job 2 Active in the same cycle
    assert j1.state == j2.state == JobState.DONE
    assert position(ctl, axis) == pytest.approx(1500.0, abs=1e-9)
    assert max(abs(s[2]) for s in rec.samples) <= max(50.0, v2) * (1 + 1e-9)


def test_kernel_reversing_blend_stops_at_the_first_target():
    """S7-Technology "Overlay motion 3": second target 700 < 1000: v = 0 exactly at 1000, then -30 to 700."""
    ctl, axis = sim_axis()
    j1 = Job(JobKind.RELATIVE, position=1000.0, velocity=50.0)
    j2 = Job(JobKind.ABSOLUTE, position=700.0, velocity=30.0)
    axis.home_direct(Job(JobKind.HOME_DIRECT, position=0.0))
    axis.submit(j1)
    ctl.run(5.0)
    axis.submit(j2, BufferMode.BLENDING_HIGH)
    rec = Recorder(ctl, axis)
    ctl.run_until(lambda: not j2.busy, 120.0)
    peak = max(s[1] for s in rec.samples)
    assert peak == pytest.approx(1000.0, abs=1e-9)            # never beyond the first target
    at_peak = [s for s in rec.samples if s[1] == pytest.approx(1000.0, abs=1e-6)]
    assert all(abs(s[2]) <= ACC * DT + 1e-9 for s in at_peak)
    assert min(s[2] for s in rec.samples) == pytest.approx(-30.0)
    assert j1.state == j2.state == JobState.DONE and position(ctl, axis) == pytest.approx(700.0, abs=1e-9)


def test_kernel_blend_is_lowered_to_what_the_next_distance_can_stop_from():
    """A short second move (5 units, deceleration 10) can only be entered at sqrt(2 * 10 * 5) = 10, less what
    the axis travels in the servo cycle before the second job takes over."""
    ctl, axis = sim_axis()
    j1 = Job(JobKind.RELATIVE, position=1000.0, velocity=50.0)
    j2 = Job(JobKind.RELATIVE, position=5.0, velocity=50.0)
    axis.submit(j1)
    ctl.run(5.0)
    axis.submit(j2, BufferMode.BLENDING_HIGH)
    rec = Recorder(ctl, axis)
    ctl.run_until(lambda: not j2.busy, 120.0)
    _t, _p, v = rec.crossing(1000.0)
    assert math.sqrt(2 * ACC * (5.0 - 10.0 * DT)) - ACC * DT <= v <= math.sqrt(2 * ACC * 5.0)
    assert position(ctl, axis) == pytest.approx(1005.0, abs=1e-9)
    assert max(s[1] for s in rec.samples) == pytest.approx(1005.0, abs=1e-9)


def test_kernel_late_blend_is_lowered_to_what_the_remaining_distance_can_reach():
    """Submitted while job 1 already brakes 50 units before its target: from v0 the axis can at most speed up
    over those 50 units, v^2 = v0^2 + 2 * 10 * 50, below the 70 BlendingHigh asks for."""
    ctl, axis = sim_axis()
    j1 = Job(JobKind.RELATIVE, position=1000.0, velocity=50.0)
    axis.submit(j1)
    ctl.run_until(lambda: position(ctl, axis) >= 950.0, 60.0)
    p0, v0 = position(ctl, axis), velocity(ctl, axis)
    assert 0 < v0 < 50.0                                   # braking already
    j2 = Job(JobKind.RELATIVE, position=500.0, velocity=70.0)
    axis.submit(j2, BufferMode.BLENDING_HIGH)
    rec = Recorder(ctl, axis)
    ctl.run_until(lambda: not j2.busy, 120.0)
    _t, _p, v = rec.crossing(1000.0)
    reach = math.sqrt(v0 * v0 + 2 * ACC * (1000.0 - p0))
    assert v == pytest.approx(reach, abs=2 * ACC * DT)
    assert position(ctl, axis) == pytest.approx(1500.0, abs=1e-9)


def test_kernel_aborting_job_aborts_active_and_pending_jobs_on_the_axis():
    ctl, axis = sim_axis()
    axis.queue.depth = 2
    j1, j2, j3 = (Job(JobKind.RELATIVE, position=1000.0, velocity=50.0) for _ in range(3))
    axis.submit(j1)
    axis.submit(j2, BufferMode.BUFFERED)
    axis.submit(j3, BufferMode.BLENDING_LOW)
    ctl.run(2.0)
    halt = Job(JobKind.HALT)
    axis.submit(halt)                                      # default: Aborting
    assert (j1.state, j2.state, j3.state) == (JobState.ABORTED,) * 3
    ctl.run_until(lambda: not halt.busy, 20.0)
    assert halt.state == JobState.DONE and velocity(ctl, axis) == 0.0
    assert position(ctl, axis) < 1000.0


def test_kernel_full_queue_rejects_on_the_axis():
    ctl, axis = sim_axis()
    j1, j2, j3 = (Job(JobKind.RELATIVE, position=100.0, velocity=50.0) for _ in range(3))
    axis.submit(j1)
    axis.submit(j2, BufferMode.BUFFERED)
    axis.submit(j3, BufferMode.BUFFERED)
    assert j3.state == JobState.ERROR and j3.fault.kind == F.QUEUE_FULL
    ctl.run_until(lambda: not j2.busy, 60.0)
    assert j1.state == j2.state == JobState.DONE and position(ctl, axis) == pytest.approx(200.0, abs=1e-9)


def test_kernel_buffered_move_after_velocity_job_starts_at_in_velocity():
    """PLCopen: behind MC_MoveVelocity the buffered job starts when InVelocity is reached (ramp 0 -> 20 with
    acceleration 10 takes 2 s), from the moving state."""
    ctl, axis = sim_axis()
    vel = Job(JobKind.VELOCITY, velocity=20.0)
    j2 = Job(JobKind.RELATIVE, position=100.0, velocity=20.0)
    axis.submit(vel)
    axis.submit(j2, BufferMode.BUFFERED)
    t0 = ctl.time
    ctl.run_until(lambda: j2.active, 10.0)
    assert ctl.time - t0 == pytest.approx(2.0, abs=2 * DT)
    assert vel.state == JobState.ABORTED and vel.reached_once
    # distance of the ramp: 20^2 / (2 * 10) = 20, then 100 relative to the set position at the takeover
    ctl.run_until(lambda: not j2.busy, 60.0)
    assert position(ctl, axis) == pytest.approx(120.0, abs=ACC * DT)


def test_kernel_buffered_job_waits_for_positioning_monitoring_on_a_servo_axis():
    """On a drive with positioning monitoring "Done" needs the actual position in the window for the dwell
    time; the buffered job starts only then (PLCopen: after Done)."""
    ctl = Controller()
    axis = ctl.add_positioning_axis("Axis_1", {"Actor.Type": 1})
    axis.power(object(), True, 1, 0)
    ctl.run_until(lambda: axis.state == "enabled", 5.0)
    j1 = Job(JobKind.RELATIVE, position=50.0, velocity=50.0)
    j2 = Job(JobKind.RELATIVE, position=50.0, velocity=50.0)
    axis.submit(j1)
    axis.submit(j2, BufferMode.BUFFERED)
    done_at = []
    ctl.on_post_servo(lambda t: done_at.append(t) if j1.state == JobState.DONE and not done_at else None)
    ctl.run_until(lambda: not j1.busy, 30.0)
    end_of_profile = axis.profile.segments[0].t         # the profile of job 2 starts at the handover
    assert j1.state == JobState.DONE and j2.active
    assert end_of_profile == pytest.approx(done_at[0] if done_at else ctl.time, abs=DT)
    ctl.run_until(lambda: not j2.busy, 30.0)
    assert j2.state == JobState.DONE and position(ctl, axis) == pytest.approx(100.0, abs=1e-9)


def test_kernel_axis_alarm_aborts_waiting_jobs():
    ctl, axis = sim_axis()
    j1, j2 = (Job(JobKind.RELATIVE, position=1000.0, velocity=50.0) for _ in range(2))
    axis.submit(j1)
    axis.submit(j2, BufferMode.BUFFERED)
    axis.raise_alarm(F.alarm(F.DRIVE_ALARM, "", F.Reaction.STOP))
    assert j1.state == JobState.ERROR and j2.state == JobState.ABORTED
    ctl.run(20.0)
    assert velocity(ctl, axis) == 0.0 and axis.queue.pending == ()


def test_kernel_disabling_the_axis_aborts_waiting_jobs():
    ctl, axis = sim_axis()
    j1, j2 = (Job(JobKind.RELATIVE, position=1000.0, velocity=50.0) for _ in range(2))
    axis.submit(j1)
    axis.submit(j2, BufferMode.BLENDING_LOW)
    ctl.run(1.0)
    axis.power(axis.power_owner, False, 1, 0)
    ctl.run(20.0)
    assert j1.state == JobState.ABORTED and j2.state == JobState.ABORTED and not j2.pending
    assert axis.state == "disabled" and velocity(ctl, axis) == 0.0


def test_kernel_cancelled_blend_stops_at_the_first_target():
    ctl, axis = sim_axis()
    j1 = Job(JobKind.RELATIVE, position=1000.0, velocity=50.0)
    j2 = Job(JobKind.RELATIVE, position=500.0, velocity=50.0)
    axis.submit(j1)
    ctl.run(5.0)
    axis.submit(j2, BufferMode.BLENDING_HIGH)
    ctl.run(1.0)
    axis.queue.abort_all()
    assert j2.state == JobState.ABORTED and j1.active
    rec = Recorder(ctl, axis)
    ctl.run_until(lambda: not j1.busy, 60.0)
    assert j1.state == JobState.DONE and position(ctl, axis) == pytest.approx(1000.0, abs=1e-9)
    assert max(s[1] for s in rec.samples) == pytest.approx(1000.0, abs=1e-9)


def test_kernel_queued_job_is_checked_when_it_is_accepted():
    ctl, axis = sim_axis()
    j1 = Job(JobKind.RELATIVE, position=100.0, velocity=50.0)
    j2 = Job(JobKind.ABSOLUTE, position=300.0, velocity=50.0)
    axis.submit(j1)
    axis.submit(j2, BufferMode.BUFFERED)              # the axis is not homed: no absolute positioning
    assert j2.state == JobState.ERROR and j2.fault.kind == F.NOT_HOMED and j1.active


def test_kernel_blend_within_software_limits_is_not_a_move_to_the_limit():
    """With software limit switches active the motion beyond the first target belongs to the next job: the
    blend passes 1000 and ends at 1500 without a limit alarm."""
    ctl, axis = sim_axis(**{"PositionLimits_SW.Active": True, "PositionLimits_SW.MinPosition": -10.0,
                            "PositionLimits_SW.MaxPosition": 1600.0})
    axis.home_direct(Job(JobKind.HOME_DIRECT, position=0.0))
    assert axis.sw_limits_effective()
    j1 = Job(JobKind.ABSOLUTE, position=1000.0, velocity=50.0)
    j2 = Job(JobKind.ABSOLUTE, position=1500.0, velocity=50.0)
    axis.submit(j1)
    axis.submit(j2, BufferMode.BLENDING_LOW)
    rec = Recorder(ctl, axis)
    ctl.run_until(lambda: not j2.busy, 120.0)
    assert rec.crossing(1000.0)[2] == pytest.approx(50.0, abs=ACC * DT + 1e-6)
    assert j1.state == j2.state == JobState.DONE and not axis.alarms
    assert position(ctl, axis) == pytest.approx(1500.0, abs=1e-9)


# --- random sequences ---------------------------------------------------------------------------------------------
_modes = st.sampled_from([BufferMode.BUFFERED, BufferMode.BLENDING_LOW, BufferMode.BLENDING_PREVIOUS,
                          BufferMode.BLENDING_NEXT, BufferMode.BLENDING_HIGH])
_moves = st.lists(st.tuples(st.floats(-400.0, 400.0).filter(lambda d: abs(d) >= 1.0),
                            st.floats(5.0, 100.0), _modes, st.floats(0.0, 3.0)), min_size=1, max_size=5)


@settings(max_examples=25, deadline=None)
@given(moves=_moves, jerk=st.sampled_from([None, 60.0]))
def test_kernel_random_buffered_and_blended_sequences(moves, jerk):
    """Never above the maximum velocity, always at the last target at the end, every job ends exactly once
    (all Done: each waits until the queue has room, so none is rejected or aborted), in order."""
    ctl, axis = sim_axis(jerk)
    vmax = axis.eff["DynamicLimits.MaxVelocity"]
    b, i = ctl.bank, axis.index
    top = [0.0]
    ctl.on_post_servo(lambda t: top.__setitem__(0, max(top[0], abs(float(b.sp_v[i])))))
    jobs, ends = [], []

    def watch(t):
        for k, job in enumerate(jobs):
            if not job.busy and k not in (e[0] for e in ends):
                ends.append((k, job.state, t))
    ctl.on_post_servo(watch)
    target = 0.0
    for distance, speed, mode, wait in moves:
        ctl.run_until(lambda: not axis.queue.pending, 200.0)
        ctl.run(wait)
        job = Job(JobKind.RELATIVE, position=distance, velocity=speed)
        jobs.append(job)
        axis.submit(job, mode)
        assert job.busy, job.fault
        target += distance
    ctl.run_until(lambda: not any(j.busy for j in jobs), 400.0)
    ctl.run(0.01)
    assert top[0] <= vmax * (1 + 1e-9)
    assert position(ctl, axis) == pytest.approx(target, abs=1e-6)
    assert velocity(ctl, axis) == 0.0
    assert [s for _k, s, _t in ends] == [JobState.DONE] * len(jobs)
    assert [k for k, _s, _t in ends] == sorted(k for k, _s, _t in ends)        # in order
    assert len({k for k, _s, _t in ends}) == len(jobs)
    assert all(j.state == JobState.DONE for j in jobs)
