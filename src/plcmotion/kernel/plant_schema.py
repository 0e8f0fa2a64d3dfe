"""The simulated machine behind an axis: its parameters (``Plant.*``) and its :class:`PlantSpec`.

These are not tags of any technology object: they describe the drive dynamics and the mechanics the
simulation puts behind an axis (where the load starts, where its switches are, how fast the drive
follows) and are set by configuration only (access ``P``).  Every family's axis schema includes them
under the same names, and its builder hands them to :func:`plant_spec` with the switch inputs of its
own tags.
"""
from __future__ import annotations

import math
from typing import Any, Iterable, Mapping

from ..drives.hydraulic_spec import CylinderSpec
from ..drives.spec import PlantSpec, SwitchSpec
from ..drives.spec_errors import DriveSpecError
from .errors import ConfigurationError
from .schema import E12, REAL, Issue, P, Param

# fmt: off
PLANT_PARAMS: list[Param] = [
    Param("Plant.SpeedTimeConstant", REAL, 0.002, P, (), 0.0, 10.0,
          doc="first-order time constant [s] of the simulated drive's closed speed loop"),
    Param("Plant.ReadyDelay", REAL, 0.0, P, (), 0.0, 60.0,
          doc="time [s] the simulated drive needs from enable until it reports 'Drive ready'"),
    Param("Plant.OffRampTime", REAL, 0.1, P, (), 0.0, 600.0,
          doc="time [s] the simulated drive ramps from maximum speed to zero when its enable is removed"),
    Param("Plant.PTOLimitFrequency", REAL, 100000.0, P, (), choices=(20000.0, 100000.0, 200000.0, 1000000.0),
          doc="limit frequency [Hz] of the pulse output (§2.1.1: 20 kHz, 100 kHz, 200 kHz or 1 MHz)"),
    Param("Plant.InitialPosition", REAL, 0.0, P, (), -E12, E12,
          doc="load position [user unit] of the simulated mechanics at controller start"),
    Param("Plant.HWLimitMinPosition", REAL, None, P, (), -E12, E12, optional=True,
          doc="machine position at and below which the low hardware limit switch is actuated"),
    Param("Plant.HWLimitMaxPosition", REAL, None, P, (), -E12, E12, optional=True,
          doc="machine position at and above which the high hardware limit switch is actuated"),
    Param("Plant.HomingSwitchPosition", REAL, None, P, (), -E12, E12, optional=True,
          doc="machine position of the lower end of the homing switch (reference cam)"),
    Param("Plant.HomingSwitchLength", REAL, 10.0, P, (), 0.0, E12, lo_open=True,
          doc="length of the homing switch [user unit]"),
    Param("Plant.HomingSwitchPeriod", REAL, None, P, (), 0.0, E12, lo_open=True, optional=True,
          doc="the homing switch repeats with this period (e.g. 360 on a rotating spindle)"),
    Param("Plant.ZeroMarkDistance", REAL, None, P, (), 0.0, E12, lo_open=True, optional=True,
          doc="distance between encoder zero marks (default: one encoder revolution)"),
    Param("Plant.ZeroMarkOffset", REAL, 0.0, P, (), -E12, E12,
          doc="machine position of one encoder zero mark"),
    Param("Plant.EndStopMinPosition", REAL, None, P, (), -E12, E12, optional=True,
          doc="machine position of a fixed end stop the load cannot pass downwards"),
    Param("Plant.EndStopMaxPosition", REAL, None, P, (), -E12, E12, optional=True,
          doc="machine position of a fixed end stop the load cannot pass upwards"),
    Param("Plant.Inertia", REAL, 1.0e-3, P, (), 0.0, E12, lo_open=True,
          doc="moment of inertia [kg m²] of motor and load at the motor shaft (drive torque)"),
]

#: the simulated cylinder of a hydraulic axis (``drives.hydraulic_spec.CylinderSpec``), for families with
#: hydraulic axes to include in their schema and hand to :func:`cylinder_spec`
CYLINDER_PARAMS: list[Param] = [
    Param("Plant.Cylinder.AreaA", REAL, 20.0, P, (), 0.0, E12, lo_open=True, doc="piston area, side A [cm²]"),
    Param("Plant.Cylinder.AreaB", REAL, 10.0, P, (), 0.0, E12, lo_open=True, doc="annulus area, side B [cm²]"),
    Param("Plant.Cylinder.SupplyPressure", REAL, 100.0, P, (), 0.0, E12, lo_open=True, doc="supply pressure [bar]"),
    Param("Plant.Cylinder.NominalFlow", REAL, 40.0, P, (), 0.0, E12, lo_open=True,
          doc="valve flow per control edge at the nominal pressure drop [l/min]"),
    Param("Plant.Cylinder.NominalPressureDrop", REAL, 35.0, P, (), 0.0, E12, lo_open=True,
          doc="pressure drop per control edge of the nominal flow [bar]"),
    Param("Plant.Cylinder.ValveTimeConstant", REAL, 0.005, P, (), 0.0, 10.0,
          doc="first-order time constant of the valve spool [s]"),
    Param("Plant.Cylinder.ValveOverlap", REAL, 0.0, P, (), 0.0, 100.0, doc="spool overlap (dead band) [%]"),
    Param("Plant.Cylinder.Mass", REAL, 50.0, P, (), 0.0, E12, lo_open=True, doc="moving mass [kg]"),
    Param("Plant.Cylinder.LoadForce", REAL, 0.0, P, (), -E12, E12,
          doc="constant external force on the piston in the positive direction [N]"),
    Param("Plant.Cylinder.StrokeMin", REAL, 0.0, P, (), -E12, E12, doc="piston position at the lower cylinder end"),
    Param("Plant.Cylinder.StrokeMax", REAL, 500.0, P, (), -E12, E12, doc="piston position at the upper cylinder end"),
    Param("Plant.Cylinder.MetresPerUnit", REAL, 0.001, P, (), 0.0, E12, lo_open=True,
          doc="one length unit of the axis in metres"),
]
# fmt: on

