"""The configuration tags of an axis at runtime: writes, validation and when a change takes effect.

A :class:`ParameterStore` is a component of an axis, parameterised by its family's schema
(``kernel.schema.AxisSchema``).  A tag assigned by the user program (or a write-parameter instruction) is
stored at once, but the motion only uses it from the moment its effective codes say (the family's schema
maps moments to codes: a drive with position control takes every change at the next servo cycle, a pulse
drive at enable, at the next command, when a jog stops, at the start of homing, ...).  Then the typed
configuration (``axis.config``) is built anew from the values in effect.  A value that is invalid at
that moment becomes the configuration alarm of that tag: emergency stop, shown at the instructions;
acknowledging it (MC_Reset) succeeds once the value is valid again.
"""
from __future__ import annotations

from dataclasses import replace
from typing import Any, Mapping, Protocol

from . import faults as F
from .faults import Fault, Reaction
from .schema import ADDR, REAL, RW, WP, P, AxisSchema
from .tag_views import TagAccessError


class ParameterHost(Protocol):
    """What the store needs of its axis."""

    name: str
    pto: bool
    ctl: Any                      # ``ctl._dirty_axes``: axes with writes due at the next servo cycle
    config: Any                   # the typed configuration the store sets

    def raise_alarm(self, fault: Fault) -> None: ...

    def _apply_bank_config(self) -> None: ...

    def _replan(self) -> None: ...


class ParameterStore:
    """Tag values written (``values``, work memory), start values (``start``, load memory), values in effect
    (``effective``) and the written tags not yet in effect (``dirty``) of one axis."""

    __slots__ = ("host", "schema", "values", "start", "effective", "dirty")

    def __init__(self, host: ParameterHost, schema: AxisSchema, values: Mapping[str, Any]):
        self.host = host
        self.schema = schema
        self.values: dict[str, Any] = dict(values)
        self.start: dict[str, Any] = dict(values)
        self.effective: dict[str, Any] = {}
        self.dirty: set[str] = set()
        self.make_effective(dict(values))

    def make_effective(self, values: dict[str, Any]) -> None:
        """Tag values ``values`` are in effect from now on: the typed axis configuration (``host.config``,
        built by the family's schema) follows them, here and nowhere else."""
        self.effective = values
        config = self.schema.build(values)
        bind = getattr(self.host.ctl, "_bind_drive", None)
        if bind is not None and config.drive.link is None:
            # a drive connected through a bus (Controller.connect_drive) replaces the simulated one
            drive = bind(self.host.name, config.drive)
            if drive is not config.drive:
                config = replace(config, drive=drive)
        self.host.config = config

    def restart(self) -> None:
        """Back to the start values (a restart of the technology object)."""
        self.values = dict(self.start)
        self.make_effective(dict(self.start))
        self.dirty.clear()

    def apply(self, moment: str) -> Fault | None:
        """Make written tag values effective at ``moment``; an invalid value becomes a config alarm."""
        if not self.dirty:
            return None
        host = self.host
        codes = self.schema.moment_codes(moment, host.pto)
        params = self.schema.params
        due = [path for path in self.dirty if codes & set(params[path].effective)]
        if not due:
            return None
        candidate = dict(self.effective)
        for path in due:
            candidate[path] = self.values[path]
        bad = self.validate(candidate, due)
        if bad is not None and bad.detail == host.config.tag_name("software_limits.minimum") + ":rule:low_above_high":
            # changed at runtime: the operating error 16#8010 (remove enable), not the download error
            bad = F.alarm(F.SW_LIMIT_ORDER, "", Reaction.REMOVE_ENABLE)
        if bad is not None:
            host.raise_alarm(bad)
            return bad
        for path in due:
            self.dirty.discard(path)
        changed = any(candidate[p] != self.effective[p] for p in due)
        self.make_effective(candidate)
        if changed:
            host._apply_bank_config()
            if moment == "servo":
                host._replan()
        return None

    def validate(self, cfg: Mapping[str, Any], paths: list[str] | None = None) -> Fault | None:
        """The configuration fault of the first invalid value among ``paths`` (all: None) or the first
        broken rule of the schema; None when ``cfg`` is valid."""
        params = self.schema.params
        for path in paths if paths is not None else list(cfg):
            param = params.get(path)
            if param is None:
                continue
            reason, _ = param.check(cfg[path])
            if reason is not None:
                return F.config_fault(path, reason, f"{path} = {cfg[path]!r}; allowed: {param.allowed()}")
        for issue in self.schema.rule_issues(cfg):
            return F.config_fault(issue.path, issue.reason, issue.message())
        return None

    def config_fault(self, apply: bool = False) -> Fault | None:
        """Validate all tag values; with ``apply`` make them effective when valid."""
        bad = self.validate(self.values)
        if bad is None and apply and self.dirty:
            self.make_effective(dict(self.values))
            self.dirty.clear()
            self.host._apply_bank_config()
        return bad

    def access(self, path: str) -> str:
        """Access right of configuration tag ``path`` on this axis (the schema's, with its pulse-only WP)."""
        return self.schema.access(path, self.host.pto)

    def write(self, path: str, value: Any, *, via_write_param: bool = False) -> None:
        """Assign a configuration tag from the user program (direct access or a write-parameter instruction)."""
        host, schema = self.host, self.schema
        path = schema.canonical(path)
        param = schema.params.get(path)
        if param is None or param.access == P or param.kind == ADDR:
            raise TagAccessError(f"{host.name}.{path} is not a writable tag of the {schema.title}")
        access = self.access(path)
        allowed = access == RW or (via_write_param and access == WP)
        if not allowed:
            raise TagAccessError(f"{host.name}.{path} is read-only in the user program (access {access}"
                                 + (", write it with MC_WriteParam while the axis is disabled" if access == WP
                                    else "") + ")")
        reason, norm = param.check(value)
        if reason == "type":
            raise TypeError(f"{host.name}.{path}: {value!r} is not a {param.kind.upper()} value")
        # an invalid value is stored and becomes the tag's configuration error when it takes effect
        self.values[path] = norm if reason is None or param.kind == REAL else value
        self.dirty.add(path)
        if not host.pto:
            host.ctl._dirty_axes.add(host)
