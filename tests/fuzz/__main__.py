"""``python -m tests.fuzz``: long fuzz campaigns and replays (see tests/fuzz/__init__.py, docs/robustness.md).

    python -m tests.fuzz --episodes 100000 [--seed S] [--jobs N] [--dialect "S7-1500T"]
    python -m tests.fuzz --replay SEED [--script] [--shrink]

Exit status 1 when an episode failed, 0 otherwise.
"""
from __future__ import annotations

import argparse
import os
import sys


def _path() -> None:
    # fuzz the code of this checkout (src/), also when another copy of plcmotion is installed
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    src = os.path.join(root, "src")
    if os.path.isdir(os.path.join(src, "plcmotion")) and src not in sys.path:
        sys.path.insert(0, src)


def main(argv: list[str] | None = None) -> int:
    _path()
    from .campaign import campaign, report
    from .gen import ALL_DIALECTS, generate
    from .repro import replay_log, script, shrink

    ap = argparse.ArgumentParser(prog="python -m tests.fuzz", description="plcmotion fuzz campaigns")
    ap.add_argument("--episodes", type=int, default=1000)
    ap.add_argument("--seed", type=int, default=0, help="first seed (episodes use seed, seed+1, ...)")
    ap.add_argument("--jobs", type=int, default=1, help="worker processes")
    ap.add_argument("--dialect", choices=ALL_DIALECTS, default=None, help="only this dialect (default: all, by seed)")
    ap.add_argument("--replay", type=int, metavar="SEED", help="rerun one episode, printing the FB call log")
    ap.add_argument("--script", action="store_true", help="with --replay: print the reproducer script")
    ap.add_argument("--ignore", action="append", default=[], metavar="SIGNATURE",
                    help="look past failures whose signature starts with this (repeatable), e.g. "
                         "'exception|OverflowError' while that defect is open")
    ap.add_argument("--shrink", type=float, default=20.0, metavar="SECONDS",
                    help="time to shrink each distinct failure (0: no shrinking)")
    args = ap.parse_args(argv)
    if args.episodes < 1 or args.jobs < 1:
        ap.error("--episodes and --jobs must be at least 1")

    if args.replay is not None:
        ep = generate(args.replay, args.dialect)
        print(f"episode {ep.seed}: {ep.dialect}, {len(ep.axes)} axes, {len(ep.fbs)} instances, "
              f"{len(ep.ops)} operations, {ep.cycles} cycles")
        f = replay_log(ep, ignore=tuple(args.ignore))
        if f is None:
            print("no failure")
            return 0
        print(f"\nFAILURE {f.kind} at {f.where}, cycle {f.cycle}: {f.message}")
        if f.detail:
            print(f.detail)
        if args.script:
            if args.shrink > 0:
                ep, f = shrink(ep, f, args.shrink, tuple(args.ignore))
            print(script(ep, f))
        return 1

    def progress(res, dt):
        if res.episodes % 1000 == 0 or res.episodes == args.episodes:
            print(f"  {res.episodes} episodes, {res.failed_episodes()} failed ({len(res.failures)} distinct), "
                  f"{res.episodes / dt:.1f} episodes/s", file=sys.stderr, flush=True)

    res = campaign(args.episodes, args.seed, args.jobs, args.dialect, progress, ignore=tuple(args.ignore))
    print(f"{res.episodes} episodes ({res.calls} instruction calls, {res.cycles} application cycles) in "
          f"{res.seconds:.1f} s: {res.episodes / res.seconds:.1f} episodes/s with {args.jobs} job(s) "
          f"({res.episodes / max(res.cpu, 1e-9):.1f} episodes per CPU second); "
          f"{res.failed_episodes()} failed, {len(res.failures)} distinct failure(s)")
    report(res, shrink_budget=args.shrink, dialect=args.dialect, ignore=tuple(args.ignore))
    return 1 if res.failures else 0


if __name__ == "__main__":
    sys.exit(main())
