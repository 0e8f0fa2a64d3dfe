"""Leading values exchanged between controllers (cross-PLC synchronous operation, S7-1500T V5 §8).

The kernel only knows these plain records and the two narrow interfaces a transport implements: a sink
that the providing axis hands one sample per servo cycle, and a source from which a leading axis proxy
fetches what has arrived.  How the samples travel (OPC UA PubSub, an in-process link) is not the
kernel's business.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol, Sequence


@dataclass(frozen=True, slots=True)
class LeadingValueSample:
    """One leading value telegram: the state of the leading axis at the sender's servo time ``time``.

    ``position`` is the unwrapped (continuous) leading value; ``modulo_length`` 0.0 means no modulo.  The
    sender's clock and the receiver's clock are the same virtual time base (one sync domain, §8.1.2).
    ``delay`` is the sender's ``CrossPlcSynchronousOperation.LocalLeadingValueDelayTime``: its local
    followers (coupling type "delayed") use this value at ``time + delay``, and so does a leading axis
    proxy for its followers (§8.1.3), which keeps the followers of both controllers in step.
    """

    time: float
    position: float
    velocity: float
    acceleration: float
    valid: bool = True                 # the leading value may be used (StatusWord.X4 of the proxy)
    tracking: bool = False             # leading axis in follow-up mode (proxy StatusWord.X6 inverted)
    modulo_length: float = 0.0
    modulo_start: float = 0.0
    sequence: int = 0                  # counts the telegrams of one sender
    delay: float = 0.0                 # the sender's local leading value delay time [s]


class LeadingValueSink(Protocol):
    def send(self, sample: LeadingValueSample) -> None:
        """Publish one sample (called once per servo cycle of the providing controller)."""


class LeadingValueSource(Protocol):
    def fetch(self, needed: float) -> Sequence[LeadingValueSample]:
        """Samples that arrived since the last call, oldest first.

        ``needed`` is the sender time the receiver is about to use; a transport may wait (by its own
        policy, bounded) until a sample at least that recent has arrived.  Never raises for a missing
        sender: an empty result is how "nothing arrived" is told.
        """
