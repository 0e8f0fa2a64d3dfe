"""The words of the CiA 402 device profile: controlword commands, statusword states, modes of operation,
and the power state machine of the drive (CiA 402-2, "drive device state machine"; CiA 402-2 object
0x6040/0x6041/0x6060/0x6061).  Pure data and one small class: no bus, no canopen import, so the master,
the simulated drive and the tests all use the same values.
"""
from __future__ import annotations

from enum import Enum, IntEnum

# --- controlword 0x6040 bits ------------------------------------------------------------------------------
CW_SWITCH_ON = 0x0001
CW_ENABLE_VOLTAGE = 0x0002
CW_QUICK_STOP = 0x0004           # 0 = quick stop active
CW_ENABLE_OPERATION = 0x0008
CW_NEW_SETPOINT = 0x0010         # profile position: new set-point (rising edge); homing: start
CW_CHANGE_IMMEDIATELY = 0x0020   # profile position: change set immediately
CW_RELATIVE = 0x0040             # profile position: target is relative
CW_FAULT_RESET = 0x0080          # rising edge resets a fault
CW_HALT = 0x0100

#: the device control commands (controlword value with the bits that matter; mask, value to test)
SHUTDOWN = 0x0006
SWITCH_ON = 0x0007
DISABLE_VOLTAGE = 0x0000
QUICK_STOP = 0x0002
DISABLE_OPERATION = 0x0007
ENABLE_OPERATION = 0x000F
FAULT_RESET = 0x0080

# --- statusword 0x6041 bits -------------------------------------------------------------------------------
SW_READY_TO_SWITCH_ON = 0x0001
SW_SWITCHED_ON = 0x0002
SW_OPERATION_ENABLED = 0x0004
SW_FAULT = 0x0008
SW_VOLTAGE_ENABLED = 0x0010
SW_QUICK_STOP = 0x0020           # 0 = quick stop active
SW_SWITCH_ON_DISABLED = 0x0040
SW_WARNING = 0x0080
SW_REMOTE = 0x0200
SW_TARGET_REACHED = 0x0400
SW_INTERNAL_LIMIT = 0x0800
SW_OMS12 = 0x1000                # pp: set-point acknowledge; pv: speed = 0; hm: homing attained;
                                 # csp/csv/cst: target value ignored = 0 (drive follows the target)
SW_OMS13 = 0x2000                # pp: following error; hm: homing error


class State(str, Enum):
    """States of the drive's power state machine (names as BaseNode402 of the canopen package spells them)."""

    NOT_READY_TO_SWITCH_ON = "NOT READY TO SWITCH ON"
    SWITCH_ON_DISABLED = "SWITCH ON DISABLED"
    READY_TO_SWITCH_ON = "READY TO SWITCH ON"
    SWITCHED_ON = "SWITCHED ON"
    OPERATION_ENABLED = "OPERATION ENABLED"
    QUICK_STOP_ACTIVE = "QUICK STOP ACTIVE"
    FAULT_REACTION_ACTIVE = "FAULT REACTION ACTIVE"
    FAULT = "FAULT"


#: statusword mask and value of each state (bits 0, 1, 2, 3, 5, 6)
STATE_BITS: dict[State, tuple[int, int]] = {
    State.NOT_READY_TO_SWITCH_ON: (0x4F, 0x00),
    State.SWITCH_ON_DISABLED: (0x4F, 0x40),
    State.READY_TO_SWITCH_ON: (0x6F, 0x21),
    State.SWITCHED_ON: (0x6F, 0x23),
    State.OPERATION_ENABLED: (0x6F, 0x27),
    State.QUICK_STOP_ACTIVE: (0x6F, 0x07),
    State.FAULT_REACTION_ACTIVE: (0x4F, 0x0F),
    State.FAULT: (0x4F, 0x08),
}


def state_of(statusword: int) -> State | None:
    """The state a statusword shows (None for a bit pattern the profile does not define)."""
    for state, (mask, value) in STATE_BITS.items():
        if statusword & mask == value:
            return state
    return None


