"""The command interaction of S7-Technology V4.1 §6.8 through the real FBs, OB1 call by OB1 call: the rules
R1-R7 and R17 of catalog part 2 §8.4 as the FB texts of §6.2 / §6.7.1 state them (the synchronous rules R10-R15
and MC_MoveToEndPos (R8) come with their FBs).  Virtual axes; positions and speeds are the kinematics of the
inputs, ErrorIDs those of the FBs' tables.
"""
from __future__ import annotations

import pytest

from plcmotion.s7t import (MC_Halt, MC_MoveAbsolute, MC_MoveAdditive, MC_MoveRelative, MC_MoveSuperImposed,
                           MC_MoveVelocity, MC_Power, MC_Reset, MC_Stop)
from plcmotion.s7t import errors as E
from plcmotion.s7t.technology import override as O
from plcmotion.s7t.technology.axes import RESTART_TIME

from _s7t_rig import VIRTUAL, controller

DYN = dict(Acceleration=100.0, Deceleration=100.0, Jerk=0.0)


class Rig:
    """One virtual axis whose MC_Power is called in every OB1 cycle with ``self.enable``."""

    def __init__(self):
        self.ctl = ctl = controller()
        self.axis = axis = ctl.add_positioning_axis("Axis1", VIRTUAL)
        self.power = MC_Power()
        self.enable = True

        @ctl.program
        def ob1() -> None:
            self.power(Axis=axis, Enable=self.enable)
        ctl.run(0.1)
        assert self.power.Status

    def p(self) -> float:
        return float(self.ctl.bank.sp_p[self.axis.index])

    def v(self) -> float:
        return float(self.ctl.bank.sp_v[self.axis.index])


# the motion FBs a held MC_Stop refuses, each with inputs that would move the axis
MOTION_CALLS = [
    (MC_Halt, dict(Deceleration=10.0)),
    (MC_MoveAbsolute, dict(Position=50.0, Velocity=10.0, **DYN)),
    (MC_MoveAbsolute, dict(Position=50.0, Velocity=10.0, Mode=1, **DYN)),
    (MC_MoveRelative, dict(Distance=50.0, Velocity=10.0, Mode=2, **DYN)),
    (MC_MoveAdditive, dict(Distance=50.0, Velocity=10.0, **DYN)),
    (MC_MoveVelocity, dict(Velocity=10.0, **DYN)),
    (MC_MoveVelocity, dict(Velocity=10.0, Mode=1, **DYN)),
    (MC_MoveSuperImposed, dict(Distance=5.0, VelocityDiff=10.0, **DYN)),
]


# --- R2: MC_Stop ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize("fb, inputs", MOTION_CALLS, ids=lambda x: getattr(x, "__name__", ""))
@pytest.mark.parametrize("phase", ["braking", "standstill"])
def test_s7t_rule_stop_locks_every_motion_command(fb, inputs, phase):
    """S7-Technology V4.1 §6.2.3 and the ErrorID tables of §6.2.4-§6.2.10: while MC_Stop brakes, and at
    standstill while its Execute is TRUE, every motion command is refused with 16#8045; once Execute is
    FALSE (MC_Stop Done) the same command starts."""
    rig = Rig()
    move, stop = MC_MoveVelocity(), MC_Stop()
    move(Axis=rig.axis, Execute=True, Velocity=40.0, **DYN)
    rig.ctl.run(0.5)
    stop(Axis=rig.axis, Execute=True, Deceleration=20.0, Jerk=0.0)
    rig.ctl.run(0.2 if phase == "braking" else 2.5)
    assert (rig.v() > 0.0) == (phase == "braking")
    new = fb()
    new(Axis=rig.axis, Execute=True, **inputs)
    assert new.Error and new.ErrorID == 0x8045 and not new.Busy and not new.ENO
    assert stop(Execute=True).Busy and not stop.CommandAborted
    rig.ctl.run_until(lambda: rig.v() == 0.0, 3.0)
    stop(Execute=False)
    assert stop.Done
    new(Execute=False)
    new(Axis=rig.axis, Execute=True, **inputs)
    assert not new.Error and (new.Busy or new.Done)


