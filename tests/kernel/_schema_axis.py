"""Kernel tests build axes of their own classes; the kernel axis takes its configuration schema from a
family's axis class (``schema``), so such a test borrows the schema of the controller's default family.

No dialect is imported: the class is found through ``Controller().add_positioning_axis``.
"""
from __future__ import annotations

from plcmotion.kernel import Controller
from plcmotion.kernel.axis import PositioningAxis


def with_schema(cls: type[PositioningAxis], params: dict) -> type[PositioningAxis]:
    """``cls`` (a kernel axis class of a test) combined with the default family's positioning axis class,
    which gives it that family's schema and tag tables but none of its factory's components."""
    family_class = type(Controller().add_positioning_axis("probe", params))
    if issubclass(family_class, cls):
        return family_class
    return type(cls.__name__, (cls, family_class), {})
