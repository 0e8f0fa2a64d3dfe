"""Synchronous operation instructions of the S7-1500/S7-1500T (V5, §9.1): MC_GearIn, MC_GearInPos,
MC_PhasingRelative, MC_PhasingAbsolute, MC_CamIn, MC_SynchronizedMotionSimulation,
MC_LeadingValueAdditive.

The jobs run in the following axis (``kernel.follower``); these classes check the inputs, hand the
jobs over and show their state.  StartSync stays TRUE once synchronization has begun, until the job
ends (the manual leaves open whether it drops with InSync; docs/s7_1500/decisions.md #18).
"""
from __future__ import annotations

from typing import Any, ClassVar

from .technology.axes import PositioningAxis1500, SynchronousAxis
from .technology.cam_to import CamTO
from ..kernel.jobs import Job, JobKind, JobState
from . import errors as E
from .base import ExecuteInstruction, Instruction, InstructionError, as_bool, as_int, as_real, dynamic, dynamics, \
    integer, real

DINT_MIN, DINT_MAX = -2147483648, 2147483647


def _is_leading_value_source(to: Any) -> bool:
    return isinstance(to, PositioningAxis1500) or callable(getattr(to, "lv_value", None))


class _SyncInstruction(ExecuteInstruction):
    """Instructions with Master and Slave inputs."""

    AXIS_TYPES: ClassVar[tuple[type, ...]] = (SynchronousAxis,)

    def _axis(self, name: str = "Slave") -> Any:
        slave = super()._axis("Slave")
        object.__setattr__(self, "_job_slave", slave)     # the job belongs to this axis until it ends
        return slave

    def _rejected_at(self) -> Any:
        # a rejected job is noted at the axis it was given to, whatever the Slave input shows now
        return getattr(self, "_job_slave", None)

    def _master(self) -> Any:
        master = getattr(self, "Master", None)
        if _is_leading_value_source(master):
            self._register(master)
            return master
        raise InstructionError(E.WRONG_TO)             # no technology object, or one that gives no leading value

    @staticmethod
    def _ratio(numerator: Any, denominator: Any) -> float:
        num, den = as_int(numerator), as_int(denominator)
        if num is None or num == 0 or not DINT_MIN <= num <= DINT_MAX:
            raise InstructionError(E.parameter("RatioNumerator"))
        if den is None or not 1 <= den <= DINT_MAX:
            raise InstructionError(E.parameter("RatioDenominator"))
        return num / den


class MC_GearIn(_SyncInstruction):  # noqa: N801
    """Start gearing: the following axis synchronizes with Acceleration/Deceleration/Jerk and is InGear
    once it moves with ratio x the leading axis's velocity and acceleration (§4.1, §9.1.1).  InGear and
    Busy stay TRUE until another job overrides the gearing."""

    INPUTS = {"Master": None, "Slave": None, "Execute": False, "RatioNumerator": 1, "RatioDenominator": 1,
              "Acceleration": -1.0, "Deceleration": -1.0, "Jerk": -1.0}
    OUTPUTS = {"InGear": False, "Busy": False, "CommandAborted": False, "Error": False, "ErrorID": 0}

    def _start(self, slave: Any) -> Job:
        master = self._master()
        ratio = self._ratio(self.RatioNumerator, self.RatioDenominator)
        dyn = dynamics(slave, self, velocity=None)
        job = Job(JobKind.GEAR_IN, acceleration=dyn["acceleration"], deceleration=dyn["deceleration"],
                  jerk=dyn["jerk"], owner=self, extra={"master": master, "ratio": ratio})
        slave.sync_submit(job)
        return job

    def _running(self, execute: bool) -> None:
        self._out(InGear=bool(self._job is not None and self._job.in_sync))


class _PositionedSync(_SyncInstruction):
    """Shared by MC_GearInPos and MC_CamIn: StartSync / InSync while the job runs."""

    def _running(self, execute: bool) -> None:
        job = self._job
        if job is not None:
            self._out(StartSync=job.start_sync, InSync=job.in_sync)

    def _sync_inputs(self, slave: Any, allowed_spr: tuple[int, ...]) -> dict[str, Any]:
        spr = integer("SyncProfileReference", self.SyncProfileReference, allowed_spr)
        x: dict[str, Any] = {"spr": spr, "master_sync": real("MasterSyncPosition", self.MasterSyncPosition)}
        distance = real("MasterStartDistance", self.MasterStartDistance)
        if spr in (1, 3, 4) and distance < 0.0:
            raise InstructionError(E.parameter("MasterStartDistance"))
        x["start_distance"] = distance
        # SyncDirection is in effect with modulo axes only (§9.1.2, §9.1.5): between linear axes it is
        # not read
        master = getattr(self, "Master", None)
        lv_modulo = getattr(master, "lv_modulo", None)
        modulo = slave.config.modulo.enabled or (callable(lv_modulo) and lv_modulo() is not None)
        x["sync_direction"] = integer("SyncDirection", self.SyncDirection, (1, 2, 3)) if modulo else 3
        return x


