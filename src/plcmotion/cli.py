"""Command line: ``plcmotion demo``, ``plcmotion run``, ``plcmotion check``."""
from __future__ import annotations

import argparse
import runpy
import sys
import time
import warnings
from pathlib import Path
from typing import Sequence

from . import ProgramErrorWarning, __version__


def _progress(fraction: float, wall: float, virtual: float, width: int = 30) -> None:
    filled = int(round(fraction * width))
    bar = "#" * filled + "-" * (width - filled)
    rtf = virtual / wall if wall > 0 else 0.0
    sys.stderr.write(f"\r[{bar}] {fraction * 100:5.1f}%  t = {virtual:8.3f} s  x{rtf:6.1f} real time")
    sys.stderr.flush()


def cmd_demo(args: argparse.Namespace) -> int:
    from . import demo
    from .trace import Trace

    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    d = demo.build()
    instr = d.instructions
    signals: dict = {f"Axis_1.{tag}": f"Axis_1.{tag}" for tag in (
        "Position", "Velocity", "Acceleration", "ActualPosition", "ActualVelocity",
        "StatusPositioning.FollowingError", "StatusBits.Enable", "StatusBits.HomingDone", "StatusBits.Done",
        "StatusBits.Error", "StatusBits.StandStill", "StatusBits.ConstantVelocity", "StatusBits.Accelerating",
        "StatusBits.Decelerating", "StatusBits.PositioningCommand", "StatusBits.VelocityCommand")}
    for name in ("move_abs", "move_rel", "velocity", "halt", "jog"):
        inst = instr[name]
        signals[f"{name}.Busy"] = (lambda i=inst: i.Busy)
    trace = Trace(d.ctl, signals).start()
    wall0 = time.perf_counter()
    d.ctl.run_until(lambda: demo.finished(d), timeout=120.0)
    d.ctl.run(0.2)
    wall = time.perf_counter() - wall0
    trace.stop()
    csv_path, png_path = out / "trace.csv", out / "trace.png"
    trace.to_csv(csv_path)
    trace.plot(png_path, title="plcmotion demo: servo axis Axis_1 (S7-1200 instructions)")
    print(demo.summary(d))
    print()
    print(f"virtual time {d.ctl.time:.3f} s in {wall:.2f} s wall clock (x{d.ctl.time / wall:.0f} real time)")
    print(f"trace: {csv_path}  plot: {png_path}")
    return 0


def cmd_check(args: argparse.Namespace) -> int:
    from .project import check_project

    outside = getattr(args, "allow_outside_paths", False)
    problems = check_project(args.project, allow_outside_paths=outside)
    if problems:
        for p in problems:
            print(p, file=sys.stderr)
        print(f"{args.project}: {len(problems)} problem{'s' if len(problems) != 1 else ''}", file=sys.stderr)
        return 1
    from .project import load_project

    ctl = load_project(args.project, allow_outside_paths=outside)
    axes = ", ".join(f"{name} ({_describe(ax)})" for name, ax in ctl.axes.items())
    others = [f"{name} ({type(to).__name__})" for name, to in {**ctl.objects, **ctl.cams}.items()]
    more = f"; {', '.join(others)}" if others else ""
    family = "" if ctl.family == "S7-1200" else f"{ctl.family}, "
    print(f"{args.project}: OK - {family}servo cycle {ctl.servo_cycle * 1000:g} ms, application cycle "
          f"{ctl.app_cycle * 1000:g} ms, {len(ctl.axes)} axes: {axes or '-'}{more}")
    return 0


def _describe(ax) -> str:
    kind = "synchronous axis, " if hasattr(ax, "possible_leading_values") else ""
    if ax.eff.get("VirtualAxis.Mode"):
        return kind + "virtual"
    drive = "PTO" if ax.pto else "simulated" if ax.sim else "PROFIdrive" if ax.eff["Actor.Type"] == 1 else "analog"
    return kind + drive


def load_program(ctl, program: str) -> None:
    """Run a user program file: it defines ``setup(ctl)`` or uses the global ``ctl`` it is given."""
    path = Path(program)
    if not path.is_file():
        raise FileNotFoundError(f"{program}: program file not found")
    namespace = runpy.run_path(str(path), init_globals={"ctl": ctl, "axes": ctl.axes}, run_name="__plcmotion__")
    setup = namespace.get("setup")
    if callable(setup):
        setup(ctl)
    if not ctl._programs:
        raise ValueError(f"{program}: registers no program; decorate a function with @ctl.program "
                         f"(inside setup(ctl) or at module level)")


