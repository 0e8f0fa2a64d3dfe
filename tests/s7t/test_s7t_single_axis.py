"""Single-axis instructions of S7-Technology V4.1: MC_Stop (§6.2.3), MC_Halt (§6.2.4), MC_MoveAbsolute on
modulo axes (§6.2.6, §6.9.4), MC_MoveAdditive (§6.2.8), MC_MoveSuperImposed (§6.2.9), MC_MoveVelocity
(§6.2.10).  Virtual axes (actual value = setpoint); expected values are the kinematics of the inputs.
"""
from __future__ import annotations

import pytest

from plcmotion.s7t import (MC_Halt, MC_MoveAbsolute, MC_MoveAdditive, MC_MoveRelative, MC_MoveSuperImposed,
                           MC_MoveVelocity, MC_Power, MC_Stop)

from _s7t_rig import VIRTUAL, enabled

TRAPEZOID = dict(Acceleration=100.0, Deceleration=100.0, Jerk=0.0)


def _v(ctl, axis) -> float:
    return float(ctl.bank.sp_v[axis.index])


def _p(ctl, axis) -> float:
    return float(ctl.bank.sp_p[axis.index])


# --- MC_Stop ------------------------------------------------------------------------------------------------
def test_s7t_stop_done_only_after_execute_false():
    """S7-Technology V4.1 §6.2.3: MC_Stop brakes with Deceleration (50 from 50: 1 s); Busy while Execute is
    TRUE even at standstill; Done for one call after Execute goes FALSE; the running command is aborted."""
    ctl, axis, _ = enabled()
    move, stop = MC_MoveVelocity(), MC_Stop()
    move(Axis=axis, Execute=True, Velocity=50.0, **TRAPEZOID)
    ctl.run(1.0)
    stop(Axis=axis, Execute=True, Deceleration=50.0, Jerk=0.0)
    assert move(Execute=True).CommandAborted
    ctl.run(0.5)
    assert _v(ctl, axis) == pytest.approx(25.0, abs=0.3)
    ctl.run(1.0)
    assert _v(ctl, axis) == 0.0 and stop(Execute=True).Busy and not stop.Done
    assert axis.db.Statusword.Stopping
    stop(Execute=False)
    assert stop.Done and not stop.Busy
    stop(Execute=False)
    assert not stop.Done
    move(Execute=False)
    move(Execute=True)
    assert move.Busy and not move.Error                   # the lock has gone with Execute


def test_s7t_stop_maximum_deceleration_above_1e12():
    """S7-Technology V4.1 §6.2.3: Deceleration > 1E12 stops with the maximum (TypeOfAxis.MaxAcceleration.maximum
    = 1000: from 100 in 0.1 s)."""
    ctl, axis, _ = enabled({**VIRTUAL, "TypeOfAxis.MaxAcceleration.maximum": 1000.0})
    move, stop = MC_MoveVelocity(), MC_Stop()
    move(Axis=axis, Execute=True, Velocity=100.0, Acceleration=500.0, Deceleration=500.0, Jerk=0.0)
    ctl.run(0.5)
    stop(Axis=axis, Execute=True, Deceleration=5.0e12, Jerk=0.0)
    ctl.run(0.05)
    assert _v(ctl, axis) == pytest.approx(50.0, abs=2.1)
    ctl.run(0.06)
    assert _v(ctl, axis) == 0.0 and not stop.Error


def test_s7t_stop_aborted_only_by_another_stop():
    """S7-Technology V4.1 §6.2.3: a new MC_Stop aborts the running one (CommandAborted); disabling with MC_Power
    does not, and the lock stays across disable and enable while Execute is TRUE."""
    ctl, axis, power = enabled()
    enable = [True]
    ctl._programs.clear()
    ctl.program(lambda: power(Axis=axis, Enable=enable[0]))
    s1, s2 = MC_Stop(), MC_Stop()
    s1(Axis=axis, Execute=True)
    ctl.run(0.02)
    s2(Axis=axis, Execute=True)
    assert s1(Execute=True).CommandAborted and s2.Busy
    enable[0] = False
    ctl.run(0.1)
    enable[0] = True
    ctl.run(0.1)
    assert power.Status and not s2(Execute=True).CommandAborted
    move = MC_MoveRelative()
    move(Axis=axis, Execute=True, Distance=10.0)
    assert move.Error and move.ErrorID == 0x8045
    s2(Execute=False)
    assert s2.Done
    move(Execute=False)
    move(Execute=True)
    assert move.Busy


