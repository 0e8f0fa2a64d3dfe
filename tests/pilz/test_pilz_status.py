"""Status timelines of the Pilz motion core commands, motion-core cycle by cycle (Pilz V6.5 Tab. 5, 8, 12, 15,
18, 23, 26, 29, 32, 35, 38 and Fig. 3, 4, 14, 16, 18)."""
from __future__ import annotations

import pytest

from ._core import A150, PROFILE, make_axis, release, rows_from, start


def _first(rows, name):
    return next((r for r in rows if getattr(r, name)), None)


def test_pilz_status_move_absolute_dwell():
    """Pilz V6.5 §1.2.7 Tab. 5, Fig. 4: I180 comes while the axis still moves, I85 when the set position equals
    the target, I92 when I85 = 1 and I180 has been 1 for I87; I89 3 during the motion, 2 after it."""
    ctl, ax = make_axis({"I22": 0.5, "I87": 0.05})
    t0 = start(ax, 1, PROFILE, I403=100.0)
    ctl.run(1.0)
    rows = rows_from(ax, t0)
    assert (rows[0].I91, rows[0].I92, rows[0].I85) == (False, False, False) and rows[0].I89 == 3
    win, prof, done = _first(rows, "I180"), _first(rows, "I85"), _first(rows, "I92")
    assert win.t < prof.t <= done.t
    assert win.E07 > 0.0                                  # I180 while the set velocity is not yet 0
    # Done exactly when the window has been held for I87 (in whole cycles) after I85 and I180
    held_since = max(win.t, min(r.t for r in rows if r.I180 and all(q.I180 for q in rows if r.t <= q.t <= done.t)))
    assert done.t == pytest.approx(max(prof.t, held_since + 0.05), abs=A150 / 2)
    assert all(r.I89 == 3 for r in rows if r.t < prof.t)
    assert rows[-1].I89 == 2 and rows[-1].I92 and rows[-1].I96 == pytest.approx(100.0)


def test_pilz_status_move_absolute_done_with_profile():
    """Pilz V6.5 Fig. 3: with I87 = 0 and the actual position in the window before the profile ends, I85 and
    I92 come in the same cycle."""
    ctl, ax = make_axis({"I22": 1.0, "I87": 0.0})
    t0 = start(ax, 1, PROFILE, I403=50.0)
    ctl.run(1.0)
    rows = rows_from(ax, t0)
    assert _first(rows, "I85").t == _first(rows, "I92").t


def test_pilz_status_handshake_done_already_true():
    """Pilz V6.5 Tab. 5 (I92): Done is 0 for at least one cycle at the start even if the end condition holds
    already - a MC_MoveAbsolute to the current position."""
    ctl, ax = make_axis({"I87": 0.0})
    t0 = start(ax, 1, PROFILE, I403=0.0)
    ctl.run(0.005)
    rows = rows_from(ax, t0)
    assert not rows[0].I92 and rows[1].I92


def test_pilz_status_speed_reached_positioning():
    """Pilz V6.5 Tab. 5 (I183): Speed reached while the profile runs at the set velocity and the actual velocity
    is within C40 of it; 0 again while braking; 0 throughout when the distance is too short for the velocity."""
    ctl, ax = make_axis({"C40": 2.0})
    t0 = start(ax, 1, PROFILE, I403=100.0)
    ctl.run(1.0)
    rows = rows_from(ax, t0)
    reached = [r for r in rows if r.I183]
    assert reached and all(abs(r.I88 - 200.0) <= 2.0 for r in reached)
    assert not rows[-1].I183
    release(ax)
    t1 = start(ax, 1, PROFILE, I403=101.0)
    ctl.run(0.5)
    assert not any(r.I183 for r in rows_from(ax, t1))


