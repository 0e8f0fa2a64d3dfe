"""ErrorIDs of the S7-1500 motion instructions: the CPU's numbers.

The S7-1500T synchronous operation manual V5 prints no ErrorID numbers; they come from the S7-1500/S7-1500T
Motion Control ErrorID list of the TIA Portal information system (shared reference
``s7-1500-errorids.md``).  ``CODES`` is the one table: the instructions return its numbers, ``describe``
gives its meaning, ``INSTRUCTION_CODES`` says which instruction can show which code, and
docs/s7_1500/errorids.md is generated from it (tools/gen_s7_1500_errorids.py).

16#8001 is the one code for "a technology alarm is behind this": the alarm itself is in
``<TO>.ErrorDetail.Number`` / ``.Reaction``.  Every other code is an instruction error: the job is not
carried out, running jobs go on, nothing needs acknowledging.  Error is never TRUE with ErrorID 0.
"""
from __future__ import annotations

from dataclasses import dataclass

from ..kernel import faults as F
from ..kernel.faults import Fault
from .technology import alarms as A


@dataclass(frozen=True)
class Code:
    """One ErrorID: its meaning, where plcmotion gives it, the remedy, and how the number was chosen
    ("list": the CPU's list names the situation; "#n": row n of docs/s7_1500/decisions.md)."""

    number: int
    meaning: str
    where: str
    remedy: str
    basis: str = "list"
    unreachable: str = ""      # why no situation in plcmotion gives it (the kernel still maps to it)


TO_ALARM = 0x8001
WRONG_TO = 0x8002
VELOCITY = 0x8003
ACCELERATION = 0x8004
DECELERATION = 0x8005
JERK = 0x8006
DIRECTION = 0x8007
DISTANCE = 0x8008
POSITION = 0x8009
MODE = 0x800A
STOP_MODE = 0x800B
SECOND_INSTANCE = 0x800C
NOT_NOW = 0x800D
RESTART_WHILE_ENABLED = 0x800E
LOCKED = 0x800F
MODE_NEEDS_ABSOLUTE = 0x8010
MODE_NOT_ABSOLUTE = 0x8011
TOO_MANY_JOBS = 0x8014
CONFIG_NOT_ACKNOWLEDGEABLE = 0x8015
ACTUAL_INVALID = 0x8016
NUMERATOR = 0x8017
DENOMINATOR = 0x8018
RECURSION = 0x8019
MASTER_OFFSET = 0x8021
SLAVE_OFFSET = 0x8022
MASTER_SCALING = 0x8023
SLAVE_SCALING = 0x8024
START_DISTANCE = 0x8026
APPLICATION_MODE = 0x8027
MASTER_SYNC_POSITION = 0x8034
SLAVE_SYNC_POSITION = 0x8035
SYNC_PROFILE = 0x8036
APPROACH = 0x8062
NO_LEADING_VALUE = 0x8063
NO_FOLLOWING_VALUE = 0x8064
PHASE_SHIFT = 0x8070
NO_SYNC = 0x8075
SYNC_SIMULATED = 0x8076
HOMING_IN_SYNC = 0x80A1
CAMMING_ACTIVE = 0x80A8
NOT_IN_SYNC = 0x80A9
CAM_EMPTY = 0x80AA
CAM_IN_USE = 0x80AB
CAM_DEFINITION = 0x80AC
SYNC_POSITION = 0x80AD
INTERNAL = 0x8FFF

# names kept for what they stand for in the instructions and tests
NOT_ENABLED = STOP_ACTIVE = LOCKED                # §A.1: the TO is locked (not enabled, or MC_Stop holds it)
NOT_HOMED = TO_ALARM                              # alarm 321 behind it (decisions #60)
JOG_BOTH = DIRECTION                              # JogForward and JogBackward TRUE at once
ALREADY_ENABLED = SECOND_INSTANCE
RESTART_IMPOSSIBLE = RESTART_WHILE_ENABLED
NOT_A_TO = WRONG_TO

