"""The integrated technology of a CPU 31xT as a whole: technology DBs, the MCDevice DB, the DB update and
OB65 (S7-Technology V4.1 §2.5.3, §5.1, §7.10, §7.11).

One :class:`TechnologyDevice` per controller (``ctl.extension``, made by the family's ``setup``).  It keeps
the technology DBs by number, so an instruction's ``Axis`` input may be a DB number as in the manual, and
runs the DB update every ``db_update_ratio`` IPO cycles (the kernel's servo cycle is the IPO cycle; default
2, the example of §5.1), in the order of §7.11:

1. ``UpdateFlag`` := 16#0100 in every DB, 2. every DB is written entirely (the MCDevice DB first),
3. ``UpdateCounter`` += 1 in every DB, 4. ``UpdateFlag`` := 0, 5. the OB65 programs run (every update).

``DoneFlag[1..32]`` of the MCDevice DB toggles when a command started with that ``DoneFlag`` completes
(§6.9.2); it is set in the DB update that follows the completion, the first moment a program can see it.
A DB update never overruns in virtual time, so ``TODBTaskOverflows`` stays 0; there is no command
processing time to measure either (``MaxLoopDuration`` and ``CmdLoopDuration`` stay 0.0).
"""
from __future__ import annotations

import numbers
from typing import Any, Callable

import numpy as np

from ...kernel.errors import ConfigurationError
from ...kernel.schema import Issue
from .tdb import Array, AxisDB, MCDeviceDB, TechnologyDB

#: number of the MCDevice DB (Technology Objects Management creates it with the first technology object)
MCDEVICE_DB = 1
UPDATE_ACTIVE = 0x0100
#: integrated inputs and outputs of the CPU 31xT (§2.4: 4 inputs, 8 outputs) as the MCDevice DB shows them
INTEGRATED_INPUTS = tuple(f"I0.{n}" for n in range(4))
INTEGRATED_OUTPUTS = tuple(f"Q0.{n}" for n in range(8))


class _DoneWatch:
    """A command started with DoneFlag = n: toggle ``DoneFlag[n]`` once ``reached(job)`` (§6.9.2), unless its
    instance has started another command meanwhile (then the first one can no longer be monitored)."""

    __slots__ = ("owner", "seq", "job", "flag", "reached")

    def __init__(self, owner: Any, seq: int, job: Any, flag: int, reached: Callable[[Any], bool]):
        self.owner, self.seq, self.job, self.flag, self.reached = owner, seq, job, flag, reached


_CURRENT: list["TechnologyDevice | None"] = [None]


def current() -> "TechnologyDevice | None":
    """The integrated technology whose user program runs now: an instruction's ``Axis`` = DB number means a
    DB of this CPU.  Outside a program (a script between ``ctl.step()`` calls) it is the controller that ran
    its programs last, or the one made last."""
    return _CURRENT[0]


