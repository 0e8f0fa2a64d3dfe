"""FB 409 MC_ChangeDataset (S7-Technology V4.1 §6.2.5, §3.1.10, §9.4 numbers 2000-2002, 2032, 2033, 4020).

Two data sets without precontrol (kpc 0) and Kv 10 / 40: at a constant 20 mm/s the following error is
v / Kv = 2.0 with data set 1 and 0.5 with data set 2 (position loop, §3.3.1), which is how a program sees
which data set is in force, beside ``datasetmonitoring.actualdataset`` (4020).
"""
from __future__ import annotations

import pytest

from plcmotion.s7t import MC_ChangeDataset, MC_Halt, MC_MoveRelative, MC_MoveVelocity, MC_Reset

from _s7t_homing_rig import Rig
from _s7t_rig import VIRTUAL, enabled

DS = "TypeOfAxis.NumberOfDataSets"
NEVER, IN_POSITION, IN_STANDSTILL, IMMEDIATELY = 92, 93, 94, 95


def _rig(change_mode: int = IMMEDIATELY, **kw) -> Rig:
    return Rig({f"{DS}.numberOfDataSets": 2, f"{DS}.changeMode": change_mode,
                f"{DS}.DataSet_1.ControllerStruct.PV_Controller.kpc": 0.0,
                f"{DS}.DataSet_2.ControllerStruct.PV_Controller.kpc": 0.0,
                f"{DS}.DataSet_2.ControllerStruct.PV_Controller.kv": 40.0}, **kw)


def _in_force(r: Rig) -> int:
    return r.axis.eff["datasetmonitoring.actualdataset"] or r.axis.eff[f"{DS}.initDataSet"]


def test_s7t_change_dataset_immediately_changes_the_controller():
    """S7-Technology V4.1 §6.2.5 IMMEDIATELY: Done in the call that starts it; the following error at 20 mm/s
    goes from v/Kv = 2.0 (data set 1) to 0.5 (data set 2) while the axis moves."""
    r = _rig()
    mv = MC_MoveVelocity()
    r.call(mv, 1.0, Execute=True, Velocity=20.0)
    assert r.axis.db.FollowingError == pytest.approx(2.0, rel=0.02)
    change = MC_ChangeDataset()
    change(Axis=r.axis, Execute=True, Dataset=2)
    assert change.Done and not change.Busy and _in_force(r) == 2
    r.call(mv, 1.0, Execute=True, Velocity=20.0)
    assert r.axis.db.FollowingError == pytest.approx(0.5, rel=0.02)
    assert mv.Busy and r.axis.db.ErrorID == 0


def test_s7t_change_dataset_done_at_once_for_the_active_one():
    """S7-Technology V4.1 §6.2.5: Done = TRUE at once when the requested data set is the one in force, also
    with changeMode IN_POSITION while the axis moves."""
    r = _rig(IN_POSITION)
    mv = MC_MoveVelocity()
    r.call(mv, 0.2, Execute=True, Velocity=20.0)
    change = MC_ChangeDataset()
    change(Axis=r.axis, Execute=True, Dataset=1)
    assert change.Done and _in_force(r) == 1


def test_s7t_change_dataset_in_position_waits_for_the_positioning_window():
    """S7-Technology V4.1 §6.2.5 IN_POSITION: started during a positioning the change waits (Busy, data set 1
    in force) until the positioning has reached its window (the move's Done); then it is Done with data set 2,
    in the same OB1 cycle."""
    r = _rig(IN_POSITION)
    move, change = MC_MoveRelative(), MC_ChangeDataset()
    move(Axis=r.axis, Execute=True, Distance=50.0, Velocity=20.0)
    change(Axis=r.axis, Execute=True, Dataset=2)
    assert move.Busy and change.Busy
    while move.Busy:
        assert change.Busy and not change.Done and _in_force(r) == 1
        r.ctl.run(r.ctl.app_cycle)
        move(Axis=r.axis, Execute=True)
        change(Axis=r.axis, Execute=True)
        assert r.ctl.time < 10.0
    assert move.Done and change.Done and _in_force(r) == 2


def test_s7t_change_dataset_in_position_on_a_disabled_axis_waits_for_the_enable():
    """S7-Technology V4.1 §6.2.5 IN_POSITION: the axis must be enabled position-controlled; the change
    happens at once when it is enabled again."""
    r = _rig(IN_POSITION, enable=False)
    change = MC_ChangeDataset()
    r.call(change, 0.1, Execute=True, Dataset=2)
    assert change.Busy and _in_force(r) == 1
    r.enable = True
    r.until(change, lambda f: f.Done, limit=1.0, Execute=True, Dataset=2)
    assert r.axis.state == "enabled" and _in_force(r) == 2


