"""FB 404 MC_Stop and FB 405 MC_Halt (S7-Technology V4.1 §6.2.3, §6.2.4)."""
from __future__ import annotations

import math

from ..kernel import axis_status as S
from ..kernel.jobs import Job, JobKind, JobState
from . import errors as E
from .base import ALL_AXES, ExecuteInstruction, dynamic
from .fb_errors import DYNAMICS_LIMITED
from .technology.axes import AxisT
from .technology.to_errors import W_DYNAMICS_LIMITED

#: MC_Stop: warning "illegal parameter value ignored, default used" (§6.2.3)
W_DEFAULT_USED = 0x0028


def _dyn(axis: AxisT) -> tuple[float, float]:
    e = axis.eff
    return e["userdefaultdynamics.negativeaccel"], e["userdefaultdynamics.positiveaccelstartjerk"]


def _beyond(value: float, maximum: float | None) -> bool:
    """``value`` exceeds a configured maximum (None or 0: none configured; INF jerk: trapezoidal)."""
    return bool(maximum) and math.isfinite(value) and value > maximum


class MC_Stop(ExecuteInstruction):  # noqa: N801 - instruction name of the manual
    """FB 404: brake the axis to standstill and keep every motion command from it while Execute is TRUE
    (also across a disable and enable with MC_Power).

    Done only once the axis stands still and Execute is FALSE (one call); Busy until then.  Only another
    MC_Stop aborts it.  Deceleration / Jerk above 1E12: the maximum of the axis (TypeOfAxis.MaxAcceleration /
    MaxJerk); between the maximum and 1E12: the maximum and warning 16#0021; Deceleration = 0: the default
    deceleration and warning 16#0028 at ErrorID.
    """

    #: a deactivated axis takes no command (§6.7.2); MC_Stop's ErrorID table (§6.2.3) has no 8045: 8044
    DEACTIVATED_ERROR = E.NOT_SUPPORTED_BY_TO

    INPUTS = {"Axis": 0, "Execute": False, "Deceleration": -1.0, "Jerk": -1.0, "DoneFlag": 0}
    TECHNOLOGIES = ALL_AXES

    def _reinit(self) -> None:
        super()._reinit()
        object.__setattr__(self, "_stop", None)
        object.__setattr__(self, "_warning", 0)

    def _start(self, axis: AxisT) -> Job:
        object.__setattr__(self, "_warning", 0)
        self._flag()
        dec_default, jerk_default = _dyn(axis)
        lim = axis.config.limits

        def zero() -> bool:
            object.__setattr__(self, "_warning", W_DEFAULT_USED)
            return True
        dec = dynamic("Deceleration", self.Deceleration, dec_default, zero=zero, above=lim.max_deceleration)
        jerk = dynamic("Jerk", self.Jerk, jerk_default, jerk=True, above=lim.max_jerk)
        if _beyond(dec, lim.max_deceleration) or _beyond(jerk, lim.max_jerk):
            # §6.2.3 ErrorIDs: a value above the configured maximum is cut to it, with warning 0021 (at
            # ErrorID and in the technology DB); a Deceleration = 0 warning 0028 stays the one shown
            if self._warning == 0:
                object.__setattr__(self, "_warning", DYNAMICS_LIMITED)
            axis.errors.note(W_DYNAMICS_LIMITED)
        job = Job(JobKind.STOP, deceleration=dec, jerk=jerk, owner=self)
        axis.submit(job)
        object.__setattr__(self, "_stop", (axis, job))
        return job

    def _completed(self, job: Job) -> bool:
        return job.state == JobState.DONE and bool(job.extra.get("released"))

    def _evaluate(self) -> None:
        super()._evaluate()
        stop = self._stop
        if stop is not None and not self._prev_execute:
            axis, job = stop
            axis.release_stop(job)
            if not job.busy:
                object.__setattr__(self, "_stop", None)

    def _update(self, execute: bool) -> None:
        job = self._job
        if job is not None and self._final is None and job.extra.get("superseded"):
            object.__setattr__(self, "_job", None)
            self._end("CommandAborted")          # another MC_Stop took the axis over (§6.2.3)
        elif job is not None and self._final is None and job.state == JobState.DONE and execute:
            self._set_busy(True)                 # standing still, but Done only after Execute = FALSE
            self._out(ErrorID=self._warning)
            return
        super()._update(execute)

    def _running(self, execute: bool) -> None:
        self._out(ErrorID=self._warning)

    def _show(self, output: str, error_id: int, error_info: int) -> None:
        super()._show(output, error_id or (self._warning if output == "Done" else 0), error_info)


class MC_Halt(ExecuteInstruction):  # noqa: N801
    """FB 405: brake the axis to standstill; a new motion command may take over (Mode 1/2 onto a running
    MC_Halt: 16#8055).  Deceleration = 0 only where the axis stands still already."""

    INPUTS = {"Axis": 0, "Execute": False, "Deceleration": -1.0, "Jerk": -1.0, "DoneFlag": 0}
    TECHNOLOGIES = ALL_AXES

    def _start(self, axis: AxisT) -> Job:
        self._flag()
        dec_default, jerk_default = _dyn(axis)
        dec = dynamic("Deceleration", self.Deceleration, dec_default, zero=lambda: S.standstill(axis)
                      and float(axis.ctl.bank.sp_v[axis.index]) == 0.0)
        jerk = dynamic("Jerk", self.Jerk, jerk_default, jerk=True)
        job = Job(JobKind.HALT, deceleration=dec, jerk=jerk, owner=self)
        axis.submit(job)
        return job


__all__ = ["MC_Stop", "MC_Halt", "W_DEFAULT_USED"]
