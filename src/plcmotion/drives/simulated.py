"""Simulated drives: a servo drive with its encoder, a stepper on a pulse output, and the ideal drive of a
simulated axis.

Servo (PROFIdrive/analog, S7-1200 V6 §2.2): the drive closes its speed loop, modelled as a first-order lag
with time constant ``PlantSpec.speed_time_constant`` and integrated exactly over each servo cycle; its speed
is limited to ``DriveSpec.max_speed``.  The encoder counts increments of finite size
(``EncoderSpec.increment``: steps per revolution times the fine resolution, or the linear grid), so the
actual position is quantised and lags the setpoint: the following error is a real quantity.  Without
enable the drive ramps down with its own ramp (``DriveSpec.off_ramp_time``), as a drive does when the
controller removes the enable.

Stepper (PTO, §2.1): open loop, the actual position is the number of output pulses, i.e. the setpoint
rounded to whole pulses; the actual velocity is the pulse frequency.

Every model takes a :class:`~plcmotion.drives.spec.DriveSpec` and reads it when a member is added (or
reconfigured), never in the servo cycle.
"""
from __future__ import annotations

import math
from typing import Any

import numpy as np

from .base import DriveChannel, DriveGroup
from .profidrive_link import ProfidriveLink, word_scale
from .spec import ActuatorKind, DriveSpec, SetpointInterface


def new_drive_group(kind: ActuatorKind | str, bank: Any) -> DriveGroup:
    """An empty group of simulated drives of ``kind`` (the controller keeps one group per kind)."""
    kind = ActuatorKind(kind)
    if kind is ActuatorKind.SPEED_SERVO:
        return ServoDrives()
    if kind is ActuatorKind.HYDRAULIC:
        from .hydraulic import HydraulicDrives      # builds on ServoDrives below
        return HydraulicDrives()
    return SetpointDrives(stepper=kind is ActuatorKind.PULSE, bank=bank)


