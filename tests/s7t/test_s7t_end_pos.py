"""MC_MoveToEndPos (S7-Technology V4.1 §6.2.11, §4.5.7.5): travel to a fixed end stop, clamping, release,
the clamping monitoring (16#801B) and the ErrorIDs of its table."""
from __future__ import annotations

import math

import pytest

from plcmotion.s7t import MC_MoveAbsolute, MC_MoveRelative, MC_MoveToEndPos, MC_Power, MC_Stop

from _s7t_rig import controller

DS = "TypeOfAxis.NumberOfDataSets.DataSet_1.ClampingMonitoring"
STOP = 50.0
AXIS = {"TypeOfAxis.Homing.referencingNecessary": 0, "Wizard.Telegram": 105, f"{DS}.recognitionMode": 106,
        f"{DS}.followingErrorDeviation": 1.0, f"{DS}.positionTolerance": 0.1, "Plant.EndStopMaxPosition": STOP}


class Rig:
    def __init__(self, params=None, enable=True):
        self.ctl = controller()
        self.axis = self.ctl.add_positioning_axis("A", {**AXIS, **(params or {})})
        self.power = MC_Power()
        self.end = MC_MoveToEndPos()
        self.inputs = dict(Execute=False, Velocity=20.0, Torque=1.0)
        self.ctl.program(lambda: (self.power(Axis=self.axis, Enable=enable), self.end(Axis=self.axis, **self.inputs)))
        self.ctl.run(0.2)

    def act(self) -> float:
        return float(self.ctl.bank.act_p[self.axis.index])

    def sp(self) -> float:
        return float(self.ctl.bank.sp_p[self.axis.index])

    def clamp(self) -> None:
        self.inputs["Execute"] = True
        self.ctl.run(STOP / 20.0 + 0.5)


def test_s7t_end_pos_clamps_at_the_stop():
    """S7-Technology V4.1 §6.2.11, §4.5.7.5: the axis travels to the end stop; once the following error
    reaches followingErrorDeviation the setpoint is held (end stop + following error), InClamping is TRUE and
    the drive presses with the Torque limit (Statusword TorqueLimiting / TorqueLimitingCommand, §7.1)."""
    r = Rig()
    r.inputs["Execute"] = True
    r.ctl.run(1.0)
    assert r.end.Busy and not r.end.InClamping and r.axis.db.Statusword.SpeedCommand
    r.ctl.run(STOP / 20.0)
    assert r.act() == pytest.approx(STOP, abs=1e-3)
    assert r.sp() == pytest.approx(STOP + 1.0, abs=0.05)
    assert r.end.InClamping and r.end.Busy and not r.end.Error
    assert r.axis.drive.torque == pytest.approx(1.0, rel=1e-6)
    sw = r.axis.db.Statusword
    assert sw.TorqueLimiting and sw.TorqueLimitingCommand and not sw.SpeedCommand
    held = r.sp()
    r.ctl.run(0.5)
    assert r.sp() == held and r.end.InClamping          # the setpoint stays held


def test_s7t_end_pos_toward_the_stop_8056():
    """S7-Technology V4.1 §6.2.11 ErrorID 8056: while clamped only commands away from the stop are taken."""
    r = Rig()
    r.clamp()
    move = MC_MoveAbsolute()
    move(Axis=r.axis, Execute=True, Position=STOP + 10.0, Velocity=10.0)
    r.ctl.run(0.02)
    move(Axis=r.axis, Execute=True)
    assert move.Error and move.ErrorID == 0x8056
    assert r.end.InClamping and r.end.Busy


def test_s7t_end_pos_moving_away_releases():
    """S7-Technology V4.1 §6.2.11 example c: a MC_MoveRelative away from the stop releases the axis (the
    clamping command is aborted); the torque limit is given back once the setpoint has left the window."""
    r = Rig()
    r.clamp()
    rel = MC_MoveRelative()
    rel(Axis=r.axis, Execute=True, Distance=-10.0, Velocity=10.0)
    r.ctl.run(0.02)
    rel(Axis=r.axis, Execute=True)
    assert not rel.Error and rel.Busy
    assert r.end.CommandAborted and not r.end.InClamping
    peak = [0.0]
    r.ctl.on_post_servo(lambda t: peak.__setitem__(0, max(peak[0], abs(r.axis.drive.torque))))
    r.ctl.run(0.05)
    assert r.axis.db.Statusword.TorqueLimitingCommand        # the setpoint has not yet passed the window
    toward = MC_MoveAbsolute()
    toward(Axis=r.axis, Execute=True, Position=STOP, Velocity=10.0)
    assert toward.Error and toward.ErrorID == 0x8056        # still refused (§6.2.11 "Interaction")
    r.ctl.run(1.45)
    assert peak[0] <= 1.0 + 1e-9                            # released with the clamping torque, no jerk
    assert r.act() == pytest.approx(STOP + 1.0 - 10.0, abs=0.05)
    assert not r.axis.db.Statusword.TorqueLimitingCommand
    assert r.axis.db.ErrorID == 0
    again = MC_MoveAbsolute()
    again(Axis=r.axis, Execute=True, Position=STOP - 5.0, Velocity=10.0)
    r.ctl.run(0.02)
    again(Axis=r.axis, Execute=True)
    assert again.Busy and not again.Error                    # out of the window: toward the stop again


