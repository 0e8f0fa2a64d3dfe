"""Turning a job into a profile: targets, dynamics, permitted direction and software limit switches.

Everything here runs when a job starts or has to be re-planned (parameter change, homing shifts the
coordinates), never per cycle.
"""
from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from .blending import blend_profile
from .jobs import Job, JobKind
from .profiles import INF, Limits, Planner, PlanningError, Profile, ReversalRequired, first_time_at_velocity

if TYPE_CHECKING:  # pragma: no cover
    from .protocols import PlannedAxis as PositioningAxis

_TOL = 1e-9
SHORT_POSITIONING = 0.002       # s, PTO positioning duration below which the velocity is reduced (§12.5)


@dataclass
class Plan:
    profile: Profile
    limit_side: str | None = None        # "min" | "max" when the motion ends at a SW limit switch
    limit_detail: str = ""               # reached | reached_emergency | exceeded
    cross_time: float | None = None      # exceeded: when the setpoint passes the limit
    reach_time: float | None = None      # velocity jobs: when the commanded velocity is reached
    override_hold: bool = False          # velocity override 0 %: the positioning waits at standstill
    stop: tuple[bool, bool] | None = None  # an internal stop: its (emergency, jerk), kept by a re-plan


class DirectionFault(Exception):
    def __init__(self, detail: str):
        super().__init__(detail)
        self.detail = detail


def jerk_limit(axis: "PositioningAxis") -> float:
    """Jerk used for planning, INF when the jerk limit is disabled (the configuration says which)."""
    return axis.config.defaults.jerk


def limits(axis: "PositioningAxis", velocity: float | None = None, *, emergency: bool = False,
           jerk: bool = True, job: Job | None = None) -> Limits:
    """Dynamics a motion of ``axis`` is planned with.

    ``velocity``: the commanded speed (None: the maximum velocity).  ``job``: a job with dynamics of its
    own (S7-1500 instructions give Acceleration, Deceleration and Jerk per job); without them the axis's
    dynamic defaults apply.  Values above the axis's own dynamic limits (``DynamicLimits.velocity``,
    ``max_acceleration``, ``max_deceleration``, ``max_jerk``, where it has them: the S7-1500) are limited
    and named in ``Limits.limited``.
    """
    c = axis.config
    dl, dd = c.limits, c.defaults
    limited: list[str] = []
    vmax = dl.max_velocity
    vcur = dl.velocity
    if vcur is not None:
        vmax = min(vmax, vcur)
    if velocity is None:
        v = vmax
    else:
        v = abs(velocity)
        if v > vmax * (1 + 1e-12):
            v = vmax
            if vcur is not None:
                limited.append("velocity")
    acc = dd.acceleration if job is None or job.acceleration is None else job.acceleration
    if emergency:
        dec = dd.emergency_deceleration
    else:
        dec = dd.deceleration if job is None or job.deceleration is None else job.deceleration
    j = dd.jerk if job is None or job.jerk is None else job.jerk
    ov = getattr(dd, "acceleration_override", None)   # stand-in configurations of tests may lack it
    if ov is not None and not emergency:        # an acceleration override scales both, within the limits
        acc *= ov / 100.0
        dec *= ov / 100.0
    amax_lim, dmax_lim = dl.max_acceleration, dl.max_deceleration
    if amax_lim is not None and acc > amax_lim * (1 + 1e-12):
        acc = amax_lim
        limited.append("acceleration")
    if dmax_lim is not None and not emergency and dec > dmax_lim * (1 + 1e-12):
        dec = dmax_lim
        limited.append("deceleration")
    jmax_lim = dl.max_jerk
    if jmax_lim and j != INF and j > jmax_lim * (1 + 1e-12):
        j = jmax_lim
        limited.append("jerk")
    return Limits(velocity=v, acceleration=acc, deceleration=dec, jerk=j if jerk else INF,
                  start_stop=dl.start_stop_velocity if axis.pto else 0.0, limited=tuple(limited),
                  max_velocity=vmax)


def _strict(lim: Limits, on: bool, reach: tuple[float, float] | None = None) -> Limits:
    return dataclasses.replace(lim, strict=True, reach=reach) if on else lim


