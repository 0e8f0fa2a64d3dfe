"""The fuzzer's invariant checks themselves: each must report a violation planted in an otherwise good
episode (a check that cannot fail would let defects through), and a good episode must pass."""
from __future__ import annotations

import numpy as np

from .gen import Episode, Op
from .repro import script, shrink
from .runner import Run
from .values import Ref


def _episode(actor: int = 1, jerk: float = 0.0) -> Episode:
    ep = Episode(0, "S7-1200 V6", {"servo_cycle": 0.001, "app_cycle": 0.004})
    ep.axes = [{"name": "Axis_1", "kind": "pos", "params": {
        "Actor.Type": actor, "DynamicLimits.MaxVelocity": 50.0, "DynamicLimits.MinVelocity": 1.0 if actor == 2 else 0.0,
        "DynamicDefaults.Acceleration": 500.0, "DynamicDefaults.Deceleration": 500.0, "DynamicDefaults.Jerk": jerk}}]
    ep.fbs = [{"name": "power", "cls": "MC_Power", "init": {"Axis": Ref("Axis_1"), "Enable": True}},
              {"name": "move", "cls": "MC_MoveRelative", "init": {"Axis": Ref("Axis_1"), "Distance": 20.0,
                                                                   "Velocity": 40.0}}]
    ep.ops = [Op(5, "in", "move", "Execute", True), Op(80, "in", "move", "Execute", False)]
    ep.cycles = 150
    return ep


def _planted(ep: Episode, hook) -> Run:
    run = Run(ep)
    run.ctl._post_servo.insert(0, hook)           # runs before the fuzzer's own servo hook
    return run


def test_fuzz_a_good_episode_passes():
    assert Run(_episode()).run() is None


def test_fuzz_nan_in_a_setpoint_is_reported():
    run = _planted(_episode(), lambda t: t > 0.1 and run.ctl.bank.sp_v.__setitem__(0, np.nan))
    f = run.run()
    assert f is not None and f.kind == "nonfinite" and "sp_v" in f.message


def test_fuzz_velocity_above_max_velocity_is_reported():
    run = _planted(_episode(), lambda t: 0.05 < t < 0.06 and run.ctl.bank.sp_v.__setitem__(0, 50.2))
    f = run.run()
    assert f is not None and f.kind == "velocity", f


def test_fuzz_a_stop_is_reported():
    run = _planted(_episode(), lambda t: t > 0.2 and run.ctl.stop("planted"))
    f = run.run()
    assert f is not None and f.kind == "stop"


def test_fuzz_an_exception_out_of_an_instruction_is_reported_and_shrunk_to_a_script():
    ep = _episode()
    ep.ops.insert(1, Op(30, "in", "move", "Execute", "yes"))    # a non-boolean at a BOOL input: ProgramError
    f = Run(ep).run()
    assert f is not None and f.kind == "exception" and "ProgramError" in f.message   # a TypeError subclass
    small, f2 = shrink(ep, f, budget=10.0)
    assert f2.signature() == f.signature() and len(small.ops) <= len(ep.ops)
    text = script(small, f2)
    compile(text, "repro.py", "exec")
    assert "FB['move'].Execute = 'yes'" in text


def _plant_segment(run: Run, at: float, jerk_sign: float) -> None:
    """At ``at`` the axis gets a segment with 20x the configured jerk, opposing its acceleration for
    ``jerk_sign`` -1 (taking it back to zero in less than a servo cycle, then cruising, as a settling plan
    does) or building it for +1, as if a plan made at that sample had it."""
    dt = run.ctl.servo_cycle

    def hook(t):
        b = run.ctl.bank
        if abs(t - at) < 1e-9 and b.sp_a[0] != 0.0:
            b.seg_t[0], b.seg_p[0], b.seg_v[0], b.seg_a[0] = t, b.sp_p[0], b.sp_v[0], b.sp_a[0]
            b.seg_j[0] = jerk_sign * np.sign(b.sp_a[0]) * 20_000.0
            b.sp_j = b.sp_j.copy()
            b.sp_j[0] = b.seg_j[0]
        elif jerk_sign < 0 and abs(t - at - dt) < 1e-9:
            a0, j0 = b.seg_a[0], b.seg_j[0]
            tau = -a0 / j0                          # when the settling segment took the acceleration to zero
            b.seg_p[0] += tau * (b.seg_v[0] + tau * (a0 / 2 + tau * j0 / 6))
            b.seg_v[0] += tau * (a0 + tau * j0 / 2)
            b.seg_t[0], b.seg_a[0], b.seg_j[0] = at + tau, 0.0, 0.0
            b.sp_a = b.sp_a.copy()
            b.sp_a[0] = 0.0
            b.sp_j = b.sp_j.copy()
            b.sp_j[0] = 0.0
    run.ctl._post_servo.insert(0, hook)


