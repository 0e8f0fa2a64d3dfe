"""Closed-form positioning without jerk limit at the edge of the float range (issue 8, fuzz seed 454750).

A running axis at 48.87 units/s whose acceleration was written as 1e-300 gets a new positioning whose
target lies (to 2e-14) at its stop point.  The gain of speed such an acceleration allows is below the float
resolution; the planner raised "target behind the stop point" (16#8FFF/16#F002 at the instruction)."""
from __future__ import annotations

import numpy as np

from plcmotion.kernel.profiles import INF, Limits, Planner


def _samples(profile, n=2001):
    ts = np.linspace(profile.segments[0].t, profile.t_end, n)
    return [profile.at(t) for t in ts]


def test_kernel_tiny_acceleration_cruises_and_brakes_onto_the_target():
    p, v = -6.958255661393161, -48.873257968615015
    target = -91.31988089920466
    lim = Limits(velocity=50.30190380482262, acceleration=1e-300, deceleration=14.156883166566857, jerk=INF)
    prof = Planner().position(0.0, p, v, 0.0, target, lim)
    final = prof.final
    assert final.p == target and final.v == 0.0
    values = _samples(prof)
    assert all(abs(s[1]) <= abs(v) * (1 + 1e-12) for s in values)          # never faster than at the start
    assert all(target - 1e-9 <= s[0] <= p + 1e-9 for s in values)        # one direction, never past the target
    # braking at the configured deceleration: 48.87 / 14.157 = 3.45 s
    assert abs(prof.t_end - abs(v) / 14.156883166566857) < 1e-6


def test_kernel_ordinary_trapezoid_is_unchanged():
    """The fallback only replaces what used to raise: a normal trapezoid keeps its three phases."""
    lim = Limits(velocity=100.0, acceleration=1000.0, deceleration=500.0, jerk=INF)
    prof = Planner().position(0.0, 0.0, 0.0, 0.0, 100.0, lim)
    # 0.1 s up (5 units), 0.2 s down (10 units), 85 units at 100/s = 0.85 s
    assert abs(prof.t_end - (0.1 + 0.85 + 0.2)) < 1e-12 and prof.final.p == 100.0
