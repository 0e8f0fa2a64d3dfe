"""The homing methods of the simulated CiA 402 drive (homing mode 6, method 0x6098) and the plant they
search: limit switches, a home switch and the encoder's index pulses.

The drive knows only its input signals (0x60FD bit 0 negative limit switch, bit 1 positive limit switch,
bit 2 home switch) and the index pulses it passes, never where they are.  Every method is one table row
(CiA 402-2 homing methods; the rows are our reading of the method figures, docs/drives/cia402.md
"Decisions"):

* the *feature*: the signal whose edge defines home, and the shape of the region where it is active -
  ``lower`` (active from -inf up to the edge: negative limit switch, negative home switch), ``upper``
  (from the edge to +inf: positive limit switch, positive home switch) or ``narrow`` (a cam active over a
  part of the travel, methods 7-14 / 23-30);
* the *edge* of that region (``low`` or ``high`` end) and the *final* direction: home is where the drive
  crosses that edge moving in the final direction - or, with an index pulse (1-14), the first index pulse
  after that crossing, further in the final direction.  17-30 are 1-14 without the index pulse;
* the *initial* direction of a narrow cam search (7-10 positive, 11-14 negative); when that leads away
  from the cam the drive reverses at the limit switch it runs into; 33/34 search the first index pulse in
  the negative / positive direction; 35/37 take the current position.

The run steers by what it knows of its side of the feature's region (below, inside, above, or not yet
known for a narrow cam): it moves towards the side the final crossing starts from, then crosses in the final
direction.  The switch search runs at the speed 0x6099:1 until the feature is first seen, everything after
(the edge crossing, the index search) at the zero search speed 0x6099:2.  A limit switch reached that the
method does not use, or the second one of a narrow search, ends the run with a homing error.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

#: the side of a feature region, ordered along the axis
_ORDER = {"below": 0, "inside": 1, "above": 2}


@dataclass(frozen=True)
class SwitchPlant:
    """Where the simulated drive's switches are and its index pulses lie (mechanical motor position [inc])."""

    negative_limit: float | None = None       #: the negative limit switch is active at and below this
    positive_limit: float | None = None       #: the positive limit switch is active at and above this
    home_low: float | None = None             #: the home switch is active in [home_low, home_high]
    home_high: float = math.inf               #: (inf: a positive home switch; home_low = -inf: a negative one)
    index_pitch: float | None = None          #: distance between index pulses; None: one per motor revolution
    index_offset: float = 0.0                 #: the position of one index pulse

    def active(self, signal: str, x: float) -> bool:
        if signal == "neg":
            return self.negative_limit is not None and x <= self.negative_limit
        if signal == "pos":
            return self.positive_limit is not None and x >= self.positive_limit
        return self.home_low is not None and self.home_low <= x <= self.home_high

    def digital_inputs(self, x: float) -> int:
        """0x60FD: bit 0 negative limit switch, bit 1 positive limit switch, bit 2 home switch."""
        return (self.active("neg", x) | self.active("pos", x) << 1 | self.active("home", x) << 2)


def switch_plant(plant: Any, scale: float, per_rev: float) -> SwitchPlant:
    """The simulated drive's switches from the axis's simulated machine (``drives.spec.PlantSpec``, machine
    position [length unit]; ``scale`` increments per length unit): its low and high hardware limit switches
    are the drive's negative and positive limit switch, its homing switch (reference cam) the drive's home
    switch, its encoder zero marks the index pulses (default: one per motor revolution, ``per_rev``)."""
    by_name = {sw.name: sw for sw in plant.switches}
    low, high, cam = (by_name.get(n) for n in ("low hardware limit switch", "high hardware limit switch",
                                               "homing switch"))
    pitch = plant.zero_mark_distance * scale if plant.zero_mark_distance else per_rev
    return SwitchPlant(negative_limit=None if low is None else low.high * scale,
                       positive_limit=None if high is None else high.low * scale,
                       home_low=None if cam is None else cam.low * scale,
                       home_high=math.inf if cam is None else cam.high * scale,
                       index_pitch=pitch, index_offset=plant.zero_mark_offset * scale)


def first_pulse(a: float, b: float, pitch: float, offset: float) -> float | None:
    """The first index pulse passed moving from ``a`` (excluded) to ``b`` (included), or None."""
    if b > a:
        p = offset + (math.floor((a - offset) / pitch) + 1) * pitch
        return p if p <= b else None
    if b < a:
        p = offset + (math.ceil((a - offset) / pitch) - 1) * pitch
        return p if p >= b else None
    return None


@dataclass(frozen=True)
class Method:
    """One homing method: the feature signal and its region, the edge, final and initial direction."""

    signal: str            # "neg", "pos", "home"; "" for the index-only methods
    region: str            # "lower", "upper", "narrow"
    edge: str              # "low", "high"
    final: int             # +1 / -1
    initial: int = 0       # narrow cam: the first search direction
    index: bool = True


