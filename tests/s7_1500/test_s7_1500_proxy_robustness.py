"""Leading axis proxy with invalid leading values from the network (issue 8, defect 2; S7-1500T V5 §8.1.2
tolerance time, §A.3.5/§A.3.6 StatusWord.X4 LeadingValueValid, alarm 900).

A telegram flagged invalid, or whose values are not finite numbers within the LREAL ranges of the
proxy's tags, is an invalid leading value: StatusWord.X4 drops when the leading value in use reaches it
(the start of the tolerance time), the followers keep moving with the last valid value extrapolated,
alarm 900 comes after the tolerance time and stops them - from where they are.  No such value ever
reaches a follower's setpoint.
"""
import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from plcmotion import Controller
from plcmotion.kernel.leading_value import LeadingValueSample
from _s7_1500_rig import Feed
from plcmotion.s7_1500 import MC_GearIn, MC_Power, MC_Reset

VIRTUAL = {"VirtualAxis": {"Mode": 1}}
V = 10.0                      # velocity of the leading axis on the other controller


class Remote:
    """CPU B: proxy P (fed by the test with the sender's telegrams), follower S geared 1:1 by MC_GearIn."""

    def __init__(self, tolerance=0.02, delay=0.0):
        self.ctl = Controller(family="S7-1500T", app_cycle=0.004)
        self.feed = Feed()
        self.delay = delay
        self.p = self.ctl.add_leading_axis_proxy(
            "P", {"Parameter": {"ToleranceTimeExternalLeadingValueInvalid": tolerance}}, source_link=self.feed)
        self.s = self.ctl.add_synchronous_axis("S", VIRTUAL, leading_values=["P"])
        self.power, self.gear, self.reset = MC_Power(), MC_GearIn(), MC_Reset()
        self.st = {"reset": False}
        self.seq = 0
        self.rows = []

        @self.ctl.program
        def main():
            self.power(Axis=self.s, Enable=True)
            self.gear(Master=self.p, Slave=self.s, Execute=self.power.Status)
            self.reset(Axis=self.p, Execute=self.st["reset"])

    def step(self, n=1, **telegram):
        """``n`` application cycles; each sends the telegram of the sender's present time (``telegram``
        overrides fields: position, velocity, valid, ...)."""
        for _ in range(n):
            t = self.ctl.time
            self.seq += 1
            fields = dict(time=t, position=V * t, velocity=V, acceleration=0.0, sequence=self.seq, delay=self.delay)
            fields.update(telegram)
            self.feed.queue.append(LeadingValueSample(**fields))
            self.ctl.step()
            self.rows.append(dict(t=self.ctl.time, x4=bool(self.p.StatusWord.X4), alarm=bool(self.p.ErrorWord.X2),
                                  p=self.p.Position, s=self.s.Position, sa=self.s.ActualPosition,
                                  in_gear=self.gear.InGear, error=self.gear.Error))

    def synchronous(self):
        self.step(100)
        assert self.gear.InGear and self.p.StatusWord.X4


BAD_VALUES = [dict(position=math.nan), dict(position=1e300), dict(position=-math.inf), dict(velocity=math.nan),
              dict(velocity=1e300), dict(acceleration=math.inf), dict(time=math.nan), dict(modulo_length=math.nan),
              dict(delay=math.inf), dict(position="12.0"), dict(valid=False)]


@pytest.mark.parametrize("bad", BAD_VALUES, ids=lambda d: "-".join(f"{k}={v}" for k, v in d.items()))
def test_s7_1500_invalid_telegrams_never_reach_the_follower_and_raise_alarm_900_defect2(bad):
    """Defect 2: NaN / 1e300 from the network made the follower's Position and ActualPosition NaN while
    InGear stayed TRUE, without an alarm.  Now: X4 FALSE at once (no delay), the follower goes on with
    the last valid leading value extrapolated (§8.1.2), alarm 900 after the tolerance time, the gearing
    ends with an error and the follower brakes from where it is; all values stay finite."""
    r = Remote(tolerance=0.02)
    r.synchronous()
    s0 = r.s.Position
    n0 = len(r.rows)
    r.step(12, **bad)
    rows = r.rows[n0:]
    assert all(math.isfinite(x[k]) for x in rows for k in ("p", "s", "sa"))
    assert not rows[0]["x4"] and not rows[0]["alarm"] and rows[0]["in_gear"]
    # within the tolerance time (20 ms = 5 application cycles) the follower keeps moving at V
    assert rows[3]["s"] == pytest.approx(s0 + 4 * 0.004 * V, abs=1e-6)
    first_alarm = next(i for i, x in enumerate(rows) if x["alarm"])
    assert 4 <= first_alarm <= 6
    assert r.p.ErrorDetail.Number == 900 and r.gear.Error and r.gear.ErrorID == 0x8001
    # the follower brakes from where it was: no step, never backwards past its stop
    steps = [b["s"] - a["s"] for a, b in zip(rows, rows[1:])]
    assert all(-1e-9 <= d <= V * 0.004 + 1e-9 for d in steps), steps


