"""Command modes, positioning bases and the MC_MoveAdditive set position of the Pilz motion core (Pilz V6.5
§1.2.5 Fig. 1/2, §1.3.5 Fig. 5/6, §1.4.5 Fig. 9/10, §1.4.6 Tab. 11, Command Mode I409 Tab. 4)."""
from __future__ import annotations

import pytest

from ._core import PROFILE, make_axis, release, start

SLOW = {**PROFILE, "I404": 500.0}


def _settle(ctl, ax, seconds=2.0):
    ctl.run(seconds)
    return ax.status.I96


@pytest.mark.parametrize("during", [False, True])
def test_pilz_command_modes_absolute_replaces_target(during):
    """Pilz V6.5 §1.2.5 examples 1/2: MC_MoveAbsolute 1000, then MC_MoveAbsolute 2000 with another velocity -
    after arrival or during the travel - both end at 2000."""
    ctl, ax = make_axis({"I10": 1000.0, "I87": 0.0})
    start(ax, 1, SLOW, I403=1000.0)
    ctl.run(3.0 if not during else 1.0)
    assert (ax.status.I96 < 1000.0) == during
    start(ax, 1, SLOW, I403=2000.0, I404=800.0)
    assert _settle(ctl, ax, 3.0) == pytest.approx(2000.0)
    assert ax.status.I92


def test_pilz_command_modes_relative_from_actual():
    """Pilz V6.5 §1.3.5: MC_MoveRelative 1000 twice after arrival ends at 2000; the second issued during the
    travel ends at the actual position at its start + 1000 (the manual's 570 -> 1570)."""
    ctl, ax = make_axis({"I10": 1000.0})
    start(ax, 2, SLOW, I403=1000.0)
    ctl.run(3.0)
    start(ax, 2, SLOW, I403=1000.0)
    assert _settle(ctl, ax, 3.0) == pytest.approx(2000.0)
    ctl2, ax2 = make_axis({"I10": 1000.0})
    start(ax2, 2, SLOW, I403=1000.0)
    ctl2.run_until(lambda: ax2.ctl.bank.act_p[ax2.index] >= 570.0)
    release(ax2)
    start(ax2, 2, SLOW, I403=1000.0, I404=800.0)
    base = ax2.status.I80                       # actual position at the start of the command
    assert 570.0 <= base < 600.0
    assert _settle(ctl2, ax2, 3.0) == pytest.approx(base + 1000.0)


@pytest.mark.parametrize("during", [False, True])
def test_pilz_command_modes_additive_from_set_position(during):
    """Pilz V6.5 §1.4.5: MC_MoveAdditive 1000 twice - after arrival or during the travel - ends at 2000."""
    ctl, ax = make_axis({"I10": 1000.0})
    start(ax, 3, SLOW, I403=1000.0)
    ctl.run(3.0 if not during else 1.0)
    start(ax, 3, SLOW, I403=1000.0, I404=800.0)
    assert _settle(ctl, ax, 3.0) == pytest.approx(2000.0)


# Tab. 11: (start position, first command, interruption, expected end or None: actual position + 200)
TAB_11 = [
    (0.0, (1, 1000.0), None, 1200.0),
    (0.0, (1, 1000.0), "stop", 1200.0),
    (0.0, (1, 1000.0), "enable", None),
    (0.0, (3, 200.0), None, 400.0),
    (0.0, (3, 200.0), "stop", 400.0),
    (0.0, (3, 200.0), "enable", None),
    (9.5, (2, 200.0), None, 409.5),
    (9.5, (2, 200.0), "stop", 409.5),
    (9.5, (2, 200.0), "enable", None),
]


@pytest.mark.parametrize("start_pos,first,interruption,end", TAB_11)
def test_pilz_command_modes_additive_tab11(start_pos, first, interruption, end):
    """Pilz V6.5 §1.4.6 Tab. 11: MC_MoveAdditive 200 after a positioning counts from its set position, also
    when MC_Stop interrupted it; after the enable went off during the travel (the window was never reached)
    from the actual position."""
    ctl, ax = make_axis({"Plant.InitialPosition": start_pos, "I10": 1000.0}, referenced=start_pos == 0.0)
    command, value = first
    start(ax, command, SLOW, I403=value)
    if interruption is None:
        ctl.run(3.0)
    else:
        ctl.run(0.2 if value < 1000 else 1.0)
        if interruption == "stop":
            start(ax, 5, I406=2000.0, I407=100000.0)
            ctl.run(0.5)
            release(ax)
        else:
            ax.enable(False)
            ctl.run(0.5)
            ax.enable(True)
            ctl.run(0.05)
            release(ax)
    here = float(ctl.bank.act_p[ax.index])
    start(ax, 3, SLOW, I403=200.0)
    final = _settle(ctl, ax, 3.0)
    assert final == pytest.approx(end if end is not None else here + 200.0)
    if interruption == "enable":
        assert here < value + start_pos - 1.0          # it did stop on the way


