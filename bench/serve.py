"""Benchmark: ``plcmotion serve`` pacing - 16 PROFIdrive axes running back-to-back moves at a 1 ms servo /
4 ms application cycle, paced to the wall clock.

Prints the lateness of the servo cycles (p50/p99/max), the overruns, the wall-clock slip and the load
average around the run.  Target (issue 14): lateness p99 <= 1 ms on the 2-core machine.

    PYTHONPATH=src python bench/serve.py                 # 60 s, 16 axes
    PYTHONPATH=src python bench/serve.py --seconds 10 --axes 4
    PYTHONPATH=src python bench/serve.py --realtime 10   # SCHED_FIFO (root or CAP_SYS_NICE)
"""
from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from axes import build  # noqa: E402  (bench/axes.py: the same axes and program)

from plcmotion.services import make_loop  # noqa: E402
from plcmotion.services.realtime import request_realtime  # noqa: E402


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seconds", type=float, default=60.0, help="virtual = wall-clock time paced [s]")
    ap.add_argument("--axes", type=int, default=16)
    ap.add_argument("--speed", type=float, default=1.0)
    ap.add_argument("--realtime", type=int, metavar="PRIORITY", help="SCHED_FIFO priority (needs root)")
    args = ap.parse_args()
    if args.realtime is not None:
        print(request_realtime(args.realtime) or f"SCHED_FIFO priority {args.realtime}")
    ctl = build(args.axes, "servo")
    loop = make_loop(ctl, speed=args.speed)
    load0 = os.getloadavg()
    cpu0, t0 = time.process_time(), time.monotonic()
    loop.run(args.seconds)
    wall, cpu = time.monotonic() - t0, time.process_time() - cpu0
    tags = loop.pacing
    print(f"{args.axes} axes, servo {ctl.servo_cycle * 1e3:g} ms / application {ctl.app_cycle * 1e3:g} ms, "
          f"{ctl.time:.1f} s paced at x{args.speed:g} in {wall:.2f} s wall, CPU {cpu / wall * 100:.0f} % of a core")
    print(f"lateness p50 {tags.LatenessP50 * 1e3:.3f} ms  p99 {tags.LatenessP99 * 1e3:.3f} ms  "
          f"max {tags.LatenessMax * 1e3:.3f} ms  overruns {tags.Overruns} of {tags.Cycles} servo cycles  "
          f"slip {tags.Slip:.3f} s")
    load1 = os.getloadavg()
    print(f"load average (1 min) before {load0[0]:.2f}, after {load1[0]:.2f} on {os.cpu_count()} cores"
          f"{'' if ctl.mode == 'RUN' else f'; controller in {ctl.mode}: {ctl.stop_reason}'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
