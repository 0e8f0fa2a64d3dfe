"""The causes the motion core reports in I90 ("PLCopen ErrorStop cause") with I91 = 1.

Pilz V6.5 lists the denial causes of every command (§1.x.2) and says that I90 names the cause of a denial or a
cancellation, 0 meaning "Error free", but it prints no numbers for them.  The numbers below are this
project's (docs/pilz/decisions.md, "I90 values"); the table of which command can be denied for which cause
is ``DENIALS``, written out from the manual's lists.
"""
from __future__ import annotations

from enum import IntEnum


class Cause(IntEnum):
    ERROR_FREE = 0
    # --- denials (§1.2.2 ... §1.12.2) ---------------------------------------------------------------------
    SW_LIMIT = 1                # set position outside the software limit switches I50/I51 (limited axis)
    DIRECTION_BLOCKED = 2       # travel direction blocked by the permitted direction I04 (endless axis)
    REVOLUTION_LENGTH = 3       # set position outside the revolution length I01 (endless axis)
    HW_LIMIT = 4                # hardware limit switch active in the direction of travel (I101/I102)
    ZERO_DYNAMICS = 5           # set velocity, acceleration, deceleration or jerk equal to zero
    ZERO_MAXIMUM = 6            # maximum acceleration I11 or maximum jerk I16 equal to zero
    NOT_REFERENCED = 7          # the axis is not referenced (I86 = 0) where the command needs it
    NOT_STANDSTILL = 8          # MC_Home: the motion core is not in standstill (I89 != 2)
    REFERENCING_INACTIVE = 9    # MC_Home: referencing type inactive (I30 = 0 / A586 = 0)
    STOP_ACTIVE = 10            # a command while MC_Stop holds the axis (§1.6.5)
    NOT_READY = 11              # the drive is not enabled or has a fault pending
    BUFFER_FULL = 12            # I409 = 1 while a follow-up command waits already (one buffered block, I83)
    # --- cancellations of a running command ------------------------------------------------------------------
    LIMIT_SWITCH_FAULT = 20     # a hardware limit switch was reached: quick stop
    SW_LIMIT_REACHED = 21       # the motion reached a software limit switch
    ENABLE_OFF = 22             # the enable was removed while the command ran
    CYCLIC_POSITION_RANGE = 23  # event 78 cause 2: cyclic set position outside 0 ... I01 (§1.11.1)
    CYCLIC_TIMEOUT = 24         # event 78 cause 3: cyclic set values missing longer than I423 (§1.8.1)
    REFERENCE_NOT_FOUND = 25    # MC_Home: the reference feature was not found
    DRIVE_FAULT = 26            # any other fault of the drive


#: command number -> the causes the manual lists for its denial (in the manual's order)
DENIALS: dict[int, tuple[Cause, ...]] = {
    0: (),
    1: (Cause.SW_LIMIT, Cause.DIRECTION_BLOCKED, Cause.REVOLUTION_LENGTH, Cause.HW_LIMIT, Cause.ZERO_DYNAMICS,
        Cause.ZERO_MAXIMUM, Cause.NOT_REFERENCED),
    2: (Cause.SW_LIMIT, Cause.DIRECTION_BLOCKED, Cause.HW_LIMIT, Cause.ZERO_DYNAMICS, Cause.ZERO_MAXIMUM,
        Cause.NOT_REFERENCED),
    3: (Cause.SW_LIMIT, Cause.DIRECTION_BLOCKED, Cause.HW_LIMIT, Cause.ZERO_DYNAMICS, Cause.ZERO_MAXIMUM,
        Cause.NOT_REFERENCED),
    4: (Cause.DIRECTION_BLOCKED, Cause.HW_LIMIT, Cause.ZERO_DYNAMICS, Cause.ZERO_MAXIMUM),
    5: (Cause.ZERO_DYNAMICS, Cause.ZERO_MAXIMUM),
    6: (Cause.NOT_STANDSTILL, Cause.REFERENCING_INACTIVE, Cause.ZERO_MAXIMUM),
    7: (),
    8: (Cause.ZERO_DYNAMICS, Cause.ZERO_MAXIMUM),
    9: (),
    10: (),
    11: (Cause.ZERO_DYNAMICS, Cause.ZERO_MAXIMUM),
}

#: causes every command except MC_DoNothing and the never-denied ones can get from the drive's state
GENERAL = (Cause.STOP_ACTIVE, Cause.NOT_READY)

__all__ = ["Cause", "DENIALS", "GENERAL"]
