"""FB 460 MC_ActivateTO and FB 457 MC_ActivateDPSlave (S7-Technology V4.1 §6.7.2, §6.7.3, §7.1, §7.10).

A deactivated axis takes no commands (16#8045), its technology DB is no longer updated but shows
``Statusword.ToDeactivated``; reactivating it initializes it as a restart does.  Deactivating the DP slave
of a drive stops its cyclic exchange: ``MCDevice.StationLifeList`` and the axis's drive communication.
"""
from __future__ import annotations

import pytest

from plcmotion.s7t import (MC_ActivateDPSlave, MC_ActivateTO, MC_MoveRelative, MC_MoveVelocity, MC_Power,
                           MC_ReadSysParameter, MC_Reset, MC_WriteParameter)
from plcmotion.s7t.technology import dp_drive

from _s7t_rig import VIRTUAL, controller, enabled

OB1 = 0.004
DIAG = dp_drive.DIAGNOSTIC_ADDRESS          # the first drive's slave
STATION = dp_drive.FIRST_STATION


def _ctl(params=None):
    ctl = controller()
    axis = ctl.add_positioning_axis("Axis1", VIRTUAL if params is None else params)
    ctl.run(0.02)
    return ctl, axis


def _run_until(ctl, fb, limit: int = 20) -> int:
    for n in range(1, limit + 1):
        ctl.run(OB1)
        fb(Execute=True)
        if not fb.Busy:
            return n
    raise AssertionError(f"{fb} still busy")


def _status(axis) -> int:
    fb = MC_ActivateTO()
    fb(Axis=axis, Execute=True, Mode=0)
    assert fb.Done
    return fb.Status


def test_s7t_deactivate_and_activate_axis():
    """S7-Technology V4.1 §6.7.2: Mode 2 deactivates (Busy, then Done; Status 4 while it runs, then 2),
    Statusword.ToDeactivated is set, commands give 8045; Mode 1 activates again (Status 3, then 1)."""
    ctl, axis = _ctl()
    assert _status(axis) == 1
    fb = MC_ActivateTO()
    fb(Axis=axis, Execute=True, Mode=2)
    assert fb.Busy and not fb.Done
    assert _status(axis) == 4
    _run_until(ctl, fb)
    assert fb.Done and fb.Status == 0                    # Status only with Mode 0
    assert _status(axis) == 2
    ctl.run(OB1)
    assert axis.db.Statusword.ToDeactivated
    for cls, inputs in ((MC_Power, dict(Enable=True)), (MC_MoveVelocity, dict(Execute=True, Velocity=5.0)),
                        (MC_Reset, dict(Execute=True)), (MC_ReadSysParameter, dict(Execute=True, ParameterNumber=3))):
        inst = cls()
        inst(Axis=axis, **inputs)
        assert inst.Error and inst.ErrorID == 0x8045, cls.__name__
    assert MC_WriteParameter()(Axis=axis, Execute=True, ParameterNumber=3, Value=1.0).ErrorID == 0x8086
    fb(Execute=False)
    fb(Execute=True, Mode=1)
    assert fb.Busy and _status(axis) == 3
    _run_until(ctl, fb)
    assert fb.Done and _status(axis) == 1
    ctl.run(OB1)
    assert not axis.db.Statusword.ToDeactivated
    power = MC_Power()
    power(Axis=axis, Enable=True)
    assert not power.Error


def test_s7t_deactivated_axis_db_is_not_updated():
    """S7-Technology V4.1 §6.7.2: the technology DB of a deactivated TO keeps its values (CommandPosition 12.5
    of the last update before the deactivation) while the DB updates go on (UpdateCounter)."""
    ctl = controller()
    axis = ctl.add_positioning_axis("Axis1", VIRTUAL)
    power, on = MC_Power(), [True]

    @ctl.program
    def ob1():
        power(Axis=axis, Enable=on[0])
    ctl.run(0.1)
    move = MC_MoveRelative()
    move(Axis=axis, Execute=True, Distance=12.5)
    ctl.run(1.0)
    assert axis.db.CommandPosition == pytest.approx(12.5)
    on[0] = False
    ctl.run(0.2)
    fb = MC_ActivateTO()
    fb(Axis=axis, Execute=True, Mode=2)
    _run_until(ctl, fb)
    assert fb.Done
    counter = axis.db.UpdateCounter
    ctl.bank.sp_v[axis.index] = 3.0          # a value an update would copy into CommandVelocity
    ctl.run(OB1)
    assert axis.db.UpdateCounter > counter
    assert axis.db.CommandPosition == pytest.approx(12.5) and axis.db.Statusword.ToDeactivated
    assert axis.db.CommandVelocity == 0.0
    assert axis.db.Statusword.Done and axis.db.Statusword.Standstill        # the last values stay


