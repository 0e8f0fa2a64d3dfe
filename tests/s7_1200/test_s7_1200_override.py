"""Override response of the S7-1200 V6 motion instructions: which command aborts which.

Derived from the "Override response" lists of the manual (S7-1200 Motion Control V6.0):
  §11.1.4.1 MC_Halt, §11.1.5.1 MC_MoveAbsolute, §11.1.6.1 MC_MoveRelative, §11.1.7.1 MC_MoveVelocity,
  §11.1.8.1 MC_MoveJog: each is aborted by, and aborts, MC_Home Mode 3, MC_Halt, MC_MoveAbsolute,
  MC_MoveRelative, MC_MoveVelocity, MC_MoveJog, MC_CommandTable.
  §11.1.3.1 MC_Home Mode 0/1: cannot be aborted, does not abort; position-related commands are resumed
  according to the new home position.
  §11.1.1.1 MC_Power: Enable = FALSE aborts all commands; §11.1.2.1 MC_Reset aborts nothing.
  §9.3 override of MC_MoveRelative by MC_MoveAbsolute; §9.6 rejected commands leave the motion running.
  Function charts §11.1.4.2 (S-HALT-1/2), §11.1.5.2 (S-MABS-2), §11.1.6.2 (S-MREL-2), §11.1.7.2 (S-MVEL-1/2).
"""
from __future__ import annotations

import pytest

from _s7_1200_rig import (MC_Halt, MC_Home, MC_MoveAbsolute, MC_MoveJog, MC_MoveRelative, MC_MoveVelocity,
                          MC_Reset, Rig, calls_with, contiguous_to_end)

MOTION = ["MC_Halt", "MC_MoveAbsolute", "MC_MoveRelative", "MC_MoveVelocity", "MC_MoveJog"]


def quiet(o: dict) -> bool:
    return not any(o.get(k) for k in ("Busy", "Done", "CommandAborted", "Error", "InVelocity"))


def start_active(rig: Rig, kind: str, name: str = "act"):
    """Start ``kind`` as the active command (its start input stays TRUE) and let it run for a while;
    returns the instance, which is busy (moving) afterwards."""
    if kind == "MC_Halt":
        rig.add("pre", MC_MoveVelocity(), Velocity=60.0, Execute=True)
        rig.scan_until(lambda s: s["pre"]["InVelocity"], 400, "set-up motion for MC_Halt")
        fb = rig.add(name, MC_Halt(), Execute=True)
    elif kind == "MC_MoveAbsolute":
        fb = rig.add(name, MC_MoveAbsolute(), Position=400.0, Velocity=60.0, Execute=True)
    elif kind == "MC_MoveRelative":
        fb = rig.add(name, MC_MoveRelative(), Distance=400.0, Velocity=60.0, Execute=True)
    elif kind == "MC_MoveVelocity":
        fb = rig.add(name, MC_MoveVelocity(), Velocity=60.0, Execute=True)
    else:
        fb = rig.add(name, MC_MoveJog(), Velocity=60.0, JogForward=True)
    snaps = rig.scans(30)
    assert all(s[name]["Busy"] for s in snaps), f"set-up: {kind} not busy"
    assert rig.axis.Velocity != 0.0
    return fb


def start_new(rig: Rig, kind: str, name: str = "new"):
    """The overriding command: heads for a different velocity/target (-20.0 / position -100)."""
    if kind == "MC_Halt":
        return rig.add(name, MC_Halt(), Execute=True), None
    if kind == "MC_MoveAbsolute":
        return rig.add(name, MC_MoveAbsolute(), Position=-100.0, Velocity=20.0, Execute=True), -100.0
    if kind == "MC_MoveRelative":
        p0 = rig.axis.Position
        return rig.add(name, MC_MoveRelative(), Distance=-100.0, Velocity=20.0, Execute=True), p0 - 100.0
    if kind == "MC_MoveVelocity":
        return rig.add(name, MC_MoveVelocity(), Velocity=-20.0, Execute=True), None
    return rig.add(name, MC_MoveJog(), Velocity=20.0, JogBackward=True), None


def release(fb) -> None:
    if isinstance(fb, MC_MoveJog):
        fb.JogForward = fb.JogBackward = False
    else:
        fb.Execute = False


def homed_rig(**kw) -> Rig:
    rig = Rig(acc=100.0, dec=50.0, **kw)
    rig.home(0.0)
    return rig


