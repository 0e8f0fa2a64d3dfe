"""S7-1500/S7-1500T Motion Control instructions (technology version V5, TIA Portal V16).

>>> from plcmotion import Controller
>>> from plcmotion.s7_1500 import MC_Power, MC_GearIn
"""
from .cam import MC_GetCamFollowingValue, MC_GetCamLeadingValue, MC_InterpolateCam
from .errors import describe
from .homing import MC_Home
from .motion import (MC_Halt, MC_MoveAbsolute, MC_MoveJog, MC_MoveRelative, MC_MoveSuperimposed, MC_MoveVelocity,
                     MC_Stop)
from .power import MC_Power, MC_Reset
from .sync import (MC_CamIn, MC_GearIn, MC_GearInPos, MC_LeadingValueAdditive, MC_PhasingAbsolute,
                   MC_PhasingRelative, MC_SynchronizedMotionSimulation)

__all__ = ["MC_Power", "MC_Reset", "MC_Home", "MC_Halt", "MC_Stop", "MC_MoveAbsolute", "MC_MoveRelative",
           "MC_MoveVelocity", "MC_MoveJog", "MC_MoveSuperimposed", "MC_GearIn", "MC_GearInPos", "MC_CamIn",
           "MC_PhasingRelative", "MC_PhasingAbsolute", "MC_SynchronizedMotionSimulation",
           "MC_LeadingValueAdditive", "MC_InterpolateCam", "MC_GetCamLeadingValue", "MC_GetCamFollowingValue",
           "describe"]
