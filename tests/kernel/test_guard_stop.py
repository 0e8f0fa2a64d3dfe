"""``MotionPlanner.guard_stop``: a stop with a ramp of its own (a family's stop program) kept inside the active
software limit switches like a motion (the project rule: no axis beyond its limits).  Driven on a virtual axis
with a software limit switch at 100, without any instruction."""
from __future__ import annotations

import pytest

from plcmotion import Controller
from plcmotion.kernel.profiles import Planner

PARAMS = {"Wizard": {"Virtual": 1}, "TypeOfAxis.Homing.referencingNecessary": 0,
          "swlimit": {"state": 1, "plusposition": 100.0, "minusposition": -100.0},
          "TypeOfAxis.EmergencyRampGenerator.maxDeceleration": 200.0}


def _axis():
    ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
    return ctl.add_positioning_axis("A", PARAMS)


@pytest.mark.parametrize("p, v, stop_at, side", [
    (90.0, 50.0, 100.0, "max"),        # a 2 s ramp from 50 would end at 140: braked to the switch
    (-90.0, -50.0, -100.0, "min"),
    (40.0, 50.0, 90.0, None),          # the ramp ends at 90 before the switch: unchanged
])
def test_kernel_guard_stop_ends_at_the_switch(p, v, stop_at, side):
    """A linear 2 s ramp from ``v`` at ``p``: it ends at the switch where it would pass it (limit side noted,
    the configured or the emergency deceleration), else it is kept."""
    axis = _axis()
    ramp = Planner.ramp_stop(0.0, p, v, abs(v) / 2.0)
    plan = axis.motion.guard_stop(0.0, p, v, 0.0, ramp)
    assert plan.profile.final.p == pytest.approx(stop_at, abs=1e-9)
    assert plan.profile.final.v == 0.0
    assert plan.limit_side == side
    if side is None:
        assert plan.profile is ramp


def test_kernel_guard_stop_beyond_the_emergency_distance_is_exceeded():
    """0.5 before the switch at 50 (emergency braking needs 50² / 400 = 6.25): the stop passes it; the plan
    says so ("exceeded"), the family reports it (S7-Technology 8015)."""
    axis = _axis()
    plan = axis.motion.guard_stop(0.0, 99.5, 50.0, 0.0, Planner.ramp_stop(0.0, 99.5, 50.0, 25.0))
    assert plan.limit_side == "max" and plan.limit_detail == "exceeded"
    assert plan.profile.final.p == pytest.approx(99.5 + 6.25)
