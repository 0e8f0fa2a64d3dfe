"""The leading value a technology object provides (``kernel.leading.LeadingValueProvider``), without any
dialect: the component alone on a small fake host, then on an axis of a kernel ``Controller``.

Expected values come from kinematics and the S7-1500T V5 manual, never from the code under test:
an extrapolation over the time T is where a motion of constant acceleration is T later,
p + v*T + a*T^2/2 (§3.3.4: "Delay times at constant velocity or at constant acceleration or deceleration
can be compensated for"); a value delayed by the local delay time is the value of that time ago (§3.3.3);
the leading-axis-dependent time is T_i + T_Ipo + the position filter times (§3.3.6).
"""
from __future__ import annotations

import dataclasses
from types import SimpleNamespace

import numpy as np
import pytest

from plcmotion import Controller
from plcmotion.kernel.axis_config import Extrapolation, LeadingValueOutput, LeadingValueSourceConfig, Modulo
from plcmotion.kernel.jobs import Job, JobKind
from plcmotion.kernel.leading import AxisLeadingValue, LeadingAxisHost, LeadingValueProvider
from plcmotion.kernel.leading_value import LeadingValueSample

DT = 0.001                      # servo cycle [s]


# --- a fake host: one axis row in a bank, a sync stage that records what is registered ----------------------
class FakeSync:
    def __init__(self) -> None:
        self.ext: list = []
        self.post: list = []

    def register_ext(self, provider):
        self.ext.append(provider)
        return len(self.ext) - 1

    def register_post(self, fn):
        if fn not in self.post:
            self.post.append(fn)


class FakeController:
    """The clock, the bank row of axis 0 and the sync stage; ``cycle`` runs one servo cycle in the order of
    the servo stages (the setpoint is interpolated, then the sync stage reads leading values, then the
    values after the couplings are recorded)."""

    def __init__(self) -> None:
        self.time = 0.0
        self.servo_cycle = DT
        self._bank_time = 0.0
        self.sync = FakeSync()
        self.bank = SimpleNamespace(**{k: np.zeros(1) for k in ("sp_p", "sp_v", "sp_a", "act_p", "act_v")},
                                    closed_loop=np.zeros(1, dtype=bool))
        self.slots: list = []

    def at(self, t: float, sp=(0.0, 0.0, 0.0), act=(0.0, 0.0)) -> None:
        """The bank after the servo cycle at ``t`` (before a provider starts: where the axis stands)."""
        b = self.bank
        self.time = self._bank_time = t
        b.sp_p[0], b.sp_v[0], b.sp_a[0] = sp
        b.act_p[0], b.act_v[0] = act

    def cycle(self, t: float, sp=(0.0, 0.0, 0.0), act=(0.0, 0.0)) -> None:
        self.at(t, sp, act)
        self.slots = [provider(t) for provider in self.sync.ext]
        for fn in self.sync.post:
            fn(t)


class FakeAxis:
    """Implements ``LeadingAxisHost``: a virtual axis (no encoder delay, exact velocity)."""

    name = "Leader"
    index = 0
    servo = False
    sim = True

    def __init__(self, config: LeadingValueSourceConfig) -> None:
        self.ctl = FakeController()
        self.config = config
        self.state = "enabled"
        self.position_controlled = True
        self.alarm: object | None = None

    def _blocking_alarm(self):
        return self.alarm


def fake(following_time=0.0, delay=0.0, output=False, modulo=Modulo(), **filters) -> AxisLeadingValue:
    config = LeadingValueSourceConfig(
        modulo=modulo, extrapolation=Extrapolation(following_axis_time=following_time, **filters),
        leading_value_output=LeadingValueOutput(enabled=output, local_delay_time=delay))
    host: LeadingAxisHost = FakeAxis(config)
    return AxisLeadingValue(host)


def accelerating(a: float, v0: float = 0.0, p0: float = 0.0):
    """Position, velocity and acceleration of a motion with constant acceleration ``a``."""
    return lambda t: (p0 + v0 * t + 0.5 * a * t * t, v0 + a * t, a)


