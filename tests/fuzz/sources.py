"""A leading value source for leading axis proxies in fuzz episodes: a constant-velocity leading axis of
"another controller" whose telegrams are sometimes corrupted (NaN, 1e300, far-ahead times) or missing."""
from __future__ import annotations

import random

from plcmotion.kernel.leading_value import LeadingValueSample


class FuzzLeadingSource:
    def __init__(self, velocity: float, glitch: float, gap: float, seed: int):
        self.velocity, self.glitch, self.gap = velocity, glitch, gap
        self.rnd = random.Random(seed)
        self.seq = 0

    def fetch(self, needed: float) -> list[LeadingValueSample]:
        rnd = self.rnd
        if rnd.random() < self.gap:
            return []
        self.seq += 1
        t, p, v, a = needed, self.velocity * needed, self.velocity, 0.0
        valid = True
        if rnd.random() < self.glitch:
            kind = rnd.randrange(5)
            if kind == 0:
                p = float("nan")
            elif kind == 1:
                p = rnd.choice((1e300, -1e300, float("inf")))
            elif kind == 2:
                v = float("nan")
            elif kind == 3:
                t = needed + rnd.choice((1e3, 1e9))
            else:
                valid = False
        return [LeadingValueSample(t, p, v, a, valid=valid, sequence=self.seq)]
