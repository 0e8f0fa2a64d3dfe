"""FB-level ErrorIDs of the S7-Technology V4.1 technology functions (FB 401 ... FB 463, §6).

An FB reports at ``Error``/``ErrorID`` that a command could not be *started* (16#80xx, 16#81xx) and a few
warnings (16#00xx); errors found while a command runs go to the technology DB instead
(:mod:`plcmotion.s7t.technology.tdb_errors`).  Each FB's table of §6 lists the codes it can give, most of
them with the same meaning in every FB (:data:`COMMON`); :mod:`plcmotion.s7t.fb_tables` holds the per-FB sets
and the FB-specific causes.  Texts are ours, the codes and names the manual's.
"""
from __future__ import annotations

from dataclasses import dataclass

from .fb_tables import FB_BY_NAME, FB_NAMES, table  # noqa: F401  (FB_NAMES: FB number -> name, re-exported)

# --- named codes (common list of §6, every FB table repeats them) ---------------------------------------------
NO_ERROR = 0x0000
INTERNAL_ERROR = 0x8001
COMMAND_MEMORY_FULL = 0x8005            # command memory in use by another process
INSUFFICIENT_MEMORY = 0x8006
TRANSFER_BUFFER_BUSY = 0x800B
NO_ACTUAL_VALUE = 0x8022
NO_MEASURED_VALUE = 0x8034
DISABLED_OR_WRONG_MODE = 0x8040
ILLEGAL_PARAMETER = 0x8043
NOT_SUPPORTED = 0x8044                  # command not supported by the technology object
NOT_ALLOWED = 0x8045                    # command not allowed in the current state
CANNOT_ACKNOWLEDGE = 0x8047
CANNOT_RESTART = 0x8048
OBJECT_CONNECTION_MISSING = 0x804A
RATE_TOO_HIGH = 0x804C                  # commands of one instance DB faster than the interface takes them
INVALID_AXIS_TYPE = 0x804D
ONE_INSTANCE_PER_AXIS = 0x804E
AXIS_CHANGE_AT_POWER = 0x804F
TECHNOLOGY_NOT_READY = 0x8050
ACCESS_DENIED = 0x8051
DIFFERENT_RUN_LEVELS = 0x8052
INVALID_INSTANCE_DB = 0x8053
DEACTIVATION_NOT_PERMITTED = 0x8054
LATCHING_NOT_ALLOWED = 0x8055           # appending / overlaying refused
FIXED_STOP_ACTIVE = 0x8056              # axis clamped: only motions away from the end stop
ACTIVATION_ALREADY_ACTIVE = 0x8057
DP_SLAVE_NOT_CONFIGURABLE = 0x8058
CAM_POINT_OUT_OF_RANGE = 0x8061
CAM_INTERPOLATED = 0x8062
CAM_EMPTY = 0x8066
NO_SYNCHRONOUS_OPERATION = 0x8079
INVALID_MASTER_SETPOINT = 0x807A
RECURSIVE_INTERCONNECTION = 0x807B
INVALID_PARAMETER_NUMBER = 0x8080
PARAMETER_READ_ONLY = 0x8081
NOT_A_TECHNOLOGY_DB = 0x8083
INVALID_TECHNOLOGY_DB = 0x8084
PARAMETER_NOT_AVAILABLE = 0x8086
INVALID_ANY_DB = 0x8088
INVALID_DATA_LENGTH = 0x8089
INVALID_REAL_IN_DB = 0x808A
INVALID_REAL = 0x808B                   # an input holds no valid REAL
INVALID_POINTER = 0x808C
RECORD_TOO_LONG = 0x808D
INVALID_DATA_FORMAT = 0x808E
INVALID_ADDRESS = 0x8090
# warnings an FB reports itself
RESTART_REQUIRED = 0x0020
DYNAMICS_LIMITED = 0x0021
INTERPOLATION_PROPERTY = 0x0027
ILLEGAL_VALUE_IGNORED = 0x0028
END_POS_REVERSE_IGNORED = 0x0029


@dataclass(frozen=True)
class FBCode:
    """An FB ErrorID: its name in the manual and what to do about it (our words)."""
    code: int
    message: str
    remedy: str = ""

    @property
    def warning(self) -> bool:
        return self.code < 0x8000


def _t(*rows: tuple[int, str, str]) -> dict[int, FBCode]:
    return {c: FBCode(c, m, r) for c, m, r in rows}


