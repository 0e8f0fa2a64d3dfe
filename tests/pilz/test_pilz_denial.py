"""Denial causes of the Pilz motion core, table-driven with their I90 values (Pilz V6.5 §1.2.2, §1.3.2,
§1.4.2, §1.5.2, §1.6.2, §1.7.2, §1.9.2, §1.12.2; I90 numbering: docs/pilz/decisions.md)."""
from __future__ import annotations

import pytest

from plcmotion.pilz import Cause

from ._core import PROFILE, make_axis, release, start

LIMITED = {"I50": 1000.0, "I51": -1000.0}
ENDLESS = {"I00": 1, "I01": 360.0}

# (case, axis parameters, referenced, command, registers, I90)
CASES = [
    ("abs outside SW limit", LIMITED, True, 1, {**PROFILE, "I403": 1500.0}, Cause.SW_LIMIT),
    ("abs direction blocked by I04", {**ENDLESS, "I04": 1}, True, 1, {**PROFILE, "I403": 300.0, "I411": 2},
     Cause.DIRECTION_BLOCKED),
    ("abs outside revolution length", ENDLESS, True, 1, {**PROFILE, "I403": 360.0}, Cause.REVOLUTION_LENGTH),
    ("abs negative on endless axis", ENDLESS, True, 1, {**PROFILE, "I403": -1.0}, Cause.REVOLUTION_LENGTH),
    ("abs velocity 0", {}, True, 1, {**PROFILE, "I403": 10.0, "I404": 0.0}, Cause.ZERO_DYNAMICS),
    ("abs acceleration 0", {}, True, 1, {**PROFILE, "I403": 10.0, "I405": 0.0}, Cause.ZERO_DYNAMICS),
    ("abs deceleration 0", {}, True, 1, {**PROFILE, "I403": 10.0, "I406": 0.0}, Cause.ZERO_DYNAMICS),
    ("abs jerk 0", {}, True, 1, {**PROFILE, "I403": 10.0, "I407": 0.0}, Cause.ZERO_DYNAMICS),
    ("abs I11 = 0", {"I11": 0.0}, True, 1, {**PROFILE, "I403": 10.0}, Cause.ZERO_MAXIMUM),
    ("abs I16 = 0", {"I16": 0.0}, True, 1, {**PROFILE, "I403": 10.0}, Cause.ZERO_MAXIMUM),
    ("abs not referenced", {}, False, 1, {**PROFILE, "I403": 10.0}, Cause.NOT_REFERENCED),
    ("rel outside SW limit", LIMITED, True, 2, {**PROFILE, "I403": -1001.0}, Cause.SW_LIMIT),
    ("rel direction blocked", {**ENDLESS, "I04": 2}, True, 2, {**PROFILE, "I403": 10.0}, Cause.DIRECTION_BLOCKED),
    ("rel velocity 0", {}, False, 2, {**PROFILE, "I403": 10.0, "I404": 0.0}, Cause.ZERO_DYNAMICS),
    ("rel I16 = 0", {"I16": 0.0}, False, 2, {**PROFILE, "I403": 10.0}, Cause.ZERO_MAXIMUM),
    ("rel with SW limits, not referenced", LIMITED, False, 2, {**PROFILE, "I403": 10.0}, Cause.NOT_REFERENCED),
    ("add outside SW limit", LIMITED, True, 3, {**PROFILE, "I403": 2000.0}, Cause.SW_LIMIT),
    ("add direction blocked", {**ENDLESS, "I04": 1}, True, 3, {**PROFILE, "I403": -10.0}, Cause.DIRECTION_BLOCKED),
    ("add jerk 0", {}, False, 3, {**PROFILE, "I403": 10.0, "I407": 0.0}, Cause.ZERO_DYNAMICS),
    ("add with SW limits, not referenced", LIMITED, False, 3, {**PROFILE, "I403": 10.0}, Cause.NOT_REFERENCED),
    ("vel direction blocked", {**ENDLESS, "I04": 1}, True, 4, {**PROFILE, "I404": -10.0}, Cause.DIRECTION_BLOCKED),
    ("vel deceleration 0", {}, False, 4, {**PROFILE, "I406": 0.0}, Cause.ZERO_DYNAMICS),
    ("vel I11 = 0", {"I11": 0.0}, False, 4, PROFILE, Cause.ZERO_MAXIMUM),
    ("stop I16 = 0", {"I16": 0.0}, False, 5, PROFILE, Cause.ZERO_MAXIMUM),
    ("home type inactive", {"I30": 0}, False, 6, {}, Cause.REFERENCING_INACTIVE),
    ("home CiA 402 method 0", {"A586": 0}, False, 6, {}, Cause.REFERENCING_INACTIVE),
    ("move speed jerk 0", {}, False, 8, {"I426": 10.0, "I407": 0.0}, Cause.ZERO_DYNAMICS),
    ("move speed I16 = 0", {"I16": 0.0}, False, 8, {"I426": 10.0, "I407": 1000.0}, Cause.ZERO_MAXIMUM),
    ("halt I11 = 0", {"I11": 0.0}, False, 11, PROFILE, Cause.ZERO_MAXIMUM),
]


