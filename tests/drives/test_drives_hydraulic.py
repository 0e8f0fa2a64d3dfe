"""The simulated hydraulic axis (S7-Technology V4.1 §3.1.4, §4.6.4, §6.2.1 StopMode 3, §6.2.13): valve
output through the valve characteristic, cylinder physics, enable and fault sequences, configuration errors.

Expected values come from the equations of a leakage-free differential cylinder behind a 4/3 valve
(orifice equation Q = K y sqrt(dp) at both control edges, K = Q_N / sqrt(dp_N)), written out here.
"""
from __future__ import annotations

import math
from dataclasses import replace

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from plcmotion.drives import (ActuatorKind, CylinderSpec, DriveSpec, DriveSpecError, EncoderSpec, HydraulicSpec,
                              PlantSpec, SetpointInterface, ValveCharacteristic, ValveType, new_drive_group)
from plcmotion.kernel.bank import AxisBank

DT = 0.001
LSB = 100.0 / 27648.0               # one count of the S7 analog output [%] (27648 = 100 % = 10 V)

# data-sheet values of the cylinder used below
AA, AB = 20e-4, 10e-4               # m²
PS = 100e5                          # Pa
K = 40.0 / 60000.0 / math.sqrt(35e5)  # m³/s per sqrt(Pa): 40 l/min at 35 bar per control edge


def spec(hyd: HydraulicSpec | None = None, cyl: CylinderSpec | None = None, x0: float = 100.0,
         **plant) -> DriveSpec:
    return DriveSpec(actuator=ActuatorKind.HYDRAULIC, interface=SetpointInterface.ANALOG,
                     encoder=EncoderSpec(rotary=False, step_length=0.001, fine_bits=0),
                     hydraulic=hyd, plant=PlantSpec(initial_position=x0, cylinder=cyl or CylinderSpec(), **plant))


class Rig:
    """One hydraulic drive on its own bank, stepped like the servo cycle: read actual values, write command."""

    def __init__(self, drive: DriveSpec, enable: bool = True):
        self.bank = AxisBank()
        self.group = new_drive_group(drive.actuator, self.bank)
        self.i = self.bank.add()
        self.ch = self.group.add(self.i, drive, DT, 0.0)
        self.k = 0
        if enable:
            self.ch.set_enable(True, 0.0)

    @property
    def t(self) -> float:
        return self.k * DT

    def cycle(self, command: float = 0.0) -> None:
        self.k += 1
        self.group.read(self.bank, self.t, DT)
        self.bank.cmd_v[self.i] = command
        self.group.write(self.bank, self.t)

    def run(self, seconds: float, command: float = 0.0) -> None:
        for _ in range(round(seconds / DT)):
            self.cycle(command)

    @property
    def position(self) -> float:
        return float(self.bank.act_p[self.i])

    def velocity(self, seconds: float = 0.1, command: float = 0.0) -> float:
        """Mean velocity of the load over ``seconds`` of travel with ``command``."""
        x0 = self.ch.mechanical_position()
        self.run(seconds, command)
        return (self.ch.mechanical_position() - x0) / seconds


def steady(y: float, force: float = 0.0) -> float:
    """Velocity [mm/s] at spool opening y against an external force [N] in the positive direction:
    extending p_S A_A + F = v² (A_A³ + A_B³) / (K y)², retracting -p_S A_B + F = -v² (A_A³ + A_B³) / (K y)²."""
    drive = PS * AA if y > 0 else -PS * AB
    net = drive + force
    return math.copysign(K * abs(y) * math.sqrt(abs(net) / (AA ** 3 + AB ** 3)), net) * 1000.0


