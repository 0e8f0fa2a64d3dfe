"""Command interaction of S7-Technology V4.1 (§6.8): which active command a new one aborts, lets go on, or
is refused by, as data.

The five matrices of §6.8.1-§6.8.5 are figures the text of the manual does not carry; what is here is
assembled from their legends, the two examples of §6.8.6 and every FB's "Interaction of commands",
"Purpose", "Prerequisites" and ErrorID texts (§6.2, §6.3, §6.7).  Each cell the texts leave open is decided
in docs/s7t/decisions.md (the "?" cells of the catalog).

Shape (what instructions and the axis must do for the policy to apply):

* A row/column is a *command class*: the FB name (``MC_MoveAbsolute``), for MC_Home the mode group
  (``MC_Home Mode 0/1`` active, ``Mode 2`` passive, ``Mode 3-7`` set/correct, ``Mode 8`` cancel), for the
  synchronous FBs the FB name and its state of §6.8 ("w" waiting for its (de)synchronization condition,
  "d" driving: synchronizing, synchronous or desynchronizing), for a clamped MC_MoveToEndPos
  ``MC_MoveToEndPos InClamping``.  Table-3 commands that start no job are rows for a query
  (``POLICY.cell(row, column)``); MC_Power is two rows (``Enable=TRUE`` / ``Enable=FALSE``).
* :func:`instruction` names a job's class: ``job.extra["fb"]`` (the FB name) when the instruction sets it,
  else by kernel job kind (ABSOLUTE -> MC_MoveAbsolute, ...; MC_MoveAdditive and MC_MoveToEndPos must set
  it).  A synchronous job is "d" once ``start_sync``/``in_sync`` or ``extra["driving"]`` is set (a
  ``JobKind.GEAR_IN`` job synchronizes at once: always "d"); MC_MoveToEndPos is ``InClamping`` while
  ``extra["clamped"]``.  When a waiting synchronous job starts to drive, its "d" row is applied again
  (``axis._override(instruction(job), t, job)``; the kernel follower passes its own class names, which are
  aliases of the MC_GearIn / MC_Phasing rows and columns here): that is how "Waiting abort", "Abort 2" and
  "Superimposed abort" act at the condition, not at the start.
* The axis yields each running command as a ``kernel.policy.Activity`` of its class: the axis job, a
  waiting passive homing, the superimposed motion, the couplings, and MC_Stop from its start until its
  Done (standstill and Execute = FALSE: the lock of §6.2.3).
* Direction rules ("Abort direction") read ``extra["heading"]`` (+1/-1) of the MC_MoveToEndPos job (its
  effective direction) and ``job.target`` (where it clamped); a new job's direction is its
  ``extra["heading"]`` if set, else the sign of its distance / velocity / (position - clamp position).
* ``Mode`` 0/1/2 -> ``POLICY.buffer_mode(Mode)`` (Aborting / Buffered / BlendingLow); one job may wait
  (``queue_depth`` 1, a second one: 8005).  ``APPENDING`` refuses a waiting job (8055, 8045, 8056).

Reject cells carry kernel fault kinds; :data:`ERROR_IDS` gives each its ErrorID (:func:`error_id`).
"""
from __future__ import annotations

from typing import Iterable

from ...kernel import faults as F
from ...kernel.faults import Fault
from ...kernel.job_queue import BufferMode
from ...kernel.jobs import Job, JobKind
from ...kernel import policy as K
from ...kernel.policy import (ABORT, GEAR_IN, KEEP, PHASING, SUPERIMPOSED_SLOT, SYNC_ACTIVE, SYNC_WAITING, Activity,
                              Cell, Judged, OverridePolicy, Reject, Response, merge, table)

