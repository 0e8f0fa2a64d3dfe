"""Tags of the positioning axis as attributes and as string paths (S7-1200 V6 §12.9).

``axis.StatusBits.Enable``, ``axis.DynamicDefaults.Jerk`` and ``axis.Sensor[1].ActiveHoming.Mode`` read the
same values as ``axis.tag("StatusBits.Enable")`` etc.  Status tags are computed when read (nothing is copied
per cycle); configuration tags are the values in the technology data block, which the user program may
assign where the manual grants write access (RW).
"""
from __future__ import annotations

import difflib
from typing import TYPE_CHECKING, Any, Callable

from . import faults as F
from . import parameters as P
from .jobs import JobKind

if TYPE_CHECKING:  # pragma: no cover
    from .axis import PositioningAxis



def _b(ax: "PositioningAxis"):
    return ax.ctl.bank


def _job_kind(ax: "PositioningAxis") -> JobKind | None:
    job = ax.job
    return job.kind if job is not None and job.busy else None


def communication_fault(ax: "PositioningAxis") -> bool:
    """A drive or an encoder on the bus failed or lost its sign of life (S7-1200 V6 §12.8 16#800C/16#003E,
    16#003F, 16#800A/16#0040, 16#0041: ErrorBits.CommunicationFault, S7-1500 ErrorWord.X7)."""
    return any(a.kind in (F.DRIVE_ALARM, F.ENCODER) and a.detail in ("station", "sign_of_life") for a in ax.alarms)


def _alarm_kinds(ax: "PositioningAxis") -> set[str]:
    return {a.kind for a in ax.alarms}


def _sw_active(ax: "PositioningAxis", side: str) -> bool:
    if not ax.sw_limits_effective():
        return False
    p = float(_b(ax).sp_p[ax.index])
    if side == "min":
        return p <= ax.eff["PositionLimits_SW.MinPosition"]
    return p >= ax.eff["PositionLimits_SW.MaxPosition"]


def _accel_state(ax: "PositioningAxis") -> int:
    """+1 accelerating, -1 decelerating, 0 constant velocity or standstill (setpoint)."""
    b, i = _b(ax), ax.index
    v, a = float(b.sp_v[i]), float(b.sp_a[i])
    if abs(a) <= 1e-9 * max(1.0, ax.eff["DynamicDefaults.Acceleration"]):
        return 0
    return 1 if a * v > 0 or v == 0.0 else -1


def _constant_velocity(ax: "PositioningAxis") -> bool:
    b, i = _b(ax), ax.index
    if _accel_state(ax) != 0:
        return False
    if float(b.sp_v[i]) != 0.0:
        return True
    # §11.1.7: MC_MoveVelocity with Velocity 0 reports ConstantVelocity at standstill
    return ax.holding_zero_velocity


def _standstill(ax: "PositioningAxis") -> bool:
    b, i = _b(ax), ax.index
    if ax.servo:
        return bool(b.standstill[i])
    return float(b.sp_v[i]) == 0.0


def _positioning_job(ax: "PositioningAxis"):
    """The running positioning: MC_MoveAbsolute/-Relative or a positioning step of a command table (§10.2)."""
    job = ax.job
    if job is None or not job.busy:
        return None
    if job.kind in (JobKind.ABSOLUTE, JobKind.RELATIVE):
        return job
    if job.kind == JobKind.TABLE and job.extra.get("phase") == "position":
        return job
    return None


def _distance(ax: "PositioningAxis") -> float:
    job = _positioning_job(ax)
    return 0.0 if job is None else abs(job.target - float(_b(ax).sp_p[ax.index]))


def _target(ax: "PositioningAxis") -> float:
    job = _positioning_job(ax)
    return 0.0 if job is None else ax._wrap(job.target)


