"""A kernel Controller axis on the simulated hydraulic drive and on a servo drive against a fixed end stop
(S7-Technology V4.1 §3.1.4 hydraulic axes, §3.3.1 position control, §6.2.11 MC_MoveToEndPos).

The axis is the default family's positioning axis whose drive specification is replaced by a hydraulic one
(no instruction involved): the kernel's position controller closes the loop over the valve and cylinder.
"""
from __future__ import annotations

import copy
import dataclasses

import numpy as np
import pytest

from plcmotion.drives import (ActuatorKind, CylinderSpec, DriveSpec, EncoderSpec, HydraulicSpec, PlantSpec,
                              SetpointInterface, ValveCharacteristic, ValveType)
from plcmotion.kernel import Controller
from plcmotion.kernel import family as families
from plcmotion.kernel.jobs import Job, JobKind, JobState

FAMILY = "Drives-Hydraulic-Test"
PARAMS = {"Actor.Type": 1, "DynamicLimits.MaxVelocity": 300.0, "DynamicDefaults.Acceleration": 1000.0,
          "DynamicDefaults.Deceleration": 1000.0, "DynamicDefaults.Jerk": 0.0,
          "FollowingError": {"MaxValue": 1000.0, "MinValue": 1000.0}}
# the valve profile as measured on the simulated cylinder: 100 % extends at 531 mm/s, -100 % retracts at 376 mm/s
PROFILE = ValveCharacteristic(((-100.0, -375.7), (0.0, 0.0), (100.0, 531.4)))


def hydraulic_spec(plant: PlantSpec, *, valve: ValveType = ValveType.Q, stop: float | None = None) -> DriveSpec:
    return DriveSpec(actuator=ActuatorKind.HYDRAULIC, interface=SetpointInterface.ANALOG,
                     encoder=EncoderSpec(rotary=False, step_length=0.001, fine_bits=0),
                     hydraulic=HydraulicSpec(valve=valve, characteristic=PROFILE),
                     plant=dataclasses.replace(plant, cylinder=CylinderSpec(), end_stop_max=stop))


def axis_class(make_drive):
    """The default family's positioning axis with its drive specification replaced by ``make_drive(plant)``."""
    base = type(Controller().add_positioning_axis("probe", {"Actor.Type": 1}))
    schema = copy.copy(base.schema)
    build = base.schema.build

    def hydraulic_build(cfg):
        config = build(cfg)
        return dataclasses.replace(config, drive=make_drive(config.drive.plant))
    schema._build = hydraulic_build
    return type("HydraulicTestAxis", (base,), {"schema": schema})


@pytest.fixture(scope="module", autouse=True)
def hydraulic_families():
    """Two test families: a Q valve cylinder, and a P/Q valve cylinder with a fixed end stop at 250 mm."""
    made = []
    for name, make in ((FAMILY + "-Q", hydraulic_spec),
                       (FAMILY + "-PQ", lambda plant: hydraulic_spec(plant, valve=ValveType.PQ, stop=250.0))):
        cls = axis_class(make)

        def factory(ctl, axis_name, flat, where, cls=cls):
            return ctl.new_axis(cls, axis_name, flat, where)
        made.append(families.register(families.Family(name, versions=(1,), default_version=1,
                                                       factories={families.POSITIONING_AXIS: factory})))
    yield
    for fam in made:
        families._REGISTRY.pop(fam.name)


def enabled(valve: str = "Q", **control: float):
    """An enabled cylinder axis at 100 mm (machine position; its incremental encoder counts from 0 there)."""
    ctl = Controller(servo_cycle=0.001, app_cycle=0.004, family=f"{FAMILY}-{valve}")
    axis = ctl.add_positioning_axis("Cylinder", {**PARAMS, "Plant.InitialPosition": 100.0,
                                                 **{f"PositionControl.{k}": v for k, v in control.items()}})
    axis.power(object(), True, 1, 0)
    ctl.run(0.05)
    assert axis.state == "enabled"
    axis.homed = True
    return ctl, axis


