"""FB 401 MC_Power and FB 402 MC_Reset (S7-Technology V4.1 §6.2.1, §6.7.1)."""
from __future__ import annotations

from typing import Any

from ..kernel.faults import Reaction
from ..kernel.jobs import Job, JobKind, JobState
from . import errors as E
from .base import ALL_AXES, ExecuteInstruction, Instruction, InstructionError, as_bool, integer, real
from .technology.axes import (DEFAULT_STOP, FAST_STOP, GEAR_STOP, OFF2_STOP, QUICK_STOP, RAMP_STOP, TIME_STOP,
                              AxisT)
from .technology import coordinates, override
from .technology.device import TechnologyDevice

#: MC_Power Mode (§6.2.1): 0 default, 1 speed-controlled, 2 following mode with the power unit enabled,
#: 3 following mode with the power unit disabled, 4 simulation, 5 position-controlled
DEFAULT_MODE, SPEED_CONTROLLED, FOLLOWING_ENABLED, FOLLOWING_DISABLED, SIMULATION, POSITION_CONTROLLED = range(6)


def modes(axis: AxisT) -> tuple[int, ...]:
    """The Mode values an axis takes: a virtual axis only 0, a real one also simulation (4) (§6.2.1 table)."""
    if axis.virtual:
        return (DEFAULT_MODE,)
    if not axis.positioning:
        return (DEFAULT_MODE, SPEED_CONTROLLED, FOLLOWING_ENABLED, FOLLOWING_DISABLED, SIMULATION)
    return (DEFAULT_MODE, SPEED_CONTROLLED, FOLLOWING_ENABLED, FOLLOWING_DISABLED, SIMULATION, POSITION_CONTROLLED)


def stop_modes(axis: AxisT) -> tuple[int, ...]:
    """StopMode values: 3 (OFF2) on hydraulic axes only, 5 and 6 (the drive's ramps) on real electric axes."""
    out = [DEFAULT_STOP, FAST_STOP, TIME_STOP, GEAR_STOP]
    if axis.hydraulic:
        out.append(OFF2_STOP)
    elif not axis.virtual:
        out += [RAMP_STOP, QUICK_STOP]
    return tuple(sorted(out))


