"""Kinds of technology object the S7-Technology V4.1 tables are keyed by (manual chapters 3, 7 and 9.4).

The parameter list (§9.4) has one table for all axes and says per entry which axis technologies it serves;
the ErrorID tables (§7.12) are split by technology DB.  ``TOKind`` names both without importing the family's
technology objects, so the tables stay plain data.
"""
from __future__ import annotations

from enum import Enum


class TOKind(str, Enum):
    """A technology object type as the parameter list and the ErrorID tables distinguish them."""
    AXIS = "Axis"                                    # speed-controlled, positioning and synchronization axis
    EXTERNAL_ENCODER = "ExternalEncoder"
    OUTPUT_CAM = "OutputCam"
    CAM_TRACK = "CamTrack"
    CAM = "Cam"
    MEASURING_INPUT = "MeasuringInput"
    MCDEVICE = "MCDevice"
    TRACE = "Trace"

    def __str__(self) -> str:
        return self.value


class AxisType(str, Enum):
    """Axis technology as the "Supported for" column of §9.4 names it; a hydraulic axis is one of these with a
    valve drive (§3.1.4)."""
    SPEED = "speed-controlled"
    POSITIONING = "positioning"
    SYNCHRONIZATION = "synchronization"

    def __str__(self) -> str:
        return self.value
