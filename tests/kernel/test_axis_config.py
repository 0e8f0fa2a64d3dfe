"""The neutral axis configuration (issue 9 item 1): what the builder makes of the kernel parameters, when an
axis's configuration follows a written tag, and that the kernel reads it instead of tag paths.

The expected values come from the parameter documentation (start values and meanings of the kernel's
parameter set, S7-1200 Motion Control V6 §12.9 and the §5.4 configuration dialogs), worked out by hand.
"""
from __future__ import annotations

import ast
import math
import pathlib
import re

import pytest

from plcmotion.drives.spec import ActuatorKind, EncoderInterface, EncoderKind
from plcmotion.kernel import Controller
from plcmotion.kernel.axis_config import AxisConfig
from plcmotion.s7_1200.technology import parameters as P
from plcmotion.s7_1200.technology.builder import axis_config
from plcmotion.s7_1500.technology import builder as B1500
from plcmotion.s7_1500.technology.parameters import S7_1500

KERNEL = pathlib.Path(__file__).resolve().parents[2] / "src" / "plcmotion" / "kernel"


def params(**values):
    """Kernel parameters: the start values with ``values`` (dotted paths, ``__`` for ``.``) over them."""
    p = P.defaults()
    for key, value in values.items():
        path = key.replace("__", ".").replace("Sensor1", "Sensor[1]")
        assert path in p, path
        p[path] = value
    return p


PROFIDRIVE = dict(Actor__Type=1, DynamicLimits__MinVelocity=0.0, Sensor1__Interface__Type=2)


# --- the builder --------------------------------------------------------------------------------------------
def test_kernel_start_values_of_a_pulse_axis():
    c = axis_config(P.defaults())
    assert isinstance(c, AxisConfig)
    assert c.units.length == "mm"                                   # LengthUnit 1013
    assert c.drive.actuator is ActuatorKind.PULSE                   # Actor.Type 2: pulse output
    assert (c.limits.max_velocity, c.limits.start_stop_velocity) == (250.0, 10.0)
    assert (c.defaults.acceleration, c.defaults.deceleration, c.defaults.emergency_deceleration) == (48.0, 48.0, 120.0)
    assert c.defaults.jerk == 192.0
    assert not c.modulo.enabled and (c.modulo.start, c.modulo.length) == (0.0, 360.0)
    assert not c.software_limits.enabled
    assert (c.software_limits.minimum, c.software_limits.maximum) == (-10000.0, 10000.0)
    assert not c.hardware_limits.enabled and c.hardware_limits.min_input == c.hardware_limits.max_input == ""
    assert (c.position_control.kv, c.position_control.precontrol) == (10.0, 100.0)
    fe = c.following_error
    assert fe.enabled and (fe.min_value, fe.max_value, fe.min_velocity) == (10.0, 100.0, 10.0)
    assert (c.positioning.tolerance_time, c.positioning.min_dwell_time, c.positioning.window) == (1.0, 0.1, 1.0)
    assert (c.standstill.velocity_threshold, c.standstill.min_dwell_time) == (5.0, 0.01)
    assert c.pulse_output.slice_time == pytest.approx(0.002)        # PTOSliceTime 2 ms
    assert c.homing.approach_positive and (c.homing.approach_velocity, c.homing.referencing_velocity) == (200.0, 40.0)
    assert c.signals.enable_output == c.signals.ready_input == ""


def test_kernel_an_axis_without_the_extended_limits_has_none():
    """The S7-1200 parameter set has no current velocity limit, no maximum acceleration/deceleration/jerk, no
    velocity override, no extrapolation and no cross-PLC output."""
    c = axis_config(P.defaults())
    assert c.limits.velocity is c.limits.max_acceleration is c.limits.max_deceleration is c.limits.max_jerk is None
    assert c.defaults.velocity_override is None and c.following_error.warning_level is None
    assert c.extrapolation is None
    assert not c.leading_value_output.enabled and c.leading_value_output.local_delay_time == 0.0