class MC_GearInPos(_PositionedSync):  # noqa: N801
    """Gearing with synchronous positions (S7-1500T, §4.2, §9.1.2).

    SyncProfileReference 0: in advance with Velocity/Acceleration/Deceleration/Jerk, synchronous at
    MasterSyncPosition/SlaveSyncPosition; 1: in advance over MasterStartDistance; 3: subsequent, starting
    at MasterSyncPosition and synchronous MasterStartDistance later.  Synchronous law:
    slave = SlaveSyncPosition + ratio x (master - MasterSyncPosition)."""

    INPUTS = {"Master": None, "Slave": None, "Execute": False, "RatioNumerator": 1, "RatioDenominator": 1,
              "MasterSyncPosition": 0.0, "SlaveSyncPosition": 0.0, "SyncProfileReference": 1,
              "MasterStartDistance": 1.0, "Velocity": -1.0, "Acceleration": -1.0, "Deceleration": -1.0,
              "Jerk": -1.0, "SyncDirection": 3}
    OUTPUTS = {"StartSync": False, "InSync": False, "Busy": False, "CommandAborted": False, "Error": False,
               "ErrorID": 0}

    def _start(self, slave: Any) -> Job:
        master = self._master()
        ratio = self._ratio(self.RatioNumerator, self.RatioDenominator)
        x = self._sync_inputs(slave, (0, 1, 3))
        x["slave_sync"] = real("SlaveSyncPosition", self.SlaveSyncPosition)
        x.update(master=master, ratio=ratio)
        dyn = dynamics(slave, self) if x["spr"] == 0 else {}
        job = Job(JobKind.GEAR_IN_POS, velocity=dyn.get("velocity", 0.0), acceleration=dyn.get("acceleration"),
                  deceleration=dyn.get("deceleration"), jerk=dyn.get("jerk"), owner=self, extra=x)
        slave.sync_submit(job)
        return job


class MC_CamIn(_PositionedSync):  # noqa: N801
    """Start camming with a cam (S7-1500T, §5, §9.1.5).

    slave = f((master - MasterOffset) / MasterScaling) x SlaveScaling + SlaveOffset.  ApplicationMode:
    0 once (the job ends with EndOfProfile at the cam end), 1 cyclic, 2 cyclic appending.
    SyncProfileReference: 0 in advance with dynamics, 1 in advance over MasterStartDistance, 2 direct
    synchronous setting, 3 subsequent from MasterSyncPosition, 4 subsequent from the current position.
    EndOfProfile shows the cam end for at least one call."""

    INPUTS = {"Master": None, "Slave": None, "Cam": None, "Execute": False, "MasterOffset": 0.0,
              "SlaveOffset": 0.0, "MasterScaling": 1.0, "SlaveScaling": 1.0, "MasterSyncPosition": 0.0,
              "SyncProfileReference": 1, "MasterStartDistance": 0.0, "Velocity": -1.0, "Acceleration": -1.0,
              "Deceleration": -1.0, "Jerk": -1.0, "ApplicationMode": 0, "SyncDirection": 3}
    OUTPUTS = {"StartSync": False, "InSync": False, "Busy": False, "CommandAborted": False, "Error": False,
               "ErrorID": 0, "EndOfProfile": False}

    def _reinit(self) -> None:
        super()._reinit()
        object.__setattr__(self, "_eop_seen", 0)

    def _start(self, slave: Any) -> Job:
        master = self._master()
        cam = self.Cam
        if not isinstance(cam, CamTO):
            raise InstructionError(E.WRONG_TO)
        self._register(cam)
        x = self._sync_inputs(slave, (0, 1, 2, 3, 4))
        # with direct synchronous setting the offsets come from the present positions (§5.4.4)
        direct = x["spr"] == 2
        x["master_offset"] = 0.0 if direct else real("MasterOffset", self.MasterOffset)
        x["slave_offset"] = 0.0 if direct else real("SlaveOffset", self.SlaveOffset)
        ms = real("MasterScaling", self.MasterScaling)
        if ms <= 0.0:
            raise InstructionError(E.parameter("MasterScaling"))
        x["master_scaling"] = ms
        x["slave_scaling"] = real("SlaveScaling", self.SlaveScaling)
        x["app_mode"] = integer("ApplicationMode", self.ApplicationMode, (0, 1, 2))
        x.update(master=master, cam=cam)
        dyn = dynamics(slave, self) if x["spr"] == 0 else {}
        job = Job(JobKind.CAM_IN, velocity=dyn.get("velocity", 0.0), acceleration=dyn.get("acceleration"),
                  deceleration=dyn.get("deceleration"), jerk=dyn.get("jerk"), owner=self, extra=x)
        object.__setattr__(self, "_eop_seen", 0)
        slave.sync_submit(job)
        return job

    def _running(self, execute: bool) -> None:
        super()._running(execute)
        job = self._job
        count = job.end_of_profile if job is not None else 0
        self._out(EndOfProfile=count > self._eop_seen)
        object.__setattr__(self, "_eop_seen", count)

    def _final_for(self, job: Job):
        if job.state == JobState.DONE:
            return ("EndOfProfile", 0, 0)
        return super()._final_for(job)


