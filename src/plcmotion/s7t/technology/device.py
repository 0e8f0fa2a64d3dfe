"""The integrated technology of a CPU 31xT as a whole: technology DBs, the MCDevice DB, the DB update and
OB65 (S7-Technology V4.1 §2.5.3, §5.1, §5.4, §7.10, §7.11).

One :class:`TechnologyDevice` per controller (``ctl.extension``, made by the family's ``setup``).  It keeps
the technology DBs by number, so an instruction's ``Axis`` input may be a DB number as in the manual, and
runs the DB update in every basic clock, every ``db_update_ratio`` IPO cycles (the kernel's servo cycle is the
IPO cycle; default 2, the example of §5.1), in the order of §7.11:

1. ``UpdateFlag`` := 16#0100 in every DB of this clock, 2. each of them is written entirely (the MCDevice DB
first), 3. their ``UpdateCounter`` += 1, 4. ``UpdateFlag`` := 0, 5. the OB65 programs run (in every basic
clock, whether a DB was updated in it or not).

Which DBs a basic clock updates is the per-DB reduction ratio and offset of Technology Objects Management
(§7.11, :meth:`TechnologyDevice.set_db_update`): basic clock k (0, 1, 2, ... since the start) updates DB n when
k mod reduction = offset; the default 1 / 0 updates every DB in every clock.  The MCDevice DB is updated in
every basic clock (decision D88).  A change made while the controller runs waits for its next start
(``MCDevice.Statusword.RequestStartUp`` until then, §7.10).

``DoneFlag[1..32]`` of the MCDevice DB toggles when a command started with that ``DoneFlag`` completes
(§6.9.2); it is set in the DB update that follows the completion, the first moment a program can see it.

Command processing and overflows in virtual time (decision D89): a command an instruction starts is carried
out by the IPO cycle that follows the program's call; ``CmdLoopDuration`` is the mean and ``MaxLoopDuration`` the
longest virtual time from a command's start to that IPO cycle [s] - one IPO cycle in plcmotion, since the
programs run between IPO cycles - and both are 0.0 until the first command after the start or an MC_Reset of the
MCDevice DB.  A DB update never overruns in virtual time; :meth:`TechnologyDevice.inject_update_overflow`
makes the next basic clocks overflow as on an overloaded CPU: their update is discarded (no DB written, no OB65)
and ``TODBTaskOverflows`` counts them (§7.10, §7.11).
"""
from __future__ import annotations

import numbers
from typing import Any, Callable

import numpy as np

