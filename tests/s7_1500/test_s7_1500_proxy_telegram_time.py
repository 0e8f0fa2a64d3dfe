"""Leading axis proxy and telegram times far from the expected one (issue 8, leftover of defect 2/9;
S7-1500T V5 §8.1.2 tolerance time and invalid leading value, §8.1.3 delay, §A.3.6 StatusWord.X4).

A telegram whose time is finite but far in the future (1e9 s while the controller is at 2 s) used to
become the proxy's newest telegram, so that every later genuine telegram was "not newer" and ignored:
the proxy froze and alarm 900 stopped the followers for good.  The admissible time of a telegram is now
bounded around what the proxy expects - from the local time minus the sender's delay (minus a window)
up to the local time plus the window, the window being ``LeadingAxisProxy.telegram_time_window`` (1 s by
default) or ten tolerance times if that is longer.  A telegram outside is an invalid telegram like one
with a NaN time: it never becomes the leading value and does not block the genuine ones that follow.
"""
import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from plcmotion import Controller
from plcmotion.kernel.leading_value import LeadingValueSample
from _s7_1500_rig import Feed
from plcmotion.s7_1500 import MC_GearIn, MC_Power

VIRTUAL = {"VirtualAxis": {"Mode": 1}}
V = 10.0
CYCLE = 0.004


class Remote:
    """Proxy P fed with the sender's telegrams (one genuine per application cycle, plus forged ones),
    follower S geared 1:1 by MC_GearIn."""

    def __init__(self, tolerance=0.02, delay=0.0):
        self.ctl = Controller(family="S7-1500T", app_cycle=CYCLE)
        self.feed = Feed()
        self.delay = delay
        self.p = self.ctl.add_leading_axis_proxy(
            "P", {"Parameter": {"ToleranceTimeExternalLeadingValueInvalid": tolerance}}, source_link=self.feed)
        self.s = self.ctl.add_synchronous_axis("S", VIRTUAL, leading_values=["P"])
        self.power, self.gear = MC_Power(), MC_GearIn()
        self.seq = 0
        self.rows = []

        @self.ctl.program
        def main():
            self.power(Axis=self.s, Enable=True)
            self.gear(Master=self.p, Slave=self.s, Execute=self.power.Status)

    def genuine(self):
        t = self.ctl.time
        self.seq += 1
        return LeadingValueSample(time=t, position=V * t, velocity=V, acceleration=0.0, sequence=self.seq,
                                  delay=self.delay)

    def step(self, n=1, before=(), after=()):
        """``n`` application cycles; forged telegrams ``before``/``after`` the genuine one of each."""
        for _ in range(n):
            self.feed.queue.extend(before)
            self.feed.queue.append(self.genuine())
            self.feed.queue.extend(after)
            self.ctl.step()
            t = self.ctl.time
            self.rows.append(dict(t=t, x4=bool(self.p.StatusWord.X4), alarm=bool(self.p.ErrorWord.X2),
                                  p=self.p.Position, s=self.s.Position, in_gear=self.gear.InGear,
                                  error=self.gear.Error))

    def synchronous(self):
        self.step(100)
        assert self.gear.InGear and self.p.StatusWord.X4

    def in_step(self, row):
        """The proxy gives the sender's value of (now - delay): V * (t - delay)."""
        return abs(row["p"] - V * (row["t"] - self.delay)) <= 1e-6


def forged(time, **fields):
    values = dict(position=-5e11, velocity=0.0, acceleration=0.0, sequence=1 << 40, delay=0.0)
    values.update(fields)
    return LeadingValueSample(time=time, **values)


@pytest.mark.parametrize("when", [1e9, 1e12, 2.0 + 100.0, -1e9, -1e12],
                         ids=["1e9", "1e12", "now+100", "-1e9", "-1e12"])
@pytest.mark.parametrize("delay", [0.0, 0.008])
def test_s7_1500_a_forged_telegram_far_from_now_does_not_freeze_the_proxy_s8_1_2(when, delay):
    """Defect (leftover of 2): the forged telegram of time 1e9 s became the newest one and the proxy
    ignored the genuine stream after it (alarm 900 after the tolerance time).  Now it is an invalid
    telegram: the genuine telegrams go on being used, the follower stays in gear and in step, no alarm."""
    r = Remote(tolerance=0.02, delay=delay)
    r.step(500)                                  # the controller at 2 s
    assert r.gear.InGear
    n0 = len(r.rows)
    r.step(1, after=[forged(when)])
    r.step(50)
    rows = r.rows[n0:]
    assert r.ctl.mode == "RUN"
    assert not any(x["alarm"] or x["error"] for x in rows)
    assert all(x["in_gear"] for x in rows)
    assert all(r.in_step(x) for x in rows), [x["p"] - V * (x["t"] - delay) for x in rows][:5]
    assert r.p.StatusWord.X4 and r.p.Position == pytest.approx(V * (r.ctl.time - delay), abs=1e-6)
    steps = [b["s"] - a["s"] for a, b in zip(rows, rows[1:])]
    assert all(d == pytest.approx(V * CYCLE, abs=1e-9) for d in steps)


