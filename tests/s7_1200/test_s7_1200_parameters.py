"""MC_ChangeDynamic, MC_ReadParam and MC_WriteParam of the S7-1200 V6 (§11.1.10 - §11.1.12).

Manual rules checked here (S7-1200 Motion Control V6.0, seeds/000; V7 error list, seeds/004):
  §11.1.10.1 MC_ChangeDynamic: times -> DynamicDefaults tags with the relations of §5.4.4.4; Done at once,
             no Busy / CommandAborted (§9.5.2); aborts nothing, cannot be aborted; results outside the
             admissible range are the user's responsibility (they become configuration errors)
  §11.1.11.1 MC_ReadParam: continuous reading of the RP tags while Enable = TRUE
  §11.1.12.1 MC_WriteParam: RW tags at any time, WP tags only while the axis is disabled
  §12.8      16#840C..16#840F (16#0002, 16#000A; V7 16#0005), 16#8410 (16#0028, 16#0029, 16#002A, 16#002B,
             16#002C), 16#8411 (16#0002; V7 16#0005, 16#0006), 16#8208 / 16#8209 (16#0002, 16#000A),
             16#8408 (Axis)
  §12.9      access R / RW / WP / RP and effective codes: PROFIdrive next servo cycle (10), PTO at enable
             (1, 2), at the next motion command start (5), when a jog stops (6)
  §9.5.2     Done / Error latched while Execute is TRUE, otherwise shown for exactly one call
  §9.6       configuration errors 16#86xx at the triggering instruction and at MC_Power
"""
from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from plcmotion import Controller
from plcmotion.s7_1200 import (MC_ChangeDynamic, MC_MoveJog, MC_MoveRelative, MC_MoveVelocity, MC_Power,
                               MC_ReadParam, MC_Reset, MC_WriteParam)
from plcmotion.s7_1200.variables import Bool, DInt, Int, Real, UDInt

NAN, INF = math.nan, math.inf
DOCS = Path(__file__).resolve().parents[2] / "docs" / "instructions" / "parameters.md"

_DYN = {"Acceleration": 50.0, "Deceleration": 50.0, "EmergencyDeceleration": 500.0, "Jerk": 0.0}
PTO = {"Actor": {"Type": 2}, "DynamicLimits": {"MaxVelocity": 100.0, "MinVelocity": 1.0}, "DynamicDefaults": _DYN}
PD = {"Actor": {"Type": 1}, "DynamicLimits": {"MaxVelocity": 100.0}, "DynamicDefaults": _DYN}
CONFIGS = {"pto": PTO, "pd": PD}


# ----------------------------------------------------------------------------------------------------------
# harness: one controller, one axis; scan() calls the given instances once, then one application cycle
def make(kind: str = "pto", extra: dict | None = None):
    ctl = Controller(servo_cycle=0.001, app_cycle=0.004)
    cfg = dict(CONFIGS[kind]) if kind in CONFIGS else {}
    cfg.update(extra or {})
    return ctl, ctl.add_positioning_axis("Axis_1", cfg)


def enabled(kind: str = "pto", extra: dict | None = None):
    ctl, axis = make(kind, extra)
    power = MC_Power(Axis=axis, Enable=True)
    ctl.run_until(lambda: power().Status, timeout=2.0)
    return ctl, axis, power


def scan(ctl, *fbs):
    """One call of every instance (outputs copied right after the call), then one application cycle."""
    outs = []
    for fb in fbs:
        fb()
        outs.append(dict(fb.outputs))
    ctl.step()
    return outs if len(outs) != 1 else outs[0]


def moving(kind: str = "pto", velocity: float = 80.0):
    """Enabled axis accelerating towards ``velocity`` with MC_MoveVelocity (Execute held)."""
    ctl, axis, power = enabled(kind)
    mv = MC_MoveVelocity(Axis=axis, Execute=True, Velocity=velocity)
    for _ in range(3):
        scan(ctl, power, mv)
    assert mv.Busy and 0.0 < axis.Velocity < velocity
    return ctl, axis, power, mv


def dyn(axis, which: str = "cfg") -> dict[str, float]:
    values = getattr(axis, which)
    return {k.split(".")[1]: values[k] for k in values if k.startswith("DynamicDefaults.")}


def typed(data_type: str, value):
    return {"Bool": Bool, "Int": Int, "DInt": DInt, "UDInt": UDInt, "Real": Real}[data_type](value)


def assert_error(outputs: dict, error_id: int, error_info: int):
    assert outputs["Error"], outputs
    assert (outputs["ErrorID"], outputs["ErrorInfo"]) == (error_id, error_info), \
        f"16#{outputs['ErrorID']:04X}/16#{outputs['ErrorInfo']:04X}"


def change_all(**times) -> MC_ChangeDynamic:
    return MC_ChangeDynamic(ChangeRampUp=True, ChangeRampDown=True, ChangeEmergency=True, ChangeJerkTime=True,
                            **times)


# ==========================================================================================================
# typed variables (the PLC tags the VARIANT Value points to)
def test_s7_1200_variables_types_ranges_repr_equality():
    """Value of MC_ReadParam / MC_WriteParam is a VARIANT to a tag of BOOL, INT, DINT, UDINT or REAL (§11.1.12)."""
    assert Bool().value is False and Int().value == 0 and DInt().value == 0 and UDInt().value == 0
    assert Real().value == 0.0 and isinstance(Real().value, float)
    assert repr(Real(2.5)) == "Real(2.5)" and repr(Bool(True)) == "Bool(True)" and repr(Int(-3)) == "Int(-3)"
    assert Real(2.5) == 2.5 and DInt(7) == 7 and Bool(True) == True  # noqa: E712
    assert DInt(7) != Int(7) and DInt(7) == DInt(7) and Real(1) == Real(1.0)
    assert Real(3).value == 3.0 and isinstance(Real(3).value, float)
    assert Bool(np.bool_(True)).value is True and DInt(np.int64(5)).value == 5
    assert float(DInt(4)) == 4.0 and int(Real(4.7)) == 4 and [10, 20][Int(1)] == 20
    assert Int(-32768) == -32768 and Int(32767) == 32767
    assert DInt(-2 ** 31) == -2 ** 31 and DInt(2 ** 31 - 1) == 2 ** 31 - 1 and UDInt(2 ** 32 - 1) == 2 ** 32 - 1
    assert math.isnan(Real(NAN).value) and Real(INF).value == INF          # a REAL tag can hold NaN / inf
    for cls, bad in ((Int, 32768), (Int, -32769), (DInt, 2 ** 31), (UDInt, -1), (UDInt, 2 ** 32)):
        with pytest.raises(ValueError):
            cls(bad)
    for cls, bad in ((Bool, 1), (Bool, 0.0), (Int, 1.0), (DInt, True), (DInt, "1"), (Real, True), (Real, "1.0"),
                     (Real, None.__class__)):
        with pytest.raises(TypeError):
            cls(bad)
    v = DInt(1)
    with pytest.raises(TypeError):
        v.value = 2.0
    assert v == 1                                          # a rejected assignment leaves the value
    with pytest.raises(TypeError):
        hash(v)


