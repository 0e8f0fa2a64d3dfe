"""The update of each technology DB (reduction ratio and offset), the update overflows and the command loop
durations of the MCDevice DB (S7-Technology V4.1 §5.4, §7.10, §7.11).

Basic clock = the DB update cycle (here 2 IPO cycles of 1 ms).  A DB with reduction r and offset o is updated
in the basic clocks k (0, 1, 2, ... since the start) with k mod r = o; the MCDevice DB and OB65 in every
basic clock.  Loop durations in plcmotion: the virtual time from a command's start in a program to the IPO
cycle that carries it out - one IPO cycle (decision D89).
"""
from __future__ import annotations

import pytest

from plcmotion import s7t
from plcmotion.s7t import MC_MoveVelocity, MC_Reset

from _s7t_rig import VIRTUAL, controller, enabled


def _three_axes():
    ctl = controller(servo_cycle=0.001, app_cycle=0.002)
    dev = s7t.device(ctl)
    axes = [ctl.add_positioning_axis(name, VIRTUAL) for name in ("A", "B", "C")]
    return ctl, dev, axes


def test_s7t_db_update_reduction_and_offset():
    """S7-Technology V4.1 §7.11 "graded step-down ratio and offset": A every clock (1/0), B every 2nd clock
    from clock 0 (2/0), C every 3rd clock from clock 1 (3/1).  In 12 basic clocks: A 12 updates, B 6, C 4;
    the MCDevice DB 12 and OB65 12 calls; OB65 sees B's counter rise only in even clocks."""
    ctl, dev, (a, b, c) = _three_axes()
    dev.set_db_update(b.db_number, 2, 0)
    dev.set_db_update(c.db_number, 3, 1)
    assert dev.db_update(b.db_number) == (2, 0) and dev.db_update(a.db_number) == (1, 0)
    seen: list[tuple[int, int, int, int]] = []

    @s7t.ob65(ctl)
    def ob65():
        seen.append((dev.mcdevice.UpdateCounter, a.db.UpdateCounter, b.db.UpdateCounter, c.db.UpdateCounter))
    ctl.run(0.024)                                  # 24 IPO cycles = 12 basic clocks
    assert len(seen) == 12
    assert [s[0] for s in seen] == list(range(1, 13)) and [s[1] for s in seen] == list(range(1, 13))
    assert [s[2] for s in seen] == [1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6]
    assert [s[3] for s in seen] == [0, 1, 1, 1, 2, 2, 2, 3, 3, 3, 4, 4]


def test_s7t_db_update_snapshot_of_a_reduced_db_is_older():
    """S7-Technology V4.1 §7.11: a DB with reduction 4 shows the axis's position of its last update, up to 4
    basic clocks old, while a DB updated every clock follows the axis each clock."""
    ctl = controller(servo_cycle=0.001, app_cycle=0.002)
    dev = s7t.device(ctl)
    fast, slow = (ctl.add_positioning_axis(n, VIRTUAL) for n in ("Fast", "Slow"))
    dev.set_db_update(slow.db_number, 4, 0)
    powers = [s7t.MC_Power(), s7t.MC_Power()]
    moves = [MC_MoveVelocity(), MC_MoveVelocity()]

    @ctl.program
    def ob1():
        for power, move, axis in zip(powers, moves, (fast, slow)):
            power(Axis=axis, Enable=True)
            if power.Status:
                move(Axis=axis, Execute=True, Velocity=100.0, Acceleration=1e5, Deceleration=1e5, Jerk=0.0)
    ctl.run(0.2)
    values = []
    for _ in range(8):
        ctl.run(0.002)
        values.append((fast.db.ActualPosition, slow.db.ActualPosition))
    fast_steps = [round(b[0] - a[0], 6) for a, b in zip(values, values[1:])]
    slow_steps = [round(b[1] - a[1], 6) for a, b in zip(values, values[1:])]
    assert fast_steps == [0.2] * 7                  # 100 per s, one basic clock of 2 ms
    assert sorted(set(slow_steps)) == [0.0, 0.8]    # a step of 4 clocks every 4th clock


