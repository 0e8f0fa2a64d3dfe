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
from .axes import AXIS_CLASSES, AxisT, PositioningAxisT, SpeedAxis, SynchronizationAxis
from .builder import POSITIONING, SPEED, SYNCHRONIZATION
from .device import TechnologyDevice
from .policy_basic import POLICY
from .schema import AXIS
from .to_errors import describe_fault

NAME = "S7-Technology"

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
        raise ConfigurationError(where, [Issue("Wizard.Technology", "selection", technology,
                                               "allowed here: " + " or ".join(names[t] for t in technologies))])
    ext = device(ctl)
    number = ext.db_number(cfg["DBNumber"], where)
    axis = ctl.new_axis(AXIS_CLASSES[technology], name, {**flat, "Wizard.Technology": technology}, where,
                        db_number=number, **kw)
    ext.register(axis)
    return axis


def _positioning_axis(ctl: Any, name: str, flat: Mapping[str, Any], where: str) -> AxisT:
    return _new_axis(ctl, name, flat, where, (SPEED, POSITIONING))


def _synchronization_axis(ctl: Any, name: str, flat: Mapping[str, Any], where: str, *,
                          leading_values: Any = ()) -> AxisT:
    return _new_axis(ctl, name, flat, where, (SYNCHRONIZATION,), leading_values=leading_values)


S7_TECHNOLOGY = K.register(K.Family(
    NAME, versions=(4,), default_version=4,
    factories={K.POSITIONING_AXIS: _positioning_axis, K.SYNCHRONOUS_AXIS: _synchronization_axis},
    job_kinds=JOB_KINDS, policy=POLICY, schemas={K.POSITIONING_AXIS: AXIS, K.SYNCHRONOUS_AXIS: AXIS},
    describe_fault=describe_fault, setup=TechnologyDevice))

__all__ = ["S7_TECHNOLOGY", "NAME", "AxisT", "SpeedAxis", "PositioningAxisT", "SynchronizationAxis",
           "TechnologyDevice", "device"]
