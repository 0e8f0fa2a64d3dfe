"""The base and the superimposing coordinate system of an axis and their transfer (S7-Technology V4.1 §3.1.7,
§6.2.2 "Notes on Mode = 7", TypeOfAxis.DecodingConfig.transferSuperimposed; system variables 4030
superimposedmotion.position and 4040 basicmotion.position of §9.4, read with MC_ReadSysParameter §6.7.4).

TRANSFER_STANDSTILL (0, default) takes the superimposed coordinate into the base system when the axis stands,
when a command overrides the basic motion, in following mode (and without enable) and at a restart;
TRANSFER_MERGE (1) not at standstill; TRANSFER_RESET (2) neither at standstill nor at an override.  The total
position never moves by a transfer.  Expected values: the distances commanded.
"""
from __future__ import annotations

import pytest

from plcmotion.s7t import (MC_Home, MC_MoveAbsolute, MC_MoveRelative, MC_MoveSuperImposed, MC_Power,
                           MC_ReadSysParameter)

from _s7t_rig import VIRTUAL, controller

TRANSFER = "TypeOfAxis.DecodingConfig.transferSuperimposed"
STANDSTILL, MERGE, RESET = 0, 1, 2
DYN = dict(Acceleration=100.0, Deceleration=100.0, Jerk=0.0)


def _read(axis, number: int) -> float:
    fb = MC_ReadSysParameter()
    fb(Axis=axis, Execute=True, ParameterNumber=number)
    assert fb.Done, fb
    return fb.Value


def _coordinates(axis) -> tuple[float, float, float]:
    """(superimposed 4030, basic 4040, total = parameter 1 commandposition)."""
    return _read(axis, 4030), _read(axis, 4040), _read(axis, 1)


class _Power:
    """MC_Power in OB1 with the Enable of ``on``."""

    def __init__(self, axis):
        self.fb, self.on = MC_Power(), True
        axis.ctl.program(lambda: self.fb(Axis=axis, Enable=self.on))


def _axis(transfer: int):
    ctl = controller()
    axis = ctl.add_positioning_axis("Axis1", {**VIRTUAL, TRANSFER: transfer})
    power = _Power(axis)
    ctl.run(0.1)
    assert power.fb.Status
    return ctl, axis, power


def _moved_with_superimposed(transfer: int):
    """MC_MoveAbsolute to 100 at 20 (5 s) and, 0.5 s later, MC_MoveSuperImposed by 20 at 10 more (done after
    about 2.6 s, while the positioning still runs)."""
    ctl, axis, power = _axis(transfer)
    move, sup = MC_MoveAbsolute(), MC_MoveSuperImposed()
    move(Axis=axis, Execute=True, Position=100.0, Velocity=20.0, **DYN)
    ctl.run(0.5)
    sup(Axis=axis, Execute=True, Distance=20.0, VelocityDiff=10.0, **DYN)
    ctl.run_until(lambda: sup(Execute=True).Done, 5.0)
    ctl.run(0.1)
    assert move(Execute=True).Busy
    sup_p, basic, total = _coordinates(axis)
    assert sup_p == pytest.approx(20.0) and basic == pytest.approx(total - 20.0)   # moving: no transfer yet
    ctl.run_until(lambda: move(Execute=True).Done, 10.0)
    ctl.run(0.1)
    return ctl, axis, power


@pytest.mark.parametrize("transfer, superimposed", [(STANDSTILL, 0.0), (MERGE, 20.0), (RESET, 20.0)])
def test_s7t_coordinates_transfer_at_standstill(transfer, superimposed):
    """S7-Technology V4.1 §6.2.2 Mode 7 notes: at standstill only TRANSFER_STANDSTILL takes the superimposed 20
    into the base system; the total stays 120."""
    _ctl, axis, _power = _moved_with_superimposed(transfer)
    sup_p, basic, total = _coordinates(axis)
    assert total == pytest.approx(120.0)
    assert sup_p == pytest.approx(superimposed) and basic == pytest.approx(120.0 - superimposed)


