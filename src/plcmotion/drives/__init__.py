"""Drives behind one neutral interface: simulated servo drives, steppers on pulse outputs, ideal drives.

Every drive model takes a :class:`DriveSpec` (``drives.spec``) and serves the kernel through a
:class:`DriveGroup` (per servo cycle, on the bank's arrays) and a :class:`DriveChannel` per axis (events).
"""
from .base import DriveChannel, DriveGroup
from .simulated import ServoDrives, SetpointDrives, new_drive_group
from .spec import (ActuatorKind, DriveSpec, EncoderInterface, EncoderKind, EncoderSpec, PlantSpec, SetpointInterface,
                   SwitchSpec)

__all__ = ["ActuatorKind", "DriveChannel", "DriveGroup", "DriveSpec", "EncoderInterface", "EncoderKind",
           "EncoderSpec", "PlantSpec", "ServoDrives", "SetpointDrives", "SetpointInterface", "SwitchSpec",
           "new_drive_group"]
