"""Holding brake control of the Pilz motion core (Pilz V6.5 §1.2.4 "the brake is released", §1.2.6 / §1.6.6
"engage brake at the end", I42 wait time, F00 brake control)."""
from __future__ import annotations

from ._core import PROFILE, make_axis, start

BRAKE = {"F00": 1, "BrakeOutput": "Q0.0", "I42": 0.1, "I87": 0.0}


def test_pilz_brake_released_and_engaged_after_wait_time():
    """Pilz V6.5 §1.2.4 / §1.2.6: a start from standstill releases the brake; with I410 it engages I42 after
    Done (Done is reported before the brake engages)."""
    ctl, ax = make_axis(BRAKE, referenced=False)
    assert not ctl.outputs["Q0.0"]                 # applied
    start(ax, 2, PROFILE, I403=20.0, I410=True)
    assert ctl.outputs["Q0.0"]                     # released at the start
    ctl.run_until(lambda: ax.status.I92, timeout=2.0)
    t_done = ctl.time
    assert ctl.outputs["Q0.0"]
    ctl.run_until(lambda: not ctl.outputs["Q0.0"], timeout=1.0)
    assert abs(ctl.time - t_done - 0.1) <= 0.0015


def test_pilz_brake_new_command_within_wait_time():
    """Pilz V6.5 §1.2.6: a command started within I42 moves the axis without engaging the brake."""
    ctl, ax = make_axis(BRAKE)
    start(ax, 1, PROFILE, I403=20.0, I410=True)
    ctl.run_until(lambda: ax.status.I92, timeout=2.0)
    ctl.run(0.05)
    start(ax, 1, PROFILE, I403=40.0, I410=False)
    seen = []
    for _ in range(500):
        ctl.step()
        seen.append(ctl.outputs["Q0.0"])
    assert all(seen)


def test_pilz_brake_without_brake_control():
    """Pilz V6.5 §1.2.4 "prerequisite: F00 = 1": without brake control the output never changes."""
    ctl, ax = make_axis({**BRAKE, "F00": 0})
    start(ax, 1, PROFILE, I403=20.0, I410=True)
    ctl.run(1.0)
    assert not ctl.outputs["Q0.0"]


def test_pilz_brake_stop_engages():
    """Pilz V6.5 §1.6.6: MC_Stop with I410 engages the brake I42 after standstill."""
    ctl, ax = make_axis(BRAKE)
    start(ax, 4, PROFILE, I404=50.0)
    ctl.run(0.2)
    start(ax, 5, I406=1000.0, I407=100000.0, I410=True)
    ctl.run(1.0)
    assert ax.status.I92 and not ctl.outputs["Q0.0"]
