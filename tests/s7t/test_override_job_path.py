"""The S7-Technology override policy on the kernel's one job path (queue, blending, refusals).

Until the family's axis lands, a test family registers ``POLICY`` on a kernel axis that borrows the default
family's schema (as the kernel tests do); the jobs are what the S7-Technology instructions submit.  Expected
outcomes come from S7-Technology V4.1 §6.2.6 / §6.2.10 (Mode 0/1/2, the MC_MoveVelocity append example) and
the ErrorIDs 8055 / 8005, mapped by ``override.error_id``.
"""
from __future__ import annotations

import pytest

from plcmotion import Controller
from plcmotion.kernel import family as families
from plcmotion.kernel.axis import PositioningAxis
from plcmotion.kernel.jobs import Job, JobKind, JobState
from plcmotion.s7t.technology import override as O

FAMILY = "S7T-Override-Test"
SERVO = {"Actor.Type": 1, "DynamicLimits.MaxVelocity": 100.0,
         "DynamicDefaults.Acceleration": 50.0, "DynamicDefaults.Deceleration": 50.0,
         "FollowingError": {"MaxValue": 1000.0, "MinValue": 1000.0}}


@pytest.fixture(scope="module", autouse=True)
def s7t_policy_family():
    axis_class = type(Controller().add_positioning_axis("probe", {"Actor.Type": 1}))
    assert issubclass(axis_class, PositioningAxis)

    def axis(ctl, name, flat, where):
        return ctl.new_axis(axis_class, name, flat, where)
    fam = families.register(families.Family(FAMILY, versions=(1,), default_version=1,
                                            factories={families.POSITIONING_AXIS: axis}, policy=O.POLICY))
    yield
    families._REGISTRY.pop(fam.name)


def enabled():
    ctl = Controller(family=FAMILY)
    axis = ctl.add_positioning_axis("A", SERVO)
    assert axis.power(object(), True, 1, 0) is None
    ctl.run(0.2)
    assert axis.state == "enabled" and axis.policy is O.POLICY
    return ctl, axis


def speed(ctl, axis) -> float:
    return abs(float(ctl.bank.sp_v[axis.index]))


def test_s7t_override_path_append_velocity_after_relative():
    """S7-Technology V4.1 §6.2.10 "Append motion" example (L14849-14862): MC_MoveVelocity Mode 1 during a
    MC_MoveRelative: the positioning is not canceled, it completes (Done), then the velocity motion starts."""
    ctl, axis = enabled()
    rel = Job(JobKind.RELATIVE, position=40.0, velocity=20.0)
    axis.submit(rel, O.POLICY.buffer_mode(0))
    ctl.run(0.3)
    vel = Job(JobKind.VELOCITY, velocity=15.0)
    axis.submit(vel, O.POLICY.buffer_mode(1))
    assert rel.busy and vel.busy and not vel.active
    ctl.run_until(lambda: rel.state == JobState.DONE, 10.0)
    assert vel.active and speed(ctl, axis) < 1.0          # the axis stops at the transition (Mode 1)
    ctl.run_until(lambda: vel.in_velocity, 5.0)
    assert speed(ctl, axis) == pytest.approx(15.0)


def test_s7t_override_path_velocity_never_behind_velocity():
    """S7-Technology V4.1 §6.2.10 Prerequisites (L14636-14638): MC_MoveVelocity cannot be appended to an
    active MC_MoveVelocity (8055); Mode 0 overrides it."""
    ctl, axis = enabled()
    first = Job(JobKind.VELOCITY, velocity=20.0)
    axis.submit(first, O.POLICY.buffer_mode(0))
    ctl.run(0.2)
    second = Job(JobKind.VELOCITY, velocity=5.0)
    axis.submit(second, O.POLICY.buffer_mode(1))
    assert second.state == JobState.ERROR and O.error_id(second.fault) == 0x8055 and first.active
    third = Job(JobKind.VELOCITY, velocity=5.0)
    axis.submit(third, O.POLICY.buffer_mode(0))
    assert first.state == JobState.ABORTED and third.active


def test_s7t_override_path_no_append_during_halt_and_one_waiting_command():
    """S7-Technology V4.1 ErrorID 8055 (L13765-13773: MC_Halt active) and 8005 (command memory full): one
    command waits behind the active one."""
    ctl, axis = enabled()
    axis.submit(Job(JobKind.RELATIVE, position=200.0, velocity=20.0), O.POLICY.buffer_mode(0))
    ctl.run(0.3)
    queued = Job(JobKind.RELATIVE, position=10.0, velocity=20.0)
    axis.submit(queued, O.POLICY.buffer_mode(1))
    full = Job(JobKind.ABSOLUTE, position=10.0, velocity=20.0)
    axis.homed = True
    axis.submit(full, O.POLICY.buffer_mode(2))
    assert queued.busy and full.state == JobState.ERROR and O.error_id(full.fault) == 0x8005
    halt = Job(JobKind.HALT)
    axis.submit(halt, O.POLICY.buffer_mode(0))
    assert queued.state == JobState.ABORTED and halt.active        # Mode 0 cancels the waiting one too
    late = Job(JobKind.RELATIVE, position=10.0, velocity=20.0)
    axis.submit(late, O.POLICY.buffer_mode(1))
    assert late.state == JobState.ERROR and O.error_id(late.fault) == 0x8055 and halt.active


def test_s7t_override_path_overlay_passes_the_target_at_the_lower_velocity():
    """S7-Technology V4.1 §6.2.7 Mode 2 "Overlay motion" (L13885-13887; catalog part 2 §8.5): the transition
    is overlaid at the lower of the two velocities when the direction stays."""
    ctl, axis = enabled()
    first = Job(JobKind.RELATIVE, position=100.0, velocity=30.0)
    axis.submit(first, O.POLICY.buffer_mode(0))
    second = Job(JobKind.RELATIVE, position=100.0, velocity=10.0)
    axis.submit(second, O.POLICY.buffer_mode(2))
    at_handover = []
    ctl.on_post_servo(lambda t: at_handover.append(speed(ctl, axis)) if first.state == JobState.DONE
                      and not at_handover else None)
    ctl.run_until(lambda: first.state == JobState.DONE, 20.0)
    ctl.step()
    assert second.active and at_handover and at_handover[0] == pytest.approx(10.0, abs=0.5)
