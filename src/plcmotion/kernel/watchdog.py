"""Cycle-time monitoring of the user programs, the watchdog a PLC has on its program cycle.

A CPU watches its program cycle against a maximum cycle time and goes to STOP (or calls the time error
OB80) when it is exceeded; S7-1200 V6 §2.2.7.3 (Overflows) gives the motion OBs the same reaction.  Here the
programs of
one application cycle (the OB1 of plcmotion) are timed on the wall clock; a run longer than
``multiple`` x application cycle is an overrun.  The wall clock of a Python simulation says nothing about
the virtual controller, so by default an overrun is only reported (a warning, a counter, the last overrun);
``stop=True`` reacts like the CPU.  Virtual time never depends on the wall clock, and an injected overrun
(virtual commissioning) is as deterministic as the rest of the run.
"""
from __future__ import annotations

import math
import numbers
from dataclasses import dataclass

MAX_MULTIPLE = 1e6          # watchdog times beyond a million application cycles are a typing error
#: default watchdog time in application cycles (0.4 s at the default 4 ms): generous, because a Python
#: program may pause for an import or the garbage collector without anything being wrong
DEFAULT_MULTIPLE = 100.0


class CycleOverrunWarning(RuntimeWarning):
    """The user programs of an application cycle took longer than the cycle watchdog allows."""


@dataclass(frozen=True)
class Overrun:
    """One overrun: virtual ``time`` of the application cycle [s], wall-clock ``duration`` of its programs
    [s], the watchdog ``limit`` [s], and whether it was ``injected`` (``Controller.inject_cycle_overrun``)."""
    time: float
    duration: float
    limit: float
    injected: bool = False


def check_multiple(value: object) -> float | None:
    """``cycle_watchdog``: None or 0 (off), or a number of application cycles in [1, 1e6]."""
    if value is None or (isinstance(value, numbers.Real) and not isinstance(value, bool) and value == 0):
        return None
    # the comparison is exact for ints of any size (math.isfinite(10**400) overflows) and false for NaN
    if not isinstance(value, numbers.Real) or isinstance(value, bool) or not 1.0 <= value <= MAX_MULTIPLE:
        shown = repr(value) if len(repr(value)) <= 40 else repr(value)[:37] + "..."
        raise ValueError(f"cycle_watchdog must be a number of application cycles in [1, {MAX_MULTIPLE:g}] "
                         f"or 0/None (off), got {shown}")
    return float(value)


class CycleWatchdog:
    """Counts the overruns of the program cycle; ``check`` says whether a run was one."""

    def __init__(self, app_cycle: float, multiple: object = DEFAULT_MULTIPLE, stop: object = False):
        if not isinstance(stop, bool):
            raise ValueError(f"cycle_watchdog_stop must be True or False, got {stop!r}")
        self.multiple = check_multiple(multiple)
        if stop and self.multiple is None:
            # a STOP on overruns that are never detected would silently do nothing
            raise ValueError("cycle_watchdog_stop = True needs a cycle watchdog: give cycle_watchdog a number of "
                             f"application cycles in [1, {MAX_MULTIPLE:g}], not 0/None (off)")
        #: watchdog time [s] (None: no monitoring)
        self.limit = None if self.multiple is None else self.multiple * app_cycle
        #: go to STOP on an overrun (as a CPU on its maximum cycle time) instead of only reporting it
        self.stop = stop
        #: number of overruns since the controller was created
        self.count = 0
        #: the last overrun (None: none yet)
        self.last: Overrun | None = None
        #: wall-clock run time of the programs of the last application cycle and the longest one [s]
        self.cycle_time = 0.0
        self.longest = 0.0
        self._injected = 0
        self._injected_duration = 0.0

    def inject(self, cycles: object = 1, duration: object = None) -> None:
        """The next ``cycles`` application cycles count as overruns of ``duration`` seconds each
        (default: twice the watchdog time)."""
        if self.limit is None:
            raise ValueError("no cycle watchdog to trip: create the controller with cycle_watchdog=<multiple>")
        if isinstance(cycles, bool) or not isinstance(cycles, numbers.Integral) or not 1 <= cycles <= 10**9:
            raise ValueError(f"cycles must be a whole number of application cycles >= 1, got {cycles!r}")
        if duration is None:
            duration = 2.0 * self.limit
        if (isinstance(duration, bool) or not isinstance(duration, numbers.Real)
                or not self.limit < duration <= 1e9):       # exact for huge ints, false for NaN
            shown = repr(duration) if len(repr(duration)) <= 40 else repr(duration)[:37] + "..."
            raise ValueError(f"duration must be a wall-clock time [s] longer than the watchdog time "
                             f"{self.limit:g} s, got {shown}")
        self._injected = int(cycles)
        self._injected_duration = float(duration)

    def check(self, t: float, duration: float) -> Overrun | None:
        """Account the programs' run of the application cycle at virtual time ``t``; the overrun, if it was one."""
        injected = self._injected > 0
        if injected:
            self._injected -= 1
            duration = max(duration, self._injected_duration)
        self.cycle_time = duration
        self.longest = max(self.longest, duration)
        if self.limit is None or duration <= self.limit:
            return None
        self.count += 1
        self.last = Overrun(t, duration, self.limit, injected)
        return self.last

    def reportable(self) -> bool:
        """Warn at the 1st, 2nd, 4th, 8th ... overrun: a slow machine must not drown the output."""
        return self.count & (self.count - 1) == 0

    def describe(self, o: Overrun) -> str:
        what = "injected overrun" if o.injected else "overrun"
        return (f"cycle time {what} at t = {o.time:.6g} s: the programs took {o.duration * 1000:.4g} ms, longer "
                f"than the watchdog time {o.limit * 1000:.4g} ms ({self.multiple:g} x application cycle); "
                f"{self.count} overrun{'s' if self.count != 1 else ''} so far")
