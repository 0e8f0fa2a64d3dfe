"""Technology alarms of the S7-1500 technology objects: the CPU's numbers, reactions, ErrorWord/WarningWord
bits and restart needs (S7-1500T V5 §7.1.1, §A.1.39-§A.1.41, §A.2.9-§A.2.11, §A.3.7-§A.3.9; the numbers
and reactions from the CPU's alarm list, ../shared/reference/s7-1500-errorids.md §4).

``ALARMS`` is the one table: the technology objects read their ``ErrorDetail``/``ErrorWord``/``WarningWord``
from it, the S7-1500 axis takes the reaction it executes from it (``enforce``), and docs/s7_1500/alarms.md
is rendered from it (``render_markdown``; a test keeps the page current).  The kernel reports its faults
in its own vocabulary (``kernel.faults``); :func:`number` says which CPU alarm each one is.  The choices
where the CPU's list needed a reading are rows #79-#101 of docs/s7_1500/decisions.md.
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Iterable

from ...kernel import faults as F
from ...kernel.faults import Fault, Reaction

#: ErrorDetail.Reaction of an axis (§A.1.40)
REACTIONS = {0: "no reaction", 1: "stop with current dynamic values", 2: "stop with maximum dynamic values",
             3: "stop with emergency stop ramp", 4: "remove enable", 5: "track setpoints"}
#: ErrorDetail.Reaction of the other technology objects that stop their processing (§A.2.10, §A.3.8)
CAM_STOP, PROXY_INVALID, ENCODER_DISABLE = 6, 13, 4
#: the kernel reaction that carries out an axis reaction code
KERNEL_REACTION = {0: Reaction.NONE, 2: Reaction.MAX_DYNAMICS, 3: Reaction.EMERGENCY, 4: Reaction.REMOVE_ENABLE}
#: which pending alarm ErrorDetail shows: the one with the strongest reaction (decisions.md #97)
_SEVERITY = {4: 5, 5: 4, 3: 3, 2: 2, 1: 1, 0: 0}

AXIS, ENCODER, PROXY, CAM = "axis", "external encoder", "leading axis proxy", "cam"


@dataclass(frozen=True)
class Alarm:
    """One technology alarm as the CPU reports it and as plcmotion raises it."""

    number: int
    title: str
    meaning: str                 # in our own words
    arises: str                  # where plcmotion raises it
    reaction: int                # ErrorDetail.Reaction on an axis (0 for a warning)
    word: str                    # "E" ErrorWord or "W" WarningWord
    bit: int
    restart: bool                # needs a restart of the technology object (MC_Reset Restart = TRUE)
    remedy: str
    objects: tuple[str, ...] = (AXIS,)
    #: the axis carries out ``reaction`` (False: the kernel has planned the motion already - the stop at
    #: a software limit switch - and the reaction is only shown)
    enforce: bool = True
    #: details of the kernel fault that need a restart although the alarm as such does not
    restart_details: tuple[str, ...] = ()

    @property
    def warning(self) -> bool:
        return self.word == "W"


_A = Alarm
ALARMS: dict[int, Alarm] = {a.number: a for a in (
    _A(101, "Configuration error",
       "a configuration value is not allowed or contradicts another one",
       "MC_Power or the effective moment of a written tag finds a value outside its range or a broken rule "
       "(other than the dynamic limits and the software limit switch order)",
       4, "E", 1, True, "correct the value (start value or program), then restart the technology object "
       "(MC_Reset with Restart = TRUE while disabled)"),
    _A(104, "Software limit switches swapped",
       "the negative software limit switch does not lie below the positive one",
       "PositionLimits_SW.MinPosition >= MaxPosition becomes effective while the axis runs",
       2, "E", 1, False, "write limit positions with MinPosition < MaxPosition, then MC_Reset"),
    _A(201, "Internal error",
       "the technology object met a defect it cannot continue from",
       "an exception inside the kernel or an instruction while handling the object (also 16#8FFF at the job)",
       4, "E", 0, True, "restart the technology object; report the case with last_internal_error",
       (AXIS, ENCODER, CAM)),
    _A(304, "Velocity limit zero",
       "the velocity limit in force is zero, so no motion can be planned",
       "DynamicLimits.Velocity written as 0 (or below) becomes effective",
       3, "E", 2, False, "write a positive DynamicLimits.Velocity, then MC_Reset"),
    _A(305, "Acceleration or deceleration limit zero",
       "an acceleration or deceleration limit in force is zero",
       "DynamicLimits.MaxAcceleration, MaxDeceleration or DynamicDefaults.EmergencyDeceleration written as "
       "0 (or below) becomes effective",
       3, "E", 2, False, "write a positive value, then MC_Reset"),
    _A(321, "Axis not homed",
       "an absolute positioning needs a homed axis",
       "MC_MoveAbsolute starts while StatusWord.HomingDone is FALSE",
       3, "E", 3, False, "home the axis (MC_Home) and acknowledge with MC_Reset"),
    _A(341, "Homing data not usable",
       "the approach or homing velocity of active homing cannot be used",
       "MC_Home Mode 3/5 with Homing.ApproachVelocity or ReferencingVelocity 0 or above the velocity limit",
       2, "E", 10, False, "write a usable homing velocity, then MC_Reset"),
    _A(342, "Reference mark not found",
       "active homing did not find the homing mark in the travel range",
       "MC_Home active homing runs into a hardware limit switch without reversal, or the search ends",
       3, "E", 10, False, "check the homing cam / zero mark and the approach direction, then MC_Reset"),
    _A(411, "Encoder error",
       "the encoder reports an error; its actual values are not valid",
       "a fault of the simulated encoder (inject_fault 'encoder' / 'encoder_loss' off the bus), invalid actual "
       "values at enable, an external encoder whose measured value is no number in range",
       4, "E", 5, False, "remove the encoder fault, then MC_Reset", (AXIS, ENCODER)),
    _A(412, "Actual value outside its range",
       "the actual value left the measuring range of the absolute encoder or jumped by more than one "
       "modulo length within a servo cycle",
       "the limit-switch watch of an axis with an absolute encoder or a modulo axis",
       4, "E", 5, False, "bring the axis back into the range / check the encoder, then MC_Reset"),
    _A(421, "Drive error",
       "the drive reports a fault or does not become ready",
       "a fault of the simulated drive (inject_fault 'drive', 'drive_not_ready'), a drive on a bus that "
       "reports a fault, a drive ready signal that drops",
       4, "E", 4, False, "remove the drive fault, then MC_Reset"),
    _A(431, "Communication error",
       "the cyclic communication with the drive or the encoder failed or lost its sign of life",
       "inject_fault with detail 'station' or 'sign_of_life', 'communication_loss', 'encoder_loss' on the bus",
       4, "E", 7, False, "restore the communication, then MC_Reset", (AXIS, ENCODER)),
    _A(501, "Velocity limited",
       "a job asked for more velocity than the dynamic limits allow; it runs at the limit",
       "MC_Move*/MC_Halt/MC_MoveJog/synchronous jobs above DynamicLimits.Velocity",
       0, "W", 6, False, "lower the velocity of the job or raise the limit"),
    _A(502, "Acceleration limited",
       "a job asked for more acceleration or deceleration than the dynamic limits allow",
       "a job above DynamicLimits.MaxAcceleration / MaxDeceleration",
       0, "W", 6, False, "lower the job's acceleration/deceleration or raise the limit"),
    _A(503, "Jerk limited",
       "a job asked for more jerk than the dynamic limits allow",
       "a job above DynamicLimits.MaxJerk",
       0, "W", 6, False, "lower the job's jerk or raise the limit"),
    _A(521, "Following error too large",
       "the difference between setpoint and actual position exceeds the permitted following error",
       "the following error monitoring of a drive axis (FollowingError.*)",
       4, "E", 11, False, "check the drive, the load and the position controller; then MC_Reset"),
    _A(522, "Following error warning",
       "the following error passed the warning level of the permitted following error",
       "the following error monitoring (FollowingError.WarningLevel)",
       0, "W", 11, False, "none needed; check the drive tuning if it recurs"),
    _A(531, "Hardware limit switch",
       "a hardware limit switch was reached, or a move into an actuated switch was asked for",
       "the input watch of PositionLimits_HW; a job towards an actuated switch; both switches at once or a "
       "switch actuated against the direction of travel (swapped switches: restart needed)",
       4, "E", 9, False, "acknowledge with MC_Reset and move away from the switch; with swapped or both "
       "switches fix the wiring and restart the technology object", restart_details=("polarity", "both")),
    _A(533, "Software limit switch reached",
       "the motion stopped at a software limit switch",
       "a job whose motion would pass PositionLimits_SW stops at the switch position (also in synchronous "
       "operation)",
       2, "E", 8, False, "acknowledge with MC_Reset and move back into the working range", enforce=False),
    _A(534, "Software limit switch passed",
       "the axis is beyond a software limit switch",
       "a motion that could not stop before the switch position (switches activated or moved while moving)",
       4, "E", 8, False, "acknowledge with MC_Reset and move back into the working range", enforce=False),
    _A(541, "Positioning monitoring",
       "the axis did not reach the positioning window in the tolerance time, or left it within the "
       "minimum dwell time",
       "the end of an MC_MoveAbsolute/MC_MoveRelative/MC_Halt on a drive axis (PositioningMonitoring.*)",
       4, "E", 12, False, "check the drive and the monitoring values; then MC_Reset"),
    _A(601, "Leading value error",
       "the leading axis given is not a configured possible leading value of the following axis, or its "
       "leading value became invalid",
       "MC_GearIn/MC_GearInPos/MC_CamIn with an unconfigured Master; a coupled leading axis proxy or external "
       "encoder whose value becomes invalid",
       2, "E", 14, False, "configure the leading value / restore the leading value, then MC_Reset"),
    _A(612, "Cam not interpolated",
       "the cam given for camming has not been interpolated",
       "MC_CamIn with a cam technology object that MC_InterpolateCam has not interpolated (since its start or "
       "its last restart)",
       4, "E", 2, False, "interpolate the cam with MC_InterpolateCam, then MC_Reset and start MC_CamIn again"),
    _A(900, "External leading value invalid",
       "no valid leading value telegram arrived within the tolerance time",
       "the leading axis proxy (Parameter.ToleranceTimeExternalLeadingValueInvalid)",
       0, "E", 2, False, "restore the cross-PLC transfer, then MC_Reset at the proxy", (PROXY,)),
)}

#: kernel fault kind -> alarm number where the kind alone decides (see ``number``)
_BY_KIND = {
    F.INTERNAL: 201, F.SW_LIMIT_ORDER: 104, F.NOT_HOMED: 321, F.HOMING_APPROACH_ZERO: 341,
    F.HOMING_REFERENCING_ZERO: 341, F.REFERENCE_NOT_FOUND: 342, F.POSITION_RANGE: 412, F.DRIVE_NOT_READY: 421,
    F.FOLLOWING_ERROR: 521, F.HW_LIMIT_MIN: 531, F.HW_LIMIT_MAX: 531, F.HW_LIMIT_FREE: 531,
    F.POSITIONING: 541, F.STANDSTILL: 541, F.SYNC_MASTER: 601, F.LV_INVALID: 601, F.CAM_NOT_INTERPOLATED: 612,
}
_COMMUNICATION = ("station", "sign_of_life")
_VELOCITY_LIMITS = ("DynamicLimits.Velocity", "DynamicLimits.MaxVelocity")
_ACCELERATION_LIMITS = ("DynamicLimits.MaxAcceleration", "DynamicLimits.MaxDeceleration",
                        "DynamicDefaults.EmergencyDeceleration")
#: dynamic value notes of an axis (``LayeredAxis.warnings``) -> warning number
WARNING_OF_LIMIT = {"velocity": 501, "acceleration": 502, "deceleration": 502, "jerk": 503}


def _config_number(detail: str) -> int:
    path, _, reason = detail.partition(":")
    if reason == "too_low" and path in _VELOCITY_LIMITS:
        return 304
    if reason == "too_low" and path in _ACCELERATION_LIMITS:
        return 305
    if path == "PositionLimits_SW.MinPosition" and reason == "rule:low_above_high":
        return 104
    if path.startswith("Homing.") and path.endswith("Velocity"):
        return 341
    return 101


def number(fault: Fault, owner: str = AXIS) -> int:
    """The CPU's alarm number of a kernel alarm raised on a technology object of kind ``owner``."""
    kind, detail = fault.kind, fault.detail
    if owner == PROXY and kind == F.LV_INVALID:
        return 900
    if kind in (F.DRIVE_ALARM, F.ENCODER):
        if detail in _COMMUNICATION:
            return 431
        return 421 if kind == F.DRIVE_ALARM else 411
    if kind in (F.SW_LIMIT_MIN, F.SW_LIMIT_MAX):
        return 534 if detail == "exceeded" else 533
    if kind == F.CONFIG:
        return _config_number(detail)
    return _BY_KIND.get(kind, 201)


