"""Simulated hydraulic axes: a proportional valve on a +-10 V output moving a differential cylinder.

Controller side (S7-Technology V4.1 §3.1.4, §4.6.4): the position controller's velocity command goes
through the active valve characteristic (:class:`~plcmotion.drives.valve.ValveCharacteristic`, the inverse
of the valve profile) to an output in percent of 10 V, limited to ``HydraulicSpec.output_min/max`` and
quantised like an S7 analog output (27648 = 100 % = 10 V).  A changed characteristic does not make the
output jump: the difference fades at ``HydraulicSpec.output_ramp`` (§6.2.13, 100 %/s by default).  Without
enable, or on a fault, the output ramps at that rate to the substitute value ``off_output`` (the OFF2-style
stop of MC_Power StopMode 3 with QOutputValue).

Plant: the spool follows the output through a first-order lag and opens by the valve's curve (overlap: a dead
band).  Oil is incompressible and nothing leaks, so the orifice equation Q = K y sqrt(dp) at both control
edges and the flows v*A_A, v*A_B fix the chamber pressures for a velocity v; the force balance on the
moving mass m is

    m dv/dt = P0(y) + F_load - v|v| (A_A³ + A_B³) / (K y)²,   P0 = p_S A_A (y > 0), -p_S A_B (y < 0),

integrated with the implicit Euler step (stable for any opening; a closed valve holds the piston).  A P/Q
valve limits |P0| to the force limit.  At a cylinder end or a fixed end stop the piston stands still and
presses with P0.  The encoder counts the piston position in increments as for a servo drive.
"""
from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

import numpy as np

from .base import DriveChannel
from .hydraulic_spec import CylinderSpec, HydraulicSpec, ValveType
from .simulated import ServoDrives, _limit_value, _ServoChannel
from .spec import ActuatorKind, DriveSpec, SetpointInterface
from .spec_errors import DriveSpecError
from .valve import ValveCharacteristic, interp_rows, pad_rows

_COUNTS_PER_PERCENT = 276.48             # S7 analog output: 27648 = 100 % = 10 V


class _HydraulicChannel(_ServoChannel):
    """Events and read-backs of one hydraulic axis (enable, ready, fault, homing, zero marks as a servo)."""

    group: "HydraulicDrives"

    # --- the valve output --------------------------------------------------------------------------------
    @property
    def characteristic(self) -> ValveCharacteristic:
        """The active valve characteristic."""
        return self.group.chars[self.member]

    def set_characteristic(self, characteristic: ValveCharacteristic | None) -> None:
        """Activate ``characteristic`` (None: the straight line through +-reference velocity).  While the
        drive is on, the jump of the output it would cause is compensated at ``output_ramp``."""
        if characteristic is not None and not isinstance(characteristic, ValveCharacteristic):
            raise TypeError(f"a valve characteristic is a ValveCharacteristic or None, got {characteristic!r}")
        g, m = self.group, self.member
        new = characteristic or ValveCharacteristic.linear(float(g.vref[m]))
        c = float(g.cmd[m])
        if g.on[m]:
            g.blend[m] += g.chars[m].output(c) - new.output(c)
            g.blending = True
        g.chars[m] = new
        g.tables()

    def reconfigure(self, spec: DriveSpec) -> None:
        """The valve settings a program may change while the axis runs (S7-Technology V4.1 §9.4: parameter
        5009, the output ramp, and 1401/1402, the output limits, all "effective immediately"): the next
        servo cycle works with them.  The valve, cylinder and characteristic stay as commissioned."""
        hyd = spec.hydraulic
        if hyd is None:
            return
        g, m = self.group, self.member
        g.ramp[m], g.omin[m], g.omax[m] = hyd.output_ramp, hyd.output_min, hyd.output_max

    def set_off_output(self, percent: float) -> None:
        """The substitute output [%] the output ramps to without enable (MC_Power QOutputValue)."""
        if isinstance(percent, bool) or not isinstance(percent, (int, float)) or not -100.0 <= percent <= 100.0:
            raise ValueError(f"substitute output must be a number in [-100, 100] %, got {percent!r}")
        self.group.offu[self.member] = float(percent)

    @property
    def output_percent(self) -> float:
        """The output now [% of 10 V]."""
        return float(self.group.out[self.member])

    @property
    def output_voltage(self) -> float:
        """The output now [V]."""
        return float(self.group.out[self.member]) / 10.0

    # --- the cylinder --------------------------------------------------------------------------------------
    @property
    def pressures(self) -> tuple[float, float]:
        """Pressures of chamber A and chamber B [bar] (pressure sensors A/B)."""
        g, m = self.group, self.member
        return float(g.pa[m]) / 1e5, float(g.pb[m]) / 1e5

    @property
    def force(self) -> float:
        """Cylinder force p_A A_A - p_B A_B [N], positive in the axis's positive direction."""
        return float(self.group.force[self.member])

    @property
    def spool_opening(self) -> float:
        """The valve spool's opening (-1 ... 1)."""
        return float(self.group.y[self.member])

    # --- force limit (P/Q valve) -------------------------------------------------------------------------
    @property
    def can_limit_torque(self) -> bool:
        return bool(self.group.pq[self.member])

    def set_torque_limit(self, limit: float | None) -> None:
        """Limit the cylinder force to ``limit`` [N] (a P/Q valve's pressure limiting), None: no run-time
        limit (a configured ``HydraulicSpec.force_limit`` stays)."""
        g, m = self.group, self.member
        if not g.pq[m]:
            raise ValueError("a Q valve cannot limit the force (a P/Q valve can: HydraulicSpec.valve = ValveType.PQ)")
        g.fset[m] = _limit_value(limit, "force limit [N]")
        g.flim[m] = min(g.fmax[m], g.fset[m])

    @property
    def torque(self) -> float:
        return self.force

    @property
    def torque_limit_active(self) -> bool:
        return bool(self.group.fact[self.member])

    def disturb(self, jump: float = 0.0, force: float | None = None, blocked: bool | None = None) -> None:
        if force:
            raise ValueError("the load of a hydraulic drive is a force in N (CylinderSpec.load_force), not a "
                             "speed offset: only jump and blocked can be injected")
        g, m = self.group, self.member
        if jump:
            g.x[m] += jump
        if blocked is not None:
            g.blk[m] = blocked
        g.disturbed = bool(g.blk.any())


