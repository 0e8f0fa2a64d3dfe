"""Status output timelines of the S7-1200 V6 motion instructions, call by call.

Derived from the manual (S7-1200 Motion Control V6.0, TIA Portal V14):
  §9.5.2  instructions with "Done": MC_Reset, MC_Home, MC_Halt, MC_MoveAbsolute, MC_MoveRelative
  §9.5.3  MC_MoveVelocity (incl. the notes on suppressed CommandAborted/Error, and §11.1.7.1 Velocity = 0.0)
  §9.5.4  MC_MoveJog (incl. the notes on one-cycle CommandAborted/Error, §11.1.8.1 both jog inputs TRUE)
One scan of the rig = one call of every instance = one execution cycle of the manual.
"""
from __future__ import annotations

import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from _s7_1200_rig import (MC_Halt, MC_Home, MC_MoveAbsolute, MC_MoveJog, MC_MoveRelative, MC_MoveVelocity,
                          MC_Reset, Rig, calls_with, contiguous_to_end)

FINALS = ("Done", "CommandAborted", "Error")


def quiet(o: dict) -> bool:
    """No status output set (Busy, Done, CommandAborted, Error, InVelocity all FALSE)."""
    return not any(o.get(k) for k in ("Busy", "Done", "CommandAborted", "Error", "InVelocity"))


# ----------------------------------------------------------------------------------------------------------
# §9.5.2 set-ups: a running command of each Done-type instruction, registered as "cmd"
def setup_relative(rig: Rig):
    fb = rig.add("cmd", MC_MoveRelative(), Distance=20.0, Velocity=50.0)
    return fb, rig.axis.Position + 20.0


def setup_absolute(rig: Rig):
    rig.home(0.0)
    fb = rig.add("cmd", MC_MoveAbsolute(), Position=-30.0, Velocity=50.0)
    return fb, -30.0


def setup_halt(rig: Rig):
    mv = rig.add("mv", MC_MoveVelocity(), Velocity=50.0, Execute=True)
    rig.scan_until(lambda s: s["mv"]["InVelocity"], 400, "set-up: MC_MoveVelocity at 50")
    mv.Execute = False
    fb = rig.add("cmd", MC_Halt())
    return fb, None


SETUPS = {"MC_MoveRelative": setup_relative, "MC_MoveAbsolute": setup_absolute, "MC_Halt": setup_halt}


def _check_done_at_standstill(rig: Rig, snaps, target):
    """The call showing Done: axis at standstill (and at the target); not later than one call after the
    setpoint has arrived (§9.5.2 'The command is complete and the axis is at a standstill')."""
    end = snaps[-1]
    assert end["cmd"]["Done"] and not end["cmd"]["Busy"]
    assert end.vel == 0.0
    if target is not None:
        assert end.pos == pytest.approx(target, abs=1e-6)
    arrived = [s.n for s in snaps if s.vel == 0.0 and (target is None or abs(s.pos - target) < 1e-6)]
    assert arrived and end.n - arrived[0] <= 1, "Done shown later than one call after standstill at the target"
    assert not any(s["cmd"]["Done"] for s in snaps[:-1]), "Done before the command finished"


@pytest.mark.parametrize("kind", list(SETUPS))
def test_s7_1200_9_5_2_done_latched_while_execute_true_then_falls_with_execute(kind):
    """§9.5.2 'Complete execution' ②③④: Busy while active; at the end Busy FALSE and Done TRUE; Done stays
    TRUE while Execute stays TRUE and changes to FALSE together with Execute."""
    rig = Rig()
    fb, target = SETUPS[kind](rig)
    fb.Execute = True
    snaps = rig.run_scans_while(lambda s: s["cmd"]["Busy"], 1500)
    assert len(snaps) > 10, "the command should take a while"
    assert all(s["cmd"]["Busy"] and not any(s["cmd"][k] for k in FINALS) for s in snaps[:-1])
    _check_done_at_standstill(rig, snaps, target)
    for s in rig.scans(8):                                   # Execute still TRUE: Done latched
        assert s["cmd"]["Done"] and not s["cmd"]["Busy"], f"scan {s.n}: Done not latched while Execute TRUE"
    fb.Execute = False
    s = rig.scan()
    assert quiet(s["cmd"]), "Done must change to FALSE together with Execute (§9.5.2 ④)"
    assert all(quiet(s["cmd"]) for s in rig.scans(5))


@pytest.mark.parametrize("kind", list(SETUPS))
def test_s7_1200_9_5_2_done_one_cycle_when_execute_already_false(kind):
    """§9.5.2 ①⑤: Execute reset during the command; Busy stays TRUE regardless of Execute; Done TRUE for
    only one execution cycle."""
    rig = Rig()
    fb, target = SETUPS[kind](rig)
    fb.Execute = True
    first = rig.scan()
    assert first["cmd"]["Busy"]
    fb.Execute = False
    snaps = [first] + rig.run_scans_while(lambda s: s["cmd"]["Busy"], 1500)
    assert all(s["cmd"]["Busy"] for s in snaps[:-1]), "Busy must not depend on Execute"
    _check_done_at_standstill(rig, snaps, target)
    assert all(quiet(s["cmd"]) for s in rig.scans(6)), "Done shown for more than one cycle"


@pytest.mark.parametrize("mode,start,position,expected", [(0, 7.5, 123.4, 123.4), (1, 7.5, -20.0, -12.5)])
@pytest.mark.parametrize("held", [True, False], ids=["execute_held", "execute_pulse"])
def test_s7_1200_9_5_2_mc_home_direct_done_timing(mode, start, position, expected, held):
    """§9.5.2 with MC_Home Mode 0/1 (§11.1.3.1): new position (0: Position, 1: position + Position),
    HomingDone TRUE; Done latched while Execute TRUE, else shown for exactly one call."""
    rig = Rig()
    if start:
        rig.add("mr", MC_MoveRelative(), Distance=start, Velocity=50.0, Execute=True)
        rig.scan_until(lambda s: s["mr"]["Done"], 500, "set-up move")
    fb = rig.add("cmd", MC_Home(), Mode=mode, Position=position, Execute=True)
    snaps = rig.scans(1 if not held else 6)
    fb.Execute = False
    snaps += rig.scans(6)
    done = calls_with(snaps, "cmd", "Done")
    assert done, "MC_Home Mode 0/1 never showed Done"
    if held:
        assert done[0] <= 1 and done == list(range(done[0], 6)), f"Done must stay TRUE while Execute TRUE: {done}"
    else:
        assert len(done) == 1 and done[0] <= 1, f"Done must be shown for exactly one call, saw {done}"
    assert not any(s["cmd"]["Error"] or s["cmd"]["CommandAborted"] for s in snaps)
    assert rig.axis.Position == pytest.approx(expected)
    assert rig.axis.StatusBits.HomingDone
    assert snaps[done[0]]["cmd"]["ReferenceMarkPosition"] == pytest.approx(expected)


