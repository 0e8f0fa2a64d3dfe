"""ErrorIDs / ErrorInfos of the S7-1200 Motion Control V6 instructions on a positioning axis.

Derived from the V6 function manual (seeds/000_a03aa7b7d80586ce.txt):

* §12.8 "List of ErrorIDs and ErrorInfos (technology objects as of V6)" -- the codes;
* §9.6 "Error displays of the Motion Control statements" -- which error class is shown where
  (triggering instruction only, or also at MC_Power), whether the axis stops and whether the
  error needs MC_Reset (§11.1.2.1);
* §11.1.x -- the value ranges of the inputs of every instruction.

Every test is table driven: one row per ErrorID/ErrorInfo and instruction.
"""
from __future__ import annotations

import math

import pytest

from plcmotion import Controller
from plcmotion.s7_1200 import (MC_Halt, MC_Home, MC_MoveAbsolute, MC_MoveJog, MC_MoveRelative,
                               MC_MoveVelocity, MC_Power, MC_Reset)

NAN, INF = math.nan, math.inf

# ----------------------------------------------------------------------------------------------------
# axis configurations
_DYN = {"Acceleration": 50.0, "Deceleration": 50.0, "Jerk": 500.0, "EmergencyDeceleration": 500.0}

PD = {"Actor": {"Type": 1}, "DynamicLimits": {"MaxVelocity": 100.0}, "DynamicDefaults": dict(_DYN)}
PTO = {"Actor": {"Type": 2}, "DynamicLimits": {"MaxVelocity": 100.0, "MinVelocity": 10.0},
       "DynamicDefaults": dict(_DYN)}
PD_MODULO = dict(PD, Modulo={"Enable": True, "Length": 360.0, "StartValue": 0.0})
PD_SW = dict(PD, PositionLimits_SW={"Active": True, "MinPosition": -100.0, "MaxPosition": 100.0})
PTO_SW = dict(PTO, PositionLimits_SW={"Active": True, "MinPosition": -100.0, "MaxPosition": 100.0})
PTO_NOJERK = dict(PTO, DynamicDefaults=dict(_DYN, Jerk=0.0))
CONFIGS = {"pto_nojerk": PTO_NOJERK, "pd": PD, "pto": PTO, "pd_modulo": PD_MODULO, "pd_sw": PD_SW, "pto_sw": PTO_SW}


def make_axis(kind: str = "pd"):
    ctl = Controller(servo_cycle=0.001, app_cycle=0.004)
    axis = ctl.add_positioning_axis("Axis_1", CONFIGS[kind])
    return ctl, axis


def enable(ctl, axis, power=None):
    power = power or MC_Power()
    power(Axis=axis, Enable=True)
    ctl.run_until(lambda: power().Status, timeout=2.0)
    assert axis.StatusBits.Enable
    return power


def home(ctl, axis, position=0.0):
    h = MC_Home()
    h(Axis=axis, Execute=True, Mode=0, Position=position)
    ctl.run_until(lambda: h().Done or h.Error, timeout=1.0)
    assert h.Done and axis.StatusBits.HomingDone
    h(Execute=False)
    return h


def ready_axis(kind: str, homed: bool = True):
    ctl, axis = make_axis(kind)
    power = enable(ctl, axis)
    if homed:
        home(ctl, axis)
    return ctl, axis, power


def settle(ctl, *fbs, cycles: int = 3):
    """Run a few application cycles, calling the instruction instances every cycle (§9.3)."""
    for _ in range(cycles):
        ctl.step()
        for fb in fbs:
            fb()


def start_velocity(ctl, axis, velocity=30.0):
    """A running MC_MoveVelocity that has reached its velocity (InVelocity)."""
    mv = MC_MoveVelocity()
    mv(Axis=axis, Execute=True, Velocity=velocity)
    ctl.run_until(lambda: mv().InVelocity, timeout=3.0)
    return mv


def assert_error(fb, error_id, error_info=None):
    assert fb.Error, f"{type(fb).__name__} shows no error: {fb!r}"
    if not isinstance(fb, MC_Power):          # MC_Power is Busy while Enable is TRUE (§11.1.1)
        assert not fb.Busy                    # §9.5.2: Busy FALSE once the command has ended
    assert fb.ErrorID == error_id, f"ErrorID 16#{fb.ErrorID:04X}, expected 16#{error_id:04X}"
    if error_info is not None:
        infos = error_info if isinstance(error_info, (tuple, set, frozenset)) else (error_info,)
        assert fb.ErrorInfo in infos, (f"ErrorInfo 16#{fb.ErrorInfo:04X}, expected "
                                       + " or ".join(f"16#{i:04X}" for i in infos))