def test_pilz_status_move_velocity():
    """Pilz V6.5 §1.5.7 Tab. 15, Fig. 14 (300, then 200, then 400): I183, I85 and I92 rise together when the
    set velocity is reached; the second command (lower velocity) keeps I183 = 1 while I85 / I92 restart from 0
    (handshake) and come at 200; the third (higher) clears all three, which come together at 400; I89 = 4."""
    ctl, ax = make_axis({"C40": 5.0, "I10": 500.0})      # a window wider than the drive model's lag
    t0 = start(ax, 4, PROFILE, I404=300.0)
    ctl.run(0.5)
    rows = rows_from(ax, t0)
    first = _first(rows, "I92")
    assert first.I183 and first.I85 and abs(first.E07 - 300.0) < 1e-9
    assert all(r.I85 for r in rows if r.I183) and all(r.I92 == (r.I85 and r.I183) for r in rows[1:])
    assert all(r.I89 == 4 for r in rows)
    t1 = start(ax, 4, PROFILE, I404=200.0)
    ctl.run(0.5)
    rows = rows_from(ax, t1)
    assert not rows[0].I92 and not rows[0].I85
    assert all(r.I183 for r in rows)                  # "The Speed reached state remains active"
    second = _first(rows, "I92")
    assert abs(second.E07 - 200.0) < 1e-9 and second.I85
    assert all(not r.I92 for r in rows if r.E07 > 200.0 + 1e-9)
    t2 = start(ax, 4, PROFILE, I404=400.0)
    ctl.run(0.5)
    rows = rows_from(ax, t2)
    assert not rows[0].I92 and not rows[0].I85 and not rows[0].I183
    third = _first(rows, "I92")
    assert abs(third.E07 - 400.0) < 1e-9 and third.I183
    assert all(r.I85 for r in rows if r.I183) and all(r.I92 == (r.I85 and r.I183) for r in rows[1:])


def test_pilz_status_move_velocity_zero():
    """Pilz V6.5 §1.5.2: velocity 0 is no denial; the axis stays in continuous motion (I89 = 4) at 0."""
    ctl, ax = make_axis()
    start(ax, 4, PROFILE, I404=0.0)
    ctl.run(0.01)
    assert not ax.status.I91 and ax.status.I92 and ax.status.I89 == 4


def test_pilz_status_stop():
    """Pilz V6.5 §1.6.4 / §1.6.7 Fig. 16: I89 = 6 from the start; I183 when the actual velocity is within C40 of
    0; I85 and I92 when set and actual velocity are 0; I89 stays 6 while Execute is 1, then 2."""
    ctl, ax = make_axis({"C40": 5.0})
    start(ax, 4, PROFILE, I404=100.0)
    ctl.run(0.3)
    t0 = start(ax, 5, I406=1000.0, I407=100000.0)
    ctl.run(0.5)
    rows = rows_from(ax, t0)
    assert all(r.I89 == 6 for r in rows)
    reached, done = _first(rows, "I183"), _first(rows, "I92")
    assert reached.t <= done.t
    assert done.I85 and done.E07 == 0.0 and abs(done.I88) <= 5.0
    release(ax)
    assert ax.status.I89 == 2 and ax.status.I92


def test_pilz_status_halt_then_new_command():
    """Pilz V6.5 §1.12.4 / §1.12.5 Fig. 17: MC_Halt keeps I89 = 3 while Execute is 1 and may be replaced before
    standstill; the interrupted command does not resume by itself."""
    ctl, ax = make_axis()
    start(ax, 4, PROFILE, I404=100.0)
    ctl.run(0.3)
    t0 = start(ax, 11, I406=500.0, I407=100000.0)
    ctl.run(0.05)
    assert all(r.I89 == 3 for r in rows_from(ax, t0))
    assert ax.status.E07 > 0.0
    t1 = start(ax, 4, PROFILE, I404=-50.0)       # accepted before standstill
    ctl.run(0.3)
    assert not any(r.I91 for r in rows_from(ax, t1)) and ax.status.E07 == -50.0
    start(ax, 11, I406=500.0, I407=100000.0)
    ctl.run(0.5)
    release(ax)
    ctl.run(0.2)
    assert ax.status.E07 == 0.0 and ax.status.I89 == 2


def test_pilz_status_home_search():
    """Pilz V6.5 §1.7.4 / §1.7.7 Tab. 23: a referencing with a search movement puts I89 to 8 and back to 2 at
    its end; I86 and I92 at the end; I183 and I85 stay 0."""
    ctl, ax = make_axis({"I30": 3, "I31": 0, "I35": 1, "Plant.ZeroMarkDistance": 10.0, "Plant.ZeroMarkOffset": 4.0,
                         "I34": 100.0}, referenced=False)
    t0 = start(ax, 6)
    ctl.run(2.0)
    rows = rows_from(ax, t0)
    assert rows[1].I89 == 8 and not rows[1].I86
    done = _first(rows, "I92")
    assert done.I86 and done.I89 == 2
    assert not any(r.I183 or r.I85 for r in rows)


def test_pilz_status_home_set_reference():
    """Pilz V6.5 §1.7.4: setting the reference (I30 = 5) keeps I89 at 2; I86 and I92 follow the handshake."""
    ctl, ax = make_axis({"I34": 25.0}, referenced=False)
    t0 = start(ax, 6)
    ctl.run(0.003)
    rows = rows_from(ax, t0)
    assert all(r.I89 == 2 for r in rows)
    assert not rows[0].I92 and rows[1].I92 and rows[1].I86
    assert ax.status.I96 == pytest.approx(25.0)


