"""The homing component (``kernel.homing.Homing``) alone on a fake axis, and on a kernel Controller axis.

No instruction (dialect) is used: jobs go to the component or the axis directly.  Expected values come from
S7-1200 Motion Control V6 §11.1.3 (MC_Home Mode 0: the current position becomes ``Position``; Mode 1: the
current position is shifted by ``Position``) and §5.4.4.5 (passive homing: no motion of its own, homed
when the configured side of the homing switch is reached in the homing direction; at standstill the next
edge homes the axis; active homing: search at the approach velocity, then the configured side at the
homing velocity, StatusBits.HomingDone FALSE in between), and the project conventions on the side of the
switch (docs/decisions.md #31-#34: the lower side crossed in the positive direction is the entry edge; the
homing event's position is accurate to one servo cycle of travel).
"""
from __future__ import annotations

from types import SimpleNamespace
from typing import Any

import pytest

from plcmotion import Controller
from plcmotion.kernel.axis_config import DynamicLimits, Homing as HomingConfig, HomingMethod, Modulo, \
    StandstillMonitoring
from plcmotion.kernel.bank import AxisBank
from plcmotion.kernel.homing import Homing, HomingAxis
from plcmotion.kernel.jobs import Job, JobKind, JobState
from plcmotion.kernel.profiles import Planner

SWITCH = "I0.0"


# --- (a) the component alone on a fake axis -----------------------------------------------------------------
class FakeDrive:
    """The drive channel as homing uses it: set the actual value, latch zero marks."""

    def __init__(self, axis: "FakeAxis"):
        self.axis = axis
        self.armed: float | None = None

    def set_actual(self, bank: AxisBank, p: float) -> None:
        bank.act_p[self.axis.index] = p

    def mechanical_position(self) -> float:
        return float(self.axis.ctl.bank.act_p[self.axis.index])

    def arm_zero_mark(self, d: float) -> None:
        self.armed = d

    def disarm_zero_mark(self) -> None:
        self.armed = None

    def zero_mark_latched(self) -> float | None:
        return None


class FakeAxis:
    """An enabled servo axis at ``position`` with a homing switch on input I0.0 (positive homing direction,
    lower side of the switch), implementing ``HomingAxis``."""

    pto = sim = False
    servo = True
    position_controlled = True

    def __init__(self, position: float = 37.5, *, modulo: Modulo = Modulo()):
        self.ctl = SimpleNamespace(bank=AxisBank(), inputs={SWITCH: False}, rules=frozenset(), _input_axes=[],
                                   _retain_axis=lambda axis: None)
        self.index = self.ctl.bank.add()
        self.ctl.bank.sp_p[self.index] = self.ctl.bank.act_p[self.index] = position
        method = HomingMethod(mode=2, input=SWITCH, active_high=True, upper_side=False)
        self.config = SimpleNamespace(
            homing=HomingConfig(approach_positive=True, active=method, passive=method), modulo=modulo,
            limits=DynamicLimits(), standstill=StandstillMonitoring(velocity_threshold=1.0),
            drive=SimpleNamespace(encoder=SimpleNamespace(absolute=False, interface=None, increment=1e-6)))
        self.drive = FakeDrive(self)
        self.motion: Any = None
        self.profile = Planner.hold(0.0, position)
        self.job: Job | None = None
        self.state = "enabled"
        self.homed = False
        self.abs_offset = 0.0
        self.alarms: list = []
        self._interpolating = False
        self.replans = 0
        self.homing = Homing(self)

    now = 0.0
    sensor_valid = True

    def commanded_velocity(self, velocity: float) -> float:
        return velocity

    def position_resolution(self) -> float:
        return 1e-6

    def sw_limits_effective(self) -> bool:
        return False

    def _wrap(self, value: float) -> float:
        m = self.config.modulo
        return (value - m.start) % m.length + m.start if m.enabled else value

    def _replan(self) -> None:
        self.replans += 1

    def _finish_job(self, job: Job, state: JobState, t: float, fault=None) -> None:
        job.finish(state, fault)

    def _blocking_alarm(self):
        return None

    # the motion part of the host (active homing) is not used by these tests
    def _state_now(self): raise AssertionError("no motion expected")
    def _state_at(self, t): raise AssertionError("no motion expected")
    def _start_profile(self, profile, plan=None): raise AssertionError("no motion expected")
    def _start_positioning_monitor(self, job, t): raise AssertionError("no motion expected")
    def _apply_dirty(self, moment): raise AssertionError("a servo axis applies tags at once")
    def raise_alarm(self, fault, job=None): raise AssertionError(f"unexpected alarm {fault}")
    def submit(self, job): raise AssertionError("no motion expected")

    # what a servo cycle would do: move the load and read the switch
    def moving(self, velocity: float) -> None:
        self.ctl.bank.act_v[self.index] = self.ctl.bank.sp_v[self.index] = velocity

    def switch(self, on: bool) -> None:
        self.ctl.inputs[SWITCH] = on
        self.homing.check_inputs(self.now)

    @property
    def position(self) -> float:
        return float(self.ctl.bank.act_p[self.index])


