"""The simulated PROFIBUS DP(DRIVE) of a CPU 31xT: one DP slave per real drive, their data records and the
technology's command slices (S7-Technology V4.1 §2.4, §5.6, §6.7.3, §6.7.8-§6.7.11, §7.10).

Addresses (plcmotion's HW Config, as the manual leaves them to the project): the drives of the real axes in
the order of their technology DB numbers get PROFIBUS addresses 2, 3, ..., the logical base address
``BASE_ADDRESS + 32 k`` (input and output, in the technology's area 64..1023 of §5.6) and the diagnostic
address ``DIAGNOSTIC_ADDRESS - k``.  A hydraulic axis is no DP(DRIVE) slave: its valve is driven by an
analog output (§3.1.4), there is no drive to talk to.  The integrated I/O of the CPU has the base address 0 (not on
DP(DRIVE)).  ``MCDevice.StationLifeList[address]`` is 1 while the slave takes part in cyclic exchange.

Each drive slave carries record 47, the PROFIdrive parameter channel, answered by a
``drives.profidrive.parameter_model.ParameterModel`` with the drive parameters listed in :func:`_parameters`.

Commands to the bus are carried out in the technology's command slices: one follows every technology DB
update, and a request written in one slice is answered in the next (``Slices.after``), so a record or
drive-parameter command is Busy for at least two DB updates.
"""
from __future__ import annotations

import weakref
from dataclasses import dataclass, field
from typing import Any, Callable

from ...drives.profidrive import parameter_model as PM
from . import activation
from .tdb import Array

BASE_ADDRESS = 256
DIAGNOSTIC_ADDRESS = 1023
FIRST_STATION = 2
INTEGRATED_IO_ADDRESS = 0
STATIONS = 128

#: DP slave Status of MC_ActivateDPSlave (§6.7.3; 4 "being deactivated" is never shown)
ACTIVATED, DEACTIVATED, ACTIVATING, NOT_CONNECTED = 1, 2, 3, 5
#: command slices from an initiated activation until the slave is back in cyclic exchange (plcmotion's)
ACTIVATION_SLICES = 4


class Slices:
    """The command slices of one technology: work due after a number of DB updates (run after the update
    in the same IPO cycle).  The hook runs only while something is due."""

    def __init__(self, device: Any):
        self.device = device
        self._due: list[tuple[int, int, Callable[[], None]]] = []
        self._seq = 0
        self._hooked = False

    def after(self, updates: int, fn: Callable[[], None]) -> None:
        """Run ``fn`` in the command slice after ``updates`` more DB updates."""
        self._seq += 1
        self._due.append((self.device.updates + updates, self._seq, fn))
        if not self._hooked:
            self._hooked = True
            self.device.ctl.on_post_servo(self._tick)

    def _tick(self, t: float) -> None:
        if not self._due:
            return
        now = self.device.updates
        ready = sorted(d for d in self._due if d[0] <= now)
        if ready:
            self._due = [d for d in self._due if d[0] > now]
            for _, _, fn in ready:
                fn()

    def clear(self) -> None:
        self._due.clear()


@dataclass
class Slave:
    """A drive on DP(DRIVE)."""
    station: int
    base_address: int
    diagnostic_address: int
    axis: Any
    parameters: PM.ParameterModel
    status: int = ACTIVATED
    busy_records: set[int] = field(default_factory=set)      # records with a write in progress
    drive_request: bool = False                              # a drive-parameter command is out (80C7)
    lost: bool = False                                       # the axis has the communication fault of it
    pending: bool = False                                    # an MC_ActivateDPSlave command waits

    @property
    def active(self) -> bool:
        """The slave takes part in cyclic exchange."""
        return self.status == ACTIVATED


def _parameters(axis: Any) -> PM.ParameterModel:
    """The drive parameters of the simulated drive of ``axis`` (SINAMICS numbers)."""
    spec = axis.config.drive
    bank, i = axis.ctl.bank, axis.index

    def speed(_: int) -> float:            # r0063 actual speed [1/min]
        per_rev = axis.config.drive.length_per_revolution
        return float(bank.act_v[i]) / per_rev * 60.0 if per_rev else 0.0

    def faults(k: int) -> float:           # r0947[0..7] fault numbers, newest first
        inj = getattr(axis, "fault_injection", None)
        drive_fault = inj is not None and "drive" in inj.faults
        return float(axis.config.drive.fault_code) if drive_fault and k == 0 else 0.0

    def state() -> bool:
        return axis.state in ("enabled", "disabling")

    params = [
        PM.DriveParameter(922, PM.UNSIGNED16, minimum=1, maximum=999, only_when_off=True),   # p0922 telegram
        PM.DriveParameter(1082, PM.FLOAT32, minimum=0.0, maximum=210000.0),                  # p1082 max speed
        PM.DriveParameter(1120, PM.FLOAT32, minimum=0.0, maximum=999999.0),                  # p1120 ramp-up
        PM.DriveParameter(2000, PM.FLOAT32, minimum=6.0, maximum=210000.0),                  # p2000 ref. speed
        PM.DriveParameter(63, PM.FLOAT32, writable=False, read_fn=speed),                    # r0063
        PM.DriveParameter(947, PM.UNSIGNED16, elements=8, writable=False, read_fn=faults),   # r0947[0..7]
    ]
    values = {922: [float(axis.cfg["Wizard.Telegram"])], 1082: [spec.max_speed], 1120: [0.0],
              2000: [spec.reference_speed]}
    return PM.ParameterModel(params, values, pulses_on=state)


