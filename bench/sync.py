"""Benchmark: synchronous operation on an S7-1500T (issue: 1 master + 32 following axes, half gearing, half
camming with 1000-point cams, 1 ms servo cycle: real-time factor >= 5 on 2 cores; MC_InterpolateCam of a
1000-point cam < 50 ms).

The leading axis runs at constant velocity with a velocity change every second; the following axes are
PROFIdrive axes with simulated drives (``--drive virtual`` for virtual axes).  Each cam follower has a cam
of its own (1000 points, cubic spline), so the cam table holds 16 different cams.

    python bench/sync.py                      # 32 followers, servo drives, 10 s virtual time
    python bench/sync.py --followers 64 --drive virtual --seconds 5
"""
from __future__ import annotations

import argparse
import math
import time

import numpy as np

from plcmotion import Controller
from plcmotion.kernel.cam import interpolate
from plcmotion.s7_1500 import MC_CamIn, MC_GearIn, MC_InterpolateCam, MC_MoveVelocity, MC_Power

POINTS = 1000


def cam_points(k: int) -> list[tuple[float, float]]:
    x = np.linspace(0.0, 360.0, POINTS)
    y = 40.0 * (1.0 - np.cos(np.radians(x))) + (k % 5) * 2.0 * np.sin(np.radians(3 * x))
    return list(zip(x.tolist(), y.tolist()))


def build(followers: int, drive: str) -> tuple[Controller, dict]:
    ctl = Controller(servo_cycle=0.001, app_cycle=0.004, family="S7-1500T")
    rotary = {"Properties": {"MotionType": 1}, "Units": {"LengthUnit": 1005, "VelocityUnit": 1521},
              "Modulo": {"Enable": True, "Length": 360.0}}
    master = ctl.add_positioning_axis("Master", {"VirtualAxis": {"Mode": 1}, **rotary,
                                                 "DynamicLimits": {"MaxVelocity": 3600.0, "Velocity": 3600.0}})
    params = {"VirtualAxis": {"Mode": 1}} if drive == "virtual" else {
        "Actor": {"Type": 1, "DriveParameter": {"MaxSpeed": 6000.0, "ReferenceSpeed": 6000.0}},
        "FollowingError": {"MaxValue": 500.0, "MinValue": 500.0}}
    axes, cams = [], []
    for k in range(followers):
        axes.append(ctl.add_synchronous_axis(f"Follower_{k + 1}", params, leading_values=["Master"]))
        if k % 2:
            cams.append(ctl.add_cam(f"Cam_{k + 1}", cam_points(k), interpolation_mode=1, boundary_conditions=1))
        else:
            cams.append(None)
    powers = [MC_Power() for _ in range(followers + 1)]
    mv = MC_MoveVelocity()
    interp = {id(c): MC_InterpolateCam() for c in cams if c is not None}
    couple = [MC_CamIn() if cam is not None else MC_GearIn() for cam in cams]
    state = {"v": 360.0}

    @ctl.program
    def main() -> None:
        powers[0](Axis=master, Enable=True)
        second = int(ctl.time)
        v = 360.0 if second % 2 == 0 else 540.0
        if v != state["v"]:
            state["v"] = v
            mv(Axis=master, Execute=False)
        mv(Axis=master, Execute=powers[0].Status, Velocity=v, Acceleration=3600.0, Deceleration=3600.0,
           Jerk=36000.0)
        for k, (axis, power, cam, fb) in enumerate(zip(axes, powers[1:], cams, couple)):
            power(Axis=axis, Enable=True)
            if cam is None:
                fb(Master=master, Slave=axis, Execute=power.Status, RatioNumerator=1 + k % 3, RatioDenominator=2)
            else:
                ic = interp[id(cam)]
                ic(Cam=cam, Execute=True)
                fb(Master=master, Slave=axis, Cam=cam, Execute=power.Status and ic.Done, ApplicationMode=1,
                   SyncProfileReference=1, MasterStartDistance=90.0, SlaveScaling=1.0 + 0.1 * (k % 4))

    return ctl, {"followers": axes, "fbs": couple, "master": master}


def measure(followers: int, drive: str, seconds: float) -> dict:
    ctl, parts = build(followers, drive)
    ctl.run(2.0)                               # enable, interpolate, synchronize
    synced = sum(1 for fb in parts["fbs"] if getattr(fb, "InSync", False) or getattr(fb, "InGear", False))
    t0 = time.perf_counter()
    ctl.run(seconds)
    wall = time.perf_counter() - t0
    if ctl.stop_reason:
        raise RuntimeError(ctl.stop_reason)
    errors = [fb.ErrorID for fb in parts["fbs"] if fb.Error]
    n_axes = followers + 1
    cycles = seconds / ctl.servo_cycle
    return {"followers": followers, "drive": drive, "synchronous": synced, "errors": errors,
            "rtf": seconds / wall, "axis_cycles_per_s": n_axes * cycles / wall, "us_per_cycle": wall / cycles * 1e6}


def interpolate_timing(repeat: int = 5) -> dict:
    pts = cam_points(1)
    out = {}
    for mode, name in ((0, "linear"), (1, "cubic spline"), (2, "Bezier")):
        best = math.inf
        for _ in range(repeat):
            t0 = time.perf_counter()
            interpolate(pts, [], mode, 1)
            best = min(best, time.perf_counter() - t0)
        out[name] = best * 1e3
    # through the instruction, as a user sees it (job processed at the next servo cycle)
    ctl = Controller(family="S7-1500T")
    cam = ctl.add_cam("Cam", pts, interpolation_mode=1, boundary_conditions=1)
    fb = MC_InterpolateCam()
    fb(Cam=cam, Execute=True)
    t0 = time.perf_counter()
    ctl.step()
    out["MC_InterpolateCam (cubic, one application cycle)"] = (time.perf_counter() - t0) * 1e3
    fb(Cam=cam, Execute=True)
    assert fb.Done
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--followers", type=int, default=32)
    ap.add_argument("--drive", choices=("servo", "virtual"), default="servo")
    ap.add_argument("--seconds", type=float, default=10.0)
    args = ap.parse_args()
    for name, ms in interpolate_timing().items():
        print(f"interpolate {POINTS} points, {name:48s} {ms:7.2f} ms  (target < 50 ms)")
    r = measure(args.followers, args.drive, args.seconds)
    print(f"1 master + {r['followers']} followers ({r['drive']}), {r['synchronous']} synchronous, "
          f"errors {r['errors']}: real-time factor {r['rtf']:.2f} (target >= 5), "
          f"{r['axis_cycles_per_s']:,.0f} axis-cycles/s, {r['us_per_cycle']:.0f} us per servo cycle")


if __name__ == "__main__":
    main()