def max_dynamics(axis: "PositioningAxis") -> Limits:
    """Stop with the maximum dynamic values (S7-1500: MaxDeceleration and MaxJerk)."""
    dl, dd = axis.config.limits, axis.config.defaults
    dec = dd.deceleration if dl.max_deceleration is None else dl.max_deceleration
    acc = dd.acceleration if dl.max_acceleration is None else dl.max_acceleration
    j = dl.max_jerk or INF
    return Limits(velocity=dl.max_velocity, acceleration=acc, deceleration=dec, jerk=j)


def wrap(value: float, start: float, length: float) -> float:
    """Value in the modulo range [start, start + length)."""
    r = math.fmod(value - start, length)
    if r < 0:
        r += length
    if r >= length:  # fmod rounding at the upper edge
        r = 0.0
    return start + r


def modulo_target(axis: "PositioningAxis", position: float, direction: int, velocity_sign: float,
                  p: float, v: float, a: float, lim: Limits, planner: Planner) -> float:
    """Unwrapped target of MC_MoveAbsolute on a modulo axis (S7-1200 V6 §11.1.5, §5.4.4.2).

    ``direction``: 0 sign of the velocity, 1 positive, 2 negative, 3 shortest distance.  While the axis
    already moves in the requested direction the target is never placed behind its stop point, so that
    it is approached without reversing.
    """
    start, length = axis.config.modulo.start, axis.config.modulo.length
    goal = wrap(position, start, length)
    here = wrap(p, start, length)
    ahead = math.fmod(goal - here, length)
    if ahead < 0:
        ahead += length
    if direction == 0:
        direction = 1 if velocity_sign >= 0 else 2
    if direction == 1:
        d = ahead
        if v > 0:
            ref = planner.stop_position(p, v, a, lim)
            while p + d < ref - _TOL:
                d += length
        return p + d
    if direction == 2:
        d = -math.fmod(length - ahead, length) if ahead else 0.0
        if v < 0:
            ref = planner.stop_position(p, v, a, lim)
            while p + d > ref + _TOL:
                d -= length
        return p + d
    return p + (ahead if ahead <= length / 2 else ahead - length)


def _extremes(profile: Profile) -> tuple[float, float]:
    ps = [s.p for s in profile.segments]
    return min(ps), max(ps)