class _ServoChannel(DriveChannel):
    def __init__(self, group: "ServoDrives", member: int):
        self.group, self.member = group, member

    def set_enable(self, on: bool, t: float) -> None:
        g, m = self.group, self.member
        if on and not g.en[m]:
            g.ready_at[m] = t + g.ready_delay[m]
        g.en[m] = on
        link = g.links[m]
        if link is None:
            g.pulses[m] = on                        # analog drive: the enable output switches it
        else:
            link.command(on)                        # PROFIdrive: STW1, the drive steps through its states
            g.stepping.add(m)

    def ready(self, t: float) -> bool:
        g, m = self.group, self.member
        link = g.links[m]
        running = link.operation_enabled if link is not None else bool(g.en[m])
        return running and not g.flt[m] and t >= g.ready_at[m] - 1e-12

    def disturb(self, jump: float = 0.0, force: float | None = None, blocked: bool | None = None) -> None:
        g, m = self.group, self.member
        if jump:
            g.x[m] += jump                          # slip or collision: the encoder sees the load elsewhere
        if force is not None:
            g.dist[m] = force
        if blocked is not None:
            g.blk[m] = blocked
        g.disturbed = bool(g.dist.any() or g.blk.any())

    def set_fault(self, on: bool) -> None:
        g, m = self.group, self.member
        g.flt[m] = on
        link = g.links[m]
        if link is not None:
            link.set_fault(on)
            g.stepping.add(m)

    @property
    def setpoint_word(self) -> int:
        """The speed setpoint word sent to the drive: NSOLL_A/NSOLL_B (PROFIdrive) or the analog output."""
        return int(self.group.word[self.member])

    @property
    def analog_voltage(self) -> float:
        """Voltage of the +-10 V analog speed setpoint (27648 = 10 V) of an analog drive."""
        if self.group.links[self.member] is not None:
            raise TypeError("a PROFIdrive axis has no analog speed setpoint")
        return self.setpoint_word / 27648.0 * 10.0

    def telegrams(self) -> tuple:
        """(output, input) telegram of a PROFIdrive axis as it is on the bus now."""
        g, m = self.group, self.member
        link = g.links[m]
        if link is None:
            raise TypeError("only axes with a PROFIdrive drive exchange telegrams")
        link.cycles = g.cycles
        q = float(g.q[m])
        count = math.floor(float(g.x[m]) / q)
        hit = float(g.zm_hit[m])
        latched = not math.isnan(hit)
        zm = (bool(g.zm_dir[m]), latched, int(g.zm_count[m]) if latched else 0)
        absolute = None
        if link.revolutions:
            per_rev = link.steps << link.fine2
            absolute = math.floor(float(g.x[m]) / float(g.rev_dist[m]) * per_rev) % (link.revolutions * per_rev)
        rpm = float(g.v[m]) / float(g.lead[m]) * 60.0
        return link.telegrams(setpoint_word=int(g.word[m]), actual_rpm=rpm, count=count, zero_mark=zm,
                              absolute_count=absolute)

    def mechanical_position(self) -> float:
        return float(self.group.x[self.member])

    def arm_zero_mark(self, direction: float) -> None:
        g, m = self.group, self.member
        g.zm_dir[m] = 1.0 if direction > 0 else -1.0
        g.zm_hit[m] = math.nan

    def disarm_zero_mark(self) -> None:
        self.group.zm_dir[self.member] = 0.0

    def zero_mark_latched(self) -> float | None:
        g, m = self.group, self.member
        hit = g.zm_hit[m]
        if math.isnan(hit):
            return None
        g.zm_hit[m] = math.nan
        g.zm_dir[m] = 0.0
        return float(hit)

    def set_actual(self, bank: Any, value: float) -> None:
        g, m = self.group, self.member
        counted = math.floor(g.x[m] / g.q[m]) * g.q[m]
        old = counted + g.off[m]
        g.off[m] = value - counted
        g.last[m] += value - old
        bank.act_p[g.idx[m]] = value

    # --- torque limit and fixed end stops ---------------------------------------------------------------
    @property
    def can_limit_torque(self) -> bool:
        return True

    def set_torque_limit(self, limit: float | None) -> None:
        g, m = self.group, self.member
        g.tset[m] = _limit_value(limit, "torque limit [N m]")
        g.tlim[m] = min(g.tmax[m], g.tset[m])
        g.limited = True

    @property
    def torque(self) -> float:
        g, m = self.group, self.member
        if g.limited:
            return float(g.trq[m])
        # not modelled cycle by cycle yet: the speed loop's demand of this moment
        return float(g.jt[m] * (g.cmd[m] - g.v[m]) * (1.0 - g.e[m]) / g.dt)

    @property
    def torque_limit_active(self) -> bool:
        g = self.group
        return bool(g.limited and g.tact[self.member])


def _limit_value(limit: float | None, what: str) -> float:
    """A torque/force limit as a float (inf for None); a ValueError for anything but a number > 0."""
    if limit is None:
        return math.inf
    if isinstance(limit, bool) or not isinstance(limit, (int, float)) or not limit > 0 or math.isnan(limit):
        raise ValueError(f"{what} must be a number > 0 or None, got {limit!r}")
    return float(limit)


def _selector(idx: np.ndarray) -> slice | np.ndarray:
    """Where a group's members sit in the axis bank: a slice when they are consecutive axes (the usual
    case; a view instead of a gathered copy), else the index array."""
    n = len(idx)
    if n and int(idx[-1]) - int(idx[0]) == n - 1 and bool(np.all(np.diff(idx) == 1)):
        return slice(int(idx[0]), int(idx[0]) + n)
    return idx


