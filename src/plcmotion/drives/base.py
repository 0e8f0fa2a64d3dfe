"""The neutral interface between the kernel and whatever moves the axis.

A drive model is built from a :class:`~plcmotion.drives.spec.DriveSpec` (actuator, interface, speed range,
mechanics, timing, encoder, simulated plant), never from a family's tags.  Drives of one kind form a
*group* that is updated for all its members at once, on the kernel's arrays (``kernel.bank``); each member
axis gets a *channel* for what happens on events.

Per servo cycle the kernel calls, for every group:

1. ``group.read(bank, t, dt)`` before interpolation: the actual values of time ``t`` into
   ``bank.act_p`` [length unit] and ``bank.act_v`` [length unit/s] of the group's members, in axis
   coordinates (positive = the axis's positive direction, whatever the drive's polarity);
2. ``group.write(bank, t)`` after position control: this cycle's command out of the bank -
   ``bank.cmd_v`` (speed setpoint [length unit/s], for drives with their own speed loop) or
   ``bank.sp_p``/``bank.sp_v`` (position setpoint, for drives that follow a position: steppers, ideal
   drives, a CiA 402 drive in cyclic synchronous position mode).

On events the kernel uses the member's :class:`DriveChannel`: ``set_enable`` (MC_Power enables or
disables; the drive runs its own switch-on sequence), ``ready`` (the drive executes setpoints; polled
while enabling and for the status), ``set_fault`` (a fault of the drive itself: not ready, the power
section stops following the setpoint and ramps down), ``set_actual`` (homing re-references the actual
value), ``reconfigure`` (the axis configuration changed at run time: a new spec), the zero mark latch
(``arm_zero_mark``/``zero_mark_latched``/``disarm_zero_mark``), ``communication_ok`` and the torque
(force) limit (``set_torque_limit``).  It reads back ``mechanical_position`` (where the load really is: what
switches and zero marks see), ``torque`` and ``torque_limit_active`` (a drive pushing against a fixed end
stop, ``PlantSpec.end_stop_min``/``end_stop_max``).

Nothing here runs per cycle per axis in Python: a group keeps its members' state in numpy arrays.
"""
from __future__ import annotations

from abc import ABC, abstractmethod
from typing import Any, Protocol

from .spec import DriveSpec


class DriveReports(Protocol):
    """Where a drive that finds faults by itself (a drive on a bus: CiA 402 EMCY, statusword, heartbeat) or
    homes by itself (CiA 402 homing mode: ``homed``) reports them: the axis's device fault list (``kernel.fault_injection.FaultInjection``).  ``kind`` is
    ``"drive"`` (a fault of the drive) or ``"communication_loss"`` (the bus connection is lost); the
    alarm then takes the family's reaction like any device fault."""

    def inject(self, kind: str, detail: str = "", *, persistent: bool = False) -> None: ...

    def homed(self, position: float) -> None:
        """The drive ran its own homing and its actual value reads ``position`` [axis length unit] now: the
        axis is homed there (each family's homing status follows the kernel's)."""


