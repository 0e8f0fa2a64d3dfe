"""Which running command a new one aborts on an S7-1200 axis: the "Override response" lists of S7-1200 Motion
Control V6 §11.1 as one table.

The manual gives the lists per instruction (§11.1.3.1 MC_Home by mode, §11.1.4.1 MC_Halt, §11.1.5.1
MC_MoveAbsolute, §11.1.6.1 MC_MoveRelative, §11.1.7.1 MC_MoveVelocity, §11.1.8.1 MC_MoveJog, §11.1.9.1
MC_CommandTable): "can be aborted by" and "aborts".  Here they are one table, rows = the new command,
columns = the running one: "A" it is aborted (CommandAborted), "-" it goes on, "R" the new command is
rejected because of the running one (ErrorID 16#8207 with the ErrorInfo of §12.8):

* MC_Home Mode 0/1/6/7 cannot be aborted and aborts nothing; position-related commands go on in the new
  coordinates.  Mode 0/1 needs no command table to be active (§11.1.3 "Requirements", 16#8207/16#0019).
* MC_Home Mode 2 is aborted only by MC_Home Mode 2/3 and runs beside the motion commands.
* Every other homing method is rejected while active homing runs (16#8207/16#0016).
* A command table is rejected while a passive homing waits (16#8207/16#0018); it aborts the running command
  only when its first Positioning, Velocity set point or Halt step starts (§11.1.9.1).
* MC_Power Enable = FALSE aborts everything; MC_Reset, MC_ChangeDynamic, MC_ReadParam and MC_WriteParam
  abort nothing and cannot be aborted (not in the table: they start no job).
"""
from __future__ import annotations

from ...kernel import faults as F
from ...kernel.jobs import Job, JobKind
from ...kernel.policy import OverridePolicy, Reject, table

HOME_DIRECT = "MC_Home Mode 0/1"
HOME_ADJUST = "MC_Home Mode 6/7"               # absolute encoder adjustment
HOME_PASSIVE = "MC_Home Mode 2"
HOME_ACTIVE = "MC_Home Mode 3"
HALT = "MC_Halt"
MOVE_ABSOLUTE = "MC_MoveAbsolute"
MOVE_RELATIVE = "MC_MoveRelative"
MOVE_VELOCITY = "MC_MoveVelocity"
MOVE_JOG = "MC_MoveJog"
COMMAND_TABLE = "MC_CommandTable"

_BY_KIND = {JobKind.HOME_PASSIVE: HOME_PASSIVE, JobKind.HOME_ACTIVE: HOME_ACTIVE, JobKind.HALT: HALT,
            JobKind.ABSOLUTE: MOVE_ABSOLUTE, JobKind.RELATIVE: MOVE_RELATIVE, JobKind.VELOCITY: MOVE_VELOCITY,
            JobKind.JOG: MOVE_JOG, JobKind.TABLE: COMMAND_TABLE}


def instruction(job: Job) -> str:
    """The instruction (and MC_Home mode) a job comes from: the rows and columns of the table."""
    if job.kind == JobKind.HOME_DIRECT:
        return HOME_ADJUST if job.mode in (6, 7) else HOME_DIRECT
    cls = _BY_KIND.get(job.kind)
    if cls is None:
        raise ValueError(f"no S7-1200 instruction starts a {job.kind} job")
    return cls


COLUMNS = (HOME_DIRECT, HOME_ADJUST, HOME_PASSIVE, HOME_ACTIVE, HALT, MOVE_ABSOLUTE, MOVE_RELATIVE, MOVE_VELOCITY,
           MOVE_JOG, COMMAND_TABLE)
TABLE = table(COLUMNS, {
    #               Home0/1 Home6/7 Home2  Home3  Halt  Abs  Rel  Vel  Jog  Table
    HOME_DIRECT:   "-       -       -      R16    -     -    -    -    -    R19",
    HOME_ADJUST:   "-       -       -      R16    -     -    -    -    -    -",
    HOME_PASSIVE:  "-       -       A      R16    -     -    -    -    -    R19",
    HOME_ACTIVE:   "-       -       A      A      A     A    A    A    A    A",
    HALT:          "-       -       -      A      A     A    A    A    A    A",
    MOVE_ABSOLUTE: "-       -       -      A      A     A    A    A    A    A",
    MOVE_RELATIVE: "-       -       -      A      A     A    A    A    A    A",
    MOVE_VELOCITY: "-       -       -      A      A     A    A    A    A    A",
    MOVE_JOG:      "-       -       -      A      A     A    A    A    A    A",
    COMMAND_TABLE: "-       -       R18    A      A     A    A    A    A    A",
}, R16=Reject(F.REJECTED, "homing_active"), R18=Reject(F.REJECTED, "table_homing"),
    R19=Reject(F.REJECTED, "homing_table"))

#: S7-1200 instructions have no BufferMode input: every command takes the axis over (Aborting)
POLICY = OverridePolicy("S7-1200", TABLE, classify=instruction,
                        position_control=frozenset({JobKind.ABSOLUTE, JobKind.RELATIVE, JobKind.HOME_ACTIVE}))

__all__ = ["COLUMNS", "COMMAND_TABLE", "HALT", "HOME_ACTIVE", "HOME_ADJUST", "HOME_DIRECT", "HOME_PASSIVE",
           "MOVE_ABSOLUTE", "MOVE_JOG", "MOVE_RELATIVE", "MOVE_VELOCITY", "POLICY", "TABLE", "instruction"]
