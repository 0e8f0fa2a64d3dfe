"""Fixed end stops of the simulated machine and the drive's torque (force) limit, for electric servo drives
and hydraulic cylinders (S7-Technology V4.1 §6.2.11 MC_MoveToEndPos, §6.2.12 MC_SetTorqueLimit, §3.3.1
torque or pressure limiting).

The load stops at the end stop; the drive keeps pushing with the torque its speed loop asks for, capped by
its limit.  Expected values from the equations: servo torque = J 2 pi / lead * acceleration, with the
first-order speed loop's acceleration (c - v)(1 - e^(-dt/T)) / dt; a cylinder against a stop presses with
p_S A (or the P/Q valve's limit).
"""
from __future__ import annotations

import math
from dataclasses import replace

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from plcmotion.drives import (ActuatorKind, CylinderSpec, DriveSpec, DriveSpecError, EncoderSpec, HydraulicSpec,
                              PlantSpec, SetpointInterface, ValveType, new_drive_group)
from plcmotion.kernel.bank import AxisBank

DT = 0.001
TC = 0.002
J = 2.0e-3                                  # kg m²
JT = J * 2.0 * math.pi / 1.0                # N m per (length unit / s²) at 1 length unit per revolution
E = math.exp(-DT / TC)

# analog servo: 27648 = 1620 1/min, 1 length unit per revolution, so 10 units/s is the exact word 10240
SERVO = DriveSpec(actuator=ActuatorKind.SPEED_SERVO, interface=SetpointInterface.ANALOG, reference_speed=1620.0,
                  max_speed=1620.0, length_per_revolution=1.0,
                  encoder=EncoderSpec(steps_per_revolution=1024, fine_bits=10, distance_per_revolution=1.0),
                  plant=PlantSpec(speed_time_constant=TC, inertia=J, end_stop_max=5.0, end_stop_min=-5.0))


def hydraulic(valve: ValveType = ValveType.Q, force_limit: float | None = None, load: float = 0.0,
              stop: float | None = 200.0) -> DriveSpec:
    return DriveSpec(actuator=ActuatorKind.HYDRAULIC, interface=SetpointInterface.ANALOG,
                     encoder=EncoderSpec(rotary=False, step_length=0.001, fine_bits=0),
                     hydraulic=HydraulicSpec(valve=valve, reference_velocity=500.0, force_limit=force_limit),
                     plant=PlantSpec(initial_position=100.0, end_stop_max=stop,
                                     cylinder=CylinderSpec(load_force=load, valve_time_constant=0.0)))


class Rig:
    def __init__(self, spec: DriveSpec):
        self.bank = AxisBank()
        self.group = new_drive_group(spec.actuator, self.bank)
        self.i = self.bank.add()
        self.ch = self.group.add(self.i, spec, DT, 0.0)
        self.ch.set_enable(True, 0.0)
        self.k = 0

    def run(self, seconds: float, command: float) -> None:
        for _ in range(round(seconds / DT)):
            self.k += 1
            self.group.read(self.bank, self.k * DT, DT)
            self.bank.cmd_v[self.i] = command
            self.group.write(self.bank, self.k * DT)


# --- electric servo drive -----------------------------------------------------------------------------
def test_drives_end_stop_holds_the_load_of_a_servo_drive_with_its_torque_at_the_limit():
    """S7-Technology V4.1 §6.2.11: driving against a fixed end stop, the load stands at the stop and the drive
    presses with the torque its speed loop asks for; a torque limit (§6.2.12) caps it and reports the limit
    as active."""
    rig = Rig(SERVO)
    rig.run(1.0, 10.0)
    assert rig.ch.mechanical_position() == 5.0
    demand = JT * 10.0 * (1.0 - E) / DT             # speed loop at standstill, setpoint 10 units/s
    assert rig.ch.torque == pytest.approx(demand, rel=1e-9)
    assert not rig.ch.torque_limit_active
    rig.ch.set_torque_limit(2.0)
    rig.run(0.1, 10.0)
    assert rig.ch.mechanical_position() == 5.0
    assert rig.ch.torque == pytest.approx(2.0, rel=1e-12)
    assert rig.ch.torque_limit_active
    rig.ch.set_torque_limit(None)
    rig.run(0.01, 10.0)
    assert rig.ch.torque == pytest.approx(demand, rel=1e-9) and not rig.ch.torque_limit_active


