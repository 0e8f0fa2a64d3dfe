"""Encoders of an S7-Technology axis: encoder changeover with the data sets, incremental and absolute encoders,
MC_Home Mode 5 (S7-Technology V4.1 §3.1.8, §3.1.9, §3.1.10, §4.5.1, §6.2.2, §6.2.5, §9.4 numbers 3000, 4020,
4050, 4412).

The rig's axis has two encoders measuring the same load; data set 2 measures with encoder 2.  Incremental
encoders count from 0 at power-up (§3.1.8), so after direct homing of encoder 1 to ``Position`` = 4 the two
encoders differ by 4: a changeover without synchronization makes the position controller move the load by 4
(the "compensating movement" of §6.2.5), with ``SyncEncoder`` the load stays where it is.
"""
from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from plcmotion.s7t import (MC_ChangeDataset, MC_Home, MC_MoveAbsolute, MC_MoveVelocity, MC_Power,
                           MC_ReadSysParameter, MC_Reset)

from _s7t_homing_rig import Rig
from _s7t_rig import VIRTUAL, controller, enabled

DS = "TypeOfAxis.NumberOfDataSets"
IN_POSITION, IMMEDIATELY = 93, 95
INCREMENTAL, ABSOLUTE = 0, 1
TWO_ENCODERS = {f"{DS}.numberOfDataSets": 2, "TypeOfAxis.NumberOfEncoders.numberOfEncoders": 2,
                f"{DS}.DataSet_2.EncoderNumber.EncoderNumber": 2}
VALID, NOT_VALID = 206, 204                        # §9.4.12.40 EnumSensorState


def _rig(change_mode: int = IMMEDIATELY, encoder_2: int = INCREMENTAL, enable: bool = True, **params) -> Rig:
    return Rig({**TWO_ENCODERS, f"{DS}.changeMode": change_mode, "Wizard.Encoder_2.EncoderType": encoder_2,
                **params}, enable=enable)


def _read(r: Rig, number: int, index: int = 1) -> MC_ReadSysParameter:
    rd = MC_ReadSysParameter()
    rd(Axis=r.axis, Execute=True, ParameterNumber=number, Index=index)
    return rd


def _settle(r: Rig, seconds: float = 1.0) -> None:
    r.ctl.run(seconds)


def _home_direct(r: Rig, position: float) -> None:
    h = MC_Home()
    r.call(h, 0.02, Execute=True, Mode=3, Position=position)
    assert h.Done, h


@pytest.mark.parametrize("sync, moved, homed", [(False, 4.0, False), (True, 0.0, True)])
def test_s7t_encoders_changeover_with_and_without_synchronization(sync, moved, homed):
    """S7-Technology V4.1 §6.2.5 "Encoder synchronization": without SyncEncoder the new encoder's actual value
    is taken and the axis makes a compensating movement (here 4, the difference of the encoders); with it the
    actual value of the old encoder is set on the new one and the load does not move.  4412 names the encoder
    in force, 4020 the data set (§9.4); HomingDone follows the encoder (D79)."""
    r = _rig()
    _settle(r, 0.2)
    assert _read(r, 4412).ValueDInt == 1 and _read(r, 3000).ValueDInt == 2
    _home_direct(r, 4.0)
    _settle(r, 0.2)
    mech0 = r.mech
    change = MC_ChangeDataset()
    r.call(change, 0.02, Execute=True, Dataset=2, SyncEncoder=sync)
    assert change.Done and not change.Error
    _settle(r, 1.0)
    db = r.axis.db
    assert _read(r, 4412).ValueDInt == 2 and _read(r, 4020).ValueDInt == 2
    assert r.mech - mech0 == pytest.approx(moved, abs=0.01)
    assert db.ActualPosition == pytest.approx(4.0, abs=0.01) and db.ErrorID == 0
    assert bool(db.Statusword.HomingDone) is homed