def test_pilz_command_modes_buffered_starts_at_end():
    """Pilz V6.5 Tab. 4 Command Mode I409 = 1: the new command starts when the running one ends; Done (I92)
    of the pair only at the end of the follow-up (Tab. 5)."""
    ctl, ax = make_axis({"I87": 0.0})
    start(ax, 1, SLOW, I403=100.0)
    ctl.run(0.1)
    t1 = start(ax, 1, SLOW, I403=50.0, I409=1)
    peak = 0.0
    for _ in range(3000):
        ctl.step()
        peak = max(peak, ax.status.I96)
        if ax.status.I92:
            break
    assert peak == pytest.approx(100.0)          # the first target is reached before the second starts
    assert ax.status.I96 == pytest.approx(50.0) and ctl.time > t1


def test_pilz_command_modes_abort_takes_over():
    """Pilz V6.5 Fig. 2: Command Mode 0 cancels the running command at once (never reaches its target)."""
    ctl, ax = make_axis()
    start(ax, 1, SLOW, I403=100.0)
    ctl.run(0.1)
    start(ax, 1, SLOW, I403=50.0, I409=0)
    peak = 0.0
    for _ in range(3000):
        ctl.step()
        peak = max(peak, ax.status.I96)
    assert peak < 60.0 and ax.status.I96 == pytest.approx(50.0)


def test_pilz_command_modes_end_velocity_passes_target():
    """Pilz V6.5 §1.2.6: with an end velocity the set position is passed at that velocity (I85 and Done there);
    with a buffered follow-up the axis goes on into it without stopping."""
    ctl, ax = make_axis()
    start(ax, 1, SLOW, I403=100.0, I429=50.0)
    start(ax, 1, SLOW, I403=200.0, I409=1, I429=0.0)
    slowest = 1e9
    for _ in range(1500):
        ctl.step()
        if 90.0 < ax.status.I96 < 110.0:
            slowest = min(slowest, ax.status.E07)
    assert slowest == pytest.approx(50.0, rel=0.02)
    assert ax.status.I96 == pytest.approx(200.0)


@pytest.mark.parametrize("mode", [0, 1])
def test_pilz_command_modes_torque_control(mode):
    """Pilz V6.5 Tab. 31 lists Command Mode I409 for MC_TorqueControl (Drive Based / PROFIdrive J21): with 0 the
    set torque takes over at once (with torque 0 the load coasts past 100); with 1 it waits until the running
    MC_MoveAbsolute has ended at its target - I83 = 2 and I92 = 0 meanwhile - then switches to the set torque
    at once (§1.10 information) with I92 from the second cycle A150 after that (Tab. 32)."""
    ctl, ax = make_axis({"I87": 0.0, "E65": 5.0, "E66": 5.0})
    start(ax, 1, SLOW, I403=100.0)
    ctl.run(0.1)
    start(ax, 9, I428=0.0, I409=mode)
    rows = []
    for _ in range(2000):
        ctl.step()
        rows.append((ctl.time, ax.status.I83, ax.status.I92, ax.status.I96, ax.status.E07))
    peak = max(r[3] for r in rows)
    if mode == 0:
        # torque 0 on a load without friction: it coasts on past the target instead of braking at 100
        assert peak > 101.0 and rows[2][2] and all(r[1] != 2 for r in rows)
        return
    assert peak == pytest.approx(100.0, abs=0.5)     # ended at its target (the actual value within I22)
    waiting = [r for r in rows if r[1] == 2]
    assert waiting and all(not r[2] for r in waiting)
    end = waiting[-1][0]
    after = [r for r in rows if r[0] > end]
    assert [r[2] for r in after[:3]] == [False, False, True]
    assert all(r[1] == 3 for r in after[2:])
    assert all(abs(r[3] - 100.0) < 0.5 and r[4] == 0.0 for r in after)     # torque 0 at rest: it stays


def test_pilz_command_modes_torque_control_waiting_cancelled():
    """Pilz V6.5 Tab. 31 (I409 = 1) with §1.2.7 (I91 "denied or cancelled"): the enable going off while an
    MC_TorqueControl waits behind a positioning cancels it (I90 = 22, I89 = 0); it never takes the axis over."""
    ctl, ax = make_axis({"I87": 0.0})
    start(ax, 1, SLOW, I403=100.0)
    ctl.run(0.1)
    start(ax, 9, I428=1.0, I409=1)
    ctl.run(0.05)
    assert ax.status.I83 == 2 and not ax.status.I92
    ax.enable(False)
    ctl.run(0.3)
    assert ax.status.I91 and ax.status.I90 == 22 and ax.status.I89 == 0 and ax.status.E02 == 0.0
