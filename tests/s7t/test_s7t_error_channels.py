"""The two error channels of S7-Technology (S7-Technology V4.1 §5.10, §5.12, §6.7.1, §6.9.3, §7.12).

Channel 1: a command that cannot be started shows Error/ErrorID at its instruction (no acknowledgement, the
next command clears it).  Channel 2: an error while the object runs (or a check made after the command was
accepted) ends the command with CommandAborted; the ErrorID is in the technology DB (ErrorID, the first
three in ErrorBuffer, Statusword.Error/Errorstop, an ErrorStatus bit) until MC_Reset.  Warnings 00xx go to
the technology DB without Statusword.Error.  The instruction ErrorIDs are table-driven below.
"""
from __future__ import annotations

import math

import pytest

from plcmotion import s7t
from plcmotion.s7t import (MC_Halt, MC_MoveAbsolute, MC_MoveAdditive, MC_MoveRelative, MC_MoveSuperImposed,
                           MC_MoveVelocity, MC_Power, MC_Reset, MC_Stop)

from _s7t_rig import VIRTUAL, controller, enabled

REAL_AXIS = {"TypeOfAxis.Homing.referencingNecessary": 0}


def test_s7t_command_error_needs_no_acknowledgement():
    """S7-Technology V4.1 §5.10: MC_MoveAbsolute on a disabled axis cannot start: Error, ErrorID 16#8040 at the
    instruction, ENO FALSE, nothing in the technology DB; after enabling, the next command runs without
    MC_Reset."""
    ctl = controller()
    axis = ctl.add_positioning_axis("A", VIRTUAL)
    move = MC_MoveAbsolute()
    out = move(Axis=axis, Execute=True, Position=10.0)
    assert out is move and move.Error and move.ErrorID == 0x8040 and not move.Busy and move.ENO is False
    assert move.BIE is False
    ctl.run(0.02)
    assert axis.db.ErrorID == 0 and list(axis.db.ErrorBuffer) == [0, 0, 0] and not axis.db.Statusword.Error
    power = MC_Power()
    ctl.program(lambda: power(Axis=axis, Enable=True))
    ctl.run(0.02)
    move(Execute=False)
    assert not move.Error and move.ENO
    move(Execute=True)
    assert move.Busy and not move.Error


def test_s7t_error_while_running_goes_to_the_technology_db():
    """S7-Technology V4.1 §5.12, §7.12.1: a blocked real axis exceeds its following error: the running
    MC_MoveVelocity ends with CommandAborted (no Error), the DB shows ErrorID 16#8016, ErrorBuffer[0],
    Statusword.Error and Errorstop, ErrorStatus.FollowingError; MC_Power Status drops.  MC_Reset clears the
    DB and, Enable still TRUE, the axis is enabled again (§6.2.1 example)."""
    ctl, axis, power = enabled(REAL_AXIS, run=0.3)
    move = MC_MoveVelocity()
    move(Axis=axis, Execute=True, Velocity=50.0)
    ctl.run(0.5)
    axis.disturb_load(blocked=True)
    ctl.run(1.0)
    move(Execute=True)
    assert move.CommandAborted and not move.Error and move.ErrorID == 0 and not move.Busy
    db = axis.db
    assert db.ErrorID == 0x8016 and db.ErrorBuffer[0] == 0x8016 and db.ErrorBuffer[1] == 0
    assert db.Statusword.Error and db.Statusword.Errorstop and db.ErrorStatus.FollowingError
    assert not power.Status and power.Busy and not power.Error
    axis.disturb_load(blocked=False)
    reset = MC_Reset()
    reset(Axis=axis, Execute=True)
    assert reset.Done and db.ErrorID == 0 and list(db.ErrorBuffer) == [0, 0, 0] and db.ErrorStatus == 0
    ctl.run(0.3)
    assert power.Status and not axis.db.Statusword.Error


def test_s7t_error_buffer_keeps_the_first_three():
    """S7-Technology V4.1 §5.12: ErrorBuffer holds the first three errors/warnings since the last
    acknowledgement (element 0 the first), ErrorID the latest; warnings (16#0021: dynamic values limited to
    the maximum velocity) leave Statusword.Error FALSE."""
    ctl, axis, power = enabled({**REAL_AXIS, "TypeOfAxis.MaxVelocity.maximum": 100.0}, run=0.3)
    for distance in (1.0, -1.0, 1.0, -1.0):
        move = MC_MoveRelative()
        move(Axis=axis, Execute=True, Distance=distance, Velocity=500.0)
        ctl.run_until(lambda: move(Execute=True).Done, 2.0)
    ctl.run(0.01)
    assert axis.db.ErrorID == 0x0021 and list(axis.db.ErrorBuffer) == [0x0021] * 3
    assert not axis.db.Statusword.Error
    reset = MC_Reset()
    reset(Axis=axis, Execute=True)
    assert reset.Done and list(axis.db.ErrorBuffer) == [0, 0, 0]
    move = MC_MoveRelative()
    move(Axis=axis, Execute=True, Distance=1.0, Velocity=500.0)
    ctl.run(0.1)
    axis.disturb_load(blocked=True)
    move2 = MC_MoveVelocity()
    move2(Axis=axis, Execute=True, Velocity=80.0)
    ctl.run(2.0)
    assert list(axis.db.ErrorBuffer)[:2] == [0x0021, 0x8016] and axis.db.ErrorID == 0x8016
    assert axis.db.Statusword.Error