class _Phasing(_SyncInstruction):
    ABSOLUTE = False
    PROGRESS = "CoveredPhaseShift"
    INPUTS = {"Master": None, "Slave": None, "Execute": False, "PhaseShift": 0.0, "Velocity": -1.0,
              "Acceleration": -1.0, "Deceleration": -1.0, "Jerk": -1.0}

    def _start(self, slave: Any) -> Job:
        master = self._master()
        shift = real("PhaseShift", self.PhaseShift)
        dyn = dynamics(slave, self)
        job = Job(JobKind.PHASING, velocity=dyn["velocity"], acceleration=dyn["acceleration"],
                  deceleration=dyn["deceleration"], jerk=dyn["jerk"], owner=self,
                  extra={"master": master, "slave": slave, "shift": shift, "absolute": self.ABSOLUTE})
        self._out(**{self.PROGRESS: 0.0})
        slave.sync_submit(job)
        return job

    def _progress(self, job: Job) -> float:
        slave = job.extra["slave"]           # the axis the job started on (rewiring acts at the next edge)
        if self.ABSOLUTE:
            return slave.phase_shift()
        return slave.covered_phase_shift(job)

    def _running(self, execute: bool) -> None:
        job = self._job
        if job is not None:
            self._out(**{self.PROGRESS: self._progress(job)})

    def _final_for(self, job: Job):
        if job.state == JobState.DONE:
            target = job.extra["shift"] if self.ABSOLUTE else job.extra["shift"]
            object.__setattr__(self, "_last", target)
        return super()._final_for(job)

    def _clear_outputs(self) -> None:
        keep = getattr(self, self.PROGRESS)
        super()._clear_outputs()
        self._out(**{self.PROGRESS: keep})

    def _show(self, output: str, error_id: int, error_info: int) -> None:
        super()._show(output, error_id, error_info)
        if output == "Done":
            self._out(**{self.PROGRESS: self._last})

    def _reinit(self) -> None:
        super()._reinit()
        object.__setattr__(self, "_last", 0.0)


class MC_PhasingRelative(_Phasing):  # noqa: N801
    """Shift the leading value of a gearing by PhaseShift relative to the present shift (S7-1500T,
    §4.5, §9.1.3): effective leading value = leading value + phase shift.  The dynamics are those of the
    following axis's added motion.  CoveredPhaseShift shows the part done so far."""

    OUTPUTS = {"Done": False, "Busy": False, "CommandAborted": False, "Error": False, "ErrorID": 0,
               "CoveredPhaseShift": 0.0}


class MC_PhasingAbsolute(_Phasing):  # noqa: N801
    """Shift the leading value of a gearing to the absolute PhaseShift (S7-1500T, §9.1.4)."""

    ABSOLUTE = True
    PROGRESS = "AbsolutePhaseShift"
    OUTPUTS = {"Done": False, "Busy": False, "CommandAborted": False, "Error": False, "ErrorID": 0,
               "AbsolutePhaseShift": 0.0}


