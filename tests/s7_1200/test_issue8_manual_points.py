"""Issue 8, manual points of S7-1200 found wrong: the input filter timed from the switch edge (decision 33,
S7-1200 V6 §5.4.4.5), Simulation.Mode written with MC_WriteParam (V6 §12.9.19) and the V7 tags
StatusSensor[1].* / ErrorBits.AdaptionError (V7 §12.9.20, §12.9.22)."""
from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from test_s7_1200_homing import SERVO, Bench

from plcmotion.s7_1200 import MC_MoveVelocity


# --- decision 33: the input filter runs from the edge ------------------------------------------------------
@settings(max_examples=12)
@given(filt=st.sampled_from([0.0004, 0.001, 0.0025, 0.0064, 0.0095]),
       velocity=st.floats(min_value=1.0, max_value=40.0), start=st.floats(min_value=99.0, max_value=99.5))
def test_s7_1200_decision33_filtered_input_changes_within_filter_plus_one_servo_cycle(filt, velocity, start):
    """S7-1200 V6 §5.4.4.5 (input filter, 6.4 ms by default), decision 33: the homing switch input (as the CPU
    sees it, ``ctl.inputs``) changes in the first servo cycle at or after switch edge + filter time, i.e.
    filter time + [0, 1) servo cycle after the load crossed the end of the switch - for any filter time and
    any phase of the edge between two servo cycles (issue 8: 7.75 ms with the default 6.4 ms filter)."""
    b = Bench(actor=1, extra={"Plant.InitialPosition": start}, cam_filter=filt)
    rows: list[tuple[float, float, bool]] = []
    b.ctl.on_post_servo(lambda t: rows.append((t, b.axis.drive.mechanical_position(), b.ctl.inputs["I0.0"])))
    b.start(MC_MoveVelocity(), Velocity=velocity)
    b.until(lambda: bool(rows) and rows[-1][2], 2.0, "the filtered homing switch input came on")
    k = next(i for i, r in enumerate(rows) if r[1] >= 100.0)        # first sample on the switch
    (t0, x0, _), (t1, x1, _) = rows[k - 1], rows[k]
    edge = t0 + (t1 - t0) * (100.0 - x0) / (x1 - x0)               # where the load crossed the switch end
    seen = next(r[0] for r in rows if r[2])                         # first servo cycle that sees it
    assert filt - 1e-9 <= seen - edge < filt + SERVO, (seen - edge, filt)


# --- S7-1200 V6 §12.9.19: Simulation.Mode of a PTO axis is WP --------------------------------------------
def _pto_axis():
    from plcmotion import Controller

    ctl = Controller()
    axis = ctl.add_positioning_axis("Axis_1", {"Actor": {"Type": 2},
                                               "DynamicLimits": {"MaxVelocity": 100.0, "MinVelocity": 1.0}})
    return ctl, axis


def test_s7_1200_12_9_19_pto_simulation_mode_written_with_write_param_gives_8647_at_enable():
    """S7-1200 V6 §12.9.19: Simulation.Mode has access WP for a PTO axis (MC_WriteParam while the axis is
    disabled, effective at enable, code 2); §12.8 16#8647/16#0001 "simulation is not supported for PTO axes":
    enabling the PTO axis with Mode 1 fails with that code; writing 0 back, MC_Reset and enable work again."""
    from plcmotion.s7_1200 import MC_Power, MC_Reset, MC_WriteParam
    from plcmotion.s7_1200.variables import DInt

    ctl, axis = _pto_axis()
    wp = MC_WriteParam(Parameter=axis.ref("Simulation.Mode"), Value=DInt(1), Execute=True)
    wp()
    assert wp.Done and not wp.Error, wp.outputs
    assert axis.tag("Simulation.Mode") == 1 and not axis.StatusBits.AxisSimulation
    power = MC_Power(Axis=axis, Enable=True)
    for _ in range(5):
        power()
        ctl.step()
    power()
    assert power.Error and (power.ErrorID, power.ErrorInfo) == (0x8647, 0x0001), power.outputs
    assert not power.Status and not axis.StatusBits.Enable and axis.StatusBits.Error
    assert axis.ErrorBits.ConfigFault
    # correct the value (axis still disabled), acknowledge, enable
    power.Enable = False
    power()
    back = MC_WriteParam(Parameter=axis.ref("Simulation.Mode"), Value=DInt(0), Execute=True)
    back()
    assert back.Done, back.outputs
    reset = MC_Reset(Axis=axis, Execute=True)
    reset()
    ctl.step()
    power.Enable = True
    for _ in range(5):
        power()
        reset()
        ctl.step()
    assert power.Status and not power.Error and axis.StatusBits.Enable, (power.outputs, axis.alarms)