# --- MC_Halt ------------------------------------------------------------------------------------------------
def test_s7t_halt_is_overridden_by_motion():
    """S7-Technology V4.1 §6.2.4: MC_Halt brakes with its Deceleration; a new motion command takes over
    (CommandAborted at MC_Halt); appending or overlaying onto a running MC_Halt is refused with 16#8055."""
    ctl, axis, _ = enabled()
    move, halt = MC_MoveVelocity(), MC_Halt()
    move(Axis=axis, Execute=True, Velocity=50.0, **TRAPEZOID)
    ctl.run(1.0)
    halt(Axis=axis, Execute=True, Deceleration=10.0, Jerk=0.0)
    ctl.run(1.0)
    assert _v(ctl, axis) == pytest.approx(40.0, abs=0.1) and halt(Execute=True).Busy
    append = MC_MoveAbsolute()
    append(Axis=axis, Execute=True, Position=500.0, Mode=1)
    assert append.Error and append.ErrorID == 0x8055
    new = MC_MoveVelocity()
    new(Axis=axis, Execute=True, Velocity=20.0, **TRAPEZOID)
    assert halt(Execute=True).CommandAborted and new.Busy


def test_s7t_halt_done_at_standstill():
    """S7-Technology V4.1 §6.2.4: Done when zero velocity is reached (from 30 with 60: 0.5 s)."""
    ctl, axis, _ = enabled()
    move, halt = MC_MoveVelocity(), MC_Halt()
    move(Axis=axis, Execute=True, Velocity=30.0, **TRAPEZOID)
    ctl.run(1.0)
    halt(Axis=axis, Execute=True, Deceleration=60.0, Jerk=0.0)
    t0 = ctl.time
    t = ctl.run_until(lambda: halt(Execute=True).Done, 2.0)
    assert t - t0 == pytest.approx(0.5, abs=0.005) and _v(ctl, axis) == 0.0


# --- MC_MoveVelocity ----------------------------------------------------------------------------------------
def test_s7t_move_velocity_override_example():
    """S7-Technology V4.1 §6.2.10 override example: FB1 at 50 (InVel_1), FB2 at 15: CommandAborted_1 stays TRUE
    while Exe_1 is TRUE; InVel_2 at 15.  Phase b: Exe_1 only pulsed: Abort_1 for one call."""
    ctl, axis, _ = enabled()
    fb1, fb2 = MC_MoveVelocity(), MC_MoveVelocity()
    fb1(Axis=axis, Execute=True, Velocity=50.0, **TRAPEZOID)
    ctl.run_until(lambda: fb1(Execute=True).InVelocity, 2.0)
    fb2(Axis=axis, Execute=True, Velocity=15.0, **TRAPEZOID)
    for _ in range(3):
        ctl.run(0.1)
        assert fb1(Execute=True).CommandAborted and not fb1.InVelocity and not fb1.Busy
    ctl.run_until(lambda: fb2(Execute=True).InVelocity, 2.0)
    assert _v(ctl, axis) == pytest.approx(15.0)
    fb1(Execute=False)
    fb1(Execute=True, Velocity=50.0)
    fb1(Execute=False)                                   # pulsed
    fb2(Execute=False)
    fb2(Execute=True, Velocity=15.0)
    assert fb1(Execute=False).CommandAborted
    assert not fb1(Execute=False).CommandAborted         # only one call


def test_s7t_move_velocity_zero_completes():
    """S7-Technology V4.1 §6.2.10: Velocity = 0.0 is allowed; InVelocity at standstill, the command is then
    complete (Busy FALSE) and InVelocity stays while Execute is TRUE."""
    ctl, axis, _ = enabled()
    fb1, fb0 = MC_MoveVelocity(), MC_MoveVelocity()
    fb1(Axis=axis, Execute=True, Velocity=20.0, **TRAPEZOID)
    ctl.run(0.5)
    fb0(Axis=axis, Execute=True, Velocity=0.0, **TRAPEZOID)
    assert fb0.Busy and not fb0.Error
    ctl.run(0.3)
    assert fb0(Execute=True).InVelocity and not fb0.Busy and _v(ctl, axis) == 0.0
    ctl.run(0.2)
    assert fb0(Execute=True).InVelocity and not fb0.CommandAborted


