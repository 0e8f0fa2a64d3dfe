"""The error channel of a technology object: ErrorID, ErrorBuffer and ErrorStatus of its technology DB
(S7-Technology V4.1 §5.12, §7.1, §7.12).

Errors and warnings that arise while a technology object runs go to its technology DB, not to an
instruction: ``ErrorID`` (the latest error 8xxx or warning 00xx), ``ErrorBuffer`` (the first three since the
last acknowledgement, element 0 the first; later ones are not kept) and the ``ErrorStatus`` bit of the cause.
MC_Reset (Restart = FALSE) clears them once their cause is gone.  The manual says these members change
independently of the DB update clock (§7.11); here they change at the moment the error is noted (decision
of issue 11), so a program reading ``axis.db.ErrorID`` sees it at once.

:func:`tdb_error` maps a kernel fault to its §7.12 ErrorID and ErrorStatus bit.
"""
from __future__ import annotations

from ...kernel import faults as F
from ...kernel.faults import Fault
from .tdb_error_texts import TEXTS

# --- ErrorIDs of the axis technology DB (§7.12.1) used by this package ----------------------------------
INTERNAL = 0x8002
CONFIGURATION = 0x8004
COMMAND_MEMORY_FULL = 0x8005
DRIVE_FAILED = 0x8010
HOMING = 0x8012
HW_LIMIT_SWITCH = 0x8013
SW_LIMIT_REACHED = 0x8014
SW_LIMIT_OVERSHOT = 0x8015
FOLLOWING_ERROR = 0x8016
STANDSTILL = 0x8018
POSITIONING = 0x8019
CLAMPING = 0x801B
DYNAMIC_LIMITS = 0x801C
REFERENCE_NOT_FOUND = 0x801D
ACTUAL_VALUE = 0x8031
DISABLED = 0x8040
NOT_HOMED = 0x8041
ILLEGAL_PARAMETER = 0x8043
NOT_ALLOWED = 0x8045
LIMIT_SWITCH_COMMAND = 0x804B
LEADING_AXIS = 0x8074
END_LIMITS = 0x8085
# warnings (Statusword.Error stays FALSE)
W_RESTART = 0x0020
W_DYNAMICS_LIMITED = 0x0021
W_SW_LIMIT = 0x0026

#: the kernel fault kind of the clamping monitoring (MC_MoveToEndPos, §4.5.7.5): 16#801B
CLAMPING_FAULT = "clamping"

# --- ErrorStatus bits (§7.1) ----------------------------------------------------------------------------
ERROR_STATUS_BITS = {
    "SystemFault": 0, "ConfigFault": 1, "UserFault": 2, "FaultDrive": 3, "Reserve4": 4, "FollowingWarning": 5,
    "FollowingError": 6, "StandstillFault": 7, "PositioningError": 8, "SynchronOpError": 9, "DynamicError": 10,
    "ClampingError": 11, "SoftwareLimitPos": 12, "SoftwareLimitNeg": 13, "LimitSwitchActive": 14,
    "SensorFreqViolation": 15, "ReferenceNotFound": 16, "ZeroMonitoring": 17, "Overspeed": 18,
    "FollowObjectError": 19, "SupImpFollowObjectError": 20}
_B = ERROR_STATUS_BITS

#: axis alarms of the kernel: (ErrorID, ErrorStatus bit or None)
_ALARMS: dict[str, tuple[int, int | None]] = {
    F.INTERNAL: (INTERNAL, _B["SystemFault"]),
    F.CONFIG: (CONFIGURATION, _B["ConfigFault"]),
    F.SW_LIMIT_ORDER: (END_LIMITS, _B["ConfigFault"]),
    F.DRIVE_NOT_READY: (DRIVE_FAILED, _B["FaultDrive"]),
    F.DRIVE_ALARM: (DRIVE_FAILED, _B["FaultDrive"]),
    F.ENCODER: (ACTUAL_VALUE, _B["FaultDrive"]),
    F.POSITION_RANGE: (ACTUAL_VALUE, _B["FaultDrive"]),
    F.HW_LIMIT_MIN: (HW_LIMIT_SWITCH, _B["LimitSwitchActive"]),
    F.HW_LIMIT_MAX: (HW_LIMIT_SWITCH, _B["LimitSwitchActive"]),
    F.HW_LIMIT_FREE: (LIMIT_SWITCH_COMMAND, _B["LimitSwitchActive"]),
    F.FOLLOWING_ERROR: (FOLLOWING_ERROR, _B["FollowingError"]),
    F.REFERENCE_NOT_FOUND: (REFERENCE_NOT_FOUND, _B["ReferenceNotFound"]),
    F.HOMING_APPROACH_ZERO: (HOMING, _B["ConfigFault"]),
    F.HOMING_REFERENCING_ZERO: (HOMING, _B["ConfigFault"]),
    F.DIRECTION: (DYNAMIC_LIMITS, _B["DynamicError"]),
    F.SYNC_MASTER: (LEADING_AXIS, _B["SynchronOpError"]),
    F.LV_INVALID: (LEADING_AXIS, _B["SynchronOpError"]),
    CLAMPING_FAULT: (CLAMPING, _B["ClampingError"]),
}

