"""A failing episode as a short, self-contained Python script, and shrinking it to a minimal one.

Shrinking removes operations, instruction instances and trailing cycles as long as the episode still
fails with the same signature (delta debugging, bounded in time).
"""
from __future__ import annotations

import copy
import time
from typing import Callable

from .gen import Episode
from .runner import Failure, Run
from .values import lit


def fails_same(ep: Episode, sig: str, ignore: tuple[str, ...] = ()) -> Failure | None:
    f = Run(ep, ignore=ignore).run()
    return f if f is not None and f.signature() == sig else None


def shrink(ep: Episode, failure: Failure, budget: float = 20.0,
           ignore: tuple[str, ...] = ()) -> tuple[Episode, Failure]:
    """A smaller episode that fails the same way (within ``budget`` seconds)."""
    sig = failure.signature()
    deadline = time.monotonic() + budget
    best = copy.deepcopy(ep)
    best.cycles = min(best.cycles, failure.cycle + 1)
    best.ops = [o for o in best.ops if o.cycle <= failure.cycle]
    f = fails_same(best, sig, ignore) or failure
    if f is failure:
        best = copy.deepcopy(ep)

    def attempt(cand: Episode) -> bool:
        nonlocal best, f
        if time.monotonic() > deadline:
            return False
        got = fails_same(cand, sig, ignore)
        if got is not None:
            best, f = cand, got
            best.cycles = min(best.cycles, got.cycle + 1)
            best.ops = [o for o in best.ops if o.cycle <= got.cycle]
            return True
        return False

    # operations: ddmin-style, chunks from large to single
    n = 2
    while len(best.ops) >= 1 and time.monotonic() < deadline:
        ops = best.ops
        size = max(1, len(ops) // n)
        removed = False
        for start in range(0, len(ops), size):
            cand = copy.deepcopy(best)
            cand.ops = ops[:start] + ops[start + size:]
            if attempt(cand):
                removed = True
                break
        if not removed:
            if size == 1:
                break
            n = min(len(ops), n * 2)
    # instruction instances nobody needs (not referenced by an op)
    for fb in list(best.fbs):
        if time.monotonic() > deadline:
            break
        cand = copy.deepcopy(best)
        cand.fbs = [x for x in cand.fbs if x["name"] != fb["name"]]
        cand.ops = [o for o in cand.ops if not (o.kind == "in" and o.target == fb["name"])]
        attempt(cand)
    # initial inputs back to their defaults
    for fb in best.fbs:
        for k in list(fb["init"]):
            if time.monotonic() > deadline:
                break
            cand = copy.deepcopy(best)
            for x in cand.fbs:
                if x["name"] == fb["name"]:
                    del x["init"][k]
            attempt(cand)
    # fewer technology objects (followers, cams, tables, proxies) when unused
    for group in ("cams", "tables", "proxies"):
        if getattr(best, group) and time.monotonic() < deadline:
            cand = copy.deepcopy(best)
            setattr(cand, group, [])
            attempt(cand)
    return best, f


_EPILOGUE = {
    "exception": "# the last call above raises (an instruction must give an ErrorID instead)",
    "stop": "print('mode:', ctl.mode)\nprint(ctl.stop_reason)",
    "internal": "for ax in AXES:\n    if ax.last_internal_error:\n        print(ax.name, ax.last_internal_error)",
    "nonfinite": "print('first non-finite setpoint/actual values (t, axis, field):', NONFINITE[:3])\n"
                 "for ax in AXES:\n    print(ax.name, ax.Position, ax.Velocity, ax.ActualPosition, ax.ActualVelocity)",
    "velocity": "for ax in AXES:\n    print(ax.name, 'peak |Velocity| of the setpoint', PEAK[ax.name], 'MaxVelocity',"
                " ax.tag('DynamicLimits.MaxVelocity'))",
    "acceleration": "for ax in AXES:\n    print(ax.name, 'peak |acceleration| of the setpoint', PEAK_A[ax.name])",
    "jerk": "for ax in AXES:\n    print(ax.name, 'peak |jerk| of the setpoint', PEAK_J[ax.name])",
    "swlimit": "for ax in AXES:\n    print(ax.name, ax.Position, ax.ActualPosition, ax.tag('PositionLimits_SW.MinPosition'),"
               " ax.tag('PositionLimits_SW.MaxPosition'))",
    "exclusive": "print({n: fb.outputs for n, fb in FB.items()})",
    "stuck": "ctl.run(3.0)  # a further 3 s: the instruction is still Busy\nprint({n: fb.outputs for n, fb in FB.items()"
             " if getattr(fb, 'Busy', False)})",
    "setup": "",
}


def script(ep: Episode, failure: Failure | None = None) -> str:
    """Python source that replays ``ep`` with plain plcmotion calls (run with PYTHONPATH=src)."""
    is1500 = ep.family() != "S7-1200"
    mod = "plcmotion.s7t" if ep.dialect == "S7-Technology" else "plcmotion.s7_1500" if is1500 else "plcmotion.s7_1200"
    classes = sorted({f["cls"] for f in ep.fbs})
    lines = [
        f"# fuzz episode seed {ep.seed} ({ep.dialect})" + (f": {failure.kind} - {failure.message}" if failure else ""),
        f"# replay: python -m tests.fuzz --replay {ep.seed}"
        + (" --dialect 'S7-Technology'" if ep.dialect == "S7-Technology" else ""),
        "import numpy as np",
        "from plcmotion import Controller",
        "from plcmotion.s7_1200 import variables",
        f"from {mod} import {', '.join(classes + (['add_cam_disk'] if ep.dialect == 'S7-Technology' else []))}",
    ]
    if ep.proxies:
        lines.append("from tests.fuzz.sources import FuzzLeadingSource")
    lines.append("")
    lines.append(f"ctl = Controller({', '.join(f'{k}={lit(v)}' for k, v in ep.ctl.items())})")
    lines.append("TO = {}")
    for px in ep.proxies:
        lines.append(f"TO[{px['name']!r}] = ctl.add_leading_axis_proxy({px['name']!r}, {{}}, source_link="
                     f"FuzzLeadingSource({px['velocity']!r}, {px['glitch']!r}, {px['gap']!r}, {px['seed']!r}))")
    for a in ep.axes:
        if a["kind"] == "sync":
            lines.append(f"TO[{a['name']!r}] = ctl.add_synchronous_axis({a['name']!r}, {lit(a['params'])},\n"
                         f"    leading_values={lit(a['leading'])})")
        else:
            lines.append(f"TO[{a['name']!r}] = ctl.add_positioning_axis({a['name']!r}, {lit(a['params'])})")
    for c in ep.cams:
        if "db" in c:                  # S7-Technology: a cam disk (valve profile)
            lines.append(f"TO[{c['name']!r}] = add_cam_disk(ctl, {c['name']!r}, {lit(c['points'])}, "
                         f"db_number={c['db']})")
            continue
        lines.append(f"TO[{c['name']!r}] = ctl.add_cam({c['name']!r}, {lit(c['points'])}, "
                     f"interpolation_mode={c['interpolation']}, boundary_conditions={c['boundary']})")
    for t in ep.tables:
        lines.append(f"TO[{t['name']!r}] = ctl.add_command_table({t['name']!r}, {lit(t['commands'])})")
    lines.append("AXES = [" + ", ".join(f"TO[{a['name']!r}]" for a in ep.axes) + "]")
    lines.append("FB = {}")
    for f in ep.fbs:
        args = ", ".join(f"{k}={lit(v)}" for k, v in f["init"].items())
        lines.append(f"FB[{f['name']!r}] = {f['cls']}({args})")
    lines += [
        "PEAK = {ax.name: 0.0 for ax in AXES}; PEAK_A = dict(PEAK); PEAK_J = dict(PEAK); NONFINITE = []",
        "",
        "@ctl.on_post_servo",
        "def peaks(t):",
        "    b = ctl.bank",
        "    for ax in AXES:",
        "        PEAK[ax.name] = max(PEAK[ax.name], abs(b.sp_v[ax.index]))",
        "        PEAK_A[ax.name] = max(PEAK_A[ax.name], abs(b.sp_a[ax.index]))",
        "        PEAK_J[ax.name] = max(PEAK_J[ax.name], abs(b.sp_j[ax.index]))",
        "        for f in ('sp_p', 'sp_v', 'sp_a', 'act_p', 'act_v', 'cmd_v', 'fe'):",
        "            if not np.isfinite(getattr(b, f)[ax.index]):",
        "                NONFINITE.append((t, ax.name, f))",
        "",
        "",
        "def cycle(n=1):",
        "    \"\"\"n application cycles: every instance called once (a cyclic OB), then the servo cycles.\"\"\"",
        "    for _ in range(n):",
        "        for fb in FB.values():",
        "            fb()",
        "        ctl.step()",
        "",
        "",
    ]
    by_cycle: dict[int, list] = {}
    for o in ep.ops:
        by_cycle.setdefault(o.cycle, []).append(o)
    done = 0
    last = ep.cycles if failure is None else failure.cycle + 1
    for c in sorted(by_cycle):
        if c >= last:
            break
        if c > done:
            lines.append(f"cycle({c - done})")
        for o in by_cycle[c]:
            if o.kind == "in":
                lines.append(f"FB[{o.target!r}].{o.key} = {lit(o.value)}")
            else:
                lines.append(f"TO[{o.target!r}].set_tag({o.key!r}, {lit(o.value)})")
        done = c
    if last > done:
        lines.append(f"cycle({last - done})")
    if failure is not None:
        lines.append(_EPILOGUE.get(failure.kind, ""))
    return "\n".join(lines) + "\n"


def replay_log(ep: Episode, out: Callable[[str], None] = print, ignore: tuple[str, ...] = ()) -> Failure | None:
    """Run ``ep`` printing the operations and every change of an instruction's outputs (the FB call log)."""
    pending: list[str] = []

    def log(line: str) -> None:        # a cycle header only for cycles where something happens
        if pending:
            out(pending.pop())
        out(line)

    run = Run(ep, log=log, ignore=ignore)
    if run.failure is not None:
        return run.failure
    orig_step = run.step

    def step(ops):
        pending[:] = [f"cycle {run.cycle} t = {run.ctl.time:.3f} s"]
        orig_step(ops)
    run.step = step  # type: ignore[method-assign]
    return run.run()