# ==========================================================================================================
# MC_ChangeDynamic (§11.1.10)
def test_s7_1200_11_1_10_default_inputs_reproduce_default_dynamics():
    """§11.1.10.1 input defaults 5.00 / 5.00 / 2.00 / 0.25 s and §5.4.4.4 relations: with the default
    configuration (MaxVelocity 250, start/stop velocity 10, PTO) the result is the default dynamics
    Acceleration 48, Deceleration 48, EmergencyDeceleration 120, Jerk 192 (§12.9.11 start values)."""
    ctl, axis = make("default")
    assert axis.cfg["DynamicLimits.MaxVelocity"] == 250.0 and axis.cfg["DynamicLimits.MinVelocity"] == 10.0
    for path, value in (("Acceleration", 1.0), ("Deceleration", 2.0), ("EmergencyDeceleration", 3.0),
                        ("Jerk", 4.0)):
        setattr(axis.DynamicDefaults, path, value)
    cd = change_all(Axis=axis, Execute=True)
    assert (cd.RampUpTime, cd.RampDownTime, cd.EmergencyRampTime, cd.JerkTime) == (5.0, 5.0, 2.0, 0.25)
    out = scan(ctl, cd)
    assert out == {"Done": True, "Error": False, "ErrorID": 0, "ErrorInfo": 0}
    assert dyn(axis) == {"Acceleration": 48.0, "Deceleration": 48.0, "EmergencyDeceleration": 120.0, "Jerk": 192.0}


def test_s7_1200_11_1_10_profidrive_start_stop_velocity_is_zero():
    """§5.4.4.4: for PROFIdrive/analog drives the start/stop velocity is fixed at zero, so the ramp times
    refer to the full MaxVelocity: 100/5 = 20, 100/5 = 20, 100/2 = 50, jerk 20/0.25 = 80."""
    ctl, axis = make("pd")
    assert axis.cfg["DynamicLimits.MinVelocity"] == 0.0
    scan(ctl, change_all(Axis=axis, Execute=True))
    assert dyn(axis) == {"Acceleration": 20.0, "Deceleration": 20.0, "EmergencyDeceleration": 50.0, "Jerk": 80.0}


def test_s7_1200_11_1_10_only_selected_values_change():
    """§11.1.10.1: each Change* input selects one tag; the others keep their values."""
    ctl, axis = make("pto")                                  # MaxVelocity 100, start/stop 1 -> span 99
    before = dyn(axis)
    cd = MC_ChangeDynamic(Axis=axis, Execute=True, ChangeRampDown=True, RampDownTime=0.5, RampUpTime=-1.0)
    assert scan(ctl, cd)["Done"]
    assert dyn(axis) == dict(before, Deceleration=99.0 / 0.5)
    cd2 = MC_ChangeDynamic(Axis=axis, Execute=True, ChangeEmergency=True, EmergencyRampTime=0.1)
    assert scan(ctl, cd2)["Done"]
    assert dyn(axis) == dict(before, Deceleration=198.0, EmergencyDeceleration=pytest.approx(990.0))
    nothing = MC_ChangeDynamic(Axis=axis, Execute=True)
    assert scan(ctl, nothing)["Done"]                        # no Change* selected: Done, nothing written
    assert dyn(axis)["Deceleration"] == 198.0


def test_s7_1200_11_1_10_jerk_from_new_or_current_acceleration():
    """§5.4.4.4 smoothing time = Acceleration / Jerk (decision: the acceleration after this call -- the new
    one when RampUpTime is changed in the same call, otherwise the tag value)."""
    ctl, axis = make("pto")
    cd = MC_ChangeDynamic(Axis=axis, Execute=True, ChangeJerkTime=True, JerkTime=0.5)
    scan(ctl, cd)
    assert axis.cfg["DynamicDefaults.Jerk"] == 50.0 / 0.5                  # current acceleration 50
    both = MC_ChangeDynamic(Axis=axis, Execute=True, ChangeRampUp=True, RampUpTime=0.99, ChangeJerkTime=True,
                            JerkTime=0.5)
    scan(ctl, both)
    assert axis.cfg["DynamicDefaults.Acceleration"] == pytest.approx(100.0)
    assert axis.cfg["DynamicDefaults.Jerk"] == pytest.approx(200.0)        # from the new acceleration


def test_s7_1200_11_1_10_uses_tag_values_of_the_velocity_limits():
    """Decision: the conversion uses the values in the technology DB at the call -- including a WP change
    of MaxVelocity that takes effect only at the next enable (§12.9.10 code 2) -- so that the ramp times
    hold once the new limits are in effect."""
    ctl, axis = make("pto")
    wp = MC_WriteParam(Parameter=axis.ref("DynamicLimits.MaxVelocity"), Value=51.0, Execute=True)
    assert scan(ctl, wp)["Done"]
    assert axis.eff["DynamicLimits.MaxVelocity"] == 100.0 and axis.cfg["DynamicLimits.MaxVelocity"] == 51.0
    scan(ctl, MC_ChangeDynamic(Axis=axis, Execute=True, ChangeRampUp=True, RampUpTime=2.0))
    assert axis.cfg["DynamicDefaults.Acceleration"] == 25.0                # (51 - 1) / 2


@given(up=st.floats(1e-3, 1e3), down=st.floats(1e-3, 1e3), emergency=st.floats(1e-3, 1e3),
       jerk_time=st.floats(1e-3, 1e3))
def test_s7_1200_11_1_10_results_satisfy_the_5_4_4_4_relations(up, down, emergency, jerk_time):
    """§5.4.4.4: ramp time = (MaxVelocity - start/stop velocity) / value, smoothing time = Acceleration/Jerk
    hold for the written values, for any admissible input."""
    ctl, axis = make("pto")
    scan(ctl, change_all(Axis=axis, Execute=True, RampUpTime=up, RampDownTime=down, EmergencyRampTime=emergency,
                         JerkTime=jerk_time))
    d = dyn(axis)
    assert 99.0 / d["Acceleration"] == pytest.approx(up)
    assert 99.0 / d["Deceleration"] == pytest.approx(down)
    assert 99.0 / d["EmergencyDeceleration"] == pytest.approx(emergency)
    assert d["Acceleration"] / d["Jerk"] == pytest.approx(jerk_time)


TIME_INPUTS = [("ChangeRampUp", "RampUpTime", 0x840C), ("ChangeRampDown", "RampDownTime", 0x840D),
               ("ChangeEmergency", "EmergencyRampTime", 0x840E), ("ChangeJerkTime", "JerkTime", 0x840F)]
BAD_TIMES = [(NAN, 0x0002), (INF, 0x0002), (-INF, 0x0002), ("5", 0x0002), (True, 0x0002), (None, 0x0002),
             (0.0, 0x000A), (-0.0, 0x000A), (-1.0, 0x000A), (1.0000001e12, 0x0005), (1e300, 0x0005)]


@pytest.mark.parametrize("change,name,error_id", TIME_INPUTS, ids=[t[1] for t in TIME_INPUTS])
@pytest.mark.parametrize("value,error_info", BAD_TIMES, ids=[repr(b[0]) for b in BAD_TIMES])
def test_s7_1200_12_8_840C_840F_invalid_time_inputs(change, name, error_id, value, error_info):
    """§12.8 16#840C RampUpTime, 16#840D RampDownTime, 16#840E EmergencyRampTime, 16#840F JerkTime:
    16#0002 invalid number format, 16#000A value <= 0; V7 list 16#0005 value > 1.0E12 (printed under 16#840C,
    applied to all four).  Block parameter error: nothing is written, the axis carries on."""
    ctl, axis, power, mv = moving("pto")
    before = dyn(axis)
    cd = change_all(Axis=axis, Execute=True, **{name: value})
    out, mv_out = scan(ctl, cd, mv)
    assert_error(out, error_id, error_info)
    assert not out["Done"]
    assert dyn(axis) == before
    assert mv_out["Busy"] and not mv_out["Error"] and not power().Error


