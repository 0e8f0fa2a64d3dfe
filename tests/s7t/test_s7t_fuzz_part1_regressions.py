"""Defects the S7-Technology fuzz campaign found in the FBs and objects of part 1 beyond the motion commands
(``python -m tests.fuzz --dialect S7-Technology``: MC_Stop and MC_ActivateTO around a deactivated object,
MC_SetTorqueLimit, MC_ActivateDPSlave with hydraulic axes), each as the manual's expectation.  An FB gives only the
ErrorIDs of its own table (S7-Technology V4.1 §6); the seed of the episode that found the defect is in the
docstring."""
from __future__ import annotations

from plcmotion.s7t import (MC_ActivateDPSlave, MC_ActivateTO, MC_MoveVelocity, MC_Power, MC_SetTorqueLimit,
                           MC_Stop, add_cam_disk, device)
from plcmotion.s7t.technology import dp_drive

from _s7t_rig import VIRTUAL, controller

OB1 = 0.004
HYDRAULIC = {"TypeOfAxis.Homing.referencingNecessary": 0, "Wizard.DriveTechnology": 1, "Plant.InitialPosition": 100.0,
             "TypeOfAxis.MaxVelocity.maximum": 300.0, "Drive.ValveProfile1": 20}
ELECTRIC = {"TypeOfAxis.Homing.referencingNecessary": 0, "Wizard.Telegram": 105}


def _deactivated(ctl, axis) -> None:
    fb = MC_ActivateTO()
    fb(Axis=axis, Execute=True, Mode=2)
    for _ in range(20):
        if fb.Done:
            break
        ctl.run(OB1)
        fb(Execute=True)
    assert fb.Done, fb


def test_s7t_stop_on_a_deactivated_axis_gives_8044():
    """S7-Technology V4.1 §6.7.2 (a deactivated technology object takes no commands) with the ErrorID table
    of MC_Stop (§6.2.3: no 8045): MC_Stop on a deactivated axis is refused with 16#8044, and the activated
    axis takes it again.  Fuzz seed 7."""
    ctl = controller()
    axis = ctl.add_positioning_axis("Axis1", VIRTUAL)
    ctl.run(0.02)
    _deactivated(ctl, axis)
    stop = MC_Stop()
    stop(Axis=axis, Execute=True)
    assert stop.Error and stop.ErrorID == 0x8044 and not stop.Busy
    activate = MC_ActivateTO()
    activate(Axis=axis, Execute=True, Mode=1)
    for _ in range(20):
        ctl.run(OB1)
        if activate(Execute=True).Done:
            break
    stop(Execute=False)
    stop(Execute=True)
    assert stop.Busy and not stop.Error


def test_s7t_activate_to_on_the_mcdevice_db_gives_8084():
    """S7-Technology V4.1 §6.7.2 MC_ActivateTO ErrorIDs (no 8044; 8084: no technology object exists for the
    technology DB at Axis): the MCDevice DB (DB 1) names no technology object.  Fuzz seed 6."""
    ctl = controller()
    ctl.add_positioning_axis("Axis1", VIRTUAL)
    ctl.run(0.02)
    fb = MC_ActivateTO()
    fb(Axis=device(ctl).mcdevice.number, Execute=True, Mode=1)
    assert fb.Error and fb.ErrorID == 0x8084


def test_s7t_set_torque_limit_on_a_disabled_axis_gives_8045():
    """S7-Technology V4.1 §6.2.12: MC_SetTorqueLimit needs an enabled axis; its ErrorID table has no 8040, the
    refusal is 16#8045 (command not allowed in the current state).  Fuzz seed 14."""
    ctl = controller()
    axis = ctl.add_positioning_axis("Axis1", ELECTRIC)
    ctl.run(0.1)
    fb = MC_SetTorqueLimit()
    fb(Axis=axis, Execute=True, EnableLimit=True, MaxTorque=1.0)
    assert fb.Error and fb.ErrorID == 0x8045
    power = MC_Power()
    power(Axis=axis, Enable=True)
    ctl.run(0.2)
    assert power(Enable=True).Status
    fb(Execute=False)
    fb(Execute=True)
    assert fb.Done and not fb.Error


def test_s7t_dp_slaves_are_the_electric_drives_only():
    """S7-Technology V4.1 §3.1.4, §6.7.3: a hydraulic axis's valve hangs on an analog output, not on a drive
    of DP(DRIVE).  With a hydraulic axis (DB 2) before an electric one (DB 3) the first DP slave is the
    electric drive; deactivating it while its axis moves gives that axis the communication fault, and the
    controller stays in RUN (it went to STOP, the hydraulic axis had been made a slave).  Fuzz seed 23."""
    ctl = controller()
    hydraulic = ctl.add_positioning_axis("H", {**HYDRAULIC, "DBNumber": 2})
    add_cam_disk(ctl, "Cam_1", [(-100.0, -300.0), (0.0, 0.0), (100.0, 300.0)], db_number=20)
    electric = ctl.add_positioning_axis("E", {**ELECTRIC, "DBNumber": 3})
    powers = {a: MC_Power() for a in (hydraulic, electric)}
    move = MC_MoveVelocity()

    @ctl.program
    def ob1() -> None:
        for a, p in powers.items():
            p(Axis=a, Enable=True)
    ctl.run(0.2)
    move(Axis=electric, Execute=True, Velocity=20.0)
    ctl.run(0.1)
    bus = dp_drive.bus(device(ctl))
    assert bus.by_address(dp_drive.BASE_ADDRESS).axis is electric and bus.of(hydraulic) is None
    slave = MC_ActivateDPSlave()
    slave(DiagnosticAddress=dp_drive.DIAGNOSTIC_ADDRESS, Execute=True, Mode=2)
    for _ in range(10):
        ctl.run(OB1)
        if slave(Execute=True).Done:
            break
    assert slave.Done
    ctl.run(0.1)
    assert ctl.mode == "RUN"
    assert electric.state != "enabled" and hydraulic.state == "enabled"
    second = MC_ActivateDPSlave()
    second(DiagnosticAddress=dp_drive.DIAGNOSTIC_ADDRESS - 1, Execute=True, Mode=0)
    assert second.Error and second.ErrorID != 0