def test_s7t_reactivation_initializes_like_a_restart():
    """S7-Technology V4.1 §6.7.2 note: after reactivation the system variables are initialized as after a
    restart: the axis is no longer homed, its position is kept at 0 offsets; a written "Restart" parameter
    still waits for MC_Reset Restart = TRUE."""
    ctl, axis = _ctl()
    axis.homed = True
    MC_WriteParameter()(Axis=axis, Execute=True, ParameterNumber=1202, Value=720.0)   # modulo length, Restart
    fb = MC_ActivateTO()
    fb(Axis=axis, Execute=True, Mode=2)
    _run_until(ctl, fb)
    fb(Execute=False)
    fb(Execute=True, Mode=1)
    _run_until(ctl, fb)
    assert not axis.homed
    ctl.run(OB1)
    assert axis.db.Statusword.RequestRestart
    assert axis.config.modulo.length == 360.0


@pytest.mark.parametrize("mode", [-1, 3, 1.5])
def test_s7t_activate_to_invalid_mode(mode):
    """S7-Technology V4.1 §6.7.2 (8043): Mode 0, 1 or 2 only."""
    ctl, axis = _ctl()
    fb = MC_ActivateTO()
    fb(Axis=axis, Execute=True, Mode=mode)
    assert fb.Error and fb.ErrorID == 0x8043


def test_s7t_deactivate_enabled_axis_refused():
    """S7-Technology V4.1 §6.7.2 (8045): an axis enabled with MC_Power is not deactivated."""
    ctl, axis, power = enabled()
    fb = MC_ActivateTO()
    fb(Axis=axis, Execute=True, Mode=2)
    assert fb.Error and fb.ErrorID == 0x8045
    assert _status(axis) == 1 and power(Enable=True).Status


def test_s7t_second_activation_command_refused():
    """S7-Technology V4.1 §6.7.2 (8057): a deactivation or activation of the TO is already running."""
    ctl, axis = _ctl()
    a, b = MC_ActivateTO(), MC_ActivateTO()
    a(Axis=axis, Execute=True, Mode=2)
    b(Axis=axis, Execute=True, Mode=1)
    assert a.Busy and b.Error and b.ErrorID == 0x8057


def test_s7t_activate_to_errors_of_the_axis_input():
    """S7-Technology V4.1 §6.7.2 ErrorIDs 8083 (no technology DB)."""
    ctl, axis = _ctl()
    fb = MC_ActivateTO()
    fb(Axis=4711, Execute=True, Mode=0)
    assert fb.Error and fb.ErrorID == 0x8083


def test_s7t_activate_to_does_not_abort_commands_of_other_axes():
    """S7-Technology V4.1 §6.8: MC_ActivateTO aborts no command (of another axis)."""
    ctl, axis, power = enabled()
    other = ctl.add_positioning_axis("Axis2", VIRTUAL)
    move = MC_MoveVelocity()
    move(Axis=axis, Execute=True, Velocity=10.0)
    fb = MC_ActivateTO()
    fb(Axis=other, Execute=True, Mode=2)
    _run_until(ctl, fb)
    assert fb.Done and move(Execute=True).Busy and not move.CommandAborted


# --- MC_ActivateDPSlave ----------------------------------------------------------------------------------------
def _real():
    ctl = controller()
    axis = ctl.add_positioning_axis("Drive1", {"TypeOfAxis.Homing.referencingNecessary": 0})
    ctl.run(0.02)
    return ctl, axis


def _slave_status(ctl) -> int:
    fb = MC_ActivateDPSlave()
    fb(DiagnosticAddress=DIAG, Execute=True, Mode=0)
    assert fb.Done
    return fb.Status


def test_s7t_deactivate_dp_slave_of_a_deactivated_axis():
    """S7-Technology V4.1 §6.7.3: the procedure of the manual - deactivate the axis, then its DP slave: Done
    when initiated, Status 2, StationLifeList[station] = 0, no bus fault at the axis; activating the slave:
    Status 3 until it is back in cyclic exchange, then 1 and StationLifeList 1."""
    ctl, axis = _real()
    assert _slave_status(ctl) == 1 and ctl.extension.mcdevice.StationLifeList[STATION] == 1
    to = MC_ActivateTO()
    to(Axis=axis, Execute=True, Mode=2)
    _run_until(ctl, to)
    fb = MC_ActivateDPSlave()
    fb(DiagnosticAddress=DIAG, Execute=True, Mode=2)
    assert fb.Busy
    _run_until(ctl, fb)
    assert fb.Done and _slave_status(ctl) == 2
    assert ctl.extension.mcdevice.StationLifeList[STATION] == 0
    assert not axis.alarms
    fb(Execute=False)
    fb(Execute=True, Mode=1)
    _run_until(ctl, fb)
    assert fb.Done and _slave_status(ctl) == 3
    ctl.run(10 * OB1)
    assert _slave_status(ctl) == 1 and ctl.extension.mcdevice.StationLifeList[STATION] == 1