def test_s7t_encoders_synchronization_at_the_in_position_moment():
    """S7-Technology V4.1 §6.2.5 IN_POSITION with SyncEncoder: started during a positioning the change waits;
    at the positioning window the encoders are synchronized and the axis stays at the target (no step)."""
    r = _rig(IN_POSITION, **{"TypeOfAxis.Homing.referencingNecessary": 0})
    _home_direct(r, 4.0)
    move, change = MC_MoveAbsolute(), MC_ChangeDataset()
    move(Axis=r.axis, Execute=True, Position=50.0, Velocity=50.0)
    change(Axis=r.axis, Execute=True, Dataset=2, SyncEncoder=True)
    assert change.Busy and _read(r, 4412).ValueDInt == 1
    r.until(change, lambda f: f.Done, limit=5.0, Execute=True, Dataset=2, SyncEncoder=True)
    mech = r.mech
    _settle(r, 0.5)
    assert _read(r, 4412).ValueDInt == 2
    assert r.axis.db.ActualPosition == pytest.approx(50.0, abs=0.01) and r.mech == pytest.approx(mech, abs=0.01)


def test_s7t_encoders_invalid_new_encoder_refuses_the_change():
    """S7-Technology V4.1 §6.2.5 prerequisites and 8045: the encoder of the new data set must give valid values
    (MC_ReadSysParameter 4050 with the encoder as Index); a valid one is taken."""
    r = _rig()
    r.axis.encoders.set_valid(2, False)
    assert _read(r, 4050, 2).ValueDInt == NOT_VALID and _read(r, 4050, 1).ValueDInt == VALID
    change = MC_ChangeDataset()
    change(Axis=r.axis, Execute=True, Dataset=2)
    assert change.Error and change.ErrorID == 0x8045 and _read(r, 4412).ValueDInt == 1
    r.axis.encoders.set_valid(2, True)
    change(Axis=r.axis, Execute=False)
    change(Axis=r.axis, Execute=True, Dataset=2)
    assert change.Done and _read(r, 4412).ValueDInt == 2
    assert _read(r, 4050, 3).ErrorID == 0x8080          # the axis has two encoders


def test_s7t_encoders_power_off_aborts_a_waiting_change():
    """S7-Technology V4.1 §6.8.3 (table 3): MC_Power Enable = FALSE aborts an active MC_ChangeDataset - a change
    waiting for the positioning window ends with CommandAborted and data set 1 stays in force."""
    r = _rig(IN_POSITION)
    mv, change = MC_MoveVelocity(), MC_ChangeDataset()
    r.call(mv, 0.2, Execute=True, Velocity=20.0)
    r.call(change, 0.1, Execute=True, Dataset=2)
    assert change.Busy and not change.Done
    r.enable = False
    r.call(change, 0.5, Execute=True, Dataset=2)
    assert change.CommandAborted and not change.Busy and not change.Error
    assert _read(r, 4020).ValueDInt == 1
    r.enable = True
    r.call(change, 0.5, Execute=True, Dataset=2)
    assert change.CommandAborted and _read(r, 4020).ValueDInt == 1     # no new edge: nothing new


def test_s7t_encoders_restart_returns_to_the_initial_encoder():
    """S7-Technology V4.1 §3.1.10, §3.1.8: after MC_Reset Restart = TRUE data set 1 and its encoder are in
    force again; the actual value is encoder 1's (it kept counting while encoder 2 was in force) and the
    incremental encoder has lost its homing."""
    r = _rig(enable=False)
    _home_direct(r, 4.0)
    change = MC_ChangeDataset()
    r.call(change, 0.02, Execute=True, Dataset=2)
    assert change.Done
    _settle(r, 0.1)
    assert r.axis.db.ActualPosition == pytest.approx(0.0, abs=0.01)
    reset = MC_Reset()
    r.until(reset, lambda f: f.Done, limit=2.0, Execute=True, Restart=True)
    _settle(r, 0.1)
    assert _read(r, 4412).ValueDInt == 1
    assert r.axis.db.ActualPosition == pytest.approx(4.0, abs=0.01)
    assert not r.axis.db.Statusword.HomingDone


# --- absolute encoders ------------------------------------------------------------------------------------
ABS_AXIS = {"Wizard.Encoder_1.EncoderType": ABSOLUTE, "Plant.InitialPosition": 37.0, "swlimit.state": 0}


def _abs_rig(state_file, **params) -> Rig:
    return Rig({**ABS_AXIS, **params}, state_file=str(state_file))


