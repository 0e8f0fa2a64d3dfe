"""The wall clock the paced loop waits on: a monotonic nanosecond counter and a sleep until a deadline.

Tests inject a scripted clock; the real one is ``time.monotonic_ns`` (never set back, not stepped by NTP)
and ``time.sleep``.  A sleep may end late on a busy, non-real-time OS: the loop measures that as lateness."""
from __future__ import annotations

import time
from typing import Protocol


class Clock(Protocol):
    def now_ns(self) -> int:
        """A monotonic time [ns]; only differences mean something."""
        ...

    def sleep_until(self, deadline_ns: int) -> None:
        """Return no earlier than ``deadline_ns`` (as far as the OS allows)."""
        ...


class MonotonicClock:
    """``time.monotonic_ns`` and ``time.sleep``."""

    def now_ns(self) -> int:
        return time.monotonic_ns()

    def sleep_until(self, deadline_ns: int) -> None:
        remaining = deadline_ns - time.monotonic_ns()
        if remaining > 0:
            time.sleep(remaining * 1e-9)