class MotionPlanner:
    """Plans the jobs of one axis."""

    def __init__(self, axis: "PositioningAxis"):
        self.axis = axis
        self.planner = Planner()
        self.last_limits: Limits | None = None     # dynamics of the last job plan (limited values)

    # --- direction permitted to a stepper (PulseOutput.direction_mode, S7-1200 V6 §5.4.4.1) -------------
    def _permitted(self, sign: float) -> bool:
        mode = self.axis.config.pulse_output.direction_mode if self.axis.pto else 0
        return mode == 0 or (mode == 1 and sign > 0) or (mode == 2 and sign < 0)

    def _check_direction(self, profile: Profile, p: float) -> None:
        lo, hi = _extremes(profile)
        going_up = hi > p + _TOL or profile.final.v > 0
        going_down = lo < p - _TOL or profile.final.v < 0
        if going_up and not self._permitted(1.0) or going_down and not self._permitted(-1.0):
            if going_up and going_down:
                raise DirectionFault("reversal")
            raise DirectionFault("not_permitted")

    # --- job plans --------------------------------------------------------------------------------------
    def plan(self, job: Job, t: float, p: float, v: float, a: float, *, replan: bool = False,
             reach: tuple[float, float] | None = None) -> Plan:
        """Plan ``job`` from the state (p, v, a) at ``t``; ``replan``: the running job anew with changed
        dynamics (S7-1200 V6 §12.9.11 code 10), which must not leave the job's velocity bounds either --
        beyond the velocities ``reach`` the running plan passes through anyway (see ``Limits.reach``)."""
        ax = self.axis
        kind = job.kind
        pl = self.planner
        if kind in (JobKind.ABSOLUTE, JobKind.RELATIVE):
            lim = _strict(limits(ax, ax.commanded_velocity(job.velocity), job=job), replan, reach)
            self.last_limits = lim
            target = job.target
            if lim.velocity <= 0.0:                  # velocity override 0 %: wait at standstill
                return Plan(pl.stop(t, p, v, a, lim), override_hold=True)
            blend = job.extra.get("blend_speed", 0.0)     # passes the target into a queued job (job_queue)
            reverse = self._permitted(-1) and self._permitted(1)
            try:
                if blend:
                    profile = blend_profile(pl, t, p, v, a, target, lim, blend, allow_reverse=reverse)
                else:
                    profile = pl.position(t, p, v, a, target, lim, allow_reverse=reverse,
                                          end_velocity=job.extra.get("end_velocity", 0.0))
            except ReversalRequired:
                raise DirectionFault("reversal") from None
            self._check_direction(profile, p)
            if ax.pto and profile.duration < SHORT_POSITIONING and abs(v) <= 1e-12 and target != p and not blend:
                # §12.5: a positioning shorter than 2 ms runs at pulses x 500 Hz, i.e. takes 2 ms
                profile = Planner.constant_move(t, p, target, SHORT_POSITIONING)
            return self._guard(Plan(profile), t, p, v, a, lim, cruise=abs(job.velocity), passes_on=bool(blend),
                               job=job)
        if kind in (JobKind.VELOCITY, JobKind.JOG):
            target_v = 0.0 if job.jog_released else ax.commanded_velocity(job.velocity)
            lim = _strict(limits(ax, None, job=job), replan, reach)
            self.last_limits = lim
            if abs(target_v) > lim.velocity:
                target_v = math.copysign(lim.velocity, target_v)
            profile = pl.velocity(t, p, v, a, target_v, lim)
            if target_v != 0.0:
                self._check_direction(profile, p)
            plan = self._guard(Plan(profile, reach_time=profile.t_end), t, p, v, a, lim, cruise=abs(target_v),
                               job=job)
            return plan
        if kind in (JobKind.HALT, JobKind.STOP):
            lim = _strict(max_dynamics(ax) if job.extra.get("max_dynamics") else limits(ax, None, job=job), replan, reach)
            self.last_limits = lim
            return self._guard(Plan(pl.stop(t, p, v, a, lim)), t, p, v, a, lim, cruise=abs(v), job=job)
        raise ValueError(f"no motion plan for {kind}")

    def stop(self, t: float, p: float, v: float, a: float, *, emergency: bool, jerk: bool) -> Plan:
        """Internal stop (error reaction, disabling)."""
        ax = self.axis
        if emergency and not jerk:
            dec = ax.config.defaults.emergency_deceleration
            vss = ax.config.limits.start_stop_velocity if ax.pto else 0.0
            profile = _ramp_stop(t, p, v, dec, vss)
            lim = limits(ax, None, emergency=True, jerk=False)
        else:
            lim = limits(ax, None, emergency=emergency, jerk=jerk)
            profile = self.stop_with(t, p, v, a, lim)
        try:
            plan = self._guard(Plan(profile), t, p, v, a, lim, cruise=abs(v))
        except (PlanningError, DirectionFault):
            plan = Plan(profile)
        plan.stop = (emergency, jerk)
        return plan

    def guard_stop(self, t: float, p: float, v: float, a: float, profile: Profile) -> Plan:
        """A stop with a ramp of its own (a family's stop program: a stop time, the maximum dynamics) kept
        inside the active software limit switches like any motion: where it would pass one it ends there,
        braking with the configured deceleration or, where that is too late, the emergency deceleration."""
        lim = limits(self.axis, None, emergency=True, jerk=False)
        try:
            return self._guard(Plan(profile), t, p, v, a, lim, cruise=abs(v))
        except (PlanningError, DirectionFault):
            return Plan(profile)

    def stop_with(self, t: float, p: float, v: float, a: float, lim: Limits) -> Profile:
        """A stop with the dynamics ``lim`` that always gives a profile: where even the closed-form
        fallback of the planner fails, the emergency ramp without jerk (§12.8) stops the axis."""
        try:
            return self.planner.stop(t, p, v, a, lim)
        except PlanningError:
            return _ramp_stop(t, p, v, self.axis.config.defaults.emergency_deceleration, lim.start_stop)

    def ramp_out(self, t: float, p: float, v: float, duration: float) -> Plan:
        """Linear velocity ramp to zero in ``duration`` (PTO immediate stop, §11.1.1)."""
        if abs(v) <= 1e-12 or duration <= 0:
            return Plan(Planner.hold(t, p))
        return Plan(Planner.ramp_stop(t, p, v, abs(v) / duration))

    # --- software limit switches (§2.3, §5.4.4.3, §12.4) -------------------------------------------
    def _guard(self, plan: Plan, t: float, p: float, v: float, a: float, lim: Limits, cruise: float,
               passes_on: bool = False, job: Job | None = None) -> Plan:
        """``passes_on``: the motion beyond the profile's end belongs to the next job, which is guarded
        when it starts; only the way to the target counts here.  ``job``: the motion runs towards the limit
        with the job's own dynamics (S7-1500, S7-Technology), where the job brings them."""
        ax = self.axis
        if not ax.sw_limits_effective():
            return plan
        lo_lim = ax.config.software_limits.minimum
        hi_lim = ax.config.software_limits.maximum
        profile = plan.profile
        # a stop point within half a position increment of the limit counts as at the limit: plans made
        # from different states of the same braking differ in the last digits
        tol = ax.position_resolution() / 2
        side = None
        for seg in profile.segments:          # the limit met first in time decides
            if seg.p > hi_lim + tol:
                side = "max"
                break
            if seg.p < lo_lim - tol:
                side = "min"
                break
        if side is None and profile.final.v == 0.0:
            final = profile.final
            final.p = min(max(final.p, lo_lim), hi_lim)
        if side is None and not passes_on:
            fv = profile.final.v
            side = "max" if fv > 0 else "min" if fv < 0 else None
        if side is None:
            return plan
        sign = 1.0 if side == "max" else -1.0
        limit = hi_lim if side == "max" else lo_lim
        pl = self.planner
        # already at or beyond the limit and the motion heads further
        if (p - limit) * sign > _TOL:
            return Plan(_ramp_stop(t, p, v if v * sign > 0 else 0.0, ax.config.defaults.emergency_deceleration,
                                   lim.start_stop), side, "exceeded", cross_time=t)
        moving_out = v * sign > 1e-12
        if moving_out:
            stop = pl.stop_position(p, v, a, _limit_braking(ax, limits(ax, None, job=job)))
        else:
            stop = p
        if (stop - limit) * sign <= _TOL:
            speed = max(min(cruise, ax.config.limits.max_velocity), lim.start_stop, 1e-12)
            lim2 = _limit_braking(ax, limits(ax, speed, job=job))
            try:
                profile = pl.position(t, p, v, a, limit, lim2)
            except ReversalRequired:  # pragma: no cover - position() reverses when allowed
                raise DirectionFault("reversal") from None
            reach = first_time_at_velocity(profile, sign * speed) if plan.reach_time is not None else None
            return Plan(profile, side, "reached", reach_time=reach)
        # the configured deceleration is not enough any more (§12.4): emergency deceleration without jerk
        emerg = ax.config.defaults.emergency_deceleration
        need = v * v / (2 * emerg)
        if need <= abs(limit - p) + _TOL:
            return Plan(Planner.ramp_stop_at(t, p, v, emerg, limit), side, "reached_emergency")
        profile = _ramp_stop(t, p, v, emerg, lim.start_stop)
        # time at which the setpoint passes the limit: p + v*tau - sign*emerg*tau^2/2 = limit
        d = abs(limit - p)
        disc = v * v - 2 * emerg * d
        tau = (abs(v) - math.sqrt(max(disc, 0.0))) / emerg
        return Plan(profile, side, "exceeded", cross_time=t + tau)


