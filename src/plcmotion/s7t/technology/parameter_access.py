"""Technology parameters of an axis by number: what MC_ReadSysParameter reads and MC_WriteParameter writes
(S7-Technology V4.1 §6.7.4, §6.7.5, §5.16, §9.4).

A parameter number of §9.4 names either a configuration tag of the axis (its expert-list name, data set /
encoder ``_x`` replaced by the Index; ``schema``) or a system variable the technology computes (actual
values, states).  A parameter the axis's configuration does not hold (another data set, a function this
axis was not configured with) is "not configured" and gives 16#8080, as the manual requires the parameter
to be configured in S7T Config.

Writes (§5.16, §6.7.5): the value is checked against the parameter list (range, ENUM code, access) and
against the other parameters of the axis (the schema's rules, e.g. a leadscrew pitch that makes the
maximum velocity unreachable: 16#8043).  An "Immediately" parameter takes effect in the next IPO cycle -
a moving axis plans again with it; a "Restart" parameter waits for MC_Reset Restart = TRUE (warning
16#0020 and ``Statusword.RequestRestart`` while a written value differs from the one in effect).  Written
values survive restarts and CPU STOP -> RUN and are lost at POWER OFF -> ON (the configured values come
back).  Parameter 4001 = COLLECT_CHANGED_CONFIG_DATA (82) holds "Immediately" writes back until 4001 =
ACTIVATE_CHANGED_CONFIG_DATA (81) activates them together.

Reading a written "Restart" parameter gives the value in effect until the restart (the axis still works
with it); a written "Immediately" parameter reads back at once.
"""
from __future__ import annotations

import math
import re
import weakref
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from ...kernel import axis_status as S
from ...kernel.jobs import JobKind
from ...kernel.tag_views import TagAccessError
from . import activation, coordinates
from . import parameter_words as W
from . import datasets as D
from .encoders import ABSOLUTE, CYCLIC_ABSOLUTE, encoder_type
from .parameters import (ILLEGAL_PARAMETER, INVALID_NUMBER, READ_ONLY, RESTART_REQUIRED, Parameter, parameter)
from .to_kinds import AxisType, TOKind

if TYPE_CHECKING:  # pragma: no cover
    from .axes import AxisT

NOT_AVAILABLE = 0x8086          # parameter not available now (TO restarting)

#: MC_ReadSysParameter outputs (§6.7.4)
OUT_REAL, OUT_DINT, OUT_DWORD1, OUT_DWORD2, OUT_BOOL = "Value", "ValueDInt", "ValueDword1", "ValueDword2", "ValueBool"

_AXIS_TYPE = {0: AxisType.SPEED, 1: AxisType.POSITIONING, 2: AxisType.SYNCHRONIZATION}
_COLLECT, _ACTIVATE = 82, 81                        # EnumToActivationModeSetConfigData
_LIMIT_EXCEEDED, _LIMIT_OK = 101, 102               # EnumLimitExceededOk
_SENSOR_NOT_VALID, _SENSOR_VALID = 204, 206         # EnumSensorState
_INACTIVE, _ACTIVE = 0, 1                           # EnumActiveInactive
_POSITIONING = (JobKind.ABSOLUTE, JobKind.RELATIVE)


@dataclass
class _AxisWrites:
    """What MC_WriteParameter changed on one axis: the configured values to restore at POWER OFF -> ON,
    the collect mode of 4001 and the "Immediately" writes it holds back."""
    configured: dict[str, Any] = field(default_factory=dict)
    collecting: bool = False
    held: dict[str, Any] = field(default_factory=dict)


_WRITES: "weakref.WeakKeyDictionary[Any, _AxisWrites]" = weakref.WeakKeyDictionary()


_HOOKED: "weakref.WeakSet[Any]" = weakref.WeakSet()


def _writes(axis: "AxisT") -> _AxisWrites:
    w = _WRITES.get(axis)
    if w is None:
        w = _WRITES[axis] = _AxisWrites()
        device = getattr(axis.ctl, "extension", None)
        if device is not None and device not in _HOOKED:
            _HOOKED.add(device)
            device.on_reinitialize.append(lambda reason, ctl=weakref.ref(axis.ctl): _reinitialized(ctl(), reason))
    return w


def _reinitialized(ctl: Any, reason: str) -> None:
    if ctl is not None and reason == "power":
        for axis in list(_WRITES):
            if axis.ctl is ctl:
                power_on(axis)


# --- system variables (read-only parameters the technology computes) ------------------------------------
def _target_distance(ax: "AxisT") -> float:
    job = ax.job
    if job is None or not job.busy or job.kind not in _POSITIONING:
        return 0.0
    return float(job.target - ax._state_now()[0])


