"""Departures from the manual found by the review of issue 11 (S7-Technology V4.1 §3.1.2, §6.2.1, §6.2.2,
§6.2.3, §6.2.9, §7.9): expected values from the manual's rules and the physics of the configured maxima."""
from __future__ import annotations

import pytest

from plcmotion import s7t
from plcmotion.s7t import (MC_Home, MC_MoveRelative, MC_MoveSuperImposed, MC_MoveVelocity, MC_Power,
                           MC_Stop, MC_WriteParameter)

from _s7t_rig import VIRTUAL, controller, enabled

REAL = {"DBNumber": 10}                        # a real positioning axis, incremental encoder, not homed


def _switchable(params: dict):
    """A controller with one axis and an MC_Power whose Enable and Mode the test sets (``state``)."""
    ctl = controller()
    axis = ctl.add_positioning_axis("A", params)
    power, state = MC_Power(), {"Enable": True, "Mode": 0}

    @ctl.program
    def ob1() -> None:
        power(Axis=axis, Enable=state["Enable"], Mode=state["Mode"])
    ctl.run(0.1)
    assert power.Status
    return ctl, axis, power, state


def _relative(ctl, axis, distance: float) -> None:
    move = MC_MoveRelative()
    move(Axis=axis, Execute=True, Distance=distance)
    ctl.run_until(lambda: move(Execute=True).Done, 5.0)


@pytest.mark.parametrize("homed_at", [None, 500.0])
def test_s7t_simulation_mode_keeps_the_position(homed_at):
    """S7-Technology V4.1 §3.1.2, §6.2.1 Mode 4: simulation sets the actual values equal to the setpoints
    without moving the axis.  Entering it from a disabled axis starts at the encoder's actual value (homed
    or not: nothing is lost by disable/enable); a motion in simulation moves the actual value only, and
    after Enable = FALSE the actual value is the machine's again."""
    ctl, axis, power, state = _switchable(REAL)
    db = axis.db
    if homed_at is not None:
        home = MC_Home()
        home(Axis=axis, Execute=True, Mode=3, Position=homed_at)
        assert home.Done
    base = homed_at or 0.0
    _relative(ctl, axis, 30.0)
    machine = db.ActualPosition
    assert machine == pytest.approx(base + 30.0, abs=0.1)
    state["Enable"] = False
    ctl.run(0.1)
    state["Enable"], state["Mode"] = True, 4
    ctl.run(0.1)
    assert power.Status and db.Statusword.Simulation
    assert db.ActualPosition == pytest.approx(machine, abs=1e-3)
    assert db.CommandPosition == pytest.approx(machine, abs=1e-3)
    _relative(ctl, axis, 10.0)
    assert db.ActualPosition == pytest.approx(db.CommandPosition, abs=1e-9)      # following error 0
    assert db.ActualPosition == pytest.approx(machine + 10.0, abs=1e-3)
    state["Enable"] = False
    ctl.run(0.1)
    assert not db.Statusword.Simulation
    assert db.ActualPosition == pytest.approx(machine, abs=1e-3)     # the machine never moved
    state["Enable"], state["Mode"] = True, 0
    ctl.run(0.1)
    assert power.Status and db.ActualPosition == pytest.approx(machine, abs=1e-3)


@pytest.mark.parametrize("diff, peak, warned", [(30.0, 60.0, True), (5.0, 55.0, False)])
def test_s7t_superimposed_sum_stays_within_the_maximum_velocity(diff, peak, warned):
    """S7-Technology V4.1 §6.2.9: the superimposed dynamics add to the basic motion's; a sum above the
    configured maximum velocity (60) is limited to it with warning 16#0021 in the technology DB.  Basic
    MC_MoveVelocity 50 plus VelocityDiff 30 peaks at 60; plus 5 at 55 without a warning.  The superimposed
    distance (20) is added in full either way."""
    ctl, axis, _ = enabled({**VIRTUAL, "TypeOfAxis.MaxVelocity.maximum": 60.0}, run=0.1)
    db = axis.db
    move = MC_MoveVelocity()
    move(Axis=axis, Execute=True, Velocity=50.0)
    ctl.run_until(lambda: move(Execute=True).InVelocity, 2.0)
    assert db.ErrorID == 0
    sup = MC_MoveSuperImposed()
    sup(Axis=axis, Execute=True, Distance=20.0, VelocityDiff=diff)
    t0, p0, fastest = ctl.time, db.CommandPosition, 0.0
    while not sup(Execute=True).Done:
        ctl.step()
        fastest = max(fastest, db.CommandVelocity)
        assert ctl.time - t0 < 5.0
    assert fastest == pytest.approx(peak, abs=1e-6)
    assert db.ErrorID == (0x0021 if warned else 0)
    assert db.CommandPosition - p0 == pytest.approx(50.0 * (ctl.time - t0) + 20.0, abs=0.5)