def test_kernel_extrapolation_at_constant_velocity_is_p_plus_v_t():
    """S7-1500T V5 §3.3.4: without filters the extrapolated actual value is where the leading value is
    the extrapolation time later: p + v*T."""
    lv = fake(following_time=0.008)
    motion = accelerating(0.0, v0=120.0, p0=5.0)
    lv.ctl.at(0.0, act=motion(0.0)[:2])
    slot = lv.lv_slot("actual")
    for k in range(1, 50):
        t = k * DT
        p, v, _ = motion(t)
        lv.ctl.cycle(t, act=(p, v))
        assert lv.lv_value("actual", t)[:2] == pytest.approx((p + v * 0.008, v), abs=1e-9)
        assert lv.ctl.slots[slot] == pytest.approx((p + v * 0.008, v, 0.0), abs=1e-9)


@pytest.mark.parametrize("a, v0, T", [(200.0, 0.0, 0.01), (-80.0, 50.0, 0.004), (30.0, -20.0, 0.0)])
def test_kernel_extrapolation_at_constant_acceleration_is_p_plus_v_t_plus_half_a_t2(a, v0, T):
    """S7-1500T V5 §3.3.4: a constant acceleration is compensated: x = p + v*T + a*T^2/2, the extrapolated
    velocity v + a*T is not asked for (the filtered velocity is shown), the acceleration is a."""
    lv = fake(following_time=T)
    motion = accelerating(a, v0=v0)
    lv.ctl.at(0.0, act=motion(0.0)[:2])
    lv.lv_slot("actual")
    for k in range(1, 40):
        t = k * DT
        p, v, _ = motion(t)
        lv.ctl.cycle(t, act=(p, v))
        x, _v, acc = lv.lv_value("actual", t)
        assert x == pytest.approx(p + v * T + 0.5 * a * T * T, abs=1e-9)
        assert acc == pytest.approx(a, rel=1e-9)
    fp, fv, xp, _xv = lv.extrapolation_status()                # StatusExtrapolation (§A.1.32)
    assert (fp, fv) == pytest.approx(motion(39 * DT)[:2], abs=1e-9)
    assert xp == pytest.approx(fp + fv * T + 0.5 * a * T * T, abs=1e-9)


def test_kernel_actual_value_between_cycles_is_carried_forward_with_its_dynamics():
    lv = fake()
    motion = accelerating(100.0, v0=10.0)
    lv.ctl.at(0.0, act=motion(0.0)[:2])
    lv.lv_slot("actual")
    for k in range(1, 10):
        lv.ctl.cycle(k * DT, act=motion(k * DT)[:2])
    t = 9 * DT + 0.0004
    assert lv.lv_value("actual", t) == pytest.approx(motion(t), abs=1e-9)


def test_kernel_delayed_value_is_the_value_of_the_delay_time_ago():
    """S7-1500T V5 §3.3.3: the delayed leading value is the setpoint of LocalLeadingValueDelayTime ago."""
    delay = 4 * DT
    lv = fake(delay=delay)
    motion = accelerating(250.0, v0=-3.0, p0=1.0)
    lv.ctl.at(0.0, sp=motion(0.0))
    slot = lv.lv_slot("delayed")
    for k in range(1, 30):
        t = k * DT
        lv.ctl.cycle(t, sp=motion(t))
        if k >= 4:
            assert lv.lv_value("delayed", t) == pytest.approx(motion(t - delay), abs=1e-9)
            assert lv.ctl.slots[slot] == pytest.approx(motion(t - delay), abs=1e-9)
    # StatusProvidedLeadingValue.DelayedLeadingValue (§8.1.4): the same value, for the last cycle
    assert lv.delayed_leading_value() == pytest.approx(motion(29 * DT - delay), abs=1e-9)


def test_kernel_delay_between_samples_is_exact_for_a_constant_jerk():
    """A delay that is not a whole number of cycles: between two recorded setpoints the position of a
    motion of constant jerk (a cubic) is reproduced exactly from their positions and velocities."""
    delay = 2.5 * DT
    lv = fake(delay=delay)
    lv.lv_slot("delayed")
    j = 6000.0

    def motion(t):
        return j * t ** 3 / 6, j * t * t / 2, j * t

    for k in range(1, 20):
        lv.ctl.cycle(k * DT, sp=motion(k * DT))
    t = 19 * DT
    assert lv.lv_value("delayed", t)[0] == pytest.approx(motion(t - delay)[0], abs=1e-12)


