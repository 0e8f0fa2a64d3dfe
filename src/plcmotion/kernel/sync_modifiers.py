"""What modifies a running synchronous operation of a following axis (S7-1500T V5): the leading value
shift of a gearing (MC_PhasingRelative/-Absolute, §4.5), the additive leading value
(MC_LeadingValueAdditive, §3.5) and the simulation of synchronous operation
(MC_SynchronizedMotionSimulation, §3.4).

Functions of a :class:`~plcmotion.kernel.follower.Follower` (typed here by what they use of it,
:class:`Modified`), which keeps the jobs and the additive value they set.
"""
from __future__ import annotations

from typing import Any, Protocol

from . import faults as F
from .faults import Fault, Reaction
from .jobs import Job, JobState
from .profiles import INF, Planner, PlanningError
from .sync import Coupling


class Modified(Protocol):
    """What the modifiers use of the follower component."""

    host: Any                                  # the following axis (see follower.FollowerHost)
    coupling: Coupling | None
    waiting: Coupling | None
    phasing_job: Job | None
    lv_additive: tuple[float, float, float] | None
    lv_additive_job: Job | None
    sim_job: Job | None

    def coupled_state_at(self, t: float) -> tuple[float, float, float]: ...
    def watch_sw_limits(self) -> None: ...


# --- phasing (MC_PhasingRelative / -Absolute, §4.5) ---------------------------------------------------
def start_phasing(f: Modified, job: Job, t: float) -> None:
    c = f.coupling
    assert c is not None
    axis = f.host
    now_p, now_v, now_a = c.phase.at(t) if c.phase is not None else (0.0, 0.0, 0.0)
    target = job.extra["shift"] if job.extra.get("absolute") else now_p + job.extra["shift"]
    job.extra["phase_start"] = now_p
    scale = max(abs(c.ratio), 1e-12)     # the dynamics are those of the following axis (§9.1.3)
    jerk = job.jerk if job.jerk is not None else INF
    try:
        prof = axis.motion.planner.free(t, now_p, now_v, now_a, target_p=target, vmin=-job.velocity / scale,
                                        vmax=job.velocity / scale, amin=-job.deceleration / scale,
                                        amax=job.acceleration / scale, jerk=jerk / scale)
    except PlanningError as exc:
        axis.raise_alarm(F.alarm(F.INTERNAL, "planning", Reaction.EMERGENCY, str(exc)), job=job)
        return
    if f.phasing_job is not None and f.phasing_job.busy:
        axis._finish_job(f.phasing_job, JobState.ABORTED, t)
    f.phasing_job = job
    c.phase = prof
    c.phase_seg = 0
    phase_segment(f, c, t)


def phase_segment(f: Modified, c: Coupling, t: float) -> None:
    """The phase shift's profile enters its segment at ``t``: the sync stage takes it, the axis's
    "phase" timer waits for the next one; at the end the phasing job is done."""
    axis = f.host
    prof = c.phase
    while prof.end_of(c.phase_seg) <= t + 1e-9:
        c.phase_seg += 1
    lv = axis.ctl.sync.level_of(c)
    if lv is not None:
        lv.set_phase(c)
    else:
        axis.ctl.sync.changed()
    nxt = prof.end_of(c.phase_seg)
    if nxt < INF:
        axis._timers["phase"] = nxt
    else:
        axis._timers.pop("phase", None)
        job = f.phasing_job
        if job is not None and job.busy:
            axis._finish_job(job, JobState.DONE, t)
    axis._schedule()


def hold_phase(f: Modified, t: float) -> None:
    """An aborted phasing keeps the phase shift reached so far."""
    c = f.coupling
    if c is not None and c.phase is not None:
        p = c.phase.at(t)[0]
        c.phase = Planner.hold(t, p)
        c.phase_seg = 0
        phase_segment(f, c, t)


def covered_phase_shift(f: Modified, job: Job) -> float:
    c = f.coupling
    if c is None or c.phase is None:
        return job.extra.get("covered", 0.0)
    return c.phase.at(f.host.now)[0] - job.extra.get("phase_start", 0.0)


# --- additive leading value (MC_LeadingValueAdditive, §3.5) ---------------------------------------
def set_lv_additive(f: Modified, job: Job, p: float, v: float, a: float) -> Fault | None:
    """Apply an additive leading value (each call while Enable is TRUE)."""
    axis = f.host
    if job is not f.lv_additive_job:
        if axis.ctl.mode != "RUN":
            return F.reject(F.REJECTED, "starting_up")
        if axis.state != "enabled" and not (f.sim_job is not None and f.sim_job.busy):
            return F.reject(F.NOT_ENABLED)
        old = f.lv_additive_job
        if old is not None and old.busy:
            axis._finish_job(old, JobState.ABORTED, axis.now)
        f.lv_additive_job = job
    f.lv_additive = (p, v, a)
    push_additive(f)
    return None


def end_lv_additive(f: Modified, job: Job) -> None:
    if job is f.lv_additive_job:
        f.lv_additive_job = None
        f.lv_additive = None
        push_additive(f)
        if job.busy:
            f.host._finish_job(job, JobState.DONE, f.host.now)


def push_additive(f: Modified) -> None:
    """Hand the additive value to the compiled couplings of the sync stage."""
    sync = f.host.ctl.sync
    for c in (f.coupling, f.waiting):
        if c is None:
            continue
        lv = sync.level_of(c)
        if lv is not None:
            lv.set_additive(c)
        else:
            sync.changed()


# --- simulation of synchronous operation (MC_SynchronizedMotionSimulation, §3.4) -----------------
def start_simulation(f: Modified, job: Job) -> Fault | None:
    axis = f.host
    if not axis.ctl.offers_job(job.kind):
        return F.reject(F.NOT_AVAILABLE, "simulation")
    c = f.coupling
    if c is None or not c.job.in_sync:
        return F.reject(F.NOT_SYNCHRONOUS, "simulation")
    t = axis.now
    p, v, a = f.coupled_state_at(t)
    sp, _, _ = axis.sup_state_at(t)
    c.simulated = True
    f.watch_sw_limits()
    axis.ctl.sync.changed()
    f.sim_job = job
    # the setpoint from the synchronous operation stands still; superimposed motion goes on
    axis._start_profile(Planner.hold(t, p - sp))
    return None


def end_simulation(f: Modified, job: Job) -> None:
    if job is not f.sim_job:
        return
    axis = f.host
    t = axis.now
    f.sim_job = None
    if job.busy:
        axis._finish_job(job, JobState.DONE, t)
    c = f.coupling
    if c is None:
        return
    running = axis.job
    if running is not None and running.busy:
        axis._finish_job(running, JobState.ABORTED, t)
    c.simulated = False
    f.watch_sw_limits()
    axis.ctl.sync.changed()
    if axis.state in ("enabled", "disabling"):
        axis._set_position_control(True)
    # the synchronous setpoints act at once, without a new synchronization (§9.1.6)
    axis._start_profile(Planner.hold(t, 0.0))
