"""One axis's CiA 402 drive as the kernel sees it (``axis.drive``): what the drive sent last, what the master
wants, and the controlword and RPDO of a cycle; faults and communication losses found in what arrives are
reported to the axis once (``attach``).  The bus exchange itself is ``master.Cia402Drives``.

Fault rules (docs/drives/cia402.md): a statusword in FAULT / FAULT REACTION ACTIVE or an EMCY with an error
code is a drive fault; leaving OPERATION ENABLED while the master kept asking for it (or after a quick
stop) is "drive has shut down"; no heartbeat for 1.5 heartbeat times, a heartbeat that is no longer
OPERATIONAL, or no TPDOs for ``PDO_TIMEOUT_CYCLES`` cycles is a communication loss.  MC_Reset
(``set_fault(False)``) sends a fault reset edge (and NMT start to a node that left OPERATIONAL) and looks at
the drive anew after a settling time: a fault still there is reported again.
"""
from __future__ import annotations

import math
import struct
from typing import Any, Protocol

import canopen
from canopen.sdo import SdoAbortedError, SdoCommunicationError

from ..base import DriveChannel, DriveReports
from ..spec import DriveSpec
from . import profile as P
from .link import Cia402Link
from .profile import MODE_NAMES, Mode, State

_TPDO1, _TPDO2 = struct.Struct("<HiB"), struct.Struct("<ihH")
#: cycles without the TPDOs of a node before it counts as lost (a node without heartbeat)
PDO_TIMEOUT_CYCLES = 3


class BusClock(Protocol):
    """What a channel reads of its group."""

    now: float                      # the time of the last read [s]
    servo_cycle: float              # [s]

    def rescale(self, ch: "Cia402Channel", spec: DriveSpec) -> None: ...


def _drive_data(spec: DriveSpec) -> tuple[Any, ...]:
    """What the SDO set-up of the scaling and ramps reads of a spec (``master.Cia402Drives._scaling``)."""
    e = spec.encoder
    return (spec.length_per_revolution, e.steps_per_revolution, e.fine_bits, e.inverse_direction,
            spec.max_speed, spec.off_ramp_time)