def test_fuzz_a_jerk_above_the_configured_jerk_is_reported():
    run = Run(_episode(jerk=1000.0))

    def hook(t):
        if abs(t - 0.03) < 1e-9:
            b = run.ctl.bank
            b.sp_j = b.sp_j.copy()          # the output only (the bank's sp_j may share the segment's array)
            b.sp_j[0] = 5000.0
    run.ctl._post_servo.insert(0, hook)
    f = run.run()
    assert f is not None and f.kind == "jerk", f


def test_fuzz_a_fresh_segment_building_acceleration_with_a_jerk_above_the_configured_one_is_reported():
    run = Run(_episode(jerk=1000.0))
    _plant_segment(run, 0.03, +1.0)
    f = run.run()
    assert f is not None and f.kind == "jerk", f


def test_fuzz_a_settling_segment_is_out_of_the_jerk_checks_scope():
    """docs/decisions.md row 66: a re-plan may take back the acceleration it starts with using a jerk above
    the configured one (so the velocity keeps its bound); such a segment starts at the re-plan and opposes
    the acceleration."""
    run = Run(_episode(jerk=1000.0))
    _plant_segment(run, 0.03, -1.0)
    assert run.run() is None


def _s7t_episode() -> Episode:
    ep = Episode(0, "S7-Technology", {"servo_cycle": 0.002, "app_cycle": 0.004, "family": "S7-Technology"})
    ep.axes = [{"name": "Axis_1", "kind": "pos", "params": {
        "DBNumber": 10, "Wizard.Virtual": 1, "TypeOfAxis.Homing.referencingNecessary": 0,
        "swlimit.state": 1, "swlimit.minusposition": -100.0, "swlimit.plusposition": 100.0}}]
    ep.fbs = [{"name": "power", "cls": "MC_Power", "init": {"Axis": Ref("Axis_1"), "Enable": True}},
              {"name": "move", "cls": "MC_MoveRelative", "init": {"Axis": 10, "Distance": 20.0, "Velocity": 40.0}}]
    ep.ops = [Op(5, "in", "move", "Execute", True)]
    ep.cycles = 400
    return ep


def test_fuzz_s7t_a_good_episode_passes():
    """S7-Technology V4.1: an axis addressed by its DB number moves and the episode passes every check."""
    run = Run(_s7t_episode())
    assert run.run() is None
    assert run.fbs["move"].Done and abs(run.ctl.bank.sp_p[0] - 20.0) < 1e-9


def test_fuzz_s7t_an_errorid_outside_the_table_and_a_limit_overrun_are_reported():
    """The S7-Technology checks: an ErrorID MC_MoveRelative's table (§6.2.7) does not list, and a setpoint
    beyond the active software limit switch."""
    run = Run(_s7t_episode())
    inst = run.fbs["move"]
    evaluate = inst._evaluate

    def planted() -> None:
        evaluate()
        if run.ctl.time > 0.2:
            inst.__dict__["ErrorID"] = 0x8041        # an ErrorID of the technology DB, not of the FB
    object.__setattr__(inst, "_evaluate", planted)
    f = run.run()
    assert f is not None and f.kind == "errorid", f
    run = Run(_s7t_episode())

    def runaway(t: float) -> None:                    # a setpoint running at 500 mm/s through the limit at 100
        if t > 0.2:
            b = run.ctl.bank
            b.sp_p[0], b.sp_v[0] = 20.0 + 500.0 * (t - 0.2), 500.0
    run.ctl._post_servo.insert(0, runaway)
    f = run.run()
    assert f is not None and f.kind == "swlimit", f


def _s7_1500_episode() -> Episode:
    ep = Episode(0, "S7-1500", {"servo_cycle": 0.001, "app_cycle": 0.004, "family": "S7-1500"})
    ep.axes = [{"name": "Axis_1", "kind": "pos", "params": {}}]
    ep.fbs = [{"name": "power", "cls": "MC_Power", "init": {"Axis": Ref("Axis_1"), "Enable": True}},
              {"name": "move", "cls": "MC_MoveRelative", "init": {"Axis": Ref("Axis_1"), "Distance": 20.0}}]
    ep.ops = [Op(5, "in", "move", "Execute", True), Op(80, "in", "move", "Execute", False)]
    ep.cycles = 150
    return ep


def test_fuzz_s7_1500_an_errorid_outside_the_instruction_list_is_reported():
    """The S7-1500 check: MC_MoveRelative showing 16#8009 (illegal Position, a code of MC_MoveAbsolute, not
    of MC_MoveRelative) is reported; the good episode passes."""
    assert Run(_s7_1500_episode()).run() is None
    run = Run(_s7_1500_episode())
    inst = run.fbs["move"]
    evaluate = inst._evaluate

    def planted() -> None:
        evaluate()
        if run.ctl.time > 0.2:
            inst.__dict__["ErrorID"] = 0x8009
    object.__setattr__(inst, "_evaluate", planted)
    f = run.run()
    assert f is not None and f.kind == "errorid", f