class DPDrive:
    """DP(DRIVE) of one technology: slaves of the real drives, StationLifeList, command slices."""

    def __init__(self, device: Any):
        self.device = device
        self.slices = Slices(device)
        self.slaves: list[Slave] = []
        self.refresh()

    def refresh(self, new: Any = None) -> None:
        """Take the real axes configured so far onto the bus (new ones at the end).  ``new``: an axis being
        added, which the controller lists only once its family has made it."""
        known = {id(s.axis) for s in self.slaves}
        candidates = list(self.device.ctl.axes.values())
        if new is not None and all(a is not new for a in candidates):
            candidates.append(new)
        axes = sorted((a for a in candidates
                       if getattr(a, "db_number", None) is not None and not getattr(a, "virtual", True)
                       and not getattr(a, "hydraulic", False)),
                      key=lambda a: a.db_number)
        for axis in axes:
            if id(axis) not in known:
                k = len(self.slaves)
                self.slaves.append(Slave(FIRST_STATION + k, BASE_ADDRESS + 32 * k, DIAGNOSTIC_ADDRESS - k, axis,
                                         _parameters(axis)))
        self.publish()

    def publish(self) -> None:
        """MCDevice.StationLifeList: 1 for every slave in cyclic exchange."""
        life = [0] * STATIONS
        for s in self.slaves:
            life[s.station] = 1 if s.active else 0
        self.device.mcdevice._write(StationLifeList=Array(0, life))

    def by_address(self, address: int) -> Slave | None:
        self.refresh()
        return next((s for s in self.slaves if s.base_address == address), None)

    def by_diagnostic(self, address: int) -> Slave | None:
        self.refresh()
        return next((s for s in self.slaves if s.diagnostic_address == address), None)

    def of(self, axis: Any) -> Slave | None:
        self.refresh()
        return next((s for s in self.slaves if s.axis is axis), None)

    # --- MC_ActivateDPSlave -------------------------------------------------------------------------------
    def set_active(self, slave: Slave, active: bool, initiated: Callable[[], None]) -> None:
        """(De)activate ``slave``: the command is initiated in the next command slice (``initiated``, the
        FB's Done).  Deactivation takes the slave out of cyclic exchange at once (Status 2; §6.7.3 never
        shows 4); an activation shows Status 3 until the slave is back in cyclic exchange
        ``ACTIVATION_SLICES`` slices later.  Without cyclic exchange the drive of an active axis is not
        reachable: the kernel's communication fault (Statusword.CyclicInterface FALSE and the drive error
        in the technology DB); an axis deactivated first (MC_ActivateTO, as §6.7.3 asks) gets it only if it
        is activated again while its slave is still deactivated."""
        slave.pending = True

        def initiate() -> None:
            slave.pending = False
            if active:
                slave.status = ACTIVATING
                self.slices.after(ACTIVATION_SLICES, lambda: self._connected(slave))
            else:
                slave.status = DEACTIVATED
                if not activation.deactivated(slave.axis):
                    self._lose(slave)
                self.publish()
            initiated()
        self.slices.after(1, initiate)

    def _connected(self, slave: Slave) -> None:
        if slave.status == ACTIVATING:
            slave.status = ACTIVATED
            self._restore(slave)
            self.publish()

    def _lose(self, slave: Slave) -> None:
        slave.axis.inject_fault("communication_loss", persistent=True)
        slave.lost = True

    def _restore(self, slave: Slave) -> None:
        if slave.lost:
            slave.axis.clear_fault("communication_loss")    # the alarm stays until MC_Reset
            slave.lost = False

    def to_activated(self, axis: Any) -> None:
        """An axis was activated again (MC_ActivateTO): without its slave it has no drive communication."""
        slave = self.of(axis)
        if slave is not None and slave.status == DEACTIVATED:
            self._lose(slave)

    def reinitialize(self) -> None:
        """POWER OFF -> ON: every slave takes part in cyclic exchange again, running requests are gone."""
        self.slices.clear()
        for s in self.slaves:
            self._restore(s)
            s.status = ACTIVATED
            s.pending = False
            s.busy_records.clear()
            s.drive_request = False
        self.publish()


_BUSES: "weakref.WeakKeyDictionary[Any, DPDrive]" = weakref.WeakKeyDictionary()


def bus(device: Any) -> DPDrive:
    """The DP(DRIVE) of a technology (``s7t.device(ctl)``), made on first use."""
    found = _BUSES.get(device)
    if found is None:
        found = _BUSES[device] = DPDrive(device)
        device.on_reinitialize.append(lambda reason, ref=weakref.ref(found): _power(ref(), reason))
    return found


def _power(b: DPDrive | None, reason: str) -> None:
    if b is not None and reason == "power":
        b.reinitialize()


__all__ = ["DPDrive", "Slave", "Slices", "bus", "BASE_ADDRESS", "DIAGNOSTIC_ADDRESS", "FIRST_STATION",
           "INTEGRATED_IO_ADDRESS", "ACTIVATED", "DEACTIVATED", "ACTIVATING", "NOT_CONNECTED", "ACTIVATION_SLICES"]
