"""Which running job a new job aborts on an S7-1500 axis: the tables of S7-1500T V5 §9.3.1 and §9.3.2 as data.

Jobs are grouped into the classes the manual's tables use (the kernel's classes, ``kernel.policy``).
Rows: the new job, columns: the running job; "A" it is aborted (CommandAborted), "-" it goes on.  A waiting
synchronous job (GearInPos/CamIn before StartSync) aborts nothing; when it becomes active it is looked up
again as ``SYNC_ACTIVE`` (§9.3.2 note 1).  Two cells are more than A or -:

* "B" (§9.3.1): a new MC_Stop aborts a running one with the same or a weaker stop response; a weaker one is
  rejected (the stronger stop goes on).
* Active homing against an active GearInPos/CamIn (§9.3.2 "-": the synchronous operation goes on): the
  homing job is rejected, it cannot move the axis while it follows its leading value.
"""
from __future__ import annotations

from ...kernel import faults as F
from ...kernel.jobs import Job, JobKind
from ...kernel.policy import (GEAR_IN, HALT, HOME_ACTIVE, HOME_CANCEL, HOME_PASSIVE, LV_ADDITIVE, MOTION, PHASING,
                              STOP, SUPERIMPOSED, SUPERIMPOSED_SLOT, SYNC_ACTIVE, SYNC_WAITING, OverridePolicy,
                              Ranked, Reject, job_class, merge, table)

#: MC_Stop modes and their stop response (a new MC_Stop aborts one with the same or a lower one, §9.3.1 B)
STOP_MODES = {0: 2, 2: 1}      # 0 emergency stop ramp (strongest), 2 maximum dynamic values

_B = Ranked(rank=lambda job: STOP_MODES.get(job.mode, 0), weaker=Reject(F.STOP_ACTIVE, "weaker"))
_R = Reject(F.SYNC_ACTIVE)

# §9.3.1: columns = running homing and motion jobs ("Halt/Move*/Jog" is one column: HALT and MOTION)
_TABLE_9_3_1 = table(
    (HOME_PASSIVE, HOME_ACTIVE, HALT, MOTION, STOP, SUPERIMPOSED), {
        #              Home 2/8/10  Home 3/5  Halt  Move*/Jog  Stop  MoveSuperimposed
        HOME_ACTIVE:  "A            A         A     A          -     A",
        HOME_CANCEL:  "A            -         -     -          -     -",
        HALT:         "-            A         A     A          -     A",
        MOTION:       "-            A         A     A          -     A",
        SUPERIMPOSED: "-            -         -     -          -     A",
        STOP:         "A            A         A     A          B     A",
        GEAR_IN:      "-            A         A     A          -     A",
        SYNC_WAITING: "-            -         -     -          -     -",
        SYNC_ACTIVE:  "-            A         A     A          -     A",
        LV_ADDITIVE:  "-            -         -     -          -     -",
    }, B=_B)

# §9.3.2: columns = running synchronous operation jobs
_TABLE_9_3_2 = table(
    (GEAR_IN, SYNC_WAITING, SYNC_ACTIVE, PHASING, LV_ADDITIVE), {
        #              GearIn  waiting  active  Phasing  LeadingValueAdditive
        HOME_ACTIVE:  "A       -        R       -        -",
        HALT:         "A       -        A       A        -",
        MOTION:       "A       -        A       A        -",
        SUPERIMPOSED: "-       -        -       -        -",
        STOP:         "A       A        A       A        A",
        GEAR_IN:      "A       A        A       A        -",
        SYNC_WAITING: "-       A        -       -        -",
        SYNC_ACTIVE:  "A       A        A       A        -",
        PHASING:      "-       -        -       A        -",
        LV_ADDITIVE:  "-       -        -       -        A",
    }, R=_R)

POLICY = OverridePolicy(
    "S7-1500", merge(_TABLE_9_3_1, _TABLE_9_3_2), classify=job_class,
    slots={SUPERIMPOSED: SUPERIMPOSED_SLOT},          # MC_MoveSuperimposed adds to the basic motion
    # MC_Halt brakes position-controlled too (a velocity job without position control is left by it)
    position_control=frozenset({JobKind.ABSOLUTE, JobKind.RELATIVE, JobKind.HOME_ACTIVE, JobKind.HALT}),
    plan_after_override=True)                         # an ended superimposed part is taken over first


def aborts(new: str, running: str) -> bool:
    """Does a new job of class ``new`` abort a running job of class ``running``?"""
    return POLICY.aborts(new, running)


__all__ = ["GEAR_IN", "HALT", "HOME_ACTIVE", "HOME_CANCEL", "HOME_PASSIVE", "LV_ADDITIVE", "MOTION", "PHASING",
           "POLICY", "STOP", "STOP_MODES", "SUPERIMPOSED", "SYNC_ACTIVE", "SYNC_WAITING", "Job", "aborts",
           "job_class"]
