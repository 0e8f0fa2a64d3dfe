"""Which running job a new job aborts on an S7-1500 axis (S7-1500T V5 §9.3.1, §9.3.2).

Jobs are grouped into the classes the manual's tables use.  ``aborts(new, running)`` answers one cell:
True = the running job ends with CommandAborted, False = it continues.  A waiting synchronous job
(GearInPos/CamIn before StartSync) aborts nothing; when it becomes active it is looked up again as
``SYNC_ACTIVE`` (§9.3.2 note 1).
"""
from __future__ import annotations

from .jobs import Job, JobKind

HOME_PASSIVE = "home_passive"            # MC_Home Mode 2, 8, 10
HOME_ACTIVE = "home_active"              # MC_Home Mode 3, 5
HOME_CANCEL = "home_cancel"              # MC_Home Mode 9
MOTION = "motion"                        # MC_Halt, MC_MoveAbsolute/-Relative/-Velocity, MC_MoveJog
HALT = "halt"                            # MC_Halt where it differs from the other motion jobs (§9.3.2)
STOP = "stop"                            # MC_Stop
SUPERIMPOSED = "superimposed"            # MC_MoveSuperimposed
GEAR_IN = "gear_in"                      # MC_GearIn
SYNC_WAITING = "sync_waiting"            # MC_GearInPos / MC_CamIn waiting
SYNC_ACTIVE = "sync_active"              # MC_GearInPos / MC_CamIn synchronizing or synchronous
PHASING = "phasing"                      # MC_PhasingAbsolute / -Relative
LV_ADDITIVE = "lv_additive"              # MC_LeadingValueAdditive

# §9.3.1: columns = running homing and motion jobs
_MOTION_TABLE: dict[str, dict[str, bool]] = {
    #                 running: home_passive home_active motion  stop  superimposed
    HOME_ACTIVE:  dict(home_passive=True, home_active=True, motion=True, stop=False, superimposed=True),
    HOME_CANCEL:  dict(home_passive=True, home_active=False, motion=False, stop=False, superimposed=False),
    MOTION:       dict(home_passive=False, home_active=True, motion=True, stop=False, superimposed=True),
    SUPERIMPOSED: dict(home_passive=False, home_active=False, motion=False, stop=False, superimposed=True),
    STOP:         dict(home_passive=True, home_active=True, motion=True, stop=True, superimposed=True),
    GEAR_IN:      dict(home_passive=False, home_active=True, motion=True, stop=False, superimposed=True),
    SYNC_WAITING: dict(home_passive=False, home_active=False, motion=False, stop=False, superimposed=False),
    SYNC_ACTIVE:  dict(home_passive=False, home_active=True, motion=True, stop=False, superimposed=True),
    LV_ADDITIVE:  dict(home_passive=False, home_active=False, motion=False, stop=False, superimposed=False),
}

# §9.3.2: columns = running synchronous operation jobs
_SYNC_TABLE: dict[str, dict[str, bool]] = {
    #                 running: gear_in sync_waiting sync_active phasing lv_additive
    HOME_ACTIVE:  dict(gear_in=True, sync_waiting=False, sync_active=False, phasing=False, lv_additive=False),
    HALT:         dict(gear_in=True, sync_waiting=False, sync_active=True, phasing=True, lv_additive=False),
    MOTION:       dict(gear_in=True, sync_waiting=False, sync_active=True, phasing=True, lv_additive=False),
    SUPERIMPOSED: dict(gear_in=False, sync_waiting=False, sync_active=False, phasing=False, lv_additive=False),
    STOP:         dict(gear_in=True, sync_waiting=True, sync_active=True, phasing=True, lv_additive=True),
    GEAR_IN:      dict(gear_in=True, sync_waiting=True, sync_active=True, phasing=True, lv_additive=False),
    SYNC_WAITING: dict(gear_in=False, sync_waiting=True, sync_active=False, phasing=False, lv_additive=False),
    SYNC_ACTIVE:  dict(gear_in=True, sync_waiting=True, sync_active=True, phasing=True, lv_additive=False),
    PHASING:      dict(gear_in=False, sync_waiting=False, sync_active=False, phasing=True, lv_additive=False),
    LV_ADDITIVE:  dict(gear_in=False, sync_waiting=False, sync_active=False, phasing=False, lv_additive=True),
}

_MOTION_KINDS = {JobKind.ABSOLUTE, JobKind.RELATIVE, JobKind.VELOCITY, JobKind.JOG}


def job_class(job: Job) -> str:
    """The §9.3 class of a job in its current state."""
    kind = job.kind
    if kind == JobKind.HALT:
        return HALT
    if kind in _MOTION_KINDS:
        return MOTION
    if kind == JobKind.HOME_ACTIVE:
        return HOME_ACTIVE
    if kind == JobKind.HOME_PASSIVE:
        return HOME_PASSIVE
    if kind == JobKind.HOME_CANCEL:
        return HOME_CANCEL
    if kind == JobKind.STOP:
        return STOP
    if kind == JobKind.SUPERIMPOSED:
        return SUPERIMPOSED
    if kind == JobKind.GEAR_IN:
        return GEAR_IN
    if kind in (JobKind.GEAR_IN_POS, JobKind.CAM_IN):
        return SYNC_ACTIVE if (job.start_sync or job.in_sync) else SYNC_WAITING
    if kind == JobKind.PHASING:
        return PHASING
    if kind == JobKind.LV_ADDITIVE:
        return LV_ADDITIVE
    raise ValueError(f"no override class for {kind}")


def aborts(new: str, running: str) -> bool:
    """Does a new job of class ``new`` abort a running job of class ``running``?"""
    motion_col = MOTION if running == HALT else running
    if motion_col in (HOME_PASSIVE, HOME_ACTIVE, MOTION, STOP, SUPERIMPOSED):
        row = _MOTION_TABLE.get(MOTION if new == HALT else new)
        return bool(row and row.get(motion_col, False))
    if running in (GEAR_IN, SYNC_WAITING, SYNC_ACTIVE, PHASING, LV_ADDITIVE):
        row = _SYNC_TABLE.get(new)
        if row is None and new == HOME_PASSIVE:
            return False
        if row is None and new == HOME_CANCEL:
            return False
        return bool(row and row.get(running, False))
    return False