def alarm_of(fault: Fault, owner: str = AXIS) -> Alarm:
    return ALARMS[number(fault, owner)]


def needs_restart(fault: Fault, owner: str = AXIS) -> bool:
    """Only a restart of the technology object clears this alarm (MC_Reset Restart = TRUE)."""
    alarm = alarm_of(fault, owner)
    return alarm.restart or fault.detail in alarm.restart_details


def reaction_code(fault: Fault, owner: str = AXIS) -> int:
    """ErrorDetail.Reaction of ``fault`` on a technology object of kind ``owner``."""
    alarm = alarm_of(fault, owner)
    if alarm.warning:
        return 0
    return {AXIS: alarm.reaction, ENCODER: ENCODER_DISABLE, PROXY: PROXY_INVALID, CAM: CAM_STOP}[owner]


def enforce(fault: Fault) -> Fault:
    """``fault`` with the kernel reaction that carries out the CPU's axis reaction of its alarm."""
    alarm = alarm_of(fault)
    if not alarm.enforce:
        return fault
    wanted = KERNEL_REACTION[alarm.reaction]
    return fault if fault.reaction == wanted else dataclasses.replace(fault, reaction=wanted)


def shown(alarms: Iterable[Fault], owner: str = AXIS) -> Fault | None:
    """The pending alarm ErrorDetail shows: the strongest reaction, the earliest among equals."""
    best: Fault | None = None
    rank = -1
    for fault in alarms:
        r = _SEVERITY.get(reaction_code(fault, owner), 0)
        if r > rank:
            best, rank = fault, r
    return best


