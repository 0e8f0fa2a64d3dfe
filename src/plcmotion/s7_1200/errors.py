"""ErrorIDs and ErrorInfos of S7-1200 Motion Control V6 (§12.8) and how kernel faults map onto them.

Descriptions are short paraphrases for messages and traces; the manual's list is the reference.
"""
from __future__ import annotations

from ..kernel import faults as F
from ..kernel.faults import Fault

# --- block parameter errors (§12.8 "Block parameter error"): raised by the instructions themselves -----
INVALID_FORMAT = 0x0002
ABOVE_1E12 = 0x0005
BELOW_MINUS_1E12 = 0x0006
ABOVE_MAX_VELOCITY = 0x0008
BELOW_START_STOP = 0x0009
NOT_POSITIVE = 0x000A
INVALID_SELECTION = 0x0011
BELOW_ZERO = 0x0024
OUT_OF_RANGE = 0x0030

POSITION = 0x8400
DISTANCE = 0x8401
VELOCITY = 0x8402
DIRECTION = 0x8403
MODE = 0x8404
STOP_MODE = 0x8405
JOG_BOTH = 0x8406
POWER_SWITCH = 0x8407
AXIS = 0x8408
START_MODE = 0x8412

# --- kernel alarms -> (ErrorID, ErrorInfo) ------------------------------------------------------------
_ALARMS: dict[tuple[str, str], tuple[int, int]] = {
    (F.DRIVE_NOT_READY, ""): (0x8000, 0x0001),
    (F.SW_LIMIT_MIN, "reached"): (0x8001, 0x000E),
    (F.SW_LIMIT_MIN, "reached_emergency"): (0x8001, 0x000F),
    (F.SW_LIMIT_MIN, "exceeded"): (0x8001, 0x0010),
    (F.SW_LIMIT_MAX, "reached"): (0x8002, 0x000E),
    (F.SW_LIMIT_MAX, "reached_emergency"): (0x8002, 0x000F),
    (F.SW_LIMIT_MAX, "exceeded"): (0x8002, 0x0010),
    (F.HW_LIMIT_MIN, ""): (0x8003, 0x000E),
    (F.HW_LIMIT_MAX, ""): (0x8004, 0x000E),
    (F.HW_USED, ""): (0x8005, 0x0001),
    (F.DIRECTION, "not_permitted"): (0x8008, 0x002E),
    (F.DIRECTION, "reversal"): (0x8008, 0x002F),
    (F.REFERENCE_NOT_FOUND, ""): (0x8009, 0x0033),
    (F.ENCODER, ""): (0x800A, 0x0001),
    (F.ENCODER, "hardware"): (0x800A, 0x0034),
    (F.ENCODER, "dirty"): (0x800A, 0x0035),
    (F.ENCODER, "absolute_value"): (0x800A, 0x0036),
    (F.ENCODER, "zero_mark"): (0x800A, 0x0037),
    (F.ENCODER, "parking"): (0x800A, 0x0038),
    (F.ENCODER, "station"): (0x800A, 0x0040),
    (F.ENCODER, "sign_of_life"): (0x800A, 0x0041),
    (F.POSITION_RANGE, "positive"): (0x800B, 0x0039),
    (F.POSITION_RANGE, "negative"): (0x800B, 0x003A),
    (F.POSITION_RANGE, "modulo_jump"): (0x800B, 0x003B),
    (F.DRIVE_ALARM, ""): (0x800C, 0x0001),
    (F.DRIVE_ALARM, "control_requested"): (0x800C, 0x003C),
    (F.DRIVE_ALARM, "shutdown"): (0x800C, 0x003D),
    (F.DRIVE_ALARM, "station"): (0x800C, 0x003E),
    (F.DRIVE_ALARM, "sign_of_life"): (0x800C, 0x003F),
    (F.FOLLOWING_ERROR, ""): (0x800D, 0x0001),
    (F.HW_LIMIT_FREE, "wrong_direction"): (0x800E, 0x0042),
    (F.HW_LIMIT_FREE, "polarity"): (0x800E, 0x0043),
    (F.HW_LIMIT_FREE, "both"): (0x800E, 0x0044),
    (F.POSITIONING, "not_reached"): (0x800F, 0x0045),
    (F.POSITIONING, "left"): (0x800F, 0x0046),
    (F.SW_LIMIT_ORDER, ""): (0x8010, 0x0001),
    (F.HOMING_APPROACH_ZERO, ""): (0x8011, 0x000A),
    (F.HOMING_REFERENCING_ZERO, ""): (0x8012, 0x000A),
    (F.INTERNAL, ""): (0x8FFF, 0xF001),
    (F.INTERNAL, "planning"): (0x8FFF, 0xF002),
}

