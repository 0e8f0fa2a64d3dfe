"""The dynamics of a superimposed positioning within the axis's maxima (S7-Technology V4.1 §6.2.9).

MC_MoveSuperImposed's dynamic values add to those of the basic motion; where the sum would exceed the
configured maximum velocity or acceleration, the superimposed part is planned with what the basic motion
leaves over for the rest of its profile (warning 16#0021 in the technology DB).  Planning-time only: the
servo cycle adds the two layers as before.
"""
from __future__ import annotations

import dataclasses
from typing import Any

from ...kernel.profile_curve import INF, Profile, velocity_reach

#: the share of a commanded value the superimposed part keeps when the basic motion leaves no headroom
#: (it runs at the maximum): the part still ends, the sum may exceed the maximum by that much
#: (plcmotion's choice, issue 11 review A3)
MIN_SHARE = 0.01


def _acceleration_reach(profile: Profile, t: float) -> float:
    """The largest |acceleration| ``profile`` has from ``t`` on (linear inside each segment)."""
    peak = abs(profile.at(t)[2])
    segs = profile.segments
    for k, seg in enumerate(segs):
        end = profile.end_of(k)
        if end <= t:
            continue
        if end == INF:
            if seg.j != 0.0:
                return INF
            peak = max(peak, abs(seg.a))
            continue
        peak = max(peak, abs(seg.a), abs(seg.a + (end - seg.t) * seg.j))
    return peak


def _headroom(value: float, maximum: float | None, used: float) -> tuple[float, bool]:
    """``value`` cut so that ``used + value`` stays within ``maximum``; and whether it was cut."""
    if not maximum or used + value <= maximum * (1 + 1e-12):
        return value, False
    return max(maximum - used, MIN_SHARE * value), True


def within_maxima(basic: Profile, t: float, distance: float, lim: Any, limits: Any) -> tuple[Any, bool]:
    """The ``lim`` of a superimposed positioning by ``distance`` started at ``t`` on top of the basic
    motion ``basic``, cut to the axis's ``limits`` (``DynamicLimits``); and whether anything was cut."""
    if distance == 0.0:
        return lim, False
    lo, hi = velocity_reach(basic, t)
    used_v = hi if distance > 0.0 else -lo          # the basic velocity in the part's direction
    velocity, cut_v = _headroom(lim.velocity, limits.max_velocity, max(used_v, 0.0))
    used_a = _acceleration_reach(basic, t)
    acceleration, cut_a = _headroom(lim.acceleration, limits.max_acceleration, used_a)
    deceleration, cut_d = _headroom(lim.deceleration, limits.max_deceleration or limits.max_acceleration, used_a)
    if not (cut_v or cut_a or cut_d):
        return lim, False
    return dataclasses.replace(lim, velocity=velocity, acceleration=acceleration, deceleration=deceleration), True


__all__ = ["within_maxima", "MIN_SHARE"]