def test_s7t_not_homed_is_a_technology_error():
    """S7-Technology V4.1 §6.2.6, §7.12.1: with "Homing required" = YES the technology refuses an absolute
    positioning of an axis that is not homed after accepting it: CommandAborted at the instruction (8041 is
    none of its ErrorIDs) and 16#8041 in the technology DB."""
    ctl, axis, _ = enabled({"Wizard.Virtual": 1})
    move = MC_MoveAbsolute()
    move(Axis=axis, Execute=True, Position=10.0)
    assert move.CommandAborted and not move.Error
    assert axis.db.ErrorID == 0x8041 and axis.db.ErrorStatus.UserFault


def test_s7t_stop_holds_the_axis_8045():
    """S7-Technology V4.1 §6.2.3 example b: while MC_Stop.Execute is TRUE a motion command gets 16#8045."""
    ctl, axis, _ = enabled()
    stop = MC_Stop()
    stop(Axis=axis, Execute=True)
    ctl.run(0.01)
    move = MC_MoveVelocity()
    move(Axis=axis, Execute=True, Velocity=10.0)
    assert move.Error and move.ErrorID == 0x8045 and axis.db.ErrorID == 0


# --- instruction ErrorIDs, table-driven (§6.1 common ErrorIDs, §6.2 per instruction) ----------------------
NAN, INF = math.nan, math.inf
MOVES = [
    # instruction, inputs, ErrorID
    (MC_MoveAbsolute, dict(Position=1.0e12), 0x8043),
    (MC_MoveAbsolute, dict(Position=-1.0e12), 0x8043),
    (MC_MoveAbsolute, dict(Position=NAN), 0x808B),
    (MC_MoveAbsolute, dict(Position=INF), 0x808B),
    (MC_MoveAbsolute, dict(Position="10"), 0x808B),
    (MC_MoveAbsolute, dict(Velocity=0.0), 0x8043),
    (MC_MoveAbsolute, dict(Velocity=2.0e12), 0x8043),
    (MC_MoveAbsolute, dict(Acceleration=0.0), 0x8043),
    (MC_MoveAbsolute, dict(Deceleration=0.0), 0x8043),
    (MC_MoveAbsolute, dict(Jerk=NAN), 0x808B),
    (MC_MoveAbsolute, dict(Direction=5), 0x8043),
    (MC_MoveAbsolute, dict(Direction=-1), 0x8043),
    (MC_MoveAbsolute, dict(Mode=3), 0x8043),
    (MC_MoveAbsolute, dict(DoneFlag=33), 0x8043),
    (MC_MoveAbsolute, dict(DoneFlag=-1), 0x8043),
    (MC_MoveRelative, dict(Distance=NAN), 0x808B),
    (MC_MoveRelative, dict(Distance=1.5e12), 0x8043),
    (MC_MoveRelative, dict(Mode=7), 0x8043),
    (MC_MoveAdditive, dict(Distance=-INF), 0x808B),
    (MC_MoveAdditive, dict(Velocity=0.0), 0x8043),
    (MC_MoveSuperImposed, dict(VelocityDiff=0.0), 0x8043),
    (MC_MoveSuperImposed, dict(Distance=NAN), 0x808B),
    (MC_MoveVelocity, dict(Direction=2), 0x8043),
    (MC_MoveVelocity, dict(Mode=2), 0x8043),
    (MC_MoveVelocity, dict(Velocity=NAN), 0x808B),
    (MC_MoveVelocity, dict(Velocity=1.0e12), 0x8043),
    (MC_MoveVelocity, dict(DoneFlag=100), 0x8043),
    (MC_Halt, dict(Jerk=NAN), 0x808B),
    (MC_Halt, dict(DoneFlag=33), 0x8043),
    (MC_Stop, dict(Deceleration=NAN), 0x808B),
    (MC_Stop, dict(Jerk=-INF), 0x808B),
    (MC_Stop, dict(DoneFlag=33), 0x8043),
]


@pytest.mark.parametrize("fb, inputs, error_id", MOVES, ids=lambda v: getattr(v, "__name__", None) or repr(v))
def test_s7t_input_error_ids(fb, inputs, error_id):
    """S7-Technology V4.1 §6.9.3, §6.2: an invalid input gives its ErrorID at the instruction; the axis does
    not move and its technology DB stays free of errors."""
    ctl, axis, _ = enabled()
    inst = fb()
    inst(Axis=axis, Execute=True, **inputs)
    assert inst.Error and inst.ErrorID == error_id and not inst.Busy and inst.ENO is False
    ctl.run(0.05)
    inst(Execute=True)
    assert inst.Error and inst.ErrorID == error_id                 # held while Execute is TRUE
    assert float(ctl.bank.sp_p[axis.index]) == 0.0 and axis.db.ErrorID == 0
    inst(Execute=False)
    assert not inst.Error and inst.ErrorID == 0