def test_kernel_a_modulo_profidrive_axis_in_degrees():
    c = axis_config(params(**PROFIDRIVE, Units__LengthUnit=1005, Modulo__Enable=True, Modulo__StartValue=-180.0,
                           Modulo__Length=360.0, Sensor1__Type=1, Sensor1__Parameter__DeterminableRevolutions=4096,
                           PositionControl__Kv=40.0, PositionControl__Kpc=80.0))
    assert c.units.length == "°"
    assert c.modulo.enabled and (c.modulo.start, c.modulo.length) == (-180.0, 360.0)
    assert c.drive.actuator is ActuatorKind.SPEED_SERVO
    assert c.drive.encoder.kind is EncoderKind.ABSOLUTE and c.drive.encoder.determinable_revolutions == 4096
    assert c.drive.encoder.interface is EncoderInterface.DRIVE_TELEGRAM
    assert c.limits.start_stop_velocity == 0.0
    assert (c.position_control.kv, c.position_control.precontrol) == (40.0, 80.0)


def test_kernel_switches_homing_and_drive_signals():
    c = axis_config(params(PositionLimits_HW__Active=True, PositionLimits_HW__MinSwitchAddress="I0.1",
                           PositionLimits_HW__MaxSwitchAddress="I0.2", PositionLimits_HW__MaxSwitchLevel=True,
                           Sensor1__ActiveHoming__DigitalInputAddress="I0.3", Sensor1__ActiveHoming__SwitchLevel=False,
                           Sensor1__ActiveHoming__SideInput=True, Sensor1__ActiveHoming__HomePositionOffset=2.5,
                           Sensor1__PassiveHoming__DigitalInputAddress="I0.4", Homing__ApproachDirection=False,
                           Homing__AutoReversal=True, Actor__Interface__DriveReadyInput="I1.0",
                           Actor__Interface__EnableDriveOutput="Q0.0", Actor__Interface__PTO=2, Actor__DirectionMode=1))
    hw = c.hardware_limits
    assert hw.enabled and (hw.min_input, hw.max_input) == ("I0.1", "I0.2")
    assert (hw.min_active_high, hw.max_active_high) == (False, True)    # FALSE: NC contact, TRUE: NO contact
    h = c.homing
    assert not h.approach_positive and h.auto_reversal
    assert (h.active.input, h.active.active_high, h.active.upper_side, h.active.home_offset) == ("I0.3", False, True, 2.5)
    assert (h.passive.input, h.passive.active_high, h.passive.upper_side) == ("I0.4", True, False)
    assert h.active.mode == h.passive.mode == 2                          # homing via digital input
    assert (c.signals.ready_input, c.signals.enable_output) == ("I1.0", "Q0.0")
    assert (c.pulse_output.generator, c.pulse_output.direction_mode) == (2, 1)


@pytest.mark.parametrize("jerk,limited", [(0.0, False), (1e-9, False), (2e-9, True), (192.0, True)])
def test_kernel_jerk_limit_of_a_drive_with_position_control_s5_4_4_4(jerk, limited):
    """§5.4.4.4: a jerk above 1e-9 switches the jerk limit on; without it motions are planned jerk-free."""
    c = axis_config(params(**PROFIDRIVE, DynamicDefaults__Jerk=jerk))
    assert c.defaults.jerk == (jerk if limited else math.inf)


@pytest.mark.parametrize("jerk,limited", [(3.9e-5, False), (4.0e-5, True)])
def test_kernel_jerk_limit_of_a_pulse_axis_s5_4_4_4(jerk, limited):
    """§5.4.4.4: on a pulse axis a jerk below 0.004 pulses/s^3 switches the limit off; with 10 mm per motor
    revolution and 1000 pulses per revolution one pulse is 0.01 mm, so the threshold is 4e-5 mm/s^3."""
    c = axis_config(params(DynamicDefaults__Jerk=jerk))
    assert c.defaults.jerk == (jerk if limited else math.inf)