def test_s7t_deactivate_dp_slave_takes_drive_communication_away():
    """S7-Technology V4.1 §6.7.3, §7.1: deactivating the slave of an active axis stops the cyclic exchange
    with its drive: Statusword.CyclicInterface FALSE and an error in the technology DB, the enabled axis
    is disabled; once the slave is active again MC_Reset acknowledges and the axis can be enabled."""
    ctl, axis = _real()
    power = MC_Power()

    @ctl.program
    def ob1():
        power(Axis=axis, Enable=True)
    ctl.run(0.3)
    assert power.Status and axis.db.Statusword.CyclicInterface
    fb = MC_ActivateDPSlave()
    fb(DiagnosticAddress=DIAG, Execute=True, Mode=2)
    _run_until(ctl, fb)
    ctl.run(0.05)
    assert not axis.db.Statusword.CyclicInterface and axis.db.ErrorID != 0 and not power.Status
    fb(Execute=False)
    fb(Execute=True, Mode=1)
    _run_until(ctl, fb)
    ctl.run(0.1)
    reset = MC_Reset()
    reset(Axis=axis, Execute=True)
    assert reset.Done and axis.db.ErrorID == 0
    ctl.run(0.5)
    assert power.Status and axis.db.Statusword.CyclicInterface


def test_s7t_reactivated_axis_without_its_slave_has_no_drive():
    """S7-Technology V4.1 §6.7.2/§6.7.3: an axis activated again while its DP slave is still deactivated has
    no cyclic communication with its drive."""
    ctl, axis = _real()
    to, dp = MC_ActivateTO(), MC_ActivateDPSlave()
    to(Axis=axis, Execute=True, Mode=2)
    _run_until(ctl, to)
    dp(DiagnosticAddress=DIAG, Execute=True, Mode=2)
    _run_until(ctl, dp)
    to(Execute=False)
    to(Execute=True, Mode=1)
    _run_until(ctl, to)
    ctl.run(OB1)
    assert not axis.db.Statusword.CyclicInterface


@pytest.mark.parametrize("inputs, error_id", [
    (dict(DiagnosticAddress=DIAG, Mode=3), 0x8043),
    (dict(DiagnosticAddress=DIAG, Mode=-1), 0x8043),
    (dict(DiagnosticAddress=100, Mode=0), 0x8090),          # no slave at that diagnostic address
])
def test_s7t_activate_dp_slave_errors(inputs, error_id):
    """S7-Technology V4.1 §6.7.3 ErrorIDs: 8043 Mode, 8090 logical address invalid."""
    ctl, axis = _real()
    fb = MC_ActivateDPSlave()
    fb(Execute=True, **inputs)
    assert fb.Error and fb.ErrorID == error_id


def test_s7t_activate_dp_slave_already_running():
    """S7-Technology V4.1 §6.7.3 (8057): a second (de)activation of the slave while one runs."""
    ctl, axis = _real()
    a, b = MC_ActivateDPSlave(), MC_ActivateDPSlave()
    a(DiagnosticAddress=DIAG, Execute=True, Mode=2)
    b(DiagnosticAddress=DIAG, Execute=True, Mode=1)
    assert a.Busy and b.Error and b.ErrorID == 0x8057


def test_s7t_power_off_activates_everything_again():
    """S7-Technology V4.1 §6.7.2/§6.7.3: a deactivation by the program does not outlast POWER OFF -> ON (only
    the S7T Config object states do); the slave is in cyclic exchange again."""
    ctl, axis = _real()
    to, dp = MC_ActivateTO(), MC_ActivateDPSlave()
    to(Axis=axis, Execute=True, Mode=2)
    _run_until(ctl, to)
    dp(DiagnosticAddress=DIAG, Execute=True, Mode=2)
    _run_until(ctl, dp)
    ctl.power_cycle()
    ctl.run(0.02)
    assert _status(axis) == 1 and _slave_status(ctl) == 1
    assert ctl.extension.mcdevice.StationLifeList[STATION] == 1