# --- cylinder physics ------------------------------------------------------------------------------------
@pytest.mark.parametrize("output, opening", [(60.0, 0.6), (-60.0, -0.6), (100.0, 1.0), (-25.0, -0.25)])
def test_drives_hydraulic_speed_from_flow_and_piston_area_in_each_direction(output, opening):
    """S7-Technology V4.1 §3.1.4: the output meters the flow; the piston moves at flow / area.  With no
    load the force balance p_A A_A = p_B A_B gives v = K y sqrt(p_S A / (A_A³ + A_B³)) with A = A_A
    extending and A_B retracting: the differential cylinder extends faster than it retracts."""
    reference = 500.0                                   # straight line: 100 % <-> 500 mm/s
    rig = Rig(spec(HydraulicSpec(reference_velocity=reference), CylinderSpec(valve_time_constant=0.0)))
    rig.run(0.2, output / 100.0 * reference)            # settle
    v = rig.velocity(0.2, output / 100.0 * reference)
    assert v == pytest.approx(steady(opening), rel=2e-3)
    pa, pb = (p * 1e5 for p in rig.ch.pressures)
    vs = v / 1000.0
    y = rig.ch.spool_opening
    assert y == pytest.approx(opening, abs=1e-4)
    if opening > 0:   # P -> A and B -> T: both control edges pass the flows v A_A and v A_B
        assert K * y * math.sqrt(PS - pa) == pytest.approx(vs * AA, rel=3e-3)
        assert K * y * math.sqrt(pb) == pytest.approx(vs * AB, rel=3e-3)
    else:             # P -> B and A -> T
        assert K * -y * math.sqrt(PS - pb) == pytest.approx(-vs * AB, rel=3e-3)
        assert K * -y * math.sqrt(pa) == pytest.approx(-vs * AA, rel=3e-3)
    assert pa * AA - pb * AB == pytest.approx(0.0, abs=5.0)     # no load: the forces balance
    assert rig.ch.force == pytest.approx(0.0, abs=5.0)


def test_drives_hydraulic_a_load_force_slows_extension_and_speeds_up_retraction():
    """S7-Technology V4.1 §3.1.4: a constant load force F against the positive direction enters the force
    balance: v = K y sqrt((p_S A_A - F) / (A_A³ + A_B³)) extending, K |y| sqrt((p_S A_B + F) / ...) retracting."""
    load = -8000.0                                       # N, pushing in the negative direction
    cyl = CylinderSpec(valve_time_constant=0.0, load_force=load)
    rig = Rig(spec(HydraulicSpec(reference_velocity=500.0), cyl, x0=250.0))
    rig.run(0.1, 250.0)
    assert rig.velocity(0.1, 250.0) == pytest.approx(steady(0.5, load), rel=3e-3)
    rig.run(0.1, -250.0)
    assert rig.velocity(0.1, -250.0) == pytest.approx(steady(-0.5, load), rel=3e-3)
    assert rig.ch.force == pytest.approx(-load, rel=1e-3)        # the cylinder carries the load


def test_drives_hydraulic_spool_lag_and_overlap_dead_band():
    """S7-Technology V4.1 §4.6.4: a valve with overlap opens only beyond it (a dead band); the spool follows
    the output with its time constant, so the opening after one time constant is 1 - 1/e of the step."""
    cyl = CylinderSpec(valve_time_constant=0.02, valve_overlap=5.0)
    rig = Rig(spec(HydraulicSpec(reference_velocity=500.0), cyl))
    rig.run(0.2, 4.0 / 100.0 * 500.0)                    # 4 % output: inside the overlap
    assert rig.ch.spool_opening == 0.0
    assert rig.velocity(0.1, 20.0) == 0.0
    rig.cycle(0.5 * 500.0)                               # step to 50 %: opening (50 - 5) / 95
    rig.run(0.02, 0.5 * 500.0)
    assert rig.ch.spool_opening == pytest.approx(45.0 / 95.0 * (1.0 - math.exp(-1.0)), rel=2e-3)


def test_drives_hydraulic_closed_valve_holds_the_piston_against_its_load():
    """S7-Technology V4.1 §3.1.4: an incompressible, leakage-free cylinder behind a closed valve does not move,
    whatever the load."""
    rig = Rig(spec(HydraulicSpec(reference_velocity=500.0), CylinderSpec(load_force=-15000.0)))
    rig.run(0.3, 0.0)
    assert rig.ch.mechanical_position() == 100.0
    assert rig.position == pytest.approx(100.0, abs=0.001)


# --- valve characteristic ----------------------------------------------------------------------------------
DEAD_BAND = ValveCharacteristic(((-100.0, -300.0), (-3.0, 0.0), (3.0, 0.0), (100.0, 300.0)))


@pytest.mark.parametrize("velocity, percent", [
    (0.0, 0.0), (1.0, 3.0 + 97.0 / 300.0), (-150.0, -(3.0 + 48.5)), (300.0, 100.0), (900.0, 100.0),
    (-300.0, -100.0)])
