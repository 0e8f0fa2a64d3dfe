"""Superimposed motion (``kernel.superimposed.SuperimposedMotion``, MC_MoveSuperimposed of S7-1500T V5
§6.1.5.4 / §9.3.1), without any dialect: the component alone on a fake host, then on an axis of a kernel
``Controller`` built by a test family that attaches the component.

Expected values come from kinematics: a superimposed distance D with velocity v and acceleration =
deceleration a (no jerk limit) is a trapezoid of duration D/v + v/a, whose position is added to the
basic motion; a second distance adds to the first.
"""
from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from ._schema_axis import with_schema

from plcmotion import Controller
from plcmotion.kernel import family as families
from plcmotion.kernel import faults as F
from plcmotion.kernel import servo_cycle
from plcmotion.kernel.axis import PositioningAxis
from plcmotion.kernel.jobs import Job, JobKind, JobState
from plcmotion.kernel.profiles import Limits, Planner, PlanningError
from plcmotion.kernel.superimposed import TIMER, SuperimposedHost, SuperimposedMotion

DT = 0.001
LIM = Limits(velocity=5.0, acceleration=10.0, deceleration=10.0)     # jerk limit off: a trapezoid


def trapezoid(distance: float, v: float = 5.0, a: float = 10.0):
    """Position of a rest-to-rest trapezoid over ``distance`` (v reached: distance >= v^2/a)."""
    t_acc = v / a
    d = abs(distance)
    t_end = d / v + t_acc
    sign = 1.0 if distance >= 0 else -1.0

    def s(t: float) -> float:
        if t <= 0.0:
            return 0.0
        if t < t_acc:
            return sign * 0.5 * a * t * t
        if t < t_end - t_acc:
            return sign * (0.5 * a * t_acc ** 2 + v * (t - t_acc))
        if t < t_end:
            return sign * (d - 0.5 * a * (t_end - t) ** 2)
        return distance
    return s, t_end


def superimposed_job(distance: float) -> Job:
    return Job(JobKind.SUPERIMPOSED, position=distance, velocity=5.0)


# --- the component alone --------------------------------------------------------------------------------------
class FakeAxis:
    """Implements ``SuperimposedHost``: one bank row, its timers, its jobs; the basic motion is a constant
    velocity ``basic_v`` from 0 (written into the bank as the interpolate stage would)."""

    index = 0

    def __init__(self, basic_v: float = 0.0, planner=None) -> None:
        bank = SimpleNamespace(**{k: np.zeros(1) for k in (
            "sp_p", "sp_v", "sp_a", "sup_t", "sup_p", "sup_v", "sup_a", "sup_j")})
        self.ctl = SimpleNamespace(bank=bank, _n_sup=0)
        self.now = 0.0
        self.motion = SimpleNamespace(planner=planner or Planner())
        self._timers: dict[str, float] = {}
        self.scheduled = 0
        self.alarms: list = []
        self.basic_v = basic_v

    def _schedule(self) -> None:
        self.scheduled += 1

    def _finish_job(self, job, state, t, fault=None) -> None:
        job.finish(state, fault)

    def raise_alarm(self, fault, job=None) -> None:
        self.alarms.append((fault, job))

    def cycle(self, sup: SuperimposedMotion, t: float) -> float:
        """One servo cycle at ``t``: due timer, basic setpoint, superimpose stage; the total position."""
        self.now = t
        due = self._timers.get(TIMER)
        if due is not None and due <= t + 1e-9:
            del self._timers[TIMER]
            sup.on_timer(t)
        b = self.ctl.bank
        b.sp_p[0], b.sp_v[0], b.sp_a[0] = self.basic_v * t, self.basic_v, 0.0
        if self.ctl._n_sup:
            servo_cycle.superimpose(self.ctl, t)
        return float(b.sp_p[0])


def alone(basic_v: float = 0.0, planner=None) -> tuple[FakeAxis, SuperimposedMotion]:
    host = FakeAxis(basic_v, planner)
    typed: SuperimposedHost = host
    return host, SuperimposedMotion(typed)


