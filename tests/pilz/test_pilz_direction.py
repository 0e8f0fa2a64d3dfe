"""Movement direction I411 of MC_MoveAbsolute on an endless axis (Pilz V6.5 §1.2.4)."""
from __future__ import annotations

import pytest

from ._core import PROFILE, make_axis, start

ENDLESS = {"I00": 1, "I01": 360.0, "I22": 0.5, "I10": 1000.0}


def _travel(ctl, ax, seconds=3.0):
    p0 = ax.status.I96
    lo = hi = 0.0
    for _ in range(int(seconds / 0.001)):
        ctl.step()
        lo, hi = min(lo, ax.status.E07), max(hi, ax.status.E07)
    return ax.status.I96 - p0, lo, hi


# (I411, start position, target, expected signed travel)
STANDSTILL = [
    (0, 0.0, 270.0, -90.0), (3, 0.0, 270.0, -90.0), (0, 0.0, 90.0, 90.0),
    (1, 0.0, 270.0, 270.0), (1, 100.0, 90.0, 350.0), (2, 0.0, 90.0, -270.0), (2, 90.0, 100.0, -350.0),
    (1, 0.0, 359.7, -0.3), (2, 0.0, 0.3, 0.3),           # within I22: the shortest way
]


@pytest.mark.parametrize("i411,here,target,travel", STANDSTILL)
def test_pilz_direction_from_standstill(i411, here, target, travel):
    """Pilz V6.5 §1.2.4 "Behavior when positioning from a standstill": 0 / 3 the shortest way, 1 positive and 2
    negative unless the target lies within the position window I22 (then the shortest way)."""
    ctl, ax = make_axis(ENDLESS)
    if here:
        start(ax, 1, PROFILE, I403=here, I411=1)
        ctl.run(2.0)
    start(ax, 1, PROFILE, I403=target, I411=i411)
    moved, lo, hi = _travel(ctl, ax)
    assert moved == pytest.approx(travel, abs=1e-6)
    assert (lo >= 0.0) if travel > 0 else (hi <= 0.0)


@pytest.mark.parametrize("i411", [0, 3])
def test_pilz_direction_from_motion_keeps_direction(i411):
    """Pilz V6.5 §1.2.4 "from an ongoing movement": 0 / 3 keep the current direction - a target just behind the
    axis is reached by going on around, without reversing."""
    ctl, ax = make_axis(ENDLESS)
    start(ax, 4, PROFILE, I404=100.0)
    ctl.run(0.5)
    here = ax.status.I96 % 360.0
    start(ax, 1, PROFILE, I403=(here - 20.0) % 360.0, I411=i411, I404=100.0)
    moved, lo, _hi = _travel(ctl, ax, 6.0)
    assert lo >= 0.0 and moved > 300.0
    assert ax.status.I96 % 360.0 == pytest.approx((here - 20.0) % 360.0, abs=1e-6)


def test_pilz_direction_from_motion_reverses_when_required():
    """Pilz V6.5 §1.2.4: 2 "only negative" while moving positive: brake and reverse, then approach negatively."""
    ctl, ax = make_axis(ENDLESS)
    start(ax, 4, PROFILE, I404=100.0)
    ctl.run(0.5)
    here = ax.status.I96
    start(ax, 1, PROFILE, I403=(here + 40.0) % 360.0, I411=2, I404=100.0)
    moved, lo, hi = _travel(ctl, ax, 8.0)
    assert hi > 0.0 and lo < 0.0 and moved < 0.0
    assert ax.status.I96 % 360.0 == pytest.approx((here + 40.0) % 360.0, abs=1e-6)


def test_pilz_direction_from_motion_several_turns():
    """Pilz V6.5 §1.2.4: several revolutions may be used to brake at the set position from motion."""
    ctl, ax = make_axis({**ENDLESS, "I10": 5000.0})
    start(ax, 4, PROFILE, I404=3000.0, I405=20000.0, I406=20000.0, I407=1e6)
    ctl.run(0.5)
    here = ax.status.I96
    start(ax, 1, PROFILE, I403=(here + 10.0) % 360.0, I411=1, I404=3000.0, I406=2000.0, I407=1e6)
    moved, lo, _hi = _travel(ctl, ax, 6.0)
    assert lo >= 0.0 and moved > 360.0
    assert ax.status.I96 % 360.0 == pytest.approx((here + 10.0) % 360.0, abs=1e-6)
