"""A scripted wall clock and a small project for the services tests."""
from __future__ import annotations

from typing import Callable

from plcmotion import Controller

ORIGIN = 5_000_000_000          # ns: an arbitrary start of the monotonic clock

PROJECT = """\
[controller]
servo_cycle = 0.001
app_cycle = 0.004

[axes.Axis_1]
type = "positioning"
Actor.Type = 1
DynamicLimits.MaxVelocity = 500.0
DynamicDefaults.Acceleration = 1000.0
DynamicDefaults.Deceleration = 1000.0
DynamicDefaults.EmergencyDeceleration = 2000.0
DynamicDefaults.Jerk = 10000.0
"""

PROGRAM = """\
from plcmotion.s7_1200 import MC_MoveVelocity, MC_Power


def setup(ctl):
    axis = ctl.axes["Axis_1"]
    power, run = MC_Power(), MC_MoveVelocity()

    @ctl.program
    def main():
        power(Axis=axis, Enable=True, StopMode=0)
        run(Axis=axis, Execute=power.Status, Velocity=200.0)
"""


class ScriptedClock:
    """Time passes only where the test says: a sleep ends ``oversleep(k)`` ns after its deadline (k: the
    number of the sleep), and ``advance`` is work that takes time.  ``sleeps`` keeps every deadline."""

    def __init__(self, oversleep: Callable[[int], int] = lambda k: 0):
        self.t = ORIGIN
        self.oversleep = oversleep
        self.sleeps: list[int] = []

    def now_ns(self) -> int:
        return self.t

    def sleep_until(self, deadline_ns: int) -> None:
        self.sleeps.append(deadline_ns)
        self.t = max(self.t, deadline_ns) + self.oversleep(len(self.sleeps))

    def advance(self, ns: int) -> None:
        self.t += ns


def controller() -> Controller:
    """One S7-1200 axis running at 200 mm/s (servo 1 ms, application 4 ms)."""
    from plcmotion.s7_1200 import MC_MoveVelocity, MC_Power

    ctl = Controller(servo_cycle=0.001, app_cycle=0.004)
    axis = ctl.add_positioning_axis("Axis_1", {
        "Actor": {"Type": 1}, "DynamicLimits": {"MaxVelocity": 500.0},
        "DynamicDefaults": {"Acceleration": 1000.0, "Deceleration": 1000.0, "EmergencyDeceleration": 2000.0,
                            "Jerk": 10000.0}})
    power, run = MC_Power(), MC_MoveVelocity()

    @ctl.program
    def main():
        power(Axis=axis, Enable=True, StopMode=0)
        run(Axis=axis, Execute=power.Status, Velocity=200.0)
    return ctl