def test_s7t_rule_stop_ends_basic_and_superimposed_motion():
    """S7-Technology V4.1 §6.2.3 (MC_Stop stops all motions of the axis): a running positioning and a
    superimposed positioning both end CommandAborted in the call that starts MC_Stop; the axis stands still
    after v/a = 40/100 + 10/100 s."""
    rig = Rig()
    move, sup, stop = MC_MoveRelative(), MC_MoveSuperImposed(), MC_Stop()
    move(Axis=rig.axis, Execute=True, Distance=500.0, Velocity=40.0, **DYN)
    rig.ctl.run(0.6)
    sup(Axis=rig.axis, Execute=True, Distance=100.0, VelocityDiff=10.0, **DYN)
    rig.ctl.run(0.2)
    assert rig.v() == pytest.approx(50.0, abs=1e-6)
    stop(Axis=rig.axis, Execute=True, Deceleration=100.0, Jerk=0.0)
    assert move(Execute=True).CommandAborted and sup(Execute=True).CommandAborted
    rig.ctl.run(0.52)
    assert rig.v() == 0.0 and stop(Execute=True).Busy


def test_s7t_rule_stop_is_aborted_only_by_stop():
    """S7-Technology V4.1 §6.2.3: only another MC_Stop sets MC_Stop's CommandAborted; motion commands are
    refused (8045) and MC_Power Enable = FALSE disables the axis without aborting it (R1 exception)."""
    rig = Rig()
    stop, halt, move = MC_Stop(), MC_Halt(), MC_MoveVelocity()
    stop(Axis=rig.axis, Execute=True)
    rig.ctl.run(0.05)
    halt(Axis=rig.axis, Execute=True)
    move(Axis=rig.axis, Execute=True, Velocity=5.0, **DYN)
    assert halt.ErrorID == 0x8045 and move.ErrorID == 0x8045
    rig.enable = False
    rig.ctl.run(0.1)
    assert rig.axis.state == "disabled" and stop(Execute=True).Busy and not stop.CommandAborted
    other = MC_Stop()
    other(Axis=rig.axis, Execute=True)
    assert stop(Execute=True).CommandAborted and not stop.Busy and other.Busy


# --- R1: MC_Power ----------------------------------------------------------------------------------------------
def test_s7t_rule_power_off_aborts_all_commands():
    """S7-Technology V4.1 §6.2.1 (Enable = FALSE aborts all commands of the axis; Enable = TRUE none): the
    running positioning, the command waiting behind it (Mode 1) and the superimposed positioning end
    CommandAborted in the OB1 cycle that disables."""
    rig = Rig()
    move, queued, sup = MC_MoveRelative(), MC_MoveRelative(), MC_MoveSuperImposed()
    move(Axis=rig.axis, Execute=True, Distance=500.0, Velocity=40.0, **DYN)
    queued(Axis=rig.axis, Execute=True, Distance=10.0, Velocity=40.0, Mode=1, **DYN)
    sup(Axis=rig.axis, Execute=True, Distance=100.0, VelocityDiff=10.0, **DYN)
    rig.ctl.run(0.3)
    assert move(Execute=True).Busy and queued(Execute=True).Busy and sup(Execute=True).Busy
    rig.power(Axis=rig.axis, Enable=True)                   # Enable TRUE again: aborts nothing
    assert move(Execute=True).Busy and queued(Execute=True).Busy and sup(Execute=True).Busy
    rig.enable = False
    rig.ctl.step()
    assert move(Execute=True).CommandAborted and queued(Execute=True).CommandAborted
    assert sup(Execute=True).CommandAborted