def test_kernel_status_is_zero_until_a_follower_asks_for_it():
    lv = fake(following_time=0.01, delay=0.002)
    assert lv.extrapolation_status() == (0.0, 0.0, 0.0, 0.0)
    assert lv.delayed_leading_value() == (0.0, 0.0, 0.0)
    assert lv.extrapolator is None and lv.delay_line is None and not lv.ctl.sync.ext


def test_kernel_extrapolation_time_adds_the_leading_axis_dependent_time_when_included():
    """S7-1500T V5 §3.3.6: LeadingAxisDependentTime = T_i + T_Ipo + PositionFilter.T1 + T2 (T_i = 0 for a
    virtual axis); §3.3.4: effective time = that (if included) + FollowingAxisDependentTime + local delay."""
    lv = fake(following_time=0.005, delay=0.003, position_filter_t1=0.002, position_filter_t2=0.001)
    assert lv.leading_axis_dependent_time() == pytest.approx(0.0 + DT + 0.002 + 0.001)
    assert lv.extrapolation_time() == pytest.approx(0.005 + 0.003)
    lv = fake(following_time=0.005, delay=0.003, position_filter_t1=0.002, position_filter_t2=0.001,
              include_leading_axis_time=True)
    assert lv.extrapolation_time() == pytest.approx(0.005 + 0.003 + DT + 0.003)
    lv.host.sim = False                                    # a drive's encoder: T_i is one servo cycle
    assert lv.leading_axis_dependent_time() == pytest.approx(DT + DT + 0.003)


def test_kernel_setpoint_coupling_needs_a_position_controlled_enabled_axis():
    """S7-1500T V5 §3.3.5: setpoint coupling waits until the leading axis is position-controlled."""
    lv = fake()
    assert lv.lv_position_controlled() and lv.leading_value_invalid("setpoint") is None
    lv.host.position_controlled = False
    assert not lv.lv_position_controlled()
    lv.host.position_controlled = True
    lv.host.state = "disabled"
    assert not lv.lv_position_controlled()


def test_kernel_modulo_of_the_leading_value():
    assert fake().lv_modulo() is None
    assert fake(modulo=Modulo(enabled=True, start=-180.0, length=360.0)).lv_modulo() == (-180.0, 360.0)


def test_kernel_cross_plc_output_sends_the_setpoint_with_the_local_delay_every_cycle():
    """S7-1500T V5 §8.1.3/§8.1.4: one telegram per servo cycle with the setpoint, validity, modulo and the
    sender's local delay; without the leading value output configured nothing can be sent."""
    with pytest.raises(ValueError, match="EnableLeadingValueOutput"):
        fake().provide_leading_value(SimpleNamespace(send=lambda s: None))
    lv = fake(delay=0.002, output=True, modulo=Modulo(enabled=True, start=0.0, length=360.0))
    sent: list[LeadingValueSample] = []
    lv.provide_leading_value(SimpleNamespace(send=sent.append))
    motion = accelerating(10.0, v0=30.0)
    for k in range(1, 4):
        lv.ctl.cycle(k * DT, sp=motion(k * DT))
    lv.host.alarm = object()                                # a pending alarm: the value is not valid
    lv.ctl.cycle(4 * DT, sp=motion(4 * DT))
    assert [s.sequence for s in sent] == [1, 2, 3, 4]
    assert [s.valid for s in sent] == [True, True, True, False]
    s = sent[2]
    assert (s.time, s.position, s.velocity, s.acceleration) == pytest.approx((3 * DT, *motion(3 * DT)))
    assert s.delay == 0.002 and s.modulo_length == 360.0 and not s.tracking


