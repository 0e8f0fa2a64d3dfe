"""ErrorIDs the S7-Technology instructions show at their ``ErrorID`` output (S7-Technology V4.1 §6.2, §6.7.1;
the common ones of every instruction table).

These are the errors of the first channel (§5.10): the command could not be started.  A command that was
started and then ended by the technology object - an error while it ran, or a check the technology makes
after accepting it (e.g. "axis not homed", §6.8 "abort error") - shows ``CommandAborted`` at the instruction
and its ErrorID in the technology DB (``technology.to_errors``).  :func:`fb_error` says which channel a kernel
fault takes; the refusals of the command interaction (§6.8) take the ErrorIDs ``technology.override`` gives
them (8045, 8055, 8056, 8005 and the warning 0029, which the instruction shows with Error FALSE).
"""
from __future__ import annotations

from ..kernel import faults as F
from ..kernel.faults import Fault
from .technology import override

NO_ERROR = 0x0000
INTERNAL_ERROR = 0x8001              # internal error
COMMAND_MEMORY_FULL = 0x8005         # command canceled, command memory in use (too many commands)
NO_ACTUAL_VALUE = 0x8022             # no actual value at the axis
AXIS_DISABLED = 0x8040               # axis disabled or in the wrong mode
ILLEGAL_PARAMETER = 0x8043           # illegal parameter value
NOT_SUPPORTED_BY_TO = 0x8044         # command not supported by the technology object
NOT_ALLOWED_IN_STATE = 0x8045        # command not allowed in the current state (MC_Stop active, restart running)
CANNOT_ACKNOWLEDGE = 0x8047          # MC_Reset: the error cannot be acknowledged
CANNOT_RESTART = 0x8048              # MC_Reset: restart not possible (axis not disabled)
OUTPUT_RATE_TOO_HIGH = 0x804C        # command output rate too high
INVALID_AXIS_TYPE = 0x804D           # invalid axis type
MISSING_CONNECTION = 0x804A         # required object connection missing (MC_SetCharacteristic)
ONE_INSTANCE_ONLY = 0x804E           # MC_Power: only one active instance per axis
OTHER_AXIS_ENABLED = 0x804F          # MC_Power: disabling an axis this instance did not enable
TECHNOLOGY_NOT_READY = 0x8050        # technology not ready (CPU not in RUN / restart OB)
LATCHING_NOT_ALLOWED = 0x8055        # appending / overlaying not allowed in the current state
END_POS_IGNORED = 0x0029             # warning: MC_MoveToEndPos in reverse direction ignored
CLAMPING_ACTIVE = 0x8056             # cancellation due to active travel to fixed stop
NOT_A_TECHNOLOGY_DB = 0x8083         # the DB at Axis is no technology DB
INVALID_TECHNOLOGY_DB = 0x8084       # invalid technology DB
INVALID_REAL = 0x808B                # parameter value of invalid REAL format

TEXTS = {
    NO_ERROR: "no error",
    INTERNAL_ERROR: "internal error",
    COMMAND_MEMORY_FULL: "command canceled, command memory in use by another process",
    NO_ACTUAL_VALUE: "no actual value at the axis",
    AXIS_DISABLED: "axis disabled or in the wrong mode",
    ILLEGAL_PARAMETER: "illegal parameter value",
    NOT_SUPPORTED_BY_TO: "command not supported by the technology object",
    NOT_ALLOWED_IN_STATE: "command not allowed in the current state",
    CANNOT_ACKNOWLEDGE: "cannot acknowledge this error",
    CANNOT_RESTART: "unable to restart",
    OUTPUT_RATE_TOO_HIGH: "command output rate too high",
    INVALID_AXIS_TYPE: "invalid axis type",
    MISSING_CONNECTION: "required object connection is missing",
    ONE_INSTANCE_ONLY: "only one instance allowed per axis",
    OTHER_AXIS_ENABLED: "the axis was not enabled by this instance",
    TECHNOLOGY_NOT_READY: "technology not ready",
    LATCHING_NOT_ALLOWED: "latching (appending/overlaying) motion not allowed in the current state",
    CLAMPING_ACTIVE: "cancellation due to active travel to fixed stop",
    END_POS_IGNORED: "MC_MoveToEndPos in reverse direction ignored",
    NOT_A_TECHNOLOGY_DB: "DB is not a technology DB",
    INVALID_TECHNOLOGY_DB: "invalid technology DB",
    INVALID_REAL: "parameter value of invalid REAL format",
}

#: rejections the instruction reports itself (the command is not started)
_AT_THE_INSTRUCTION = {
    F.NOT_ENABLED: AXIS_DISABLED, F.PENDING_ALARM: AXIS_DISABLED, F.STOP_ACTIVE: NOT_ALLOWED_IN_STATE,
    F.TOO_MANY_COMMANDS: COMMAND_MEMORY_FULL, F.QUEUE_FULL: COMMAND_MEMORY_FULL,
    F.NOT_APPENDABLE: LATCHING_NOT_ALLOWED, F.SYNC_ACTIVE: LATCHING_NOT_ALLOWED,
    F.NOT_AVAILABLE: NOT_SUPPORTED_BY_TO, F.ALREADY_ENABLED: ONE_INSTANCE_ONLY,
    F.RESTART_IMPOSSIBLE: CANNOT_RESTART,
}
_REJECTED_DETAIL = {"starting_up": TECHNOLOGY_NOT_READY, "position_control_required": AXIS_DISABLED,
                    "actual_invalid": AXIS_DISABLED, "restarting": NOT_ALLOWED_IN_STATE}


def fb_error(fault: Fault) -> int | None:
    """The ErrorID a rejected command shows at its instruction, or None when the technology DB takes it
    (the instruction shows CommandAborted): an axis error, "axis not homed" (8041), a target outside the
    numeric range (8043 in the technology DB)."""
    if fault.ack:
        return None
    code = override.error_id(fault)                      # a refusal of the command interaction (§6.8)
    if code is not None:
        return code
    if fault.kind == F.REJECTED:
        return _REJECTED_DETAIL.get(fault.detail)
    if fault.kind == F.INTERNAL:
        return INTERNAL_ERROR
    if fault.kind in (F.NOT_HOMED,):
        return None
    return _AT_THE_INSTRUCTION.get(fault.kind, NOT_ALLOWED_IN_STATE)


def is_warning(error_id: int) -> bool:
    """An ErrorID the instruction shows with Error FALSE: the command was not executed (§5.10)."""
    return error_id in override.WARNINGS


def describe(error_id: int) -> str:
    """Text of an instruction ErrorID."""
    return TEXTS.get(error_id, f"unknown ErrorID 16#{error_id:04X}")


__all__ = [name for name in dir() if name.isupper()] + ["fb_error", "describe", "is_warning"]