def test_s7_1500_a_telegram_outside_the_window_is_invalid_like_a_nan_time_s8_1_2():
    """Out of the admissible window is the same as no time at all: the proxy's invalid-telegram path
    (StatusWord.X4 drops while the value in use lies beyond the last valid telegram, §A.3.6) - before the
    fix a far-future telegram froze the proxy, a far-past one was taken silently."""
    outs = {}
    for name, when in (("nan", math.nan), ("future", 1e9), ("past", -1e9)):
        r = Remote(tolerance=0.02)
        r.synchronous()
        n0 = len(r.rows)
        r.step(1, after=[forged(when, valid=True)])
        r.step(10)
        outs[name] = [(x["x4"], x["alarm"], x["p"]) for x in r.rows[n0:]]
    assert outs["future"] == outs["nan"] and outs["past"] == outs["nan"]
    assert not outs["nan"][0][0] and all(x4 and not alarm for x4, alarm, _ in outs["nan"][1:])


def test_s7_1500_a_forged_delay_with_a_far_time_is_no_way_around_the_window_s8_1_3():
    """A forged telegram with a huge delay and a time matching it (t - 1e9) at the start, before any
    genuine telegram: it is admitted only as far as its own delay says, and the genuine stream takes
    over at once (the sender's delay is that of the newest telegram)."""
    r = Remote(tolerance=0.02)
    r.step(1, before=[forged(-1e9 + 0.0, delay=1e9)])
    r.step(100)
    assert r.gear.InGear and r.p.StatusWord.X4
    assert r.p.Position == pytest.approx(V * r.ctl.time, abs=1e-6)


def test_s7_1500_a_forged_invalid_telegram_just_ahead_blocks_x4_no_longer_than_the_next_genuine_one_a_3_6():
    """An invalid-flagged telegram dated ahead of the local time (inside the window) counts from now:
    the next genuine telegram makes the leading value valid again, no alarm 900."""
    r = Remote(tolerance=0.02)
    r.synchronous()
    n0 = len(r.rows)
    r.step(1, after=[forged(r.ctl.time + 0.5, valid=False)])
    r.step(20)
    rows = r.rows[n0:]
    assert not any(x["alarm"] for x in rows)
    assert all(x["x4"] for x in rows[1:])


def test_s7_1500_the_window_is_configurable():
    """``telegram_time_window``: a stricter bound makes a telegram 0.5 s ahead invalid too; a wider one
    (or a long tolerance time) admits it."""
    r = Remote(tolerance=0.02)
    r.p.telegram_time_window = 0.1
    r.step(100)
    n0 = len(r.rows)
    r.step(1, after=[forged(r.ctl.time + 0.5)])
    r.step(20)
    assert all(r.in_step(x) for x in r.rows[n0:]) and not any(x["alarm"] for x in r.rows[n0:])
    with pytest.raises(ValueError):
        r.p.telegram_time_window = math.nan
    with pytest.raises(ValueError):
        r.p.telegram_time_window = 0.0


# times out of the window (1 s; the controller runs at < 2 s): relative to now, or absolute
_relative = st.tuples(st.one_of(st.floats(1.5, 1e12), st.floats(-1e12, -1.5)), st.just(True))
_absolute = st.tuples(st.one_of(st.floats(1e3, 1e12), st.floats(-1e12, -1e3),
                                st.sampled_from([math.nan, math.inf, -math.inf])), st.just(False))
_value = st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.floats(-1e3, 1e3))
_forged = st.builds(lambda when, p, v, valid, delay: (when[0], when[1], dict(position=p, velocity=v, valid=valid,
                                                                            delay=delay)),
                    st.one_of(_relative, _absolute), _value, _value, st.booleans(), st.sampled_from([0.0, 0.008, 1e9]))


@settings(max_examples=30, deadline=None, suppress_health_check=list(HealthCheck))
@given(delay=st.sampled_from([0.0, 0.008]),
       plan=st.lists(st.tuples(st.integers(0, 2), st.lists(_forged, max_size=3), st.booleans()), min_size=1,
                     max_size=30))
def test_s7_1500_forged_telegrams_never_take_the_follower_out_of_step_hypothesis(delay, plan):
    """Invariant (hypothesis): telegrams forged with times out of the admissible window (far future, far
    past, non-finite; relative to now or absolute) and any values, interleaved before or after a genuine
    stream, never take the follower out of step: no alarm 900, InGear throughout, the proxy's value is
    the genuine one of (now - delay) and the follower moves evenly - during the attack and after it."""
    r = Remote(tolerance=0.02, delay=delay)
    r.synchronous()
    n0 = len(r.rows)
    for gap, forgeries, first in plan:
        t = r.ctl.time
        tel = [forged((t + dt) if rel else dt, **f) for dt, rel, f in forgeries]
        r.step(1, before=tel if first else (), after=() if first else tel)
        r.step(gap)
    r.step(30)
    rows = r.rows[n0:]
    assert r.ctl.mode == "RUN"
    assert not any(x["alarm"] or x["error"] for x in rows)
    assert all(x["in_gear"] for x in rows)
    assert all(r.in_step(x) for x in rows)
    steps = [b["s"] - a["s"] for a, b in zip(rows, rows[1:])]
    assert all(d == pytest.approx(V * CYCLE, abs=1e-9) for d in steps)
    assert r.p.StatusWord.X4