def test_s7t_move_velocity_append_after_positioning():
    """S7-Technology V4.1 §6.2.10 append example: MC_MoveRelative 1000 runs; MC_MoveVelocity Mode 1 (15)
    waits: the positioning ends with Done_1, then the velocity motion follows at once; appending
    MC_MoveVelocity onto a running MC_MoveVelocity is refused (16#8055)."""
    ctl, axis, _ = enabled()
    rel, vel = MC_MoveRelative(), MC_MoveVelocity()
    rel(Axis=axis, Execute=True, Distance=100.0, Velocity=50.0, **TRAPEZOID)
    ctl.run(0.5)
    vel(Axis=axis, Execute=True, Velocity=15.0, Mode=1, **TRAPEZOID)
    assert vel.Busy and not vel.InVelocity
    t_done = ctl.run_until(lambda: rel(Execute=True).Done, 5.0)
    assert _p(ctl, axis) == pytest.approx(100.0, abs=0.5)
    t_in = ctl.run_until(lambda: vel(Execute=True).InVelocity, 2.0)
    assert t_in - t_done == pytest.approx(0.15, abs=0.01)         # 15 with acceleration 100
    again = MC_MoveVelocity()
    again(Axis=axis, Execute=True, Velocity=30.0, Mode=1)
    assert again.Error and again.ErrorID == 0x8055


def test_s7t_move_velocity_speed_control_is_retained():
    """S7-Technology V4.1 §6.2.10: PositionControl = FALSE switches to speed control (Statusword.SpeedMode);
    it stays after the command until a positioning - MC_MoveRelative with Distance 0.0 ends it without
    motion."""
    ctl, axis, _ = enabled()
    vel = MC_MoveVelocity()
    vel(Axis=axis, Execute=True, Velocity=10.0, PositionControl=False, Direction=3)
    ctl.run(0.5)
    assert axis.db.Statusword.SpeedMode and _v(ctl, axis) < 0.0
    halt = MC_Halt()
    halt(Axis=axis, Execute=True)
    ctl.run_until(lambda: halt(Execute=True).Done, 2.0)
    ctl.run(0.01)
    assert axis.db.Statusword.SpeedMode
    rel = MC_MoveRelative()
    p = _p(ctl, axis)
    rel(Axis=axis, Execute=True, Distance=0.0)
    ctl.run_until(lambda: rel(Execute=True).Done, 1.0)
    ctl.run(0.01)
    assert not axis.db.Statusword.SpeedMode and _p(ctl, axis) == pytest.approx(p)


def test_s7t_move_velocity_directions():
    """S7-Technology V4.1 §6.2.10: Direction 1 positive, 3 negative, 4 the current direction, 0 the default
    (positive); the velocity is a magnitude."""
    ctl, axis, _ = enabled()
    fb = MC_MoveVelocity()
    for direction, sign in ((3, -1), (4, -1), (1, 1), (4, 1), (0, 1)):
        fb(Axis=axis, Execute=False)
        fb(Axis=axis, Execute=True, Velocity=20.0, Direction=direction, **TRAPEZOID)
        ctl.run_until(lambda: fb(Execute=True).InVelocity, 2.0)
        assert _v(ctl, axis) == pytest.approx(20.0 * sign)


# --- MC_MoveAbsolute on modulo axes -------------------------------------------------------------------------
MODULO = {**VIRTUAL, "Wizard.AxisType": 1, "Modulo": {"state": 1, "length": 360.0, "startValue": 0.0}}


