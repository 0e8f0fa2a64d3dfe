"""Motion profiles of MC_MoveRelative (S7-1200 Motion Control V6).

Manual (seeds/000_a03aa7b7d80586ce.txt):

* §5.4.4.4 "Dynamics": acceleration, deceleration, jerk; "Behavior of the axis when using the jerk
  limit": acceleration and deceleration are ramped, the same jerk applies to all rising and falling
  acceleration edges; smoothing time t1 = acceleration / jerk for the acceleration ramp and
  t2 = deceleration / jerk for the deceleration ramp.  Jerk = 0.0 disables the jerk limit
  (position-controlled axes: Jerk > 1e-9 enables it) -> trapezoidal velocity profile.
* §11.1.6: "Velocity ... is not always reached" (acceleration, deceleration, distance).
* PROFIdrive axes have start/stop velocity 0 (§5.4.4.4), so the setpoint profile from standstill to
  standstill is the time-optimal jerk-limited profile with these limits -- computed here with ruckig
  as the independent reference.

Durations are measured from the call of MC_MoveRelative (rising edge of Execute) to the first servo
cycle whose setpoint (axis.Position, axis.Velocity) is at the target and at rest.
"""
from __future__ import annotations

import math

import pytest
from ruckig import InputParameter, Result, Ruckig, Trajectory

from plcmotion import Controller
from plcmotion.s7_1200 import MC_MoveRelative, MC_Power

DT = 0.001


def ruckig_duration(distance, velocity, acc, dec, jerk):
    """Time-optimal rest-to-rest duration (ruckig) for |distance|; acceleration means "speeding up",
    deceleration "slowing down" (§5.4.4.4), so the motion is mirrored to the positive direction."""
    otg = Ruckig(1)
    inp = InputParameter(1)
    inp.current_position = [0.0]
    inp.current_velocity = [0.0]
    inp.current_acceleration = [0.0]
    inp.target_position = [abs(distance)]
    inp.target_velocity = [0.0]
    inp.target_acceleration = [0.0]
    inp.max_velocity = [velocity]
    inp.max_acceleration = [acc]
    inp.min_acceleration = [-dec]
    inp.max_jerk = [jerk if jerk > 0 else math.inf]
    traj = Trajectory(1)
    result = otg.calculate(inp, traj)
    assert result in (Result.Working, Result.Finished)
    return traj.duration


def make(actor=1, acc=50.0, dec=50.0, jerk=500.0, vmax=200.0, vmin=None):
    ctl = Controller(servo_cycle=DT, app_cycle=0.004)
    cfg = {"Actor": {"Type": actor}, "DynamicLimits": {"MaxVelocity": vmax},
           "DynamicDefaults": {"Acceleration": acc, "Deceleration": dec, "Jerk": jerk,
                               "EmergencyDeceleration": 10 * max(acc, dec)}}
    if vmin is not None:
        cfg["DynamicLimits"]["MinVelocity"] = vmin
    axis = ctl.add_positioning_axis("Axis_1", cfg)
    power = MC_Power()
    power(Axis=axis, Enable=True)
    ctl.run_until(lambda: power().Status, timeout=2.0)
    ctl.run(0.02)
    return ctl, axis


def run_move(ctl, axis, distance, velocity):
    """Start MC_MoveRelative, record (t, p, v, a) every servo cycle until the setpoint rests at the
    target; return (duration, samples)."""
    samples = []

    def rec(t):
        samples.append((t, axis.Position, axis.Velocity, axis.Acceleration))

    p0 = axis.Position
    target = p0 + distance
    ctl.on_post_servo(rec)
    mr = MC_MoveRelative()
    t_cmd = ctl.time
    mr(Axis=axis, Execute=True, Distance=distance, Velocity=velocity)
    tol = 1e-7 * max(1.0, abs(distance))

    def arrived():
        mr()
        return bool(samples) and abs(samples[-1][1] - target) <= tol and abs(samples[-1][2]) <= 1e-9

    try:
        ctl.run_until(arrived, timeout=60.0)
    finally:
        ctl.remove_hook(rec)
    t_arrive = next(t for t, p, v, _a in samples if abs(p - target) <= tol and abs(v) <= 1e-9)
    assert not mr.Error
    return t_arrive - t_cmd, samples