_C = Code
CODES: tuple[Code, ...] = (
    _C(TO_ALARM, "a technology alarm stopped the job or keeps it from starting",
       "any instruction whose job a technology alarm ends; a job given while an alarm is pending; MC_Power while "
       "an alarm is pending; MC_MoveAbsolute on an unhomed axis (alarm 321); MC_GearIn/GearInPos/CamIn with a "
       "leading axis that is no configured leading value (alarm 601); MC_CamIn with a cam not interpolated "
       "(alarm 612); MC_Reset while the cause of an alarm remains",
       "read <TO>.ErrorDetail.Number and .Reaction, remove the cause, acknowledge with MC_Reset, start the job "
       "again", "list; #60-#62"),
    _C(WRONG_TO, "the technology object at Axis, Slave, Master or Cam cannot be used by this instruction",
       "no technology object, one of another type (a positioning axis as Slave, an axis as Cam), a Master that "
       "is not the leading value of the running synchronous operation (phasing), a leading value source that "
       "cannot give the configured coupling type, a function of the S7-1500T on an S7-1500",
       "connect a technology object of the type the input takes", "list; #63"),
    _C(VELOCITY, "invalid velocity", "Velocity = 0.0 where it is used, NaN/infinity, > 1.0E12; MC_MoveJog with a "
       "negative Velocity; VelocityDiff of MC_MoveSuperimposed; Velocity of MC_LeadingValueAdditive",
       "give a value in range (< 0.0 takes DynamicDefaults)"),
    _C(ACCELERATION, "invalid acceleration", "Acceleration (AccelerationDiff) = 0.0, NaN/infinity, > 1.0E12; "
       "Acceleration of MC_LeadingValueAdditive", "give a value in range (< 0.0 takes DynamicDefaults)"),
    _C(DECELERATION, "invalid deceleration", "Deceleration (DecelerationDiff) = 0.0, NaN/infinity, > 1.0E12",
       "give a value in range (< 0.0 takes DynamicDefaults)"),
    _C(JERK, "invalid jerk", "Jerk (JerkDiff) NaN/infinity or > 1.0E12 (0.0 is a trapezoidal profile)",
       "give a value in range (< 0.0 takes DynamicDefaults)", "list; #64"),
    _C(DIRECTION, "invalid direction, or both jog directions at once",
       "Direction of MC_MoveAbsolute (modulo axis) or MC_MoveVelocity out of range; SyncDirection of "
       "MC_GearInPos/MC_CamIn out of range with a modulo axis; MC_MoveJog with JogForward and JogBackward TRUE "
       "(the axis brakes)", "give a valid value; set only one jog input"),
    _C(DISTANCE, "invalid distance", "Distance of MC_MoveRelative/MC_MoveSuperimposed NaN/infinity or beyond "
       "1.0E12; a relative target beyond +/-1.0E12", "give a distance whose target stays in range", "list; #65"),
    _C(POSITION, "invalid position", "Position of MC_MoveAbsolute or MC_Home NaN/infinity or beyond 1.0E12; "
       "Position of MC_LeadingValueAdditive", "give a position in range", "list; #66"),
    _C(MODE, "invalid mode", "Mode of MC_Home or MC_Stop, StartMode of MC_Power out of range; an MC_Home "
       "mode the technology object does not offer (external encoder: 0, 1, 6, 7) or has no homing configured "
       "for", "give a mode the object supports", "list; #66"),
    _C(STOP_MODE, "invalid StopMode", "StopMode of MC_Power not 0, 1 or 2", "give 0, 1 or 2"),
    _C(SECOND_INSTANCE, "another instance of the instruction already works on this technology object",
       "MC_Power Enable = TRUE while another MC_Power instance has the object enabled",
       "use one MC_Power instance per technology object"),
    _C(NOT_NOW, "the technology object cannot take the job at this moment",
       "a job while the controller is not in RUN (start-up after STOP -> RUN); direct homing (MC_Home Mode "
       "0/1/6/7) while an active homing runs", "repeat the job when start-up or the homing has ended",
       "list; #67"),
    _C(RESTART_WHILE_ENABLED, "a restart is not possible while the technology object is enabled or in use",
       "MC_Reset Restart = TRUE while the object is enabled or being disabled, while a cam is used for camming "
       "or is being interpolated", "disable the object (end the camming) first", "list; #68"),
    _C(LOCKED, "the technology object is locked: not enabled, or MC_Stop holds it",
       "a motion, homing or synchronous job on a disabled axis; any job while MC_Stop.Execute is TRUE; an "
       "MC_Stop with a weaker stop response than the running one", "enable the axis with MC_Power; reset "
       "MC_Stop.Execute", "list; #74"),
    _C(MODE_NEEDS_ABSOLUTE, "the homing mode needs an absolute encoder",
       "MC_Home Mode 6 or 7 on an axis with an incremental encoder", "use mode 0, 1, 2, 3, 5, 8 or 10"),
    _C(MODE_NOT_ABSOLUTE, "the homing mode is not possible with an absolute encoder",
       "MC_Home Mode 2, 3, 5, 8 or 10 on a real axis with an absolute encoder", "use mode 0, 1, 6 or 7"),
    _C(TOO_MANY_JOBS, "too many jobs at once at the technology object",
       "a job while the axis already has as many busy instructions as it can keep",
       "wait until running jobs have ended", "list; #78",
       "an S7-1500 job of each kind aborts the one before it, so no axis reaches 100 busy instructions"),
    _C(CONFIG_NOT_ACKNOWLEDGEABLE, "the alarm cannot be acknowledged: the configuration itself is invalid",
       "MC_Reset while a configuration alarm persists (a tag value still out of range); MC_Reset with Restart = "
       "FALSE while an alarm that needs a restart of the technology object is pending (101, 201, 531 with "
       "swapped or both switches; StatusWord.X3)",
       "correct the configuration, then acknowledge; an alarm that needs a restart: disable the object and call "
       "MC_Reset with Restart = TRUE", "list; #100"),
    _C(ACTUAL_INVALID, "the actual values are not valid",
       "a position-controlled job or homing on a drive axis whose encoder reports no valid actual value",
       "restore the encoder, wait for StatusSensor.State = 2", "list; #75",
       "an encoder fault is alarm 411 until it is gone, so a job meets the alarm (16#8001) first"),
    _C(NUMERATOR, "invalid gear ratio numerator", "RatioNumerator 0, not whole or outside the DINT range",
       "give a whole number other than 0"),
    _C(DENOMINATOR, "invalid gear ratio denominator", "RatioDenominator < 1, not whole or outside the DINT range",
       "give a whole number >= 1"),
    _C(RECURSION, "the coupling would form a cycle: the following axis is a leading value of its own chain",
       "MC_GearIn/GearInPos/CamIn whose leading axis follows the following axis (directly or through others), "
       "or whose Master is the Slave", "couple in one direction only"),
    _C(MASTER_OFFSET, "invalid MasterOffset", "MC_CamIn MasterOffset NaN/infinity or beyond 1.0E12",
       "give a finite offset"),
    _C(SLAVE_OFFSET, "invalid SlaveOffset", "MC_CamIn SlaveOffset NaN/infinity or beyond 1.0E12",
       "give a finite offset"),
    _C(MASTER_SCALING, "invalid MasterScaling", "MC_CamIn MasterScaling <= 0, NaN/infinity or beyond 1.0E12",
       "give a positive scaling"),
    _C(SLAVE_SCALING, "invalid SlaveScaling", "MC_CamIn SlaveScaling NaN/infinity or beyond 1.0E12",
       "give a finite scaling"),
    _C(START_DISTANCE, "invalid leading value distance",
       "MasterStartDistance < 0 or not finite; synchronization in advance (SyncProfileReference 1) started with "
       "the leading axis closer than MasterStartDistance to MasterSyncPosition or moving away from it",
       "start the job earlier or give a shorter distance", "list; #69"),
    _C(APPLICATION_MODE, "invalid ApplicationMode", "MC_CamIn ApplicationMode not 0, 1 or 2", "give 0, 1 or 2"),
    _C(MASTER_SYNC_POSITION, "invalid MasterSyncPosition", "MC_GearInPos/MC_CamIn MasterSyncPosition NaN/infinity "
       "or beyond 1.0E12", "give a finite position"),
    _C(SLAVE_SYNC_POSITION, "invalid SlaveSyncPosition", "MC_GearInPos SlaveSyncPosition NaN/infinity or beyond "
       "1.0E12", "give a finite position"),
    _C(SYNC_PROFILE, "invalid SyncProfileReference", "MC_GearInPos not 0, 1 or 3; MC_CamIn not 0 ... 4",
       "give a reference the instruction offers"),
    _C(APPROACH, "invalid ApproachLeadingValue", "MC_GetCamLeadingValue ApproachLeadingValue NaN/infinity or "
       "beyond 1.0E12", "give a finite value"),
    _C(NO_LEADING_VALUE, "no leading value of the cam gives this following value",
       "MC_GetCamLeadingValue: the cam never takes FollowingValue, FollowingValue not finite, or the cam is not "
       "interpolated", "interpolate the cam; ask for a value inside its range of values", "list; #70"),
    _C(NO_FOLLOWING_VALUE, "the cam has no following value for this leading value",
       "MC_GetCamFollowingValue: LeadingValue outside the definition range or not finite, or the cam is not "
       "interpolated", "interpolate the cam; ask inside its definition range", "list; #70"),
    _C(PHASE_SHIFT, "invalid PhaseShift", "MC_PhasingRelative/Absolute PhaseShift NaN/infinity or beyond 1.0E12",
       "give a finite shift"),
    _C(NO_SYNC, "no synchronous operation is active on the axis",
       "MC_PhasingRelative/Absolute without a gearing; MC_SynchronizedMotionSimulation on an axis that is not "
       "synchronous", "start MC_GearIn first and wait for InGear", "list; #71"),
    _C(SYNC_SIMULATED, "the synchronous operation of the axis is being simulated",
       "MC_GearIn/GearInPos/CamIn/Phasing while MC_SynchronizedMotionSimulation is active on the following axis",
       "end the simulation (Enable = FALSE)", "list; #71"),
    _C(HOMING_IN_SYNC, "a following axis cannot be homed actively while MC_GearInPos/MC_CamIn is active on it",
       "MC_Home Mode 3/5 during active MC_GearInPos/MC_CamIn", "end the synchronous operation first",
       "list; #72"),
    _C(CAMMING_ACTIVE, "phasing needs a gearing, the axis is camming", "MC_PhasingRelative/Absolute while "
       "MC_CamIn is the synchronous operation", "phase only a gearing (MC_GearIn)"),
    _C(NOT_IN_SYNC, "the gearing is not yet synchronous (InGear FALSE)", "MC_PhasingRelative/Absolute while "
       "MC_GearIn is still synchronizing", "wait for InGear", "list; #71"),
    _C(CAM_EMPTY, "the cam has no valid points or segments", "MC_InterpolateCam on a cam without valid elements",
       "define points or segments and mark them valid"),
    _C(CAM_IN_USE, "the cam is in use and cannot be interpolated", "MC_InterpolateCam while a MC_CamIn job uses the "
       "cam (also waiting)", "end the camming first"),
    _C(CAM_DEFINITION, "the points or segments of the cam cannot be interpolated",
       "MC_InterpolateCam with a single point, non-finite or out-of-range values, a segment with xmax <= xmin, "
       "an invalid InterpolationMode or BoundaryConditions", "correct the cam data", "list; #73"),
    _C(SYNC_POSITION, "the synchronous position lies outside the definition range of the cam",
       "MC_CamIn MasterSyncPosition outside the cam; SyncProfileReference 4 with a cam run once whose leading "
       "values leave the cam", "give a position inside the cam (scaled and offset)"),
    _C(INTERNAL, "unexpected internal error", "a defect in plcmotion; the axis it concerns is stopped",
       "report it with the trace"),
)
_BY_NUMBER = {c.number: c for c in CODES}

