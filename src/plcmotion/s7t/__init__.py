"""S7-Technology V4.1 (CPU 31xT) instructions: the FB 4xx of the S7-Tech library on plcmotion's kernel.

>>> from plcmotion import Controller
>>> from plcmotion.s7t import MC_Power, MC_MoveAbsolute
>>> ctl = Controller(family="S7-Technology")

An instruction's ``Axis`` input takes the technology object or the number of its technology DB; the
technology DB of an axis is ``axis.db`` (a snapshot updated every ``db_update_ratio`` IPO cycles), the
MCDevice DB ``s7t.device(ctl).mcdevice``; programs that run after every DB update (OB65) are registered
with ``@s7t.ob65(ctl)``.
"""
from __future__ import annotations

from typing import Any, Callable

from . import errors
from .errors import describe
from .drive_functions import MC_SetCharacteristic, MC_SetTorqueLimit
from .end_pos import MC_MoveToEndPos
from .dataset import MC_ChangeDataset
from .homing import MC_Home
from .move import MC_MoveAbsolute, MC_MoveAdditive, MC_MoveRelative, MC_MoveSuperImposed, MC_MoveVelocity
from .activation import MC_ActivateDPSlave, MC_ActivateTO
from .parameter_fbs import MC_ReadSysParameter, MC_WriteParameter
from .periphery import MC_ReadPeriphery, MC_WritePeriphery
from .power import MC_Power, MC_Reset
from .records import MC_ReadDriveParameter, MC_ReadRecord, MC_WriteDriveParameter, MC_WriteRecord
from .stop import MC_Halt, MC_Stop
from .technology import NAME, TechnologyDevice, device
from .technology.cam_disk import CamDisk, add_cam_disk


def ob65(ctl: Any, fn: Callable[[], Any] | None = None, *, name: str | None = None):
    """Register ``fn`` as an OB65 program of ``ctl``: it runs after every technology DB update (§5.1, §7.11).
    Use as ``@s7t.ob65(ctl)`` or ``s7t.ob65(ctl, fn)``."""
    return device(ctl).ob65(fn, name=name)


__all__ = ["MC_Power", "MC_Reset", "MC_Home", "MC_Stop", "MC_Halt", "MC_MoveAbsolute", "MC_MoveRelative",
           "MC_MoveAdditive", "MC_MoveSuperImposed", "MC_MoveVelocity", "MC_MoveToEndPos", "MC_SetTorqueLimit",
           "MC_SetCharacteristic", "MC_ChangeDataset", "MC_ReadSysParameter", "MC_WriteParameter", "MC_ReadPeriphery",
           "MC_WritePeriphery", "MC_ReadRecord", "MC_WriteRecord", "MC_ReadDriveParameter", "MC_WriteDriveParameter",
           "MC_ActivateTO", "MC_ActivateDPSlave", "CamDisk", "add_cam_disk", "NAME", "TechnologyDevice", "device",
           "ob65", "describe", "errors"]