def test_kernel_extended_limits_extrapolation_and_leading_value_output():
    """The S7-1500 axis has them (S7-1500T V5 §A.1.9, §A.1.10, §A.1.16, §A.1.17, §A.1.24)."""
    p = S7_1500.defaults()
    p.update({"DynamicLimits.Velocity": 80.0, "DynamicLimits.MaxAcceleration": 900.0,
              "DynamicLimits.MaxDeceleration": 800.0, "DynamicLimits.MaxJerk": 0.0, "Override.Velocity": 50.0,
              "FollowingError.WarningLevel": 90.0,
              "Extrapolation.PositionFilter.T1": 0.001, "Extrapolation.PositionFilter.T2": 0.002,
              "Extrapolation.VelocityFilter.T1": 0.003, "Extrapolation.VelocityFilter.T2": 0.004,
              "Extrapolation.VelocityTolerance.Range": 2.0, "Extrapolation.Hysteresis.Value": 0.5,
              "Extrapolation.FollowingAxisDependentTime": 0.006,
              "Extrapolation.Settings.SystemDefinedExtrapolation": 1,
              "Extrapolation.Settings.ExtrapolatedVelocityMode": 0,
              "CrossPlcSynchronousOperation.Interface[1].EnableLeadingValueOutput": True,
              "CrossPlcSynchronousOperation.LocalLeadingValueDelayTime": 0.01})
    c = B1500.axis_config(p)
    assert (c.limits.velocity, c.limits.max_acceleration, c.limits.max_deceleration) == (80.0, 900.0, 800.0)
    assert c.limits.max_jerk == 0.0
    assert c.defaults.velocity_override == 50.0 and c.following_error.warning_level == 90.0
    x = c.extrapolation
    assert (x.position_filter_t1, x.position_filter_t2, x.velocity_filter_t1, x.velocity_filter_t2) == \
        (0.001, 0.002, 0.003, 0.004)
    assert (x.velocity_tolerance, x.hysteresis, x.following_axis_time) == (2.0, 0.5, 0.006)
    assert x.include_leading_axis_time and not x.differentiated_velocity
    assert c.leading_value_output.enabled and c.leading_value_output.local_delay_time == 0.01
    s = B1500.source_config(p)                    # the same leading value part for an encoder
    assert (s.modulo, s.extrapolation, s.leading_value_output) == (c.modulo, c.extrapolation, c.leading_value_output)


def test_kernel_the_config_names_real_tags_for_its_faults():
    c = axis_config(P.defaults())
    assert c.tag_names and all(c.tag_name(f) in P.SCHEMA for f in c.tag_names)


def test_kernel_the_config_is_a_value():
    c = axis_config(P.defaults())
    with pytest.raises(AttributeError):
        c.modulo.enabled = True                   # frozen: nobody changes it behind the axis's back
    assert axis_config(P.defaults()) == c


# --- when the config of an axis changes ---------------------------------------------------------------------
def _axis(**values):
    ctl = Controller()
    flat = {k.replace("__", ".").replace("Sensor1", "Sensor[1]"): v for k, v in values.items()}
    return ctl, ctl.add_positioning_axis("ax", flat)


def test_kernel_a_servo_axis_takes_a_written_tag_at_the_next_servo_cycle_s12_9():
    """Effective code 10 (PROFIdrive/analog): the next servo cycle after the write."""
    ctl, ax = _axis(**PROFIDRIVE)
    before = ax.config
    ctl.step()
    assert ax.config is before                    # nothing written: the same object, not rebuilt per cycle
    ax.write_tag("DynamicDefaults.Acceleration", 30.0)
    assert ax.config.defaults.acceleration == 48.0
    ctl.step()
    assert ax.config.defaults.acceleration == 30.0
    assert ax.config.defaults.deceleration == 48.0