def test_kernel_superimposed_distance_adds_to_the_basic_motion_as_a_trapezoid():
    """A distance of 10 at 5 units/s and 10 units/s^2: the position of the trapezoid (2.5 s) is added to
    a basic motion at 20 units/s in every servo cycle; then the part holds its distance (Done)."""
    host, sup = alone(basic_v=20.0)
    job = superimposed_job(10.0)
    sup.start(job, LIM)
    assert sup.active and job.busy and host.ctl._n_sup == 1
    s, t_end = trapezoid(10.0)
    for k in range(1, 3001):
        t = k * DT
        total = host.cycle(sup, t)
        assert total == pytest.approx(20.0 * t + s(t), abs=1e-9)
        assert job.busy == (t < t_end - 1e-9)
    assert job.state == JobState.DONE and not sup.active
    assert sup.state_at(host.now) == pytest.approx((10.0, 0.0, 0.0))
    assert TIMER not in host._timers and host.ctl._n_sup == 1        # the distance stays superimposed


def test_kernel_superimposed_distances_accumulate():
    """A second superimposed job starts from the state the first one left: 10 + (-4) = 6."""
    host, sup = alone()
    first, second = superimposed_job(10.0), superimposed_job(-4.0)
    sup.start(first, LIM)
    for k in range(1, 2600):
        host.cycle(sup, k * DT)
    sup.start(second, LIM)
    t0 = host.now
    s, t_end = trapezoid(-4.0)
    for k in range(2600, 5000):
        t = k * DT
        assert host.cycle(sup, t) == pytest.approx(10.0 + s(t - t0), abs=1e-9)
    assert first.state == second.state == JobState.DONE and host.ctl._n_sup == 1


def test_kernel_new_superimposed_job_aborts_the_running_one_and_starts_from_its_state():
    host, sup = alone()
    first, second = superimposed_job(10.0), superimposed_job(1.0)
    sup.start(first, LIM)
    for k in range(1, 1001):                                 # 1 s: cruising at 5 units/s
        host.cycle(sup, k * DT)
    before = sup.state_at(host.now)
    sup.start(second, LIM)
    assert first.state == JobState.ABORTED and second.busy
    # no jump in position and velocity (without a jerk limit the acceleration may jump)
    assert sup.state_at(host.now)[:2] == pytest.approx(before[:2])
    for k in range(1001, 4000):
        host.cycle(sup, k * DT)
    assert second.state == JobState.DONE
    assert sup.state_at(host.now)[0] == pytest.approx(before[0] + 1.0)


def test_kernel_distance_zero_from_rest_is_done_at_once():
    host, sup = alone()
    job = superimposed_job(0.0)
    sup.start(job, LIM)
    assert job.state == JobState.DONE and sup.state_at(0.0) == (0.0, 0.0, 0.0)


def test_kernel_basic_job_takes_the_superimposed_state_over():
    """S7-1500T V5 §9.3.1: a basic motion job that aborts the superimposed motion takes over its state
    (``carry``); the part is zero again, the servo stage has nothing to add."""
    host, sup = alone()
    job = superimposed_job(10.0)
    sup.start(job, LIM)
    for k in range(1, 1001):
        host.cycle(sup, k * DT)
    t = host.now
    state = sup.state_at(t)
    sup.take_over(t)
    assert job.state == JobState.ABORTED and sup.carry == pytest.approx(state)
    assert sup.profile is None and sup.job is None and host.ctl._n_sup == 0 and TIMER not in host._timers
    b = host.ctl.bank
    assert (b.sup_p[0], b.sup_v[0], b.sup_a[0], b.sup_j[0]) == (0.0, 0.0, 0.0, 0.0)
    assert sup.state_at(t + 1.0) == (0.0, 0.0, 0.0)


def test_kernel_alarm_ends_the_superimposed_job_with_error_and_clear_forgets_everything():
    host, sup = alone()
    job = superimposed_job(10.0)
    sup.start(job, LIM)
    host.cycle(sup, 0.5)
    fault = F.alarm(F.INTERNAL, "test")
    sup.take_over(0.5, JobState.ERROR, fault)
    assert job.state == JobState.ERROR and job.fault is fault and sup.carry is not None
    again = superimposed_job(3.0)
    sup.start(again, LIM)
    sup.clear()
    assert again.state == JobState.ABORTED and sup.carry is None and sup.profile is None
    assert host.ctl._n_sup == 0