def test_drives_end_stop_torque_limit_caps_the_acceleration_of_a_free_load():
    """S7-Technology V4.1 §6.2.12: with the torque limited, the drive accelerates at limit / inertia:
    x = a t² / 2 from standstill."""
    rig = Rig(replace(SERVO, max_torque=0.1, plant=replace(SERVO.plant, end_stop_max=None)))
    rig.run(0.2, 10.0)
    a = 0.1 / JT
    t = 0.2 - DT                                    # the first command acts from the second cycle on
    assert rig.ch.mechanical_position() == pytest.approx(0.5 * a * t ** 2, rel=1e-9)
    assert rig.ch.torque == pytest.approx(0.1) and rig.ch.torque_limit_active
    rig.ch.set_torque_limit(0.05)                   # a run-time limit below the drive's maximum wins
    rig.run(0.01, 10.0)
    assert rig.ch.torque == pytest.approx(0.05)
    rig.ch.set_torque_limit(1.0)                    # above the drive's maximum: the maximum stays
    rig.run(0.01, 10.0)
    assert rig.ch.torque == pytest.approx(0.1)


def test_drives_end_stop_load_leaves_the_stop_when_the_drive_reverses():
    """S7-Technology V4.1 §6.2.11 (example c): a motion away from the end stop releases the clamping."""
    rig = Rig(SERVO)
    rig.run(1.0, 10.0)
    rig.run(0.2, -5.0)
    assert rig.ch.mechanical_position() < 5.0 - 0.5
    rig.run(3.0, -10.0)
    assert rig.ch.mechanical_position() == -5.0                     # the lower end stop


def test_drives_end_stop_torque_limit_survives_disable():
    """S7-Technology V4.1 §6.2.12: the torque limit stays when MC_Power removes the enable."""
    rig = Rig(SERVO)
    rig.ch.set_torque_limit(2.0)
    rig.ch.set_enable(False, 0.0)
    rig.ch.set_enable(True, 0.0)
    rig.run(1.0, 10.0)
    assert rig.ch.torque == pytest.approx(2.0)


@pytest.mark.parametrize("value", [0.0, -1.0, math.nan, "2", True])
def test_drives_end_stop_invalid_torque_limit_is_refused(value):
    """S7-Technology V4.1 §6.2.12: a torque limit must be a value > 0 (MaxTorque < 0 is not permitted)."""
    rig = Rig(SERVO)
    with pytest.raises(ValueError):
        rig.ch.set_torque_limit(value)


@pytest.mark.parametrize("plant, field", [
    (dict(end_stop_min=5.0, end_stop_max=5.0), "PlantSpec.end_stop_min/end_stop_max"),
    (dict(end_stop_max=-1.0), "PlantSpec.initial_position"),
    (dict(inertia=0.0), "PlantSpec.inertia"),
])
def test_drives_end_stop_configuration_errors_name_the_field(plant, field):
    """S7-Technology V4.1 §6.2.11: end stops must leave the load room, with the load between them."""
    with pytest.raises(DriveSpecError) as err:
        PlantSpec(**plant)
    assert err.value.field == field


def test_drives_end_stop_ideal_and_stepper_drives_cannot_limit_torque():
    """S7-Technology V4.1 §6.2.12: torque limiting needs a real drive (a virtual axis has none)."""
    bank = AxisBank()
    for kind in (ActuatorKind.IDEAL, ActuatorKind.PULSE):
        ch = new_drive_group(kind, bank).add(bank.add(), DriveSpec(actuator=kind), DT, 0.0)
        assert not ch.can_limit_torque and ch.torque == 0.0 and not ch.torque_limit_active
        with pytest.raises(ValueError):
            ch.set_torque_limit(1.0)


