"""S7-1200 Motion Control technology objects (V6/V7) and their registration as the family "S7-1200".

The positioning axis is the kernel's axis with the S7-1200 schema and status tags (``axis``, ``parameters``,
``builder``, ``tags``); the family's own objects are the command table (``command_table``) and the component
that runs it on an axis (``table_runner``; ``axis.table_runner``).  This package says how a controller of this
family creates them and which version-dependent rules apply.  ``plcmotion`` imports it on import.
"""
from __future__ import annotations

from typing import Any, Mapping

from ...kernel import family as K
from .axis import PositioningAxis
from .command_table import CommandTable
from .override import POLICY
from .parameters import S7_1200 as SCHEMA
from .table_runner import TableRunner


def _rules(version: int) -> frozenset[str]:
    # S7-1200 V7 rules (docs/decisions.md rows 49 and 54): a new command on a PTO axis waits for the next
    # Actor.PTOSliceTime boundary; MC_Home Mode 0/1 also works on a disabled PROFIdrive/analog axis
    return frozenset({K.PULSE_SLICE_TIME, K.DIRECT_HOMING_WHEN_DISABLED}) if version >= 7 else frozenset()


def _positioning_axis(ctl: Any, name: str, flat: Mapping[str, Any], where: str) -> PositioningAxis:
    axis = ctl.new_axis(PositioningAxis, name, flat, where)
    axis.table_runner = axis.attach_runner(TableRunner(axis))     # MC_CommandTable (§11.1.9)
    if ctl.technology_version >= 7:
        axis._use_v7_tags()              # V7 status tags: StatusSensor[1], ErrorBits.AdaptionError
    return axis


def _command_table(ctl: Any, name: str, commands: Any) -> CommandTable:
    return CommandTable(ctl, name, commands)


S7_1200 = K.register(K.Family("S7-1200", versions=(6, 7), default_version=6,
                              factories={K.POSITIONING_AXIS: _positioning_axis, K.COMMAND_TABLE: _command_table},
                              rules=_rules, policy=POLICY, schemas={K.POSITIONING_AXIS: SCHEMA}))

__all__ = ["S7_1200"]
