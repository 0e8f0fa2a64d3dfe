"""The monitoring functions of an axis in its technology DB: which ErrorIDs and ErrorStatus bits a kernel
monitoring fault gives, and how the axis reacts (S7-Technology V4.1 §3.5 of the catalog, §4.5.7, §4.5.10,
§4.5.11, §7.1, §7.12.1).

The manual's error tables name the error and its cause but no reaction column; the reactions below are the
kernel's for each fault and are plcmotion's decision where the manual only says "the axis is stopped":

======= =============================================== ==================== ===================================
ErrorID message                                         ErrorStatus bit      reaction
======= =============================================== ==================== ===================================
0026    position limited to software limit switch       -                    warning; the axis travels on
8013    hardware limit switch is active                 LimitSwitchActive    enable removed (the drive brakes)
804B    limit switch active; invalid command            LimitSwitchActive    comes with 8013
8014    software limit switch actuated                  SoftwareLimitPos/Neg the axis stops at the switch
8015    software limit switch overshot                  SoftwareLimitPos/Neg enable removed
8016    following error out of limits                   FollowingError       enable removed
8017    following error has exceeded the warning limit  FollowingWarning     none: the axis goes on
8018    standstill monitoring error                     StandstillFault      enable removed
8019    positioning monitoring error                    PositioningError     enable removed
801D    reference cam or encoder zero mark not found    ReferenceNotFound    homing ends, the axis brakes (stop)
======= =============================================== ==================== ===================================

A hardware limit switch gives two entries at once (§4.5.7.2: "stopped with error messages 8013 and 804B").
All other faults keep the core's mapping (``to_errors.tdb_error``).
"""
from __future__ import annotations

from typing import Any

from ...kernel import faults as F
from ...kernel.faults import Fault, Reaction
from ...kernel.jobs import Job, JobKind
from .to_errors import ERROR_STATUS_BITS as B
from .to_errors import tdb_error

HW_LIMIT_SWITCH = 0x8013
SW_LIMIT_REACHED = 0x8014
SW_LIMIT_OVERSHOT = 0x8015
FOLLOWING_ERROR = 0x8016
FOLLOWING_WARNING = 0x8017
SW_LIMIT_WARNING = 0x0026
STANDSTILL = 0x8018
POSITIONING = 0x8019
REFERENCE_NOT_FOUND = 0x801D
LIMIT_SWITCH_COMMAND = 0x804B

_POSITIONINGS = (JobKind.ABSOLUTE, JobKind.RELATIVE)

#: kernel fault kind -> the technology DB entries (ErrorID, ErrorStatus bit), in the order they are noted
_MONITORS: dict[str, tuple[tuple[int, int], ...]] = {
    F.HW_LIMIT_MIN: ((HW_LIMIT_SWITCH, B["LimitSwitchActive"]), (LIMIT_SWITCH_COMMAND, B["LimitSwitchActive"])),
    F.HW_LIMIT_MAX: ((HW_LIMIT_SWITCH, B["LimitSwitchActive"]), (LIMIT_SWITCH_COMMAND, B["LimitSwitchActive"])),
    F.FOLLOWING_ERROR: ((FOLLOWING_ERROR, B["FollowingError"]),),
    F.STANDSTILL: ((STANDSTILL, B["StandstillFault"]),),
    F.POSITIONING: ((POSITIONING, B["PositioningError"]),),
    F.REFERENCE_NOT_FOUND: ((REFERENCE_NOT_FOUND, B["ReferenceNotFound"]),),
}

#: 8017 is an error of the technology DB (Statusword.Error) without a reaction, noted each time the following
#: error rises above ``DynamicFollowing.warningLimit`` % of the admissible one (§4.5.11.3, §7.12.1)
FOLLOWING_WARNING_ENTRY = (FOLLOWING_WARNING, B["FollowingWarning"])