def _write(axis, number: int, **value) -> int:
    write = MC_WriteParameter()
    write(Axis=axis, Execute=True, ParameterNumber=number, Index=1, **value)
    assert write.Done, write
    return write.ErrorID


@pytest.mark.parametrize("state", ["restart pending", "collecting changes"])
def test_s7t_home_refused_while_parameter_changes_wait(state):
    """S7-Technology V4.1 §6.2.2 ErrorID 16#8045: MC_Home is refused while a parameter change waits for a
    restart (MC_WriteParameter of a "Restart" parameter, 8 maximum velocity: 16#0020) and while parameter
    4001 is COLLECT_CHANGED_CONFIG_DATA (82); with 4001 back at ACTIVATE_CHANGED_CONFIG_DATA (81) it homes."""
    ctl, axis, _ = enabled({**REAL, "TypeOfAxis.Homing.referencingNecessary": 0}, run=0.1)
    if state == "restart pending":
        assert _write(axis, 8, Value=500.0) == 0x0020
        ctl.run(0.02)                              # the technology DB shows it at its next update
        assert axis.db.Statusword.RequestRestart
    else:
        assert _write(axis, 4001, ValueDInt=82) == 0
    home = MC_Home()
    home(Axis=axis, Execute=True, Mode=3, Position=1.0)
    assert home.Error and home.ErrorID == 0x8045 and not home.Done
    assert not axis.db.Statusword.HomingDone
    if state == "collecting changes":
        assert _write(axis, 4001, ValueDInt=81) == 0
        home = MC_Home()
        home(Axis=axis, Execute=True, Mode=3, Position=1.0)
        ctl.run(0.02)
        assert home.Done and axis.db.ActualPosition == pytest.approx(1.0, abs=1e-6)


def test_s7t_station_life_list_shows_the_drives_from_the_start():
    """S7-Technology V4.1 §7.9: StationLifeList has a 1 for every station on DP(DRIVE) that is available -
    the drives of the real axes in cyclic exchange, before any DP instruction is called; a virtual axis has
    no station."""
    ctl = controller()
    ctl.add_positioning_axis("V", {**VIRTUAL, "DBNumber": 12})
    real = [ctl.add_positioning_axis("A", {"DBNumber": 10})]
    power = [MC_Power() for _ in real]

    @ctl.program
    def ob1() -> None:
        for p, axis in zip(power, real):
            p(Axis=axis, Enable=True)
    ctl.run(0.1)
    assert all(p.Status for p in power) and all(a.db.Statusword.CyclicInterface for a in real)
    assert sum(s7t.device(ctl).mcdevice.StationLifeList) == 1


@pytest.mark.parametrize("deceleration, stop_time, warning", [
    (1e6, 0.1, 0x0021),          # cut to the maximum 1000: 100 / 1000 s, warning
    (2e12, 0.1, 0),              # above +1E12: the maximum deceleration, as the manual asks - no warning
    (500.0, 0.2, 0),             # within the maximum: 100 / 500 s
])
def test_s7t_stop_dynamics_above_the_maximum_warn(deceleration, stop_time, warning):
    """S7-Technology V4.1 §6.2.3: MC_Stop with a Deceleration above the configured maximum
    (TypeOfAxis.MaxAcceleration.maximum 1000) stops with the maximum and gives warning 16#0021 (ErrorID,
    Error FALSE; also in the technology DB); above +1E12 it is the documented "maximum deceleration"."""
    ctl, axis, _ = enabled({**VIRTUAL, "TypeOfAxis.MaxAcceleration.maximum": 1000.0,
                            "userdefaultdynamics.positiveaccel": 1000.0,
                            "userdefaultdynamics.negativeaccel": 1000.0}, run=0.1)
    move = MC_MoveVelocity()
    move(Axis=axis, Execute=True, Velocity=100.0, Jerk=0.0)
    ctl.run_until(lambda: move(Execute=True).InVelocity, 2.0)
    stop = MC_Stop()
    stop(Axis=axis, Execute=True, Deceleration=deceleration, Jerk=0.0)
    assert not stop.Error and stop.ErrorID == warning
    t0 = ctl.time
    ctl.run_until(lambda: axis.db.CommandVelocity == 0.0, 2.0)
    assert ctl.time - t0 == pytest.approx(stop_time, abs=0.01)
    assert axis.db.ErrorID == warning and not axis.db.Statusword.Error
    stop(Execute=False)
    assert stop.Done and stop.ErrorID == warning
