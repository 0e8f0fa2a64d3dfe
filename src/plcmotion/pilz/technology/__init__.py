"""Pilz drive axes with the motion core of the 6th-generation drive controllers (Pilz V6.5), registered as the
family "Pilz".

``DriveAxis`` (``axis``) is the kernel's axis with the motion core (``core``: command register and status
words), the Pilz referencing (``referencing``, ``homing_methods``), the override policy of Command Mode I409
(``override``), the denial causes and their I90 values (``causes``) and the front-end mapping tables
(``front_ends``).  ``plcmotion`` imports this package on import.
"""
from __future__ import annotations

from typing import Any, Mapping

from ...kernel import family as K
from .axis import DriveAxis
from .causes import Cause
from .override import JOB_KINDS, POLICY
from .parameters import PILZ_AXIS


def _drive_axis(ctl: Any, name: str, flat: Mapping[str, Any], where: str) -> DriveAxis:
    return ctl.new_axis(DriveAxis, name, flat, where)


def describe_fault(fault: Any) -> str:
    """How a summary names a fault of a Pilz axis: the I90 cause the motion core reports for it."""
    from .core import cause_of

    cause = cause_of(fault)
    return f"I90 = {int(cause)} ({cause.name.lower().replace('_', ' ')}): {fault}"


PILZ = K.register(K.Family("Pilz", versions=(65,), default_version=65,
                           factories={K.POSITIONING_AXIS: _drive_axis}, job_kinds=JOB_KINDS, policy=POLICY,
                           schemas={K.POSITIONING_AXIS: PILZ_AXIS}, describe_fault=describe_fault))

__all__ = ["Cause", "DriveAxis", "PILZ"]
