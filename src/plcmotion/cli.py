"""Command line: ``plcmotion demo``, ``plcmotion run``, ``plcmotion serve``, ``plcmotion check``.

Every argument is checked before anything runs: a bad one gives one line on stderr and exit code 2
(issue 8, defect 10).  ``run`` exits 1 when the controller ended in STOP and 130 after Ctrl-C.
"""
from __future__ import annotations

import argparse
import math
import os
import runpy
import sys
import tempfile
import time
import warnings
from pathlib import Path
from typing import Sequence

from . import CycleOverrunWarning, ProgramErrorWarning, __version__
from .drives.spec import SetpointInterface
from .kernel import family as families

#: longest ``--duration`` [s of virtual time] (116 days): beyond it a run does not end in practice
MAX_DURATION = 1e7
#: plot formats matplotlib writes without extra packages
PLOT_FORMATS = (".png", ".pdf", ".svg", ".svgz", ".eps", ".ps")


class UsageError(Exception):
    """A bad command line argument (one line, exit code 2)."""


class _Parser(argparse.ArgumentParser):
    def error(self, message: str):  # type: ignore[override]  # one line instead of usage + message + exit
        raise UsageError(f"{self.prog}: error: {message} (see {self.prog} --help)")


def _output_file(option: str, path: str) -> str | None:
    """Why ``path`` cannot be written as the file of ``option`` (checked before the run), or None."""
    where = f"{option} {path}"
    if not path.strip():
        return f"{option}: needs a file name"
    p = Path(path)
    try:
        if p.is_dir():
            return f"{where}: is a folder; give a file name"
        parent = p.parent
        if not parent.exists():
            return f"{where}: the folder {parent} does not exist (create it first)"
        if not parent.is_dir():
            return f"{where}: {parent} is not a folder"
        if not os.access(parent, os.W_OK | os.X_OK) or (p.exists() and not os.access(p, os.W_OK)):
            return f"{where}: no permission to write it"
        # os.access says yes to root everywhere (/proc, read-only mounts): open it as the run will
        existed = p.exists()
        with open(p, "a"):
            pass
        if not existed:
            p.unlink()
    except OSError as exc:
        return f"{where}: cannot write it ({exc.strerror or exc})"
    return None


def _check_run_args(args: argparse.Namespace) -> str | None:
    """The first problem of the ``run`` arguments (before the project is loaded), or None."""
    d = args.duration
    if not math.isfinite(d) or d <= 0:
        return f"--duration {d!r}: allowed: a finite time > 0 s of virtual time"
    if d > MAX_DURATION:
        return f"--duration {d:g}: allowed: at most {MAX_DURATION:g} s of virtual time"
    if args.every is not None and args.every < 1:
        return f"--every {args.every}: allowed: a whole number >= 1 of servo cycles"
    if (args.signal or args.every is not None) and not (args.trace or args.plot):
        return "--signal and --every set what is traced: give --trace FILE.csv or --plot FILE.png"
    for option, path in (("--trace", args.trace), ("--plot", args.plot)):
        if path is not None:
            problem = _output_file(option, path)
            if problem:
                return problem
    if args.plot is not None and Path(args.plot).suffix.lower() not in PLOT_FORMATS:
        return f"--plot {args.plot}: the file name must end in {', '.join(PLOT_FORMATS)}"
    if args.trace is not None and args.plot is not None and Path(args.trace).resolve() == Path(args.plot).resolve():
        return f"--trace and --plot name the same file {args.plot}: the plot would overwrite the trace"
    return None


def _out_folder(out: Path) -> str | None:
    """Why the demo's output folder cannot be used, or None (it is created if missing)."""
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        return f"--out {out}: cannot create the folder ({exc.strerror or exc})"
    if not os.access(out, os.W_OK | os.X_OK):
        return f"--out {out}: no permission to write into the folder"
    try:                                # os.access says yes to root even where nobody can write (/proc)
        with tempfile.TemporaryFile(dir=out):
            pass
    except OSError as exc:
        return f"--out {out}: cannot write into the folder ({exc.strerror or exc})"
    for name in ("trace.csv", "trace.png"):
        problem = _output_file("--out", os.fspath(out / name))
        if problem:
            return problem
    return None


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
    problem = _out_folder(out)
    if problem:
        print(f"plcmotion demo: {problem}", file=sys.stderr)
        return 2
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
    try:                                # e.g. the disk filled up during the demo
        trace.to_csv(csv_path)
        trace.plot(png_path, title="plcmotion demo: servo axis Axis_1 (S7-1200 instructions)")
    except OSError as exc:
        print(f"plcmotion demo: --out {out}: cannot write the results ({exc.strerror or exc})", file=sys.stderr)
        return 1
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
    family = "" if ctl.family == families.default().name else f"{ctl.family}, "
    print(f"{args.project}: OK - {family}servo cycle {ctl.servo_cycle * 1000:g} ms, application cycle "
          f"{ctl.app_cycle * 1000:g} ms, {len(ctl.axes)} axes: {axes or '-'}{more}")
    ctl.close()
    return 0


