"""Pilz drive axes with the motion core of Pilz motion commands V6.5: the register interface and PLCopen-style
function blocks over it.

>>> from plcmotion import Controller
>>> from plcmotion.pilz import MC_MoveAbsolute
>>> ctl = Controller(family="Pilz")
>>> axis = ctl.add_positioning_axis("X", {"I10": 500.0})

A program either drives the command register directly (``axis.registers.I401 = 1`` ... ``axis.registers.I402 =
True``, status in ``axis.status``) or uses the blocks (``MC_MoveAbsolute(Axis=axis, Execute=True, ...)``).
See docs/pilz/index.md.
"""
from .motion import (INPUT_REFUSED, NOT_A_DRIVE_AXIS, MC_CyclicPosition, MC_CyclicSpeed, MC_Halt, MC_Home,
                     MC_MoveAbsolute, MC_MoveAdditive, MC_MoveRelative, MC_MoveSpeed, MC_MoveVelocity, MC_Stop,
                     MC_TorqueControl, MotionCommand)
from .signals import trace_signals
from .technology import PILZ, Cause, DriveAxis
from .technology.registers import CommandRegister, RegisterError, StatusWords

__all__ = ["Cause", "CommandRegister", "DriveAxis", "INPUT_REFUSED", "MC_CyclicPosition", "MC_CyclicSpeed",
           "MC_Halt", "MC_Home", "MC_MoveAbsolute", "MC_MoveAdditive", "MC_MoveRelative", "MC_MoveSpeed",
           "MC_MoveVelocity", "MC_Stop", "MC_TorqueControl", "MotionCommand", "NOT_A_DRIVE_AXIS", "PILZ",
           "RegisterError", "StatusWords", "trace_signals"]