#: codes of the CPU's list plcmotion never gives, with the reason (decisions #76)
NOT_PRODUCED: tuple[tuple[str, str], ...] = (
    ("16#8012, 16#8013, 16#8110, 16#8111", "the TIA Portal axis control panel is not modelled"),
    ("16#8037, 16#8077, 16#8078", "MC_GearOut / MC_CamOut do not exist in technology version 5"),
    ("16#8079", "MC_GearInVelocity does not exist in technology version 5"),
    ("16#8080 ... 16#8084, 16#808A, 16#808C", "MC_OffsetAbsolute/Relative and the newer phasing inputs "
     "(PhasingDistance, ProfileReference, StartPosition) do not exist in technology version 5"),
    ("16#808B", "MC_CamIn SyncProfileReference 5 is newer than technology version 5"),
    ("16#8065, 16#8066", "ApproachDirection of MC_GetCamLeadingValue is newer than technology version 5"),
    ("16#8040 ... 16#8047, 16#804A ... 16#804F", "output cams, torque limiting, fixed stop and torque data are "
     "not modelled for the S7-1500"),
    ("16#8050, 16#8051, 16#8074", "MC_SetSensor is not modelled (one encoder per axis, decisions #37)"),
    ("16#8055, 16#805A ... 16#805D", "MC_SetAxisSTW and MC_WriteParameter are not modelled"),
    ("16#8071", "no job is refused because the axis runs without position control (StatusWord.X28)"),
    ("16#80A2, 16#80A3, 16#80A5 ... 16#80A7", "measuring inputs are not modelled"),
    ("16#80AE, 16#80B1 ... 16#80E0", "kinematics technology objects are not modelled"),
    ("16#80E1 ... 16#80EF", "MC_CopyCamData and MC_SaveAbsoluteEncoderData are newer than technology version 5"),
    ("16#80F0 ... 16#80FE", "the Interpreter technology object is not modelled"),
)