@pytest.mark.parametrize("new_kind", MOTION)
@pytest.mark.parametrize("active_kind", MOTION)
def test_s7_1200_11_1_override_matrix_motion_commands(active_kind, new_kind):
    """§11.1.4.1-§11.1.8.1 override lists: every one of MC_Halt, MC_MoveAbsolute, MC_MoveRelative,
    MC_MoveVelocity, MC_MoveJog aborts every other (and itself) when started: the active one shows
    Busy FALSE, CommandAborted TRUE (latched, start input still TRUE); the axis follows the new command."""
    rig = homed_rig()
    act = start_active(rig, active_kind)
    new, target = start_new(rig, new_kind)
    snaps = rig.scans(6)
    ca = calls_with(snaps, "act", "CommandAborted")
    assert ca and ca[0] <= 1, f"{active_kind} not aborted by {new_kind}"
    assert contiguous_to_end(ca, len(snaps)), f"{active_kind}.CommandAborted not latched"
    assert all(not s["act"]["Busy"] for s in snaps[ca[0]:])
    assert all(not s["new"]["CommandAborted"] and not s["new"]["Error"] for s in snaps)
    # the axis now executes the new command
    if new_kind == "MC_Halt":
        end = rig.scan_until(lambda s: s["new"]["Done"], 1000, "MC_Halt Done")
        assert end.vel == 0.0
    elif target is not None:
        end = rig.scan_until(lambda s: s["new"]["Done"], 4000, f"{new_kind} Done")
        assert end.pos == pytest.approx(target, abs=1e-6) and end.vel == 0.0
    else:
        end = rig.scan_until(lambda s: s["new"]["InVelocity"], 2000, f"{new_kind} InVelocity")
        assert end.vel == pytest.approx(-20.0) and end["new"]["Busy"]
    assert calls_with(rig.history[-3:], "act", "CommandAborted") == [0, 1, 2]
    release(act)
    assert quiet(rig.scan()["act"])


@pytest.mark.parametrize("active_kind", ["MC_Halt", "MC_MoveAbsolute", "MC_MoveRelative"])
def test_s7_1200_9_5_2_override_with_execute_false_shows_abort_one_cycle(active_kind):
    """§9.5.2 ⑤ for overridden Done-type commands: Execute already FALSE -> CommandAborted one cycle."""
    rig = homed_rig()
    act = start_active(rig, active_kind)
    release(act)
    rig.scans(3)
    rig.add("new", MC_MoveVelocity(), Velocity=-20.0, Execute=True)
    snaps = rig.scans(6)
    ca = calls_with(snaps, "act", "CommandAborted")
    assert ca == [ca[0]] and ca[0] <= 1, f"CommandAborted calls {ca}"


@pytest.mark.parametrize("mode", [0, 1])
@pytest.mark.parametrize("active_kind", MOTION)
def test_s7_1200_11_1_3_home_direct_neither_aborts_nor_is_aborted(active_kind, mode):
    """§11.1.3.1 Mode 0/1: 'The MC_Home command does not abort any active Motion Control commands' - the
    running command stays Busy, never shows CommandAborted and ends normally; MC_Home shows Done."""
    rig = homed_rig()
    start_active(rig, active_kind)
    home = rig.add("h", MC_Home(), Mode=mode, Position=50.0, Execute=True)
    snaps = rig.scans(10)
    assert calls_with(snaps, "h", "Done"), "MC_Home Mode 0/1 did not complete"
    assert not calls_with(snaps, "h", "CommandAborted") and not calls_with(snaps, "h", "Error")
    assert not calls_with(snaps, "act", "CommandAborted"), f"MC_Home Mode {mode} aborted {active_kind}"
    assert all(s["act"]["Busy"] for s in snaps if not s["act"].get("Done"))
    home.Execute = False
    if active_kind in ("MC_Halt", "MC_MoveAbsolute", "MC_MoveRelative"):
        end = rig.scan_until(lambda s: not s["act"]["Busy"], 4000, f"{active_kind} end")
        assert end["act"]["Done"], f"{active_kind} must end with Done, got {end['act']}"
    else:
        rig.scan_until(lambda s: s["act"]["InVelocity"], 500, f"{active_kind} InVelocity")
        snaps = rig.scans(20)
        assert all(s["act"]["Busy"] and s["act"]["InVelocity"] and s.vel == pytest.approx(60.0) for s in snaps)


