"""Homing by a reference point approach with three velocities, distance monitoring and coordinate
corrections: a :class:`~kernel.homing.Homing` an axis class chooses with ``homing_class = ApproachHoming``.

The settings are ``config.homing.approach`` (:class:`~kernel.axis_config.ReferenceApproach`) beside the
plain homing settings: ``approach_positive`` is the start direction, ``approach_velocity`` the search for
the cam or an external mark, ``referencing_velocity`` the slower search for the zero mark, and
``active.mode`` / ``passive.mode`` the method (0 encoder zero mark only, 1 cam then encoder zero mark,
2 external mark only: an input edge).  Differences to the plain approach:

* a zero mark *before* the cam: after the cam the axis reverses and takes the first zero mark after
  leaving the cam backwards; *after* the cam: the first zero mark after leaving it forwards;
* the homing event sets ``Position - home_offset`` and the axis then always positions to ``Position`` at
  the entry velocity (reversing when that lies within its braking distance; the shortest way on a modulo
  axis);
* distance monitoring: travel from the start to the cam (or external mark) and from the cam (or the
  start) to the zero mark; exceeding it ends the approach with ``reference_not_found/distance``;
* passive homing only while moving in a configured direction (or either), and with the same monitors,
  which stop the axis's motion;
* corrections that keep the homed state: of the actual value, of the basic motion's coordinates and of
  the superimposed motion's coordinates; the latter stay apart (``superimposed_offset``) until they go
  over to the basic coordinates at the moment ``transfer_superimposed`` names.
"""
from __future__ import annotations

from . import faults as F
from .axis_config import ReferenceApproach
from .faults import Fault, Reaction
from .homing import Homing
from .jobs import Job, JobKind, JobState
from .motion import limits

#: moments a superimposed correction goes over to the basic coordinates, per ``transfer_superimposed``
TRANSFER_MOMENTS = {
    "standstill": frozenset({"standstill", "override", "following", "restart"}),
    "merge": frozenset({"override", "following", "restart"}),
    "reset": frozenset({"following", "restart"}),
}
CORRECTION_LAYERS = ("actual", "base", "superimposed")


