"""Which DataSetMessage sequence numbers a subscriber accepts (UInt16, wrapping at 65536).

A number is *ahead* of the last accepted one by ``d = (seq - last) mod 65536``.  It is accepted if
``1 <= d <= window``; ``d == 0`` or a number from the recent past (``d > 65536 - window``) is a duplicate
or late and dropped.  Anything else is *out of window*: dropped, because one datagram with a
far-ahead number must not make the subscriber discard every genuine one after it.

Resynchronisation (a publisher restarted and counts afresh, or many datagrams were lost): once
``resync`` out-of-window numbers in a row are each ahead of the previous one by ``1..window``, the
subscriber adopts the newest and accepts from there.  A lone forged or replayed datagram never
resynchronises it; a real restart costs ``resync - 1`` samples.  ``restart()`` makes the next number
acceptable whatever it is (used after the sender was declared lost).
"""
from __future__ import annotations

__all__ = ["SequenceWindow"]

_MOD = 1 << 16


class SequenceWindow:
    def __init__(self, window: int = 256, resync: int = 3) -> None:
        if isinstance(window, bool) or not isinstance(window, int) or not 0 < window < _MOD // 2:
            raise ValueError(f"sequence_window must be an integer 1..{_MOD // 2 - 1}, got {window!r}")
        if isinstance(resync, bool) or not isinstance(resync, int) or not 0 < resync <= 1000:
            raise ValueError(f"resync_count must be an integer 1..1000, got {resync!r}")
        self.window = window
        self.resync = resync
        self.last: int | None = None
        self._candidate: int | None = None
        self._run = 0
        self.missed = 0             # numbers skipped by accepted ones (lost datagrams)
        self.resyncs = 0

    def restart(self) -> None:
        self.last = None
        self._candidate, self._run = None, 0

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
            self._candidate, self._run = None, 0
            return "accept"
        if ahead == 0 or ahead > _MOD - self.window:
            return "duplicate"
        cand = self._candidate
        if cand is not None and 0 < (seq - cand) % _MOD <= self.window:
            self._run += 1
        else:
            self._run = 1
        self._candidate = seq
        if self._run >= self.resync:
            self.last = seq
            self._candidate, self._run = None, 0
            self.resyncs += 1
            return "accept"
        return "window"
