"""The servo cycle as named stages (kernel/servo_cycle.py), tested without any dialect.

What a stage order means is observable from the outside: a hook before the motion stages sees the actual
values and inputs of its own cycle but the setpoints and drive commands of the previous one; a hook after
them sees the setpoints and drive commands of its own cycle.  A defect escaping a stage stops the
controller (a PLC goes to STOP on a fault in its motion OB, S7-1200 V6 §2.2.7.3) and the reason names
the stage; a defect while handling one axis stops only that axis.
"""
from __future__ import annotations

import warnings

import pytest

from plcmotion import Controller
from plcmotion.drives.simulated import ServoDrives
from plcmotion.kernel import monitoring, servo_cycle
from plcmotion.kernel.io import DigitalInputs
from plcmotion.kernel.jobs import Job, JobKind, JobState

#: the stages as the architecture documents them, in order
DOCUMENTED = ("read_drives", "read_encoders", "read_inputs", "pre_servo", "accept_jobs", "watch_inputs",
              "replan", "axis_events", "interpolate", "superimpose", "couple", "control", "monitor",
              "write_drives", "post_servo")

#: the order the issue asks for (read drives, pre-servo, events, interpolate, couple, control, monitor,
#: write drives, post-servo): it must hold whatever stages are added between
REQUIRED_ORDER = ("read_drives", "pre_servo", "axis_events", "interpolate", "couple", "control", "monitor",
                  "write_drives", "post_servo")

SERVO_AXIS = {"Actor": {"Type": 1, "DriveParameter": {"MaxSpeed": 6000.0, "ReferenceSpeed": 3000.0}},
              "DynamicLimits": {"MaxVelocity": 400.0},
              "DynamicDefaults": {"Acceleration": 2000.0, "Deceleration": 2000.0, "Jerk": 40000.0},
              "FollowingError": {"MaxValue": 100.0}}


class Owner:
    """Stands for the instruction instance that owns the enable and the jobs."""


def enabled_axis(ctl: Controller, name: str = "Axis_1"):
    axis = ctl.add_positioning_axis(name, SERVO_AXIS)
    owner = Owner()
    assert axis.power(owner, True, 1, 0) is None
    ctl.run_until(lambda: axis.state == "enabled", timeout=1.0)
    return axis


def move(axis, distance: float, velocity: float = 200.0) -> Job:
    """A relative move, as MC_MoveRelative submits it (an axis that is not homed may not move absolutely)."""
    job = Job(JobKind.RELATIVE, position=distance, velocity=velocity, owner=Owner())
    axis.submit(job)
    assert job.state == JobState.BUSY
    return job


# --- the list of stages -------------------------------------------------------------------------------------------
def test_kernel_stage_names_are_public_and_in_the_documented_order():
    ctl = Controller()
    assert ctl.servo_stages == DOCUMENTED
    assert len(set(ctl.servo_stages)) == len(ctl.servo_stages)


def test_kernel_the_order_the_issue_asks_for_holds():
    names = Controller().servo_stages
    positions = [names.index(stage) for stage in REQUIRED_ORDER]
    assert positions == sorted(positions)
    assert names[0] == "read_drives" and names[-1] == "post_servo"


def test_kernel_every_stage_is_described_for_docs_and_trace_tools():
    described = servo_cycle.describe()
    assert [name for name, _ in described] == list(DOCUMENTED)
    assert all(len(text) > 20 for _, text in described)


def test_kernel_a_malformed_stage_table_is_refused():
    def noop(ctl, t):
        pass
    for bad in ((servo_cycle.ServoStage("x", noop), servo_cycle.ServoStage("x", noop)),     # name twice
                (servo_cycle.ServoStage("not a name", noop),),
                (servo_cycle.ServoStage("x", noop, ("bank.n; import os",)),)):
        with pytest.raises(ValueError):
            servo_cycle.compile_cycle(bad)