def _sw_state(ax: "AxisT", side: int) -> int:
    sl = ax.config.software_limits
    if not ax.sw_limits_effective():
        return _LIMIT_OK
    p = S.position(ax)
    beyond = p <= sl.minimum if side < 0 else p >= sl.maximum
    return _LIMIT_EXCEEDED if beyond else _LIMIT_OK


def _hw_state(ax: "AxisT", side: str) -> int:
    return _LIMIT_EXCEEDED if ax.hw_approached.get(side) else _LIMIT_OK


def _bero(ax: "AxisT") -> int:
    """homingcommand.berostate: the reference cam of active homing is actuated (its input at its level)."""
    cam = ax.config.homing.active
    return _ACTIVE if cam.input and ax.ctl.inputs[cam.input] == cam.active_high else _INACTIVE


def _superimposed(ax: "AxisT") -> tuple[float, float]:
    """The superimposing coordinate system (technology.coordinates); a speed axis has none."""
    if getattr(ax, "superimposed", None) is None or not ax.positioning:
        return 0.0, 0.0
    return coordinates.superimposed_state(ax)


_SYSTEM: dict[int, Any] = {
    1: lambda ax: float(S.position(ax)),
    10: lambda ax: 0.0 if ax.without_encoder else float(ax.ctl.bank.act_v[ax.index]),
    11: lambda ax: float(ax.ctl.bank.sp_v[ax.index]),
    2000: lambda ax: ax.eff["TypeOfAxis.NumberOfDataSets.numberOfDataSets"],
    3000: lambda ax: 0 if ax.virtual else ax.encoders.count,     # a virtual axis has no encoder
    4020: lambda ax: D.active(ax.eff),
    4030: lambda ax: _superimposed(ax)[0],
    4031: lambda ax: _superimposed(ax)[1],
    4040: lambda ax: float(S.position(ax)) - _superimposed(ax)[0],
    4041: lambda ax: float(ax.ctl.bank.sp_v[ax.index]) - _superimposed(ax)[1],
    4050: lambda ax, x=1: _SENSOR_VALID if ax.encoders.is_valid(x) else _SENSOR_NOT_VALID,
    4162: _target_distance,
    4173: lambda ax: float(ax.homing.reference_mark),     # the position the axis was homed to last
    4174: _bero,
    4400: lambda ax: _sw_state(ax, -1),
    4401: lambda ax: _sw_state(ax, +1),
    4410: lambda ax: _hw_state(ax, "min"),
    4411: lambda ax: _hw_state(ax, "max"),
    4412: lambda ax: ax.encoders.active,
    5002: lambda ax: ax.drive.output_percent,                       # hydraulic axes only (list: "Hydraulic.")
    5014: lambda ax: _ACTIVE if S.drive_in_operation(ax) else _INACTIVE,
    5020: lambda ax: 0.0 if ax.without_encoder else float(ax.ctl.bank.act_v[ax.index]),
}
#: system variables indexed 1..8 of which the model has only index 1
_PER_ENCODER = frozenset({4020, 4030, 4031, 4040, 4041, 5020})
#: sensordata_x.state: Index = one of the axis's encoders (technology.encoders)
_SENSOR_STATE = 4050
#: drive words and absolute encoder adjustment (technology.parameter_words)
_ADJUSTMENT, _ADJUSTED, _CONTROL_WORDS, _STATUS_WORDS = 4010, 4011, 4500, 4501
_WORDS = {_CONTROL_WORDS: W.control_words, _STATUS_WORDS: W.status_words}


def _tag(p: Parameter, index: int) -> str:
    name = p.expert_name
    for marker in ("DataSet_x", "Encoder_x", "Encoder_X"):
        name = name.replace(marker, marker[:-1] + str(index))
    return name


@dataclass(frozen=True)
class Access:
    """A parameter resolved for one axis: the list entry, the tag (None: a system variable) and the
    MC_ReadSysParameter output that carries its value."""
    parameter: Parameter
    tag: str | None
    output: str


def output_of(p: Parameter) -> str:
    if p.data_type == "REAL":
        return OUT_REAL
    if p.data_type == "2xDWORD":
        return OUT_DWORD2
    if p.data_type in ("DWORD", "WORD"):
        return OUT_DWORD1
    return OUT_DINT


def input_of(p: Parameter) -> str:
    """The MC_WriteParameter input(s) of ``p``: as :func:`output_of`, but 4500 is written as value + mask in
    ValueDword1 + ValueDword2 (§6.7.5 example "Drive control word")."""
    return OUT_DWORD2 if p.value_input == "ValueDword1+ValueDword2" else output_of(p)


