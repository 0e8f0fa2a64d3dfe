"""MC_Power Mode 4, simulation mode (S7-Technology V4.1 §3.1.2 "Simulation mode", §6.2.1 Mode table, §7.1
Statusword bit 17, §9.3 control panel "Simulation OFF").

In simulation the axis runs its commands with actual value = setpoint and following error 0 while the drive is
not enabled, so the machine does not move; disabling ends it and the actual value is the encoder's again.
"""
from __future__ import annotations

import pytest

from plcmotion.s7t import MC_MoveAbsolute, MC_MoveVelocity, MC_Power

from _s7t_rig import controller

REAL_AXIS = {"TypeOfAxis.Homing.referencingNecessary": 0, "Plant.InitialPosition": 5.0}
SIMULATION = 4


def _sim(params=None, technology: int = 1):
    ctl = controller()
    axis = ctl.add_positioning_axis("A", {**REAL_AXIS, "Wizard.Technology": technology, **(params or {})})
    power = MC_Power()
    state = {"enable": True}
    ctl.program(lambda: power(Axis=axis, Enable=state["enable"], Mode=SIMULATION))
    ctl.run(0.1)
    return ctl, axis, power, state


def test_s7t_simulation_mode_moves_the_model_not_the_machine():
    """S7-Technology V4.1 §3.1.2: in simulation mode a positioning runs to its target with actual = setpoint
    and following error 0, the drive stays disabled and the load does not move; Statusword.Simulation is TRUE,
    DriveEnabled FALSE (the drive is not enabled), MC_Power.Status TRUE."""
    ctl, axis, power, _ = _sim()
    db = axis.db
    assert power.Status and not power.Error and db.Statusword.Simulation and not db.Statusword.DriveEnabled
    mech = axis.drive.mechanical_position()
    move = MC_MoveAbsolute()
    ctl.program(lambda: move(Axis=axis, Execute=True, Position=105.0, Velocity=100.0))
    seen = []
    ctl.on_post_servo(lambda t: seen.append(float(ctl.bank.fe[axis.index])))
    ctl.run_until(lambda: move.Done, 5.0)
    assert db.ActualPosition == pytest.approx(105.0, abs=1e-6) and db.FollowingError == 0.0
    assert max(abs(x) for x in seen) == 0.0
    assert axis.drive.mechanical_position() == pytest.approx(mech, abs=1e-9)


def test_s7t_simulation_mode_ends_with_the_disable():
    """S7-Technology V4.1 §3.1.2, §9.3 "Simulation OFF": leaving simulation mode the axis sees the machine's
    encoder's position again: the load stood still all the time, so the incremental encoder still reads 0,
    where it counted from at power-up (§3.1.8); Statusword.Simulation FALSE."""
    ctl, axis, power, state = _sim()
    mv = MC_MoveVelocity()
    ctl.program(lambda: mv(Axis=axis, Execute=True, Velocity=50.0))
    ctl.run(1.0)
    assert axis.db.ActualPosition > 25.0 and axis.drive.mechanical_position() == pytest.approx(5.0, abs=1e-9)
    state["enable"] = False
    ctl.run(2.0)
    assert not power.Status and not axis.db.Statusword.Simulation
    assert axis.db.ActualPosition == pytest.approx(0.0, abs=0.01)


def test_s7t_simulation_mode_speed_axis():
    """S7-Technology V4.1 §6.2.1 Mode table: a real speed-controlled axis takes Mode 4 too: its actual
    velocity is the setpoint velocity, the drive does not turn."""
    ctl, axis, power, _ = _sim(technology=0)
    mv = MC_MoveVelocity()
    ctl.program(lambda: mv(Axis=axis, Execute=True, Velocity=30.0))
    ctl.run_until(lambda: mv.InVelocity, 3.0)
    ctl.run(0.1)
    assert axis.db.ActualVelocity == pytest.approx(30.0, abs=1e-6) and axis.db.Statusword.Simulation
    assert axis.drive.mechanical_position() == pytest.approx(5.0, abs=1e-9)


def test_s7t_simulation_mode_stays_after_an_error_and_mc_reset():
    """S7-Technology V4.1 §6.2.1 (Mode is taken at the rising edge of Enable; an axis disabled by an error is
    enabled again by MC_Reset while Enable stays TRUE): re-enabled after MC_Reset the axis is simulated again,
    the drive is not enabled."""
    from plcmotion.s7t import MC_Reset
    ctl, axis, power, _ = _sim()
    axis.inject_fault("drive")
    ctl.run(0.2)
    assert not power.Status and not axis.db.Statusword.Simulation
    axis.clear_fault("drive")
    reset = MC_Reset()
    ctl.program(lambda: reset(Axis=axis, Execute=True))
    ctl.run(0.5)
    assert power.Status and axis.db.Statusword.Simulation and not axis.db.Statusword.DriveEnabled