def test_s7_1200_11_1_3_home_direct_move_absolute_resumed_in_new_coordinates():
    """§11.1.3.1 Mode 0: 'Position-related motion commands are resumed after homing according to the new
    homing position': MC_MoveAbsolute to 100.0 continues and stops at 100.0 of the new coordinates."""
    rig = homed_rig()
    mv = rig.add("abs", MC_MoveAbsolute(), Position=100.0, Velocity=40.0, Execute=True)
    rig.scan_until(lambda s: s.pos > 30.0, 1000, "half way")
    rig.add("h", MC_Home(), Mode=0, Position=0.0, Execute=True)
    snaps = rig.run_scans_while(lambda s: not s["abs"]["Done"], 3000)
    assert not calls_with(snaps, "abs", "CommandAborted")
    assert snaps[-1].pos == pytest.approx(100.0, abs=1e-6)
    assert mv.Done and rig.axis.Position == pytest.approx(100.0, abs=1e-6)


def test_s7_1200_11_1_3_home_direct_not_aborted_by_motion_started_in_same_cycle():
    """§11.1.3.1 Mode 0/1: 'cannot be aborted by any other Motion Control command' - a motion command
    started in the same cycle right after MC_Home does not make it show CommandAborted."""
    rig = Rig()
    home = rig.add("h", MC_Home(), Mode=0, Position=5.0, Execute=True)
    rig.add("mr", MC_MoveRelative(), Distance=10.0, Velocity=20.0, Execute=True)
    snaps = rig.scans(5)
    assert calls_with(snaps, "h", "Done") and not calls_with(snaps, "h", "CommandAborted")
    assert rig.axis.StatusBits.HomingDone
    assert all(s["mr"]["Busy"] for s in snaps)
    end = rig.scan_until(lambda s: s["mr"]["Done"], 1000, "move done")
    assert end.pos == pytest.approx(15.0, abs=1e-6)
    home.Execute = False


def test_s7_1200_11_1_4_halt_braking_then_aborted_by_motion_command():
    """Function chart S-HALT-1/-2 (§11.1.4.2, Acc 10 / Dec 5): MC_Halt brakes with the configured
    deceleration; while braking another motion command aborts it -> Abort_2 TRUE, Busy_2 FALSE; the
    axis follows the new command."""
    rig = Rig(acc=10.0, dec=5.0)
    rig.add("mv", MC_MoveVelocity(), Velocity=20.0, Execute=True)
    rig.scan_until(lambda s: s["mv"]["InVelocity"], 1000, "velocity 20")
    halt = rig.add("halt", MC_Halt(), Execute=True)
    snaps = rig.scans(100)                                   # 0.4 s of braking at 5.0
    assert calls_with(snaps, "mv", "CommandAborted")
    assert all(s["halt"]["Busy"] for s in snaps)
    assert snaps[-1].vel == pytest.approx(20.0 - 5.0 * (snaps[-1].t - snaps[0].t), abs=0.03)
    rig.add("new", MC_MoveVelocity(), Velocity=30.0, Execute=True)
    snaps = rig.scans(5)
    ca = calls_with(snaps, "halt", "CommandAborted")
    assert ca and ca[0] <= 1 and contiguous_to_end(ca, len(snaps))
    assert not calls_with(snaps, "halt", "Done")
    end = rig.scan_until(lambda s: s["new"]["InVelocity"], 2000, "new velocity")
    assert end.vel == pytest.approx(30.0)
    halt.Execute = False
    assert quiet(rig.scan()["halt"])


def test_s7_1200_11_1_5_override_absolute_by_absolute_without_stop():
    """Function chart S-MABS-2 (§11.1.5.2, Acc/Dec 10): MC_MoveAbsolute_1 to 1000.0 overridden by
    MC_MoveAbsolute_2 to 1500.0 with another velocity -> Abort_1; the axis changes to the new velocity
    and moves to 1500.0 without stopping; Done_2 at 1500.0."""
    rig = Rig(acc=10.0, dec=10.0, max_v=200.0)
    rig.home(0.0)
    m1 = rig.add("m1", MC_MoveAbsolute(), Position=1000.0, Velocity=50.0, Execute=True)
    rig.scan_until(lambda s: s.pos > 400.0, 5000, "position 400")
    m2 = rig.add("m2", MC_MoveAbsolute(), Position=1500.0, Velocity=100.0, Execute=True)
    snaps = rig.run_scans_while(lambda s: not s["m2"]["Done"], 10000)
    ca = calls_with(snaps, "m1", "CommandAborted")
    assert ca and ca[0] <= 1 and all(not s["m1"]["Busy"] for s in snaps[ca[0]:])
    moving = snaps[:-1]
    assert min(s.vel for s in moving) > 0.0, "the axis must not stop between the two commands"
    assert max(s.vel for s in moving) == pytest.approx(100.0), "the new velocity must be used"
    assert min(s.vel for s in moving[:50]) >= 50.0 - 1e-9, "no braking at the override"
    assert snaps[-1].pos == pytest.approx(1500.0, abs=1e-6) and snaps[-1].vel == 0.0
    assert not calls_with(snaps, "m1", "Done")
    m1.Execute = m2.Execute = False


