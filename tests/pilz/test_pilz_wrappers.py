"""The PLCopen-style function blocks over the Pilz command register (plcmotion.pilz; Pilz V6.5 §1 status
tables, mapped as docs/pilz/index.md describes)."""
from __future__ import annotations

import math

import pytest

from plcmotion import Controller
from plcmotion.pilz import (INPUT_REFUSED, NOT_A_DRIVE_AXIS, Cause, MC_Halt, MC_Home, MC_MoveAbsolute,
                            MC_MoveVelocity, MC_Stop)

from ._core import make_axis

DYN = {"Acceleration": 2000.0, "Deceleration": 2000.0, "Jerk": 100000.0}


def _call(ctl, fbs, cycles):
    for _ in range(cycles):
        for fb, kw in fbs:
            fb(**kw)
        ctl.step()


def test_pilz_wrappers_move_absolute_done():
    """Pilz V6.5 Tab. 5: the block's Done is I92 of its command; Busy until then; Done stays while Execute."""
    ctl, ax = make_axis({"I87": 0.0})
    mv = MC_MoveAbsolute(Axis=ax, Position=50.0, Velocity=200.0, **DYN)
    _call(ctl, [(mv, {"Execute": True})], 3)
    assert mv.Busy and mv.Active and not mv.Done
    _call(ctl, [(mv, {"Execute": True})], 1000)
    assert mv.Done and not mv.Busy and ax.status.I96 == pytest.approx(50.0)
    _call(ctl, [(mv, {"Execute": False})], 1)
    assert not mv.Done                               # latched only while Execute is TRUE
    quick = MC_MoveAbsolute(Axis=ax, Position=80.0, Velocity=200.0, **DYN)
    _call(ctl, [(quick, {"Execute": True})], 2)
    _call(ctl, [(quick, {"Execute": False})], 5)     # Execute falls before the end: Done for one call
    seen = []
    for _ in range(500):
        quick(Execute=False)
        seen.append(quick.Done)
        ctl.step()
    assert seen.count(True) == 1


def test_pilz_wrappers_aborted_by_next_command():
    """Pilz V6.5 Fig. 2: a second command replaces the first: the first block shows CommandAborted."""
    ctl, ax = make_axis()
    first = MC_MoveAbsolute(Axis=ax, Position=500.0, Velocity=200.0, **DYN)
    second = MC_MoveAbsolute(Axis=ax, Position=10.0, Velocity=200.0, **DYN)
    _call(ctl, [(first, {"Execute": True})], 100)
    _call(ctl, [(first, {"Execute": True}), (second, {"Execute": True})], 5)
    assert first.CommandAborted and not first.Busy and second.Busy


def test_pilz_wrappers_error_id_is_i90():
    """Pilz V6.5 §1.2.2: a denial ends the block with Error and ErrorID = I90."""
    ctl, ax = make_axis()
    mv = MC_MoveAbsolute(Axis=ax, Position=50.0, Velocity=0.0, **DYN)
    _call(ctl, [(mv, {"Execute": True})], 5)
    assert mv.Error and mv.ErrorID == Cause.ZERO_DYNAMICS and not mv.Busy


def test_pilz_wrappers_bad_inputs():
    """A wrong Axis (ErrorID 100) or a set value the register refuses (101) end the block with Error, without
    an exception and without touching the register."""
    ctl, ax = make_axis()
    other = Controller().add_positioning_axis("S7")
    bad_axis = MC_MoveAbsolute(Axis=other, Position=1.0, Velocity=1.0, **DYN)
    bad_value = MC_MoveAbsolute(Axis=ax, Position=math.nan, Velocity=1.0, **DYN)
    _call(ctl, [(bad_axis, {"Execute": True}), (bad_value, {"Execute": True})], 3)
    assert bad_axis.Error and bad_axis.ErrorID == NOT_A_DRIVE_AXIS
    assert bad_value.Error and bad_value.ErrorID == INPUT_REFUSED
    assert ax.status.I96 == 0.0 and ax.registers.I403 == 0.0


def test_pilz_wrappers_velocity_stop_halt_home():
    """Pilz V6.5 §1.5.7, §1.6.4, §1.12.4: InVelocity = I92 of MC_MoveVelocity; MC_Stop holds the axis while its
    Execute is TRUE (a MC_MoveVelocity then is denied, I90 = 10); MC_Halt ends Done at standstill."""
    ctl, ax = make_axis()
    vel = MC_MoveVelocity(Axis=ax, Velocity=100.0, **DYN)
    stop = MC_Stop(Axis=ax, Deceleration=1000.0, Jerk=100000.0)
    _call(ctl, [(vel, {"Execute": True})], 300)
    assert vel.InVelocity and vel.Busy
    _call(ctl, [(vel, {"Execute": True}), (stop, {"Execute": True})], 400)
    assert vel.CommandAborted and stop.Done and ax.status.I89 == 6
    again = MC_MoveVelocity(Axis=ax, Velocity=50.0, **DYN)
    _call(ctl, [(stop, {"Execute": True}), (again, {"Execute": True})], 5)
    # while MC_Stop's Execute is TRUE it holds the register (I402 high): the new block waits, Busy
    assert ax.status.E07 == 0.0 and again.Busy and ax.status.I89 == 6
    halt = MC_Halt(Axis=ax, Deceleration=1000.0, Jerk=100000.0)
    _call(ctl, [(stop, {"Execute": False}), (again, {"Execute": True})], 300)
    assert again.InVelocity
    _call(ctl, [(again, {"Execute": True}), (halt, {"Execute": True})], 300)
    assert halt.Done and ax.status.E07 == 0.0
    home = MC_Home(Axis=ax)
    _call(ctl, [(halt, {"Execute": False}), (home, {"Execute": True})], 5)
    assert home.Done


def test_pilz_wrappers_in_velocity_follows_done():
    """Pilz V6.5 Tab. 15: I92 of MC_MoveVelocity = I85 and I183 (E07 = I404); InVelocity mirrors it while the
    command runs - the override I230 = 50 takes it away, 100 brings it back; Busy stays TRUE."""
    ctl, ax = make_axis({"C40": 5.0})
    vel = MC_MoveVelocity(Axis=ax, Velocity=100.0, Acceleration=2000.0, Deceleration=2000.0, Jerk=100000.0)
    ctl.program(lambda: vel(Execute=True))
    ctl.run(0.3)
    assert vel.InVelocity and vel.Busy
    ax.registers.I230 = 50.0
    ctl.run(0.3)
    assert not vel.InVelocity and vel.Busy and not vel.Error
    ax.registers.I230 = 100.0
    ctl.run(0.3)
    assert vel.InVelocity and vel.Busy