# ----------------------------------------------------------------------------------------------------
# Block parameter errors 16#8400...16#8412 (§12.8 "Block parameter error"; §11.1.x input ranges)
#
# Row: (instruction, axis kind, homed, inputs, ErrorID, ErrorInfo)
# "start" for MC_MoveJog is the rising edge of the jog input given in inputs.
BLOCK_PARAMETER_ERRORS = [
    # ---- MC_MoveAbsolute §11.1.5: -1.0e12 <= Position <= 1.0e12; start/stop <= Velocity <= max
    (MC_MoveAbsolute, "pd", True, dict(Position=NAN, Velocity=20.0), 0x8400, 0x0002),
    (MC_MoveAbsolute, "pd", True, dict(Position=INF, Velocity=20.0), 0x8400, 0x0002),
    (MC_MoveAbsolute, "pd", True, dict(Position=-INF, Velocity=20.0), 0x8400, 0x0002),
    (MC_MoveAbsolute, "pd", True, dict(Position=1.5e12, Velocity=20.0), 0x8400, 0x0005),
    (MC_MoveAbsolute, "pd", True, dict(Position=-1.5e12, Velocity=20.0), 0x8400, 0x0006),
    (MC_MoveAbsolute, "pto", True, dict(Position=NAN, Velocity=20.0), 0x8400, 0x0002),
    (MC_MoveAbsolute, "pto", True, dict(Position=2e12, Velocity=20.0), 0x8400, 0x0005),
    (MC_MoveAbsolute, "pto", True, dict(Position=-2e12, Velocity=20.0), 0x8400, 0x0006),
    (MC_MoveAbsolute, "pd", True, dict(Position=10.0, Velocity=NAN), 0x8402, 0x0002),
    (MC_MoveAbsolute, "pd", True, dict(Position=10.0, Velocity=INF), 0x8402, 0x0002),
    (MC_MoveAbsolute, "pd", True, dict(Position=10.0, Velocity=-INF), 0x8402, 0x0002),
    (MC_MoveAbsolute, "pd", True, dict(Position=10.0, Velocity=100.5), 0x8402, 0x0008),
    (MC_MoveAbsolute, "pd", True, dict(Position=10.0, Velocity=-20.0), 0x8402, 0x0024),
    (MC_MoveAbsolute, "pd", True, dict(Position=10.0, Velocity=0.0), 0x8402, 0x0030),  # documented decision
    (MC_MoveAbsolute, "pto", True, dict(Position=10.0, Velocity=150.0), 0x8402, 0x0008),
    (MC_MoveAbsolute, "pto", True, dict(Position=10.0, Velocity=5.0), 0x8402, 0x0009),
    (MC_MoveAbsolute, "pto", True, dict(Position=10.0, Velocity=0.0), 0x8402, 0x0009),
    (MC_MoveAbsolute, "pto", True, dict(Position=10.0, Velocity=-20.0), 0x8402, 0x0024),
    (MC_MoveAbsolute, "pto", True, dict(Position=10.0, Velocity=INF), 0x8402, 0x0002),
    # Direction is evaluated only with modulo (§11.1.5): 0..3
    (MC_MoveAbsolute, "pd_modulo", True, dict(Position=10.0, Velocity=20.0, Direction=4), 0x8403, 0x0011),
    (MC_MoveAbsolute, "pd_modulo", True, dict(Position=10.0, Velocity=20.0, Direction=-1), 0x8403, 0x0011),
    # only Direction 0 takes the sign of Velocity; otherwise Velocity < 0 is invalid
    (MC_MoveAbsolute, "pd_modulo", True, dict(Position=10.0, Velocity=-20.0, Direction=1), 0x8402, 0x0024),
    (MC_MoveAbsolute, "pd_modulo", True, dict(Position=10.0, Velocity=-20.0, Direction=3), 0x8402, 0x0024),
    (MC_MoveAbsolute, "pd_modulo", True, dict(Position=10.0, Velocity=150.0, Direction=0), 0x8402, 0x0008),
    (MC_MoveAbsolute, "pd_modulo", True, dict(Position=NAN, Velocity=20.0, Direction=3), 0x8400, 0x0002),
    # ---- MC_MoveRelative §11.1.6: -1.0e12 <= Distance <= 1.0e12
    (MC_MoveRelative, "pd", False, dict(Distance=NAN, Velocity=20.0), 0x8401, 0x0002),
    (MC_MoveRelative, "pd", False, dict(Distance=INF, Velocity=20.0), 0x8401, 0x0002),
    (MC_MoveRelative, "pd", False, dict(Distance=-INF, Velocity=20.0), 0x8401, 0x0002),
    (MC_MoveRelative, "pd", False, dict(Distance=1.5e12, Velocity=20.0), 0x8401, 0x0005),
    (MC_MoveRelative, "pd", False, dict(Distance=-1.5e12, Velocity=20.0), 0x8401, 0x0006),
    (MC_MoveRelative, "pto", False, dict(Distance=NAN, Velocity=20.0), 0x8401, 0x0002),
    (MC_MoveRelative, "pto", False, dict(Distance=3e12, Velocity=20.0), 0x8401, 0x0005),
    (MC_MoveRelative, "pto", False, dict(Distance=-3e12, Velocity=20.0), 0x8401, 0x0006),
    (MC_MoveRelative, "pd", False, dict(Distance=10.0, Velocity=NAN), 0x8402, 0x0002),
    (MC_MoveRelative, "pd", False, dict(Distance=10.0, Velocity=INF), 0x8402, 0x0002),
    (MC_MoveRelative, "pd", False, dict(Distance=10.0, Velocity=101.0), 0x8402, 0x0008),
    (MC_MoveRelative, "pd", False, dict(Distance=10.0, Velocity=-1.0), 0x8402, 0x0024),
    (MC_MoveRelative, "pd", False, dict(Distance=10.0, Velocity=0.0), 0x8402, 0x0030),  # documented decision
    (MC_MoveRelative, "pto", False, dict(Distance=10.0, Velocity=9.0), 0x8402, 0x0009),
    (MC_MoveRelative, "pto", False, dict(Distance=10.0, Velocity=0.0), 0x8402, 0x0009),
    (MC_MoveRelative, "pto", False, dict(Distance=10.0, Velocity=100.01), 0x8402, 0x0008),
    (MC_MoveRelative, "pto", False, dict(Distance=10.0, Velocity=-50.0), 0x8402, 0x0024),
    (MC_MoveRelative, "pto", False, dict(Distance=10.0, Velocity=-INF), 0x8402, 0x0002),
    # ---- MC_MoveVelocity §11.1.7: start/stop <= |Velocity| <= max, 0.0 permitted; Direction 0..2
    (MC_MoveVelocity, "pd", False, dict(Velocity=NAN), 0x8402, 0x0002),
    (MC_MoveVelocity, "pd", False, dict(Velocity=INF), 0x8402, 0x0002),
    (MC_MoveVelocity, "pd", False, dict(Velocity=-INF), 0x8402, 0x0002),
    (MC_MoveVelocity, "pd", False, dict(Velocity=150.0), 0x8402, 0x0008),
    (MC_MoveVelocity, "pd", False, dict(Velocity=-150.0), 0x8402, 0x0008),
    (MC_MoveVelocity, "pto", False, dict(Velocity=5.0), 0x8402, 0x0009),
    (MC_MoveVelocity, "pto", False, dict(Velocity=-5.0), 0x8402, 0x0009),
    (MC_MoveVelocity, "pto", False, dict(Velocity=120.0), 0x8402, 0x0008),
    (MC_MoveVelocity, "pto", False, dict(Velocity=NAN), 0x8402, 0x0002),
    (MC_MoveVelocity, "pd", False, dict(Velocity=20.0, Direction=3), 0x8403, 0x0011),
    (MC_MoveVelocity, "pd", False, dict(Velocity=20.0, Direction=-1), 0x8403, 0x0011),
    (MC_MoveVelocity, "pto", False, dict(Velocity=20.0, Direction=7), 0x8403, 0x0011),
    # ---- MC_MoveJog §11.1.8: start/stop <= Velocity <= max
    (MC_MoveJog, "pd", False, dict(JogForward=True, Velocity=NAN), 0x8402, 0x0002),
    (MC_MoveJog, "pd", False, dict(JogForward=True, Velocity=INF), 0x8402, 0x0002),
    (MC_MoveJog, "pd", False, dict(JogBackward=True, Velocity=150.0), 0x8402, 0x0008),
    (MC_MoveJog, "pd", False, dict(JogForward=True, Velocity=-20.0), 0x8402, 0x0024),
    (MC_MoveJog, "pto", False, dict(JogForward=True, Velocity=5.0), 0x8402, 0x0009),
    (MC_MoveJog, "pto", False, dict(JogBackward=True, Velocity=NAN), 0x8402, 0x0002),
    (MC_MoveJog, "pto", False, dict(JogBackward=True, Velocity=100.5), 0x8402, 0x0008),
    # JogForward and JogBackward at the same time (§11.1.8: 16#8406)
    (MC_MoveJog, "pd", False, dict(JogForward=True, JogBackward=True, Velocity=20.0), 0x8406, 0x0001),
    (MC_MoveJog, "pto", False, dict(JogForward=True, JogBackward=True, Velocity=20.0), 0x8406, 0x0001),
    # ---- MC_Home §11.1.3: Mode 0,1,2,3,6,7; -1.0e12 <= Position <= 1.0e12
    (MC_Home, "pd", False, dict(Mode=4, Position=0.0), 0x8404, 0x0011),
    (MC_Home, "pd", False, dict(Mode=5, Position=0.0), 0x8404, 0x0011),
    (MC_Home, "pd", False, dict(Mode=8, Position=0.0), 0x8404, 0x0011),
    (MC_Home, "pd", False, dict(Mode=-1, Position=0.0), 0x8404, 0x0011),
    (MC_Home, "pto", False, dict(Mode=4, Position=0.0), 0x8404, 0x0011),
    # modes 2/3 need a configured homing switch (none configured here): 16#0015
    (MC_Home, "pd", False, dict(Mode=2, Position=0.0), 0x8404, 0x0015),
    (MC_Home, "pd", False, dict(Mode=3, Position=0.0), 0x8404, 0x0015),
    (MC_Home, "pto", False, dict(Mode=2, Position=0.0), 0x8404, 0x0015),
    (MC_Home, "pto", False, dict(Mode=3, Position=0.0), 0x8404, 0x0015),
    # modes 6/7 with an incremental encoder (Sensor[1].Type start value 0 = incremental): 16#0055
    (MC_Home, "pd", False, dict(Mode=6, Position=0.0), 0x8404, 0x0055),
    (MC_Home, "pd", False, dict(Mode=7, Position=0.0), 0x8404, 0x0055),
    (MC_Home, "pd", False, dict(Mode=0, Position=NAN), 0x8400, 0x0002),
    (MC_Home, "pd", False, dict(Mode=0, Position=INF), 0x8400, 0x0002),
    (MC_Home, "pd", False, dict(Mode=1, Position=-INF), 0x8400, 0x0002),
    (MC_Home, "pd", False, dict(Mode=0, Position=1.5e12), 0x8400, 0x0005),
    (MC_Home, "pd", False, dict(Mode=1, Position=-1.5e12), 0x8400, 0x0006),
    (MC_Home, "pto", False, dict(Mode=0, Position=NAN), 0x8400, 0x0002),
    (MC_Home, "pto", False, dict(Mode=0, Position=5e12), 0x8400, 0x0005),
]


