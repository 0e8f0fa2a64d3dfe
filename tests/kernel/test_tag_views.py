"""Tag views (issue 9 item 2): a technology object presents its family's status and configuration tags as
attributes and string paths; the kernel module knows no tag, the vocabulary is the object's class's.

Alone on a small fake object with its own vocabulary, and through a kernel Controller axis."""
from __future__ import annotations

from typing import Any

import pytest

from plcmotion.kernel import Controller
from plcmotion.kernel import axis_status as S
from plcmotion.kernel.schema import BOOL, REAL, RW, R, AxisSchema, Param
from plcmotion.kernel.tag_views import TagAccessError, TagRef, TagViews

SCHEMA = AxisSchema("test object", [
    Param("Limits.Speed", REAL, 10.0, RW, (10,), 0.0, 100.0),
    Param("Probe[1].Inverted", BOOL, False, R),
])


class Thing(TagViews):
    """A technology object of a made-up family: two status tags in a group, one alone."""

    schema = SCHEMA
    _dynamic = {"State.Ready": lambda o: o.ready, "State.Count": lambda o: o.count, "Speed": lambda o: 2.5}
    _dynamic_types = {"State.Ready": "Bool", "State.Count": "DInt", "Speed": "LReal"}
    _dynamic_aliases = {"State.Okay": "State.Ready"}
    _status_groups = ("State",)
    _read_param_tags = frozenset({"State.Ready"})

    def __init__(self):
        self.name = "thing"
        self.ready, self.count = True, 3
        self.cfg = SCHEMA.defaults()
        self.written: list[tuple[str, Any]] = []

    def write_tag(self, path: str, value: Any) -> None:
        self.written.append((path, value))
        self.cfg[path] = value


def test_kernel_tag_views_status_and_configuration_by_attribute_and_path():
    t = Thing()
    assert t.State.Ready is True and t.State.Count == 3 and t.Speed == 2.5
    assert t.tag("State.Okay") is True                          # an alias spelling
    assert t.Limits.Speed == 10.0 == t.tag("Limits.Speed")
    assert t.Probe[1].Inverted is False                         # an array structure
    t.Limits.Speed = 20.0
    assert t.written == [("Limits.Speed", 20.0)] and t.tag("Limits.Speed") == 20.0
    with pytest.raises(TagAccessError):
        t.State.Ready = False                                   # a status tag is never written
    with pytest.raises(KeyError, match="not a tag of the test object"):
        t.tag("Limits.Sped")
    assert sorted(Thing.tag_paths()) == sorted(["State.Ready", "State.Count", "Speed", "Limits.Speed",
                                                "Probe[1].Inverted"])


def test_kernel_tag_views_references_for_read_and_write_instructions():
    t = Thing()
    ref = t.ref("State.Ready")
    assert isinstance(ref, TagRef) and ref.read() is True and ref.readable_by_read_param and ref.access == "RP"
    count = t.ref("State.Count")
    assert not count.readable_by_read_param and count.access == "RCCP"
    assert t.ref("Limits.Speed").data_type == "LReal"


def test_kernel_tag_views_of_a_controller_axis_use_the_axis_status():
    """A kernel Controller axis: the family's status tags read the neutral axis status (setpoint position,
    standstill) - at rest a disabled axis stands still at its start position."""
    ctl = Controller()
    axis = ctl.add_positioning_axis("ax", {"Actor.Type": 1, "DynamicLimits.MinVelocity": 0.0,
                                           "Sensor[1].Interface.Type": 2, "Plant.InitialPosition": 12.5})
    ctl.step()
    assert S.position(axis) == pytest.approx(12.5) and S.velocity(axis) == 0.0
    assert axis.tag("Position") == S.position(axis)
    assert S.accel_state(axis) == 0 and not S.accelerating(axis) and not S.decelerating(axis)
    assert not S.software_limit_active(axis, "min") and not S.communication_fault(axis)