def test_kernel_a_kind_of_leading_to_gives_its_own_values():
    """The provider's machinery on a TO that is no axis: the subclass says what is measured (here a
    measured position only, as an external encoder), the rest - extrapolation, delay - is the same."""
    class Measured(LeadingValueProvider):
        def __init__(self, host):
            super().__init__(host)
            self.pv = (0.0, 0.0)

        def actual_values(self):
            return self.pv

        def velocity_lag(self, dt):
            return 0.0

        def provided_value(self):
            ex = self.ensure_extrapolator()
            return ex.position, ex.velocity, ex.acceleration

    host = FakeAxis(LeadingValueSourceConfig(extrapolation=Extrapolation(following_axis_time=0.002)))
    m = Measured(host)
    m.lv_slot("actual")
    for k in range(1, 10):
        m.pv = (40.0 * k * DT, 40.0)
        host.ctl.cycle(k * DT)
    assert m.provided_value() == pytest.approx((40.0 * 9 * DT + 40.0 * 0.002, 40.0, 0.0), abs=1e-12)


# --- on an axis of a kernel Controller ------------------------------------------------------------------------
def leader(**config):
    """A virtual axis of a kernel controller moving at 50 units/s, with a provider configured by ``config``."""
    ctl = Controller()
    axis = ctl.add_positioning_axis("Leader", {"Actor.Type": 1, "Simulation.Mode": 1, "DynamicLimits.MaxVelocity": 100.0,
                                               "DynamicDefaults.Acceleration": 1000.0,
                                               "DynamicDefaults.Deceleration": 1000.0, "DynamicDefaults.Jerk": 0.0})
    axis.config = dataclasses.replace(axis.config, **config)     # what a family's schema would produce
    lv = AxisLeadingValue(axis)
    assert axis.power(object(), True, 1, 0) is None
    ctl.run(0.02)
    axis.submit(Job(JobKind.VELOCITY, velocity=50.0))
    ctl.run(0.2)                                        # 50 units/s reached after 0.05 s
    return ctl, axis, lv


def test_kernel_controller_axis_provides_its_setpoint_and_extrapolated_actual_value():
    """Setpoint coupling reads the setpoint of the same cycle; actual value coupling the actual value
    extrapolated by T: at constant velocity p_act + v*T (S7-1500T V5 §3.3.2, §3.3.4)."""
    ctl, axis, lv = leader(extrapolation=Extrapolation(following_axis_time=0.006))
    lv.lv_slot("actual")
    b, i = ctl.bank, axis.index
    seen, measured = [], []
    ctl.on_pre_servo(lambda t: measured.append(float(b.act_p[i])))      # the actual value of this cycle
    ctl.on_post_servo(lambda t: seen.append((lv.lv_value("setpoint", t), lv.lv_value("actual", t),
                                             float(b.sp_p[i]), measured[-1])))
    ctl.run(0.05)
    for (sp, act, p_set, p_act) in seen[2:]:
        assert sp == pytest.approx((p_set, 50.0, 0.0), abs=1e-9)
        assert act[:2] == pytest.approx((p_act + 50.0 * 0.006, 50.0), abs=1e-9)


def test_kernel_controller_axis_delayed_value_is_its_setpoint_of_the_delay_ago():
    """S7-1500T V5 §3.3.3: delayed coupling reads the leading axis's setpoint of LocalLeadingValueDelayTime
    ago; the cross-PLC telegram carries that delay (§8.1.3)."""
    ctl, axis, lv = leader(leading_value_output=LeadingValueOutput(enabled=True, local_delay_time=0.005))
    lv.lv_slot("delayed")
    sent: list[LeadingValueSample] = []
    lv.provide_leading_value(SimpleNamespace(send=sent.append))
    b, i = ctl.bank, axis.index
    setpoints, delayed = [], []
    ctl.on_post_servo(lambda t: (setpoints.append(float(b.sp_p[i])), delayed.append(lv.lv_value("delayed", t)[0])))
    ctl.run(0.05)
    for k in range(5, len(setpoints)):
        assert delayed[k] == pytest.approx(setpoints[k - 5], abs=1e-9)
    assert len(sent) == len(setpoints) and all(s.delay == 0.005 and s.valid for s in sent)
    assert [s.position for s in sent[-len(setpoints):]] == pytest.approx(setpoints, abs=1e-12)