#: the reaction of each monitoring ErrorID (see the table above); ``None``: none of its own (8014 stops at the
#: switch by its plan, 804B comes with 8013 or refuses a motion into the switch)
REACTIONS: dict[int, Reaction | None] = {
    HW_LIMIT_SWITCH: Reaction.REMOVE_ENABLE, LIMIT_SWITCH_COMMAND: None, SW_LIMIT_REACHED: None,
    SW_LIMIT_OVERSHOT: Reaction.REMOVE_ENABLE, FOLLOWING_ERROR: Reaction.REMOVE_ENABLE, FOLLOWING_WARNING: None,
    STANDSTILL: Reaction.REMOVE_ENABLE, POSITIONING: Reaction.REMOVE_ENABLE, REFERENCE_NOT_FOUND: Reaction.STOP,
}


#: §4.5.7.2 safety range of the hardware limit switches: 1000 / (increments per position unit).  The internal
#: resolution is a setting of the axis wizard that the parameter list of §9.4 does not carry; plcmotion takes
#: the manual's example, 1000 increments per unit, so the range is 1 length unit (docs/s7t decision D85)
INTERNAL_RESOLUTION = 1000.0
HW_LIMIT_SAFETY_RANGE = 1000.0 / INTERNAL_RESOLUTION


class HwLimitRetraction:
    """§4.5.7.2 "retraction": where the axis met a hardware limit switch (8013) and whether it has left it.

    MC_Reset acknowledges the error reaction at once (the axis can be enabled and driven back), but the
    technology DB keeps ErrorID, ErrorBuffer and ErrorStatus.LimitSwitchActive until the axis has passed
    the saved position plus the safety range towards the permitted range; a later MC_Reset clears them.
    Positions are the machine's (``drive.mechanical_position``), so a homing in between does not move them.
    """

    __slots__ = ("side", "position")

    def __init__(self, side: str, position: float):
        self.side, self.position = side, position

    def left(self, position: float) -> bool:
        """The axis at ``position`` is out of the switch's range (§4.5.7.2)."""
        if self.side == "max":
            return position < self.position - HW_LIMIT_SAFETY_RANGE
        return position > self.position + HW_LIMIT_SAFETY_RANGE


def hw_limit_side(fault: Fault) -> str | None:
    """"min"/"max" for the fault of a hardware limit switch just reached (8013), else None."""
    if fault.kind == F.HW_LIMIT_MIN:
        return "min"
    if fault.kind == F.HW_LIMIT_MAX:
        return "max"
    return None


#: §4.5.7.3 check box "monitoring of the software limit switches at start of motion" (no expert-list name in
#: the manual: a family tag; off unless configured)
SW_LIMIT_AT_START = "Wizard.SWLimitMonitoringAtStart"


def note_sw_limit_at_start(axis: Any, job: Job) -> None:
    """§4.5.7.3: with the check box set, a position-controlled command whose target lies beyond a software
    limit switch shows warning 0026 as it starts (the axis then travels up to the switch: 8014)."""
    plan = axis._plan
    if job.kind in _POSITIONINGS and plan is not None and plan.limit_side and axis.eff[SW_LIMIT_AT_START]:
        axis.errors.note(SW_LIMIT_WARNING)


def tdb_errors(fault: Fault) -> list[tuple[int, int | None]]:
    """The technology DB entries (ErrorID, ErrorStatus bit) of a kernel fault, in order."""
    if fault.ack and fault.kind in _MONITORS:
        return list(_MONITORS[fault.kind])
    return [tdb_error(fault)]


__all__ = ["HwLimitRetraction", "hw_limit_side", "HW_LIMIT_SAFETY_RANGE", "INTERNAL_RESOLUTION", "tdb_errors", "note_sw_limit_at_start", "SW_LIMIT_AT_START", "SW_LIMIT_WARNING", "REACTIONS", "FOLLOWING_WARNING", "FOLLOWING_WARNING_ENTRY", "HW_LIMIT_SWITCH", "SW_LIMIT_REACHED", "SW_LIMIT_OVERSHOT", "FOLLOWING_ERROR",
           "STANDSTILL", "POSITIONING", "REFERENCE_NOT_FOUND", "LIMIT_SWITCH_COMMAND"]
