"""Leading axis proxy technology object (TO_LeadingAxisProxy, S7-1500T V5 §8, §A.3).

The proxy stands in for a leading axis of another controller.  Every servo cycle it takes the leading
value telegrams that have arrived (from any :class:`~plcmotion.kernel.leading_value.LeadingValueSource`)
and provides the leading value for the local time minus the sender's delay, which every telegram carries
(the leading axis's ``CrossPlcSynchronousOperation.LocalLeadingValueDelayTime``): the value the sender's
delayed local followers use at the same time, so that followers on all controllers move in step (§8.1.3:
"depending on the set delay time, the leading value at the leading axis proxy is automatically
interpolated or extrapolated").  It is interpolated between received values when they reach that far
(``StatusExternalLeadingValue.AdjustmentTime`` < 0), extrapolated from the newest one when they do not
(> 0).  The proxy's own ``Parameter.LocalLeadingValueDelayTime`` is the delay of a virtual following axis
that provides the value on in a cascade (§8.2.3.2, §A.3.4): that axis (coupling "cascade") gets the value
earlier by this time, so that the next proxy can interpolate; the other followers are not shifted.

If no valid value newer than the tolerance ``Parameter.ToleranceTimeExternalLeadingValueInvalid`` has
arrived, the proxy raises technology alarm 900: ``StatusWord.X4 (LeadingValueValid)`` goes FALSE, the
error bits are set and the followers coupled to it are stopped.  Within the tolerance time the value is
extrapolated and the followers keep moving (§8.2.3).
"""
from __future__ import annotations

import math
import numbers
from collections import deque
from typing import TYPE_CHECKING, Any, Callable, Mapping

from ...kernel import faults as F
from ...kernel.tag_views import TagAccessError
from ...kernel.faults import Fault, Reaction
from ...kernel.leading_value import LeadingValueSample, LeadingValueSource
from ...kernel.schema import E12, REAL, RW, AxisSchema, Param
from ...kernel.tag_views import TagViews as AxisTagsMixin
from ...kernel.words import pack, word_type
from . import alarms as A

if TYPE_CHECKING:  # pragma: no cover
    from ...kernel.runtime import Controller

_PARAMS = [
    Param("Parameter.LocalLeadingValueDelayTime", REAL, 0.0, RW, (10,), 0.0, E12,
          doc="delay of the virtual following axis that provides the value on in a cascade [s]"),
    Param("Parameter.ToleranceTimeExternalLeadingValueInvalid", REAL, 0.01, RW, (10,), 0.0, E12,
          doc="time without a valid leading value before alarm 900 [s]"),
]
PROXY_SCHEMA = AxisSchema("leading axis proxy", _PARAMS)

ProxyStatusWord = word_type("StatusWord", {"Control": 0, "Error": 1, "RestartActive": 2,
                                           "OnlineStartValuesChanged": 3, "LeadingValueValid": 4,
                                           "LeadingValueModulo": 5, "LeadingAxisControl": 6})
ProxyErrorWord = word_type("ErrorWord", {"SystemFault": 0, "ConfigFault": 1, "UserFault": 2,
                                         "CommandNotAccepted": 3, "CommunicationFault": 7})
ProxyWarningWord = word_type("WarningWord", {"SystemWarning": 0, "ConfigWarning": 1, "UserWarning": 2,
                                             "CommandNotAccepted": 3, "CommunicationWarning": 7})
ALARM_INVALID = 900          # alarms.ALARMS[900]: ErrorWord.X2, ErrorDetail.Reaction 13
#: default of LeadingAxisProxy.telegram_time_window [s]: generous for a sender that runs ahead (virtual time
#: on another process, an application cycle ahead in-process), small against a forged far-future time
TELEGRAM_TIME_WINDOW = 1.0


def _status(p: "LeadingAxisProxy") -> int:
    s = p.newest
    return ProxyStatusWord(pack({0: True, 1: bool(p.alarms), 4: p.valid, 5: s is not None and s.modulo_length > 0.0,
                                 6: s is not None and not s.tracking}))


DYNAMIC: dict[str, Callable[["LeadingAxisProxy"], Any]] = {
    "Position": lambda p: p._wrap(p.value[0]),
    "Velocity": lambda p: p.value[1],
    "Acceleration": lambda p: p.value[2],
    "StatusWord": _status,
    "ErrorWord": lambda p: ProxyErrorWord(pack(A.error_bits(p.alarms, A.PROXY))),
    "WarningWord": lambda p: ProxyWarningWord(pack({7: p.extrapolating_late})),
    "ErrorDetail.Number": lambda p: A.error_detail(p.alarms, A.PROXY)[0],
    "ErrorDetail.Reaction": lambda p: A.error_detail(p.alarms, A.PROXY)[1],
    "StatusExternalLeadingValue.ModuloLength": lambda p: p.newest.modulo_length if p.newest else 0.0,
    "StatusExternalLeadingValue.ModuloStartValue": lambda p: p.newest.modulo_start if p.newest else 0.0,
    "StatusExternalLeadingValue.AdjustmentTime": lambda p: p.adjustment_time,
}