def test_s7t_end_pos_clamping_monitoring_801b():
    """S7-Technology V4.1 §7.12.1 16#801B: the axis leaves the position tolerance after fixed end stop
    detection without a new motion command: clamping monitoring error, ErrorStatus.ClampingError."""
    r = Rig()
    r.clamp()
    r.axis.disturb_load(jump=-1.0)                     # the load is pushed back off the stop
    r.ctl.run(0.05)
    assert r.axis.db.ErrorID == 0x801B
    assert r.axis.db.ErrorStatus.ClampingError
    assert r.end.CommandAborted and not r.end.InClamping


def test_s7t_end_pos_same_direction_takes_over_reverse_8045():
    """S7-Technology V4.1 §6.2.11 "Interaction": a new MC_MoveToEndPos in the same direction overrides the
    clamped one (a new Torque: 2.0); a reversing one while clamped is refused with 16#8045."""
    r = Rig()
    r.clamp()
    again = MC_MoveToEndPos()
    again(Axis=r.axis, Execute=True, Velocity=20.0, Torque=2.0)
    r.ctl.run(0.5)
    again(Axis=r.axis, Execute=True)
    assert r.end.CommandAborted and again.InClamping
    assert 1.5 < r.axis.drive.torque <= 2.0 + 1e-9     # presses harder than the old limit, within the new
    back = MC_MoveToEndPos()
    back(Axis=r.axis, Execute=True, Velocity=20.0, Direction=3)
    r.ctl.run(0.02)
    back(Axis=r.axis, Execute=True)
    assert back.Error and back.ErrorID == 0x8045 and again.InClamping


def test_s7t_end_pos_reverse_before_the_stop_warning_0029():
    """S7-Technology V4.1 §6.2.11 ErrorIDs: a reversing MC_MoveToEndPos started over the active one before
    the end stop is ignored with warning 16#0029 (Error stays FALSE); the active one goes on."""
    r = Rig()
    r.inputs["Execute"] = True
    r.ctl.run(0.5)
    back = MC_MoveToEndPos()
    back(Axis=r.axis, Execute=True, Velocity=20.0, Direction=3)
    r.ctl.run(0.02)
    back(Axis=r.axis, Execute=True)
    assert back.ErrorID == 0x0029 and back.CommandAborted and not back.Error and not back.Busy
    assert r.end.Busy and not r.end.CommandAborted
    r.ctl.run(STOP / 20.0)
    assert r.end.InClamping


NAN = math.nan


@pytest.mark.parametrize("inputs, params, code", [
    (dict(Velocity=0.0), {}, 0x8043),                  # the initial value 0.0 is not permitted
    (dict(Direction=2), {}, 0x8043),
    (dict(Direction=7), {}, 0x8043),
    (dict(Torque=0.0), {}, 0x8043),
    (dict(Torque=5.0), {}, 0x8043),                    # above the torque reference 3.2 N m
    (dict(DoneFlag=33), {}, 0x8043),
    (dict(Torque=NAN), {}, 0x808B),
    (dict(Velocity=2e12), {}, 0x8043),
    ({}, {f"{DS}.recognitionMode": 105}, 0x8043),      # fixed end stop detection not enabled
    ({}, {"Wizard.Telegram": 3}, 0x8043),              # no torque reduction in the telegram
    ({}, {"Wizard.Virtual": 1}, 0x804D),
    ({}, {"Wizard.DriveTechnology": 1, "Plant.InitialPosition": 10.0}, 0x804D),
    (dict(Axis=999), {}, 0x8083),
])
def test_s7t_end_pos_error_ids(inputs, params, code):
    """S7-Technology V4.1 §6.2.11 "MC_MoveToEndPos - ErrorIDs": the command is not started."""
    r = Rig(params)
    fb = MC_MoveToEndPos()
    fb(**{"Axis": r.axis, "Execute": True, "Velocity": 20.0, "Torque": 1.0, **inputs})
    assert fb.Error and fb.ErrorID == code and not fb.Busy


def test_s7t_end_pos_disabled_8040_and_stop_8045():
    """S7-Technology V4.1 §6.2.11 ErrorIDs 8040 (axis not enabled) and 8045 (MC_Stop active)."""
    r = Rig(enable=False)
    fb = MC_MoveToEndPos()
    fb(Axis=r.axis, Execute=True, Velocity=20.0)
    r.ctl.run(0.02)
    fb(Axis=r.axis, Execute=True)
    assert fb.Error and fb.ErrorID == 0x8040
    r2 = Rig()
    stop = MC_Stop()
    stop(Axis=r2.axis, Execute=True)
    r2.ctl.run(0.1)
    stop(Axis=r2.axis, Execute=True)
    fb2 = MC_MoveToEndPos()
    fb2(Axis=r2.axis, Execute=True, Velocity=20.0)
    r2.ctl.run(0.02)
    fb2(Axis=r2.axis, Execute=True)
    assert fb2.Error and fb2.ErrorID == 0x8045