# --- hydraulic cylinder ---------------------------------------------------------------------------------
def test_drives_end_stop_q_valve_cylinder_presses_with_the_supply_pressure():
    """S7-Technology V4.1 §3.1.4: a Q valve meters flow only; against a fixed end stop no oil flows, chamber A
    reaches the supply pressure and the cylinder presses with p_S A_A = 100 bar * 20 cm² = 20 kN."""
    rig = Rig(hydraulic())
    rig.run(1.0, 250.0)
    assert rig.ch.mechanical_position() == 200.0
    assert rig.ch.pressures == pytest.approx((100.0, 0.0), abs=1e-9)
    assert rig.ch.force == pytest.approx(20000.0)
    assert not rig.ch.torque_limit_active
    rig.run(2.0, -250.0)                              # retracting to the cylinder's lower end
    assert rig.ch.mechanical_position() == 0.0
    assert rig.ch.force == pytest.approx(-100e5 * 10e-4)


def test_drives_end_stop_pq_valve_pressure_limit_holds_the_force():
    """S7-Technology V4.1 §3.3.1 (pressure limiting): a P/Q valve limits the driving pressure, so against the
    stop the force equals the limit (p_A = F / A_A) and the limit is reported active; the configured limit
    is an upper bound for the run-time one."""
    rig = Rig(hydraulic(ValveType.PQ, force_limit=8000.0))
    rig.run(1.0, 250.0)
    assert rig.ch.mechanical_position() == 200.0
    assert rig.ch.force == pytest.approx(8000.0) and rig.ch.torque == pytest.approx(8000.0)
    assert rig.ch.pressures == pytest.approx((8000.0 / 20e-4 / 1e5, 0.0))
    assert rig.ch.torque_limit_active and rig.ch.can_limit_torque
    rig.ch.set_torque_limit(5000.0)
    rig.run(0.01, 250.0)
    assert rig.ch.force == pytest.approx(5000.0) and rig.ch.pressures[0] == pytest.approx(25.0)
    rig.ch.set_torque_limit(12000.0)
    rig.run(0.01, 250.0)
    assert rig.ch.force == pytest.approx(8000.0)


def test_drives_end_stop_pq_valve_yields_to_a_load_above_its_force_limit():
    """S7-Technology V4.1 §3.3.1: with the force limited to 5 kN a 6 kN load pushes the piston back: the net
    force -1 kN drives v = -K y sqrt(1000 N / (A_A³ + A_B³)) through the opened valve."""
    rig = Rig(hydraulic(ValveType.PQ, load=-6000.0, stop=None))
    rig.ch.set_torque_limit(5000.0)
    rig.run(0.3, 250.0)                                  # 50 % output: y = 0.5
    x0 = rig.ch.mechanical_position()
    rig.run(0.1, 250.0)
    k = 40.0 / 60000.0 / math.sqrt(35e5)
    expected = -k * 0.5 * math.sqrt(1000.0 / (20e-4 ** 3 + 10e-4 ** 3)) * 1000.0
    assert (rig.ch.mechanical_position() - x0) / 0.1 == pytest.approx(expected, rel=1e-3)
    assert rig.ch.force == pytest.approx(6000.0, rel=1e-6) and rig.ch.torque_limit_active


@settings(max_examples=30, deadline=None)
@given(st.lists(st.tuples(st.floats(-1e4, 1e4, allow_nan=False), st.integers(1, 200),
                          st.one_of(st.none(), st.floats(0.01, 50.0))), min_size=1, max_size=8))
def test_drives_end_stop_servo_load_never_passes_its_end_stops(seq):
    """S7-Technology V4.1 §6.2.11: whatever the speed commands and torque limits, the load stays between its
    fixed end stops [-5, 5] and the torque never exceeds the limit in force."""
    rig = Rig(SERVO)
    for command, cycles, limit in seq:
        rig.ch.set_torque_limit(limit)
        for _ in range(cycles):
            rig.run(DT, command)
            assert -5.0 <= rig.ch.mechanical_position() <= 5.0
            if limit is not None:
                assert abs(rig.ch.torque) <= limit * (1 + 1e-12)
