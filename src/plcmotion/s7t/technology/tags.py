"""The members of an axis technology DB as tags of the axis (S7-Technology V4.1 §7.1-§7.3).

A program of this family reads an axis through its technology DB (``axis.db.ActualPosition``); the same
members are tag paths of the axis (``axis.tag("ActualPosition")``, ``"Table.Statusword.Standstill"`` in a
trace or a project's ``[trace]`` section), so traces and the command line name the columns as the manual
names the members.  They read the technology DB, i.e. the values of the last DB update (§7.11): a trace
shows what the user program sees.  ``ErrorBuffer[0..2]`` stays a member of ``axis.db`` only (an ARRAY, no
traceable number).
"""
from __future__ import annotations

from types import MappingProxyType
from typing import Any, Callable, Mapping


def _member(name: str) -> Callable[[Any], Any]:
    return lambda axis: getattr(axis.db, name)


#: members of every axis technology DB (speed-controlled axis, §7.1) and their data types
_COMMON: dict[str, str] = {
    "Statusword": "DWORD", "ErrorID": "WORD", "ErrorStatus": "DWORD", "UpdateFlag": "WORD",
    "UpdateCounter": "WORD", "CommandVelocity": "REAL", "CommandAcceleration": "REAL", "ActualVelocity": "REAL",
    "ActualAcceleration": "REAL", "SpeedOverride": "REAL", "AccelerationOverride": "REAL"}
#: the members positioning and synchronization axes have in addition (§7.2, §7.3)
_POSITION: dict[str, str] = {
    "ActualPosition": "REAL", "CommandPosition": "REAL", "TargetPosition": "REAL", "Distance": "REAL",
    "DecelerationDistance": "REAL", "FollowingError": "REAL"}

SPEED_TYPES: Mapping[str, str] = MappingProxyType(dict(_COMMON))
POSITION_TYPES: Mapping[str, str] = MappingProxyType({**_COMMON, **_POSITION})
SPEED_TAGS: dict[str, Callable[[Any], Any]] = {name: _member(name) for name in SPEED_TYPES}
POSITION_TAGS: dict[str, Callable[[Any], Any]] = {name: _member(name) for name in POSITION_TYPES}

_BITS = ("DriveEnabled", "HomingDone", "Done", "Error", "Standstill", "ConstantVelocity", "Accelerating",
         "Decelerating")
#: what ``Trace(ctl)`` and ``plcmotion run --trace`` record of an axis when no signals are given
POSITION_TRACE = ("CommandPosition", "ActualPosition", "CommandVelocity", "ActualVelocity", "CommandAcceleration",
                  "FollowingError") + tuple(f"Statusword.{b}" for b in _BITS + ("PositioningCommand", "SpeedCommand"))
SPEED_TRACE = ("CommandVelocity", "ActualVelocity", "CommandAcceleration") + tuple(
    f"Statusword.{b}" for b in _BITS if b != "HomingDone") + ("Statusword.SpeedCommand",)
#: the two values ``plcmotion run`` prints per axis at the end of a run
POSITION_SUMMARY = ("CommandPosition", "ActualPosition")
SPEED_SUMMARY = ("CommandVelocity", "ActualVelocity")

__all__ = ["SPEED_TAGS", "POSITION_TAGS", "SPEED_TYPES", "POSITION_TYPES", "POSITION_TRACE", "SPEED_TRACE",
           "POSITION_SUMMARY", "SPEED_SUMMARY"]