def move(ctl, axis, target: float, seconds: float = 3.0) -> tuple[Job, float, float]:
    """Position to ``target``; (the job, how far the actual value went beyond the target, peak |output| [V])."""
    b, i = ctl.bank, axis.index
    up = target > float(b.act_p[i])
    job = Job(JobKind.ABSOLUTE, position=target, velocity=150.0)
    axis.submit(job)
    assert job.state == JobState.BUSY
    beyond, volts = -1e9, 0.0
    for _ in range(round(seconds / 0.001)):
        ctl.run(0.001)
        p = float(b.act_p[i])
        beyond = max(beyond, (p - target) if up else (target - p))
        volts = max(volts, abs(axis.drive.output_voltage))
    return job, beyond, volts


@pytest.mark.parametrize("target", [300.0, -60.0])
def test_drives_hydraulic_axis_p_controller_reaches_the_target_without_overshoot(target):
    """S7-Technology V4.1 §3.1.4, §3.3.1: a P position controller (no precontrol) drives the cylinder through
    the valve characteristic to the target, extending and retracting: the actual value approaches the
    target from one side (it never passes it) and ends in a 0.01 mm window, the output within +-10 V."""
    ctl, axis = enabled(Kpc=0.0)
    job, beyond, volts = move(ctl, axis, target)
    assert job.state == JobState.DONE
    assert beyond <= 0.0005                                  # half an encoder increment
    assert float(ctl.bank.act_p[axis.index]) == pytest.approx(target, abs=0.01)
    assert volts <= 10.0 and not axis.alarms


def test_drives_hydraulic_axis_with_precontrol_overshoot_stays_within_the_valve_lag():
    """S7-Technology V4.1 §3.3.1: with full speed precontrol and no balancing filter the valve's lag lets the
    piston run past the target by at most velocity x spool time constant (150 mm/s x 5 ms = 0.75 mm); the
    loop is stable and settles in the 0.01 mm window in both directions."""
    ctl, axis = enabled()
    for target in (300.0, 120.0):
        job, beyond, volts = move(ctl, axis, target)
        assert job.state == JobState.DONE
        assert beyond < 0.75
        assert float(ctl.bank.act_p[axis.index]) == pytest.approx(target, abs=0.01)
        assert volts <= 10.0
    assert not axis.alarms


def test_drives_hydraulic_axis_against_the_end_stop_following_error_grows_at_the_force_limit():
    """S7-Technology V4.1 §6.2.11: moving against a fixed end stop the actual position stays at the stop while
    the setpoint moves on, so the following error grows; the P/Q valve holds the force at its limit."""
    ctl, axis = enabled("PQ")
    axis.drive.set_torque_limit(4000.0)
    b, i = ctl.bank, axis.index
    stop = 250.0 - axis.drive.mechanical_position() + float(b.act_p[i])    # the stop in axis coordinates
    axis.submit(Job(JobKind.VELOCITY, velocity=50.0))
    ctl.run(3.5)                                           # 100 -> 250 mm at 50 mm/s, then against the stop
    errors = []
    for _ in range(5):
        ctl.run(0.2)
        errors.append(float(b.fe[i]))
        assert axis.drive.mechanical_position() == 250.0
        assert float(b.act_p[i]) == pytest.approx(stop, abs=0.001)
    assert list(np.diff(errors)) == pytest.approx([50.0 * 0.2] * 4, rel=1e-6)   # grows with the setpoint
    assert axis.drive.force == pytest.approx(4000.0) and axis.drive.torque_limit_active


def test_drives_servo_axis_against_the_end_stop_torque_at_the_limit():
    """S7-Technology V4.1 §6.2.11, §6.2.12: a servo axis of the default family with a fixed end stop in its
    plant parameters (``Plant.EndStopMaxPosition``): the load stops there, the following error grows with the
    setpoint and the drive's torque stands at the limit set at run time."""
    ctl = Controller(servo_cycle=0.001, app_cycle=0.004)
    axis = ctl.add_positioning_axis("Axis_1", {**PARAMS, "Plant.EndStopMaxPosition": 20.0})
    axis.power(object(), True, 1, 0)
    ctl.run(0.05)
    axis.drive.set_torque_limit(1.5)
    axis.submit(Job(JobKind.VELOCITY, velocity=10.0))
    ctl.run(2.5)
    b, i = ctl.bank, axis.index
    fe = float(b.fe[i])
    ctl.run(0.5)
    assert axis.drive.mechanical_position() == 20.0
    assert float(b.fe[i]) - fe == pytest.approx(10.0 * 0.5, rel=1e-6)
    assert axis.drive.torque == pytest.approx(1.5) and axis.drive.torque_limit_active
