"""Project files: a controller and its axes described in TOML.

A project file has up to three sections::

    [controller]                  # optional
    servo_cycle = 0.001           # s, default 0.001
    app_cycle = 0.004             # s, a whole multiple of servo_cycle, default 0.004

    [axes.Axis_1]                 # one table per positioning axis, created in file order
    type = "positioning"          # optional; the only axis type so far
    "Actor.Type" = 2              # a tag as a quoted dotted key ...
    [axes.Axis_1.DynamicLimits]   # ... or as a nested table
    MaxVelocity = 500.0
    [axes.Axis_1."Sensor[1]".ActiveHoming]
    Mode = 2

    [trace]                       # optional: what ``plcmotion run`` records by default
    signals = ["Axis_1.Position", "Axis_1.Velocity"]
    every = 1                     # record every n-th servo cycle

    [inputs]                      # optional: input filters of single inputs [s] (default input_filter)
    "I0.3" = { filter = 0.0008 }

    [[switches]]                  # optional: switches placed in the simulated machine, and
    [[faults]]                    # faults played at given times (plcmotion.project_faults)

    [command_tables.Table_1]      # optional: command table technology objects (S7-1200 V6 §6)
    Command = [
        { Type = 5, Position = 100.0, Velocity = 50.0, NextStep = 1, StepCode = 1 },
        { Type = 7, Velocity = 20.0, Duration = 2.0 },
    ]

``servo_cycle`` lies in [0.1 ms, 32 ms], ``app_cycle`` is a whole multiple of it up to 1 s
(``plcmotion.kernel.runtime.SERVO_CYCLE_MIN`` ...).  ``[controller]`` may also set ``input_filter``
(default filter time of the digital inputs, 0.0064 s), ``technology_version`` (the integer 6 or 7: the
S7-1200 Motion Control version whose rules apply where they differ) and ``state_file``: where retentive
data (the absolute encoder adjustment) is kept, relative to the project file; by default
``<project>.state.json`` next to it.

Files the project names (``state_file``, a cam's ``csv``) must lie in the project file's folder or
below it; ``load_project(path, allow_outside_paths=True)`` (``plcmotion check/run
--allow-outside-paths``) also accepts ``../`` and absolute paths.  A cam CSV that is no point list is
reported by line and reason only, never by its content.

Integer settings and tags take TOML integers only (``1``, not ``1.0``).  Size limits
(``plcmotion.project_rules``) are checked before any object is built: 2 MiB and 50000
lines, 1000 technology objects, lists of 4096 items, 12 levels of nesting, 1000 points and 50 segments per cam,
32 steps per command table.
``cycle_watchdog`` (default 100; 0 = off) is the wall-clock time the user programs of one application
cycle may take, in application cycles, and ``cycle_watchdog_stop = true`` puts the controller in STOP on
an overrun, as a CPU does when its maximum cycle time is exceeded (with the watchdog on: 0 and
``cycle_watchdog_stop = true`` together are refused).

``family = "S7-1500T"`` (or ``"S7-1500"``; default ``"S7-1200"``) makes it an S7-1500 controller.  Its
axis tables then use the S7-1500 tag names (``plcmotion.s7_1500.technology.parameters``) and may have
``type = "synchronous"`` with ``leading_values = ["Master", { name = "Encoder", coupling = "actual" }]``,
``type = "external_encoder"`` or ``type = "leading_axis_proxy"``; cams are declared in ``[cams.<name>]``::

    [cams.Knife]
    points = [[0.0, 0.0], [180.0, 50.0], [360.0, 0.0]]    # Point[1..n]
    segments = [ { xmin = 0.0, xmax = 10.0, a0 = 0.0, a1 = 1.0 } ]
    csv = "knife.csv"                                     # or a point list file (relative to the project)
    interpolation_mode = 1                                # 0 linear, 1 cubic spline, 2 Bezier
    boundary_conditions = 1

Axis names are identifiers (letters, digits, underscore; not starting with a digit).  Inside an axis
table the keys are the tag paths of the positioning axis (``plcmotion.s7_1200.technology.parameters.SCHEMA``,
S7-1200 Motion Control V6 §12.9, plus the ``Plant.*`` parameters of the simulated machine); the
alternative spellings of the manuals (``Sensor.Sensor[1].``, ``PositionLimitsSW.``, ...) are accepted.
Tags the file does not set keep their start values.  A trace signal is ``"<axis>.<tag>"`` with any tag
``PositioningAxis.tag`` can read (status or configuration).

API:

* ``load_project(path)`` returns a ready :class:`~plcmotion.kernel.runtime.Controller` with the axes
  created, or raises :class:`ProjectError` listing every problem of the file.
* ``check_project(path)`` returns the same problems as a list of strings (empty when the file is valid).
* The trace settings travel on the returned controller as
  ``ctl.project = {"path": "<the path as given>", "trace": {"signals": [...], "every": n}}``;
  without a ``[trace]`` section the signal list is empty and ``every`` is 1.

Every problem is one line of the form ``<file>: <key path> = <value>: <what is allowed>``, where the key
path is the full path in the file (``axes.Axis_1.DynamicLimits.MaxVelocity``) and the value is shown in
TOML spelling.  Problems of the tag values come from the same checks ``Controller.add_positioning_axis``
runs (``parameters.validate``), so a file that passes here also passes there.
"""
from __future__ import annotations