#: status tags: path -> getter
DYNAMIC: dict[str, Callable[["PositioningAxis"], Any]] = {
    "Position": lambda ax: ax._wrap(float(_b(ax).sp_p[ax.index])),
    "Velocity": lambda ax: float(_b(ax).sp_v[ax.index]),
    "Acceleration": lambda ax: float(_b(ax).sp_a[ax.index]),
    "ActualPosition": lambda ax: ax._wrap(float(_b(ax).act_p[ax.index])),
    "ActualVelocity": lambda ax: float(_b(ax).act_v[ax.index]),
    "StatusPositioning.Distance": _distance,
    "StatusPositioning.TargetPosition": _target,
    "StatusPositioning.FollowingError": lambda ax: float(_b(ax).fe[ax.index]) if ax.servo else 0.0,
    "StatusDrive.InOperation": lambda ax: ax.state in ("enabled", "disabling") and ax.drive.ready(ax.now),
    "StatusDrive.CommunicationOK": lambda ax: ax.communication_ok("drive"),
    "StatusDrive.AdaptionState": lambda ax: 3,
    "StatusSensor.State": lambda ax: 0 if ax.pto else (2 if ax.sensor_valid else 0),
    "StatusSensor.CommunicationOK": lambda ax: ax.communication_ok("encoder"),
    "StatusSensor.AbsEncoderOffset": lambda ax: ax.abs_offset,
    "StatusSensor.AdaptionState": lambda ax: 3,
    "StatusBits.Activated": lambda ax: ax.activated,
    "StatusBits.Enable": lambda ax: ax.state in ("enabled", "disabling"),
    "StatusBits.HomingDone": lambda ax: ax.homed,
    "StatusBits.Done": lambda ax: _job_kind(ax) is None,
    "StatusBits.Error": lambda ax: bool(ax.alarms),
    "StatusBits.StandStill": _standstill,
    "StatusBits.PositioningCommand": lambda ax: _job_kind(ax) in (JobKind.ABSOLUTE, JobKind.RELATIVE),
    # §11.1.7: after MC_MoveVelocity(0) reached standstill both bits stay until the next motion command
    "StatusBits.VelocityCommand": lambda ax: _job_kind(ax) in (JobKind.VELOCITY, JobKind.JOG)
    or ax.holding_zero_velocity,
    "StatusBits.HomingCommand": lambda ax: _job_kind(ax) in (JobKind.HOME_ACTIVE,) or (
        ax.passive_home is not None and ax.passive_home.busy),
    "StatusBits.CommandTableActive": lambda ax: _job_kind(ax) == JobKind.TABLE,
    "StatusBits.ConstantVelocity": _constant_velocity,
    "StatusBits.Accelerating": lambda ax: _accel_state(ax) > 0,
    "StatusBits.Decelerating": lambda ax: _accel_state(ax) < 0,
    "StatusBits.ControlPanelActive": lambda ax: False,
    "StatusBits.DriveReady": lambda ax: ax.state in ("enabled", "disabling") and ax.drive.ready(ax.now),
    "StatusBits.RestartRequired": lambda ax: False,
    "StatusBits.SWLimitMinActive": lambda ax: _sw_active(ax, "min"),
    "StatusBits.SWLimitMaxActive": lambda ax: _sw_active(ax, "max"),
    "StatusBits.HWLimitMinActive": lambda ax: ax.hw_approached["min"],
    "StatusBits.HWLimitMaxActive": lambda ax: ax.hw_approached["max"],
    "StatusBits.AxisSimulation": lambda ax: ax.sim,
    "StatusBits.NonPositionControlled": lambda ax: ax.servo and ax.state in ("enabled", "disabling")
    and not ax.position_controlled,
    "ErrorBits.SystemFault": lambda ax: F.INTERNAL in _alarm_kinds(ax),
    "ErrorBits.ConfigFault": lambda ax: bool(_alarm_kinds(ax) & {F.CONFIG, F.HOMING_APPROACH_ZERO,
                                                                 F.HOMING_REFERENCING_ZERO}),
    "ErrorBits.DriveFault": lambda ax: bool(_alarm_kinds(ax) & {F.DRIVE_NOT_READY, F.DRIVE_ALARM}),
    "ErrorBits.SWLimit": lambda ax: bool(_alarm_kinds(ax) & {F.SW_LIMIT_MIN, F.SW_LIMIT_MAX, F.SW_LIMIT_ORDER}),
    "ErrorBits.HWLimit": lambda ax: bool(_alarm_kinds(ax) & {F.HW_LIMIT_MIN, F.HW_LIMIT_MAX, F.HW_LIMIT_FREE}),
    "ErrorBits.DirectionFault": lambda ax: F.DIRECTION in _alarm_kinds(ax),
    "ErrorBits.HWUsed": lambda ax: F.HW_USED in _alarm_kinds(ax) or ax.pto_used_by_other(),
    "ErrorBits.SensorFault": lambda ax: F.ENCODER in _alarm_kinds(ax),
    "ErrorBits.CommunicationFault": lambda ax: communication_fault(ax),
    "ErrorBits.FollowingErrorFault": lambda ax: F.FOLLOWING_ERROR in _alarm_kinds(ax),
    "ErrorBits.PositioningFault": lambda ax: F.POSITIONING in _alarm_kinds(ax),
}
#: data types of the status tags (§12.9.1 - §12.9.4, §12.9.20 - §12.9.24)
DYNAMIC_TYPES: dict[str, str] = {path: ("Bool" if path.startswith(("StatusBits.", "ErrorBits."))
                                        or path in ("StatusDrive.InOperation", "StatusDrive.CommunicationOK",
                                                    "StatusSensor.CommunicationOK")
                                        else "DInt" if path.endswith(("State", "AdaptionState")) else "Real")
                                 for path in DYNAMIC}