def test_drives_hydraulic_output_voltage_from_the_characteristic_with_dead_band(velocity, percent):
    """S7-Technology V4.1 §4.6.4: the valve profile (output % -> velocity) is inverted; across the dead band
    of +-3 % the output jumps, so the smallest velocity already opens the valve; -100 % = -10 V,
    +100 % = +10 V (§3.1.4)."""
    rig = Rig(spec(HydraulicSpec(characteristic=DEAD_BAND)))
    rig.cycle(velocity)
    assert rig.ch.output_percent == pytest.approx(percent, abs=LSB / 2)
    assert rig.ch.output_voltage == pytest.approx(percent / 10.0, abs=LSB / 20)
    assert rig.ch.setpoint_word == round(percent * 276.48)


def test_drives_hydraulic_characteristic_with_kink_and_offset_zero():
    """S7-Technology V4.1 §4.6.4, §6.2.1 (hydraulic example: zero speed at 3 % valve output): a kinked profile
    is followed piece by piece; a profile whose velocity 0 lies at 3 % holds the axis with 3 %."""
    kink = ValveCharacteristic(((-100.0, -400.0), (0.0, 0.0), (50.0, 100.0), (100.0, 400.0)))
    assert kink.output(50.0) == pytest.approx(25.0)
    assert kink.output(250.0) == pytest.approx(75.0)
    assert kink.output(-200.0) == pytest.approx(-50.0)
    offset = ValveCharacteristic(((-100.0, -300.0), (3.0, 0.0), (100.0, 300.0)))
    rig = Rig(spec(HydraulicSpec(characteristic=offset)))
    rig.cycle(0.0)
    assert rig.ch.output_percent == pytest.approx(3.0, abs=LSB / 2)


def test_drives_hydraulic_one_sided_pump_profile_gives_zero_for_the_other_direction():
    """S7-Technology V4.1 §4.6.4: a profile of a variable-speed pump covers one direction; negative
    manipulated values are limited to 0 by its first row."""
    pump = ValveCharacteristic(((0.0, 0.0), (100.0, 200.0)))
    assert pump.output(-50.0) == 0.0
    assert pump.output(100.0) == pytest.approx(50.0)
    flat = ValveCharacteristic(((-100.0, 0.0), (0.0, 0.0), (100.0, 200.0)))
    assert flat.output(-50.0) == 0.0


def test_drives_hydraulic_characteristic_from_a_cam_curve():
    """S7-Technology V4.1 §4.6.4: the valve profile is a cam (leading value output %, following value
    velocity); a linear cam through its points gives the same characteristic as the points."""
    from plcmotion.kernel.cam import interpolate
    points = [(-100.0, -300.0), (-3.0, 0.0), (3.0, 0.0), (100.0, 300.0)]
    curve = interpolate(points, [], 0)
    char = ValveCharacteristic.from_curve(curve)
    for v in (-300.0, -150.0, -1.0, 0.0, 1.0, 150.0, 300.0):
        assert char.output(v) == pytest.approx(DEAD_BAND.output(v), abs=1e-9)


@pytest.mark.parametrize("points, field", [
    ([(0.0, 0.0)], "ValveCharacteristic.points"),
    ([(-100.0, 100.0), (100.0, -100.0)], "ValveCharacteristic.points"),       # falling: not monotonic
    ([(-100.0, 10.0), (100.0, 300.0)], "ValveCharacteristic.points"),         # no velocity 0
    ([(-120.0, -300.0), (100.0, 300.0)], "ValveCharacteristic.points[0] output"),
    ([(0.0, 0.0), (0.0, 1.0)], "ValveCharacteristic.points"),
    ([(0.0, math.nan), (10.0, 1.0)], "ValveCharacteristic.points[0] velocity"),
])
def test_drives_hydraulic_invalid_characteristic_is_a_precise_error(points, field):
    """S7-Technology V4.1 §4.6.4: a valve profile must be monotonic over at most -100 ... +100 % and contain
    standstill; anything else is refused naming the field."""
    with pytest.raises(DriveSpecError) as err:
        ValveCharacteristic(tuple(points))
    assert err.value.field == field


def test_drives_hydraulic_characteristic_changeover_is_compensated_at_100_percent_per_second():
    """S7-Technology V4.1 §6.2.13: MC_SetCharacteristic may change the characteristic while moving; the
    control signal compensation is limited to 100 %/s (a jump of 100 % is compensated in 1 s)."""
    rig = Rig(spec(HydraulicSpec(reference_velocity=500.0)))
    rig.run(0.05, 100.0)
    assert rig.ch.output_percent == pytest.approx(20.0, abs=LSB)
    rig.ch.set_characteristic(ValveCharacteristic.linear(250.0))   # the same velocity now needs 40 %
    outputs = []
    for _ in range(250):
        rig.cycle(100.0)
        outputs.append(rig.ch.output_percent)
    for k, u in enumerate(outputs, start=1):
        assert u == pytest.approx(40.0 - max(20.0 - 100.0 * k * DT, 0.0), abs=LSB)