def _describe(ax) -> str:
    named = getattr(ax, "technology_name", None)     # a family's own name of the kind of axis
    kind = "synchronous axis, " if hasattr(ax, "possible_leading_values") else ""
    if ax.parameters.effective.get("VirtualAxis.Mode"):         # an S7-1500 tag: a virtual axis has no drive
        return kind + "virtual"
    interface = ax.config.drive.interface
    drive = "PTO" if ax.pto else "simulated" if ax.sim else "PROFIdrive" if interface is SetpointInterface.PROFIDRIVE \
        else "CiA 402" if interface is SetpointInterface.CANOPEN else "analog"
    if named:
        return named if ax.sim else f"{named}, {drive}"
    return kind + drive


def _values(ax) -> str:
    """The two values printed per axis after a run: the family's own (``summary_tags``), Position and
    ActualPosition, or - for a family whose axis has neither (a Pilz drive axis names its values by
    register) - the kernel's setpoint and actual position."""
    tags = getattr(ax, "summary_tags", ("Position", "ActualPosition"))
    try:
        return ", ".join(f"{tag} {ax.tag(tag):.6g}" for tag in tags)
    except KeyError:
        b, i = ax.ctl.bank, ax.index
        return f"setpoint {float(b.sp_p[i]):.6g}, actual {float(b.act_p[i]):.6g}"


def load_program(ctl, program: str, extra: dict | None = None) -> None:
    """Run a user program file: it defines ``setup(ctl)`` or uses the global ``ctl`` it is given
    (``extra``: further globals, e.g. ``pacing`` under ``plcmotion serve``)."""
    path = Path(program)
    if not path.is_file():
        raise FileNotFoundError(f"{program}: program file not found")
    try:
        namespace = runpy.run_path(str(path), init_globals={"ctl": ctl, "axes": ctl.axes, **(extra or {})},
                                   run_name="__plcmotion__")
    except SystemExit as exc:            # not the CLI's exit: the program file must register programs
        raise RuntimeError(f"the file called sys.exit({exc.code!r}) while it was loaded") from None
    setup = namespace.get("setup")
    if callable(setup):
        setup(ctl)
    if not ctl._programs:
        raise ValueError(f"{program}: registers no program; decorate a function with @ctl.program "
                         f"(inside setup(ctl) or at module level)")


def _load(args: argparse.Namespace, before_program=None):
    """The controller of ``args.project`` with ``args.program`` loaded, or the exit code of the failure.
    ``before_program(ctl)`` gives further globals of the program file."""
    from .kernel.runtime import exception_text
    from .project import ProjectError, load_project

    try:
        ctl = load_project(args.project, allow_outside_paths=getattr(args, "allow_outside_paths", False))
    except ProjectError as exc:
        print(exc, file=sys.stderr)
        return 2
    try:
        load_program(ctl, args.program, before_program(ctl) if before_program is not None else None)
    except KeyboardInterrupt:
        print(f"{args.program}: interrupted while loading", file=sys.stderr)
        return 130
    except BaseException as exc:  # noqa: BLE001 - the user's file: report it, do not show our internals
        print(f"{args.program}: {exception_text(exc)}", file=sys.stderr)
        return 2
    return ctl


def _print_objects(ctl) -> None:
    """Each axis and technology object after a run: state, values, errors; the watchdog's overruns."""
    family = families.lookup(ctl.family)

    def alarms(to) -> str:
        """The family's view of the object's errors (its alarm numbers and texts, its error records)."""
        return ", ".join(families.error_texts(family, to)) or "no error"

    for name, ax in ctl.axes.items():
        errors = alarms(ax)
        print(f"  {name}: {ax.state}, {_values(ax)}, homed {ax.homed}, {errors}")
    for name, to in ctl.objects.items():
        errors = alarms(to)
        print(f"  {name}: {type(to).__name__}, {errors}")
    wd = ctl.watchdog
    if wd.count:
        print(f"cycle watchdog: {wd.count} cycle time overrun{'s' if wd.count != 1 else ''} (longest program "
              f"run {wd.longest * 1000:.4g} ms, watchdog time {wd.limit * 1000:.4g} ms)")