#: status tags that MC_ReadParam may read ("RP" in §12.9); ErrorBits.HWLimit is RCCP only (§12.9.24)
READ_PARAM_TAGS = frozenset(p for p in DYNAMIC if p != "ErrorBits.HWLimit" and p != "Acceleration")

_DYNAMIC_ALIASES = {
    "StatusSensor[1].AdaptionState": "StatusSensor.AdaptionState",
    "ErrorBits.FollowingError": "ErrorBits.FollowingErrorFault",      # V7 table spelling
}

#: S7-1200 V7 (technology_version 7): the encoder status is the structure StatusSensor[1] (V7 §12.9.20; the
#: V6 names stay, they are V7's Openness names) and ErrorBits has AdaptionError (V7 §12.9.22).  The
#: simulated drives take no parameters from the drive (AdaptionState 3), so no transfer can fail.
DYNAMIC_V7: dict[str, Callable[["PositioningAxis"], Any]] = {
    **DYNAMIC,
    **{f"StatusSensor[1].{name}": DYNAMIC[f"StatusSensor.{name}"]
       for name in ("State", "CommunicationOK", "AbsEncoderOffset", "AdaptionState")},
    "ErrorBits.AdaptionError": lambda ax: False,
}
DYNAMIC_TYPES_V7: dict[str, str] = {**DYNAMIC_TYPES, **{
    path: DYNAMIC_TYPES[path.replace("[1]", "")] for path in DYNAMIC_V7 if path.startswith("StatusSensor[1].")},
    "ErrorBits.AdaptionError": "Bool"}
READ_PARAM_TAGS_V7 = frozenset(p for p in DYNAMIC_V7 if p != "ErrorBits.HWLimit" and p != "Acceleration")
_DYNAMIC_ALIASES_V7 = {"ErrorBits.FollowingError": "ErrorBits.FollowingErrorFault"}
_STATUS_GROUPS = ("StatusBits", "ErrorBits", "StatusPositioning", "StatusDrive", "StatusSensor")


class TagRef:
    """A reference to one tag of an axis, what a VARIANT pointer to ``<axis>.<tag>`` is in a PLC program
    (used by MC_ReadParam / MC_WriteParam).  Create it with ``axis.ref("StatusBits.Enable")``."""

    __slots__ = ("axis", "path", "data_type", "status")

    def __init__(self, axis: "PositioningAxis", path: str, data_type: str, status: bool):
        self.axis, self.path, self.data_type, self.status = axis, path, data_type, status

    def read(self) -> Any:
        return self.axis.tag(self.path)

    @property
    def readable_by_read_param(self) -> bool:
        return self.status and self.path in self.axis._read_param_tags

    @property
    def access(self) -> str:
        """Access right of §12.9: 'RP' status tags, 'RW', 'WP', 'R' configuration tags."""
        if self.status:
            return "RP" if self.path in self.axis._read_param_tags else "RCCP"
        access_of = getattr(self.axis, "tag_access", None)
        return access_of(self.path) if access_of is not None else self.axis.schema.params[self.path].access

    def __repr__(self) -> str:
        return f"<TagRef {self.axis.name}.{self.path} : {self.data_type}>"