def _start(fb, axis, inputs):
    if isinstance(fb, MC_MoveJog):
        fb(Axis=axis, **inputs)
    else:
        fb(Axis=axis, Execute=True, **inputs)


def _row_id(row):
    cls, kind, _homed, inputs, eid, einfo = row
    args = ",".join(f"{k}={v}" for k, v in inputs.items())
    return f"{cls.__name__}-{kind}-{args}-16#{eid:04X}/16#{einfo:04X}"


@pytest.mark.parametrize("row", BLOCK_PARAMETER_ERRORS, ids=_row_id)
def test_s7_1200_block_parameter_error_12_8(row):
    """§12.8 block parameter errors (16#84xx): shown at the instruction, latched while the start input
    stays TRUE (§9.5.2), NOT at MC_Power, StatusBits.Error stays FALSE (§9.6), no MC_Reset needed."""
    cls, kind, homed, inputs, error_id, error_info = row
    ctl, axis, power = ready_axis(kind, homed=homed)
    fb = cls()
    _start(fb, axis, inputs)
    settle(ctl, fb, power, cycles=3)
    assert_error(fb, error_id, error_info)
    # §9.6: block parameter errors are indicated only in the triggering instruction
    assert not power.Error and power.ErrorID == 0
    assert not axis.StatusBits.Error
    assert power.Status and axis.StatusBits.Enable
    # the axis did not move
    assert axis.Velocity == 0.0