def _typed(axis: HomingAxis) -> HomingAxis:
    return axis                      # the fake is a HomingAxis (checked by a type checker, not at run time)


@pytest.mark.parametrize("mode, position, expected", [(0, 100.0, 100.0), (0, -12.5, -12.5),
                                                      (1, 10.0, 47.5), (1, -40.0, -2.5)])
def test_kernel_homing_direct_sets_the_actual_position(mode, position, expected):
    """S7-1200 V6 §11.1.3 MC_Home Mode 0: the actual position becomes Position; Mode 1: it moves by
    Position.  The setpoint and the profile move with it (no jump of the following error)."""
    axis = FakeAxis(37.5)
    homing = _typed(axis).homing
    job = Job(JobKind.HOME_DIRECT, position=position, mode=mode)
    homing.home_direct(job)
    b = axis.ctl.bank
    assert job.state == JobState.DONE and axis.homed
    assert axis.position == pytest.approx(expected) and b.sp_p[axis.index] == pytest.approx(expected)
    assert axis.profile.at(0.0)[0] == pytest.approx(expected)
    assert job.reference_position == pytest.approx(expected) == homing.reference_mark
    assert axis.replans == 1                                  # the running motion is planned in the new frame


def test_kernel_homing_direct_on_a_modulo_axis_wraps_the_position():
    """A modulo axis counts in [start, start + length): Mode 0 with Position 370 on 0..360 gives 10."""
    axis = FakeAxis(90.0, modulo=Modulo(enabled=True, start=0.0, length=360.0))
    job = Job(JobKind.HOME_DIRECT, position=370.0, mode=0)
    axis.homing.home_direct(job)
    assert axis.position == pytest.approx(10.0) and job.reference_position == pytest.approx(10.0)


def test_kernel_homing_direct_needs_an_enabled_axis():
    """S7-1200 V6 §12.8 16#8001: MC_Home on a disabled axis is rejected; nothing moves."""
    axis = FakeAxis(37.5)
    axis.state = "disabled"
    job = Job(JobKind.HOME_DIRECT, position=0.0, mode=0)
    axis.homing.home_direct(job)
    assert job.state == JobState.ERROR and not axis.homed and axis.position == 37.5


def test_kernel_homing_passive_arms_and_fires_on_the_switch_edge():
    """S7-1200 V6 §5.4.4.5: passive homing starts no motion; moving in the homing direction (positive),
    reaching the lower side of the switch (its rising edge) homes the axis: that position becomes Position."""
    axis = FakeAxis(80.0)
    job = Job(JobKind.HOME_PASSIVE, position=0.0, mode=2)
    axis.homing.home(job)
    assert job.busy and axis.homing.passive is job and axis.homing.passive_busy and not axis.homed
    assert axis.position == 80.0                              # no motion of its own
    axis.moving(10.0)
    axis.ctl.bank.act_p[axis.index] = 100.0                   # the load reaches the switch at 100
    axis.switch(True)
    assert job.state == JobState.DONE and axis.homed and axis.homing.passive is None
    assert axis.position == pytest.approx(0.0) and job.reference_position == 0.0


def test_kernel_homing_passive_ignores_edges_against_the_homing_direction():
    """S7-1200 V6 §5.4.4.5: the configured side counts only when reached in the homing direction."""
    axis = FakeAxis(130.0)
    job = Job(JobKind.HOME_PASSIVE, position=0.0, mode=2)
    axis.homing.home(job)
    axis.moving(-10.0)
    axis.switch(True)                                         # enters the switch from above: upper side
    axis.switch(False)                                        # leaves it at the lower side, moving negative
    assert job.busy and not axis.homed and axis.position == 130.0
    axis.moving(10.0)
    axis.switch(True)                                         # the lower side in the positive direction
    assert job.state == JobState.DONE and axis.position == pytest.approx(0.0)


