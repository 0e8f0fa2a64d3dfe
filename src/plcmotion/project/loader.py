"""Reading a project file: the file itself, ``[controller]``, ``[inputs]`` and ``[trace]``; the technology
object sections are ``project.objects``, switches and faults ``plcmotion.project_faults``.  One ``_Loader``
reads one file and collects every problem instead of stopping at the first."""
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

from .. import project_rules as R
from ..toml_text import MAX_SHOWN as _MAX_SHOWN
from ..toml_text import Shown as _Shown
from ..toml_text import key as _key
from ..toml_text import near as _near
from ..toml_text import toml_value
from ..kernel import family as families
from ..kernel import schema as P
from ..kernel.runtime import APP_CYCLE_MAX, SERVO_CYCLE_MAX, SERVO_CYCLE_MIN, Controller
from . import objects as O

SECTIONS = ("controller", "axes", "drives", "trace", "inputs", "command_tables", "cams", "switches", "faults")
CONTROLLER_DEFAULTS: dict[str, float] = {"servo_cycle": 0.001, "app_cycle": 0.004}
CYCLE_RANGES = {"servo_cycle": (SERVO_CYCLE_MIN, SERVO_CYCLE_MAX), "app_cycle": (SERVO_CYCLE_MIN, APP_CYCLE_MAX)}
CONTROLLER_KEYS = ("servo_cycle", "app_cycle", "input_filter", "state_file", "technology_version", "family",
                   "cycle_watchdog", "cycle_watchdog_stop")
TRACE_KEYS = ("signals", "every")
MAX_EVERY = 1_000_000_000

_POSITION = re.compile(r"line (\d+), column (\d+)")


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
        used, advice = O.beyond_default(doc)
        if ctl.family == families.default().name and used:
            self.note(f"controller.family is not set, so {ctl.family} is assumed, but the file has {used}: "
                      + advice)
            return None, self.problems
        self.inputs(ctl, doc.get("inputs"))
        from .drives import load_drives         # drives on a bus are connected before their axes exist
        load_drives(self, ctl, doc.get("drives"), doc.get("axes"))
        declared = O.load_axes(self, ctl, doc.get("axes"))
        O.load_cams(self, ctl, doc.get("cams"), declared)
        O.load_command_tables(self, ctl, doc.get("command_tables"), declared)
        # virtual commissioning: placed switches and timed faults (docs/fault_injection.md)
        from ..project_faults import load_faults, load_switches
        load_switches(self, ctl, doc.get("switches"), declared)
        load_faults(self, ctl, doc.get("faults"), declared)
        trace = self.trace(ctl, doc.get("trace"), declared)
        ctl.project = {"path": self.label, "trace": trace}  # type: ignore[attr-defined]
        if self.problems:
            ctl.close()                          # a drive bus opened for a valid axis is released again
            return None, self.problems
        return ctl, self.problems


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
        FAMILIES = families.names()
        family = section.get("family", families.default().name)
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
        fam = families.lookup(extra["family"]) if "family" in extra else families.default()
        version = section.get("technology_version", fam.default_version)
        if type(version) is not int or version not in fam.versions:     # 7.0 is a float in TOML: refused
            self.bad("controller.technology_version", version,
                     " or ".join(map(str, fam.versions)) + f" ({fam.name} Motion Control "
                     + " / ".join(f"V{v}.0" for v in fam.versions) + ")")
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
            return Controller(family=extra.get("family"))
        try:
            return Controller(cycles["servo_cycle"], cycles["app_cycle"], **extra)
        except ValueError as exc:               # a rule of the runtime this loader does not know
            self.note(f"controller: {exc}")
            return Controller()

    def _watchdog(self, section: dict[str, Any], extra: dict[str, Any]) -> None:
        """cycle_watchdog / cycle_watchdog_stop (plcmotion.kernel.watchdog)."""
        from ..kernel.watchdog import MAX_MULTIPLE, check_multiple

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
        from ..kernel.io import check_address
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
                own = getattr(axis, "trace_tags", None)       # a family's own tag names, e.g. its DB members
                such = ", ".join(own[:3]) + f" ({type(axis).__name__}.tag_paths() lists them)" if own else \
                    "Position, ActualVelocity, StatusBits.Enable (PositioningAxis.tag_paths() lists them)"
                reason += f"; allowed: a status or configuration tag such as {such}"
            self.note(f"{key} = {toml_value(signal)}: {reason}")
            return False
        return True
