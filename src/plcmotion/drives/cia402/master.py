"""The master side: the CiA 402 drives on one CAN bus as one kernel drive group (set-up and the cycle).

One servo cycle of the group (``read`` at the start of the cycle, ``write`` at its end):

``read(t)``
    sends SYNC and waits - bounded - until every node that answered last cycle has sent its two
    synchronous TPDOs (statusword, position actual, mode display; velocity actual, torque actual, error
    code).  Those carry the values the drives sampled at this SYNC; heartbeats and EMCY messages a node
    sent before them are in by then as well, because a node's frames arrive in the order it sent them.
    Then, per node: the power state from the statusword, faults (statusword FAULT or an EMCY with an
    error code) reported once to the axis as a drive fault, heartbeat and PDO timeouts reported as a
    communication loss, and the actual values converted into the bank.
``write(t)``
    sends each node's RPDO: the controlword (the next step of the power state machine towards what the
    kernel asked, a fault reset edge after MC_Reset, the new-set-point handshake in pp), the set value
    of the mode (target position from ``sp_p`` in csp/pp, target velocity from ``cmd_v`` in csv/pv,
    target torque from the master's speed controller on ``cmd_v`` in cst) and the mode of operation.
    A synchronous RPDO takes effect in the drive at the next SYNC: the next ``read``.

So the bus carries, per node and cycle, one RPDO, one SYNC (shared) and two TPDOs, and the group's
outcome depends on the frames only, never on thread timing: with the simulated drive (which answers on
its own notifier thread, synchronously on SYNC) the same program gives the same trace bit for bit.  On a
real bus the group paces the virtual time to the wall clock (``Cia402Link.realtime``), and the waiting is
bounded by 80 % of the servo cycle (``VIRTUAL_WAIT`` on the virtual bus, where a loaded machine may
schedule the simulated drive's thread late).  A node that missed a cycle is not waited for until its
TPDOs come again, only looked for during 2 ms: a lost node costs one bounded wait, and one that comes back
is found again.  What each node's values mean for its axis is ``channel.Cia402Channel``.

Units: position [inc] = (axis position - homing offset) / increment, increment = load travel per motor
revolution / increments per motor revolution (0x608F); velocities in inc/s.
"""
from __future__ import annotations

import atexit
import threading
import time
import weakref
from typing import Any

import canopen
from canopen.sdo import SdoAbortedError, SdoCommunicationError

from ..base import DriveChannel, DriveGroup
from ..spec import DriveSpec
from .channel import Cia402Channel
from .drive_core import MotorSpec
from .homing import switch_plant
from .link import Cia402Link
from .profile import Mode

_NMT_START, _NMT_PRE_OPERATIONAL = 0x01, 0x80
#: the bound of the wait for TPDOs on the virtual bus [s] (wall clock; generous: it only costs when a node
#: is lost, and a late thread must not look like a lost node)
VIRTUAL_WAIT = 0.5
#: SDO response timeout while a node is set up [s]; on the virtual bus the simulated drive answers from a
#: thread of this process, which a loaded machine may schedule late (a lost node then costs this much longer)
SDO_TIMEOUT = 1.0
VIRTUAL_SDO_TIMEOUT = 3.0
#: virtual CAN channel -> the group that has it (``Cia402Drives._claim_virtual``)
_VIRTUAL_OWNERS: dict[str, "Cia402Drives"] = {}
#: groups with an open bus: closed at interpreter exit, so that no notifier thread outlives the program
_OPEN: "weakref.WeakSet[Cia402Drives]" = weakref.WeakSet()


@atexit.register
def _close_all() -> None:
    for group in list(_OPEN):
        group.close()


class Cia402Error(ConnectionError):
    """A CiA 402 drive could not be set up on its bus (no answer, an object it refuses)."""


