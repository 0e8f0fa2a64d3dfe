"""Test rig of the S7-Technology tests: a controller of the family with axes and their MC_Power instances."""
from __future__ import annotations

from typing import Any

from plcmotion import Controller
from plcmotion.s7t import MC_Power

#: a virtual positioning axis that needs no homing for absolute positionings (its actual value is the setpoint)
VIRTUAL = {"Wizard": {"Virtual": 1}, "TypeOfAxis.Homing.referencingNecessary": 0}


def controller(servo_cycle: float = 0.002, app_cycle: float = 0.004, **kw: Any) -> Controller:
    return Controller(family="S7-Technology", servo_cycle=servo_cycle, app_cycle=app_cycle, **kw)


def enabled(params: dict | None = None, *, ctl: Controller | None = None, name: str = "Axis1",
            run: float = 0.1):
    """A controller with one axis enabled by an MC_Power instance called in every OB1 cycle."""
    ctl = ctl or controller()
    axis = ctl.add_positioning_axis(name, VIRTUAL if params is None else params)
    power = MC_Power()

    @ctl.program
    def ob1() -> None:
        power(Axis=axis, Enable=True)
    ctl.run(run)
    assert power.Status, power
    return ctl, axis, power
