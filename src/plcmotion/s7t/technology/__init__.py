"""S7-Technology V4.1 (CPU 31xT) technology objects and their registration as the family "S7-Technology".

``Controller(family="S7-Technology")``: the kernel's servo cycle is the IPO cycle (position control and
interpolation), the application cycle is OB1 (§5.1, §5.3).  The controller's ``extension`` is the
integrated technology (``device.TechnologyDevice``): technology DBs by number, MCDevice DB, DB update and
OB65.  Axes are created with ``ctl.add_positioning_axis(name, params)`` - its tag ``Wizard.Technology`` = 0
makes a speed-controlled axis, 1 (default) a positioning axis - and ``ctl.add_synchronous_axis`` for the
synchronization axis (technology 2).
"""
from __future__ import annotations

from typing import Any, Mapping

from ...kernel import family as K
from ...kernel.errors import ConfigurationError
from ...kernel.jobs import JobKind
from ...kernel.schema import Issue
from .axes import AxisT, PositioningAxisT, SpeedAxis, SynchronizationAxis
from .builder import POSITIONING, SPEED, SYNCHRONIZATION
from .device import TechnologyDevice
from .hydraulic_axis import axis_class
from .override import POLICY
from .schema import AXIS
from .to_errors import describe_fault, error_view

NAME = "S7-Technology"
#: ``technology_version``: 10 * major + minor of the technology (V4.1 only, docs/s7t/decisions.md)
VERSION = 41

#: the kernel jobs of the instructions of this family so far (§6.2: single-axis instructions)
JOB_KINDS = frozenset({JobKind.HALT, JobKind.STOP, JobKind.ABSOLUTE, JobKind.RELATIVE, JobKind.VELOCITY,
                       JobKind.SUPERIMPOSED, JobKind.RESET, JobKind.HOME_DIRECT, JobKind.HOME_ACTIVE,
                       JobKind.HOME_PASSIVE, JobKind.HOME_CANCEL})


def device(ctl: Any) -> TechnologyDevice:
    """The integrated technology of an S7-Technology controller (``ctl.extension``)."""
    ext = getattr(ctl, "extension", None)
    if not isinstance(ext, TechnologyDevice):
        raise TypeError(f"not an S7-Technology controller (Controller(family={NAME!r})): {ctl!r}")
    return ext


def _new_axis(ctl: Any, name: str, flat: Mapping[str, Any], where: str, technologies: tuple[int, ...],
              **kw: Any) -> AxisT:
    cfg, issues = AXIS.validate(flat)
    if issues:
        raise ConfigurationError(where, issues)
    technology = cfg["Wizard.Technology"]
    if "Wizard.Technology" not in flat:
        technology = technologies[-1]
    elif technology not in technologies:
        names = {SPEED: "0 (speed-controlled)", POSITIONING: "1 (positioning)", SYNCHRONIZATION: "2 (synchronization)"}
        kind = "synchronous" if technologies == (SYNCHRONIZATION,) else "positioning"
        other = ('a synchronization axis is type = "synchronous"' if kind == "positioning" else
                 'a speed-controlled or positioning axis is type = "positioning"')
        raise ConfigurationError(where, [Issue("Wizard.Technology", "selection", technology,
                                               "allowed: " + " or ".join(names[t] for t in technologies)
                                               + f' for type = "{kind}"; {other}')])
    ext = device(ctl)
    number = ext.db_number(cfg["DBNumber"], where)
    axis = ctl.new_axis(axis_class(technology, cfg), name, {**flat, "Wizard.Technology": technology}, where,
                        db_number=number, **kw)
    ext.register(axis)
    return axis


def _positioning_axis(ctl: Any, name: str, flat: Mapping[str, Any], where: str) -> AxisT:
    return _new_axis(ctl, name, flat, where, (SPEED, POSITIONING))


def _synchronization_axis(ctl: Any, name: str, flat: Mapping[str, Any], where: str, *,
                          leading_values: Any = ()) -> AxisT:
    return _new_axis(ctl, name, flat, where, (SYNCHRONIZATION,), leading_values=leading_values)


#: the DP cycle is a whole multiple of 0.25 ms and the IPO cycle (the kernel's servo cycle) a whole multiple of
#: the DP cycle (S7-Technology V4.1 §5.1, "system clocks" of S7T Config)
DP_CYCLE_GRANULARITY = 0.00025


def _setup(ctl: Any) -> TechnologyDevice:
    """The integrated technology of a new controller; its IPO cycle (``servo_cycle``) must be a whole number
    of 0.25 ms."""
    n = ctl.servo_cycle / DP_CYCLE_GRANULARITY
    if abs(n - round(n)) > 1e-9 * n:
        raise ValueError(f"servo_cycle = {ctl.servo_cycle!r}: the IPO cycle of {NAME} is a whole multiple of the "
                         f"DP cycle, itself a whole multiple of 0.25 ms (e.g. 0.001, 0.002)")
    return TechnologyDevice(ctl)


S7_TECHNOLOGY = K.register(K.Family(
    NAME, versions=(VERSION,), default_version=VERSION,
    factories={K.POSITIONING_AXIS: _positioning_axis, K.SYNCHRONOUS_AXIS: _synchronization_axis},
    job_kinds=JOB_KINDS, policy=POLICY, schemas={K.POSITIONING_AXIS: AXIS, K.SYNCHRONOUS_AXIS: AXIS},
    describe_fault=describe_fault, error_view=error_view, setup=_setup))

__all__ = ["S7_TECHNOLOGY", "NAME", "VERSION", "POLICY", "DP_CYCLE_GRANULARITY", "AxisT", "SpeedAxis",
           "PositioningAxisT", "SynchronizationAxis", "TechnologyDevice", "device"]