class ServoDrives(DriveGroup):
    """Closed-loop drives (PROFIdrive telegram or analog speed setpoint) with incremental encoders.

    Torque: the drive's speed loop asks for the torque ``inertia * angular acceleration``; a torque limit
    (``DriveSpec.max_torque``, ``set_torque_limit``) caps the acceleration, and a fixed end stop
    (``PlantSpec.end_stop_min``/``end_stop_max``) holds the load while the drive keeps pushing, so the
    following error grows and the torque rises to its limit.  This costs nothing per cycle in groups where
    no member has a limit or an end stop (``limited``)."""

    closed_loop = True
    _FIELDS = ("x", "v", "cmd", "e", "tfac", "vlim", "off_dec", "ready_at", "ready_delay", "q", "off", "last",
               "zm_dir", "zm_dist", "zm_off", "zm_hit", "zm_count", "lead", "qscale", "qmax", "word", "rev_dist",
               "dist", "jt", "tmax", "tset", "tlim", "trq", "lo", "hi")

    def __init__(self) -> None:
        self.idx = np.zeros(0, dtype=np.intp)
        self.en = np.zeros(0, dtype=bool)
        self.flt = np.zeros(0, dtype=bool)        # drive fault: pulses off, the motor coasts/ramps down
        self.pulses = np.zeros(0, dtype=bool)     # the drive's power section is on and follows its setpoint
        self.blk = np.zeros(0, dtype=bool)        # injected: the load stands against an obstacle
        self.disturbed = False                    # any external force or blocked load (fault injection)
        self.tact = np.zeros(0, dtype=bool)       # the torque limit holds the drive back
        self.limited = False                      # any member with a torque limit or an end stop
        self.dt = 0.001
        self.links: list[ProfidriveLink | None] = []
        self.stepping: set[int] = set()           # PROFIdrive members whose state machine is moving
        self.cycles = 0
        for name in self._FIELDS:
            setattr(self, name, np.zeros(0))

    def add(self, index: int, spec: DriveSpec, servo_cycle: float, t: float) -> DriveChannel:
        plant, enc = spec.plant, spec.encoder
        tc = plant.speed_time_constant
        e = math.exp(-servo_cycle / tc) if tc > 0 else 0.0
        vlim = spec.max_velocity
        off_time = spec.off_ramp_time
        q = enc.increment
        x0 = plant.initial_position
        rev_dist = enc.distance_per_revolution
        zm_dist = plant.zero_mark_distance
        if zm_dist is None:
            # one zero mark per encoder revolution; a linear encoder has a single one
            zm_dist = rev_dist if enc.rotary else math.inf
        profidrive = spec.interface is SetpointInterface.PROFIDRIVE
        scale, limit = word_scale(spec.telegram, analog=not profidrive)
        lead = spec.length_per_revolution
        values = dict(x=x0, v=0.0, cmd=0.0, e=e, tfac=tc * (1 - e), vlim=vlim,
                      off_dec=(vlim / off_time) if off_time > 0 else math.inf, ready_at=math.inf,
                      ready_delay=spec.ready_delay, q=q, off=0.0, last=math.floor(x0 / q) * q,
                      zm_dir=0.0, zm_dist=zm_dist, zm_off=plant.zero_mark_offset, zm_hit=math.nan,
                      zm_count=0.0, lead=lead, qscale=scale / spec.reference_speed, qmax=float(limit), word=0.0,
                      rev_dist=rev_dist, dist=0.0, **self._torque_values(spec))
        for name in self._FIELDS:
            setattr(self, name, np.append(getattr(self, name), values[name]))
        self.idx = np.append(self.idx, index)
        self.sel = _selector(self.idx)
        # constant factors of the setpoint word (computed as the write did every cycle)
        self.neg_vlim = -self.vlim
        self.wscale = 60.0 * self.qscale
        self.wmin = -self.qmax - 1.0
        self.en = np.append(self.en, False)
        self.flt = np.append(self.flt, False)
        self.pulses = np.append(self.pulses, False)
        self.blk = np.append(self.blk, False)
        self.tact = np.append(self.tact, False)
        self.dt = servo_cycle
        self.limited = bool(self.limited or np.isfinite(self.tlim[-1]) or np.isfinite(self.lo[-1])
                            or np.isfinite(self.hi[-1]))
        member = len(self.idx) - 1
        self.links.append(ProfidriveLink(spec, servo_cycle) if profidrive else None)
        if profidrive:
            self.stepping.add(member)                 # leave "switching on inhibited" (OFF1 word)
        return _ServoChannel(self, member)

    def read(self, bank: Any, t: float, dt: float) -> None:
        if not len(self.idx):
            return
        self.cycles += 1
        if self.stepping:
            for m in sorted(self.stepping):
                link = self.links[m]
                link.step(dt)
                self.pulses[m] = link.operation_enabled
                if link.steady:
                    self.stepping.discard(m)
        on = self.pulses & ~self.flt & (self.ready_at <= t - dt + 1e-12)  # in operation during the last cycle
        c, v0 = self.cmd, self.v
        if self.disturbed:
            c = c - self.dist        # an external force: the speed loop settles this much below its setpoint
        # enabled: exact solution of the first-order speed loop for a command held over dt
        v_on = c + (v0 - c) * self.e
        x_on = c * dt + (v0 - c) * self.tfac
        if on.all():
            # the usual case: every drive of the group follows its setpoint (the ramp-down is not needed)
            self.v = v_on
            dx = x_on
        else:
            # not enabled: the drive ramps down on its own
            speed = np.abs(v0)
            dv = self.off_dec * dt
            v_off = np.sign(v0) * np.maximum(speed - dv, 0.0)
            with np.errstate(invalid="ignore", divide="ignore"):
                x_off = np.where(speed > dv, (v0 + v_off) * (0.5 * dt), v0 * speed / (2 * self.off_dec))
            self.v = np.where(on, v_on, v_off)
            dx = np.where(on, x_on, x_off)
        x_prev = self.x
        if self.limited:
            dx = self._limit(v0, dx, dt)
        if self.disturbed:
            self.v = np.where(self.blk, 0.0, self.v)
            dx = np.where(self.blk, 0.0, dx)
        self.x = self.x + dx
        if self.zm_dir.any():
            self._zero_marks(x_prev)
        act = np.floor(self.x / self.q) * self.q + self.off
        sel = self.sel
        bank.act_v[sel] = (act - self.last) / dt
        bank.act_p[sel] = act
        self.last = act

    @staticmethod
    def _torque_values(spec: DriveSpec) -> dict[str, float]:
        plant = spec.plant
        lo, hi = plant.travel()
        tmax = math.inf if spec.max_torque is None else float(spec.max_torque)
        # torque per load acceleration: inertia times the motor's angular acceleration per length unit/s²
        return dict(jt=plant.inertia * 2.0 * math.pi / spec.length_per_revolution, tmax=tmax, tset=math.inf,
                    tlim=tmax, trq=0.0, lo=lo, hi=hi)

    def _limit(self, v0: np.ndarray, dx: np.ndarray, dt: float) -> np.ndarray:
        """Cap the acceleration of this cycle at the torque limit and stop the load at its end stops;
        keeps the torque of the cycle (``trq``, ``tact``) and returns the travel."""
        a = (self.v - v0) / dt
        amax = self.tlim / self.jt
        sat = np.abs(a) > amax
        if sat.any():
            a = np.clip(a, -amax, amax)
            self.v = np.where(sat, v0 + a * dt, self.v)
            dx = np.where(sat, (v0 + 0.5 * a * dt) * dt, dx)
        self.trq = self.jt * a
        self.tact = sat
        x1 = self.x + dx
        stop = (x1 > self.hi) | (x1 < self.lo)
        if stop.any():
            # the load stands at the stop; the drive keeps pushing with the torque of its speed loop
            dx = np.where(stop, np.clip(x1, self.lo, self.hi) - self.x, dx)
            self.v = np.where(stop, 0.0, self.v)
        return dx

    def write(self, bank: Any, t: float) -> None:
        if len(self.idx):
            # the speed setpoint travels as an integer word: 16#4000 / 16#40000000 = 100 % of the reference
            # speed (PROFIdrive), 27648 = 100 % on an analog output (§2.2.2, §5.4.3.2)
            # np.minimum(np.maximum()) gives np.clip's result bit for bit (signed zeros, NaN), without its wrappers
            cmd = np.minimum(np.maximum(bank.cmd_v[self.sel], self.neg_vlim), self.vlim)
            word = np.minimum(np.maximum((cmd * self.wscale / self.lead).round(), self.wmin), self.qmax)
            self.word = word
            self.cmd = word * self.lead / self.wscale

    def _zero_marks(self, x_prev: np.ndarray) -> None:
        """Latch the exact encoder value at a zero mark crossed in the armed direction (hardware latch)."""
        for m in np.flatnonzero(self.zm_dir):
            a, b, d = float(x_prev[m]), float(self.x[m]), float(self.zm_dir[m])
            if (b - a) * d <= 0.0:
                continue
            dist, off = float(self.zm_dist[m]), float(self.zm_off[m])
            if math.isinf(dist):
                mark = off if (off - a) * d > 0 and (b - off) * d >= 0 else None
            else:
                k = math.floor((a - off) / dist) + (1 if d > 0 else 0)
                mark = off + k * dist
                if d < 0 and mark >= a:
                    mark -= dist
                if not ((mark - a) * d > 0 and (b - mark) * d >= 0):
                    mark = None
            if mark is not None:
                q = float(self.q[m])
                self.zm_count[m] = math.floor(mark / q)
                self.zm_hit[m] = math.floor(mark / q) * q + float(self.off[m])
                self.zm_dir[m] = 0.0