class Cia402Channel(DriveChannel):
    """One axis's CiA 402 drive (``axis.drive``)."""

    def __init__(self, group: BusClock, index: int, spec: DriveSpec, link: Cia402Link):
        self.group, self.index, self.link = group, index, link
        self.node_id = link.node_id
        self.mode = MODE_NAMES[link.mode]
        self.spec = spec
        self.q = 1.0                    # axis length unit per increment
        self.off = 0.0                  # axis position = increments * q + off
        self.reports: DriveReports | None = None
        self.simulated: Any = None      # the SimulatedCia402 of this node when the project started one
        self.remote: canopen.RemoteNode | None = None
        # what the drive sent last
        self.statusword = 0
        self.state: State | None = None
        self.mode_display = 0
        self.position = 0
        self.velocity = 0
        self.torque_actual = 0            # 0x6077 torque actual value [per mille of the rated torque]
        self.error_code = 0
        self.emcy: list[tuple[int, int]] = []     # (error code, error register) received, newest last
        # what the master wants
        self.enable = False
        self.quick_stop_request = False
        self.forced_fault = False                # a drive fault injected on the controller side
        self.controlword = 0
        self._sent = (0, 0)             # the last two controlwords sent (a drive answers one SYNC later)
        self._reset_edge = False
        self._nmt_start = False
        self._pp_target: int | None = None
        self._pp_pulse = False
        #: drive-based homing (``home_in_drive``): "", "running", "attained", "error"
        self.homing = ""
        self.homing_error = ""          # why home_in_drive could not start the run ("" none)
        self._homing_started = False
        # supervision
        self.last_heartbeat = 0.0
        self.heartbeat_state: int | None = None
        self.missed = 0
        self.fault_reported = False
        self.comm_reported = False
        self.settle_until = -math.inf
        self.rescale_error = ""             # why the last rewrite of the scaling failed ("" none)
        self._echo = False
        self._emcy_fault = False

    # --- the kernel's view ----------------------------------------------------------------------------
    def attach(self, reports: DriveReports) -> None:
        self.reports = reports

    def set_enable(self, on: bool, t: float) -> None:
        self.enable = on
        if on:
            self.quick_stop_request = False

    def ready(self, t: float) -> bool:
        return (self.state is State.OPERATION_ENABLED and self.mode_display == self.mode and not self.forced_fault
                and self.communication_ok)

    @property
    def communication_ok(self) -> bool:
        return not self.comm_reported and self.missed < PDO_TIMEOUT_CYCLES

    def set_fault(self, on: bool) -> None:
        if self._echo:
            return                      # the alarm this channel reported comes back here: nothing to do
        if on:
            self.forced_fault = True
            return
        # MC_Reset: acknowledge - a fault reset edge to the drive, and look at the drive anew afterwards
        self.forced_fault = False
        self.fault_reported = self.comm_reported = False
        self._reset_edge = True
        self._nmt_start = self.heartbeat_state is not None and self.heartbeat_state != 0x05
        g = self.group
        self.settle_until = g.now + max(3 * g.servo_cycle, 0.02)

    def reconfigure(self, spec: DriveSpec) -> None:
        """The axis configuration became effective anew (a parameter write at its effective moment, a
        restart): when what the drive was set up with changed - travel per revolution (leadscrew, gear),
        encoder resolution and direction, maximum speed, off-ramp time - the master writes the position
        scaling and the ramps to the drive again and converts with the new increment.  The actual value
        stays the drive's count times the increment: a new travel per revolution scales it."""
        old, self.spec = self.spec, spec
        if self.remote is not None and _drive_data(old) != _drive_data(spec):
            self.group.rescale(self, spec)

    def set_actual(self, bank: Any, value: float) -> None:
        self.off = value - self.position * self.q
        bank.act_p[self.index] = value

    def mechanical_position(self) -> float:
        return self.position * self.q

    def quick_stop(self) -> None:
        """Send the quick stop command: the drive stops with its quick stop deceleration (0x6085) and ends
        in SWITCH ON DISABLED; a new enable of the axis switches it on again."""
        self.quick_stop_request = True

    # --- the cycle ------------------------------------------------------------------------------------
    def _report(self, kind: str, detail: str = "") -> None:
        if self.reports is None:
            return
        self._echo = True
        try:
            self.reports.inject(kind, detail)
        finally:
            self._echo = False

    def _take(self, tpdo1: bytes | None, tpdo2: bytes | None, events: list[tuple[int, bytes]], t: float) -> None:
        for cob, data in events:
            if cob >= 0x700:
                self.last_heartbeat = t
                self.heartbeat_state = data[0] & 0x7F if data else None
            elif len(data) >= 3:
                code, register = struct.unpack_from("<HB", data)
                self.emcy.append((code, register))
                del self.emcy[:-16]
                if code:
                    self._emcy_fault = True
        before = self.state
        if tpdo1 is not None and tpdo2 is not None:
            self.missed = 0
            self.statusword, self.position, self.mode_display = _TPDO1.unpack_from(tpdo1)
            self.velocity, self.torque_actual, self.error_code = _TPDO2.unpack_from(tpdo2)
            self.state = P.state_of(self.statusword)
            if self.homing == "running":
                self._homing_status()
        else:
            self.missed += 1
        if t < self.settle_until:
            self._emcy_fault = False
            return
        faulted = self.state in (State.FAULT, State.FAULT_REACTION_ACTIVE) or self._emcy_fault
        self._emcy_fault = False
        if faulted and not self.fault_reported:
            self.fault_reported = True
            self._report("drive")
        elif (self.enable and before is State.OPERATION_ENABLED and self.state is not State.OPERATION_ENABLED
              and not faulted and not self.fault_reported
              and (self.quick_stop_request
                   or all(P.command_of(cw) is P.Command.ENABLE_OPERATION for cw in self._sent))):
            # the drive left operation while the axis holds the enable: by itself, or by a quick stop
            self.fault_reported = True
            self._report("drive", "shutdown")
        hb = self.link.heartbeat_ms * 1e-3
        lost = self.missed >= PDO_TIMEOUT_CYCLES
        if hb > 0:
            lost = lost or t - self.last_heartbeat > max(1.5 * hb, 2 * self.group.servo_cycle)
            lost = lost or (self.heartbeat_state is not None and self.heartbeat_state != 0x05)
        if lost and not self.comm_reported:
            self.comm_reported = True
            self._report("communication_loss")

    def _rpdo(self, bank: Any) -> bytes:
        if self.homing == "running":
            return self._homing_rpdo()
        enable = self.enable and not self.forced_fault and self.communication_ok
        cw = P.next_command(self.state, enable, self.quick_stop_request)
        if self._reset_edge:
            cw, self._reset_edge = P.FAULT_RESET, False
        operating = self.state is State.OPERATION_ENABLED and enable
        i = self.index
        mode = self.mode
        if mode in (Mode.CYCLIC_SYNC_POSITION, Mode.PROFILE_POSITION):
            target = self._increments(float(bank.sp_p[i])) if operating else self.position
            if mode is Mode.PROFILE_POSITION and operating:
                # streamed set points: a new one (bit 4 rising, change at once) whenever it moved
                if self._pp_pulse:
                    self._pp_pulse = False
                    target = self._pp_target if self._pp_target is not None else target
                elif target != self._pp_target:
                    self._pp_target, self._pp_pulse = target, True
                    cw |= P.CW_NEW_SETPOINT | P.CW_CHANGE_IMMEDIATELY
                else:
                    target = self._pp_target
            value = struct.pack("<i", target)
        elif mode is Mode.CYCLIC_SYNC_TORQUE:
            rev_s = (float(bank.cmd_v[i]) - float(bank.act_v[i])) / self.spec.length_per_revolution
            torque = self.link.speed_gain * rev_s if operating else 0.0
            value = struct.pack("<h", int(max(-32768, min(32767, round(torque)))))
        else:
            v = float(bank.cmd_v[i]) / self.q if operating else 0.0
            value = struct.pack("<i", int(max(-2**31, min(2**31 - 1, round(v)))))
        self.controlword = cw
        self._sent = (cw, self._sent[0])
        return struct.pack("<H", cw) + value + struct.pack("<b", int(mode))

    # --- homing mode (drive-based homing) ------------------------------------------------------------------
    def home_in_drive(self, method: int, *, offset: float = 0.0, switch_speed: float | None = None,
                      zero_speed: float | None = None, acceleration: float | None = None) -> None:
        """Run the drive's own homing (CiA 402 homing mode 6) while the axis is disabled.

        ``method`` is the drive's homing method 0x6098 (1-14 limit/home switch and index pulse, 17-30 the same
        without the index pulse, 33/34 index pulse, 35/37 here is home), ``offset`` the home offset 0x607C
        [axis length unit]; the speeds 0x6099:1 (switch search) and 0x6099:2 (zero search) [length unit/s]
        and the acceleration 0x609A [length unit/s^2] are written when given.  The master switches the drive
        on in homing mode, starts it (controlword bit 4) and switches it off again when the statusword shows
        "homing attained" (bits 12 + 10: :attr:`homing` = "attained") or a homing error (bit 13: "error").
        The drive's position then reads ``offset`` at its home position, and the axis is homed there: the
        channel reports it to the axis (``DriveReports.homed``), so every family's homing status follows."""
        if self.enable:
            raise RuntimeError(f"node {self.node_id}: drive-based homing needs the axis disabled (MC_Power "
                               "Enable = FALSE); the kernel moves an enabled axis itself")
        if isinstance(method, bool) or not isinstance(method, int) or not -128 <= method <= 127:
            raise ValueError(f"homing method must be an integer in [-128, 127] (0x6098), got {method!r}")
        values = {"offset": offset, "switch_speed": switch_speed, "zero_speed": zero_speed,
                  "acceleration": acceleration}
        for name, value in values.items():
            if value is not None and (isinstance(value, bool) or not isinstance(value, (int, float))
                                      or not math.isfinite(value)):
                raise ValueError(f"{name} must be a finite number, got {value!r}")
        sdo = self.remote.sdo
        what = "0x6098 homing method"
        try:
            sdo[0x6098].raw = method
            what = "0x607C home offset"
            sdo[0x607C].raw = self._clamp32(offset / self.q)
            for what, value, obj in (("0x6099:1 speed during search for switch", switch_speed, sdo[0x6099][1]),
                                     ("0x6099:2 speed during search for zero", zero_speed, sdo[0x6099][2]),
                                     ("0x609A homing acceleration", acceleration, sdo[0x609A])):
                if value is not None:
                    obj.raw = min(self._clamp32(abs(value) / self.q), 2**32 - 1)
        except (SdoCommunicationError, SdoAbortedError) as exc:
            # a drive that refuses a value (a method it does not offer) or does not answer: no homing run
            self.homing, self.homing_error = "error", f"{what}: {exc}"
            if isinstance(exc, SdoCommunicationError):
                self._report("communication_loss")
            return
        self.homing_error = ""
        self.off = 0.0
        self.homing = "running"
        self._homing_started = False

    def _homing_status(self) -> None:
        """The statusword of a homing run (CiA 402-2 homing mode: bit 13 error, bit 12 attained, bit 10 target
        reached): attained once the drive stands at home, with the axis homed at the position it reads."""
        sw = self.statusword
        if self.state in (State.FAULT, State.FAULT_REACTION_ACTIVE):
            self.homing = "error"
        elif not self._homing_started or self.mode_display != Mode.HOMING:
            return
        elif sw & P.SW_OMS13:
            self.homing = "error"
        elif sw & (P.SW_OMS12 | P.SW_TARGET_REACHED) == P.SW_OMS12 | P.SW_TARGET_REACHED:
            self.homing = "attained"
            if self.reports is not None:
                self.reports.homed(self.position * self.q + self.off)

    def _homing_rpdo(self) -> bytes:
        state = self.state
        cw = P.next_command(state, True)
        if state is State.OPERATION_ENABLED and self.mode_display == Mode.HOMING:
            cw |= P.CW_NEW_SETPOINT
            # the drive takes bit 4 at the next SYNC: statuswords from the one after it belong to this run
            self._homing_started = self._homing_started or bool(self.controlword & P.CW_NEW_SETPOINT)
        target = self.position if self.mode in (Mode.CYCLIC_SYNC_POSITION, Mode.PROFILE_POSITION) else 0
        size = "<h" if self.mode is Mode.CYCLIC_SYNC_TORQUE else "<i"
        self.controlword = cw
        self._sent = (cw, self._sent[0])
        return struct.pack("<H", cw) + struct.pack(size, target) + struct.pack("<b", int(Mode.HOMING))

    @staticmethod
    def _clamp32(x: float) -> int:
        return int(max(-2**31, min(2**31 - 1, round(x))))

    def _increments(self, position: float) -> int:
        n = round((position - self.off) / self.q)
        return int(max(-2**31, min(2**31 - 1, n)))
