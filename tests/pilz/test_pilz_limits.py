"""Invariants of the Pilz motion core under any command sequence (Pilz V6.5 §1.2.2, §1.2.3, §1.5.3, §1.7.3):
the set position never leaves the software limit switches of a limited axis and the set velocity never
exceeds I10, whatever the set values and the override."""
from __future__ import annotations

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from ._core import make_axis, release, start

LIMITS = {"I50": 300.0, "I51": -300.0, "I10": 400.0, "I11": 4000.0, "I16": 200000.0}

commands = st.sampled_from([1, 2, 3, 4, 5, 8, 11])
values = st.floats(min_value=-1000.0, max_value=1000.0, allow_nan=False)
dynamics = st.floats(min_value=0.0, max_value=20000.0, allow_nan=False)
step = st.tuples(commands, values, st.floats(min_value=0.0, max_value=900.0), dynamics, dynamics,
                 st.floats(min_value=0.0, max_value=250.0), st.integers(min_value=20, max_value=250))


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(step, min_size=1, max_size=5))
def test_pilz_limits_never_beyond(sequence):
    """Pilz V6.5 §1.2.2 / §1.2.3 / §1.9.3: software limit switches hold and |set velocity| <= I10 always."""
    ctl, ax = make_axis(LIMITS)
    worst_v, lo, hi = 0.0, 0.0, 0.0
    for command, value, velocity, acc, jerk, override, cycles in sequence:
        ax.registers.I230 = override
        start(ax, command, I403=value, I404=velocity if command != 4 else value, I405=acc, I406=acc, I407=jerk,
              I426=value, I216=acc, I217=acc)
        for _ in range(cycles):
            ctl.step()
            s = ax.status
            worst_v = max(worst_v, abs(s.E07))
            lo, hi = min(lo, s.I96), max(hi, s.I96)
        release(ax)
        if ax.alarms:
            ax.reset()
    assert worst_v <= 400.0 * (1 + 1e-9)
    assert -300.0 - 1e-6 <= lo and hi <= 300.0 + 1e-6


cyclic_values = st.lists(st.floats(min_value=-5000.0, max_value=5000.0, allow_nan=False), min_size=5, max_size=40)


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from([7, 9, 10]), cyclic_values, st.sampled_from([0, 1]))
def test_pilz_limits_cyclic_never_above_i10(command, values, endless):
    """Pilz V6.5 §1.8.3, §1.10.5, §1.11.3: whatever the controller sends, the set velocity of MC_CyclicSpeed,
    MC_TorqueControl and MC_CyclicPosition never exceeds I10."""
    ctl, ax = make_axis({"I10": 400.0, "I00": endless, "I01": 360.0, "Drive.Inertia": 0.001, "E65": 50.0,
                         "E66": 50.0})
    name = {7: "I426", 9: "I428", 10: "I421"}[command]
    feed = {"k": 0}

    def controller():
        v = values[feed["k"] % len(values)]
        feed["k"] += 1
        if command == 10 and endless:
            v = v % 360.0
        ax.registers.write(name, v)

    ctl.program(controller)
    start(ax, command, **{name: 0.0})
    worst = 0.0
    for _ in range(200):
        ctl.step()
        worst = max(worst, abs(ax.status.E07))
    assert worst <= 400.0 * (1 + 1e-9)


_VALUES = st.sampled_from([0.0, -1.0, 1.0, 50.0, -50.0, 359.0, 400.0, -1000.0, 1e6, 1e-9])
_REGS = ("I403", "I404", "I405", "I406", "I407", "I421", "I426", "I428", "I429", "I430", "I431", "I216", "I217")
_STEP = st.tuples(st.integers(min_value=0, max_value=11), st.tuples(*[_VALUES] * len(_REGS)),
                  st.integers(min_value=0, max_value=1), st.integers(min_value=0, max_value=3),
                  st.sampled_from([0.0, 50.0, 150.0]), st.sampled_from([1, 10, 100, 300]), st.booleans())


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from([0, 1]), st.sampled_from([0.0, 100.0, 5000.0]), st.sampled_from([0.0, 1e3, 1e5]),
       st.lists(_STEP, min_size=1, max_size=6))
def test_pilz_limits_any_register_sequence(endless, i11, i16, steps):
    """Pilz V6.5 §1 (the register interface): whatever a program writes - zero, tiny, huge and negative set
    values, any command, any command mode, direction, override, Execute pattern - the motion core answers with
    its status words: no internal error (16#8FFF) and the controller stays in RUN."""
    ctl, ax = make_axis({"I00": endless, "I01": 360.0, "I11": i11, "I16": i16, "I50": 300.0, "I51": -300.0,
                         "I30": 3, "Plant.ZeroMarkDistance": 10.0}, referenced=False)
    for command, values, mode, direction, override, cycles, low in steps:
        ax.registers.I230 = override
        start(ax, command, **dict(zip(_REGS, values)), I409=mode, I411=direction)
        for _ in range(cycles):
            ctl.step()
        if low:
            release(ax)
        if ax.alarms:
            ax.reset()
        assert ctl.mode == "RUN" and ax.last_internal_error is None