# --- command classes (rows and columns) -------------------------------------------------------------------
POWER_ON = "MC_Power Enable=TRUE"
POWER_OFF = "MC_Power Enable=FALSE"
RESET = "MC_Reset"
RESTART = "MC_Reset Restart"
CHANGE_DATASET = "MC_ChangeDataset"
SET_TORQUE_LIMIT = "MC_SetTorqueLimit"
SET_CHARACTERISTIC = "MC_SetCharacteristic"
HOME_ACTIVE = "MC_Home Mode 0/1"
HOME_PASSIVE = "MC_Home Mode 2"
HOME_SET = "MC_Home Mode 3-7"
HOME_CANCEL = "MC_Home Mode 8"
STOP = "MC_Stop"
HALT = "MC_Halt"
MOVE_ABSOLUTE = "MC_MoveAbsolute"
MOVE_RELATIVE = "MC_MoveRelative"
MOVE_ADDITIVE = "MC_MoveAdditive"
MOVE_VELOCITY = "MC_MoveVelocity"
MOVE_SUPERIMPOSED = "MC_MoveSuperImposed"
MOVE_TO_END_POS = "MC_MoveToEndPos"
CLAMPED = "MC_MoveToEndPos InClamping"

#: synchronous FBs of tables (1) (§6.3); each is a class per state, "<FB> w" and "<FB> d"
SYNC_FBS = ("MC_GearIn", "MC_CamIn", "MC_GearOut", "MC_CamOut",
            "MC_GearInSuperImposed", "MC_CamInSuperImposed", "MC_GearOutSuperImposed", "MC_CamOutSuperImposed")
PHASING_FB = "MC_Phasing"
PHASING_SI = "MC_PhasingSuperImposed"


def w(fb: str) -> str:
    return f"{fb} w"


def d(fb: str) -> str:
    return f"{fb} d"


GI, CI, GO, CO, GIS, CIS, GOS, COS = SYNC_FBS

# --- refusals and their ErrorIDs ----------------------------------------------------------------------------
STOP_ACTIVE = Reject(F.STOP_ACTIVE)                        # 8045 MC_Stop active / its Execute still TRUE
RESTARTING = Reject(F.REJECTED, "restarting")              # 8045 the TO restarts (MC_Reset Restart = TRUE)
END_POS_ACTIVE = Reject(F.REJECTED, "end_pos_active")      # 8045 active homing while MC_MoveToEndPos is active
END_POS_REVERSE = Reject(F.REJECTED, "end_pos_reverse")    # 8045 reversing MC_MoveToEndPos while clamped
END_POS_IGNORED = Reject(F.REJECTED, "end_pos_ignored")    # 0029 (warning) reversing MC_MoveToEndPos before
CLAMPED_AT_STOP = Reject(F.REJECTED, "clamped")            # 8056 clamped: only commands away from the stop
LATCHING = Reject(F.NOT_APPENDABLE, "latching")            # 8055 appending/overlay not allowed now

ERROR_IDS: dict[Reject, int] = {
    STOP_ACTIVE: 0x8045, RESTARTING: 0x8045, END_POS_ACTIVE: 0x8045, END_POS_REVERSE: 0x8045,
    END_POS_IGNORED: 0x0029, CLAMPED_AT_STOP: 0x8056, LATCHING: 0x8055,
}
#: ErrorIDs that are warnings: the command is not executed, Error stays FALSE (§5.10)
WARNINGS = frozenset({0x0029})
# the kernel queue's own refusals: a second waiting job (8005 command memory full), waiting behind a job
# that has no end to wait for (8055)
_QUEUE_IDS = {F.QUEUE_FULL: 0x8005, F.NOT_APPENDABLE: 0x8055}


def error_id(fault: Fault) -> int | None:
    """The ErrorID of a refusal this policy (or the job queue behind it) gives; None for other faults."""
    for reject, code in ERROR_IDS.items():
        if (fault.kind, fault.detail) == (reject.kind, reject.detail):
            return code
    return _QUEUE_IDS.get(fault.kind)


# --- "Abort direction" (MC_MoveToEndPos, §6.2.11 "Interaction of commands") ---------------------------------
def _sign(x: float) -> int:
    return (x > 0) - (x < 0)


def heading(job: Job | None, at: float) -> int:
    """The direction a new job moves the axis from position ``at`` (0: none known, e.g. MC_Halt)."""
    if job is None:
        return 0
    given = job.extra.get("heading")
    if given is not None:
        return _sign(given)
    if job.kind in (JobKind.RELATIVE, JobKind.SUPERIMPOSED):
        return _sign(job.position)
    if job.kind in (JobKind.VELOCITY, JobKind.JOG):
        return _sign(job.velocity)
    if job.kind == JobKind.ABSOLUTE:
        return _sign(job.position - at)
    return 0


