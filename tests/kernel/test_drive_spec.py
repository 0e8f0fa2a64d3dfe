"""Drives behind the neutral interface: drive groups built from hand-written specs (no tag dict) follow their
commands as ``drives.spec`` / ``drives.base`` document, and the S7-1200 spec builder maps the axis
parameters (S7-1200 V6 §12.9 names, values derived by hand from the parameter docs) to the right spec."""
from __future__ import annotations

import math

import pytest

from plcmotion.drives import (ActuatorKind, DriveSpec, EncoderInterface, EncoderKind, EncoderSpec, PlantSpec,
                              SetpointInterface, SwitchSpec, new_drive_group)
from plcmotion.drives.plant import Plant
from plcmotion.kernel.bank import AxisBank
from plcmotion.s7_1200.technology.builder import drive_spec
from plcmotion.kernel.io import DigitalInputs

DT = 0.001

# An analog drive whose setpoint word has a binary quantum: 27648 = 100 % of the reference speed, with
# 1 length unit per revolution and 1620 1/min reference speed one word is 1620 / 60 / 27648 = 1/1024 units/s,
# so the speeds used below travel without rounding.  Max speed 1620 1/min = 27 units/s.
ANALOG = DriveSpec(actuator=ActuatorKind.SPEED_SERVO, interface=SetpointInterface.ANALOG,
                   reference_speed=1620.0, max_speed=1620.0, length_per_revolution=1.0, ready_delay=0.0,
                   off_ramp_time=0.27,
                   encoder=EncoderSpec(steps_per_revolution=1024, fine_bits=10, distance_per_revolution=1.0),
                   plant=PlantSpec(speed_time_constant=0.0))


class Rig:
    """One drive group on its own bank, stepped like the servo cycle: read actual values, write commands."""

    def __init__(self, spec: DriveSpec):
        self.bank = AxisBank()
        self.group = new_drive_group(spec.actuator, self.bank)
        self.index = self.bank.add()
        self.ch = self.group.add(self.index, spec, DT, 0.0)
        self.k = 0

    @property
    def t(self) -> float:
        return self.k * DT

    def cycle(self, speed: float = 0.0, position: float | None = None) -> None:
        self.k += 1
        b, i = self.bank, self.index
        self.group.read(b, self.t, DT)
        b.cmd_v[i] = speed
        if position is not None:
            b.sp_p[i] = position
        self.group.write(b, self.t)

    def run(self, seconds: float, speed: float = 0.0) -> None:
        for _ in range(round(seconds / DT)):
            self.cycle(speed)

    @property
    def position(self) -> float:
        return float(self.bank.act_p[self.index])

    @property
    def velocity(self) -> float:
        return float(self.bank.act_v[self.index])


# --- the simulated speed-controlled drive -------------------------------------------------------------
def test_kernel_ready_after_the_ready_delay_and_not_without_enable_or_with_a_fault():
    rig = Rig(DriveSpec(**{**ANALOG.__dict__, "ready_delay": 0.05}))
    assert not rig.ch.ready(0.0)
    rig.ch.set_enable(True, 0.0)
    assert not rig.ch.ready(0.049)
    assert rig.ch.ready(0.05)
    rig.ch.set_fault(True)
    assert not rig.ch.ready(0.06)
    rig.ch.set_fault(False)
    assert rig.ch.ready(0.06)
    rig.ch.set_enable(False, 0.07)
    assert not rig.ch.ready(0.07)


def test_kernel_a_disabled_drive_does_not_follow_its_speed_setpoint():
    rig = Rig(ANALOG)
    rig.run(0.1, speed=10.0)
    assert rig.position == 0.0 and rig.ch.mechanical_position() == 0.0


