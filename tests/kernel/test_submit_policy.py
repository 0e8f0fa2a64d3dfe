"""The kernel's one job path driven by a family's override policy, without any dialect.

A small test family registers its own policy table (below, written out as data): which running activity a
new job aborts (A), lets go on (-), refuses the new job for (R) or compares with it (B, the higher rank
wins).  The expected outcomes are the cells of that table and the PLCopen buffer mode rules (Aborting ends
the running job and every waiting one), never values taken from the code under test.
"""
from __future__ import annotations

import dataclasses

import pytest

from ._schema_axis import with_schema

from plcmotion import Controller
from plcmotion.kernel import faults as F
from plcmotion.kernel import family as families
from plcmotion.kernel.axis import PositioningAxis
from plcmotion.kernel.job_queue import BufferMode
from plcmotion.kernel.jobs import Job, JobKind, JobState
from plcmotion.kernel.policy import (ABORT, HALT, HOME_ACTIVE, HOME_PASSIVE, KEEP, MOTION, PLCOPEN, Activity,
                                     OverridePolicy, Ranked, Reject, table)

BRAKING = Reject(F.REJECTED, "braking")
WEAKER = Reject(F.REJECTED, "weaker")
CELLS = table((HOME_PASSIVE, HOME_ACTIVE, HALT, MOTION), {
    #             passive  active  halt  motion
    MOTION:      "-        A       R     A",      # a move while the axis brakes is refused
    HALT:        "A        A       B     A",      # a halt ends passive homing; B: the harder halt wins
    HOME_ACTIVE: "A        A       A     A",
}, R=BRAKING, B=Ranked(rank=lambda job: job.mode, weaker=WEAKER))
POLICY = OverridePolicy("test", CELLS, position_control=frozenset({JobKind.ABSOLUTE, JobKind.RELATIVE, JobKind.HALT}),
                        queue_depth=2)

SERVO = {"Actor.Type": 1, "DynamicLimits.MaxVelocity": 100.0,
         "DynamicDefaults.Acceleration": 50.0, "DynamicDefaults.Deceleration": 50.0,
         "Sensor": {"Sensor[1]": {"PassiveHoming": {"Mode": 2, "DigitalInputAddress": "I0.0"}}},
         "Plant": {"HomingSwitchPosition": 1.0e6}, "FollowingError": {"MaxValue": 1000.0, "MinValue": 1000.0}}


def _family(name: str, policy: OverridePolicy | None) -> families.Family:
    axis_class = with_schema(PositioningAxis, {"Actor.Type": 1})

    def axis(ctl, axis_name, flat, where):
        return ctl.new_axis(axis_class, axis_name, flat, where)
    return families.Family(name, versions=(1,), default_version=1,
                           factories={families.POSITIONING_AXIS: axis}, policy=policy)


@pytest.fixture(scope="module", autouse=True)
def policy_families():
    made = [families.register(_family("Kernel-Policy-Test", POLICY)),
            families.register(_family("Kernel-No-Policy", None))]
    yield
    for fam in made:
        families._REGISTRY.pop(fam.name)


def enabled_axis(family: str = "Kernel-Policy-Test"):
    ctl = Controller(family=family)
    axis = ctl.add_positioning_axis("A", SERVO)
    ctl.inputs["I0.0"] = False
    assert axis.power(object(), True, 1, 0) is None
    ctl.run(0.2)
    assert axis.state == "enabled"
    return ctl, axis


def velocity(ctl, axis) -> float:
    return float(ctl.bank.sp_v[axis.index])


def moving(ctl, axis, v: float = 40.0) -> Job:
    job = Job(JobKind.VELOCITY, velocity=v)
    axis.submit(job)
    ctl.run_until(lambda: job.in_velocity, 5.0)
    return job


# --- the policy as data -------------------------------------------------------------------------------------
def test_kernel_policy_table_marks_become_cells():
    assert CELLS[MOTION] == {HOME_PASSIVE: KEEP, HOME_ACTIVE: ABORT, HALT: BRAKING, MOTION: ABORT}
    assert POLICY.cell(HOME_PASSIVE, MOTION) is KEEP          # a row the table has not: the activity goes on
    assert POLICY.aborts(MOTION, MOTION) and not POLICY.aborts(MOTION, HALT) and not POLICY.aborts(MOTION, HOME_PASSIVE)
    assert POLICY.aborts(HALT, HALT)                          # the table view of a ranked cell: it can abort
    with pytest.raises(ValueError, match="3 marks for 4 columns"):
        table((HOME_PASSIVE, HOME_ACTIVE, HALT, MOTION), {MOTION: "A A A"})