AXIS_INPUTS = [
    (MC_MoveAbsolute, 999, 0x8083),        # no technology DB with this number
    (MC_MoveAbsolute, 0, 0x8083),          # the default 0
    (MC_MoveAbsolute, "Axis1", 0x8083),
    (MC_MoveAbsolute, 1, 0x8044),          # the MCDevice DB
    (MC_MoveAbsolute, "speed", 0x8044),    # a speed-controlled axis has no positioning
    (MC_MoveRelative, "speed", 0x8044),
    (MC_MoveAdditive, "speed", 0x8044),
    (MC_MoveSuperImposed, "speed", 0x8044),
    (MC_Halt, 999, 0x8083),
    (MC_Stop, 1, 0x8044),
    (MC_MoveVelocity, 1.5, 0x8083),
    (MC_Reset, 999, 0x8083),
    (MC_Power, 999, 0x8083),
    (MC_Power, 1, 0x8044),
]


@pytest.mark.parametrize("fb, axis_input, error_id", AXIS_INPUTS, ids=lambda v: getattr(v, "__name__", None) or repr(v))
def test_s7t_axis_input_error_ids(fb, axis_input, error_id):
    """S7-Technology V4.1 §6.1 common ErrorIDs: 16#8083 the DB at Axis is no technology DB, 16#8044 the
    technology object does not support the command (the MCDevice DB, a speed-controlled axis for a
    positioning)."""
    ctl = controller()
    ctl.add_positioning_axis("Axis1", VIRTUAL)
    speed = ctl.add_positioning_axis("Speed", {**VIRTUAL, "Wizard.Technology": 0})
    value = speed if axis_input == "speed" else axis_input
    inst = fb()
    if fb is MC_Power:
        inst(Axis=value, Enable=True)
    else:
        inst(Axis=value, Execute=True)
    assert inst.Error and inst.ErrorID == error_id


def test_s7t_db_number_above_32767():
    """S7-Technology V4.1 §6.9.3: DB 32768..65535 is given at the INT input as number - 65536."""
    ctl = controller()
    axis = ctl.add_positioning_axis("A", {**VIRTUAL, "DBNumber": 40000})
    power = MC_Power()
    ctl.program(lambda: power(Axis=40000 - 65536, Enable=True))
    ctl.run(0.02)
    assert power.Status and axis.state == "enabled"


POWER_INPUTS = [
    (dict(Mode=129), 0x8043, {}),
    (dict(Mode=-1), 0x8043, {}),
    (dict(Mode=5), 0x8043, VIRTUAL),              # virtual axes: Mode 0 only (§6.2.1)
    (dict(Mode=4), 0x8043, VIRTUAL),              # simulation mode: real axes only (§6.2.1 table)
    (dict(StopMode=7), 0x8043, {}),
    (dict(StopMode=3), 0x8043, REAL_AXIS),        # OFF2Stop: hydraulic axes only
    (dict(StopMode=5), 0x8043, VIRTUAL),          # drive ramps: real electric axes only
    (dict(QOutputValue=NAN), 0x808B, {}),
    (dict(QOutputValue=150.0), 0x8043, {}),
]


@pytest.mark.parametrize("inputs, error_id, params", POWER_INPUTS, ids=repr)
def test_s7t_power_input_error_ids(inputs, error_id, params):
    """S7-Technology V4.1 §6.2.1: invalid Mode, StopMode or QOutputValue at the rising edge of Enable: the
    axis is not enabled, Error and the ErrorID while Enable is TRUE."""
    ctl = controller()
    axis = ctl.add_positioning_axis("A", params or VIRTUAL)
    power = MC_Power()
    ctl.program(lambda: power(Axis=axis, Enable=True, **inputs))
    ctl.run(0.3)
    assert power.Error and power.ErrorID == error_id and power.Busy and not power.Status
    assert axis.state == "disabled"


def test_s7t_reset_error_ids():
    """S7-Technology V4.1 §6.7.1: restart only while disabled (16#8048); while a restart runs the object
    takes no commands and another MC_Reset gets 16#8045; MC_Reset with the MCDevice DB is done at once."""
    ctl, axis, power = enabled()
    reset = MC_Reset()
    reset(Axis=axis, Execute=True, Restart=True)
    assert reset.Error and reset.ErrorID == 0x8048
    ctl.program(lambda: power(Axis=axis, Enable=False))
    ctl.run(0.1)
    assert not power.Status and not power.Busy
    restart = MC_Reset()
    restart(Axis=axis, Execute=True, Restart=True)
    assert restart.Busy and not restart.Done
    again, move = MC_Reset(), MC_MoveVelocity()
    again(Axis=axis, Execute=True)
    assert again.Error and again.ErrorID == 0x8045
    ctl.run(0.5)
    assert restart(Execute=True).Done and not restart.Busy
    mcdevice = MC_Reset()
    mcdevice(Axis=s7t.device(ctl).mcdevice.number, Execute=True)
    assert mcdevice.Done
    del move
