"""The following-axis component (kernel.follower.Follower), at kernel level (no dialect).

(a) The component alone on a small fake host that implements ``FollowerHost``, with the controller's sync
stage evaluating the coupling every servo cycle as the kernel does; (b) a synchronous axis of a kernel
``Controller`` driven by kernel jobs.  Expected values come from the synchronous operation functions of the
S7-1500T V5 manual (gearing: following value = ratio x leading value + offset, §4.1/§4.2; phase shift: the
leading value is shifted, §4.5) and from kinematics, never from the code under test.
"""
from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

from plcmotion import Controller
from plcmotion.kernel import faults as F
from plcmotion.kernel.follower import Follower
from plcmotion.kernel.jobs import Job, JobKind, JobState
from plcmotion.kernel.profiles import Planner
from plcmotion.kernel.sync import SyncStage

DT = 0.001            # servo cycle
SPEED = 10.0          # leading value velocity (units/s)


# --- a fake host ------------------------------------------------------------------------------------------
class FakeLeader:
    """A leading axis moving at constant velocity: position SPEED * t (setpoint coupling, §3.3)."""

    name = "Leader"
    index = 0
    provides_setpoints = True

    def at(self, t):
        return SPEED * t, SPEED, 0.0

    def lv_value(self, mode, t):
        return self.at(t)

    def leading_value_invalid(self, mode):
        return None

    def lv_position_controlled(self):
        return True

    def lv_modulo(self):
        return None


class FakeController:
    """What the follower and the sync stage use of a controller: the setpoint arrays of two axes."""

    mode = "RUN"
    features = frozenset()
    servo_cycle = DT

    def __init__(self, leader):
        self.time = 0.0
        self._bank_time = 0.0
        self.bank = SimpleNamespace(sp_p=np.zeros(2), sp_v=np.zeros(2), sp_a=np.zeros(2))
        self.sync = SyncStage(self)
        self.leader = leader

    def offers_job(self, kind):
        return True

    def _lookup(self, name):
        return self.leader if name == self.leader.name else None


class FakeHost:
    """A following axis reduced to what ``FollowerHost`` asks: an own profile, job ends and alarms."""

    name = "Follower"
    index = 1

    def __init__(self, leading_values=("Leader",)):
        self.ctl = FakeController(FakeLeader())
        self.config = SimpleNamespace(modulo=SimpleNamespace(enabled=False, length=0.0),
                                      leading_value_output=SimpleNamespace(enabled=False))
        self.motion = SimpleNamespace(planner=Planner())
        self.profile = Planner.hold(0.0, 0.0)
        self.state = "enabled"
        self.job = self.stop_job = self.sup_job = None
        self.holding_zero_velocity = False
        self.last_internal_error = None
        self._interpolating = False
        self._timers: dict[str, float] = {}
        self.alarms: list = []
        self.overrides: list[str] = []
        self.follower = Follower(self, leading_values, self.name)

    @property
    def now(self):
        return self.ctl.time

    def raise_alarm(self, fault, job=None):
        self.alarms.append(fault)

    def _blocking_alarm(self):
        return None

    def _finish_job(self, job, state, t, fault=None):
        job.finish(state, fault)

    def _start_profile(self, profile):
        self.profile = profile

    def _state_at(self, t):
        return self.profile.at(t)

    def _set_position_control(self, on):
        pass

    def _schedule(self):
        pass

    def _override(self, new, t, new_job):
        self.overrides.append(new)

    def _note_limits(self, lim, job=None):
        pass

    def sw_limits_effective(self):
        return False

    def sup_state_at(self, t):
        return 0.0, 0.0, 0.0

    def _sup_clear(self):
        pass

    # the servo cycle, as kernel/servo_cycle.py orders it: events, interpolate, couple
    def cycle(self):
        ctl = self.ctl
        t = ctl.time = round(ctl.time + DT, 9)
        if self._timers.get("phase", math.inf) <= t + 1e-9:
            self.follower.on_phase_timer(t)
        b = ctl.bank
        b.sp_p[0], b.sp_v[0], b.sp_a[0] = ctl.leader.at(t)
        b.sp_p[1], b.sp_v[1], b.sp_a[1] = self.profile.at(t)
        ctl.sync.run(t)
        ctl._bank_time = t

    def run(self, seconds):
        for _ in range(round(seconds / DT)):
            self.cycle()

    def position(self):
        return float(self.ctl.bank.sp_p[1])


