"""MC_Power (S7-Technology V4.1 §6.2.1, §5.14, §3.1.2): emergency programs (StopMode), modes of operation,
the virtual axis's DriveEnabled and the speed-controlled axis.
"""
from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from plcmotion.s7t import MC_MoveAbsolute, MC_MoveVelocity, MC_Power

from _s7t_rig import VIRTUAL, controller

REAL_AXIS = {"TypeOfAxis.Homing.referencingNecessary": 0, "TypeOfAxis.EmergencyRampGenerator.maxDeceleration": 200.0,
             "TypeOfAxis.MaxAcceleration.maximum": 1000.0, "userdefaultdynamics.stoptime": 2.0}


class Powered:
    def __init__(self, params, **power_inputs):
        self.ctl = controller()
        self.axis = self.ctl.add_positioning_axis("A", params)
        self.power = MC_Power()
        self.enable = True
        self.inputs = power_inputs
        self.ctl.program(lambda: self.power(Axis=self.axis, Enable=self.enable, **self.inputs))
        self.ctl.run(0.3)

    def v(self) -> float:
        return float(self.ctl.bank.sp_v[self.axis.index])


@pytest.mark.parametrize("stop_mode, seconds", [(0, 0.5), (1, 0.1), (2, 2.0)])
def test_s7t_stop_modes_brake_time(stop_mode, seconds):
    """S7-Technology V4.1 §6.2.1 StopMode: 0 the emergency stop deceleration (200: from 100 in 0.5 s),
    1 the maximum deceleration (1000: 0.1 s), 2 within the stop time (2 s); then the axis is disabled."""
    r = Powered(REAL_AXIS, StopMode=stop_mode)
    move = MC_MoveVelocity()
    move(Axis=r.axis, Execute=True, Velocity=100.0, Acceleration=500.0, Jerk=0.0)
    r.ctl.run(0.6)
    assert r.v() == pytest.approx(100.0)
    r.enable = False
    r.ctl.run(seconds / 2)
    assert r.v() == pytest.approx(50.0, abs=100.0 * 0.01 / seconds + 0.5)
    assert r.power.Busy and r.axis.state == "disabling"
    r.ctl.run(seconds / 2 + 0.02)
    assert r.axis.state == "disabled" and not r.power.Status and not r.power.Busy
    assert move(Execute=True).CommandAborted


LIMITED = {**VIRTUAL, "swlimit": {"state": 1, "plusposition": 100.0, "minusposition": -100.0},
           "TypeOfAxis.EmergencyRampGenerator.maxDeceleration": 200.0, "TypeOfAxis.MaxAcceleration.maximum": 1000.0}


def _stopped_near_the_switch(stop_mode: int, stop_time: float, velocity: float, at: float) -> tuple[float, "Powered"]:
    """A virtual axis moving at ``velocity`` towards the plus software limit switch (100) is disabled with
    ``stop_mode`` once its setpoint passes ``at``: the largest setpoint seen until it is disabled."""
    r = Powered({**LIMITED, "userdefaultdynamics.stoptime": stop_time}, StopMode=stop_mode)
    move = MC_MoveVelocity()
    move(Axis=r.axis, Execute=True, Velocity=velocity, Acceleration=1000.0, Deceleration=1000.0, Jerk=0.0)
    r.ctl.run_until(lambda: r.axis.db.CommandPosition >= at, at / velocity + 1.0)   # travel time + ramp
    r.enable = False
    highest = -1e9
    for _ in range(int((stop_time + 1.0) / r.ctl.app_cycle)):
        r.ctl.run(r.ctl.app_cycle)
        highest = max(highest, float(r.ctl.bank.sp_p[r.axis.index]))
    assert r.axis.state == "disabled"
    return highest, r


def test_s7t_stop_program_ends_at_the_software_limit_switch():
    """S7-Technology V4.1 §4.5.7.3 (the software limit switches limit the traversing range "in all operating
    modes") with §6.2.1 StopMode 2 (TimeStop, 2 s): disabled at 90 while moving at 50, the ramp of the stop
    time would end at 90 + 50 · 2 / 2 = 140; the axis stops at the switch (100) instead and 8014 is in its
    technology DB (decision D87: a stop program is a motion of the axis)."""
    highest, r = _stopped_near_the_switch(2, 2.0, 50.0, 90.0)
    assert highest == pytest.approx(100.0, abs=1e-6)
    assert r.axis.db.ErrorID == 0x8014 and r.axis.db.ErrorStatus.SoftwareLimitPos


@settings(max_examples=25, deadline=None)
@given(stop_mode=st.sampled_from([0, 1, 2, 4]), stop_time=st.floats(0.05, 3.0), velocity=st.floats(5.0, 120.0),
       at=st.floats(0.0, 95.0))
