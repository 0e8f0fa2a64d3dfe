"""FB 403 MC_Home: home or set an axis (S7-Technology V4.1 §6.2.2, configuration §4.5.10).

``Mode``: 0 active homing to the configured reference point coordinate (``userdefaulthoming.homeposition``),
1 active homing to ``Position``, 2 passive homing to ``Position``, 3 direct homing (the position becomes
``Position``), 4 correction of the actual value, 5 absolute encoder adjustment, 6 / 7 correction of the
setpoint in the basic / superimposed coordinate system (each: the position becomes the position minus
``Position``), 8 cancel a passive homing.  Modes 4, 6, 7 keep the homed state (``Statusword.HomingDone``).

Which modes an axis takes (§6.2.2 note): a virtual axis 3, 4, 6, 7 (else 16#804D); an incremental encoder
0-4, 6, 7; an absolute encoder 3-7 (a mode of the other encoder type: 16#8045, plcmotion's choice, the manual
names no code) - the encoder of the data set in force (``technology.encoders``).  Modes 0, 1, 2 need an axis enabled position-controlled (16#8040), 0 and 1 no MC_Stop
(16#8045); 2, 3, 5 not in speed-controlled mode (16#8045); 3, 4, 6, 7 run on a disabled axis too, 5 only on
an axis enabled position-controlled at standstill (16#8045, docs/s7t/decisions.md D78).  No mode while a
parameter change waits for a restart or parameter 4001 collects changes (16#8045).  The active homing
sequences, distance monitoring (16#801D in the technology DB) and the corrections are the kernel's
``reference_approach.ApproachHoming``.
"""
from __future__ import annotations

from ..kernel.jobs import Job, JobKind, JobState
from ..kernel.policy import ABORT
from . import errors as E
from .base import POSITION_AXES, ExecuteInstruction, InstructionError, integer, real
from .technology import coordinates, override, parameter_access
from .technology.axes import AxisT
from .technology.homing_params import ENC, MODE_NO_REFERENCE

ACTIVE, ACTIVE_POSITION, PASSIVE, DIRECT, CORRECT_ACTUAL, ABSOLUTE_ENCODER, CORRECT_BASE, CORRECT_SUPERIMPOSED, \
    CANCEL_PASSIVE = range(9)

#: §6.2.2 note: the modes each kind of axis supports
MODES_VIRTUAL = frozenset({3, 4, 6, 7, 8})
MODES_INCREMENTAL = frozenset({0, 1, 2, 3, 4, 6, 7, 8})
MODES_ABSOLUTE = frozenset({3, 4, 5, 6, 7, 8})
#: EnumToActivationModeSetConfigData of parameter 4001 (§9.4)
COLLECT_CHANGED_CONFIG_DATA = 82
_CORRECTIONS = {CORRECT_ACTUAL: "actual", CORRECT_BASE: "base", CORRECT_SUPERIMPOSED: "superimposed"}