# --- what a hook sees, by its place in the cycle ---------------------------------------------------------------------
def test_kernel_pre_servo_sees_this_cycles_actuals_but_last_cycles_setpoints_and_commands():
    ctl = Controller()
    axis = enabled_axis(ctl)
    i = axis.index
    pre, post = [], []

    def sample(t):
        return (t, float(ctl.bank.sp_p[i]), axis.drive.setpoint_word, float(ctl.bank.act_p[i]))

    ctl.on_pre_servo(lambda t: pre.append(sample(t)))
    ctl.on_post_servo(lambda t: post.append(sample(t)))
    move(axis, 100.0)
    ctl.run(0.3)
    assert len(pre) == len(post) > 250
    moving = 0
    for k in range(1, len(pre)):
        t, sp, word, act = pre[k]
        assert t == post[k][0]
        # setpoint and drive command are those the previous cycle computed and sent
        assert (sp, word) == post[k - 1][1:3]
        # the actual value was read at the start of this cycle: post sees the same one
        assert act == post[k][3]
        if post[k][1] != sp:
            moving += 1
    assert moving > 200                       # the motion stages ran between the hooks in (almost) every cycle
    # the drive answers the command of the last cycle: the actual value changes between cycles, not in one
    assert sum(pre[k][3] != post[k - 1][3] for k in range(1, len(pre))) > 200


def test_kernel_post_servo_sees_this_cycles_setpoint_and_drive_command():
    """The setpoint a post hook sees at t lies on the planned move at t (it is not one cycle old), and the
    speed setpoint word already on its way to the drive was made from this cycle's command."""
    ctl = Controller()
    axis = enabled_axis(ctl)
    i = axis.index
    post = []
    ctl.on_post_servo(lambda t: post.append((t, float(ctl.bank.sp_p[i]), float(ctl.bank.sp_v[i]),
                                             axis.drive.setpoint_word, float(ctl.bank.cmd_v[i]))))
    job = move(axis, 50.0)
    ctl.run_until(lambda: job.state == JobState.DONE, timeout=2.0)
    # the setpoint moves with its own velocity: between two cycles it advances by the mean of their velocities
    dt = ctl.servo_cycle
    for (t0, p0, v0, _, _), (t1, p1, v1, _, _) in zip(post, post[1:]):
        assert t1 - t0 == pytest.approx(dt)
        assert p1 - p0 == pytest.approx(0.5 * (v0 + v1) * dt, abs=0.05 * 400.0 * dt)
    # the end position is reached in the cycle in which the profile ends, and seen there
    assert post[-1][1] == pytest.approx(50.0)
    # the word sent is made from this cycle's speed command: a monotone function of it (a word made from the
    # previous cycle's command would not be, since the command rises while accelerating and falls while braking)
    pairs = sorted((cmd, word) for _, _, _, word, cmd in post)
    assert pairs[0][1] < 0 < pairs[-1][1] or pairs[-1][1] > pairs[0][1]
    assert all(w0 <= w1 for (_, w0), (_, w1) in zip(pairs, pairs[1:]))


def test_kernel_pre_servo_sees_the_inputs_of_this_cycle():
    """The machine model writes the inputs from the positions read in this cycle before the pre-servo hooks."""
    ctl = Controller()
    axis = enabled_axis(ctl)
    ctl.inputs.set_filter("I0.0", 0.0)
    ctl.plant.place_switch("I0.0", axis=axis, low=20.0)
    seen = []
    ctl.on_pre_servo(lambda t: seen.append((axis.drive.mechanical_position(), ctl.inputs["I0.0"])))
    job = move(axis, 40.0)
    ctl.run_until(lambda: job.state == JobState.DONE, timeout=2.0)
    assert any(on for _, on in seen) and not all(on for _, on in seen)
    for position, on in seen:
        assert on == (position >= 20.0)


# --- faults ---------------------------------------------------------------------------------------------------
def _boom(*args, **kwargs):
    raise ZeroDivisionError("injected kernel defect")


@pytest.mark.parametrize("owner, attribute, stage", [
    (ServoDrives, "read", "read_drives"),
    (DigitalInputs, "update", "read_inputs"),
    (monitoring, "standstill", "monitor"),
    (ServoDrives, "write", "write_drives"),
])
def test_kernel_a_failing_stage_stops_the_controller_and_names_the_stage(monkeypatch, owner, attribute, stage):
    ctl = Controller()
    axis = enabled_axis(ctl)
    move(axis, 100.0)
    ctl.run(0.02)
    after = []
    ctl.on_post_servo(after.append)
    monkeypatch.setattr(owner, attribute, _boom)
    with warnings.catch_warnings():
        warnings.simplefilter("error")             # no warning either: a kernel defect is no program fault
        ctl.step()                                 # nothing escapes step()
    monkeypatch.undo()
    assert ctl.mode == "STOP"
    assert f"stage {stage!r}" in ctl.stop_reason and "ZeroDivisionError" in ctl.stop_reason
    assert axis.state != "enabled"                 # STOP removes the enable (S7-1200 V6 §2.2.7.4)
    # the servo cycle does not run again until restart, the virtual time goes on
    n, t = len(after), ctl.time
    ctl.step()
    assert len(after) == n and ctl.time > t


