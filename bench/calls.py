"""Benchmark: the cost of one steady-state instruction call (inputs unchanged, nothing to do).

Prints microseconds per call for MC_Power holding an enabled axis, MC_MoveRelative while its job runs, an
idle MC_Halt, and the floor: a Python call that sets two attributes.  Target: <= 0.5 us per call.

    python bench/calls.py
"""
from __future__ import annotations

import time
import timeit

from plcmotion import Controller
from plcmotion.s7_1200 import MC_Halt, MC_MoveRelative, MC_Power


class _Floor:
    def __call__(self, **inputs: object) -> "_Floor":
        self.__dict__.update(inputs)
        return self


def measure(number: int = 100_000, repeat: int = 5) -> dict[str, float]:
    ctl = Controller(servo_cycle=0.001, app_cycle=0.004)
    axis = ctl.add_positioning_axis("Axis_1", {"Actor": {"Type": 1, "DriveParameter": {
        "MaxSpeed": 6000.0, "ReferenceSpeed": 3000.0}}, "DynamicLimits": {"MaxVelocity": 400.0}})
    power, move, halt, floor = MC_Power(), MC_MoveRelative(), MC_Halt(), _Floor()
    for _ in range(50):
        power(Axis=axis, Enable=True)
        ctl.step()
    move(Axis=axis, Execute=True, Distance=1.0e6, Velocity=10.0)
    ctl.step()
    assert power.Status and move.Busy, "set-up failed"
    cases = {
        "MC_Power(Axis, Enable) enabled": lambda: power(Axis=axis, Enable=True),
        "MC_MoveRelative(Axis, Execute) busy": lambda: move(Axis=axis, Execute=True),
        "MC_MoveRelative() busy": lambda: move(),
        "MC_Halt(Axis, Execute) idle": lambda: halt(Axis=axis, Execute=False),
        "floor: call setting 2 attributes": lambda: floor(Axis=axis, Enable=True),
    }
    return {name: min(timeit.repeat(f, timer=time.process_time, number=number, repeat=repeat)) / number * 1e6
            for name, f in cases.items()}


def main() -> None:
    for name, us in measure().items():
        print(f"{name:>40}: {us:6.3f} us")


if __name__ == "__main__":
    main()