def test_s7t_db_update_change_waits_for_a_start():
    """S7-Technology V4.1 §7.10 Statusword.RequestStartUp: a reduction changed while the CPU runs is not in
    effect until the next start; until then the MCDevice DB requests it."""
    ctl, dev, (a, _b, _c) = _three_axes()
    ctl.run(0.01)
    dev.set_db_update(a.db_number, 2, 1)
    assert dev.db_update(a.db_number) == (1, 0)
    assert dev.mcdevice.Statusword.RequestStartUp
    before = a.db.UpdateCounter
    ctl.run(0.008)
    assert a.db.UpdateCounter - before == 4
    ctl.stop("test")
    ctl.start()
    assert dev.db_update(a.db_number) == (2, 1) and not dev.mcdevice.Statusword.RequestStartUp
    before = a.db.UpdateCounter
    ctl.run(0.008)
    assert a.db.UpdateCounter - before == 2


@pytest.mark.parametrize("number, reduction, offset", [
    (1, 2, 0),              # the MCDevice DB: every basic clock
    (99, 2, 0),             # no technology DB
    (2, 0, 0), (2, 2, 2), (2, 2, -1), (2, 1.5, 0), (2, True, 0),
])
def test_s7t_db_update_settings_are_checked(number, reduction, offset):
    """S7-Technology V4.1 §7.11: the reduction is a whole number >= 1, the offset one of its clocks."""
    _ctl, dev, _axes = _three_axes()
    with pytest.raises(ValueError, match="set_db_update"):
        dev.set_db_update(number, reduction, offset)


def test_s7t_db_update_overflow_discards_the_update():
    """S7-Technology V4.1 §7.11 (firmware V3.2 and later): an update that overflows is discarded - no DB
    written, OB65 not called - and counted in MCDevice.TODBTaskOverflows; MC_Reset on the MCDevice DB sets the
    count to 0 (§6.7.1, §7.10)."""
    ctl, dev, (a, _b, _c) = _three_axes()
    calls = []
    s7t.ob65(ctl)(lambda: calls.append(a.db.UpdateCounter))
    ctl.run(0.004)
    before, n = a.db.UpdateCounter, len(calls)
    dev.inject_update_overflow(3)
    ctl.run(0.006)                                  # 3 basic clocks, all discarded
    assert a.db.UpdateCounter == before and len(calls) == n
    ctl.run(0.002)
    assert a.db.UpdateCounter == before + 1 and dev.mcdevice.TODBTaskOverflows == 3
    reset = MC_Reset()
    reset(Axis=1, Execute=True)
    assert reset.Done and dev.mcdevice.TODBTaskOverflows == 0
    with pytest.raises(ValueError):
        dev.inject_update_overflow(0)


def test_s7t_db_update_command_loop_durations():
    """S7-Technology V4.1 §7.10 CmdLoopDuration (mean) and MaxLoopDuration (longest) command execution time:
    0.0 until a command is given; in plcmotion one IPO cycle (2 ms here) per command; MC_Reset on the
    MCDevice DB and a restart of the CPU clear them (§6.7.1)."""
    ctl, axis, _power = enabled()
    mc = s7t.device(ctl).mcdevice
    assert mc.CmdLoopDuration == 0.0 and mc.MaxLoopDuration == 0.0
    move = MC_MoveVelocity()
    move(Axis=axis, Execute=True, Velocity=10.0)
    ctl.run(0.004)
    assert mc.CmdLoopDuration == pytest.approx(0.002) and mc.MaxLoopDuration == pytest.approx(0.002)
    reset = MC_Reset()
    reset(Axis=1, Execute=True)
    assert mc.CmdLoopDuration == 0.0 and mc.MaxLoopDuration == 0.0
    ctl.run(0.004)
    assert mc.CmdLoopDuration == 0.0
