"""The reference point approach (``kernel.reference_approach.ApproachHoming``) on a kernel Controller axis
with a simulated servo drive, a reference cam and encoder zero marks; no instruction is used.

Expected values come from the machine geometry and from the sequences of S7-Technology V4.1 §4.5.10
(active homing: cam then the first zero mark before or after it, zero mark only, external zero mark only;
the homing event sets ``Position - offset``, then the axis travels to ``Position`` at the entry velocity;
distance monitoring cancels the approach; passive homing in a configured direction; §4.5.10.6 corrections
keep the homed state; §6.2.2 the transfer of the superimposed coordinate system).
"""
from __future__ import annotations

from dataclasses import replace
from typing import Any

import pytest

from plcmotion import Controller
from plcmotion.kernel import faults as F
from plcmotion.kernel import family as families
from plcmotion.kernel.axis import PositioningAxis
from plcmotion.kernel.axis_config import ReferenceApproach
from plcmotion.kernel.jobs import Job, JobKind, JobState
from plcmotion.kernel.reference_approach import TRANSFER_MOMENTS, ApproachHoming

from ._schema_axis import with_schema

SWITCH = "I0.0"
CAM_LO, CAM_HI = 100.0, 120.0              # machine positions of the reference cam's ends
ZM_DIST, ZM_OFF = 10.0, 5.0                # encoder zero marks at ..., 95, 105, 115, 125, ...
V_APP, V_RED, V_ENTRY = 50.0, 5.0, 20.0
ACC = 200.0
DT = 0.001


class ApproachAxis(PositioningAxis):
    homing_class = ApproachHoming


PARAMS = {"Actor.Type": 1, "DynamicLimits.MaxVelocity": 100.0,
          "DynamicDefaults.Acceleration": ACC, "DynamicDefaults.Deceleration": ACC,
          "DynamicDefaults.EmergencyDeceleration": 1000.0, "DynamicDefaults.Jerk": 0.0,
          "Homing.ApproachVelocity": V_APP, "Homing.ReferencingVelocity": V_RED,
          "Homing.ApproachDirection": True, "Homing.AutoReversal": False,
          "Sensor[1].ActiveHoming.DigitalInputAddress": SWITCH, "Sensor[1].ActiveHoming.SideInput": False,
          "Sensor[1].ActiveHoming.SwitchLevel": True,
          "Sensor[1].PassiveHoming.DigitalInputAddress": SWITCH, "Sensor[1].PassiveHoming.SideInput": False,
          "Plant.HomingSwitchPosition": CAM_LO, "Plant.HomingSwitchLength": CAM_HI - CAM_LO,
          "Plant.ZeroMarkDistance": ZM_DIST, "Plant.ZeroMarkOffset": ZM_OFF}


@pytest.fixture(scope="module")
def family():
    axis_class = with_schema(ApproachAxis, PARAMS)
    fam = families.register(families.Family(
        "Kernel-Approach-Homing", versions=(1,), default_version=1,
        factories={families.POSITIONING_AXIS: lambda ctl, name, flat, where: ctl.new_axis(axis_class, name, flat,
                                                                                        where)}))
    yield fam.name
    families._REGISTRY.pop(fam.name)


def _axis(family: str, *, active: int = 1, passive: int = 1, offset: float = 0.0, start: float = 0.0,
          positive: bool = True, **approach: Any):
    """An enabled axis at machine ``start``; homing methods (0 zero mark, 1 cam + zero mark, 2 external
    mark on the cam input) and the approach settings given."""
    ctl = Controller(family=family, servo_cycle=DT, input_filter=0.0)
    params = dict(PARAMS, **{"Plant.InitialPosition": start, "Homing.ApproachDirection": positive})
    axis = ctl.add_positioning_axis("Axis_1", params)
    h = axis.config.homing
    settings = ReferenceApproach(**dict({"entry_velocity": V_ENTRY}, **approach))
    axis.config = replace(axis.config, homing=replace(
        h, approach=settings, active=replace(h.active, mode=active, home_offset=offset),
        passive=replace(h.passive, mode=passive)))
    assert axis.power(object(), True, 1, 0) is None
    ctl.run_until(lambda: axis.state == "enabled", 5.0)
    return ctl, axis


