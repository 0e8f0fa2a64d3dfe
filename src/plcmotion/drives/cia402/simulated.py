"""A simulated CiA 402 servo drive on a CAN bus: a ``canopen`` LocalNode with the object dictionary of
the EDS file shipped here (``cia402_servo.eds``) and a :class:`~.drive_core.DriveCore` inside.

It behaves like a drive on the bus, and nothing else connects it to the master:

* SDO: every object of the EDS reads and writes through the node's SDO server; the 402 objects the drive
  updates itself (statusword, actual values, digital inputs, error code) read their live value;
* NMT: the node starts in PRE-OPERATIONAL and exchanges PDOs only in OPERATIONAL;
* PDOs: communication and mapping parameters 0x1400-0x1A03 are read from the dictionary whenever they are
  written, so a master may map anything mappable (whole bytes); synchronous RPDOs (transmission type
  0-240) take effect at the next SYNC, asynchronous ones (254/255) at once; synchronous TPDOs go out at
  every n-th SYNC, event-driven TPDOs (254/255) whenever their content changed;
* time: the drive has no clock of its own - each SYNC moves it on by the communication cycle period
  0x1006 (or, when that is 0, the interpolation time period 0x60C2), so it runs in the master's virtual
  time and a run is repeatable bit for bit;
* on SYNC it answers synchronously, in this order: the motion of the period just ended, its heartbeat
  (0x1017, counted in SYNC time) and EMCY messages, the synchronous TPDOs sampled now, then the RPDOs
  received before the SYNC take effect;
* EMCY: a fault sends its error code (0x603F) and error register (0x1001); a successful fault reset
  sends the "no error" EMCY.

The node runs on its own ``canopen.Network`` (its own python-can bus and notifier thread), exactly as a
separate device would; tests reach inside only through :meth:`inject_fault`, :meth:`clear_fault`,
:meth:`silence` and :meth:`heartbeat` (a broken device), and read :attr:`position` for checks.
"""
from __future__ import annotations

import struct
import threading
from typing import Any

import canopen
from canopen import objectdictionary as od
from canopen.sdo import SdoAbortedError

from .drive_core import DriveCore, MotorSpec
from .link import EDS_PATH
from .profile import EMCY_GENERIC

_STRUCT = {od.INTEGER8: "b", od.INTEGER16: "h", od.INTEGER32: "i", od.UNSIGNED8: "B", od.UNSIGNED16: "H",
           od.UNSIGNED32: "I", od.BOOLEAN: "?"}
#: the objects the drive itself updates (read live)
_LIVE = {0x6041, 0x6061, 0x6064, 0x606C, 0x6077, 0x603F, 0x1001, 0x60FD, 0x6062, 0x60F4}
_NMT_OPERATIONAL = 0x05


class _Pdo:
    """One PDO as configured in the dictionary: COB-ID, transmission type, mapped (index, subindex, format)."""

    def __init__(self, cob_id: int, trans: int, entries: list[tuple[int, int, str]]):
        self.cob_id, self.trans = cob_id, trans
        self.entries = entries
        self.fmt = "<" + "".join(f for _, _, f in entries)
        self.size = struct.calcsize(self.fmt)
        self.last: bytes | None = None

    @property
    def synchronous(self) -> bool:
        return self.trans <= 240