def test_kernel_a_pulse_axis_takes_a_parameter_at_enable_s12_9():
    """Effective code 2 (PTO): a value written with MC_WriteParam counts from the next enable."""
    ctl, ax = _axis()
    ax.write_tag("DynamicLimits.MaxVelocity", 100.0, via_write_param=True)
    for _ in range(5):
        ctl.step()
    assert ax.config.limits.max_velocity == 250.0
    owner = object()
    assert ax.power(owner, True, 1, 0) is None
    assert ax.config.limits.max_velocity == 100.0


def test_kernel_an_invalid_value_leaves_the_config_as_it_was():
    ctl, ax = _axis(**PROFIDRIVE)
    ax.write_tag("DynamicDefaults.Deceleration", -1.0)       # stored; invalid when it takes effect
    ctl.step()
    assert ax.alarms                                          # the configuration error of that tag
    assert ax.config.defaults.deceleration == 48.0


def test_kernel_a_restart_returns_to_the_start_values():
    ctl, ax = _axis(**PROFIDRIVE)
    ax.write_tag("PositionLimits_SW.MaxPosition", 500.0)
    ctl.step()
    assert ax.config.software_limits.maximum == 500.0
    assert ax.restart() is None
    assert ax.config.software_limits.maximum == 10000.0


# --- the kernel reads no tag path ------------------------------------------------------------------------------
#: a vendor tag path: dotted PascalCase names, optionally indexed (``Modulo.Enable``, ``Sensor[1].Type``)
TAG_PATH = re.compile(r"^[A-Z][A-Za-z0-9_]*(\[\d+\])?(\.[A-Z][A-Za-z0-9_]*(\[\d+\])?)+$")

#: kernel modules that may still name tags, and why
ALLOWED = {
    "plant_schema.py": "the simulated machine's parameters (Plant.*): no family's tags, every family's schema has them",
}


def _tag_paths(source: str) -> list[tuple[int, str]]:
    hits = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.JoinedStr):
            parts = [v.value for v in node.values if isinstance(v, ast.Constant)]
            if not any(ch.isalpha() for part in parts for ch in part):
                continue                           # e.g. an address f"{area}{byte}.{bit}"
            text = "".join(v.value if isinstance(v, ast.Constant) else "X" for v in node.values)
        elif isinstance(node, ast.Constant) and isinstance(node.value, str):
            text = node.value
        else:
            continue
        if any(ch.isspace() for ch in text):
            continue                               # prose (a docstring, a message), not a key
        if TAG_PATH.match(text.split(":")[0]):     # also "<tag>:<reason>" fault details
            hits.append((node.lineno, text))
    return sorted(hits)


def test_kernel_the_tag_path_check_finds_tag_paths():
    found = _tag_paths('x = e["Modulo.Enable"]\ny = f"Sensor[1].{kind}Homing.Mode"\nz = "A.B:rule:x"')
    assert {(1, "Modulo.Enable"), (2, "Sensor[1].XHoming.Mode"), (3, "A.B:rule:x")} <= set(found)
    assert _tag_paths('a = f"{kind}{byte}.{bit}"\nb = "plcmotion.kernel"\nc = "Ends here. Then A.B: says"') == []


def test_kernel_converted_kernel_modules_name_no_tag_path():
    found = {}
    for path in sorted(KERNEL.glob("*.py")):
        if path.name in ALLOWED:
            continue
        hits = _tag_paths(path.read_text(encoding="utf-8"))
        if hits:
            found[path.name] = hits
    assert not found, f"kernel modules that read tag paths (use axis.config): {found}"


def test_kernel_the_allowed_list_is_not_stale():
    """A module allowed to name tags does name one (else it belongs to the checked ones); one that left the
    kernel (moved into its family) needs no entry any more."""
    for name in ALLOWED:
        path = KERNEL / name
        if not path.exists():
            continue
        assert _tag_paths(path.read_text(encoding="utf-8")), f"{name} names no tag path any more: check it"
