"""The parameter store component (issue 9 items 1 and 3): tag writes, access rights and the moment a written
value takes effect, alone on a fake host with a small schema and through a kernel Controller axis.

The rules come from the effectiveness legends of S7-1200 Motion Control V6 §12.9: a drive with position
control takes a written value at the next servo cycle (code 10), a pulse drive at enable (codes 1, 2), at
the next command (5), ...; a value that is invalid when it takes effect is the configuration error of its
tag; RW tags may be written by the program, WP tags only with MC_WriteParam, R tags not at all."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import pytest

from plcmotion.kernel import Controller
from plcmotion.kernel import faults as F
from plcmotion.kernel.parameter_store import ParameterStore
from plcmotion.kernel.schema import INT, P, R, REAL, RW, SERVO, WP, AxisSchema, Issue, Param
from plcmotion.kernel.tag_views import TagAccessError


@dataclass(frozen=True)
class _Config:
    speed: float
    gain: float

    def tag_name(self, field: str) -> str:
        return {"software_limits.minimum": "Low"}.get(field, field)


def _rules(cfg):
    return [Issue("Low", "rule:low_above_high", cfg["Low"], "below High")] if cfg["Low"] > cfg["High"] else []


SCHEMA = AxisSchema("test object", [
    Param("Speed", REAL, 10.0, RW, (1, 10), 0.0, 100.0),
    Param("Gain", REAL, 2.0, WP, (2,), 0.0, 5.0, lo_open=True),
    Param("Kind", INT, 0, R, (), choices=(0, 1)),
    Param("Low", REAL, 0.0, RW, (10, 5), -100.0, 100.0),
    Param("High", REAL, 50.0, RW, (10, 5), -100.0, 100.0),
    Param("Model.Lag", REAL, 0.0, P, (), 0.0, 1.0),
], rules=_rules, build=lambda v: _Config(v["Speed"], v["Gain"]),
    pulse_moments={"enable": {1, 2}, "command": {5}}, pulse_only_write_param={"Gain"})


@dataclass(eq=False)
class FakeHost:
    """The Protocol ParameterHost: a name, the drive kind, a controller with its set of dirty axes."""

    pto: bool = False
    name: str = "obj"
    config: Any = None
    alarms: list = field(default_factory=list)
    replans: int = 0
    bank_updates: int = 0

    def __post_init__(self):
        self.ctl = type("Ctl", (), {"_dirty_axes": set()})()

    def raise_alarm(self, fault):
        self.alarms.append(fault)

    def _apply_bank_config(self):
        self.bank_updates += 1

    def _replan(self):
        self.replans += 1


def _store(pto=False, **values):
    host = FakeHost(pto=pto)
    cfg, issues = SCHEMA.validate(values)
    assert not issues
    return host, ParameterStore(host, SCHEMA, cfg)


def test_kernel_parameter_store_builds_the_config_of_the_start_values():
    host, store = _store(Speed=20.0)
    assert host.config == _Config(20.0, 2.0)
    assert store.values == store.start == store.effective and not store.dirty


def test_kernel_parameter_store_servo_write_takes_effect_at_the_next_servo_cycle():
    """S7-1200 V6 §12.9, code 10: the next servo cycle (a drive with position control)."""
    host, store = _store()
    store.write("Speed", 30.0)
    assert store.values["Speed"] == 30.0 and store.effective["Speed"] == 10.0
    assert host in host.ctl._dirty_axes                    # the servo cycle looks at it
    assert store.apply("enable") is None and store.effective["Speed"] == 10.0
    assert store.apply(SERVO) is None
    assert store.effective["Speed"] == 30.0 and host.config.speed == 30.0
    assert host.bank_updates == 1 and host.replans == 1 and not store.dirty


def test_kernel_parameter_store_pulse_write_waits_for_its_moment():
    """S7-1200 V6 §12.9: on a PTO axis code 1 counts at enable, code 5 at the next command."""
    host, store = _store(pto=True)
    store.write("Speed", 30.0)
    store.write("Low", -10.0)
    assert host not in host.ctl._dirty_axes                # a pulse drive: not at the next servo cycle
    assert store.apply(SERVO) is None and store.effective["Speed"] == 10.0
    store.apply("command")
    assert store.effective["Low"] == -10.0 and store.effective["Speed"] == 10.0
    store.apply("enable")
    assert store.effective["Speed"] == 30.0 and host.replans == 0      # no running motion to re-plan at enable


def test_kernel_parameter_store_access_rights():
    """RW: the program; WP: only with MC_WriteParam; R and plant parameters: never; WP of a pulse-only tag is
    R on other drives (S7-1200 V6 §12.9.19 Simulation.Mode)."""
    host, store = _store(pto=True)
    with pytest.raises(TagAccessError, match="read-only"):
        store.write("Gain", 3.0)
    store.write("Gain", 3.0, via_write_param=True)
    with pytest.raises(TagAccessError, match="read-only"):
        store.write("Kind", 1, via_write_param=True)
    with pytest.raises(TagAccessError, match="not a writable tag"):
        store.write("Model.Lag", 0.5)
    with pytest.raises(TypeError):
        store.write("Speed", "fast")
    _, servo = _store()
    assert (servo.access("Gain"), store.access("Gain")) == (R, WP)


def test_kernel_parameter_store_invalid_value_becomes_the_config_alarm_of_its_tag():
    """An invalid value is stored and becomes the configuration error of its tag when it takes effect; the
    configuration in effect stays as it was."""
    host, store = _store()
    store.write("Speed", 500.0)                              # above the range [0, 100]
    bad = store.apply(SERVO)
    assert bad is not None and bad.kind == F.CONFIG and host.alarms == [bad]
    assert host.config.speed == 10.0 and "Speed" in store.dirty
    store.write("Speed", 50.0)
    assert store.config_fault(apply=True) is None and host.config.speed == 50.0


def test_kernel_parameter_store_limit_order_changed_at_runtime_is_the_operating_error():
    """S7-1200 V6 §12.8: software limits in the wrong order written at runtime give 16#8010 (remove enable),
    not the configuration error of the tag."""
    host, store = _store()
    store.write("Low", 60.0)
    bad = store.apply(SERVO)
    assert bad.kind == F.SW_LIMIT_ORDER


def test_kernel_parameter_store_restart_returns_to_the_start_values():
    host, store = _store()
    store.write("Speed", 30.0)
    store.apply(SERVO)
    store.restart()
    assert store.values["Speed"] == store.effective["Speed"] == 10.0 and host.config.speed == 10.0


def test_kernel_parameter_store_of_a_controller_axis():
    """Through a kernel Controller axis (the default family's schema): a written RW tag takes effect at the
    next servo cycle on a drive with position control (code 10)."""
    ctl = Controller()
    axis = ctl.add_positioning_axis("ax", {"Actor.Type": 1, "DynamicLimits.MinVelocity": 0.0,
                                           "Sensor[1].Interface.Type": 2})
    assert isinstance(axis.parameters, ParameterStore)
    axis.write_tag("DynamicDefaults.Acceleration", 30.0)
    assert axis.cfg["DynamicDefaults.Acceleration"] == 30.0 and axis.eff["DynamicDefaults.Acceleration"] != 30.0
    ctl.step()
    assert axis.eff["DynamicDefaults.Acceleration"] == 30.0 and axis.config.defaults.acceleration == 30.0
