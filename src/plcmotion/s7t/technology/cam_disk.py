"""A minimal cam disk technology object: what MC_SetCharacteristic needs of one (S7-Technology V4.1 §3.5,
§4.6.4, §7.5).

A valve profile is a cam disk whose leading value is the valve output [%] and whose following value is the
velocity it gives.  The cam disk TO with its FBs (MC_CamClear, MC_CamSectorAdd, MC_CamInterpolate, ...) is
issue 12; until then :func:`add_cam_disk` creates one from points (linear interpolation between them) or from
an interpolated kernel cam (``kernel.cam_curve.CamCurve``), with a technology DB number so that instructions
can name it by number.  Its technology DB carries only the common members (UpdateCounter, ErrorID,
ErrorBuffer).
"""
from __future__ import annotations

from typing import Any, Sequence

from ...drives.spec_errors import DriveSpecError
from ...drives.valve import ValveCharacteristic
from ...kernel.errors import ConfigurationError
from ...kernel.schema import Issue
from .device import TechnologyDevice
from .tdb import TechnologyDB


class CamDiskDB(TechnologyDB):
    """The technology DB of a cam disk (§7.5; members of the common part only)."""

    kind = "cam disk technology DB"


class CamDisk:
    """A cam disk TO: name, technology DB number and the cam (points or an interpolated kernel cam)."""

    def __init__(self, name: str, number: int, cam: Any):
        self.name = name
        self.db_number = number
        self.cam = cam
        self.db = CamDiskDB(number)
        self.characteristic = _characteristic(cam)

    def __repr__(self) -> str:
        return f"<CamDisk {self.name} DB{self.db_number}>"


def _characteristic(cam: Any) -> ValveCharacteristic:
    """The valve characteristic of a cam used as valve profile (a DriveSpecError if it cannot be one)."""
    if hasattr(cam, "bp") and callable(getattr(cam, "value", None)):
        return ValveCharacteristic.from_curve(cam)
    return ValveCharacteristic(tuple(tuple(p) for p in cam))


def add_cam_disk(ctl: Any, name: str, cam: Sequence[tuple[float, float]] | Any, *,
                 db_number: int | None = None) -> CamDisk:
    """Create the cam disk ``name`` on the S7-Technology controller ``ctl``: ``cam`` is a list of points
    (leading value, following value) or an interpolated kernel cam.  A cam that cannot be a valve profile
    (not monotonic, no standstill, outputs beyond +-100 %) is a ConfigurationError naming the point."""
    ext = ctl.extension
    if not isinstance(ext, TechnologyDevice):
        raise TypeError(f"not an S7-Technology controller: {ctl!r}")
    where = f"cam disk {name!r}"
    number = ext.db_number(db_number, where)
    try:
        disk = CamDisk(name, number, cam)
    except DriveSpecError as exc:
        raise ConfigurationError(where, [Issue(exc.field, "rule:valve_profile", exc.value, exc.allowed)]) from None
    ext.register_object(disk)
    return disk


__all__ = ["CamDisk", "CamDiskDB", "add_cam_disk"]