@pytest.mark.parametrize("held", [True, False], ids=["execute_held", "execute_pulse"])
def test_s7_1200_9_5_2_mc_reset_done_timing_and_no_command_aborted(held):
    """§9.5.2: MC_Reset is a Done-type instruction that cannot be aborted and so has no CommandAborted;
    §11.1.2.1: Done = error acknowledged (StatusBits.Error FALSE)."""
    rig = Rig()
    fb = rig.add("cmd", MC_Reset(), Execute=True)
    assert "CommandAborted" not in fb.outputs
    snaps = rig.scans(1 if not held else 5)
    fb.Execute = False
    snaps += rig.scans(5)
    done = calls_with(snaps, "cmd", "Done")
    if held:
        assert done and done[0] <= 1 and done == list(range(done[0], 5))
    else:
        assert len(done) == 1 and done[0] <= 1
    assert not rig.axis.StatusBits.Error


# ----------------------------------------------------------------------------------------------------------
# §9.5.2 abort and error
@pytest.mark.parametrize("kind", list(SETUPS))
@pytest.mark.parametrize("held", [True, False], ids=["execute_held", "execute_pulse"])
def test_s7_1200_9_5_2_command_aborted_timing(kind, held):
    """§9.5.2 'Abort command' ③④⑤: on abort Busy FALSE and CommandAborted TRUE; latched while Execute TRUE
    and FALSE together with Execute; only one execution cycle when Execute was already FALSE."""
    rig = Rig()
    fb, _ = SETUPS[kind](rig)
    fb.Execute = True
    rig.scans(10 if held else 1)
    if not held:
        fb.Execute = False
        rig.scans(9)
    assert fb.Busy
    new = rig.add("new", MC_MoveRelative(), Distance=-5.0, Velocity=20.0, Execute=True)
    snaps = rig.scans(8)
    ca = calls_with(snaps, "cmd", "CommandAborted")
    assert ca, f"{kind} not aborted by MC_MoveRelative"
    assert ca[0] <= 1, "CommandAborted must appear with the next call after the override"
    assert not snaps[ca[0]]["cmd"]["Busy"]
    if held:
        assert contiguous_to_end(ca, len(snaps)), "CommandAborted not latched while Execute TRUE"
        fb.Execute = False
        assert quiet(rig.scan()["cmd"]), "CommandAborted must fall together with Execute"
    else:
        assert len(ca) == 1, f"CommandAborted shown {len(ca)} calls although Execute was FALSE"
    assert all(quiet(s["cmd"]) for s in rig.scans(3))
    assert new.Busy or new.Done


def _sw_limit_rig(**kw) -> Rig:
    rig = Rig(sw=(-1000.0, 10.0), **kw)
    rig.home(0.0)
    return rig


@pytest.mark.parametrize("kind", ["MC_MoveRelative", "MC_MoveAbsolute"])
@pytest.mark.parametrize("held", [True, False], ids=["execute_held", "execute_pulse"])
def test_s7_1200_9_5_2_error_during_execution_timing(kind, held):
    """§9.5.2 'Error during command execution' ③④⑤ with the high SW limit switch (§12.8 16#8002/16#000E:
    reached with the configured deceleration): Busy FALSE, Error TRUE, latched while Execute TRUE, one
    cycle otherwise.  §9.6: an operating error with axis stop is also shown at MC_Power."""
    rig = _sw_limit_rig()
    if kind == "MC_MoveRelative":
        fb = rig.add("cmd", MC_MoveRelative(), Distance=50.0, Velocity=50.0, Execute=True)
    else:
        fb = rig.add("cmd", MC_MoveAbsolute(), Position=50.0, Velocity=50.0, Execute=True)
    first = rig.scan()
    assert first["cmd"]["Busy"]
    if not held:
        fb.Execute = False
    snaps = [first] + rig.run_scans_while(lambda s: s["cmd"]["Busy"], 1000)
    end = snaps[-1]
    assert end["cmd"]["Error"] and not end["cmd"]["Busy"]
    assert (end["cmd"]["ErrorID"], end["cmd"]["ErrorInfo"]) == (0x8002, 0x000E)
    assert end.pos == pytest.approx(10.0, abs=1e-6) and end.vel == 0.0
    assert end["power"]["Error"] and end["power"]["ErrorID"] == 0x8002
    after = rig.scans(5)
    if held:
        assert all(s["cmd"]["Error"] and s["cmd"]["ErrorID"] == 0x8002 for s in after)
        fb.Execute = False
        after = rig.scans(3)
    assert all(quiet(s["cmd"]) and s["cmd"]["ErrorID"] == 0 for s in after), \
        "Error shown for more than one cycle / not falling together with Execute"


BAD_INPUTS = [
    (MC_MoveRelative, {"Distance": 10.0, "Velocity": 150.0}, (0x8402, 0x0008)),
    (MC_MoveRelative, {"Distance": 10.0, "Velocity": 0.5}, (0x8402, 0x0009)),
    (MC_MoveRelative, {"Distance": 2.0e12, "Velocity": 10.0}, (0x8401, 0x0005)),
    (MC_MoveRelative, {"Distance": math.nan, "Velocity": 10.0}, (0x8401, 0x0002)),
    (MC_MoveAbsolute, {"Position": -2.0e12, "Velocity": 10.0}, (0x8400, 0x0006)),
    (MC_MoveVelocity, {"Velocity": 150.0}, (0x8402, 0x0008)),
    (MC_MoveVelocity, {"Velocity": 10.0, "Direction": 5}, (0x8403, 0x0011)),
    (MC_Home, {"Mode": 4, "Position": 0.0}, (0x8404, 0x0011)),
    (MC_Home, {"Mode": 0, "Position": 2.0e12}, (0x8400, 0x0005)),
]


