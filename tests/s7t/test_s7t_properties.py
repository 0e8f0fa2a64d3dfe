"""Invariants of the S7-Technology instructions under any input (S7-Technology V4.1 §5.8, §5.10, §4.5.7.3,
§6.9.3): a call never raises and never stops the CPU, the axis never passes its software limit switches
(active, "Homing required" = NO: always monitored), and the status outputs stay exclusive - at most one of
Done / CommandAborted / Error, and none of them while Busy.
"""
from __future__ import annotations

import math

import pytest

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from plcmotion.s7t import (MC_ChangeDataset, MC_Halt, MC_Home, MC_MoveAbsolute, MC_MoveAdditive, MC_MoveRelative,
                           MC_MoveSuperImposed, MC_MoveToEndPos, MC_MoveVelocity, MC_SetTorqueLimit, MC_Stop)

from _s7t_rig import VIRTUAL, enabled

LIMIT = 200.0
LIMITS = {**VIRTUAL, "swlimit": {"state": 1, "minusposition": -LIMIT, "plusposition": LIMIT},
          "TypeOfAxis.MaxVelocity.maximum": 400.0, "TypeOfAxis.MaxAcceleration.maximum": 2000.0}

REALS = st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.sampled_from(
    [-1.0, 0.0, 1.0e-300, 1.0e12, -1.0e12, 2.0e12, 5.0, 50.0, 500.0, 10**400, -(10**400)]),
    st.integers(-10**6, 10**6), st.just("7"), st.none())
INTS = st.one_of(st.integers(-3, 40), st.sampled_from([2**31, -(2**31), 1.5, math.nan]), st.just(True))
FBS = [MC_MoveAbsolute, MC_MoveRelative, MC_MoveAdditive, MC_MoveSuperImposed, MC_MoveVelocity, MC_Halt, MC_Stop]
REAL_INPUTS = ("Position", "Distance", "Velocity", "VelocityDiff", "Acceleration", "Deceleration", "Jerk",
               "Torque", "MaxTorque")
INT_INPUTS = ("Mode", "Direction", "DoneFlag", "Dataset")

#: an electric real axis (telegram 105, torque reduction) with two data sets and a fixed end stop inside its
#: software limit switches, for the instructions a virtual axis does not take
DS = "TypeOfAxis.NumberOfDataSets"
CLAMP = f"{DS}.DataSet_1.ClampingMonitoring"
REAL_LIMITS = {"TypeOfAxis.Homing.referencingNecessary": 0, "Wizard.Telegram": 105,
               "swlimit": {"state": 1, "minusposition": -LIMIT, "plusposition": LIMIT},
               "TypeOfAxis.MaxVelocity.maximum": 400.0, "TypeOfAxis.MaxAcceleration.maximum": 2000.0,
               f"{CLAMP}.recognitionMode": 106, f"{CLAMP}.followingErrorDeviation": 1.0,
               f"{CLAMP}.positionTolerance": 0.1, "Plant.EndStopMaxPosition": LIMIT / 4,
               f"{DS}.numberOfDataSets": 2, f"{DS}.DataSet_2.ControllerStruct.PV_Controller.kv": 40.0}
REAL_FBS = FBS + [MC_MoveToEndPos, MC_SetTorqueLimit, MC_Home, MC_ChangeDataset]


@st.composite
def command(draw, fbs=FBS):
    fb = draw(st.sampled_from(range(len(fbs))))
    cls = fbs[fb]
    inputs = {name: draw(REALS) for name in REAL_INPUTS if name in cls.INPUTS and draw(st.booleans())}
    inputs.update({name: draw(INTS) for name in INT_INPUTS if name in cls.INPUTS and draw(st.booleans())})
    if "Axis" in inputs:
        del inputs["Axis"]
    return fb, inputs, draw(st.sampled_from([0.0, 0.02, 0.2, 1.0])), draw(st.booleans())


def _exclusive(inst) -> bool:
    o = inst.outputs
    finals = [o.get("Done", False), o.get("CommandAborted", False), o.get("Error", False)]
    return sum(finals) <= 1 and not (o["Busy"] and any(finals))


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(command(), min_size=1, max_size=6))
def test_s7t_bad_inputs_never_raise_nor_pass_the_limits(commands):
    """S7-Technology V4.1 §6.9.3, §4.5.7.3: any input values: the instructions answer with ErrorIDs, the CPU
    stays in RUN and the axis stays inside its software limit switches; outputs stay exclusive (§5.8)."""
    _run(LIMITS, FBS, commands)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(command(REAL_FBS), min_size=1, max_size=6))
def test_s7t_bad_inputs_on_a_real_axis_never_raise_nor_pass_the_limits(commands):
    """S7-Technology V4.1 §6.9.3, §4.5.7.3, §5.8 on an electric real axis, with MC_MoveToEndPos (§6.2.11),
    MC_SetTorqueLimit (§6.2.12), MC_Home (§6.2.2) and MC_ChangeDataset (§6.2.5) in the mix: no call raises,
    the CPU stays in RUN, outputs stay exclusive and the axis stays inside its software limit switches
    until an MC_Home command redefines its coordinates."""
    _run(REAL_LIMITS, REAL_FBS, commands)


def _run(params: dict, fbs: list, commands) -> None:
    ctl, axis, _ = enabled(params, run=0.01)
    instances = [cls() for cls in fbs]
    b, i = ctl.bank, axis.index
    homed = False                        # an MC_Home sets the position anywhere: the limits are its coordinates
    for fb, inputs, wait, release in commands:
        inst = instances[fb]
        inst(Axis=axis, Execute=False)
        inst(Axis=axis, Execute=True, **inputs)
        homed = homed or isinstance(inst, MC_Home)
        assert _exclusive(inst)
        steps = max(1, int(wait / ctl.app_cycle))
        for _ in range(steps):
            ctl.step()
            for other in instances:
                other(Execute=other.Execute and not release)
                assert _exclusive(other)
            assert ctl.mode == "RUN", ctl.stop_reason
            if not homed:
                assert -LIMIT - 1e-6 <= float(b.sp_p[i]) <= LIMIT + 1e-6
                assert -LIMIT - 1e-6 <= float(b.act_p[i]) <= LIMIT + 1e-6


def test_s7t_superimposed_motion_stops_at_the_limit():
    """S7-Technology V4.1 §4.5.7.3, §6.2.9: a superimposed positioning that would carry the axis past its
    software limit switch ends at the switch; warning 16#0026 (position limited to the software limit
    switch) in the technology DB."""
    ctl, axis, _ = enabled(LIMITS, run=0.01)
    b, i = ctl.bank, axis.index
    move, sup = MC_MoveAbsolute(), MC_MoveSuperImposed()
    move(Axis=axis, Execute=True, Position=150.0, Velocity=100.0)
    ctl.run(0.5)
    sup(Axis=axis, Execute=True, Distance=100.0, VelocityDiff=50.0)
    top = 0.0
    for _ in range(1000):
        ctl.step()
        top = max(top, float(b.sp_p[i]))
    assert move(Execute=True).Done and sup(Execute=True).Done
    assert top == pytest.approx(LIMIT, abs=1e-6) and float(b.sp_p[i]) == pytest.approx(LIMIT, abs=1e-6)
    assert axis.db.ErrorID == 0x0026 and not axis.db.Statusword.Error