def test_s7_1200_12_8_840C_checks_in_input_order_and_only_selected_inputs():
    """Several invalid times: the first in parameter order is reported; an unselected time is not checked."""
    ctl, axis = make("pto")
    cd = MC_ChangeDynamic(Axis=axis, Execute=True, ChangeRampDown=True, RampDownTime=0.0, ChangeJerkTime=True,
                          JerkTime=NAN, RampUpTime=NAN)
    assert_error(scan(ctl, cd), 0x840D, 0x000A)
    ok = MC_ChangeDynamic(Axis=axis, Execute=True, RampUpTime=-1.0, RampDownTime=NAN, EmergencyRampTime=0.0,
                          JerkTime="x")
    assert scan(ctl, ok)["Done"]
    valid_limit = MC_ChangeDynamic(Axis=axis, Execute=True, ChangeRampUp=True, RampUpTime=1.0e12)
    assert scan(ctl, valid_limit)["Done"]                                  # 1.0E12 itself is admissible
    assert axis.cfg["DynamicDefaults.Acceleration"] == pytest.approx(99.0e-12)


def test_s7_1200_12_8_8208_velocity_span_not_positive():
    """§12.8 16#8208 "difference between maximum and start/stop velocity is invalid" (16#000A <= 0): the
    ramp times cannot be converted when MaxVelocity = start/stop velocity (a valid PTO configuration,
    §5.4.4.4 'maximum >= start/stop') or below it; nothing is written."""
    ctl, axis = make("pto", {"DynamicLimits": {"MaxVelocity": 100.0, "MinVelocity": 100.0}})
    before = dyn(axis)
    for change in ("ChangeRampUp", "ChangeRampDown", "ChangeEmergency"):
        cd = MC_ChangeDynamic(Axis=axis, Execute=True, ChangeJerkTime=True, **{change: True})
        assert_error(scan(ctl, cd), 0x8208, 0x000A)
    assert dyn(axis) == before
    jerk_only = MC_ChangeDynamic(Axis=axis, Execute=True, ChangeJerkTime=True, JerkTime=0.5)
    assert scan(ctl, jerk_only)["Done"]                                    # the jerk needs no velocity span
    assert axis.cfg["DynamicDefaults.Jerk"] == 100.0
    ctl2, axis2 = make("pto")
    wp = MC_WriteParam(Parameter=axis2.ref("DynamicLimits.MinVelocity"), Value=150.0, Execute=True)
    assert scan(ctl2, wp)["Done"]                                          # start/stop above max: span < 0
    assert_error(scan(ctl2, MC_ChangeDynamic(Axis=axis2, Execute=True, ChangeRampUp=True)), 0x8208, 0x000A)


def test_s7_1200_12_8_8208_velocity_span_invalid_number():
    """§12.8 16#8208/16#0002: a velocity limit in the DB that is not a number (white box: a corrupted DB value,
    MC_WriteParam itself refuses to write NaN)."""
    ctl, axis = make("pto")
    axis.cfg["DynamicLimits.MaxVelocity"] = NAN
    assert_error(scan(ctl, MC_ChangeDynamic(Axis=axis, Execute=True, ChangeRampUp=True)), 0x8208, 0x0002)


@pytest.mark.parametrize("acceleration,error_info", [(-1.0, 0x000A), (0.0, 0x000A), (NAN, 0x0002), (INF, 0x0002)])
def test_s7_1200_12_8_8209_invalid_acceleration_for_the_jerk(acceleration, error_info):
    """§12.8 16#8209 "invalid acceleration" (16#0002 / 16#000A): JerkTime is converted with the acceleration;
    an invalid Acceleration tag (a direct assignment, not yet effective) gives no jerk; nothing is written.
    With RampUpTime changed in the same call the new, valid acceleration is used."""
    ctl, axis = make("pto")
    axis.DynamicDefaults.Acceleration = acceleration
    jerk = axis.cfg["DynamicDefaults.Jerk"]
    cd = MC_ChangeDynamic(Axis=axis, Execute=True, ChangeJerkTime=True, ChangeRampDown=True, RampDownTime=1.0)
    assert_error(scan(ctl, cd), 0x8209, error_info)
    assert axis.cfg["DynamicDefaults.Jerk"] == jerk and axis.cfg["DynamicDefaults.Deceleration"] == 50.0
    fixed = MC_ChangeDynamic(Axis=axis, Execute=True, ChangeJerkTime=True, ChangeRampUp=True, RampUpTime=1.0)
    assert scan(ctl, fixed)["Done"]
    assert dyn(axis)["Acceleration"] == 99.0 and dyn(axis)["Jerk"] == 99.0 / 0.25


def test_s7_1200_12_8_840C_block_parameter_error_before_8208():
    """Decision 12: block parameter errors (16#84xx) before the conversion errors (16#82xx)."""
    ctl, axis = make("pto", {"DynamicLimits": {"MaxVelocity": 100.0, "MinVelocity": 100.0}})
    cd = MC_ChangeDynamic(Axis=axis, Execute=True, ChangeRampUp=True, RampUpTime=0.0)
    assert_error(scan(ctl, cd), 0x840C, 0x000A)


class _OtherTechnologyObject:
    """Stand-in for a technology object of another type (e.g. a command table): has a controller and tags."""

    def __init__(self, ctl):
        self.ctl = ctl

    def tag(self, path):  # pragma: no cover - never read
        return None


@pytest.mark.parametrize("axis_value,error_info", [(None, 0x001C), (3.0, 0x001C), ("Axis_1", 0x001C),
                                                   ("other_to", 0x001B)])
def test_s7_1200_12_8_8408_change_dynamic_invalid_axis(axis_value, error_info):
    """§12.8 16#8408: Axis is not a Motion Control technology DB (16#001C) or a technology object of another
    type (16#001B)."""
    ctl, _ = make("pto")
    axis_value = _OtherTechnologyObject(ctl) if axis_value == "other_to" else axis_value
    assert_error(scan(ctl, change_all(Axis=axis_value, Execute=True)), 0x8408, error_info)


def test_s7_1200_11_1_10_outputs_and_override():
    """§9.5.2: MC_ChangeDynamic completes at once -- no Busy, no CommandAborted output; Done TRUE in the
    call with the rising edge, latched while Execute stays TRUE.  §11.1.10.1 override: it aborts no running
    command and is not aborted by one."""
    ctl, axis, power, mv = moving("pd")
    cd = MC_ChangeDynamic(Axis=axis, ChangeRampUp=True, RampUpTime=4.0)
    assert set(cd.outputs) == {"Done", "Error", "ErrorID", "ErrorInfo"}
    assert not hasattr(cd, "Busy") and not hasattr(cd, "CommandAborted")
    cd.Execute = True
    outs = [scan(ctl, cd, mv) for _ in range(4)]
    assert all(o[0]["Done"] for o in outs)
    assert all(o[1]["Busy"] and not o[1]["CommandAborted"] for o in outs)
    assert not hasattr(cd, "Busy")
    halt_like = MC_MoveVelocity(Axis=axis, Execute=True, Velocity=10.0)
    o = scan(ctl, cd, halt_like, mv)
    assert o[0]["Done"] and o[2]["CommandAborted"]                        # only the motion command is aborted
    cd.Execute = False
    assert scan(ctl, cd) == {"Done": False, "Error": False, "ErrorID": 0, "ErrorInfo": 0}


