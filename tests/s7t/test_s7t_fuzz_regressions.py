"""Defects the S7-Technology fuzz campaign found (``python -m tests.fuzz --dialect S7-Technology``), each
as the manual's expectation; the seed of the episode that found it is in the docstring."""
from __future__ import annotations

from plcmotion.s7t import MC_MoveVelocity, MC_Power, MC_Reset, MC_Stop

import pytest
from _s7t_rig import VIRTUAL, controller


def _axis(ctl):
    axis = ctl.add_positioning_axis("Axis1", {**VIRTUAL, "userdefaultdynamics.stoptime": 1.0})
    return axis, MC_Power(Axis=axis, StopMode=2)        # TimeStop: disabling takes a while


def test_s7t_stop_accepted_while_the_axis_is_disabled_by_mc_power():
    """S7-Technology V4.1 §6.2.3 (MC_Stop ErrorIDs: no 8040): MC_Stop locks the axis whatever MC_Power does;
    started while MC_Power's stop program brakes the axis it gives no error, stays Busy while Execute is
    TRUE, keeps the re-enabled axis from moving (8045 at MC_MoveVelocity) and is Done after Execute = FALSE.
    Fuzz seed 6 (--dialect S7-Technology)."""
    ctl = controller()
    axis, power = _axis(ctl)
    move, stop = MC_MoveVelocity(), MC_Stop()
    power(Enable=True)
    ctl.run(0.1)
    move(Axis=axis, Execute=True, Velocity=50.0)
    ctl.run(0.5)
    power(Enable=False)
    ctl.step()
    assert axis.state == "disabling"
    stop(Axis=axis, Execute=True)
    assert not stop.Error and stop.ErrorID == 0 and stop.Busy
    ctl.run(1.5)
    assert not power(Enable=False).Status
    power(Enable=True)
    ctl.run(0.1)
    move(Execute=False)
    move(Execute=True, Velocity=50.0)
    assert move.Error and move.ErrorID == 0x8045
    assert stop(Execute=True).Busy and not stop.Done
    stop(Execute=False)
    assert stop.Done and not stop.Busy and not stop.Error


def test_s7t_stop_accepted_during_a_restart():
    """S7-Technology V4.1 §6.2.3, §6.7.1: while MC_Reset Restart = TRUE restarts the disabled axis, MC_Stop
    is accepted (its table has no 8045) and its lock holds after the restart.  Fuzz seed 49."""
    ctl = controller()
    axis, power = _axis(ctl)
    reset, stop, move = MC_Reset(), MC_Stop(), MC_MoveVelocity()
    ctl.run(0.05)
    reset(Axis=axis, Execute=True, Restart=True)
    assert reset.Busy
    stop(Axis=axis, Execute=True)
    assert not stop.Error and stop.ErrorID == 0 and stop.Busy
    ctl.run(0.5)
    assert reset(Execute=True).Done
    power(Enable=True)
    ctl.run(0.1)
    assert power(Enable=True).Status
    move(Axis=axis, Execute=True, Velocity=10.0)
    assert move.Error and move.ErrorID == 0x8045


def test_s7t_move_velocity_keeps_its_dynamics_with_active_software_limits():
    """S7-Technology V4.1 §6.2.10 (MC_MoveVelocity's Acceleration) with software limit switches active
    (§4.5.7.3, parameter 4 swlimit.state): far from the limits the axis accelerates at the command's 10 /s²,
    as without limits (defect reported by the parameter-FB branch: the limit guard used the defaults)."""
    from plcmotion.s7t import MC_MoveVelocity, MC_Power
    velocities = []
    for state in (0, 1):
        ctl = controller()
        ax = ctl.add_positioning_axis("A", {"Wizard.Virtual": 1, "TypeOfAxis.Homing.referencingNecessary": 0,
                                            "swlimit.state": state, "swlimit.minusposition": -1.0e6,
                                            "swlimit.plusposition": 1.0e6})
        power, move = MC_Power(), MC_MoveVelocity()
        power(Axis=ax, Enable=True)
        ctl.run_until(lambda: power(Axis=ax, Enable=True).Status, timeout=1.0)
        move(Axis=ax, Execute=True, Velocity=50.0, Acceleration=10.0, Jerk=0.0)
        ctl.run(1.0)
        move(Axis=ax, Execute=True)
        velocities.append(ax.db.CommandVelocity)
    assert velocities[0] == pytest.approx(velocities[1], abs=1e-6)
    assert 8.0 < velocities[1] < 11.5