#: the code of an invalid value at each input (16#8003 ... 16#8070)
INPUT_CODES = {
    "Position": POSITION, "Distance": DISTANCE, "Velocity": VELOCITY, "Acceleration": ACCELERATION,
    "Deceleration": DECELERATION, "Jerk": JERK, "Direction": DIRECTION, "Mode": MODE, "StartMode": MODE,
    "StopMode": STOP_MODE, "RatioNumerator": NUMERATOR, "RatioDenominator": DENOMINATOR,
    "MasterSyncPosition": MASTER_SYNC_POSITION, "SlaveSyncPosition": SLAVE_SYNC_POSITION,
    "SyncProfileReference": SYNC_PROFILE, "MasterStartDistance": START_DISTANCE, "SyncDirection": DIRECTION,
    "ApplicationMode": APPLICATION_MODE, "MasterOffset": MASTER_OFFSET, "SlaveOffset": SLAVE_OFFSET,
    "MasterScaling": MASTER_SCALING, "SlaveScaling": SLAVE_SCALING, "PhaseShift": PHASE_SHIFT,
    "LeadingValue": NO_FOLLOWING_VALUE, "FollowingValue": NO_LEADING_VALUE, "ApproachLeadingValue": APPROACH,
    "VelocityDiff": VELOCITY, "AccelerationDiff": ACCELERATION, "DecelerationDiff": DECELERATION,
    "JerkDiff": JERK,
}


