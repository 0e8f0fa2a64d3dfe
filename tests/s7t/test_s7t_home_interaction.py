"""MC_Home Mode 2, 3-7 and 8 and MC_ChangeDataset in the command interaction (S7-Technology V4.1 §6.8.2,
§6.8.3; MC_Home §6.2.2, MC_ChangeDataset §6.2.5), cycle by cycle on the homing rig: a real positioning axis,
reference cam at machine 100..120, active homing approaching at 50 mm/s, deceleration 200 mm/s^2.

Rows of the table: Mode 2 and Mode 3-7 abort an active or passive homing and leave MC_Stop and the motions
alone; Mode 8 aborts only a passive homing; MC_ChangeDataset is refused only by a running restart (8045).
"""
from __future__ import annotations

import pytest

from plcmotion.s7t import MC_ChangeDataset, MC_Home, MC_MoveRelative, MC_MoveVelocity, MC_Reset, MC_Stop

from _s7t_homing_rig import V_APPROACH, Rig

DECEL = 200.0                                    # userdefaultdynamics.negativeaccel of the rig
DS = "TypeOfAxis.NumberOfDataSets"
IMMEDIATELY = 95
NO_MARK = {"Plant.ZeroMarkOffset": 200.0, "Plant.ZeroMarkDistance": 100000.0}


def _start_active_homing(r: Rig) -> MC_Home:
    """Mode 1 from machine 0: the axis approaches the cam (at 100) at V_APPROACH; 0.5 s later it runs at it."""
    active = MC_Home()
    r.call(active, 0.5, Execute=True, Mode=1, Position=0.0)
    assert active.Busy and not active.Error
    assert r.axis.db.ActualVelocity == pytest.approx(V_APPROACH, rel=1e-3)
    return active


def _run(r: Rig, seconds: float, *fbs_and_inputs) -> None:
    end = r.ctl.time + seconds
    while r.ctl.time < end - 1e-9:
        r.ctl.run(r.ctl.app_cycle)
        for fb, inputs in fbs_and_inputs:
            fb(Axis=r.axis, **inputs)


def test_s7t_home_mode2_aborts_an_active_homing_cycle_by_cycle():
    """S7-Technology V4.1 §6.8.2 (MC_Home Mode 2 row, column active homing: abort), §6.2.2: the passive
    homing is accepted (Busy, no Error) in the call that starts it, the active homing shows CommandAborted
    in its next call, and the axis, left without the homing's motion, brakes to standstill within
    v^2 / (2 a) = 6.25 of where it was (v 50, a 200) instead of running on towards the cam.  The only
    zero mark is at 200, so the passive homing stays armed."""
    r = Rig(NO_MARK)
    active = _start_active_homing(r)
    passive = MC_Home()
    passive(Axis=r.axis, Execute=True, Mode=2, Position=0.0)
    at_abort = r.mech
    assert passive.Busy and not passive.Error and passive.ErrorID == 0
    active(Axis=r.axis, Execute=True)
    assert active.CommandAborted and not active.Busy and not active.Error
    _run(r, 1.0, (passive, dict(Execute=True)), (active, dict(Execute=True)))
    assert r.axis.db.Statusword.Standstill
    assert at_abort < r.mech <= at_abort + V_APPROACH ** 2 / (2 * DECEL) + 0.1
    assert passive.Busy and not r.axis.db.Statusword.HomingDone       # armed, no mark has passed


