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
from ...kernel.jobs import JobKind
from ...kernel.motion import limits
from ...kernel.tag_views import TagAccessError
from ...kernel.words import DWord, pack, word_type
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

    def update(self, ctl: Any) -> None:
        """Write the whole DB from the axis's state now (one DB update, §7.11 step 2)."""
        ax = self._axis
        if activation.deactivated(ax):
            # not processed (§6.7.2): the DB keeps its values, only Statusword.ToDeactivated is shown
            self._write(Statusword=Statusword(int(self.Statusword) | 1 << STATUSWORD_BITS["ToDeactivated"]))
            return
        b, i, t = ctl.bank, ax.index, ctl.time
        v_act = 0.0 if ax.without_encoder else float(b.act_v[i])
        last = self._last
        a_act = 0.0 if last is None or t <= last[0] else (v_act - last[1]) / (t - last[0])
        object.__setattr__(self, "_last", (t, v_act))
        override = ax.config.defaults.velocity_override
        values: dict[str, Any] = dict(
            Statusword=Statusword(statusword(ax)), CommandVelocity=float(b.sp_v[i]),
            CommandAcceleration=float(b.sp_a[i]), ActualVelocity=v_act, ActualAcceleration=a_act,
            SpeedOverride=100.0 if override is None else float(override), AccelerationOverride=100.0)
        if ax.positioning:
            values.update(ActualPosition=S.actual_position(ax), CommandPosition=S.position(ax),
                          FollowingError=float(b.fe[i]), **_positioning(ax, self.TargetPosition))
        self._write(**values)


def _positioning(ax: "AxisT", last_target: float) -> dict[str, float]:
    """TargetPosition, Distance and DecelerationDistance: valid while a positioning runs (§7.2); outside
    one the target of the last positioning stays and the distances are 0."""
    job = ax.job
    if job is None or not job.busy or job.kind not in _POSITIONING:
        return dict(TargetPosition=last_target, Distance=0.0, DecelerationDistance=0.0)
    p, v, a = ax._state_now()
    try:
        stop = ax.motion.planner.stop_position(p, v, a, limits(ax, job.velocity, job=job))
    except Exception:  # noqa: BLE001 - a diagnostic value: an unplannable state shows no distance
        stop = p
    return dict(TargetPosition=ax._wrap(job.target), Distance=abs(job.target - p), DecelerationDistance=abs(stop - p))


def statusword(ax: "AxisT") -> int:
    """§7.1 Statusword of an axis from its kernel state."""
    job = ax.job
    kind = job.kind if job is not None and job.busy else None
    stop = ax.stop_job
    follower = ax.follower
    synchr = follower is not None and follower.coupling is not None
    motion = kind is not None or ax.superimposed_active or synchr or (stop is not None and stop.busy) or \
        ax.queue_waiting()
    enabled = ax.state in ("enabled", "disabling")
    acc = S.accel_state(ax)
    b, i = ax.ctl.bank, ax.index
    hw = ax.hw_approached
    bits = {
        0: ax.virtual or (enabled and not ax.following_mode and ax.drive.ready(ax.now)),
        1: ax.positioning and ax.homed,
        2: not motion,
        3: ax.superimposed_active,
        4: ax.errors.error,
        5: any(a.reaction != Reaction.NONE for a in ax.alarms),
        6: stop is not None,
        7: S.standstill(ax),
        8: kind in _POSITIONING or ax.superimposed_active,
        9: kind == JobKind.VELOCITY,
        10: synchr,
        11: kind in _HOMING or ax.homing.passive is not None,
        12: not enabled or ax.following_mode,
        13: acc == 0 and float(b.sp_v[i]) != 0.0,
        14: acc > 0,
        15: acc < 0,
        16: ax.restart_requested,
        18: ax.virtual or (S.drive_communication_ok(ax) and not any(a.kind == F.DRIVE_ALARM for a in ax.alarms)),
        19: ax.virtual or ax.sensor_valid,
        20: not ax.positioning or not ax.position_controlled,
        26: bool(hw.get("min")),
        27: bool(hw.get("max")),
    }
    return pack(bits)


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