@pytest.mark.parametrize("cls,inputs,codes", BAD_INPUTS,
                         ids=[f"{c.__name__}-{e[0]:04X}-{e[1]:04X}" for c, _, e in BAD_INPUTS])
@pytest.mark.parametrize("held", [True, False], ids=["execute_held", "execute_pulse"])
def test_s7_1200_9_5_2_parameter_error_at_rising_edge(cls, inputs, codes, held):
    """§9.6 block parameter errors (§12.8 16#8400-16#8404): the command is not executed - Error TRUE at the
    call with the rising edge, Busy never TRUE; Error latched while Execute TRUE (§9.5.2 ④), FALSE with the
    next call once Execute is FALSE; the axis does not move."""
    rig = Rig()
    rig.home(0.0)
    fb = rig.add("cmd", cls(), Execute=True, **inputs)
    snaps = rig.scans(4 if held else 1)
    assert all(s["cmd"]["Error"] and not s["cmd"]["Busy"] for s in snaps)
    assert all((s["cmd"]["ErrorID"], s["cmd"]["ErrorInfo"]) == codes for s in snaps)
    fb.Execute = False
    after = rig.scans(3)
    assert all(quiet(s["cmd"]) for s in after)
    assert rig.axis.Position == 0.0 and rig.axis.Velocity == 0.0
    assert not after[-1]["power"]["Error"], "a block parameter error is shown only at the instruction (§9.6)"


def test_s7_1200_9_5_2_halt_at_standstill_done():
    """§9.5.2 / §11.1.4.1: MC_Halt on an axis at standstill - 'zero velocity reached' at once: Done (one
    cycle with Execute pulsed)."""
    rig = Rig()
    halt = rig.add("cmd", MC_Halt(), Execute=True)
    snaps = rig.scans(1)
    halt.Execute = False
    snaps += rig.scans(4)
    assert calls_with(snaps, "cmd", "Done") in ([0], [1])
    assert not calls_with(snaps, "cmd", "Error") and not calls_with(snaps, "cmd", "CommandAborted")


@pytest.mark.parametrize("cls,inputs,change", [
    (MC_MoveRelative, {"Distance": 20.0, "Velocity": 20.0}, {"Distance": 50.0, "Velocity": 40.0}),
    (MC_MoveAbsolute, {"Position": 20.0, "Velocity": 20.0}, {"Position": -50.0, "Velocity": 40.0}),
    (MC_MoveVelocity, {"Velocity": 20.0}, {"Velocity": 40.0}),
])
def test_s7_1200_9_3_inputs_taken_over_only_at_rising_edge(cls, inputs, change):
    """§9.3: 'Input values are taken over at the rising edge of Execute'; later changes are ignored until
    the next start (exceptions only MC_Power.StopMode and MC_MoveJog.Velocity)."""
    rig = Rig()
    rig.home(0.0)
    fb = rig.add("cmd", cls(), Execute=True, **inputs)
    rig.scans(5)
    for k, v in change.items():
        setattr(fb, k, v)
    snaps = rig.scans(300)
    assert max(abs(s.vel) for s in snaps) == pytest.approx(20.0), "Velocity change must be ignored"
    if cls is not MC_MoveVelocity:
        assert snaps[-1]["cmd"]["Done"] and snaps[-1].pos == pytest.approx(20.0, abs=1e-6)
    else:
        assert snaps[-1]["cmd"]["InVelocity"] and snaps[-1].vel == pytest.approx(20.0)


def test_s7_1200_9_6_move_absolute_not_homed_8204():
    """§11.1.5.1 requirement 'axis is homed' / §12.8 16#8204/16#0001; error latched while Execute TRUE."""
    rig = Rig()
    fb = rig.add("cmd", MC_MoveAbsolute(), Position=10.0, Velocity=10.0, Execute=True)
    snaps = rig.scans(5)
    assert snaps[1]["cmd"]["Error"] and (snaps[1]["cmd"]["ErrorID"], snaps[1]["cmd"]["ErrorInfo"]) == (0x8204, 1)
    assert all(s["cmd"]["Error"] for s in snaps[1:])
    assert rig.axis.Velocity == 0.0
    fb.Execute = False
    assert quiet(rig.scan()["cmd"])


# ----------------------------------------------------------------------------------------------------------
# §9.5.2 as a property: random Execute patterns and overrides keep the output rules
@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.tuples(st.booleans(), st.booleans(), st.integers(1, 30)), min_size=1, max_size=10))
def test_s7_1200_9_5_2_property_random_execute_patterns(segments):
    """§9.5.2 for two MC_MoveRelative instances overriding each other under random Execute patterns:
    Busy/Done/CommandAborted/Error exclusive (checked in every scan by the rig); a final status seen while
    Execute is TRUE stays until Execute falls and is FALSE at the call where Execute is FALSE; one seen with
    Execute FALSE is gone at the next call; Busy falls only with a final status; every command ends with
    exactly one final status kind."""
    rig = Rig()
    a = rig.add("a", MC_MoveRelative(), Distance=1.0, Velocity=50.0)
    b = rig.add("b", MC_MoveRelative(), Distance=-1.0, Velocity=50.0)
    for ea, eb, n in segments + [(False, False, 60)]:
        a.Execute, b.Execute = ea, eb
        rig.scans(n)
    h = [s for s in rig.history if "a" in s.out]
    for name in ("a", "b"):
        seen_kind = None
        for prev, cur in zip(h, h[1:]):
            p, c = prev[name], cur[name]
            pe, ce = prev.inp[name]["Execute"], cur.inp[name]["Execute"]
            edge = ce and not pe
            if edge:
                seen_kind = None
                continue
            fin_p = [k for k in FINALS if p[k]]
            fin_c = [k for k in FINALS if c[k]]
            if fin_c:
                assert seen_kind in (None, fin_c[0]), f"{name}: two different final states for one command"
                seen_kind = fin_c[0]
            if fin_p and pe and ce:
                assert fin_c == fin_p, f"scan {cur.n}: {name}.{fin_p[0]} not latched while Execute TRUE"
            if fin_p and not ce:
                assert not fin_c, f"scan {cur.n}: {name}.{fin_p[0]} shown more than one cycle with Execute FALSE"
            if p["Busy"] and not c["Busy"]:
                assert fin_c, f"scan {cur.n}: {name}.Busy fell without Done/CommandAborted/Error"
            if fin_p and not p["Busy"] and c["Busy"]:
                raise AssertionError(f"scan {cur.n}: {name}.Busy TRUE again without a new rising edge")


