"""Invariants of the command interaction (S7-Technology V4.1 §6.8, §6.2.3, §6.2.6, §6.2.10) under any sequence of
valid commands, OB1 cycle by OB1 cycle: a command refused at its start gets only an ErrorID of the interaction
(8005, 8045, 8055); no motion command starts while an MC_Stop holds the axis; only a new MC_Stop sets an
MC_Stop's CommandAborted; at most one basic command waits behind the running one; MC_Home Mode 3/4 (§6.2.2: no
MC_Stop lock, refused only by a restart) always start, MC_Home Mode 8 without a passive homing gets 8045.
(MC_ChangeDataset is not in the pool: the axis is virtual, which has one data set, 16#804D.)
"""
from __future__ import annotations

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from plcmotion.s7t import (MC_Halt, MC_Home, MC_MoveAbsolute, MC_MoveAdditive, MC_MoveRelative, MC_MoveSuperImposed,
                           MC_MoveVelocity, MC_Stop)

from _s7t_rig import enabled

DYN = dict(Acceleration=200.0, Deceleration=200.0, Jerk=0.0)
#: (FB, inputs, Mode values it takes) - every input valid, so any refusal is one of the interaction
POOL = [
    (MC_MoveAbsolute, dict(Position=40.0, Velocity=30.0, **DYN), (0, 1, 2)),
    (MC_MoveAbsolute, dict(Position=-20.0, Velocity=50.0, **DYN), (0, 1, 2)),
    (MC_MoveRelative, dict(Distance=15.0, Velocity=40.0, **DYN), (0, 1, 2)),
    (MC_MoveAdditive, dict(Distance=-10.0, Velocity=40.0, **DYN), (0,)),
    (MC_MoveVelocity, dict(Velocity=25.0, **DYN), (0, 1)),
    (MC_MoveVelocity, dict(Velocity=15.0, Direction=3, **DYN), (0, 1)),
    (MC_Halt, dict(Deceleration=150.0, Jerk=0.0), (0,)),
    (MC_MoveSuperImposed, dict(Distance=5.0, VelocityDiff=10.0, **DYN), (0,)),
    (MC_Stop, dict(Deceleration=300.0, Jerk=0.0), (0,)),
    (MC_Stop, dict(Deceleration=100.0, Jerk=0.0), (0,)),
    (MC_Home, dict(Position=5.0), (3, 4, 8)),
]
INTERACTION = {0x8005, 0x8045, 0x8055}
BASIC = (MC_MoveAbsolute, MC_MoveRelative, MC_MoveAdditive, MC_MoveVelocity, MC_Halt)


@st.composite
def step(draw):
    """(instance, Execute, Mode) set before one OB1 cycle, and how many cycles to run then."""
    k = draw(st.integers(0, len(POOL) - 1))
    return k, draw(st.booleans()), draw(st.sampled_from(POOL[k][2])), draw(st.sampled_from([1, 1, 3, 20, 80]))


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(step(), min_size=1, max_size=25))
def test_s7t_interaction_invariants(steps):
    """S7-Technology V4.1 §6.8 with §6.2.3 (MC_Stop lock 8045, CommandAborted only by MC_Stop), §6.2.6 / §6.2.10
    (Mode 1/2: 8055, one waiting command: 8005), §6.2.2 MC_Home Mode 3/4/8 (§6.8.2:
    nothing refuses Mode 3/4 here)."""
    ctl, axis, _ = enabled()
    fbs = [cls() for cls, _, _ in POOL]
    execute = [False] * len(POOL)
    mode = [0] * len(POOL)
    stop_ids = [k for k, (cls, _, _) in enumerate(POOL) if cls is MC_Stop]
    for k, exe, m, cycles in steps:
        execute[k], mode[k] = exe, m
        for _ in range(cycles):
            before = [(f.Busy, f.CommandAborted) for f in fbs]
            locked = any(fbs[s].Busy for s in stop_ids)
            started = []
            for j, (cls, inputs, modes) in enumerate(POOL):
                rising = execute[j] and not fbs[j].Execute
                extra = {"Mode": mode[j]} if len(modes) > 1 else {}
                fbs[j](Axis=axis, Execute=execute[j], **inputs, **extra)
                if rising:
                    started.append(j)
                    f = fbs[j]
                    if f.Error:
                        assert f.ErrorID in INTERACTION, (cls.__name__, hex(f.ErrorID))
                    if cls is MC_Home and mode[j] != 8:
                        assert not f.Error, (cls.__name__, mode[j], hex(f.ErrorID))
                    elif cls is MC_Home:
                        assert f.Error and f.ErrorID == 0x8045      # no passive homing in the pool
                    elif locked and cls is not MC_Stop:
                        assert f.Error and f.ErrorID == 0x8045, cls.__name__
            for j, (cls, inputs, modes) in enumerate(POOL):       # a second call: every output up to date
                fbs[j](Axis=axis, Execute=execute[j], **inputs, **({"Mode": mode[j]} if len(modes) > 1 else {}))
            for s in stop_ids:
                if fbs[s].CommandAborted and not before[s][1]:
                    assert any(o in started for o in stop_ids if o != s), "MC_Stop aborted by no MC_Stop"
            busy_basic = [j for j, (cls, _, _) in enumerate(POOL) if cls in BASIC and fbs[j].Busy]
            assert len(busy_basic) <= 2, [POOL[j][0].__name__ for j in busy_basic]
            assert ctl.mode == "RUN", ctl.stop_reason
            ctl.step()
