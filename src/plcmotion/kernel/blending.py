"""Planning a positioning that passes its target in motion (PLCopen blending, kernel/job_queue.py).

Which speeds a positioning can pass its target with depends on the state it is in and on the distance
left: speeding up to ``u`` or slowing down to ``u`` takes a distance of its own.  All distances come from
the existing ``Planner`` (ruckig's time-optimal velocity ramps, the closed-form trapezoid without a jerk
limit); nothing here solves kinematics by hand:

* ``ramp_distance``: the way covered while changing the speed from a state to ``u``;
* ``reachable_speeds``: the interval of speeds the target can be passed with;
* ``stoppable_speed``: the highest speed from which a following positioning can still stop at its target;
* ``blend_profile``: the profile to the target with the end speed kept within what is reachable.  Above the
  job's own velocity (BlendingNext / BlendingHigh into a faster job) the job cruises at its velocity and
  speeds up on the last stretch, so that it passes the target at the higher speed and never earlier.
"""
from __future__ import annotations

import dataclasses
import math

from .profiles import INF, Limits, Planner, Profile, Segment

_REL = 1e-9
_STEPS = 60


def _speed_limits(lim: Limits, speed: float) -> Limits:
    """``lim`` allowing the speed ``speed`` (ramps beyond the job's own velocity, never beyond the axis)."""
    return dataclasses.replace(lim, velocity=max(lim.velocity, speed), strict=False, reach=None)


def ramp_distance(planner: Planner, v: float, a: float, speed: float, sign: float, lim: Limits) -> float:
    """Distance (in direction ``sign``) covered from velocity ``v`` / acceleration ``a`` until the axis moves
    at ``speed`` in direction ``sign`` with zero acceleration, changing the speed as fast as ``lim`` allows."""
    prof = planner.velocity(0.0, 0.0, v, a, sign * speed, _speed_limits(lim, speed))
    return sign * prof.final.p


def _bisect(ok, lo: float, hi: float) -> float:
    """Largest x in [lo, hi] with ok(x), given ok(lo) and ok monotonic (True below, False above)."""
    for _ in range(_STEPS):
        mid = 0.5 * (lo + hi)
        if ok(mid):
            lo = mid
        else:
            hi = mid
        if hi - lo <= _REL * max(1.0, hi):
            break
    return lo


def reachable_speeds(planner: Planner, p: float, v: float, a: float, target: float, lim: Limits
                     ) -> tuple[float, float] | None:
    """(lowest, highest) speed with which a motion from (p, v, a) can pass ``target`` without turning back.

    Above the job's velocity (``lim.velocity``) the motion first reaches that velocity and only then speeds
    up further (see ``blend_profile``).  None: the target lies behind the point where the axis can stop.
    """
    d = target - p
    sign = math.copysign(1.0, v if abs(v) > 1e-9 else d)
    dist = d * sign
    if dist < 0.0:
        return None
    top = lim.hard_velocity
    cruise = lim.velocity
    tol = _REL * max(1.0, abs(target))

    def need(u: float) -> float:
        if u > cruise and sign * v <= cruise:
            return ramp_distance(planner, v, a, cruise, sign, lim) + ramp_distance(planner, sign * cruise, 0.0,
                                                                                   u, sign, lim)
        return ramp_distance(planner, v, a, u, sign, lim)

    # the speed that takes the least way: the one the current acceleration settles at
    jerk = lim.jerk
    u_star = sign * v + (sign * a * abs(a) / (2.0 * jerk) if jerk < INF else 0.0)
    u_star = min(max(u_star, 0.0), top)
    if need(u_star) > dist - tol:
        return None
    hi = top if need(top) <= dist - tol else _bisect(lambda u: need(u) <= dist - tol, u_star, top)
    if need(0.0) <= dist - tol:
        lo = 0.0
    else:
        # largest speed that is still infeasible from below, mirrored: bisect on the falling side
        lo_ok, lo_bad = u_star, 0.0
        for _ in range(_STEPS):
            mid = 0.5 * (lo_ok + lo_bad)
            if need(mid) <= dist - tol:
                lo_ok = mid
            else:
                lo_bad = mid
            if lo_ok - lo_bad <= _REL * max(1.0, lo_ok):
                break
        lo = lo_ok
    return lo, hi