JERK_CASES = [
    # distance, velocity, acceleration, deceleration, jerk
    (100.0, 40.0, 50.0, 50.0, 500.0),       # cruise phase at Velocity
    (10.0, 40.0, 50.0, 50.0, 500.0),        # Velocity not reached
    (0.5, 40.0, 50.0, 50.0, 500.0),         # neither velocity nor acceleration reached
    (200.0, 80.0, 20.0, 80.0, 200.0),       # deceleration > acceleration
    (200.0, 80.0, 80.0, 20.0, 400.0),       # acceleration > deceleration
    (-150.0, 60.0, 30.0, 90.0, 300.0),      # negative direction
    (37.5, 150.0, 120.0, 45.0, 2000.0),
    (0.05, 10.0, 100.0, 100.0, 10000.0),
    (500.0, 200.0, 200.0, 50.0, 5000.0),
]


@pytest.mark.parametrize("distance,velocity,acc,dec,jerk", JERK_CASES)
def test_kernel_jerk_limited_duration_matches_ruckig_5_4_4_4(distance, velocity, acc, dec, jerk):
    """§5.4.4.4 jerk limit + §11.1.6: from standstill the jerk-limited MC_MoveRelative reaches its
    target in the time-optimal duration for Velocity / Acceleration / Deceleration / Jerk (ruckig
    reference) within one servo cycle, and never exceeds any of the limits."""
    ctl, axis = make(acc=acc, dec=dec, jerk=jerk)
    duration, samples = run_move(ctl, axis, distance, velocity)
    reference = ruckig_duration(distance, velocity, acc, dec, jerk)
    assert abs(duration - reference) <= DT + 1e-9, f"duration {duration:.6f} s, ruckig {reference:.6f} s"
    sign = math.copysign(1.0, distance)
    vs = [v * sign for _t, _p, v, _a in samples]
    accs = [a * sign for _t, _p, _v, a in samples]
    assert min(vs) >= -1e-9                                   # no motion against the direction
    assert max(vs) <= velocity * (1 + 1e-9)
    assert max(accs) <= acc * (1 + 1e-9)
    assert min(accs) >= -dec * (1 + 1e-9)
    # the same jerk on every edge (§5.4.4.4): |da| per servo cycle <= jerk * dt
    steps = [abs(b - a) for a, b in zip(accs, accs[1:])]
    assert max(steps) <= jerk * DT * (1 + 1e-6) + 1e-9


TRAPEZ_CASES = [
    (100.0, 40.0, 50.0, 50.0),
    (10.0, 40.0, 50.0, 50.0),
    (400.0, 80.0, 20.0, 80.0),
    (-250.0, 60.0, 90.0, 30.0),
    (3.0, 100.0, 10.0, 40.0),
]


@pytest.mark.parametrize("distance,velocity,acc,dec", TRAPEZ_CASES)
def test_kernel_trapezoidal_profile_without_jerk_5_4_4_4(distance, velocity, acc, dec):
    """§5.4.4.4: Jerk = 0.0 disables the jerk limit: the acceleration is piecewise constant and takes
    only the values +Acceleration, 0 and -Deceleration; the duration is the time-optimal trapezoidal
    one (ruckig with infinite jerk) within one servo cycle."""
    ctl, axis = make(acc=acc, dec=dec, jerk=0.0)
    duration, samples = run_move(ctl, axis, distance, velocity)
    reference = ruckig_duration(distance, velocity, acc, dec, 0.0)
    assert abs(duration - reference) <= DT + 1e-9, f"duration {duration:.6f} s, reference {reference:.6f} s"
    sign = math.copysign(1.0, distance)
    allowed = (acc, 0.0, -dec)
    for _t, _p, v, a in samples:
        assert min(abs(a * sign - x) for x in allowed) <= 1e-9 * max(acc, dec), f"acceleration {a}"
        assert v * sign <= velocity * (1 + 1e-9)
    accs = [a * sign for *_x, a in samples]
    # piecewise constant: +acc first, then (possibly) 0, then -dec -- at most 3 changes incl. the end
    changes = sum(1 for a, b in zip(accs, accs[1:]) if abs(a - b) > 1e-9)
    assert changes <= 3
    assert max(accs) == pytest.approx(acc)
    assert min(accs) == pytest.approx(-dec)


