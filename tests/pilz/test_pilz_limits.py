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