# ----------------------------------------------------------------------------------------------------------
# §9.5.3 MC_MoveVelocity
@pytest.mark.parametrize("held", [True, False], ids=["execute_held", "execute_pulse"])
def test_s7_1200_9_5_3_busy_and_invelocity_independent_of_execute(held):
    """§9.5.3 'The parameterized velocity is reached' ①②, §11.1.7.1 PLCopen note: InVelocity TRUE when the
    velocity is reached; Busy and InVelocity stay TRUE regardless of Execute until overridden or error."""
    rig = Rig()
    mv = rig.add("mv", MC_MoveVelocity(), Velocity=50.0, Execute=True)
    first = rig.scan()
    assert first["mv"]["Busy"] and not first["mv"]["InVelocity"]
    if not held:
        mv.Execute = False
    snaps = rig.run_scans_while(lambda s: not s["mv"]["InVelocity"], 400)
    assert all(s["mv"]["Busy"] for s in snaps)
    assert all(s.vel < 50.0 for s in snaps[:-1]), "InVelocity late"
    assert snaps[-1].vel == pytest.approx(50.0)
    mv.Execute = False
    for s in rig.scans(60):
        assert s["mv"]["Busy"] and s["mv"]["InVelocity"], f"scan {s.n}: Busy/InVelocity fell without override"
        assert not (s["mv"]["CommandAborted"] or s["mv"]["Error"])
        assert s.vel == pytest.approx(50.0)
    assert rig.axis.StatusBits.VelocityCommand and rig.axis.StatusBits.ConstantVelocity


def _mv_then_override(held: bool, reached: bool, new_velocity: float = 15.0):
    """MC_MoveVelocity 'mv' (Velocity 50) overridden by a second MC_MoveVelocity 'mv2' (S-MVEL-1/-2)."""
    rig = Rig(acc=10.0 if not reached else 100.0, dec=10.0)
    mv = rig.add("mv", MC_MoveVelocity(), Velocity=50.0, Execute=True)
    rig.scan()
    if not held:
        mv.Execute = False
    if reached:
        rig.scan_until(lambda s: s["mv"]["InVelocity"], 400, "velocity 50 reached")
        rig.scans(5)
    else:
        snaps = rig.scans(40)
        assert not any(s["mv"]["InVelocity"] for s in snaps)
    mv2 = rig.add("mv2", MC_MoveVelocity(), Velocity=new_velocity, Execute=True)
    return rig, mv, mv2


@pytest.mark.parametrize("held", [True, False], ids=["execute_held", "execute_pulse"])
def test_s7_1200_9_5_3_abort_before_velocity_reached(held):
    """§9.5.3 'aborted prior to reaching the parameterized velocity' ③④⑤ (function chart S-MVEL-2):
    Busy FALSE, CommandAborted TRUE - latched while Execute TRUE, one cycle otherwise; the new command
    reaches 15.0 and keeps moving."""
    rig, mv, mv2 = _mv_then_override(held, reached=False)
    snaps = rig.scans(6)
    ca = calls_with(snaps, "mv", "CommandAborted")
    assert ca and ca[0] <= 1
    assert all(not s["mv"]["Busy"] and not s["mv"]["InVelocity"] for s in snaps[1:])
    if held:
        assert contiguous_to_end(ca, len(snaps))
        mv.Execute = False
        assert quiet(rig.scan()["mv"])
    else:
        assert len(ca) == 1
    s = rig.scan_until(lambda s: s["mv2"]["InVelocity"], 1000, "InVel_2")
    assert s.vel == pytest.approx(15.0) and s["mv2"]["Busy"]
    assert all(s["mv2"]["Busy"] and s["mv2"]["InVelocity"] and s.vel == pytest.approx(15.0) for s in rig.scans(20))


def test_s7_1200_9_5_3_abort_after_velocity_reached_with_execute_true_is_shown():
    """§9.5.3 (the note suppresses the abort only when Execute is FALSE) and function chart S-MVEL-1:
    InVel_1 TRUE, then overridden -> Abort_1 TRUE (latched while Execute TRUE), InVel_1 FALSE, Busy_1 FALSE."""
    rig, mv, mv2 = _mv_then_override(held=True, reached=True)
    snaps = rig.scans(6)
    ca = calls_with(snaps, "mv", "CommandAborted")
    assert ca and ca[0] <= 1 and contiguous_to_end(ca, len(snaps))
    assert not snaps[-1]["mv"]["InVelocity"] and not snaps[-1]["mv"]["Busy"]
    mv.Execute = False
    assert quiet(rig.scan()["mv"])
    s = rig.scan_until(lambda s: s["mv2"]["InVelocity"], 1000, "InVel_2")
    assert s.vel == pytest.approx(15.0)


def test_s7_1200_9_5_3_no_abort_shown_after_velocity_reached_with_execute_false():
    """§9.5.3 note: velocity reached, Execute FALSE and a new command starts -> no CommandAborted; Busy and
    InVelocity fall because the command has been overridden (§11.1.7.1 PLCopen note)."""
    rig, mv, mv2 = _mv_then_override(held=False, reached=True)
    snaps = rig.scans(10)
    assert not calls_with(snaps, "mv", "CommandAborted"), "CommandAborted must not be indicated"
    assert not calls_with(snaps, "mv", "Error")
    assert not snaps[1]["mv"]["Busy"] and not snaps[1]["mv"]["InVelocity"]
    assert all(quiet(s["mv"]) for s in snaps[1:])


@pytest.mark.parametrize("held", [True, False], ids=["execute_held", "execute_pulse"])
def test_s7_1200_9_5_3_error_before_velocity_reached(held):
    """§9.5.3 'An error has occurred prior to reaching the parameterized velocity' ③④⑤: high SW limit
    (16#8002) hit while still accelerating -> Busy FALSE, Error TRUE, latched while Execute TRUE, else one
    cycle."""
    rig = Rig(sw=(-1000.0, 5.0), acc=10.0)
    rig.home(0.0)
    mv = rig.add("mv", MC_MoveVelocity(), Velocity=50.0, Execute=True)
    rig.scan()
    if not held:
        mv.Execute = False
    snaps = rig.run_scans_while(lambda s: s["mv"]["Busy"], 1000)
    assert not any(s["mv"]["InVelocity"] for s in snaps)
    end = snaps[-1]
    assert end["mv"]["Error"] and end["mv"]["ErrorID"] == 0x8002 and not end["mv"]["InVelocity"]
    after = rig.scans(4)
    if held:
        assert all(s["mv"]["Error"] and s["mv"]["ErrorID"] == 0x8002 for s in after)
        mv.Execute = False
        after = rig.scans(2)
    assert all(quiet(s["mv"]) for s in after)


