"""Pacing the servo cycles of a controller to the wall clock, with absolute deadlines.

Servo cycle ``n`` (counted from the first paced one) is due at ``origin + n * period``; the loop sleeps
until that deadline and never "sleeps one period", so waiting errors do not add up over hours.  The
lateness of a cycle is its actual start minus its deadline.  A cycle that starts after the *next*
deadline is an overrun, the MC-Servo overflow of a CPU (S7-1200 V6 §2.2.7.3 "Overflows": the CPU goes to
STOP; S7-Technology V4.1 §5.1: a configured number of overflows is tolerated, STOP once it is exceeded).
After an overrun the deadlines are laid anew from that cycle (the late time is "slip"), because virtual
time advances one servo cycle per cycle and a burst of catch-up cycles would run the machine faster than
real time.

The reaction to overruns is ``warn`` (count and log, at the 1st, 2nd, 4th, 8th ... overrun) or ``stop``:
more than ``tolerated`` overruns in a row put the controller in STOP through ``Controller.stop``, the
same STOP the cycle watchdog of the kernel gives, which ``stop`` also switches on for the programs.
"""
from __future__ import annotations

import logging
from typing import Any, Callable

from .clock import Clock, MonotonicClock
from .lateness import LatenessStats

WARN, STOP = "warn", "stop"
REACTIONS = (WARN, STOP)
#: overruns in a row tolerated by the ``stop`` reaction before the controller goes to STOP
DEFAULT_TOLERATED = 2

log = logging.getLogger("plcmotion.serve")

#: the pacing tags (``Pacing.<name>``) and their meaning; times in s
TAGS: dict[str, str] = {
    "LatenessP50": "median lateness of the servo cycles of the window [s]",
    "LatenessP99": "99th percentile lateness of the servo cycles of the window [s]",
    "LatenessMax": "largest lateness of the run [s]",
    "Overruns": "servo cycles that started after the next deadline",
    "Cycles": "servo cycles paced",
    "Slip": "wall-clock time lost to overruns (deadlines laid anew) [s]",
    "Speed": "wall-clock speed factor (2: twice real time)",
}


class PacingTags:
    """The pacing figures as tags of an object named ``Pacing``: ``tags.tag("LatenessP99")``,
    ``tags.LatenessP99``, ``tags.tag_getter(path)``, as the tags of a technology object read."""

    name = "Pacing"

    def __init__(self, pacer: "Pacer"):
        self._getters: dict[str, Callable[[], Any]] = {
            "LatenessP50": lambda: pacer.stats.percentile_ns(50) / 1e9,
            "LatenessP99": lambda: pacer.stats.percentile_ns(99) / 1e9,
            "LatenessMax": lambda: pacer.stats.max_ns / 1e9,
            "Overruns": lambda: pacer.overruns,
            "Cycles": lambda: pacer.stats.count,
            "Slip": lambda: pacer.slip_ns / 1e9,
            "Speed": lambda: pacer.speed,
        }

    @staticmethod
    def tag_paths() -> list[str]:
        return list(TAGS)

    def tag_getter(self, path: str) -> Callable[[], Any]:
        path = path.removeprefix("Pacing.")
        try:
            return self._getters[path]
        except KeyError:
            raise KeyError(f"Pacing has no tag {path!r}; tags: {', '.join(TAGS)}") from None

    def tag(self, path: str) -> Any:
        return self.tag_getter(path)()

    def __getattr__(self, name: str) -> Any:
        getters = self.__dict__.get("_getters", {})
        if name in getters:
            return getters[name]()
        raise AttributeError(f"Pacing has no tag {name!r}; tags: {', '.join(TAGS)}")

    def values(self) -> dict[str, Any]:
        return {name: g() for name, g in self._getters.items()}