@pytest.mark.parametrize("transfer, superimposed", [(MERGE, 0.0), (RESET, 20.0)])
def test_s7t_coordinates_transfer_at_override(transfer, superimposed):
    """S7-Technology V4.1 §6.2.2 Mode 7 notes: a new basic command (MC_MoveRelative by 10) takes the
    superimposed coordinate over with TRANSFER_MERGE, not with TRANSFER_RESET; the axis ends at 130."""
    ctl, axis, _power = _moved_with_superimposed(transfer)
    rel = MC_MoveRelative()
    rel(Axis=axis, Execute=True, Distance=10.0, Velocity=20.0, **DYN)
    sup_p, basic, total = _coordinates(axis)
    assert sup_p == pytest.approx(superimposed) and basic == pytest.approx(total - superimposed)
    ctl.run_until(lambda: rel(Execute=True).Done, 5.0)
    sup_p, basic, total = _coordinates(axis)
    assert total == pytest.approx(130.0)
    assert sup_p == pytest.approx(superimposed) and basic == pytest.approx(130.0 - superimposed)


def test_s7t_coordinates_transfer_reset_when_the_enable_is_removed():
    """S7-Technology V4.1 §6.2.2 example "Mode 7" with TRANSFER_RESET: the superimposed coordinate goes over
    only when the enable signals are cancelled (the axis follows its actual value: following mode)."""
    ctl, axis, power = _moved_with_superimposed(RESET)
    assert _read(axis, 4030) == pytest.approx(20.0)
    power.on = False
    ctl.run(0.1)
    assert axis.state == "disabled" and not power.fb.Status
    sup_p, basic, total = _coordinates(axis)
    assert sup_p == 0.0 and basic == pytest.approx(120.0) and total == pytest.approx(120.0)


@pytest.mark.parametrize("transfer, superimposed", [(STANDSTILL, 0.0), (MERGE, -5.0)])
def test_s7t_coordinates_mode7_correction(transfer, superimposed):
    """S7-Technology V4.1 §6.2.2 Mode 7 (new setpoint = superimposing position - Position): on a standing axis
    the correction by 5 is in the superimposing system; TRANSFER_STANDSTILL takes it over at once (the axis
    stands), TRANSFER_MERGE keeps it until the next basic command."""
    ctl, axis, _power = _axis(transfer)
    home = MC_Home()
    home(Axis=axis, Execute=True, Mode=7, Position=5.0)
    assert home.Done
    sup_p, basic, total = _coordinates(axis)
    assert total == pytest.approx(-5.0)
    assert sup_p == pytest.approx(superimposed) and basic == pytest.approx(-5.0 - superimposed)
    rel = MC_MoveRelative()
    rel(Axis=axis, Execute=True, Distance=1.0, Velocity=20.0, **DYN)
    ctl.run_until(lambda: rel(Execute=True).Done, 5.0)
    assert _coordinates(axis) == (0.0, pytest.approx(-4.0), pytest.approx(-4.0))


def test_s7t_coordinates_a_second_superimposed_keeps_the_first():
    """S7-Technology V4.1 §6.2.9 with TRANSFER_MERGE: a new MC_MoveSuperImposed aborts the first (5 of 20 done
    at standstill); the superimposing system holds both parts (5 + 10 = 15), the base system nothing."""
    ctl, axis, _power = _axis(MERGE)
    s1, s2 = MC_MoveSuperImposed(), MC_MoveSuperImposed()
    s1(Axis=axis, Execute=True, Distance=20.0, VelocityDiff=10.0, Acceleration=1e4, Deceleration=1e4, Jerk=0.0)
    ctl.run_until(lambda: _read(axis, 4030) >= 5.0, 2.0)
    s2(Axis=axis, Execute=True, Distance=10.0, VelocityDiff=10.0, **DYN)
    first = _read(axis, 4030)
    ctl.run_until(lambda: s2(Execute=True).Done, 5.0)
    ctl.run(0.1)
    assert s1(Execute=True).CommandAborted
    sup_p, basic, total = _coordinates(axis)
    assert sup_p == pytest.approx(first + 10.0) and basic == pytest.approx(0.0) and total == pytest.approx(sup_p)