MOTION_CLASSES = [MC_Halt, MC_MoveAbsolute, MC_MoveRelative, MC_MoveVelocity, MC_MoveJog, MC_Home, MC_Reset]


@pytest.mark.parametrize("bad_axis", [None, 42, "Axis_1", object()], ids=["None", "int", "str", "object"])
@pytest.mark.parametrize("cls", MOTION_CLASSES + [MC_Power], ids=lambda c: c.__name__)
def test_s7_1200_invalid_axis_8408(cls, bad_axis):
    """§12.8 16#8408/16#001C: the Axis parameter is not a Motion Control technology DB."""
    ctl = Controller()
    fb = cls()
    if cls is MC_Power:
        fb(Axis=bad_axis, Enable=True)
    elif cls is MC_MoveJog:
        fb(Axis=bad_axis, JogForward=True)
    else:
        fb(Axis=bad_axis, Execute=True)
    ctl.step()
    fb()
    assert fb.Error
    assert fb.ErrorID == 0x8408
    assert fb.ErrorInfo == 0x001C
    if hasattr(fb, "Status"):
        assert not fb.Status


@pytest.mark.parametrize("kind", ["pd", "pto"])
@pytest.mark.parametrize("stop_mode", [3, -1, 17])
def test_s7_1200_mc_power_invalid_stopmode_8405(kind, stop_mode):
    """§11.1.1 StopMode 0/1/2; §12.8 16#8405/16#0011 invalid StopMode, shown at MC_Power."""
    ctl, axis = make_axis(kind)
    power = MC_Power()
    power(Axis=axis, Enable=True, StopMode=stop_mode)
    settle(ctl, power, cycles=3)
    assert_error(power, 0x8405, 0x0011)


@pytest.mark.parametrize("start_mode", [2, -1, 9])
def test_s7_1200_mc_power_invalid_startmode_8412(start_mode):
    """§11.1.1 StartMode 0/1 (PROFIdrive axis); §12.8 16#8412/16#0011 invalid StartMode."""
    ctl, axis = make_axis("pd")
    power = MC_Power()
    power(Axis=axis, Enable=True, StartMode=start_mode)
    settle(ctl, power, cycles=3)
    assert_error(power, 0x8412, 0x0011)


def test_s7_1200_mc_power_invalid_stopmode_while_enabled_not_axis_error():
    """§9.6: a block parameter error (16#8405) is not an axis error: StatusBits.Error stays FALSE and a
    running motion continues."""
    ctl, axis, power = ready_axis("pd", homed=False)
    mv = start_velocity(ctl, axis, 30.0)
    power(StopMode=5)
    settle(ctl, power, mv, cycles=3)
    assert_error(power, 0x8405, 0x0011)
    assert not axis.StatusBits.Error
    assert mv.Busy and mv.InVelocity
    assert axis.Velocity == pytest.approx(30.0)


