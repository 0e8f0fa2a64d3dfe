"""Trace signals of a Pilz drive axis, for :class:`plcmotion.trace.Trace` (the plots of docs/pilz).

The set and actual position and velocity are named like the kernel's axis values (``<axis>.Position``,
``<axis>.ActualPosition``, ``<axis>.Velocity``, ``<axis>.ActualVelocity``), so a trace plot draws them as the
axis's motion panels; the status words of the motion core (Pilz V6.5 §1, status tables) follow as a timeline:
the bits as step lanes, the PLCopen state I89, the command state I83 and the motion ID I82 as values.
"""
from __future__ import annotations

from typing import Any, Callable

from .technology.axis import DriveAxis

#: the status bits of the timeline, with what they say
BITS: dict[str, str] = {"I85": "profile done", "I180": "in window", "I183": "speed reached", "I92": "done",
                        "I91": "error", "I86": "in reference"}
#: the status values of the timeline
VALUES: dict[str, str] = {"I89": "PLCopen state", "I83": "command state", "I82": "motion ID"}


def _status(axis: DriveAxis, name: str) -> Callable[[], Any]:
    return lambda: getattr(axis.status, name)          # axis.status: the core renews it at a restart


def trace_signals(axis: DriveAxis) -> dict[str, Callable[[], Any]]:
    """Column name -> getter: set/actual position and velocity, then the status bits and values."""
    core = axis.core
    signals: dict[str, Callable[[], Any]] = {
        f"{axis.name}.Position": lambda: axis.status.I96,
        f"{axis.name}.ActualPosition": core.actual_position,
        f"{axis.name}.Velocity": lambda: axis.status.E07,
        f"{axis.name}.ActualVelocity": lambda: axis.status.I88,
    }
    for name, meaning in BITS.items():
        signals[f"{name} {meaning}"] = _status(axis, name)
    for name, meaning in VALUES.items():
        signals[f"{name} {meaning}"] = _status(axis, name)
    return signals


__all__ = ["BITS", "VALUES", "trace_signals"]
