"""Families of technology objects: what a manual family plugs into the kernel.

The kernel runs axes, couplings and drives; it does not know which manual's technology objects a program
uses.  A family (a package such as ``plcmotion.s7_1200``) registers a :class:`Family` that names the objects
it offers and how to create them, which job kinds its instructions may start, which optional kernel features
it uses and which version-dependent rules apply.  ``Controller(family=...)`` looks the family up here and
delegates every ``add_*`` to its factories, so a new family is a new package, not a kernel edit.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable, Mapping

from .policy import OverridePolicy

# kinds of technology objects a family can offer (the Controller.add_* methods create them)
POSITIONING_AXIS = "a positioning axis"
SYNCHRONOUS_AXIS = "a synchronous axis"
EXTERNAL_ENCODER = "an external encoder"
LEADING_AXIS_PROXY = "a leading axis proxy"
CAM = "a cam"
COMMAND_TABLE = "a command table"

#: the controller table each kind of object is kept in (``Controller.axes``, ``.cams``, ...); others: ``objects``
TABLES = {POSITIONING_AXIS: "axes", SYNCHRONOUS_AXIS: "axes", CAM: "cams", COMMAND_TABLE: "command_tables"}

#: optional kernel features a family switches on
ACTUAL_VALUE_COUPLING = "actual value coupling"    # couple to the actual or delayed value of a leading value

#: version-dependent rules a family may put in force (``Family.rules``)
PULSE_SLICE_TIME = "pulse slice time"              # a new command on a pulse output starts at a segment boundary
DIRECT_HOMING_WHEN_DISABLED = "direct homing when disabled"   # set/shift the position of a disabled servo axis


def _no_rules(version: int) -> frozenset[str]:
    return frozenset()


@dataclass(frozen=True)
class Family:
    """What a manual family contributes.

    ``factories`` map an object kind (the constants above) to ``factory(ctl, name, params, *, source, **kw)``
    that validates the parameters with the family's schema and returns the new object.  ``job_kinds`` are the
    kernel job kinds the family's instructions may submit (None: all); a kind outside it is refused as "not
    available".  ``rules(version)`` gives the names of version-dependent rules the kernel asks for (e.g. a
    newer technology version's homing of a disabled axis).  ``policy``: the override rules of its instructions
(which running job a new one aborts, keeps or is rejected by), the depth of the axis job queue and the
mapping of its buffer-mode input (``kernel.policy``); None: the PLCopen default, every motion job takes over.
    ``schemas`` map an object kind to the ``kernel.schema.AxisSchema`` that checks its tags, so a project
    file can report every bad tag of an object before creating it (a kind without one cannot be declared
    in a project file).  ``describe_fault(fault)``: how summaries name a kernel fault of the family's
    objects (its alarm number and text); None: the fault's own text.  ``error_view(obj)``: the texts a
    summary shows for the errors of one object, where the family keeps errors the kernel's alarms do not
    hold (an error record of its own); None: one text per alarm (``error_texts``).  ``setup(ctl)``: the family's
    controller-wide runtime state (e.g. data blocks shared by all its objects), made once per controller and
    kept as ``ctl.extension``; a restart of the controller calls its ``reinitialize(reason)`` when it has
    one.  None: the family has no such state."""

    name: str
    versions: tuple[int, ...]
    default_version: int
    factories: Mapping[str, Callable[..., Any]]
    job_kinds: frozenset[Any] | None = None
    features: frozenset[str] = frozenset()
    rules: Callable[[int], frozenset[str]] = field(default=_no_rules)
    policy: OverridePolicy | None = None
    schemas: Mapping[str, Any] = field(default_factory=dict)
    describe_fault: Callable[[Any], str] | None = None
    error_view: Callable[[Any], list[str]] | None = None
    setup: Callable[[Any], Any] | None = None


_REGISTRY: dict[str, Family] = {}


def register(family: Family) -> Family:
    """Make ``family`` available to ``Controller(family=family.name)`` (idempotent for the same object)."""
    known = _REGISTRY.get(family.name)
    if known is not None and known is not family:
        raise ValueError(f"a family named {family.name!r} is registered already")
    _REGISTRY[family.name] = family
    return family


def names() -> tuple[str, ...]:
    """Names of the registered families, in the order they were registered."""
    return tuple(_REGISTRY)


def lookup(name: Any) -> Family:
    """The registered family ``name``; a ValueError listing the known ones otherwise."""
    family = _REGISTRY.get(name) if isinstance(name, str) else None
    if family is None:
        raise ValueError(f"family must be one of {', '.join(_REGISTRY)}, got {name!r}")
    return family


def default() -> Family:
    """The family of ``Controller()`` without ``family``: the first one registered (``plcmotion`` registers
    S7-1200 first, so existing programs keep their meaning)."""
    if not _REGISTRY:
        raise ValueError("no family is registered: import plcmotion (or a family package) first")
    return next(iter(_REGISTRY.values()))


def error_texts(family: Family, obj: Any) -> list[str]:
    """What a summary shows for the errors of ``obj`` (an object of ``family``); empty: none.  The family's
    ``error_view`` where it has one, else each alarm of the object, named by ``describe_fault``."""
    if family.error_view is not None:
        return list(family.error_view(obj))
    describe = family.describe_fault
    alarms = getattr(obj, "alarms", ())
    if describe is None:
        return [str(a) for a in alarms]
    return [f"{describe(a)} [{a}]" for a in alarms]


def offering(kind: str) -> tuple[str, ...]:
    """Names of the families that offer objects of ``kind``."""
    return tuple(n for n, f in _REGISTRY.items() if kind in f.factories)