@pytest.mark.parametrize("level", [True, False])
def test_kernel_homing_passive_at_standstill_homes_on_the_next_edge(level):
    """S7-1200 V6 §5.4.4.5 note: without a motion the next rising or falling edge of the switch homes."""
    axis = FakeAxis(55.0)
    axis.ctl.inputs[SWITCH] = not level
    job = Job(JobKind.HOME_PASSIVE, position=5.0, mode=2)
    axis.homing.home(job)
    axis.switch(level)
    assert job.state == JobState.DONE and axis.position == pytest.approx(5.0)


def test_kernel_homing_end_passive_aborts_the_armed_job():
    """Another job that aborts passive homing (S7-1500T V5 §9.3.1 table, an alarm) ends it; the switch
    then homes nothing."""
    axis = FakeAxis(80.0)
    job = Job(JobKind.HOME_PASSIVE, position=0.0, mode=2)
    axis.homing.home(job)
    axis.homing.end_passive(JobState.ABORTED)
    assert job.state == JobState.ABORTED and axis.homing.passive is None
    axis.moving(10.0)
    axis.switch(True)
    assert not axis.homed and axis.position == 80.0


# --- (b) through a kernel Controller axis -------------------------------------------------------------------
CAM_LO, CAM_HI = 100.0, 120.0          # machine positions of the ends of the homing switch
V_APP, V_REF = 50.0, 5.0
DT = 0.001


def _axis(**homing: Any):
    ctl = Controller(servo_cycle=DT, input_filter=0.0)      # no filter delay: one servo cycle of accuracy
    params = {"Actor.Type": 1, "DynamicLimits.MaxVelocity": 100.0,
              "DynamicDefaults.Acceleration": 200.0, "DynamicDefaults.Deceleration": 200.0,
              "DynamicDefaults.EmergencyDeceleration": 1000.0, "DynamicDefaults.Jerk": 0.0,
              "Homing.ApproachVelocity": V_APP, "Homing.ReferencingVelocity": V_REF,
              "Homing.ApproachDirection": True, "Homing.AutoReversal": False,
              "Sensor[1].ActiveHoming.DigitalInputAddress": SWITCH, "Sensor[1].ActiveHoming.SideInput": False,
              "Sensor[1].ActiveHoming.SwitchLevel": True, "Sensor[1].ActiveHoming.HomePositionOffset": 0.0,
              "Sensor[1].PassiveHoming.DigitalInputAddress": SWITCH, "Sensor[1].PassiveHoming.SideInput": False,
              "Plant.HomingSwitchPosition": CAM_LO, "Plant.HomingSwitchLength": CAM_HI - CAM_LO}
    params.update(homing)
    axis = ctl.add_positioning_axis("Axis_1", params)
    assert axis.power(object(), True, 1, 0) is None
    ctl.run_until(lambda: axis.state == "enabled", 5.0)
    return ctl, axis


def _position(ctl, axis) -> float:
    return float(ctl.bank.act_p[axis.index])


def test_kernel_homing_is_a_component_of_the_controller_axis():
    """The axis owns its homing; the armed passive job lives there, not on the axis."""
    ctl, axis = _axis()
    assert isinstance(axis.homing, Homing) and axis.homing.axis is axis
    assert "passive_home" not in vars(axis) and "reference_mark" not in vars(axis)
    assert axis.homing_configured(2) and axis.homing_configured(3)


def test_kernel_homing_direct_through_the_axis():
    """S7-1200 V6 §11.1.3 Mode 0 then Mode 1 on an enabled drive axis standing at 0."""
    ctl, axis = _axis()
    job = Job(JobKind.HOME_DIRECT, position=250.0, mode=0)
    axis.home_direct(job)
    assert job.state == JobState.DONE and axis.homed
    ctl.run(0.05)
    assert _position(ctl, axis) == pytest.approx(250.0, abs=1e-6)
    job = Job(JobKind.HOME_DIRECT, position=-20.0, mode=1)
    axis.home_direct(job)
    ctl.run(0.05)
    assert job.state == JobState.DONE and _position(ctl, axis) == pytest.approx(230.0, abs=1e-6)


def test_kernel_homing_passive_during_a_relative_move():
    """S7-1200 V6 §5.4.4.5: MC_Home Mode 2 arms, a relative move (not aborted) carries the axis over the
    lower side of the switch at machine 100, which becomes Position 0: the move ends at machine 200, i.e.
    at 100 in the new coordinates, within one servo cycle of travel at the move's velocity."""
    ctl, axis = _axis()
    home = Job(JobKind.HOME_PASSIVE, position=0.0, mode=2)
    axis.home(home)
    move = Job(JobKind.RELATIVE, position=200.0, velocity=V_APP)
    axis.submit(move)
    assert home.busy and move.busy and axis.passive_home is home
    ctl.run_until(lambda: not move.busy, 30.0)
    assert home.state == JobState.DONE and move.state == JobState.DONE and axis.homed
    ctl.run(1.0)                                              # the position loop settles on the target
    mech = axis.drive.mechanical_position()
    assert mech == pytest.approx(200.0, abs=1e-3)
    # the edge is seen up to one servo cycle after the load passed machine 100
    assert mech - CAM_LO - V_APP * DT - 1e-6 <= _position(ctl, axis) <= mech - CAM_LO + 1e-6
    assert home.reference_position == 0.0 and axis.homing.passive is None


