"""Configuration tags of an axis at runtime: writes, validation and when a change takes effect.

A tag assigned by the user program (or MC_WriteParam) is stored at once, but the motion only uses it from
the moment its effective code says (S7-1200 V6 §12.9 legends): PROFIdrive/analog axes at the next servo
cycle (code 10), PTO axes at enable (1, 2), at the next command start (5), when a jog stops (6), at the
start of passive (7) or active homing (8).  A value that is invalid at that moment becomes the axis
configuration error of that tag (16#86xx): emergency stop, shown at the instruction and at MC_Power
(§9.6); MC_Reset clears it once the value is valid again.
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, Mapping

from . import faults as F
from . import parameters as P
from .faults import Fault, Reaction

if TYPE_CHECKING:  # pragma: no cover
    from .axis import PositioningAxis


class TagAccessError(AttributeError):
    """Writing a tag the user program may not write (access R or WP, S7-1200 V6 §12.9 legends)."""


_PTO_MOMENTS = {"enable": {1, 2}, "command": {5}, "jog_stop": {6}, "passive_homing": {7},
                "active_homing": {8}, "disable": {1}}
_SERVO_CODES = {10, 1, 2, 5, 6, 7, 8}


class ConfigMixin:
    """Runtime configuration of the positioning axis (mixed into PositioningAxis)."""

    def _make_effective(self: "PositioningAxis", values: dict[str, Any]) -> None:
        """Tag values ``values`` are in effect from now on: the typed axis configuration (``axis.config``,
        built by the family's schema) follows them, here and nowhere else."""
        self.ueff = self.eff = values
        self.config = self.schema.build(values)

    def _moment_codes(self: "PositioningAxis", moment: str) -> set[int]:
        if not self.pto:
            return _SERVO_CODES if moment == "servo" else set()
        return _PTO_MOMENTS.get(moment, set())

    def _apply_dirty(self: "PositioningAxis", moment: str) -> Fault | None:
        """Make written tag values effective at ``moment``; an invalid value becomes a config alarm."""
        if not self._dirty:
            return None
        codes = self._moment_codes(moment)
        params = self.schema.params
        due = [path for path in self._dirty if codes & set(params[path].effective)]
        if not due:
            return None
        candidate = dict(self.ueff)
        for path in due:
            candidate[path] = self.cfg[path]
        bad = self._validate(candidate, due)
        if bad is not None and bad.detail == "PositionLimits_SW.MinPosition:rule:low_above_high":
            # changed at runtime: the operating error 16#8010 (remove enable), not the download error
            bad = F.alarm(F.SW_LIMIT_ORDER, "", Reaction.REMOVE_ENABLE)
        if bad is not None:
            self.raise_alarm(bad)
            return bad
        for path in due:
            self._dirty.discard(path)
        changed = any(candidate[p] != self.ueff[p] for p in due)
        self._make_effective(candidate)
        if changed:
            self._apply_bank_config()
            if moment == "servo":
                self._replan()
        return None

    def _validate(self: "PositioningAxis", cfg: Mapping[str, Any], paths: list[str] | None = None) -> Fault | None:
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

    def _config_fault(self: "PositioningAxis", apply: bool = False) -> Fault | None:
        """Validate all tag values; with ``apply`` make them effective when valid."""
        bad = self._validate(self.cfg)
        if bad is None and apply and self._dirty:
            self._make_effective(dict(self.cfg))
            self._dirty.clear()
            self._apply_bank_config()
        return bad

    def tag_access(self: "PositioningAxis", path: str) -> str:
        """Access right of configuration tag ``path`` on this axis (§12.9 legends; WP of Simulation.Mode
        only for PTO axes, §12.9.19)."""
        access = self.schema.params[path].access
        return P.R if access == P.WP and path in P.PTO_ONLY_WP and not self.pto else access

    def write_tag(self: "PositioningAxis", path: str, value: Any, *, via_write_param: bool = False) -> None:
        """Assign a configuration tag from the user program (direct access or MC_WriteParam)."""
        path = self.schema.canonical(path)
        param = self.schema.params.get(path)
        if param is None or param.access == P.P or param.kind == P.ADDR:
            raise TagAccessError(f"{self.name}.{path} is not a writable tag of the {self.schema.title}")
        access = self.tag_access(path)
        allowed = access == P.RW or (via_write_param and access == P.WP)
        if not allowed:
            raise TagAccessError(f"{self.name}.{path} is read-only in the user program (access {access}"
                                 + (", write it with MC_WriteParam while the axis is disabled" if access == P.WP
                                    else "") + ")")
        reason, norm = param.check(value)
        if reason == "type":
            raise TypeError(f"{self.name}.{path}: {value!r} is not a {param.kind.upper()} value")
        # an invalid value is stored and becomes the tag's configuration error when it takes effect
        self.cfg[path] = norm if reason is None or param.kind == P.REAL else value
        self._dirty.add(path)
        if not self.pto:
            self.ctl._dirty_axes.add(self)