def parameter(name: str) -> int:
    """ErrorID for an invalid value at input ``name``."""
    return INPUT_CODES[name]


# --- kernel faults -> ErrorID ---------------------------------------------------------------------------
_REJECT = {
    F.NOT_ENABLED: LOCKED, F.STOP_ACTIVE: LOCKED, F.ALREADY_ENABLED: SECOND_INSTANCE,
    F.NOT_HOMED: TO_ALARM, F.PENDING_ALARM: TO_ALARM, F.SYNC_MASTER: TO_ALARM,
    F.TOO_MANY_COMMANDS: TOO_MANY_JOBS, F.QUEUE_FULL: TOO_MANY_JOBS,
    F.RESTART_IMPOSSIBLE: RESTART_WHILE_ENABLED, F.SYNC_ACTIVE: HOMING_IN_SYNC, F.NOT_AVAILABLE: WRONG_TO,
    F.LV_NOT_READY: WRONG_TO, F.SYNC_SIMULATION: SYNC_SIMULATED, F.COUPLING_CYCLE: RECURSION,
    F.START_DISTANCE: START_DISTANCE, F.SYNC_POSITION_RANGE: SYNC_POSITION, F.CAM_IN_USE: CAM_IN_USE,
    F.CAM_NOT_INTERPOLATED: TO_ALARM, F.CAM_NO_SOLUTION: NO_LEADING_VALUE,
    F.CAM_OUT_OF_RANGE: NO_FOLLOWING_VALUE, F.INTERNAL: INTERNAL,
}
#: (kind, detail) pairs that differ from the kind's code
_DETAIL = {
    (F.REJECTED, "starting_up"): NOT_NOW, (F.REJECTED, "homing_active"): NOT_NOW,
    (F.REJECTED, "position_control_required"): ACTUAL_INVALID, (F.REJECTED, "actual_invalid"): ACTUAL_INVALID,
    (F.REJECTED, "numeric_limit"): DISTANCE,
    (F.NOT_SYNCHRONOUS, "none"): NO_SYNC, (F.NOT_SYNCHRONOUS, "simulation"): NO_SYNC,
    (F.NOT_SYNCHRONOUS, "simulated"): SYNC_SIMULATED, (F.NOT_SYNCHRONOUS, "camming"): CAMMING_ACTIVE,
    (F.NOT_SYNCHRONOUS, "not_in_sync"): NOT_IN_SYNC, (F.NOT_SYNCHRONOUS, "master"): WRONG_TO,
    (F.CAM_DEFINITION, "empty"): CAM_EMPTY,
}
#: (instruction, fault kind) pairs whose code depends on the instruction
_BY_INSTRUCTION = {
    ("MC_GetCamLeadingValue", F.CAM_NOT_INTERPOLATED): NO_LEADING_VALUE,
    ("MC_GetCamFollowingValue", F.CAM_NOT_INTERPOLATED): NO_FOLLOWING_VALUE,
    ("MC_Reset", F.CAM_IN_USE): RESTART_WHILE_ENABLED,
}


