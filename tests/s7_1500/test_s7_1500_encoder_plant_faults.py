"""External encoder with a bad measured value (issue 8, leftover of defect 3/11; S7-1500T V5 §7.1.1
ErrorWord.X5 "SensorFault", §A.1.31 StatusSensor State/Error, §3.3.2 actual value coupling).

The simulated machine an external encoder measures is user code (``drive_plant``) or a constant velocity
(``set_plant_velocity``).  A measured value that is not a finite number within the LREAL position range
(NaN, inf, 1e300, a string) is an encoder fault of the technology object - technology alarm 203 with
the reaction "remove enable", ErrorWord.X5, StatusSensor[1].State 0 - exactly as ``inject_fault`` gives:
never a STOP, never a non-finite actual or leading value.  The followers coupled to the encoder's
actual value lose their leading value and are stopped from where they are (gearing ends with 16#8001).
A plant function that raises is a fault of the user's program: the controller goes to STOP with the
reason, like a servo hook that raises (Controller._run_hooks).
"""
import math
import warnings

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from plcmotion import Controller
from plcmotion.kernel.runtime import ProgramErrorWarning
from plcmotion.s7_1500 import MC_GearIn, MC_Power, MC_Reset

VIRTUAL = {"VirtualAxis": {"Mode": 1}}
FINE = {"Sensor[1]": {"Parameter": {"DistancePerRevolution": 100.0, "StepsPerRevolution": 1 << 20}}}
V = 100.0


class Bench:
    """External encoder Enc measuring a conveyor at V, follower S geared 1:1 to its actual value."""

    def __init__(self, mode="actual"):
        self.ctl = Controller(family="S7-1500T", app_cycle=0.001)
        self.enc = self.ctl.add_external_encoder("Enc", {"Sensor": FINE, "Plant": {"Velocity": V}})
        self.s = self.ctl.add_synchronous_axis("S", VIRTUAL, leading_values=[("Enc", mode)])
        self.pe, self.ps, self.gear, self.reset = MC_Power(), MC_Power(), MC_GearIn(), MC_Reset()
        self.flags = {"gear": True, "reset": False}

        @self.ctl.program
        def main():
            self.pe(Axis=self.enc, Enable=True)
            self.ps(Axis=self.s, Enable=True)
            # Execute stays TRUE once started (the encoder's fault removes its enable: MC_Power.Status
            # falls, and a job's Error shows only one call after a falling Execute)
            self.flags["go"] = self.flags.get("go") or (self.pe.Status and self.ps.Status)
            self.gear(Master=self.enc, Slave=self.s, Execute=self.flags["gear"] and self.flags["go"])
            self.reset(Axis=self.enc, Execute=self.flags["reset"])
        self.ctl.run_until(lambda: self.gear.InGear, timeout=2.0)
        self.ctl.run(0.05)

    def run(self, n):
        rows = []
        for _ in range(n):
            self.ctl.step()
            e = self.enc
            rows.append(dict(pos=e.ActualPosition, vel=e.ActualVelocity, s=self.s.Position, sa=self.s.ActualPosition,
                             sv=self.s.Velocity, x=e.StatusExtrapolation.ExtrapolatedPosition))
        return rows


BAD = [math.nan, math.inf, -math.inf, 1e300, -2e12, "12.5", None, 10 ** 400, True]