from ...kernel.errors import ConfigurationError
from ...kernel.schema import Issue
from .tdb import Array, AxisDB, MCDeviceDB, MCDeviceStatusword, TechnologyDB

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
        self._clock = 0                             # basic clocks since the start (§7.11)
        #: DB number -> (reduction, offset) in effect, and the ones set for the next start
        self._schedule: dict[int, tuple[int, int]] = {}
        self._requested: dict[int, tuple[int, int]] = {}
        self._overflows_to_come = 0
        self._overflows = 0
        self._loops = 0                             # commands since the start or MC_Reset of the MCDevice DB
        self._loop_sum = 0.0
        self._loop_max = 0.0
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
        bus(self).refresh(to)

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

    # --- the update of each DB: reduction ratio and offset (§7.11) ------------------------------------
    def set_db_update(self, number: Any, reduction: Any = 1, offset: Any = 0) -> None:
        """Technology Objects Management, expert mode: technology DB ``number`` is updated in every
        ``reduction``-th basic clock, in the clocks k with k mod reduction = ``offset``.  Before the controller
        has run it takes effect at once; later at the next start (``MCDevice.Statusword.RequestStartUp``)."""
        db = self.db(number)
        if db is None or db is self.mcdevice:
            raise ValueError(f"set_db_update: {number!r} is no technology DB of a technology object "
                             f"(the MCDevice DB DB{MCDEVICE_DB} is updated in every basic clock)")
        for name, value, lo, hi in (("reduction", reduction, 1, 1000), ("offset", offset, 0, 999)):
            if isinstance(value, bool) or not isinstance(value, numbers.Integral) or not lo <= value <= hi:
                raise ValueError(f"set_db_update: {name} must be a whole number in [{lo}, {hi}], got {value!r}")
        if offset >= reduction:
            raise ValueError(f"set_db_update: offset must be below the reduction ({reduction}), got {offset!r}")
        entry = (int(reduction), int(offset))
        if self._clock == 0 and self.ctl.time == 0.0:
            self._set_schedule(number, entry)
            return
        self._requested[number] = entry
        self._request_startup()

    def db_update(self, number: int) -> tuple[int, int]:
        """(reduction, offset) in effect for technology DB ``number``."""
        return self._schedule.get(number, (1, 0))

    def _set_schedule(self, number: int, entry: tuple[int, int]) -> None:
        if entry == (1, 0):
            self._schedule.pop(number, None)
        else:
            self._schedule[number] = entry

    def _request_startup(self) -> None:
        pending = any(self._requested[n] != self.db_update(n) for n in self._requested)
        self.mcdevice._write(Statusword=MCDeviceStatusword(int(pending) << 2))

    def _due(self, db: TechnologyDB, clock: int) -> bool:
        reduction, offset = self._schedule.get(db.number, (1, 0))
        return clock % reduction == offset

    # --- command processing and overflows in virtual time (§5.4, §7.10) ----------------------------------
    def note_command(self) -> None:
        """An instruction started a command: it is carried out in the next IPO cycle."""
        duration = self.ctl.servo_cycle
        self._loops += 1
        self._loop_sum += duration
        self._loop_max = max(self._loop_max, duration)

    def inject_update_overflow(self, count: Any = 1) -> None:
        """Fault injection (virtual commissioning): the DB updates of the next ``count`` basic clocks overflow -
        they are discarded, OB65 is not called, ``TODBTaskOverflows`` counts them (§7.11)."""
        if isinstance(count, bool) or not isinstance(count, numbers.Integral) or not 1 <= count <= 1_000_000:
            raise ValueError(f"inject_update_overflow: count must be a whole number in [1, 1000000], got {count!r}")
        self._overflows_to_come += int(count)

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
        """The DB update of one basic clock in the order of §7.11, then OB65."""
        ctl = self.ctl
        clock = self._clock
        self._clock += 1
        if self._overflows_to_come:
            self._overflows_to_come -= 1            # discarded: no DB written, no OB65 (§7.11)
            self._overflows = min(self._overflows + 1, 0xFFFF_FFFF)
            return
        schedule = self._schedule
        if schedule:
            dbs = [db for db in self._dbs.values() if db is self.mcdevice or self._due(db, clock)]
            axis_dbs = [db for db in self._axis_dbs if self._due(db, clock)]
            rows = np.array([db._axis.index for db in axis_dbs], dtype=np.intp)
        else:
            dbs = list(self._dbs.values())          # the MCDevice DB first
            axis_dbs, rows = self._axis_dbs, self._rows
        for db in dbs:
            db._write(UpdateFlag=UPDATE_ACTIVE)
        if self._watches:
            self._toggle_done_flags()
        self._write_mcdevice()
        if axis_dbs:
            b, t = ctl.bank, ctl.time
            columns = (b.sp_p[rows].tolist(), b.sp_v[rows].tolist(), b.sp_a[rows].tolist(), b.act_p[rows].tolist(),
                       b.act_v[rows].tolist(), b.fe[rows].tolist(), b.standstill[rows].tolist())
            for db, values in zip(axis_dbs, zip(*columns)):
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
        loops = self._loops
        self.mcdevice._write(MaxLoopDuration=self._loop_max, CmdLoopDuration=self._loop_sum / loops if loops else 0.0,
                             TODBTaskOverflows=self._overflows, DoneFlag=Array(1, list(self._done_flags)),
                             DIStatus=Array(0, [ins[a] for a in INTEGRATED_INPUTS]),
                             DOStatus=Array(0, [outs[a] for a in INTEGRATED_OUTPUTS]))

    # --- MC_Reset on the MCDevice DB and restarts ------------------------------------------------------
    def reset_mcdevice(self) -> None:
        """MC_Reset with the MCDevice DB (§6.7.1, §7.10): MaxLoopDuration and TODBTaskOverflows to 0; its
        ErrorBuffer is cleared, its ErrorID cannot be acknowledged (§5.11)."""
        self._reset_loops()
        self.mcdevice._write(MaxLoopDuration=0.0, CmdLoopDuration=0.0, TODBTaskOverflows=0)
        errors = self.mcdevice._errors
        errors.buffer.clear()

    def _reset_loops(self) -> None:
        self._loops, self._loop_sum, self._loop_max, self._overflows = 0, 0.0, 0.0, 0

    def reinitialize(self, reason: str) -> None:
        """CPU STOP -> RUN or POWER OFF -> ON: technology DBs are not retentive (§7), the DoneFlags and the
        update clock start anew."""
        self._watches.clear()
        self._done_flags = [False] * 32
        self._ipo = 0
        self._clock = 0
        self._reset_loops()
        for number, entry in self._requested.items():       # changed schedules take effect at a start
            self._set_schedule(number, entry)
        self._requested.clear()
        self.mcdevice._write(Statusword=MCDeviceStatusword(0))
        self.mcdevice._write(MaxLoopDuration=0.0, CmdLoopDuration=0.0, TODBTaskOverflows=0,
                             DoneFlag=Array(1, [False] * 32))
        for hook in tuple(self.on_reinitialize):
            hook(reason)


__all__ = ["TechnologyDevice", "current", "MCDEVICE_DB", "UPDATE_ACTIVE", "INTEGRATED_INPUTS", "INTEGRATED_OUTPUTS"]