# ----------------------------------------------------------------------------------------------------
# Values at the edge of the permitted ranges are accepted (§11.1.x parameter tables)
ACCEPTED = [
    (MC_MoveAbsolute, "pd", True, dict(Position=1.0e12, Velocity=100.0)),
    (MC_MoveAbsolute, "pd", True, dict(Position=-1.0e12, Velocity=100.0)),
    (MC_MoveAbsolute, "pto", True, dict(Position=50.0, Velocity=10.0)),          # = start/stop velocity
    (MC_MoveAbsolute, "pto", True, dict(Position=50.0, Velocity=100.0)),         # = max velocity
    # Direction is evaluated only with modulo and ignored for PTO (§11.1.5)
    (MC_MoveAbsolute, "pd", True, dict(Position=50.0, Velocity=20.0, Direction=9)),
    (MC_MoveAbsolute, "pto", True, dict(Position=50.0, Velocity=20.0, Direction=9)),
    (MC_MoveRelative, "pd", False, dict(Distance=1.0e12, Velocity=100.0)),
    (MC_MoveRelative, "pd", False, dict(Distance=-1.0e12, Velocity=100.0)),
    (MC_MoveRelative, "pd", False, dict(Distance=1.0e9, Velocity=100.0)),
    (MC_MoveRelative, "pto", False, dict(Distance=1.0e9, Velocity=100.0)),
    (MC_MoveRelative, "pd", False, dict(Distance=1.0e11, Velocity=100.0)),
    (MC_MoveRelative, "pto_nojerk", False, dict(Distance=5.0e11, Velocity=100.0)),
    (MC_MoveAbsolute, "pto_nojerk", True, dict(Position=-5.0e11, Velocity=100.0)),
    (MC_MoveRelative, "pto", False, dict(Distance=-50.0, Velocity=10.0)),
    # MC_MoveVelocity: negative Velocity (sign = direction) and Velocity = 0.0 are permitted (§11.1.7)
    (MC_MoveVelocity, "pd", False, dict(Velocity=-100.0)),
    (MC_MoveVelocity, "pto", False, dict(Velocity=-10.0)),
    (MC_MoveVelocity, "pto", False, dict(Velocity=0.0)),
    (MC_MoveVelocity, "pd", False, dict(Velocity=0.0)),
    (MC_MoveVelocity, "pd", False, dict(Velocity=-40.0, Direction=1)),
    (MC_MoveVelocity, "pd", False, dict(Velocity=-40.0, Direction=2)),
    # Current = TRUE: Velocity and Direction are ignored (§11.1.7)
    (MC_MoveVelocity, "pd", False, dict(Velocity=NAN, Direction=9, Current=True)),
    (MC_MoveJog, "pto", False, dict(JogForward=True, Velocity=10.0)),
    (MC_MoveJog, "pd", False, dict(JogBackward=True, Velocity=100.0)),
    (MC_Home, "pd", False, dict(Mode=0, Position=1.0e12)),
    (MC_Home, "pd", False, dict(Mode=1, Position=-1.0e12)),
]


@pytest.mark.parametrize("row", ACCEPTED, ids=lambda r: f"{r[0].__name__}-{r[1]}-"
                         + ",".join(f"{k}={v}" for k, v in r[3].items()))
def test_s7_1200_valid_limit_values_accepted_11_1(row):
    """§11.1.x: values inside (and at the edge of) the documented ranges give no error."""
    cls, kind, homed, inputs = row
    ctl, axis, power = ready_axis(kind, homed=homed)
    fb = cls()
    _start(fb, axis, inputs)
    settle(ctl, fb, power, cycles=2)
    assert not fb.Error, f"{fb!r}"
    assert not power.Error


# ----------------------------------------------------------------------------------------------------
# Operating errors without axis stop 16#8200...16#820C (§9.6, §12.8)
NOT_ENABLED = [
    (MC_Halt, {}),
    (MC_MoveAbsolute, dict(Position=10.0, Velocity=20.0)),
    (MC_MoveRelative, dict(Distance=10.0, Velocity=20.0)),
    (MC_MoveVelocity, dict(Velocity=20.0)),
    (MC_MoveJog, dict(JogForward=True, Velocity=20.0)),
    (MC_MoveJog, dict(JogBackward=True, Velocity=20.0)),
    (MC_Home, dict(Mode=0, Position=5.0)),
    (MC_Home, dict(Mode=1, Position=5.0)),
]


@pytest.mark.parametrize("kind", ["pd", "pto"])
@pytest.mark.parametrize("cls,inputs", NOT_ENABLED, ids=lambda x: getattr(x, "__name__", None)
                         or ",".join(f"{k}={v}" for k, v in x.items()) or "-")
def test_s7_1200_not_enabled_8200(kind, cls, inputs):
    """§12.8 16#8200/16#0001 "Axis is not enabled" (requirement "axis enabled" of §11.1.3-§11.1.8);
    an operating error without axis stop: only at the instruction (§9.6)."""
    ctl, axis = make_axis(kind)
    power = MC_Power()
    power(Axis=axis, Enable=False)
    fb = cls()
    _start(fb, axis, inputs)
    settle(ctl, fb, power, cycles=2)
    assert_error(fb, 0x8200, 0x0001)
    assert not power.Error
    assert not axis.StatusBits.Error


def test_s7_1200_not_enabled_8200_homed_pd_axis_move_absolute():
    """§12.8 16#8200: MC_MoveAbsolute on a homed but disabled PROFIdrive axis (incremental encoder:
    disabling does not reset "homed", §11.1.3.1 list of resets)."""
    ctl, axis, power = ready_axis("pd", homed=True)
    power(Enable=False)
    ctl.run_until(lambda: not power().Status and not power.Busy, timeout=2.0)
    assert axis.StatusBits.HomingDone
    mv = MC_MoveAbsolute()
    mv(Axis=axis, Execute=True, Position=10.0, Velocity=20.0)
    settle(ctl, mv, power, cycles=2)
    assert_error(mv, 0x8200, 0x0001)


@pytest.mark.parametrize("kind", ["pd", "pto"])
def test_s7_1200_second_mc_power_8201(kind):
    """§12.8 16#8201/16#0001: axis already enabled by another MC_Power instance (§9.3 one MC_Power per
    axis).  Without axis stop: the first instance keeps the axis, the motion continues (§9.6)."""
    ctl, axis, power = ready_axis(kind, homed=False)
    mv = start_velocity(ctl, axis, 40.0)
    second = MC_Power()
    second(Axis=axis, Enable=True)
    settle(ctl, second, power, mv, cycles=3)
    assert_error(second, 0x8201, 0x0001)
    assert not second.Status
    assert power.Status and not power.Error
    assert not axis.StatusBits.Error
    assert mv.Busy and mv.InVelocity and not mv.CommandAborted
    assert axis.Velocity == pytest.approx(40.0)