def test_kernel_policy_ranked_cell_compares_the_two_jobs():
    running = Activity(HALT, Job(JobKind.HALT, mode=2), lambda t: None)
    assert POLICY.decide(HALT, Job(JobKind.HALT, mode=1), running) == WEAKER
    assert POLICY.decide(HALT, Job(JobKind.HALT, mode=2), running) is ABORT
    assert POLICY.decide(HALT, Job(JobKind.HALT, mode=3), running) is ABORT


def test_kernel_policy_buffer_modes_of_plcopen():
    """PLCopen Part 1 numbers mcAborting = 0 ... mcBlendingHigh = 5; a family maps its own input."""
    assert [PLCOPEN.buffer_mode(n) for n in range(6)] == list(BufferMode)
    assert POLICY.buffer_mode(0) is BufferMode.ABORTING
    with pytest.raises(ValueError, match="no buffer mode 1"):
        POLICY.buffer_mode(1)


def test_kernel_family_policy_reaches_the_axis():
    _ctl, axis = enabled_axis()
    assert axis.policy is POLICY and axis.queue.depth == 2
    _ctl, axis = enabled_axis("Kernel-No-Policy")
    assert axis.policy is PLCOPEN and axis.queue.depth == 1


# --- the one job path on a kernel axis ------------------------------------------------------------------------
def test_kernel_submit_abort_cell_ends_the_running_job():
    ctl, axis = enabled_axis()
    run = moving(ctl, axis)
    new = Job(JobKind.RELATIVE, position=50.0, velocity=20.0)
    axis.submit(new)
    assert run.state == JobState.ABORTED and new.active and axis.job is new
    ctl.run_until(lambda: not new.busy, 20.0)
    assert new.state == JobState.DONE and velocity(ctl, axis) == 0.0


def test_kernel_submit_reject_cell_refuses_the_new_job_and_the_running_one_goes_on():
    ctl, axis = enabled_axis()
    moving(ctl, axis)
    halt = Job(JobKind.HALT)
    axis.submit(halt)
    ctl.run(0.1)
    move = Job(JobKind.RELATIVE, position=50.0, velocity=20.0)
    axis.submit(move)
    assert move.state == JobState.ERROR and (move.fault.kind, move.fault.detail) == (F.REJECTED, "braking")
    assert halt.active and axis.job is halt
    ctl.run_until(lambda: not halt.busy, 5.0)
    assert halt.state == JobState.DONE and velocity(ctl, axis) == 0.0


def test_kernel_submit_keep_cell_lets_passive_homing_run_beside_a_move():
    ctl, axis = enabled_axis()
    passive = Job(JobKind.HOME_PASSIVE, mode=2)
    axis.home(passive)
    assert passive.busy and axis.passive_home is passive
    run = moving(ctl, axis)                        # MOTION / passive: "-"
    assert passive.busy and run.busy
    halt = Job(JobKind.HALT)
    axis.submit(halt)                              # HALT / passive: "A"; HALT / motion: "A"
    assert passive.state == JobState.ABORTED and axis.passive_home is None and run.state == JobState.ABORTED


def test_kernel_submit_ranked_cell_keeps_the_higher_rank():
    ctl, axis = enabled_axis()
    moving(ctl, axis)
    first = Job(JobKind.HALT, mode=2)
    axis.submit(first)
    weaker = Job(JobKind.HALT, mode=1)
    axis.submit(weaker)
    assert weaker.state == JobState.ERROR and weaker.fault.detail == "weaker" and first.active
    harder = Job(JobKind.HALT, mode=3)
    axis.submit(harder)
    assert first.state == JobState.ABORTED and harder.active


def test_kernel_submit_aborting_clears_the_queue_and_replaces_the_running_job():
    """PLCopen Aborting: the running job and every job waiting behind it end aborted (depth 2 from the policy)."""
    ctl, axis = enabled_axis()
    j1 = Job(JobKind.RELATIVE, position=500.0, velocity=20.0)
    j2 = Job(JobKind.RELATIVE, position=10.0, velocity=20.0)
    j3 = Job(JobKind.RELATIVE, position=10.0, velocity=20.0)
    axis.submit(j1)
    axis.submit(j2, BufferMode.BUFFERED)
    axis.submit(j3, BufferMode.BUFFERED)
    assert axis.queue.pending == (j2, j3)
    ctl.run(0.5)
    j4 = Job(JobKind.VELOCITY, velocity=-10.0)
    axis.submit(j4)
    assert [j.state for j in (j1, j2, j3)] == [JobState.ABORTED] * 3
    assert axis.queue.pending == () and j4.active and axis.job is j4