class MC_Power(Instruction):  # noqa: N801 - instruction name of the manual
    """FB 401: enable or disable an axis (level-triggered ``Enable``).

    ``Mode`` 4 (simulation, real axes, §3.1.2): the axis is enabled without enabling its drive; its actual
    values are its setpoints (following error 0) and the machine stands still (``Statusword.Simulation``).
    Disabling ends it; from then on the actual values are the encoder's again (docs/s7t/decisions.md D81).

    ``Mode`` is taken at the rising edge of Enable, ``StopMode`` and ``QOutputValue`` at both edges (an
    invalid value at the falling edge shows its ErrorID for one call and the value of the rising edge is
    used).  ``Status``: the axis is enabled by this instance and no error stops it (``Statusword.Error`` and
    ``Errorstop``); the errors of the axis are in its technology DB, not here.  A second instance enabling
    the same axis gets 16#804E; disabling from an instance whose Axis input names another axis than the
    one it enabled, 16#804F (the enabled axis stays enabled).
    """

    INPUTS = {"Axis": 0, "Enable": False, "Mode": 0, "StopMode": 0, "QOutputValue": 0.0, "FOutputValue": 0.0}
    OUTPUTS = {"Status": False, "Busy": False, "Error": False, "ErrorID": 0}
    TECHNOLOGIES = ALL_AXES

    def _reinit(self) -> None:
        super()._reinit()
        for name, value in (("_prev", False), ("_mode", 0), ("_stop", 0), ("_edge_error", 0), ("_enabled", None),
                            ("_to", None)):
            object.__setattr__(self, name, value)

    def _evaluate(self) -> None:
        enable = as_bool(self, "Enable", self.Enable)
        rise, fall = enable and not self._prev, self._prev and not enable
        object.__setattr__(self, "_prev", enable)
        mine = self._enabled
        try:
            axis = self._axis()
        except InstructionError as err:
            if fall and mine is not None and mine.power_owner is self:
                err = InstructionError(E.OTHER_AXIS_ENABLED)
            self._show(None, enable, err.error_id)
            return
        if fall and mine is not None and mine is not axis and mine.power_owner is self:
            self._show(None, False, E.OTHER_AXIS_ENABLED)          # only the axis it enabled may it disable
            return
        if rise:
            object.__setattr__(self, "_edge_error", self._take_edge(axis))
        one_call = 0
        if fall:
            one_call = self._take_stop(axis, fall=True)
        if enable and self._edge_error:
            self._show(axis, enable, self._edge_error)            # a new rising edge tries again
            return
        reject = self._power(axis, enable, rise)
        if axis.power_owner is self:
            object.__setattr__(self, "_enabled", axis)
        elif mine is axis:
            object.__setattr__(self, "_enabled", None)
        if reject:
            self._show(axis, enable, reject)
        else:
            self._show(axis, enable, one_call)

    def _take_edge(self, axis: AxisT) -> int:
        """Mode, StopMode and QOutputValue at the rising edge: 0 or the ErrorID of an invalid one."""
        try:
            mode = integer("Mode", self.Mode, modes(axis))
            err = self._take_stop(axis)
            if err:
                return err
        except InstructionError as exc:
            return exc.error_id
        object.__setattr__(self, "_mode", mode)
        if axis.power_owner is None or axis.power_owner is self:
            axis.following_mode = mode == FOLLOWING_ENABLED
            axis.simulation_requested = mode == SIMULATION  # read when the axis is enabled (also after MC_Reset)
            if mode in (FOLLOWING_ENABLED, FOLLOWING_DISABLED):
                coordinates.transfer(axis, "following")     # §6.2.2 Mode 7 notes: following mode
        return 0

    def _take_stop(self, axis: AxisT, fall: bool = False) -> int:
        try:
            stop = integer("StopMode", self.StopMode, stop_modes(axis))
            q = real("QOutputValue", self.QOutputValue)
            if not -100.0 <= q <= 100.0:
                raise InstructionError(E.ILLEGAL_PARAMETER)
        except InstructionError as exc:
            if fall and exc.error_id == E.ILLEGAL_PARAMETER and self.StopMode in stop_modes(axis):
                return E.INVALID_REAL      # an invalid QOutputValue at the falling edge: 808B, one call
            return exc.error_id
        object.__setattr__(self, "_stop", stop)
        if axis.power_owner is None or axis.power_owner is self:
            axis.q_output_value = q
        return 0

    def _power(self, axis: AxisT, enable: bool, rise: bool) -> int:
        """Hand Enable to the axis; an ErrorID when it refuses."""
        if self._mode == FOLLOWING_DISABLED:
            # following mode with the power unit disabled: the axis stays disabled, its actual values follow
            owner = axis.power_owner
            if enable:
                if owner is not None and owner is not self:
                    return E.ONE_INSTANCE_ONLY
                if axis.state != "disabled":
                    axis.power(self, False, 0, self._stop)
                axis.power_owner = self
            elif owner is self and axis.state == "disabled":
                axis.power_owner = None
            return 0
        if enable == (axis.state == "disabled"):
            # enabling or disabling is a command of table 3 of §6.8 (refused while the object restarts)
            refusal = override.refusal(override.POWER_ON if enable else override.POWER_OFF, axis._activities())
            if refusal is not None:
                code = E.fb_error(refusal.fault())
                return E.NOT_ALLOWED_IN_STATE if code is None else code
        mode = self._mode
        start = 1 if mode == POSITION_CONTROLLED or (
            mode in (DEFAULT_MODE, SIMULATION) and axis.positioning and axis.position_controlled) else 0
        stop = self._stop
        if not enable and getattr(axis, "torque_limiting_command", False) and not axis.virtual:
            stop = RAMP_STOP       # torque reduction active: StopMode ignored, the drive's own ramp (§6.2.1)
        fault = axis.power(self, enable, start, stop)
        if fault is None:
            return 0
        code = E.fb_error(fault)
        return E.INTERNAL_ERROR if code is None else code

    def _show(self, axis: AxisT | None, enable: bool, error_id: int) -> None:
        if axis is None:
            status, busy = False, enable
        else:
            owner = axis.power_owner is self
            stopped = axis.errors.error and any(a.reaction != Reaction.NONE for a in axis.alarms)
            status = owner and axis.state in ("enabled", "disabling") and not stopped
            busy = enable or (owner and axis.state == "disabling")
        self._out(Status=status, Busy=busy, Error=error_id != 0, ErrorID=error_id)


class MC_Reset(ExecuteInstruction):  # noqa: N801
    """FB 402: acknowledge the errors of a technology object (Restart = FALSE) or restart it with its
    configured values (Restart = TRUE, only while it is disabled; it takes no commands until the restart
    is over).  With the MCDevice DB: MaxLoopDuration and TODBTaskOverflows are reset (§7.10)."""

    INPUTS = {"Axis": 0, "Execute": False, "Restart": False}
    TECHNOLOGIES = ALL_AXES
    TAKES_MCDEVICE = True

    def _start(self, to: Any) -> Job:
        restart = as_bool(self, "Restart", self.Restart)
        job = Job(JobKind.RESET, owner=self)
        if isinstance(to, TechnologyDevice):
            to.reset_mcdevice()
            job.finish(JobState.DONE)
            return job
        refusal = override.refusal(override.RESTART if restart else override.RESET, to._activities())
        if refusal is not None:                                  # a restart runs (§6.7.1, §6.8.3): 8045
            raise InstructionError(E.fb_error(refusal.fault()) or E.NOT_ALLOWED_IN_STATE)
        if restart:
            if to.begin_restart() is not None:
                raise InstructionError(E.CANNOT_RESTART)
            job.extra["restart"] = to
            return job
        if to.acknowledge() is not None:
            raise InstructionError(E.CANNOT_ACKNOWLEDGE)
        job.finish(JobState.DONE)
        return job

    def _update(self, execute: bool) -> None:
        job = self._job
        if job is not None and job.busy and not job.extra["restart"].restarting:
            job.finish(JobState.DONE)
        super()._update(execute)


__all__ = ["MC_Power", "MC_Reset", "modes", "stop_modes"]