@pytest.mark.parametrize("kind", ["pd", "pto"])
def test_s7_1200_not_homed_8204(kind):
    """§11.1.5 requirement "homed"; §12.8 16#8204/16#0001; without stop: a running motion continues,
    shown only at MC_MoveAbsolute (§9.6)."""
    ctl, axis, power = ready_axis(kind, homed=False)
    assert not axis.StatusBits.HomingDone
    mv = start_velocity(ctl, axis, 30.0)
    ma = MC_MoveAbsolute()
    ma(Axis=axis, Execute=True, Position=10.0, Velocity=20.0)
    settle(ctl, ma, mv, power, cycles=3)
    assert_error(ma, 0x8204, 0x0001)
    assert not power.Error and not axis.StatusBits.Error
    assert mv.Busy and mv.InVelocity and not mv.CommandAborted
    assert axis.Velocity == pytest.approx(30.0)


# ----------------------------------------------------------------------------------------------------
# §9.6 error display classes: errors without axis stop while a motion is running
def _bad_relative(axis):
    fb = MC_MoveRelative()
    fb(Axis=axis, Execute=True, Distance=NAN, Velocity=20.0)
    return fb, 0x8401, 0x0002


def _bad_absolute_velocity(axis):
    fb = MC_MoveAbsolute()
    fb(Axis=axis, Execute=True, Position=10.0, Velocity=500.0)
    return fb, 0x8402, 0x0008


def _bad_velocity_direction(axis):
    fb = MC_MoveVelocity()
    fb(Axis=axis, Execute=True, Velocity=10.0, Direction=4)
    return fb, 0x8403, 0x0011


def _bad_jog_velocity(axis):
    fb = MC_MoveJog()
    fb(Axis=axis, JogForward=True, Velocity=-10.0)
    return fb, 0x8402, 0x0024


def _bad_home_mode(axis):
    fb = MC_Home()
    fb(Axis=axis, Execute=True, Mode=5)
    return fb, 0x8404, 0x0011


def _home_not_configured(axis):
    fb = MC_Home()
    fb(Axis=axis, Execute=True, Mode=3)
    return fb, 0x8404, 0x0015


def _not_homed(axis):
    fb = MC_MoveAbsolute()
    fb(Axis=axis, Execute=True, Position=10.0, Velocity=20.0)
    return fb, 0x8204, 0x0001


def _second_power(axis):
    fb = MC_Power()
    fb(Axis=axis, Enable=True)
    return fb, 0x8201, 0x0001


WITHOUT_STOP = [_bad_relative, _bad_absolute_velocity, _bad_velocity_direction, _bad_jog_velocity,
                _bad_home_mode, _home_not_configured, _not_homed, _second_power]


@pytest.mark.parametrize("kind", ["pd", "pto"])
@pytest.mark.parametrize("trigger", WITHOUT_STOP, ids=lambda f: f.__name__.strip("_"))
def test_s7_1200_error_class_without_axis_stop_9_6(kind, trigger):
    """§9.6: operating errors without axis stop and block parameter errors: "If the axis is in motion,
    the motion is continued.  The errors are only indicated in the Motion Control instruction which
    triggers the error" -- not at MC_Power, no StatusBits.Error, no MC_Reset needed."""
    ctl, axis, power = ready_axis(kind, homed=False)
    mv = start_velocity(ctl, axis, 30.0)
    fb, error_id, error_info = trigger(axis)
    settle(ctl, fb, mv, power, cycles=3)
    assert_error(fb, error_id, error_info)
    assert not power.Error and power.ErrorID == 0
    assert not axis.StatusBits.Error
    assert not any(axis.ErrorBits.as_dict().values())
    assert mv.Busy and mv.InVelocity and not mv.CommandAborted and not mv.Error
    assert axis.Velocity == pytest.approx(30.0)
    # no acknowledgement needed: a new command is accepted at once
    mr = MC_MoveRelative()
    mr(Axis=axis, Execute=True, Distance=5.0, Velocity=20.0)
    settle(ctl, mr, mv, cycles=1)
    assert mr.Busy and not mr.Error
    assert mv.CommandAborted


# ----------------------------------------------------------------------------------------------------
# Operating errors with axis stop: SW limit switches 16#8001 / 16#8002 ErrorInfo 16#000E
def _limit_move(cls, direction):
    target = 150.0 * direction
    if cls is MC_MoveAbsolute:
        return dict(Execute=True, Position=target, Velocity=40.0)
    if cls is MC_MoveRelative:
        return dict(Execute=True, Distance=target, Velocity=40.0)
    if cls is MC_MoveVelocity:
        return dict(Execute=True, Velocity=40.0 * direction)
    return dict(JogForward=direction > 0, JogBackward=direction < 0, Velocity=40.0)


@pytest.mark.parametrize("kind", ["pd_sw", "pto_sw"])
@pytest.mark.parametrize("direction,error_id", [(+1, 0x8002), (-1, 0x8001)], ids=["high", "low"])
@pytest.mark.parametrize("cls", [MC_MoveAbsolute, MC_MoveRelative, MC_MoveVelocity, MC_MoveJog],
                         ids=lambda c: c.__name__)
