"""What the ErrorIDs of the S7-Technology V4.1 technology DBs mean (§7.12), in our words.

One entry per code: the manual's message (its name for the code), the causes and the remedy condensed, and the
reaction of the technology object where the manual states one (§7.12, §4.5.7.2-§4.5.7.3 limit switches,
§4.7.14.5 synchronous operation monitoring, §6.5.1 output cams); ``None`` where it states none.  Texts that
differ per TO are in :data:`OVERRIDES`; which TDB lists which code, with its alarm numbers, is in
:mod:`plcmotion.s7t.technology.tdb_errors`.
"""
from __future__ import annotations

from typing import NamedTuple


class Text(NamedTuple):
    message: str
    cause: str
    remedy: str
    reaction: str | None = None


_RESTART = "MC_Reset with Restart = TRUE on the disabled TO"

# fmt: off
TEXTS: dict[int, Text] = {
    # --- warnings (00xx): Statusword.Error stays FALSE ------------------------------------------------------
    0x0010: Text("Failure of a non position-controlled encoder",
                 "the encoder of a data set that is not active failed",
                 "alarm 20015 of S7T Config names the encoder"),
    0x0020: Text("Restart to activate the parameter changes",
                 "a parameter whose change needs a restart was changed",
                 f"apply the change by a restart: {_RESTART}"),
    0x0021: Text("Dynamic response values are limited",
                 "velocity, acceleration, deceleration or jerk of the command exceed the configured limits; active "
                 "superimposed commands may add to them",
                 "check the maximum values, the speed setpoint interface, the encoder and the mechanics; acknowledge "
                 "when only one motion command is left (synchronization axis: when the superimposed motion has ended)",
                 "the dynamic values are limited to the configured maxima"),
    0x0022: Text("Internal warning", "a temporary internal problem", "see the alarm view of S7T Config"),
    0x0023: Text("Maximum acceleration limits the holding time",
                 "the configured holding time cannot be kept with the effective maximum acceleration",
                 "configure a longer holding time or a higher maximum acceleration",
                 "the holding time is prolonged"),
    0x0024: Text("No long-term stability of gearing",
                 "numerator and denominator of the gear ratio are so large that rounding drifts over a long run",
                 "use another ratio or synchronize again from time to time"),
    0x0026: Text("Position limited to software limit switch",
                 "the target of a positioning command lies beyond a software limit switch",
                 "check the computed target position",
                 "the axis travels only up to the software limit switch and then reports 8014 (§4.5.7.3)"),
    0x0027: Text("Interpolation properties cannot be maintained",
                 "position or gradient jump at a transition between cam segments",
                 "move the interpolation limits, check the profile or change the segment interpolation criteria"),
    # --- system, configuration, resources -------------------------------------------------------------------
    0x8001: Text("Fatal internal error", "project or software inconsistent; the user cannot fix it",
                 "check the project, recompile all and download; report the alarm's code to the hotline"),
    0x8002: Text("Internal error", "version conflict, firmware error or inconsistent software",
                 "check the project, recompile all and download; report the alarm's code to the hotline"),
    0x8003: Text("Fatal configuration error",
                 "the configuration is faulty, or a hardware driver or its device is missing (e.g. leadscrew pitch 0, "
                 "homing past the zero mark with an absolute encoder)",
                 "check changed parameters, the devices in HW Config and the telegram type; download the technology "
                 "again"),
    0x8004: Text("Configuration error", "the configuration of the TO is incomplete or faulty",
                 "check changed parameters and the alarm view"),
    0x8005: Text("Command memory is full", "the TO cannot store another command",
                 "raise the maximum number of active command IDs (numberOfMaxBufferedCommandId), which also raises "
                 "the command capacity"),
    0x8006: Text("Insufficient memory", "the integrated technology ran out of memory",
                 "use fewer TOs, cam points or polynomials"),
    0x8008: Text("Invalid technology DB", "the DB has no valid internal ID (e.g. it was made by copying)",
                 "generate the DB again in Technology Objects Management and download"),
    0x8009: Text("The technology DB is disabled because it was replaced with a newer instance",
                 "a newer DB with another number was downloaded for the TO", "delete this DB"),
    0x800A: Text("HW driver not available", "the driver of a device is missing or used by another TO",
                 "check the device, its wiring and the topology; compare HW Config with the TO's configuration"),
    0x8010: Text("Drive failed",
                 "drive or external device failed, or communication broke (configuration or parameter data)",
                 "check device, wiring and the telegram configured in HW Config"),
    # --- motion monitoring ----------------------------------------------------------------------------------
    0x8012: Text("Homing error", "homing mode not supported (e.g. with an absolute encoder, homing velocity 0)",
                 "check the homing configuration"),
    0x8013: Text("Hardware limit switch is active",
                 "a hardware limit switch responded, its polarity is reversed, or the retraction went the wrong way",
                 "move the axis back into its range (by hand, or acknowledge and retract with the drive); check the "
                 "switch wiring",
                 "the axis is stopped (8013 together with 804B); the error can be acknowledged for good only after "
                 "the axis has left the switch by a safety distance (§4.5.7.2)"),
    0x8014: Text("Software limit switch actuated", "a motion was stopped at the software limit switch",
                 "check the motion program",
                 "the motion stops at the limit position; an active position control stays, a speed-controlled axis "
                 "changes to position control if so configured (§4.5.7.3)"),
    0x8015: Text("Software limit switch overshot", "the axis travelled past the software limit switch",
                 "check the motion program"),
    0x8016: Text("Following error out of limits",
                 "the difference between position setpoint and actual position exceeded the configured limit",
                 "check the encoder direction, the position control loop and the following error monitoring"),
    0x8017: Text("Following error has exceeded the warning limit",
                 "the difference between position setpoint and actual position exceeded the warning limit (reported "
                 "as an error)",
                 "check the encoder direction, the position control loop and the following error monitoring"),
    0x8018: Text("Standstill monitoring error",
                 "the axis left the standstill window or did not reach it in time",
                 "check speed and position control loops and the standstill monitoring settings"),
    0x8019: Text("Positioning monitoring error", "the axis did not reach the positioning window in time",
                 "check speed and position control loops and the positioning monitoring settings"),
    0x801A: Text("Synchronous operation monitoring error",
                 "the following axis is outside the configured synchronism tolerance (setpoint or actual value)",
                 "check synchronization and desynchronization settings, gear ratio and units; raise the tolerance",
                 "the following axis is stopped; with \"report error of master axis\" configured the leading axis is "
                 "stopped too and reports 801A (§4.7.14.5)"),
    0x801B: Text("Clamping monitoring error",
                 "the clamped axis left the position tolerance after fixed end stop detection without a new command",
                 "check the end stop, the position control loop and the clamping monitoring settings"),
    0x801C: Text("Dynamic limits are exceeded",
                 "the internal monitoring intervened: the programmed values would break the limits or make the axis "
                 "reverse or overshoot",
                 "do not program override or retraction dynamics too low; allow for superimposed motions"),
    0x801D: Text("Reference cam or encoder zero mark not found",
                 "cam or zero mark outside the allowed distance, a limit monitoring responded, or too fast",
                 "check the distances and the limit monitoring; reduce the homing velocity"),
    0x801F: Text("Dynamic control loop out of range",
                 "control loops not optimized, wrong encoder direction, following error monitoring too tight, or "
                 "speed setpoint and actual speed too far apart",
                 "check the encoder direction, the control loop parameters and the following error monitoring"),
    0x8020: Text("Setpoint limiting active",
                 "the speed setpoint is limited by the manipulated variable limit",
                 "check the manipulated variable limits (Axis > Control > static controller data), the setpoint "
                 "interface, the mechanics and the encoder",
                 "the speed setpoint is limited"),
    0x8021: Text("Invalid cam position",
                 "the actual value at the cam is invalid: its axis or external encoder restarted, or the encoder's "
                 "actual value failed (e.g. drive failure)",
                 "remove the cause and acknowledge; start the output cam again",
                 "an actual-value output cam is switched off and its command aborted (§6.5.1)"),
    0x8030: Text("Limit frequency of the measuring system exceeded", "the encoder pulse rate is out of range",
                 "check the encoder wiring and the configured maximum velocity"),
    0x8031: Text("Actual value monitoring error",
                 "incremental encoder overflow, or one position-control cycle moves more than the modulo length",
                 "check the actual value adaptation of the configuration"),
    0x8032: Text("Cannot shift the coordinate system",
                 "setting or correcting the actual value would break the internal traversing limit",
                 "check the programmed shift", "the coordinate system is not shifted"),
    0x8033: Text("Encoder zero mark monitoring triggered", "wrong number of increments between two zero marks",
                 "check the encoder wiring and the configured resolution"),
    0x8034: Text("Could not record a measured value in this range",
                 "the expected edge did not come inside the measuring range",
                 "check the measuring range and the measuring input's electrics",
                 "the measurement ends without a value"),
    0x8035: Text("Measuring command canceled",
                 "drive or encoder error, aborted by the recording device, or several measuring inputs on one encoder",
                 "remove the encoder or drive error; one measuring input per encoder at a time",
                 "the measuring command is cancelled"),
    # --- command and state -----------------------------------------------------------------------------------
    0x8040: Text("The axis / external encoder are disabled, or the wrong mode is set",
                 "the enable a motion command needs is missing",
                 "acknowledge all errors and enable the object in the mode the command needs"),
    0x8041: Text("Axis not homed", "the motion command needs a homed axis",
                 "home the axis (MC_Home) or configure \"Homing required = no\""),
    0x8042: Text("Invalid change of the axis status",
                 "a state change was refused: the current phase is not finished or the transition is impossible",
                 "repeat the command; reset first"),
    0x8043: Text("Invalid command parameter value or default value",
                 "an input of the command or a configured default it uses is invalid",
                 "correct the inputs; check the defaults in use"),
    0x8044: Text("Command not supported by the technology object",
                 "the TO does not support this command (e.g. measuring at a virtual axis)",
                 "address the right object or change the configuration"),
    0x8045: Text("Command not allowed in current state",
                 "a command of higher priority (e.g. MC_Stop) is active, the TO is disabled or not ready, or a "
                 "measuring command came during homing",
                 "acknowledge errors, wait for the TO's initialization after a restart, enable it, end MC_Stop; no "
                 "measuring during homing"),
    0x8046: Text("Command not supported by the drive",
                 "the drive does not support the command (e.g. a homing method), or a measuring-input command is "
                 "active at the axis",
                 "check the drive settings and the configuration"),
    0x8047: Text("Cannot acknowledge this error",
                 "MC_Reset cannot acknowledge it (the axis was stopped by an error that stays, or new errors came "
                 "during acknowledgement or restart)",
                 "remove all causes and acknowledge again; some errors need power off and on"),
    0x8048: Text("Unable to restart", "the TO is active, or a pending error blocks the restart",
                 "acknowledge the errors and disable the TO"),
    0x8049: Text("Illegal object combination",
                 "the TOs are interconnected in a circle (each the other's master), or the axes of one synchronous "
                 "operation run at different run levels",
                 "define one leading/following direction; put leading and following axis into the same run level "
                 "(usually the interpolator cycle)"),
    0x804A: Text("Required object connection is missing",
                 "the needed combination of leading axis, following axis and cam is not configured, or the cam is not "
                 "the axis's valve profile",
                 "select the masters, cams or valve profiles at the synchronous object's configuration"),
    0x804B: Text("Limit switch active; invalid command",
                 "a hardware limit switch is active; only motions back into the operating range are allowed",
                 "check mechanics and wiring; correct the program or use software limit switches",
                 "commands that do not move towards the operating range are refused"),
    # --- cams and synchronous operation -----------------------------------------------------------------------
    0x8051: Text("Read/write access denied", "the cam was to be deleted or changed while in use",
                 "end the synchronous operation first; for a valve profile assign another cam (MC_SetCharacteristic)"),
    0x8060: Text("Error when adding a cam segment", "the new segment is faulty (e.g. start point = end point)",
                 "check the segment's values"),
    0x8061: Text("Cam point out of the domain/range",
                 "the position given to MC_GetCamPoint lies outside the cam's domain or range",
                 "give a position inside the cam"),
    0x8062: Text("Access to an interpolated cam not allowed",
                 "a command that edits the cam (e.g. MC_CamSectorAdd) reached an interpolated cam",
                 "clear the cam (MC_CamClear) before editing it"),
    0x8063: Text("Cam is not interpolated", "camming started with a cam that is not interpolated",
                 "check the cam's Status in its TDB, add points or segments and interpolate"),
    0x8064: Text("Failed to access the cam",
                 "the cam does not exist, is not interconnected with the synchronous operation or already active, or "
                 "the master position is outside its definition range",
                 "check the cam and its interconnection; for relative camming camstartpositionmaster, for non-cyclic "
                 "absolute camming the master position (with MasterOffset) must lie in the cam's domain"),
    0x8065: Text("Range violation for cam", "a cam point violates the defined cam range",
                 "check start and end positions of synchronization and desynchronization"),
    0x8072: Text("Error occurred while activating/deactivating the synchronous operation",
                 "the leading axis was in an invalid state during (de)synchronization (e.g. it reversed during "
                 "position-based synchronization)",
                 "check the leading axis's motion or choose another synchronization strategy"),
    0x8073: Text("Violation of leading axis dynamics in synchronous operation",
                 "the leading axis's dynamics are too high during (de)synchronization",
                 "check the leading axis's motion or choose another synchronization strategy"),
    0x8074: Text("The leading axis is not configured for synchronous operation",
                 "the axis at Master is not a configured leading axis, an external encoder as master is not enabled, "
                 "or the leading axis runs speed-controlled",
                 "configure the leading axis or use a configured one; run it position-controlled or enable it"),
    0x8077: Text("Deactivation of synchronous operation aborted",
                 "the end command does not match the coupling (gearing vs camming)",
                 "end camming with MC_CamOut, gearing with MC_GearOut, or use MC_Halt / MC_Stop"),
    0x8078: Text("Superimposed synchronous operation is not possible",
                 "superimposed synchronous operation was configured for the axis in the expert list",
                 "correct the expert list"),
    0x8082: Text("Invalid Zero value in parameter", "a parameter that must not be 0 is 0",
                 "check parameters, defaults and dynamic limits (e.g. maximum velocity, deceleration)"),
    0x8085: Text("Impermissible end limit configuration",
                 "software limit switch positions implausible (out of range, or the negative above the positive one, "
                 "e.g. from the order of changes)",
                 "correct the software limit switches: the positive must lie above the negative one"),
    0x8087: Text("Illegal output cam position",
                 "at least one cam position lies beyond the operating range (e.g. moved by the delay/rate time)",
                 "check the cam positions; reduce the delay time"),
}

