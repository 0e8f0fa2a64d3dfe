"""The base and the superimposing coordinate system of an axis and when the second goes over into the first
(S7-Technology V4.1 §3.1.7, §6.2.2 "Notes on Mode = 7", parameter TypeOfAxis.DecodingConfig.transferSuperimposed).

The total setpoint is the basic motion plus the superimposed motion.  In plcmotion the superimposed
coordinate (system variable 4030 ``superimposedmotion.position``) is

* the position of the superimposed layer while it is loaded (``axis.superimposed``: MC_MoveSuperImposed; the
  layer keeps its end position after the command is Done), plus
* ``axis.homing.superimposed_offset``: what belongs to the superimposing system but already moves with the
  basic profile - MC_Home Mode 7 corrections (``kernel.reference_approach``) and a layer the kernel folded
  into the basic motion (a basic command or an error reaction took it over) without a transfer.

4040 ``basicmotion.position`` is the total minus that.  A *transfer* makes the superimposed coordinate part
of the basic one (it becomes 0; the total does not move).  It happens at the moments the configuration names
(``kernel.reference_approach.TRANSFER_MOMENTS``): "standstill" (the axis stands, no coupling, TRANSFER_STANDSTILL
only), "override" (a command overrides the basic motion; not with TRANSFER_RESET), "following" (MC_Power Mode
2/3, and when the enable is removed: the axis follows its actual value) and "restart" (MC_Reset Restart = TRUE).
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from ...kernel.profiles import Planner
from ...kernel.reference_approach import TRANSFER_MOMENTS

if TYPE_CHECKING:  # pragma: no cover
    from .axes import AxisT

_EPS_T = 1e-9


def superimposed_state(ax: "AxisT") -> tuple[float, float]:
    """(position, velocity) in the superimposing coordinate system now (4030, 4031)."""
    offset = getattr(ax.homing, "superimposed_offset", 0.0)
    if ax.sup_profile is None:
        return offset, 0.0
    p, v, _ = ax.sup_state_at(ax.now)
    return float(p) + offset, float(v)


def transfers_at(ax: "AxisT", moment: str) -> bool:
    """Does the configured transfer take place at ``moment``?"""
    return moment in TRANSFER_MOMENTS[ax.homing.settings.transfer_superimposed]


def layer_taken_over(ax: "AxisT", position: float) -> None:
    """The kernel folded the superimposed layer at ``position`` into the basic motion (a basic command
    overrode it, an error reaction or a disable took it over): without a transfer the coordinate stays in the
    superimposing system."""
    if position:
        ax.homing.superimposed_offset += position


def at_standstill(ax: "AxisT") -> bool:
    """Both layers at rest, no command moving the axis and no coupling ("the axis must be desynchronized")."""
    t = ax.now
    for job in (ax.job, ax.sup_job, ax.stop_job):
        if job is not None and job.busy:
            return False
    follower = ax.follower
    if follower is not None and follower.coupling is not None:
        return False
    for prof in (ax.profile, ax.sup_profile):
        if prof is not None and (prof.final.v != 0.0 or prof.final.a != 0.0 or t < prof.t_end - _EPS_T):
            return False
    return True


def transfer(ax: "AxisT", moment: str) -> bool:
    """``moment`` has come: when the configuration transfers then, a resting superimposed layer becomes part
    of the basic profile and the superimposed coordinate goes to 0 (True).  A moving layer stays (only the
    standstill and the disable moments come with a resting one)."""
    if not transfers_at(ax, moment):
        return False
    t = ax.now
    sup = ax.sup_profile
    if sup is not None and sup.final.v == 0.0 and sup.final.a == 0.0 and t >= sup.t_end - _EPS_T:
        ax.superimposed.take_over(t)             # its state is carried into the basic motion ...
        p, _v, _a = ax._state_now()
        ax._start_profile(Planner.hold(t, p))     # ... which rests there from now on
    elif sup is not None:
        return False
    ax.homing.transfer_superimposed(moment)
    return True


def transfer_at_standstill(ax: "AxisT") -> None:
    if transfers_at(ax, "standstill") and at_standstill(ax):
        transfer(ax, "standstill")


__all__ = ["superimposed_state", "transfers_at", "layer_taken_over", "at_standstill", "transfer",
           "transfer_at_standstill"]