def state_bits(state: State) -> int:
    """The statusword bits 0..6 of ``state`` (voltage enabled, bit 4, is added by the drive)."""
    return STATE_BITS[state][1]


class Mode(IntEnum):
    """Modes of operation 0x6060 / display 0x6061."""

    PROFILE_POSITION = 1
    PROFILE_VELOCITY = 3
    HOMING = 6
    CYCLIC_SYNC_POSITION = 8
    CYCLIC_SYNC_VELOCITY = 9
    CYCLIC_SYNC_TORQUE = 10


#: the names a project file uses for the modes
MODE_NAMES: dict[str, Mode] = {"pp": Mode.PROFILE_POSITION, "pv": Mode.PROFILE_VELOCITY, "hm": Mode.HOMING,
                               "csp": Mode.CYCLIC_SYNC_POSITION, "csv": Mode.CYCLIC_SYNC_VELOCITY,
                               "cst": Mode.CYCLIC_SYNC_TORQUE}
#: the modes an axis can be operated in (homing mode is entered only for a drive-based homing run)
AXIS_MODES = ("csp", "csv", "cst", "pp", "pv")
#: 0x6502 supported drive modes: bit of each mode
SUPPORTED_BITS = {Mode.PROFILE_POSITION: 0, Mode.PROFILE_VELOCITY: 2, Mode.HOMING: 5,
                  Mode.CYCLIC_SYNC_POSITION: 7, Mode.CYCLIC_SYNC_VELOCITY: 8, Mode.CYCLIC_SYNC_TORQUE: 9}


class Command(str, Enum):
    """Device control commands decoded from a controlword."""

    SHUTDOWN = "shutdown"
    SWITCH_ON = "switch on"
    ENABLE_OPERATION = "enable operation"
    DISABLE_VOLTAGE = "disable voltage"
    QUICK_STOP = "quick stop"
    DISABLE_OPERATION = "disable operation"


def command_of(controlword: int) -> Command:
    """The device control command of a controlword (bits 0-3; fault reset is an edge of bit 7, see
    :class:`PowerStateMachine`).  Bit patterns per CiA 402-2: disable voltage wins over quick stop, which
    wins over the rest."""
    if not controlword & CW_ENABLE_VOLTAGE:
        return Command.DISABLE_VOLTAGE
    if not controlword & CW_QUICK_STOP:
        return Command.QUICK_STOP
    if not controlword & CW_SWITCH_ON:
        return Command.SHUTDOWN
    if controlword & CW_ENABLE_OPERATION:
        return Command.ENABLE_OPERATION
    return Command.SWITCH_ON          # also "disable operation" from OPERATION ENABLED


class PowerStateMachine:
    """The drive's state machine with the numbered transitions of the profile.

    ``command(cw)`` applies a controlword and returns the transition number taken (None: none).  A fault
    (``fault()``) goes through FAULT REACTION ACTIVE (13) to FAULT (14, ``reaction_done``); a rising edge
    of controlword bit 7 leaves FAULT (15) once the cause is gone.  Quick stop (11) ends in SWITCH ON
    DISABLED (12) when the quick stop ramp is done (``quick_stop_done``; option code 2 of 0x605A).
    """

    def __init__(self) -> None:
        self.state = State.SWITCH_ON_DISABLED        # after transition 1 (self-test done)
        self._last_cw = 0

    def command(self, cw: int, cause_present: bool = False) -> int | None:
        reset_edge = bool(cw & CW_FAULT_RESET) and not self._last_cw & CW_FAULT_RESET
        self._last_cw = cw
        s, cmd = self.state, command_of(cw)
        if s is State.FAULT:
            if reset_edge and not cause_present:
                self.state = State.SWITCH_ON_DISABLED
                return 15
            return None
        if s is State.FAULT_REACTION_ACTIVE or s is State.NOT_READY_TO_SWITCH_ON:
            return None
        if cw & CW_FAULT_RESET:
            return None                # bit 7 set outside FAULT: no command is executed with it
        table = _TRANSITIONS.get(s, {})
        if cmd in table:
            self.state, number = table[cmd]
            return number
        return None

    def fault(self) -> None:
        if self.state not in (State.FAULT, State.FAULT_REACTION_ACTIVE):
            self.state = State.FAULT_REACTION_ACTIVE        # transition 13

    def reaction_done(self) -> None:
        if self.state is State.FAULT_REACTION_ACTIVE:
            self.state = State.FAULT                        # transition 14

    def quick_stop_done(self) -> None:
        if self.state is State.QUICK_STOP_ACTIVE:
            self.state = State.SWITCH_ON_DISABLED           # transition 12

    @property
    def power_on(self) -> bool:
        """The power stage follows the setpoint (torque on the motor)."""
        return self.state in (State.OPERATION_ENABLED, State.QUICK_STOP_ACTIVE, State.FAULT_REACTION_ACTIVE)