# --- R3: MC_Halt -----------------------------------------------------------------------------------------------
@pytest.mark.parametrize("fb, inputs", [
    (MC_MoveAbsolute, dict(Position=500.0, Velocity=10.0, Mode=1, **DYN)),
    (MC_MoveAbsolute, dict(Position=500.0, Velocity=10.0, Mode=2, **DYN)),
    (MC_MoveRelative, dict(Distance=50.0, Velocity=10.0, Mode=1, **DYN)),
    (MC_MoveRelative, dict(Distance=50.0, Velocity=10.0, Mode=2, **DYN)),
    (MC_MoveVelocity, dict(Velocity=10.0, Mode=1, **DYN)),
], ids=["abs1", "abs2", "rel1", "rel2", "vel1"])
def test_s7t_rule_no_append_onto_halt(fb, inputs):
    """S7-Technology V4.1 §6.2.4 / ErrorID 8055 of §6.2.6, §6.2.7, §6.2.10: Mode 1 or 2 onto a running
    MC_Halt is refused with 16#8055, MC_Halt goes on and is Done at standstill (40/10 = 4 s)."""
    rig = Rig()
    move, halt = MC_MoveVelocity(), MC_Halt()
    move(Axis=rig.axis, Execute=True, Velocity=40.0, **DYN)
    rig.ctl.run(0.5)
    halt(Axis=rig.axis, Execute=True, Deceleration=10.0, Jerk=0.0)
    rig.ctl.run(1.0)
    new = fb()
    new(Axis=rig.axis, Execute=True, **inputs)
    assert new.Error and new.ErrorID == 0x8055
    assert halt(Execute=True).Busy and rig.v() == pytest.approx(30.0, abs=0.05)
    rig.ctl.run_until(lambda: halt(Execute=True).Done, 3.5)
    assert rig.v() == 0.0


def test_s7t_rule_superimposed_runs_beside_halt():
    """S7-Technology V4.1 §6.2.4 / §6.2.9: MC_MoveSuperImposed during MC_Halt runs superimposed without
    aborting it; MC_Halt is Done when the basic motion stands still while the superimposed one goes on."""
    rig = Rig()
    move, halt, sup = MC_MoveVelocity(), MC_Halt(), MC_MoveSuperImposed()
    move(Axis=rig.axis, Execute=True, Velocity=20.0, **DYN)
    rig.ctl.run(0.5)
    halt(Axis=rig.axis, Execute=True, Deceleration=100.0, Jerk=0.0)
    sup(Axis=rig.axis, Execute=True, Distance=30.0, VelocityDiff=10.0, **DYN)
    assert halt(Execute=True).Busy and sup.Busy and not halt.CommandAborted
    rig.ctl.run_until(lambda: halt(Execute=True).Done, 1.0)
    assert sup(Execute=True).Busy and rig.v() == pytest.approx(10.0, abs=1e-6)
    rig.ctl.run_until(lambda: sup(Execute=True).Done, 5.0)


# --- R4 / R5: Mode 0 and Mode 1, one waiting command -----------------------------------------------------------
def test_s7t_rule_mode_zero_aborts_mode_one_waits():
    """S7-Technology V4.1 §6.2.6: Mode 0 aborts the running positioning (CommandAborted in the same call);
    Mode 1 waits: the running one is Done at its target, then the waiting one runs from there."""
    rig = Rig()
    a, b, c = MC_MoveAbsolute(), MC_MoveAbsolute(), MC_MoveRelative()
    a(Axis=rig.axis, Execute=True, Position=300.0, Velocity=40.0, **DYN)
    rig.ctl.run(0.5)
    b(Axis=rig.axis, Execute=True, Position=100.0, Velocity=40.0, **DYN)
    assert a(Execute=True).CommandAborted and b.Busy
    c(Axis=rig.axis, Execute=True, Distance=-50.0, Velocity=40.0, Mode=1, **DYN)
    assert c.Busy and b(Execute=True).Busy
    rig.ctl.run_until(lambda: b(Execute=True).Done, 10.0)
    assert rig.p() == pytest.approx(100.0, abs=1e-6) and c(Execute=True).Busy
    rig.ctl.run_until(lambda: c(Execute=True).Done, 10.0)
    assert rig.p() == pytest.approx(50.0, abs=1e-6)


def test_s7t_rule_second_waiting_command_is_refused():
    """S7-Technology V4.1 ErrorID 8005 (command memory full): one command waits behind the running one, a
    second gets 16#8005 and the first still runs after both."""
    rig = Rig()
    run, wait1, wait2 = MC_MoveRelative(), MC_MoveVelocity(), MC_MoveAbsolute()
    run(Axis=rig.axis, Execute=True, Distance=100.0, Velocity=40.0, **DYN)
    wait1(Axis=rig.axis, Execute=True, Velocity=5.0, Mode=1, **DYN)
    wait2(Axis=rig.axis, Execute=True, Position=0.0, Velocity=5.0, Mode=1, **DYN)
    assert wait1.Busy and wait2.Error and wait2.ErrorID == 0x8005
    rig.ctl.run_until(lambda: run(Execute=True).Done, 10.0)
    rig.ctl.run_until(lambda: wait1(Execute=True).InVelocity, 2.0)
    assert rig.v() == pytest.approx(5.0)


