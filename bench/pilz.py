"""Benchmark: N Pilz drive axes (family "Pilz") running back-to-back jerk-limited MC_MoveRelative commands
through their command registers at a 1 ms servo / 4 ms application cycle.

Prints axis-cycles per second, the real-time factor (virtual seconds per wall-clock second), the CPU time
per axis and servo cycle in µs (process time, so other processes on a shared machine count less) and the part
of it spent in the Pilz axis's own input stage (``DriveAxis._check_inputs``: the motion core, which runs in
every servo cycle - Pilz V6.5 §1: the motion-core cycle A150 = the servo cycle - and the kernel's input check).

    python bench/pilz.py                     # 1, 16, 64 axes, 5 s virtual time
    python bench/pilz.py --axes 16 --seconds 10
"""
from __future__ import annotations

import argparse
import time

from plcmotion import Controller
from plcmotion.pilz import DriveAxis


def build(n: int) -> Controller:
    ctl = Controller(family="Pilz", servo_cycle=0.001, app_cycle=0.004)
    params = {"I10": 400.0, "I11": 2000.0, "I16": 40000.0, "I22": 0.5, "I87": 0.01}
    axes = []
    for k in range(n):
        axis = ctl.add_positioning_axis(f"Axis_{k + 1}", params)
        axis.enable()
        # different distances so that the axes do not move in lock-step
        axes.append([axis, 50.0 + 7.0 * (k % 13), True])

    @ctl.program
    def main() -> None:
        for cell in axes:
            axis, dist, forward = cell
            reg, st = axis.registers, axis.status
            if reg.I402:
                if st.I92 or st.I91:                 # done (or denied): Execute low for one application cycle
                    reg.I402 = False
            elif st.I89 == 2:                        # standstill: the next move, alternating direction
                reg.I401, reg.I403, reg.I404 = 2, dist if forward else -dist, 400.0
                reg.I405, reg.I406, reg.I407 = 2000.0, 2000.0, 40000.0
                reg.I402 = True
                cell[2] = not forward

    return ctl


def _clock_cost(n: int = 20000) -> float:
    """What an empty timed interval measures (the clock read itself) [s]: the bias of each timed call."""
    clock = time.process_time
    total = 0.0
    for _ in range(n):
        c = clock()
        total += clock() - c
    return total / n


def _timed_input_stage() -> list[float]:
    """Wrap DriveAxis._check_inputs with a clock (process time); returns the running total [s]."""
    total = [0.0]
    inner = DriveAxis._check_inputs
    clock = time.process_time

    def timed(self: DriveAxis, t: float) -> None:
        c = clock()
        inner(self, t)
        total[0] += clock() - c

    DriveAxis._check_inputs = timed                    # type: ignore[method-assign]
    return total


def measure(n: int, seconds: float) -> tuple[float, float, float, float]:
    ctl = build(n)
    ctl.run(0.1)                          # enable and first commands outside the measurement
    t0, c0 = time.perf_counter(), time.process_time()
    ctl.run(seconds)
    wall, cpu = time.perf_counter() - t0, time.process_time() - c0
    if ctl.stop_reason:
        raise RuntimeError(ctl.stop_reason)
    cycles = round(seconds / ctl.servo_cycle)
    # the same run again with the input stage timed (the clock calls cost a little, so this is a second run)
    inner = DriveAxis._check_inputs
    ctl = build(n)
    ctl.run(0.1)
    total = _timed_input_stage()
    try:
        ctl.run(seconds)
    finally:
        DriveAxis._check_inputs = inner                # type: ignore[method-assign]
    # the clock reads inside the timed interval count in the total: take their share out
    inner_cost = _clock_cost() * (cycles * n)
    return (cycles * n / wall, seconds / wall, cpu / (cycles * n) * 1e6,
            max(0.0, total[0] - inner_cost) / (cycles * n) * 1e6)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--axes", type=int, nargs="*", default=[1, 16, 64])
    ap.add_argument("--seconds", type=float, default=5.0, help="virtual time per run")
    args = ap.parse_args()
    print(f"{'axes':>5} {'axis-cycles/s':>14} {'real-time factor':>17} {'CPU µs/axis/cycle':>18} "
          f"{'of it motion core':>18}")
    for n in args.axes:
        rate, rtf, us, core = measure(n, args.seconds)
        print(f"{n:>5} {rate:>14,.0f} {rtf:>17.2f} {us:>18.1f} {core:>18.1f}")


if __name__ == "__main__":
    main()
