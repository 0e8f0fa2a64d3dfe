"""A planned motion as the servo cycle sees it: segments of constant jerk (piecewise cubic position).

:mod:`.profiles` plans a :class:`Profile` once per command or parameter change; the axis evaluates it every
servo cycle (:meth:`Profile.at`) and asks it where its velocity goes (:func:`velocity_reach`,
:func:`first_time_at_velocity`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

INF = math.inf


@dataclass(slots=True)
class Segment:
    t: float        # absolute start time
    p: float
    v: float
    a: float
    j: float

    def at(self, t: float) -> tuple[float, float, float]:
        tau = t - self.t
        return (self.p + tau * (self.v + tau * (self.a / 2 + tau * self.j / 6)),
                self.v + tau * (self.a + tau * self.j / 2),
                self.a + tau * self.j)


@dataclass(slots=True)
class Profile:
    """Segments in time order; the last segment lasts forever (hold or constant velocity)."""

    segments: list[Segment]
    t_end: float                      # end of the motion part (start of the final segment)
    milestones: dict[str, float] = field(default_factory=dict)

    @property
    def final(self) -> Segment:
        return self.segments[-1]

    def end_of(self, index: int) -> float:
        return self.segments[index + 1].t if index + 1 < len(self.segments) else INF

    def at(self, t: float) -> tuple[float, float, float]:
        seg = self.segments[0]
        for s in self.segments:
            if s.t > t:
                break
            seg = s
        return seg.at(t)

    @property
    def duration(self) -> float:
        return self.t_end - self.segments[0].t


def velocity_reach(profile: Profile, t: float) -> tuple[float, float]:
    """(lowest, highest) velocity ``profile`` passes through from ``t`` on (extremes inside segments too)."""
    lo = hi = profile.at(t)[1]
    segs = profile.segments
    for k, seg in enumerate(segs):
        end = profile.end_of(k)
        if end <= t:
            continue
        taus = [max(seg.t, t) - seg.t]
        if end < INF:
            taus.append(end - seg.t)
        elif seg.a != 0.0 or seg.j != 0.0:
            # a final segment that keeps changing the velocity: unbounded on that side
            return (-INF if seg.a < 0 or seg.j < 0 else lo), (INF if seg.a > 0 or seg.j > 0 else hi)
        if seg.j != 0.0 and taus[0] < -seg.a / seg.j < taus[-1]:
            taus.append(-seg.a / seg.j)
        for tau in taus:
            v = seg.v + tau * (seg.a + tau * seg.j / 2)
            lo, hi = min(lo, v), max(hi, v)
    return lo, hi


def first_time_at_velocity(profile: Profile, v: float, tol: float = 1e-9) -> float | None:
    """Start of the first segment that cruises at ``v`` (used for InVelocity)."""
    for seg in profile.segments:
        if abs(seg.v - v) <= tol * max(1.0, abs(v)) and seg.a == 0.0 and seg.j == 0.0:
            return seg.t
    return None
