"""Mechanics changed at run time reach the CiA 402 drive: the master writes the position scaling again
(position encoder resolution 0x608F and the factor group's feed constant 0x6092, CiA 402-2) and converts
with the new load travel per motor revolution.  S7-Technology V4.1 §6.7.5 (MC_WriteParameter, warning 0020,
effective at the restart), parameter 1100 leadscrew pitch; S7-1200 Motion Control V6 §12.8 (16#800C/16#003E
station failure) for a drive that does not answer."""
from __future__ import annotations

from dataclasses import replace

import pytest

pytest.importorskip("canopen")
pytest.importorskip("can")

from plcmotion import Controller  # noqa: E402
from plcmotion.drives.cia402 import Cia402Link  # noqa: E402
from plcmotion.s7t import MC_MoveAbsolute, MC_Power, MC_Reset, MC_WriteParameter  # noqa: E402

from _cia402_rig import Rig, channel  # noqa: E402

INC_PER_REV = 2048 << 11


def test_drives_cia402_s7t_leadscrew_written_at_run_time():
    """S7-Technology: the leadscrew pitch 1100 written from 10 to 20 mm per revolution with MC_WriteParameter
    (0020: effective at the restart) and MC_Reset Restart = TRUE: afterwards MC_MoveAbsolute to 40 mm turns
    the CiA 402 drive 40 / 20 = 2 motor revolutions (2 x 2^22 increments), not 4."""
    ctl = Controller(family="S7-Technology", servo_cycle=0.001, app_cycle=0.002)
    ctl.connect_drive("Real", Cia402Link(channel=channel(), node_id=3, simulate=True))
    axis = ctl.add_positioning_axis("Real", {"TypeOfAxis.MaxVelocity.maximum": 100.0,
                                             "TypeOfAxis.Homing.referencingNecessary": 0})
    try:
        power, reset, inputs = MC_Power(), MC_Reset(), {"enable": False, "restart": False}

        def ob1() -> None:
            power(Axis=axis, Enable=inputs["enable"])
            reset(Axis=axis, Execute=inputs["restart"], Restart=True)
        ctl.program(ob1)
        ctl.run(0.01)
        write = MC_WriteParameter()(Axis=axis, Execute=True, ParameterNumber=1100, Index=1, Value=20.0)
        assert write.Done and write.ErrorID == 0x0020
        inputs["restart"] = True
        ctl.run_until(lambda: reset.Done, timeout=1.0)
        assert axis.config.drive.length_per_revolution == 20.0
        inputs["enable"] = True
        ctl.run(0.1)
        assert power.Status
        move = MC_MoveAbsolute()
        for _ in range(1000):
            move(Axis=axis, Execute=True, Position=40.0, Velocity=50.0)
            if move.Done or move.Error:
                break
            ctl.run(0.004)
        assert move.Done and not move.Error
        assert axis.drive.simulated.position == pytest.approx(2 * INC_PER_REV, abs=0.01 * INC_PER_REV)
    finally:
        ctl.close()


def test_drives_cia402_encoder_resolution_rewritten():
    """A new encoder resolution (fine resolution 11 -> 10 bit) that becomes effective while the axis is
    disabled is written to the drive: 0x608F:1 and the feed constant 0x6092:1 read 2048 x 2^10 increments
    per revolution, and one increment is 10 mm / 2^21 on the master's side."""
    r = Rig("csp", enable=False)
    try:
        r.steps(3)
        spec = r.axis.config.drive
        r.drive.reconfigure(replace(spec, encoder=replace(spec.encoder, fine_bits=10)))
        sdo = r.drive.remote.sdo
        assert sdo[0x608F][1].raw == sdo[0x6092][1].raw == 2048 << 10
        assert r.drive.q == 10.0 / (2048 << 10)
        r.drive.reconfigure(replace(spec, encoder=replace(spec.encoder, fine_bits=10)))   # unchanged: no SDO
        assert r.drive.rescale_error == ""
    finally:
        r.close()


def test_drives_cia402_rescale_without_answer_is_a_communication_fault():
    """A drive that does not answer while the scaling is written again: no exception in the controller, a
    station failure 16#800C/16#003E at the axis (S7-1200 V6 §12.8), the object named in ``rescale_error``."""
    r = Rig("csp", enable=False)
    try:
        r.steps(3)
        r.sim.silence(True)
        spec = r.axis.config.drive
        r.drive.reconfigure(replace(spec, length_per_revolution=5.0))
        assert "0x608F" in r.drive.rescale_error
        r.steps(2)
        assert (r.power.ErrorID, r.power.ErrorInfo) == (0x800C, 0x003E)
    finally:
        r.close()
