"""Pacing the servo cycles to a wall clock: absolute deadlines, lateness statistics, overruns and their
reactions, the speed factor and the pacing tags - on a scripted clock, so every figure is exact.

S7-1200 V6 §2.2.7.3 (Overflows): an MC-Servo overflow sets the CPU to STOP; S7-Technology V4.1 §5.1: a set
number of overflows is tolerated, STOP once it is exceeded."""
from __future__ import annotations

import logging

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from plcmotion.services import LatenessStats, Pacer, ServeLoop, make_loop

from ._fixtures import ORIGIN, ScriptedClock, controller

MS = 1_000_000


def _serve(clock, seconds=1.0, **kw):
    ctl = controller()
    loop = make_loop(ctl, clock=clock, **kw)
    loop.run(seconds)
    return ctl, loop


def test_services_deadlines_are_absolute_so_late_wakeups_do_not_add_up():
    """Every sleep ends 0.3 ms late: cycle n still starts at origin + n x 1 ms + 0.3 ms, so after 1000
    cycles the last start is 999.3 ms after the first (a loop sleeping "one period" would be 300 ms late)."""
    clock = ScriptedClock(oversleep=lambda k: 300_000)
    ctl, loop = _serve(clock)
    assert ctl.time == pytest.approx(1.0)
    assert len(clock.sleeps) == 999                       # the first cycle sets the origin
    assert clock.sleeps == [ORIGIN + n * MS for n in range(1, 1000)]
    assert clock.t == ORIGIN + 999 * MS + 300_000
    tags = loop.pacing
    assert tags.Cycles == 1000 and tags.Overruns == 0 and tags.Slip == 0.0
    assert tags.LatenessMax == pytest.approx(0.3e-3, abs=1e-12)


def test_services_lateness_percentiles_are_nearest_rank_over_the_cycles():
    """Sleep k ends (k mod 100) us late: over cycles 0..999 each lateness 0..99 us occurs 10 times, so the
    500th smallest (p50) is 49 us, the 990th (p99) 98 us, the largest 99 us."""
    clock = ScriptedClock(oversleep=lambda k: (k % 100) * 1000)
    _, loop = _serve(clock)
    p = loop.pacing
    assert (p.tag("LatenessP50"), p.tag("LatenessP99"), p.tag("LatenessMax")) == (49e-6, 98e-6, 99e-6)
    assert p.tag("Overruns") == 0 and p.tag("Pacing.Cycles") == 1000


def test_services_speed_scales_the_wall_clock_without_rounding_drift():
    """--speed 3: a 1 ms servo cycle takes 1/3 ms; cycle 3000 is due exactly 1 s after the first (a loop
    adding a rounded 333333 ns period would be 1 us early)."""
    clock = ScriptedClock()
    ctl, loop = _serve(clock, seconds=3.004, speed=3.0)
    assert clock.sleeps[2999] == ORIGIN + 1_000_000_000
    assert clock.sleeps[:3] == [ORIGIN + 333_333, ORIGIN + 666_667, ORIGIN + 1_000_000]
    assert loop.pacing.Speed == 3.0
    clock = ScriptedClock()
    _serve(clock, seconds=0.1, speed=0.5)                  # half real time: 2 ms per servo cycle
    assert clock.sleeps[:2] == [ORIGIN + 2 * MS, ORIGIN + 4 * MS] and clock.t == ORIGIN + 99 * 2 * MS


def _slow_cycles(ctl, clock, times, work_ns):
    """Servo cycles at the virtual ``times`` [s] take ``work_ns`` of wall-clock time."""
    marks = {round(t * 1000) for t in times}
    ctl.on_post_servo(lambda t: clock.advance(work_ns) if round(t * 1000) in marks else None)


def test_services_a_cycle_starting_after_the_next_deadline_is_an_overrun_and_lays_deadlines_anew(caplog):
    """A servo cycle working 1.5 ms makes the next start 0.5 ms late (no overrun); one working 2.5 ms makes
    it 1.5 ms late, after the next deadline: an overrun.  The deadlines then count from that start, so the
    cycles after it are on time again and 1.5 ms of wall clock slipped."""
    clock = ScriptedClock()
    ctl = controller()
    _slow_cycles(ctl, clock, [0.100], 1_500_000)
    _slow_cycles(ctl, clock, [0.200], 2_500_000)
    loop = make_loop(ctl, clock=clock)
    with caplog.at_level(logging.WARNING, logger="plcmotion.serve"):
        loop.run(0.4)
    p = loop.pacing
    assert p.Overruns == 1 and ctl.mode == "RUN"
    assert p.LatenessMax == pytest.approx(1.5e-3, abs=1e-12) and p.Slip == pytest.approx(1.5e-3, abs=1e-12)
    assert p.LatenessP99 == 0.0                  # 2 late cycles of 400 are fewer than 1 %
    assert sorted(loop.pacer.stats.samples())[-3:] == [0, 500_000, 1_500_000]
    assert clock.t == ORIGIN + 399 * MS + 1_500_000               # every later cycle on its new deadline
    assert [r.getMessage() for r in caplog.records if "overrun" in r.getMessage()][0].startswith(
        "servo cycle overrun at t = 0.201 s: started 1.5 ms late")