def error_detail(alarms: list[Fault], owner: str = AXIS) -> tuple[int, int]:
    """(ErrorDetail.Number, ErrorDetail.Reaction) of a technology object with these pending alarms."""
    fault = shown(alarms, owner)
    if fault is None:
        return 0, 0
    return number(fault, owner), reaction_code(fault, owner)


def error_bits(alarms: Iterable[Fault], owner: str = AXIS) -> dict[int, bool]:
    """ErrorWord bits of the pending alarms."""
    bits: dict[int, bool] = {}
    for fault in alarms:
        alarm = alarm_of(fault, owner)
        if not alarm.warning:
            bits[alarm.bit] = True
    return bits


def restart_required(alarms: Iterable[Fault], owner: str = AXIS) -> bool:
    """StatusWord.X3 (shown by the manual as "Restart required", §7.1.1): a pending alarm needs a restart."""
    return any(needs_restart(f, owner) for f in alarms)


def alarm_text(number_: int, reaction: int | None = None) -> str:
    """``"alarm 521 Following error too large (reaction: remove enable)"``."""
    alarm = ALARMS.get(number_)
    text = f"alarm {number_} {alarm.title if alarm is not None else 'technology alarm'}"
    if reaction is None:
        return text
    return text + f" (reaction: {REACTIONS.get(reaction, reaction)})"