def _pos(ctl, axis) -> float:
    return float(ctl.bank.act_p[axis.index])


def _home(ctl, axis, position: float = 0.0) -> Job:
    job = Job(JobKind.HOME_ACTIVE, position=position, mode=3)
    axis.home(job)
    ctl.run_until(lambda: not job.busy, 60.0)
    ctl.run(0.5)
    return job


@pytest.mark.parametrize("after, mark", [(True, 125.0), (False, 95.0)])
def test_kernel_reference_approach_cam_and_zero_mark(family, after, mark):
    """S7-Technology V4.1 §4.5.10.2 "reference cam and encoder zero mark", positive start: the cam at
    machine 100 is found at the approach velocity; the zero mark *after* the cam is the first one after
    leaving it forwards (125), the one *before* it the first one after leaving it backwards (95).  The
    mark gets Position (offset 0); the axis then travels back to it: it stands at the mark, homed."""
    ctl, axis = _axis(family, zero_mark_after_cam=after)
    job = _home(ctl, axis, 0.0)
    assert job.state == JobState.DONE and axis.homed
    assert axis.drive.mechanical_position() == pytest.approx(mark, abs=0.01)
    assert _pos(ctl, axis) == pytest.approx(0.0, abs=0.01)
    assert job.reference_position == 0.0


def test_kernel_reference_approach_offset_travel_at_entry_velocity(family):
    """S7-Technology V4.1 §4.5.10.2: the zero mark (machine 125) gets Position - offset = 10 - 3 = 7, the
    axis travels the offset to Position 10 (machine 128) at no more than the entry velocity; HomingDone is
    set at the zero mark already, before the travel has ended."""
    ctl, axis = _axis(family, offset=3.0)
    job = Job(JobKind.HOME_ACTIVE, position=10.0, mode=3)
    axis.home(job)
    ctl.run_until(lambda: job.extra.get("phase") == "offset", 60.0)
    assert axis.homed and job.busy
    top = 0.0
    while job.busy:
        ctl.run(DT)
        top = max(top, abs(float(ctl.bank.sp_v[axis.index])))
    ctl.run(0.5)
    assert job.state == JobState.DONE
    assert top <= V_ENTRY + 1e-9
    assert axis.drive.mechanical_position() == pytest.approx(128.0, abs=0.01)
    assert _pos(ctl, axis) == pytest.approx(10.0, abs=0.01)
    assert job.reference_position == pytest.approx(7.0)


def test_kernel_reference_approach_zero_mark_only(family):
    """S7-Technology V4.1 §4.5.10.2 "encoder zero mark only": at the shutdown velocity to the first zero
    mark in the start direction; negative start from machine 12 finds the mark at 5."""
    ctl, axis = _axis(family, active=0, start=12.0, positive=False)
    top = 0.0
    job = Job(JobKind.HOME_ACTIVE, position=50.0, mode=3)
    axis.home(job)
    while job.busy:
        ctl.run(DT)
        top = max(top, abs(float(ctl.bank.sp_v[axis.index])))
    ctl.run(0.5)
    assert job.state == JobState.DONE and top <= max(V_RED, V_ENTRY) + 1e-9
    assert axis.drive.mechanical_position() == pytest.approx(5.0, abs=0.01)
    assert _pos(ctl, axis) == pytest.approx(50.0, abs=0.01)