class LeadingAxisProxy(AxisTagsMixin):
    """Leading axis proxy TO; ``source`` delivers the leading value telegrams (a transport)."""

    kind = "TO_LeadingAxisProxy"
    schema = PROXY_SCHEMA
    _dynamic = DYNAMIC
    _dynamic_types = {p: "LReal" for p in DYNAMIC}
    _dynamic_aliases: dict[str, str] = {}
    _status_groups = ("ErrorDetail", "StatusExternalLeadingValue")      # Parameter.*: configuration
    _read_param_tags = frozenset(DYNAMIC)
    provides_setpoints = True
    provides_actual_values = False

    def __init__(self, ctl: "Controller", name: str, cfg: Mapping[str, Any], source: LeadingValueSource | None):
        self.ctl = ctl
        self.name = name
        self.db_number = ctl._next_db_number()
        self.cfg = dict(cfg)
        self.load_cfg = dict(cfg)
        self.eff = self.cfg
        self.source = source
        self.alarms: list[Fault] = []
        self._time_window = TELEGRAM_TIME_WINDOW
        self._slot: int | None = None
        self._cascade_slot: int | None = None
        self._reset()
        # the telegrams are monitored from the start, with or without a follower (LeadingValueValid, alarm 900)
        self.lv_slot("setpoint")

    def _reset(self) -> None:
        self.samples: deque[LeadingValueSample] = deque()      # usable telegrams only, oldest first
        self.newest: LeadingValueSample | None = None          # the newest usable telegram
        self.value = (0.0, 0.0, 0.0)
        self.value_time = 0.0
        self.ahead = (0.0, 0.0, 0.0)       # the value for a virtual axis that provides it on (cascade)
        self.valid = False
        self.adjustment_time = 0.0
        self.sender_delay = 0.0            # the sender's local delay, from its newest telegram
        self.extrapolating_late = False
        self._last_valid_time: float | None = None
        # sender time of the newest invalid telegram after the newest usable one (None: there is none)
        self._bad_time: float | None = None

    def __repr__(self) -> str:
        return f"<LeadingAxisProxy {self.name} {'valid' if self.valid else 'invalid'}>"

    def connect(self, source: LeadingValueSource) -> None:
        """Take the leading value telegrams from ``source`` from now on."""
        self.source = source

    # --- each servo cycle ---------------------------------------------------------------------------------
    def _receive(self, t: float) -> None:
        """Take over the telegrams that arrived.  One that is flagged invalid or carries a value that is
        not a finite number within the LREAL ranges of the proxy's tags (§A.3.2, §A.3.5) is an invalid
        leading value: it starts the tolerance time and never reaches the followers (§8.1.2)."""
        try:
            arrived = self.source.fetch(t - self.sender_delay) if self.source is not None else ()
            arrived = list(arrived)
        except Exception:           # a broken transport is a communication error, not a controller STOP
            arrived = []
        newest = self.newest
        window = self._window()
        latest = t + window
        for s in arrived:
            when = _time_of(s)
            ok = usable(s)
            if when is not None and not (t - (s.delay if ok else self.sender_delay) - window <= when <= latest):
                # far from the time expected (a forged or broken telegram): taken as invalid, like one
                # without a time - it must neither become the newest (blocking the genuine telegrams
                # after it) nor keep the value invalid until its time
                ok, when = False, None
            if ok:
                if newest is None or when > newest.time:
                    self.samples.append(s)
                    newest = self.newest = s
                    self.sender_delay = s.delay
                    self._last_valid_time = when
                    if self._bad_time is not None and when > self._bad_time:
                        self._bad_time = None
                continue
            # an invalid telegram: newer than the last usable one, or of unknown time (taken as now);
            # one dated ahead of the local time counts from now
            if when is None:
                when = newest.time if newest is not None else -math.inf
            when = min(when, t)
            if newest is None or when >= newest.time:
                self._bad_time = when if self._bad_time is None else max(self._bad_time, when)

    @property
    def telegram_time_window(self) -> float:
        """Admissible distance [s] of a telegram's time from the expected one: a telegram dated after the
        local time plus this window, or before the local time minus the sender's delay minus this window,
        is invalid.  The window is at least ten tolerance times (``_window``); default 1 s."""
        return self._time_window

    @telegram_time_window.setter
    def telegram_time_window(self, seconds: float) -> None:
        if isinstance(seconds, bool) or not _finite(seconds) or not float(seconds) > 0.0:
            raise ValueError(f"{self.name}.telegram_time_window must be a number in (0, 1e12] s, got {seconds!r}")
        self._time_window = float(seconds)

    def _window(self) -> float:
        return max(self._time_window, 10.0 * self.eff["Parameter.ToleranceTimeExternalLeadingValueInvalid"])

    def update(self, t: float) -> tuple[float, float, float]:
        self._receive(t)
        # the value the sender's delayed followers use now (§8.1.3)
        delay = self.sender_delay
        wanted = t - delay
        keep = delay + 8 * self.ctl.servo_cycle
        while len(self.samples) > 2 and self.samples[1].time < wanted - keep:
            self.samples.popleft()
        newest = self.newest
        tolerance = self.eff["Parameter.ToleranceTimeExternalLeadingValueInvalid"]
        if newest is None:
            self.valid = False
            self.value_time = t
            if self._bad_time is not None and not self.alarms:
                self._invalid(t)            # only invalid telegrams so far
            return self.value
        self.adjustment_time = wanted - newest.time
        last_valid = self._last_valid_time
        assert last_valid is not None
        late = wanted - last_valid > tolerance + 1e-12
        # §A.3.6 StatusWord.X4: the value in use lies beyond the last valid telegram and an invalid one
        # came after it - the tolerance time runs from here (the followers go on, extrapolated, §8.1.2)
        invalid_now = self._bad_time is not None and wanted > last_valid
        self.extrapolating_late = self.adjustment_time > 0.0 and not late and not invalid_now
        if late:
            if self.valid or not self.alarms:
                self._invalid(t)
            self.valid = False
        else:
            self.valid = not invalid_now and not self.alarms
        value = self._at(wanted)
        if not _in_range(value):
            # extrapolated beyond any sensible value (a long tolerance time): hold the last value
            value = (self.value[0], 0.0, 0.0)
            self.valid = False
        self.value = value
        self.value_time = t
        if self._cascade_slot is not None:
            ahead = self._at(wanted + self.cascade_delay)
            self.ahead = ahead if _in_range(ahead) else (self.ahead[0], 0.0, 0.0)
        return self.value

    @property
    def cascade_delay(self) -> float:
        """Parameter.LocalLeadingValueDelayTime: the delay of the virtual following axis that provides
        this leading value on to a further controller (§8.1.3, §8.2.3.2)."""
        return float(self.eff["Parameter.LocalLeadingValueDelayTime"])

    def _update_ahead(self, t: float) -> tuple[float, float, float]:
        if self.value_time != t:                        # the main slot has not run yet in this cycle
            self.update(t)
        return self.ahead

    def _at(self, wanted: float) -> tuple[float, float, float]:
        s = self.samples
        newest = self.newest
        assert newest is not None
        if wanted >= newest.time:
            dt = wanted - newest.time
            p, v, a = newest.position, newest.velocity, newest.acceleration
            if v * a < 0.0 and dt > -v / a:
                # a braking leading value is extrapolated to its standstill, not into a reversal
                return p - 0.5 * v * v / a, 0.0, 0.0
            return p + dt * (v + 0.5 * dt * a), v + dt * a, a
        prev = None
        for sample in reversed(s):
            if sample.time <= wanted:
                prev = sample
                break
            nxt = sample
        if prev is None:
            first = s[0]
            return first.position, first.velocity, first.acceleration
        h = nxt.time - prev.time
        w = (wanted - prev.time) / h
        w2, w3 = w * w, w * w * w
        p = ((2 * w3 - 3 * w2 + 1) * prev.position + (w3 - 2 * w2 + w) * h * prev.velocity
             + (-2 * w3 + 3 * w2) * nxt.position + (w3 - w2) * h * nxt.velocity)
        return p, prev.velocity + w * (nxt.velocity - prev.velocity), prev.acceleration + w * (
            nxt.acceleration - prev.acceleration)

    def _invalid(self, t: float) -> None:
        fault = F.alarm(F.LV_INVALID, "", Reaction.NONE, f"no valid leading value at {self.name}")
        if fault not in self.alarms:
            self.alarms.append(fault)
        # the followers coupled to an invalid leading value are stopped - once this servo cycle's
        # setpoints are complete, so that they brake from where they are
        self.ctl.sync.stop_followers_of(
            self, F.alarm(F.LV_INVALID, self.name, Reaction.STOP, f"leading value of {self.name} invalid"))

    # --- leading value source ------------------------------------------------------------------------------
    def lv_value(self, mode: str, t: float) -> tuple[float, float, float]:
        if mode == "cascade" and self.newest is not None:
            self.lv_slot(mode)
            return self._extrapolated(self._at(t - self.sender_delay + self.cascade_delay), t, t)
        return self._extrapolated(self.value, self.value_time, t)

    @staticmethod
    def _extrapolated(value: tuple[float, float, float], at: float, t: float) -> tuple[float, float, float]:
        p, v, a = value
        dt = t - at
        if dt > 0.0:
            p, v = p + dt * (v + 0.5 * dt * a), v + dt * a
        return p, v, a

    def lv_slot(self, mode: str) -> int:
        if self._slot is None:
            self._slot = self.ctl.sync.register_ext(self.update)
        if mode == "cascade":
            if self._cascade_slot is None:
                self._cascade_slot = self.ctl.sync.register_ext(self._update_ahead)
            return self._cascade_slot
        return self._slot

    def leading_value_invalid(self, mode: str) -> str | None:
        """Why a new coupling cannot use this proxy now (None: it can): an alarm of the proxy (900)
        means its leading value is invalid until acknowledged (§8.2.3).  Before the first telegram there is
        no alarm yet: the coupling starts and the tolerance time decides."""
        return f"leading value of {self.name} invalid" if self.alarms else None

    def lv_position_controlled(self) -> bool:
        """A follower with setpoint coupling waits until the proxy has a valid leading value."""
        if self._slot is None:
            self.lv_slot("setpoint")
            self.update(self.ctl.time)
        return self.valid

    def lv_modulo(self) -> tuple[float, float] | None:
        s = self.newest
        return (s.modulo_start, s.modulo_length) if s is not None and s.modulo_length > 0.0 else None

    def _wrap(self, value: float) -> float:
        m = self.lv_modulo()
        if m is None:
            return value
        start, length = m
        r = math.fmod(value - start, length)
        return start + (r + length if r < 0 else r)

    # --- MC_Reset -----------------------------------------------------------------------------------------
    def acknowledge(self) -> Fault | None:
        """Acknowledge alarm 900 once valid leading values arrive again."""
        if self.newest is not None and self._bad_time is None and self._last_valid_time is not None and \
                self.ctl.time - self.sender_delay - self._last_valid_time <= \
                self.eff["Parameter.ToleranceTimeExternalLeadingValueInvalid"] + 1e-12:
            self.alarms.clear()
            self.valid = True
            return None
        return self.alarms[0] if self.alarms else None

    def restart(self) -> Fault | None:
        self.reinitialize("restart")
        return None

    def reinitialize(self, reason: str) -> None:
        self.cfg = dict(self.load_cfg)
        self.eff = self.cfg
        self.alarms.clear()
        self._reset()

    def write_tag(self, path: str, value: Any, *, via_write_param: bool = False) -> None:
        param = self.schema.params.get(path)
        if param is None:
            raise TagAccessError(f"{self.name}.{path} is not a writable tag of the leading axis proxy")
        reason, norm = param.check(value)
        if reason is not None:
            raise ValueError(f"{self.name}.{path} = {value!r}: allowed {param.allowed()}")
        self.cfg[path] = norm


#: value range of the proxy's LREAL tags (§A.3.5: -1.0E12 .. 1.0E12)
LIMIT = 1.0e12


def _finite(x: Any, limit: float = LIMIT) -> bool:
    """A real number (not bool) within +/- ``limit``."""
    if isinstance(x, bool) or not isinstance(x, numbers.Real):
        return False
    try:
        return abs(float(x)) <= limit
    except (TypeError, ValueError, OverflowError):
        return False


def _time_of(s: Any) -> float | None:
    t = getattr(s, "time", None)
    return float(t) if _finite(t) else None


def usable(s: Any) -> bool:
    """Can this telegram's value be used?  Flagged valid, a finite time and values within range."""
    try:
        return getattr(s, "valid", False) in (True, 1) and _time_of(s) is not None \
            and all(_finite(getattr(s, f, None)) for f in ("position", "velocity", "acceleration",
                                                          "modulo_start")) \
            and _finite(s.modulo_length) and s.modulo_length >= 0.0 \
            and _finite(s.delay) and s.delay >= 0.0
    except Exception:
        return False


def _in_range(value: tuple[float, float, float]) -> bool:
    return all(_finite(v) for v in value)


__all__ = ["LeadingAxisProxy", "PROXY_SCHEMA", "usable"]
