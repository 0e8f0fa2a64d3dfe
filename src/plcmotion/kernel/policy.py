"""Override policy: what a new job does to what already runs on an axis.

Every family's manual says, per instruction, which running jobs a new one aborts, which go on beside it and
when the new one is refused.  The kernel's one job path (``PositioningAxis.start_job``) asks the family's
:class:`OverridePolicy` and applies its answer with the kernel's own mechanisms: end the running motion,
the waiting command table, the passive homing or another running activity aborted, start the job in the
superimposed slot, or reject it with a fault.  Waiting jobs go with the job they wait for (kernel/job_queue.py);
buffered and blended jobs wait in the axis queue, whose depth and buffer-mode mapping the policy also gives.

A policy is data: a classifier (job -> the class name the manual's tables use) and a table of cells,
rows = class of the new job, columns = class of the running activity.  A missing cell means the running
activity goes on.  A cell is :data:`ABORT`, :data:`KEEP`, a :class:`Reject` with the fault the new job
ends with, a :class:`Ranked` cell that compares the two jobs (a stronger stop replaces a weaker one), or a
:class:`Judged` cell whose answer a function of the two jobs gives (e.g. by the direction of the new motion).

A second, optional table (``appending``) refuses a job that is to *wait* behind the running one (a buffered
or blended job) because of what runs: some manuals allow appending only in certain states.  Jobs that take
the axis over at once never look at it.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from enum import Enum
from typing import Callable, Iterable, Mapping, Union

from . import faults as F
from .faults import Fault
from .job_queue import BufferMode
from .jobs import Job, JobKind

# The kernel's grouping of its job kinds into override classes; a family may use it (the S7-1500 tables do)
# or classify by instruction (the S7-1200 lists).  Kernel code that starts an activity on its own (a
# coupling becoming active) names it with these.
HOME_PASSIVE = "home_passive"            # passive homing: waits for a homing event beside the motion
HOME_ACTIVE = "home_active"              # active homing: a motion of its own
HOME_CANCEL = "home_cancel"              # cancel a passive homing
MOTION = "motion"                        # positioning, velocity and jog jobs
HALT = "halt"                            # braking to standstill (where a table differs from MOTION)
STOP = "stop"                            # stop that locks the axis until released
SUPERIMPOSED = "superimposed"            # motion added on top of the basic motion
GEAR_IN = "gear_in"                      # gearing synchronized over time
SYNC_WAITING = "sync_waiting"            # positioned gearing / camming waiting for its leading value
SYNC_ACTIVE = "sync_active"              # positioned gearing / camming synchronizing or synchronous
PHASING = "phasing"                      # phase shift of a gearing
LV_ADDITIVE = "lv_additive"              # additive leading value
TABLE = "table"                          # command table

#: the slot a job of a class starts in (``OverridePolicy.slots``); every other class runs as the axis job
SUPERIMPOSED_SLOT = "superimposed"

_MOTION_KINDS = frozenset({JobKind.ABSOLUTE, JobKind.RELATIVE, JobKind.VELOCITY, JobKind.JOG})
_SYNC_POSITIONED = frozenset({JobKind.GEAR_IN_POS, JobKind.CAM_IN})
_BY_KIND = {JobKind.HALT: HALT, JobKind.HOME_ACTIVE: HOME_ACTIVE, JobKind.HOME_PASSIVE: HOME_PASSIVE,
            JobKind.HOME_CANCEL: HOME_CANCEL, JobKind.STOP: STOP, JobKind.SUPERIMPOSED: SUPERIMPOSED,
            JobKind.GEAR_IN: GEAR_IN, JobKind.PHASING: PHASING, JobKind.LV_ADDITIVE: LV_ADDITIVE,
            JobKind.TABLE: TABLE}


def job_class(job: Job) -> str:
    """The kernel's override class of a job in its current state (a waiting positioned coupling is not yet
    active: it is looked up again when it starts to synchronize)."""
    kind = job.kind
    if kind in _MOTION_KINDS:
        return MOTION
    if kind in _SYNC_POSITIONED:
        return SYNC_ACTIVE if (job.start_sync or job.in_sync) else SYNC_WAITING
    cls = _BY_KIND.get(kind)
    if cls is None:
        raise ValueError(f"no override class for {kind}")
    return cls


class Response(Enum):
    ABORT = "A"      # the running activity ends aborted (CommandAborted)
    KEEP = "-"       # it goes on beside the new job


ABORT, KEEP = Response.ABORT, Response.KEEP


@dataclass(frozen=True)
class Reject:
    """The new job is refused with the fault ``kind``/``detail``; the running activity goes on."""

    kind: str
    detail: str = ""

    def fault(self) -> Fault:
        return F.reject(self.kind, self.detail)


@dataclass(frozen=True)
class Ranked:
    """A cell that compares the jobs: ``rank(job)`` of the new one at least that of the running one aborts
    it, else the new job is rejected with ``weaker`` (S7-1500 "B": a stop replaces a weaker stop)."""

    rank: Callable[[Job], int]
    weaker: Reject

    def decide(self, new: Job, running: Job | None) -> Response | Reject:
        if running is not None and self.rank(new) < self.rank(running):
            return self.weaker
        return ABORT


@dataclass(frozen=True)
class Judged:
    """A cell answered by ``judge(new, running)`` (either may be None: a query without a job, an activity
    without a job of its own): ABORT, KEEP or a Reject.  For rules a fixed mark cannot give, e.g. "the
    running job is aborted when the new one moves away from it, else the new one is refused"."""

    judge: Callable[[Job | None, Job | None], Union[Response, Reject]]

    def decide(self, new: Job | None, running: Job | None) -> Response | Reject:
        return self.judge(new, running)