_ROWS = {
    1: Method("neg", "lower", "high", +1), 2: Method("pos", "upper", "low", -1),
    3: Method("home", "upper", "low", -1), 4: Method("home", "upper", "low", +1),
    5: Method("home", "lower", "high", +1), 6: Method("home", "lower", "high", -1),
    7: Method("home", "narrow", "low", -1, +1), 8: Method("home", "narrow", "low", +1, +1),
    9: Method("home", "narrow", "high", -1, +1), 10: Method("home", "narrow", "high", +1, +1),
    11: Method("home", "narrow", "high", +1, -1), 12: Method("home", "narrow", "high", -1, -1),
    13: Method("home", "narrow", "low", +1, -1), 14: Method("home", "narrow", "low", -1, -1),
}
#: 0x6098 -> method; 33/34 (index pulse only) and 35/37 (current position) are handled by :class:`HomingRun`
METHODS: dict[int, Method] = {**_ROWS, **{n + 16: Method(m.signal, m.region, m.edge, m.final, m.initial, False)
                                          for n, m in _ROWS.items()}}
#: every method the simulated drive offers
OFFERED = tuple(sorted((*METHODS, 33, 34, 35, 37)))


class HomingRun:
    """One homing run from mechanical position ``x``.  Each SYNC the drive asks :meth:`velocity` for the
    velocity to ramp to and then tells :meth:`moved` where the motor went; ``home`` is the mechanical home
    position once found, ``error`` a reason when the run failed."""

    def __init__(self, method: int, plant: SwitchPlant, x: float, pitch: float, fast: float, slow: float):
        self.plant, self.pitch, self.fast, self.slow = plant, pitch, abs(fast), abs(slow)
        self.home: float | None = None
        self.error = ""
        self.seen = False                    # the feature was seen: from now on the zero search speed
        self.index_from: float | None = None  # the index search runs from here (the edge crossing)
        self.m: Method | None = None
        self.side = ""
        if method in (35, 37):
            self.home = x
            return
        if method in (33, 34):
            self.index_from, self.dir = x, (-1 if method == 33 else +1)
            return
        m = METHODS.get(method)
        if m is None:
            self.error = f"homing method {method} is not offered by this drive"
            return
        self.m = m
        self.dir = m.initial
        self.reversed = False
        if plant.active(m.signal, x):
            self.side, self.seen = "inside", True
        elif m.region != "narrow":
            self.side = "above" if m.region == "lower" else "below"
        elif m.initial and plant.active("pos" if m.initial > 0 else "neg", x):
            self.side, self.reversed = ("above" if m.initial > 0 else "below"), True
        if m.signal != "home" and plant.active("pos" if m.signal == "neg" else "neg", x):
            self.error = "started on the opposite limit switch"

    @property
    def done(self) -> bool:
        return self.home is not None or bool(self.error)

    def velocity(self) -> float:
        """The velocity [inc/s, mechanical] the drive ramps to now."""
        if self.done:
            return 0.0
        if self.index_from is not None:
            return self.dir * self.slow
        m = self.m
        pre = {("low", 1): "below", ("low", -1): "inside", ("high", 1): "inside", ("high", -1): "above"}[
            (m.edge, m.final)]
        if self.side == pre:
            d = m.final
        elif self.side:
            d = 1 if _ORDER[pre] > _ORDER[self.side] else -1
        else:
            d = m.initial
        return d * (self.slow if self.seen else self.fast)

    def moved(self, a: float, b: float) -> None:
        """The motor went from ``a`` to ``b`` in the last SYNC period: switch edges and index pulses."""
        if self.done or a == b:
            return
        if self.index_from is not None:
            self._index(a, b)
            return
        m, plant = self.m, self.plant
        for limit in ("neg", "pos"):
            if plant.active(limit, b) and not plant.active(limit, a) and limit != m.signal:
                toward = 1 if limit == "pos" else -1
                if m.region == "narrow" and not self.side and not self.reversed and toward == m.initial:
                    self.side, self.reversed = ("above" if toward > 0 else "below"), True
                else:
                    self.error = f"{'positive' if limit == 'pos' else 'negative'} limit switch reached"
                    return
        was, now = plant.active(m.signal, a), plant.active(m.signal, b)
        if was == now:
            return
        d = 1 if b > a else -1
        edge = ("low" if d > 0 else "high") if now else ("high" if d > 0 else "low")
        self.side = "inside" if now else ("above" if d > 0 else "below")
        self.seen = True
        if edge == m.edge and d == m.final:
            at = (plant.home_low if edge == "low" else plant.home_high) if m.signal == "home" else \
                (plant.negative_limit if m.signal == "neg" else plant.positive_limit)
            if not m.index:
                self.home = float(at)
                return
            self.index_from, self.dir = float(at), m.final
            self._index(float(at), b)

    def _index(self, a: float, b: float) -> None:
        if (b - a) * self.dir <= 0:
            return
        p = first_pulse(max(a, self.index_from) if self.dir > 0 else min(a, self.index_from), b, self.pitch,
                        self.plant.index_offset)
        if p is not None:
            self.home = p
