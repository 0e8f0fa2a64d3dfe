"""Superimposed motion: a positioning added on top of the basic motion (MC_MoveSuperimposed, S7-1500T V5
§6.1.5.4, §9.3.1).

The superimposed part has a profile of its own, added to the setpoint of the axis whatever the basic
motion is (standstill, a positioning, synchronous operation).  Its distance accumulates: a new
superimposed job starts from the state of the previous one.  When a basic motion job aborts it (§9.3.1),
the superimposed state is handed to the new job, which then plans from the total setpoint, and the
superimposed part is zero again.

Cost per servo cycle: none in Python.  The active constant-jerk segment of the part sits in the bank
(``sup_t/sup_p/sup_v/sup_a/sup_j``), which the ``superimpose`` servo stage evaluates for all axes at once
while ``_n_sup`` axes have a part; the component only runs at a segment boundary (the axis timer
``"superimposed"``) and when a job starts or ends.
"""
from __future__ import annotations

from typing import Any, Protocol

from . import faults as F
from .faults import Fault, Reaction
from .jobs import Job, JobState
from .profiles import PlanningError, Profile

_EPS_T = 1e-9
#: name of the axis timer at the end of the part's active segment
TIMER = "superimposed"


class SuperimposedController(Protocol):
    """What the component needs of the controller: the bank and the count of axes with a part."""

    bank: Any
    _n_sup: int                       # guards the superimpose servo stage


class SuperimposedHost(Protocol):
    """What :class:`SuperimposedMotion` needs of its axis."""

    @property
    def ctl(self) -> SuperimposedController: ...

    @property
    def index(self) -> int: ...

    @property
    def now(self) -> float: ...

    @property
    def motion(self) -> Any: ...      # MotionPlanner: ``planner.position(t, p, v, a, target, lim)``

    _timers: dict[str, float]         # the axis's timers (name -> due time), see ``_schedule``

    def _schedule(self) -> None: ...

    def _finish_job(self, job: Job, state: JobState, t: float, fault: Fault | None = None) -> None: ...

    def raise_alarm(self, fault: Fault, job: Job | None = None) -> None: ...


class SuperimposedMotion:
    """The superimposed motion of one axis (``axis.superimposed``).

    ``profile`` is the part's profile (None: no part), ``job`` the MC_MoveSuperimposed job that made it,
    ``carry`` the state a basic job took over (added to the basic motion until that job's profile starts).
    """

    def __init__(self, host: SuperimposedHost):
        self.host = host
        self.profile: Profile | None = None
        self.job: Job | None = None
        self.seg = 0
        self.carry: tuple[float, float, float] | None = None

    def __repr__(self) -> str:
        return f"<SuperimposedMotion {'active' if self.active else 'idle'}>"

    @property
    def active(self) -> bool:
        """StatusWord.X23 (S7-1500T V5 §A.1.34): a superimposed motion is running."""
        return self.job is not None and self.job.busy

    def state_at(self, t: float) -> tuple[float, float, float]:
        """(position, velocity, acceleration) of the superimposed part at ``t``."""
        if self.profile is None:
            return 0.0, 0.0, 0.0
        return self.profile.at(t)

    def start(self, job: Job, lim: Any) -> None:
        """Plan the superimposed positioning by ``job.position`` from the present superimposed state
        (a running superimposed job is aborted, its distance so far stays)."""
        host = self.host
        t = host.now
        p, v, a = self.state_at(t)
        try:
            profile = host.motion.planner.position(t, p, v, a, p + job.position, lim)
        except PlanningError as exc:
            host.raise_alarm(F.alarm(F.INTERNAL, "planning", Reaction.EMERGENCY, str(exc)), job=job)
            return
        if self.job is not None and self.job.busy:
            host._finish_job(self.job, JobState.ABORTED, t)
        self.job = job
        self._load(profile)
        if self.seg == len(profile.segments) - 1:
            # nothing left to superimpose (e.g. Distance 0 from a resting part): no end event will come
            host._finish_job(job, JobState.DONE, t)

    def on_timer(self, t: float) -> None:
        """The axis timer ``"superimposed"``: the active segment has ended."""
        prof = self.profile
        if prof is None:
            return
        self._segment(t)
        if self.seg == len(prof.segments) - 1:
            job = self.job
            if job is not None and job.busy:
                self.host._finish_job(job, JobState.DONE, t)

    def take_over(self, t: float, state: JobState = JobState.ABORTED, fault: Fault | None = None) -> None:
        """End the part: a running job ends with ``state`` (Aborted by a basic job, Error with an alarm);
        the part's state at ``t`` is remembered in ``carry`` for the basic motion's next plan."""
        job = self.job
        if self.profile is not None:
            self.carry = self.state_at(t)
        if job is not None and job.busy:
            self.host._finish_job(job, state, t, fault)
        if self.profile is None:
            return
        self.job = None
        self._load(None)

    def clear(self) -> None:
        """Forget the part and any carried state (restart of the technology object)."""
        job = self.job
        if job is not None and job.busy:
            self.host._finish_job(job, JobState.ABORTED, self.host.now)
        self.job = None
        self.carry = None
        if self.profile is not None:
            self._load(None)

    # --- the bank row and the timer -------------------------------------------------------------------
    def _load(self, profile: Profile | None) -> None:
        host = self.host
        had = self.profile is not None
        self.profile = profile
        self.seg = 0
        ctl = host.ctl
        if profile is None:
            b, i = ctl.bank, host.index
            b.sup_t[i] = b.sup_p[i] = b.sup_v[i] = b.sup_a[i] = b.sup_j[i] = 0.0
            host._timers.pop(TIMER, None)
            if had:
                ctl._n_sup -= 1
        else:
            if not had:
                ctl._n_sup += 1
            self._segment(host.now)
        host._schedule()

    def _segment(self, t: float) -> None:
        """Put the segment active at ``t`` into the bank and set the timer to its end."""
        prof = self.profile
        assert prof is not None
        while prof.end_of(self.seg) <= t + _EPS_T:
            self.seg += 1
        seg = prof.segments[self.seg]
        host = self.host
        b, i = host.ctl.bank, host.index
        b.sup_t[i], b.sup_p[i], b.sup_v[i], b.sup_a[i], b.sup_j[i] = seg.t, seg.p, seg.v, seg.a, seg.j
        nxt = prof.end_of(self.seg)
        if nxt < float("inf"):
            host._timers[TIMER] = nxt
        else:
            host._timers.pop(TIMER, None)