@pytest.mark.parametrize("rising, edge", [(True, CAM_LO), (False, CAM_HI)])
def test_kernel_reference_approach_external_zero_mark(family, rising, edge):
    """S7-Technology V4.1 §4.5.10.2 "external zero mark only": the configured signal transition of the
    external mark (here the cam input: rising at machine 100, falling at 120) homes the axis; it then
    stands at Position, one servo cycle of approach travel from the edge at most."""
    ctl, axis = _axis(family, active=2, external_rising=rising)
    job = _home(ctl, axis, 0.0)
    assert job.state == JobState.DONE and axis.homed
    assert edge - 0.01 <= axis.drive.mechanical_position() <= edge + V_APP * DT + 0.01
    assert _pos(ctl, axis) == pytest.approx(0.0, abs=0.01)


def test_kernel_reference_approach_cam_distance_monitoring(family):
    """S7-Technology V4.1 §4.5.10.2 "maximum distance to reference cam": the cam at machine 100 is not within
    60 of the start at 0: the approach ends with reference_not_found/distance (801D); the axis brakes."""
    ctl, axis = _axis(family, cam_distance=60.0)
    job = Job(JobKind.HOME_ACTIVE, position=0.0, mode=3)
    axis.home(job)
    ctl.run_until(lambda: not job.busy, 60.0)
    assert job.state == JobState.ERROR
    assert (job.fault.kind, job.fault.detail) == (F.REFERENCE_NOT_FOUND, "distance")
    assert job.fault.reaction.value == "stop"
    ctl.run(1.0)
    assert not axis.homed and float(ctl.bank.act_v[axis.index]) == pytest.approx(0.0, abs=1e-3)
    assert 60.0 <= axis.drive.mechanical_position() <= 60.0 + V_APP ** 2 / (2 * ACC) + V_APP * DT + 0.1


def test_kernel_reference_approach_zero_mark_distance_monitoring(family):
    """S7-Technology V4.1 §4.5.10.2 "maximum distance to encoder zero mark": from the cam (machine 100) the
    mark after it (125) lies 25 away, more than the 15 allowed: 801D, no homing."""
    ctl, axis = _axis(family, zero_mark_distance=15.0)
    job = Job(JobKind.HOME_ACTIVE, position=0.0, mode=3)
    axis.home(job)
    ctl.run_until(lambda: not job.busy, 60.0)
    assert job.state == JobState.ERROR and job.fault.detail == "distance" and not axis.homed
    assert axis.drive.mechanical_position() < 125.0


@pytest.mark.parametrize("direction, homes", [(0, True), (1, True), (-1, False)])
def test_kernel_reference_approach_passive_direction(family, direction, homes):
    """S7-Technology V4.1 §4.5.10.3 passive "reference cam and encoder zero mark": a relative move of 200
    from 0 passes the cam (100..120); the next zero mark after it (125) gets Position 0, so the move ends at
    200 - 125 = 75 (§4.5.10.4: the move keeps its distance).  With direction "negative only" the positive
    pass does not home."""
    ctl, axis = _axis(family, passive_direction=direction)
    home = Job(JobKind.HOME_PASSIVE, position=0.0, mode=2)
    axis.home(home)
    move = Job(JobKind.RELATIVE, position=200.0, velocity=V_APP)
    axis.submit(move)
    ctl.run_until(lambda: not move.busy, 30.0)
    ctl.run(1.0)
    assert axis.drive.mechanical_position() == pytest.approx(200.0, abs=0.01)
    if homes:
        assert home.state == JobState.DONE and axis.homed
        assert _pos(ctl, axis) == pytest.approx(75.0, abs=0.01)
    else:
        assert home.busy and not axis.homed
        assert axis.homing.cancel_passive() and home.state == JobState.ABORTED
        assert not axis.homing.cancel_passive()


def test_kernel_reference_approach_passive_distance_monitor_stops_the_motion(family):
    """S7-Technology V4.1 §4.5.10.3: a passive homing monitor that trips ends the homing with an error
    (801D) and terminates the axis's motion; a move of 200 stops short of it."""
    ctl, axis = _axis(family, cam_distance=50.0)
    home = Job(JobKind.HOME_PASSIVE, position=0.0, mode=2)
    axis.home(home)
    move = Job(JobKind.RELATIVE, position=200.0, velocity=V_APP)
    axis.submit(move)
    ctl.run_until(lambda: not move.busy, 30.0)
    ctl.run(1.0)
    assert home.state == JobState.ERROR and home.fault.detail == "distance"
    assert move.state == JobState.ERROR
    assert 50.0 <= axis.drive.mechanical_position() < 60.0 + 1.0


