"""Configuration schemas of technology objects: the generic mechanics, no family's tags.

A family declares each configurable tag of its technology objects once as a :class:`Param` (path, data
type, start value, access right, the moments its change takes effect, admissible range) and collects them
in an :class:`AxisSchema` with its cross-tag rules, its alternative spellings and its builder of the typed
:class:`~plcmotion.kernel.axis_config.AxisConfig`.  This module checks values against such a schema
(:meth:`AxisSchema.validate`), reports every problem as an :class:`Issue` and flattens nested parameter
tables (a project file's) into tag paths.
"""
from __future__ import annotations

import math
import numbers
from dataclasses import dataclass
from typing import Any, Iterable, Mapping

import numpy as np

BOOL, INT, REAL, ADDR = "bool", "int", "real", "address"

#: access rights: R read, RW read/write by the user program, WP write with a write-parameter instruction
#: while the axis is disabled, P plant/simulation parameter (configuration only, not a tag)
R, RW, WP, P = "R", "RW", "WP", "P"

#: the largest magnitude of a configuration value (the range the manuals give for LREAL tags)
E12 = 1.0e12


@dataclass(frozen=True)
class Param:
    path: str
    kind: str
    start: Any
    access: str = R
    effective: tuple[int, ...] = ()
    lo: float | None = None
    hi: float | None = None
    lo_open: bool = False           # lo itself is not allowed
    choices: tuple | None = None
    doc: str = ""
    optional: bool = False          # None allowed (not configured)
    unique: bool = False            # no two objects of one controller may have the same value (a DB number)

    def check(self, value: Any) -> tuple[str, Any] | None:
        """Return ``(reason, normalised)``: reason None when valid.

        Reasons: ``type`` (wrong data type), ``format`` (NaN/inf), ``too_low``, ``too_high``,
        ``selection`` (not one of the allowed values).
        """
        if value is None and self.optional:
            return None, None
        if self.kind == ADDR:
            if not isinstance(value, str):
                return "type", value
            if value.strip() == "":
                return None, ""
            from .io import check_address
            try:
                return None, check_address(value, self.choices[0] if self.choices else None)
            except ValueError:
                return "selection", value
        if self.kind == BOOL:
            if isinstance(value, bool):
                return None, value
            if isinstance(value, np.bool_):
                return None, bool(value)
            if isinstance(value, numbers.Integral) and value in (0, 1):
                return None, bool(value)
            return "type", value
        if self.kind == INT:
            # integers only: 1.0 is a REAL (a TOML file and the Python API tell them apart)
            if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Integral):
                return "type", value
            value = int(value)
        else:  # REAL: numbers only (numpy scalars included), never strings or booleans
            if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
                return "type", value
            try:
                value = float(value)
            except OverflowError:                # an int beyond the LREAL range (10**400): held as +-inf
                return ("too_high", math.inf) if value > 0 else ("too_low", -math.inf)
            if not math.isfinite(value):
                return "format", value
        if self.choices is not None and value not in self.choices:
            return "selection", value
        if self.lo is not None and (value < self.lo or (self.lo_open and value == self.lo)):
            return "too_low", value
        if self.hi is not None and value > self.hi:
            return "too_high", value
        return None, value

    def allowed(self) -> str:
        """Human-readable admissible range, used in configuration error messages."""
        if self.kind == BOOL:
            return "true or false"
        if self.kind == ADDR:
            kind = self.choices[0] if self.choices else "I"
            return f"an {'input' if kind == 'I' else 'output'} address like '{kind}0.{3 if kind == 'I' else 1}' or ''"
        if self.choices is not None:
            return "one of " + ", ".join(str(c) for c in self.choices)
        lo = "-inf" if self.lo is None else repr(self.lo)
        hi = "+inf" if self.hi is None else repr(self.hi)
        left = "(" if self.lo_open else "["
        return f"{'integer' if self.kind == INT else 'real'} in {left}{lo}, {hi}]"



def flatten(tree: Mapping[str, Any], prefix: str = "") -> dict[str, Any]:
    """Flatten nested dicts keyed by tag path components into ``{"A.B.C": value}``.

    Raises ValueError when two spellings give the same path (``"A.B": 1`` beside ``"A": {"B": 2}``)
    or the nesting is deeper than any tag path; :func:`flatten_checked` reports these as issues."""
    flat, issues = flatten_checked(tree, prefix)
    if issues:
        raise ValueError("; ".join(i.message() for i in issues))
    return flat


