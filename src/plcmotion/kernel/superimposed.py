"""Superimposed motion: a positioning added on top of the basic motion (MC_MoveSuperimposed, S7-1500).

The superimposed part has a profile of its own, evaluated every servo cycle and added to the setpoint of
the axis, whatever the basic motion is (standstill, a positioning, synchronous operation).  Its distance
accumulates: a new superimposed job starts from the state of the previous one.  When a basic motion job
aborts it (S7-1500T V5 §9.3.1), the superimposed state is handed to the new job, which then plans from
the total setpoint, and the superimposed part is zero again.
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from .jobs import Job, JobState
from .profiles import Planner, PlanningError, Profile

if TYPE_CHECKING:  # pragma: no cover
    from .axis import PositioningAxis

_EPS_T = 1e-9


class SuperimposedMixin:
    """Mixed into the S7-1500 axis."""

    def _sup_init(self: "PositioningAxis") -> None:
        self.sup_profile: Profile | None = None      # None: no superimposed part
        self.sup_job: Job | None = None
        self._sup_seg = 0
        self._sup_carry: tuple[float, float, float] | None = None

    @property
    def superimposed_active(self: "PositioningAxis") -> bool:
        """StatusWord.X23: a superimposed motion is running."""
        return self.sup_job is not None and self.sup_job.busy

    def sup_state_at(self: "PositioningAxis", t: float) -> tuple[float, float, float]:
        if self.sup_profile is None:
            return 0.0, 0.0, 0.0
        return self.sup_profile.at(t)

    def start_superimposed(self: "PositioningAxis", job: Job, lim) -> None:
        """Plan the superimposed positioning by ``job.position`` from the present superimposed state."""
        t = self.now
        p, v, a = self.sup_state_at(t)
        try:
            profile = self.motion.planner.position(t, p, v, a, p + job.position, lim)
        except PlanningError as exc:
            from . import faults as F
            from .faults import Reaction
            self.raise_alarm(F.alarm(F.INTERNAL, "planning", Reaction.EMERGENCY, str(exc)), job=job)
            return
        if self.sup_job is not None and self.sup_job.busy:
            self._finish_job(self.sup_job, JobState.ABORTED, t)
        self.sup_job = job
        self._sup_load(profile)
        if self._sup_seg == len(profile.segments) - 1:
            # nothing left to superimpose (e.g. Distance 0 from a resting part): no end event will come
            self._finish_job(job, JobState.DONE, t)

    def _sup_load(self: "PositioningAxis", profile: Profile | None) -> None:
        was = self.sup_profile is not None
        self.sup_profile = profile
        self._sup_seg = 0
        b, i = self.ctl.bank, self.index
        if profile is None:
            b.sup_t[i] = b.sup_p[i] = b.sup_v[i] = b.sup_a[i] = b.sup_j[i] = 0.0
            self._timers.pop("superimposed", None)
            if was:
                self.ctl._n_sup -= 1
        else:
            if not was:
                self.ctl._n_sup += 1
            self._sup_segment(t=self.now)
        self._schedule()

    def _sup_segment(self: "PositioningAxis", t: float) -> None:
        prof = self.sup_profile
        assert prof is not None
        while prof.end_of(self._sup_seg) <= t + _EPS_T:
            self._sup_seg += 1
        seg = prof.segments[self._sup_seg]
        b, i = self.ctl.bank, self.index
        b.sup_t[i], b.sup_p[i], b.sup_v[i], b.sup_a[i], b.sup_j[i] = seg.t, seg.p, seg.v, seg.a, seg.j
        nxt = prof.end_of(self._sup_seg)
        if nxt < float("inf"):
            self._timers["superimposed"] = nxt
        else:
            self._timers.pop("superimposed", None)

    def _on_superimposed_timer(self: "PositioningAxis", t: float) -> None:
        if self.sup_profile is None:
            return
        self._sup_segment(t)
        if self._sup_seg == len(self.sup_profile.segments) - 1:
            job = self.sup_job
            if job is not None and job.busy:
                self._finish_job(job, JobState.DONE, t)

    def _sup_take_over(self: "PositioningAxis", t: float) -> None:
        """A basic job takes the superimposed state over: remember it for the next plan, end the part."""
        if self.sup_profile is None:
            return
        self._sup_carry = self.sup_state_at(t)
        if self.sup_job is not None and self.sup_job.busy:
            self._finish_job(self.sup_job, JobState.ABORTED, t)
        self.sup_job = None
        self._sup_load(None)

    def _sup_clear(self: "PositioningAxis") -> None:
        if self.sup_job is not None and self.sup_job.busy:
            self._finish_job(self.sup_job, JobState.ABORTED, self.now)
        self.sup_job = None
        self._sup_carry = None
        if self.sup_profile is not None:
            self._sup_load(None)

    @staticmethod
    def _hold(t: float, p: float) -> Profile:
        return Planner.hold(t, p)