class _DirectChannel(DriveChannel):
    """Drives whose actual value is derived from the setpoint (stepper, ideal drive)."""

    def __init__(self, group: "SetpointDrives", member: int):
        self.group, self.member = group, member
        self.enabled = False
        self.fault = False

    def set_enable(self, on: bool, t: float) -> None:
        self.enabled = on

    def ready(self, t: float) -> bool:
        return self.enabled and not self.fault

    def set_fault(self, on: bool) -> None:
        self.fault = on

    def disturb(self, jump: float = 0.0, force: float | None = None, blocked: bool | None = None) -> None:
        g, m = self.group, self.member
        if not g.stepper:
            raise ValueError("a simulated axis (Simulation.Mode = 1) has an ideal drive and no load to disturb")
        if force is not None or blocked is not None:
            raise ValueError("a stepper on a pulse output (PTO) runs open loop: only a position jump (lost steps) "
                             "can be injected")
        g.mech_offset[m] += jump            # lost steps: the load is elsewhere, the pulse count does not see it

    def set_actual(self, bank: Any, value: float) -> None:
        g, m = self.group, self.member
        i = g.idx[m]
        # the load does not move when the coordinates change: keep the machine position continuous
        g.mech_offset[m] += float(bank.act_p[i]) - value
        g.grid[m] = value
        bank.act_p[i] = value

    def mechanical_position(self) -> float:
        g, m = self.group, self.member
        return float(g.bank.act_p[g.idx[m]]) + float(g.mech_offset[m])

    @property
    def communication_ok(self) -> bool:
        return not self.group.stepper

    def reconfigure(self, spec: DriveSpec) -> None:
        """Mechanics written at runtime (effective at enable, §12.9.5/§12.9.8): new pulse length."""
        g, m = self.group, self.member
        if g.stepper:
            g.pulse[m] = spec.pulse_length