def test_s7t_change_dataset_in_standstill():
    """S7-Technology V4.1 §6.2.5 IN_STANDSTILL: while the axis runs the change waits; after MC_Halt has
    brought it to standstill it is Done."""
    r = _rig(IN_STANDSTILL)
    mv, halt, change = MC_MoveVelocity(), MC_Halt(), MC_ChangeDataset()
    r.call(mv, 0.5, Execute=True, Velocity=20.0)
    r.call(change, 0.5, Execute=True, Dataset=2)
    assert change.Busy and _in_force(r) == 1
    r.until(halt, lambda f: f.Done, Execute=True)
    r.until(change, lambda f: f.Done, limit=1.0, Execute=True, Dataset=2)
    assert r.axis.db.Statusword.Standstill and _in_force(r) == 2


@pytest.mark.parametrize("params, inputs, error_id", [
    ({f"{DS}.changeMode": NEVER}, {"Dataset": 2}, 0x8045),
    ({}, {"Dataset": 3}, 0x8043),
    ({}, {"Dataset": 0}, 0x8043),
    ({}, {"Dataset": 2, "DoneFlag": 40}, 0x8043),
])
def test_s7t_change_dataset_errors(params, inputs, error_id):
    """S7-Technology V4.1 §6.2.5 ErrorIDs: changeMode NEVER (8045); a data set the axis does not have or an
    invalid DoneFlag (8043)."""
    r = Rig({f"{DS}.numberOfDataSets": 2, **params})
    change = MC_ChangeDataset()
    change(Axis=r.axis, Execute=True, **inputs)
    assert change.Error and change.ErrorID == error_id and _in_force(r) == 1


def test_s7t_change_dataset_virtual_axis():
    """S7-Technology V4.1 §6.2.5 804D: a virtual axis (it has one data set, §3.1.10)."""
    ctl, axis, _power = enabled(VIRTUAL)
    change = MC_ChangeDataset()
    change(Axis=axis, Execute=True, Dataset=1)
    assert change.Error and change.ErrorID == 0x804D


def test_s7t_change_dataset_restart_returns_to_the_initial_one():
    """S7-Technology V4.1 §3.1.10: after a restart (MC_Reset Restart = TRUE) the data set "active after
    startup" (initDataSet) is in force again."""
    r = _rig(enable=False)
    change = MC_ChangeDataset()
    r.call(change, 0.02, Execute=True, Dataset=2)
    assert change.Done and _in_force(r) == 2
    reset = MC_Reset()
    r.until(reset, lambda f: f.Done, limit=2.0, Execute=True, Restart=True)
    assert _in_force(r) == 1 and r.axis.config.position_control.kv == 10.0


@pytest.mark.parametrize("dataset, error_id", [(1, 0x801B), (2, 0)])
def test_s7t_change_dataset_switches_the_clamping_monitoring(dataset, error_id):
    """S7-Technology V4.1 §6.2.5 with §9.4 numbers 2010/2011 (indexed by data set): the clamping window of the
    data set in force watches the clamped axis - pushed 1.0 off the end stop, data set 1 (tolerance 0.1) gives
    16#801B, data set 2 (tolerance 5.0) does not."""
    from plcmotion.s7t import MC_MoveToEndPos, MC_Power
    from _s7t_rig import controller
    cm1, cm2 = f"{DS}.DataSet_1.ClampingMonitoring", f"{DS}.DataSet_2.ClampingMonitoring"
    ctl = controller()
    axis = ctl.add_positioning_axis("A", {
        "TypeOfAxis.Homing.referencingNecessary": 0, "Wizard.Telegram": 105, f"{cm1}.recognitionMode": 106,
        f"{cm1}.followingErrorDeviation": 1.0, f"{cm1}.positionTolerance": 0.1, f"{cm2}.positionTolerance": 5.0,
        "Plant.EndStopMaxPosition": 50.0, f"{DS}.numberOfDataSets": 2, f"{DS}.changeMode": IMMEDIATELY})
    power, end, change = MC_Power(), MC_MoveToEndPos(), MC_ChangeDataset()
    ctl.program(lambda: (power(Axis=axis, Enable=True), end(Axis=axis, Execute=power.Status, Velocity=20.0, Torque=1.0),
                         change(Axis=axis, Execute=True, Dataset=dataset)))
    ctl.run(3.5)
    assert end.InClamping and change.Done
    axis.disturb_load(jump=-1.0)
    ctl.run(0.05)
    assert axis.db.ErrorID == error_id and end.InClamping == (error_id == 0)


def test_s7t_change_dataset_waiting_change_survives_a_restart():
    """S7-Technology V4.1 §6.8.3 table 3 (row MC_Reset Restart, column MC_ChangeDataset: no influence) with
    §6.2.5 IN_POSITION: a change waiting on a disabled axis stays Busy through a restart and is Done with the
    enable."""
    r = _rig(IN_POSITION, enable=False)
    change = MC_ChangeDataset()
    r.call(change, 0.1, Execute=True, Dataset=2)
    assert change.Busy
    reset = MC_Reset()
    r.until(reset, lambda f: f.Done, limit=2.0, Execute=True, Restart=True)
    r.call(change, 0.1, Execute=True, Dataset=2)
    assert change.Busy and not change.CommandAborted and _in_force(r) == 1
    r.enable = True
    r.call(change, 0.3, Execute=True, Dataset=2)
    assert change.Done and _in_force(r) == 2