@pytest.mark.parametrize("direction, position, travel", [
    (1, 400.0, 40.0 - 100.0 + 360.0),      # positive: 100 -> 40 (400 reduced into the range, §6.9.4)
    (3, 400.0, 40.0 - 100.0),              # negative
    (2, 300.0, -160.0),                    # shortest distance
    (2, 200.0, 100.0),
    (0, 40.0, 300.0),                      # the default direction: positive
])
def test_s7t_modulo_directions(direction, position, travel):
    """S7-Technology V4.1 §6.2.6, §6.9.4: on a modulo axis Position is reduced into the modulo range; Direction
    1 positive, 2 shortest distance, 3 negative, 0 the configured default."""
    ctl, axis, _ = enabled(MODULO)
    first = MC_MoveAbsolute()
    first(Axis=axis, Execute=True, Position=100.0, Velocity=500.0)
    ctl.run_until(lambda: first(Execute=True).Done, 5.0)
    start = _p(ctl, axis)
    move = MC_MoveAbsolute()
    move(Axis=axis, Execute=True, Position=position, Velocity=500.0, Direction=direction)
    ctl.run_until(lambda: move(Execute=True).Done, 10.0)
    assert _p(ctl, axis) - start == pytest.approx(travel, abs=1e-6)
    ctl.run(0.01)
    assert axis.db.ActualPosition == pytest.approx(position % 360.0, abs=1e-6)


def test_s7t_modulo_overlay_with_current_direction_refused():
    """S7-Technology V4.1 §6.2.6: Mode 2 with Direction 4 (the current direction) on a modulo axis: 16#8043."""
    ctl, axis, _ = enabled(MODULO)
    move = MC_MoveAbsolute()
    move(Axis=axis, Execute=True, Position=10.0, Direction=4, Mode=2)
    assert move.Error and move.ErrorID == 0x8043


# --- MC_MoveAdditive ----------------------------------------------------------------------------------------
def test_s7t_move_additive_corrects_the_target():
    """S7-Technology V4.1 §6.2.8 example b: a second MC_MoveAdditive before the first is done aborts it; the
    axis ends at the first target plus the second Distance (100 + 30 from 0); at standstill it moves
    Distance like MC_MoveRelative."""
    ctl, axis, _ = enabled()
    a1, a2 = MC_MoveAdditive(), MC_MoveAdditive()
    a1(Axis=axis, Execute=True, Distance=100.0, Velocity=50.0, **TRAPEZOID)
    ctl.run(0.5)
    a2(Axis=axis, Execute=True, Distance=30.0, Velocity=50.0, **TRAPEZOID)
    assert a1(Execute=True).CommandAborted
    ctl.run_until(lambda: a2(Execute=True).Done, 10.0)
    assert _p(ctl, axis) == pytest.approx(130.0, abs=1e-6)
    a1(Execute=False)
    a1(Execute=True, Distance=-20.0)
    ctl.run_until(lambda: a1(Execute=True).Done, 10.0)
    assert _p(ctl, axis) == pytest.approx(110.0, abs=1e-6)


def test_s7t_move_additive_over_velocity_motion():
    """S7-Technology V4.1 §6.2.8: over a motion without target (MC_MoveVelocity) the target is the position at
    the override plus Distance."""
    ctl, axis, _ = enabled()
    vel, add = MC_MoveVelocity(), MC_MoveAdditive()
    vel(Axis=axis, Execute=True, Velocity=10.0, **TRAPEZOID)
    ctl.run(1.0)
    p0 = _p(ctl, axis)
    add(Axis=axis, Execute=True, Distance=50.0, Velocity=10.0, **TRAPEZOID)
    ctl.run_until(lambda: add(Execute=True).Done, 10.0)
    assert _p(ctl, axis) == pytest.approx(p0 + 50.0, abs=1e-6) and vel(Execute=True).CommandAborted