@pytest.mark.parametrize("layer", ["actual", "base", "superimposed"])
def test_kernel_reference_approach_corrections_keep_the_homed_state(family, layer):
    """S7-Technology V4.1 §4.5.10.6: a correction by Position gives (current position) - Position and
    leaves the homed state as it was; nothing moves."""
    ctl, axis = _axis(family)
    axis.homing.set_position(Job(JobKind.HOME_DIRECT, position=100.0))
    assert axis.homed
    ctl.run(0.1)
    mech = axis.drive.mechanical_position()
    job = Job(JobKind.HOME_DIRECT, position=30.0)
    axis.homing.correct(job, layer)
    ctl.run(0.2)
    assert job.state == JobState.DONE and axis.homed
    assert _pos(ctl, axis) == pytest.approx(70.0, abs=0.01)
    assert axis.drive.mechanical_position() == pytest.approx(mech, abs=1e-3)
    assert axis.homing.superimposed_offset == (-30.0 if layer == "superimposed" else 0.0)
    with pytest.raises(ValueError):
        axis.homing.correct(Job(JobKind.HOME_DIRECT), "tool")


# S7-Technology V4.1 §6.2.2 notes on Mode 7: when each transferSuperimposed setting transfers
TRANSFER_TABLE = [
    ("standstill", {"standstill": True, "override": True, "following": True, "restart": True}),
    ("merge", {"standstill": False, "override": True, "following": True, "restart": True}),
    ("reset", {"standstill": False, "override": False, "following": True, "restart": True}),
]


@pytest.mark.parametrize("mode, moments", TRANSFER_TABLE)
def test_kernel_reference_approach_transfer_of_superimposed_corrections(family, mode, moments):
    """S7-Technology V4.1 §6.2.2 (TypeOfAxis.DecodingConfig.transferSuperimposed): a Mode-7 correction goes
    over to the basic coordinates at the moments its setting names, and only then; the position stays."""
    assert set(TRANSFER_MOMENTS[mode]) == {m for m, yes in moments.items() if yes}
    for moment, yes in moments.items():
        ctl, axis = _axis(family, transfer_superimposed=mode)
        axis.homing.correct(Job(JobKind.HOME_DIRECT, position=5.0), "superimposed")
        before = _pos(ctl, axis)
        assert axis.homing.transfer_superimposed(moment) is yes
        assert axis.homing.superimposed_offset == (0.0 if yes else -5.0)
        assert _pos(ctl, axis) == before


@pytest.mark.parametrize("required", [True, False])
def test_kernel_reference_approach_homing_required(family, required):
    """S7-Technology V4.1 §4.5.10.7 "Homing required": Yes - an absolute positioning of an axis that is not
    homed is refused and its software limit switches are not in force; No - it runs, and they are."""
    ctl, axis = _axis(family)
    h = axis.config.homing
    axis.config = replace(axis.config, homing=replace(h, required=required),
                          software_limits=replace(axis.config.software_limits, enabled=True))
    job = Job(JobKind.ABSOLUTE, position=10.0, velocity=V_APP)
    axis.submit(job)
    assert not axis.homed
    if required:
        assert job.state == JobState.ERROR and job.fault.kind == F.NOT_HOMED
        assert not axis.sw_limits_effective()
    else:
        ctl.run_until(lambda: not job.busy, 10.0)
        assert job.state == JobState.DONE and axis.sw_limits_effective()
        ctl.run(1.0)                                      # the position loop settles on the target
        assert _pos(ctl, axis) == pytest.approx(10.0, abs=0.01)
