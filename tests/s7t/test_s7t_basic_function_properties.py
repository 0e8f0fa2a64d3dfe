"""Invariants of the basic-function FBs of S7-Technology V4.1 §6.7 under any input: a call never raises and
never stops the CPU, an ErrorID is one the FB's table lists (§6.7.2-§6.7.11), the status outputs stay
exclusive (§5.8) and a running motion is never aborted by them (§6.8).
"""
from __future__ import annotations

import math

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from plcmotion.s7t import (MC_ActivateDPSlave, MC_ActivateTO, MC_MoveVelocity, MC_Power, MC_ReadDriveParameter,
                           MC_ReadPeriphery, MC_ReadRecord, MC_ReadSysParameter, MC_WriteDriveParameter,
                           MC_WriteParameter, MC_WritePeriphery, MC_WriteRecord)
from plcmotion.s7t.fb_errors import fb_codes

from _s7t_rig import VIRTUAL, controller

FBS = [MC_ReadSysParameter, MC_WriteParameter, MC_ReadPeriphery, MC_WritePeriphery, MC_ReadRecord, MC_WriteRecord,
       MC_ReadDriveParameter, MC_WriteDriveParameter, MC_ActivateTO, MC_ActivateDPSlave]
ANY = st.one_of(
    st.integers(-70000, 70000), st.sampled_from([0, 1, 2, 3, 47, 63, 64, 256, 1023, 2000, 4142, 4241, 2**31]),
    st.floats(allow_nan=True, allow_infinity=True), st.sampled_from([1.5, -0.0, 1e12, math.nan]),
    st.none(), st.just("x"), st.binary(max_size=70), st.binary(max_size=70).map(bytearray))
BOOL_INPUTS = ("InOut", "InputOutput", "ValueBool")


@st.composite
def call(draw):
    cls = draw(st.sampled_from(range(len(FBS))))
    names = [n for n in FBS[cls].INPUTS if n not in ("Execute", "Enable", *BOOL_INPUTS)]
    inputs = {n: draw(ANY) for n in names if draw(st.booleans())}
    inputs.update({n: draw(st.booleans()) for n in BOOL_INPUTS if n in FBS[cls].INPUTS})
    return cls, inputs, draw(st.booleans()), draw(st.sampled_from([0.0, 0.004, 0.02]))


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(call(), min_size=1, max_size=8))
def test_s7t_basic_functions_any_input(calls):
    """S7-Technology V4.1 §6.7, §6.8: arbitrary inputs give the FB's ErrorIDs, never an exception; the CPU stays
    in RUN, outputs stay exclusive, and the motion of an axis is not aborted."""
    ctl = controller()
    axis = ctl.add_positioning_axis("Virtual", VIRTUAL)
    ctl.add_positioning_axis("Real", {"TypeOfAxis.Homing.referencingNecessary": 0})     # a drive on DP(DRIVE)
    power, move = MC_Power(), MC_MoveVelocity()
    ctl.program(lambda: power(Axis=axis, Enable=True))
    ctl.run(0.05)
    move(Axis=axis, Execute=True, Velocity=10.0)
    instances = [cls() for cls in FBS]
    for index, inputs, edge, wait in calls:
        inst = instances[index]
        start = "Enable" if "Enable" in inst.INPUTS else "Execute"
        axis_input = {"Axis": axis} if "Axis" in inst.INPUTS and "Axis" not in inputs else {}
        inst(**{start: False})
        inst(**{start: edge, **axis_input, **inputs})
        ctl.run(wait)
        out = inst.outputs
        finals = [out.get("Done", False), out.get("Error", False)]
        assert sum(finals) <= 1 and not (out["Busy"] and any(finals)), (inst, inputs)
        if out["Error"]:
            assert out["ErrorID"] in fb_codes(type(inst).__name__), (inst, hex(out["ErrorID"]), inputs)
        assert ctl.mode == "RUN", ctl.stop_reason
    move(Execute=True)
    assert not move.CommandAborted or axis.alarms, axis.alarms      # only an error of the axis ends it