class DriveChannel(ABC):
    """Event-time access to one member of a drive group (the kernel keeps it as ``axis.drive``)."""

    @abstractmethod
    def set_enable(self, on: bool, t: float) -> None:
        """Switch the drive enable at time ``t`` (enable output, PROFIdrive STW1, CiA 402 controlword):
        the drive steps through its own states and is :meth:`ready` after them (``DriveSpec.ready_delay``);
        without enable it ramps down with ``DriveSpec.off_ramp_time``."""

    @abstractmethod
    def ready(self, t: float) -> bool:
        """'Drive ready' at time ``t``: enabled, switched on, no fault, the drive executes setpoints."""

    @abstractmethod
    def set_actual(self, bank: Any, value: float) -> None:
        """Re-reference the actual position so that it reads ``value`` now (homing)."""

    @abstractmethod
    def mechanical_position(self) -> float:
        """Where the load really is, in machine coordinates (what switches and zero marks see)."""

    def attach(self, reports: DriveReports) -> None:
        """The kernel hands the drive the axis's fault list once the axis exists; drives that only fail by
        fault injection ignore it."""

    @property
    def communication_ok(self) -> bool:
        """The controller exchanges data with the drive (FALSE: no drive on a bus to talk to)."""
        return True

    def reconfigure(self, spec: DriveSpec) -> None:
        """The axis configuration changed at run time: ``spec`` is the whole new specification, the drive
        takes what it can change while running (the stepper its pulse length; a servo drive keeps the values
        it was commissioned with)."""

    def set_fault(self, on: bool) -> None:
        """A fault of the drive itself (fault injection) comes (``on``) or goes: it stops executing setpoints,
        is not ready and ramps down (``DriveSpec.off_ramp_time``); it reports ``DriveSpec.fault_code``."""

    def disturb(self, jump: float = 0.0, force: float | None = None, blocked: bool | None = None) -> None:
        """A disturbance of the load (fault injection): ``jump`` moves the load at once, ``force`` is an
        external force given as the speed it costs the drive's speed loop, ``blocked`` holds the load."""
        raise ValueError("this drive has no simulated load to disturb")

    # encoder zero marks (reference mark search of a PROFIdrive encoder); drives without them ignore it
    def arm_zero_mark(self, direction: float) -> None:
        """Latch the actual value at the next zero mark passed in ``direction`` (+1 / -1)."""

    def disarm_zero_mark(self) -> None:
        """Stop a zero mark search."""

    def zero_mark_latched(self) -> float | None:
        """The actual value latched at a zero mark since arming (once), or None."""
        return None

    # torque (force) limiting: fixed end stops, clamping
    @property
    def can_limit_torque(self) -> bool:
        """The drive limits its torque (a hydraulic drive: its force) on request."""
        return False

    def set_torque_limit(self, limit: float | None) -> None:
        """Limit the drive's torque [N m] (a hydraulic drive's force [N]) to ``limit`` > 0 from now on, or
        lift the limit (None).  The limit stays while the drive is disabled."""
        raise ValueError("this drive cannot limit its torque")

    @property
    def torque(self) -> float:
        """The torque [N m] (a hydraulic drive: the force [N]) the drive gives now, positive in the axis's
        positive direction."""
        return 0.0

    @property
    def torque_limit_active(self) -> bool:
        """The drive gives as much torque (force) as its limit allows: it wants more."""
        return False


class DriveGroup(ABC):
    """All drives of one kind, updated together on the bank's arrays once per servo cycle."""

    #: the controller closes a position loop over these drives (they take ``bank.cmd_v``)
    closed_loop: bool = False

    @abstractmethod
    def add(self, index: int, spec: DriveSpec, servo_cycle: float, t: float) -> DriveChannel:
        """Attach the axis with bank index ``index`` and drive ``spec`` at time ``t`` (``servo_cycle`` [s]);
        the group reads the spec here and keeps what it needs in its arrays."""

    @abstractmethod
    def read(self, bank: Any, t: float, dt: float) -> None:
        """Bring the actual values of time ``t`` (``dt`` after the last read) into ``bank.act_p`` and
        ``bank.act_v`` of the members."""

    @abstractmethod
    def write(self, bank: Any, t: float) -> None:
        """Take this cycle's commands of the members from the bank (``cmd_v`` or ``sp_p``/``sp_v``)."""

    def close(self) -> None:
        """Release what the group holds outside the process (a bus connection); simulated groups hold none."""


class DriveLink(ABC):
    """A drive connected through something the kernel does not know (a CANopen bus ...), attached to an
    axis's :class:`DriveSpec` as ``spec.link``.  Axes whose links share a ``group_key`` form one group."""

    #: the key of the drive group (e.g. one group per bus)
    group_key: str

    @abstractmethod
    def new_group(self, bank: Any) -> DriveGroup:
        """An empty group for the drives of this link's ``group_key``."""

    @abstractmethod
    def bind(self, spec: DriveSpec) -> DriveSpec:
        """The spec of the axis with this link: ``spec`` (built by the family from its tags) with the link
        attached and the interface it implies; ValueError naming the reason when the axis cannot have it."""