def describe(fault: Fault) -> str:
    """A kernel fault as the S7-1500 axis alarm with its number, title and reaction (messages, CLI)."""
    return alarm_text(number(fault), reaction_code(fault))


# --- the documentation page ---------------------------------------------------------------------------------
_OWNER_REACTION = {ENCODER: f"{ENCODER_DISABLE} (the external encoder is disabled)",
                   PROXY: f"{PROXY_INVALID} (the leading value is invalid)",
                   CAM: f"{CAM_STOP} (processing of the cam ends)"}


def _reaction_cell(alarm: Alarm) -> str:
    if alarm.warning:
        return "0 (warning)"
    parts = []
    if AXIS in alarm.objects:
        parts.append(f"{alarm.reaction} ({REACTIONS[alarm.reaction]})")
    parts += [f"{o}: {_OWNER_REACTION[o]}" for o in alarm.objects if o != AXIS]
    return "; ".join(parts)


def render_markdown() -> str:
    """docs/s7_1500/alarms.md from ``ALARMS`` (tests/s7_1500/test_s7_1500_alarm_table.py keeps it current)."""
    lines = [
        "# Technology alarms of the S7-1500 technology objects",
        "",
        "Generated from `plcmotion.s7_1500.technology.alarms.ALARMS` (`render_markdown()`); do not edit by hand.",
        "",
        "A technology alarm is pending on a technology object until it is acknowledged: `<TO>.StatusWord.X1`",
        "(Error), its bit in `<TO>.ErrorWord` (a warning: in `<TO>.WarningWord`), and `<TO>.ErrorDetail.Number`",
        "/ `ErrorDetail.Reaction` of the pending alarm with the strongest reaction (warnings do not show in",
        "ErrorDetail). An instruction whose job the alarm ends, or that is called while it blocks the object,",
        "shows ErrorID 16#8001. MC_Reset acknowledges an alarm whose cause is gone; an alarm marked *restart*",
        "sets `StatusWord.X3` (RestartRequired) and is cleared only by a restart of the technology object",
        "(MC_Power Enable = FALSE, then MC_Reset with Restart = TRUE). Reactions of an axis (S7-1500T V5",
        "§A.1.40): " + ", ".join(f"{k} {v}" for k, v in REACTIONS.items()) + ". The external encoder shows 4",
        "(disabled), the cam 6 (processing ends, §A.2.10), the leading axis proxy 13 (leading value invalid,",
        "§A.3.8). Decisions: [decisions.md](decisions.md).",
        "",
        "| No. | Alarm | Meaning | Where plcmotion raises it | Reaction | Bit | Restart | Remedy |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for a in ALARMS.values():
        word = "ErrorWord" if a.word == "E" else "WarningWord"
        restart = "yes" if a.restart else ("with " + ", ".join(a.restart_details) if a.restart_details else "no")
        objects = "" if a.objects == (AXIS,) else " (" + ", ".join(a.objects) + ")"
        lines.append(f"| {a.number} | {a.title}{objects} | {a.meaning} | {a.arises} | {_reaction_cell(a)} | "
                     f"{word}.X{a.bit} | {restart} | {a.remedy} |")
    lines += ["", "Alarms of the CPU's list that plcmotion does not raise (no situation of the model leads there, "
              "decisions.md #101): 102, 103, 105-114 (drive/encoder adaptation, isochronous mode, cross-PLC "
              "configuration), 202-204, 306 (MaxJerk 0 means no jerk limit), 307, 308 (targets beyond 1.0E12 are "
              "refused at the instruction), 322, 323, 343, 401, 504, 511, 542, 550 (a drive moving on its own: the "
              "simulated drives have no such function), 551, 552, 561-563, 603, 608, 700-758 (output cams, cam "
              "tracks, measuring inputs), 801-820 (kinematics), 901-903, 1001-1012 (Interpreter). Reaction 5 "
              "(follow-up setpoints) belongs to 550 only, so no alarm shows it.", ""]
    return "\n".join(lines)


if __name__ == "__main__":      # python -m plcmotion.s7_1500.technology.alarms > docs/s7_1500/alarms.md
    print(render_markdown(), end="")
