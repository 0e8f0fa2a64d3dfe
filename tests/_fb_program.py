"""A PLC program around one axis for tests of any family: the instruction instances added to it are called
once per application cycle, in the order they were added (the way a cyclic OB calls its FBs), starting with
the axis's MC_Power.  Used by the S7-1200 tests and the CiA 402 drive tests (tests/drives/_cia402_rig.py);
each names its controller, axis and instructions, this holds only the program and the waiting."""
from __future__ import annotations

from collections.abc import Callable
from typing import Any


class FbProgram:
    """``FbProgram(ctl, axis, power)``: ``power`` (the family's MC_Power instance) is the first instance;
    with ``enable`` the constructor waits until its Status is TRUE.  ``sample`` is called after every servo
    cycle (a trace), from before the enable on."""

    def __init__(self, ctl: Any, axis: Any, power: Any, *, enable: bool = True, enable_timeout: float = 1.0,
                 sample: Callable[[float], None] | None = None):
        self.ctl, self.axis = ctl, axis
        self.fbs: list[Any] = []
        self.power = self.add(power)
        self.ctl.program(self._scan)
        if sample is not None:
            self.ctl.on_post_servo(sample)
        if enable:
            self.until(lambda: self.power.Status, enable_timeout, "axis enabled")

    def add(self, fb: Any, **inputs: Any) -> Any:
        """Call ``fb`` with this axis every application cycle from now on (``inputs`` set first)."""
        fb.Axis = self.axis
        for k, v in inputs.items():
            setattr(fb, k, v)
        self.fbs.append(fb)
        return fb

    def _scan(self) -> None:
        for fb in self.fbs:
            fb()

    def until(self, pred: Callable[[], bool], timeout: float, what: str) -> None:
        """Step the controller until ``pred`` holds; fail naming ``what`` after ``timeout`` seconds."""
        end = self.ctl.time + timeout
        while not pred():
            assert self.ctl.time < end, f"{what}: not within {timeout} s (t = {self.ctl.time:.3f})"
            self.ctl.step()

    def steps(self, n: int) -> None:
        for _ in range(n):
            self.ctl.step()

    def start(self, fb: Any, **inputs: Any) -> Any:
        """A rising edge at Execute of ``fb`` (added if new); the instance is called in the next cycle."""
        if fb not in self.fbs:
            self.add(fb)
        for k, v in inputs.items():
            setattr(fb, k, v)
        fb.Execute = True
        self.ctl.step()
        return fb

    def finish(self, fb: Any, timeout: float, what: str, *, release: bool = True) -> Any:
        """Wait until ``fb`` is Done or has an Error, then take its Execute away - called once more without
        it when ``release`` (its outputs are then those of the falling edge)."""
        self.until(lambda: fb.Done or fb.Error, timeout, what)
        fb.Execute = False
        if release:
            self.ctl.step()
        return fb