def test_s7t_encoders_absolute_value_at_power_up_and_adjustment(tmp_path):
    """S7-Technology V4.1 §3.1.9: an absolute encoder gives its position at once (here the load at 37, not
    adjusted: not homed); MC_Home Mode 5 sets the actual position to Position by an offset that is stored
    permanently: after POWER OFF (a new controller on the same state file) and after a restart the axis is at
    the adjusted position and homed."""
    sf = tmp_path / "press.state.json"
    r = _abs_rig(sf)
    db = r.axis.db
    assert db.ActualPosition == pytest.approx(37.0, abs=0.001) and not db.Statusword.HomingDone
    h = MC_Home()
    r.call(h, 0.02, Execute=True, Mode=5, Position=100.0)
    assert h.Done and not h.Error
    _settle(r, 0.1)
    assert db.ActualPosition == pytest.approx(100.0, abs=0.001) and db.Statusword.HomingDone
    assert r.mech == pytest.approx(37.0, abs=0.01)
    again = _abs_rig(sf)
    assert again.axis.db.ActualPosition == pytest.approx(100.0, abs=0.001)
    assert again.axis.db.Statusword.HomingDone
    again.enable = False
    _settle(again, 0.2)
    reset = MC_Reset()
    again.until(reset, lambda f: f.Done, limit=2.0, Execute=True, Restart=True)
    _settle(again, 0.1)
    assert again.axis.db.ActualPosition == pytest.approx(100.0, abs=0.001) and again.axis.db.Statusword.HomingDone


def test_s7t_encoders_incremental_encoder_loses_homing_at_power_off(tmp_path):
    """S7-Technology V4.1 §3.1.8: an incremental encoder counts from 0 after POWER ON and must be homed again."""
    sf = tmp_path / "m.state.json"
    r = Rig({"Plant.InitialPosition": 37.0}, state_file=str(sf))
    _home_direct(r, 100.0)
    again = Rig({"Plant.InitialPosition": 37.0}, state_file=str(sf))
    assert again.axis.db.ActualPosition == pytest.approx(0.0, abs=0.001) and not again.axis.db.Statusword.HomingDone


def test_s7t_encoders_second_absolute_encoder_keeps_its_own_adjustment(tmp_path):
    """S7-Technology V4.1 §3.1.9, §9.4 number 4010 (absoluteencoder_x: one adjustment per encoder): encoder 2
    adjusted while data set 2 is in force keeps its offset across POWER OFF; encoder 1 (incremental) is not
    affected, and changing over to encoder 2 again without synchronization gives its adjusted value."""
    sf = tmp_path / "two.state.json"
    params = {**TWO_ENCODERS, f"{DS}.changeMode": IMMEDIATELY, "Wizard.Encoder_2.EncoderType": ABSOLUTE,
              "Plant.InitialPosition": 37.0, "swlimit.state": 0}
    r = Rig(params, state_file=str(sf))
    change = MC_ChangeDataset()
    r.call(change, 0.02, Execute=True, Dataset=2, SyncEncoder=True)
    h = MC_Home()
    r.call(h, 0.02, Execute=True, Mode=5, Position=200.0)
    assert h.Done, h
    again = Rig(params, state_file=str(sf))
    assert _read(again, 4412).ValueDInt == 1 and again.axis.db.ActualPosition == pytest.approx(0.0, abs=0.001)
    again.enable = False
    _settle(again, 0.1)
    change2 = MC_ChangeDataset()
    again.call(change2, 0.02, Execute=True, Dataset=2, SyncEncoder=False)
    _settle(again, 0.1)
    assert again.axis.db.ActualPosition == pytest.approx(200.0, abs=0.001) and again.axis.db.Statusword.HomingDone


# --- MC_Home and the encoder type: ErrorIDs ---------------------------------------------------------------
def _mode5_moving(r: Rig) -> None:
    mv = MC_MoveVelocity()
    r.call(mv, 0.3, Execute=True, Velocity=20.0)


