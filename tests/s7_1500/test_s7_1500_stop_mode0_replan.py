"""MC_Stop Mode 0 brakes with the emergency-stop ramp (S7-1500T sync V5 §6.1.5.3, MC_Stop Mode 0): a dynamics
tag written while that ramp runs must not turn it into a stop with the dynamic defaults (fuzz seed 201112)."""
from __future__ import annotations

from plcmotion import Controller
from plcmotion.s7_1500 import MC_Home, MC_MoveVelocity, MC_Power, MC_Stop

CFG = {"DynamicLimits.MaxVelocity": 60.0, "DynamicLimits.Velocity": 60.0, "DynamicLimits.MaxAcceleration": 400.0,
       "DynamicLimits.MaxDeceleration": 400.0, "DynamicLimits.MaxJerk": 1.0e5, "DynamicDefaults.Velocity": 50.0,
       "DynamicDefaults.Acceleration": 400.0, "DynamicDefaults.Deceleration": 20.0, "DynamicDefaults.Jerk": 1.0e5,
       "DynamicDefaults.EmergencyDeceleration": 200.0, "FollowingError.MaxValue": 1.0e6,
       "PositionLimits_SW.Active": True, "PositionLimits_SW.MinPosition": -1.0e4,
       "PositionLimits_SW.MaxPosition": 1.0e4}


def _stop_time(write_tag: bool) -> float:
    ctl = Controller(servo_cycle=0.001, app_cycle=0.004, family="S7-1500")
    ax = ctl.add_positioning_axis("Axis_1", CFG)
    fbs = [MC_Power(Axis=ax, Enable=True), MC_Home(Axis=ax, Mode=0, Position=0.0),
           MC_MoveVelocity(Axis=ax, Velocity=50.0), MC_Stop(Axis=ax, Mode=0)]
    power, home, run, stop = fbs

    def cycle(n: int = 1) -> None:
        for _ in range(n):
            for fb in fbs:
                fb()
            ctl.step()

    cycle(2)
    home.Execute = True
    cycle(2)
    assert home.Done
    run.Execute = True
    cycle(100)
    assert run.InVelocity
    if write_tag:
        ax.set_tag("DynamicDefaults.Acceleration", 300.0)
    stop.Execute = True
    for n in range(1, 1000):
        cycle()
        if abs(ax.tag("Velocity")) == 0.0:
            return n * ctl.app_cycle
    return float("inf")


def test_s7_1500_mc_stop_mode0_keeps_emergency_ramp_when_dynamics_tag_written():
    """§6.1.5.3: 50 / 200 = 0.25 s down the emergency ramp; the dynamic defaults (Deceleration 20) would take
    2.5 s.  A write of DynamicDefaults.Acceleration in the same cycle must not change the stop."""
    plain = _stop_time(False)
    assert plain < 0.3
    assert _stop_time(True) < 0.3
