"""FB 415 MC_MoveToEndPos: travel to a fixed end stop and clamp there (S7-Technology V4.1 §6.2.11, §4.5.7.5).

The command is a position-controlled motion at ``Velocity`` in its direction, with the drive torque limited to
``Torque`` [N m] and the following error monitoring off.  The fixed end stop is detected by the configured
``ClampingMonitoring.recognitionMode`` (parameter 2012): 106 when the following error reaches
``followingErrorDeviation`` (2010), 107 when the drive gives its full (limited) torque.  Then the motion
stops and the setpoint is held: at "position at the end stop + following error" (106) or "+ clamping
tolerance" (107), so the drive keeps pressing with the limited torque; the command stays Busy with
``InClamping`` TRUE while the actual position is within ``positionTolerance`` (2011) of where it clamped.
Leaving that window without a new motion command is the clamping monitoring error 16#801B (ErrorStatus
bit ClampingError, the axis is stopped and disabled as for the other monitoring errors).

The override policy (``technology.override``) decides what new commands do: away from the stop they abort
MC_MoveToEndPos, towards it 16#8056, a reversing MC_MoveToEndPos 16#8045 (clamped) or warning 16#0029
(before the stop).  For it the job carries ``extra["fb"]``, ``extra["heading"]`` (+1/-1),
``extra["clamped"]`` and ``target`` = the actual position where it clamped.  After a release the torque
limit stays until the setpoint has left the clamping window on the side away from the stop (§6.2.11
example c), then MC_SetTorqueLimit's limit (or none) is back and the following error is monitored again.

Real electric axes only (virtual or hydraulic: 16#804D); the drive needs a telegram with torque reduction
(101-106) and Torque must not exceed the torque reference ``maxTorque`` (else 16#8043).
"""
from __future__ import annotations

import weakref
from typing import Any

from ..kernel.faults import Reaction, alarm
from ..kernel.jobs import Job, JobKind
from ..kernel.policy import Activity
from ..kernel.profiles import Planner
from . import errors as E
from .base import InstructionError, integer, real
from .move import _K_NEGATIVE, _Move, _default_direction
from .technology import override as O
from .technology.axes import AxisT
from .technology.datasets import in_force
from .technology.hydraulic_params import (CLAMP_BY_FOLLOWING_ERROR_DEVIATION, CLAMP_WHEN_TORQUE_LIMIT_REACHED,
                                          FE_DEVIATION, MAX_TORQUE, POSITION_TOLERANCE, RECOGNITION_MODE,
                                          TORQUE_TELEGRAMS)
from .technology.to_errors import CLAMPING_FAULT


def _nothing(t: float) -> None:
    """Ending the released clamping activity: its command has ended already."""


class _Watch:
    """One axis's MC_MoveToEndPos from its start until the torque limit is given back."""

    __slots__ = ("axis", "job", "torque", "clamp")

    def __init__(self, axis: AxisT, job: Job, torque: float):
        self.axis, self.job, self.torque = axis, job, torque
        self.clamp: float | None = None            # actual position where the end stop was detected

    def tolerance(self) -> float:
        return float(in_force(self.axis.eff, POSITION_TOLERANCE))     # of the data set in force

    def step(self, t: float) -> bool:
        """One servo cycle; FALSE when the watch is over."""
        ax, job = self.axis, self.job
        b, i = ax.ctl.bank, ax.index
        if job.busy and b.fe_on[i]:
            b.fe_on[i] = False                     # no following error monitoring while it runs (§4.5.7.5)
            ax.ctl._n_fe -= 1
        if self.clamp is None:
            if not job.busy:
                return False
            if job.active and self._detected(float(b.fe[i])):
                self._clamp(t)
            return True
        if job.busy:
            if abs(float(b.act_p[i]) - self.clamp) > self.tolerance():
                # the end stop gave way, or the axis was pushed off, without a new motion command
                ax.raise_alarm(alarm(CLAMPING_FAULT, "left", Reaction.REMOVE_ENABLE), job)
            return True
        # released: the torque limit stays, and commands toward the stop are refused, until the setpoint has
        # left the clamping window on the side away from the stop (until then the drive still presses on it)
        back = job.extra["heading"] * (float(b.sp_p[i]) - self.clamp)
        inside = ax.state == "enabled" and back >= -self.tolerance()
        ax.releasing_clamp = Activity(O.CLAMPED, job, _nothing) if inside else None
        return inside

    def _detected(self, fe: float) -> bool:
        mode = self.axis.eff[RECOGNITION_MODE]
        heading = self.job.extra["heading"]
        if mode == CLAMP_BY_FOLLOWING_ERROR_DEVIATION:
            return fe * heading >= in_force(self.axis.eff, FE_DEVIATION)
        return mode == CLAMP_WHEN_TORQUE_LIMIT_REACHED and self.axis.drive.torque_limit_active

    def _clamp(self, t: float) -> None:
        ax, job = self.axis, self.job
        b, i = ax.ctl.bank, ax.index
        act = float(b.act_p[i])
        held = float(b.sp_p[i])
        if ax.eff[RECOGNITION_MODE] == CLAMP_WHEN_TORQUE_LIMIT_REACHED:
            held = act + job.extra["heading"] * self.tolerance()
        self.clamp = act
        job.target = act
        job.extra["clamped"] = True
        job.extra["hold_zero"] = True             # a held velocity job is not done at its profile's end
        job.in_velocity = job.reached_once = True
        ax._start_profile(Planner.hold(t, held))

    def end(self) -> None:
        """Give the torque back to MC_SetTorqueLimit's limit (or none) and monitor the following error."""
        from .drive_functions import torque_limit
        ax = self.axis
        ax.releasing_clamp = None
        limit = torque_limit(ax)
        ax.drive.set_torque_limit(limit)
        ax.torque_limiting_command = limit is not None
        ax._set_loop_flags()