def cmd_run(args: argparse.Namespace) -> int:
    from .trace import Trace, plot_csv

    problem = _check_run_args(args)
    if problem:
        print(f"plcmotion run: {problem}", file=sys.stderr)
        return 2
    ctl = _load(args)
    if isinstance(ctl, int):
        return ctl
    settings = getattr(ctl, "project", None) or {}
    trace_settings = settings.get("trace", {}) if isinstance(settings, dict) else {}
    trace = None
    if args.trace or args.plot:
        signals = args.signal or trace_settings.get("signals") or None
        try:
            trace = Trace(ctl, signals, every=args.every or trace_settings.get("every", 1), stream_to=args.trace)
            trace.start()
        except (KeyError, ValueError, TypeError) as exc:
            print(f"trace: {exc.args[0] if exc.args else exc}", file=sys.stderr)
            return 2
        except OSError as exc:
            print(f"--trace {args.trace}: {exc.strerror or exc}", file=sys.stderr)
            return 2
    n = max(1, round(args.duration / ctl.app_cycle))
    wall0 = time.perf_counter()
    last = 0.0
    show = args.progress or (not args.quiet and sys.stderr.isatty())
    interrupted = False
    try:
        with warnings.catch_warnings():
            # the CLI reports a STOP with its reason and the cycle overruns at the end of the run
            warnings.simplefilter("ignore", ProgramErrorWarning)
            warnings.simplefilter("ignore", CycleOverrunWarning)
            for k in range(n):
                ctl.step()
                now = time.perf_counter()
                if show and (now - last > 0.2 or k == n - 1):
                    last = now
                    _progress((k + 1) / n, now - wall0, ctl.time)
    except KeyboardInterrupt:           # Ctrl-C: the controller went to STOP; keep what was recorded
        interrupted = True
    finally:
        if show:
            sys.stderr.write("\n")
        if trace is not None:
            trace.stop()
        ctl.close()                     # drives on a bus: release the connection
    wall = time.perf_counter() - wall0
    plot_failed = None
    if trace is not None and args.plot and not interrupted:
        try:
            if args.trace:
                plot_csv(args.trace, args.plot)
            else:
                trace.plot(args.plot)
        except (OSError, ValueError) as exc:   # e.g. the disk filled up during the run
            plot_failed = f"--plot {args.plot}: {getattr(exc, 'strerror', None) or exc}"
    print(f"ran {ctl.time:.3f} s of virtual time in {wall:.2f} s (x{ctl.time / wall if wall else 0:.1f} real time), "
          f"mode {ctl.mode}")
    _print_objects(ctl)
    if args.trace:
        print(f"trace: {args.trace}")
    if args.plot and not interrupted and plot_failed is None:
        print(f"plot: {args.plot}")
    if interrupted:
        print(f"interrupted at t = {ctl.time:.6g} s: controller in {ctl.mode}", file=sys.stderr)
        return 130
    if plot_failed:
        print(plot_failed, file=sys.stderr)
    trace_failed = trace.write_error if trace is not None else None
    if trace_failed:
        print(f"plcmotion run: --trace {args.trace}: cannot write the trace: {trace_failed}", file=sys.stderr)
    if ctl.mode != "RUN":
        print(f"controller in {ctl.mode}: {ctl.stop_reason}", file=sys.stderr)
        return 1
    return 1 if plot_failed or trace_failed else 0


#: largest ``--speed`` factor: beyond it a 1 ms servo cycle is shorter than a Python servo cycle takes
MAX_SPEED = 1000.0


def _check_serve_args(args: argparse.Namespace) -> str | None:
    """The first problem of the ``serve`` arguments (before the project is loaded), or None."""
    d = args.duration
    if d is not None and (not math.isfinite(d) or d <= 0):
        return f"--duration {d!r}: allowed: a finite time > 0 s"
    if d is not None and d > MAX_DURATION:
        return f"--duration {d:g}: allowed: at most {MAX_DURATION:g} s"
    if not math.isfinite(args.speed) or not 0 < args.speed <= MAX_SPEED:
        return f"--speed {args.speed!r}: allowed: a factor in (0, {MAX_SPEED:g}] of real time"
    if args.virtual and args.speed != 1.0:
        return "--speed and --virtual: virtual time runs unpaced, there is no wall clock to scale"
    if args.tolerate < 0:
        return f"--tolerate {args.tolerate}: allowed: a whole number >= 0 of overruns in a row"
    if args.realtime is not None and not 1 <= args.realtime <= 99:
        return f"--realtime {args.realtime}: allowed: a SCHED_FIFO priority in [1, 99]"
    if args.realtime is not None and args.virtual:
        return "--realtime and --virtual: virtual time runs unpaced, there is nothing to schedule in real time"
    return None