@pytest.mark.parametrize("bad", BAD, ids=["nan", "inf", "-inf", "1e300", "-2e12", "str", "None", "10e400", "bool"])
def test_s7_1500_bad_measured_value_is_an_encoder_fault_not_a_stop_s7_1_1(bad):
    """§7.1.1 / §A.1.31: a measured value that is no number in range is an error of the encoder system:
    alarm 411, reaction 4 (the encoder is disabled), StatusWord.X1, ErrorWord.X5 (SensorFault), StatusSensor[1].State
    0 and StatusSensor[1].Error; the controller stays in RUN and no value becomes non-finite.  Before the
    fix ``math.floor(nan)`` stopped the controller with an internal error (1e300 was taken as a position)."""
    b = Bench()
    b.enc.drive_plant(lambda t: bad)
    rows = b.run(20)
    e = b.enc
    assert b.ctl.mode == "RUN", b.ctl.stop_reason
    assert e.ErrorDetail.Number == 411 and e.ErrorDetail.Reaction == 4
    assert e.StatusWord.Error and not e.StatusWord.Enable and e.ErrorWord.X5
    assert e.StatusSensor[1].State == 0 and e.StatusSensor[1].Error
    assert not b.pe.Status and b.pe.Error
    assert all(math.isfinite(v) and abs(v) < 1e6 for r in rows for v in r.values()), rows


def test_s7_1500_followers_of_a_failed_encoder_stop_from_where_they_are_s3_3_2():
    """The leading value of actual value coupling needs valid actual values (§3.3.2): when the encoder
    fails, the gearing ends with 16#8001 and the follower brakes from where it is - no step, no reversal,
    no velocity beyond the conveyor's."""
    b = Bench()
    b.enc.drive_plant(lambda t: math.nan)
    rows = b.run(200)
    assert b.gear.Error and b.gear.ErrorID == 0x8001 and not b.gear.InGear
    assert b.s.StatusWord.Error
    steps = [q["s"] - p["s"] for p, q in zip(rows, rows[1:])]
    assert all(-1e-9 <= d <= V * 0.001 * 1.01 for d in steps), steps
    assert rows[-1]["sv"] == pytest.approx(0.0, abs=1e-9)


def test_s7_1500_injected_encoder_fault_also_stops_the_followers_s3_3_2():
    """Same mechanism for ExternalEncoder.inject_fault (it left the gearing InGear on a frozen value)."""
    b = Bench()
    b.enc.inject_fault()
    rows = b.run(200)
    assert b.enc.ErrorWord.X5 and b.enc.ErrorDetail.Number == 411
    assert b.gear.Error and b.gear.ErrorID == 0x8001
    assert all(-1e-9 <= q["s"] - p["s"] <= V * 0.001 * 1.01 for p, q in zip(rows, rows[1:]))


def test_s7_1500_gearing_to_an_encoder_that_already_failed_is_refused_s3_3_2():
    """Issue 8 review: a MC_GearIn started after the encoder failed coupled to the held value and showed
    InGear.  With the actual value invalid there is no leading value (§3.3.2): the job ends with 16#8001
    and the follower shows the alarm of an invalid leading value (601), as for a fault during the coupling."""
    ctl = Controller(family="S7-1500T", app_cycle=0.001)
    enc = ctl.add_external_encoder("Enc", {"Sensor": FINE, "Plant": {"Velocity": V}})
    s = ctl.add_synchronous_axis("S", VIRTUAL, leading_values=[("Enc", "actual")])
    pe, ps, gear = MC_Power(Axis=enc, Enable=True), MC_Power(Axis=s, Enable=True), MC_GearIn()

    def cycles(n, execute=False):
        outs = []
        for _ in range(n):
            pe()
            ps()
            gear(Master=enc, Slave=s, Execute=execute, RatioNumerator=1, RatioDenominator=1)
            outs.append((gear.Busy, gear.InGear, gear.Error, gear.ErrorID))
            ctl.step()
        return outs

    cycles(50)
    enc.inject_fault()
    cycles(5)
    assert s.StatusWord.Enable and not s.StatusWord.Error      # the follower itself is fine
    outs = cycles(20, execute=True)
    assert not any(busy or in_gear for busy, in_gear, _, _ in outs), outs
    assert gear.Error and gear.ErrorID == 0x8001
    assert s.StatusWord.Error and s.ErrorDetail.Number == 601      # the follower's leading value error
    assert s.Velocity == 0.0