def stoppable_speed(planner: Planner, distance: float, lim: Limits) -> float:
    """Highest speed (at most the axis limit) from which the axis can stop within ``distance``."""
    top = lim.hard_velocity
    if distance <= 0.0:
        return 0.0

    def ok(u: float) -> bool:
        return ramp_distance(planner, u, 0.0, 0.0, 1.0, lim) <= distance * (1 - _REL)

    return top if ok(top) else _bisect(ok, 0.0, top)


def end_speed(planner: Planner, p: float, v: float, a: float, target: float, lim: Limits, speed: float) -> float:
    """``speed`` moved into what a motion from (p, v, a) can pass ``target`` with (0: it stops there)."""
    if speed <= 0.0:
        return 0.0
    span = reachable_speeds(planner, p, v, a, target, lim)
    if span is None:
        return 0.0
    lo, hi = span
    return min(max(speed, lo), hi)


def _ramp_then_cruise(planner: Planner, t: float, p: float, v: float, a: float, x: float, speed: float,
                      sign: float, lim: Limits) -> tuple[list[Segment], float]:
    """Segments that change the speed to ``speed`` at once and keep it up to ``x``, and the time at ``x``."""
    ramp = planner.velocity(t, p, v, a, sign * speed, _speed_limits(lim, speed))
    segments = ramp.segments[:-1]
    rest = max((x - ramp.final.p) * sign, 0.0)       # >= 0 up to rounding: the speed is reachable
    if rest > 0.0:
        segments.append(Segment(ramp.t_end, ramp.final.p, sign * speed, 0.0, 0.0))
    return segments, ramp.t_end + rest / speed


def blend_profile(planner: Planner, t: float, p: float, v: float, a: float, target: float, lim: Limits,
                  speed: float, *, allow_reverse: bool = True) -> Profile:
    """Time-optimal move to ``target`` passing it at ``speed`` (clamped by ``end_speed``) and going on.

    At or below the job's velocity this is ``Planner.position`` with an end velocity; above it the move
    runs to the point from which the last ramp up to ``speed`` ends exactly at the target.  Where the axis
    cannot stop before that point any more (``Planner.position`` would turn back), it changes its speed at
    once and keeps it up to there.
    """
    u = end_speed(planner, p, v, a, target, lim, speed)
    if u <= 0.0:
        return planner.position(t, p, v, a, target, lim, allow_reverse=allow_reverse)
    sign = math.copysign(1.0, v if abs(v) > 1e-9 else target - p)
    cruise = lim.velocity
    ramp = None
    start, first_speed = target, u
    if u > cruise * (1 + _REL) and sign * v <= cruise * (1 + _REL):
        ramp = planner.velocity(0.0, 0.0, sign * cruise, 0.0, sign * u, _speed_limits(lim, u))
        start, first_speed = target - ramp.final.p, cruise
    if (start - planner.stop_position(p, v, a, lim)) * sign < -1e-9 or first_speed > cruise * (1 + _REL):
        segments, t0 = _ramp_then_cruise(planner, t, p, v, a, start, first_speed, sign, lim)
    else:
        first = planner.position(t, p, v, a, start, lim, allow_reverse=allow_reverse, end_velocity=first_speed)
        segments, t0 = first.segments[:-1], first.t_end
    if ramp is not None:
        segments += [Segment(t0 + s.t, start + s.p, s.v, s.a, s.j) for s in ramp.segments[:-1]]
        t0 += ramp.t_end
    segments.append(Segment(t0, target, sign * u, 0.0, 0.0))
    return Profile(segments, t0)
