"""Per-cycle state of all axes of a controller, kept as arrays (one element per axis).

The servo cycle evaluates every axis at once with numpy; Python code per axis runs only when something
happens (a segment ends, a milestone is reached, a monitor trips).  Arrays are exactly as long as there are
axes and are re-allocated when an axis is added, so code must look fields up on the bank each cycle
instead of keeping references to them.
"""
from __future__ import annotations

import numpy as np

FLOAT_FIELDS = (
    # active profile segment (constant jerk) and the time of the next event of the axis
    "seg_t", "seg_p", "seg_v", "seg_a", "seg_j", "next_event",
    # setpoint of this cycle, actual values, speed command to the drive, following error
    "sp_p", "sp_v", "sp_a", "sp_j", "act_p", "act_v", "cmd_v", "fe",
    # position controller
    "kv", "kpc",
    # following error monitoring (velocity dependent limit; warning at fe_warn times the limit, inf: none)
    "fe_min", "fe_max", "fe_vmin", "fe_slope", "fe_warn",
    # positioning monitoring
    "pm_target", "pm_deadline", "pm_in_since", "pm_window", "pm_dwell",
    # standstill signal
    "ss_threshold", "ss_dwell", "ss_since",
    # superimposed motion (S7-1500 MC_MoveSuperimposed): a second profile segment added to the setpoint
    "sup_t", "sup_p", "sup_v", "sup_a", "sup_j",
    # its position part in this cycle (the positioning window is about the basic target plus it)
    "sup_now",
)
BOOL_FIELDS = (
    "closed_loop",     # position loop active (servo axis, enabled, position-controlled)
    "follow_act",      # setpoint position follows the actual position (disabled or not position-controlled)
    "fe_on",           # following error monitoring active
    "fe_warned",       # following error above its warning level (reported once per excursion)
    "pm_on",           # positioning monitoring running
    "servo",           # PROFIdrive/analog axis (not PTO, not simulated)
    "standstill",      # standstill signal
    "simulated",       # the actual values are the setpoints, the drive stands (a family's simulation mode)
)


class AxisBank:
    def __init__(self) -> None:
        self.n = 0
        # how many elements of closed_loop / follow_act are TRUE, kept by the axes that set them
        # (PositioningAxis._set_loop_flags) so that the servo cycle can skip a uniform mask
        self.n_closed = 0
        self.n_follow = 0
        for name in FLOAT_FIELDS:
            setattr(self, name, np.zeros(0))
        for name in BOOL_FIELDS:
            setattr(self, name, np.zeros(0, dtype=bool))

    def add(self) -> int:
        """Append one axis; returns its index."""
        i = self.n
        for name in FLOAT_FIELDS:
            setattr(self, name, np.append(getattr(self, name), 0.0))
        for name in BOOL_FIELDS:
            setattr(self, name, np.append(getattr(self, name), False))
        self.n += 1
        self.next_event[i] = np.inf
        self.fe_warn[i] = np.inf
        self.pm_in_since[i] = np.nan
        return i
