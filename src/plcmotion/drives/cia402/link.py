"""What connects an axis to a CiA 402 drive: bus, node, mode of operation and a few drive settings
(:class:`Cia402Link`, a ``drives.base.DriveLink``).  Checked when it is made, so a wrong value is found
when the project file is read, not on the bus.  No canopen import here: a project can be checked
without the optional packages."""
from __future__ import annotations

import math
import os
from dataclasses import dataclass, replace
from typing import Any

from ..base import DriveGroup, DriveLink
from ..spec import ActuatorKind, DriveSpec, SetpointInterface
from .profile import AXIS_MODES

#: the object dictionary of the simulated drive, shipped with the package
EDS_PATH = os.path.join(os.path.dirname(__file__), "cia402_servo.eds")

#: the fields a project's ``[drives.<axis>]`` table may set, with their meaning (docs/drives/cia402.md)
FIELDS = {
    "type": 'the drive kind: "cia402"',
    "interface": 'the python-can interface: "socketcan" in the field, "virtual" in tests and demos',
    "channel": 'the CAN channel: "can0" (socketcan), any name on the virtual bus',
    "node_id": "the drive's CANopen node id, 1..127",
    "mode": 'mode of operation: "csp", "csv", "cst" (cyclic synchronous), "pp", "pv" (profile)',
    "simulate": "start a simulated CiA 402 drive with this node id on the bus (true/false)",
    "bitrate": "CAN bit rate [bit/s] for interfaces that set it (e.g. 1000000)",
    "heartbeat_ms": "producer heartbeat time written to the drive [ms], 0 = off",
    "eds": "the drive's EDS file (default: the generic servo shipped with plcmotion)",
    "increments_per_revolution": "position encoder resolution 0x608F [inc per motor revolution] (default: "
                                 "read from the drive)",
    "speed_gain": "cst mode: the master's speed controller [per mille of rated torque per motor rev/s]",
    "realtime": "pace the servo cycle to the wall clock (default: true except on the virtual bus)",
}


class LinkError(ValueError):
    """A CiA 402 link setting that cannot be used; ``field`` names it."""

    def __init__(self, field: str, message: str):
        self.field = field
        super().__init__(f"{field}: {message}")


@dataclass(frozen=True)
class Cia402Link(DriveLink):
    """A CiA 402 drive on a CAN bus, for ``Controller.connect_drive(axis, link)``."""

    interface: str = "virtual"
    channel: str = "plcmotion"
    node_id: int = 1
    mode: str = "csp"
    simulate: bool = False
    bitrate: int | None = None
    heartbeat_ms: int = 100
    eds: str = EDS_PATH
    increments_per_revolution: int | None = None
    speed_gain: float = 200.0
    realtime: bool | None = None

    def __post_init__(self) -> None:
        for name in ("interface", "channel", "mode", "eds"):
            value = getattr(self, name)
            if not isinstance(value, str) or not value:
                raise LinkError(name, f"must be a non-empty string, got {value!r}")
        if self.mode not in AXIS_MODES:
            raise LinkError("mode", f"{self.mode!r} is no mode of operation for an axis; one of "
                            + ", ".join(repr(m) for m in AXIS_MODES))
        _int(self.node_id, "node_id", 1, 127, "a CANopen node id")
        if not isinstance(self.simulate, bool):
            raise LinkError("simulate", f"must be true or false, got {self.simulate!r}")
        if self.bitrate is not None:
            _int(self.bitrate, "bitrate", 10_000, 1_000_000, "a CAN bit rate [bit/s]")
        _int(self.heartbeat_ms, "heartbeat_ms", 0, 65535, "a heartbeat time [ms] (0 = off)")
        if self.increments_per_revolution is not None:
            _int(self.increments_per_revolution, "increments_per_revolution", 1, 2**32 - 1,
                 "increments per motor revolution")
        g = self.speed_gain
        if isinstance(g, bool) or not isinstance(g, (int, float)) or not math.isfinite(g) or not 0 < g <= 1e6:
            raise LinkError("speed_gain", f"must be a number in (0, 1e6], got {g!r}")
        if self.realtime is not None and not isinstance(self.realtime, bool):
            raise LinkError("realtime", f"must be true or false, got {self.realtime!r}")
        if not os.path.isfile(self.eds):
            raise LinkError("eds", f"no EDS file at {self.eds!r}")

    @property
    def group_key(self) -> str:            # type: ignore[override]
        return f"cia402:{self.interface}:{self.channel}"

    @property
    def paced(self) -> bool:
        """Whether the servo cycle waits for the wall clock (a real bus) or runs as fast as it can."""
        return self.realtime if self.realtime is not None else self.interface != "virtual"

    def new_group(self, bank: Any) -> DriveGroup:
        from .master import Cia402Drives     # canopen is needed from here on
        return Cia402Drives(self.interface, self.channel, bitrate=self.bitrate, paced=self.paced)

    def bind(self, spec: DriveSpec) -> DriveSpec:
        if spec.actuator is not ActuatorKind.SPEED_SERVO:
            what = "a stepper on a pulse output" if spec.actuator is ActuatorKind.PULSE else "a simulated axis"
            raise ValueError(f"a CiA 402 drive (connect_drive, [drives.<axis>]) needs an axis with a drive and an "
                             f"encoder (a servo axis); this axis is configured as {what}")
        return replace(spec, interface=SetpointInterface.CANOPEN, link=self)


def _int(value: Any, field: str, low: int, high: int, what: str) -> None:
    if isinstance(value, bool) or not isinstance(value, int):
        raise LinkError(field, f"must be an integer ({what}), got {value!r}")
    if not low <= value <= high:
        raise LinkError(field, f"{value} is out of range; {what} in [{low}, {high}]")