Cell = Union[Response, Reject, Ranked, Judged]


@dataclass(frozen=True)
class Activity:
    """Something running on an axis that a new job may end: its class, its job (None: none of its own) and
    how to end it aborted at time t."""

    cls: str
    job: Job | None
    end: Callable[[float], None]


def table(columns: Iterable[str], rows: Mapping[str, str], **special: Cell) -> dict[str, dict[str, Cell]]:
    """A table written as in a manual: ``rows`` map a new job's class to a line of "A" / "-" / "R" marks,
    one per column; a mark may name an entry of ``special`` instead (a Reject or Ranked cell)."""
    cols = tuple(columns)
    out: dict[str, dict[str, Cell]] = {}
    for new, line in rows.items():
        marks = line.split()
        if len(marks) != len(cols):
            raise ValueError(f"row {new!r}: {len(marks)} marks for {len(cols)} columns")
        out[new] = {c: ABORT if m == "A" else KEEP if m == "-" else special[m] for c, m in zip(cols, marks)}
    return out


def merge(*tables: Mapping[str, Mapping[str, Cell]]) -> dict[str, dict[str, Cell]]:
    """Tables over different running classes as one (a row of one table missing in another keeps KEEP)."""
    out: dict[str, dict[str, Cell]] = {}
    for t in tables:
        for new, row in t.items():
            out.setdefault(new, {}).update(row)
    return out


@dataclass(frozen=True)
class OverridePolicy:
    """A family's override rules as data (see the module docstring).

    ``position_control``: job kinds that switch position control on when they start (velocity and jog jobs
    bring their own choice).  ``plan_after_override``: the new job resolves its target and plans from the
    state after the override (a superimposed part it ends is taken over first) instead of before it (a job
    rejected for its target then leaves the running one alone).  ``queue_depth``: how many jobs may wait
    behind the running one; ``buffer_modes``: the family's input value -> PLCopen buffer mode.
    ``appending``: rows = class of a job that is to wait in the queue, columns = class of a running activity,
    cells = the Reject that refuses it (missing: it may wait)."""

    name: str
    cells: Mapping[str, Mapping[str, Cell]]
    classify: Callable[[Job], str] = job_class
    slots: Mapping[str, str] = field(default_factory=dict)
    position_control: frozenset[JobKind] = frozenset({JobKind.ABSOLUTE, JobKind.RELATIVE, JobKind.HOME_ACTIVE})
    plan_after_override: bool = False
    queue_depth: int = 1
    buffer_modes: Mapping[int, BufferMode] = field(default_factory=lambda: {0: BufferMode.ABORTING})
    appending: Mapping[str, Mapping[str, Reject]] = field(default_factory=dict)

    def cell(self, new: str, running: str) -> Cell:
        return self.cells.get(new, {}).get(running, KEEP)

    def decide(self, new: str, new_job: Job | None, activity: Activity) -> Response | Reject:
        """What a new job of class ``new`` does to ``activity``."""
        c = self.cell(new, activity.cls)
        if isinstance(c, Ranked):
            return c.decide(new_job, activity.job) if new_job is not None else ABORT
        if isinstance(c, Judged):
            return c.decide(new_job, activity.job)
        return c

    def aborts(self, new: str, running: str) -> bool:
        """The table view of one cell: does a new job of class ``new`` abort a running one of ``running``?
        (A Ranked cell aborts the running job of the same or a lower rank; a Judged cell may abort it.)"""
        c = self.cell(new, running)
        return c is ABORT or isinstance(c, (Ranked, Judged))

    def append_refusal(self, job: Job, activities: Iterable[Activity]) -> Reject | None:
        """Whether ``job``, to wait behind the running one, is refused because of a running activity
        (``appending``); None: it may wait."""
        if not self.appending:
            return None
        row = self.appending.get(self.classify(job))
        if not row:
            return None
        for activity in activities:
            refusal = row.get(activity.cls)
            if refusal is not None:
                return refusal
        return None

    def slot(self, new: str) -> str | None:
        return self.slots.get(new)

    def buffer_mode(self, value: int) -> BufferMode:
        """The PLCopen buffer mode for the family's input ``value``; an unknown value is refused."""
        try:
            return self.buffer_modes[value]
        except KeyError:
            raise ValueError(f"{self.name}: no buffer mode {value!r} (known: {sorted(self.buffer_modes)})") from None


#: PLCopen Part 1 without a family's lists (a family that registers no policy): a job that moves the axis
#: takes it over from the running one (Aborting); active homing also ends a passive one
_MOVERS = (MOTION, HALT, HOME_ACTIVE, TABLE)
PLCOPEN = OverridePolicy("PLCopen", cells={new: {**{r: ABORT for r in _MOVERS},
                                                 **({HOME_PASSIVE: ABORT} if new == HOME_ACTIVE else {})}
                                           for new in _MOVERS},
                         buffer_modes={int(m): m for m in BufferMode})

__all__ = ["ABORT", "KEEP", "Activity", "Cell", "Judged", "OverridePolicy", "PLCOPEN", "Ranked", "Reject", "Response",
           "job_class", "merge", "table"]