def test_s7_1200_9_3_move_relative_overridden_by_move_absolute():
    """§9.3 'It is possible to override an active MC_MoveRelative command with a MC_MoveAbsolute command'."""
    rig = homed_rig()
    rig.add("rel", MC_MoveRelative(), Distance=300.0, Velocity=60.0, Execute=True)
    rig.scans(50)
    rig.add("abs", MC_MoveAbsolute(), Position=10.0, Velocity=30.0, Execute=True)
    snaps = rig.run_scans_while(lambda s: not s["abs"]["Done"], 3000)
    assert calls_with(snaps, "rel", "CommandAborted")[0] <= 1
    assert snaps[-1].pos == pytest.approx(10.0, abs=1e-6)


def test_s7_1200_11_1_6_override_relative_distance_from_override_position():
    """Function chart S-MREL-2 (§11.1.6.2) and §11.1.6.1 ('relative to the start position'): the overriding
    MC_MoveRelative (Distance 500.0) moves by 500.0 from the position at its start; Abort_1, Done_2."""
    rig = Rig(acc=10.0, dec=10.0, max_v=200.0)
    rig.add("r1", MC_MoveRelative(), Distance=1000.0, Velocity=50.0, Execute=True)
    rig.scan_until(lambda s: s.pos > 300.0, 5000, "position 300")
    r2 = rig.add("r2", MC_MoveRelative(), Distance=500.0, Velocity=80.0)
    start = rig.axis.Position                     # the position at the call that starts the command
    r2.Execute = True
    snaps = rig.run_scans_while(lambda s: not s["r2"]["Done"], 10000)
    assert calls_with(snaps, "r1", "CommandAborted")[0] <= 1
    assert min(s.vel for s in snaps[:-1]) > 0.0
    assert snaps[-1].pos == pytest.approx(start + 500.0, abs=1e-6)


@pytest.mark.parametrize("reached", [True, False], ids=["S-MVEL-1", "S-MVEL-2"])
def test_s7_1200_11_1_7_velocity_overridden_by_velocity(reached):
    """Function charts S-MVEL-1/-2 (§11.1.7.2, Acc/Dec 10): MC_MoveVelocity_1 (after or before reaching its
    velocity) overridden by MC_MoveVelocity_2 (15.0) -> Abort_1; InVel_2 at 15.0, the axis continues."""
    rig = Rig(acc=10.0, dec=10.0)
    rig.add("v1", MC_MoveVelocity(), Velocity=30.0, Execute=True)
    if reached:
        rig.scan_until(lambda s: s["v1"]["InVelocity"], 2000, "InVel_1")
    else:
        rig.scans(100)
    rig.add("v2", MC_MoveVelocity(), Velocity=15.0, Execute=True)
    snaps = rig.run_scans_while(lambda s: not s["v2"]["InVelocity"], 3000)
    ca = calls_with(snaps, "v1", "CommandAborted")
    assert ca and ca[0] <= 1 and contiguous_to_end(ca, len(snaps))
    assert all(not s["v1"]["InVelocity"] for s in snaps[1:])
    assert snaps[-1].vel == pytest.approx(15.0)
    assert all(s["v2"]["Busy"] and s["v2"]["InVelocity"] and s.vel == pytest.approx(15.0) for s in rig.scans(50))


DISABLE_CASES = [(k, True) for k in MOTION] + [(k, False) for k in ("MC_Halt", "MC_MoveAbsolute", "MC_MoveRelative")]


@pytest.mark.parametrize("active_kind", ["MC_MoveVelocity", "MC_MoveJog"])
def test_s7_1200_11_1_1_power_disable_ends_velocity_commands_after_release(active_kind):
    """§11.1.1.1 (disabling aborts all commands) with §9.5.3 ② / §9.5.4: a velocity command whose start
    input is already FALSE is ended by the disable - Busy and InVelocity FALSE (whether CommandAborted is
    shown in this case is not stated by the manual)."""
    rig = homed_rig()
    act = start_active(rig, active_kind)
    if active_kind == "MC_MoveVelocity":
        rig.scan_until(lambda s: s["act"]["InVelocity"], 500, "velocity reached")
    release(act)
    rig.scans(2)
    rig.power.Enable = False
    rig.run_scans_while(lambda s: s["power"]["Status"], 2000)
    snaps = rig.scans(3)
    assert all(not s["act"]["Busy"] and not s["act"]["InVelocity"] for s in snaps)
    assert not calls_with(snaps[1:], "act", "CommandAborted") and not calls_with(snaps, "act", "Error")


