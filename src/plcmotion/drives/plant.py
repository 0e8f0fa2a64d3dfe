"""The simulated machine around the drives: switches that the moving load actuates.

Each servo cycle the plant looks at the machine position of every axis (``DriveChannel.mechanical_position``)
and sets the electrical level of the inputs the switches are wired to: hardware limit switches stay
actuated beyond their position (S7-1200 V6 §5.4.4.3 requires switches that remain actuated), a homing
switch (reference cam) is actuated over its length.  A drive's "ready" signal is wired the same way.
The controller's input filters then decide what the CPU sees.  A switch edge is stamped with the time the
load crossed the end of the switch (linear between two servo cycles), so that the input filter runs from
the edge itself and not from the servo cycle that first sampled it (decision 33).

Switches can be placed by a program (``Plant.place_switch``) and can fail like real ones
(``Switch.stick``, ``Switch.chatter``, ``Switch.repair``; docs/fault_injection.md).
"""
from __future__ import annotations

import math
from typing import Any, Callable

from ..kernel.io import check_address
from .base import DriveChannel
from .spec import PlantSpec


def _position(name: str, value: Any) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise TypeError(f"{name} must be a number, got {value!r}")
    try:
        x = float(value)
    except OverflowError:               # an int beyond float range (copysign would overflow again)
        x = math.inf if value > 0 else -math.inf
    if math.isnan(x):
        raise ValueError(f"{name} must not be NaN")
    return x