# --- enable, OFF2 ramp, fault --------------------------------------------------------------------------
def test_drives_hydraulic_off2_ramp_to_the_substitute_output_on_disable():
    """S7-Technology V4.1 §6.2.1 StopMode 3 (OFF2Stop, hydraulic axes): without enable the control signal
    ramps to the substitute value QOutputValue at the configured rate (default 100 %/s)."""
    rig = Rig(spec(HydraulicSpec(reference_velocity=500.0)))
    rig.run(0.05, 250.0)
    assert rig.ch.output_percent == pytest.approx(50.0, abs=LSB)
    rig.ch.set_off_output(10.0)
    rig.ch.set_enable(False, rig.t)
    assert not rig.ch.ready(rig.t)
    for k in range(1, 601):
        rig.cycle(250.0)                              # the controller's command no longer reaches the valve
        assert rig.ch.output_percent == pytest.approx(max(50.0 - 100.0 * k * DT, 10.0), abs=LSB)


def test_drives_hydraulic_substitute_output_ramp_rate_is_configurable():
    """S7-Technology V4.1 §6.2.1: the OFF2 ramp is ``userdefaultqfaxis.maxderivative.qoutput`` [%/s]."""
    rig = Rig(spec(HydraulicSpec(reference_velocity=500.0, output_ramp=400.0, off_output=-20.0)))
    rig.run(0.05, 250.0)
    rig.ch.set_enable(False, rig.t)
    rig.run(0.1)
    assert rig.ch.output_percent == pytest.approx(50.0 - 40.0, abs=LSB)
    rig.run(0.1)
    assert rig.ch.output_percent == pytest.approx(-20.0, abs=LSB)


def test_drives_hydraulic_enable_sequence_ready_after_delay_and_output_only_when_ready():
    """S7-Technology V4.1 §6.2.1: MC_Power enables the drive; until it is ready the valve keeps the substitute
    output, then it follows the controller."""
    rig = Rig(replace(spec(HydraulicSpec(reference_velocity=500.0)), ready_delay=0.05), enable=False)
    rig.run(0.01, 250.0)
    assert rig.ch.output_percent == 0.0 and not rig.ch.ready(rig.t)
    rig.ch.set_enable(True, rig.t)
    t_on = rig.t
    rig.run(0.049, 250.0)
    assert not rig.ch.ready(rig.t) and rig.ch.output_percent == 0.0
    rig.run(0.001, 250.0)
    assert rig.ch.ready(t_on + 0.05)
    assert rig.ch.output_percent == pytest.approx(50.0, abs=LSB)


def test_drives_hydraulic_fault_ramps_the_output_down_and_clears():
    """S7-Technology V4.1 §6.2.1: a drive fault removes readiness; the valve ramps to the substitute value;
    when the fault is gone the drive is ready again."""
    rig = Rig(spec(HydraulicSpec(reference_velocity=500.0)))
    rig.run(0.05, 250.0)
    rig.ch.set_fault(True)
    assert not rig.ch.ready(rig.t)
    rig.run(0.2, 250.0)
    assert rig.ch.output_percent == pytest.approx(30.0, abs=LSB)
    rig.run(0.5, 250.0)
    assert rig.ch.output_percent == 0.0
    rig.ch.set_fault(False)
    assert rig.ch.ready(rig.t)
    rig.cycle(250.0)
    assert rig.ch.output_percent == pytest.approx(50.0, abs=LSB)


def test_drives_hydraulic_output_limits_and_homing_reference():
    """S7-Technology V4.1 §4.6.13.1: manipulated variable limiting (high/low); homing re-references the actual
    value without moving the piston."""
    rig = Rig(spec(HydraulicSpec(reference_velocity=500.0, output_min=-40.0, output_max=80.0)))
    rig.cycle(10000.0)
    assert rig.ch.output_percent == pytest.approx(80.0, abs=LSB / 2)
    rig.cycle(-10000.0)
    assert rig.ch.output_percent == pytest.approx(-40.0, abs=LSB / 2)
    rig.run(0.05, 0.0)
    x = rig.ch.mechanical_position()
    rig.ch.set_actual(rig.bank, 0.0)
    rig.cycle(0.0)
    assert rig.position == pytest.approx(0.0, abs=0.001)
    assert rig.ch.mechanical_position() == pytest.approx(x, abs=1e-3)