def test_s7_1200_sw_limit_error_with_stop_8001_8002(kind, cls, direction, error_id):
    """§12.8 16#8001/16#8002 ErrorInfo 16#000E (SW limit reached with the configured deceleration);
    §9.6 operating error with axis stop: shown at the triggering instruction AND at MC_Power,
    StatusBits.Error TRUE, ErrorBits.SWLimit TRUE; needs MC_Reset (§11.1.2)."""
    ctl, axis, power = ready_axis(kind, homed=True)
    fb = cls()
    fb(Axis=axis, **_limit_move(cls, direction))
    ctl.run_until(lambda: fb().Error or (not fb.Busy and fb.Done), timeout=10.0)
    settle(ctl, fb, power, cycles=2)
    assert_error(fb, error_id, 0x000E)
    assert_error(power, error_id, 0x000E)
    assert power.Status                      # 16#000E: no "remove enable" (§12.8 reaction column)
    assert axis.StatusBits.Error and axis.ErrorBits.SWLimit
    assert axis.Velocity == 0.0
    assert axis.Position == pytest.approx(100.0 * direction, abs=1e-6)
    # still pending until MC_Reset (§11.1.2): a new command is rejected
    mr = MC_MoveRelative()
    mr(Axis=axis, Execute=True, Distance=-10.0 * direction, Velocity=20.0)
    settle(ctl, mr, power, cycles=1)
    assert mr.Error and not mr.Busy
    assert (mr.ErrorID, mr.ErrorInfo) == (error_id, 0x000E)        # documented decision
    assert axis.StatusBits.Error
    # acknowledge (§11.1.2.1: Done TRUE and StatusBits.Error FALSE)
    reset = MC_Reset()
    reset(Axis=axis, Execute=True)
    settle(ctl, reset, power, cycles=2)
    assert reset.Done and not reset.Error
    assert not axis.StatusBits.Error and not axis.ErrorBits.SWLimit
    assert not power.Error and power.ErrorID == 0 and power.Status


# ----------------------------------------------------------------------------------------------------
# Configuration error of the axis at runtime: 16#8608 (§9.6 "Value for Acceleration is invalid")
def _decel_profile(ctl, axis, power, *fbs, timeout=1.0):
    """Run until standstill; return the setpoint accelerations seen on the way (one per servo cycle)."""
    acc = []

    def rec(_t):
        acc.append(axis.Acceleration)

    ctl.on_post_servo(rec)
    try:
        ctl.run_until(lambda: [fb() for fb in fbs + (power,)] and axis.Velocity == 0.0, timeout=timeout)
    finally:
        ctl.remove_hook(rec)
    return acc


@pytest.mark.parametrize("value,infos", [(-1.0, (0x0004, 0x0030)), (0.0, (0x0004, 0x0030)),
                                         (NAN, (0x0002, 0x0030)), (INF, (0x0002, 0x0003, 0x0030))],
                         ids=["minus1", "zero", "nan", "inf"])
def test_s7_1200_runtime_invalid_acceleration_8608_pd(value, infos):
    """§9.6 configuration error on the TO ("Value for Acceleration is invalid"), §12.8 16#8608:
    an invalid runtime write of DynamicDefaults.Acceleration (effective next servo cycle on a PROFIdrive
    axis, §12.9 code 10) stops the moving axis with the emergency stop deceleration (without jerk limit,
    §12.8 reaction), the error is shown at MC_Power with StatusBits.Error / ErrorBits.ConfigFault, and
    MC_Reset acknowledges it only once the value is valid again (§11.1.2.1 requirements)."""
    ctl, axis, power = ready_axis("pd", homed=False)
    mv = start_velocity(ctl, axis, 50.0)
    axis.DynamicDefaults.Acceleration = value
    acc = _decel_profile(ctl, axis, power, mv, timeout=0.5)
    settle(ctl, mv, power, cycles=2)
    # emergency deceleration 500 without jerk: 50 -> 0 in 0.1 s at |a| = 500
    assert len(acc) <= 100 + 8
    assert max(abs(a) for a in acc) == pytest.approx(500.0, rel=1e-6)
    assert_error(power, 0x8608, infos)
    assert axis.StatusBits.Error and axis.ErrorBits.ConfigFault
    assert not mv.Busy
    # a new command is rejected while the error is pending
    mr = MC_MoveRelative()
    mr(Axis=axis, Execute=True, Distance=10.0, Velocity=20.0)
    settle(ctl, mr, power, cycles=1)
    assert mr.Error and mr.ErrorID == 0x8608
    # MC_Reset while the value is still invalid does not clear the error
    reset = MC_Reset()
    reset(Axis=axis, Execute=True)
    settle(ctl, reset, power, cycles=3)
    assert not reset.Done
    assert axis.StatusBits.Error
    assert_error(power, 0x8608, infos)
    reset(Execute=False)
    settle(ctl, reset, power, cycles=1)
    # correct the value online and acknowledge: the error is gone (§12.8 remedy "DL|ONL")
    axis.DynamicDefaults.Acceleration = 50.0
    settle(ctl, power, cycles=2)
    reset(Execute=True)
    settle(ctl, reset, power, cycles=3)
    assert reset.Done and not reset.Error
    assert not axis.StatusBits.Error and not axis.ErrorBits.ConfigFault
    ctl.run_until(lambda: power().Status, timeout=2.0)      # §11.1.1 note: re-enabled automatically
    assert not power.Error and power.ErrorID == 0
    mr2 = MC_MoveRelative()
    mr2(Axis=axis, Execute=True, Distance=10.0, Velocity=20.0)
    ctl.run_until(lambda: mr2().Done or mr2.Error, timeout=5.0)
    assert mr2.Done