def _side(end_pos: Job | None) -> int:
    return _sign(end_pos.extra.get("heading", 0)) if end_pos is not None else 0


def _away(new: Job | None, end_pos: Job | None) -> bool:
    side = _side(end_pos)
    return side != 0 and heading(new, end_pos.target if end_pos is not None else 0.0) == -side


def _release(new: Job | None, end_pos: Job | None) -> Response | Reject:
    """A basic motion on a clamped axis: away from the stop it aborts MC_MoveToEndPos, else 8056."""
    return ABORT if _away(new, end_pos) else CLAMPED_AT_STOP


def _release_superimposed(new: Job | None, end_pos: Job | None) -> Response | Reject:
    """MC_MoveSuperImposed on a clamped axis: away it runs beside it ("Superimposed"), else 8056."""
    return KEEP if _away(new, end_pos) else CLAMPED_AT_STOP


def _same_direction(new: Job | None, end_pos: Job | None, reverse: Reject) -> Response | Reject:
    side = _side(end_pos)
    return ABORT if side != 0 and _side(new) == side else reverse


J = Judged(_release)
JS = Judged(_release_superimposed)
ED = Judged(lambda new, run: _same_direction(new, run, END_POS_IGNORED))   # before the end stop
EC = Judged(lambda new, run: _same_direction(new, run, END_POS_REVERSE))   # clamped
_SPECIAL: dict[str, Cell] = {"S": STOP_ACTIVE, "R": RESTARTING, "E": END_POS_ACTIVE, "C": CLAMPED_AT_STOP,
                             "J": J, "j": JS, "D": ED, "K": EC}

# --- the tables -------------------------------------------------------------------------------------------
# Marks: A abort (Abort 1), - goes on (Superimposed / No influence / Waiting / blank), S 8045 MC_Stop,
# R 8045 restarting, E 8045 active homing vs MC_MoveToEndPos, C 8056 clamped, J / j / D / K "Abort direction"
# (basic motion / MC_MoveSuperImposed / MC_MoveToEndPos before the stop / MC_MoveToEndPos clamped).
ROWS_3 = (POWER_ON, POWER_OFF, RESET, RESTART, CHANGE_DATASET, SET_TORQUE_LIMIT, SET_CHARACTERISTIC)
ROWS_2 = (HOME_ACTIVE, HOME_PASSIVE, HOME_SET, HOME_CANCEL, STOP, HALT, MOVE_ABSOLUTE, MOVE_RELATIVE, MOVE_ADDITIVE,
          MOVE_VELOCITY, MOVE_SUPERIMPOSED, MOVE_TO_END_POS)
ROWS_1 = (w(GI), d(GI), w(CI), d(CI), w(GO), d(GO), w(CO), d(CO), PHASING_FB,
          w(GIS), d(GIS), w(CIS), d(CIS), w(GOS), d(GOS), w(COS), d(COS), PHASING_SI)
ROWS = ROWS_3 + ROWS_2 + ROWS_1

COLUMNS_2 = (HOME_ACTIVE, HOME_PASSIVE, STOP, HALT, MOVE_ABSOLUTE, MOVE_RELATIVE, MOVE_ADDITIVE, MOVE_VELOCITY,
             MOVE_SUPERIMPOSED, MOVE_TO_END_POS, CLAMPED)
COLUMNS_1 = ROWS_1
COLUMNS_3 = (CHANGE_DATASET, SET_TORQUE_LIMIT, SET_CHARACTERISTIC, RESTART)
COLUMNS = COLUMNS_2 + COLUMNS_1 + COLUMNS_3