def gear_in_pos(host, ratio=2.0, master_sync=20.0, slave_sync=0.0, distance=10.0):
    """MC_GearInPos, SyncProfileReference 1: synchronize in advance over MasterStartDistance (§4.3.3)."""
    job = Job(JobKind.GEAR_IN_POS, extra={"master": host.ctl.leader, "ratio": ratio, "master_sync": master_sync,
                                          "slave_sync": slave_sync, "spr": 1, "start_distance": distance,
                                          "sync_direction": 3})
    host.follower.submit(job)
    return job


def test_kernel_follower_gearing_ratio_two_doubles_the_leading_value_increments():
    """S7-1500T V5 §4.2, §4.3.3: GearInPos waits until the leading value reaches MasterSyncPosition minus
    MasterStartDistance (here 10, at t = 1 s), is synchronous at MasterSyncPosition (20, t = 2 s), and then
    follows SlaveSyncPosition + ratio x (leading value - MasterSyncPosition)."""
    host = FakeHost()
    job = gear_in_pos(host)
    f = host.follower
    assert job.busy and f.waiting is not None and f.coupling is None and f.waiting_function_state() == 2
    host.run(0.9)
    assert not job.start_sync and host.position() == 0.0          # waiting: the law does not act yet
    host.run(0.2)
    assert job.start_sync and f.synchronizing and not job.in_sync and f.function_state() == 2
    host.run(1.0)                                                  # t = 2.1 s: past MasterSyncPosition
    assert job.in_sync and f.synchronous and job.busy
    before_x, before_y = float(host.ctl.bank.sp_p[0]), host.position()
    for _ in range(100):
        host.cycle()
        x, y = float(host.ctl.bank.sp_p[0]), host.position()
        assert y - before_y == pytest.approx(2.0 * (x - before_x), abs=1e-9)
        assert y == pytest.approx(0.0 + 2.0 * (x - 20.0), abs=1e-9)
        before_x, before_y = x, y
    assert float(host.ctl.bank.sp_v[1]) == pytest.approx(2.0 * SPEED)
    assert f.effective_leading_value() == pytest.approx(host.ctl.leader.at(host.now))


def test_kernel_follower_phasing_shift_is_covered_completely():
    """S7-1500T V5 §4.5: a phase shift moves the leading value of the gearing by PhaseShift; at its end the
    whole shift is covered and the following value is ratio x (leading value + shift - MasterSyncPosition)."""
    host = FakeHost()
    gear_in_pos(host)
    host.run(2.1)
    f = host.follower
    assert f.synchronous
    shift = 5.0
    phasing = Job(JobKind.PHASING, velocity=20.0, acceleration=200.0, deceleration=200.0, jerk=4000.0,
                  extra={"master": host.ctl.leader, "shift": shift, "absolute": False})
    host.follower.submit(phasing)
    assert phasing.busy and f.phasing_job is phasing
    host.run(1.0)                                # 5 units at 20/s: well under a second
    assert phasing.state == JobState.DONE
    assert f.covered_phase_shift(phasing) == pytest.approx(shift, abs=1e-9)
    assert f.phase_shift() == pytest.approx(shift, abs=1e-9)
    x = float(host.ctl.bank.sp_p[0])
    assert host.position() == pytest.approx(2.0 * (x + shift - 20.0), abs=1e-9)
    assert float(host.ctl.bank.sp_v[1]) == pytest.approx(2.0 * SPEED)     # shift done: no extra velocity