def test_kernel_position_is_the_integral_of_the_commanded_speed():
    rig = Rig(ANALOG)
    rig.ch.set_enable(True, 0.0)
    rig.run(0.5, speed=10.0)
    rig.run(0.25, speed=-4.0)
    rig.cycle(0.0)             # the speed written in a cycle acts until the next cycle reads the drive
    # 10 units/s for 0.5 s, then -4 units/s for 0.25 s (an ideal speed loop): 5 - 1 = 4 units
    assert rig.ch.mechanical_position() == pytest.approx(4.0, abs=1e-9)
    assert rig.velocity == pytest.approx(-4.0, abs=1 / 1024 / DT)      # over the last cycle, +- one count


def test_kernel_first_order_speed_loop_lags_a_speed_step_by_its_time_constant():
    tc = 0.02
    rig = Rig(DriveSpec(**{**ANALOG.__dict__, "plant": PlantSpec(speed_time_constant=tc)}))
    rig.ch.set_enable(True, 0.0)
    c, T = 10.0, 0.3
    rig.run(T, speed=c)
    rig.cycle(c)               # the speed written in a cycle acts until the next cycle reads the drive
    # step response of a first-order lag: x(T) = c * (T - tc * (1 - exp(-T / tc)))
    expected = c * (T - tc * (1.0 - math.exp(-T / tc)))
    assert rig.ch.mechanical_position() == pytest.approx(expected, abs=1e-9)


def test_kernel_speed_is_limited_to_the_drives_maximum_speed():
    rig = Rig(ANALOG)
    rig.ch.set_enable(True, 0.0)
    rig.run(0.1, speed=200.0)
    x0 = rig.ch.mechanical_position()
    rig.run(0.2, speed=200.0)
    # max speed 1620 1/min at 1 unit per revolution = 27 units/s
    assert (rig.ch.mechanical_position() - x0) / 0.2 == pytest.approx(27.0, rel=1e-9)
    rig.run(0.1, speed=-200.0)
    x0 = rig.ch.mechanical_position()
    rig.run(0.2, speed=-200.0)
    assert (rig.ch.mechanical_position() - x0) / 0.2 == pytest.approx(-27.0, rel=1e-9)


def test_kernel_without_enable_the_drive_ramps_down_with_its_off_ramp():
    rig = Rig(ANALOG)
    rig.ch.set_enable(True, 0.0)
    rig.run(0.2, speed=10.0)
    x0 = rig.ch.mechanical_position()
    rig.ch.set_enable(False, rig.t)
    rig.run(0.5, speed=10.0)
    # off ramp: 27 units/s to 0 in 0.27 s = 100 units/s^2; from 10 units/s that is 0.1 s and v^2 / 2a = 0.5
    assert rig.ch.mechanical_position() - x0 == pytest.approx(0.5, abs=1e-9)
    assert rig.velocity == 0.0


def test_kernel_a_drive_fault_stops_following_and_ramps_down():
    rig = Rig(ANALOG)
    rig.ch.set_enable(True, 0.0)
    rig.run(0.2, speed=-10.0)
    x0 = rig.ch.mechanical_position()
    rig.ch.set_fault(True)
    rig.run(0.5, speed=-10.0)
    assert rig.ch.mechanical_position() - x0 == pytest.approx(-0.5, abs=1e-9)
    assert not rig.ch.ready(rig.t)


@pytest.mark.parametrize("encoder, step", [
    # rotary: 1000 marks per revolution, 4 counts per mark, 5 units per revolution -> 5 / 4000
    (EncoderSpec(steps_per_revolution=1000, fine_bits=2, distance_per_revolution=5.0), 5.0 / 4000),
    # linear: a mark every 0.01 units, 4 counts per mark
    (EncoderSpec(rotary=False, step_length=0.01, fine_bits=2), 0.0025),
])
def test_kernel_the_encoder_quantizes_the_actual_position_to_whole_increments(encoder, step):
    assert encoder.increment == pytest.approx(step, rel=1e-15)
    rig = Rig(DriveSpec(**{**ANALOG.__dict__, "encoder": encoder}))
    rig.ch.set_enable(True, 0.0)
    for speed in (3.3, -7.77, 1.234):
        for _ in range(137):
            rig.cycle(speed)
            counts = rig.position / step
            assert counts == pytest.approx(round(counts), abs=1e-6)
            # an incremental counter shows the increments passed: never ahead, less than one behind
            lag = rig.ch.mechanical_position() - rig.position
            assert -1e-9 <= lag < step + 1e-9


