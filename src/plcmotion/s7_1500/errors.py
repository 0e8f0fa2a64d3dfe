"""ErrorIDs of the S7-1500 motion instructions.

The S7-1500T synchronous operation manual defers the ErrorID numbers to the "Motion Control overview"
manual, which is not public in a form we could use (docs/research/s7_1500_errorids.md).  16#8001
("a technology alarm is pending at the technology object, see ErrorDetail") is the one code public
sources agree on; all other numbers are plcmotion's own table, grouped by cause, documented in
docs/errorids_s7_1500.md and returned by :func:`describe`.  Error is never TRUE with ErrorID 0.
"""
from __future__ import annotations

from ..kernel import faults as F
from ..kernel.faults import Fault

TO_ALARM = 0x8001              # technology alarm pending / the job ended through an alarm (ErrorDetail)
JOG_BOTH = 0x8007              # JogForward and JogBackward TRUE at the same time
INTERNAL = 0x8FFF

# --- technology object at an input -------------------------------------------------------------------
NOT_A_TO = 0x8010              # the input is not a technology object
WRONG_TO = 0x8011              # a technology object of a type the input does not take

# --- state of the technology object (16#82xx) --------------------------------------------------------
NOT_ENABLED = 0x8201
ALREADY_ENABLED = 0x8202       # enabled by another MC_Power instance
NOT_HOMED = 0x8203
STOP_ACTIVE = 0x8204           # MC_Stop locks the axis (StatusWord2.X0)
NOT_RUN = 0x8205               # CPU not in RUN
TOO_MANY_JOBS = 0x8206
POSITION_CONTROL = 0x8207      # position control needed but the actual values are invalid
RESTART_IMPOSSIBLE = 0x8208    # restart while the TO is enabled / the cam is in use
JOB_CONFLICT = 0x8209          # homing while homing/active synchronous operation; passive homing conflicts
NUMERIC_RANGE = 0x820A         # a target outside +/-1.0E12

# --- synchronous operation (16#83xx) ------------------------------------------------------------------
MASTER_NOT_CONFIGURED = 0x8301  # not a possible leading value of the following axis (ErrorWord.X14)
T_ONLY = 0x8302                 # function of the S7-1500T
NOT_SYNCHRONOUS = 0x8303        # the following axis is not synchronous with gearing
OTHER_MASTER = 0x8304           # the master differs from the leading value of the synchronous operation
SIMULATION_ACTIVE = 0x8305      # synchronous operation jobs while MC_SynchronizedMotionSimulation is active
COUPLING_CYCLE = 0x8306         # the couplings would form a cycle
START_DISTANCE = 0x8307         # SyncProfileReference 1: master closer than MasterStartDistance or moving away
SYNC_POSITION = 0x8308          # MasterSyncPosition outside the cam
COUPLING_TYPE = 0x8309          # the source cannot provide this type of leading value

# --- cams (16#84xx) -------------------------------------------------------------------------------------
CAM_IN_USE = 0x8401
CAM_NOT_INTERPOLATED = 0x8402
CAM_DEFINITION = 0x8403
CAM_NO_SOLUTION = 0x8404
CAM_OUT_OF_RANGE = 0x8405

# --- invalid input values (16#81xx, one code per input) ---------------------------------------------
PARAMETERS = ("Position", "Distance", "Velocity", "Acceleration", "Deceleration", "Jerk", "Direction", "Mode",
              "StartMode", "StopMode", "RatioNumerator", "RatioDenominator", "MasterSyncPosition",
              "SlaveSyncPosition", "SyncProfileReference", "MasterStartDistance", "SyncDirection",
              "ApplicationMode", "MasterOffset", "SlaveOffset", "MasterScaling", "SlaveScaling", "PhaseShift",
              "LeadingValue", "FollowingValue", "ApproachLeadingValue", "VelocityDiff", "AccelerationDiff",
              "DecelerationDiff", "JerkDiff")
PARAMETER_BASE = 0x8101


def parameter(name: str) -> int:
    """ErrorID for an invalid value at input ``name``."""
    return PARAMETER_BASE + PARAMETERS.index(name)