def cmd_serve(args: argparse.Namespace) -> int:
    import logging
    import signal

    from .services import make_loop
    from .services.realtime import request_realtime

    problem = _check_serve_args(args)
    if problem:
        print(f"plcmotion serve: {problem}", file=sys.stderr)
        return 2
    made: list = []

    def make(ctl) -> dict:
        loop = make_loop(ctl, virtual=args.virtual, speed=args.speed, overrun=args.overrun, tolerated=args.tolerate)
        made.append(loop)
        return {} if loop.pacing is None else {"pacing": loop.pacing}

    ctl = _load(args, make)
    if isinstance(ctl, int):
        return ctl
    loop = made[0]
    log = logging.getLogger("plcmotion.serve")
    if not log.handlers:
        handler = logging.StreamHandler(sys.stderr)
        handler.setFormatter(logging.Formatter("plcmotion serve: %(message)s"))
        log.addHandler(handler)
        log.propagate = False

    def on_signal(signum, frame) -> None:
        if loop.shutting_down:      # a second signal: no more waiting for the stop ramps
            raise KeyboardInterrupt
        loop.request_shutdown()

    if args.realtime is not None:
        refused = request_realtime(args.realtime)
        if refused:
            log.warning(refused)
    handlers = {sig: signal.signal(sig, on_signal) for sig in (signal.SIGINT, signal.SIGTERM)}
    wall0 = time.perf_counter()
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ProgramErrorWarning)        # reported at the end, as by run
            warnings.simplefilter("ignore", CycleOverrunWarning)
            loop.run(args.duration)
    except KeyboardInterrupt:
        print(f"interrupted again at t = {ctl.time:.6g} s: controller in {ctl.mode}", file=sys.stderr)
        return 130
    finally:
        for sig, old in handlers.items():
            signal.signal(sig, old)
        ctl.close()
    wall = time.perf_counter() - wall0
    print(f"served {ctl.time:.3f} s of virtual time in {wall:.2f} s (x{ctl.time / wall if wall else 0:.1f} real "
          f"time), mode {ctl.mode}, ended by {loop.ended_by}")
    if loop.pacer is not None:
        print(loop.pacer.summary())
    _print_objects(ctl)
    if loop.not_stopped:
        print(f"shutdown: {', '.join(loop.not_stopped)} still moving after {loop.shutdown_timeout:g} s: enable "
              "removed", file=sys.stderr)
        return 1
    if ctl.mode != "RUN":
        print(f"controller in {ctl.mode}: {ctl.stop_reason}", file=sys.stderr)
        return 1
    return 0


OUTSIDE_HELP = ("let state_file and cam csv paths of the project leave the project's folder "
                "(../ or absolute paths)")


def build_parser() -> argparse.ArgumentParser:
    ap = _Parser(prog="plcmotion", description="Soft motion controller with PLC motion instructions.")
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
    p = sub.add_parser("serve", help="run a project with a user program paced to the wall clock")
    p.add_argument("project", help="project file (TOML)")
    p.add_argument("program", help="user program (Python file defining setup(ctl))")
    p.add_argument("--duration", type=float, help="virtual time to run [s] (default: until Ctrl-C/SIGTERM)")
    p.add_argument("--speed", type=float, default=1.0, help="wall-clock speed factor (2: twice real time)")
    p.add_argument("--virtual", action="store_true", help="unpaced virtual time (the run of plcmotion run)")
    p.add_argument("--overrun", choices=("warn", "stop"), default="warn",
                   help="reaction to servo cycle overruns: count and log, or STOP (default: %(default)s)")
    p.add_argument("--tolerate", type=int, default=2,
                   help="overruns in a row --overrun stop tolerates (default: %(default)s)")
    p.add_argument("--realtime", type=int, metavar="PRIORITY",
                   help="run with SCHED_FIFO at this priority (1-99; Linux, needs root or CAP_SYS_NICE)")
    p.add_argument("--allow-outside-paths", action="store_true", help=OUTSIDE_HELP)
    p.set_defaults(func=cmd_serve)
    p = sub.add_parser("check", help="validate a project file")
    p.add_argument("project", help="project file (TOML)")
    p.add_argument("--allow-outside-paths", action="store_true", help=OUTSIDE_HELP)
    p.set_defaults(func=cmd_check)
    return ap


def main(argv: Sequence[str] | None = None) -> int:
    try:
        args = build_parser().parse_args(argv)
    except UsageError as exc:
        print(exc, file=sys.stderr)
        return 2
    return int(args.func(args) or 0)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