def test_kernel_inverse_encoder_direction_is_corrected_behind_the_interface():
    """Decision 53: values at the interface are in axis coordinates; the simulated machine is wired
    consistently, so an inverted encoder shows the same actual values."""
    inverse = EncoderSpec(**{**ANALOG.encoder.__dict__, "inverse_direction": True})
    rigs = [Rig(ANALOG), Rig(DriveSpec(**{**ANALOG.__dict__, "encoder": inverse}))]
    for rig in rigs:
        rig.ch.set_enable(True, 0.0)
        rig.run(0.2, speed=5.0)
    assert rigs[0].position == rigs[1].position > 0.0


def test_kernel_set_actual_re_references_without_moving_the_load():
    rig = Rig(ANALOG)
    rig.ch.set_enable(True, 0.0)
    rig.run(0.1, speed=5.0)
    mech = rig.ch.mechanical_position()
    rig.ch.set_actual(rig.bank, 100.0)
    assert rig.position == 100.0
    assert rig.ch.mechanical_position() == mech
    rig.run(0.1, speed=5.0)
    assert rig.position == pytest.approx(100.5, abs=2 / 1024)


def test_kernel_profidrive_drive_is_ready_after_its_switch_on_sequence():
    rig = Rig(DriveSpec(**{**ANALOG.__dict__, "interface": SetpointInterface.PROFIDRIVE, "telegram": 3}))
    rig.ch.set_enable(True, 0.0)
    assert not rig.ch.ready(0.0)             # S1 -> S2 -> S3 -> S4 takes servo cycles
    rig.run(0.01)
    assert rig.ch.ready(rig.t)
    out, _ = rig.ch.telegrams()
    assert int(out.STW1) & 0x000F == 0x000F  # ON, no coast stop, no quick stop, enable operation


# --- drives that follow a position setpoint ------------------------------------------------------------
def test_kernel_stepper_position_is_whole_pulses_and_reconfigure_changes_the_pulse_length():
    spec = DriveSpec(actuator=ActuatorKind.PULSE, interface=SetpointInterface.PULSES, length_per_revolution=10.0,
                     pulses_per_revolution=400)
    rig = Rig(spec)
    rig.cycle(position=1.01)
    assert rig.position == pytest.approx(1.0, abs=1e-12)          # 10 / 400 = 0.025 per pulse: 40 pulses
    rig.ch.reconfigure(DriveSpec(**{**spec.__dict__, "pulses_per_revolution": 1000}))
    rig.cycle(position=1.013)
    assert rig.position == pytest.approx(1.01, abs=1e-12)         # 0.01 per pulse: 101 pulses
    assert not rig.ch.communication_ok                            # a pulse output is no bus


def test_kernel_ideal_drive_actual_value_is_the_setpoint():
    rig = Rig(DriveSpec(actuator=ActuatorKind.IDEAL, interface=SetpointInterface.NONE))
    rig.ch.set_enable(True, 0.0)
    assert rig.ch.ready(0.0)
    rig.cycle(position=1.2345678)
    assert rig.position == 1.2345678