_REJECTS: dict[tuple[str, str], tuple[int, int]] = {
    (F.NOT_ENABLED, ""): (0x8200, 0x0001),
    (F.ALREADY_ENABLED, ""): (0x8201, 0x0001),
    (F.TOO_MANY_COMMANDS, ""): (0x8202, 0x0001),
    (F.NOT_HOMED, ""): (0x8204, 0x0001),
    (F.NOT_ACTIVATED, ""): (0x8206, 0x0001),
    (F.REJECTED, ""): (0x8207, 0x0001),
    (F.REJECTED, "homing_active"): (0x8207, 0x0016),
    (F.REJECTED, "table_homing"): (0x8207, 0x0018),
    (F.REJECTED, "homing_table"): (0x8207, 0x0019),
    (F.REJECTED, "numeric_limit"): (0x8207, 0x0052),
    (F.REJECTED, "starting_up"): (0x8207, 0x0053),
    (F.REJECTED, "actual_invalid"): (0x8207, 0x0054),
    (F.REJECTED, "position_control_required"): (0x8207, 0x006B),
    (F.HW_USED, ""): (0x8005, 0x0001),
    (F.PTO_SWITCH, ""): (0x8407, 0x0001),
    (F.RESTART_IMPOSSIBLE, "enabled"): (0x820A, 0x0013),
    (F.RESTART_IMPOSSIBLE, "control_panel"): (0x820A, 0x0027),
    (F.RESTART_IMPOSSIBLE, "not_disabled"): (0x820A, 0x002C),
    (F.RESTART_IMPOSSIBLE, "not_ready"): (0x820A, 0x0047),
    (F.RESTART_IMPOSSIBLE, "condition"): (0x820A, 0x0048),
}

