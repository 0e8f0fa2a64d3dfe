"""One started command of the motion core: what was latched at the edge of Execute and how far it got."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from ...kernel.jobs import Job
from .causes import Cause

#: Tab. 1: command numbers
DO_NOTHING, MOVE_ABSOLUTE, MOVE_RELATIVE, MOVE_ADDITIVE, MOVE_VELOCITY, STOP, HOME, CYCLIC_SPEED, MOVE_SPEED, \
    TORQUE_CONTROL, CYCLIC_POSITION, HALT = range(12)
NAMES = ("MC_DoNothing", "MC_MoveAbsolute", "MC_MoveRelative", "MC_MoveAdditive", "MC_MoveVelocity", "MC_Stop",
         "MC_Home", "MC_CyclicSpeed", "MC_MoveSpeed", "MC_TorqueControl", "MC_CyclicPosition", "MC_Halt")
POSITIONING = frozenset({MOVE_ABSOLUTE, MOVE_RELATIVE, MOVE_ADDITIVE})
VELOCITY = frozenset({MOVE_VELOCITY, MOVE_SPEED})
STOPPING = frozenset({STOP, HALT})
#: commands that run on the motion core's own cyclic set values, not on a kernel job
CYCLIC = frozenset({CYCLIC_SPEED, TORQUE_CONTROL, CYCLIC_POSITION})
#: commands whose velocity the override I230 scales (§1.2.5, §1.5.5, §1.7.5, §1.9.5)
OVERRIDDEN = frozenset({MOVE_ABSOLUTE, MOVE_RELATIVE, MOVE_ADDITIVE, MOVE_VELOCITY, HOME, MOVE_SPEED})
#: commands with Command Mode I409 on the kernel's job queue (Tab. 4, 7, 10, 14, 28); MC_TorqueControl has it
#: too (Tab. 31) and waits in the motion core (core.py), as it runs on no kernel job
BUFFERABLE = frozenset({MOVE_ABSOLUTE, MOVE_RELATIVE, MOVE_ADDITIVE, MOVE_VELOCITY, MOVE_SPEED})


@dataclass(eq=False, slots=True)
class Command:
    number: int
    values: dict[str, Any]          # the command register latched at the rising edge of Execute
    t0: float                       # motion-core cycle of the edge
    job: Job | None = None          # the kernel job that carries its motion (None: cyclic or denied)
    denied: Cause | None = None     # shown from the next cycle on (handshake)
    cancelled: Cause | None = None
    at_standstill: bool = False     # MC_Stop / MC_Halt denied at standstill: reported as Done (§1.6.7)
    done: bool = False              # I92 latched until the next command
    window_since: float | None = None
    window_reached: bool = False    # the actual position has been in I22 (MoveAdditive base, §1.4.6)
    speed_reached: bool = False     # the profile has reached the set velocity (I183)
    state: int = 2                  # the I89 this command puts the core in while it runs
    cyclic: dict[str, Any] = field(default_factory=dict)    # cyclic commands' interpolator state
    carrier: "Command | None" = None    # denied without a stop: the command whose motion goes on
    waiting: bool = False               # MC_TorqueControl with I409 = 1 behind a running block

    def value(self, name: str) -> Any:
        return self.values[name]

    @property
    def name(self) -> str:
        return NAMES[self.number]


__all__ = ["BUFFERABLE", "CYCLIC", "CYCLIC_POSITION", "CYCLIC_SPEED", "Command", "DO_NOTHING", "HALT", "HOME",
           "MOVE_ABSOLUTE", "MOVE_ADDITIVE", "MOVE_RELATIVE", "MOVE_SPEED", "MOVE_VELOCITY", "NAMES", "OVERRIDDEN",
           "POSITIONING", "STOP", "STOPPING", "TORQUE_CONTROL", "VELOCITY"]