#: deeper nesting than any tag path has (``Sensor[1].ActiveHoming.Mode``: 3 levels) is a mistake
MAX_DEPTH = 8


def flatten_checked(tree: Mapping[str, Any], prefix: str = "") -> tuple[dict[str, Any], list["Issue"]]:
    """``flatten`` that reports (instead of silently resolving) a tag set twice, once as a dotted key
    and once nested, and nesting deeper than ``MAX_DEPTH`` (also a dict that contains itself)."""
    flat: dict[str, Any] = {}
    issues: list[Issue] = []
    spelled: dict[str, str] = {}                 # flat path -> how it was written first
    stack = [(tree, prefix, "", 0)]
    while stack:                                 # iterative: no RecursionError on deep or cyclic input
        node, path, written, depth = stack.pop()
        if depth > MAX_DEPTH:
            issues.append(Issue(path, "nesting", "{...}", f"allowed: tag paths of at most {MAX_DEPTH} levels"))
            continue
        items = list(node.items())
        for key, value in reversed(items):       # the stack reverses again: keep the given order
            sub = f"{path}.{key}" if path else str(key)
            how = f"{written}[{key!r}]"
            if isinstance(value, Mapping):
                stack.append((value, sub, how, depth + 1))
        for key, value in items:
            if isinstance(value, Mapping):
                continue
            sub = f"{path}.{key}" if path else str(key)
            how = f"{written}[{key!r}]"
            if sub in flat:
                issues.append(Issue(sub, "duplicate", value, f"params{how} = {_brief(value)} and params{spelled[sub]} "
                                                           f"= {_brief(flat[sub])} set the same tag; set each tag once"))
                continue
            flat[sub] = value
            spelled[sub] = how
    return flat, issues


def _brief(value: Any) -> str:
    """``repr(value)``, shortened to a bounded excerpt (a value may be 10**400 or a long list)."""
    text = repr(value)
    return text if len(text) <= 80 else text[:60] + f"... ({len(text)} characters)"



@dataclass(frozen=True)
class Issue:
    """One configuration problem: which tag, why, which value, what is allowed."""

    path: str
    reason: str            # type | format | too_low | too_high | selection | unknown | rule:<name>
    value: Any
    allowed: str

    def message(self) -> str:
        value = _brief(self.value)
        if self.reason == "unknown":
            return f"{self.path}: unknown parameter (value {value}); {self.allowed}"
        return f"{self.path} = {value}: {self.allowed}"



def _check(params: Mapping[str, Param], canon, suggest, values: Mapping[str, Any]
           ) -> tuple[dict[str, Any], list[Issue]]:
    out: dict[str, Any] = {}
    issues: list[Issue] = []
    spelled: dict[str, tuple[str, Any]] = {}    # canonical path -> (spelling, value) of its first setting
    for raw_path, value in values.items():
        path = canon(raw_path)
        param = params.get(path)
        if param is None:
            issues.append(Issue(raw_path, "unknown", value, suggest(path)))
            continue
        if path in spelled:                      # two spellings of the manuals for one tag
            first, was = spelled[path]
            issues.append(Issue(raw_path, "duplicate", value,
                                f"the tag is already set by {first} = {_brief(was)}; set each tag once"))
            continue
        spelled[path] = (raw_path, value)
        reason, norm = param.check(value)
        if reason is not None:
            issues.append(Issue(path, reason, value, "allowed: " + param.allowed() + _hint(param, value)))
        else:
            out[path] = norm
    return out, issues


def _hint(param: Param, value: Any) -> str:
    """Why a whole-numbered REAL is refused for an integer tag."""
    if param.kind == INT and isinstance(value, float) and value.is_integer():
        return f" (an integer: write {int(value)}, not {value!r})"
    return ""



def groups(paths: Iterable[str]) -> dict[str, Any]:
    """Nested dict of path components (used to build attribute views)."""
    tree: dict[str, Any] = {}
    for path in paths:
        node = tree
        parts = path.split(".")
        for part in parts[:-1]:
            node = node.setdefault(part, {})
        node[parts[-1]] = path
    return tree



