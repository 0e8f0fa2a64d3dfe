"""Motion jobs: what an instruction hands to an axis and how far it got.

A job is created by a dialect's instruction, submitted to the axis and then only observed by the
instruction: the axis moves the job through BUSY to exactly one of DONE, ABORTED or ERROR.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from enum import Enum, IntEnum
from typing import Any

from .faults import Fault


class JobState(IntEnum):
    BUSY = 1
    DONE = 2
    ABORTED = 3
    ERROR = 4


class JobKind(Enum):
    HALT = "halt"
    ABSOLUTE = "absolute"
    RELATIVE = "relative"
    VELOCITY = "velocity"
    JOG = "jog"
    HOME_DIRECT = "home_direct"      # modes 0/1 (and absolute encoder adjustment 6/7)
    HOME_PASSIVE = "home_passive"    # mode 2
    HOME_ACTIVE = "home_active"      # mode 3
    TABLE = "table"                  # a table of motion steps, run by a runner (kernel.job_runner)
    RESET = "reset"                  # acknowledgement / restart (never moves the axis)
    HOME_CANCEL = "home_cancel"      # S7-1500 MC_Home Mode 9: cancel passive homing
    STOP = "stop"                    # S7-1500 MC_Stop: brake and keep the axis locked while Execute is TRUE
    SUPERIMPOSED = "superimposed"    # MC_MoveSuperimposed: a motion added to the basic motion
    GEAR_IN = "gear_in"
    GEAR_IN_POS = "gear_in_pos"
    CAM_IN = "cam_in"
    PHASING = "phasing"              # MC_PhasingRelative / -Absolute (extra["absolute"])
    LV_ADDITIVE = "lv_additive"      # MC_LeadingValueAdditive
    SYNC_SIMULATION = "sync_simulation"
    CAM_INTERPOLATE = "cam_interpolate"
    CAM_LEADING = "cam_leading"      # leading value for a following value (position = following value)
    CAM_FOLLOWING = "cam_following"  # following value and derivatives (position = leading value)


#: jobs that command a motion and so take the axis over from each other (S7-1200 V6 §11.1 override lists)
MOTION_KINDS = frozenset({JobKind.HALT, JobKind.ABSOLUTE, JobKind.RELATIVE, JobKind.VELOCITY, JobKind.JOG,
                          JobKind.HOME_ACTIVE, JobKind.TABLE})
POSITIONING_KINDS = frozenset({JobKind.ABSOLUTE, JobKind.RELATIVE})


@dataclass(eq=False)
class Job:
    kind: JobKind
    position: float = 0.0              # absolute target, home position or relative distance
    velocity: float = 0.0              # magnitude for positioning, signed for velocity/jog
    direction: int = 0                 # modulo direction of MC_MoveAbsolute (0..3)
    current: bool = False              # MC_MoveVelocity "maintain current velocity"
    position_controlled: bool = True
    mode: int = 0                      # homing mode
    owner: Any = None                  # the instruction instance that started the job

    state: JobState = JobState.BUSY
    fault: Fault | None = None
    in_velocity: bool = False          # velocity reached (velocity/jog jobs)
    reached_once: bool = False         # velocity has been reached at least once
    target: float = 0.0                # resolved absolute target (positioning)
    reference_position: float = 0.0    # homing: position the axis was homed to
    jog_released: bool = False
    # dynamics of the job (S7-1500 instructions); None: the axis's defaults (S7-1200 semantics)
    acceleration: float | None = None
    deceleration: float | None = None
    jerk: float | None = None          # math.inf: trapezoidal profile
    # synchronous operation (GearIn, GearInPos, CamIn)
    start_sync: bool = False           # synchronization has started (StartSync)
    in_sync: bool = False              # synchronous (InGear / InSync)
    end_of_profile: int = 0            # counts cam ends reached (EndOfProfile)
    # waiting in the axis's job queue behind the running job (PLCopen buffer modes, kernel/job_queue.py)
    pending: bool = False
    extra: dict = field(default_factory=dict)

    @property
    def busy(self) -> bool:
        return self.state == JobState.BUSY

    @property
    def active(self) -> bool:
        """PLCopen Part 1 "Active": the job controls the axis (Busy and no longer waiting in the queue)."""
        return self.state == JobState.BUSY and not self.pending

    def finish(self, state: JobState, fault: Fault | None = None) -> None:
        if self.state == JobState.BUSY:
            self.state = state
            self.fault = fault
            self.in_velocity = self.in_velocity and state == JobState.DONE
