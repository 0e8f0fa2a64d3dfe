"""Command table technology object (S7-1200 V6 §6, §12.10.8.1): up to 32 steps run by MC_CommandTable.

Each step has Type, Position, Velocity, Duration, NextStep and StepCode (tags ``Command[1..32].*``, all
writable from the user program).  Values are checked when a step is about to run; a bad step is a
configuration error of the command table (16#8700-16#8704): only MC_CommandTable shows it and the
motion of the axis continues (§9.6).
"""
from __future__ import annotations

import math
import numbers
import re
from typing import TYPE_CHECKING, Any, Iterable, Mapping

from . import faults as F
from .faults import Fault

if TYPE_CHECKING:  # pragma: no cover
    from .axis import PositioningAxis
    from .protocols import ServoHost as Controller

STEPS = 32
EMPTY, HALT, RELATIVE, ABSOLUTE, VELOCITY, WAIT = 0, 2, 5, 6, 7, 151
TYPES = (EMPTY, HALT, RELATIVE, ABSOLUTE, VELOCITY, WAIT)
COMPLETE, BLEND = 0, 1
TYPE_NAMES = {EMPTY: "Empty", HALT: "Halt", RELATIVE: "Positioning Relative", ABSOLUTE: "Positioning Absolute",
              VELOCITY: "Velocity set point", WAIT: "Wait"}
_FIELDS = {"Type": int, "Position": float, "Velocity": float, "Duration": float, "NextStep": int, "StepCode": int}
_PATH = re.compile(r"^Command\[(\d+)\]\.(\w+)$")
LIMIT = 1.0e12
TINY = 1.0e-12
MIN_DURATION, MAX_DURATION = 0.001, 64800.0


def table_fault(field: str, reason: str, step: int) -> Fault:
    return Fault(F.TABLE_CONFIG, f"{field}:{reason}", False, text=f"step {step}: {field} {reason}")


class CommandStep:
    """One row of the table; attribute names are the tag names of §12.10.8.1."""

    __slots__ = ("Type", "Position", "Velocity", "Duration", "NextStep", "StepCode", "_n")

    def __init__(self, n: int):
        object.__setattr__(self, "_n", n)
        for name in _FIELDS:
            object.__setattr__(self, name, 0 if _FIELDS[name] is int else 0.0)

    def __setattr__(self, name: str, value: Any) -> None:
        if name not in _FIELDS:
            raise AttributeError(f"Command[{self._n}] has no tag {name!r}; tags: {', '.join(_FIELDS)}")
        if isinstance(value, bool) or not isinstance(value, numbers.Real):
            raise TypeError(f"Command[{self._n}].{name} takes a number, got {value!r}")
        if _FIELDS[name] is int:
            if not isinstance(value, numbers.Integral):
                raise TypeError(f"Command[{self._n}].{name} is an integer tag, got {value!r}")
            value = int(value)
            if name == "StepCode" and not 0 <= value <= 0xFFFF:
                raise ValueError(f"Command[{self._n}].StepCode is a WORD: 0..65535, got {value}")
        else:
            try:
                value = float(value)
            except OverflowError:        # an int beyond the LREAL range: the step check shows 16#870x
                value = math.inf if value > 0 else -math.inf
        object.__setattr__(self, name, value)

    def as_dict(self) -> dict[str, Any]:
        return {name: getattr(self, name) for name in _FIELDS}

    def __repr__(self) -> str:
        return f"Command[{self._n}]({', '.join(f'{k}={v!r}' for k, v in self.as_dict().items())})"


class _Commands:
    """``table.Command[n]`` with n = 1..32."""

    __slots__ = ("_rows",)

    def __init__(self) -> None:
        self._rows = [CommandStep(n) for n in range(1, STEPS + 1)]

    def __getitem__(self, n: int) -> CommandStep:
        if not isinstance(n, int) or not 1 <= n <= STEPS:
            raise IndexError(f"Command[{n!r}]: steps are numbered 1..{STEPS}")
        return self._rows[n - 1]

    def __len__(self) -> int:
        return STEPS

    def __iter__(self):
        return iter(self._rows)