def cmd_run(args: argparse.Namespace) -> int:
    from .kernel.tags1500 import alarm_description
    from .project import ProjectError, load_project
    from .trace import Trace, plot_csv

    try:
        ctl = load_project(args.project, allow_outside_paths=getattr(args, "allow_outside_paths", False))
    except ProjectError as exc:
        print(exc, file=sys.stderr)
        return 2
    try:
        load_program(ctl, args.program)
    except Exception as exc:  # the user's file: report it, do not show our internals
        print(f"{args.program}: {type(exc).__name__}: {exc}", file=sys.stderr)
        return 2
    settings = getattr(ctl, "project", None) or {}
    trace_settings = settings.get("trace", {}) if isinstance(settings, dict) else {}
    trace = None
    if args.trace or args.plot:
        signals = args.signal or trace_settings.get("signals") or None
        try:
            trace = Trace(ctl, signals, every=args.every or trace_settings.get("every", 1), stream_to=args.trace)
        except (KeyError, ValueError, TypeError) as exc:
            print(f"trace: {exc.args[0] if exc.args else exc}", file=sys.stderr)
            return 2
        trace.start()
    n = max(1, round(args.duration / ctl.app_cycle))
    wall0 = time.perf_counter()
    last = 0.0
    show = args.progress or (not args.quiet and sys.stderr.isatty())
    try:
        with warnings.catch_warnings():
            # the CLI reports a STOP with its reason at the end of the run
            warnings.simplefilter("ignore", ProgramErrorWarning)
            for k in range(n):
                ctl.step()
                now = time.perf_counter()
                if show and (now - last > 0.2 or k == n - 1):
                    last = now
                    _progress((k + 1) / n, now - wall0, ctl.time)
    finally:
        if show:
            sys.stderr.write("\n")
        if trace is not None:
            trace.stop()
    wall = time.perf_counter() - wall0
    if trace is not None and args.plot:
        if args.trace:
            plot_csv(args.trace, args.plot)
        else:
            trace.plot(args.plot)
    print(f"ran {ctl.time:.3f} s of virtual time in {wall:.2f} s (x{ctl.time / wall if wall else 0:.1f} real time), "
          f"mode {ctl.mode}")
    def alarms(to) -> str:
        if ctl.family == "S7-1200":
            return ", ".join(str(a) for a in to.alarms) or "no error"
        return ", ".join(f"{alarm_description(a)} [{a}]" for a in to.alarms) or "no error"

    for name, ax in ctl.axes.items():
        errors = alarms(ax)
        print(f"  {name}: {ax.state}, Position {ax.Position:.6g}, ActualPosition {ax.ActualPosition:.6g}, "
              f"homed {ax.homed}, {errors}")
    for name, to in ctl.objects.items():
        errors = alarms(to)
        print(f"  {name}: {type(to).__name__}, {errors}")
    if args.trace:
        print(f"trace: {args.trace}")
    if args.plot:
        print(f"plot: {args.plot}")
    if ctl.mode != "RUN":
        print(f"controller in {ctl.mode}: {ctl.stop_reason}", file=sys.stderr)
        return 1
    return 0


OUTSIDE_HELP = ("let state_file and cam csv paths of the project leave the project's folder "
                "(../ or absolute paths)")


def build_parser() -> argparse.ArgumentParser:
    ap = argparse.ArgumentParser(prog="plcmotion", description="Soft motion controller with PLC motion instructions.")
    ap.add_argument("--version", action="version", version=f"plcmotion {__version__}")
    sub = ap.add_subparsers(dest="command", required=True)
    p = sub.add_parser("demo", help="run the built-in demo scenario; writes trace.csv and trace.png")
    p.add_argument("--out", default="plcmotion-demo", help="output directory (default: %(default)s)")
    p.set_defaults(func=cmd_demo)
    p = sub.add_parser("run", help="run a project with a user program in virtual time")
    p.add_argument("project", help="project file (TOML)")
    p.add_argument("program", help="user program (Python file defining setup(ctl))")
    p.add_argument("--duration", type=float, required=True, help="virtual time to run [s]")
    p.add_argument("--trace", help="write the trace to this CSV file (streamed, full resolution)")
    p.add_argument("--plot", help="write a plot of the trace to this PNG file")
    p.add_argument("--signal", action="append", help="signal to trace, e.g. Axis_1.Position (repeatable)")
    p.add_argument("--every", type=int, help="trace every n-th servo cycle")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.add_argument("--progress", action="store_true", help="progress bar even when not on a terminal")
    p.add_argument("--allow-outside-paths", action="store_true", help=OUTSIDE_HELP)
    p.set_defaults(func=cmd_run)
    p = sub.add_parser("check", help="validate a project file")
    p.add_argument("project", help="project file (TOML)")
    p.add_argument("--allow-outside-paths", action="store_true", help=OUTSIDE_HELP)
    p.set_defaults(func=cmd_check)
    return ap


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    return int(args.func(args) or 0)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
