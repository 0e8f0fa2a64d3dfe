"""Hydraulic axes (S7-Technology V4.1 §3.1.4, §4.6): the speed-controlled, positioning and synchronization
axis on a valve output instead of an electric drive.

They are the axes of ``axes`` with one difference at MC_Power: when Enable falls with StopMode 3 (OFF2Stop,
§6.2.1) the enable is removed at once, the valve output ramps at ``userdefaultqfaxis.maxderivative.qoutput``
(parameter 5009) to MC_Power's QOutputValue and the missing enable is noted as 16#8040 in the technology DB;
after any other stop mode, and when an error removes the enable, the output ramps to 0 % (a closed valve).  :func:`axis_class` picks the class of
an axis from its technology and its drive technology (``Wizard.DriveTechnology``).
"""
from __future__ import annotations

from typing import Any, Mapping

from .axes import AXIS_CLASSES, OFF2_STOP, AxisT, PositioningAxisT, SpeedAxis, SynchronizationAxis
from .builder import POSITIONING, SPEED, SYNCHRONIZATION
from .hydraulic_params import hydraulic
from .to_errors import DISABLED, ERROR_STATUS_BITS


class _Hydraulic:
    """What a hydraulic axis adds to its technology's axis class."""

    hydraulic = True

    def _enable(self: Any, start_mode: int) -> None:
        # the substitute output is MC_Power's after StopMode 3 only: an error that removes the enable of
        # the enabled axis closes the valve (0 %)
        self.drive.set_off_output(0.0)
        super()._enable(start_mode)  # type: ignore[misc]

    def _disable(self: Any, stop_mode: int) -> None:
        off2 = stop_mode == OFF2_STOP
        self.drive.set_off_output(self.q_output_value if off2 else 0.0)
        super()._disable(stop_mode)  # type: ignore[misc]
        if off2:
            self.errors.note(DISABLED, ERROR_STATUS_BITS["UserFault"])   # "enable signals missing" (§6.2.1)


class HydraulicSpeedAxis(_Hydraulic, SpeedAxis):
    """Speed-controlled hydraulic axis."""


class HydraulicPositioningAxis(_Hydraulic, PositioningAxisT):
    """Positioning hydraulic axis."""


class HydraulicSynchronizationAxis(_Hydraulic, SynchronizationAxis):
    """Synchronization hydraulic axis."""


HYDRAULIC_CLASSES = {SPEED: HydraulicSpeedAxis, POSITIONING: HydraulicPositioningAxis,
                     SYNCHRONIZATION: HydraulicSynchronizationAxis}


def axis_class(technology: int, cfg: Mapping[str, Any]) -> type[AxisT]:
    """The class of an axis of ``technology`` with the validated tags ``cfg``."""
    return (HYDRAULIC_CLASSES if hydraulic(cfg) else AXIS_CLASSES)[technology]


__all__ = ["HydraulicSpeedAxis", "HydraulicPositioningAxis", "HydraulicSynchronizationAxis", "HYDRAULIC_CLASSES",
           "axis_class"]