def test_kernel_superimposed_planning_error_raises_an_alarm_with_the_job():
    class Refusing(Planner):
        def position(self, *args, **kw):
            raise PlanningError("no profile")

    host, sup = alone(planner=Refusing())
    job = superimposed_job(10.0)
    sup.start(job, LIM)
    (fault, with_job), = host.alarms
    assert with_job is job and fault.kind == F.INTERNAL and sup.profile is None and host.ctl._n_sup == 0


# --- on an axis of a kernel Controller ------------------------------------------------------------------------
class AxisWithSuperimposed(PositioningAxis):
    """How a family attaches the component: it creates it and hands it its timer."""

    def __init__(self, *args, **kw) -> None:
        self.superimposed = SuperimposedMotion(self)
        super().__init__(*args, **kw)

    def _on_timer(self, name: str, t: float) -> None:
        if name == TIMER:
            self.superimposed.on_timer(t)
            return
        super()._on_timer(name, t)


@pytest.fixture
def axis():
    axis_class = with_schema(AxisWithSuperimposed, {"Actor.Type": 1, "Simulation.Mode": 1})

    def factory(ctl, name, flat, where):
        return ctl.new_axis(axis_class, name, flat, where)

    fam = families.register(families.Family("Test-Superimposed", versions=(1,), default_version=1,
                                            factories={families.POSITIONING_AXIS: factory}))
    try:
        ctl = Controller(family=fam.name)
        ax = ctl.add_positioning_axis("Axis_1", {
            "Actor.Type": 1, "Simulation.Mode": 1, "DynamicLimits.MaxVelocity": 100.0,
            "DynamicDefaults.Acceleration": 100.0, "DynamicDefaults.Deceleration": 100.0, "DynamicDefaults.Jerk": 0.0})
        assert ax.power(object(), True, 1, 0) is None
        ctl.run(0.02)
        assert ax.state == "enabled"
        yield ax
    finally:
        families._REGISTRY.pop(fam.name)


def test_kernel_controller_axis_superimposed_distance_adds_to_a_velocity_motion(axis):
    """The axis moves at 20 units/s; a superimposed distance of 10 adds the trapezoid to it cycle by cycle,
    and afterwards the axis runs 10 units ahead of its basic motion."""
    ctl = axis.ctl
    axis.submit(Job(JobKind.VELOCITY, velocity=20.0))
    ctl.run(0.5)                                        # 20 units/s reached after 0.2 s
    b, i = ctl.bank, axis.index
    t0, p0 = ctl.time, float(b.sp_p[i])
    job = superimposed_job(10.0)
    axis.superimposed.start(job, LIM)
    s, t_end = trapezoid(10.0)
    seen = []
    ctl.on_post_servo(lambda t: seen.append((t, float(b.sp_p[i]), float(b.sp_v[i]))))
    ctl.run(3.0)
    for t, p, v in seen:
        assert p == pytest.approx(p0 + 20.0 * (t - t0) + s(t - t0), abs=1e-9)
    assert job.state == JobState.DONE and not axis.superimposed.active
    t, p, v = seen[-1]
    assert p - (p0 + 20.0 * (t - t0)) == pytest.approx(10.0, abs=1e-9) and v == pytest.approx(20.0)
    assert axis.job is not None and axis.job.busy            # the basic job runs on, untouched


def test_kernel_controller_axis_superimposed_motion_at_standstill_ends_done_at_the_distance(axis):
    ctl = axis.ctl
    b, i = ctl.bank, axis.index
    p0 = float(b.sp_p[i])
    job = superimposed_job(-10.0)
    axis.superimposed.start(job, LIM)
    _s, t_end = trapezoid(-10.0)
    ctl.run(t_end - 0.01)
    assert job.busy and axis.superimposed.active
    ctl.run(0.02)
    assert job.state == JobState.DONE
    assert float(b.sp_p[i]) == pytest.approx(p0 - 10.0, abs=1e-9) and float(b.sp_v[i]) == 0.0
