"""Asking the OS for real-time scheduling of the paced loop (Linux ``SCHED_FIFO``).

Under the default time-sharing policy a process that slept waits for a CPU behind the others on a busy
machine, a few ms at a time; with ``SCHED_FIFO`` it runs as soon as its sleep ends.  It needs the right
to (root or CAP_SYS_NICE); the kernel's real-time throttling (``sched_rt_runtime_us``, 95 % by default)
still leaves the other processes some CPU if a program never returns."""
from __future__ import annotations

import os

MIN_PRIORITY, MAX_PRIORITY = 1, 99


def request_realtime(priority: int) -> str | None:
    """Run the calling process with ``SCHED_FIFO`` at ``priority``; why not, or None when it does."""
    if not MIN_PRIORITY <= priority <= MAX_PRIORITY:
        raise ValueError(f"real-time priority must be in [{MIN_PRIORITY}, {MAX_PRIORITY}], got {priority!r}")
    setter = getattr(os, "sched_setscheduler", None)
    if setter is None or not hasattr(os, "SCHED_FIFO"):
        return "this OS offers no SCHED_FIFO; running with the default scheduling"
    try:
        setter(0, os.SCHED_FIFO, os.sched_param(priority))
    except OSError as exc:
        return (f"SCHED_FIFO priority {priority} refused ({exc.strerror or exc}; needs root or CAP_SYS_NICE); "
                "running with the default scheduling")
    return None