import difflib
import json
import math
import os
import re
import tomllib
from collections.abc import Mapping
from dataclasses import replace
from pathlib import Path
from typing import Any

from . import project_rules as R
from .toml_text import MAX_SHOWN as _MAX_SHOWN
from .toml_text import Shown as _Shown
from .toml_text import key as _key
from .toml_text import leaves as _leaves
from .toml_text import near as _near
from .toml_text import quoted as _quoted
from .toml_text import toml_value
from .kernel import schema as P
from .kernel.axis import ConfigurationError
from .kernel.family import CAM
from .kernel.runtime import APP_CYCLE_MAX, SERVO_CYCLE_MAX, SERVO_CYCLE_MIN, Controller

SECTIONS = ("controller", "axes", "trace", "inputs", "command_tables", "cams", "switches", "faults")
CONTROLLER_DEFAULTS: dict[str, float] = {"servo_cycle": 0.001, "app_cycle": 0.004}
CYCLE_RANGES = {"servo_cycle": (SERVO_CYCLE_MIN, SERVO_CYCLE_MAX), "app_cycle": (SERVO_CYCLE_MIN, APP_CYCLE_MAX)}
CONTROLLER_KEYS = ("servo_cycle", "app_cycle", "input_filter", "state_file", "technology_version", "family",
                   "cycle_watchdog", "cycle_watchdog_stop")
STEP_KEYS = ("Type", "Position", "Velocity", "Duration", "NextStep", "StepCode")
TRACE_KEYS = ("signals", "every")
MAX_EVERY = 1_000_000_000
AXIS_TYPES = ("positioning",)
AXIS_TYPES_1500 = ("positioning", "synchronous", "external_encoder", "leading_axis_proxy")
COUPLINGS = ("setpoint", "actual", "delayed")
CAM_KEYS = ("points", "segments", "csv", "interpolation_mode", "boundary_conditions")

_NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")       # the rule Controller.add_positioning_axis applies
_POSITION = re.compile(r"line (\d+), column (\d+)")


class ProjectError(ValueError):
    """A project file that cannot be loaded; ``problems`` holds one message per problem."""

    def __init__(self, path: str | os.PathLike, problems: list[str]):
        self.path = os.fspath(path)
        self.problems = list(problems)
        n = len(self.problems)
        head = f"{self.path}: {n} problem{'s' if n != 1 else ''} in the project file"
        super().__init__("\n".join([head] + ["  " + p for p in self.problems]))


def load_project(path: str | os.PathLike, *, allow_outside_paths: bool = False) -> Controller:
    """Read the project file at ``path`` and return a controller with its axes created.

    Files the project names (``state_file``, cam ``csv``) must lie in the project file's folder or
    below it; ``allow_outside_paths=True`` also accepts ``../`` and absolute paths."""
    ctl, problems = _Loader(path, allow_outside_paths).load()
    if problems:
        raise ProjectError(path, problems)
    assert ctl is not None
    return ctl


def check_project(path: str | os.PathLike, *, allow_outside_paths: bool = False) -> list[str]:
    """All problems of the project file at ``path``; an empty list when it loads."""
    return _Loader(path, allow_outside_paths).load()[1]


# --------------------------------------------------------------------------------------------------------