# --- MC_MoveSuperImposed ------------------------------------------------------------------------------------
def test_s7t_superimposed_adds_to_a_positioning():
    """S7-Technology V4.1 §6.2.9: started during an absolute positioning the superimposed Distance adds to the
    end position (100 + 20); the positioning goes on (not aborted); Statusword.SuperImposedCommand."""
    ctl, axis, _ = enabled()
    move, sup = MC_MoveAbsolute(), MC_MoveSuperImposed()
    move(Axis=axis, Execute=True, Position=100.0, Velocity=20.0, **TRAPEZOID)
    ctl.run(0.5)
    sup(Axis=axis, Execute=True, Distance=20.0, VelocityDiff=10.0, **TRAPEZOID)
    ctl.run(0.1)
    assert sup.Busy and move(Execute=True).Busy and not move.CommandAborted
    assert axis.db.Statusword.SuperImposedCommand
    ctl.run_until(lambda: move(Execute=True).Done and sup(Execute=True).Done, 10.0)
    ctl.run(0.1)
    assert _p(ctl, axis) == pytest.approx(120.0, abs=1e-6)


def test_s7t_superimposed_restart_loses_the_rest():
    """S7-Technology V4.1 §6.2.9: a new MC_MoveSuperImposed aborts the running one; its remaining distance is
    lost (at standstill: 5 of the first 20 done, then 10 more: 15)."""
    ctl, axis, _ = enabled()
    s1, s2 = MC_MoveSuperImposed(), MC_MoveSuperImposed()
    s1(Axis=axis, Execute=True, Distance=20.0, VelocityDiff=10.0, Acceleration=1000.0, Deceleration=1000.0,
       Jerk=0.0)
    ctl.run(0.5)
    done_so_far = _p(ctl, axis)
    s2(Axis=axis, Execute=True, Distance=10.0, VelocityDiff=10.0, Acceleration=1000.0, Deceleration=1000.0,
       Jerk=0.0)
    assert s1(Execute=True).CommandAborted
    ctl.run_until(lambda: s2(Execute=True).Done, 5.0)
    assert _p(ctl, axis) == pytest.approx(done_so_far + 10.0, abs=0.05)
    assert done_so_far == pytest.approx(5.0 - 0.05, abs=0.1)


def test_s7t_superimposed_needs_position_control():
    """S7-Technology V4.1 §6.2.9: the axis must be enabled position-controlled: in speed control 16#8040."""
    ctl, axis, _ = enabled()
    vel = MC_MoveVelocity()
    vel(Axis=axis, Execute=True, Velocity=5.0, PositionControl=False)
    ctl.run(0.1)
    sup = MC_MoveSuperImposed()
    sup(Axis=axis, Execute=True, Distance=1.0)
    assert sup.Error and sup.ErrorID == 0x8040


def test_s7t_power_second_instance_804e_and_other_axis_804f():
    """S7-Technology V4.1 §6.2.1: a second MC_Power enabling the same axis gets 16#804E; an instance whose Axis
    input names another axis when Enable falls gets 16#804F and its axis stays enabled."""
    ctl, axis, power = enabled()
    other = ctl.add_positioning_axis("Other", VIRTUAL)
    second = MC_Power()
    second(Axis=axis, Enable=True)
    assert second.Error and second.ErrorID == 0x804E and not second.Status
    ctl._programs.clear()
    mine = MC_Power()
    mine(Axis=other, Enable=True)
    ctl.run(0.02)
    assert mine(Axis=other, Enable=True).Status
    mine(Axis=axis, Enable=False)
    assert mine.Error and mine.ErrorID == 0x804F
    ctl.run(0.1)
    assert other.state == "enabled"


def test_s7t_stop_deceleration_zero_uses_the_default():
    """S7-Technology V4.1 §6.2.3 ErrorIDs: Deceleration = 0 is ignored with warning 16#0028 (Error FALSE)
    and the axis stops with the default deceleration (userdefaultdynamics.negativeaccel 100: from 50 in
    0.5 s)."""
    ctl, axis, _ = enabled()
    move, stop = MC_MoveVelocity(), MC_Stop()
    move(Axis=axis, Execute=True, Velocity=50.0, **TRAPEZOID)
    ctl.run(1.0)
    stop(Axis=axis, Execute=True, Deceleration=0.0, Jerk=0.0)
    assert stop.Busy and not stop.Error and stop.ErrorID == 0x0028 and stop.ENO
    ctl.run(0.25)
    assert _v(ctl, axis) == pytest.approx(25.0, abs=0.5)
    ctl.run(0.3)
    assert _v(ctl, axis) == 0.0
    stop(Execute=False)
    assert stop.Done and stop.ErrorID == 0x0028