@pytest.mark.parametrize("case,params,referenced,command,registers,cause", CASES, ids=[c[0] for c in CASES])
def test_pilz_denial_cause(case, params, referenced, command, registers, cause):
    """Pilz V6.5 §1.x.2: each listed cause denies the command: I91 = 1 with its I90 and I89 = 7 from the cycle
    after the edge; in the edge cycle I91, I90, I92 are 0 (handshake of the status tables)."""
    ctl, ax = make_axis(params, referenced=referenced)
    t0 = start(ax, command, **registers)
    ctl.step()
    edge = [r for r in ax.rows if abs(r.t - t0) < 1e-9][0]
    assert (edge.I91, edge.I90, edge.I92) == (False, 0, False)
    after = ax.rows[-1]
    assert after.I91 and after.I90 == int(cause) and after.I89 == 7 and not after.I92
    assert ax.status.I96 == 0.0                 # nothing moved


def test_pilz_denial_hw_limit_in_direction():
    """Pilz V6.5 §1.2.2 / §1.5.2: an active hardware limit switch in the direction of travel denies the
    command (I90 = 4); the other direction is free."""
    ctl, ax = make_axis({"I101": "I0.0", "I102": "I0.1", "Plant.HWLimitMaxPosition": 0.0,
                         "Plant.HWLimitMinPosition": -100.0, "LimitSwitchLevel": True})
    assert ax.limit_switches.approached["max"]
    start(ax, 4, **{**PROFILE, "I404": 10.0})
    ctl.step()
    assert ax.status.I91 and ax.status.I90 == Cause.HW_LIMIT
    release(ax)
    start(ax, 2, **{**PROFILE, "I403": -10.0})
    ctl.step()
    assert not ax.status.I91 and ax.status.I89 == 3


def test_pilz_denial_home_not_standstill():
    """Pilz V6.5 §1.7.2: MC_Home is denied unless the motion core is in standstill (I89 = 2)."""
    ctl, ax = make_axis()
    start(ax, 4, **{**PROFILE, "I404": 50.0})
    ctl.run(0.01)
    release(ax)
    start(ax, 6)
    ctl.step()
    assert ax.status.I91 and ax.status.I90 == Cause.NOT_STANDSTILL


@pytest.mark.parametrize("command,state", [(5, 6), (11, 3)])
def test_pilz_denial_stop_halt_at_standstill_is_done(command, state):
    """Pilz V6.5 §1.6.7 / §1.12.7: MC_Stop / MC_Halt with deceleration or jerk 0 at standstill are reported as
    success (I91 = 0, I92 = 1), I92 only after the handshake cycle; I89 stays 6 / 3 while Execute is 1."""
    ctl, ax = make_axis()
    t0 = start(ax, command, I406=0.0, I407=0.0)
    ctl.run(0.003)
    rows = [r for r in ax.rows if r.t >= t0 - 1e-9]
    assert not rows[0].I92 and not rows[0].I91
    assert rows[-1].I92 and not rows[-1].I91 and rows[-1].I89 == state
    release(ax)
    ctl.step()
    assert ax.status.I89 == 2


# (case, command, registers, I90, stops): denied while the axis moves at 50 under MC_MoveVelocity
MOVING = [
    ("abs velocity 0", 1, {**PROFILE, "I403": 10.0, "I404": 0.0}, Cause.ZERO_DYNAMICS, True),
    ("rel acceleration 0", 2, {**PROFILE, "I403": 10.0, "I405": 0.0}, Cause.ZERO_DYNAMICS, True),
    ("add jerk 0", 3, {**PROFILE, "I403": 10.0, "I407": 0.0}, Cause.ZERO_DYNAMICS, True),
    ("vel acceleration 0", 4, {**PROFILE, "I404": 80.0, "I405": 0.0}, Cause.ZERO_DYNAMICS, False),
    ("vel lower velocity, deceleration 0", 4, {**PROFILE, "I404": 30.0, "I406": 0.0}, Cause.ZERO_DYNAMICS, False),
    ("stop deceleration 0", 5, {"I406": 0.0, "I407": 1000.0}, Cause.ZERO_DYNAMICS, False),
    ("home not in standstill (I89 = 4)", 6, {}, Cause.NOT_STANDSTILL, False),
    ("move speed jerk 0", 8, {"I426": 80.0, "I407": 0.0}, Cause.ZERO_DYNAMICS, False),
    ("halt deceleration 0", 11, {"I406": 0.0, "I407": 1000.0}, Cause.ZERO_DYNAMICS, False),
]