class TechnologyDevice:
    """The technology DBs, the MCDevice DB, the DB update and OB65 of one controller."""

    def __init__(self, ctl: Any, *, db_update_ratio: int = 2):
        self.ctl = ctl
        self._ratio = 2
        self.db_update_ratio = db_update_ratio
        self.mcdevice = MCDeviceDB(MCDEVICE_DB)
        self._dbs: dict[int, TechnologyDB] = {MCDEVICE_DB: self.mcdevice}
        self._objects: dict[int, Any] = {}
        self._axis_dbs: list[AxisDB] = []           # the axis DBs, gathered from the bank in one go
        self._rows = np.zeros(0, dtype=np.intp)
        self._ob65: list[tuple[str, Callable[[], Any]]] = []
        self._ipo = 0                               # IPO cycles since the last DB update
        self._done_flags = [False] * 32
        self._watches: list[_DoneWatch] = []
        self.updates = 0                            # DB updates since the controller started
        #: called with the reason at the end of :meth:`reinitialize` ("startup", "power")
        self.on_reinitialize: list[Callable[[str], None]] = []
        ctl.on_post_servo(self._on_ipo)
        # an INT at an instruction's Axis input names a DB of the CPU whose program runs (see ``current``)
        ctl.program(self._enter, name="S7-Technology (DB numbers of this CPU)")
        self._enter()

    def _enter(self) -> None:
        _CURRENT[0] = self

    # --- configuration --------------------------------------------------------------------------------
    @property
    def db_update_ratio(self) -> int:
        """The DB update clock in IPO cycles (S7T Config "system clocks", §5.1)."""
        return self._ratio

    @db_update_ratio.setter
    def db_update_ratio(self, value: Any) -> None:
        if isinstance(value, bool) or not isinstance(value, numbers.Integral) or not 1 <= value <= 1000:
            raise ValueError(f"db_update_ratio must be a whole number of IPO cycles in [1, 1000], got {value!r}")
        self._ratio = int(value)

    def db_number(self, requested: Any, where: str) -> int:
        """The DB number of a new technology object: ``requested`` (tag ``DBNumber``, checked by the schema)
        unless it is taken, else the lowest free number."""
        if requested is None:
            n = MCDEVICE_DB + 1
            while n in self._dbs:
                n += 1
            return n
        if requested in self._dbs:
            owner = self._objects.get(requested)
            what = f"the technology DB of {owner.name}" if owner is not None else "the MCDevice DB"
            raise ConfigurationError(where, [Issue("DBNumber", "rule:duplicate", requested,
                                                   f"allowed: a DB number no other technology object has; "
                                                   f"DB{requested} is {what}")])
        return int(requested)

    def register(self, to: Any) -> None:
        """Make the technology DB ``to.db`` known under its number."""
        self._dbs[to.db_number] = to.db
        self._objects[to.db_number] = to
        self._axis_dbs.append(to.db)
        self._rows = np.array([db._axis.index for db in self._axis_dbs], dtype=np.intp)
        from .dp_drive import bus                 # the drive's DP slave shows in StationLifeList from the start
        bus(self).refresh()

    def register_object(self, to: Any) -> None:
        """Make the technology DB ``to.db`` of a technology object that is no axis known under its number."""
        self._dbs[to.db_number] = to.db
        self._objects[to.db_number] = to

    def db(self, number: Any) -> TechnologyDB | None:
        """The technology DB with ``number`` (None: no technology DB)."""
        return self._dbs.get(number) if isinstance(number, int) and not isinstance(number, bool) else None

    def object(self, number: Any) -> Any:
        """The technology object of DB ``number`` (None for the MCDevice DB and numbers that are no TDB)."""
        return self._objects.get(number) if isinstance(number, int) and not isinstance(number, bool) else None

    # --- OB65 -------------------------------------------------------------------------------------------
    def ob65(self, fn: Callable[[], Any] | None = None, *, name: str | None = None):
        """Register a program that runs after every DB update (OB65, technology synchronization interrupt;
        decorator like ``Controller.program``)."""
        def register(f: Callable[[], Any]) -> Callable[[], Any]:
            self._ob65.append((name or getattr(f, "__name__", "OB65"), f))
            return f
        return register(fn) if fn is not None else register

    # --- DoneFlag (§6.9.2) ------------------------------------------------------------------------------
    def watch_done_flag(self, owner: Any, seq: int, job: Any, flag: int, reached: Callable[[Any], bool]) -> None:
        if flag:
            self._watches.append(_DoneWatch(owner, seq, job, flag, reached))

    def _toggle_done_flags(self) -> None:
        keep: list[_DoneWatch] = []
        for w in self._watches:
            if getattr(w.owner, "_cmd_seq", None) != w.seq:
                continue                            # the instance started a new command
            if w.reached(w.job):
                self._done_flags[w.flag - 1] = not self._done_flags[w.flag - 1]
            elif w.job.busy or getattr(w.owner, "_job", None) is w.job:
                keep.append(w)                      # still running, or its instance still holds it (MC_Stop)
        self._watches = keep

    # --- the DB update (§7.11) --------------------------------------------------------------------------
    def _on_ipo(self, t: float) -> None:
        self._ipo += 1
        if self._ipo >= self._ratio:
            self._ipo = 0
            self.update()

    def update(self) -> None:
        """One DB update in the order of §7.11, then OB65."""
        ctl = self.ctl
        dbs = list(self._dbs.values())              # the MCDevice DB first
        for db in dbs:
            db._write(UpdateFlag=UPDATE_ACTIVE)
        if self._watches:
            self._toggle_done_flags()
        self._write_mcdevice()
        if self._axis_dbs:
            b, rows, t = ctl.bank, self._rows, ctl.time
            columns = (b.sp_p[rows].tolist(), b.sp_v[rows].tolist(), b.sp_a[rows].tolist(), b.act_p[rows].tolist(),
                       b.act_v[rows].tolist(), b.fe[rows].tolist(), b.standstill[rows].tolist())
            for db, values in zip(self._axis_dbs, zip(*columns)):
                db.update(t, *values)
        for db in dbs:
            db._write(UpdateCounter=(db.UpdateCounter + 1) & 0xFFFF, UpdateFlag=0)
        self.updates += 1
        if ctl.mode == "RUN":
            self._enter()
            for name, fn in tuple(self._ob65):
                try:
                    fn()
                except BaseException as exc:  # noqa: BLE001 - a user program: STOP as any faulty OB
                    ctl._user_fault(f"OB65 program {name!r}", exc)
                    if isinstance(exc, KeyboardInterrupt):
                        raise
                    return

    def _write_mcdevice(self) -> None:
        ins, outs = self.ctl.inputs, self.ctl.outputs
        self.mcdevice._write(DoneFlag=Array(1, list(self._done_flags)),
                             DIStatus=Array(0, [ins[a] for a in INTEGRATED_INPUTS]),
                             DOStatus=Array(0, [outs[a] for a in INTEGRATED_OUTPUTS]))

    # --- MC_Reset on the MCDevice DB and restarts ------------------------------------------------------
    def reset_mcdevice(self) -> None:
        """MC_Reset with the MCDevice DB (§6.7.1, §7.10): MaxLoopDuration and TODBTaskOverflows to 0; its
        ErrorBuffer is cleared, its ErrorID cannot be acknowledged (§5.11)."""
        self.mcdevice._write(MaxLoopDuration=0.0, TODBTaskOverflows=0)
        errors = self.mcdevice._errors
        errors.buffer.clear()

    def reinitialize(self, reason: str) -> None:
        """CPU STOP -> RUN or POWER OFF -> ON: technology DBs are not retentive (§7), the DoneFlags and the
        update clock start anew."""
        self._watches.clear()
        self._done_flags = [False] * 32
        self._ipo = 0
        self.mcdevice._write(MaxLoopDuration=0.0, CmdLoopDuration=0.0, TODBTaskOverflows=0,
                             DoneFlag=Array(1, [False] * 32))
        for hook in tuple(self.on_reinitialize):
            hook(reason)


__all__ = ["TechnologyDevice", "current", "MCDEVICE_DB", "UPDATE_ACTIVE", "INTEGRATED_INPUTS", "INTEGRATED_OUTPUTS"]