@pytest.mark.parametrize("active_kind,held", DISABLE_CASES,
                         ids=[f"{k}-{'held' if h else 'pulse'}" for k, h in DISABLE_CASES])
def test_s7_1200_11_1_1_power_disable_aborts_active_command(active_kind, held):
    """§11.1.1.1 'Disabling the axis (Enable = FALSE) aborts all Motion Control commands': the active
    command shows Busy FALSE and CommandAborted (§9.5.2-§9.5.4: latched while its start input is TRUE,
    else one cycle).  MC_MoveVelocity/MC_MoveJog are only checked with the start input TRUE (the notes of
    §9.5.3/§9.5.4 concern new commands)."""
    rig = homed_rig()
    act = start_active(rig, active_kind)
    if not held:
        release(act)
        rig.scans(2)
    rig.power.Enable = False
    snaps = rig.run_scans_while(lambda s: s["power"]["Status"], 2000)
    snaps += rig.scans(4)
    ca = calls_with(snaps, "act", "CommandAborted")
    assert ca and ca[0] <= 1, f"{active_kind} not aborted by MC_Power Enable = FALSE"
    assert all(not s["act"]["Busy"] for s in snaps[ca[0]:])
    if held:
        assert contiguous_to_end(ca, len(snaps))
    else:
        assert len(ca) == 1
    assert not rig.axis.StatusBits.Enable and rig.axis.Velocity == 0.0


def test_s7_1200_11_1_2_reset_does_not_abort_active_command():
    """§11.1.2.1 'The new MC_Reset command does not abort any other active Motion Control commands'."""
    rig = Rig()
    rig.add("mr", MC_MoveRelative(), Distance=30.0, Velocity=40.0, Execute=True)
    rig.scans(20)
    rig.add("rst", MC_Reset(), Execute=True)
    snaps = rig.run_scans_while(lambda s: not s["mr"]["Done"], 2000)
    assert calls_with(snaps, "rst", "Done")
    assert not calls_with(snaps, "mr", "CommandAborted") and all(s["mr"]["Busy"] for s in snaps[:-1])
    assert snaps[-1].pos == pytest.approx(30.0, abs=1e-6)


REJECTED = [
    ("param_velocity", lambda: MC_MoveRelative(Distance=5.0, Velocity=500.0), 0x8402),
    ("param_distance", lambda: MC_MoveRelative(Distance=5.0e12, Velocity=10.0), 0x8401),
    ("jog_both_inputs", lambda: MC_MoveJog(Velocity=10.0, JogForward=True, JogBackward=True), 0x8406),
    ("not_homed", lambda: MC_MoveAbsolute(Position=5.0, Velocity=10.0), 0x8204),
    ("home_bad_mode", lambda: MC_Home(Mode=9, Position=0.0), 0x8404),
]


@pytest.mark.parametrize("name,make,error_id", REJECTED, ids=[r[0] for r in REJECTED])
def test_s7_1200_9_6_rejected_command_does_not_abort_motion(name, make, error_id):
    """§9.6: operating errors without axis stop and block parameter errors - 'If the axis is in motion, the
    motion is continued. The errors are only indicated in the Motion Control instruction which triggers the
    error.'  The running MC_MoveVelocity is not aborted."""
    rig = Rig()
    rig.add("mv", MC_MoveVelocity(), Velocity=40.0, Execute=True)
    rig.scan_until(lambda s: s["mv"]["InVelocity"], 400, "velocity")
    bad = rig.add("bad", make())
    if hasattr(bad, "Execute"):
        bad.Execute = True
    snaps = rig.scans(10)
    assert snaps[1]["bad"]["Error"] and snaps[1]["bad"]["ErrorID"] == error_id
    assert not calls_with(snaps, "mv", "CommandAborted")
    assert all(s["mv"]["Busy"] and s["mv"]["InVelocity"] and s.vel == pytest.approx(40.0) for s in snaps)
    assert not any(s["power"]["Error"] for s in snaps), "not shown at MC_Power (§9.6)"