def test_kernel_homing_active_finds_the_lower_side_of_the_switch():
    """S7-1200 V6 §5.4.4.5 active homing (Mode 3): HomingDone is FALSE while it runs; the lower side of the
    switch (machine 100), crossed in the positive direction at the homing velocity, becomes Position 0; the
    axis stops behind it.  The axis watches its inputs every servo cycle while it homes."""
    ctl, axis = _axis()
    job = Job(JobKind.HOME_ACTIVE, position=0.0, mode=3)
    axis.home(job)
    assert job.busy and axis.job is job and not axis.homed and axis in ctl._input_axes
    ctl.run_until(lambda: not job.busy, 60.0)
    assert job.state == JobState.DONE and axis.homed
    mech = axis.drive.mechanical_position()
    assert CAM_LO <= mech <= CAM_LO + V_REF * V_REF / 200.0 + 0.05   # braked from V_REF behind the edge
    assert mech - CAM_LO - V_REF * DT - 1e-6 <= _position(ctl, axis) <= mech - CAM_LO + 1e-6
    assert job.reference_position == 0.0


def test_kernel_homing_active_aborts_passive_homing():
    """S7-1200 V6 §11.1.3 override: active homing aborts a running passive homing."""
    ctl, axis = _axis()
    passive = Job(JobKind.HOME_PASSIVE, position=0.0, mode=2)
    axis.home(passive)
    active = Job(JobKind.HOME_ACTIVE, position=0.0, mode=3)
    axis.home(active)
    assert passive.state == JobState.ABORTED and axis.homing.passive is None and active.busy


# --- an axis kind without homing ------------------------------------------------------------------------
def test_kernel_homing_an_axis_kind_without_homing_refuses_it_and_still_moves():
    """An axis kind that takes no homing part (``NoHoming``, e.g. a speed-controlled axis) refuses every
    homing request as a function it does not have (PLCopen: a function block the axis type does not
    support ends with an error and moves nothing), and its motion jobs run as on any axis."""
    from plcmotion.kernel import family as families
    from plcmotion.kernel import faults as F
    from plcmotion.kernel.axis import PositioningAxis
    from plcmotion.kernel.homing import NoHoming

    from ._schema_axis import with_schema

    class SpeedAxis(PositioningAxis):
        homing_class = NoHoming

    params = {"Actor.Type": 1, "DynamicLimits.MaxVelocity": 100.0, "DynamicDefaults.Acceleration": 200.0,
              "DynamicDefaults.Deceleration": 200.0, "DynamicDefaults.Jerk": 0.0}
    axis_class = with_schema(SpeedAxis, params)
    fam = families.register(families.Family(
        "Kernel-No-Homing", versions=(1,), default_version=1,
        factories={families.POSITIONING_AXIS: lambda ctl, name, flat, where: ctl.new_axis(axis_class, name, flat,
                                                                                        where)}))
    try:
        ctl = Controller(family=fam.name, servo_cycle=DT)
        axis = ctl.add_positioning_axis("Speed_1", params)
        assert isinstance(axis.homing, NoHoming) and not axis.homing_configured(3)
        assert axis.power(object(), True, 1, 0) is None
        ctl.run_until(lambda: axis.state == "enabled", 5.0)
        jobs = [Job(JobKind.HOME_DIRECT, position=5.0, mode=0), Job(JobKind.HOME_ACTIVE, mode=3),
                Job(JobKind.HOME_PASSIVE, mode=2)]
        axis.home_direct(jobs[0])
        axis.submit(jobs[1])
        axis.submit(jobs[2])
        for job in jobs:
            assert job.state == JobState.ERROR and job.fault.kind == F.NOT_AVAILABLE
        assert not axis.homed and axis.homing.passive is None
        move = Job(JobKind.VELOCITY, velocity=20.0)
        axis.submit(move)
        ctl.run(1.0)
        assert move.busy and float(ctl.bank.act_v[axis.index]) == pytest.approx(20.0, rel=1e-3)
        assert _position(ctl, axis) > 10.0
    finally:
        families._REGISTRY.pop(fam.name)