def code(fault: Fault, instruction: str = "") -> int:
    """The ErrorID instruction ``instruction`` shows for a kernel fault."""
    if fault.ack:                                  # a technology alarm ended the job (or MC_Reset kept it)
        if instruction == "MC_Reset" and (fault.kind == F.CONFIG or A.needs_restart(fault)):
            return CONFIG_NOT_ACKNOWLEDGEABLE          # only a correct configuration / a restart clears it (#100)
        return TO_ALARM
    by_instruction = _BY_INSTRUCTION.get((instruction, fault.kind))
    if by_instruction is not None:
        return by_instruction
    detail = _DETAIL.get((fault.kind, fault.detail))
    if detail is not None:
        return detail
    if fault.kind == F.CAM_DEFINITION:
        return CAM_DEFINITION
    return _REJECT.get(fault.kind, INTERNAL)


# --- which instruction shows which code -----------------------------------------------------------------
_ANY = (TO_ALARM, WRONG_TO, NOT_NOW, INTERNAL)
_JOB = _ANY + (LOCKED,)
_DYN = (ACCELERATION, DECELERATION, JERK)
_SYNC = _ANY + (LOCKED, SYNC_SIMULATED, RECURSION) + _DYN
_POSITIONED = _SYNC + (VELOCITY, DIRECTION, START_DISTANCE, MASTER_SYNC_POSITION, SYNC_PROFILE)
_PHASING = _ANY + (LOCKED, SYNC_SIMULATED, VELOCITY, PHASE_SHIFT, NO_SYNC, CAMMING_ACTIVE,
                   NOT_IN_SYNC) + _DYN