class SimulatedCia402:
    """A CiA 402 servo drive with node id ``node_id`` for a CAN bus (``connect`` puts it on one)."""

    def __init__(self, node_id: int, *, eds: str = EDS_PATH, motor: MotorSpec = MotorSpec()):
        self.node = canopen.LocalNode(node_id, eds)
        # no wall-clock heartbeat timer of the canopen package: this drive beats in SYNC time
        self.node._write_callbacks.remove(self.node.nmt.on_write)
        self.values: dict[tuple[int, int], int] = {}
        for obj in self.node.object_dictionary.values():
            subs = [obj] if isinstance(obj, od.ODVariable) else list(obj.values())
            for var in subs:
                if var.data_type in _STRUCT:
                    default = var.default if var.default is not None else 0
                    self.values[(var.index, var.subindex)] = int(default)
        self.node.add_read_callback(self._on_read)
        self.node.add_write_callback(self._on_write)
        self.core = DriveCore(self.param, motor)
        self.network: canopen.Network | None = None
        self._lock = threading.RLock()
        self.rpdos: list[_Pdo] = []
        self.tpdos: list[_Pdo] = []
        self._rx: dict[int, bytes] = {}           # synchronous RPDO data waiting for the next SYNC
        self._subscribed: list[int] = []
        self._sync_count = 0
        self.time = 0.0                           # SYNC time [s]
        self._next_beat: float | None = None
        self._silent = False
        self._beating = True
        self._reconfigure()

    # --- the bus ---------------------------------------------------------------------------------------
    def connect(self, network: canopen.Network) -> None:
        """Put the drive on ``network`` (connected to its own bus) and send its boot-up message."""
        self.network = network
        network.add_node(self.node)
        network.subscribe(self.values[(0x1005, 0)] & 0x7FF, self._on_sync)
        self.node.nmt.state = "PRE-OPERATIONAL"     # boot-up: "initialising" -> pre-operational
        self._reconfigure()

    def param(self, index: int, sub: int = 0) -> int:
        return self.values[(index, sub)]

    @property
    def id(self) -> int:
        return self.node.id

    @property
    def position(self) -> int:
        """Position actual value 0x6064 [inc] (for checks from outside)."""
        with self._lock:
            return self.core.position_actual()

    @property
    def state(self) -> str:
        with self._lock:
            return self.core.sm.state.value

    # --- broken devices (tests, demos) -------------------------------------------------------------------
    def inject_fault(self, code: int = EMCY_GENERIC, *, cause: bool = False) -> None:
        """The drive faults at its next SYNC with EMCY ``code``; with ``cause`` a fault reset does not
        clear it until :meth:`clear_fault`."""
        with self._lock:
            self.core.inject_fault(code, cause)

    def clear_fault(self) -> None:
        """The cause of an injected fault is gone (a fault reset can leave FAULT now)."""
        with self._lock:
            self.core.clear_cause()

    def silence(self, on: bool = True) -> None:
        """The drive stops answering anything - SYNC, PDOs, SDO requests (power or cable lost) - or comes
        back."""
        if on != self._silent and self.network is not None:
            sdo = self.node.sdo
            (self.network.unsubscribe if on else self.network.subscribe)(sdo.rx_cobid, sdo.on_request)
        self._silent = on

    def heartbeat(self, on: bool) -> None:
        """Stop (or restart) only the heartbeat producer."""
        self._beating = on

    # --- object dictionary access ----------------------------------------------------------------------
    def _on_read(self, index: int, subindex: int, od: Any) -> int | None:
        if index not in _LIVE:
            return self.values.get((index, subindex))
        with self._lock:
            c = self.core
            return {0x6041: c.statusword, 0x6061: lambda: c.mode, 0x6064: c.position_actual,
                    0x606C: c.velocity_actual, 0x6077: c.torque_actual, 0x603F: lambda: c.error_code,
                    0x1001: lambda: c.error_register, 0x60FD: c.digital_inputs,
                    0x6062: lambda: c.target_position, 0x60F4: lambda: 0}[index]()

    def _on_write(self, index: int, subindex: int, od: Any, data: bytes) -> None:
        fmt = _STRUCT.get(od.data_type)
        if fmt is None:
            raise SdoAbortedError(0x06090030)
        value = struct.unpack("<" + fmt, data)[0]
        if index in _LIVE and index != 0x6040:
            raise SdoAbortedError(0x06010002)           # read only
        if 0x1600 <= index <= 0x1603 or 0x1A00 <= index <= 0x1A03:
            if subindex and value and not self._mappable(value):
                raise SdoAbortedError(0x06040041)       # the object cannot be mapped
        with self._lock:
            self.values[(index, subindex)] = int(value)
            if index in (0x6040, 0x6060):               # device control through SDO takes effect at once
                self._apply_set_values()
            if 0x1400 <= index <= 0x1BFF:
                self._reconfigure()
            if index == 0x1017:
                self._next_beat = self.time if value else None

    def _mappable(self, entry: int) -> bool:
        index, sub, bits = entry >> 16, (entry >> 8) & 0xFF, entry & 0xFF
        try:
            obj = self.node.object_dictionary.get_variable(index, sub)
        except KeyError:
            return False
        return obj is not None and obj.pdo_mappable and obj.data_type in _STRUCT and bits == len(obj)

    def _reconfigure(self) -> None:
        """Rebuild the PDO tables from the communication and mapping parameters."""
        self.rpdos = [p for p in (self._pdo(0x1400 + n, 0x1600 + n) for n in range(4)) if p is not None]
        self.tpdos = [p for p in (self._pdo(0x1800 + n, 0x1A00 + n) for n in range(4)) if p is not None]
        if self.network is None:
            return
        for cob in self._subscribed:
            self.network.unsubscribe(cob, self._on_rpdo)
        self._subscribed = [p.cob_id for p in self.rpdos]
        for cob in self._subscribed:
            self.network.subscribe(cob, self._on_rpdo)

    def _pdo(self, com: int, mapping: int) -> _Pdo | None:
        cob = self.values[(com, 1)]
        if cob & 0x80000000:
            return None
        entries = []
        for k in range(1, self.values[(mapping, 0)] + 1):
            e = self.values[(mapping, k)]
            if not self._mappable(e):
                return None
            var = self.node.object_dictionary.get_variable(e >> 16, (e >> 8) & 0xFF)
            entries.append((var.index, var.subindex, _STRUCT[var.data_type]))
        return _Pdo(cob & 0x7FF, self.values[(com, 2)], entries)

    # --- PDOs -------------------------------------------------------------------------------------------
    def _operational(self) -> bool:
        return self.node.nmt.state == "OPERATIONAL"

    def _on_rpdo(self, can_id: int, data: bytearray, timestamp: float) -> None:
        if self._silent or not self._operational():
            return
        with self._lock:
            for p in self.rpdos:
                if p.cob_id == can_id and len(data) >= p.size:
                    if p.synchronous:
                        self._rx[can_id] = bytes(data)
                    else:
                        self._take(p, bytes(data))
                        self._apply_set_values()
                        self._send_events()

    def _take(self, p: _Pdo, data: bytes) -> None:
        for (index, sub, _), value in zip(p.entries, struct.unpack_from(p.fmt, data)):
            self.values[(index, sub)] = int(value)

    def _apply_set_values(self) -> None:
        v = self.values
        self.core.apply(v[(0x6040, 0)], v[(0x6060, 0)], v[(0x607A, 0)], v[(0x60FF, 0)], v[(0x6071, 0)])

    def _payload(self, p: _Pdo) -> bytes:
        live = {0x6041: self.core.statusword, 0x6061: lambda: self.core.mode,
                0x6064: self.core.position_actual, 0x606C: self.core.velocity_actual,
                0x6077: self.core.torque_actual, 0x603F: lambda: self.core.error_code,
                0x1001: lambda: self.core.error_register, 0x60FD: self.core.digital_inputs}
        values = [live[i]() if i in live else self.values[(i, s)] for i, s, _ in p.entries]
        return struct.pack(p.fmt, *values)

    def _send_events(self) -> None:
        for p in self.tpdos:
            if not p.synchronous:
                data = self._payload(p)
                if data != p.last:
                    p.last = data
                    self.network.send_message(p.cob_id, data)

    def _on_sync(self, can_id: int, data: bytearray, timestamp: float) -> None:
        if self._silent:
            return
        net = self.network
        with self._lock:
            self._sync_count += 1
            period = self.values[(0x1006, 0)] * 1e-6
            if period <= 0:
                period = self.values[(0x60C2, 1)] * 10.0 ** self.values[(0x60C2, 2)]
            self.core.step(period)
            self.time += period
            if self._next_beat is not None and self.time >= self._next_beat - 1e-9:
                self._next_beat += self.values[(0x1017, 0)] * 1e-3
                if self._beating:
                    net.send_message(0x700 + self.id, bytes([self.node.nmt._state & 0x7F]))
            for code, register in self.core.emcy:
                net.send_message(self.values[(0x1014, 0)] & 0x7FF, struct.pack("<HB5x", code, register))
            self.core.emcy.clear()
            if not self._operational():
                return
            for p in self.tpdos:
                if p.synchronous and p.trans and self._sync_count % p.trans == 0:
                    net.send_message(p.cob_id, self._payload(p))
            if self._rx:
                for p in self.rpdos:
                    data = self._rx.pop(p.cob_id, None)
                    if data is not None:
                        self._take(p, data)
                self._apply_set_values()
            self._send_events()


def start_simulated(interface: str, channel: str, node_id: int, *, bitrate: int | None = None,
                    eds: str = EDS_PATH, motor: MotorSpec = MotorSpec()) -> tuple[SimulatedCia402, canopen.Network]:
    """A simulated drive on its own connection to the bus ``interface``/``channel``."""
    network = canopen.Network()
    network.NOTIFIER_CYCLE = 0.05
    kw: dict[str, Any] = {"interface": interface, "channel": channel}
    if bitrate is not None and interface != "virtual":
        kw["bitrate"] = bitrate
    network.connect(**kw)
    drive = SimulatedCia402(node_id, eds=eds, motor=motor)
    drive.connect(network)
    return drive, network