def test_s7t_home_mode3_aborts_an_active_homing():
    """S7-Technology V4.1 §6.8.2 (MC_Home Mode 3-7 row, column active homing: abort), §6.2.2 Mode 3: the
    position becomes Position at once (Done, HomingDone), the active homing ends CommandAborted, and the
    axis brakes to standstill (the position set at the abort plus at most the braking distance 6.25)."""
    r = Rig()
    active = _start_active_homing(r)
    direct = MC_Home()
    direct(Axis=r.axis, Execute=True, Mode=3, Position=500.0)
    active(Axis=r.axis, Execute=True)
    assert direct.Done and not direct.Error
    assert active.CommandAborted
    _run(r, 1.0, (direct, dict(Execute=True)))
    sw = r.axis.db.Statusword
    assert sw.Standstill and sw.HomingDone and not sw.Homing
    assert 500.0 < r.axis.db.ActualPosition <= 500.0 + V_APPROACH ** 2 / (2 * DECEL) + 0.1


def test_s7t_home_mode3_while_mc_stop_holds_the_axis():
    """S7-Technology V4.1 §6.8.2 (MC_Home Mode 3-7 row, column MC_Stop: no influence), §6.2.2, §6.2.3: while
    MC_Stop holds the stopped axis (Execute TRUE), Mode 3 sets the position (Done, ActualPosition = 40);
    MC_Stop stays Busy (its lock of §6.2.3) and still locks the axis: a MC_MoveRelative gets 16#8045."""
    r = Rig()
    move, stop, direct, blocked = MC_MoveVelocity(), MC_Stop(), MC_Home(), MC_MoveRelative()
    r.call(move, 0.3, Execute=True, Velocity=20.0)
    r.call(stop, 0.5, Execute=True)
    assert stop.Busy and r.axis.db.Statusword.Standstill
    direct(Axis=r.axis, Execute=True, Mode=3, Position=40.0)
    stop(Axis=r.axis, Execute=True)
    assert direct.Done and not direct.Error
    assert stop.Busy and not stop.CommandAborted
    r.ctl.run(0.05)
    assert r.axis.db.ActualPosition == pytest.approx(40.0, abs=1e-3)
    blocked(Axis=r.axis, Execute=True, Distance=10.0, Velocity=10.0)
    assert blocked.Error and blocked.ErrorID == 0x8045


def test_s7t_home_mode2_while_mc_stop_holds_the_axis():
    """S7-Technology V4.1 §6.8.2 (MC_Home Mode 2 row, column MC_Stop: no influence), §6.2.2: a passive
    homing is armed beside a held MC_Stop (Busy, no Error), and MC_Stop is not aborted."""
    r = Rig()
    stop, passive = MC_Stop(), MC_Home()
    r.call(stop, 0.1, Execute=True)
    passive(Axis=r.axis, Execute=True, Mode=2, Position=0.0)
    stop(Axis=r.axis, Execute=True)
    assert passive.Busy and not passive.Error
    assert stop.Busy and not stop.CommandAborted


def test_s7t_home_mode4_aborts_a_passive_homing():
    """S7-Technology V4.1 §6.8.2 (MC_Home Mode 3-7 row, column passive homing: abort), §6.2.2 Mode 4: the
    actual value is corrected by -Position (ActualPosition 0 -> -7) and the armed passive homing ends with
    CommandAborted."""
    r = Rig(NO_MARK)
    passive, correct = MC_Home(), MC_Home()
    r.call(passive, 0.02, Execute=True, Mode=2, Position=0.0)
    before = r.axis.db.ActualPosition
    correct(Axis=r.axis, Execute=True, Mode=4, Position=7.0)
    passive(Axis=r.axis, Execute=True)
    assert correct.Done and passive.CommandAborted and not passive.Error
    r.ctl.run(0.02)                      # the technology DB shows the corrected value from the next cycle
    assert r.axis.db.ActualPosition == pytest.approx(before - 7.0, abs=1e-6)
    assert r.axis.homing.passive is None


