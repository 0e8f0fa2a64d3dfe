"""Status timelines of MC_MoveSpeed and MC_CyclicPosition cycle by cycle, and the status of MC_MoveVelocity and
MC_MoveAbsolute under the override I230 (Pilz V6.5 Tab. 5, 15, 29, 35; §1.2.5, §1.5.5)."""
from __future__ import annotations

from ._core import A150, PROFILE, make_axis, rows_from, start


def test_pilz_status_move_speed_timeline():
    """Pilz V6.5 §1.9.7 Tab. 29: edge cycle I91 = I90 = I92 = 0 and I89 = 4; I85 when E07 = I426 (80); I183
    when I85 and the actual velocity is within C40; I92 = I85 and I183; I89 stays 4; I83 1 then 3."""
    ctl, ax = make_axis({"C40": 5.0})
    t0 = start(ax, 8, I426=80.0, I216=2000.0, I217=2000.0, I407=100000.0)
    ctl.run(0.3)
    rows = rows_from(ax, t0)
    edge = rows[0]
    assert (edge.I91, edge.I90, edge.I92, edge.I85, edge.I183, edge.I89, edge.I83) == (
        False, 0, False, False, False, 4, 1)
    assert all(r.I89 == 4 and not r.I91 for r in rows)
    for r in rows[1:]:
        assert r.I85 == (abs(r.E07 - 80.0) < 1e-9)
        assert r.I183 == (r.I85 and abs(r.I88 - 80.0) <= 5.0)
        assert r.I92 == (r.I85 and r.I183)
        assert r.I83 == (3 if r.I92 else 1)
    assert rows[-1].I92                       # 80 at 2000 /s²: reached after about 40 ms


def test_pilz_status_cyclic_position_timeline():
    """Pilz V6.5 §1.11.7 Tab. 35: I92 = 0 in the edge cycle and the cycle after it, 1 from the second cycle A150
    after the start; I183 and I85 stay 0; I89 = 11 (cyclic motion) from the edge; I91 = I90 = 0."""
    ctl, ax = make_axis({"I10": 1000.0})

    @ctl.program
    def feed():                               # a new set position every application cycle (A291 = A150)
        ax.registers.I421 = round(ctl.time, 6) * 10.0

    t0 = start(ax, 10, I421=ctl.time * 10.0)
    ctl.run(0.02)
    rows = rows_from(ax, t0)
    assert [r.I92 for r in rows[:4]] == [False, False, True, True]
    assert all(r.I89 == 11 and not r.I85 and not r.I183 and not r.I91 and r.I90 == 0 for r in rows)
    assert all(r.I92 for r in rows[2:])
    assert abs(rows[-1].E07 - 10.0) < 1e-6   # follows 10 units/s


def test_pilz_status_move_velocity_override_zero():
    """Pilz V6.5 §1.5.5 (override 0: the axis stays stationary, the command active), Tab. 15 (I85: E07 = I404;
    I92 = I85 and I183): at I230 = 0 no I85, I183, I92; once I230 is 100 again they come at I404."""
    ctl, ax = make_axis({"C40": 5.0})
    ax.registers.I230 = 0.0
    t0 = start(ax, 4, PROFILE, I404=100.0)
    ctl.run(0.2)
    rows = rows_from(ax, t0)
    assert all(r.E07 == 0.0 and r.I89 == 4 and not (r.I85 or r.I183 or r.I92) for r in rows)
    assert all(type(r.I85) is bool and type(r.I92) is bool for r in rows)
    ax.registers.I230 = 100.0
    ctl.run(0.3)
    s = ax.status
    assert s.E07 == 100.0 and s.I85 and s.I183 and s.I92


def test_pilz_status_move_velocity_done_follows_override():
    """Pilz V6.5 Tab. 15 (I85: E07 = I404, I92 = I85 and I183), decisions.md "Override": Done of MC_MoveVelocity
    is no latch - at I230 = 50 the set velocity is 50, not I404 = 100, so I85 / I183 / I92 go; back at 100 they
    come again."""
    ctl, ax = make_axis({"C40": 5.0})
    start(ax, 4, PROFILE, I404=100.0)
    ctl.run(0.3)
    assert ax.status.I92
    ax.registers.I230 = 50.0
    ctl.run(0.3)
    s = ax.status
    assert abs(s.E07 - 50.0) < 1e-9 and not (s.I85 or s.I183 or s.I92) and s.I89 == 4
    ax.registers.I230 = 100.0
    ctl.run(0.3)
    assert ax.status.I85 and ax.status.I183 and ax.status.I92


def test_pilz_status_move_absolute_override_zero_types():
    """Pilz V6.5 §1.2.5 (override 0 holds the axis) and Tab. 5: the status words stay bool while the command
    waits at I230 = 0 - I85 is 0 (the set position has not reached I403), not a number."""
    ctl, ax = make_axis()
    ax.registers.I230 = 0.0
    t0 = start(ax, 1, PROFILE, I403=100.0)
    ctl.run(0.05)
    for r in rows_from(ax, t0):
        for name in ("I85", "I91", "I92", "I180", "I183", "I190", "I191", "I193", "I199"):
            assert type(r.values[name]) is bool, name
        assert type(r.I90) is int and type(r.I89) is int and type(r.I83) is int
        assert r.I85 is False and r.I96 == 0.0
    assert A150 == ctl.servo_cycle