@pytest.mark.parametrize("kind", ["pto", "pd"])
def test_s7_1200_11_1_10_results_outside_range_become_configuration_errors(kind):
    """§11.1.10.1 note: times whose results exceed the admissible limits are accepted (Done); the tag shows its
    configuration error when the value takes effect (§9.6: at the triggering instruction and MC_Power,
    emergency stop): PTO acceleration above 9.5E9 pulses/s^2 -> 16#8608/16#0003 at the next command start;
    PROFIdrive jerk above 1E12 -> 16#8614/16#001F at the next servo cycle."""
    ctl, axis, power = enabled(kind)
    if kind == "pto":
        cd = MC_ChangeDynamic(Axis=axis, Execute=True, ChangeRampUp=True, RampUpTime=1e-9)   # 9.9e10 > 9.5e7
        assert scan(ctl, cd, power)[0]["Done"]
        assert not power.Error and axis.eff["DynamicDefaults.Acceleration"] == 50.0
        mr = MC_MoveRelative(Axis=axis, Execute=True, Distance=10.0, Velocity=20.0)
        out = scan(ctl, mr, power)
        assert_error(out[0], 0x8608, 0x0003)
        assert_error(scan(ctl, power), 0x8608, 0x0003)
    else:
        cd = MC_ChangeDynamic(Axis=axis, Execute=True, ChangeJerkTime=True, JerkTime=1e-12)  # 5e13 > 1e12
        assert scan(ctl, cd, power)[0]["Done"]
        assert_error(scan(ctl, power), 0x8614, 0x001F)
    assert axis.StatusBits.Error and axis.ErrorBits.ConfigFault


def test_s7_1200_11_1_10_effective_pto_next_command_profidrive_next_servo_cycle():
    """§11.1.10.1 'For the effectiveness of the change, refer to the description of the tag' (§12.9.11):
    PROFIdrive: next servo cycle; PTO: next start of a motion command (code 5)."""
    ctl, axis, power, mv = moving("pd")
    scan(ctl, MC_ChangeDynamic(Axis=axis, Execute=True, ChangeRampUp=True, RampUpTime=10.0), mv)
    assert axis.eff["DynamicDefaults.Acceleration"] == 10.0 and axis.Acceleration == pytest.approx(10.0)
    ctl, axis, power, mv = moving("pto")
    cd = MC_ChangeDynamic(Axis=axis, Execute=True, ChangeRampUp=True, RampUpTime=9.9)
    for _ in range(3):
        scan(ctl, cd, mv)
        assert axis.eff["DynamicDefaults.Acceleration"] == 50.0 and axis.Acceleration == pytest.approx(50.0)
    mv2 = MC_MoveVelocity(Axis=axis, Execute=True, Velocity=90.0)
    scan(ctl, mv2)
    assert axis.eff["DynamicDefaults.Acceleration"] == 10.0 and axis.Acceleration == pytest.approx(10.0)


# ==========================================================================================================
# MC_WriteParam (§11.1.12)
def _current_value(axis, path: str):
    ref = axis.ref(path)
    value = axis.cfg[ref.path]
    return typed(ref.data_type, value if ref.data_type != "Real" else float(value))


def _other_value(axis, path: str):
    """A different admissible value of the tag's data type (flipped BOOL, halved REAL; integers kept)."""
    ref = axis.ref(path)
    value = axis.cfg[ref.path]
    if ref.data_type == "Bool":
        return Bool(not value)
    if ref.data_type == "Real":
        return Real(value * 0.5 if value else 1.0)
    return typed(ref.data_type, value)


def _paths(axis, access: str) -> list[str]:
    return [p for p in axis.tag_paths() if not axis.ref(p).status and axis.ref(p).access == access]


RW_TAGS = _paths(make("default")[1], "RW")
WP_TAGS = _paths(make("pd")[1], "WP")      # used on a PROFIdrive axis (Simulation.Mode: WP only for PTO, §12.9.19)
R_TAGS = _paths(make("default")[1], "R")


def test_s7_1200_12_9_tag_classes_as_printed():
    """§12.9.10 / §12.9.11 / §12.9.5: examples of each access class."""
    assert {"DynamicDefaults.Acceleration", "DynamicDefaults.Jerk", "PositionLimits_SW.Active",
            "Homing.ApproachVelocity", "Sensor[1].ActiveHoming.HomePositionOffset"} <= set(RW_TAGS)
    assert {"DynamicLimits.MaxVelocity", "DynamicLimits.MinVelocity", "Actor.DirectionMode", "Units.LengthUnit",
            "PositionControl.Kv", "Actor.DriveParameter.PulsesPerDriveRevolution"} <= set(WP_TAGS)
    assert {"Actor.Type", "Modulo.Enable", "Modulo.Length", "FollowingError.EnableMonitoring"} <= set(R_TAGS)


@pytest.mark.parametrize("path", RW_TAGS)
def test_s7_1200_11_1_12_rw_tags_written_any_time(path):
    """§12.9 legend RW: "can be written with MC_WriteParam" -- also while the axis is enabled and moving."""
    ctl, axis, power, mv = moving("pd")
    value = _other_value(axis, path)
    assert value != axis.cfg[axis.ref(path).path]
    wp = MC_WriteParam(Parameter=axis.ref(path), Value=value, Execute=True)
    out = scan(ctl, wp, mv, power)
    assert out[0] == {"Done": True, "Busy": False, "Error": False, "ErrorID": 0, "ErrorInfo": 0}
    assert axis.cfg[axis.ref(path).path] == value.value
    assert out[1]["Busy"] and not out[2]["Error"]


@pytest.mark.parametrize("path", WP_TAGS)
def test_s7_1200_11_1_12_wp_tags_only_while_disabled(path):
    """§11.1.12.1 requirements / §12.9 legend WP: writable with MC_WriteParam if the axis is disabled
    (MC_Power.Status = FALSE); otherwise 16#8410/16#002C "the axis is not disabled" and nothing is written."""
    ctl, axis, power = enabled("pd")
    value = _other_value(axis, path)
    before = axis.cfg[axis.ref(path).path]
    wp = MC_WriteParam(Parameter=axis.ref(path), Value=value, Execute=True)
    assert_error(scan(ctl, wp), 0x8410, 0x002C)
    assert axis.cfg[axis.ref(path).path] == before
    power.Enable = False
    ctl.run_until(lambda: not power().Status and axis.state == "disabled", timeout=2.0)
    wp.Execute = False
    scan(ctl, wp)
    wp.Execute = True
    assert scan(ctl, wp) == {"Done": True, "Busy": False, "Error": False, "ErrorID": 0, "ErrorInfo": 0}
    assert axis.cfg[axis.ref(path).path] == value.value