def test_s7t_rule_velocity_not_appended_to_velocity():
    """S7-Technology V4.1 §6.2.10 Prerequisites: MC_MoveVelocity Mode 1 onto a running MC_MoveVelocity:
    16#8055; a positioning may wait behind it and takes over when the velocity is reached (30/100 = 0.3 s),
    which ends MC_MoveVelocity (it has no Done: CommandAborted); it moves 20 from there."""
    rig = Rig()
    vel, again, pos = MC_MoveVelocity(), MC_MoveVelocity(), MC_MoveRelative()
    p0 = rig.p()
    vel(Axis=rig.axis, Execute=True, Velocity=30.0, **DYN)
    again(Axis=rig.axis, Execute=True, Velocity=10.0, Mode=1, **DYN)
    assert again.Error and again.ErrorID == 0x8055 and vel(Execute=True).Busy
    pos(Axis=rig.axis, Execute=True, Distance=20.0, Velocity=30.0, Mode=1, **DYN)
    assert pos.Busy and not pos.Error
    rig.ctl.run(0.28)
    assert vel(Execute=True).Busy and not vel.CommandAborted
    rig.ctl.run(0.04)
    assert vel(Execute=True).CommandAborted and pos(Execute=True).Busy
    p_start = 0.5 * 30.0 * 0.3                      # where the velocity was reached
    rig.ctl.run_until(lambda: pos(Execute=True).Done, 3.0)
    assert rig.p() - p0 == pytest.approx(p_start + 20.0, abs=0.07)   # + up to one servo cycle at 30


# --- R6: MC_MoveAdditive ---------------------------------------------------------------------------------------
def test_s7t_rule_additive_aborts_and_moves_from_the_old_target():
    """S7-Technology V4.1 §6.2.8: MC_MoveAdditive aborts the running positioning (CommandAborted) and ends
    at its target + Distance (100 + 30)."""
    rig = Rig()
    move, add = MC_MoveRelative(), MC_MoveAdditive()
    p0 = rig.p()
    move(Axis=rig.axis, Execute=True, Distance=100.0, Velocity=40.0, **DYN)
    rig.ctl.run(0.5)
    add(Axis=rig.axis, Execute=True, Distance=30.0, Velocity=40.0, **DYN)
    assert move(Execute=True).CommandAborted and add.Busy
    rig.ctl.run_until(lambda: add(Execute=True).Done, 10.0)
    assert rig.p() - p0 == pytest.approx(130.0, abs=1e-6)


# --- R7: MC_MoveSuperImposed -----------------------------------------------------------------------------------
def test_s7t_rule_superimposed_over_a_positioning():
    """S7-Technology V4.1 §6.2.9: MC_MoveSuperImposed does not abort the running positioning (it is Done at its
    own target); a second MC_MoveSuperImposed aborts the first, whose rest is lost: after 1 s the first has
    gone 0.5 * 100 * 0.1^2 + 10 * 0.9 = 9.5, so the axis ends at 100 + 9.5 + 20."""
    rig = Rig()
    move, sup, sup2 = MC_MoveRelative(), MC_MoveSuperImposed(), MC_MoveSuperImposed()
    p0 = rig.p()
    move(Axis=rig.axis, Execute=True, Distance=100.0, Velocity=20.0, **DYN)
    rig.ctl.run(0.5)
    sup(Axis=rig.axis, Execute=True, Distance=50.0, VelocityDiff=10.0, **DYN)
    assert move(Execute=True).Busy and not move.CommandAborted
    rig.ctl.run(1.0)
    sup2(Axis=rig.axis, Execute=True, Distance=20.0, VelocityDiff=10.0, **DYN)
    assert sup(Execute=True).CommandAborted and sup2.Busy and move(Execute=True).Busy
    rig.ctl.run_until(lambda: move(Execute=True).Done and sup2(Execute=True).Done, 20.0)
    assert not move.CommandAborted and rig.p() - p0 == pytest.approx(129.5, abs=0.05)


