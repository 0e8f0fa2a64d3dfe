"""MC_SetTorqueLimit (S7-Technology V4.1 §6.2.12, §9.3.2.2): the torque limit, the Statusword bits
TorqueLimitingCommand / TorqueLimiting (§7.1), the limit across MC_Power Enable FALSE (V4.1) and the ErrorIDs."""
from __future__ import annotations

import math

import pytest

from plcmotion.s7t import MC_MoveVelocity, MC_Power, MC_SetTorqueLimit, MC_Stop

from _s7t_rig import controller

AXIS = {"TypeOfAxis.Homing.referencingNecessary": 0, "Wizard.Telegram": 105, "Plant.Inertia": 1.0e-3,
        "TypeOfAxis.MaxAcceleration.maximum": 1.0e5}


class Rig:
    def __init__(self, params=None, enable=True):
        self.ctl = controller()
        self.axis = self.ctl.add_positioning_axis("A", {**AXIS, **(params or {})})
        self.power = MC_Power()
        self.inputs = dict(Enable=enable)
        self.ctl.program(lambda: self.power(Axis=self.axis, **self.inputs))
        self.ctl.run(0.2)

    def limit(self, **inputs) -> MC_SetTorqueLimit:
        fb = MC_SetTorqueLimit()
        fb(**{"Axis": self.axis, "Execute": True, **inputs})
        return fb


def test_s7t_torque_limit_status_bits():
    """S7-Technology V4.1 §6.2.12, §7.1: with the limit set TorqueLimitingCommand is TRUE; while the drive
    needs more torque than the limit (a hard acceleration) TorqueLimiting is TRUE too; EnableLimit FALSE
    clears both."""
    r = Rig()
    fb = r.limit(MaxTorque=0.1)
    assert fb.Done and not fb.Error
    r.ctl.run(0.01)
    sw = r.axis.db.Statusword
    assert sw.TorqueLimitingCommand and not sw.TorqueLimiting
    move = MC_MoveVelocity()
    # 10 mm per motor revolution: 50000 mm/s² needs 1e-3 kg m² * 2 pi * 5000 1/s² = 31 N m > 0.1 N m
    move(Axis=r.axis, Execute=True, Velocity=500.0, Acceleration=50000.0, Jerk=0.0, PositionControl=False)
    r.ctl.run(0.01)
    assert r.axis.db.Statusword.TorqueLimiting
    assert abs(r.axis.drive.torque) == pytest.approx(0.1, rel=1e-6)
    off = r.limit(EnableLimit=False)
    assert off.Done
    r.ctl.run(0.01)
    sw = r.axis.db.Statusword
    assert not sw.TorqueLimitingCommand and not sw.TorqueLimiting


def test_s7t_torque_limit_zero_takes_the_torque_reference():
    """S7-Technology V4.1 §6.2.12 MaxTorque = 0: the configured torque reference
    TypeOfAxis.SetPointDriverInfo.DriveData.maxTorque (here 0.2 N m, §9.3.2.2) is the limit."""
    r = Rig({"TypeOfAxis.SetPointDriverInfo.DriveData.maxTorque": 0.2})
    assert r.limit(MaxTorque=0.0).Done
    move = MC_MoveVelocity()
    move(Axis=r.axis, Execute=True, Velocity=500.0, Acceleration=50000.0, Jerk=0.0, PositionControl=False)
    r.ctl.run(0.01)
    assert abs(r.axis.drive.torque) == pytest.approx(0.2, rel=1e-6)


def test_s7t_torque_limit_survives_disable():
    """S7-Technology V4.1 §6.2.12 (V4.1): the torque limit stays when MC_Power removes the enable; with the
    torque reduction active the axis is disabled at once (StopMode not used, §6.2.1)."""
    r = Rig()
    assert r.limit(MaxTorque=0.5).Done
    r.inputs["Enable"] = False
    r.ctl.run(0.05)
    assert r.axis.state == "disabled"
    assert r.axis.db.Statusword.TorqueLimitingCommand
    r.inputs["Enable"] = True
    r.ctl.run(0.1)
    move = MC_MoveVelocity()
    move(Axis=r.axis, Execute=True, Velocity=500.0, Acceleration=50000.0, Jerk=0.0, PositionControl=False)
    r.ctl.run(0.01)
    assert abs(r.axis.drive.torque) == pytest.approx(0.5, rel=1e-6)


NAN = math.nan


@pytest.mark.parametrize("inputs, params, code", [
    (dict(MaxTorque=-1.0), {}, 0x8043),
    (dict(MaxTorque=NAN), {}, 0x808B),
    (dict(DoneFlag=40), {}, 0x8043),
    ({}, {"Wizard.Telegram": 3}, 0x8043),              # the drive's telegram has no torque reduction
    ({}, {"Wizard.Virtual": 1}, 0x804D),
    ({}, {"Wizard.DriveTechnology": 2, "Plant.InitialPosition": 10.0}, 0x804D),
    (dict(Axis=999), {}, 0x8083),
])
def test_s7t_torque_limit_error_ids(inputs, params, code):
    """S7-Technology V4.1 §6.2.12 "MC_SetTorqueLimit - ErrorIDs"."""
    r = Rig(params)
    fb = r.limit(**inputs)
    assert fb.Error and fb.ErrorID == code and not fb.Done


def test_s7t_torque_limit_disabled_8045_stop_8045():
    """S7-Technology V4.1 §6.2.12 prerequisites: an enabled axis, no active MC_Stop; the FB's ErrorID table has
    no 8040, so both refusals are 8045 (command not allowed in the current state; fuzz seed 14)."""
    r = Rig(enable=False)
    fb = r.limit()
    assert fb.Error and fb.ErrorID == 0x8045
    r2 = Rig()
    stop = MC_Stop()
    stop(Axis=r2.axis, Execute=True)
    r2.ctl.run(0.1)
    fb2 = r2.limit()
    assert fb2.Error and fb2.ErrorID == 0x8045