@pytest.mark.parametrize("path", R_TAGS)
def test_s7_1200_12_8_8410_002B_read_only_tags(path):
    """§12.9 legend R (and '-'): not writable, also not with MC_WriteParam -> 16#8410/16#002B, even on a
    disabled axis; the value is not changed."""
    ctl, axis = make("default")
    before = axis.cfg[axis.ref(path).path]
    value = typed("Real", 0.0) if axis.ref(path).data_type in ("VRef", "DWord") else _current_value(axis, path)
    assert_error(scan(ctl, MC_WriteParam(Parameter=axis.ref(path), Value=value, Execute=True)), 0x8410, 0x002B)
    assert axis.cfg[axis.ref(path).path] == before


@pytest.mark.parametrize("path", ["Position", "ActualVelocity", "StatusBits.Enable", "ErrorBits.HWLimit",
                                  "StatusSensor.State", "StatusPositioning.Distance"])
def test_s7_1200_12_8_8410_002B_status_tags(path):
    """Status tags (§12.9.1 - §12.9.4, §12.9.20 - §12.9.24: RCCP / RP) cannot be written: 16#8410/16#002B."""
    ctl, axis = make("pto")
    ref = axis.ref(path)
    assert_error(scan(ctl, MC_WriteParam(Parameter=ref, Value=typed(ref.data_type, 0 if ref.data_type == "DInt"
                                                                    else ref.read()), Execute=True)),
                 0x8410, 0x002B)


@pytest.mark.parametrize("parameter", [None, "DynamicDefaults.Acceleration", 48.0, "axis", Real(1.0)],
                         ids=["None", "path_string", "float", "axis_object", "variable"])
def test_s7_1200_12_8_8410_0029_not_a_technology_object_tag(parameter):
    """§12.8 16#8410/16#0029: VARIANT "Parameter" does not point to the technology object DB."""
    ctl, axis = make("pto")
    parameter = axis if parameter == "axis" else parameter
    assert_error(scan(ctl, MC_WriteParam(Parameter=parameter, Value=1.0, Execute=True)), 0x8410, 0x0029)


MISMATCHES = [
    ("DynamicDefaults.Acceleration", 100, "plain int is DInt, tag is Real"),
    ("DynamicDefaults.Acceleration", DInt(100), "DInt to Real"),
    ("DynamicDefaults.Acceleration", True, "Bool to Real"),
    ("DynamicDefaults.Acceleration", "100.0", "STRING"),
    ("DynamicDefaults.Acceleration", None, "no value"),
    ("PositionLimits_SW.Active", 1, "DInt to Bool"),
    ("PositionLimits_SW.Active", Real(1.0), "Real to Bool"),
    ("Actor.DirectionMode", 1, "plain int (DInt) to Int"),
    ("Actor.DirectionMode", DInt(1), "DInt to Int"),
    ("Actor.DriveParameter.PulsesPerDriveRevolution", Int(500), "Int to DInt"),
    ("Actor.DriveParameter.PulsesPerDriveRevolution", UDInt(500), "UDInt to DInt"),
    ("Actor.DriveParameter.PulsesPerDriveRevolution", 500.0, "Real to DInt"),
    ("Actor.DriveParameter.PulsesPerDriveRevolution", 2 ** 40, "int beyond DInt (LInt)"),
]


@pytest.mark.parametrize("path,value,why", MISMATCHES, ids=[m[2] for m in MISMATCHES])
def test_s7_1200_12_8_8410_0028_data_types_differ(path, value, why):
    """§12.8 16#8410/16#0028: the data types of "Parameter" and "Value" do not match (no conversion)."""
    ctl, axis = make("pto")
    before = axis.cfg[path]
    assert_error(scan(ctl, MC_WriteParam(Parameter=axis.ref(path), Value=value, Execute=True)), 0x8410, 0x0028)
    assert axis.cfg[path] == before


@pytest.mark.parametrize("path,value", [
    ("DynamicDefaults.Acceleration", 20.0), ("DynamicDefaults.Acceleration", Real(20.0)),
    ("DynamicDefaults.Acceleration", np.float64(20.0)), ("PositionLimits_SW.Active", True),
    ("PositionLimits_SW.Active", Bool(True)), ("PositionLimits_SW.Active", np.bool_(True)),
    ("Actor.DirectionMode", Int(1)), ("Actor.DriveParameter.PulsesPerDriveRevolution", 500),
    ("Actor.DriveParameter.PulsesPerDriveRevolution", DInt(500)),
    ("Actor.DriveParameter.PulsesPerDriveRevolution", np.int32(500)),
], ids=lambda v: type(v).__name__ if not isinstance(v, str) else v)
def test_s7_1200_11_1_12_matching_value_types(path, value):
    """§11.1.12.1 Value: VARIANT (BOOL, INT, DINT, UDINT, REAL) -- typed variables and plain Python values of
    the same data type (bool = BOOL, int = DINT, float = REAL) are written."""
    ctl, axis = make("pto")
    assert scan(ctl, MC_WriteParam(Parameter=axis.ref(path), Value=value, Execute=True))["Done"]
    expected = value.value if hasattr(value, "value") else value
    assert axis.cfg[path] == expected and type(axis.cfg[path]) is type(axis.load_cfg[path])


@pytest.mark.parametrize("value,error_info", [(NAN, 0x0002), (INF, 0x0002), (-INF, 0x0002), (Real(NAN), 0x0002),
                                              (1.0000001e12, 0x0005), (Real(1e13), 0x0005),
                                              (-1.0000001e12, 0x0006), (-1e300, 0x0006)])
def test_s7_1200_12_8_8411_invalid_value(value, error_info):
    """§12.8 16#8411 "invalid value at parameter Value": 16#0002 invalid number format; V7 list 16#0005
    > 1.0E12, 16#0006 < -1.0E12.  Nothing is written."""
    ctl, axis = make("pto")
    before = axis.cfg["PositionLimits_SW.MinPosition"]
    wp = MC_WriteParam(Parameter=axis.ref("PositionLimits_SW.MinPosition"), Value=value, Execute=True)
    assert_error(scan(ctl, wp), 0x8411, error_info)
    assert axis.cfg["PositionLimits_SW.MinPosition"] == before


def test_s7_1200_12_8_8411_limits_themselves_are_valid():
    """+-1.0E12 are inside the number range."""
    ctl, axis = make("pto")
    for v in (1.0e12, -1.0e12):
        assert scan(ctl, MC_WriteParam(Parameter=axis.ref("PositionLimits_SW.MinPosition"), Value=v,
                                       Execute=True))["Done"]
        assert axis.cfg["PositionLimits_SW.MinPosition"] == v


def test_s7_1200_12_8_8410_check_order():
    """Order of the checks (module docstring): Parameter -> data type -> Value -> axis state."""
    ctl, axis, power = enabled("pto")
    cases = [
        (axis.ref("Actor.Type"), NAN, (0x8410, 0x002B)),                     # R tag before type / value
        (axis.ref("DynamicLimits.MaxVelocity"), 1, (0x8410, 0x0028)),        # type before axis state
        (axis.ref("DynamicLimits.MaxVelocity"), NAN, (0x8411, 0x0002)),      # value before axis state
        (axis.ref("DynamicLimits.MaxVelocity"), 50.0, (0x8410, 0x002C)),
    ]
    for ref, value, (error_id, error_info) in cases:
        assert_error(scan(ctl, MC_WriteParam(Parameter=ref, Value=value, Execute=True)), error_id, error_info)