def test_s7_1500_encoder_recovers_after_reset_once_the_value_is_valid_again_s7_1_1():
    """The fault stays while the measured value is bad (MC_Reset cannot clear it), and is acknowledged
    by MC_Reset once the machine delivers numbers again; MC_Power enables the encoder again."""
    b = Bench()
    state = {"bad": True}
    b.enc.drive_plant(lambda t: math.nan if state["bad"] else 7.0)
    b.run(5)
    b.flags["reset"] = True
    b.run(5)
    b.flags["reset"] = False
    b.run(2)
    assert b.enc.ErrorWord.X5 and not b.enc.StatusWord.Enable        # still bad: the alarm is back
    state["bad"] = False
    b.flags["reset"] = True
    b.run(5)
    assert not b.enc.StatusWord.Error and b.enc.StatusWord.Enable
    assert b.enc.ActualPosition == pytest.approx(7.0, abs=1e-3)


def test_s7_1500_plant_function_that_raises_stops_the_controller_like_a_program():
    """A plant function is user code: when it raises, the controller goes to STOP with the reason naming
    the encoder and the exception (as for a program or servo hook), with a ProgramErrorWarning; the
    function is dropped and the machine stands where it was."""
    b = Bench()

    def broken(t):
        raise ZeroDivisionError("plant model broken")
    b.enc.drive_plant(broken)
    with pytest.warns(ProgramErrorWarning, match="Enc"):
        b.ctl.step()
    assert b.ctl.mode == "STOP"
    assert "plant function of external encoder 'Enc'" in b.ctl.stop_reason
    assert "ZeroDivisionError: plant model broken" in b.ctl.stop_reason
    assert "internal error" not in b.ctl.stop_reason
    x = b.enc.plant_position
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        b.ctl.step()                        # in STOP: the broken function is not called again
    assert b.enc.plant_position == x


def test_s7_1500_plant_velocity_is_checked():
    """set_plant_velocity takes a finite number within +-1e12 (the range of Plant.Velocity); anything else
    is a clear TypeError/ValueError at the call, not a NaN machine."""
    b = Bench()
    for bad in (math.nan, math.inf, 1e300, 10 ** 400):
        with pytest.raises(ValueError, match="Plant.Velocity"):
            b.enc.set_plant_velocity(bad)
    for bad in ("1.0", None, True):
        with pytest.raises(TypeError, match="Plant.Velocity"):
            b.enc.set_plant_velocity(bad)
    assert b.enc.plant_velocity == V
    b.enc.set_plant_velocity(50)
    b.run(100)
    assert b.enc.ActualVelocity == pytest.approx(50.0, rel=0.02)


def test_s7_1500_plant_running_out_of_range_at_constant_velocity_is_an_encoder_fault():
    """A machine at 1e12 units/s leaves the LREAL position range after about a second: that is the
    encoder's fault too, not an overflowing actual value."""
    b = Bench()
    b.enc.set_plant_velocity(1e12)
    b.run(1500)
    assert b.ctl.mode == "RUN" and b.enc.ErrorWord.X5
    assert abs(b.enc.ActualPosition) <= 1e12


@settings(max_examples=40, deadline=None, suppress_health_check=list(HealthCheck))
@given(st.lists(st.one_of(st.floats(), st.floats(-1e3, 1e3), st.integers(-10 ** 400, 10 ** 400),
                          st.sampled_from([None, "x", b"1", True, 1j])), min_size=1, max_size=30))
def test_s7_1500_no_measured_value_stops_the_controller_or_leaks_a_non_finite_value(values):
    """Invariant (hypothesis): whatever the plant function returns, the controller stays in RUN and the
    encoder's and follower's values stay finite."""
    b = Bench()
    it = iter(values)
    b.enc.drive_plant(lambda t: next(it, 0.0))
    rows = b.run(len(values) + 5)
    assert b.ctl.mode == "RUN", b.ctl.stop_reason
    assert all(math.isfinite(v) for r in rows for v in r.values())