def test_s7_1500_follower_stopped_by_alarm_900_does_not_jump_to_its_own_profile_defect2():
    """The followers were stopped while the sync stage held only their own (offset) profile, so a
    follower at 15.5 jumped to 0.0 when alarm 900 came.  It must stop where it is."""
    r = Remote(tolerance=0.012)
    r.synchronous()
    n0 = len(r.rows)
    r.step(10, valid=False)
    rows = r.rows[n0 - 1:]
    assert any(x["alarm"] for x in rows)
    assert all(abs(b["s"] - a["s"]) <= V * 0.004 + 1e-9 for a, b in zip(rows, rows[1:]))
    assert all(abs(b["sa"] - a["sa"]) <= V * 0.004 + 1e-9 for a, b in zip(rows, rows[1:]))


@pytest.mark.parametrize("bad", [dict(valid=False), dict(position=math.nan)], ids=["flagged", "nan"])
def test_s7_1500_x4_drops_at_the_start_of_the_tolerance_time_not_with_alarm_900_a_3_6(bad):
    """§A.3.6 StatusWord.X4 "Leading value does not exist or is not valid"; §8.1.2: alarm 900 after the
    tolerance time, meanwhile the value is extrapolated.  With a sender delay of 8 ms the proxy uses the
    telegram of 8 ms ago: X4 drops when that value reaches the first invalid telegram, which is also
    where the tolerance time starts - exactly the tolerance time before alarm 900."""
    tol = 0.02
    r = Remote(tolerance=tol, delay=0.008)
    r.synchronous()
    n0 = len(r.rows)
    t_bad = r.ctl.time                        # sender time of the first invalid telegram
    r.step(15, **bad)
    rows = r.rows[n0:]
    t_x4 = next(x["t"] for x in rows if not x["x4"])
    t_900 = next(x["t"] for x in rows if x["alarm"])
    # the value in use is that of 8 ms ago: X4 holds while it still lies before the invalid telegram
    assert t_x4 >= t_bad + 0.008 - 1e-9
    assert t_900 - t_x4 == pytest.approx(tol, abs=0.004 + 1e-9)
    during = [x for x in rows if t_x4 <= x["t"] < t_900]
    assert during and all(not x["x4"] and not x["alarm"] and x["in_gear"] for x in during)
    assert all(b["s"] > a["s"] for a, b in zip(during, during[1:]))     # the follower keeps moving


def test_s7_1500_a_single_garbage_telegram_is_bridged_by_interpolation_s8_1_3():
    """With a sender delay the proxy interpolates between telegrams (AdjustmentTime < 0); one unusable
    telegram between valid ones is bridged: X4 stays TRUE, no alarm, the follower moves on evenly."""
    r = Remote(tolerance=0.02, delay=0.008)
    r.synchronous()
    n0 = len(r.rows)
    r.step(1, position=math.nan)
    r.step(10)
    rows = r.rows[n0:]
    assert all(x["x4"] and not x["alarm"] for x in rows)
    steps = [b["s"] - a["s"] for a, b in zip(rows, rows[1:])]
    assert all(d == pytest.approx(V * 0.004, abs=1e-9) for d in steps)


def test_s7_1500_alarm_900_acknowledged_once_valid_values_return_s8_1_2():
    r = Remote(tolerance=0.012)
    r.synchronous()
    r.step(10, position=math.inf)
    assert r.p.ErrorWord.X2 and not r.p.StatusWord.X4
    r.step(2)
    r.st["reset"] = True
    r.step(2)
    assert r.reset.Done and r.p.StatusWord.X4 and not r.p.ErrorWord.X2
    assert math.isfinite(r.p.Position) and r.p.Position == pytest.approx(V * (r.ctl.time - 0.0), abs=V * 0.004)


class BrokenTransport:
    def fetch(self, needed):
        raise OSError("socket closed")


def test_s7_1500_a_transport_that_raises_is_a_communication_error_not_a_stop_defect2():
    ctl = Controller(family="S7-1500T")
    p = ctl.add_leading_axis_proxy("P", {}, source_link=BrokenTransport())
    s = ctl.add_synchronous_axis("S", VIRTUAL, leading_values=["P"])
    pw, g = MC_Power(), MC_GearIn()

    @ctl.program
    def main():
        pw(Axis=s, Enable=True)
        g(Master=p, Slave=s, Execute=pw.Status)
    ctl.run(0.2)
    assert ctl.mode == "RUN" and not p.StatusWord.X4 and g.Busy and not g.InGear


_number = st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.floats(-1e3, 1e3),
                    st.integers(-10 ** 400, 10 ** 400), st.sampled_from([None, "x", True]))


@settings(max_examples=60, deadline=None, suppress_health_check=list(HealthCheck))
@given(stream=st.lists(st.tuples(st.booleans(), st.sampled_from(["position", "velocity", "acceleration", "time",
                                                                  "delay", "modulo_length", "modulo_start",
                                                                  "valid"]), _number),
                       min_size=1, max_size=40))
def test_s7_1500_no_telegram_stream_makes_a_setpoint_non_finite_defect2(stream):
    """Invariant (hypothesis): whatever telegrams arrive - good ones, garbage in any field - the proxy's
    Position/Velocity and the follower's setpoints stay finite and the controller stays in RUN."""
    r = Remote(tolerance=0.008)
    r.step(30)
    for good, field, value in stream:
        if good:
            r.step(1)
        else:
            r.step(1, **{field: value})
        assert r.ctl.mode == "RUN"
        assert all(math.isfinite(v) for v in (r.p.Position, r.p.Velocity, r.p.Acceleration))
        assert math.isfinite(r.s.Position) and math.isfinite(r.s.ActualPosition) and math.isfinite(r.s.Velocity)
        assert not (r.p.StatusWord.X4 and r.p.ErrorWord.X2)
