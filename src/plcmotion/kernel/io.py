"""Digital process image of the controller: inputs with input filters, outputs.

Addresses are written as on an S7 CPU: ``I0.3`` for input byte 0 bit 3, ``Q0.1`` for an output.  A
program, a test or the simulated plant sets the electrical level of an input; what the technology
objects and programs read is the filtered value: a change becomes visible only after it has been stable
for the input's filter time (S7-1200 V6 §5.4.4.3, §5.4.4.5: 6.4 ms by default), so a pulse shorter
than the filter is lost.  The filter runs from the time of the edge (the plant stamps a switch edge with
the moment the load crossed it), so the value changes in the first servo cycle at or after edge + filter
time: at most one servo cycle later than the filter time (decision 33).  ``force`` overrides the level like a force table, e.g. to break a wire.
"""
from __future__ import annotations

import math
import re
from typing import Iterator

_ADDRESS = re.compile(r"^([IQ])(\d{1,4})\.([0-7])$")
DEFAULT_FILTER = 0.0064       # s, default input filter of the CPU's digital inputs


def check_address(address: str, kind: str | None = None) -> str:
    """Validate an address like 'I0.3' / 'Q1.7'; returns it in canonical form."""
    if not isinstance(address, str):
        raise TypeError(f"address must be a string like 'I0.3', got {address!r}")
    m = _ADDRESS.match(address.strip().upper())
    if not m or (kind is not None and m.group(1) != kind):
        expected = {"I": "an input like 'I0.3'", "Q": "an output like 'Q0.1'"}.get(kind or "", "'I0.3' or 'Q0.1'")
        raise ValueError(f"{address!r} is not {expected} (byte 0..9999, bit 0..7)")
    return f"{m.group(1)}{int(m.group(2))}.{m.group(3)}"


class DigitalInputs:
    """Input process image with a filter per input."""

    def __init__(self, default_filter: float = DEFAULT_FILTER):
        self.default_filter = default_filter
        self._level: dict[str, bool] = {}       # electrical level (plant, program, test)
        self._value: dict[str, bool] = {}       # filtered value, what the CPU sees
        self._since: dict[str, float] = {}      # level differs from value since this time
        self._filter: dict[str, float] = {}
        self._forced: dict[str, bool] = {}
        self._time = 0.0

    def __getitem__(self, address: str) -> bool:
        address = check_address(address, "I")
        return self._value.get(address, False)

    def __setitem__(self, address: str, level: bool) -> None:
        self.set_level(check_address(address, "I"), bool(level))

    def __iter__(self) -> Iterator[str]:
        return iter(sorted(set(self._level) | set(self._value)))

    def set_level(self, address: str, level: bool, at: float | None = None) -> None:
        """Set the electrical level (address already checked); ``at``: time of the edge (default: now)."""
        if address in self._forced:
            return
        if self._level.get(address) == level and address in self._value:
            return
        self._level[address] = level
        when = self._time if at is None else min(at, self._time)
        if address not in self._value:
            self._value[address] = level if self.filter_time(address) == 0.0 else False
            if self._value[address] != level:
                self._since[address] = when
        elif self._value[address] != level:
            self._since.setdefault(address, when)
        else:
            self._since.pop(address, None)      # back to the old value before the filter expired
        if self.filter_time(address) == 0.0 and address in self._since:
            self._value[address] = level
            del self._since[address]

    def initialize(self, address: str, level: bool) -> None:
        """Power-on state of an input: level and filtered value at once (no filter delay)."""
        address = check_address(address, "I")
        if address in self._forced:
            return
        self._level[address] = self._value[address] = bool(level)
        self._since.pop(address, None)

    def level(self, address: str) -> bool:
        return self._level.get(check_address(address, "I"), False)

    def filter_time(self, address: str) -> float:
        return self._filter.get(address, self.default_filter)

    def set_filter(self, address: str, seconds: float) -> None:
        """Input filter of one input [s] (0 = no filter)."""
        if not isinstance(seconds, (int, float)) or isinstance(seconds, bool) or not math.isfinite(seconds) \
                or not 0.0 <= seconds <= 20.0:
            raise ValueError(f"input filter of {address} must be a time in [0, 20] s, got {seconds!r}")
        self._filter[check_address(address, "I")] = float(seconds)

    def force(self, address: str, level: bool | None) -> None:
        """Force an input to a level regardless of the plant and program; ``None`` removes the force."""
        address = check_address(address, "I")
        if level is None:
            self._forced.pop(address, None)
            return
        self._forced.pop(address, None)
        self.set_level(address, bool(level))
        self._forced[address] = bool(level)

    def begin_cycle(self, t: float) -> None:
        """Levels set from now on are stamped with servo time ``t`` (the plant writes them at the start
        of the cycle)."""
        self._time = t

    def update(self, t: float) -> None:
        """Apply the filters at time ``t`` (once per servo cycle)."""
        self._time = t
        if not self._since:
            return
        for address, since in list(self._since.items()):
            if t - since >= self.filter_time(address) - 1e-9:
                self._value[address] = self._level[address]
                del self._since[address]


class DigitalOutputs:
    """Output process image (drive enable outputs and outputs a program sets)."""

    def __init__(self) -> None:
        self._value: dict[str, bool] = {}

    def __getitem__(self, address: str) -> bool:
        return self._value.get(check_address(address, "Q"), False)

    def __setitem__(self, address: str, value: bool) -> None:
        self._value[check_address(address, "Q")] = bool(value)

    def __iter__(self) -> Iterator[str]:
        return iter(sorted(self._value))
