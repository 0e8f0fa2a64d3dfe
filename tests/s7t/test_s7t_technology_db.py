"""Technology DBs as asynchronous snapshots, the MCDevice DB and OB65 (S7-Technology V4.1 §5.1, §6.9.2, §7.1,
§7.10, §7.11).

The DB update runs every db_update_ratio IPO cycles (the kernel's servo cycle); a program sees the members
change only there, with UpdateCounter + 1 per update; OB65 runs after every update and then finds every DB
of that update consistent (UpdateFlag 0, equal counters).  DoneFlag[n] of the MCDevice DB toggles when a
command with DoneFlag = n completes.
"""
from __future__ import annotations

import pytest

from plcmotion.kernel.tag_views import TagAccessError
from plcmotion import s7t
from plcmotion.s7t import MC_MoveAbsolute, MC_MoveRelative, MC_MoveVelocity, MC_Stop

from _s7t_rig import VIRTUAL, controller, enabled


@pytest.mark.parametrize("ratio", [1, 2, 3])
def test_s7t_update_counter_counts_updates(ratio):
    """S7-Technology V4.1 §7.11: UpdateCounter of every DB grows by one per update, one update every
    db_update_ratio IPO cycles (§5.1)."""
    ctl = controller(servo_cycle=0.001, app_cycle=0.006)
    ext = s7t.device(ctl)
    ext.db_update_ratio = ratio
    axis = ctl.add_positioning_axis("A", VIRTUAL)
    before = axis.db.UpdateCounter
    ctl.run(0.6)                                    # 600 IPO cycles
    assert axis.db.UpdateCounter - before == 600 // ratio
    assert ext.mcdevice.UpdateCounter == axis.db.UpdateCounter
    assert axis.db.UpdateFlag == 0


def test_s7t_db_update_ratio_is_checked():
    """S7-Technology V4.1 §5.1: the update clock is a whole multiple of the IPO cycle."""
    ext = s7t.device(controller())
    for bad in (0, -1, 2.5, True, "2"):
        with pytest.raises(ValueError):
            ext.db_update_ratio = bad


def test_s7t_values_change_only_at_an_update():
    """S7-Technology V4.1 §7.11: between two updates the DB keeps its values while the axis moves on; at an
    update CommandPosition is the setpoint of that IPO cycle."""
    ctl, axis, _ = enabled(ctl=controller(servo_cycle=0.001, app_cycle=0.004))
    s7t.device(ctl).db_update_ratio = 4
    move = MC_MoveVelocity()
    move(Axis=axis, Execute=True, Velocity=100.0, Acceleration=1000.0, Deceleration=1000.0, Jerk=0.0)
    seen: list[tuple[int, float, float]] = []
    b, i = ctl.bank, axis.index

    @ctl.on_post_servo
    def watch(t):
        seen.append((axis.db.UpdateCounter, axis.db.CommandPosition, float(b.sp_p[i])))
    ctl.run(0.2)
    changes = 0
    for (c0, p0, _), (c1, p1, sp1) in zip(seen, seen[1:]):
        if c1 == c0:
            assert p1 == p0                         # no update: the DB value stands
        else:
            changes += 1
            assert c1 == c0 + 1 and p1 == pytest.approx(sp1, abs=1e-9)
    assert changes == 50
    assert seen[-1][2] > seen[0][2] + 10.0          # the axis moved meanwhile


def test_s7t_ob65_after_every_update_sees_a_consistent_image():
    """S7-Technology V4.1 §5.1, §7.11: OB65 runs after every DB update; UpdateFlag is 16#0000 there and all
    DBs carry the UpdateCounter of the same update (the consistency check the manual recommends)."""
    ctl = controller(servo_cycle=0.001, app_cycle=0.004)
    a = ctl.add_positioning_axis("A", VIRTUAL)
    b = ctl.add_positioning_axis("B", {**VIRTUAL, "Wizard.Technology": 0})
    mc = s7t.device(ctl).mcdevice
    calls: list[tuple[int, int, int, int]] = []

    @s7t.ob65(ctl)
    def ob65():
        calls.append((mc.UpdateCounter, a.db.UpdateCounter, b.db.UpdateCounter,
                      mc.UpdateFlag | a.db.UpdateFlag | b.db.UpdateFlag))
    start = mc.UpdateCounter
    ctl.run(0.1)
    assert len(calls) == 50                         # every 2nd of 100 IPO cycles
    assert [c[0] for c in calls] == list(range(start + 1, start + 51))
    assert all(c[0] == c[1] == c[2] and c[3] == 0 for c in calls)


def test_s7t_ob65_program_fault_stops_the_cpu():
    """S7-Technology V4.1 §5.1: OB65 is a user program; one that raises puts the CPU in STOP."""
    ctl = controller()

    @s7t.ob65(ctl)
    def ob65():
        raise ZeroDivisionError("in OB65")
    with pytest.warns(Warning):
        ctl.run(0.02)
    assert ctl.mode == "STOP" and "OB65" in ctl.stop_reason


def test_s7t_technology_db_is_write_protected():
    """S7-Technology V4.1 §7: the user program cannot write a technology DB."""
    ctl = controller()
    axis = ctl.add_positioning_axis("A", VIRTUAL)
    with pytest.raises(TagAccessError):
        axis.db.ActualPosition = 5.0
    with pytest.raises(AttributeError):
        axis.db.NoSuchMember


def test_s7t_speed_axis_db_has_no_positions():
    """S7-Technology V4.1 §7.1: the DB of a speed-controlled axis has velocities, no positions; its
    Statusword.SpeedMode is always TRUE."""
    ctl, axis, _ = enabled({**VIRTUAL, "Wizard.Technology": 0})
    assert axis.db.Statusword.SpeedMode and axis.db.Statusword.X20
    with pytest.raises(AttributeError):
        axis.db.ActualPosition