def test_s7t_stop_programs_never_pass_an_active_software_limit_switch(stop_mode, stop_time, velocity, at):
    """S7-Technology V4.1 §4.5.7.3, §6.2.1: whatever the stop program (DefaultStop, FastStop, TimeStop with
    any stop time, GearStop), the speed and the place where Enable falls, a stop program whose braking
    distance fits before the switch (emergency deceleration 200: v² / 400 ≤ 100 - position) never takes the
    setpoint past the plus software limit switch."""
    if velocity * velocity / 400.0 > 100.0 - at:
        at = 100.0 - velocity * velocity / 400.0 - 1.0
    highest, _r = _stopped_near_the_switch(stop_mode, stop_time, velocity, at)
    assert highest <= 100.0 + 1e-6


def test_s7t_drive_ramp_stop_removes_the_enable():
    """S7-Technology V4.1 §6.2.1 StopMode 5 (real electric axis): the enable is removed at once and the drive
    stops with its own ramp."""
    r = Powered(REAL_AXIS, StopMode=5)
    move = MC_MoveVelocity()
    move(Axis=r.axis, Execute=True, Velocity=100.0, Acceleration=500.0)
    r.ctl.run(0.6)
    r.enable = False
    r.ctl.run(0.01)
    assert r.axis.state == "disabled" and not r.power.Status and not r.axis.db.Statusword.DriveEnabled


def test_s7t_virtual_axis_drive_always_enabled():
    """S7-Technology V4.1 §5.14: Statusword.DriveEnabled of a virtual axis is always TRUE, also after
    Enable = FALSE; MC_Power Status follows Enable."""
    r = Powered(VIRTUAL)
    r.enable = False
    r.ctl.run(0.05)
    assert not r.power.Status and r.axis.db.Statusword.DriveEnabled and r.axis.db.Statusword.FollowUpControl


def test_s7t_following_mode_takes_no_motion():
    """S7-Technology V4.1 §3.1.2, §6.2.1: Mode 3 (following mode, power unit disabled): the axis is not
    enabled (Status FALSE, Busy TRUE, Statusword.FollowUpControl), its actual value follows the machine,
    a motion command gets 16#8040."""
    r = Powered(REAL_AXIS, Mode=3)
    assert r.power.Busy and not r.power.Status and not r.power.Error
    r.ctl.run(0.02)
    assert r.axis.db.Statusword.FollowUpControl and not r.axis.db.Statusword.DriveEnabled
    move = MC_MoveAbsolute()
    move(Axis=r.axis, Execute=True, Position=1.0)
    assert move.Error and move.ErrorID == 0x8040
    other = MC_Power()
    other(Axis=r.axis, Enable=True)
    assert other.Error and other.ErrorID == 0x804E


def test_s7t_speed_controlled_enable_mode_1():
    """S7-Technology V4.1 §6.2.1 Mode 1: a positioning axis enabled speed-controlled (Statusword.SpeedMode);
    Mode 5 position-controlled."""
    r = Powered(REAL_AXIS, Mode=1)
    r.ctl.run(0.02)
    assert r.power.Status and r.axis.db.Statusword.SpeedMode
    s = Powered(REAL_AXIS, Mode=5)
    s.ctl.run(0.02)
    assert s.power.Status and not s.axis.db.Statusword.SpeedMode


def test_s7t_speed_axis_moves_at_velocity():
    """S7-Technology V4.1 §3.2, §7.1: a speed-controlled axis runs MC_MoveVelocity; its DB shows the command
    and actual velocity (telegram 3: with encoder) and Statusword.SpeedMode."""
    r = Powered({"Wizard.Technology": 0})
    move = MC_MoveVelocity()
    move(Axis=r.axis, Execute=True, Velocity=30.0, Acceleration=300.0)
    r.ctl.run_until(lambda: move(Execute=True).InVelocity, 2.0)
    r.ctl.run(0.3)
    db = r.axis.db
    assert db.CommandVelocity == pytest.approx(30.0) and db.ActualVelocity == pytest.approx(30.0, abs=0.5)
    assert db.Statusword.SpeedMode and db.Statusword.SpeedCommand


def test_s7t_speed_axis_without_encoder_shows_no_actual_velocity():
    """S7-Technology V4.1 §7.1: ActualVelocity is 0 on a speed-controlled axis without encoder (telegram 1)."""
    r = Powered({"Wizard.Technology": 0, "Wizard.Telegram": 1})
    move = MC_MoveVelocity()
    move(Axis=r.axis, Execute=True, Velocity=30.0, Acceleration=300.0)
    r.ctl.run(0.5)
    assert r.axis.db.CommandVelocity == pytest.approx(30.0) and r.axis.db.ActualVelocity == 0.0