def test_s7_1200_12_9_19_pto_simulation_mode_not_written_while_enabled_nor_directly():
    """WP: only while the axis is disabled (16#8410/16#002C otherwise, §12.8); not by direct assignment."""
    from plcmotion import TagAccessError
    from plcmotion.s7_1200 import MC_Power, MC_WriteParam
    from plcmotion.s7_1200.variables import DInt

    ctl, axis = _pto_axis()
    power = MC_Power(Axis=axis, Enable=True)
    ctl.program(power)
    ctl.run(0.02)
    assert power.Status
    wp = MC_WriteParam(Parameter=axis.ref("Simulation.Mode"), Value=DInt(1), Execute=True)
    wp()
    assert wp.Error and (wp.ErrorID, wp.ErrorInfo) == (0x8410, 0x002C), wp.outputs
    with pytest.raises(TagAccessError):
        axis.set_tag("Simulation.Mode", 1)
    assert axis.ref("Simulation.Mode").access == "WP"


# --- S7-1200 V7 §12.9.20 / §12.9.22: StatusSensor[1].* and ErrorBits.AdaptionError -------------------------
V7_SENSOR = ("StatusSensor[1].State", "StatusSensor[1].CommunicationOK", "StatusSensor[1].AbsEncoderOffset",
             "StatusSensor[1].AdaptionState")


def _pd_axis(version: int):
    from plcmotion import Controller

    ctl = Controller(technology_version=version)
    axis = ctl.add_positioning_axis("Axis_1", {"Actor": {"Type": 1}})
    return ctl, axis


def test_s7_1200_v7_12_9_20_status_sensor_array_and_adaption_error_read_and_trace():
    """S7-1200 V7 §12.9.20: the encoder status is the structure StatusSensor[1] (State 0/1/2, CommunicationOK,
    AbsEncoderOffset, AdaptionState); §12.9.22: ErrorBits.AdaptionError (error in the data transfer).  With
    technology_version=7 they read by path and attribute, trace, and MC_ReadParam reads them (RP)."""
    from plcmotion.s7_1200 import MC_ReadParam
    from plcmotion.s7_1200.variables import Bool
    from plcmotion.trace import Trace

    ctl, axis = _pd_axis(7)
    assert axis.tag("StatusSensor[1].State") == 2                     # 2: valid
    assert axis.StatusSensor[1].State == 2
    assert axis.tag("StatusSensor[1].CommunicationOK") is True
    assert axis.StatusSensor[1].AbsEncoderOffset == 0.0
    assert axis.ErrorBits.AdaptionError is False
    assert axis.tag("StatusSensor.State") == 2                         # the Openness name still reads
    axis.inject_fault("encoder", "station")
    assert axis.StatusSensor[1].State == 0 and axis.StatusSensor[1].CommunicationOK is False
    trace = Trace(ctl, [f"Axis_1.{p}" for p in V7_SENSOR] + ["Axis_1.ErrorBits.AdaptionError"]).start()
    ctl.run(0.01)
    data = trace.stop().data
    assert list(data["Axis_1.StatusSensor[1].State"][-3:]) == [0, 0, 0]
    assert list(data["Axis_1.ErrorBits.AdaptionError"][-3:]) == [0, 0, 0]
    value = Bool(True)
    rp = MC_ReadParam(Enable=True, Parameter=axis.ref("StatusSensor[1].CommunicationOK"), Value=value)
    rp()
    assert rp.Valid and value.value is False, rp.outputs


def test_s7_1200_v6_12_9_22_has_no_status_sensor_array_nor_adaption_error():
    """S7-1200 V6 §12.9.22 lists StatusSensor.State/CommunicationOK/AbsEncoderOffset (no array) and V6's
    ErrorBits (§12.9.24) have no AdaptionError: with technology_version=6 these V7 tags do not exist."""
    from plcmotion.trace import Trace, UnknownSignalError

    ctl, axis = _pd_axis(6)
    assert axis.tag("StatusSensor.State") == 2
    for path in ("StatusSensor[1].State", "StatusSensor[1].CommunicationOK", "ErrorBits.AdaptionError"):
        with pytest.raises(KeyError):
            axis.tag(path)
    with pytest.raises(AttributeError):
        axis.ErrorBits.AdaptionError
    with pytest.raises(UnknownSignalError):
        Trace(ctl, ["Axis_1.StatusSensor[1].State"])