_REJECT = {
    F.NOT_ENABLED: NOT_ENABLED, F.ALREADY_ENABLED: ALREADY_ENABLED, F.NOT_HOMED: NOT_HOMED,
    F.STOP_ACTIVE: STOP_ACTIVE, F.TOO_MANY_COMMANDS: TOO_MANY_JOBS, F.RESTART_IMPOSSIBLE: RESTART_IMPOSSIBLE,
    F.SYNC_ACTIVE: JOB_CONFLICT, F.NOT_AVAILABLE: T_ONLY, F.SYNC_SIMULATION: SIMULATION_ACTIVE,
    F.COUPLING_CYCLE: COUPLING_CYCLE, F.START_DISTANCE: START_DISTANCE, F.SYNC_POSITION_RANGE: SYNC_POSITION,
    F.LV_NOT_READY: COUPLING_TYPE, F.SYNC_MASTER: MASTER_NOT_CONFIGURED, F.CAM_IN_USE: CAM_IN_USE,
    F.CAM_NOT_INTERPOLATED: CAM_NOT_INTERPOLATED, F.CAM_DEFINITION: CAM_DEFINITION,
    F.CAM_NO_SOLUTION: CAM_NO_SOLUTION, F.CAM_OUT_OF_RANGE: CAM_OUT_OF_RANGE, F.PENDING_ALARM: TO_ALARM,
}
_REJECTED_DETAIL = {"starting_up": NOT_RUN, "position_control_required": POSITION_CONTROL,
                    "actual_invalid": POSITION_CONTROL, "numeric_limit": NUMERIC_RANGE,
                    "homing_active": JOB_CONFLICT, "homing_table": JOB_CONFLICT, "table_homing": JOB_CONFLICT}


def code(fault: Fault) -> int:
    """The ErrorID of a kernel fault."""
    if fault.ack:                                  # a technology alarm ended the job
        return TO_ALARM if fault.kind != F.SYNC_MASTER else MASTER_NOT_CONFIGURED
    if fault.kind == F.REJECTED:
        return _REJECTED_DETAIL.get(fault.detail, JOB_CONFLICT)
    if fault.kind == F.NOT_SYNCHRONOUS:
        return OTHER_MASTER if fault.detail == "master" else NOT_SYNCHRONOUS
    if fault.kind == F.INTERNAL:
        return INTERNAL
    return _REJECT.get(fault.kind, INTERNAL)


_TEXT = {
    TO_ALARM: "a technology alarm is pending at the technology object or ended the job; see ErrorDetail",
    JOG_BOTH: "JogForward and JogBackward are TRUE at the same time",
    INTERNAL: "internal error (details in the technology object)",
    NOT_A_TO: "the input is not a technology object",
    WRONG_TO: "the technology object is of a type this input does not take",
    NOT_ENABLED: "the technology object is not enabled",
    ALREADY_ENABLED: "the axis is enabled by another MC_Power instance",
    NOT_HOMED: "the axis is not homed",
    STOP_ACTIVE: "MC_Stop holds the axis (StatusWord2.X0); reset its Execute first",
    NOT_RUN: "the CPU is not in RUN",
    TOO_MANY_JOBS: "too many jobs at the technology object",
    POSITION_CONTROL: "the job needs position control and the actual values are not valid",
    RESTART_IMPOSSIBLE: "restart not possible: the technology object is enabled or in use",
    JOB_CONFLICT: "the job is not possible while another job runs (homing, active synchronous operation)",
    NUMERIC_RANGE: "the target position is outside -1.0E12 .. 1.0E12",
    MASTER_NOT_CONFIGURED: "the leading axis is not configured as a possible leading value (ErrorWord.X14)",
    T_ONLY: "the function needs an S7-1500T CPU",
    NOT_SYNCHRONOUS: "the following axis is not synchronous with gearing (InGear/InSync)",
    OTHER_MASTER: "the Master input differs from the leading value of the synchronous operation",
    SIMULATION_ACTIVE: "synchronous operation is simulated (MC_SynchronizedMotionSimulation)",
    COUPLING_CYCLE: "the leading axis would follow its own leading value",
    START_DISTANCE: "the leading axis is closer than MasterStartDistance to the synchronous position, or moves away from it",
    SYNC_POSITION: "MasterSyncPosition is outside the cam",
    COUPLING_TYPE: "the leading value source cannot provide this type of coupling",
    CAM_IN_USE: "the cam is in use",
    CAM_NOT_INTERPOLATED: "the cam is not interpolated (MC_InterpolateCam)",
    CAM_DEFINITION: "the points and segments of the cam cannot be interpolated",
    CAM_NO_SOLUTION: "the cam never takes this following value",
    CAM_OUT_OF_RANGE: "the leading value is outside the definition range of the cam",
}


def describe(error_id: int) -> str:
    """Text of an ErrorID."""
    if PARAMETER_BASE <= error_id < PARAMETER_BASE + len(PARAMETERS):
        return f"invalid value at input {PARAMETERS[error_id - PARAMETER_BASE]}"
    if error_id == 0:
        return "no error"
    return _TEXT.get(error_id, f"unknown ErrorID 16#{error_id:04X}")


def table() -> list[tuple[int, str]]:
    """All ErrorIDs with their text (documentation)."""
    codes = sorted(set(_TEXT) | {parameter(p) for p in PARAMETERS})
    return [(c, describe(c)) for c in codes]