# --- the simulated machine ------------------------------------------------------------------------------
def test_kernel_plant_wires_the_switches_and_the_ready_signal_of_its_spec():
    rig = Rig(ANALOG)
    inputs = DigitalInputs()
    plant = Plant(inputs)
    spec = PlantSpec(switches=(SwitchSpec("I0.0", low=0.5, name="high limit"),
                               SwitchSpec("I0.1", high=-1.0, active_high=False)), ready_input="I0.2")
    plant.wire_axis(spec, rig.ch, 0.0)
    assert [inputs.level(a) for a in ("I0.0", "I0.1", "I0.2")] == [False, True, False]
    rig.ch.set_enable(True, 0.0)
    rig.run(0.2, speed=5.0)                    # the load reaches 1.0 (> 0.5)
    plant.update(rig.t)
    assert [inputs.level(a) for a in ("I0.0", "I0.1", "I0.2")] == [True, True, True]


# --- the kernel's spec builder --------------------------------------------------------------------------
def params(changes: dict | None = None) -> dict:
    """Kernel parameters with the start values of the S7-1200 V6 TO data block (§12.9) and plcmotion's plant
    defaults, with ``changes`` (dotted tag paths) applied."""
    p = {
        "Actor.Type": 1, "Actor.Interface.Telegram": 3, "Actor.DriveParameter.ReferenceSpeed": 3000.0,
        "Actor.DriveParameter.MaxSpeed": 3000.0, "Actor.DriveParameter.PulsesPerDriveRevolution": 1000,
        "Actor.Interface.DriveReadyInput": "", "Simulation.Mode": 0, "Mechanics.LeadScrew": 10.0,
        "Sensor[1].Type": 0, "Sensor[1].InverseDirection": False, "Sensor[1].System": 1,
        "Sensor[1].MountingMode": 0, "Sensor[1].Interface.Type": 0, "Sensor[1].Parameter.Resolution": 0.001,
        "Sensor[1].Parameter.StepsPerRevolution": 2048, "Sensor[1].Parameter.FineResolutionXist1": 11,
        "Sensor[1].Parameter.FineResolutionXist2": 9, "Sensor[1].Parameter.DeterminableRevolutions": 1,
        "Sensor[1].Parameter.DistancePerRevolution": 100.0,
        "Sensor[1].ActiveHoming.DigitalInputAddress": "", "Sensor[1].ActiveHoming.SwitchLevel": True,
        "Sensor[1].PassiveHoming.DigitalInputAddress": "", "Sensor[1].PassiveHoming.SwitchLevel": True,
        "PositionLimits_HW.MinSwitchAddress": "", "PositionLimits_HW.MinSwitchLevel": False,
        "PositionLimits_HW.MaxSwitchAddress": "", "PositionLimits_HW.MaxSwitchLevel": False,
        "Plant.SpeedTimeConstant": 0.002, "Plant.ReadyDelay": 0.0, "Plant.OffRampTime": 0.1,
        "Plant.InitialPosition": 0.0, "Plant.HWLimitMinPosition": None, "Plant.HWLimitMaxPosition": None,
        "Plant.HomingSwitchPosition": None, "Plant.HomingSwitchLength": 10.0, "Plant.HomingSwitchPeriod": None,
        "Plant.ZeroMarkDistance": None, "Plant.ZeroMarkOffset": 0.0,
    }
    for path, value in (changes or {}).items():
        assert path in p, path
        p[path] = value
    return p


def test_kernel_builder_profidrive_drive_with_encoder_on_the_motor_shaft():
    spec = drive_spec(params({"Mechanics.LeadScrew": 5.0, "Sensor[1].Parameter.StepsPerRevolution": 1000,
                                "Sensor[1].Parameter.FineResolutionXist1": 2, "Sensor[1].Interface.Type": 2,
                                "Actor.DriveParameter.MaxSpeed": 6000.0, "Plant.ReadyDelay": 0.25}))
    assert (spec.actuator, spec.interface, spec.telegram) == (ActuatorKind.SPEED_SERVO,
                                                              SetpointInterface.PROFIDRIVE, 3)
    assert spec.reference_speed == 3000.0 and spec.max_speed == 6000.0 and spec.ready_delay == 0.25
    # on the motor shaft the encoder turns once per lead: 5 units / (1000 marks * 2^2) = 0.00125
    assert spec.encoder.increment == pytest.approx(0.00125, rel=1e-15)
    assert spec.encoder.interface is EncoderInterface.DRIVE_TELEGRAM
    assert spec.max_velocity == pytest.approx(6000.0 / 60.0 * 5.0)   # 500 units/s
    assert spec.encoder.kind is EncoderKind.INCREMENTAL and spec.encoder.determinable_revolutions == 0