def test_s7_1200_9_5_3_no_error_after_velocity_reached_with_execute_false_shown_at_mc_power():
    """§9.5.3 note: velocity reached, Execute FALSE and an axis error occurs (SW limit approached) -> no Error
    at MC_MoveVelocity; the error is only indicated at MC_Power.  The command is stopped -> Busy FALSE."""
    rig = Rig(sw=(-1000.0, 30.0))
    rig.home(0.0)
    mv = rig.add("mv", MC_MoveVelocity(), Velocity=20.0, Execute=True)
    rig.scan()
    mv.Execute = False
    rig.scan_until(lambda s: s["mv"]["InVelocity"], 200, "velocity reached")
    snaps = rig.run_scans_while(lambda s: not s["power"]["Error"], 1000)
    rest = rig.scans(5)
    assert snaps[-1]["power"]["ErrorID"] == 0x8002
    assert rig.axis.StatusBits.Error and rig.axis.Velocity == 0.0
    assert not calls_with(snaps + rest, "mv", "Error"), "Error must not be indicated at MC_MoveVelocity"
    assert all(not s["mv"]["Busy"] and not s["mv"]["InVelocity"] for s in rest)


def test_s7_1200_9_5_3_error_after_velocity_reached_with_execute_true_is_shown():
    """§9.5.3: the note suppresses the error only with Execute FALSE; with Execute TRUE the error is shown
    and latched (④)."""
    rig = Rig(sw=(-1000.0, 30.0))
    rig.home(0.0)
    rig.add("mv", MC_MoveVelocity(), Velocity=20.0, Execute=True)
    rig.scan_until(lambda s: s["mv"]["InVelocity"], 200, "velocity reached")
    snaps = rig.run_scans_while(lambda s: s["mv"]["Busy"], 1000)
    assert snaps[-1]["mv"]["Error"] and snaps[-1]["mv"]["ErrorID"] == 0x8002
    assert all(s["mv"]["Error"] for s in rig.scans(4))


@pytest.mark.parametrize("held", [True, False], ids=["execute_held", "execute_pulse"])
def test_s7_1200_11_1_7_velocity_zero_behaves_like_halt(held):
    """§11.1.7.1 'Velocity = 0.0': aborts active motion, brakes with the configured deceleration; Busy TRUE
    while braking; at standstill InVelocity TRUE for at least one cycle; Busy falls together with
    InVelocity; both latched while Execute TRUE."""
    rig = Rig(acc=100.0, dec=50.0)
    rig.add("mv", MC_MoveVelocity(), Velocity=40.0, Execute=True)
    rig.scan_until(lambda s: s["mv"]["InVelocity"], 200, "velocity 40 reached")
    z = rig.add("z", MC_MoveVelocity(), Velocity=0.0, Execute=True)
    first = rig.scan()
    t0 = first.t
    assert first["z"]["Busy"] and not first["z"]["InVelocity"]
    if not held:
        z.Execute = False
    braking = rig.run_scans_while(lambda s: not s["z"]["InVelocity"], 400)
    assert calls_with(braking, "mv", "CommandAborted"), "the running MC_MoveVelocity must be aborted"
    assert all(s["z"]["Busy"] for s in braking)
    stop = braking[-1]
    assert stop.vel == 0.0 and stop["z"]["Busy"]
    standstill = [s for s in braking if s.vel == 0.0]
    assert stop.n - standstill[0].n <= 1, "InVelocity later than one call after standstill"
    # braked with the configured deceleration 50 from 40 to the start/stop velocity 1 (§5.4.4.4)
    assert standstill[0].t - t0 == pytest.approx((40.0 - 1.0) / 50.0, abs=0.01)
    if held:
        snaps = rig.scans(10)
        assert all(s["z"]["InVelocity"] and s["z"]["Busy"] for s in snaps), "not latched while Execute TRUE"
        z.Execute = False
        assert quiet(rig.scan()["z"]), "InVelocity/Busy must fall with Execute"
    else:
        snaps = rig.scans(6)
        inv = [s["z"]["InVelocity"] for s in snaps]
        busy = [s["z"]["Busy"] for s in snaps]
        assert inv == busy, "Busy must change to FALSE together with InVelocity"
        assert not inv[-1], "InVelocity/Busy stay TRUE although Execute is FALSE"
        assert inv == sorted(inv, reverse=True)
    assert all(quiet(s["z"]) for s in rig.scans(3))


def test_s7_1200_11_1_7_current_true_keeps_current_velocity():
    """§11.1.7.1 Current = TRUE: Velocity/Direction ignored; 'When the axis resumes motion at the current
    velocity, InVelocity returns TRUE'.  The overridden MC_MoveVelocity shows CommandAborted (Execute TRUE)."""
    rig = Rig()
    rig.add("mv", MC_MoveVelocity(), Velocity=30.0, Execute=True)
    rig.scan_until(lambda s: s["mv"]["InVelocity"], 400, "velocity 30")
    cur = rig.add("cur", MC_MoveVelocity(), Velocity=80.0, Direction=2, Current=True, Execute=True)
    snaps = rig.scans(5)
    assert snaps[1]["mv"]["CommandAborted"]
    inv = calls_with(snaps, "cur", "InVelocity")
    assert inv and inv[0] <= 1 and contiguous_to_end(inv, len(snaps))
    assert all(s["cur"]["Busy"] and s.vel == pytest.approx(30.0) for s in snaps)
    cur.Execute = False
    assert all(s["cur"]["InVelocity"] and s.vel == pytest.approx(30.0) for s in rig.scans(20))