@pytest.mark.parametrize("path,error_id", [("Acceleration", 0x8608), ("Deceleration", 0x8609),
                                           ("EmergencyDeceleration", 0x860A)])
def test_s7_1200_runtime_invalid_dynamics_pto_at_next_command(path, error_id):
    """§12.9 effective code 5 (PTO: at the next start of a motion command) + §9.6/§12.8: the invalid
    value gives a configuration error at the triggering instruction and at MC_Power; MC_Reset does not
    clear it until the value is valid again."""
    ctl, axis, power = ready_axis("pto", homed=False)
    setattr(axis.DynamicDefaults, path, -1.0)
    mr = MC_MoveRelative()
    mr(Axis=axis, Execute=True, Distance=10.0, Velocity=20.0)
    settle(ctl, mr, power, cycles=2)
    assert_error(mr, error_id, (0x0004, 0x0030))
    assert_error(power, error_id, (0x0004, 0x0030))
    assert axis.StatusBits.Error and axis.ErrorBits.ConfigFault
    assert axis.Velocity == 0.0
    reset = MC_Reset()
    reset(Axis=axis, Execute=True)
    settle(ctl, reset, power, cycles=2)
    assert not reset.Done and axis.StatusBits.Error
    reset(Execute=False)
    setattr(axis.DynamicDefaults, path, 50.0 if path != "EmergencyDeceleration" else 500.0)
    settle(ctl, reset, power, cycles=1)
    reset(Execute=True)
    settle(ctl, reset, power, cycles=2)
    assert reset.Done and not axis.StatusBits.Error
    ctl.run_until(lambda: power().Status, timeout=2.0)
    assert not power.Error
    mr(Execute=False)
    mr()
    mr(Execute=True)
    ctl.run_until(lambda: mr().Done or mr.Error, timeout=5.0)
    assert mr.Done


def test_s7_1200_mc_reset_without_pending_error_done():
    """§11.1.2.1: MC_Reset with nothing to acknowledge completes with Done (StatusBits.Error FALSE)."""
    ctl, axis, power = ready_axis("pd", homed=False)
    reset = MC_Reset()
    reset(Axis=axis, Execute=True)
    settle(ctl, reset, cycles=2)
    assert reset.Done and not reset.Error and not axis.StatusBits.Error


@pytest.mark.parametrize("kind", ["pd", "pto"])
def test_s7_1200_jog_both_directions_while_jogging_8406(kind):
    """§11.1.8: JogForward and JogBackward TRUE at the same time: "the axis stops with the configured
    deceleration" and Error 16#8406/16#0001 (a block parameter error: not at MC_Power, §9.6); Error is
    latched while a jog input is TRUE (§9.5.4)."""
    ctl, axis, power = ready_axis(kind, homed=False)
    jog = MC_MoveJog()
    jog(Axis=axis, JogForward=True, Velocity=40.0)
    ctl.run_until(lambda: jog().InVelocity, timeout=3.0)
    jog(JogBackward=True)
    acc = _decel_profile(ctl, axis, power, jog, timeout=3.0)
    settle(ctl, jog, power, cycles=2)
    assert_error(jog, 0x8406, 0x0001)
    assert not power.Error and not axis.StatusBits.Error
    # configured deceleration 50 (jerk 500), not the emergency deceleration 500
    assert max(abs(a) for a in acc) == pytest.approx(50.0, rel=1e-6)
    jog(JogForward=False)
    settle(ctl, jog, cycles=1)
    assert jog.Error                      # still latched: JogBackward is TRUE
    jog(JogBackward=False)
    settle(ctl, jog, cycles=1)
    assert not jog.Error and jog.ErrorID == 0


def test_s7_1200_pto_disable_resets_homed_8204():
    """§2.5 / §11.1.3.1: disabling a PTO axis with MC_Power resets "homed"; after enabling again
    MC_MoveAbsolute gives 16#8204/16#0001."""
    ctl, axis, power = ready_axis("pto", homed=True)
    power(Enable=False)
    ctl.run_until(lambda: not power().Status and not power.Busy, timeout=2.0)
    assert not axis.StatusBits.HomingDone
    enable(ctl, axis, power)
    ma = MC_MoveAbsolute()
    ma(Axis=axis, Execute=True, Position=10.0, Velocity=20.0)
    settle(ctl, ma, power, cycles=2)
    assert_error(ma, 0x8204, 0x0001)


@pytest.mark.parametrize("row", [r for r in BLOCK_PARAMETER_ERRORS if r[0] is not MC_MoveJog][::6], ids=_row_id)
def test_s7_1200_parameter_error_latched_while_execute_9_5_2(row):
    """§9.5.2: Error is TRUE for at least one cycle, latched while Execute stays TRUE and reset together
    with Execute (ErrorID back to 16#0000)."""
    cls, kind, homed, inputs, error_id, error_info = row
    ctl, axis, power = ready_axis(kind, homed=homed)
    fb = cls()
    _start(fb, axis, inputs)
    settle(ctl, fb, cycles=5)
    assert_error(fb, error_id, error_info)
    fb(Execute=False)
    assert not fb.Error and fb.ErrorID == 0 and fb.ErrorInfo == 0 and not fb.Busy
    settle(ctl, fb, cycles=2)
    assert not fb.Error and fb.ErrorID == 0