#: the moment every servo cycle reaches: changes of a drive with position control take effect then
SERVO = "servo"


def _no_rules(cfg: Mapping[str, Any]) -> list[Issue]:
    return []


def _same(path: str) -> str:
    return path


class AxisSchema:
    """The configuration tags of one kind of technology object, how they are checked and what they mean.

    ``params`` declare the tags; ``rules(cfg)`` checks what involves more than one tag; ``canonical(path)``
    maps the alternative spellings of the manuals to the declared path; ``build(cfg)`` turns valid tag
    values into what the kernel reads (an :class:`~plcmotion.kernel.axis_config.AxisConfig` for an axis).
    When a written tag takes effect: its ``Param.effective`` codes are matched against the codes of a
    moment (``moment_codes``): on a drive with position control every code at the next servo cycle
    (moment :data:`SERVO`), on a pulse drive the family's ``pulse_moments`` (enable, command start, ...).
    ``pulse_only_write_param`` names WP tags that are read-only on other drives.
    """

    def __init__(self, title: str, params: Iterable[Param], *, rules=None, canonical=None, build=None,
                 int_types: Mapping[str, str] | None = None, real_type: str = "LReal",
                 pulse_moments: Mapping[str, Iterable[int]] | None = None,
                 pulse_only_write_param: Iterable[str] = ()):
        self.title = title
        self.params: dict[str, Param] = {p.path: p for p in params}
        self._rules = rules or _no_rules
        self._canonical = canonical or _same
        self._build = build
        self._int_types = dict(int_types or {})
        self._real_type = real_type
        self._servo_codes = frozenset(c for p in self.params.values() for c in p.effective)
        self._pulse_moments = {m: frozenset(codes) for m, codes in (pulse_moments or {}).items()}
        self.pulse_only_write_param = frozenset(pulse_only_write_param)
        self.tree = groups(self.params)

    def canonical(self, path: str) -> str:
        return self._canonical(path)

    def defaults(self) -> dict[str, Any]:
        return {p.path: p.start for p in self.params.values()}

    def rule_issues(self, cfg: Mapping[str, Any]) -> list[Issue]:
        return self._rules(cfg)

    def suggest(self, path: str) -> str:
        import difflib

        near = difflib.get_close_matches(path, self.params.keys(), n=3, cutoff=0.6)
        return "did you mean " + " or ".join(near) + "?" if near else f"not a tag of the {self.title}"

    def check_values(self, values: Mapping[str, Any]) -> tuple[dict[str, Any], list[Issue]]:
        return _check(self.params, self.canonical, self.suggest, values)

    def validate(self, values: Mapping[str, Any], base: Mapping[str, Any] | None = None
                 ) -> tuple[dict[str, Any], list[Issue]]:
        """Merge ``values`` over ``base`` (default: the start values), check all; (values, issues)."""
        cfg = dict(self.defaults() if base is None else base)
        norm, issues = self.check_values(values)
        cfg.update(norm)
        if not issues:
            issues.extend(self.rule_issues(cfg))
        return cfg, issues

    def data_type(self, path: str) -> str:
        """The PLC data type of a configuration tag (Bool, LReal/Real, DInt, UDInt, ..., VRef for addresses)."""
        param = self.params[path]
        if param.kind == BOOL:
            return "Bool"
        if param.kind == REAL:
            return self._real_type
        if param.kind == ADDR:
            return "VRef"
        return self._int_types.get(path, "DInt")

    def build(self, cfg: Mapping[str, Any]) -> Any:
        """What the kernel reads of valid tag values ``cfg`` (the family's builder)."""
        if self._build is None:
            raise TypeError(f"the schema of the {self.title} builds no configuration")
        return self._build(cfg)

    def moment_codes(self, moment: str, pulse: bool) -> frozenset[int]:
        """The effective codes that take effect at ``moment`` on a pulse drive or another drive."""
        if not pulse:
            return self._servo_codes if moment == SERVO else frozenset()
        return self._pulse_moments.get(moment, frozenset())

    def access(self, path: str, pulse: bool) -> str:
        """Access right of tag ``path`` on an axis with a pulse drive or another drive."""
        access = self.params[path].access
        return R if access == WP and path in self.pulse_only_write_param and not pulse else access

