"""The simulated machine around the drives: switches that the moving load actuates.

Each servo cycle the plant looks at the machine position of every axis (``DriveChannel.mechanical_position``)
and sets the electrical level of the inputs the switches are wired to: hardware limit switches stay
actuated beyond their position (S7-1200 V6 §5.4.4.3 requires switches that remain actuated), a homing
switch (reference cam) is actuated over its length.  A drive's "ready" signal is wired the same way.
The controller's input filters then decide what the CPU sees.  A switch edge is stamped with the time the
load crossed the end of the switch (linear between two servo cycles), so that the input filter runs from
the edge itself and not from the servo cycle that first sampled it (decision 33).
"""
from __future__ import annotations

import math
from typing import Any, Callable

from .base import DriveChannel


class Switch:
    """A switch actuated while the machine position lies in [low, high] (repeating every ``period``)."""

    __slots__ = ("channel", "address", "low", "high", "active_high", "name", "period", "_x", "_t", "_on")

    def __init__(self, channel: DriveChannel, address: str, low: float, high: float, active_high: bool, name: str,
                 period: float | None = None):
        self.channel, self.address = channel, address
        self.low, self.high, self.active_high, self.name = low, high, active_high, name
        self.period = period
        self._x: float | None = None        # machine position, time and level of the last sample
        self._t = 0.0
        self._on: bool | None = None

    def actuated(self) -> bool:
        return self._actuated_at(self.channel.mechanical_position())

    def _actuated_at(self, x: float) -> bool:
        if self.period:
            x = self.low + (x - self.low) % self.period
        return self.low <= x <= self.high

    def level(self, t: float) -> bool:
        return self.actuated() == self.active_high

    def sample(self, t: float) -> tuple[bool, float]:
        """(level, time of its last edge): the edge is where the machine crossed an end of the switch
        between the last sample and now, linear in between; ``t`` when that is unknown."""
        x1 = self.channel.mechanical_position()
        level = self._actuated_at(x1) == self.active_high
        x0, t0, before = self._x, self._t, self._on
        self._x, self._t, self._on = x1, t, level
        if level == before or x0 is None or x1 == x0 or not math.isfinite(x0 + x1):
            return level, t
        up = x1 > x0
        crossed = []
        for end in (self.low, self.high):
            if not math.isfinite(end):
                continue
            if self.period:                 # the nearest copy of this end behind x1
                k = math.floor((x1 - end) / self.period) if up else math.ceil((x1 - end) / self.period)
                end += k * self.period
            if (x0 < end <= x1) if up else (x1 <= end < x0):
                crossed.append(end)
        if not crossed:
            return level, t
        end = max(crossed) if up else min(crossed)     # the last end crossed decides the level
        return level, t0 + (t - t0) * ((end - x0) / (x1 - x0))


class Signal:
    """An input wired to a signal of the drive (e.g. 'Drive ready')."""

    __slots__ = ("address", "source", "name")

    def __init__(self, address: str, source: Callable[[float], bool], name: str):
        self.address, self.source, self.name = address, source, name

    def level(self, t: float) -> bool:
        return bool(self.source(t))

    def sample(self, t: float) -> tuple[bool, float]:
        return self.level(t), t


class Plant:
    """All switches and signals of the simulated machine of one controller."""

    def __init__(self, inputs: Any):
        self.inputs = inputs
        self.items: list[Switch | Signal] = []

    def add(self, item: Switch | Signal, t: float = 0.0) -> None:
        self.items.append(item)
        self.inputs.initialize(item.address, item.sample(t)[0])

    def update(self, t: float) -> None:
        set_level = self.inputs.set_level
        for item in self.items:
            level, edge = item.sample(t)
            set_level(item.address, level, edge)

    def wire_axis(self, cfg: dict, channel: DriveChannel, t: float) -> None:
        """Create the switches an axis configuration describes (``Plant.*`` and the input addresses)."""
        lo = cfg["Plant.HWLimitMinPosition"]
        if lo is not None and cfg["PositionLimits_HW.MinSwitchAddress"]:
            self.add(Switch(channel, cfg["PositionLimits_HW.MinSwitchAddress"], -math.inf, lo,
                            cfg["PositionLimits_HW.MinSwitchLevel"], "low hardware limit switch"), t)
        hi = cfg["Plant.HWLimitMaxPosition"]
        if hi is not None and cfg["PositionLimits_HW.MaxSwitchAddress"]:
            self.add(Switch(channel, cfg["PositionLimits_HW.MaxSwitchAddress"], hi, math.inf,
                            cfg["PositionLimits_HW.MaxSwitchLevel"], "high hardware limit switch"), t)
        cam = cfg["Plant.HomingSwitchPosition"]
        if cam is not None:
            length = cfg["Plant.HomingSwitchLength"]
            seen: set[str] = set()
            for kind in ("ActiveHoming", "PassiveHoming"):
                address = cfg[f"Sensor[1].{kind}.DigitalInputAddress"]
                if address and address not in seen:
                    seen.add(address)
                    self.add(Switch(channel, address, cam, cam + length, cfg[f"Sensor[1].{kind}.SwitchLevel"],
                                    "homing switch", cfg["Plant.HomingSwitchPeriod"]), t)
        ready = cfg["Actor.Interface.DriveReadyInput"]
        if ready:
            self.add(Signal(ready, channel.ready, "drive ready"), t)