def test_s7_1200_12_8_8410_002C_while_enabling_and_while_disabling():
    """WP needs a disabled axis: also refused while MC_Power is still waiting for "Drive ready" and while a
    disable stop (StopMode 0) is running (MC_Power.Status still TRUE)."""
    ctl, axis = make("pd", {"Plant": {"ReadyDelay": 0.05}})
    power = MC_Power(Axis=axis, Enable=True)
    scan(ctl, power)
    assert axis.state == "enabling"
    wp = MC_WriteParam(Parameter=axis.ref("PositionControl.Kv"), Value=20.0, Execute=True)
    assert_error(scan(ctl, wp), 0x8410, 0x002C)
    ctl, axis, power, mv = moving("pto")
    ctl.run_until(lambda: mv().InVelocity, timeout=3.0)          # 80/s: emergency stop takes 0.16 s
    power.Enable = False
    scan(ctl, power, mv)
    assert axis.state == "disabling" and power.Status
    wp = MC_WriteParam(Parameter=axis.ref("DynamicLimits.MaxVelocity"), Value=50.0, Execute=True)
    assert_error(scan(ctl, wp), 0x8410, 0x002C)
    assert axis.cfg["DynamicLimits.MaxVelocity"] == 100.0


def test_s7_1200_11_1_12_effective_profidrive_next_servo_cycle():
    """§12.9.11 effective code 10: PROFIdrive -- the written Acceleration is used from the next servo cycle on
    (still the old value in the servo cycle's pre-servo hook, the new one after its interpolation)."""
    ctl, axis, power, mv = moving("pd")
    seen = []
    ctl.on_pre_servo(lambda t: seen.append(("pre", axis.eff["DynamicDefaults.Acceleration"])))
    ctl.on_post_servo(lambda t: seen.append(("post", axis.eff["DynamicDefaults.Acceleration"], axis.Acceleration)))
    wp = MC_WriteParam(Parameter=axis.ref("DynamicDefaults.Acceleration"), Value=Real(20.0), Execute=True)
    wp()
    assert wp.Done and axis.cfg["DynamicDefaults.Acceleration"] == 20.0
    assert axis.eff["DynamicDefaults.Acceleration"] == 50.0                 # written, not yet effective
    ctl.step()
    assert seen[0] == ("pre", 50.0)
    assert seen[1][:2] == ("post", 20.0) and seen[1][2] == pytest.approx(20.0)   # the running motion uses it


def test_s7_1200_11_1_12_effective_profidrive_wp_tag_next_servo_cycle():
    """§12.9.15 PositionControl.Kv: WP, effective 10 -- written on the disabled PROFIdrive axis, effective at the
    next servo cycle."""
    ctl, axis = make("pd")
    wp = MC_WriteParam(Parameter=axis.ref("PositionControl.Kv"), Value=25.0, Execute=True)
    wp()
    assert wp.Done and axis.eff["PositionControl.Kv"] == 10.0
    ctl.step()
    assert axis.eff["PositionControl.Kv"] == 25.0


def test_s7_1200_11_1_12_effective_pto_acceleration_at_next_command_start():
    """§12.9.11 effective code 5 (PTO): the written Acceleration does not change the running MC_MoveVelocity;
    it is used from the start of the next motion command."""
    ctl, axis, power, mv = moving("pto")
    wp = MC_WriteParam(Parameter=axis.ref("DynamicDefaults.Acceleration"), Value=20.0, Execute=True)
    assert scan(ctl, wp, mv)[0]["Done"]
    for _ in range(5):
        scan(ctl, mv)
        assert axis.eff["DynamicDefaults.Acceleration"] == 50.0 and axis.Acceleration == pytest.approx(50.0)
    mv2 = MC_MoveVelocity(Axis=axis, Execute=True, Velocity=90.0)
    scan(ctl, mv2)
    assert axis.eff["DynamicDefaults.Acceleration"] == 20.0 and axis.Acceleration == pytest.approx(20.0)


def test_s7_1200_11_1_12_effective_pto_deceleration_when_jog_stops():
    """§12.9.11 effective code 6 (PTO): a Deceleration written while jogging is used when the jog stops."""
    ctl, axis, power = enabled("pto")
    jog = MC_MoveJog(Axis=axis, JogForward=True, Velocity=50.0)
    ctl.run_until(lambda: jog().InVelocity, timeout=3.0)
    wp = MC_WriteParam(Parameter=axis.ref("DynamicDefaults.Deceleration"), Value=Real(25.0), Execute=True)
    assert scan(ctl, wp, jog)[0]["Done"]
    assert axis.eff["DynamicDefaults.Deceleration"] == 50.0
    jog.JogForward = False
    scan(ctl, jog)
    assert axis.eff["DynamicDefaults.Deceleration"] == 25.0
    assert axis.Acceleration == pytest.approx(-25.0)


def test_s7_1200_11_1_12_effective_pto_wp_tag_at_enable():
    """§12.9.10 effective code 2 / §12.9.11 code 1 (PTO: when the axis is enabled): MaxVelocity (WP) and
    Acceleration (RW) written while disabled are used from the next enable -- a command above the new limit
    is then refused with 16#8402/16#0008."""
    ctl, axis = make("pto")
    wp = MC_WriteParam(Parameter=axis.ref("DynamicLimits.MaxVelocity"), Value=60.0, Execute=True)
    wa = MC_WriteParam(Parameter=axis.ref("DynamicDefaults.Acceleration"), Value=30.0, Execute=True)
    assert all(o["Done"] for o in scan(ctl, wp, wa))
    for _ in range(3):
        scan(ctl)
    assert axis.eff["DynamicLimits.MaxVelocity"] == 100.0 and axis.eff["DynamicDefaults.Acceleration"] == 50.0
    power = MC_Power(Axis=axis, Enable=True)
    scan(ctl, power)
    assert power.Status and axis.eff["DynamicLimits.MaxVelocity"] == 60.0
    assert axis.eff["DynamicDefaults.Acceleration"] == 30.0
    mv = MC_MoveVelocity(Axis=axis, Execute=True, Velocity=80.0)
    assert_error(scan(ctl, mv), 0x8402, 0x0008)


@pytest.mark.parametrize("kind", ["pd", "pto"])
def test_s7_1200_11_1_12_invalid_value_becomes_configuration_error_when_effective(kind):
    """Decision (catalog §4.12 "written configuration values are validated -> configuration errors 16#86xx"):
    MC_WriteParam writes Acceleration = -1.0 and shows Done ("value was written"); the configuration error
    16#8608 appears when the value takes effect -- PROFIdrive: next servo cycle, at MC_Power and the running
    command; PTO: at the next command start, at that command and MC_Power (§9.6).  MC_Reset clears it
    once a valid value has been written."""
    ctl, axis, power, mv = moving(kind)
    wp = MC_WriteParam(Parameter=axis.ref("DynamicDefaults.Acceleration"), Value=-1.0, Execute=True)
    out = scan(ctl, wp, mv, power)
    assert out[0]["Done"] and not out[0]["Error"]
    if kind == "pd":
        assert_error(out[1] if out[1]["Error"] else scan(ctl, mv), 0x8608, 0x0004)
        assert_error(scan(ctl, power), 0x8608, 0x0004)
    else:
        assert not out[2]["Error"] and out[1]["Busy"]                       # not effective yet
        mr = MC_MoveRelative(Axis=axis, Execute=True, Distance=5.0, Velocity=20.0)
        assert_error(scan(ctl, mr), 0x8608, 0x0004)
        assert_error(scan(ctl, power), 0x8608, 0x0004)
    assert axis.ErrorBits.ConfigFault
    wp2 = MC_WriteParam(Parameter=axis.ref("DynamicDefaults.Acceleration"), Value=40.0, Execute=True)
    assert scan(ctl, wp2, power)[0]["Done"]                                # writing the remedy is allowed
    reset = MC_Reset(Axis=axis, Execute=True)
    assert scan(ctl, reset, power)[0]["Done"]
    assert not axis.StatusBits.Error and axis.eff["DynamicDefaults.Acceleration"] == 40.0