class MC_SynchronizedMotionSimulation(Instruction):  # noqa: N801
    """Keep a synchronous operation without moving the axis (S7-1500T, §3.4, §9.1.6): started in status
    Synchronous; survives MC_Power Enable = FALSE and single-axis jobs; at Enable = FALSE the
    synchronous setpoints act again at once."""

    INPUTS = {"Slave": None, "Enable": False}
    OUTPUTS = {"InSimulation": False, "Busy": False, "Error": False, "ErrorID": 0}
    AXIS_TYPES: ClassVar[tuple[type, ...]] = (SynchronousAxis,)

    def _reinit(self) -> None:
        super()._reinit()
        object.__setattr__(self, "_prev", False)
        object.__setattr__(self, "_sim", None)
        object.__setattr__(self, "_sim_axis", None)

    def _evaluate(self) -> None:
        enable = as_bool(self, "Enable", self.Enable)
        rise = enable and not self._prev
        object.__setattr__(self, "_prev", enable)
        job: Job | None = self._sim
        if job is not None and (rise or not enable):
            # the simulation belongs to the axis it started on; a new Slave acts at the next rising edge
            self._sim_axis.end_simulation(job)
            object.__setattr__(self, "_sim", None)
            job = None
        if not enable:
            self._out(InSimulation=False, Busy=False, Error=False, ErrorID=0)
            return
        if rise:
            try:
                slave = self._axis("Slave")
            except InstructionError as err:
                self._out(InSimulation=False, Busy=False, Error=True, ErrorID=err.error_id)
                return
            job = Job(JobKind.SYNC_SIMULATION, owner=self)
            fault = slave.start_simulation(job)
            if fault is not None:
                self._out(InSimulation=False, Busy=False, Error=True, ErrorID=E.code(fault, self._instruction_name()))
                return
            object.__setattr__(self, "_sim", job)
            object.__setattr__(self, "_sim_axis", slave)
        if job is None:
            return                                  # an earlier error stays shown while Enable is TRUE
        active = job.busy
        self._out(InSimulation=active, Busy=active, Error=False, ErrorID=0)


class MC_LeadingValueAdditive(Instruction):  # noqa: N801
    """Add Position/Velocity/Acceleration to the leading value of a following axis while Enable is TRUE
    (S7-1500T, §3.5, §9.1.7); the values act at once, without dynamic limits."""

    INPUTS = {"Axis": None, "Enable": False, "Position": 0.0, "Velocity": 0.0, "Acceleration": 0.0}
    OUTPUTS = {"Busy": False, "Error": False, "ErrorID": 0}
    AXIS_TYPES: ClassVar[tuple[type, ...]] = (SynchronousAxis,)

    def _reinit(self) -> None:
        super()._reinit()
        object.__setattr__(self, "_prev", False)
        object.__setattr__(self, "_add", None)
        object.__setattr__(self, "_add_axis", None)

    def _stop(self) -> None:
        """End the additive value at the axis it was started on (not at whatever Axis shows now)."""
        job: Job | None = self._add
        if job is not None:
            self._add_axis.end_lv_additive(job)
        object.__setattr__(self, "_add", None)
        object.__setattr__(self, "_add_axis", None)

    def _values(self) -> list[float]:
        values = []
        for name in ("Position", "Velocity", "Acceleration"):
            v = as_real(getattr(self, name))
            if v is None or abs(v) > 1.0e12:
                raise InstructionError(E.parameter(name))
            values.append(v)
        return values

    def _evaluate(self) -> None:
        enable = as_bool(self, "Enable", self.Enable)
        rise = enable and not self._prev
        object.__setattr__(self, "_prev", enable)
        if not enable or rise:
            self._stop()
        if not enable:
            self._out(Busy=False, Error=False, ErrorID=0)
            return
        try:
            if rise:
                # the job belongs to the axis at Axis now; rewiring acts at the next rising edge
                axis = self._axis()
                values = self._values()
                if not axis.ctl.offers_job(JobKind.LV_ADDITIVE):
                    raise InstructionError(E.WRONG_TO)   # a function of the S7-1500T (decisions #56)
                object.__setattr__(self, "_add", Job(JobKind.LV_ADDITIVE, owner=self))
                object.__setattr__(self, "_add_axis", axis)
            elif self._add is None:
                return                              # an earlier error stays shown while Enable is TRUE
            else:
                values = self._values()
        except InstructionError as err:
            self._stop()
            self._out(Busy=False, Error=True, ErrorID=err.error_id)
            return
        job: Job = self._add
        if not job.busy:
            self._out(Busy=False)                   # ended by another job; a new Enable edge restarts
            return
        fault = self._add_axis.set_lv_additive(job, *values)
        if fault is not None:
            object.__setattr__(self, "_add", None)
            object.__setattr__(self, "_add_axis", None)
            self._out(Busy=False, Error=True, ErrorID=E.code(fault, self._instruction_name()))
            return
        self._out(Busy=True, Error=False, ErrorID=0)


__all__ = ["MC_GearIn", "MC_GearInPos", "MC_CamIn", "MC_PhasingRelative", "MC_PhasingAbsolute",
           "MC_SynchronizedMotionSimulation", "MC_LeadingValueAdditive", "dynamic"]