@pytest.mark.parametrize("make, field", [
    (lambda: CylinderSpec(area_b=0.0), "CylinderSpec.area_b"),
    (lambda: CylinderSpec(stroke_min=10.0, stroke_max=10.0), "CylinderSpec.stroke_min/stroke_max"),
    (lambda: CylinderSpec(valve_overlap=100.0), "CylinderSpec.valve_overlap"),
    (lambda: CylinderSpec(valve_curve=((0.0, 1.0), (10.0, 0.0))), "CylinderSpec.valve_curve"),
    (lambda: HydraulicSpec(output_min=50.0, output_max=20.0), "HydraulicSpec.output_min/output_max"),
    (lambda: HydraulicSpec(force_limit=1000.0), "HydraulicSpec.force_limit"),           # a Q valve
    (lambda: HydraulicSpec(valve=ValveType.PQ, force_limit=-1.0), "HydraulicSpec.force_limit"),
    (lambda: HydraulicSpec(output_ramp=0.0), "HydraulicSpec.output_ramp"),
    (lambda: spec(x0=600.0), "PlantSpec.initial_position"),                             # beyond the stroke
    (lambda: DriveSpec(actuator=ActuatorKind.HYDRAULIC, interface=SetpointInterface.PULSES,
                       plant=PlantSpec(cylinder=CylinderSpec())), "DriveSpec.interface"),
])
def test_drives_hydraulic_configuration_errors_name_the_field(make, field):
    """S7-Technology V4.1 §4.6: a hydraulic axis with values outside their range is refused with the field."""
    with pytest.raises(DriveSpecError) as err:
        make()
    assert err.value.field == field


def test_drives_hydraulic_q_valve_cannot_limit_the_force():
    """S7-Technology V4.1 §3.1.4: a Q valve meters flow only (no force limiting); the channel says so."""
    rig = Rig(spec(HydraulicSpec()))
    assert not rig.ch.can_limit_torque
    with pytest.raises(ValueError):
        rig.ch.set_torque_limit(1000.0)


# --- invariants -------------------------------------------------------------------------------------------
steps = st.lists(st.tuples(st.floats(-1e5, 1e5, allow_nan=False), st.integers(1, 80),
                           st.sampled_from(["run", "off", "on", "fault", "ok", "char"])), min_size=1, max_size=12)


@settings(max_examples=40, deadline=None)
@given(steps, st.floats(1.0, 499.0), st.sampled_from([ValveType.Q, ValveType.PQ]))
def test_drives_hydraulic_output_within_10_volts_and_piston_within_stroke(seq, x0, valve):
    """S7-Technology V4.1 §3.1.4: whatever the controller asks, the output stays within -10 ... +10 V and the
    piston within the cylinder's stroke [0, 500]."""
    rig = Rig(spec(HydraulicSpec(reference_velocity=500.0, valve=valve), x0=x0))
    for command, cycles, event in seq:
        if event == "off":
            rig.ch.set_enable(False, rig.t)
        elif event == "on":
            rig.ch.set_enable(True, rig.t)
        elif event == "fault":
            rig.ch.set_fault(True)
        elif event == "ok":
            rig.ch.set_fault(False)
        elif event == "char":
            rig.ch.set_characteristic(DEAD_BAND)
        for _ in range(cycles):
            rig.cycle(command)
            assert -10.0 <= rig.ch.output_voltage <= 10.0
            assert 0.0 <= rig.ch.mechanical_position() <= 500.0


def test_drives_hydraulic_zero_mark_latched_when_the_piston_passes_it():
    """S7-Technology V4.1 §4.6.14 (homing as for electric axes, active homing with zero mark): the encoder of
    the cylinder latches its actual value at the zero mark passed in the armed direction."""
    drive = spec(HydraulicSpec(reference_velocity=500.0), CylinderSpec(valve_time_constant=0.0),
                 zero_mark_offset=150.0)
    rig = Rig(drive)
    rig.ch.arm_zero_mark(-1.0)                    # armed for the negative direction: passing upwards is ignored
    rig.run(0.3, 250.0)
    assert rig.ch.mechanical_position() > 150.0 and rig.ch.zero_mark_latched() is None
    rig.ch.arm_zero_mark(1.0)
    rig.run(0.3, -250.0)
    rig.run(0.4, 250.0)
    assert rig.ch.zero_mark_latched() == pytest.approx(150.0, abs=0.001)
    assert rig.ch.zero_mark_latched() is None     # once