#: texts that differ for one technology DB: (table, code) -> Text
OVERRIDES: dict[tuple[str, int], Text] = {
    ("synchronization axis", 0x801C): Text(
        "Dynamic limits are exceeded",
        "the internal monitoring intervened (programmed values would break the limits or make the axis reverse or "
        "overshoot), or the leading axis needs higher dynamics during synchronization than the following axis's "
        "synchronization values",
        "do not program override or retraction dynamics too low; to synchronize with the following axis's own "
        "dynamics set SyncingMotion.synchronizingAdaption = NO (parameter 4337)",
        "the following axis ignores its synchronization dynamics and follows the leading axis"),
    ("external encoder", 0x8046): Text(
        "Command not supported by the drive",
        "the drive does not support the command (e.g. a homing method), or a measuring-input command is active at "
        "the external encoder",
        "check the drive settings and the configuration"),
    # the limit switch texts of the external encoder's table name no stop: an encoder does not move by itself
    ("external encoder", 0x8013): TEXTS[0x8013]._replace(reaction=None),
    ("external encoder", 0x804B): TEXTS[0x804B]._replace(reaction=None),
    ("measuring input", 0x8044): Text(
        "Command not supported by the technology object",
        "the TO does not support this command, e.g. a measurement at a virtual axis",
        "use the right object or configuration"),
    ("output cam", 0x8043): Text(
        "Invalid command parameter value or default value",
        "an input or a default is invalid, e.g. a switching position outside the axis's operating range",
        "correct the inputs; check the defaults in use"),
    ("cam track", 0x8043): Text(
        "Invalid command parameter value or default value",
        "an input or a default is invalid, e.g. a single cam's switching position outside the operating range, or "
        "CamTrackLength 0 or negative",
        "correct the inputs; check the defaults in use"),
    ("cam track", 0x8087): Text(
        "Illegal output cam position", "at least one single output cam position is illegal",
        "check the single cam positions; reduce the delay time"),
}
# fmt: on

#: message of 8004 for the TOs other than axis, synchronization axis and external encoder
PARAMETER_ASSIGNMENT_ERROR = "Parameter assignment error"