def resolve(axis: "AxisT", number: int, index: int) -> Access | int:
    """The parameter ``number`` (data set / encoder ``index``) of ``axis``, or the ErrorID 16#8080 when the
    axis has no such parameter, index, or configured value."""
    try:
        p = parameter(TOKind.AXIS, number)
    except (KeyError, TypeError):
        return INVALID_NUMBER
    if _AXIS_TYPE[axis.technology] not in p.axis_types or p.hydraulic and not axis.hydraulic:
        return INVALID_NUMBER
    if index not in p.indices() and p.index is not None:
        return INVALID_NUMBER
    i = index if p.index is not None else 1
    if number in _SYSTEM:
        if number in _PER_ENCODER and i != 1 or number == _SENSOR_STATE and i > axis.encoders.count:
            return INVALID_NUMBER
        return Access(p, None, output_of(p))
    if number == 4001:
        return Access(p, None, OUT_DINT)
    if number in _WORDS:
        return Access(p, None, OUT_DWORD1)
    if number in (_ADJUSTMENT, _ADJUSTED):
        return Access(p, None, output_of(p)) if W.adjustment_available(axis, i) else INVALID_NUMBER
    tag = _tag(p, i)
    if tag not in axis.schema.params:
        return INVALID_NUMBER                 # not configured on this axis (S7T Config)
    if ".Encoder_" in tag and i > axis.encoders.count:
        return INVALID_NUMBER                 # an encoder the axis does not have (§4.5.1)
    if ".DataSet_" in tag and i > axis.parameters.effective.get("TypeOfAxis.NumberOfDataSets.numberOfDataSets", 1):
        return INVALID_NUMBER                 # a data set the axis does not have (§3.1.10)
    return Access(p, tag, output_of(p))


_DATA_SET = re.compile(r"\.DataSet_(\d+)\.")
_ENCODER = re.compile(r"\.Encoder_(\d+)\.")
_INCREMENTAL_ONLY = (".IncHomingEncoder.", ".IncBackLash.")


def unavailable(axis: "AxisT", tag: str | None) -> bool:
    """8086 of MC_ReadSysParameter / MC_WriteParameter (§6.7.4, §6.7.5): a parameter of a data set that is
    not in force, an incremental-encoder parameter of an absolute encoder, any parameter of an encoder of the
    type "absolute encoder cyclic absolute"."""
    if tag is None:
        return False
    m = _DATA_SET.search(tag)
    if m and int(m.group(1)) != D.active(axis.eff):
        return True
    m = _ENCODER.search(tag)
    if m and not axis.virtual:
        kind = axis.eff.get(encoder_type(int(m.group(1))))
        return kind == CYCLIC_ABSOLUTE or kind == ABSOLUTE and any(s in tag for s in _INCREMENTAL_ONLY)
    return False


def read(axis: "AxisT", number: int, index: int) -> tuple[int, str, Any]:
    """(ErrorID or 0, output, value) of MC_ReadSysParameter."""
    acc = resolve(axis, number, index)
    if isinstance(acc, int):
        return acc, OUT_REAL, 0.0
    if axis.restarting or unavailable(axis, acc.tag):
        return NOT_AVAILABLE, acc.output, 0
    p = acc.parameter
    if acc.tag is None:
        if p.number == 4001:
            return 0, OUT_DINT, _COLLECT if _writes(axis).collecting else _ACTIVATE
        if p.number in _WORDS:
            return 0, OUT_DWORD1, _WORDS[p.number](axis)
        if p.number == _ADJUSTMENT:
            return 0, acc.output, W.read_adjustment(axis, index)
        if p.number == _ADJUSTED:
            return 0, acc.output, W.adjusted(axis, index)
        value = _SYSTEM[p.number](axis, index) if p.number == _SENSOR_STATE else _SYSTEM[p.number](axis)
    else:
        store = axis.parameters
        value = store.effective.get(acc.tag) if p.needs_restart else store.values.get(acc.tag)
        held = _writes(axis).held
        if acc.tag in held:
            value = held[acc.tag]
        if value is None and (".DataSet_" in acc.tag or ".Encoder_" in acc.tag):
            # a data set / encoder without its own value of this parameter uses the first one's
            # (s7t/technology/datasets.py, stored_params.py)
            first = _tag(p, 1)
            value = store.effective.get(first) if p.needs_restart else store.values.get(first)
        if value is None:
            return INVALID_NUMBER, acc.output, 0.0    # an optional tag without a value: not configured
    if acc.output == OUT_REAL:
        value = float(value)
        if not math.isfinite(value):
            value = 0.0
    else:
        value = int(value)
    return 0, acc.output, value


