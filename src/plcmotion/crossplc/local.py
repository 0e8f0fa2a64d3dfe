"""In-process leading value link: two controllers in one Python process, no network."""
from __future__ import annotations

import threading
from collections import deque

from plcmotion.kernel.leading_value import LeadingValueSample


class LocalLink:
    """A leading value sink and source in one object, for one sender and one receiver.

    ``send`` queues the sample, ``fetch`` hands over everything queued since the previous call, oldest
    first.  ``fetch`` never waits: whoever drives both controllers decides the order in which they run,
    which keeps a local cross-PLC setup fully deterministic.  Safe to use from two threads.
    """

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._queue: deque[LeadingValueSample] = deque()

    def send(self, sample: LeadingValueSample) -> None:
        with self._lock:
            self._queue.append(sample)

    def fetch(self, needed: float) -> list[LeadingValueSample]:
        with self._lock:
            samples = list(self._queue)
            self._queue.clear()
        return samples

    def __len__(self) -> int:
        """Samples sent but not fetched yet."""
        with self._lock:
            return len(self._queue)