# --- configuration errors of the axis (§12.8 16#86xx): tag path -> ErrorID ------------------------------
CONFIG_IDS: dict[str, int] = {
    "Actor.DriveParameter.PulsesPerDriveRevolution": 0x8604,
    "Mechanics.LeadScrew": 0x8605,
    "DynamicLimits.MinVelocity": 0x8606,
    "DynamicLimits.MaxVelocity": 0x8607,
    "DynamicDefaults.Acceleration": 0x8608,
    "DynamicDefaults.Deceleration": 0x8609,
    "DynamicDefaults.EmergencyDeceleration": 0x860A,
    "PositionLimits_SW.MinPosition": 0x860B,
    "PositionLimits_SW.MaxPosition": 0x860C,
    "Sensor[1].ActiveHoming.HomePositionOffset": 0x860F,
    "Homing.ApproachVelocity": 0x8610,
    "Homing.ReferencingVelocity": 0x8611,
    "Homing.AutoReversal": 0x8613,
    "DynamicDefaults.Jerk": 0x8614,
    "Units.LengthUnit": 0x8615,
    "Sensor[1].ActiveHoming.Mode": 0x8617,
    "Sensor[1].PassiveHoming.Mode": 0x8618,
    "Actor.Type": 0x8619,
    "Actor.DirectionMode": 0x861A,
    "Sensor[1].MountingMode": 0x861D,
    "Sensor[1].Parameter.DistancePerRevolution": 0x861E,
    "Sensor[1].Parameter.Resolution": 0x861F,
    "Sensor[1].Parameter.StepsPerRevolution": 0x861F,
    "Sensor[1].Parameter.FineResolutionXist1": 0x8620,
    "Sensor[1].Type": 0x8623,
    "Sensor[1].System": 0x8624,
    "PositioningMonitoring.MinDwellTime": 0x8625,
    "PositioningMonitoring.Window": 0x8626,
    "PositionControl.Kv": 0x8628,
    "StandstillSignal.VelocityThreshold": 0x8629,
    "PositioningMonitoring.ToleranceTime": 0x862A,
    "StandstillSignal.MinDwellTime": 0x862C,
    "FollowingError.MinValue": 0x862D,
    "Modulo.Length": 0x862E,
    "Modulo.StartValue": 0x862F,
    "Modulo.Enable": 0x862E,
    "Actor.DriveParameter.ReferenceSpeed": 0x8630,
    "Sensor[1].Parameter.FineResolutionXist2": 0x8631,
    "Sensor[1].Parameter.DeterminableRevolutions": 0x8632,
    "FollowingError.MaxValue": 0x8634,
    "FollowingError.MinVelocity": 0x8635,
    "PositionControl.Kpc": 0x8636,
    "Sensor[1].Interface.Type": 0x8637,
    "Actor.DriveParameter.MaxSpeed": 0x863F,
    "Actor.DataAdaption": 0x8640,
    "Sensor[1].DataAdaption": 0x8641,
    "Sensor[1].Interface.Number": 0x8646,
    "Actor.Interface.EnableDriveOutput": 0x8602,
    "Actor.Interface.DriveReadyInput": 0x8603,
    "Actor.Interface.PTO": 0x8600,
    "PositionLimits_HW.MinSwitchAddress": 0x860D,
    "PositionLimits_HW.MaxSwitchAddress": 0x860E,
    "Sensor[1].ActiveHoming.DigitalInputAddress": 0x8612,
    "Sensor[1].PassiveHoming.DigitalInputAddress": 0x8616,
    "Simulation.Mode": 0x8647,
    "Actor.PTOSliceTime": 0x864A,
    "Sensor[1].Parameter.BehaviorGx_XIST1": 0x864B,
    "Actor.Interface.PTO_SignalType": 0x8600,
    "Actor.Interface.Telegram": 0x8622,
}
#: rules that have an ErrorID of their own
_CONFIG_RULES: dict[tuple[str, str], tuple[int, int]] = {
    ("DynamicLimits.MaxVelocity", "rule:unreachable"): (0x8645, 0x0001),
    ("Simulation.Mode", "rule:pto_simulation"): (0x8647, 0x0001),
    ("DynamicLimits.MinVelocity", "rule:min_above_max"): (0x8606, 0x0007),
    ("Homing.AutoReversal", "rule:no_hw_limits"): (0x8613, 0x0001),
    ("Actor.DirectionMode", "rule:both_without_direction_output"): (0x861A, 0x002D),
    ("Sensor[1].ActiveHoming.Mode", "rule:pto_homing_mode"): (0x8617, 0x0011),
    ("Actor.PTOSliceTime", "rule:above_20ms"): (0x864A, 0x006D),
    ("Actor.Interface.Telegram", "rule:no_encoder_in_telegram"): (0x8644, 0x0068),
    ("Sensor[1].Interface.Type", "rule:encoder_on_analog_drive"): (0x8637, 0x0011),
    ("Actor.PTOSliceTime", "rule:below_2ms"): (0x864A, 0x006E),
    ("Sensor[1].Parameter.BehaviorGx_XIST1", "rule:invalid"): (0x864B, 0x0001),
    ("PositionLimits_HW.MinSwitchAddress", "rule:missing"): (0x860D, 0x000B),
    ("PositionLimits_HW.MaxSwitchAddress", "rule:missing"): (0x860E, 0x000B),
    ("PositionLimits_HW.MinSwitchAddress", "selection"): (0x860D, 0x000B),
    ("PositionLimits_HW.MaxSwitchAddress", "selection"): (0x860E, 0x000B),
    ("Sensor[1].ActiveHoming.DigitalInputAddress", "selection"): (0x8612, 0x000B),
    ("Sensor[1].PassiveHoming.DigitalInputAddress", "selection"): (0x8616, 0x0011),
    ("Actor.Interface.EnableDriveOutput", "selection"): (0x8602, 0x000B),
    ("Actor.Interface.DriveReadyInput", "selection"): (0x8603, 0x000B),
    ("Sensor[1].PassiveHoming.Mode", "rule:pto_homing_mode"): (0x8618, 0x0011),
}
_VELOCITY_FAMILY = {0x8606, 0x8607, 0x8608, 0x8609, 0x860A}
_POSITION_FAMILY = {0x8605, 0x860B, 0x860C, 0x860F}
_HOMING_VELOCITY_FAMILY = {0x8610, 0x8611}


def _config_codes(path: str, reason: str) -> tuple[int, int]:
    if (path, reason) in _CONFIG_RULES:
        return _CONFIG_RULES[(path, reason)]
    error_id = CONFIG_IDS.get(path, 0x8FFF)
    if reason in ("type", "format"):
        return error_id, INVALID_FORMAT
    if reason == "selection":
        return error_id, INVALID_SELECTION
    if error_id in _VELOCITY_FAMILY:
        return error_id, {"too_high": 0x0003, "rule:above_hw_limit": 0x0003, "too_low": 0x0004,
                          "rule:below_hw_limit": 0x0004}.get(reason, OUT_OF_RANGE)
    if error_id in _POSITION_FAMILY:
        if error_id == 0x8605 and reason == "too_low":
            return error_id, NOT_POSITIVE
        return error_id, {"too_high": ABOVE_1E12, "too_low": BELOW_MINUS_1E12}.get(reason, OUT_OF_RANGE)
    if error_id in _HOMING_VELOCITY_FAMILY:
        return error_id, {"too_high": ABOVE_MAX_VELOCITY, "rule:above_max": ABOVE_MAX_VELOCITY,
                          "too_low": BELOW_START_STOP, "rule:below_start_stop": BELOW_START_STOP}.get(reason,
                                                                                                    OUT_OF_RANGE)
    if error_id == 0x8614:
        return error_id, {"too_high": 0x001F, "rule:above_max_jerk": 0x001F, "too_low": 0x0020}.get(reason,
                                                                                                   OUT_OF_RANGE)
    if error_id == 0x8604:
        return error_id, NOT_POSITIVE
    return error_id, OUT_OF_RANGE