_CYLINDER_FIELDS = {"AreaA": "area_a", "AreaB": "area_b", "SupplyPressure": "supply_pressure",
                    "NominalFlow": "nominal_flow", "NominalPressureDrop": "nominal_pressure_drop",
                    "ValveTimeConstant": "valve_time_constant", "ValveOverlap": "valve_overlap", "Mass": "mass",
                    "LoadForce": "load_force", "StrokeMin": "stroke_min", "StrokeMax": "stroke_max",
                    "MetresPerUnit": "metres_per_unit"}
#: the tag behind each field of the specs, for configuration errors that name the tag
_TAGS = {"PlantSpec.initial_position": "Plant.InitialPosition", "PlantSpec.inertia": "Plant.Inertia",
         "PlantSpec.end_stop_min/end_stop_max": "Plant.EndStopMinPosition",
         **{f"CylinderSpec.{f}": f"Plant.Cylinder.{t}" for t, f in _CYLINDER_FIELDS.items()},
         "CylinderSpec.stroke_min/stroke_max": "Plant.Cylinder.StrokeMin"}


def cylinder_spec(p: Mapping[str, Any]) -> CylinderSpec:
    """The simulated cylinder of a hydraulic axis with the :data:`CYLINDER_PARAMS` values in ``p``."""
    try:
        return CylinderSpec(**{f: p[f"Plant.Cylinder.{t}"] for t, f in _CYLINDER_FIELDS.items()})
    except DriveSpecError as exc:
        raise _configuration_error(exc) from None


def _configuration_error(exc: DriveSpecError) -> ConfigurationError:
    tag = _TAGS.get(exc.field, exc.field)
    return ConfigurationError("simulated machine (Plant.*)", [Issue(tag, "rule:plant", exc.value, exc.allowed)])


def plant_spec(p: Mapping[str, Any], *, hw_min: tuple[str, bool], hw_max: tuple[str, bool],
               homing_inputs: Iterable[tuple[str, bool]], ready_input: str,
               cylinder: CylinderSpec | None = None) -> PlantSpec:
    """The simulated machine of an axis with plant parameters in ``p``, its hardware limit switches wired to
    the inputs ``hw_min``/``hw_max`` and its reference cam to ``homing_inputs`` (each ``(address, actuated
    when TRUE)``, address "" for none) and the drive's ready signal to ``ready_input``; ``cylinder`` for a
    hydraulic axis (:func:`cylinder_spec`).  Positions that do not fit (the load outside its end stops or
    its cylinder) are a :class:`ConfigurationError` naming the tag."""
    switches: list[SwitchSpec] = []
    lo = p["Plant.HWLimitMinPosition"]
    if lo is not None and hw_min[0]:
        switches.append(SwitchSpec(hw_min[0], -math.inf, lo, hw_min[1], "low hardware limit switch"))
    hi = p["Plant.HWLimitMaxPosition"]
    if hi is not None and hw_max[0]:
        switches.append(SwitchSpec(hw_max[0], hi, math.inf, hw_max[1], "high hardware limit switch"))
    cam = p["Plant.HomingSwitchPosition"]
    if cam is not None:
        # one reference cam, wired to every homing input that names an address (once per input)
        length = p["Plant.HomingSwitchLength"]
        seen: set[str] = set()
        for address, level in homing_inputs:
            if address and address not in seen:
                seen.add(address)
                switches.append(SwitchSpec(address, cam, cam + length, level, "homing switch",
                                           p["Plant.HomingSwitchPeriod"]))
    try:
        return PlantSpec(
            initial_position=p["Plant.InitialPosition"],
            speed_time_constant=p["Plant.SpeedTimeConstant"],
            zero_mark_distance=p["Plant.ZeroMarkDistance"],
            zero_mark_offset=p["Plant.ZeroMarkOffset"],
            switches=tuple(switches),
            ready_input=ready_input,
            end_stop_min=p.get("Plant.EndStopMinPosition"),
            end_stop_max=p.get("Plant.EndStopMaxPosition"),
            inertia=p.get("Plant.Inertia", 1.0e-3),
            cylinder=cylinder,
        )
    except DriveSpecError as exc:
        raise _configuration_error(exc) from None
