"""The runtime kernel: virtual time, cycle order, programs, STOP on a faulty program, determinism."""
from __future__ import annotations

import math

import pytest

from plcmotion import ConfigurationError, Controller, ControllerStopped, ProgramErrorWarning, RunTimeout, TagAccessError
from plcmotion.s7_1200 import MC_MoveRelative, MC_Power


def test_kernel_cycles_and_virtual_time():
    ctl = Controller(servo_cycle=0.001, app_cycle=0.004)
    calls = []
    servo = []
    ctl.program(lambda: calls.append(ctl.time))
    ctl.on_post_servo(servo.append)
    ctl.step()
    ctl.step()
    assert calls == [0.0, 0.004]                     # programs run at the start of each application cycle
    assert servo == pytest.approx([0.001, 0.002, 0.003, 0.004, 0.005, 0.006, 0.007, 0.008])
    assert ctl.time == pytest.approx(0.008)
    ctl.run(0.1)
    assert ctl.time == pytest.approx(0.108)


def test_kernel_step_without_programs_runs_only_the_servo_cycles():
    """A controlled shutdown lets the stop ramps run out while no program commands the axes again."""
    ctl = Controller(servo_cycle=0.001, app_cycle=0.004)
    calls, servo = [], []
    ctl.program(lambda: calls.append(ctl.time))
    ctl.on_post_servo(servo.append)
    ctl.step()
    ctl.step(programs=False)
    ctl.step()
    assert calls == [0.0, 0.008] and len(servo) == 12 and ctl.app_cycles == 3
    assert ctl.time == pytest.approx(0.012)


@pytest.mark.parametrize("servo, app", [(0.001, 0.0025), (0.0, 0.004), (0.001, -1.0), (float("nan"), 0.004)])
def test_kernel_invalid_cycles_rejected(servo, app):
    with pytest.raises(ValueError):
        Controller(servo_cycle=servo, app_cycle=app)


def test_kernel_run_until_returns_time_and_times_out():
    ctl = Controller()
    t = ctl.run_until(lambda: ctl.time >= 0.05, timeout=1.0)
    assert t == pytest.approx(0.052)
    with pytest.raises(RunTimeout, match="not met within 0.1 s"):
        ctl.run_until(lambda: False, timeout=0.1)


def test_kernel_faulty_program_stops_controller_and_disables_axes():
    """A program that raises puts the controller in STOP with the reason; TOs are disabled (S7-1200 V6 §2.2.7.4)."""
    ctl = Controller()
    axis = ctl.add_positioning_axis("Axis_1")
    power = MC_Power()
    ticks = []

    @ctl.program
    def main():
        power(Axis=axis, Enable=True)
        ticks.append(ctl.time)
        if ctl.time > 0.02:
            raise ZeroDivisionError("boom")

    ctl.run(0.02)
    assert axis.StatusBits.Enable
    with pytest.warns(ProgramErrorWarning, match="STOP.*ZeroDivisionError: boom"):
        ctl.run(0.02)
    assert ctl.mode == "STOP"
    assert "ZeroDivisionError: boom" in ctl.stop_reason and "main" in ctl.stop_reason
    assert not axis.StatusBits.Enable
    n = len(ticks)
    ctl.run(0.02)                                        # STOP: programs no longer run, servo cycles do
    assert len(ticks) == n
    with pytest.raises(ControllerStopped, match="boom"):
        ctl.run_until(lambda: False, timeout=1.0)
    ctl.start()
    assert ctl.mode == "RUN" and ctl.stop_reason is None


def test_kernel_unknown_instruction_input_is_a_program_error():
    ctl = Controller()
    axis = ctl.add_positioning_axis("Axis_1")
    move = MC_MoveRelative()

    @ctl.program
    def main():
        move(Axis=axis, Execute=True, Distanse=10.0)

    with pytest.warns(ProgramErrorWarning, match="Distanse"):
        ctl.step()
    assert ctl.mode == "STOP" and "Distanse" in ctl.stop_reason


def _trace_run(servo_type: int) -> list[tuple[float, ...]]:
    ctl = Controller()
    axis = ctl.add_positioning_axis("Axis_1", {"Actor": {"Type": servo_type},
                                               "DynamicDefaults": {"Jerk": 1000.0}})
    power, move = MC_Power(), MC_MoveRelative()
    rows = []

    @ctl.program
    def main():
        power(Axis=axis, Enable=True)
        move(Axis=axis, Execute=power.Status and not move.Done, Distance=37.5, Velocity=40.0)

    ctl.on_post_servo(lambda t: rows.append((t, axis.Position, axis.Velocity, axis.ActualPosition,
                                             axis.ActualVelocity)))
    ctl.run(3.0)
    return rows


@pytest.mark.parametrize("actor", [1, 2])
def test_kernel_same_program_same_trace_bit_for_bit(actor):
    a, b = _trace_run(actor), _trace_run(actor)
    assert len(a) == 3000
    assert a == b                                      # exact float equality, not approx
    assert all(math.isfinite(x) for row in a for x in row)


def test_kernel_axis_configuration_errors_name_path_value_and_range():
    ctl = Controller()
    with pytest.raises(ConfigurationError) as info:
        ctl.add_positioning_axis("Axis_1", {"DynamicLimits": {"MaxVelocity": -5.0},
                                            "DynamicDefaults": {"Jerk": "fast"}, "Modulo": {"Lenght": 1.0}})
    msg = str(info.value)
    assert "DynamicLimits.MaxVelocity = -5.0" in msg and "(0.0, 1000000000000.0]" in msg
    assert "DynamicDefaults.Jerk = 'fast'" in msg
    assert "Modulo.Lenght" in msg and "Modulo.Length" in msg       # suggestion
    assert len(info.value.issues) == 3
    with pytest.raises(ValueError, match="identifier"):
        ctl.add_positioning_axis("Axis 1")


def test_kernel_tag_access_by_attribute_and_path():
    """Tags of S7-1200 V6 §12.9 read as attributes and by path; access rights are enforced."""
    ctl = Controller()
    axis = ctl.add_positioning_axis("Axis_1", {"DynamicDefaults": {"Jerk": 1234.0},
                                               "Sensor[1]": {"ActiveHoming": {"Mode": 2}}})
    assert axis.DynamicDefaults.Jerk == 1234.0 == axis.tag("DynamicDefaults.Jerk")
    assert axis.Sensor[1].ActiveHoming.Mode == 2 == axis.tag("Sensor.Sensor[1].ActiveHoming.Mode")
    assert axis.Sensor.Sensor[1].ActiveHoming.SideInput is False
    assert axis.tag("StatusBits.Enable") is False and axis.StatusBits.Done is True
    assert axis.DynamicLimits.MaxVelocity == 250.0                 # start value of §12.9.10
    axis.DynamicDefaults.Acceleration = 20.0                        # RW
    assert axis.DynamicDefaults.Acceleration == 20.0
    with pytest.raises(TagAccessError, match="MC_WriteParam"):
        axis.DynamicLimits.MaxVelocity = 100.0                      # R / WP
    with pytest.raises(TagAccessError):
        axis.StatusBits.Enable = True
    with pytest.raises(AttributeError, match="did you mean"):
        axis.DynamicDefaults.Jerck  # noqa: B018
    with pytest.raises(KeyError):
        axis.tag("StatusBits.Enabled")