def test_kernel_deferred_work_that_fails_names_its_stage():
    ctl = Controller()
    enabled_axis(ctl)
    ctl._defer(_boom)
    ctl.step()
    assert ctl.mode == "STOP" and "stage 'accept_jobs'" in ctl.stop_reason


def test_kernel_a_defect_in_one_axis_stops_only_that_axis(monkeypatch):
    ctl = Controller()
    a = enabled_axis(ctl, "A")
    b = enabled_axis(ctl, "B")
    move(a, 100.0)
    job_b = move(b, 100.0)
    ctl.run(0.02)

    original = type(a)._on_event

    def on_event(self, t):
        if self is a:
            raise ZeroDivisionError("defect in axis A")
        return original(self, t)

    monkeypatch.setattr(type(a), "_on_event", on_event)
    ctl.run_until(lambda: a.last_internal_error is not None, timeout=1.0)
    monkeypatch.undo()
    assert ctl.mode == "RUN"
    assert "defect in axis A" in a.last_internal_error
    ctl.run_until(lambda: job_b.state == JobState.DONE, timeout=2.0)
    assert b.state == "enabled"


def test_kernel_a_raising_hook_stops_the_controller_as_a_program_fault_and_the_cycle_completes():
    from plcmotion import ProgramErrorWarning
    ctl = Controller()
    axis = enabled_axis(ctl)

    def faulty(t):
        raise RuntimeError("hook fault")

    ctl.on_pre_servo(faulty)
    post = []
    ctl.on_post_servo(post.append)
    with pytest.warns(ProgramErrorWarning):
        ctl.step()
    assert ctl.mode == "STOP" and "servo hook" in ctl.stop_reason and "internal error" not in ctl.stop_reason
    assert axis.state != "enabled"
    assert len(post) == round(ctl.app_cycle / ctl.servo_cycle)   # every cycle ran to its end, post hooks too


def test_kernel_simulated_actual_values_are_the_setpoints():
    """A family's simulation mode (``axis.simulate_actual``; S7-Technology V4.1 §3.1.2 names one): while on,
    the control stage takes the setpoint as actual value (following error 0); off, the drive's actual value
    is read again."""
    ctl = Controller()
    axis = enabled_axis(ctl)
    i = axis.index
    axis.simulate_actual(True)
    move(axis, 50.0)
    fe = []
    ctl.on_post_servo(lambda t: fe.append((float(ctl.bank.fe[i]), float(ctl.bank.act_p[i] - ctl.bank.sp_p[i]))))
    ctl.run(0.2)
    assert all(e == 0.0 and d == 0.0 for e, d in fe) and ctl._n_sim == 1
    axis.simulate_actual(False)
    axis.simulate_actual(False)
    assert ctl._n_sim == 0
    ctl.run(0.01)
    assert float(ctl.bank.act_p[i]) == pytest.approx(axis.drive.mechanical_position(), abs=1e-3)


def test_kernel_enable_with_simulated_actual_values_leaves_the_drive_off():
    """An axis whose actual values are simulated (``axis.simulate_actual``, S7-Technology V4.1 §3.1.2) is
    enabled at once without enabling its drive; a positioning runs on the setpoints while the load stands."""
    ctl = Controller()
    axis = ctl.add_positioning_axis("Axis_1", SERVO_AXIS)
    axis.simulate_actual(True)
    assert axis.power(Owner(), True, 1, 0) is None and axis.state == "enabled"
    mech = axis.drive.mechanical_position()
    move(axis, 50.0)
    ctl.run(1.0)
    assert not axis.drive.ready(ctl.time)
    assert float(ctl.bank.act_p[axis.index]) == pytest.approx(50.0, abs=1e-9)
    assert axis.drive.mechanical_position() == pytest.approx(mech, abs=1e-12)