def test_kernel_builder_external_rotary_and_linear_encoders():
    ext = drive_spec(params({"Sensor[1].MountingMode": 2, "Sensor[1].Parameter.DistancePerRevolution": 80.0,
                               "Sensor[1].Parameter.StepsPerRevolution": 500,
                               "Sensor[1].Parameter.FineResolutionXist1": 3}))
    # an external encoder turns once per its own distance: 80 / (500 * 8) = 0.02, the lead does not count
    assert ext.encoder.increment == pytest.approx(0.02, rel=1e-15)
    lin = drive_spec(params({"Sensor[1].System": 0, "Sensor[1].Parameter.Resolution": 0.004,
                               "Sensor[1].Parameter.FineResolutionXist1": 2}))
    assert not lin.encoder.rotary and lin.encoder.increment == pytest.approx(0.001, rel=1e-15)


def test_kernel_builder_absolute_encoder_knows_its_revolutions():
    spec = drive_spec(params({"Sensor[1].Type": 1, "Sensor[1].Parameter.DeterminableRevolutions": 4096,
                                "Sensor[1].InverseDirection": True}))
    assert spec.encoder.kind is EncoderKind.ABSOLUTE and spec.encoder.absolute
    assert spec.encoder.determinable_revolutions == 4096 and spec.encoder.inverse_direction
    cyclic = drive_spec(params({"Sensor[1].Type": 2}))
    assert cyclic.encoder.kind is EncoderKind.CYCLIC_ABSOLUTE


def test_kernel_builder_pulse_analog_and_simulated_drives():
    pto = drive_spec(params({"Actor.Type": 2, "Actor.DriveParameter.PulsesPerDriveRevolution": 400}))
    assert pto.actuator is ActuatorKind.PULSE and pto.interface is SetpointInterface.PULSES
    assert pto.pulse_length == pytest.approx(10.0 / 400)
    analog = drive_spec(params({"Actor.Type": 0}))
    assert analog.actuator is ActuatorKind.SPEED_SERVO and analog.interface is SetpointInterface.ANALOG
    sim = drive_spec(params({"Simulation.Mode": 1}))
    assert sim.actuator is ActuatorKind.IDEAL


def test_kernel_builder_plant_switches_and_ready_input():
    spec = drive_spec(params({
        "Plant.HWLimitMinPosition": -100.0, "PositionLimits_HW.MinSwitchAddress": "I0.0",
        "PositionLimits_HW.MinSwitchLevel": False,
        "Plant.HWLimitMaxPosition": 100.0,                          # no input wired: no switch
        "Plant.HomingSwitchPosition": 50.0, "Plant.HomingSwitchLength": 4.0,
        "Sensor[1].ActiveHoming.DigitalInputAddress": "I0.2", "Sensor[1].PassiveHoming.DigitalInputAddress": "I0.2",
        "Actor.Interface.DriveReadyInput": "I1.0", "Plant.InitialPosition": 7.5, "Plant.SpeedTimeConstant": 0.01}))
    plant = spec.plant
    assert plant.switches == (SwitchSpec("I0.0", -math.inf, -100.0, False, "low hardware limit switch"),
                              SwitchSpec("I0.2", 50.0, 54.0, True, "homing switch", None))
    assert plant.ready_input == "I1.0"
    assert plant.initial_position == 7.5 and plant.speed_time_constant == 0.01
