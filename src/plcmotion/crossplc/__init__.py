"""Transports for cross-PLC synchronous operation (leading values between controllers).

The kernel defines what travels (``plcmotion.kernel.leading_value``); this package moves it:

* ``LocalLink`` -- in-process, deterministic, no dependencies;
* ``UadpLeadingValuePublisher`` / ``UadpLeadingValueSubscriber`` -- OPC UA PubSub, UADP over UDP, with
  optional message security (``generate_key``; it needs ``cryptography``, the ``crossplc`` extra).
  Imported on first use, so ``LocalLink`` needs nothing beyond the kernel.
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any

from .local import LocalLink

if TYPE_CHECKING:
    from .uadp import UadpLeadingValuePublisher, UadpLeadingValueSubscriber, generate_key

__all__ = ["LocalLink", "UadpLeadingValuePublisher", "UadpLeadingValueSubscriber", "generate_key"]

_UADP_NAMES = {"UadpLeadingValuePublisher", "UadpLeadingValueSubscriber", "generate_key"}


def __getattr__(name: str) -> Any:
    if name in _UADP_NAMES:
        from . import uadp

        return getattr(uadp, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
