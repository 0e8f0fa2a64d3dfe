"""S7-1200 Motion Control V6 dialect: the motion instructions with the manual's inputs, outputs and ErrorIDs.

>>> from plcmotion.s7_1200 import MC_Power, MC_Home, MC_MoveAbsolute
"""
from .command_table import MC_CommandTable
from .errors import codes, describe
from .homing import MC_Home
from .motion import MC_Halt, MC_MoveAbsolute, MC_MoveJog, MC_MoveRelative, MC_MoveVelocity
from .parameters import MC_ChangeDynamic, MC_ReadParam, MC_WriteParam
from .power import MC_Power, MC_Reset

__all__ = ["MC_Power", "MC_Reset", "MC_Home", "MC_Halt", "MC_MoveAbsolute", "MC_MoveRelative",
           "MC_MoveVelocity", "MC_MoveJog", "MC_CommandTable", "MC_ChangeDynamic", "MC_ReadParam",
           "MC_WriteParam", "codes", "describe"]