_CAM = (WRONG_TO, NOT_NOW, INTERNAL)
INSTRUCTION_CODES: dict[str, frozenset[int]] = {name: frozenset(codes) for name, codes in {
    "MC_Power": (TO_ALARM, WRONG_TO, NOT_NOW, INTERNAL, MODE, STOP_MODE, SECOND_INSTANCE),
    "MC_Reset": (TO_ALARM, WRONG_TO, INTERNAL, RESTART_WHILE_ENABLED, CONFIG_NOT_ACKNOWLEDGEABLE),
    "MC_Home": _JOB + (POSITION, MODE, MODE_NEEDS_ABSOLUTE, MODE_NOT_ABSOLUTE, HOMING_IN_SYNC),
    "MC_Halt": _JOB + (DECELERATION, JERK),
    "MC_Stop": _JOB + (MODE,),
    "MC_MoveAbsolute": _JOB + (POSITION, VELOCITY, DIRECTION) + _DYN,
    "MC_MoveRelative": _JOB + (DISTANCE, VELOCITY) + _DYN,
    "MC_MoveVelocity": _JOB + (VELOCITY, DIRECTION) + _DYN,
    "MC_MoveJog": _JOB + (VELOCITY, DIRECTION) + _DYN,
    "MC_MoveSuperimposed": _JOB + (DISTANCE, VELOCITY) + _DYN,
    "MC_GearIn": _SYNC + (NUMERATOR, DENOMINATOR),
    "MC_GearInPos": _POSITIONED + (NUMERATOR, DENOMINATOR, SLAVE_SYNC_POSITION),
    "MC_CamIn": _POSITIONED + (MASTER_OFFSET, SLAVE_OFFSET, MASTER_SCALING, SLAVE_SCALING, APPLICATION_MODE,
                               SYNC_POSITION),
    "MC_PhasingRelative": _PHASING,
    "MC_PhasingAbsolute": _PHASING,
    "MC_SynchronizedMotionSimulation": (TO_ALARM, WRONG_TO, NOT_NOW, INTERNAL, NO_SYNC),
    "MC_LeadingValueAdditive": (TO_ALARM, WRONG_TO, NOT_NOW, INTERNAL, LOCKED, POSITION, VELOCITY, ACCELERATION),
    "MC_InterpolateCam": _CAM + (CAM_EMPTY, CAM_IN_USE, CAM_DEFINITION),
    "MC_GetCamLeadingValue": _CAM + (APPROACH, NO_LEADING_VALUE),
    "MC_GetCamFollowingValue": _CAM + (NO_FOLLOWING_VALUE,),
}.items()}


def describe(error_id: int) -> str:
    """Meaning of an ErrorID."""
    if error_id == 0:
        return "no error"
    c = _BY_NUMBER.get(error_id)
    return c.meaning if c is not None else f"unknown ErrorID 16#{error_id:04X}"


def table() -> list[tuple[int, str]]:
    """All ErrorIDs the dialect gives, with their meaning (documentation)."""
    return [(c.number, c.meaning) for c in CODES]


def instructions_of(error_id: int) -> list[str]:
    """The instructions that can show ``error_id``."""
    return [name for name, codes in INSTRUCTION_CODES.items() if error_id in codes]