CASES = [
    # (encoder, situation, Mode, ErrorID) - §6.2.2 notes: absolute encoders Modes 3-7, incremental 0-4, 6, 7
    ("absolute", "enabled", 0, 0x8045), ("absolute", "enabled", 1, 0x8045), ("absolute", "enabled", 2, 0x8045),
    ("absolute", "enabled", 3, 0), ("absolute", "enabled", 4, 0), ("absolute", "enabled", 5, 0),
    ("absolute", "enabled", 6, 0), ("absolute", "enabled", 7, 0),
    ("incremental", "enabled", 5, 0x8045),
    # Mode 5: at standstill, position-controlled (8045), not with active software limit switches (§3.1.9)
    ("absolute", "disabled", 5, 0x8045), ("absolute", "moving", 5, 0x8045), ("absolute", "sw_limits", 5, 0x8045),
    ("absolute", "disabled", 3, 0),
]


@pytest.mark.parametrize("encoder, situation, mode, error_id", CASES)
def test_s7t_encoders_home_modes_by_encoder_type(encoder, situation, mode, error_id):
    """S7-Technology V4.1 §6.2.2 notes, Mode 5 and ErrorIDs 8045; §3.1.9 (no adjustment while the software
    limit switches act): what MC_Home takes on an axis with an incremental or an absolute encoder."""
    params = {"Wizard.Encoder_1.EncoderType": ABSOLUTE if encoder == "absolute" else INCREMENTAL,
              "swlimit.state": 1 if situation == "sw_limits" else 0, "TypeOfAxis.Homing.referencingNecessary": 0}
    r = Rig(params, enable=situation != "disabled")
    if situation == "moving":
        _mode5_moving(r)
    h = MC_Home()
    h(Axis=r.axis, Execute=True, Mode=mode, Position=10.0)
    if error_id:
        assert h.Error and h.ErrorID == error_id
    else:
        assert not h.Error and (h.Done or h.Busy)


def test_s7t_encoders_home_mode_5_on_a_virtual_axis():
    """S7-Technology V4.1 §6.2.2 804D: a virtual axis has no encoder to adjust (Mode 5)."""
    ctl, axis, _power = enabled(VIRTUAL)
    h = MC_Home()
    h(Axis=axis, Execute=True, Mode=5, Position=1.0)
    assert h.Error and h.ErrorID == 0x804D


def test_s7t_encoders_configuration_rule():
    """S7-Technology V4.1 §4.5.1: a data set can only measure with an encoder of the axis."""
    ctl = controller()
    with pytest.raises(Exception, match="EncoderNumber"):
        ctl.add_positioning_axis("A", {**TWO_ENCODERS, "TypeOfAxis.NumberOfEncoders.numberOfEncoders": 1})


@pytest.mark.parametrize("encoder_type, number, error_id", [
    (INCREMENTAL, 3064, 0), (ABSOLUTE, 3064, 0x8086), (2, 3064, 0x8086), (ABSOLUTE, 2033, 0),
])
def test_s7t_encoders_parameters_not_available_for_the_encoder_type(encoder_type, number, error_id):
    """S7-Technology V4.1 §6.7.4 ErrorID 8086: incremental-encoder parameters (3064 IncHomingEncoder.homingMode)
    of an absolute encoder, and any encoder parameter of an "absolute encoder cyclic absolute" (type 2), are
    not available; a parameter of no encoder (2033 Kv) is."""
    r = Rig({"Wizard.Encoder_1.EncoderType": encoder_type, "swlimit.state": 0})
    rd = _read(r, number, 1)
    assert rd.ErrorID == error_id


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(offset=st.floats(min_value=-8.0, max_value=8.0).filter(lambda d: abs(d) > 0.05), sync=st.booleans())
def test_s7t_encoders_changeover_invariant(offset, sync):
    """S7-Technology V4.1 §6.2.5: whatever the two encoders differ by (encoder 1 homed to ``offset``, encoder 2
    counting from 0), a changeover at standstill keeps the position the program sees (the setpoint); with
    SyncEncoder the load does not move, without it the load moves by exactly the difference."""
    r = _rig()
    _home_direct(r, offset)
    _settle(r, 0.1)
    mech0, pos0 = r.mech, r.axis.db.ActualPosition
    change = MC_ChangeDataset()
    r.call(change, 0.02, Execute=True, Dataset=2, SyncEncoder=sync)
    _settle(r, 1.5)
    assert change.Done and r.axis.db.ErrorID == 0
    assert r.axis.db.ActualPosition == pytest.approx(pos0, abs=0.01)
    assert r.mech - mech0 == pytest.approx(0.0 if sync else offset, abs=0.01)