class _StatusView:
    """Read-only view of a status structure (StatusBits, ErrorBits, ...)."""

    __slots__ = ("_axis", "_prefix")

    def __init__(self, axis: "PositioningAxis", prefix: str):
        object.__setattr__(self, "_axis", axis)
        object.__setattr__(self, "_prefix", prefix)

    def __getattr__(self, name: str) -> Any:
        path = f"{self._prefix}.{name}"
        getter = self._axis._dynamic.get(path)
        if getter is None:
            if any(k.startswith(path + ".") for k in self._axis._dynamic):
                return _StatusView(self._axis, path)          # nested structure
            raise AttributeError(_unknown(self._axis, path))
        return getter(self._axis)

    def __getitem__(self, key: int) -> "_StatusView":
        path = f"{self._prefix}[{key}]"
        if not any(k.startswith(path + ".") for k in self._axis._dynamic):
            raise IndexError(f"{self._axis.name}.{path} does not exist")
        return _StatusView(self._axis, path)

    def __setattr__(self, name: str, value: Any) -> None:
        from .config import TagAccessError

        raise TagAccessError(f"{self._axis.name}.{self._prefix}.{name} is a status tag and cannot be written")

    def __dir__(self) -> list[str]:
        n = len(self._prefix) + 1
        return [k[n:] for k in self._axis._dynamic if k.startswith(self._prefix + ".")]

    def as_dict(self) -> dict[str, Any]:
        return {name: getattr(self, name) for name in self.__dir__()}

    def __repr__(self) -> str:
        return f"{self._axis.name}.{self._prefix}({self.as_dict()})"


class _ConfigView:
    """View of a configuration structure; assignment goes through the access rules."""

    __slots__ = ("_axis", "_prefix", "_tree")

    def __init__(self, axis: "PositioningAxis", prefix: str, tree: dict):
        object.__setattr__(self, "_axis", axis)
        object.__setattr__(self, "_prefix", prefix)
        object.__setattr__(self, "_tree", tree)

    def __getattr__(self, name: str) -> Any:
        node = self._tree.get(name)
        if node is None:
            getter = self._axis._dynamic.get(f"{self._prefix}.{name}")
            if getter is not None:                  # a read-only tag inside a configuration structure
                return getter(self._axis)
            raise AttributeError(_unknown(self._axis, f"{self._prefix}.{name}"))
        if isinstance(node, dict):
            return _ConfigView(self._axis, f"{self._prefix}.{name}", node)
        return self._axis.cfg[node]

    def __setattr__(self, name: str, value: Any) -> None:
        node = self._tree.get(name)
        if node is None or isinstance(node, dict):
            raise AttributeError(_unknown(self._axis, f"{self._prefix}.{name}"))
        self._axis.write_tag(node, value)

    def __getitem__(self, key: int) -> "_ConfigView":
        name = f"{self._prefix.rsplit('.', 1)[-1]}[{key}]"
        if self._prefix == "Sensor" or self._prefix == "Sensor.Sensor":
            return getattr(self._axis, "_sensor_view")(key)
        raise TypeError(f"{self._prefix} is not an array ({name})")

    def __dir__(self) -> list[str]:
        return list(self._tree)

    def __repr__(self) -> str:
        return f"{self._axis.name}.{self._prefix}"


class _SensorArray:
    """``axis.Sensor[1]`` and the V6 table spelling ``axis.Sensor.Sensor[1]``."""

    __slots__ = ("_axis",)

    def __init__(self, axis: "PositioningAxis"):
        self._axis = axis

    def __getitem__(self, key: int) -> _ConfigView:
        node = self._axis.schema.tree.get(f"Sensor[{key}]")
        if node is None:
            raise IndexError(f"{self._axis.name}.Sensor[{key}]: the {self._axis.schema.title} has one encoder, "
                             f"Sensor[1]")
        return _ConfigView(self._axis, f"Sensor[{key}]", node)

    @property
    def Sensor(self) -> "_SensorArray":  # noqa: N802 - tag name
        return self


def _unknown(axis: "PositioningAxis", path: str) -> str:
    candidates = list(axis._dynamic) + list(axis.schema.params)
    near = difflib.get_close_matches(path, candidates, n=3, cutoff=0.6)
    hint = f"; did you mean {' or '.join(near)}?" if near else ""
    return f"{axis.name}.{path} is not a tag of the {axis.schema.title}{hint}"