class _Watcher:
    """The active MC_MoveToEndPos commands of one controller, stepped before every servo cycle while any."""

    def __init__(self, ctl: Any):
        self.ctl = ctl
        self.watches: dict[int, _Watch] = {}
        self.hooked = False

    def add(self, watch: _Watch) -> None:
        self.watches[watch.axis.index] = watch     # a new command replaces the axis's watch (same direction)
        if not self.hooked:
            self.ctl.on_pre_servo(self.step)
            self.hooked = True

    def step(self, t: float) -> None:
        for index, watch in list(self.watches.items()):
            try:
                going = watch.step(t)
                if not going:
                    del self.watches[index]
                    watch.end()
            except Exception as exc:  # noqa: BLE001 - a defect stops only that axis (16#8FFF)
                self.watches.pop(index, None)
                watch.axis._internal_error(exc)
        if not self.watches:
            self.ctl.remove_hook(self.step)
            self.hooked = False


_WATCHERS: "weakref.WeakKeyDictionary[Any, _Watcher]" = weakref.WeakKeyDictionary()


def _watcher(ctl: Any) -> _Watcher:
    w = _WATCHERS.get(ctl)
    if w is None:
        w = _WATCHERS[ctl] = _Watcher(ctl)
    return w


def watch_of(axis: AxisT) -> _Watch | None:
    """The axis's MC_MoveToEndPos (running, clamped or releasing), None when there is none."""
    w = _WATCHERS.get(axis.ctl)
    return None if w is None else w.watches.get(axis.index)


class MC_MoveToEndPos(_Move):  # noqa: N801 - instruction name of the manual
    """FB 415: move in ``Direction`` (0 the configured default, 1 positive, 3 negative, 4 the current
    direction; 2 is not permitted) at ``Velocity`` (no default: 0.0 is 16#8043) against a fixed end stop and
    clamp there with ``Torque`` [N m].  ``InClamping``: the end stop is reached and the axis is within the
    clamping tolerance window.  No Done: the command stays Busy while it clamps."""

    INPUTS = {"Axis": 0, "Execute": False, "Direction": 0, "Torque": 1.0, "Velocity": 0.0, "Acceleration": -1.0,
              "Deceleration": -1.0, "Jerk": -1.0, "DoneFlag": 0}
    OUTPUTS = {"InClamping": False, "Busy": False, "CommandAborted": False, "Error": False, "ErrorID": 0}

    def _start(self, axis: AxisT) -> Job:
        direction = integer("Direction", self.Direction, (0, 1, 3, 4))
        torque = real("Torque", self.Torque)
        dyn = self._dynamics(axis)
        self._flag()
        if axis.virtual or axis.hydraulic:
            raise InstructionError(E.INVALID_AXIS_TYPE)
        cfg = axis.eff
        if (torque <= 0.0 or torque > cfg[MAX_TORQUE] or cfg[RECOGNITION_MODE] not in (
                CLAMP_BY_FOLLOWING_ERROR_DEVIATION, CLAMP_WHEN_TORQUE_LIMIT_REACHED)
                or axis.cfg["Wizard.Telegram"] not in TORQUE_TELEGRAMS):
            raise InstructionError(E.ILLEGAL_PARAMETER)
        if axis.state == "enabled" and not axis.position_controlled:
            raise InstructionError(E.AXIS_DISABLED)            # needs position control (§6.2.11)
        if direction == 0:
            heading = -1 if _default_direction(axis) == _K_NEGATIVE else 1
        else:
            heading = {1: 1, 3: -1, 4: 1 if axis.last_direction > 0 else -1}[direction]
        job = Job(JobKind.VELOCITY, velocity=heading * dyn["velocity"], acceleration=dyn["acceleration"],
                  deceleration=dyn["deceleration"], jerk=dyn["jerk"], owner=self, position_controlled=True)
        job.extra.update(fb=O.MOVE_TO_END_POS, heading=heading)
        axis.submit(job, axis.policy.buffer_mode(0))
        if job.busy:
            axis.drive.set_torque_limit(torque)
            axis.torque_limiting_command = True
            _watcher(axis.ctl).add(_Watch(axis, job, torque))
        return job

    def _running(self, execute: bool) -> None:
        job = self._job
        watch = watch_of(self._to) if isinstance(self.__dict__.get("_to"), AxisT) else None
        clamped = (job is not None and watch is not None and watch.job is job and watch.clamp is not None
                   and abs(float(watch.axis.ctl.bank.act_p[watch.axis.index]) - watch.clamp) <= watch.tolerance())
        self._out(InClamping=clamped)


__all__ = ["MC_MoveToEndPos", "watch_of"]
