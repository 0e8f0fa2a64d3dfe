"""Technology DBs: the read-only image of a technology object the user program reads (S7-Technology V4.1
§2.5.3, §7.1-§7.3, §7.10, §7.11).

A technology DB is a snapshot: its members are written in the DB update of the technology (every
``db_update_ratio`` IPO cycles, ``device.TechnologyDevice``) and keep their values in between, so a program
sees a value change only at an update (§7.11), consistent within one update.  Members are named exactly as
in §7: ``axis.db.ActualPosition``, ``axis.db.Statusword.DriveEnabled`` (a DWORD whose bits also read as
``.X0`` ... ``.X31``), ``axis.db.ErrorBuffer[0]``.  ``ErrorID``, ``ErrorBuffer`` and ``ErrorStatus`` are
read from the object's error record at once (§7.11: independent of the update, see ``to_errors``).
The user program cannot write a technology DB (§7: write-protected).
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, Iterator

from ...kernel import axis_status as S
from ...kernel import faults as F
from ...kernel.faults import Reaction
from ...kernel.jobs import JobKind, JobState
from ...kernel.motion import limits
from ...kernel.tag_views import TagAccessError
from ...kernel.words import DWord, word_type
from . import activation
from .to_errors import ERROR_STATUS_BITS, ErrorRecord

if TYPE_CHECKING:  # pragma: no cover
    from .axes import AxisT

#: §7.1 Statusword of the axis technology DBs (bit numbers of the manual)
STATUSWORD_BITS = {
    "DriveEnabled": 0, "HomingDone": 1, "Done": 2, "SuperImposedCommand": 3, "Error": 4, "Errorstop": 5,
    "Stopping": 6, "Standstill": 7, "PositioningCommand": 8, "SpeedCommand": 9, "SynchrCommand": 10, "Homing": 11,
    "FollowUpControl": 12, "ConstantVelocity": 13, "Accelerating": 14, "Decelerating": 15, "RequestRestart": 16,
    "Simulation": 17, "CyclicInterface": 18, "EncoderValid": 19, "SpeedMode": 20, "TorqueLimiting": 21,
    "SupImpSynchrCommand": 22, "TorqueLimitingCommand": 23, "RequestStartUp": 24, "ToDeactivated": 25,
    "HWLimitSwitchMinus": 26, "HWLimitSwitchPlus": 27}
Statusword = word_type("Statusword", STATUSWORD_BITS, aliases={"TOdeactivated": 25})
ErrorStatus = word_type("ErrorStatus", ERROR_STATUS_BITS)
#: §7.10 Statusword of the MCDevice DB
MCDeviceStatusword = word_type("MCDeviceStatusword", {"Reserve01": 0, "Reserve02": 1, "RequestStartUp": 2})

_POSITIONING = (JobKind.ABSOLUTE, JobKind.RELATIVE)
_HOMING = (JobKind.HOME_ACTIVE, JobKind.HOME_DIRECT, JobKind.HOME_PASSIVE)


class Array:
    """A read-only ARRAY[lo..hi] of a technology DB (``DoneFlag[1..32]``, ``ErrorBuffer[0..2]``)."""

    __slots__ = ("_lo", "_values")

    def __init__(self, lo: int, values: list[Any]):
        self._lo = lo
        self._values = values

    def __getitem__(self, index: int) -> Any:
        i = index - self._lo
        if not isinstance(index, int) or i < 0 or i >= len(self._values):
            raise IndexError(f"index {index!r} outside [{self._lo}..{self._lo + len(self._values) - 1}]")
        return self._values[i]

    def __len__(self) -> int:
        return len(self._values)

    def __iter__(self) -> Iterator[Any]:
        return iter(self._values)

    def __eq__(self, other: object) -> bool:
        return list(self._values) == list(other) if isinstance(other, (list, tuple, Array)) else NotImplemented

    def __repr__(self) -> str:
        return f"Array[{self._lo}..{self._lo + len(self._values) - 1}]{self._values!r}"


class TechnologyDB:
    """Base of the technology DBs: number, UpdateFlag, UpdateCounter and write protection."""

    kind = "technology DB"

    def __init__(self, number: int, errors: ErrorRecord | None = None):
        object.__setattr__(self, "number", number)
        object.__setattr__(self, "_errors", errors if errors is not None else ErrorRecord())
        object.__setattr__(self, "UpdateFlag", 0)
        object.__setattr__(self, "UpdateCounter", 0)

    def __setattr__(self, name: str, value: Any) -> None:
        raise TagAccessError(f"DB{self.number} is a technology DB: the user program cannot write {name} "
                             f"(S7-Technology V4.1 §7)")

    def _write(self, **values: Any) -> None:
        self.__dict__.update(values)

    # --- the error members: independent of the update (§7.11) -------------------------------------------
    @property
    def ErrorID(self) -> int:  # noqa: N802 - member name of the manual
        return self._errors.error_id

    @property
    def ErrorBuffer(self) -> Array:  # noqa: N802
        return Array(0, self._errors.error_buffer())

    def __repr__(self) -> str:
        return f"<{self.kind} DB{self.number}>"


class AxisDB(TechnologyDB):
    """The technology DB of an axis: speed-controlled (§7.1), positioning (§7.2) or synchronization (§7.3)
    axis.  Position members exist only on positioning and synchronization axes."""

    kind = "axis technology DB"

    def __init__(self, axis: "AxisT"):
        super().__init__(axis.db_number, axis.errors)
        object.__setattr__(self, "_axis", axis)
        object.__setattr__(self, "_last", None)       # (t, actual velocity) of the previous update
        values: dict[str, Any] = dict(Statusword=Statusword(0), CommandVelocity=0.0, CommandAcceleration=0.0,
                                      ActualVelocity=0.0, ActualAcceleration=0.0, SpeedOverride=100.0,
                                      AccelerationOverride=100.0)
        if axis.positioning:
            values.update(ActualPosition=0.0, CommandPosition=0.0, TargetPosition=0.0, Distance=0.0,
                          DecelerationDistance=0.0, FollowingError=0.0)
        self._write(**values)

    @property
    def ErrorStatus(self) -> DWord:  # noqa: N802
        return ErrorStatus(self._errors.status)

    def __getattr__(self, name: str) -> Any:
        raise AttributeError(f"DB{self.number} ({self._axis.technology_name}) has no member {name!r}")

    def update(self, t: float, sp_p: float, sp_v: float, sp_a: float, act_p: float, act_v: float, fe: float,
               still: bool) -> None:
        """Write the whole DB from the axis's state at ``t`` (one DB update, §7.11 step 2); the bank values
        of all axes come in one gather (``device.TechnologyDevice.update``)."""
        ax = self._axis
        if activation.deactivated(ax):
            # not processed (§6.7.2): the DB keeps its values, only Statusword.ToDeactivated is shown
            self._write(Statusword=Statusword(int(self.Statusword) | 1 << STATUSWORD_BITS["ToDeactivated"]))
            return
        if ax.without_encoder:
            act_v = 0.0
        last = self._last
        a_act = 0.0 if last is None or t <= last[0] else (act_v - last[1]) / (t - last[0])
        object.__setattr__(self, "_last", (t, act_v))
        override = ax.config.defaults.velocity_override
        d = self.__dict__
        d["Statusword"] = Statusword(statusword(ax, sp_v, sp_a, still))
        d["CommandVelocity"] = sp_v
        d["CommandAcceleration"] = sp_a
        d["ActualVelocity"] = act_v
        d["ActualAcceleration"] = a_act
        d["SpeedOverride"] = 100.0 if override is None else float(override)
        acc_override = ax.config.defaults.acceleration_override
        d["AccelerationOverride"] = 100.0 if acc_override is None else float(acc_override)
        if ax.positioning:
            d["ActualPosition"] = ax._wrap(act_p)
            d["CommandPosition"] = ax._wrap(sp_p)
            d["FollowingError"] = fe
            job = ax.job
            if job is not None and job.state == JobState.BUSY and job.kind in _POSITIONING:
                d.update(_positioning(ax, job))
            else:                                   # outside a positioning: the last target, no distances
                d["Distance"] = d["DecelerationDistance"] = 0.0


def _positioning(ax: "AxisT", job: Any) -> dict[str, float]:
    """TargetPosition, Distance and DecelerationDistance while a positioning runs (§7.2)."""
    p, v, a = ax._state_now()
    try:
        stop = ax.motion.planner.stop_position(p, v, a, limits(ax, job.velocity, job=job))
    except Exception:  # noqa: BLE001 - a diagnostic value: an unplannable state shows no distance
        stop = p
    return dict(TargetPosition=ax._wrap(job.target), Distance=abs(job.target - p), DecelerationDistance=abs(stop - p))


def statusword(ax: "AxisT", v: float, a: float, still: bool) -> int:
    """§7.1 Statusword of an axis from its kernel state (setpoint velocity ``v`` and acceleration ``a``,
    the standstill signal ``still``)."""
    job = ax.job
    kind = job.kind if job is not None and job.state == JobState.BUSY else None
    stop = ax.stop_job
    follower = ax.follower
    synchr = follower is not None and follower.coupling is not None
    sup = ax.superimposed.active
    enabled = ax.state in ("enabled", "disabling")
    virtual = ax.virtual
    w = 0
    if virtual or (enabled and not ax.following_mode and ax.drive.ready(ax.now)):
        w |= 1                                                  # DriveEnabled
    if ax.positioning and ax.homed:
        w |= 1 << 1                                             # HomingDone
    if not (kind is not None or sup or synchr or (stop is not None and stop.state == JobState.BUSY)
            or ax.queue.pending):
        w |= 1 << 2                                             # Done: no motion command
    if sup:
        w |= 1 << 3 | 1 << 8                                    # SuperImposedCommand, PositioningCommand
    if ax.errors.error:
        w |= 1 << 4
    alarms = ax.alarms
    if alarms and any(f.reaction != Reaction.NONE for f in alarms):
        w |= 1 << 5                                             # Errorstop
    if stop is not None:
        w |= 1 << 6                                             # Stopping
    if (still if ax.servo else v == 0.0):
        w |= 1 << 7                                             # Standstill
    if kind in _POSITIONING:
        w |= 1 << 8
    elif kind == JobKind.VELOCITY and not job.extra.get("clamped"):
        w |= 1 << 9                       # SpeedCommand (MC_MoveToEndPos: until the end stop is detected)
    elif kind in _HOMING:
        w |= 1 << 11
    if synchr:
        w |= 1 << 10
    if ax.homing.passive is not None:
        w |= 1 << 11
    if not enabled or ax.following_mode:
        w |= 1 << 12                                            # FollowUpControl
    if abs(a) <= 1e-9 * max(1.0, ax.config.defaults.acceleration):
        if v != 0.0:
            w |= 1 << 13                                        # ConstantVelocity
    elif a * v > 0 or v == 0.0:
        w |= 1 << 14                                            # Accelerating
    else:
        w |= 1 << 15                                            # Decelerating
    if ax.restart_requested:
        w |= 1 << 16
    if ax.simulation:
        w |= 1 << 17                                            # Simulation (MC_Power Mode 4)
    if virtual or (S.drive_communication_ok(ax) and not any(f.kind == F.DRIVE_ALARM for f in alarms)):
        w |= 1 << 18                                            # CyclicInterface
    if virtual or ax.sensor_valid:
        w |= 1 << 19                                            # EncoderValid
    if not ax.positioning or not ax.position_controlled:
        w |= 1 << 20                                            # SpeedMode
    if ax.torque_limiting_command:
        w |= 1 << 23                                            # TorqueLimitingCommand
        if ax.drive.torque_limit_active:
            w |= 1 << 21                                        # TorqueLimiting: the drive is at the limit
    hw = ax.hw_approached
    if hw.get("min"):
        w |= 1 << 26
    if hw.get("max"):
        w |= 1 << 27
    return w


class MCDeviceDB(TechnologyDB):
    """The MCDevice DB (§7.10): the technology as a whole.  Its ErrorID cannot be acknowledged (§5.11);
    MC_Reset on it resets MaxLoopDuration and TODBTaskOverflows (§6.7.1)."""

    kind = "MCDevice DB"

    def __init__(self, number: int):
        super().__init__(number)
        self._write(Reserve34=0, MaxLoopDuration=0.0, CmdLoopDuration=0.0, StationLifeList=Array(0, [0] * 128),
                    DoneFlag=Array(1, [False] * 32), DIStatus=Array(0, [False] * 4), DOStatus=Array(0, [False] * 8),
                    Statusword=MCDeviceStatusword(0), TODBTaskOverflows=0)

    def __getattr__(self, name: str) -> Any:
        raise AttributeError(f"DB{self.number} (MCDevice) has no member {name!r}")


__all__ = ["Array", "AxisDB", "MCDeviceDB", "TechnologyDB", "Statusword", "ErrorStatus", "MCDeviceStatusword",
           "STATUSWORD_BITS", "statusword"]