class CommandTable:
    """Command table technology object (TO_CommandTable)."""

    def __init__(self, ctl: "Controller", name: str, commands: Iterable[Mapping[str, Any]] = ()):
        self.ctl, self.name = ctl, name
        self.Command = _Commands()
        rows = list(commands)
        if len(rows) > STEPS:
            raise ValueError(f"command table {name}: at most {STEPS} steps, got {len(rows)}")
        for n, row in enumerate(rows, start=1):
            for key, value in row.items():
                setattr(self.Command[n], key, value)
        self._start_values = [step.as_dict() for step in self.Command]   # load memory (§9.7)
        self.in_use_by: Any = None       # the MC_CommandTable job running this table

    def reinitialize(self) -> None:
        """Back to the start values (CPU STOP -> RUN, POWER ON: §2.2.7.4); runtime edits are lost."""
        for step, values in zip(self.Command, self._start_values):
            for key, value in values.items():
                setattr(step, key, value)
        self.in_use_by = None

    def __repr__(self) -> str:
        used = sum(1 for s in self.Command if s.Type != EMPTY)
        return f"<CommandTable {self.name}: {used} steps>"

    def tag(self, path: str) -> Any:
        n, field = self._parse(path)
        return getattr(self.Command[n], field)

    def set_tag(self, path: str, value: Any) -> None:
        n, field = self._parse(path)
        setattr(self.Command[n], field, value)

    def _parse(self, path: str) -> tuple[int, str]:
        m = _PATH.match(path)
        if not m or m.group(2) not in _FIELDS:
            raise KeyError(f"{self.name}.{path} is not a tag of the command table (Command[1..32].Type/Position/"
                           f"Velocity/Duration/NextStep/StepCode)")
        return int(m.group(1)), m.group(2)

    # --- checks when a step runs (§6.4.3.2, §12.8 16#8700-16#8704) ---------------------------------------
    def check_step(self, n: int, axis: "PositioningAxis") -> Fault | None:
        step = self.Command[n]
        kind = step.Type
        if kind not in TYPES:
            return table_fault("Type", "invalid", n)
        if kind in (RELATIVE, ABSOLUTE):
            bad = _check_position(step.Position)
            if bad:
                return table_fault("Position", bad, n)
            bad = _check_velocity(step.Velocity, axis, positive=True)
            if bad:
                return table_fault("Velocity", bad, n)
        if kind == VELOCITY:
            bad = _check_velocity(step.Velocity, axis, positive=False)
            if bad:
                return table_fault("Velocity", bad, n)
        if kind in (VELOCITY, WAIT):
            d = step.Duration
            if not math.isfinite(d):
                return table_fault("Duration", "format", n)
            if d > MAX_DURATION:
                return table_fault("Duration", "too_long", n)
            if d < MIN_DURATION:
                return table_fault("Duration", "too_short", n)
        if step.NextStep not in (COMPLETE, BLEND):
            return table_fault("NextStep", "invalid", n)
        if step.NextStep == BLEND and kind not in (RELATIVE, ABSOLUTE):
            return table_fault("NextStep", "not_permitted", n)
        return None


def _check_position(x: float) -> str:
    if not math.isfinite(x) or (0.0 < abs(x) < TINY):
        return "format"
    if x > LIMIT:
        return "too_high"
    if x < -LIMIT:
        return "too_low"
    return ""


def _check_velocity(v: float, axis: "PositioningAxis", positive: bool) -> str:
    if not math.isfinite(v) or (0.0 < abs(v) < TINY):
        return "format"
    if abs(v) > axis.eff["DynamicLimits.MaxVelocity"] * (1 + 1e-12):
        return "above_max"
    if v == 0.0 and not positive:
        return ""
    if (positive and v <= 0.0) or abs(v) < axis.eff["DynamicLimits.MinVelocity"] * (1 - 1e-12):
        return "below_start_stop"
    return ""


def step_problems(row: Mapping[str, Any]) -> list[tuple[str, Any, str]]:
    """``(field, value, allowed)`` for the values of one configured step that no axis could run
    (S7-1200 V6 §12.10.8.1 ranges; the checks that need the axis, e.g. Velocity above MaxVelocity,
    stay with the run of the step).  A project file is refused for these; the Python API keeps
    accepting them so that the ErrorIDs 16#8700-16#8704 can be shown at runtime."""
    out: list[tuple[str, Any, str]] = []
    for name, value in row.items():
        if name not in _FIELDS:
            out.append((name, value, "one of the fields " + ", ".join(_FIELDS)))
        elif _FIELDS[name] is int and (isinstance(value, bool) or not isinstance(value, numbers.Integral)):
            out.append((name, value, "an integer"))
        elif _FIELDS[name] is float and (isinstance(value, bool) or not isinstance(value, numbers.Real)
                                         or not abs(value) <= LIMIT):
            out.append((name, value, f"a finite number within +-{LIMIT:g}"))
    if out:
        return out
    kind = row.get("Type", EMPTY)
    if kind not in TYPES:
        out.append(("Type", kind, "one of " + ", ".join(f"{t} ({TYPE_NAMES[t]})" for t in TYPES)))
        return out
    position, velocity = row.get("Position", 0.0), row.get("Velocity", 0.0)
    if kind in (RELATIVE, ABSOLUTE):
        if _check_position(float(position)):
            out.append(("Position", position, f"a position within +-{LIMIT:g} (not below {TINY:g} in magnitude "
                                              "unless 0)"))
        if not velocity >= TINY:
            out.append(("Velocity", velocity, "a velocity > 0 for a positioning step"))
    if kind == VELOCITY and 0.0 < abs(velocity) < TINY:
        out.append(("Velocity", velocity, f"0 or a velocity of at least {TINY:g} in magnitude"))
    if kind in (VELOCITY, WAIT):
        duration = row.get("Duration", 0.0)
        if not MIN_DURATION <= duration <= MAX_DURATION:
            out.append(("Duration", duration, f"a time in [{MIN_DURATION:g}, {MAX_DURATION:g}] s"))
    nxt = row.get("NextStep", COMPLETE)
    if nxt not in (COMPLETE, BLEND):
        out.append(("NextStep", nxt, f"{COMPLETE} (complete the step) or {BLEND} (blend)"))
    elif nxt == BLEND and kind not in (RELATIVE, ABSOLUTE):
        out.append(("NextStep", nxt, f"{COMPLETE}: only positioning steps blend into the next step"))
    code = row.get("StepCode", 0)
    if not 0 <= code <= 0xFFFF:
        out.append(("StepCode", code, "a WORD: 0..65535"))
    return out
