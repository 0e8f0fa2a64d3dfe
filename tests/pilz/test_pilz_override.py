"""Velocity override I230 and the limit flags of the Pilz motion core (Pilz V6.5 §1.2.3, §1.2.5, §1.5.5,
§1.6.5, §1.9.3)."""
from __future__ import annotations

import pytest

from ._core import PROFILE, make_axis, start


def _peak(ctl, ax, seconds):
    peak = 0.0
    for _ in range(int(seconds / 0.001)):
        ctl.step()
        peak = max(peak, abs(ax.status.E07))
    return peak


def test_pilz_override_scales_velocity():
    """Pilz V6.5 §1.2.5: the override I230 scales the velocity of a positioning."""
    ctl, ax = make_axis()
    ax.registers.I230 = 50.0
    start(ax, 1, PROFILE, I403=200.0)
    assert _peak(ctl, ax, 3.0) == pytest.approx(100.0)
    assert ax.status.I96 == pytest.approx(200.0)


def test_pilz_override_zero_holds_and_resumes():
    """Pilz V6.5 §1.2.5: with I230 = 0 the axis stays stationary while the command stays active; a non-zero
    value lets it go on to the target."""
    ctl, ax = make_axis()
    start(ax, 1, PROFILE, I403=300.0)
    ctl.run(0.3)
    ax.registers.I230 = 0.0
    ctl.run(0.5)
    held = ax.status.I96
    ctl.run(0.3)
    assert ax.status.I96 == held and ax.status.E07 == 0.0 and ax.status.I89 == 3 and not ax.status.I92
    ax.registers.I230 = 100.0
    ctl.run(2.0)
    assert ax.status.I96 == pytest.approx(300.0) and ax.status.I92


def test_pilz_override_above_100_clipped():
    """Pilz V6.5 §1.2.3: an override above 100 % never lifts the velocity above I10; the clipping sets I193."""
    ctl, ax = make_axis({"I10": 300.0})
    ax.registers.I230 = 200.0
    start(ax, 4, PROFILE, I404=250.0)
    assert ax.status.I193                               # from the start: the override set before it
    assert _peak(ctl, ax, 1.0) == pytest.approx(300.0)
    assert ax.status.I193 and not ax.status.I190


def test_pilz_override_velocity_limit_flags():
    """Pilz V6.5 §1.2.3: a set velocity above I10 is limited (I190); acceleration or jerk above I11 / I16 is
    limited (I191)."""
    ctl, ax = make_axis({"I10": 300.0, "I11": 1000.0, "I16": 50000.0})
    start(ax, 4, PROFILE, I404=400.0, I405=5000.0)
    assert _peak(ctl, ax, 1.0) == pytest.approx(300.0)
    assert ax.status.I190 and ax.status.I191
    start(ax, 4, PROFILE, I404=100.0, I405=500.0, I406=500.0, I407=1000.0)
    ctl.step()
    assert not ax.status.I190 and not ax.status.I191


def test_pilz_override_ignored_by_stop():
    """Pilz V6.5 §1.6.5: MC_Stop does not apply the override: it stops with its deceleration also at I230 = 50."""
    ctl, ax = make_axis()
    start(ax, 4, PROFILE, I404=100.0)
    ctl.run(0.5)
    ax.registers.I230 = 50.0
    ctl.run(0.5)
    assert ax.status.E07 == pytest.approx(50.0)
    start(ax, 5, I406=1000.0, I407=100000.0)
    ctl.run(0.02)
    # 20 cycles after the edge: 10 ms of jerk 1e5 up to 1000, then 10 ms at 1000 -> 5 + 10 = 15 (not 7.5)
    assert 50.0 - ax.status.E07 == pytest.approx(15.0, abs=1e-6)


def test_pilz_override_applies_to_move_velocity():
    """Pilz V6.5 §1.5.5: the override is applied to MC_MoveVelocity, read every cycle."""
    ctl, ax = make_axis()
    start(ax, 4, PROFILE, I404=100.0)
    ctl.run(0.5)
    ax.registers.I230 = 25.0
    ctl.run(0.5)
    assert ax.status.E07 == pytest.approx(25.0)
