"""Activation state of a technology object (S7-Technology V4.1 §6.7.2 MC_ActivateTO).

A deactivated technology object is taken out of the technology's cyclic processing: it accepts no
commands (16#8045 at the instructions), its technology DB is no longer updated except for
``Statusword.ToDeactivated``, and reactivating it initializes its system variables as a restart does
(an axis with an incremental encoder is no longer homed; configuration values written with
MC_WriteParameter stay, a pending "Restart" change takes effect with it).

Changing the state is a command of the technology: it is carried out over ``TRANSITION_UPDATES`` technology
DB updates (state 3 "being activated" / 4 "being deactivated" meanwhile).  The state is kept here, by
object, so the axis classes need no field for it; :func:`state` completes a transition that is due.
"""
from __future__ import annotations

import weakref
from dataclasses import dataclass
from typing import Any, Callable

#: MC_ActivateTO Status (§6.7.2)
NOT_AVAILABLE, ACTIVATED, DEACTIVATED, ACTIVATING, DEACTIVATING = range(5)
#: technology DB updates a state change takes (the command is executed in the technology's command
#: slices that follow the DB updates; the number is plcmotion's)
TRANSITION_UPDATES = 2


@dataclass
class _Transition:
    target: int
    due: int                                   # the device's DB update count at which it is done
    on_done: Callable[[], None] | None = None


_STATE: "weakref.WeakKeyDictionary[Any, int]" = weakref.WeakKeyDictionary()
_PENDING: "weakref.WeakKeyDictionary[Any, _Transition]" = weakref.WeakKeyDictionary()


def _updates(to: Any) -> int:
    return int(getattr(getattr(to.ctl, "extension", None), "updates", 0))


def state(to: Any) -> int:
    """ACTIVATED, DEACTIVATED, ACTIVATING or DEACTIVATING; a transition that is due is completed here."""
    pending = _PENDING.get(to)
    if pending is not None and _updates(to) >= pending.due:
        del _PENDING[to]
        _STATE[to] = pending.target
        if pending.on_done is not None:
            pending.on_done()
    if to in _PENDING:
        return ACTIVATING if _PENDING[to].target == ACTIVATED else DEACTIVATING
    return _STATE.get(to, ACTIVATED)


def deactivated(to: Any) -> bool:
    """The object takes no commands: deactivated or being deactivated (or activated again)."""
    return (to in _STATE or to in _PENDING) and state(to) != ACTIVATED


_HOOKED: "weakref.WeakSet[Any]" = weakref.WeakSet()


def begin(to: Any, target: int, on_done: Callable[[], None] | None = None) -> None:
    """Start the change to ``target`` (ACTIVATED / DEACTIVATED)."""
    _PENDING[to] = _Transition(target, _updates(to) + TRANSITION_UPDATES, on_done)
    device = getattr(to.ctl, "extension", None)
    if device is not None and device not in _HOOKED and hasattr(device, "on_reinitialize"):
        _HOOKED.add(device)
        ctl = weakref.ref(to.ctl)
        device.on_reinitialize.append(lambda reason: _power(ctl(), reason))


def _power(ctl: Any, reason: str) -> None:
    if ctl is not None and reason == "power":
        for to in [t for t in (*_STATE, *_PENDING) if t.ctl is ctl]:
            forget(to)


def busy(to: Any) -> bool:
    """An activation or deactivation of the object is running."""
    return state(to) in (ACTIVATING, DEACTIVATING)


def forget(to: Any) -> None:
    """POWER OFF -> ON: a deactivation made by the program ends (objects start activated)."""
    _PENDING.pop(to, None)
    _STATE.pop(to, None)


def _activated(to: Any) -> None:
    _STATE.pop(to, None)


def activate(to: Any, reinitialize: Callable[[], None]) -> None:
    """Start activating ``to``; when done, ``reinitialize`` initializes its system variables."""
    def done() -> None:
        _activated(to)
        reinitialize()
    begin(to, ACTIVATED, done)


__all__ = ["state", "deactivated", "begin", "activate", "busy", "forget", "NOT_AVAILABLE", "ACTIVATED",
           "DEACTIVATED", "ACTIVATING", "DEACTIVATING", "TRANSITION_UPDATES"]