@pytest.mark.parametrize("held", [True, False], ids=["execute_held", "execute_pulse"])
def test_s7_1200_11_1_7_velocity_zero_status_bits(held):
    """§11.1.7.1 'Velocity = 0.0': status bit SpeedCommand (V4+: VelocityCommand) is set when the command
    starts, ConstantVelocity is set upon axis standstill; 'Both bits are adapted to the new situation when
    a new motion command is started'."""
    rig = Rig(acc=100.0, dec=50.0)
    rig.add("mv", MC_MoveVelocity(), Velocity=40.0, Execute=True)
    rig.scan_until(lambda s: s["mv"]["InVelocity"], 200, "velocity 40 reached")
    z = rig.add("z", MC_MoveVelocity(), Velocity=0.0, Execute=True)
    rig.scan()
    z.Execute = held
    assert rig.axis.StatusBits.VelocityCommand and not rig.axis.StatusBits.ConstantVelocity
    rig.scan_until(lambda s: s.vel == 0.0, 400, "standstill")
    rig.scans(10)
    bits = rig.axis.StatusBits
    assert bits.ConstantVelocity, "ConstantVelocity must be set at standstill"
    assert bits.VelocityCommand, "VelocityCommand must stay set until a new motion command starts"
    rig.add("mr", MC_MoveRelative(), Distance=5.0, Velocity=20.0, Execute=True)
    rig.scans(3)
    assert rig.axis.StatusBits.PositioningCommand and not rig.axis.StatusBits.VelocityCommand


def test_s7_1200_11_1_7_velocity_zero_at_standstill_reports_invelocity():
    """§11.1.7.1: Velocity = 0.0 on an axis at standstill -> InVelocity TRUE (with Busy) at once, latched
    while Execute TRUE."""
    rig = Rig()
    z = rig.add("z", MC_MoveVelocity(), Velocity=0.0, Execute=True)
    snaps = rig.scans(5)
    inv = calls_with(snaps, "z", "InVelocity")
    assert inv and inv[0] <= 1 and contiguous_to_end(inv, len(snaps))
    assert all(snaps[i]["z"]["Busy"] for i in inv)
    z.Execute = False
    assert quiet(rig.scan()["z"])


# ----------------------------------------------------------------------------------------------------------
# §9.5.4 MC_MoveJog
@pytest.mark.parametrize("direction", ["JogForward", "JogBackward"])
def test_s7_1200_9_5_4_jog_reached_held_released(direction):
    """§9.5.4 'reached and maintained' ①-⑤ and S-JOG-1: Busy from the rising edge; InVelocity when the jog
    velocity is reached and while moving at it; released -> InVelocity FALSE at once, the axis brakes with
    the configured deceleration; at standstill Busy FALSE; no CommandAborted/Error."""
    sign = 1.0 if direction == "JogForward" else -1.0
    rig = Rig(acc=100.0, dec=50.0)
    jog = rig.add("jog", MC_MoveJog(), Velocity=50.0)
    setattr(jog, direction, True)
    first = rig.scan()
    assert first["jog"]["Busy"] and not first["jog"]["InVelocity"]
    snaps = rig.run_scans_while(lambda s: not s["jog"]["InVelocity"], 400)
    assert all(s["jog"]["Busy"] for s in snaps)
    assert snaps[-1].vel == pytest.approx(sign * 50.0)
    assert all(abs(s.vel) < 50.0 for s in snaps[:-1])
    held = rig.scans(20)
    assert all(s["jog"]["InVelocity"] and s["jog"]["Busy"] for s in held)
    setattr(jog, direction, False)
    rel = rig.scan()
    t0 = rel.t
    assert not rel["jog"]["InVelocity"], "InVelocity must fall when the jog input is reset (§9.5.4 ④)"
    assert rel["jog"]["Busy"]
    braking = rig.run_scans_while(lambda s: s["jog"]["Busy"], 500)
    end = braking[-1]
    assert all(not s["jog"]["InVelocity"] for s in braking)
    assert end.vel == 0.0
    standstill = [s for s in [rel] + braking if s.vel == 0.0]
    assert end.n - standstill[0].n <= 1, "Busy must fall when the axis has come to a standstill"
    # configured deceleration 50 from 50 down to the start/stop velocity 1 (§5.4.4.4 ramp-down time)
    assert standstill[0].t - t0 == pytest.approx((50.0 - 1.0) / 50.0, abs=0.01)
    assert all(quiet(s["jog"]) for s in [end] + rig.scans(3))


def test_s7_1200_9_3_jog_velocity_change_while_jogging():
    """§9.3 (MC_MoveJog.Velocity taken over while a jog input is TRUE), function chart S-JOG-2: InVel_1
    resets, the axis brakes to -25.0, InVel_1 TRUE again; after Jog_B reset braked to standstill."""
    rig = Rig(acc=10.0, dec=5.0, max_v=100.0)
    jog = rig.add("jog", MC_MoveJog(), Velocity=50.0, JogBackward=True)
    s = rig.scan_until(lambda s: s["jog"]["InVelocity"], 2000, "InVel_1 at -50")
    assert s.vel == pytest.approx(-50.0)
    jog.Velocity = 25.0
    s = rig.scan()
    assert not s["jog"]["InVelocity"] and s["jog"]["Busy"]
    snaps = rig.run_scans_while(lambda s: not s["jog"]["InVelocity"], 2000)
    assert snaps[-1].vel == pytest.approx(-25.0)
    assert all(-50.0 - 1e-9 <= s.vel <= -25.0 + 1e-9 for s in snaps)
    jog.JogBackward = False
    end = rig.scan_until(lambda s: not s["jog"]["Busy"], 2000, "standstill")
    assert end.vel == 0.0 and quiet(end["jog"])


@pytest.mark.parametrize("reached", [False, True], ids=["accelerating", "at_velocity"])
def test_s7_1200_9_5_4_abort_latched_while_jog_input_true(reached):
    """§9.5.4 'aborted during execution' ③④: Busy FALSE and CommandAborted TRUE (independent of whether the
    velocity was reached); CommandAborted changes to FALSE when the jog input is reset."""
    rig = Rig(acc=100.0 if reached else 10.0)
    jog = rig.add("jog", MC_MoveJog(), Velocity=50.0, JogForward=True)
    if reached:
        rig.scan_until(lambda s: s["jog"]["InVelocity"], 400, "jog velocity")
    else:
        assert not any(s["jog"]["InVelocity"] for s in rig.scans(30))
    rig.add("mv", MC_MoveVelocity(), Velocity=20.0, Execute=True)
    snaps = rig.scans(10)
    ca = calls_with(snaps, "jog", "CommandAborted")
    assert ca and ca[0] <= 1 and contiguous_to_end(ca, len(snaps))
    assert all(not s["jog"]["Busy"] and not s["jog"]["InVelocity"] for s in snaps[1:])
    jog.JogForward = False
    assert all(quiet(s["jog"]) for s in rig.scans(3)), "CommandAborted must fall with the jog input"
    assert rig.fbs["mv"].Busy


