"""Which running command a new one aborts on an S7-Technology axis, for the instructions of issue 11 part 1
(S7-Technology V4.1 §6.8 "new command - active single command (2)", as far as the instruction texts of
§6.2 state it; the complete tables of §6.8 are ``override.POLICY``, which replaces this one).

Rows: the new command, columns: the running one; "A" it is aborted (CommandAborted), "-" it goes on.
* MC_Stop stops every motion, the superimposed one too; only another MC_Stop ends a running MC_Stop (§6.2.3);
  while MC_Stop holds the axis new motion is refused before this table is asked (the axis's lock, 8045).
* MC_Halt, the positionings and MC_MoveVelocity abort the basic motion and a superimposed positioning
  (§6.2.4, §6.2.6; MC_Home Mode 7 of §6.2.2 is the documented exception).
* MC_MoveSuperImposed aborts only a running MC_MoveSuperImposed (§6.2.9).
``Mode`` (§6.2.6, §6.2.10): 0 override (Aborting), 1 append (Buffered: the axis stops at the transition),
2 overlay (BlendingLow: the transition at the lower of the two velocities, standstill on a reversal);
one command may wait behind the running one.
"""
from __future__ import annotations

from ...kernel.job_queue import BufferMode
from ...kernel.jobs import JobKind
from ...kernel.policy import (HALT, HOME_ACTIVE, HOME_PASSIVE, MOTION, STOP, SUPERIMPOSED, SUPERIMPOSED_SLOT,
                              OverridePolicy, job_class, table)

_CELLS = table(
    (HOME_PASSIVE, HOME_ACTIVE, HALT, MOTION, STOP, SUPERIMPOSED), {
        #              passive  active  Halt  Move*  Stop  MoveSuperImposed
        HOME_ACTIVE:  "A        A       A     A      -     A",
        HALT:         "-        A       A     A      -     A",
        MOTION:       "-        A       A     A      -     A",
        SUPERIMPOSED: "-        -       -     -      -     A",
        STOP:         "A        A       A     A      A     A",
    })

#: ``Mode`` input of MC_MoveAbsolute / MC_MoveRelative (0, 1, 2) and MC_MoveVelocity (0, 1)
BUFFER_MODES = {0: BufferMode.ABORTING, 1: BufferMode.BUFFERED, 2: BufferMode.BLENDING_LOW}

POLICY = OverridePolicy(
    "S7-Technology (part 1)", _CELLS, classify=job_class,
    slots={SUPERIMPOSED: SUPERIMPOSED_SLOT},
    # speed control ends with every positioning, not with MC_Halt or MC_Stop (§6.2.10)
    position_control=frozenset({JobKind.ABSOLUTE, JobKind.RELATIVE, JobKind.HOME_ACTIVE}),
    plan_after_override=True, queue_depth=1, buffer_modes=BUFFER_MODES)

__all__ = ["POLICY", "BUFFER_MODES"]