def test_services_warn_counts_every_overrun_and_keeps_running():
    clock = ScriptedClock()
    ctl = controller()
    _slow_cycles(ctl, clock, [0.100 + 0.001 * i for i in range(5)], 2_500_000)
    loop = make_loop(ctl, clock=clock, overrun="warn")
    loop.run(0.2)
    assert loop.pacing.Overruns == 5 and ctl.mode == "RUN" and ctl.axes["Axis_1"].state == "enabled"


def test_services_stop_tolerates_overruns_in_a_row_then_the_cpu_goes_to_stop():
    """--overrun stop, 2 tolerated: two overruns in a row keep RUN; the third in a row is an MC-Servo overflow
    that sets the CPU to STOP (axes disabled, as at any STOP); the program watchdog reacts with STOP too."""
    clock = ScriptedClock()
    ctl = controller()
    _slow_cycles(ctl, clock, [0.100, 0.101], 2_500_000)                # 2 in a row: tolerated
    _slow_cycles(ctl, clock, [0.200, 0.201, 0.202], 2_500_000)         # 3 in a row: STOP
    loop = make_loop(ctl, clock=clock, overrun="stop", tolerated=2)
    assert ctl.watchdog.stop
    loop.run(0.15)
    assert loop.pacing.Overruns == 2 and ctl.mode == "RUN"
    loop.run(0.15)
    assert loop.pacing.Overruns == 5 and ctl.mode == "STOP"
    assert "MC-Servo overflow" in ctl.stop_reason and "3 in a row (tolerated 2)" in ctl.stop_reason
    assert ctl.axes["Axis_1"].state == "disabled"
    assert loop.ended_by == "STOP"


def test_services_pacing_tags_read_like_technology_object_tags():
    clock = ScriptedClock(oversleep=lambda k: 1000)
    _, loop = _serve(clock, seconds=0.1)
    tags = loop.pacing
    assert tags.name == "Pacing" and tags.tag_paths() == ["LatenessP50", "LatenessP99", "LatenessMax", "Overruns",
                                                          "Cycles", "Slip", "Speed"]
    getter = tags.tag_getter("Pacing.LatenessP99")
    assert getter() == tags.LatenessP99 == tags.tag("LatenessP99") == 1e-6
    with pytest.raises(KeyError, match="Pacing has no tag 'Latency'; tags: LatenessP50"):
        tags.tag("Latency")
    with pytest.raises(AttributeError, match="no tag 'Jitter'"):
        tags.Jitter


def test_services_pacing_rejects_bad_settings():
    ctl = controller()
    for kw, text in (({"speed": 0.0}, "speed must be"), ({"speed": float("nan")}, "speed must be"),
                     ({"reaction": "halt"}, "must be one of warn, stop"), ({"tolerated": -1}, "whole number")):
        with pytest.raises(ValueError, match=text):
            Pacer(ctl, **kw)
    with pytest.raises(ValueError, match="shutdown_timeout"):
        ServeLoop(ctl, shutdown_timeout=-1.0)


@given(st.lists(st.integers(0, 10**9), min_size=1, max_size=300), st.integers(1, 64),
       st.sampled_from([1, 50, 99, 100]))
def test_services_lateness_window_percentile_is_the_nearest_rank_of_the_last_cycles(samples, window, p):
    """The percentile is the smallest of the last ``window`` samples with at least p % at or below it; the
    maximum and the count cover all samples."""
    stats = LatenessStats(window)
    for s in samples:
        stats.add(s)
    last = sorted(samples[-window:])
    assert stats.percentile_ns(p) == last[max(1, -(-p * len(last) // 100)) - 1]
    assert list(stats.samples()) == samples[-window:]
    assert stats.max_ns == max(samples) and stats.count == len(samples)


@settings(max_examples=40)
@given(st.lists(st.integers(0, 999_999), min_size=1, max_size=50), st.sampled_from([0.25, 1.0, 3.0, 7.0]))
def test_services_deadlines_stay_absolute_for_any_wakeup_delays_below_a_cycle(delays, speed):
    """Wake-ups late by less than a servo cycle / speed never shift the deadlines (no overrun, no slip)."""
    period = 1e6 / speed
    clock = ScriptedClock(oversleep=lambda k: int(delays[k % len(delays)] * min(1.0, 1 / speed)) % int(period))
    ctl = controller()
    loop = make_loop(ctl, clock=clock, speed=speed)
    loop.run(0.2)
    assert clock.sleeps == [ORIGIN + round(n * period) for n in range(1, 200)]
    assert loop.pacing.Overruns == 0 and loop.pacing.Slip == 0.0