def test_kernel_follower_phasing_needs_a_synchronous_gearing():
    """S7-1500T V5 §4.5: phasing acts on a gearing that is synchronous; otherwise the job is rejected."""
    host = FakeHost()
    phasing = Job(JobKind.PHASING, velocity=20.0, acceleration=200.0, deceleration=200.0,
                  extra={"master": host.ctl.leader, "shift": 1.0, "absolute": False})
    host.follower.submit(phasing)
    assert phasing.state == JobState.ERROR and phasing.fault.kind == F.NOT_SYNCHRONOUS


def test_kernel_follower_rejects_a_leading_value_it_is_not_configured_for():
    """S7-1500T V5 §6.1.3: only a configured leading value interconnection can be coupled to."""
    host = FakeHost(leading_values=())
    job = gear_in_pos(host)
    assert job.state == JobState.ERROR and job.fault.kind == F.SYNC_MASTER
    assert [a.kind for a in host.alarms] == [F.SYNC_MASTER]
    assert host.follower.coupling is None and host.follower.waiting is None


def test_kernel_follower_aborted_coupling_goes_on_with_its_velocity():
    """An aborted synchronous operation hands the axis over in motion (S7-1500T V5 §9.3.2): the axis
    carries on from the coupled position with the coupled velocity (2 x 10 units/s) until a job brakes it."""
    host = FakeHost()
    job = gear_in_pos(host)
    host.run(2.1)
    p0 = host.position()
    host.follower.abort(host.now)
    assert job.state == JobState.ABORTED and not job.in_sync and host.follower.coupling is None
    assert host.ctl.sync.couplings == []
    host.run(0.1)
    assert host.position() == pytest.approx(p0 + 2.0 * SPEED * 0.1, abs=1e-9)


# --- through a controller's synchronous axis -------------------------------------------------------------
VIRTUAL = {"VirtualAxis.Mode": 1}


def test_kernel_follower_gear_in_on_a_controller_axis():
    """S7-1500T V5 §4.1: MC_GearIn synchronizes over time and then the following axis moves with ratio x the
    leading axis's velocity; a controller's synchronous axis owns the ability as its ``follower``."""
    ctl = Controller(family="S7-1500T")
    leader = ctl.add_positioning_axis("Leader", VIRTUAL)
    slave = ctl.add_synchronous_axis("Slave", VIRTUAL, leading_values=["Leader"])
    assert isinstance(slave.follower, Follower) and leader.follower is None
    assert type(slave).__bases__ == (type(leader),)        # a plain subclass of the positioning axis
    for ax in (leader, slave):
        assert ax.power(object(), True, 1, 0) is None
    ctl.run(0.05)
    assert leader.state == slave.state == "enabled"
    leader.submit(Job(JobKind.VELOCITY, velocity=SPEED, acceleration=100.0, deceleration=100.0, jerk=math.inf))
    ctl.run(0.5)
    gear = Job(JobKind.GEAR_IN, acceleration=100.0, deceleration=100.0, jerk=math.inf,
               extra={"master": leader, "ratio": 2.0})
    slave.follower.submit(gear)
    assert gear.busy and slave.follower.coupling is not None and slave.follower.function_state() == 1
    ctl.run(1.0)
    assert gear.in_sync and gear.busy
    b = ctl.bank
    x0, y0 = float(b.sp_p[leader.index]), float(b.sp_p[slave.index])
    ctl.run(0.2)
    dx, dy = float(b.sp_p[leader.index]) - x0, float(b.sp_p[slave.index]) - y0
    assert dx == pytest.approx(SPEED * 0.2, rel=1e-9) and dy == pytest.approx(2.0 * dx, rel=1e-9)
    assert float(b.sp_v[slave.index]) == pytest.approx(2.0 * SPEED, rel=1e-9)
    # a motion job of the following axis aborts the gearing (§9.3.2) and the axis is free again
    slave.submit(Job(JobKind.VELOCITY, velocity=0.0, acceleration=100.0, deceleration=100.0, jerk=math.inf))
    assert gear.state == JobState.ABORTED and slave.follower.coupling is None
    ctl.run(0.5)
    assert float(b.sp_v[slave.index]) == pytest.approx(0.0, abs=1e-9)