def test_s7_1200_9_5_4_abort_while_decelerating_after_release_one_cycle():
    """§9.5.4 note: jog inputs FALSE, axis still decelerating, a new command starts -> CommandAborted for
    only one execution cycle."""
    rig = Rig(dec=10.0)
    jog = rig.add("jog", MC_MoveJog(), Velocity=50.0, JogForward=True)
    rig.scan_until(lambda s: s["jog"]["InVelocity"], 400, "jog velocity")
    jog.JogForward = False
    rig.scans(20)
    assert jog.Busy and rig.axis.Velocity > 0.0
    rig.add("mv", MC_MoveVelocity(), Velocity=20.0, Execute=True)
    snaps = rig.scans(8)
    ca = calls_with(snaps, "jog", "CommandAborted")
    assert len(ca) == 1 and ca[0] <= 1, f"CommandAborted calls: {ca}"
    assert all(not s["jog"]["Busy"] for s in snaps[1:])


def test_s7_1200_11_1_8_both_jog_inputs_while_jogging_8406():
    """§11.1.8.1: JogForward and JogBackward TRUE -> the axis stops with the configured deceleration and
    Error 16#8406/16#0001 is shown (§9.5.4: Busy FALSE, latched while a jog input is TRUE)."""
    rig = Rig(acc=100.0, dec=25.0, emergency=1000.0)
    jog = rig.add("jog", MC_MoveJog(), Velocity=50.0, JogForward=True)
    rig.scan_until(lambda s: s["jog"]["InVelocity"], 400, "jog velocity")
    jog.JogBackward = True
    snaps = rig.scans(3)
    s = snaps[1]
    assert s["jog"]["Error"] and not s["jog"]["Busy"] and not s["jog"]["InVelocity"]
    assert (s["jog"]["ErrorID"], s["jog"]["ErrorInfo"]) == (0x8406, 0x0001)
    t0 = snaps[0].t
    braking = rig.run_scans_while(lambda s: s.vel != 0.0, 600)
    assert all(s["jog"]["Error"] and s["jog"]["ErrorID"] == 0x8406 for s in snaps[1:] + braking)
    # configured deceleration 25 from 50 down to the start/stop velocity 1 (§5.4.4.4 ramp-down time)
    assert braking[-1].t - t0 == pytest.approx((50.0 - 1.0) / 25.0, abs=0.01)
    assert min(s.vel for s in braking) >= 0.0, "the axis must stop, not reverse"
    jog.JogForward = False
    assert all(s["jog"]["Error"] for s in rig.scans(3)), "JogBackward still TRUE: Error stays latched"
    jog.JogBackward = False
    assert all(quiet(s["jog"]) for s in rig.scans(2))


def test_s7_1200_11_1_8_both_jog_inputs_from_standstill_8406():
    """§11.1.8.1 / §12.8 16#8406: both jog inputs TRUE at once -> Error, no motion."""
    rig = Rig()
    jog = rig.add("jog", MC_MoveJog(), Velocity=50.0, JogForward=True, JogBackward=True)
    snaps = rig.scans(4)
    assert all(s["jog"]["Error"] and s["jog"]["ErrorID"] == 0x8406 and not s["jog"]["Busy"] for s in snaps)
    assert rig.axis.Velocity == 0.0 and rig.axis.Position == 0.0
    jog.JogForward = jog.JogBackward = False
    assert quiet(rig.scan()["jog"])


def test_s7_1200_11_1_8_invalid_jog_velocity_error_latched_while_jog_input_true():
    """§11.1.8.1 Velocity limits (start/stop <= Velocity <= max), §12.8 16#8402/16#0008; §9.5.4 Error latched
    while the jog input is TRUE; no motion."""
    rig = Rig()
    jog = rig.add("jog", MC_MoveJog(), Velocity=150.0, JogBackward=True)
    snaps = rig.scans(4)
    assert all(s["jog"]["Error"] and not s["jog"]["Busy"] for s in snaps)
    assert (snaps[-1]["jog"]["ErrorID"], snaps[-1]["jog"]["ErrorInfo"]) == (0x8402, 0x0008)
    assert rig.axis.Velocity == 0.0
    jog.JogBackward = False
    assert quiet(rig.scan()["jog"])


def test_s7_1200_9_5_4_error_latched_while_jog_input_true():
    """§9.5.4 'An error has occurred' ③④: SW limit reached while jogging -> Busy FALSE, Error TRUE until
    the jog input is reset."""
    rig = Rig(sw=(-1000.0, 20.0))
    rig.home(0.0)
    jog = rig.add("jog", MC_MoveJog(), Velocity=50.0, JogForward=True)
    snaps = rig.run_scans_while(lambda s: s["jog"]["Busy"], 1000)
    end = snaps[-1]
    assert end["jog"]["Error"] and end["jog"]["ErrorID"] == 0x8002 and end.pos == pytest.approx(20.0)
    assert all(s["jog"]["Error"] for s in rig.scans(5))
    jog.JogForward = False
    assert all(quiet(s["jog"]) for s in rig.scans(2))


def test_s7_1200_9_5_4_error_while_decelerating_after_release_one_cycle():
    """§9.5.4 note: jog inputs FALSE, axis still decelerating, a new error occurs (SW limit approached) ->
    Error for only one execution cycle.  The SW limit is brought into the braking path by MC_Home Mode 0
    during the braking (§12.4.1 example 3)."""
    rig = Rig(sw=(-1000.0, 1000.0), acc=100.0, dec=10.0, emergency=1000.0)
    rig.home(0.0)
    jog = rig.add("jog", MC_MoveJog(), Velocity=50.0, JogForward=True)
    rig.scan_until(lambda s: s["jog"]["InVelocity"], 400, "jog velocity")
    jog.JogForward = False
    rig.scans(25)                      # braking: v ~ 46, 100+ units still to go
    assert jog.Busy and rig.axis.Velocity > 40.0
    rig.add("h", MC_Home(), Mode=0, Position=960.0, Execute=True)
    snaps = rig.run_scans_while(lambda s: s["jog"]["Busy"], 400)
    snaps += rig.scans(5)
    err = calls_with(snaps, "jog", "Error")
    assert len(err) == 1, f"jog Error shown in calls {err}; expected exactly one"
    s = snaps[err[0]]
    assert s["jog"]["ErrorID"] == 0x8002
    assert rig.axis.Position <= 1000.0 + 1e-6


