"""Motion profiles: planned once per command or parameter change, evaluated every servo cycle.

This module plans; the profile it gives (segments and their evaluation) is in :mod:`.profile_curve`.

A profile is a list of segments of constant jerk (piecewise cubic position).  Jerk-limited segments come
from ruckig's time-optimal solution from the current position, velocity and acceleration; with the jerk
limit disabled ruckig is asked for the acceleration-limited (trapezoidal) solution (``max_jerk = inf``).

Acceleration and deceleration limits of a PLC axis refer to the magnitude of the velocity (speeding up /
slowing down), not to the sign of the acceleration.  ruckig has one signed pair of limits, so a motion that
changes direction is planned in two stages: brake to standstill with the deceleration, then travel the rest
in the other direction with the acceleration.  Within one direction the signed limits map exactly.

Stepper (PTO) profiles start and end with a velocity step between 0 and the start/stop velocity
(S7-1200 V6 §5.4.4.4, §12.6): the ramp is planned from and to the start/stop velocity.

Re-planning from a moving state with new dynamics (S7-1200 V6 §11.1.10, §12.9.11 effective code 10: a
changed Acceleration/Jerk acts from the next servo cycle) can start with an acceleration that the new
jerk cannot take back in time: reducing 500 mm/s² with a jerk of 40 mm/s³ takes 12.5 s, during which
the velocity runs far past every limit (ruckig's brake pre-trajectory only respects the jerk).  Such a
start state is first *settled*: the acceleration is brought to zero with the smallest jerk that keeps the
velocity within the job's bounds (at least the configured jerk; an acceleration step when even that is
too late).  A state the new jerk can absorb within the velocity limit is planned unchanged.  When ruckig
gives up numerically, closed-form jerk-limited ramps take over, so that planning always gives a profile.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import ruckig

from .profile_curve import INF, Profile, Segment, first_time_at_velocity, velocity_reach  # noqa: F401 (re-exported)
from .profile_fallback import closed_form

_EPS_V = 1e-9


class PlanningError(RuntimeError):
    """The trajectory generator could not produce a profile for the requested motion."""


@dataclass(slots=True)
class Limits:
    """Dynamics a motion is planned with (user units)."""

    velocity: float
    acceleration: float
    deceleration: float
    jerk: float = INF               # INF: jerk limit disabled (trapezoid)
    start_stop: float = 0.0         # PTO start/stop velocity
    limited: tuple[str, ...] = ()   # commanded values cut to the dynamic limits (S7-1500 alarms 501-504)
    max_velocity: float = 0.0       # velocity limit of the axis (0: ``velocity``), never to be exceeded
    strict: bool = False            # re-plan of a running job: its own velocity bounds are hard too
    reach: tuple[float, float] | None = None   # re-plan: (lowest, highest) velocity the running plan still
                                               # passes through; the new plan may use that range too

    @property
    def hard_velocity(self) -> float:
        return self.max_velocity or self.velocity


class _Builder:
    """Collects segments back to back starting at ``t``."""

    def __init__(self, t: float, p: float, v: float, a: float):
        self.t, self.p, self.v, self.a = t, p, v, a
        self.segments: list[Segment] = []

    def add(self, duration: float, p: float, v: float, a: float, j: float) -> None:
        if duration <= 0.0:
            return
        self.segments.append(Segment(self.t, p, v, a, j))
        self.t += duration
        tau = duration
        self.p = p + tau * (v + tau * (a / 2 + tau * j / 6))
        self.v = v + tau * (a + tau * j / 2)
        self.a = a + tau * j

    def jump(self, v: float) -> None:
        """Velocity step (stepper start/stop velocity); takes no time."""
        self.v, self.a = v, 0.0

    def finish(self, p: float, v: float, milestones: dict[str, float] | None = None) -> Profile:
        t_end = self.t
        self.segments.append(Segment(t_end, p, v, 0.0, 0.0))
        return Profile(self.segments, t_end, milestones or {})


class Planner:
    """Reusable ruckig instance (one degree of freedom)."""

    def __init__(self) -> None:
        self._otg = ruckig.Ruckig(1)
        self._inp = ruckig.InputParameter(1)
        self._traj = ruckig.Trajectory(1)

    # --- ruckig -------------------------------------------------------------------------------------
    def _solve(self, b: _Builder, *, target_p: float | None, target_v: float, vmax: float,
               amax: float, amin: float, jerk: float) -> None:
        """Append the time-optimal segments from the builder's state to the target."""
        if jerk == INF:
            if target_p is None:
                self._ramp(b, target_v, amax, amin)
            else:
                self._trapezoid(b, target_p, target_v, vmax, amax, amin)
            return
        inp = self._inp
        inp.current_position = [b.p]
        inp.current_velocity = [b.v]
        inp.current_acceleration = [b.a if jerk < INF else 0.0]
        inp.target_velocity = [target_v]
        inp.target_acceleration = [0.0]
        inp.max_acceleration = [amax]
        inp.min_acceleration = [amin]
        inp.max_jerk = [jerk]
        if target_p is None:
            inp.control_interface = ruckig.ControlInterface.Velocity
            inp.target_position = [b.p]
            inp.max_velocity = [max(vmax, abs(b.v), abs(target_v))]
        else:
            inp.control_interface = ruckig.ControlInterface.Position
            inp.target_position = [target_p]
            inp.max_velocity = [vmax]
        try:
            result = self._otg.calculate(inp, self._traj)
        except Exception as exc:          # ruckig raises for inputs beyond its numerical range
            result = exc
        if result not in (ruckig.Result.Working, ruckig.Result.Finished):
            if target_p is not None and self._solve_long(b, target_p, target_v, vmax, amax, amin, jerk):
                return
            if not closed_form(b, target_p, target_v, vmax, amax, amin, jerk):
                raise PlanningError(f"ruckig: {result!r} for p={b.p!r} v={b.v!r} a={b.a!r} -> "
                                    f"p={target_p!r} v={target_v!r} (vmax={vmax}, a=[{amin}, {amax}], j={jerk})")
            return
        prof = self._traj.profiles[0][0]
        brake = prof.brake
        if brake.duration > 0.0:
            for i in range(2):
                b.add(brake.t[i], brake.p[i], brake.v[i], brake.a[i], brake.j[i])
        for i in range(7):
            b.add(prof.t[i], prof.p[i], prof.v[i], prof.a[i], prof.j[i])
        post = prof.accel
        if post.duration > 0.0:
            for i in range(2):
                b.add(post.t[i], post.p[i], post.v[i], post.a[i], post.j[i])
        # remove numerical residue at the end of the solution
        if target_p is not None:
            b.p = target_p
        b.v, b.a = target_v, 0.0

    @staticmethod
    def _ramp(b: _Builder, target_v: float, amax: float, amin: float) -> None:
        """Velocity change at constant acceleration (no jerk limit)."""
        dv = target_v - b.v
        if abs(dv) > 0.0:
            a = amax if dv > 0 else amin
            b.add(dv / a, b.p, b.v, a, 0.0)
        b.v, b.a = target_v, 0.0

    @staticmethod
    def _trapezoid(b: _Builder, target_p: float, target_v: float, vmax: float, amax: float, amin: float) -> None:
        """Time-optimal positioning without jerk limit, in closed form.

        Travels in one direction from the builder's state to ``target_p``, arriving with ``target_v``
        (zero, or the start/stop velocity of a stepper): speed change to the peak speed, cruise, brake.
        The caller guarantees that the target is not behind the stop point.
        """
        sign = 1.0 if target_p >= b.p else -1.0
        acc, dec = (amax, -amin) if sign > 0 else (-amin, amax)
        dist = (target_p - b.p) * sign
        u0 = max(b.v * sign, 0.0)
        ue = abs(target_v)
        if u0 > vmax:
            peak = vmax                          # braking to the new limit first never passes the target
        else:
            tri = math.sqrt(max((dist + u0 * u0 / (2 * acc) + ue * ue / (2 * dec)) / (1 / (2 * acc) + 1 / (2 * dec)),
                                0.0))
            peak = max(min(vmax, tri), u0, ue)
        d1 = (peak * peak - u0 * u0) / (2 * acc) if peak >= u0 else (u0 * u0 - peak * peak) / (2 * dec)
        d3 = (peak * peak - ue * ue) / (2 * dec)
        cruise = dist - d1 - d3
        if cruise < -1e-9 * max(1.0, dist) and peak > u0:
            # an acceleration so small that the speed gain lies below the float resolution of the speed (fuzz
            # seed 454750: 1e-300): the rounding of peak**2 - u0**2, divided by it, swamps the distance.  The
            # gain is nil - cruise at the current speed instead of speeding up.
            peak = u0
            d1, d3 = 0.0, (u0 * u0 - ue * ue) / (2 * dec)
            cruise = dist - d3
        if cruise < -1e-9 * max(1.0, dist):
            raise PlanningError(f"trapezoid: target {target_p!r} behind the stop point (p={b.p!r}, v={b.v!r})")
        p, v = b.p, sign * u0
        if peak > u0:
            b.add((peak - u0) / acc, p, v, sign * acc, 0.0)
        elif peak < u0:
            b.add((u0 - peak) / dec, p, v, -sign * dec, 0.0)
        if cruise > 1e-12 * max(1.0, dist) and peak > 0.0:
            b.add(cruise / peak, b.p, sign * peak, 0.0, 0.0)
        if peak > ue:
            b.add((peak - ue) / dec, b.p, sign * peak, -sign * dec, 0.0)
        b.p, b.v, b.a = target_p, target_v, 0.0

    def _solve_long(self, b: _Builder, target_p: float, target_v: float, vmax: float, amax: float, amin: float,
                    jerk: float) -> bool:
        """Long moves beyond ruckig's numerical range: ramp to the maximum velocity, cruise, ramp down.

        Exact whenever the move has a constant-velocity phase, which is always the case for the distances
        where ruckig gives up (about 1e9 times the velocity limit).
        """
        sign = 1.0 if target_p > b.p else -1.0
        up = _Builder(b.t, b.p, b.v, b.a)
        down = _Builder(0.0, 0.0, sign * vmax, 0.0)
        try:
            self._solve(up, target_p=None, target_v=sign * vmax, vmax=vmax, amax=amax, amin=amin, jerk=jerk)
            self._solve(down, target_p=None, target_v=target_v, vmax=vmax, amax=amax, amin=amin, jerk=jerk)
        except PlanningError:
            return False
        cruise = (target_p - up.p - down.p) * sign
        if cruise < 0 or vmax <= 0:
            return False
        for seg in up.segments:
            b.segments.append(seg)
        b.t, b.p, b.v, b.a = up.t, up.p, up.v, up.a
        b.add(cruise / vmax, b.p, sign * vmax, 0.0, 0.0)
        t0, p0 = b.t, b.p
        for seg in down.segments:
            b.segments.append(Segment(t0 + seg.t, p0 + seg.p, seg.v, seg.a, seg.j))
        b.t, b.p, b.v, b.a = t0 + down.t, target_p, target_v, 0.0
        return True

    @staticmethod
    def _signed_limits(direction: float, lim: Limits) -> tuple[float, float]:
        """(max_acc, min_acc) for motion in ``direction``: speeding up uses Acceleration, slowing Deceleration."""
        if direction >= 0:
            return lim.acceleration, -lim.deceleration
        return lim.deceleration, -lim.acceleration

    # --- building blocks ----------------------------------------------------------------------------
    @staticmethod
    def _settle(b: _Builder, lim: Limits, sign: float, lo: float, hi: float) -> None:
        """Take back an acceleration the jerk of ``lim`` cannot absorb within the velocity limits.

        Speeds are counted in direction ``sign``.  Reducing the builder's acceleration to zero with the
        jerk limit ends at speed ``u0``.  The bounds ``u0`` must stay in: standstill (no reversal) and the
        axis's velocity limit; for a re-plan of the running job (``lim.strict``) the job's own bounds
        [``lo``, ``hi``], widened to the speeds the running plan reaches anyway (``lim.reach``, up to the
        velocity limit) -- a re-plan need not be stricter than the plan it replaces, so a state that the
        old plan's overshoot explains keeps the configured jerk.  Within the bounds the state is left to
        ruckig as it is: the overshoot of a new command's velocity that the jerk limit makes unavoidable
        is ordinary.  Otherwise the acceleration is brought to zero with the smallest jerk (at least the
        configured one) that just ends on the violated bound (``hi`` for a positioning's search, see
        ``_settle_before``), or stepped to zero when the speed is already there.
        """
        jerk = lim.jerk
        alpha = sign * b.a
        if jerk == INF or abs(alpha) <= 1e-12:
            return
        u = sign * b.v
        hard_v = lim.hard_velocity
        if lim.strict:
            r_lo, r_hi = lim.reach if lim.reach is not None else (b.v, b.v)
            s_lo, s_hi = (r_lo, r_hi) if sign > 0 else (-r_hi, -r_lo)
            top = max(hi, u, min(s_hi, hard_v))
            floor = min(lo, u, max(s_lo, 0.0))
            end_top = top
        else:
            top, floor = max(hard_v, u), 0.0
            end_top = max(min(hi, hard_v), u)
        u0 = u + alpha * abs(alpha) / (2.0 * jerk)
        tol = 1e-9 * max(1.0, top)
        if floor - tol <= u0 <= top + tol:
            return
        bound = end_top if alpha > 0 else floor
        room = abs(bound - u)
        if room > 1e-12 * max(1.0, top):
            j2 = max(jerk, alpha * alpha / (2.0 * room))
            b.add(abs(alpha) / j2, b.p, b.v, b.a, -math.copysign(j2, b.a))
            b.v = sign * bound
        b.a = 0.0

    def _settle_before(self, b: _Builder, lim: Limits, sign: float, target: float) -> None:
        """Settle (see ``_settle``) for a positioning: at most to the job's velocity, and only as fast as
        still lets the new dynamics stop before ``target`` (found by bisection; the stop point moves
        out with the speed the settling ends at)."""
        def settled(hi: float) -> _Builder:
            c = _Builder(b.t, b.p, b.v, b.a)
            self._settle(c, lim, sign, 0.0, hi)
            return c

        def short(c: _Builder) -> bool:
            return (target - self.stop_position(c.p, c.v, c.a, lim)) * sign >= -1e-12 * max(1.0, abs(target))

        top = lim.velocity if lim.strict else lim.hard_velocity
        c = settled(top)
        if c.a == b.a:
            return                                   # the new jerk absorbs the acceleration
        u = sign * b.v
        if top > u and not short(c):
            lo, hi = u, top
            for _ in range(60):
                mid = 0.5 * (lo + hi)
                if short(settled(mid)):
                    lo = mid
                else:
                    hi = mid
                if hi - lo <= 1e-9 * max(1.0, hi):
                    break
            c = settled(lo)
        b.segments.extend(c.segments)
        b.t, b.p, b.v, b.a = c.t, c.p, c.v, c.a

    def _brake_to_standstill(self, b: _Builder, lim: Limits) -> None:
        """Slow down to zero velocity (stepper: to the start/stop velocity, then step to zero)."""
        vss = lim.start_stop
        still = abs(b.v) <= max(_EPS_V, vss)
        if still and (lim.jerk == INF or abs(b.a) <= 1e-12 or vss):
            b.jump(0.0)
            return
        sign = math.copysign(1.0, b.v if abs(b.v) > _EPS_V else b.a)
        self._settle(b, lim, sign, 0.0, abs(b.v))          # a stop never speeds up to settle
        if abs(b.v) <= max(_EPS_V, vss) and abs(b.a) <= 1e-12:
            b.jump(0.0)
            return
        amax, amin = self._signed_limits(sign, lim)
        self._solve(b, target_p=None, target_v=sign * vss if abs(b.v) > vss else 0.0, vmax=abs(b.v),
                    amax=amax, amin=amin, jerk=lim.jerk)
        b.jump(0.0)

    def stop_position(self, p: float, v: float, a: float, lim: Limits) -> float:
        """Where the axis comes to rest when it starts braking now."""
        b = _Builder(0.0, p, v, a)
        self._brake_to_standstill(b, lim)
        return b.p

    # --- public plans -------------------------------------------------------------------------------
    def position(self, t: float, p: float, v: float, a: float, target: float, lim: Limits,
                 *, allow_reverse: bool = True, end_velocity: float = 0.0) -> Profile:
        """Time-optimal move to ``target`` with standstill there.

        ``end_velocity`` (blending, e.g. the command table's "Blend motion"): arrive at the target with
        this speed in the direction of travel and keep it; 0 stops there.
        Raises ``ReversalRequired`` when the motion would have to change direction and
        ``allow_reverse`` is False (permitted-direction check of §5.4.4.1).
        """
        b = _Builder(t, p, v, a)
        vss = lim.start_stop
        if vss and abs(v) <= vss * (1 + 1e-9):
            b.jump(0.0)                     # a stepper at its start/stop velocity stops at once
        if lim.jerk < INF and abs(b.a) > 1e-12:
            way = b.v if abs(b.v) > _EPS_V else target - b.p
            self._settle_before(b, lim, 1.0 if way >= 0 else -1.0, target)
        moving = abs(b.v) > _EPS_V or (lim.jerk < INF and abs(b.a) > 1e-12)
        if moving:
            sign = math.copysign(1.0, b.v if abs(b.v) > _EPS_V else b.a)
            stop = self.stop_position(b.p, b.v, b.a, lim)
            if (target - stop) * sign < -1e-9:          # target lies behind the stop point: reverse
                if not allow_reverse:
                    raise ReversalRequired()
                self._brake_to_standstill(b, lim)
                moving = False
        if not moving:
            b.a = 0.0 if abs(b.v) <= _EPS_V else b.a
            if abs(target - b.p) <= 1e-12:
                b.jump(0.0)
                return b.finish(target, 0.0)
            sign = 1.0 if target > b.p else -1.0
            if vss:
                b.jump(sign * vss)
        else:
            sign = math.copysign(1.0, b.v if abs(b.v) > _EPS_V else b.a)
        blend = abs(end_velocity)
        if blend > 0.0:
            blend = max(min(blend, max(lim.velocity, lim.start_stop)), lim.start_stop)
            self._approach(b, target, sign, lim, sign * blend)
            return b.finish(target, sign * blend)
        self._approach(b, target, sign, lim)
        return b.finish(target, 0.0)

    def _approach(self, b: _Builder, target: float, sign: float, lim: Limits,
                  v_final: float | None = None) -> None:
        """Final stage of a positioning: travel in direction ``sign`` and stop at ``target``.

        When the axis is faster than the new velocity limit and close to the target, slowing down to the
        limit first would carry it past the target; then the lowest velocity limit that still arrives
        without passing the target is used (found by bisection, the profile family is monotonic in it).
        The same search keeps a stepper from dropping below its start/stop velocity before the end.
        """
        amax, amin = self._signed_limits(sign, lim)
        v_end = sign * lim.start_stop if v_final is None else v_final
        vmax = max(lim.velocity, lim.start_stop, abs(v_end))
        state = (b.t, b.p, b.v, b.a, len(b.segments))

        def attempt(limit: float) -> bool:
            b.t, b.p, b.v, b.a = state[:4]
            del b.segments[state[4]:]
            self._solve(b, target_p=target, target_v=v_end, vmax=limit, amax=amax, amin=amin, jerk=lim.jerk)
            return self._passes(b.segments[state[4]:], b.t, target, sign, min(lim.start_stop, abs(v_end)))

        if not attempt(vmax):
            return
        lo, hi = vmax, max(vmax, abs(state[2])) * (1 + 1e-9) + 1e-9
        if attempt(hi):
            # the target is (numerically) at the stop point: brake to standstill, which ends at or before
            # the target, and creep the rest of the way from standstill
            b.t, b.p, b.v, b.a = state[:4]
            del b.segments[state[4]:]
            self._brake_to_standstill(b, lim)
            if (target - b.p) * sign > 1e-12 * max(1.0, abs(target)):
                if lim.start_stop:
                    b.jump(sign * lim.start_stop)
                self._solve(b, target_p=target, target_v=v_end, vmax=vmax, amax=amax, amin=amin, jerk=lim.jerk)
            b.p, b.v, b.a = target, v_end, 0.0
            return
        for _ in range(48):
            mid = 0.5 * (lo + hi)
            if attempt(mid):
                lo = mid
            else:
                hi = mid
            if hi - lo <= 1e-9 * hi:
                break
        attempt(hi)

    @staticmethod
    def _passes(segments: list[Segment], t_end: float, target: float, sign: float, vss: float) -> bool:
        """Does a stage pass ``target``, turn back, or (stepper) run below the start/stop velocity?"""
        tol_p = 1e-9 * max(1.0, abs(target))
        for k, seg in enumerate(segments):
            end = segments[k + 1].t if k + 1 < len(segments) else t_end
            dur = end - seg.t
            if (seg.p - target) * sign > tol_p:
                return True
            # smallest velocity in the direction of travel over the segment
            cands = [0.0, dur]
            if seg.j != 0.0:
                tau = -seg.a / seg.j
                if 0.0 < tau < dur:
                    cands.append(tau)
            v_min = min(sign * (seg.v + x * (seg.a + x * seg.j / 2)) for x in cands)
            if v_min < vss - 1e-9 * max(1.0, vss) - 1e-12:
                return True
        return False

    def velocity(self, t: float, p: float, v: float, a: float, target_v: float, lim: Limits) -> Profile:
        """Ramp to ``target_v`` and keep it; milestone ``reached`` when the velocity is reached."""
        b = _Builder(t, p, v, a)
        if target_v == 0.0:
            self._brake_to_standstill(b, lim)
            return b.finish(b.p, 0.0, {"reached": b.t})
        moving = abs(v) > _EPS_V
        if moving and (v > 0) != (target_v > 0):
            self._brake_to_standstill(b, lim)
            moving = False
        if not moving:
            b.a = 0.0 if lim.jerk == INF else b.a
            if lim.start_stop:
                b.jump(math.copysign(lim.start_stop, target_v))
        sign = 1.0 if target_v > 0 else -1.0
        amax, amin = self._signed_limits(sign, lim)
        u, ut = sign * b.v, abs(target_v)
        self._settle(b, lim, sign, min(u, ut), max(u, ut) if lim.strict else lim.hard_velocity)
        if abs(b.v - target_v) > 1e-12 or (lim.jerk < INF and abs(b.a) > 1e-12):
            self._solve(b, target_p=None, target_v=target_v, vmax=abs(target_v), amax=amax, amin=amin,
                        jerk=lim.jerk)
        return b.finish(b.p, target_v, {"reached": b.t})

    def stop(self, t: float, p: float, v: float, a: float, lim: Limits) -> Profile:
        """Brake to standstill with the deceleration (and jerk) of ``lim``."""
        return self.velocity(t, p, v, a, 0.0, lim)

    def free(self, t: float, p: float, v: float, a: float, *, target_p: float | None, vmin: float, vmax: float,
             amin: float, amax: float, jerk: float, duration: float | None = None) -> Profile:
        """Time-optimal motion with signed limits to ``target_p`` (velocity and acceleration zero), or to
        velocity and acceleration zero when ``target_p`` is None; ``duration`` stretches it to at least
        that time.  Used for the synchronization offsets of following axes, whose limits are not
        symmetric (the leading axis's motion is added to them)."""
        inp = self._inp
        inp.control_interface = (ruckig.ControlInterface.Velocity if target_p is None
                                 else ruckig.ControlInterface.Position)
        inp.current_position, inp.current_velocity, inp.current_acceleration = [p], [v], [a if jerk < INF else 0.0]
        inp.target_position = [p if target_p is None else target_p]
        inp.target_velocity, inp.target_acceleration = [0.0], [0.0]
        inp.max_velocity, inp.min_velocity = [max(vmax, 0.0)], [min(vmin, 0.0)]
        inp.max_acceleration, inp.min_acceleration = [amax], [amin]
        inp.max_jerk = [jerk]
        inp.minimum_duration = duration
        try:
            result = self._otg.calculate(inp, self._traj)
        except Exception as exc:
            result = exc
        finally:
            inp.minimum_duration = None
            inp.min_velocity = None
        if result not in (ruckig.Result.Working, ruckig.Result.Finished):
            raise PlanningError(f"ruckig: {result!r} for p={p!r} v={v!r} a={a!r} -> {target_p!r} "
                                f"(v=[{vmin}, {vmax}], a=[{amin}, {amax}], j={jerk}, T={duration})")
        b = _Builder(t, p, v, a if jerk < INF else 0.0)
        prof = self._traj.profiles[0][0]
        for part in (prof.brake, None, prof.accel):
            if part is None:
                for i in range(7):
                    b.add(prof.t[i], prof.p[i], prof.v[i], prof.a[i], prof.j[i] if jerk < INF else 0.0)
            elif part.duration > 0.0:
                for i in range(2):
                    b.add(part.t[i], part.p[i], part.v[i], part.a[i], part.j[i] if jerk < INF else 0.0)
        end_p = b.p if target_p is None else target_p
        return b.finish(end_p, 0.0, {"reached": b.t})

    @staticmethod
    def ramp_stop(t: float, p: float, v: float, deceleration: float) -> Profile:
        """Brake at constant deceleration without jerk limit (emergency stop ramp, §12.8)."""
        b = _Builder(t, p, v, 0.0)
        if abs(v) > _EPS_V:
            a = -math.copysign(deceleration, v)
            b.add(abs(v) / deceleration, p, v, a, 0.0)
        return b.finish(b.p, 0.0, {"reached": b.t})

    @staticmethod
    def ramp_stop_at(t: float, p: float, v: float, deceleration: float, stop_at: float) -> Profile:
        """Keep the velocity, then brake at ``deceleration`` without jerk to stand exactly at ``stop_at``."""
        b = _Builder(t, p, v, 0.0)
        brake = v * v / (2 * deceleration)
        cruise = abs(stop_at - p) - brake
        if abs(v) > _EPS_V:
            if cruise > 0:
                b.add(cruise / abs(v), p, v, 0.0, 0.0)
            b.add(abs(v) / deceleration, b.p, v, -math.copysign(deceleration, v), 0.0)
        return b.finish(stop_at, 0.0, {"reached": b.t})

    @staticmethod
    def constant_move(t: float, p: float, target: float, duration: float) -> Profile:
        """Travel to ``target`` at constant velocity in ``duration`` (velocity steps at both ends)."""
        b = _Builder(t, p, 0.0, 0.0)
        b.add(duration, p, (target - p) / duration, 0.0, 0.0)
        return b.finish(target, 0.0)

    @staticmethod
    def hold(t: float, p: float) -> Profile:
        return Profile([Segment(t, p, 0.0, 0.0, 0.0)], t)

    @staticmethod
    def cruise(t: float, p: float, v: float) -> Profile:
        return Profile([Segment(t, p, v, 0.0, 0.0)], t, {"reached": t})


class ReversalRequired(Exception):
    """The requested motion needs a change of direction."""