_TABLE: dict[tuple[str, str], tuple[int, int]] = {
    ("Type", "invalid"): (0x8700, 0x0001),
    ("Position", "format"): (0x8701, 0x0002), ("Position", "too_high"): (0x8701, 0x0005),
    ("Position", "too_low"): (0x8701, 0x0006),
    ("Velocity", "format"): (0x8702, 0x0002), ("Velocity", "above_max"): (0x8702, 0x0008),
    ("Velocity", "below_start_stop"): (0x8702, 0x0009),
    ("Duration", "format"): (0x8703, 0x0002), ("Duration", "too_long"): (0x8703, 0x0021),
    ("Duration", "too_short"): (0x8703, 0x0022),
    ("NextStep", "invalid"): (0x8704, 0x0011), ("NextStep", "not_permitted"): (0x8704, 0x0023),
}


def codes(fault: Fault) -> tuple[int, int]:
    """(ErrorID, ErrorInfo) of a kernel fault."""
    if fault.kind == F.TABLE_CONFIG:
        field, _, reason = fault.detail.partition(":")
        return _TABLE.get((field, reason), (0x8700, 0x0001))
    if fault.kind == F.CONFIG:
        path, _, reason = fault.detail.partition(":")
        return _config_codes(path, reason)
    if fault.kind == F.PENDING_ALARM:
        kind, _, detail = fault.detail.partition("/")
        return codes(Fault(kind, detail, True))
    table = _ALARMS if fault.ack else _REJECTS
    found = table.get((fault.kind, fault.detail)) or table.get((fault.kind, ""))
    if found is None:
        return 0x8FFF, 0xF000
    return found


DESCRIPTIONS: dict[int, str] = {
    0x8000: "drive error, 'Drive ready' lost",
    0x8001: "low software limit switch reached or passed",
    0x8002: "high software limit switch reached or passed",
    0x8003: "low hardware limit switch reached",
    0x8004: "high hardware limit switch reached",
    0x8005: "pulse generator (PTO) used by another enabled axis",
    0x8008: "motion direction not permitted",
    0x8009: "reference switch or zero mark not found",
    0x800A: "encoder alarm",
    0x800B: "position out of range",
    0x800C: "drive alarm",
    0x800D: "permitted following error exceeded",
    0x800E: "hardware limit switch: axis cannot be freed that way",
    0x800F: "target range not reached or left (positioning monitoring)",
    0x8010: "low software limit above high software limit",
    0x8011: "homing approach velocity is zero",
    0x8012: "homing referencing velocity is zero",
    0x8200: "axis is not enabled",
    0x8201: "axis already enabled by another MC_Power instance",
    0x8202: "too many simultaneously active commands",
    0x8204: "axis is not homed",
    0x8206: "technology object not activated yet",
    0x8207: "command rejected",
    0x8208: "difference between maximum and start/stop velocity invalid",
    0x8209: "invalid acceleration",
    0x820A: "restart of the axis not possible",
    0x8400: "invalid Position",
    0x8401: "invalid Distance",
    0x8402: "invalid Velocity",
    0x8403: "invalid Direction",
    0x8404: "invalid Mode",
    0x8405: "invalid StopMode",
    0x8406: "JogForward and JogBackward both TRUE",
    0x8407: "switch the PTO to another axis only after disabling the active one",
    0x8408: "invalid Axis",
    0x8409: "invalid CommandTable",
    0x840A: "invalid StartStep",
    0x840B: "invalid EndStep",
    0x840C: "invalid RampUpTime",
    0x840D: "invalid RampDownTime",
    0x840E: "invalid EmergencyRampTime",
    0x840F: "invalid JerkTime",
    0x8410: "invalid Parameter",
    0x8411: "invalid Value",
    0x8412: "invalid StartMode",
    0x8645: "maximum velocity cannot be reached with the drive parameters",
    0x8700: "command table: invalid command type",
    0x8701: "command table: invalid position / travel path",
    0x8702: "command table: invalid velocity",
    0x8703: "command table: invalid duration",
    0x8704: "command table: invalid next step",
    0x8FFF: "internal error",
}


def describe(error_id: int, error_info: int = 0) -> str:
    """Short description of an ErrorID (configuration errors name the faulty tag)."""
    if 0x8600 <= error_id <= 0x864B and error_id not in DESCRIPTIONS:
        tags = [p for p, e in CONFIG_IDS.items() if e == error_id]
        return "invalid configuration value " + (" / ".join(tags) if tags else "")
    return DESCRIPTIONS.get(error_id, "")