# fmt: off
#: the meaning every FB table gives a code (§6, catalog part 2 §1.3); FB-specific causes in fb_tables
COMMON: dict[int, FBCode] = _t(
    (0x0000, "No error", ""),
    (0x0020, "Restart to activate the parameter changes",
     "The change waits for a restart of the TO (MC_Reset with Restart = TRUE); none is needed if the value did not "
     "change. Axes and external encoders show it in Statusword.RequestRestart, output cams and measuring inputs "
     "with ErrorID 0020 in their technology DB."),
    (0x0021, "Dynamic response values are limited",
     "The commanded dynamics exceed the configured limits and were limited; check the values."),
    (0x0027, "Interpolation property can not be maintained",
     "A segment transition of the cam is not continuous as the interpolation type requires; check the segments."),
    (0x0028, "Illegal parameter value was ignored", "The default value was used instead of the invalid input."),
    (0x0029, '"MC_MoveToEndPos" ignored in reverse direction',
     "A MC_MoveToEndPos may replace an active one only in the same direction."),
    (0x8001, "Internal error", "Project or software inconsistent: recompile and download."),
    (0x8005, "Command canceled because command memory is in use by another process",
     "Too many commands are active (in particular of the record, periphery, cam-sector and cam-track data FBs). "
     "Keep calling each FB until Done, CommandAborted or Error, and avoid redundant commands."),
    (0x8006, "Insufficient memory", "The integrated technology is out of memory; use fewer points or objects."),
    (0x800B, "Transfer buffer cannot be reserved",
     "Another data-transfer command (cam sectors, periphery, records, drive parameters, cam-track data) holds the "
     "buffer; do not run them at the same time."),
    (0x8022, "No actual value at the axis / external encoder",
     "Encoder or bus not ready; check that the actual value is valid before the command."),
    (0x8034, "Could not record a measured value in the measuring range",
     "No edge in the range; check the range and the measuring input."),
    (0x8040, "The axis / external encoder is disabled, or wrong mode",
     "Acknowledge errors and enable the object in the mode the command needs (e.g. position-controlled)."),
    (0x8043, "Illegal parameter value",
     "An input (REAL, Mode, Direction, DoneFlag, ...) or a configured default used by the command is out of range."),
    (0x8044, "Command not supported by the technology object",
     "The TDB at the input is a TO type this FB does not serve (e.g. an output cam at a motion FB)."),
    (0x8045, "Command not allowed in current state",
     "Typically MC_Stop active, TO deactivated, restart running or pending, or changes being collected."),
    (0x8047, "Cannot acknowledge this error",
     "Remove the cause first; some errors need a power cycle."),
    (0x8048, "Unable to restart", "A restart needs a disabled axis / an unused cam."),
    (0x804A, "Required object connection is missing",
     "Select the master, cam or valve profile at the object's configuration."),
    (0x804C, "Command output rate too high",
     "Commands of the same instance DB came faster than the interface takes them; the second was refused. Use "
     "separate instance DBs or repeat."),
    (0x804D, "Invalid axis type", "The command needs another axis type (e.g. a real electric axis)."),
    (0x804E, "Only one instance allowed per axis", "Another MC_Power instance is busy on this axis."),
    (0x804F, 'Change of the axis at "MC_Power" is not allowed',
     "Only the MC_Power instance that enabled an axis can disable it."),
    (0x8050, "Technology not ready", "CPU in HOLD (breakpoint test) or the command came from a restart OB."),
    (0x8051, "Read/write access denied", "The cam is in use (synchronous operation or valve profile)."),
    (0x8052, "Block call at different run levels",
     "One instance DB called in OBs that interrupt each other; use one instance DB per run level."),
    (0x8053, "Invalid instance DB", "The instance DB is faulty (e.g. wrong length)."),
    (0x8054, "Deactivation of a technology object not permitted", "The TO is still in use."),
    (0x8055, "Latching motion not allowed in current state",
     "Appending or overlaying is refused while synchronous operation or MC_Halt is active."),
    (0x8056, "Cancellation due to active travel to fixed stop",
     "The axis is clamped; only commands moving away from the end stop are accepted."),
    (0x8057, "A deactivation / activation command is already active", "Wait for the running command."),
    (0x8058, "DP slave cannot be configured", "The slave's configuration could not be loaded on activation."),
    (0x8061, "Cam point out of the domain/range", "The position lies outside the cam's definition or value range."),
    (0x8062, "Access to interpolated cam not permitted", "Clear the cam (MC_CamClear) before editing it."),
    (0x8066, "The cam disk is empty", "Add points or segments before interpolating."),
    (0x8079, "No synchronous operation with specified master active",
     "Start gearing or camming with this master first."),
    (0x807A, "Invalid master setpoint", "The leading axis delivers no valid value."),
    (0x807B, "Recursive interconnection of technology objects",
     "The master takes its value (directly or not) from the slave."),
    (0x8080, "Invalid parameter number or parameter index", "The TO has no such parameter or index."),
    (0x8081, "Parameter cannot be changed", "The parameter is read-only."),
    (0x8083, "DB is not a technology DB", "The DB at the TO input is missing or no technology DB."),
    (0x8084, "Invalid technology DB",
     "No TO exists for this technology DB, or the DB holds invalid data; download the technology or regenerate "
     "the DB."),
    (0x8086, "Parameter not available", "Not readable now (inactive data set, restart, encoder type); retry."),
    (0x8088, "Invalid DB (ANY pointer)", "The ANY pointer names no DB, or the area is too short."),
    (0x8089, "Invalid data length (ANY pointer)", "The data area's length does not fit the FB's rule."),
    (0x808A, "Invalid REAL values in DB", "The data area holds values that are no valid REAL."),
    (0x808B, "Parameter value of invalid REAL format", "A REAL input holds no valid floating-point value."),
    (0x808C, "Pointer format is invalid or not supported", "Use an ANY pointer to an allowed area and type."),
    (0x808D, "Data record length out of range", "The record is longer than the FB can transfer."),
    (0x808E, "Invalid data format", "The data do not match the parameter's format."),
    (0x8090, "Invalid logical base address", "No module at that address, or it is not a base address."),
    (0x8091, "Logical base address is not available", "The address is not on DP(DRIVE) (e.g. CPU I/O)."),
    (0x8092, "Faulty response ID", "Data record transfer failed."),
    (0x80A0, "Error when reading module data", "Negative acknowledgement: module removed or defective."),
    (0x80A1, "Error when writing to module", "Negative acknowledgement: module removed or defective."),
    (0x80A2, "DP protocol error in layer 2", "Retry in the next cycle."),
    (0x80A3, "DP protocol error in user interface", "Data record transfer failed."),
    (0x80B0, "Data record not supported", "The module has no such record (number 0..255)."),
    (0x80B1, "Faulty length definition", "The Data area does not fit the record's length."),
    (0x80B5, "System function cannot be executed", "Not possible in the drive's present state; retry."),
    (0x80B7, "Faulty command", "PROFIBUS DP error."),
    (0x80C0, "No read data", "Retry in the next cycle."),
    (0x80C2, "Maximum number of commands reached", "Retry immediately."),
    (0x80C3, "Module at capacity limits", "Resources busy; retry immediately."),
    (0x80C4, "Communication error", "Retry immediately."),
    (0x80C5, "Access to distributed I/O failed", "Retry in the next cycle."),
    (0x80C6, "Priority class error", "Retry in the next cycle."),
    (0x80C7, "A command has already been output to the drive", "Retry in the next cycle."),
    (0x8100, "Parameter not found", "The drive has no such parameter."),
    (0x8101, "Parameter cannot be changed", "The drive parameter is read-only."),
    (0x8102, "Parameter limits violated", "The value is outside the drive parameter's limits."),
    (0x8103, "Subindex not found", "The drive parameter has no such subindex."),
    (0x8104, "Parameter not indexed", "Use NumberOfElements = 0 for this drive parameter."),
    (0x8105, "Invalid data type", "The data type does not match the drive parameter."),
    (0x8106, "Parameter value unequal 0", "Only 0 may be written."),
    (0x810B, "No exclusive access", "Another master holds the parameter."),
    (0x8111, "Access denied in current state", "Not accessible in the drive's present state."),
    (0x8114, "Illegal parameter value", "The value is not allowed for this drive parameter."),
    (0x8115, "Max. transferable length exceeded", "Fewer elements per request."),
    (0x8116, "Value is invalid or not supported", "Check attribute, number of elements, number and subindex."),
    (0x8117, "Invalid format", "The value's format is invalid."),
    (0x8118, "Invalid number of parameter data", "Number of values and of addresses differ."),
    (0x8119, "Axis does not exist", "The drive has no such axis."),
)
# fmt: on