class SetpointDrives(DriveGroup):
    """Actual value = setpoint: rounded to whole pulses for a stepper on a PTO, exact for the ideal drive."""

    def __init__(self, stepper: bool, bank: Any) -> None:
        self.stepper = stepper
        self.idx = np.zeros(0, dtype=np.intp)
        self.pulse = np.zeros(0)
        self.grid = np.zeros(0)
        self.mech_offset = np.zeros(0)          # machine position = actual value + offset
        self.bank = bank

    def add(self, index: int, spec: DriveSpec, servo_cycle: float, t: float) -> DriveChannel:
        pulse = spec.pulse_length if self.stepper else 0.0
        self.idx = np.append(self.idx, index)
        self.sel = _selector(self.idx)
        self.pulse = np.append(self.pulse, pulse)
        self.grid = np.append(self.grid, 0.0)
        self.mech_offset = np.append(self.mech_offset, spec.plant.initial_position)
        return _DirectChannel(self, len(self.idx) - 1)

    def read(self, bank: Any, t: float, dt: float) -> None:
        pass

    def write(self, bank: Any, t: float) -> None:
        if not len(self.idx):
            return
        sel = self.sel
        sp = bank.sp_p[sel]
        if self.stepper:
            sp = ((sp - self.grid) / self.pulse).round() * self.pulse + self.grid
        bank.act_p[sel] = sp
        bank.act_v[sel] = bank.sp_v[sel]