class ApproachHoming(Homing):
    """MC_Home of an axis with :class:`ReferenceApproach` settings (see the module docstring)."""

    def __init__(self, axis, **kw):
        super().__init__(axis, **kw)
        self.superimposed_offset = 0.0      # corrections of the superimposed coordinates not yet transferred

    @property
    def settings(self) -> ReferenceApproach:
        return self.axis.config.homing.approach or ReferenceApproach()

    # --- configuration --------------------------------------------------------------------------------
    def configured(self, mode: int) -> bool:
        """Is the method of active (3) or passive (2) homing usable: an input for cam and external mark, an
        encoder with zero marks (a drive encoder: every simulated servo drive has them) for zero marks."""
        a = self.axis
        if a.sim:
            return True
        h = a.config.homing
        method = h.active if mode == 3 else h.passive
        if method.mode == 0:
            return a.servo
        if method.mode == 1:
            return a.servo and bool(method.input)
        return bool(method.input)

    def _velocity_fault(self) -> Fault | None:
        """A velocity of the approach that is 0 is a homing error (the approach cannot run)."""
        h, s = self.axis.config.homing, self.settings
        used = [("approach", h.approach_velocity), ("shutdown", h.referencing_velocity), ("entry", s.entry_velocity)]
        if h.active.mode == 0:
            used = used[1:]                              # the zero mark search uses the shutdown velocity only
        for name, v in used:
            if not v > 0.0:
                return F.alarm(F.HOMING_REFERENCING_ZERO, name, Reaction.STOP)
        return None

    # --- active homing ----------------------------------------------------------------------------------
    def _start(self, job: Job, t: float) -> None:
        a = self.axis
        if a.sim:
            super()._start(job, t)                       # no marks to search: brake and home at standstill
            return
        a.homed = False
        h, s = a.config.homing, self.settings
        d = 1.0 if h.approach_positive else -1.0
        here = self._latch_position()
        method = h.active.mode
        job.extra.update(d=d, method=method, origin=here, cam=self._cam("Active"))
        if method == 0:
            job.extra["limit"] = s.zero_mark_distance
            self._phase(job, "zero_mark", d * h.referencing_velocity, t)
            a.drive.arm_zero_mark(d)
            return
        job.extra["limit"] = s.cam_distance
        if method == 1 and job.extra["cam"]:
            self._cam_found(job, t)                      # standing on the cam: the zero mark search begins
            return
        self._phase(job, "search", d * h.approach_velocity, t)

    def _cam_found(self, job: Job, t: float) -> None:
        """The cam is reached: on to the zero mark after it (forwards) or before it (backwards)."""
        a, x = self.axis, job.extra
        s, v_ref = self.settings, a.config.homing.referencing_velocity
        x.update(origin=self._latch_position(), limit=s.zero_mark_distance)
        if s.zero_mark_after_cam:
            x["zdir"] = x["d"]
            self._phase(job, "leave", x["d"] * v_ref, t)
        else:
            x["zdir"] = -x["d"]
            self._phase(job, "turn", 0.0, t)

    def _active_inputs(self, job: Job, t: float) -> None:
        x = job.extra
        if x.get("phase") in (None, "simulated", "offset"):
            return
        cam = self._cam("Active")
        rising, falling = cam and not x["cam"], (not cam) and x["cam"]
        x["cam"] = cam
        if self._too_far(x):
            self._not_found(job)
            return
        phase, method = x["phase"], x["method"]
        if phase == "zero_mark":
            latched = self.axis.drive.zero_mark_latched()
            if latched is not None:
                self._event(job, latched, t)
        elif method == 2 and phase == "search" and (rising if self.settings.external_rising else falling):
            self._event(job, self._latch_position(), t)
        elif method == 1 and phase == "search" and rising:
            self._cam_found(job, t)
        elif method == 1 and phase == "leave" and falling:
            x["phase"] = "zero_mark"                     # off the cam: the first zero mark from here on
            self.axis.drive.arm_zero_mark(x["zdir"])

    def _too_far(self, x: dict) -> bool:
        limit = x.get("limit")
        return limit is not None and abs(self._latch_position() - x["origin"]) > limit

    def _not_found(self, job: Job) -> None:
        """Distance monitoring: the cam or the mark is not within the configured distance."""
        self.axis.drive.disarm_zero_mark()
        job.extra["phase"] = "failed"
        self.axis.raise_alarm(F.alarm(F.REFERENCE_NOT_FOUND, "distance", Reaction.STOP), job=job)

    def on_profile_end(self, job: Job, t: float) -> None:
        phase = job.extra.get("phase")
        if phase == "turn":
            self._phase(job, "leave", job.extra["zdir"] * self.axis.config.homing.referencing_velocity, t)
        elif phase in ("search", "leave", "zero_mark", "failed"):
            return                                       # constant velocity reached: keep going
        else:
            super().on_profile_end(job, t)               # simulated homing, the end of the travel to Position

    def _event(self, job: Job, latched: float, t: float) -> None:
        """The homing event at the actual position ``latched``: it gets ``Position - home_offset``; then the
        axis positions to ``Position`` at the entry velocity."""
        a = self.axis
        a.drive.disarm_zero_mark()
        target = a._wrap(job.position)
        self._set_home(latched, target - a.config.homing.active.home_offset)
        job.reference_position = self.reference_mark
        p, v, acc = a._state_now()
        goal = self._nearest(p, target)
        job.extra["phase"] = "offset"
        job.target = goal
        a._start_profile(a.motion.planner.position(t, p, v, acc, goal, limits(a, self.settings.entry_velocity)))
        a._interpolating = True

    def _nearest(self, p: float, target: float) -> float:
        """``target`` as reached from ``p``: itself, on a modulo axis the shortest way."""
        m = self.axis.config.modulo
        if not m.enabled:
            return target
        delta = (target - p) % m.length
        if delta > m.length / 2:
            delta -= m.length
        return p + delta

    # --- passive homing ----------------------------------------------------------------------------------
    def _arm_passive(self, job: Job) -> None:
        a = self.axis
        s = self.settings
        method = a.config.homing.passive.mode
        job.extra.update(method=method, cam=self._cam("Passive"), origin=self._latch_position(),
                         limit=s.zero_mark_distance if method == 0 else s.cam_distance, zdir=0.0)
        self.passive = job
        if not a.sim and a not in a.ctl._input_axes:     # distance monitors and zero marks need every cycle
            a.ctl._input_axes.append(a)
        if method == 0 and s.passive_direction:
            job.extra["zdir"] = float(s.passive_direction)
            a.drive.arm_zero_mark(s.passive_direction)

    def _passive_inputs(self, job: Job, t: float) -> None:
        a, x, s = self.axis, job.extra, self.settings
        cam = self._cam("Passive")
        rising, falling = cam and not x["cam"], (not cam) and x["cam"]
        x["cam"] = cam
        if self._too_far(x):
            # passive homing has no motion of its own: the monitor ends the axis's motion (reaction stop)
            a.drive.disarm_zero_mark()
            fault = F.alarm(F.REFERENCE_NOT_FOUND, "distance", Reaction.STOP)
            self.end_passive(JobState.ERROR, fault)
            a.raise_alarm(fault)
            return
        motion = self._moving_direction()
        allowed = motion != 0.0 and s.passive_direction in (0, motion)
        method = x["method"]
        if method == 2:
            if allowed and (rising if s.passive_rising else falling):
                self._passive_event(job, self._latch_position(), t)
            return
        if method == 1 and falling and allowed:
            # the cam is passed: the next zero mark in this direction homes; its distance counts from here
            x.update(origin=self._latch_position(), limit=s.zero_mark_distance, zdir=motion)
            a.drive.arm_zero_mark(motion)
        elif method == 0 and s.passive_direction == 0 and motion != 0.0 and motion != x["zdir"]:
            x["zdir"] = motion                           # "current direction": the zero mark ahead of the axis
            a.drive.arm_zero_mark(motion)
        if x["zdir"]:
            latched = a.drive.zero_mark_latched()
            if latched is not None:
                self._passive_event(job, latched, t)

    def cancel_passive(self) -> bool:
        """End an armed passive homing (Aborted); False when none is armed (or it is done)."""
        if not self.passive_busy:
            return False
        self.axis.drive.disarm_zero_mark()
        self.end_passive(JobState.ABORTED)
        return True

    # --- set and correct the coordinates ------------------------------------------------------------------
    def set_position(self, job: Job) -> None:
        """Direct homing: the present position becomes ``job.position``; the axis is homed.  Enabled or not,
        at standstill or moving (the motion carries on in the new coordinates)."""
        a = self.axis
        if a.job is not None and a.job.busy and a.job.kind == JobKind.HOME_ACTIVE:
            job.finish(JobState.ERROR, F.reject(F.REJECTED, "homing_active"))
            return
        here = float(a.ctl.bank.sp_p[a.index])
        self._set_home(here, a._wrap(job.position))
        job.reference_position = self.reference_mark
        job.finish(JobState.DONE)
        a._replan()

    def correct(self, job: Job, layer: str) -> None:
        """A correction by ``-job.position`` that keeps the homed state: of the actual value ("actual"), of the
        basic motion's coordinates ("base") or of the superimposed motion's ("superimposed").  Each moves the
        axis's coordinates (setpoint, actual value, targets) alike, so the following error stays and nothing
        moves; a superimposed correction is also kept as ``superimposed_offset`` until it is transferred."""
        if layer not in CORRECTION_LAYERS:
            raise ValueError(f"correction layer {layer!r} is not one of {CORRECTION_LAYERS}")
        a = self.axis
        delta = -job.position
        self._shift(delta)
        if layer == "superimposed":
            self.superimposed_offset += delta
        job.finish(JobState.DONE)
        a._replan()

    def transfer_superimposed(self, moment: str) -> bool:
        """``moment`` ("standstill", "override", "following", "restart") has come: when the configured
        transfer takes place then, the superimposed corrections become part of the basic coordinates
        (True).  The total position does not change."""
        if self.superimposed_offset == 0.0 or moment not in TRANSFER_MOMENTS[self.settings.transfer_superimposed]:
            return False
        self.superimposed_offset = 0.0
        return True


__all__ = ["ApproachHoming", "CORRECTION_LAYERS", "TRANSFER_MOMENTS"]