#: code ranges some FB tables give as one row (PROFIdrive parameter errors of the drive)
RANGES: dict[tuple[int, int], FBCode] = {
    (0x8120, 0x8164): FBCode(0x8120, "Reserved parameter error of the drive", "See the drive's documentation."),
    (0x8165, 0x81FF): FBCode(0x8165, "Manufacturer-specific parameter error of the drive",
                             "See the drive's documentation."),
}


def common(code: int) -> FBCode | None:
    """The general meaning of an FB ErrorID (also for codes of the drive ranges), None if unknown."""
    if code in COMMON:
        return COMMON[code]
    for (lo, hi), entry in RANGES.items():
        if lo <= code <= hi:
            return FBCode(code, entry.message, entry.remedy)
    return None


def fb_codes(fb_name: str) -> frozenset[int]:
    """All ErrorIDs the FB's table lists (0000 included); KeyError for an FB name §6 does not have."""
    return table(fb_name).all_codes()


def describe(code: int, fb_name: str | None = None) -> str:
    """"16#8043 Illegal parameter value: ..." for an FB ErrorID; with ``fb_name`` the FB's own cause is added, and
    a code the FB's table does not list is said to be so.  An unknown code is named as unknown.  Never raises."""
    try:
        code = int(code)
    except (TypeError, ValueError):
        return f"{code!r} is no ErrorID"
    head = f"16#{code & 0xFFFF:04X}" if 0 <= code <= 0xFFFF else f"{code}"
    fb = FB_BY_NAME.get(fb_name) if isinstance(fb_name, str) else None
    entry = common(code)
    if fb is not None and code in fb.messages:
        entry = FBCode(code, fb.messages[code], entry.remedy if entry else "")
    if entry is None:
        return f"{head}: unknown ErrorID of S7-Technology V4.1"
    text = f"{head} {entry.message}"
    if fb is not None:
        if code not in fb.all_codes():
            return f"{text} (not an ErrorID of {fb.name})"
        if code in fb.causes:
            return f"{text}: {fb.causes[code]}"
    return f"{text}: {entry.remedy}" if entry.remedy else text