class Cia402Drives(DriveGroup):
    """The CiA 402 drives on one CAN bus (``interface``/``channel``)."""

    #: the kernel's position controller computes ``cmd_v`` for them (csv/pv targets, cst's speed controller)
    closed_loop = True

    def __init__(self, interface: str, channel: str, *, bitrate: int | None = None, paced: bool = False):
        self.interface, self.channel, self.bitrate, self.paced = interface, channel, bitrate, paced
        self._claim_virtual()
        self.network = self._connect()
        _OPEN.add(self)
        self.sim_network: canopen.Network | None = None
        self.members: list[Cia402Channel] = []
        self.by_id: dict[int, Cia402Channel] = {}
        self.simulated: dict[int, Any] = {}
        self.servo_cycle = 0.001
        self.now = 0.0
        self._cond = threading.Condition()
        self._rx: dict[int, bytes] = {}
        self._pending: set[int] = set()
        self._events: list[tuple[int, bytes]] = []
        self._wall0: float | None = None
        self._t0 = 0.0
        self.late_cycles = 0              # cycles in which a node's TPDOs did not arrive in time
        self._what = ""                   # the object an SDO set-up is writing (for its error message)

    def _claim_virtual(self) -> None:
        """python-can's virtual bus is one per process: a virtual channel belongs to one controller at a time,
        and opening it again closes the earlier controller's connection (and its simulated drives), as if
        that controller had been switched off - a controller dropped without ``close`` cannot disturb the
        next one."""
        if self.interface != "virtual":
            return
        earlier = _VIRTUAL_OWNERS.get(self.channel)
        if earlier is not None and earlier is not self:
            earlier.close()
        _VIRTUAL_OWNERS[self.channel] = self

    def _connect(self) -> canopen.Network:
        network = canopen.Network()
        network.NOTIFIER_CYCLE = 0.05           # the notifier thread notices a disconnect within 50 ms
        kw: dict[str, Any] = {"interface": self.interface, "channel": self.channel}
        if self.bitrate is not None and self.interface != "virtual":
            kw["bitrate"] = self.bitrate
        try:
            network.connect(**kw)
        except Exception as exc:  # noqa: BLE001 - python-can raises many kinds; name the bus
            raise Cia402Error(f"CAN bus {self.interface}/{self.channel} cannot be opened: {exc}") from None
        return network

    # --- members --------------------------------------------------------------------------------------
    def add(self, index: int, spec: DriveSpec, servo_cycle: float, t: float) -> DriveChannel:
        link: Cia402Link = spec.link
        if link.node_id in self.by_id:
            raise Cia402Error(f"node {link.node_id} on {self.interface}/{self.channel} drives another axis already")
        self.servo_cycle, self.now = servo_cycle, t
        ch = Cia402Channel(self, index, spec, link)
        inc = link.increments_per_revolution
        if link.simulate:
            from .simulated import SimulatedCia402
            if self.sim_network is None:
                self.sim_network = self._connect()
            per_rev = inc or spec.encoder.steps_per_revolution << spec.encoder.fine_bits
            scale = per_rev / spec.length_per_revolution          # increments per length unit
            motor = MotorSpec(speed_time_constant=spec.plant.speed_time_constant,
                              initial_position=spec.plant.initial_position * scale,
                              plant=switch_plant(spec.plant, scale, per_rev))
            sim = SimulatedCia402(link.node_id, eds=link.eds, motor=motor)
            sim.connect(self.sim_network)
            self.simulated[link.node_id] = ch.simulated = sim
        self._configure(ch, spec, servo_cycle)
        ch.last_heartbeat = t
        self.members.append(ch)
        self.by_id[link.node_id] = ch
        tp1, tp2 = 0x180 + link.node_id, 0x280 + link.node_id
        self.network.subscribe(tp1, self._on_tpdo)
        self.network.subscribe(tp2, self._on_tpdo)
        self.network.subscribe(0x80 + link.node_id, self._on_event)
        self.network.subscribe(0x700 + link.node_id, self._on_event)
        ch.remote.nmt.send_command(_NMT_START)
        return ch

    def _configure(self, ch: Cia402Channel, spec: DriveSpec, servo_cycle: float) -> None:
        """SDO set-up of a node in PRE-OPERATIONAL: timing, heartbeat, PDO mapping, mode, units, ramps."""
        link = ch.link
        node = canopen.RemoteNode(link.node_id, link.eds)
        self.network.add_node(node)
        node.sdo.RESPONSE_TIMEOUT = VIRTUAL_SDO_TIMEOUT if self.interface == "virtual" else SDO_TIMEOUT
        ch.remote = node
        nid = link.node_id
        what = "NMT pre-operational"
        try:
            node.nmt.send_command(_NMT_PRE_OPERATIONAL)
            sdo = node.sdo
            what = ""
            what = self._scaling(ch, spec)
            us = int(round(servo_cycle * 1e6))
            value, exp = (us // 100, -4) if us % 1000 else (us // 1000, -3)
            for what, index, sub, v in (
                    ("0x1006 communication cycle period", 0x1006, None, us),
                    ("0x60C2 interpolation time period", 0x60C2, 1, min(value, 255)),
                    ("0x60C2 interpolation time index", 0x60C2, 2, exp),
                    ("0x1017 producer heartbeat time", 0x1017, None, link.heartbeat_ms),
                    ("0x6060 modes of operation", 0x6060, None, int(ch.mode))):
                (sdo[index] if sub is None else sdo[index][sub]).raw = v
            target = {Mode.CYCLIC_SYNC_VELOCITY: (0x60FF, 32), Mode.PROFILE_VELOCITY: (0x60FF, 32),
                      Mode.CYCLIC_SYNC_TORQUE: (0x6071, 16)}.get(ch.mode, (0x607A, 32))
            maps = {0x1400: (0x200 + nid, [(0x6040, 16), target, (0x6060, 8)]),
                    0x1800: (0x180 + nid, [(0x6041, 16), (0x6064, 32), (0x6061, 8)]),
                    0x1801: (0x280 + nid, [(0x606C, 32), (0x6077, 16), (0x603F, 16)])}
            for com in (0x1400, 0x1401, 0x1402, 0x1403, 0x1800, 0x1801, 0x1802, 0x1803):
                what = f"PDO 0x{com:04X}"
                cob = sdo[com][1].raw
                sdo[com][1].raw = cob | 0x80000000
                if com not in maps:
                    continue
                cob_id, entries = maps[com]
                mapping = com + 0x200
                sdo[com][2].raw = 1                     # synchronous, every SYNC
                sdo[mapping][0].raw = 0
                for k, (index, bits) in enumerate(entries, 1):
                    sdo[mapping][k].raw = (index << 16) | bits
                sdo[mapping][0].raw = len(entries)
                sdo[com][1].raw = cob_id
            what = "0x6064 position actual value"
            ch.position = sdo[0x6064].raw
        except (SdoCommunicationError, SdoAbortedError, KeyError) as exc:
            what = what or self._what
            hint = " (is the drive on the bus, with this node id and bit rate?)" \
                if isinstance(exc, SdoCommunicationError) else ""
            raise Cia402Error(f"CiA 402 drive node {nid} on {self.interface}/{self.channel}: {what}: {exc}{hint}"
                              ) from None
        ch.off = spec.plant.initial_position - ch.position * ch.q if link.simulate else 0.0

    def _scaling(self, ch: Cia402Channel, spec: DriveSpec) -> str:
        """SDO: what follows from the axis's mechanics and drive data - the position encoder resolution
        0x608F (from the link; for a simulated drive from the axis's encoder) and with it the feed constant
        0x6092 of the factor group (when the EDS has it), polarity 0x607E, max motor
        speed 0x6080, the quick stop, profile acceleration and deceleration 0x6085/0x6083/0x6084 (the
        maximum velocity within the off-ramp time) and profile velocity 0x6081 - and the channel's
        increment ``q`` [length unit per increment].  At set-up and again when the mechanics change at run
        time (``Cia402Channel.reconfigure``).  Returns "" (the name of the object being written is kept for
        the error message of a failure)."""
        sdo, link = ch.remote.sdo, ch.link
        self._what = "0x608F position encoder resolution"
        inc = link.increments_per_revolution
        if inc is None and link.simulate:
            inc = spec.encoder.steps_per_revolution << spec.encoder.fine_bits
        if inc is not None:
            sdo[0x608F][1].raw = inc
            sdo[0x608F][2].raw = 1
        resolution = (sdo[0x608F][1].raw, max(sdo[0x608F][2].raw, 1))
        if 0x6092 in ch.remote.object_dictionary:
            # the factor group: a feed constant of one encoder resolution per shaft revolution makes the
            # drive's position unit the increment (position factor 1), whatever it was set to before
            self._what = "0x6092 feed constant"
            sdo[0x6092][1].raw, sdo[0x6092][2].raw = resolution
        ch.q = spec.length_per_revolution / (resolution[0] / resolution[1])
        ramp = spec.max_velocity / ch.q / spec.off_ramp_time if spec.off_ramp_time > 0 else 2**32 - 1
        ramp = int(min(ramp, 2**32 - 1))
        for self._what, index, v in (
                ("0x607E polarity", 0x607E, 0xC0 if spec.encoder.inverse_direction else 0),
                ("0x6080 max motor speed", 0x6080, int(round(spec.max_speed))),
                ("0x6085 quick stop deceleration", 0x6085, ramp),
                ("0x6083 profile acceleration", 0x6083, ramp),
                ("0x6084 profile deceleration", 0x6084, ramp),
                ("0x6081 profile velocity", 0x6081, int(min(spec.max_velocity / ch.q, 2**32 - 1)))):
            sdo[index].raw = v
        return ""

    def rescale(self, ch: Cia402Channel, spec: DriveSpec) -> None:
        """The axis's mechanics changed at run time: write the scaling again (:meth:`_scaling`).  A node that
        does not take it is lost to the axis (communication fault), never an exception in the cycle."""
        try:
            self._scaling(ch, spec)
        except (SdoCommunicationError, SdoAbortedError, KeyError) as exc:
            ch.rescale_error = f"{self._what}: {exc}"
            ch._report("communication_loss")

    # --- bus callbacks (the network's notifier thread) -------------------------------------------------
    def _on_tpdo(self, can_id: int, data: bytearray, timestamp: float) -> None:
        with self._cond:
            self._rx[can_id] = bytes(data)
            self._pending.discard(can_id)
            self._cond.notify_all()

    def _on_event(self, can_id: int, data: bytearray, timestamp: float) -> None:
        with self._cond:
            self._events.append((can_id, bytes(data)))

    # --- the cycle ------------------------------------------------------------------------------------
    def read(self, bank: Any, t: float, dt: float) -> None:
        if not self.members:
            return
        self.now = t
        if self.paced:
            self._pace(t)
        # wait for the nodes that answered last cycle; a silent node gets only a short look (2 ms)
        main, extra = set(), set()
        for ch in self.members:
            (extra if ch.missed else main).update((0x180 + ch.node_id, 0x280 + ch.node_id))
        with self._cond:
            self._rx.clear()
            self._pending = main | extra
        self.network.sync.transmit()
        timeout = 0.8 * self.servo_cycle if self.paced else VIRTUAL_WAIT
        with self._cond:
            if not self._cond.wait_for(lambda: not self._pending & main, timeout):
                self.late_cycles += 1
            if extra:
                self._cond.wait_for(lambda: not self._pending, min(0.002, timeout))
            rx, events = dict(self._rx), self._events
            self._events = []
        for ch in self.members:
            nid = ch.node_id
            mine = [(cob, data) for cob, data in events if cob & 0x7F == nid]
            ch._take(rx.get(0x180 + nid), rx.get(0x280 + nid), mine, t)
            i = ch.index
            bank.act_p[i] = ch.position * ch.q + ch.off
            bank.act_v[i] = ch.velocity * ch.q

    def write(self, bank: Any, t: float) -> None:
        for ch in self.members:
            if ch._nmt_start:
                ch._nmt_start = False
                ch.remote.nmt.send_command(_NMT_START)
            self.network.send_message(0x200 + ch.node_id, ch._rpdo(bank))

    def _pace(self, t: float) -> None:
        now = time.perf_counter()
        if self._wall0 is None:
            self._wall0, self._t0 = now, t
        delay = self._wall0 + (t - self._t0) - now
        if delay > 0:
            time.sleep(delay)

    def close(self) -> None:
        for net in (self.network, self.sim_network):
            if net is not None:
                try:
                    net.disconnect()
                except Exception:  # noqa: BLE001 - closing a bus that is gone already
                    pass
                net.subscribers.clear()         # no callback keeps the axes alive after the bus is closed
        for ch in self.members:
            ch.reports = None
        self.sim_network = None
        _OPEN.discard(self)
        if _VIRTUAL_OWNERS.get(self.channel) is self:
            del _VIRTUAL_OWNERS[self.channel]
