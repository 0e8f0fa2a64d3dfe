"""Drives behind one narrow interface: simulated servo drives, steppers on pulse outputs, ideal drives."""
from .base import DriveChannel, DriveGroup
from .simulated import ServoDrives, SetpointDrives

__all__ = ["DriveChannel", "DriveGroup", "ServoDrives", "SetpointDrives"]
