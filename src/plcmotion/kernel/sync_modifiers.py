"""What modifies a running synchronous operation of a following axis (S7-1500T V5): the leading value
shift of a gearing (MC_PhasingRelative/-Absolute, §4.5), the additive leading value
(MC_LeadingValueAdditive, §3.5) and the simulation of synchronous operation
(MC_SynchronizedMotionSimulation, §3.4)."""
from __future__ import annotations

from typing import TYPE_CHECKING

from . import faults as F
from .faults import Fault, Reaction
from .jobs import Job, JobState
from .profiles import INF, Planner, PlanningError
from .sync import Coupling

if TYPE_CHECKING:  # pragma: no cover
    from .axis import PositioningAxis as Axis


class SyncModifiersMixin:
    """Phasing, additive leading value and simulation of the synchronous axis's coupling."""

    # --- phasing (MC_PhasingRelative / -Absolute, §4.5) ---------------------------------------------------
    def _start_phasing(self: "Axis", job: Job, t: float) -> None:
        c = self.coupling
        assert c is not None
        now_p, now_v, now_a = c.phase.at(t) if c.phase is not None else (0.0, 0.0, 0.0)
        target = job.extra["shift"] if job.extra.get("absolute") else now_p + job.extra["shift"]
        job.extra["phase_start"] = now_p
        scale = max(abs(c.ratio), 1e-12)     # the dynamics are those of the following axis (§9.1.3)
        jerk = job.jerk if job.jerk is not None else INF
        try:
            prof = self.motion.planner.free(t, now_p, now_v, now_a, target_p=target, vmin=-job.velocity / scale,
                                            vmax=job.velocity / scale, amin=-job.deceleration / scale,
                                            amax=job.acceleration / scale, jerk=jerk / scale)
        except PlanningError as exc:
            self.raise_alarm(F.alarm(F.INTERNAL, "planning", Reaction.EMERGENCY, str(exc)), job=job)
            return
        if self.phasing_job is not None and self.phasing_job.busy:
            self._finish_job(self.phasing_job, JobState.ABORTED, t)
        self.phasing_job = job
        c.phase = prof
        c.phase_seg = 0
        self._phase_segment(c, t)

    def _phase_segment(self: "Axis", c: Coupling, t: float) -> None:
        prof = c.phase
        while prof.end_of(c.phase_seg) <= t + 1e-9:
            c.phase_seg += 1
        lv = self.ctl.sync.level_of(c)
        if lv is not None:
            lv.set_phase(c)
        else:
            self.ctl.sync.changed()
        nxt = prof.end_of(c.phase_seg)
        if nxt < INF:
            self._timers["phase"] = nxt
        else:
            self._timers.pop("phase", None)
            job = self.phasing_job
            if job is not None and job.busy:
                self._finish_job(job, JobState.DONE, t)
        self._schedule()

    def covered_phase_shift(self: "Axis", job: Job) -> float:
        c = self.coupling
        if c is None or c.phase is None:
            return job.extra.get("covered", 0.0)
        return c.phase.at(self.now)[0] - job.extra.get("phase_start", 0.0)

    # --- additive leading value (MC_LeadingValueAdditive, §3.5) ---------------------------------------
    def set_lv_additive(self: "Axis", job: Job, p: float, v: float, a: float) -> Fault | None:
        """Apply an additive leading value (each call while Enable is TRUE)."""
        if job is not self.lv_additive_job:
            if self.ctl.mode != "RUN":
                return F.reject(F.REJECTED, "starting_up")
            if self.state != "enabled" and not (self.sim_job is not None and self.sim_job.busy):
                return F.reject(F.NOT_ENABLED)
            old = self.lv_additive_job
            if old is not None and old.busy:
                self._finish_job(old, JobState.ABORTED, self.now)
            self.lv_additive_job = job
        self.lv_additive = (p, v, a)
        self._push_additive()
        return None

    def end_lv_additive(self: "Axis", job: Job) -> None:
        if job is self.lv_additive_job:
            self.lv_additive_job = None
            self.lv_additive = None
            self._push_additive()
            if job.busy:
                self._finish_job(job, JobState.DONE, self.now)

    def _push_additive(self: "Axis") -> None:
        for c in (self.coupling, self.waiting):
            if c is None:
                continue
            lv = self.ctl.sync.level_of(c)
            if lv is not None:
                lv.set_additive(c)
            else:
                self.ctl.sync.changed()

    # --- simulation of synchronous operation (MC_SynchronizedMotionSimulation, §3.4) -----------------
    def start_simulation(self: "Axis", job: Job) -> Fault | None:
        if not self.ctl.offers_job(job.kind):
            return F.reject(F.NOT_AVAILABLE, "simulation")
        c = self.coupling
        if c is None or not c.job.in_sync:
            return F.reject(F.NOT_SYNCHRONOUS, "simulation")
        t = self.now
        p, v, a = self._coupled_state_at(t)
        sp, _, _ = self.sup_state_at(t)
        c.simulated = True
        self._watch_sw_limits()
        self.ctl.sync.changed()
        self.sim_job = job
        # the setpoint from the synchronous operation stands still; superimposed motion goes on
        self._start_profile(Planner.hold(t, p - sp))
        return None

    def end_simulation(self: "Axis", job: Job) -> None:
        if job is not self.sim_job:
            return
        t = self.now
        self.sim_job = None
        if job.busy:
            self._finish_job(job, JobState.DONE, t)
        c = self.coupling
        if c is None:
            return
        running = self.job
        if running is not None and running.busy:
            self._finish_job(running, JobState.ABORTED, t)
        c.simulated = False
        self._watch_sw_limits()
        self.ctl.sync.changed()
        if self.state in ("enabled", "disabling"):
            self._set_position_control(True)
        # the synchronous setpoints act at once, without a new synchronization (§9.1.6)
        self._start_profile(Planner.hold(t, 0.0))