def _limit_braking(axis: "PositioningAxis", lim: Limits) -> Limits:
    """The dynamics of a motion that comes to a stop at a software limit switch.  An axis whose
    ``sw_limit_max_deceleration`` is set brakes there with its maximum deceleration (the alarm's reaction
    "stop with the maximum dynamic values"); the motion up to the braking keeps the job's dynamics."""
    if not getattr(axis, "sw_limit_max_deceleration", False):
        return lim
    dec = max_dynamics(axis).deceleration
    return dataclasses.replace(lim, deceleration=dec) if dec > lim.deceleration else lim


def _ramp_stop(t: float, p: float, v: float, dec: float, vss: float) -> Profile:
    """Emergency ramp without jerk; a stepper ramps to its start/stop velocity and then stops."""
    if vss and abs(v) > vss:
        prof = Planner.ramp_stop(t, p, v, dec)
        # stop at the start/stop velocity instead of zero
        seg = prof.segments[0]
        dur = (abs(v) - vss) / dec
        end_p = seg.p + v * dur + seg.a * dur * dur / 2
        prof.segments[-1].t = t + dur
        prof.segments[-1].p = end_p
        prof.t_end = t + dur
        prof.milestones["reached"] = t + dur
        return prof
    if vss:
        return Planner.hold(t, p)
    return Planner.ramp_stop(t, p, v, dec)
