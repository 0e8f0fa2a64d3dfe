"""Lowering ``DynamicLimits.Velocity`` while MC_MoveVelocity still accelerates close to it (fuzz seed 216525;
docs/decisions.md row 66, docs/s7_1500/decisions.md row 26).  The velocity limit holds: the setpoint never
passes the new limit, and the acceleration is taken back to zero once (a settling jerk above MaxJerk only for
that), after which the axis cruises at the new limit."""
from __future__ import annotations

import pytest

from plcmotion import Controller
from plcmotion.s7_1500 import MC_MoveVelocity, MC_Power


def test_s7_1500_lowered_velocity_limit_holds_during_the_acceleration_phase():
    ctl = Controller(servo_cycle=0.001, app_cycle=0.002, family="S7-1500T")
    ax = ctl.add_positioning_axis("Axis_1", {
        "DynamicLimits.MaxVelocity": 67.51, "DynamicLimits.Velocity": 67.51, "DynamicLimits.MaxAcceleration": 198.3,
        "DynamicLimits.MaxDeceleration": 1604.3, "DynamicLimits.MaxJerk": 1805.5, "DynamicDefaults.Velocity": 22.28,
        "DynamicDefaults.Acceleration": 92.74, "DynamicDefaults.Deceleration": 522.28,
        "DynamicDefaults.Jerk": 1805.5, "DynamicDefaults.EmergencyDeceleration": 1623.3, "Simulation.Mode": 1})
    power, move = MC_Power(Axis=ax, Enable=True), MC_MoveVelocity(Axis=ax, Velocity=21.5)
    samples: list[tuple[float, float, float, float]] = []
    ctl.on_post_servo(lambda t: samples.append((t, float(ctl.bank.sp_v[ax.index]), float(ctl.bank.sp_a[ax.index]),
                                                float(ctl.bank.sp_j[ax.index]))))

    def cycle(n: int = 1) -> None:
        for _ in range(n):
            power()
            move()
            ctl.step()

    cycle(5)
    move.Execute = True
    cycle(1)
    while samples[-1][1] < 20.6:             # close to 21.5, still accelerating (about 54 mm/s²)
        cycle(1)
    assert samples[-1][2] > 40.0
    start = len(samples)
    ax.set_tag("DynamicLimits.Velocity", 21.136941933859042)
    cycle(100)
    after = samples[start:]
    assert max(v for _, v, _, _ in after) <= 21.136941933859042 + 1e-9
    assert after[-1][1] == pytest.approx(21.136941933859042)
    # the acceleration goes back to zero without changing sign (no undershoot of the velocity)
    assert min(a for _, _, a, _ in after) >= -1e-9
    # a jerk above MaxJerk only while the acceleration is taken back, never after it is zero
    over = [(t, a) for t, _, a, j in after if abs(j) > 1805.5 * (1 + 1e-9)]
    assert over and all(a > 0 for _, a in over)
    assert move.Busy and move.InVelocity and not move.Error