class Pacer:
    """Paces the servo cycles of ``ctl`` (a pre-servo hook while attached).

    ``speed``: wall-clock speed factor (2: a servo cycle of 1 ms takes 0.5 ms).  ``reaction``: ``warn`` or
    ``stop``; ``tolerated``: overruns in a row the ``stop`` reaction tolerates."""

    def __init__(self, ctl: Any, *, speed: float = 1.0, reaction: str = WARN, tolerated: int = DEFAULT_TOLERATED,
                 clock: Clock | None = None, window: int | None = None):
        if not (isinstance(speed, (int, float)) and 0 < speed < float("inf")):
            raise ValueError(f"speed must be a finite factor > 0, got {speed!r}")
        if reaction not in REACTIONS:
            raise ValueError(f"overrun reaction must be one of {', '.join(REACTIONS)}, got {reaction!r}")
        if isinstance(tolerated, bool) or not isinstance(tolerated, int) or tolerated < 0:
            raise ValueError(f"tolerated overruns must be a whole number >= 0, got {tolerated!r}")
        self.ctl = ctl
        self.speed = float(speed)
        self.reaction = reaction
        self.tolerated = tolerated
        self.clock: Clock = clock if clock is not None else MonotonicClock()
        #: wall-clock length of a servo cycle [ns] (a float: deadlines are rounded one by one, never summed)
        self.period_ns = ctl.servo_cycle * 1e9 / self.speed
        self.stats = LatenessStats() if window is None else LatenessStats(window)
        self.overruns = 0
        self.in_a_row = 0
        self.slip_ns = 0
        self.origin_ns: int | None = None
        self._n = 0                     # servo cycles since the origin
        self.tags = PacingTags(self)
        if reaction == STOP and ctl.watchdog.limit is not None:
            ctl.watchdog.stop = True    # the programs' cycle watchdog reacts as the CPU does, too

    def attach(self) -> "Pacer":
        self.ctl.on_pre_servo(self._cycle)
        return self

    def detach(self) -> None:
        self.ctl.remove_hook(self._cycle)

    def deadline_ns(self, n: int) -> int:
        """Deadline of servo cycle ``n`` after the origin."""
        assert self.origin_ns is not None
        return self.origin_ns + round(n * self.period_ns)

    def _cycle(self, t: float) -> None:
        clock = self.clock
        if self.origin_ns is None:
            self.origin_ns = clock.now_ns()
        deadline = self.deadline_ns(self._n)
        now = clock.now_ns()
        if now < deadline:
            clock.sleep_until(deadline)
            now = clock.now_ns()
        late = now - deadline
        self.stats.add(late)
        self._n += 1
        if late >= self.period_ns:              # started after the next deadline: an overrun
            self._overrun(t, late, now)
        else:
            self.in_a_row = 0

    def _overrun(self, t: float, late: int, now: int) -> None:
        self.overruns += 1
        self.in_a_row += 1
        # lay the deadlines anew: the next cycle is due one period after this one started
        self.slip_ns += late
        self.origin_ns, self._n = now, 1
        text = (f"servo cycle overrun at t = {t:.6g} s: started {late * 1e-6:.4g} ms late (servo cycle "
                f"{self.period_ns * 1e-6:.4g} ms wall clock); {self.overruns} overrun"
                f"{'s' if self.overruns != 1 else ''} so far")
        if self.reaction == STOP and self.in_a_row > self.tolerated:
            self.ctl.stop(f"{text}, {self.in_a_row} in a row (tolerated {self.tolerated}): MC-Servo overflow, "
                          f"the CPU goes to STOP")
            log.warning("%s: controller in STOP", text)
        elif self.overruns & (self.overruns - 1) == 0:
            log.warning(text)

    def summary(self) -> str:
        s = self.stats
        return (f"pacing: {s.count} servo cycles at x{self.speed:g}, lateness p50 {s.percentile_ns(50) * 1e-6:.3f} ms, "
                f"p99 {s.percentile_ns(99) * 1e-6:.3f} ms, max {s.max_ns * 1e-6:.3f} ms, {self.overruns} overrun"
                f"{'s' if self.overruns != 1 else ''}, slip {self.slip_ns * 1e-9:.3f} s")
