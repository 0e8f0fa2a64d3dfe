"""Which running command a new one ends on a Pilz drive axis (Pilz V6.5 §1, Command Mode I409).

The motion core has one command channel per axis: a command that starts takes the axis over from whatever
runs (Fig. 2: a new MC_MoveAbsolute during travel replaces the target), unless its Command Mode I409 says
"start at the end of the running command", which is the kernel's Buffered mode with one waiting job (the
"buffered subsequent motion block" of I83).  Commands started while MC_Stop holds the axis are denied by the
motion core itself (§1.6.5, cause STOP_ACTIVE), before a job exists.  So the table is one row of "A".
"""
from __future__ import annotations

from ...kernel.job_queue import BufferMode
from ...kernel.jobs import Job, JobKind
from ...kernel.policy import OverridePolicy, table
from . import command as C

COLUMNS = tuple(C.NAMES[n] for n in (1, 2, 3, 4, 5, 6, 8, 11))


def command(job: Job) -> str:
    """The command a job comes from: its ``extra["command"]`` number (Tab. 1)."""
    return C.NAMES[job.extra.get("command", C.MOVE_ABSOLUTE)]


TABLE = table(COLUMNS, {name: " ".join("A" for _ in COLUMNS) for name in COLUMNS})

#: I409 = 0 cancels the running command, 1 starts at its end
POLICY = OverridePolicy("Pilz", TABLE, classify=command,
                        position_control=frozenset({JobKind.ABSOLUTE, JobKind.RELATIVE, JobKind.HOME_ACTIVE}),
                        queue_depth=1, buffer_modes={0: BufferMode.ABORTING, 1: BufferMode.BUFFERED})

#: the kernel job kinds the motion core starts
JOB_KINDS = frozenset({JobKind.ABSOLUTE, JobKind.RELATIVE, JobKind.VELOCITY, JobKind.HALT, JobKind.HOME_ACTIVE,
                       JobKind.HOME_DIRECT})

__all__ = ["COLUMNS", "JOB_KINDS", "POLICY", "TABLE", "command"]