class MC_Home(ExecuteInstruction):  # noqa: N801 - instruction name of the manual
    """FB 403 (see the module docstring)."""

    INPUTS = {"Axis": 0, "Execute": False, "Position": 0.0, "Mode": 0, "DoneFlag": 0}
    TECHNOLOGIES = POSITION_AXES

    def _start(self, axis: AxisT) -> Job:
        position = real("Position", self.Position)
        mode = integer("Mode", self.Mode, range(9))
        self._flag()
        self._check(axis, mode)
        if mode == CANCEL_PASSIVE:
            job = Job(JobKind.HOME_CANCEL, mode=mode, owner=self)
            self._interact(axis, override.HOME_CANCEL, job)
            if not axis.homing.cancel_passive():
                raise InstructionError(E.NOT_ALLOWED_IN_STATE)   # none armed, or it has homed already
            job.finish(JobState.DONE)
            return job
        if mode in (ACTIVE, ACTIVE_POSITION, PASSIVE):
            if mode == ACTIVE:
                position = axis.eff["userdefaulthoming.homeposition"]
            kind = JobKind.HOME_PASSIVE if mode == PASSIVE else JobKind.HOME_ACTIVE
            job = Job(kind, position=position, mode=2 if mode == PASSIVE else 3, owner=self)
            if mode == PASSIVE:
                self._interact(axis, override.HOME_PASSIVE, job)
            axis.home(job)                       # Mode 0/1: the kernel's job start applies the policy
            return job
        job = Job(JobKind.HOME_DIRECT, position=position, mode=mode, owner=self)
        self._interact(axis, override.HOME_SET, job)
        if mode == DIRECT:
            axis.homing.set_position(job)
        elif mode == ABSOLUTE_ENCODER:
            job.mode = 7                         # the kernel's absolute encoder adjustment to Position
            axis.home_direct(job)
            if job.state == JobState.DONE:
                # the stored offset is to the encoder's absolute value, whatever corrected the actual value
                # before (a synchronized encoder changeover, Modes 3/4): §3.1.9
                axis.abs_offset = float(axis.ctl.bank.act_p[axis.index]) - axis.homing.absolute_raw()
                axis.ctl._retain_axis(axis)
        else:
            # §6.2.2 notice: an axis in following mode corrects Mode 7 in the basic coordinate system
            layer = "base" if mode == CORRECT_SUPERIMPOSED and axis.following_mode else _CORRECTIONS[mode]
            axis.homing.correct(job, layer)
            coordinates.transfer_at_standstill(axis)     # TRANSFER_STANDSTILL takes a Mode 7 over at rest
        return job

    def _interact(self, axis: AxisT, new: str, job: Job) -> None:
        """§6.8 for the modes that start no kernel job (2, 3-7, 8): the policy's refusal (its ErrorID), else
        the activities it aborts end with CommandAborted.  An aborted active homing would leave its approach
        motion running without a job, so the axis brakes with the configured deceleration (an MC_Halt of
        its own, which the policy lets abort the homing; docs/s7t/decisions.md D26, D65)."""
        reject = override.refusal(new, axis._activities(), job)
        if reject is not None:
            code = E.fb_error(reject.fault())
            raise InstructionError(E.NOT_ALLOWED_IN_STATE if code is None else code)
        running = axis.job
        if running is not None and running.busy and running.kind == JobKind.HOME_ACTIVE \
                and override.POLICY.cell(new, override.HOME_ACTIVE) is ABORT:
            brake = Job(JobKind.HALT)
            axis.submit(brake)
            if brake.state == JobState.ERROR:            # the axis cannot brake: leave the homing running
                raise InstructionError(E.NOT_ALLOWED_IN_STATE)
        if new != override.HOME_CANCEL:          # Mode 8 ends its passive homing itself (cancel_passive)
            axis._override(new, axis.now, job)

    def _check(self, axis: AxisT, mode: int) -> None:
        """The §6.2.2 restrictions of ``mode`` on this axis, in the order the manual lists them."""
        if axis.virtual:
            supported = MODES_VIRTUAL
        else:
            supported = MODES_ABSOLUTE if axis.absolute_encoder() else MODES_INCREMENTAL
        if mode not in supported:
            raise InstructionError(E.INVALID_AXIS_TYPE if axis.virtual else E.NOT_ALLOWED_IN_STATE)
        if axis.restarting or axis.restart_requested or _collecting(axis):
            # §6.2.2: a parameter change waits for a restart (MC_WriteParameter gave 0020), or parameter
            # 4001 collects the changes (COLLECT_CHANGED_CONFIG_DATA): 8045
            raise InstructionError(E.NOT_ALLOWED_IN_STATE)
        enabled = axis.state == "enabled" and not axis.following_mode
        speed_mode = not axis.position_controlled
        if mode in (ACTIVE, ACTIVE_POSITION, PASSIVE) and not enabled:
            raise InstructionError(E.AXIS_DISABLED)
        if mode in (ACTIVE, ACTIVE_POSITION):
            if speed_mode:
                raise InstructionError(E.AXIS_DISABLED)         # position-controlled operation needed
            if axis.stop_job is not None:
                raise InstructionError(E.NOT_ALLOWED_IN_STATE)  # MC_Stop active
            if axis.eff[f"{ENC}.homingMode"] == MODE_NO_REFERENCE:
                raise InstructionError(E.NOT_ALLOWED_IN_STATE)  # no active homing configured
        if mode in (PASSIVE, DIRECT, ABSOLUTE_ENCODER) and speed_mode and axis.state == "enabled":
            raise InstructionError(E.NOT_ALLOWED_IN_STATE)      # not in speed-controlled mode
        if mode == ABSOLUTE_ENCODER:
            # §6.2.2 Mode 5: at standstill and position-controlled (8045 "absolute encoder adjustment while
            # not position-controlled", D78); §3.1.9: not while the software limit switches act
            controlled = enabled and not speed_mode
            if not controlled or not axis.ctl.bank.standstill[axis.index] or axis.sw_limits_effective():
                raise InstructionError(E.NOT_ALLOWED_IN_STATE)


def _collecting(axis: AxisT) -> bool:
    """Parameter 4001 (activationmodechangedconfigdata) is COLLECT_CHANGED_CONFIG_DATA."""
    code, _, value = parameter_access.read(axis, 4001, 1)
    return code == 0 and value == COLLECT_CHANGED_CONFIG_DATA


__all__ = ["MC_Home", "MODES_VIRTUAL", "MODES_INCREMENTAL", "MODES_ABSOLUTE"]