@pytest.mark.parametrize("case,command,registers,cause,stops", MOVING, ids=[c[0] for c in MOVING])
def test_pilz_denial_while_moving(case, command, registers, cause, stops):
    """Pilz V6.5 §1.2.4, §1.3.4, §1.4.4: a denied MC_MoveAbsolute / Relative / Additive stops the motion by a
    quick stop; §1.5.2, §1.6.2, §1.7.2, §1.9.2, §1.12.2 give the other commands' denials no reaction, so the
    running MC_MoveVelocity goes on at its set velocity (50).  I91 = 1 with the cause, I89 = 7."""
    ctl, ax = make_axis()
    start(ax, 4, **{**PROFILE, "I404": 50.0})
    ctl.run(0.2)
    assert ax.status.E07 == 50.0
    start(ax, command, **registers)
    ctl.run(0.1)
    assert ax.status.I91 and ax.status.I90 == int(cause) and ax.status.I89 == 7
    assert not (ax.status.I92 or ax.status.I85 or ax.status.I183)
    assert ax.status.E07 == (0.0 if stops else 50.0)


def test_pilz_denial_during_stop():
    """Pilz V6.5 §1.6.5, Fig. 15: commands started while MC_Stop is active are denied (I90 = 10); after
    standstill and Execute = 0 they start again."""
    ctl, ax = make_axis()
    start(ax, 4, **{**PROFILE, "I404": 100.0})
    ctl.run(0.2)
    start(ax, 5, I406=500.0, I407=100000.0)
    ctl.run(0.02)
    release(ax)
    start(ax, 4, **{**PROFILE, "I404": 100.0})
    ctl.step()
    assert ax.status.I90 == Cause.STOP_ACTIVE
    ctl.run(0.5)
    release(ax)
    start(ax, 4, **{**PROFILE, "I404": 100.0})
    ctl.step()
    assert not ax.status.I91 and ax.status.I89 == 4


@pytest.mark.parametrize("command,registers", [(7, {"I426": 1.0}), (9, {"I428": 0.0}), (10, {"I421": 0.0})])
def test_pilz_denial_never(command, registers):
    """Pilz V6.5 §1.8.2, §1.10.2, §1.11.2: the cyclic commands and MC_TorqueControl are never denied, even with
    zero dynamics parameters."""
    ctl, ax = make_axis({"I11": 0.0, "I16": 0.0})

    @ctl.program
    def feed():
        for k, v in registers.items():
            ax.registers.write(k, v)

    start(ax, command, **registers)
    ctl.run(0.005)
    assert not ax.status.I91 and ax.status.I92


def test_pilz_denial_cancel_enable_off():
    """Pilz V6.5 §1.2.7 (I91 "denied or cancelled"), §1.4.6: the enable going off cancels the running command
    (I91, I90 = 22); I89 = 0 while disabled."""
    ctl, ax = make_axis()
    start(ax, 4, **{**PROFILE, "I404": 50.0})
    ctl.run(0.1)
    ax.enable(False)
    ctl.run(0.3)
    assert ax.status.I91 and ax.status.I90 == Cause.ENABLE_OFF and ax.status.I89 == 0


def test_pilz_denial_cancel_limit_switch():
    """Pilz V6.5 §1.5.3 / §1.8.3: reaching a hardware limit switch stops the axis with a quick stop and a limit
    switch fault (I91, I90 = 20, I89 = 7); the enable stays on; after the fault reset the axis moves away."""
    ctl, ax = make_axis({"I101": "I0.0", "I102": "I0.1", "Plant.HWLimitMaxPosition": 20.0,
                         "Plant.HWLimitMinPosition": -100.0, "LimitSwitchLevel": True})
    start(ax, 4, **{**PROFILE, "I404": 50.0})
    ctl.run(1.0)
    assert ax.status.I91 and ax.status.I90 == Cause.LIMIT_SWITCH_FAULT and ax.status.I89 == 7
    assert ax.state == "enabled" and ax.status.E07 == 0.0
    ax.reset()
    release(ax)
    start(ax, 4, **{**PROFILE, "I404": 50.0})
    ctl.step()
    assert ax.status.I90 == Cause.HW_LIMIT                 # still on the switch: not towards it
    start(ax, 4, **{**PROFILE, "I404": -50.0})
    ctl.run(0.1)
    assert not ax.status.I91 and ax.status.E07 == -50.0


