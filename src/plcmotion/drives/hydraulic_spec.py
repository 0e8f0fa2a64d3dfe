"""What a hydraulic axis is, in the words of motion control: the valve output and the cylinder behind it.

S7-Technology V4.1 §3.1.4, §4.6: the controller drives a proportional valve with a +-10 V output (a
manipulated variable of -100 ... +100 %), the valve meters the oil flow into a cylinder, an encoder measures
the piston.  :class:`HydraulicSpec` (``DriveSpec.hydraulic``) is the controller's side: valve type, the
valve characteristic that turns the velocity command into an output, output limits, the substitute output
and its ramp.  :class:`CylinderSpec` (``PlantSpec.cylinder``) is the simulated machine: piston areas,
supply pressure, valve size and dynamics, moving mass, load, stroke.  Units are those of a hydraulics data
sheet (cm², bar, l/min, N, kg); positions and velocities are in the axis's length unit.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from enum import Enum

from .spec_errors import DriveSpecError, finite
from .valve import ValveCharacteristic


class ValveType(str, Enum):
    #: flow (velocity) valve: the output meters the flow; against an obstacle the cylinder presses with the
    #: full supply pressure
    Q = "Q"
    #: flow valve with pressure limiting: the pressure on the driving side is limited so that the cylinder
    #: force does not exceed the force limit (configured or set at run time)
    PQ = "PQ"


@dataclass(frozen=True)
class HydraulicSpec:
    """The controller side of a hydraulic axis: how the velocity command becomes a valve output."""

    valve: ValveType = ValveType.Q
    #: velocity at 100 % output while no valve characteristic is active (the straight line) [length unit/s]
    reference_velocity: float = 500.0
    #: the active valve characteristic at start (None: the straight line through +-reference_velocity);
    #: changed at run time with ``set_characteristic`` of the drive channel
    characteristic: ValveCharacteristic | None = None
    output_min: float = -100.0           #: manipulated variable limiting, low [% of 10 V]
    output_max: float = 100.0            #: manipulated variable limiting, high [% of 10 V]
    #: substitute output [%] the output ramps to when the drive is disabled or faults (OFF2-style stop;
    #: S7-Technology V4.1 MC_Power QOutputValue); changed at run time with ``set_off_output``
    off_output: float = 0.0
    #: rate [%/s] of that ramp and of the compensation of a characteristic changeover
    #: (S7-Technology V4.1 parameter 5009, default 100 %/s)
    output_ramp: float = 100.0
    #: force limit [N] of a P/Q valve from the start (None: none until ``set_torque_limit``)
    force_limit: float | None = None

    def __post_init__(self) -> None:
        if not isinstance(self.valve, ValveType):
            raise DriveSpecError("HydraulicSpec.valve", self.valve, "must be ValveType.Q or ValveType.PQ")
        if finite("HydraulicSpec.reference_velocity", self.reference_velocity) <= 0.0:
            raise DriveSpecError("HydraulicSpec.reference_velocity", self.reference_velocity, "must be > 0")
        if self.characteristic is not None and not isinstance(self.characteristic, ValveCharacteristic):
            raise DriveSpecError("HydraulicSpec.characteristic", self.characteristic,
                                 "must be a ValveCharacteristic or None")
        lo = finite("HydraulicSpec.output_min", self.output_min)
        hi = finite("HydraulicSpec.output_max", self.output_max)
        if not -100.0 <= lo < hi <= 100.0:
            raise DriveSpecError("HydraulicSpec.output_min/output_max", (self.output_min, self.output_max),
                                 "need -100 <= output_min < output_max <= 100 [%]")
        if not -100.0 <= finite("HydraulicSpec.off_output", self.off_output) <= 100.0:
            raise DriveSpecError("HydraulicSpec.off_output", self.off_output, "must lie in [-100, 100] %")
        if finite("HydraulicSpec.output_ramp", self.output_ramp) <= 0.0:
            raise DriveSpecError("HydraulicSpec.output_ramp", self.output_ramp, "must be > 0 %/s")
        if self.force_limit is not None:
            if self.valve is not ValveType.PQ:
                raise DriveSpecError("HydraulicSpec.force_limit", self.force_limit,
                                     "only a P/Q valve (ValveType.PQ) limits the force")
            if finite("HydraulicSpec.force_limit", self.force_limit) <= 0.0:
                raise DriveSpecError("HydraulicSpec.force_limit", self.force_limit, "must be > 0 N")

    def active_characteristic(self) -> ValveCharacteristic:
        return self.characteristic or ValveCharacteristic.linear(self.reference_velocity)


@dataclass(frozen=True)
class CylinderSpec:
    """The simulated cylinder and its valve: a differential cylinder (side A = piston side, pushes in the
    axis's positive direction; side B = rod side) fed through a 4/3 proportional valve from a constant
    supply pressure, oil incompressible and without leakage (the orifice equation Q = K * opening *
    sqrt(pressure drop) at each control edge)."""

    area_a: float = 20.0                 #: piston area, side A [cm²]
    area_b: float = 10.0                 #: annulus area, side B [cm²]
    supply_pressure: float = 100.0       #: [bar]
    nominal_flow: float = 40.0           #: valve flow per control edge at the nominal pressure drop [l/min]
    nominal_pressure_drop: float = 35.0  #: pressure drop per control edge of the nominal flow [bar]
    valve_time_constant: float = 0.005   #: first-order lag of the spool [s] (0: none)
    #: spool overlap [% of 10 V]: the valve opens only beyond it (a dead band)
    valve_overlap: float = 0.0
    #: the spool opening as a curve (output %, opening -1 ... 1), rising; () for the straight line with
    #: ``valve_overlap``
    valve_curve: tuple[tuple[float, float], ...] = ()
    mass: float = 50.0                   #: moving mass [kg]
    load_force: float = 0.0              #: constant external force in the positive direction [N]
    stroke_min: float = 0.0              #: piston position at the cylinder's lower end [length unit]
    stroke_max: float = 500.0            #: piston position at the cylinder's upper end [length unit]
    metres_per_unit: float = 0.001       #: one length unit in metres (0.001: the axis counts in mm)

    def __post_init__(self) -> None:
        for name in ("area_a", "area_b", "supply_pressure", "nominal_flow", "nominal_pressure_drop", "mass",
                     "metres_per_unit"):
            if finite(f"CylinderSpec.{name}", getattr(self, name)) <= 0.0:
                raise DriveSpecError(f"CylinderSpec.{name}", getattr(self, name), "must be > 0")
        if finite("CylinderSpec.valve_time_constant", self.valve_time_constant) < 0.0:
            raise DriveSpecError("CylinderSpec.valve_time_constant", self.valve_time_constant, "must be >= 0 s")
        if not 0.0 <= finite("CylinderSpec.valve_overlap", self.valve_overlap) < 100.0:
            raise DriveSpecError("CylinderSpec.valve_overlap", self.valve_overlap, "must lie in [0, 100) %")
        finite("CylinderSpec.load_force", self.load_force)
        lo = finite("CylinderSpec.stroke_min", self.stroke_min)
        hi = finite("CylinderSpec.stroke_max", self.stroke_max)
        if not lo < hi:
            raise DriveSpecError("CylinderSpec.stroke_min/stroke_max", (self.stroke_min, self.stroke_max),
                                 "need stroke_min < stroke_max")
        curve = self.opening_curve()
        for (u0, y0), (u1, y1) in zip(curve, curve[1:]):
            if not (u1 > u0 and y1 >= y0):
                raise DriveSpecError("CylinderSpec.valve_curve", self.valve_curve,
                                     "outputs must rise and openings must not fall")
        if any(not -100.0 <= u <= 100.0 or not -1.0 <= y <= 1.0 for u, y in curve):
            raise DriveSpecError("CylinderSpec.valve_curve", self.valve_curve,
                                 "outputs in [-100, 100] %, openings in [-1, 1]")

    def opening_curve(self) -> tuple[tuple[float, float], ...]:
        """The spool opening (-1 ... 1) over the output [%] as rising points."""
        if self.valve_curve:
            pts = []
            for k, pair in enumerate(self.valve_curve):
                if not isinstance(pair, (list, tuple)) or len(pair) != 2:
                    raise DriveSpecError(f"CylinderSpec.valve_curve[{k}]", pair, "must be a pair (output %, opening)")
                pts.append((finite(f"CylinderSpec.valve_curve[{k}]", pair[0]),
                            finite(f"CylinderSpec.valve_curve[{k}]", pair[1])))
            if len(pts) < 2:
                raise DriveSpecError("CylinderSpec.valve_curve", self.valve_curve, "give at least two points")
            return tuple(pts)
        ov = float(self.valve_overlap)
        if ov == 0.0:
            return ((-100.0, -1.0), (100.0, 1.0))
        return ((-100.0, -1.0), (-ov, 0.0), (ov, 0.0), (100.0, 1.0))

    # --- derived SI values ------------------------------------------------------------------------------
    @property
    def flow_coefficient(self) -> float:
        """K of Q = K * opening * sqrt(dp) [m³/s per sqrt(Pa)]."""
        return self.nominal_flow / 60000.0 / math.sqrt(self.nominal_pressure_drop * 1e5)

    def steady_velocity(self, opening: float, force: float = 0.0) -> float:
        """Velocity [length unit/s] at a constant ``opening`` against an external ``force`` [N] in the
        positive direction (force balance of the two orifice flows, see ``drives.hydraulic``)."""
        aa, ab = self.area_a * 1e-4, self.area_b * 1e-4
        ps = self.supply_pressure * 1e5
        if opening == 0.0:
            return 0.0
        drive = ps * aa if opening > 0 else -ps * ab
        net = drive + force + self.load_force
        v = self.flow_coefficient * abs(opening) * math.sqrt(abs(net) / (aa ** 3 + ab ** 3))
        return math.copysign(v, net) / self.metres_per_unit


__all__ = ["CylinderSpec", "HydraulicSpec", "ValveType"]
