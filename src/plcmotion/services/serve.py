"""The serve loop: the controller's application cycles paced to the wall clock (or in virtual time),
services beside it, and a controlled shutdown.

Services (an OPC UA server, a web panel) run in threads or asyncio tasks of their own.  They never touch
the controller while it runs a cycle: they read ``ServeLoop.snapshot``, an immutable view the loop
replaces after every application cycle (one reference assignment, so a reader sees one whole cycle
without a lock), and they hand commands to ``ServeLoop.call_soon``, which the loop runs between two
application cycles in its own thread.

Shutdown (``request_shutdown``, e.g. from SIGINT/SIGTERM): the programs no longer run, every enabled axis
is disabled by the family's own disabling path with the StopMode its enabling instruction gave (its
configured stop ramp), the servo cycles run until all axes stand disabled (at most ``shutdown_timeout``
s of virtual time; then the enable is removed), the retentive data is saved (if there is any) and the
services stopped.
"""
from __future__ import annotations

import math
import os
import queue
import threading
from dataclasses import dataclass, field
from typing import Any, Callable, Protocol

from ..kernel import retain
from .pacing import DEFAULT_TOLERATED, WARN, Pacer, PacingTags

#: virtual time the stop ramps of a shutdown may take before the enables are removed [s]
DEFAULT_SHUTDOWN_TIMEOUT = 10.0
DISABLED = "disabled"


@dataclass(frozen=True)
class Snapshot:
    """What the controller looked like after one application cycle."""
    time: float
    app_cycles: int
    mode: str
    pacing: dict[str, Any] = field(default_factory=dict)
    tags: dict[str, Any] = field(default_factory=dict)


class Service(Protocol):
    """Something running beside the loop (``start`` returns at once; ``stop`` ends it)."""

    name: str

    def start(self, loop: "ServeLoop") -> None: ...

    def stop(self) -> None: ...


class ServeLoop:
    """Runs ``ctl`` paced to the wall clock (``pacer``) or, with ``pacer=None``, in virtual time."""

    def __init__(self, ctl: Any, pacer: Pacer | None = None, *, services: tuple[Service, ...] = (),
                 shutdown_timeout: float = DEFAULT_SHUTDOWN_TIMEOUT):
        if not (math.isfinite(shutdown_timeout) and shutdown_timeout >= 0):
            raise ValueError(f"shutdown_timeout must be a finite time >= 0 s, got {shutdown_timeout!r}")
        self.ctl = ctl
        self.pacer = pacer
        self.services = tuple(services)
        self.shutdown_timeout = shutdown_timeout
        self._shutdown = threading.Event()
        self._commands: queue.SimpleQueue[Callable[[], Any]] = queue.SimpleQueue()
        self._watched: dict[str, Callable[[], Any]] = {}
        #: the last published state (None before the first cycle)
        self.snapshot: Snapshot | None = None
        #: why the run ended: "duration", "shutdown" or "STOP"
        self.ended_by: str | None = None
        #: axes that were still moving when the shutdown timeout ran out (their enable was removed)
        self.not_stopped: list[str] = []

    @property
    def pacing(self) -> PacingTags | None:
        return None if self.pacer is None else self.pacer.tags

    # --- for services --------------------------------------------------------------------------------
    def watch(self, name: str, getter: Callable[[], Any]) -> None:
        """Publish ``getter()`` as ``snapshot.tags[name]`` after every application cycle (call before ``run``)."""
        self._watched[name] = getter

    def call_soon(self, fn: Callable[[], Any]) -> None:
        """Run ``fn()`` in the loop's thread before the next application cycle (thread-safe)."""
        self._commands.put(fn)

    def request_shutdown(self) -> None:
        """End the run with a controlled shutdown (thread- and signal-safe)."""
        self._shutdown.set()

    @property
    def shutting_down(self) -> bool:
        return self._shutdown.is_set()

    # --- running -------------------------------------------------------------------------------------
    def run(self, duration: float | None = None) -> None:
        """Application cycles until ``duration`` s of virtual time (None: until a shutdown request) or a
        shutdown request; then the controlled shutdown.  Programs or services that put the controller
        in STOP do not end the run: a CPU in STOP still serves its clients."""
        ctl = self.ctl
        n = None if duration is None else max(1, round(duration / ctl.app_cycle))
        if self.pacer is not None:
            self.pacer.attach()
        for service in self.services:
            service.start(self)
        try:
            k = 0
            while (n is None or k < n) and not self._shutdown.is_set():
                self._run_commands()
                if self._shutdown.is_set():         # a service's command asked for it
                    break
                ctl.step()
                k += 1
                self._publish()
            self.ended_by = "shutdown" if self._shutdown.is_set() else "duration"
            self.shut_down()
        finally:
            for service in reversed(self.services):
                service.stop()
            if self.pacer is not None:
                self.pacer.detach()

    def shut_down(self) -> None:
        """Stop every axis with its own stop ramp, run the servo cycles until they stand, save retain data."""
        ctl = self.ctl
        if self.ended_by == "shutdown":
            for axis in ctl.axes.values():
                owner = axis.power_owner
                if owner is not None and axis.state != DISABLED:
                    axis.power(owner, False, 0, axis.stop_mode)
            limit = ctl.time + self.shutdown_timeout
            while any(a.state != DISABLED for a in ctl.axes.values()) and ctl.time < limit - 1e-12:
                ctl.step(programs=False)
                self._publish()
            self.not_stopped = [name for name, a in ctl.axes.items() if a.state != DISABLED]
            if self.not_stopped:
                ctl.stop("shutdown: the stop ramps did not end within "
                         f"{self.shutdown_timeout:g} s; enable removed")
        if ctl.mode != "RUN" and self.ended_by == "duration":
            self.ended_by = "STOP"
        # the kernel writes the state file whenever retentive data changes; this keeps it whole at the end
        # without leaving an empty file beside a project that has nothing to retain
        if ctl.state_file and (ctl.retain or os.path.exists(ctl.state_file)):
            retain.save(ctl.state_file, ctl.retain)

    def _run_commands(self) -> None:
        while True:
            try:
                fn = self._commands.get_nowait()
            except queue.Empty:
                return
            fn()

    def _publish(self) -> None:
        if not self.services and not self._watched:
            return
        ctl = self.ctl
        pacing = {} if self.pacer is None else self.pacer.tags.values()
        self.snapshot = Snapshot(ctl.time, ctl.app_cycles, ctl.mode, pacing,
                                 {name: g() for name, g in self._watched.items()})


def make_loop(ctl: Any, *, virtual: bool = False, speed: float = 1.0, overrun: str = WARN,
              tolerated: int = DEFAULT_TOLERATED, clock: Any = None,
              services: tuple[Service, ...] = ()) -> ServeLoop:
    """The loop ``plcmotion serve`` runs: paced unless ``virtual``."""
    pacer = None if virtual else Pacer(ctl, speed=speed, reaction=overrun, tolerated=tolerated, clock=clock)
    return ServeLoop(ctl, pacer, services=services)