def test_s7t_statusword_follows_the_motion():
    """S7-Technology V4.1 §7.1: Statusword bits of a positioning: PositioningCommand and Accelerating while
    it runs, Done (no motion command) and Standstill after it; SpeedCommand for MC_MoveVelocity."""
    ctl, axis, _ = enabled()
    move = MC_MoveRelative()
    move(Axis=axis, Execute=True, Distance=100.0, Velocity=50.0, Acceleration=100.0, Deceleration=100.0,
         Jerk=0.0)
    ctl.run(0.1)
    w = axis.db.Statusword
    assert w.PositioningCommand and w.Accelerating and not w.Done and not w.Standstill
    assert axis.db.TargetPosition == 100.0 and 0.0 < axis.db.Distance < 100.0
    ctl.run_until(lambda: move(Execute=True).Done, 5.0)
    ctl.run(0.05)
    w = axis.db.Statusword
    assert w.Done and w.Standstill and not w.PositioningCommand and w.DriveEnabled
    vel = MC_MoveVelocity()
    vel(Axis=axis, Execute=True, Velocity=10.0)
    ctl.run(0.05)
    assert axis.db.Statusword.SpeedCommand and not axis.db.Statusword.Done


def _flag(ctl, n):
    return s7t.device(ctl).mcdevice.DoneFlag[n]


def test_s7t_done_flag_toggles_on_completion():
    """S7-Technology V4.1 §6.9.2: DoneFlag[n] of the MCDevice DB toggles each time a command with DoneFlag = n
    is done (FALSE -> TRUE -> FALSE), and only then."""
    ctl, axis, _ = enabled()
    move = MC_MoveRelative()
    assert _flag(ctl, 3) is False
    move(Axis=axis, Execute=True, Distance=10.0, Velocity=100.0, DoneFlag=3)
    ctl.run(0.02)
    assert _flag(ctl, 3) is False                    # still moving
    ctl.run_until(lambda: move(Execute=True).Done, 5.0)
    ctl.run(0.01)
    assert _flag(ctl, 3) is True and _flag(ctl, 4) is False
    move(Execute=False)
    move(Execute=True)
    ctl.run_until(lambda: move(Execute=True).Done, 5.0)
    ctl.run(0.01)
    assert _flag(ctl, 3) is False


def test_s7t_done_flag_not_toggled_when_the_instance_is_reused():
    """S7-Technology V4.1 §6.9.2: the flag toggles only while the command can still be monitored: a second
    command of the same instance before the first is done leaves only the second to toggle it."""
    ctl, axis, _ = enabled()
    move = MC_MoveAbsolute()
    move(Axis=axis, Execute=True, Position=50.0, Velocity=100.0, DoneFlag=5)
    ctl.run(0.05)
    move(Execute=False)
    move(Execute=True, Position=60.0, DoneFlag=0)   # the same instance, no DoneFlag this time
    ctl.run_until(lambda: move(Execute=True).Done, 5.0)
    ctl.run(0.05)
    assert _flag(ctl, 5) is False


def test_s7t_done_flag_of_move_velocity_and_stop():
    """S7-Technology V4.1 §6.9.2: MC_MoveVelocity toggles its flag when the velocity is reached; MC_Stop when
    it is done (standstill and Execute FALSE, §6.2.3)."""
    ctl, axis, _ = enabled()
    vel, stop = MC_MoveVelocity(), MC_Stop()
    vel(Axis=axis, Execute=True, Velocity=20.0, Acceleration=200.0, DoneFlag=1)
    ctl.run_until(lambda: vel(Execute=True).InVelocity, 2.0)
    ctl.run(0.01)
    assert _flag(ctl, 1) is True
    stop(Axis=axis, Execute=True, DoneFlag=32)
    ctl.run(1.0)
    assert _flag(ctl, 32) is False                  # standing still, but Execute is still TRUE
    stop(Execute=False)
    ctl.run(0.01)
    assert _flag(ctl, 32) is True


def test_s7t_mcdevice_shows_integrated_io():
    """S7-Technology V4.1 §7.10: DIStatus[0..3] / DOStatus[0..7] are the integrated inputs and outputs."""
    ctl = controller()
    ctl.inputs.set_filter("I0.2", 0.0)
    ctl.inputs["I0.2"] = True
    ctl.outputs["Q0.7"] = True
    ctl.run(0.02)
    mc = s7t.device(ctl).mcdevice
    assert list(mc.DIStatus) == [False, False, True, False]
    assert mc.DOStatus[7] and not mc.DOStatus[0]
    with pytest.raises(IndexError):
        mc.DoneFlag[0]


def test_s7t_technology_dbs_are_not_retentive():
    """S7-Technology V4.1 §7, §7.10: technology DBs are not retentive: after POWER OFF -> ON the DoneFlags are
    FALSE again and the errors of the technology objects are gone."""
    ctl, axis, _ = enabled({"Wizard.Virtual": 1})          # "Homing required" = YES
    move = MC_MoveRelative()
    move(Axis=axis, Execute=True, Distance=1.0, DoneFlag=2)
    ctl.run_until(lambda: move(Execute=True).Done, 2.0)
    MC_MoveAbsolute()(Axis=axis, Execute=True, Position=5.0)   # not homed: 16#8041 in the DB
    ctl.run(0.01)
    assert _flag(ctl, 2) is True and axis.db.ErrorID == 0x8041 and axis.db.Statusword.Error
    ctl.power_cycle()
    ctl.run(0.01)
    assert _flag(ctl, 2) is False and axis.db.ErrorID == 0 and not axis.db.Statusword.Error