@pytest.mark.parametrize("command,registers,state", [(7, {"I426": 20.0}, 11), (9, {"I428": 0.5}, 4),
                                                     (10, {"I421": 0.0}, 11)])
def test_pilz_status_cyclic_done_second_cycle(command, registers, state):
    """Pilz V6.5 Tab. 26, 32, 35: I92 = 1 from the second cycle A150 after the start (it acknowledges the
    start); I183 and I85 stay 0; I89 = 11 (cyclic) or 4 (torque)."""
    ctl, ax = make_axis()

    @ctl.program
    def controller():
        for k, v in registers.items():
            ax.registers.write(k, v)

    t0 = start(ax, command, **registers)
    ctl.run(0.01)
    rows = rows_from(ax, t0)
    assert [r.I92 for r in rows[:4]] == [False, False, True, True]
    assert all(r.I89 == state for r in rows)
    assert not any(r.I183 or r.I85 or r.I91 for r in rows)


def test_pilz_status_do_nothing():
    """Pilz V6.5 §1.1: MC_DoNothing produces no status and does not switch the motion ID."""
    ctl, ax = make_axis({"I87": 0.0})
    start(ax, 1, PROFILE, I403=0.0, I400=7)
    ctl.run(0.01)
    before = ax.rows[-1].values
    start(ax, 0, I400=9)
    ctl.run(0.01)
    assert ax.rows[-1].values == before and ax.status.I82 == 7


def test_pilz_status_motion_id():
    """Pilz V6.5 Tab. 3: I400 becomes the active motion ID I82 at the start of a command."""
    ctl, ax = make_axis()
    start(ax, 4, PROFILE, I404=10.0, I400=42)
    assert ax.status.I82 == 42


def test_pilz_status_controller_restart():
    """decisions.md (Pilz V6.5 §1): after a controller restart the core runs no command; a new command starts
    from the register's start values and runs normally."""
    ctl, ax = make_axis()
    start(ax, 1, PROFILE, I403=100.0)
    ctl.run(0.2)
    ctl.power_cycle()
    ax.enable()
    ctl.run(0.05)
    assert ax.status.I89 == 2 and not ax.status.I92 and not ax.status.I91 and ax.registers.I401 == 0
    start(ax, 2, PROFILE, I403=10.0)
    ctl.run(1.0)
    assert ax.status.I92 and ax.status.I96 == pytest.approx(ax.status.I80 + 10.0, abs=1e-9)


def test_pilz_status_as_tags():
    """The status words and the command register read as tags (``axis.tag``, attributes), as the kernel's tag
    views give them to traces and programs; a register write through the tag path is refused (use
    ``axis.write``)."""
    from plcmotion.kernel.tag_views import TagAccessError
    from plcmotion.pilz import RegisterError

    ctl, ax = make_axis()
    start(ax, 4, PROFILE, I404=20.0)
    ctl.run(0.2)
    assert ax.tag("I92") is True and ax.I89 == 4 and ax.tag("I404") == 20.0 and ax.tag("I10") == 500.0
    with pytest.raises((TagAccessError, KeyError, RegisterError)):
        ax.set_tag("I404", 1.0)
    with pytest.raises(RegisterError):
        ax.write("I92", True)


@pytest.mark.parametrize("command", [2, 3])
def test_pilz_status_relative_additive(command):
    """Pilz V6.5 Tab. 8 / Tab. 12: I85 when the set position equals I403 + I80 (MC_MoveRelative, I80 = actual
    position at the start) or I403 + the set position at the start (MC_MoveAdditive); I92 after I180 held I87;
    the handshake cycle first."""
    ctl, ax = make_axis({"Plant.InitialPosition": 9.5, "I22": 0.5, "I87": 0.03}, referenced=False)
    t0 = start(ax, command, PROFILE, I403=40.0)
    ctl.run(1.0)
    rows = rows_from(ax, t0)
    assert not rows[0].I85 and not rows[0].I92 and rows[0].I89 == 3
    prof, done = _first(rows, "I85"), _first(rows, "I92")
    assert prof.I96 == pytest.approx(ax.status.I80 + 40.0) == pytest.approx(49.5, abs=0.01)
    assert done.t >= prof.t and all(r.I180 for r in rows if done.t - 0.03 - 1e-9 <= r.t <= done.t)
    assert rows[-1].I89 == 2
