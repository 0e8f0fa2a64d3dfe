"""Drives behind one neutral interface: simulated servo drives, steppers on pulse outputs, ideal drives,
hydraulic axes (valve and cylinder).

Every drive model takes a :class:`DriveSpec` (``drives.spec``) and serves the kernel through a
:class:`DriveGroup` (per servo cycle, on the bank's arrays) and a :class:`DriveChannel` per axis (events).
"""
from .base import DriveChannel, DriveGroup
from .simulated import ServoDrives, SetpointDrives, new_drive_group
from .hydraulic_spec import CylinderSpec, HydraulicSpec, ValveType
from .spec import (ActuatorKind, DriveSpec, EncoderInterface, EncoderKind, EncoderSpec, PlantSpec, SetpointInterface,
                   SwitchSpec)
from .spec_errors import DriveSpecError
from .valve import ValveCharacteristic

__all__ = ["ActuatorKind", "CylinderSpec", "DriveChannel", "DriveGroup", "DriveSpec", "DriveSpecError",
           "EncoderInterface", "EncoderKind", "EncoderSpec", "HydraulicSpec", "PlantSpec", "ServoDrives",
           "SetpointDrives", "SetpointInterface", "SwitchSpec", "ValveCharacteristic", "ValveType", "new_drive_group"]
