"""Benchmark: N axes running back-to-back jerk-limited moves at a 1 ms servo / 4 ms application cycle.

Prints axis-cycles per second (servo cycles x axes per wall-clock second) and the real-time factor
(virtual seconds per wall-clock second).  Targets on a 2-core machine: real-time factor >= 10 for 16 axes
and >= 1 for 128 axes.

    python bench/axes.py                     # 1, 16, 64, 128 axes, PTO and PROFIdrive, 10 s virtual time
    python bench/axes.py --axes 16 --seconds 30 --drive servo
"""
from __future__ import annotations

import argparse
import time

from plcmotion import Controller
from plcmotion.s7_1200 import MC_MoveRelative, MC_Power


def build(n: int, drive: str) -> Controller:
    ctl = Controller(servo_cycle=0.001, app_cycle=0.004)
    params = {
        "Actor": {"Type": 1 if drive == "servo" else 2},
        "DynamicLimits": {"MaxVelocity": 400.0},
        "DynamicDefaults": {"Acceleration": 2000.0, "Deceleration": 2000.0, "Jerk": 40000.0},
    }
    if drive == "servo":
        params["Actor"]["DriveParameter"] = {"MaxSpeed": 6000.0, "ReferenceSpeed": 3000.0}
        params["FollowingError"] = {"MaxValue": 100.0}
    else:
        params["DynamicLimits"]["MinVelocity"] = 1.0
    cells = []
    for k in range(n):
        axis = ctl.add_positioning_axis(f"Axis_{k + 1}", params)
        # different distances so that the axes do not move in lock-step
        cells.append((axis, MC_Power(), MC_MoveRelative(), 50.0 + 7.0 * (k % 13)))

    @ctl.program
    def main() -> None:
        for axis, power, move, dist in cells:
            power(Axis=axis, Enable=True)
            if move.Done or move.Error or not move.Busy:
                # back to back: a new move on every completion, alternating direction
                forward = not getattr(move, "forward", False)
                object.__setattr__(move, "forward", forward)
                move(Axis=axis, Execute=False)
                move(Axis=axis, Execute=power.Status, Distance=dist if forward else -dist, Velocity=400.0)
            else:
                move()

    return ctl


def measure(n: int, drive: str, seconds: float) -> tuple[float, float, int]:
    ctl = build(n, drive)
    ctl.run(0.1)                          # enable and first plans outside the measurement
    moves_before = sum(1 for _ in ctl.axes)
    t0 = time.perf_counter()
    ctl.run(seconds)
    wall = time.perf_counter() - t0
    if ctl.stop_reason:
        raise RuntimeError(ctl.stop_reason)
    cycles = round(seconds / ctl.servo_cycle)
    return cycles * n / wall, seconds / wall, moves_before


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--axes", type=int, nargs="*", default=[1, 16, 64, 128])
    ap.add_argument("--seconds", type=float, default=10.0, help="virtual time per run")
    ap.add_argument("--drive", choices=["pto", "servo", "both"], default="both")
    args = ap.parse_args()
    drives = ["pto", "servo"] if args.drive == "both" else [args.drive]
    print(f"{'drive':>6} {'axes':>5} {'axis-cycles/s':>14} {'real-time factor':>17}")
    for drive in drives:
        for n in args.axes:
            rate, rtf, _ = measure(n, drive, args.seconds)
            print(f"{drive:>6} {n:>5} {rate:>14,.0f} {rtf:>17.2f}")


if __name__ == "__main__":
    main()
