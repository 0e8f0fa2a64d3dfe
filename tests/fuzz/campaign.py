"""Seeded fuzz campaigns: episodes ``seed, seed+1, ...`` over N processes, failures deduplicated by
signature, each distinct failure shrunk to a minimal reproducer script."""
from __future__ import annotations

import multiprocessing as mp
import os
import time
import warnings
from dataclasses import dataclass, field

from .gen import generate
from .repro import script, shrink
from .runner import Failure, Run


@dataclass
class Result:
    episodes: int = 0
    calls: int = 0
    cycles: int = 0
    seconds: float = 0.0
    cpu: float = 0.0           # CPU seconds of the episodes (all processes): the rate on an idle machine
    failures: dict[str, list[tuple[int, Failure]]] = field(default_factory=dict)   # signature -> (seed, failure)

    def failed_episodes(self) -> int:
        return sum(len(v) for v in self.failures.values())


def run_seed(seed: int, dialect: str | None = None, ignore: tuple[str, ...] = ()) -> tuple[int, Failure | None, int, int]:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")            # ProgramErrorWarning etc.: the invariants judge
        r = Run(generate(seed, dialect), ignore=ignore)
        f = r.run()
    return seed, f, r.calls, r.cycle + 1


def _chunk(args: tuple[int, int, str | None, tuple[str, ...]]) -> tuple[float, list[tuple[int, Failure | None, int, int]]]:
    start, n, dialect, ignore = args
    t0 = time.process_time()
    out = [run_seed(s, dialect, ignore) for s in range(start, start + n)]
    return time.process_time() - t0, out


def campaign(episodes: int, seed: int = 0, jobs: int = 1, dialect: str | None = None,
             progress=None, chunk: int = 50, ignore: tuple[str, ...] = ()) -> Result:
    """Episodes ``seed .. seed+episodes-1``; failures whose signature starts with one of ``ignore`` are
    looked past (the episode goes on), to find what hides behind a known defect."""
    res = Result()
    t0 = time.monotonic()
    work = [(s, min(chunk, seed + episodes - s), dialect, ignore) for s in range(seed, seed + episodes, chunk)]

    def take(timed):
        cpu, batch = timed
        res.cpu += cpu
        for s, f, calls, cycles in batch:
            res.episodes += 1
            res.calls += calls
            res.cycles += cycles
            if f is not None:
                res.failures.setdefault(f.signature(), []).append((s, f))
        if progress:
            progress(res, time.monotonic() - t0)

    if jobs <= 1:
        for w in work:
            take(_chunk(w))
    else:
        ctx = mp.get_context("fork" if hasattr(os, "fork") else "spawn")
        with ctx.Pool(jobs) as pool:
            for batch in pool.imap_unordered(_chunk, work):
                take(batch)
    res.seconds = time.monotonic() - t0
    return res


def report(res: Result, *, shrink_budget: float = 20.0, out=print, dialect: str | None = None,
           ignore: tuple[str, ...] = ()) -> None:
    """Every distinct failure: its count, first seed, message and a minimal reproducer."""
    for sig, items in sorted(res.failures.items(), key=lambda kv: -len(kv[1])):
        seed, f = min(items, key=lambda sf: sf[0])
        out(f"\n=== {f.kind}: {f.message}")
        out(f"    signature {sig}; {len(items)} episode(s), seeds {', '.join(str(s) for s, _ in items[:10])}"
            + (" ..." if len(items) > 10 else ""))
        out(f"    replay: python -m tests.fuzz --replay {seed}" + (f" --dialect '{dialect}'" if dialect else "")
            + "".join(f" --ignore '{i}'" for i in ignore))
        ep = generate(seed, dialect)
        if shrink_budget > 0:
            ep, f = shrink(ep, f, shrink_budget, ignore)
        out("    minimal reproducer (PYTHONPATH=src python repro.py):")
        out("\n".join("    | " + line for line in script(ep, f).splitlines()))
