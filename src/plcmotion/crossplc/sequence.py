"""Which DataSetMessage sequence numbers a subscriber accepts (UInt16, wrapping at 65536).

A number is *ahead* of the last accepted one by ``d = (seq - last) mod 65536``.  It is accepted if
``1 <= d <= window``; ``d == 0`` or a number from the recent past (``d > 65536 - window``) is a duplicate
or late and dropped.  Anything else is *out of window*: dropped, because one datagram with a
far-ahead number must not make the subscriber discard every genuine one after it.

Resynchronisation (a publisher restarted and counts afresh, or many datagrams were lost): once
``resync`` out-of-window numbers in a row are each ahead of the previous one by ``1..window``, the
subscriber adopts the newest and accepts from there.  A lone forged or replayed datagram never
resynchronises it; a real restart costs ``resync - 1`` samples.  Up to ``_RUNS`` such runs are followed
at once (the oldest is forgotten), so forged datagrams interleaved with a restarted publisher's do not
keep it from resynchronising.  ``restart()`` makes the next number acceptable whatever it is (used after
the sender was declared lost).
"""
from __future__ import annotations

__all__ = ["SequenceWindow"]

_MOD = 1 << 16
_RUNS = 8           # out-of-window runs followed at once (bounded work and memory)


class SequenceWindow:
    def __init__(self, window: int = 256, resync: int = 3) -> None:
        if isinstance(window, bool) or not isinstance(window, int) or not 0 < window < _MOD // 2:
            raise ValueError(f"sequence_window must be an integer 1..{_MOD // 2 - 1}, got {window!r}")
        if isinstance(resync, bool) or not isinstance(resync, int) or not 0 < resync <= 1000:
            raise ValueError(f"resync_count must be an integer 1..1000, got {resync!r}")
        self.window = window
        self.resync = resync
        self.last: int | None = None
        self._runs: dict[int, int] = {}     # newest number of an out-of-window run -> its length
        self.missed = 0             # numbers skipped by accepted ones (lost datagrams)
        self.resyncs = 0

    def restart(self) -> None:
        self.last = None
        self._runs.clear()

    def check(self, seq: int) -> str:
        """'accept', 'duplicate' (or late) or 'window' (out of window, dropped)."""
        last = self.last
        if last is None:
            self.last = seq
            return "accept"
        ahead = (seq - last) % _MOD
        if 0 < ahead <= self.window:
            self.missed += ahead - 1
            self.last = seq
            self._runs.clear()
            return "accept"
        if ahead == 0 or ahead > _MOD - self.window:
            return "duplicate"
        runs = self._runs
        run = 1
        for newest in runs:
            if 0 < (seq - newest) % _MOD <= self.window:
                run = runs.pop(newest) + 1
                break
        if run >= self.resync:
            self.last = seq
            runs.clear()
            self.resyncs += 1
            return "accept"
        if len(runs) >= _RUNS:
            del runs[next(iter(runs))]
        runs[seq] = run
        return "window"
