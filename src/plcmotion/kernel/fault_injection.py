"""Fault injection on the simulated devices of an axis, for virtual commissioning.

What fails is the simulated machine, never the controller: the drive, the encoder, the bus, the load.  The
technology object then finds the fault the way it would on a real machine - by a device alarm, by an
invalid actual value, or by its own monitoring (following error, positioning monitoring) - and reacts as
the manual lists (S7-1200 V6 §12.8, S7-1500T V5 §7.1.1 / alarms 521, 541).  Switch faults are injected on
the plant (``Controller.plant``, ``drives.plant.Switch``); ``FaultScenario`` plays faults at given times
(the ``[[faults]]`` of a project file).  Guide: docs/fault_injection.md.

``FaultInjection`` is a component of an axis (``axis.fault_injection``) that keeps the injected faults; the
axis offers its public calls as its own (``axis.inject_fault`` ...).
"""
from __future__ import annotations

import math
from typing import Any, Callable, Protocol

from ..drives.base import DriveChannel
from ..drives.spec import EncoderInterface, SetpointInterface
from . import faults as F
from .axis_config import AxisConfig
from .faults import Reaction

#: device fault kinds and the alarm each raises
DEVICE_ALARMS = {"drive": F.DRIVE_ALARM, "encoder": F.ENCODER, "drive_not_ready": F.DRIVE_NOT_READY}
#: the details each device fault kind knows (S7-1200 V6 §12.8 ErrorInfo of 16#800C, 16#800A, 16#8000)
DETAILS = {"drive": ("", "control_requested", "shutdown", "station", "sign_of_life"),
           "encoder": ("", "hardware", "dirty", "absolute_value", "zero_mark", "parking", "station", "sign_of_life"),
           "drive_not_ready": ("",)}
#: kinds named after what is lost; they stand for device faults (see ``_expand``)
LOSS_KINDS = ("encoder_loss", "communication_loss")
KINDS = tuple(DEVICE_ALARMS) + LOSS_KINDS
_DEVICE_OF = {alarm: device for device, alarm in DEVICE_ALARMS.items()}
_LIMIT = 1e12
#: setpoint interfaces on a bus, whose communication can be lost
_BUS_INTERFACES = (SetpointInterface.PROFIDRIVE, SetpointInterface.CANOPEN)


def checked_real(name: str, value: Any) -> float:
    """A REAL argument of the public fault and plant API: a finite number within ±1e12, else a clear error."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise TypeError(f"{name} must be a number, got {value!r}")
    try:
        x = float(value)
    except OverflowError:
        x = math.inf
    if not math.isfinite(x) or abs(x) > _LIMIT:
        shown = repr(value) if len(repr(value)) <= 40 else f"an int of {len(str(abs(value)))} digits"
        raise ValueError(f"{name} must be a finite number in [-1e12, 1e12], got {shown}")
    return x


class Retainer(Protocol):
    """The controller keeps an axis's retentive data (the "homed" state of an absolute encoder)."""

    def _retain_axis(self, axis: Any) -> None: ...


class FaultHost(Protocol):
    """What fault injection needs from its axis."""

    ctl: Retainer
    name: str
    config: AxisConfig
    drive: DriveChannel
    pto: bool
    sim: bool
    servo: bool
    homed: bool

    @property
    def homing(self) -> "DriveHoming": ...

    def raise_alarm(self, fault: F.Fault) -> None: ...


class DriveHoming(Protocol):
    """The homing part of the axis, for a homing run in the drive."""

    def drive_homed(self, position: float) -> None: ...