# ----------------------------------------------------------------------------------------------------------
# §9.5.3 / §9.5.4 as properties
def _edge(prev, cur, name, key):
    return cur.inp[name][key] and not prev.inp[name][key]


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.tuples(st.booleans(), st.booleans(), st.integers(1, 40)), min_size=1, max_size=10))
def test_s7_1200_9_5_3_property_two_velocity_commands(segments):
    """§9.5.3 for two MC_MoveVelocity instances (+20 / -20) under random Execute patterns: InVelocity only
    at the commanded velocity and, once reached, kept (with Busy) until another command takes over;
    CommandAborted shown after an override unless the velocity was reached and Execute is FALSE;
    CommandAborted latched while Execute TRUE, gone at the call where Execute is FALSE."""
    rig = Rig(acc=200.0, dec=200.0)
    a = rig.add("a", MC_MoveVelocity(), Velocity=20.0)
    b = rig.add("b", MC_MoveVelocity(), Velocity=-20.0)
    for ea, eb, n in segments + [(False, False, 5)]:
        a.Execute, b.Execute = ea, eb
        rig.scans(n)
    h = [s for s in rig.history if "a" in s.out]
    v = {"a": 20.0, "b": -20.0}
    for x, y in (("a", "b"), ("b", "a")):
        for k in range(1, len(h) - 1):
            prev, cur = h[k], h[k + 1]
            p, c = prev[x], cur[x]
            if c["InVelocity"]:
                assert cur.vel == pytest.approx(v[x]) and c["Busy"], f"scan {cur.n}: {x}.InVelocity off-velocity"
            if _edge(prev, cur, x, "Execute"):
                continue
            # y is called after x ("a" before "b"): y's start in scan k is seen by x in scan k+1;
            # y called before x: y's start in scan k+1 is seen by x in the same scan
            y_start = _edge(h[k - 1], prev, y, "Execute") if x == "a" else _edge(prev, cur, y, "Execute")
            if p["CommandAborted"] and not cur.inp[x]["Execute"]:
                assert not c["CommandAborted"], f"scan {cur.n}: {x}.CommandAborted with Execute FALSE"
            if p["CommandAborted"] and prev.inp[x]["Execute"] and cur.inp[x]["Execute"]:
                assert c["CommandAborted"], f"scan {cur.n}: {x}.CommandAborted not latched"
            if p["Busy"] and not y_start:
                assert c["Busy"], f"scan {cur.n}: {x}.Busy fell without override"
                if p["InVelocity"]:
                    assert c["InVelocity"], f"scan {cur.n}: {x}.InVelocity fell without override"
            if p["Busy"] and y_start:
                assert not c["Busy"] and not c["InVelocity"], f"scan {cur.n}: {x} not overridden"
                if prev.inp[x]["Execute"] != cur.inp[x]["Execute"]:
                    continue                           # Execute changed together with the override
                if p["InVelocity"] and not cur.inp[x]["Execute"]:
                    assert not c["CommandAborted"], f"scan {cur.n}: {x}: abort shown (§9.5.3 note)"
                else:
                    assert c["CommandAborted"], f"scan {cur.n}: {x}: abort not shown"


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.tuples(st.sampled_from(["-", "F", "B", "FB"]), st.booleans(), st.integers(1, 40)),
                min_size=1, max_size=10))
def test_s7_1200_9_5_4_property_jog_with_interfering_commands(segments):
    """§9.5.4 for MC_MoveJog under random jog inputs and MC_MoveVelocity starts: InVelocity only while a
    jog input is TRUE and at the jog velocity; Busy falls only at standstill, with CommandAborted or with
    Error; CommandAborted/Error latched while a jog input is TRUE, FALSE when both are reset, shown for
    only one cycle when both inputs were already FALSE; both inputs TRUE -> 16#8406."""
    rig = Rig(acc=200.0, dec=100.0)
    jog = rig.add("jog", MC_MoveJog(), Velocity=20.0)
    mv = rig.add("mv", MC_MoveVelocity(), Velocity=10.0)
    for inputs, ex, n in segments + [("-", False, 40)]:
        jog.JogForward, jog.JogBackward = "F" in inputs, "B" in inputs
        mv.Execute = ex
        rig.scans(n)
    h = [s for s in rig.history if "jog" in s.out]
    held = lambda s: s.inp["jog"]["JogForward"] or s.inp["jog"]["JogBackward"]  # noqa: E731
    for k in range(1, len(h) - 1):
        prev, cur = h[k], h[k + 1]
        p, c = prev["jog"], cur["jog"]
        if c["InVelocity"]:
            assert held(cur) and c["Busy"], f"scan {cur.n}: InVelocity without jog input"
            sign = 1.0 if cur.inp["jog"]["JogForward"] else -1.0
            assert cur.vel == pytest.approx(sign * 20.0), f"scan {cur.n}: InVelocity off-velocity"
        if cur.inp["jog"]["JogForward"] and cur.inp["jog"]["JogBackward"] and \
                not (prev.inp["jog"]["JogForward"] and prev.inp["jog"]["JogBackward"]):
            assert c["Error"] and c["ErrorID"] == 0x8406, f"scan {cur.n}: both jog inputs without 16#8406"
        if _edge(prev, cur, "jog", "JogForward") or _edge(prev, cur, "jog", "JogBackward"):
            continue
        for flag in ("CommandAborted", "Error"):
            if p[flag] and held(prev) and held(cur):
                assert c[flag], f"scan {cur.n}: {flag} not latched while a jog input is TRUE"
            if p[flag] and not held(cur):
                assert not c[flag], f"scan {cur.n}: {flag} kept although both jog inputs are FALSE"
        if p["Busy"] and not c["Busy"]:
            mv_start = _edge(h[k - 1], prev, "mv", "Execute")          # mv is called after jog
            if mv_start:
                assert c["CommandAborted"], f"scan {cur.n}: jog overridden without CommandAborted"
            elif not c["Error"]:
                assert cur.vel == 0.0 and not held(cur), f"scan {cur.n}: Busy fell before standstill"