#: a command that was accepted but could not be carried out (e.g. an appended one whose turn came while the
#: axis was no longer enabled): §6.8 "abort error", the ErrorID goes to the technology DB
_REJECTIONS: dict[str, int] = {
    F.NOT_ENABLED: DISABLED, F.NOT_HOMED: NOT_HOMED, F.TOO_MANY_COMMANDS: COMMAND_MEMORY_FULL,
    F.QUEUE_FULL: COMMAND_MEMORY_FULL, F.HW_LIMIT_FREE: LIMIT_SWITCH_COMMAND,
}


def tdb_error(fault: Fault) -> tuple[int, int | None]:
    """(ErrorID, ErrorStatus bit) of a kernel fault in the technology DB (§7.12.1)."""
    if fault.ack:
        if fault.kind in (F.SW_LIMIT_MIN, F.SW_LIMIT_MAX):
            bit = _B["SoftwareLimitNeg"] if fault.kind == F.SW_LIMIT_MIN else _B["SoftwareLimitPos"]
            return (SW_LIMIT_OVERSHOT if fault.detail == "exceeded" else SW_LIMIT_REACHED), bit
        if fault.kind == F.POSITIONING:
            return (STANDSTILL, _B["StandstillFault"]) if fault.detail == "left" else \
                (POSITIONING, _B["PositioningError"])
        return _ALARMS.get(fault.kind, (INTERNAL, _B["SystemFault"]))
    if fault.kind == F.REJECTED and fault.detail == "numeric_limit":
        return ILLEGAL_PARAMETER, _B["UserFault"]
    return _REJECTIONS.get(fault.kind, NOT_ALLOWED), _B["UserFault"]


def describe_fault(fault: Fault) -> str:
    """How summaries name a kernel fault of an S7-Technology object: its technology DB ErrorID."""
    error_id, _bit = tdb_error(fault)
    kind = "warning" if is_warning(error_id) else "error"
    return f"technology DB {kind} 16#{error_id:04X} ({fault})"


def error_view(to: object) -> list[str]:
    """What a summary (``plcmotion run``) shows for a technology object: the error channel of its technology
    DB - ErrorID with its message and the ErrorBuffer - which holds errors and warnings that need no kernel
    alarm (an "abort error" of a command, 8017, a kept 8013 after MC_Reset); without an entry there, the
    object's alarms."""
    record = getattr(to, "errors", None)
    if isinstance(record, ErrorRecord) and record.error_id:
        code = record.error_id
        kind = "warning" if is_warning(code) else "error"
        text = TEXTS.get(code)
        message = f' "{text.message}"' if text is not None else ""
        buffer = ", ".join(f"16#{c:04X}" for c in record.buffer)
        return [f"technology DB {kind} 16#{code:04X}{message} (ErrorBuffer {buffer})"]
    return [f"{describe_fault(a)} [{a}]" for a in getattr(to, "alarms", ())]


def is_warning(error_id: int) -> bool:
    """Warnings are 00xx, errors 8xxx (§5.12)."""
    return error_id < 0x8000


class ErrorRecord:
    """ErrorID, ErrorBuffer[0..2] and ErrorStatus of one technology DB, and whether an error (not only a
    warning) is pending since the last acknowledgement (``Statusword.Error``)."""

    __slots__ = ("error_id", "buffer", "status", "error")

    def __init__(self) -> None:
        self.clear()

    def clear(self) -> None:
        self.error_id = 0
        self.buffer: list[int] = []
        self.status = 0
        self.error = False

    def note(self, error_id: int, bit: int | None = None) -> None:
        """An error or warning occurred: it is the latest, and one of the first three if there is room."""
        self.error_id = error_id
        if len(self.buffer) < 3:
            self.buffer.append(error_id)
        if not is_warning(error_id):
            self.error = True
            if bit is not None:
                self.status |= 1 << bit

    def error_buffer(self) -> list[int]:
        """ErrorBuffer[0..2] as the DB shows it: the first three, 0 where none."""
        return self.buffer + [0] * (3 - len(self.buffer))


__all__ = ["ErrorRecord", "tdb_error", "describe_fault", "error_view", "is_warning", "ERROR_STATUS_BITS"]