class _Loader:
    """Reads one project file, collecting every problem instead of stopping at the first."""

    def __init__(self, path: str | os.PathLike, allow_outside_paths: bool = False):
        self.path = Path(path)
        self.label = os.fspath(path)
        self.problems: list[str] = []
        self.allow_outside = allow_outside_paths

    def inside(self, key: str, name: str) -> Path | None:
        """``name`` relative to the project file's folder; None (and a problem) when it leaves the
        folder (``../``, an absolute path, a link pointing out) and outside paths are not allowed."""
        folder = self.path.parent
        target = folder / name
        if self.allow_outside:
            return target
        try:
            inside = target.resolve().is_relative_to(folder.resolve())
        except (OSError, RuntimeError, ValueError):  # a link loop, a NUL byte
            inside = False
        if not inside:
            self.bad(key, name, "a file in the project's folder or below it (outside paths need "
                                "load_project(..., allow_outside_paths=True) or --allow-outside-paths)")
            return None
        return target

    # --- messages -----------------------------------------------------------------------------------
    def note(self, text: str) -> None:
        self.problems.append(f"{self.label}: {text}")

    def bad(self, key: str, value: Any, allowed: str) -> None:
        self.note(f"{key} = {toml_value(value)}: allowed: {allowed}")

    def unknown(self, key: str, value: Any, what: str, known: list[str] | tuple[str, ...]) -> None:
        self.note(f"{key}: unknown {what} (value {toml_value(value)}); {_near(key.rsplit('.', 1)[-1], known)}")

    def issue(self, axis_key: str, issue: P.Issue, written: Mapping[str, str]) -> None:
        """A problem found by the parameter checks, named by the key path the file uses."""
        suffix = ""
        if issue.reason == "unknown":
            path = issue.path                         # already the spelling of the file
        elif issue.path in written:
            path = written[issue.path]
        else:
            path, suffix = issue.path, " (start value; the file does not set this tag)"
        shown = replace(issue, path=f"{axis_key}.{path}", value=_Shown(issue.value))
        self.note(shown.message() + suffix)

    # --- the whole file -----------------------------------------------------------------------------
    def load(self) -> tuple[Controller | None, list[str]]:
        doc = self.read()
        if doc is None:
            return None, self.problems
        limits = R.size_problems(doc)
        if limits:                               # before any work that grows with the file
            for key, message in limits:
                self.note(f"{key}: {message}")
            return None, self.problems
        for key, value in doc.items():
            if key not in SECTIONS:
                self.unknown(key, value, "section", SECTIONS)
        ctl = self.controller(doc.get("controller"))
        if getattr(self, "family_unknown", False):
            # which technology objects and tags exist depends on the family: check them once it is known
            return None, self.problems
        used = self._s7_1500_objects(doc)
        if ctl.family == "S7-1200" and used:
            self.note(f"controller.family is not set, so S7-1200 is assumed, but the file has {used}: "
                      'set family = "S7-1500T" (or "S7-1500") in [controller]')
            return None, self.problems
        self.inputs(ctl, doc.get("inputs"))
        declared = self.axes(ctl, doc.get("axes"))
        self.cams(ctl, doc.get("cams"), declared)
        self.command_tables(ctl, doc.get("command_tables"), declared)
        # virtual commissioning: placed switches and timed faults (docs/fault_injection.md)
        from .project_faults import load_faults, load_switches
        load_switches(self, ctl, doc.get("switches"), declared)
        load_faults(self, ctl, doc.get("faults"), declared)
        trace = self.trace(ctl, doc.get("trace"), declared)
        ctl.project = {"path": self.label, "trace": trace}  # type: ignore[attr-defined]
        return (None if self.problems else ctl), self.problems

    @staticmethod
    def _s7_1500_objects(doc: Mapping[str, Any]) -> str:
        """The S7-1500 technology objects a file declares without naming its family ("" if none)."""
        controller = doc.get("controller")
        if isinstance(controller, dict) and "family" in controller:
            return ""
        axes = doc.get("axes")
        kinds = sorted({a.get("type") for a in axes.values() if isinstance(a, dict) and isinstance(a.get("type"), str)}
                       - set(AXIS_TYPES)) if isinstance(axes, dict) else []
        found = [f"{k} axes" if k in ("positioning", "synchronous") else k.replace("_", " ") + "s" for k in kinds
                 if isinstance(k, str) and k in AXIS_TYPES_1500]
        if doc.get("cams"):
            found.append("cams")
        return " and ".join(found)

    def read(self) -> dict[str, Any] | None:
        try:
            size = self.path.stat().st_size
            if size > R.MAX_FILE_BYTES and self.path.is_file():
                self.note(f"the file has {size} bytes; allowed: at most {R.MAX_FILE_BYTES} bytes for a project file")
                return None
            with self.path.open("rb") as f:     # bounded: a device or pipe has no st_size and may never end
                data = f.read(R.MAX_FILE_BYTES + 1)
            if len(data) > R.MAX_FILE_BYTES:
                self.note(f"the file has more than {R.MAX_FILE_BYTES} bytes; allowed: at most {R.MAX_FILE_BYTES} "
                          "bytes for a project file")
                return None
        except FileNotFoundError:
            self.note("file not found")
            return None
        except IsADirectoryError:
            self.note("is a directory, not a project file")
            return None
        except OSError as exc:
            self.note(f"cannot read the file: {exc.strerror or exc}")
            return None
        try:
            text = data.decode("utf-8")
        except UnicodeDecodeError as exc:
            self.note(f"not UTF-8 text (invalid byte at offset {exc.start}); TOML files are UTF-8")
            return None
        lines = text.count("\n") + 1
        if lines > R.MAX_LINES:
            self.note(f"the file has {lines} lines; allowed: at most {R.MAX_LINES} lines for a project file")
            return None
        try:
            return tomllib.loads(text)
        except tomllib.TOMLDecodeError as exc:
            message = str(exc)
            where = _POSITION.search(message)
            if where:
                lines = text.splitlines()
                row = int(where.group(1))
                if 1 <= row <= len(lines):
                    line = lines[row - 1].strip()
                    line = line if len(line) <= _MAX_SHOWN else line[:_MAX_SHOWN - 3] + "..."
                    message += f"; line {row} reads: {line}"
            self.note(f"TOML syntax error: {message}")
            return None
        except RecursionError:                   # tomllib parses nested arrays and inline tables recursively
            self.note(f"tables or lists nested too deeply; allowed: at most {R.MAX_DEPTH} levels")
            return None

    # --- [controller] -------------------------------------------------------------------------------
    def controller(self, section: Any) -> Controller:
        """The controller of the file; a default one (to go on checking the axes) when the section is bad."""
        if section is None:
            section = {}
        if not isinstance(section, dict):
            self.bad("controller", section, "a table [controller] with servo_cycle and app_cycle")
            return Controller()
        before = len(self.problems)
        for key, value in section.items():
            if key not in CONTROLLER_KEYS:
                self.unknown(f"controller.{key}", value, "key", list(CONTROLLER_KEYS))
        extra: dict[str, Any] = {}
        from .kernel.family import names as family_names
        FAMILIES = family_names()
        family = section.get("family", "S7-1200")
        if family not in FAMILIES:
            same = [f for f in FAMILIES if isinstance(family, str) and f.lower() == family.strip().lower()]
            hint = f" (did you mean {json.dumps(same[0])}?)" if same else ""
            self.bad("controller.family", family, ", ".join(json.dumps(f) for f in FAMILIES) + hint
                     + " (the technology objects are checked once the family is valid)")
            self.family_unknown = True
        else:
            extra["family"] = family
        filt = section.get("input_filter", 0.0064)
        if isinstance(filt, bool) or not isinstance(filt, (int, float)) or not 0.0 <= filt <= 20.0:
            self.bad("controller.input_filter", filt, "a time in [0, 20] s, e.g. 0.0064")
        else:
            extra["input_filter"] = float(filt)
        s71200 = extra.get("family", "S7-1200") == "S7-1200"
        version = section.get("technology_version", 6 if s71200 else 5)
        allowed = (6, 7) if s71200 else (5,)
        if type(version) is not int or version not in allowed:     # 7.0 is a float in TOML: refused
            self.bad("controller.technology_version", version, "6 or 7 (S7-1200 Motion Control V6.0 / V7.0)"
                     if s71200 else "5 (S7-1500 Motion Control V5.0)")
        else:
            extra["technology_version"] = version
        state = section.get("state_file", self.path.name.rsplit(".", 1)[0] + ".state.json")
        if not isinstance(state, str) or not state.strip():
            self.bad("controller.state_file", state, "a file name, relative to the project file")
        else:
            where = self.inside("controller.state_file", state)
            if where is not None:
                extra["state_file"] = os.fspath(where)
        self._watchdog(section, extra)
        cycles: dict[str, float] = {}
        for key, default in CONTROLLER_DEFAULTS.items():
            value = section.get(key, default)
            lo, hi = CYCLE_RANGES[key]
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not lo <= value <= hi:
                self.bad(f"controller.{key}", value, f"a positive number of seconds in [{lo:g}, {hi:g}], "
                                                     f"e.g. {default:g}")
            else:
                cycles[key] = float(value)
        if len(cycles) == 2:
            servo, app = cycles["servo_cycle"], cycles["app_cycle"]
            ratio = app / servo
            if abs(ratio - round(ratio)) > 1e-9 * ratio or round(ratio) < 1:
                given = "" if "app_cycle" in section else " (default)"
                lower, upper = max(1, math.floor(ratio)) * servo, max(1, math.ceil(ratio)) * servo
                self.note(f"controller.app_cycle = {toml_value(app)}{given}: allowed: a whole multiple "
                          f"of servo_cycle = {toml_value(servo)} s, e.g. {lower:g} or {upper:g}")
        if len(self.problems) > before:         # go on checking the objects against the right family
            return Controller(family=extra.get("family", "S7-1200"))
        try:
            return Controller(cycles["servo_cycle"], cycles["app_cycle"], **extra)
        except ValueError as exc:               # a rule of the runtime this loader does not know
            self.note(f"controller: {exc}")
            return Controller()

    def _watchdog(self, section: dict[str, Any], extra: dict[str, Any]) -> None:
        """cycle_watchdog / cycle_watchdog_stop (plcmotion.kernel.watchdog)."""
        from .kernel.watchdog import MAX_MULTIPLE, check_multiple

        if "cycle_watchdog" in section:
            try:
                extra["cycle_watchdog"] = check_multiple(section["cycle_watchdog"])
            except ValueError:
                self.bad("controller.cycle_watchdog", section["cycle_watchdog"],
                         f"a number of application cycles in [1, {MAX_MULTIPLE:g}], or 0 (off)")
        if "cycle_watchdog_stop" in section:
            stop = section["cycle_watchdog_stop"]
            if not isinstance(stop, bool):
                self.bad("controller.cycle_watchdog_stop", stop, "true or false")
            elif stop and "cycle_watchdog" in extra and extra["cycle_watchdog"] is None:
                self.bad("controller.cycle_watchdog_stop", stop,
                         "false while cycle_watchdog is 0 (off): there is no watchdog whose overrun could stop")
            else:
                extra["cycle_watchdog_stop"] = stop

    # --- [inputs] -----------------------------------------------------------------------------------
    def inputs(self, ctl: Controller, section: Any) -> None:
        if section is None:
            return
        if not isinstance(section, dict):
            self.bad("inputs", section, 'a table of inputs, e.g. "I0.3" = { filter = 0.0008 }')
            return
        from .kernel.io import check_address
        for address, spec in section.items():
            key = f"inputs.{_key(address)}"
            try:
                address = check_address(address, "I")
            except (TypeError, ValueError):
                self.note(f"{key}: not an input address; allowed: I<byte>.<bit>, e.g. I0.3")
                continue
            if not isinstance(spec, dict):
                self.bad(key, spec, "a table { filter = <seconds> }")
                continue
            for name, value in spec.items():
                if name != "filter":
                    self.unknown(f"{key}.{name}", value, "key", ["filter"])
                    continue
                try:
                    if isinstance(value, bool) or not isinstance(value, (int, float)) or not 0.0 <= value <= 20.0:
                        raise ValueError(value)          # also ints beyond float range (no OverflowError)
                    ctl.inputs.set_filter(address, value)
                except ValueError:
                    self.bad(f"{key}.filter", value, "a time in [0, 20] s")

    # --- [command_tables.<name>] ----------------------------------------------------------------------
    def command_tables(self, ctl: Controller, section: Any, declared: list[str]) -> None:
        if section is None:
            return
        if not isinstance(section, dict):
            self.bad("command_tables", section, "one table [command_tables.<name>] per command table")
            return
        for name, table in section.items():
            key = f"command_tables.{_key(name)}"
            if not _NAME.match(name) or name in declared:
                self.note(f"{key}: the name must be an identifier not used by an axis")
                continue
            if not isinstance(table, dict):
                self.bad(key, table, "a table with Command = [ { Type = ..., ... }, ... ]")
                continue
            for extra in table:
                if extra != "Command":
                    self.unknown(f"{key}.{extra}", table[extra], "key", ["Command"])
            steps = table.get("Command", [])
            if not isinstance(steps, list) or len(steps) > 32:
                self.bad(f"{key}.Command", steps, "a list of at most 32 steps")
                continue
            from .s7_1200.technology.command_table import step_problems
            rows = []
            ok = True
            for n, step in enumerate(steps, start=1):
                skey = f"{key}.Command[{n}]"
                if not isinstance(step, dict):
                    self.bad(skey, step, "a table { Type = 5, Position = 100.0, Velocity = 50.0 }")
                    ok = False
                    continue
                for field, value, allowed in step_problems(step):
                    if field not in STEP_KEYS:
                        self.unknown(f"{skey}.{field}", value, "key", STEP_KEYS)
                    else:
                        self.bad(f"{skey}.{field}", value, allowed)
                    ok = False
                rows.append(step)
            if ok:
                try:
                    ctl.add_command_table(name, rows)
                except (TypeError, ValueError) as exc:
                    self.note(f"{key}: {exc}")

    # --- [axes.<name>] ------------------------------------------------------------------------------
    def axes(self, ctl: Controller, section: Any) -> list[str]:
        """Create the axes on ``ctl``; returns the names of all axis tables (valid or not)."""
        if section is None:
            return []
        if not isinstance(section, dict):
            self.bad("axes", section, "one table [axes.<name>] per axis")
            return []
        for name, table in section.items():
            key = f"axes.{_key(name)}"
            valid_name = bool(_NAME.match(name))
            if not valid_name:
                self.note(f"{key}: the axis name {_quoted(name)} is not an identifier; "
                          f"allowed: letters, digits and underscores, not starting with a digit")
            if not isinstance(table, dict):
                self.bad(key, table, f"a table of axis tags, e.g. [{key}] with \"Actor.Type\" = 2")
                continue
            self.axis(ctl, name, key, table, create=valid_name)
        names = list(section)
        for name, table in section.items():
            raw = table.get("leading_values", []) if isinstance(table, dict) else []
            for source in (raw if isinstance(raw, (list, dict)) else []):     # other kinds: reported in axis()
                source_name = source.get("name") if isinstance(source, dict) else source
                if isinstance(source_name, str) and (source_name not in names or source_name == name):
                    self.note(f"axes.{_key(name)}.leading_values: {_quoted(source_name)} is not a technology "
                              f"object of this file; allowed: {', '.join(n for n in names if n != name) or 'none'}")
        return names

    def _schema(self, ctl: Controller, kind: str) -> Any:
        if ctl.family == "S7-1200":
            from .s7_1200.technology.parameters import S7_1200
            return S7_1200
        if kind == "external_encoder":
            from .s7_1500.technology.external_encoder import ENCODER_SCHEMA
            return ENCODER_SCHEMA
        if kind == "leading_axis_proxy":
            from .s7_1500.technology.proxy import PROXY_SCHEMA
            return PROXY_SCHEMA
        from .s7_1500.technology.parameters import S7_1500
        return S7_1500

    def _leading_values(self, key: str, value: Any) -> list[tuple[str, str]] | None:
        if isinstance(value, dict):
            value = [{"name": k, "coupling": v} for k, v in value.items()]
        if not isinstance(value, list):
            self.bad(key, value, 'a list of names or { name = "...", coupling = "setpoint" | "actual" | "delayed" }')
            return None
        out = []
        for i, item in enumerate(value):
            if isinstance(item, str):
                out.append((item, "setpoint"))
            elif isinstance(item, dict) and isinstance(item.get("name"), str) and \
                    item.get("coupling", "setpoint") in COUPLINGS and set(item) <= {"name", "coupling"}:
                out.append((item["name"], item.get("coupling", "setpoint")))
            else:
                self.bad(f"{key}[{i}]", item, 'a name or { name = "...", coupling = "setpoint" | "actual" | "delayed" }')
                return None
        return out

    def axis(self, ctl: Controller, name: str, key: str, table: dict[str, Any], *, create: bool) -> None:
        values = dict(table)
        types = AXIS_TYPES if ctl.family == "S7-1200" else AXIS_TYPES_1500
        kind = values.pop("type", types[0])
        if kind not in types:
            self.bad(f"{key}.type", kind, "one of " + ", ".join(json.dumps(t) for t in types))
            create = False
        leading = None
        if "leading_values" in values:
            raw = values.pop("leading_values")
            if kind != "synchronous":
                self.note(f"{key}.leading_values: only an axis of type = \"synchronous\" has leading values")
                create = False
            else:
                leading = self._leading_values(f"{key}.leading_values", raw)
                # itself as leading value: reported with the other unknown sources in axes()
                create = create and leading is not None and all(source != name for source, _ in leading)
        schema = self._schema(ctl, kind)
        flat: dict[str, Any] = {}
        written: dict[str, str] = {}                # canonical tag path -> spelling in the file
        for path, value in _leaves(values):
            canon = schema.canonical(path)
            if isinstance(value, Mapping) and any(tag.startswith(canon + ".") for tag in schema.params):
                continue                            # an empty group of tags, e.g. [axes.A.Homing]
            if canon in written:
                first = written[canon]
                self.note(f"{key}.{path} = {toml_value(value)}: the tag is already set by "
                          f"{key}.{first} = {toml_value(flat[first])}; set each tag once")
                create = False
                continue
            written[canon] = path
            flat[path] = value
        _cfg, issues = schema.validate(flat)
        for issue in issues:
            self.issue(key, issue, written)
        if issues or not create:
            return
        try:
            where = f"{self.label}: {key}"
            if kind == "synchronous":
                ctl.add_synchronous_axis(name, flat, leading_values=leading or (), source=where)
            elif kind == "external_encoder":
                ctl.add_external_encoder(name, flat, source=where)
            elif kind == "leading_axis_proxy":
                ctl.add_leading_axis_proxy(name, flat, source=where)
            else:
                ctl.add_positioning_axis(name, flat, source=where)
        except ConfigurationError as exc:
            for issue in exc.issues:
                self.issue(key, issue, written)
        except Exception as exc:  # noqa: BLE001 - report, never a traceback out of a project file
            self.note(f"{key}: the axis could not be created: {type(exc).__name__}: {exc}")

    # --- [cams.<name>] -------------------------------------------------------------------------------
    def cams(self, ctl: Controller, section: Any, declared: list[str]) -> None:
        if section is None:
            return
        if not isinstance(section, dict):
            self.bad("cams", section, "one table [cams.<name>] per cam")
            return
        if not ctl.offers(CAM):
            self.note('cams: cams need family = "S7-1500T" in [controller]')
            return
        from .s7_1500.technology.cam_to import SEGMENT_FIELDS
        for name, table in section.items():
            key = f"cams.{_key(name)}"
            if not _NAME.match(name) or name in declared:
                self.note(f"{key}: the name must be an identifier not used by an axis")
                continue
            if not isinstance(table, dict):
                self.bad(key, table, "a table with points, segments, interpolation_mode, boundary_conditions")
                continue
            ok = True
            for extra, value in table.items():
                if extra not in CAM_KEYS:
                    self.unknown(f"{key}.{extra}", value, "key", CAM_KEYS)
                    ok = False
            points = table.get("points", [])
            if not isinstance(points, list):
                self.bad(f"{key}.points", points, "a list of [x, y] number pairs")
                ok, points = False, []
            elif (bad := R.point_problem(points)) is not None:
                i, allowed = bad
                if i is None:
                    self.note(f"{key}.points: {len(points)} points; allowed: {allowed}")
                else:
                    self.bad(f"{key}.points[{i}]", points[i], allowed)
                ok, points = False, []
            if "csv" in table:
                path = table["csv"]
                if not isinstance(path, str):
                    self.bad(f"{key}.csv", path, "a file name relative to the project file")
                    ok = False
                elif (where := self.inside(f"{key}.csv", path)) is None:
                    ok = False
                else:
                    from .cams.io import PointListError, import_points
                    try:
                        # a file that is no point list is named with line and reason, never its content
                        read = [list(p) for p in import_points(where, show_content=False,
                                                               max_points=R.MAX_CAM_POINTS)]
                    except PointListError as exc:
                        self.note(f"{key}.csv = {toml_value(path)}: {exc}")
                        ok = False
                    except OSError as exc:
                        self.note(f"{key}.csv = {toml_value(path)}: cannot read the file: {exc.strerror or exc}")
                        ok = False
                    else:
                        if ok and (bad := R.point_problem(points + read)) is not None:
                            at = "" if bad[0] is None else f" (at point {bad[0] + 1} of both together)"
                            self.bad(f"{key}.csv", path, "points that continue the points of the table: "
                                     + bad[1] + at)
                            ok = False
                        points = points + read
            segments = table.get("segments", [])
            if not isinstance(segments, list):
                self.bad(f"{key}.segments", segments, "a list of tables with " + ", ".join(SEGMENT_FIELDS))
                ok, segments = False, []
            elif (bad := R.segment_problem(segments, SEGMENT_FIELDS)) is not None:
                i, allowed = bad
                if i is None:
                    self.note(f"{key}.segments: {len(segments)} segments; allowed: {allowed}")
                else:
                    self.bad(f"{key}.segments[{i}]", segments[i], allowed)
                ok, segments = False, []
            settings = {}
            for field, allowed in (("interpolation_mode", (0, 1, 2)), ("boundary_conditions", (0, 1))):
                value = table.get(field, 0)
                if type(value) is not int or value not in allowed:      # 1.0 is a float in TOML: refused
                    self.bad(f"{key}.{field}", value, "the integer " + " or ".join(map(str, allowed)))
                    ok = False
                settings[field] = value
            if ok:
                try:
                    ctl.add_cam(name, [tuple(p) for p in points], segments, **settings)
                except (TypeError, ValueError) as exc:
                    self.note(f"{key}: {exc}")

    # --- [trace] ------------------------------------------------------------------------------------
    def trace(self, ctl: Controller, section: Any, declared: list[str]) -> dict[str, Any]:
        settings: dict[str, Any] = {"signals": [], "every": 1}
        if section is None:
            return settings
        if not isinstance(section, dict):
            self.bad("trace", section, "a table [trace] with signals and every")
            return settings
        for key, value in section.items():
            if key not in TRACE_KEYS:
                self.unknown(f"trace.{key}", value, "key", TRACE_KEYS)
        signals = section.get("signals", [])
        if not isinstance(signals, list):
            self.bad("trace.signals", signals, 'a list of strings "<axis>.<tag>", e.g. ["Axis_1.Position"]')
        else:
            settings["signals"] = [s for i, s in enumerate(signals)
                                   if self.signal(ctl, f"trace.signals[{i}]", s, declared)]
        every = section.get("every", 1)
        if isinstance(every, bool) or not isinstance(every, int) or not 1 <= every <= MAX_EVERY:
            self.bad("trace.every", every, f"an integer >= 1 (record every n-th servo cycle), at most {MAX_EVERY}")
        else:
            settings["every"] = every
        return settings

    def signal(self, ctl: Controller, key: str, signal: Any, declared: list[str]) -> bool:
        if not isinstance(signal, str):
            self.bad(key, signal, 'a string "<axis>.<tag>", e.g. "Axis_1.Position"')
            return False
        name, dot, tag = signal.partition(".")
        if not dot or not name or not tag:
            self.bad(key, signal, '"<axis>.<tag>", e.g. "Axis_1.Position"')
            return False
        if name not in declared:
            axes = ", ".join(declared) if declared else "none, the file has no [axes.<name>] table"
            close = difflib.get_close_matches(name, declared, n=1, cutoff=0.6)
            hint = f" (did you mean {close[0]}?)" if close else ""
            self.note(f"{key} = {toml_value(signal)}: unknown axis {name}{hint}; "
                      f"allowed: \"<axis>.<tag>\" with an axis of this file: {axes}")
            return False
        axis = ctl.axes.get(name) or ctl.objects.get(name)
        if axis is None:                            # the axis has problems of its own, reported above
            return False
        try:
            axis.tag_getter(tag)
        except KeyError as exc:
            reason = str(exc.args[0])
            if "did you mean" not in reason:
                reason += "; allowed: a status or configuration tag such as Position, ActualVelocity, " \
                          "StatusBits.Enable (PositioningAxis.tag_paths() lists them)"
            self.note(f"{key} = {toml_value(signal)}: {reason}")
            return False
        return True


__all__ = ["AXIS_TYPES", "AXIS_TYPES_1500", "SECTIONS", "ProjectError", "check_project", "load_project", "toml_value"]