class FaultInjection:
    """The injected faults of one axis's simulated devices (``axis.fault_injection``).

    ``faults``: device ("drive", "encoder", "drive_not_ready") -> (detail, persistent).  The axis offers
    ``inject_fault``, ``clear_fault``, ``disturb_load``, ``communication_ok`` and ``sensor_valid`` as its
    own (the public fault API, docs/fault_injection.md) and asks :meth:`acknowledge` / :meth:`keeps_alarm`
    at MC_Reset.
    """

    def __init__(self, axis: FaultHost):
        self.axis = axis
        self.faults: dict[str, tuple[str, bool]] = {}

    # --- device faults ---------------------------------------------------------------------------------
    def inject(self, kind: str, detail: str = "", *, persistent: bool = False) -> None:
        """Let a simulated device of the axis fail.

        ``kind``:

        * ``"drive"`` (S7-1200 16#800C; detail "", "control_requested", "shutdown", "station",
          "sign_of_life"), ``"encoder"`` (16#800A; detail "", "hardware", "dirty", "absolute_value",
          "zero_mark", "parking", "station", "sign_of_life"), ``"drive_not_ready"`` (16#8000);
        * ``"encoder_loss"``: the encoder fails - on the bus a station failure (16#800A/16#0040), otherwise a
          hardware error (16#800A/16#0034); actual values invalid, "homed" lost;
        * ``"communication_loss"`` (PROFIdrive axes): the drive's telegram fails (16#800C/16#003E,
          CommunicationFault), with it the encoder on that telegram (``Sensor[1].Interface.Type`` 2).

        Every kind removes the enable.  A transient fault is gone once acknowledged (MC_Reset); a
        ``persistent`` one stays until ``clear_fault``.  The S7-1500 shows the same faults as technology
        alarms 421 (drive, ErrorWord X4), 411 (encoder, X5) and 431 (station failure or sign of life, X7)
        (docs/s7_1500/alarms.md).
        """
        if not isinstance(kind, str) or kind not in KINDS:
            raise ValueError(f"fault kind {kind!r}: one of {', '.join(KINDS)}")
        if not isinstance(detail, str):
            raise TypeError(f"fault detail must be a string, got {detail!r}")
        if not isinstance(persistent, bool):
            raise TypeError(f"persistent must be True or False, got {persistent!r}")
        ax = self.axis
        for device, device_detail in self.expand(kind, detail):
            self.faults[device] = (device_detail, bool(persistent))
            if device in ("drive", "drive_not_ready"):
                ax.drive.set_fault(True)
            if device == "encoder" or (device == "drive" and device_detail == "station"):
                ax.homed = False                       # §2.5: an encoder error resets "homed"
                ax.ctl._retain_axis(ax)                # also for absolute encoders, across power cycles
            ax.raise_alarm(F.alarm(DEVICE_ALARMS[device], device_detail, Reaction.REMOVE_ENABLE))

    def homed(self, position: float) -> None:
        """A drive that homes by itself (CiA 402 homing mode) reports that it is homed and its actual value
        reads ``position`` [axis length unit]: the axis's homing makes the axis homed there
        (``kernel.homing.Homing.drive_homed``), so each family's "homed" status follows.  The fault list is
        where the kernel attaches a drive's reports (``DriveChannel.attach``), so it hands this on."""
        self.axis.homing.drive_homed(checked_real("position", position))

    def expand(self, kind: str, detail: str) -> list[tuple[str, str]]:
        """The device faults (device, detail) a fault kind stands for (ValueError when it cannot be)."""
        ax = self.axis
        if kind in DEVICE_ALARMS:
            if ax.sim:
                raise ValueError(f"axis {ax.name}: a simulated axis (Simulation.Mode = 1 or a virtual axis) has "
                                 f"no drive or encoder that could fail ({kind!r})")
            if kind == "encoder" and ax.pto:
                raise ValueError(f"axis {ax.name}: a pulse output axis (Actor.Type = 2) has no encoder")
            if detail not in DETAILS[kind]:
                raise ValueError(f"fault {kind!r}: detail {detail!r} is not one of "
                                 + ", ".join(repr(d) for d in DETAILS[kind]))
            return [(kind, detail)]
        if detail:
            raise ValueError(f"fault kind {kind!r} takes no detail (got {detail!r})")
        encoder = ax.config.drive.encoder.interface
        on_bus = encoder in (EncoderInterface.PROFIDRIVE, EncoderInterface.DRIVE_TELEGRAM)
        if kind == "encoder_loss":
            if not ax.servo:
                raise ValueError(f"axis {ax.name}: encoder_loss needs an axis with an encoder "
                                 "(PROFIdrive or analog drive, Simulation.Mode = 0)")
            return [("encoder", "station" if on_bus else "hardware")]
        if not ax.servo or ax.config.drive.interface not in _BUS_INTERFACES:
            raise ValueError(f"axis {ax.name}: communication_loss needs a PROFIdrive axis (Actor.Type = 1, "
                             "Simulation.Mode = 0) or a drive on a bus (CiA 402); an analog drive or a pulse "
                             "output has no bus")
        lost = [("drive", "station")]
        if encoder is EncoderInterface.DRIVE_TELEGRAM:
            lost.append(("encoder", "station"))      # the encoder travels in the drive's telegram
        return lost

    def clear(self, kind: str | None = None) -> None:
        """Remove the cause of an injected fault, or of all with ``kind=None`` (an alarm it raised still
        has to be acknowledged with MC_Reset).  ``"load"`` removes an external force and a blocked load."""
        if kind is not None and kind not in KINDS and kind != "load":
            raise ValueError(f"fault kind {kind!r}: one of {', '.join(KINDS + ('load',))}")
        if kind is None or kind == "load":
            if self.axis.servo:
                self.axis.drive.disturb(force=0.0, blocked=False)
            if kind == "load":
                return
        if kind is None:
            devices = list(self.faults)
        elif kind in DEVICE_ALARMS:
            devices = [kind]
        else:
            devices = [d for d, _ in self.expand(kind, "")]
        for device in devices:
            if device in self.faults:
                self.faults[device] = (self.faults[device][0], False)

    def acknowledge(self) -> None:
        """MC_Reset: transient device faults are gone; a drive without a pending fault is ready again."""
        for kind, (_detail, persistent) in list(self.faults.items()):
            if not persistent:
                del self.faults[kind]
                if kind in ("drive", "drive_not_ready") and not {"drive", "drive_not_ready"} & set(self.faults):
                    self.axis.drive.set_fault(False)

    def keeps_alarm(self, fault: F.Fault) -> bool:
        """The alarm of a device that is still faulty persists through MC_Reset; an encoder that stays
        invalid may be acknowledged to move the axis without position control (S7-1200 V6 §12.7)."""
        device = _DEVICE_OF.get(fault.kind)
        return device is not None and device in self.faults and device != "encoder"

    def communication_ok(self, device: str) -> bool:
        """StatusDrive/StatusSensor.CommunicationOK: cyclic bus communication with the drive / encoder
        (PROFIdrive and analog axes; FALSE after an injected station failure or sign-of-life fault)."""
        if self.axis.pto:
            return False
        detail = self.faults.get(device, ("", False))[0]
        return detail not in ("station", "sign_of_life")

    @property
    def sensor_valid(self) -> bool:
        """StatusSensor.State = 2: actual values valid (no encoder fault pending)."""
        return "encoder" not in self.faults

    # --- load disturbance -------------------------------------------------------------------------------
    def disturb_load(self, *, jump: float = 0.0, force: float | None = None, blocked: bool | None = None) -> None:
        """Disturb the load of the simulated drive; the axis's monitoring decides what follows.

        * ``jump``: the load moves by this distance [user unit] at once (slip, collision); a stepper
          (PTO) loses steps - its pulse count does not see it, its switches do;
        * ``force``: an external force, stated by its effect since the drive model has no masses: the
          speed [user unit/s] by which the drive's speed loop falls short of its setpoint while the force
          acts (positive against positive motion); 0 removes it;
        * ``blocked``: TRUE holds the load against an obstacle (the drive cannot move it), FALSE frees it.

        Following error monitoring (S7-1200 16#800D, S7-1500 alarm 521) and positioning monitoring
        (16#800F, alarm 541) trip when the deviation is beyond their limits.  ``clear_fault("load")``
        removes force and obstacle.
        """
        j, f = check_load(self.axis, jump, force, blocked)
        self.axis.drive.disturb(jump=j, force=f, blocked=blocked)