class Switch:
    """A switch actuated while the machine position lies in [low, high] (repeating every ``period``).

    Faults of the contact: ``stick(True/False)`` keeps it actuated / released whatever the load does,
    ``chatter(period)`` makes it bounce: in the second half of every period it shows the opposite of what
    the load says.  The controller's input filter decides whether the CPU sees the bouncing.
    """

    __slots__ = ("channel", "address", "low", "high", "active_high", "name", "period", "stuck", "chatter_period",
                 "_chatter_t0", "_x", "_t", "_on")

    def __init__(self, channel: DriveChannel, address: str, low: float, high: float, active_high: bool, name: str,
                 period: float | None = None):
        self.channel, self.address = channel, address
        self.low, self.high, self.active_high, self.name = low, high, active_high, name
        self.period = period
        self.stuck: bool | None = None
        self.chatter_period: float | None = None
        self._chatter_t0 = 0.0
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
        return self._faulty(self.actuated(), t) == self.active_high

    def _faulty(self, on: bool, t: float) -> bool:
        """What the contact shows when the load says ``on`` (a stuck or chattering contact lies)."""
        if self.stuck is not None:
            on = self.stuck
        if self.chatter_period is not None:
            # phase in periods, robust against rounding of the cycle times (t = k * servo_cycle)
            x = (t - self._chatter_t0) / self.chatter_period
            if x - math.floor(x + 1e-9) >= 0.5 - 1e-9:
                on = not on
        return on

    # --- faults of the contact (fault injection) ---------------------------------------------------------
    def stick(self, actuated: bool) -> None:
        """The contact sticks: actuated (TRUE) or released (FALSE) whatever the load does."""
        if not isinstance(actuated, bool):
            raise TypeError(f"stick() takes True (stuck actuated) or False (stuck released), got {actuated!r}")
        self.stuck = actuated

    def chatter(self, period: float, *, start: float = 0.0) -> None:
        """The contact bounces with this period [s] (from controller time ``start``): half of each period it
        shows the opposite of its true state."""
        p = _position("chatter period", period)
        if not 0.0 < p <= 3600.0:
            raise ValueError(f"chatter period must be in (0, 3600] s, got {p!r}")
        t0 = _position("chatter start", start)
        if math.isinf(t0):
            raise ValueError("chatter start must be a finite controller time [s]")
        self.chatter_period = p
        self._chatter_t0 = t0

    def repair(self) -> None:
        """The contact works again."""
        self.stuck = None
        self.chatter_period = None

    def __repr__(self) -> str:
        fault = (f" stuck {'actuated' if self.stuck else 'released'}" if self.stuck is not None else "") + (
            f" chattering {self.chatter_period:g} s" if self.chatter_period is not None else "")
        return f"<Switch {self.name} {self.address} [{self.low:g}, {self.high:g}]{fault}>"

    def sample(self, t: float) -> tuple[bool, float]:
        """(level, time of its last edge): the edge is where the machine crossed an end of the switch
        between the last sample and now, linear in between; ``t`` when that is unknown."""
        x1 = self.channel.mechanical_position()
        physical = self._actuated_at(x1)
        level = self._faulty(physical, t) == self.active_high
        x0, t0, before = self._x, self._t, self._on
        self._x, self._t, self._on = x1, t, level
        if (level == before or x0 is None or x1 == x0 or not math.isfinite(x0 + x1)
                or level != (physical == self.active_high)):
            return level, t                  # no edge, no motion, or the contact's fault made the edge
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

    def __init__(self, inputs: Any, controller: Any = None):
        self.inputs = inputs
        self.controller = controller
        self.items: list[Switch | Signal] = []
        self._scenario: Any = None

    @property
    def scenario(self) -> Any:
        """Faults played at given controller times (``kernel.fault_injection.FaultScenario``)."""
        if self._scenario is None:
            from ..kernel.fault_injection import FaultScenario
            self._scenario = FaultScenario(self.controller)
        return self._scenario

    def add(self, item: Switch | Signal, t: float = 0.0) -> None:
        self.items.append(item)
        self.inputs.initialize(item.address, item.sample(t)[0])

    @property
    def switches(self) -> list[Switch]:
        return [item for item in self.items if isinstance(item, Switch)]

    def switch(self, address: str) -> Switch:
        """The switch wired to input ``address`` (e.g. to make it fail: ``plant.switch("I0.2").stick(True)``)."""
        address = check_address(address, "I")
        for item in self.items:
            if isinstance(item, Switch) and item.address == address:
                return item
        wired = ", ".join(sorted({sw.address for sw in self.switches})) or "none"
        raise KeyError(f"no switch is wired to {address} (switches on: {wired})")

    def place_switch(self, address: str, *, axis: Any, low: float = -math.inf, high: float = math.inf,
                     active_high: bool = True, period: float | None = None, name: str = "switch",
                     t: float | None = None) -> Switch:
        """Place a switch at machine positions of ``axis`` (an axis or its name) and wire it to input
        ``address``: it is actuated while the load is in [low, high] (``period``: repeated every period, e.g.
        once per turn).  ``active_high=False`` is an NC contact (the input is FALSE while actuated).
        A limit switch is ``low=<position>`` (or ``high=<position>``) alone, a cam both.  The axis sees
        the switch where its configuration names that input (``PositionLimits_HW.*SwitchAddress``,
        ``Sensor[1].*Homing.DigitalInputAddress``); a program reads it as ``ctl.inputs[address]``."""
        address = check_address(address, "I")
        lo, hi = _position("low", low), _position("high", high)
        if lo > hi:
            raise ValueError(f"switch at {address}: low = {lo!r} must not be above high = {hi!r}")
        if math.isinf(lo) and math.isinf(hi):
            raise ValueError(f"switch at {address}: give low and/or high (a machine position)")
        if period is not None:
            period = _position("period", period)
            if not 0.0 < period < math.inf:
                raise ValueError(f"switch at {address}: period must be a finite length > 0, got {period!r}")
            if math.isinf(lo) or math.isinf(hi):
                raise ValueError(f"switch at {address}: a repeating switch needs both low and high")
        if not isinstance(active_high, bool):
            raise TypeError(f"active_high must be True or False, got {active_high!r}")
        if not isinstance(name, str):
            raise TypeError(f"name must be a string, got {type(name).__name__}")
        if any(item.address == address for item in self.items):
            raise ValueError(f"input {address} is already wired in the plant")
        channel = getattr(axis, "drive", None)
        if not isinstance(channel, DriveChannel):
            ctl = self.controller
            try:
                channel = ctl[axis].drive if isinstance(axis, str) and ctl is not None else None
            except KeyError:
                channel = None
            if not isinstance(channel, DriveChannel):
                raise ValueError(f"switch at {address}: axis {axis!r} is not a positioning or synchronous axis "
                                 "of this controller")
        return self._place(channel, address, lo, hi, active_high, str(name), period,
                           self.inputs._time if t is None else t)

    def _place(self, channel: DriveChannel, address: str, low: float, high: float, active_high: bool, name: str,
               period: float | None, t: float) -> Switch:
        switch = Switch(channel, address, low, high, active_high, name, period)
        self.add(switch, t)
        return switch

    def update(self, t: float) -> None:
        set_level = self.inputs.set_level
        for item in self.items:
            level, edge = item.sample(t)
            set_level(item.address, level, edge)

    def wire_axis(self, spec: PlantSpec, channel: DriveChannel, t: float) -> None:
        """Create the switches of one axis's simulated machine and wire its drive's ready signal."""
        for sw in spec.switches:
            self._place(channel, sw.address, sw.low, sw.high, sw.active_high, sw.name, sw.period, t)
        if spec.ready_input:
            self.add(Signal(spec.ready_input, channel.ready, "drive ready"), t)