class HydraulicDrives(ServoDrives):
    """Hydraulic axes (valve, cylinder, encoder), all members updated at once on numpy arrays."""

    closed_loop = True
    _HFIELDS = ("u", "out", "blend", "omin", "omax", "offu", "ramp", "vref", "y", "ev", "aa", "ab", "ps", "kf",
                "csum", "mass", "fext", "mpu", "fmax", "fset", "flim", "force", "pa", "pb")

    def __init__(self) -> None:
        super().__init__()
        for name in self._HFIELDS:
            setattr(self, name, np.zeros(0))
        self.pq = np.zeros(0, dtype=bool)         # a P/Q valve (can limit the force)
        self.fact = np.zeros(0, dtype=bool)       # the force limit holds the cylinder back
        self.on = np.zeros(0, dtype=bool)         # output follows the controller (enabled, ready, no fault)
        self.chars: list[ValveCharacteristic] = []
        self.curves: list[tuple[tuple[float, float], ...]] = []
        self.blending = False

    def add(self, index: int, spec: DriveSpec, servo_cycle: float, t: float) -> DriveChannel:
        if spec.actuator is not ActuatorKind.HYDRAULIC:
            raise DriveSpecError("DriveSpec.actuator", spec.actuator, "a hydraulic drive group takes "
                                 "ActuatorKind.HYDRAULIC")
        hyd = spec.hydraulic or HydraulicSpec()
        cyl = spec.plant.cylinder or CylinderSpec()
        # the +-10 V output is an analog word whether it leaves on a module or on an IM 174/ADI4
        super().add(index, replace(spec, interface=SetpointInterface.ANALOG), servo_cycle, t)
        self.lo[-1], self.hi[-1] = spec.plant.travel(hydraulic=True)
        aa, ab = cyl.area_a * 1e-4, cyl.area_b * 1e-4
        fmax = math.inf if hyd.force_limit is None else float(hyd.force_limit)
        tv = cyl.valve_time_constant
        values = dict(u=hyd.off_output, out=hyd.off_output, blend=0.0, omin=hyd.output_min, omax=hyd.output_max,
                      offu=hyd.off_output, ramp=hyd.output_ramp, vref=hyd.reference_velocity, y=0.0,
                      ev=math.exp(-servo_cycle / tv) if tv > 0 else 0.0, aa=aa, ab=ab,
                      ps=cyl.supply_pressure * 1e5, kf=cyl.flow_coefficient, csum=aa ** 3 + ab ** 3, mass=cyl.mass,
                      fext=cyl.load_force, mpu=cyl.metres_per_unit, fmax=fmax, fset=math.inf, flim=fmax,
                      force=0.0, pa=0.0, pb=0.0)
        for name in self._HFIELDS:
            setattr(self, name, np.append(getattr(self, name), values[name]))
        self.out[-1] = np.round(self.out[-1] * _COUNTS_PER_PERCENT) / _COUNTS_PER_PERCENT
        self.word[-1] = np.round(hyd.off_output * _COUNTS_PER_PERCENT)
        self.pq = np.append(self.pq, hyd.valve is ValveType.PQ)
        self.fact = np.append(self.fact, False)
        self.on = np.append(self.on, False)
        self.chars.append(hyd.active_characteristic())
        self.curves.append(cyl.opening_curve())
        self.tables()
        return _HydraulicChannel(self, len(self.idx) - 1)

    def tables(self) -> None:
        """Pad the members' characteristics and valve curves into arrays (when one is added or changed)."""
        branches = [c.branches() for c in self.chars]
        self.cpv, self.cpu = pad_rows(b[0] for b in branches)
        self.cnv, self.cnu = pad_rows(b[1] for b in branches)
        self.cu0 = np.array([b[2] for b in branches])
        self.fu, self.fy = pad_rows(self.curves)

    def read(self, bank: Any, t: float, dt: float) -> None:
        if not len(self.idx):
            return
        # spool: first-order lag towards the opening the held output asks for
        target = interp_rows(self.fu, self.fy, self.out)
        y = target + (self.y - target) * self.ev
        y = np.where(np.abs(y) < 1e-12, 0.0, y)     # a spool settled within 1e-12 of centre is closed
        self.y = y
        drive_raw = np.where(y > 0.0, self.ps * self.aa, np.where(y < 0.0, -self.ps * self.ab, 0.0))
        drive = np.clip(drive_raw, -self.flim, self.flim)
        # implicit Euler of m dv/dt = drive + F_load - v|v| C / (K y)²  (SI units)
        v0 = self.v * self.mpu
        c = v0 + (drive + self.fext) * (dt / self.mass)
        s = (self.kf * y) ** 2
        g = self.csum * dt / self.mass
        open_ = s > 0.0
        s_safe = np.where(open_, s, 1.0)
        v1 = np.where(open_, 2.0 * c * s / (s_safe + np.sqrt(s * s + 4.0 * g * s * np.abs(c))), 0.0)
        dx = 0.5 * (v0 + v1) * dt / self.mpu
        if self.disturbed:
            v1 = np.where(self.blk, 0.0, v1)
            dx = np.where(self.blk, 0.0, dx)
        x_prev = self.x
        x1 = self.x + dx
        stop = (x1 > self.hi) | (x1 < self.lo)
        if stop.any():
            x1 = np.clip(x1, self.lo, self.hi)          # the piston stands at the cylinder end / end stop
            v1 = np.where(stop, 0.0, v1)
        self.x = x1
        self.v = v1 / self.mpu
        # force and chamber pressures of this velocity (a closed valve keeps its trapped pressures)
        loss = np.where(open_, v1 * np.abs(v1) / s_safe, 0.0)        # sgn(v) (v / (K y))²
        self.force = np.where(open_, drive - loss * self.csum, -self.fext)
        with np.errstate(divide="ignore", invalid="ignore"):
            pa = np.where(y > 0.0, drive / self.aa - loss * self.aa ** 2, -loss * self.aa ** 2)
            pb = np.where(y > 0.0, loss * self.ab ** 2, -drive / self.ab + loss * self.ab ** 2)
        self.pa = np.where(open_, pa, self.pa)
        self.pb = np.where(open_, pb, self.pb)
        self.fact = (np.abs(drive_raw) > self.flim) & (np.abs(self.force) >= self.flim * (1.0 - 1e-9))
        if self.zm_dir.any():
            self._zero_marks(x_prev)
        act = np.floor(self.x / self.q) * self.q + self.off
        bank.act_v[self.idx] = (act - self.last) / dt
        bank.act_p[self.idx] = act
        self.last = act

    def write(self, bank: Any, t: float) -> None:
        if not len(self.idx):
            return
        c = np.nan_to_num(bank.cmd_v[self.idx], nan=0.0)
        self.cmd = c
        u = np.where(c > 0.0, interp_rows(self.cpv, self.cpu, np.maximum(c, 0.0)),
                     np.where(c < 0.0, interp_rows(self.cnv, self.cnu, np.maximum(-c, 0.0)), self.cu0))
        step = self.ramp * self.dt
        if self.blending:
            # a characteristic changeover: the output's jump fades at the output ramp
            self.blend = np.sign(self.blend) * np.maximum(np.abs(self.blend) - step, 0.0)
            u = u + self.blend
            self.blending = bool(self.blend.any())
        self.on = self.pulses & ~self.flt & (self.ready_at <= t + 1e-12)
        # without enable or on a fault: ramp to the substitute output (OFF2-style stop)
        off = self.u + np.clip(self.offu - self.u, -step, step)
        self.u = u = np.clip(np.where(self.on, u, off), self.omin, self.omax)
        # the analog word; the ramps run on the exact value so that its rounding does not add up
        self.word = np.round(u * _COUNTS_PER_PERCENT)
        self.out = self.word / _COUNTS_PER_PERCENT


__all__ = ["HydraulicDrives"]
