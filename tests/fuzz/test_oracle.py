"""The fuzzer's invariant checks themselves: each must report a violation planted in an otherwise good
episode (a check that cannot fail would let defects through), and a good episode must pass."""
from __future__ import annotations

import numpy as np

from .gen import Episode, Op
from .repro import script, shrink
from .runner import Run
from .values import Ref


def _episode(actor: int = 1) -> Episode:
    ep = Episode(0, "S7-1200 V6", {"servo_cycle": 0.001, "app_cycle": 0.004})
    ep.axes = [{"name": "Axis_1", "kind": "pos", "params": {
        "Actor.Type": actor, "DynamicLimits.MaxVelocity": 50.0, "DynamicLimits.MinVelocity": 1.0 if actor == 2 else 0.0,
        "DynamicDefaults.Acceleration": 500.0, "DynamicDefaults.Deceleration": 500.0, "DynamicDefaults.Jerk": 0.0}}]
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


def test_a_good_episode_passes():
    assert Run(_episode()).run() is None


def test_nan_in_a_setpoint_is_reported():
    run = _planted(_episode(), lambda t: t > 0.1 and run.ctl.bank.sp_v.__setitem__(0, np.nan))
    f = run.run()
    assert f is not None and f.kind == "nonfinite" and "sp_v" in f.message


def test_velocity_above_max_velocity_is_reported():
    run = _planted(_episode(), lambda t: 0.05 < t < 0.06 and run.ctl.bank.sp_v.__setitem__(0, 50.2))
    f = run.run()
    assert f is not None and f.kind == "velocity", f


def test_a_stop_is_reported():
    run = _planted(_episode(), lambda t: t > 0.2 and run.ctl.stop("planted"))
    f = run.run()
    assert f is not None and f.kind == "stop"


def test_an_exception_out_of_an_instruction_is_reported_and_shrunk_to_a_script():
    ep = _episode()
    ep.ops.insert(1, Op(30, "in", "move", "Execute", "yes"))    # a non-boolean at a BOOL input: ProgramError
    f = Run(ep).run()
    assert f is not None and f.kind == "exception" and "ProgramError" in f.message   # a TypeError subclass
    small, f2 = shrink(ep, f, budget=10.0)
    assert f2.signature() == f.signature() and len(small.ops) <= len(ep.ops)
    text = script(small, f2)
    compile(text, "repro.py", "exec")
    assert "FB['move'].Execute = 'yes'" in text