def test_s7_1200_11_1_12_invalid_wp_value_refuses_enable():
    """A WP value outside its range (PTO: DirectionMode 5, written while disabled) becomes the configuration
    error of the tag at the enable (§12.9.5 code 2): 16#861A/16#0011 at MC_Power, the axis stays disabled."""
    ctl, axis = make("pto")
    assert scan(ctl, MC_WriteParam(Parameter=axis.ref("Actor.DirectionMode"), Value=Int(5), Execute=True))["Done"]
    power = MC_Power(Axis=axis, Enable=True)
    assert_error(scan(ctl, power), 0x861A, 0x0011)
    assert not power.Status and axis.state == "disabled"


def test_s7_1200_11_1_12_does_not_abort_and_is_not_aborted():
    """§11.1.12.1 override response: MC_WriteParam aborts no running command, no command aborts it."""
    ctl, axis, power, mv = moving("pto")
    wp = MC_WriteParam(Parameter=axis.ref("DynamicDefaults.Jerk"), Value=0.0, Execute=True)
    out = scan(ctl, wp, mv)
    assert out[0]["Done"] and out[1]["Busy"] and not out[1]["CommandAborted"]
    mv2 = MC_MoveVelocity(Axis=axis, Execute=True, Velocity=20.0)
    out = scan(ctl, wp, mv2, mv)
    assert out[0]["Done"] and out[2]["CommandAborted"]


# ==========================================================================================================
# §9.5.2 output timing of MC_ChangeDynamic and MC_WriteParam
def _instances(axis):
    return {
        "ChangeDynamic ok": MC_ChangeDynamic(Axis=axis, ChangeRampUp=True, RampUpTime=2.0),
        "ChangeDynamic error": MC_ChangeDynamic(Axis=axis, ChangeRampUp=True, RampUpTime=0.0),
        "WriteParam ok": MC_WriteParam(Parameter=axis.ref("DynamicDefaults.Jerk"), Value=10.0),
        "WriteParam error": MC_WriteParam(Parameter=axis.ref("Actor.Type"), Value=DInt(1)),
    }


@pytest.mark.parametrize("name", ["ChangeDynamic ok", "ChangeDynamic error", "WriteParam ok", "WriteParam error"])
def test_s7_1200_9_5_2_latched_while_execute_true(name):
    """§9.5.2 (catalog T1/T4): the command ends in the call with the rising edge (Busy never TRUE); Done or
    Error stays TRUE while Execute is TRUE and drops together with Execute."""
    ctl, axis, power = enabled("pto")
    fb = _instances(axis)[name]
    final = "Error" if name.endswith("error") else "Done"
    fb.Execute = True
    outs = [scan(ctl, fb) for _ in range(5)]
    assert all(o[final] and not o.get("Busy", False) for o in outs)
    assert all(o["Done"] != o["Error"] for o in outs)
    fb.Execute = False
    after = [scan(ctl, fb) for _ in range(3)]
    assert not any(o["Done"] or o["Error"] or o.get("Busy") or o["ErrorID"] for o in after)


@pytest.mark.parametrize("name", ["ChangeDynamic ok", "ChangeDynamic error", "WriteParam ok", "WriteParam error"])
def test_s7_1200_9_5_2_one_call_when_execute_pulsed(name):
    """§9.5.2: with Execute already FALSE at the next call the final status is shown for exactly one call --
    here the call with the edge, as the command completes within it."""
    ctl, axis, power = enabled("pto")
    fb = _instances(axis)[name]
    final = "Error" if name.endswith("error") else "Done"
    fb.Execute = True
    first = scan(ctl, fb)
    fb.Execute = False
    rest = [scan(ctl, fb) for _ in range(3)]
    assert first[final]
    assert not any(o["Done"] or o["Error"] for o in rest)


def test_s7_1200_9_5_2_new_edge_restarts():
    """A new rising edge starts a new command: the previous Error is replaced by the new result."""
    ctl, axis = make("pto")
    wp = MC_WriteParam(Parameter=axis.ref("DynamicDefaults.Jerk"), Value=NAN, Execute=True)
    assert_error(scan(ctl, wp), 0x8411, 0x0002)
    wp.Execute, wp.Value = False, 5.0
    scan(ctl, wp)
    wp.Execute = True
    assert scan(ctl, wp)["Done"] and axis.cfg["DynamicDefaults.Jerk"] == 5.0
    wp.Value = 7.0                                                          # inputs taken over at the edge only
    scan(ctl, wp)
    assert axis.cfg["DynamicDefaults.Jerk"] == 5.0


# ==========================================================================================================
# MC_ReadParam (§11.1.11)
def _readable(axis) -> list[str]:
    groups = ("StatusPositioning.", "StatusDrive.", "StatusSensor.", "StatusBits.", "ErrorBits.")
    return [p for p in axis.tag_paths() if p in ("Position", "Velocity", "ActualPosition", "ActualVelocity")
            or (p.startswith(groups) and p != "ErrorBits.HWLimit")]


READABLE = _readable(make("pd")[1])


@pytest.mark.parametrize("path", READABLE)
def test_s7_1200_11_1_11_every_rp_tag_is_readable(path):
    """§11.1.11.1 Parameter: Position, Velocity, ActualPosition, ActualVelocity, StatusPositioning.*,
    StatusDrive.*, StatusSensor.*, StatusBits.*, ErrorBits.* (RP in §12.9) -- read into a variable of the
    tag's data type; Valid and Busy TRUE."""
    ctl, axis, power, mv = moving("pd")
    ref = axis.ref(path)
    value = typed(ref.data_type, {"Bool": False, "Real": 0.0}.get(ref.data_type, 0))
    rp = MC_ReadParam(Parameter=ref, Value=value, Enable=True)
    rp()
    assert rp.outputs == {"Valid": True, "Busy": True, "Error": False, "ErrorID": 0, "ErrorInfo": 0}
    assert value.value == axis.tag(path) and type(value.value) is {"Bool": bool, "Real": float}.get(
        ref.data_type, int)


