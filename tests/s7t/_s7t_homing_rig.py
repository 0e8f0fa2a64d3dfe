"""Test rig of the homing and monitoring tests: a real positioning axis on the simulated plant with a reference
cam on I0.0 (machine 100..120) and encoder zero marks every 10 starting at 5, enabled by MC_Power in OB1."""
from __future__ import annotations

from typing import Any

from plcmotion.s7t import MC_Home, MC_Power, MC_Reset

from _s7t_rig import controller

ENC = "TypeOfAxis.NumberOfEncoders.Encoder_1.IncHomingEncoder"
CAM_LO, CAM_HI = 100.0, 120.0
V_APPROACH, V_ENTRY, V_REDUCED = 50.0, 20.0, 5.0

REAL_AXIS = {
    f"{ENC}.homingMode": 22, f"{ENC}.logAdressBero": 0, f"{ENC}.bitNumberBero": 0,
    "Plant.HomingSwitchPosition": CAM_LO, "Plant.HomingSwitchLength": CAM_HI - CAM_LO,
    "Plant.ZeroMarkDistance": 10.0, "Plant.ZeroMarkOffset": 5.0,
    "userdefaulthoming": {"homingapproachvelocity": V_APPROACH, "homingentryvelocity": V_ENTRY,
                          "homingreducedvelocity": V_REDUCED},
    "userdefaultdynamics": {"positiveaccel": 200.0, "negativeaccel": 200.0, "positiveaccelstartjerk": 0.0},
    # a narrow positioning window, so that Done means "at the reference point" to a few micrometres
    "TypeOfAxis.PositionMonitoring.tolerance": 0.005,
}


class Rig:
    """One axis with MC_Power (always enabled in OB1), MC_Home and MC_Reset instances."""

    def __init__(self, params: dict[str, Any] | None = None, *, enable: bool = True, **kw: Any):
        self.ctl = controller(**kw)
        merged = dict(REAL_AXIS)
        merged.update(params or {})
        self.axis = self.ctl.add_positioning_axis("Axis1", merged)
        self.power, self.home, self.reset = MC_Power(), MC_Home(), MC_Reset()
        self.enable = enable

        @self.ctl.program
        def ob1() -> None:
            self.power(Axis=self.axis, Enable=self.enable)
        self.ctl.run(0.2)

    @property
    def mech(self) -> float:
        return self.axis.drive.mechanical_position()

    def call(self, fb: Any, duration: float, **inputs: Any) -> Any:
        """Call ``fb`` with ``inputs`` in every OB1 cycle for ``duration`` seconds (Execute held)."""
        end = self.ctl.time + duration
        fb(Axis=self.axis, **inputs)
        while self.ctl.time < end - 1e-9:
            self.ctl.run(self.ctl.app_cycle)
            fb(Axis=self.axis, **inputs)
        return fb

    def until(self, fb: Any, done, limit: float = 30.0, **inputs: Any) -> float:
        """Call ``fb`` every OB1 cycle until ``done(fb)``; returns the time it took."""
        t0 = self.ctl.time
        fb(Axis=self.axis, **inputs)
        while not done(fb):
            assert self.ctl.time - t0 < limit, f"{fb!r} did not finish within {limit} s"
            self.ctl.run(self.ctl.app_cycle)
            fb(Axis=self.axis, **inputs)
        return self.ctl.time - t0

    def acknowledge(self) -> Any:
        self.reset(Axis=self.axis, Execute=False)
        self.reset(Axis=self.axis, Execute=True)
        self.ctl.run(0.02)
        return self.reset