class LoadHost(Protocol):
    name: str
    pto: bool
    sim: bool


def check_load(axis: LoadHost, jump: Any = 0.0, force: Any = None, blocked: Any = None
               ) -> tuple[float, float | None]:
    """The checked (jump, force) of a load disturbance of ``axis``; TypeError/ValueError naming the problem."""
    j = checked_real("jump", jump)
    f = None if force is None else checked_real("force", force)
    if blocked is not None and not isinstance(blocked, bool):
        raise TypeError(f"blocked must be True, False or None, got {blocked!r}")
    if axis.sim:
        raise ValueError(f"axis {axis.name}: a simulated axis (Simulation.Mode = 1) has an ideal drive and no "
                         "load to disturb")
    if axis.pto and (f is not None or blocked is not None):
        raise ValueError(f"axis {axis.name}: a stepper on a pulse output (PTO) runs open loop: only a position "
                         "jump (lost steps) can be injected")
    return j, f


class ServoClock(Protocol):
    """The controller as a scenario sees it: it calls hooks before each servo cycle."""

    def on_pre_servo(self, fn: Callable[[float], Any]) -> Any: ...


class FaultScenario:
    """Faults injected at given controller times (virtual commissioning runs, ``[[faults]]`` of a project).

    ``scenario.at(0.5, lambda: axis.inject_fault("communication_loss"), "bus of Axis_1 lost")``: the
    action runs at the start of the first servo cycle at or after 0.5 s, before the axes look at their
    inputs and monitoring.  Actions are the public fault injection calls; check them before the run.
    """

    def __init__(self, ctl: ServoClock):
        self.ctl = ctl
        self.pending: list[tuple[float, int, Callable[[], Any], str]] = []
        self.done: list[tuple[float, str]] = []          # (time, what) of the actions that ran
        self._hooked = False

    def at(self, t: float, action: Callable[[], Any], what: str = "") -> None:
        t = checked_real("time", t)
        if not callable(action):        # found now, not as a STOP at time t
            raise TypeError(f"action must be callable (a function without arguments), got {action!r}")
        if t < 0.0:
            raise ValueError(f"fault time must be >= 0 s, got {t!r}")
        self.pending.append((t, len(self.pending) + len(self.done), action, what))
        self.pending.sort(key=lambda e: (e[0], e[1]))
        if not self._hooked:
            self.ctl.on_pre_servo(self._tick)
            self._hooked = True

    def _tick(self, t: float) -> None:
        while self.pending and self.pending[0][0] <= t + 1e-9:
            when, _, action, what = self.pending.pop(0)
            action()
            self.done.append((t, what))
