"""The serve loop's interface for services and its controlled shutdown, in virtual time.

A service runs beside the loop, reads the published snapshot and hands commands to the loop's thread; a
shutdown disables each axis with the StopMode of its MC_Power (S7-1200 V6 §11.1.1) and runs the servo
cycles until the axes stand, at most ``shutdown_timeout``."""
from __future__ import annotations

import threading

import pytest

from plcmotion.services import ServeLoop, make_loop

from ._fixtures import ScriptedClock, controller


class Watcher:
    """A service in a thread of its own: waits for a snapshot at t >= 0.5 s (the axis at speed), then asks for a shutdown."""

    name = "watcher"

    def __init__(self):
        self.seen = []
        self.requested: list[float] = []
        self.stopped = False
        self._thread: threading.Thread | None = None

    def start(self, loop: ServeLoop) -> None:
        def watch():
            while not loop.shutting_down:
                snap = loop.snapshot
                if snap is not None and snap.time >= 0.5 - 1e-9:
                    self.seen.append(snap)
                    loop.call_soon(lambda: (self.requested.append(loop.ctl.time), loop.request_shutdown()))
                    return
                threading.Event().wait(0.001)
        self._thread = threading.Thread(target=watch, daemon=True)
        self._thread.start()

    def stop(self) -> None:
        self.stopped = True
        self._thread.join(timeout=10)


def test_services_a_service_reads_snapshots_and_commands_through_the_loop():
    ctl = controller()
    watcher = Watcher()
    loop = make_loop(ctl, clock=ScriptedClock(), speed=1.0, services=(watcher,))
    loop.watch("Axis_1.Velocity", ctl.axes["Axis_1"].tag_getter("Velocity"))
    loop.run(None)                                       # until the service asks for the shutdown
    snap = watcher.seen[0]
    assert watcher.stopped and loop.ended_by == "shutdown"
    assert snap.mode == "RUN" and snap.tags["Axis_1.Velocity"] == 200.0 and snap.pacing["Overruns"] == 0
    assert snap.pacing["Cycles"] == round(snap.time * 1000)
    # braking from 200 mm/s with the EmergencyDeceleration 2000 mm/s^2 (StopMode 0) takes 0.1 s
    assert ctl.axes["Axis_1"].state == "disabled" and ctl.mode == "RUN" and not loop.not_stopped
    assert watcher.requested[0] >= snap.time
    assert loop.snapshot.time - watcher.requested[0] == pytest.approx(0.1, abs=0.004)


def test_services_shutdown_removes_the_enable_when_the_ramp_outlasts_the_timeout():
    ctl = controller()
    loop = ServeLoop(ctl, None, shutdown_timeout=0.02)
    ctl.run(0.5)
    loop.request_shutdown()
    loop.run(None)
    assert loop.not_stopped == ["Axis_1"] and ctl.mode == "STOP" and "did not end within 0.02 s" in ctl.stop_reason
    assert ctl.axes["Axis_1"].state == "disabled"
    assert ctl.time == pytest.approx(0.52)
