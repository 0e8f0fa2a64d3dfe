"""Closed-form jerk-limited profiles: the defined fallback where ruckig gives up numerically.

ruckig refuses inputs whose time scales differ by many orders of magnitude (e.g. a jerk of 5e-8 with a
velocity of 40: phases of 1e9 s).  A plan must still come out (issue 8 defect 5), so these build
the motion on the profile builder of ``profiles`` from textbook S-curves: a velocity change from zero
acceleration (constant jerk up, constant acceleration, constant jerk down), and a positioning that
brakes to standstill and travels rest to rest.  Not time-optimal where an acceleration was present
(it is dropped), but within the velocity, acceleration and jerk limits.
"""
from __future__ import annotations

import math
from typing import Any

INF = math.inf


def scurve(b: Any, target_v: float, amax: float, amin: float, jerk: float) -> None:
    """Jerk-limited velocity change of builder ``b`` from zero acceleration to ``target_v``."""
    b.a = 0.0
    dv = target_v - b.v
    if dv == 0.0:
        return
    sgn = 1.0 if dv > 0 else -1.0
    acc = amax if dv > 0 else -amin
    if not acc > 0.0:
        raise ValueError(f"no acceleration to change the velocity ({amin}, {amax})")
    if jerk == INF:
        b.add(abs(dv) / acc, b.p, b.v, sgn * acc, 0.0)
    else:
        t1 = acc / jerk
        if abs(dv) <= acc * t1:
            t1, t2 = math.sqrt(abs(dv) / jerk), 0.0
        else:
            t2 = abs(dv) / acc - t1
        b.add(t1, b.p, b.v, 0.0, sgn * jerk)
        b.add(t2, b.p, b.v, b.a, 0.0)
        b.add(t1, b.p, b.v, b.a, -sgn * jerk)
    b.v, b.a = target_v, 0.0


def ramp_time(dv: float, acc: float, jerk: float) -> float:
    """Duration of a jerk-limited velocity change ``dv`` >= 0 from and to zero acceleration."""
    if jerk == INF:
        return dv / acc
    t1 = acc / jerk
    return 2.0 * math.sqrt(dv / jerk) if dv <= acc * t1 else dv / acc + t1


def closed_form(b: Any, target_p: float | None, target_v: float, vmax: float, amax: float, amin: float,
                jerk: float) -> bool:
    """Append the motion to ``target_p`` (None: to ``target_v``) to builder ``b``; False when even this
    has no finite solution.  A positioning's peak speed is found by bisection (its distance rises with it)."""
    try:
        if target_p is None:
            scurve(b, target_v, amax, amin, jerk)
            return True
        scurve(b, 0.0, amax, amin, jerk)
        dist = abs(target_p - b.p)
        sgn = 1.0 if target_p >= b.p else -1.0
        acc, dec = (amax, -amin) if sgn > 0 else (-amin, amax)
        if dist > 0.0 and vmax > 0.0:
            def travel(u: float) -> float:
                return u / 2.0 * (ramp_time(u, acc, jerk) + ramp_time(u, dec, jerk))
            peak = vmax
            if travel(vmax) > dist:
                lo, hi = 0.0, vmax
                for _ in range(200):
                    mid = 0.5 * (lo + hi)
                    if travel(mid) > dist:
                        hi = mid
                    else:
                        lo = mid
                    if hi - lo <= 1e-15 * vmax:
                        break
                peak = lo
            if peak > 0.0:
                scurve(b, sgn * peak, amax, amin, jerk)
                cruise = dist - travel(peak)
                if cruise > 0.0:
                    b.add(cruise / peak, b.p, b.v, 0.0, 0.0)
                scurve(b, 0.0, amax, amin, jerk)
        b.p, b.v, b.a = target_p, target_v, 0.0
        return all(math.isfinite(x) for x in (b.t, b.p, b.v))
    except (ArithmeticError, ValueError):
        return False