class AxisTagsMixin:
    """Attribute and string-path access to the tags of the technology object.

    The status tags (``_dynamic``), their groups and the configuration schema are class attributes so
    that another technology object family can present the same kernel state under its own names.
    """

    _dynamic: dict[str, Callable[["PositioningAxis"], Any]] = DYNAMIC
    _dynamic_types: dict[str, str] = DYNAMIC_TYPES
    _dynamic_aliases: dict[str, str] = _DYNAMIC_ALIASES
    _status_groups: tuple[str, ...] = _STATUS_GROUPS
    _read_param_tags: frozenset[str] = READ_PARAM_TAGS

    def _use_v7_tags(self) -> None:
        """Present the S7-1200 V7 status tags on this axis (StatusSensor[1].*, ErrorBits.AdaptionError)."""
        self._dynamic = DYNAMIC_V7
        self._dynamic_types = DYNAMIC_TYPES_V7
        self._dynamic_aliases = _DYNAMIC_ALIASES_V7
        self._read_param_tags = READ_PARAM_TAGS_V7

    @property
    def Sensor(self) -> _SensorArray:  # noqa: N802
        return _SensorArray(self)  # type: ignore[arg-type]

    def _sensor_view(self, key: int) -> _ConfigView:
        return _SensorArray(self)[key]  # type: ignore[arg-type]

    def __getattr__(self, name: str) -> Any:
        # only called for names not found normally: status and configuration structures
        if name.startswith("__"):
            raise AttributeError(name)
        cls = type(self)
        if name in cls._status_groups or any(k.startswith(name + "[") for k in cls._dynamic):
            return _StatusView(self, name)  # type: ignore[arg-type]
        if name in cls._dynamic:
            return cls._dynamic[name](self)
        node = cls.schema.tree.get(name)  # type: ignore[attr-defined]
        if isinstance(node, dict) and not name.startswith("Sensor"):
            return _ConfigView(self, name, node)  # type: ignore[arg-type]
        raise AttributeError(f"{type(self).__name__} has no attribute {name!r}")

    # --- string paths ----------------------------------------------------------------------------------
    def tag(self, path: str) -> Any:
        """Value of the tag at ``path`` (e.g. ``"StatusBits.Enable"``, ``"Sensor[1].ActiveHoming.Mode"``)."""
        return self.tag_getter(path)()

    def tag_getter(self, path: str) -> Callable[[], Any]:
        """A function returning the current value of the tag at ``path`` (fast repeated reads)."""
        canon = self._dynamic_aliases.get(path, path)
        getter = self._dynamic.get(canon)
        if getter is not None:
            return lambda: getter(self)  # type: ignore[arg-type]
        word, _, bit = canon.rpartition(".")
        word_getter = self._dynamic.get(word)
        if word_getter is not None and bit:
            value = word_getter(self)  # type: ignore[arg-type]
            if hasattr(value, "bits"):                    # a bit of a status word: "StatusWord.X22"
                try:
                    getattr(value, bit)
                except AttributeError:
                    names = list(value.bits())
                    close = difflib.get_close_matches(bit, names, n=1, cutoff=0.6)
                    hint = f" (did you mean {word}.{close[0]}?)" if close else ""
                    raise KeyError(f"{self.name}.{path}: {word} has no bit {bit!r}{hint}; allowed: X0 .. X31 "  # type: ignore[attr-defined]
                                   f"or a bit name: {', '.join(names)}") from None
                return lambda: getattr(word_getter(self), bit)  # type: ignore[arg-type]
        schema = self.schema  # type: ignore[attr-defined]
        canon = schema.canonical(path)
        if canon in schema.params and schema.params[canon].access != P.P:
            return lambda: self.cfg[canon]  # type: ignore[attr-defined]
        raise KeyError(_unknown(self, path))  # type: ignore[arg-type]

    def ref(self, path: str) -> TagRef:
        """A reference to the tag at ``path`` (for MC_ReadParam / MC_WriteParam)."""
        canon = self._dynamic_aliases.get(path, path)
        if canon in self._dynamic:
            return TagRef(self, canon, self._dynamic_types[canon], True)  # type: ignore[arg-type]
        schema = self.schema  # type: ignore[attr-defined]
        canon = schema.canonical(path)
        if canon in schema.params and schema.params[canon].access != P.P:
            return TagRef(self, canon, schema.data_type(canon), False)  # type: ignore[arg-type]
        raise KeyError(_unknown(self, path))  # type: ignore[arg-type]

    def set_tag(self, path: str, value: Any) -> None:
        """Assign a tag by path with the access rules of direct assignment in the user program."""
        self.write_tag(path, value)  # type: ignore[attr-defined]

    @classmethod
    def tag_paths(cls) -> list[str]:
        """All tag paths of the technology object (status and configuration)."""
        return list(cls._dynamic) + [p for p, prm in cls.schema.params.items() if prm.access != P.P]  # type: ignore[attr-defined]