def test_kernel_submit_refused_job_leaves_the_running_job_and_its_queue():
    ctl, axis = enabled_axis()
    moving(ctl, axis)
    halt = Job(JobKind.HALT)
    axis.submit(halt)
    after = Job(JobKind.RELATIVE, position=10.0, velocity=20.0)
    axis.submit(after, BufferMode.BUFFERED)          # waits behind the halt
    refused = Job(JobKind.VELOCITY, velocity=10.0)
    axis.submit(refused)                             # MOTION / halt: "R"
    assert refused.state == JobState.ERROR and halt.active and axis.queue.pending == (after,)
    ctl.run_until(lambda: not halt.busy, 5.0)
    assert halt.state == JobState.DONE and after.active
    ctl.run_until(lambda: not after.busy, 10.0)
    assert after.state == JobState.DONE


@pytest.mark.parametrize("family, controlled_after_halt", [("Kernel-Policy-Test", True), ("Kernel-No-Policy", False)])
def test_kernel_submit_position_control_follows_the_policy(family, controlled_after_halt):
    """A velocity job without position control, then a halt: the policy lists the job kinds that switch
    position control on (HALT in the test policy, not in the PLCopen default)."""
    ctl, axis = enabled_axis(family)
    run = Job(JobKind.VELOCITY, velocity=20.0, position_controlled=False)
    axis.submit(run)
    ctl.run(0.2)
    assert not axis.position_controlled
    axis.submit(Job(JobKind.HALT))
    assert axis.position_controlled is controlled_after_halt


@pytest.mark.parametrize("after_override", [False, True])
def test_kernel_submit_target_checked_before_or_after_the_override(after_override):
    """``plan_after_override`` False: a job refused for its target (beyond 1e12) leaves the running job
    alone; True: the running job is ended first, then the new one is refused."""
    ctl, axis = enabled_axis()
    axis.policy = dataclasses.replace(POLICY, plan_after_override=after_override)
    run = moving(ctl, axis)
    far = Job(JobKind.RELATIVE, position=2.0e12, velocity=20.0)
    axis.submit(far)
    assert far.state == JobState.ERROR and far.fault.detail == "numeric_limit"
    assert run.state == (JobState.ABORTED if after_override else JobState.BUSY)


def test_kernel_submit_superimposed_slot_needs_the_ability():
    """A policy that routes a class to the superimposed slot on an axis without superimposed motion: the job
    is refused as not available, the running one goes on."""
    ctl, axis = enabled_axis()
    axis.policy = dataclasses.replace(POLICY, slots={MOTION: "superimposed"})
    axis.policy = dataclasses.replace(axis.policy, classify=lambda job: HALT if job.kind == JobKind.HALT else MOTION)
    halt = Job(JobKind.HALT)
    axis.submit(halt)
    add = Job(JobKind.RELATIVE, position=1.0, velocity=1.0)
    axis.submit(add)
    assert add.state == JobState.ERROR and add.fault.kind == F.NOT_AVAILABLE and halt.busy


def test_kernel_submit_second_job_of_a_cycle_starts_from_the_output_state():
    """Two jobs in one application cycle: the first (Jerk 0, a trapezoid whose acceleration steps at once)
    never runs a servo cycle, so the second starts from the state the axis was given - at rest, a = 0 -
    and its jerk-limited ramp gives a = J t, v = J t^2 / 2 after the first servo cycle (t = 1 ms)."""
    ctl, axis = enabled_axis()
    first = Job(JobKind.VELOCITY, velocity=50.0, jerk=float("inf"))
    second = Job(JobKind.VELOCITY, velocity=50.0, jerk=1000.0)
    samples = []
    ctl.on_post_servo(lambda t: samples.append((float(ctl.bank.sp_v[axis.index]), float(ctl.bank.sp_a[axis.index]))))
    axis.submit(first)
    axis.submit(second)
    ctl.step()
    assert first.state == JobState.ABORTED and second.active
    v1, a1 = samples[0]
    assert a1 == pytest.approx(1000.0 * 0.001, rel=1e-9) and v1 == pytest.approx(1000.0 * 0.001 ** 2 / 2, rel=1e-9)