# --- R17: restart ----------------------------------------------------------------------------------------------
def test_s7t_rule_restart_refuses_commands():
    """S7-Technology V4.1 §6.7.1 / §6.8.3: while MC_Reset Restart = TRUE runs, the object takes no command:
    another MC_Reset and MC_Power Enable = TRUE get 16#8045; after the restart MC_Power enables it."""
    rig = Rig()
    rig.enable = False
    rig.ctl.run(0.1)
    restart, again = MC_Reset(), MC_Reset()
    restart(Axis=rig.axis, Execute=True, Restart=True)
    assert restart.Busy
    again(Axis=rig.axis, Execute=True)
    assert again.Error and again.ErrorID == 0x8045
    rig.enable = True
    rig.ctl.step()
    assert rig.power.Error and rig.power.ErrorID == 0x8045 and not rig.power.Status
    rig.ctl.run(RESTART_TIME + 0.1)
    assert restart(Execute=True).Done and rig.power.Status and not rig.power.Error


@pytest.mark.parametrize("fb, inputs", [
    (MC_Halt, dict(Deceleration=100.0)),
    (MC_MoveAbsolute, dict(Position=0.0, Velocity=10.0, **DYN)),
    (MC_MoveRelative, dict(Distance=5.0, Velocity=10.0, **DYN)),
    (MC_MoveAdditive, dict(Distance=5.0, Velocity=10.0, **DYN)),
    (MC_MoveVelocity, dict(Velocity=10.0, **DYN)),
], ids=["halt", "abs", "rel", "add", "vel"])
def test_s7t_rule_basic_motion_ends_superimposed_motion(fb, inputs):
    """S7-Technology V4.1 §6.2.2 (only the MC_Home Mode 7 configuration keeps a superimposed motion when a basic
    motion starts; D16): a new basic motion command ends a running MC_MoveSuperImposed with CommandAborted."""
    rig = Rig()
    move, sup = MC_MoveVelocity(), MC_MoveSuperImposed()
    move(Axis=rig.axis, Execute=True, Velocity=20.0, **DYN)
    rig.ctl.run(0.3)
    sup(Axis=rig.axis, Execute=True, Distance=100.0, VelocityDiff=10.0, **DYN)
    rig.ctl.run(0.3)
    assert sup(Execute=True).Busy
    new = fb()
    new(Axis=rig.axis, Execute=True, **inputs)
    assert not new.Error and sup(Execute=True).CommandAborted and move(Execute=True).CommandAborted


# --- the ErrorIDs of the refusals at the FB ----------------------------------------------------------------------
@pytest.mark.parametrize("reject, error_id, warning", [
    (O.STOP_ACTIVE, 0x8045, False),          # "MC_Stop active" (§6.2.4-§6.2.11 ErrorID tables)
    (O.RESTARTING, 0x8045, False),           # "MC_Reset (Restart = TRUE) is already active" (§6.7.1)
    (O.END_POS_ACTIVE, 0x8045, False),       # MC_Home Mode 0/1 while MC_MoveToEndPos is active (§6.2.2)
    (O.END_POS_REVERSE, 0x8045, False),      # MC_MoveToEndPos reversing while clamped (§6.2.11)
    (O.END_POS_IGNORED, 0x0029, True),       # warning: MC_MoveToEndPos ignored in reverse direction (§6.2.11)
    (O.CLAMPED_AT_STOP, 0x8056, False),      # cancellation due to active travel to fixed stop
    (O.LATCHING, 0x8055, False),             # appending / overlaying not allowed in the current state
], ids=lambda x: getattr(x, "detail", None) or getattr(x, "kind", None) or str(x))
def test_s7t_rule_refusal_error_ids(reject, error_id, warning):
    """S7-Technology V4.1 §6.2 ErrorID tables, §5.10: each refusal of the command interaction shows its ErrorID at
    the FB; only 16#0029 is a warning (Error FALSE)."""
    assert E.fb_error(reject.fault()) == error_id
    assert E.is_warning(error_id) is warning