@pytest.mark.parametrize("acc,dec", [(20.0, 80.0), (80.0, 20.0), (25.0, 50.0)])
@pytest.mark.parametrize("jerk", [0.0, 400.0], ids=["trapezoidal", "jerk"])
def test_kernel_separate_acceleration_and_deceleration_5_4_4_4(acc, dec, jerk):
    """§5.4.4.4: ramp-up uses Acceleration, ramp-down uses Deceleration; with the jerk limit the
    ramp-up lasts v/acc + acc/jerk (smoothing time t1 = acc/jerk) and the ramp-down v/dec + dec/jerk
    (t2 = dec/jerk); without it v/acc and v/dec."""
    velocity, distance = 80.0, 800.0
    ctl, axis = make(acc=acc, dec=dec, jerk=jerk)
    _duration, samples = run_move(ctl, axis, distance, velocity)
    accs = [a for *_x, a in samples]
    assert max(accs) == pytest.approx(acc, rel=1e-9)
    assert min(accs) == pytest.approx(-dec, rel=1e-9)
    t_up = sum(DT for a in accs if a > 1e-9)
    t_down = sum(DT for a in accs if a < -1e-9)
    up = velocity / acc + (acc / jerk if jerk else 0.0)
    down = velocity / dec + (dec / jerk if jerk else 0.0)
    assert t_up == pytest.approx(up, abs=2 * DT)
    assert t_down == pytest.approx(down, abs=2 * DT)
    assert max(v for _t, _p, v, _a in samples) == pytest.approx(velocity, rel=1e-9)


@pytest.mark.parametrize("acc,dec", [(20.0, 80.0), (80.0, 20.0)])
@pytest.mark.parametrize("jerk", [0.0, 400.0], ids=["trapezoidal", "jerk"])
def test_kernel_separate_acceleration_and_deceleration_pto_5_4_4_4(acc, dec, jerk):
    """§5.4.4.4 on a PTO axis (start/stop velocity 1.0): the acceleration never exceeds Acceleration
    when speeding up nor Deceleration when slowing down, and both are used; the target is reached."""
    ctl, axis = make(actor=2, acc=acc, dec=dec, jerk=jerk, vmax=100.0, vmin=1.0)
    _duration, samples = run_move(ctl, axis, 500.0, 80.0)
    accs = [a for *_x, a in samples]
    assert max(accs) == pytest.approx(acc, rel=1e-6)
    assert min(accs) == pytest.approx(-dec, rel=1e-6)
    assert max(v for _t, _p, v, _a in samples) == pytest.approx(80.0, rel=1e-9)
    if jerk == 0.0:
        for a in accs:
            assert min(abs(a - x) for x in (acc, 0.0, -dec)) <= 1e-9 * max(acc, dec)


def test_kernel_pd_done_after_positioning_monitoring_5_4_4_6():
    """§5.4.4.6 positioning monitoring (PROFIdrive): after the setpoint interpolation has ended the actual
    position must be in the positioning window for the minimum dwell time before the command is Done;
    Done therefore comes no earlier than MinDwellTime after the setpoint reached the target."""
    ctl = Controller(servo_cycle=DT, app_cycle=0.004)
    axis = ctl.add_positioning_axis("Axis_1", {
        "Actor": {"Type": 1}, "DynamicLimits": {"MaxVelocity": 200.0},
        "DynamicDefaults": {"Acceleration": 50.0, "Deceleration": 50.0, "Jerk": 500.0,
                            "EmergencyDeceleration": 500.0},
        "PositioningMonitoring": {"Window": 0.5, "MinDwellTime": 0.2, "ToleranceTime": 1.0}})
    power = MC_Power()
    power(Axis=axis, Enable=True)
    ctl.run_until(lambda: power().Status, timeout=2.0)
    samples = []
    ctl.on_post_servo(lambda t: samples.append((t, axis.Position, axis.Velocity)))
    mr = MC_MoveRelative()
    mr(Axis=axis, Execute=True, Distance=50.0, Velocity=40.0)
    t_done = ctl.run_until(lambda: mr().Done or mr.Error, timeout=10.0)
    assert mr.Done
    t_arrive = next(t for t, p, v in samples if abs(p - 50.0) <= 1e-7 and abs(v) <= 1e-9)
    assert t_done >= t_arrive + 0.2 - 1e-9
    assert t_done <= t_arrive + 1.0 + 0.2 + 0.01
    assert abs(axis.ActualPosition - 50.0) <= 0.5