# active single-axis commands (tables (2) of §6.8.2 / §6.8.5 as columns)
_SINGLE_AXIS = table(COLUMNS_2, {
    #                    Home01 Home2 Stop Halt Abs Rel Add Vel Sup End Clamped
    POWER_ON:           "-      -     -    -    -   -   -   -   -   -   -",
    POWER_OFF:          "A      A     -    A    A   A   A   A   A   A   A",
    RESET:              "-      -     -    -    -   -   -   -   -   -   -",
    RESTART:            "-      -     -    -    -   -   -   -   -   -   -",
    CHANGE_DATASET:     "-      -     -    -    -   -   -   -   -   -   -",
    SET_TORQUE_LIMIT:   "-      -     S    -    -   -   -   -   -   -   C",
    SET_CHARACTERISTIC: "-      -     -    -    -   -   -   -   -   -   -",
    HOME_ACTIVE:        "A      A     S    A    A   A   A   A   A   E   E",
    HOME_PASSIVE:       "A      A     -    -    -   -   -   -   -   -   -",
    HOME_SET:           "A      A     -    -    -   -   -   -   -   -   -",
    HOME_CANCEL:        "-      A     -    -    -   -   -   -   -   -   -",
    STOP:               "A      -     A    A    A   A   A   A   A   A   A",
    HALT:               "A      -     S    A    A   A   A   A   A   A   J",
    MOVE_ABSOLUTE:      "A      -     S    A    A   A   A   A   A   A   J",
    MOVE_RELATIVE:      "A      -     S    A    A   A   A   A   A   A   J",
    MOVE_ADDITIVE:      "A      -     S    A    A   A   A   A   A   A   J",
    MOVE_VELOCITY:      "A      -     S    A    A   A   A   A   A   A   J",
    MOVE_SUPERIMPOSED:  "-      -     S    -    -   -   -   -   A   -   j",
    MOVE_TO_END_POS:    "A      -     S    A    A   A   A   A   A   D   K",
    w(GI):              "-      -     S    -    -   -   -   -   -   -   C",
    d(GI):              "A      -     S    A    A   A   A   A   -   A   C",
    w(CI):              "-      -     S    -    -   -   -   -   -   -   C",
    d(CI):              "A      -     S    A    A   A   A   A   -   A   C",
    w(GO):              "-      -     S    -    -   -   -   -   -   -   -",
    d(GO):              "-      -     S    -    -   -   -   -   -   -   -",
    w(CO):              "-      -     S    -    -   -   -   -   -   -   -",
    d(CO):              "-      -     S    -    -   -   -   -   -   -   -",
    PHASING_FB:         "-      -     S    -    -   -   -   -   -   -   C",
    w(GIS):             "-      -     S    -    -   -   -   -   -   -   C",
    d(GIS):             "-      -     S    -    -   -   -   -   -   -   C",
    w(CIS):             "-      -     S    -    -   -   -   -   -   -   C",
    d(CIS):             "-      -     S    -    -   -   -   -   -   -   C",
    w(GOS):             "-      -     S    -    -   -   -   -   -   -   -",
    d(GOS):             "-      -     S    -    -   -   -   -   -   -   -",
    w(COS):             "-      -     S    -    -   -   -   -   -   -   -",
    d(COS):             "-      -     S    -    -   -   -   -   -   -   -",
    PHASING_SI:         "-      -     S    -    -   -   -   -   -   -   C",
}, **_SPECIAL)

