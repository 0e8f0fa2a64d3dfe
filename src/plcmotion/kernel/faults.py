"""Faults the kernel reports, in a vocabulary of its own.

The kernel says *what* went wrong (``Fault.kind`` and ``Fault.detail``) and *how the axis reacted*; each
dialect maps that to the ErrorID/ErrorInfo codes of its manual.  Two families exist:

* axis alarms (``ack=True``): stay pending on the axis until acknowledged (MC_Reset); shown at the
  instruction that was active and at the enabling instruction (S7-1200 V6 §9.6 "with axis stop" and
  configuration errors of the axis);
* command rejections (``ack=False``): only the instruction that asked is told; the axis carries on.
"""
from __future__ import annotations

from dataclasses import dataclass
from enum import Enum


class Reaction(Enum):
    NONE = "none"                    # nothing beyond what the text of the fault says
    STOP = "stop"                    # brake with the configured deceleration
    EMERGENCY = "emergency"          # brake with the emergency deceleration, no jerk limit (§12.8)
    MAX_DYNAMICS = "max_dynamics"    # brake with the configured maximum dynamics (deceleration and jerk limits)
    REMOVE_ENABLE = "remove_enable"  # setpoint zero, drive enable removed, drive brakes by itself


@dataclass(frozen=True)
class Fault:
    kind: str
    detail: str = ""
    ack: bool = False
    reaction: Reaction = Reaction.NONE
    text: str = ""

    def __str__(self) -> str:
        extra = f"/{self.detail}" if self.detail else ""
        return f"{self.kind}{extra}" + (f": {self.text}" if self.text else "")


# --- axis alarms (need acknowledgement) -------------------------------------------------------------
DRIVE_NOT_READY = "drive_not_ready"
SW_LIMIT_MIN = "sw_limit_min"            # details: reached, reached_emergency, exceeded
SW_LIMIT_MAX = "sw_limit_max"
HW_LIMIT_MIN = "hw_limit_min"
HW_LIMIT_MAX = "hw_limit_max"
HW_USED = "hw_used"
DIRECTION = "direction"                  # details: not_permitted, reversal
REFERENCE_NOT_FOUND = "reference_not_found"
ENCODER = "encoder"
POSITION_RANGE = "position_range"        # details: positive, negative, modulo_jump
DRIVE_ALARM = "drive_alarm"
FOLLOWING_ERROR = "following_error"
HW_LIMIT_FREE = "hw_limit_free"          # details: wrong_direction, polarity, both
POSITIONING = "positioning"              # details: not_reached, left
STANDSTILL = "standstill"                # standstill monitoring after a positioning: not_reached, left
SW_LIMIT_ORDER = "sw_limit_order"
HOMING_APPROACH_ZERO = "homing_approach_zero"
HOMING_REFERENCING_ZERO = "homing_referencing_zero"
CONFIG = "config"                        # detail: "<tag path>:<reason>"
INTERNAL = "internal"

# --- rejections (no acknowledgement) ----------------------------------------------------------------
NOT_ENABLED = "not_enabled"
ALREADY_ENABLED = "already_enabled"      # another enabling instruction owns the axis
TOO_MANY_COMMANDS = "too_many_commands"
NOT_HOMED = "not_homed"
NOT_ACTIVATED = "not_activated"          # the axis does not hold its (shared) pulse generator yet
REJECTED = "rejected"                    # details: homing_active, table_homing, homing_table, numeric_limit,
#                                          starting_up, actual_invalid, position_control_required
PTO_SWITCH = "pto_switch"                # the shared pulse generator is held by another enabled axis
RESTART_IMPOSSIBLE = "restart_impossible"  # details: enabled, not_disabled
PENDING_ALARM = "pending_alarm"          # a new command while an alarm waits for acknowledgement
TABLE_CONFIG = "table_config"            # a step of a command table is invalid: "<field>:<reason>"
CAM_IN_USE = "cam_in_use"                # MC_InterpolateCam / restart while the cam is used for camming
CAM_NOT_INTERPOLATED = "cam_not_interpolated"
CAM_DEFINITION = "cam_definition"        # points/segments cannot be interpolated: detail = reason
CAM_NO_SOLUTION = "cam_no_solution"      # MC_GetCamLeadingValue: the cam never takes the value
CAM_OUT_OF_RANGE = "cam_out_of_range"    # MC_GetCamFollowingValue: leading value outside the range
NOT_AVAILABLE = "not_available"          # function of the S7-1500T used on an S7-1500 (detail: function)
STOP_ACTIVE = "stop_active"              # S7-1500: the axis is locked by MC_Stop
SYNC_ACTIVE = "sync_active"              # active homing while a GearInPos/CamIn is active (docs/decisions)
SYNC_SIMULATION = "sync_simulation"      # synchronous operation jobs while it is simulated
NOT_SYNCHRONOUS = "not_synchronous"      # phasing / simulation need status Synchronous (detail: none,
#                                          simulated, camming, not_in_sync, master, simulation)
COUPLING_CYCLE = "coupling_cycle"        # the leading axis would follow its own leading value
START_DISTANCE = "start_distance"        # SyncProfileReference 1: master closer than MasterStartDistance
SYNC_POSITION_RANGE = "sync_position_range"  # MasterSyncPosition outside the cam
LV_NOT_READY = "lv_not_ready"            # the leading value source cannot provide a value (detail)
# axis alarm of a synchronous axis: the master of the job is not configured as a possible leading value
SYNC_MASTER = "sync_master"
LV_INVALID = "lv_invalid"                # leading axis proxy: external leading value invalid (alarm 900)
QUEUE_FULL = "queue_full"                # the axis's job queue holds as many waiting jobs as it can (depth)
NOT_APPENDABLE = "not_appendable"        # a job cannot wait behind the running one (detail: its kind)


def alarm(kind: str, detail: str = "", reaction: Reaction = Reaction.NONE, text: str = "") -> Fault:
    return Fault(kind, detail, True, reaction, text)


def reject(kind: str, detail: str = "", text: str = "") -> Fault:
    return Fault(kind, detail, False, Reaction.NONE, text)


def config_fault(path: str, reason: str, text: str = "") -> Fault:
    """Invalid configuration value discovered at runtime (§9.6: emergency stop, shown at MC_Power)."""
    return Fault(CONFIG, f"{path}:{reason}", True, Reaction.EMERGENCY, text)