def test_pilz_denial_cancel_software_limit():
    """Pilz V6.5 §1.2.2 / decisions.md: a velocity command that runs into a software limit switch stops at it
    and is cancelled (I90 = 21); the set position never passes the switch."""
    ctl, ax = make_axis({"I50": 100.0, "I51": -100.0})
    start(ax, 4, **{**PROFILE, "I404": 200.0})
    ctl.run(1.5)
    assert ax.status.I91 and ax.status.I90 == Cause.SW_LIMIT_REACHED
    assert max(r.I96 for r in ax.rows) <= 100.0 + 1e-9


@pytest.mark.parametrize("params,command,registers", [
    ({"I11": 0.0, "I30": 3}, 6, {}), ({"I16": 0.0, "A586": 34}, 6, {}),
    ({"I11": 0.0}, 8, {"I426": 100.0, "I407": 1000.0})])
def test_pilz_denial_zero_maximum_without_motion(params, command, registers):
    """decisions.md (Pilz V6.5 §1.7.2, §1.9.2 extended): MC_Home with a search and MC_MoveSpeed cannot move with
    I11 = 0 or I16 = 0: denied with I90 = 6 instead of a profile without acceleration; setting the reference
    still works."""
    ctl, ax = make_axis(params, referenced=False)
    start(ax, command, **registers)
    ctl.step()
    assert ax.status.I91 and ax.status.I90 == Cause.ZERO_MAXIMUM and not ax.alarms
    ctl2, ax2 = make_axis({**params, "A586": None, "I30": 5}, referenced=False)
    start(ax2, 6)
    ctl2.run(0.003)
    assert ax2.status.I92


def _during_stop(ctl, ax):
    start(ax, 4, **{**PROFILE, "I404": 100.0})
    ctl.run(0.2)
    start(ax, 5, I406=500.0, I407=100000.0)
    ctl.run(0.02)


def _disabled(ctl, ax):
    ax.enable(False)
    ctl.run(0.1)


def _one_waiting(ctl, ax):
    start(ax, 1, **{**PROFILE, "I403": 100.0})
    ctl.run(0.05)
    start(ax, 1, **{**PROFILE, "I403": 150.0, "I409": 1})
    ctl.run(0.01)


# (case, set-up, command, registers, I90): the causes of the drive's state (decisions.md, denials.md)
GENERAL_CASES = [
    ("MC_MoveVelocity while MC_Stop is active", _during_stop, 4, {**PROFILE, "I404": 100.0}, Cause.STOP_ACTIVE),
    ("MC_Halt while MC_Stop is active", _during_stop, 11, PROFILE, Cause.STOP_ACTIVE),
    ("MC_MoveAbsolute with the drive disabled", _disabled, 1, {**PROFILE, "I403": 10.0}, Cause.NOT_READY),
    ("MC_CyclicSpeed with the drive disabled", _disabled, 7, {"I426": 10.0}, Cause.NOT_READY),
    ("second buffered MC_MoveAbsolute", _one_waiting, 1, {**PROFILE, "I403": 200.0, "I409": 1},
     Cause.BUFFER_FULL),
]


@pytest.mark.parametrize("case,setup,command,registers,cause", GENERAL_CASES, ids=[c[0] for c in GENERAL_CASES])
def test_pilz_denial_general_cause(case, setup, command, registers, cause):
    """Pilz V6.5 §1.6.5 / Fig. 15 (I90 = 10: commands while MC_Stop holds the axis), §1 I89 (I90 = 11: drive
    not ready), Tab. 15 I83 "running and buffered subsequent motion block" (I90 = 12: one block waits already):
    I91 = 1 with the cause from the cycle after the edge, 0 in the edge cycle."""
    ctl, ax = make_axis()
    setup(ctl, ax)
    t0 = start(ax, command, **registers)
    ctl.step()
    edge = [r for r in ax.rows if abs(r.t - t0) < 1e-9][0]
    assert (edge.I91, edge.I90, edge.I92) == (False, 0, False)
    assert ax.status.I91 and ax.status.I90 == int(cause)