# active synchronous commands (tables (1) of §6.8.1 / §6.8.4 as columns); basic | superimposed sync object
_ALL_A = " ".join(["A"] * 18)
_NONE = " ".join(["-"] * 18)
_BASIC_A = " ".join(["A"] * 9 + ["-"] * 9)
_SYNC = table(COLUMNS_1, {
    **{row: _NONE for row in (POWER_ON, RESET, RESTART, CHANGE_DATASET, SET_TORQUE_LIMIT, SET_CHARACTERISTIC,
                              HOME_PASSIVE, HOME_SET, HOME_CANCEL, MOVE_SUPERIMPOSED)},
    **{row: _ALL_A for row in (POWER_OFF, STOP, HOME_ACTIVE, HALT, MOVE_ABSOLUTE, MOVE_RELATIVE, MOVE_ADDITIVE,
                               MOVE_VELOCITY, MOVE_TO_END_POS)},
    #          basic: GIw GId CIw CId GOw GOd COw COd Ph | superimposed: GIw GId CIw CId GOw GOd COw COd Ph
    w(GI):     "A   -   A   -   A   -   A   -   -    -   -   -   -   -   -   -   -   -",
    d(GI):     "A   A   A   A   A   A   A   A   A    -   -   -   -   -   -   -   -   -",
    w(CI):     "A   -   A   -   A   -   A   -   -    -   -   -   -   -   -   -   -   -",
    d(CI):     "A   A   A   A   A   A   A   A   A    -   -   -   -   -   -   -   -   -",
    w(GO):     "-   -   -   -   A   -   -   -   -    -   -   -   -   -   -   -   -   -",
    d(GO):     "A   A   -   -   A   -   -   -   A    -   -   -   -   -   -   -   -   -",
    w(CO):     "-   -   -   -   -   -   A   -   -    -   -   -   -   -   -   -   -   -",
    d(CO):     "-   -   A   A   -   -   A   -   A    -   -   -   -   -   -   -   -   -",
    PHASING_FB: "-  -   -   -   -   -   -   -   A    -   -   -   -   -   -   -   -   -",
    w(GIS):    "-   -   -   -   -   -   -   -   -    A   -   A   -   A   -   A   -   -",
    d(GIS):    "-   -   -   -   -   -   -   -   -    A   A   A   A   A   A   A   A   A",
    w(CIS):    "-   -   -   -   -   -   -   -   -    A   -   A   -   A   -   A   -   -",
    d(CIS):    "-   -   -   -   -   -   -   -   -    A   A   A   A   A   A   A   A   A",
    w(GOS):    "-   -   -   -   -   -   -   -   -    -   -   -   -   A   -   -   -   -",
    d(GOS):    "-   -   -   -   -   -   -   -   -    A   A   -   -   A   -   -   -   A",
    w(COS):    "-   -   -   -   -   -   -   -   -    -   -   -   -   -   -   A   -   -",
    d(COS):    "-   -   -   -   -   -   -   -   -    -   -   A   A   -   -   A   -   A",
    PHASING_SI: "-  -   -   -   -   -   -   -   -    -   -   -   -   -   -   -   -   A",
})

# active table-(3) commands (§6.8.3) as columns
_TABLE_3 = table(COLUMNS_3, {
    **{row: "-  -  -  R" for row in ROWS},
    #                    ChangeDataset SetTorqueLimit SetCharacteristic Restart
    # MC_Stop is accepted while the TO restarts and keeps its lock afterwards: its ErrorID table (§6.2.3) has no
    # 8045 and its lock holds whatever happens to the enable (fuzz seed 49 of the S7-Technology campaign)
    STOP:               "-             -              -                 -",
    POWER_OFF:          "A             A              A                 -",
    SET_TORQUE_LIMIT:   "-             A              -                 R",
    SET_CHARACTERISTIC: "-             -              A                 R",
}, R=RESTARTING)

TABLE: dict[str, dict[str, Cell]] = merge(_SINGLE_AXIS, _SYNC, _TABLE_3)

#: "Waiting" of table (3): the new command waits until the active one is Done (the instruction serializes it)
WAITING = frozenset({(CHANGE_DATASET, CHANGE_DATASET)})

# --- Mode 1/2: appending and overlaying (§6.2.6, §6.2.7, §6.2.10 "Prerequisites", ErrorIDs 8055/8045) ----
APPENDABLE = (MOVE_ABSOLUTE, MOVE_RELATIVE, MOVE_VELOCITY)
_NO_APPEND: dict[str, Reject] = {
    STOP: STOP_ACTIVE, RESTART: RESTARTING, HALT: LATCHING, HOME_ACTIVE: LATCHING,
    MOVE_TO_END_POS: LATCHING, CLAMPED: LATCHING, **{c: LATCHING for c in COLUMNS_1}}
APPENDING: dict[str, dict[str, Reject]] = {
    MOVE_ABSOLUTE: dict(_NO_APPEND), MOVE_RELATIVE: dict(_NO_APPEND),
    MOVE_VELOCITY: {**_NO_APPEND, MOVE_VELOCITY: LATCHING},     # never behind an active MC_MoveVelocity
}

#: Mode input -> buffer mode: 0 override, 1 append (stop at the transition), 2 overlay (blend at the lower
#: velocity, 0 on reversal: kernel BLENDING_LOW).  MC_MoveVelocity accepts 0/1 only (its own 8043).
BUFFER_MODES = {0: BufferMode.ABORTING, 1: BufferMode.BUFFERED, 2: BufferMode.BLENDING_LOW}