def test_s7_1200_11_1_11_reads_at_every_call_while_enabled():
    """§11.1.11.1 "continuous reading", §12.9 RP "value determined at the start of the command" (each call):
    Value follows the setpoint position of a moving axis; Enable = FALSE stops the updates and resets the
    outputs, Value keeps its last value."""
    ctl, axis, power, mv = moving("pto")
    pos = Real()
    rp = MC_ReadParam(Parameter=axis.ref("Position"), Value=pos)
    assert scan(ctl, rp, mv)[0] == {"Valid": False, "Busy": False, "Error": False, "ErrorID": 0, "ErrorInfo": 0}
    assert pos == 0.0
    rp.Enable = True
    seen = []
    for _ in range(10):
        rp()
        assert pos.value == axis.Position and rp.Valid and rp.Busy
        seen.append(pos.value)
        mv()
        ctl.step()
    assert seen == sorted(seen) and seen[-1] > seen[0]
    rp.Enable = False
    last = pos.value
    assert scan(ctl, rp, mv)[0] == {"Valid": False, "Busy": False, "Error": False, "ErrorID": 0, "ErrorInfo": 0}
    scan(ctl, rp, mv)
    assert pos.value == last != axis.Position


def test_s7_1200_11_1_11_bool_and_dint_status_tags_change():
    """StatusBits (BOOL) and StatusSensor.State (DINT) read with matching variables (catalog §11 item 15:
    the printed VARIANT (REAL) is too narrow -- the data type of the tag applies)."""
    ctl, axis = make("pto")
    enable, state = Bool(), DInt(-1)
    rp_enable = MC_ReadParam(Parameter=axis.ref("StatusBits.Enable"), Value=enable, Enable=True)
    rp_state = MC_ReadParam(Parameter=axis.ref("StatusSensor.State"), Value=state, Enable=True)
    power = MC_Power(Axis=axis, Enable=False)
    scan(ctl, rp_enable, rp_state, power)
    assert enable == False and state == 0 and rp_enable.Valid and rp_state.Valid  # noqa: E712 - PTO: no encoder
    power.Enable = True
    scan(ctl, power)
    scan(ctl, rp_enable)
    assert enable == True  # noqa: E712


@pytest.mark.parametrize("path", ["DynamicDefaults.Acceleration", "DynamicLimits.MaxVelocity", "Actor.Type",
                                  "PositionLimits_SW.Active", "Units.LengthUnit", "ErrorBits.HWLimit",
                                  "Acceleration"])
def test_s7_1200_12_8_8410_002A_tag_not_readable_with_read_param(path):
    """§12.8 16#8410/16#002A "the value at the VARIANT pointer Parameter cannot be read": configuration tags
    (access R/RW/WP, not RP), ErrorBits.HWLimit (RCCP only, §12.9.24), the S7-1500 name Acceleration."""
    ctl, axis = make("pto")
    ref = axis.ref(path)
    value = typed(ref.data_type if ref.data_type in ("Bool", "Int", "DInt", "UDInt", "Real") else "Real", 0
                  if ref.data_type != "Bool" else False)
    rp = MC_ReadParam(Parameter=ref, Value=value, Enable=True)
    out = scan(ctl, rp)
    assert_error(out, 0x8410, 0x002A)
    assert not out["Valid"] and not out["Busy"]


@pytest.mark.parametrize("parameter", [None, "Position", 0.0, "axis"], ids=["None", "string", "float", "axis"])
def test_s7_1200_12_8_8410_0029_read_param_not_a_technology_object_tag(parameter):
    """§12.8 16#8410/16#0029 at MC_ReadParam."""
    ctl, axis = make("pto")
    rp = MC_ReadParam(Parameter=axis if parameter == "axis" else parameter, Value=Real(), Enable=True)
    assert_error(scan(ctl, rp), 0x8410, 0x0029)


@pytest.mark.parametrize("path,value", [("Position", DInt(0)), ("Position", Bool(False)),
                                        ("StatusBits.Enable", Real(0.0)), ("StatusBits.Enable", DInt(0)),
                                        ("StatusSensor.State", Int(0)), ("StatusSensor.State", UDInt(0)),
                                        ("StatusSensor.State", Real(0.0))])
def test_s7_1200_12_8_8410_0028_read_param_data_types_differ(path, value):
    """§12.8 16#8410/16#0028: the variable at Value has another data type than the tag; Value unchanged."""
    ctl, axis, power, mv = moving("pto")
    before = value.value
    rp = MC_ReadParam(Parameter=axis.ref(path), Value=value, Enable=True)
    out = scan(ctl, rp)
    assert_error(out, 0x8410, 0x0028)
    assert not out["Valid"] and not out["Busy"] and value.value == before


def test_s7_1200_11_1_11_error_held_until_enable_false():
    """Remedy of 16#8410 "correct the VARIANT pointer; restart the command": the error stays (no reading)
    while Enable is TRUE, even after the pointer was corrected; Enable FALSE -> TRUE restarts."""
    ctl, axis, power, mv = moving("pto")
    pos = Real()
    rp = MC_ReadParam(Parameter=axis.ref("DynamicDefaults.Acceleration"), Value=pos, Enable=True)
    assert_error(scan(ctl, rp), 0x8410, 0x002A)
    rp.Parameter = axis.ref("Position")
    for _ in range(3):
        assert_error(scan(ctl, rp), 0x8410, 0x002A)
    assert pos == 0.0
    rp.Enable = False
    assert scan(ctl, rp) == {"Valid": False, "Busy": False, "Error": False, "ErrorID": 0, "ErrorInfo": 0}
    rp.Enable = True
    rp()
    assert rp.Valid and not rp.Error and pos.value == axis.Position != 0.0


def test_s7_1200_11_1_11_value_must_be_a_variable():
    """Value is an InOut: a constant there is a programming error (TypeError), as it would not compile."""
    ctl, axis = make("pto")
    rp = MC_ReadParam(Parameter=axis.ref("Position"), Value=0.0, Enable=True)
    with pytest.raises(TypeError, match="typed variable"):
        rp()
    MC_ReadParam(Parameter=axis.ref("Position"), Value=0.0, Enable=False)()   # not used while Enable = FALSE


def test_s7_1200_11_1_11_override_and_reinit():
    """§11.1.11.1 override: MC_ReadParam neither aborts nor is aborted; STOP -> RUN reinitialises the instance
    (instance DB start values) like every instruction."""
    ctl, axis, power, mv = moving("pto")
    v = Real()
    rp = MC_ReadParam(Parameter=axis.ref("Velocity"), Value=v, Enable=True)
    out = scan(ctl, rp, mv)
    assert out[0]["Valid"] and out[1]["Busy"] and not out[1]["CommandAborted"]
    mv2 = MC_MoveVelocity(Axis=axis, Execute=True, Velocity=20.0)
    out = scan(ctl, mv2, rp)
    assert out[1]["Valid"] and out[1]["Busy"]
    ctl.stop("test")
    ctl.start()
    assert rp.outputs == {"Valid": False, "Busy": False, "Error": False, "ErrorID": 0, "ErrorInfo": 0}


# ==========================================================================================================
# documentation page: every example runs
def _doc_examples() -> list[str]:
    return re.findall(r"```python\n(.*?)```", DOCS.read_text(), re.S)


def test_s7_1200_docs_page_has_an_example_for_each_instruction():
    text = "\n".join(_doc_examples())
    for name in ("MC_ChangeDynamic", "MC_ReadParam", "MC_WriteParam"):
        assert f"{name}(" in text


@pytest.mark.parametrize("index", range(len(_doc_examples())))
def test_s7_1200_docs_examples_run(index):
    exec(compile(_doc_examples()[index], f"{DOCS.name}[{index}]", "exec"), {"__name__": "__doc_example__"})
