"""The S7-Technology override policy on the kernel's one job path (queue, blending, refusals), through the
family's own axis (``Controller(family="S7-Technology")``) and instructions.

Expected outcomes come from S7-Technology V4.1 §6.2.6 / §6.2.7 / §6.2.10 (Mode 0/1/2, the MC_MoveVelocity
append example) and the ErrorIDs 8055 / 8005 of those FBs; speeds are the kinematics of the inputs (a
virtual axis: its actual value is its setpoint).
"""
from __future__ import annotations

import pytest

from plcmotion.s7t import MC_Halt, MC_MoveAbsolute, MC_MoveRelative, MC_MoveVelocity
from plcmotion.s7t.technology import override as O

from _s7t_rig import enabled

DYN = dict(Acceleration=50.0, Deceleration=50.0, Jerk=0.0)


def speed(ctl, axis) -> float:
    return abs(float(ctl.bank.sp_v[axis.index]))


def test_s7t_override_path_policy_is_the_familys():
    """S7-Technology V4.1 §6.8: the axes of the family decide with the command interaction of §6.8."""
    _ctl, axis, _ = enabled()
    assert axis.policy is O.POLICY and axis.ctl.technology_version == 41


def test_s7t_override_path_append_velocity_after_relative():
    """S7-Technology V4.1 §6.2.10 "Append motion" example: MC_MoveVelocity Mode 1 during a MC_MoveRelative:
    the positioning is not canceled, it completes (Done), then the velocity motion starts from standstill."""
    ctl, axis, _ = enabled()
    rel, vel = MC_MoveRelative(), MC_MoveVelocity()
    rel(Axis=axis, Execute=True, Distance=40.0, Velocity=20.0, **DYN)
    ctl.run(0.3)
    vel(Axis=axis, Execute=True, Velocity=15.0, Mode=1, **DYN)
    assert rel(Execute=True).Busy and vel.Busy and not vel.InVelocity and not vel.Error
    ctl.run_until(lambda: rel(Execute=True).Done, 10.0)
    assert not vel(Execute=True).CommandAborted and speed(ctl, axis) < 1.0   # stopped at the transition
    ctl.run_until(lambda: vel(Execute=True).InVelocity, 5.0)
    assert speed(ctl, axis) == pytest.approx(15.0) and not rel.CommandAborted


def test_s7t_override_path_velocity_never_behind_velocity():
    """S7-Technology V4.1 §6.2.10 Prerequisites: MC_MoveVelocity cannot be appended to an active
    MC_MoveVelocity (8055 "latching not allowed"); Mode 0 overrides it (CommandAborted at the first)."""
    ctl, axis, _ = enabled()
    first, second, third = MC_MoveVelocity(), MC_MoveVelocity(), MC_MoveVelocity()
    first(Axis=axis, Execute=True, Velocity=20.0, **DYN)
    ctl.run(0.2)
    second(Axis=axis, Execute=True, Velocity=5.0, Mode=1, **DYN)
    assert second.Error and second.ErrorID == 0x8055 and first(Execute=True).Busy
    third(Axis=axis, Execute=True, Velocity=5.0, Mode=0, **DYN)
    assert first(Execute=True).CommandAborted and third.Busy


def test_s7t_override_path_no_append_during_halt_and_one_waiting_command():
    """S7-Technology V4.1 §6.2.6 ErrorIDs 8005 (command memory full: one command waits behind the active
    one) and 8055 (MC_Halt active); MC_Halt (Mode 0) aborts the running command and the waiting one."""
    ctl, axis, _ = enabled()
    run, queued, full, halt, late = (MC_MoveRelative(), MC_MoveRelative(), MC_MoveAbsolute(), MC_Halt(),
                                     MC_MoveRelative())
    run(Axis=axis, Execute=True, Distance=200.0, Velocity=20.0, **DYN)
    ctl.run(0.3)
    queued(Axis=axis, Execute=True, Distance=10.0, Velocity=20.0, Mode=1, **DYN)
    full(Axis=axis, Execute=True, Position=10.0, Velocity=20.0, Mode=2, **DYN)
    assert queued.Busy and not queued.Error and full.Error and full.ErrorID == 0x8005
    halt(Axis=axis, Execute=True, Deceleration=10.0, Jerk=0.0)
    assert run(Execute=True).CommandAborted and queued(Execute=True).CommandAborted and halt.Busy
    late(Axis=axis, Execute=True, Distance=10.0, Velocity=20.0, Mode=1, **DYN)
    assert late.Error and late.ErrorID == 0x8055 and halt(Execute=True).Busy


def test_s7t_override_path_overlay_passes_the_target_at_the_lower_velocity():
    """S7-Technology V4.1 §6.2.7 Mode 2 "Overlay motion": the transition between two positionings in the
    same direction is passed at the lower of the two velocities (10 after 30), without a stop; the second
    ends at 200."""
    ctl, axis, _ = enabled()
    first, second = MC_MoveRelative(), MC_MoveRelative()
    p0 = float(ctl.bank.sp_p[axis.index])
    first(Axis=axis, Execute=True, Distance=100.0, Velocity=30.0, **DYN)
    second(Axis=axis, Execute=True, Distance=100.0, Velocity=10.0, Mode=2, **DYN)
    trace: list[tuple[float, float]] = []
    ctl.on_post_servo(lambda t: trace.append((float(ctl.bank.sp_p[axis.index]) - p0, speed(ctl, axis))))
    ctl.run_until(lambda: second(Execute=True).Done, 30.0)
    assert first(Execute=True).Done and not first.CommandAborted
    assert trace[-1][0] == pytest.approx(200.0, abs=1e-6)
    at_target = min(trace, key=lambda pv: abs(pv[0] - 100.0))
    assert at_target[1] == pytest.approx(10.0, abs=0.2)
    assert min(v for p, v in trace if 60.0 < p < 190.0) > 9.9         # no stop at the transition