def test_s7t_home_mode8_leaves_an_active_homing_alone():
    """S7-Technology V4.1 §6.8.2 (MC_Home Mode 8 row: no influence on active homing), §6.2.2 ErrorID 8045
    "Mode 8 without a running passive homing": with only an active homing running, Mode 8 gives 16#8045
    and the active homing goes on at the approach velocity."""
    r = Rig()
    active = _start_active_homing(r)
    cancel = MC_Home()
    cancel(Axis=r.axis, Execute=True, Mode=8)
    active(Axis=r.axis, Execute=True)
    assert cancel.Error and cancel.ErrorID == 0x8045
    assert active.Busy and not active.CommandAborted
    r.ctl.run(0.1)
    assert r.axis.db.ActualVelocity == pytest.approx(V_APPROACH, rel=1e-3)


def test_s7t_home_mode8_cancels_passive_homing_during_mc_stop():
    """S7-Technology V4.1 §6.8.2 (MC_Home Mode 8 row: aborts a passive homing; MC_Stop: no influence):
    Mode 8 during a held MC_Stop cancels the passive homing (CommandAborted) and is Done; MC_Stop goes on."""
    r = Rig()
    stop, passive, cancel = MC_Stop(), MC_Home(), MC_Home()
    r.call(passive, 0.02, Execute=True, Mode=2, Position=0.0)
    r.call(stop, 0.1, Execute=True)
    cancel(Axis=r.axis, Execute=True, Mode=8)
    passive(Axis=r.axis, Execute=True)
    stop(Axis=r.axis, Execute=True)
    assert cancel.Done and passive.CommandAborted
    assert stop.Busy and not stop.CommandAborted


# --- MC_ChangeDataset (table 3 row) --------------------------------------------------------------------------
def _dataset_rig(**kw) -> Rig:
    return Rig({f"{DS}.numberOfDataSets": 2, f"{DS}.changeMode": IMMEDIATELY,
                f"{DS}.DataSet_2.ControllerStruct.PV_Controller.kv": 40.0}, **kw)


def test_s7t_change_dataset_during_mc_stop():
    """S7-Technology V4.1 §6.8.3 (MC_ChangeDataset row, column MC_Stop: no influence), §6.2.5: while MC_Stop
    brakes the axis, the change (IMMEDIATELY) is Done in its first call and Kv 40 is in force; MC_Stop
    goes on to its Done."""
    r = _dataset_rig()
    move, stop, change = MC_MoveVelocity(), MC_Stop(), MC_ChangeDataset()
    r.call(move, 0.3, Execute=True, Velocity=20.0)
    stop(Axis=r.axis, Execute=True, Deceleration=10.0)
    r.ctl.run(r.ctl.app_cycle)
    stop(Axis=r.axis, Execute=True, Deceleration=10.0)
    assert stop.Busy
    change(Axis=r.axis, Execute=True, Dataset=2)
    assert change.Done and not change.Error
    assert r.axis.config.position_control.kv == 40.0
    r.call(stop, 3.0, Execute=True, Deceleration=10.0)          # 20 / 10 = 2 s to standstill
    assert stop.Busy and not stop.CommandAborted and r.axis.db.Statusword.Standstill
    stop(Axis=r.axis, Execute=False)
    assert stop.Done


def test_s7t_change_dataset_during_a_restart():
    """S7-Technology V4.1 §6.8.3 (column MC_Reset Restart: refused), §6.2.5 ErrorID 8045 "the technology
    object is currently performing a restart": while the restart runs the change gives 16#8045 and the data
    set stays; after it, a new command changes it."""
    r = _dataset_rig(enable=False)
    reset, change = MC_Reset(), MC_ChangeDataset()
    reset(Axis=r.axis, Execute=True, Restart=True)
    assert reset.Busy
    change(Axis=r.axis, Execute=True, Dataset=2)
    assert change.Error and change.ErrorID == 0x8045
    assert r.axis.config.position_control.kv == 10.0
    r.until(reset, lambda f: f.Done, limit=2.0, Execute=True, Restart=True)
    change(Axis=r.axis, Execute=False)
    change(Axis=r.axis, Execute=True, Dataset=2)
    assert change.Done and r.axis.config.position_control.kv == 40.0