C = Command
_TRANSITIONS: dict[State, dict[Command, tuple[State, int]]] = {
    State.SWITCH_ON_DISABLED: {C.SHUTDOWN: (State.READY_TO_SWITCH_ON, 2)},
    State.READY_TO_SWITCH_ON: {C.SWITCH_ON: (State.SWITCHED_ON, 3), C.ENABLE_OPERATION: (State.SWITCHED_ON, 3),
                               C.DISABLE_VOLTAGE: (State.SWITCH_ON_DISABLED, 7),
                               C.QUICK_STOP: (State.SWITCH_ON_DISABLED, 7)},
    State.SWITCHED_ON: {C.ENABLE_OPERATION: (State.OPERATION_ENABLED, 4), C.SHUTDOWN: (State.READY_TO_SWITCH_ON, 6),
                        C.DISABLE_VOLTAGE: (State.SWITCH_ON_DISABLED, 10),
                        C.QUICK_STOP: (State.SWITCH_ON_DISABLED, 10)},
    State.OPERATION_ENABLED: {C.SWITCH_ON: (State.SWITCHED_ON, 5), C.SHUTDOWN: (State.READY_TO_SWITCH_ON, 8),
                              C.DISABLE_VOLTAGE: (State.SWITCH_ON_DISABLED, 9),
                              C.QUICK_STOP: (State.QUICK_STOP_ACTIVE, 11)},
    State.QUICK_STOP_ACTIVE: {C.DISABLE_VOLTAGE: (State.SWITCH_ON_DISABLED, 12),
                              C.ENABLE_OPERATION: (State.OPERATION_ENABLED, 16)},
}
del C


def next_command(state: State | None, enable: bool, quick_stop: bool = False) -> int:
    """The controlword a master sends in ``state`` to walk towards OPERATION ENABLED (``enable``) or
    towards SWITCH ON DISABLED / READY TO SWITCH ON (not ``enable``); ``quick_stop`` requests a quick
    stop (from OPERATION ENABLED; elsewhere it keeps the drive switched off)."""
    if state is None or state in (State.FAULT, State.FAULT_REACTION_ACTIVE, State.NOT_READY_TO_SWITCH_ON):
        return DISABLE_VOLTAGE
    if quick_stop:
        # quick stop from operation; once it ended in SWITCH ON DISABLED the drive stays there until the
        # master asks for operation anew
        return QUICK_STOP if state in (State.OPERATION_ENABLED, State.QUICK_STOP_ACTIVE) else DISABLE_VOLTAGE
    if not enable:
        return SHUTDOWN if state is not State.QUICK_STOP_ACTIVE else DISABLE_VOLTAGE
    if state is State.SWITCH_ON_DISABLED:
        return SHUTDOWN
    if state is State.READY_TO_SWITCH_ON:
        return SWITCH_ON
    return ENABLE_OPERATION


#: EMCY error codes (CiA 301 / CiA 402-2) the simulated drive uses; the master reports any code
EMCY_NO_ERROR = 0x0000
EMCY_OVERCURRENT = 0x2310        # continuous over current
EMCY_FOLLOWING_ERROR = 0x8611    # positioning controller: following error
EMCY_HEARTBEAT = 0x8130          # life guard / heartbeat error
EMCY_GENERIC = 0x1000