def write(axis: "AxisT", number: int, index: int, value: Any) -> int:
    """MC_WriteParameter: 0 (done), 16#0020 (done, restart needed) or the ErrorID of a refused write.
    ``value`` is what the parameter's input holds (REAL: float; DINT/ENUM: int; DWORD: int)."""
    acc = resolve(axis, number, index)
    if isinstance(acc, int):
        return acc
    p = acc.parameter
    if axis.restarting or activation.deactivated(axis) or unavailable(axis, acc.tag):
        return NOT_AVAILABLE                  # restarting, or deactivated: not processed (§6.7.2)
    code = p.check(value, index if p.index is not None else None, axis.ctl.servo_cycle)
    if code is not None:
        return code
    if p.number == 4001:
        return _activation_mode(axis, int(value))
    if p.number == _CONTROL_WORDS:
        return W.write_control_words(axis, value)
    if p.number == _ADJUSTMENT:
        return W.write_adjustment(axis, index, value)
    if acc.tag is None:
        return READ_ONLY
    store, tag = axis.parameters, acc.tag
    param = store.schema.params[tag]
    norm = float(value) if p.data_type == "REAL" else int(value)
    reason, norm = param.check(norm)
    if reason is not None:
        return ILLEGAL_PARAMETER
    w = _writes(axis)
    # checked together with the other values as they will be: written ones, also those awaiting a restart
    pending = {t: store.start[t] for t in w.configured}
    candidate = {**store.values, **pending, **w.held, tag: norm}
    if store.validate(candidate, [tag]) is not None:
        return ILLEGAL_PARAMETER
    if p.needs_restart:
        _remember(w, store, tag, norm)
        axis.restart_requested = _restart_pending(axis)
        return RESTART_REQUIRED if norm != store.effective[tag] else 0
    if w.collecting:
        _remember(w, store, tag, norm)
        w.held[tag] = norm
        return 0
    return _now(axis, tag, norm)


def _remember(w: _AxisWrites, store: Any, tag: str, value: Any) -> None:
    w.configured.setdefault(tag, store.start[tag])
    store.start[tag] = value                  # a restart keeps the written value (§5.16)


def _now(axis: "AxisT", tag: str, value: Any) -> int:
    """An "Immediately" parameter: in effect from the next IPO cycle (the store's servo moment).  Where the
    schema keeps the tag as a start value (its effect list is empty) the manual's "Immediately" wins: the
    configuration takes it at once."""
    store = axis.parameters
    if store.schema.params[tag].effective:
        try:
            store.write(tag, value, via_write_param=True)
        except (TagAccessError, TypeError):
            return READ_ONLY                  # a tag the schema keeps from the user program
    else:
        store.values[tag] = value
        store.make_effective({**store.effective, tag: value})
        axis._apply_bank_config()
    _remember(_writes(axis), store, tag, value)
    return 0


def _activation_mode(axis: "AxisT", mode: int) -> int:
    w = _writes(axis)
    if mode == _COLLECT:
        w.collecting = True
        return 0
    w.collecting = False
    held, w.held = w.held, {}
    for tag, value in held.items():
        _now(axis, tag, value)
    return 0


def _restart_pending(axis: "AxisT") -> bool:
    store = axis.parameters
    return any(store.start[t] != store.effective.get(t) for t in _writes(axis).configured
               if t in store.start and not store.schema.params[t].effective)


def reinitialize_keeping_pending(axis: "AxisT") -> None:
    """Initialize the axis as a restart does, but keep written "Restart" values waiting for the real
    restart (MC_ActivateTO reactivation, §6.7.2)."""
    store = axis.parameters
    w = _WRITES.get(axis)
    pending = {} if w is None else {t: store.effective[t] for t in w.configured
                                    if not store.schema.params[t].effective and store.start[t] != store.effective[t]}
    axis.reinitialize("restart")
    if pending:
        store.make_effective({**store.effective, **pending})
        axis._apply_bank_config()
        axis.restart_requested = True


def power_on(axis: "AxisT") -> None:
    """POWER OFF -> ON: the configured values are in effect again (§5.16); the axis is disabled."""
    w = _WRITES.pop(axis, None)
    if w is None or not w.configured:
        return
    store = axis.parameters
    store.start.update(w.configured)
    store.restart()
    axis.restart_requested = False
    axis._apply_bank_config()


__all__ = ["Access", "resolve", "read", "write", "power_on", "reinitialize_keeping_pending", "output_of", "input_of",
           "NOT_AVAILABLE",
           "OUT_REAL", "OUT_DINT", "OUT_DWORD1", "OUT_DWORD2", "OUT_BOOL"]
