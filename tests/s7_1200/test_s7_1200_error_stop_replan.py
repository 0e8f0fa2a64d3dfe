"""An error reaction on the emergency-stop ramp has no jerk limit and brakes with EmergencyDeceleration
(S7-1200 V6 §12.8): a re-plan during that ramp (here a direct MC_Home shifting the coordinate) must keep it,
not turn it into a stop with the dynamic defaults (fuzz seed 124621)."""
from __future__ import annotations

from plcmotion import Controller
from plcmotion.s7_1200 import MC_Home, MC_MoveRelative, MC_MoveVelocity, MC_Power

CFG = {"Actor.Type": 2, "Actor.Interface.PTO": 1, "DynamicLimits.MaxVelocity": 20.0,
       "DynamicLimits.MinVelocity": 0.02, "DynamicDefaults.Acceleration": 200.0,
       "DynamicDefaults.Deceleration": 4.0, "DynamicDefaults.EmergencyDeceleration": 40.0,
       "DynamicDefaults.Jerk": 1.0e5, "PositionLimits_SW.Active": True,
       "PositionLimits_SW.MinPosition": -1.0e4, "PositionLimits_SW.MaxPosition": 1.0e4}


def _stop_time(home_during_stop: bool) -> float:
    ctl = Controller(servo_cycle=0.001, app_cycle=0.002, technology_version=7)
    ax = ctl.add_positioning_axis("Axis_1", CFG)
    power = MC_Power(Axis=ax, Enable=True)
    run = MC_MoveVelocity(Axis=ax, Velocity=15.0)
    rel = MC_MoveRelative(Axis=ax, Distance=100.0)
    home = MC_Home(Axis=ax, Mode=0, Position=0.0)
    fbs = [power, run, rel, home]

    def cycle() -> None:
        for fb in fbs:
            fb()
        ctl.step()

    for _ in range(4):
        cycle()
    run.Execute = True
    for _ in range(200):
        cycle()
    assert run.InVelocity
    ax.set_tag("DynamicDefaults.Deceleration", -1.0)   # invalid: the next job raises an error reaction
    rel.Execute = True
    cycle()
    assert rel.Error
    if home_during_stop:
        home.Execute = True
    for n in range(1, 5000):
        cycle()
        if abs(ax.tag("Velocity")) <= 0.02:
            return n * ctl.app_cycle
    return float("inf")


def test_s7_1200_error_stop_ramp_kept_after_direct_home_during_stop():
    """15 / 40 = 0.375 s down the emergency ramp; the dynamic defaults would take far longer."""
    assert _stop_time(False) < 0.45
    assert _stop_time(True) < 0.45