# --- classes of jobs ---------------------------------------------------------------------------------------
_BY_KIND = {JobKind.HALT: HALT, JobKind.ABSOLUTE: MOVE_ABSOLUTE, JobKind.RELATIVE: MOVE_RELATIVE,
            JobKind.VELOCITY: MOVE_VELOCITY, JobKind.STOP: STOP, JobKind.SUPERIMPOSED: MOVE_SUPERIMPOSED,
            JobKind.HOME_ACTIVE: HOME_ACTIVE, JobKind.HOME_PASSIVE: HOME_PASSIVE, JobKind.HOME_DIRECT: HOME_SET,
            JobKind.HOME_CANCEL: HOME_CANCEL, JobKind.GEAR_IN: GI, JobKind.GEAR_IN_POS: GI, JobKind.CAM_IN: CI,
            JobKind.PHASING: PHASING_FB}
_FBS = frozenset(ROWS_2) | frozenset(SYNC_FBS) | {PHASING_FB, PHASING_SI}


def driving(job: Job) -> bool:
    """§6.8 state "d": synchronizing, synchronous or desynchronizing (a GEAR_IN job synchronizes at once)."""
    return bool(job.kind == JobKind.GEAR_IN or job.start_sync or job.in_sync or job.extra.get("driving"))


def instruction(job: Job) -> str:
    """The command class of a job (see the module docstring)."""
    fb = job.extra.get("fb") or _BY_KIND.get(job.kind)
    if fb not in _FBS:
        raise ValueError(f"no S7-Technology command class for {job.kind} / {job.extra.get('fb')!r}")
    if fb in SYNC_FBS:
        return d(fb) if driving(job) else w(fb)
    if fb == MOVE_TO_END_POS and job.extra.get("clamped"):
        return CLAMPED
    return fb


# the kernel's own class names (kernel code that starts a coupling, the follower's activities; the layered
# axis's held MC_Stop and its superimposed motion) -> ours
_KERNEL_ALIASES = {GEAR_IN: d(GI), SYNC_ACTIVE: d(GI), SYNC_WAITING: w(GI), PHASING: PHASING_FB,
                   K.STOP: STOP, K.SUPERIMPOSED: MOVE_SUPERIMPOSED}
for _alias, _ours in _KERNEL_ALIASES.items():
    TABLE[_alias] = dict(TABLE[_ours])
    for _row in (*TABLE.values(), *APPENDING.values()):
        if _ours in _row:
            _row[_alias] = _row[_ours]

POLICY = OverridePolicy(
    "S7-Technology", TABLE, classify=instruction,
    slots={MOVE_SUPERIMPOSED: SUPERIMPOSED_SLOT},       # MC_MoveSuperImposed adds to the basic motion (§6.2.9)
    # MC_Halt keeps speed-controlled mode (§6.2.10 PositionControl); MC_MoveAdditive is a RELATIVE job
    position_control=frozenset({JobKind.ABSOLUTE, JobKind.RELATIVE, JobKind.HOME_ACTIVE}),
    plan_after_override=True,                           # an aborted superimposed part is taken over first
    queue_depth=1, buffer_modes=BUFFER_MODES, appending=APPENDING)


def refusal(new: str, activities: Iterable[Activity], new_job: Job | None = None) -> Reject | None:
    """For a command that starts no kernel job (table 3, MC_Home Mode 8 ...): the Reject of the first
    activity that refuses a new command of class ``new``; None: it may start."""
    for activity in activities:
        answer = POLICY.decide(new, new_job, activity)
        if isinstance(answer, Reject):
            return answer
    return None


__all__ = ["APPENDABLE", "APPENDING", "BUFFER_MODES", "CHANGE_DATASET", "CLAMPED", "COLUMNS", "ERROR_IDS", "HALT",
           "HOME_ACTIVE", "HOME_CANCEL", "HOME_PASSIVE", "HOME_SET", "MOVE_ABSOLUTE", "MOVE_ADDITIVE",
           "MOVE_RELATIVE", "MOVE_SUPERIMPOSED", "MOVE_TO_END_POS", "MOVE_VELOCITY", "PHASING_FB", "PHASING_SI",
           "POLICY", "POWER_OFF", "POWER_ON", "RESET", "RESTART", "ROWS", "SET_CHARACTERISTIC", "SET_TORQUE_LIMIT",
           "STOP", "SYNC_FBS", "TABLE", "WAITING", "WARNINGS", "d", "driving", "error_id", "heading",
           "instruction", "refusal", "w"]
