"""Configuration parameters of a Pilz drive axis (the motion core's axis parameters), as a kernel schema.

The names are the drive's parameter identifiers used by Pilz motion commands V6.5 (I00 travel range, I10
maximum velocity, ...).  The manual names them but gives no ranges or start values; the values chosen here
are listed in docs/pilz/decisions.md.  The command register (I400 ... I431, I230) and the status words are
not configuration: they are ``registers.py``.  ``builder.axis_config`` turns valid values into the kernel's
typed configuration.
"""
from __future__ import annotations

from typing import Any, Mapping

from ...kernel.plant_schema import PLANT_PARAMS
from ...kernel.schema import ADDR, BOOL, E12, INT, P, R, REAL, RW, AxisSchema, Issue, Param
from .builder import axis_config
from .homing_methods import CIA402_METHODS

#: effective at the next motion-core cycle
NOW = (10,)

# fmt: off
_PARAMS: list[Param] = [
    # --- travel range, permitted direction, limits (Pilz V6.5 §1.2.2, §1.2.3, §1.2.4) -----------------
    Param("I00", INT, 0, RW, NOW, choices=(0, 1), doc="travel range: 0 limited, 1 endless"),
    Param("I01", REAL, 360.0, RW, NOW, 0.0, E12, lo_open=True, doc="revolution length of an endless axis"),
    Param("I04", INT, 0, RW, NOW, choices=(0, 1, 2),
          doc="permitted direction: 0 both, 1 positive only, 2 negative only (values: decisions.md)"),
    Param("I10", REAL, 500.0, RW, NOW, 0.0, E12, lo_open=True, doc="maximum velocity [unit/s]"),
    Param("I11", REAL, 5000.0, RW, NOW, 0.0, E12, doc="maximum acceleration and deceleration [unit/s^2]"),
    Param("I16", REAL, 100000.0, RW, NOW, 0.0, E12, doc="maximum jerk [unit/s^3]"),
    Param("I22", REAL, 0.1, RW, NOW, 0.0, E12, doc="position window [unit]"),
    Param("I87", REAL, 0.0, RW, NOW, 0.0, 600.0, doc="time the actual position stays in I22 before Done [s]"),
    Param("C40", REAL, 1.0, RW, NOW, 0.0, E12, doc="velocity window around the set velocity [unit/s]"),
    Param("I50", REAL, 0.0, RW, NOW, -E12, E12, doc="positive software limit switch (I50 = I51: not used)"),
    Param("I51", REAL, 0.0, RW, NOW, -E12, E12, doc="negative software limit switch"),
    Param("I25", REAL, 100.0, RW, NOW, 0.0, 100.0, doc="velocity feed-forward of the position controller [%]"),
    Param("I20", REAL, 20.0, RW, NOW, 0.0, 2000.0, lo_open=True, doc="position controller gain Kv [1/s]"),
    Param("I42", REAL, 0.0, RW, NOW, 0.0, 600.0, doc="brake wait time before the brake engages [s]"),
    Param("F00", INT, 0, R, (), choices=(0, 1), doc="brake control: 0 inactive, 1 active"),
    Param("BrakeOutput", ADDR, "", R, (), choices=("Q",), doc="output that releases the holding brake ('' none)"),
    Param("I113", INT, 0, RW, NOW, choices=(0, 1),
          doc="MC_MoveVelocity set value takeover (I424): 0 at the start only, 1 cyclic"),
    Param("I119", INT, 0, RW, NOW, choices=(0, 1),
          doc="disable v-set at command change: 0 cyclic takeover (default), 1 takeover only at the start"),
    Param("I423", REAL, 0.01, RW, NOW, 0.0, 10.0, doc="extrapolation time of missing cyclic set values [s]"),
    Param("E65", REAL, 10.0, RW, NOW, 0.0, E12, doc="maximum positive torque/force"),
    Param("E66", REAL, 10.0, RW, NOW, 0.0, E12, doc="maximum negative torque/force (magnitude)"),
    # --- limit and reference switches (Pilz V6.5 §1.2.2, Tab. 21) -------------------------------------
    Param("I101", ADDR, "", R, (), choices=("I",), doc="source of the positive limit switch (input, '' none)"),
    Param("I102", ADDR, "", R, (), choices=("I",), doc="source of the negative limit switch"),
    Param("I103", ADDR, "", R, (), choices=("I",), doc="source of the reference switch"),
    Param("LimitSwitchLevel", BOOL, False, R,
          doc="limit switches are actuated while their input is TRUE (False: NC contacts)"),
    Param("ReferenceSwitchLevel", BOOL, True, R, doc="reference switch actuated while its input is TRUE"),
    # --- referencing (Pilz V6.5 §1.7.1 Tab. 21, Tab. 19, Tab. 22) --------------------------------------
    Param("I30", INT, 5, RW, NOW, choices=(0, 1, 2, 3, 4, 5),
          doc="referencing type: 0 inactive, 1 reference input, 2 limit switch, 3 zero pulse, "
              "4 torque/force stop, 5 define home"),
    Param("I31", INT, 0, RW, NOW, choices=(0, 1), doc="referencing direction: 0 positive, 1 negative"),
    Param("I35", INT, 0, RW, NOW, choices=(0, 1), doc="referencing with zero pulse: 0 no, 1 yes"),
    Param("ReferenceSwitchPlacement", INT, 0, RW, NOW, choices=(0, 1),
          doc="I30 = 1: 0 switch at the end of travel in I31, 1 switch in the middle (reverse at a limit switch)"),
    Param("A586", INT, None, RW, NOW, choices=(0,) + CIA402_METHODS, optional=True,
          doc="CiA 402 homing method; set: it selects the method instead of I30/I31/I35"),
    Param("I28", REAL, 1.0, RW, NOW, 0.0, E12, doc="torque/force limit of the torque/force stop referencing"),
    Param("I29", REAL, 0.1, RW, NOW, 0.0, 600.0,
          doc="time the torque/force must stay at the limit I28 before the reference is set [s]"),
    Param("I32", REAL, 50.0, RW, NOW, 0.0, E12, doc="referencing speed fast [unit/s]"),
    Param("I33", REAL, 10.0, RW, NOW, 0.0, E12, doc="referencing speed slow [unit/s]"),
    Param("I34", REAL, 0.0, RW, NOW, -E12, E12, doc="reference position"),
    Param("I39", REAL, 500.0, RW, NOW, 0.0, E12, doc="referencing acceleration and deceleration [unit/s^2]"),
    Param("I44", REAL, 10000.0, RW, NOW, 0.0, E12, doc="referencing jerk [unit/s^3]"),
    Param("I43", INT, 0, RW, NOW, choices=(0, 1), doc="travel to the reference position after referencing"),
    # --- drive (simulated servo) ------------------------------------------------------------------------
    Param("Drive.MaxSpeed", REAL, 6000.0, R, (), 0.0, E12, lo_open=True, doc="maximum motor speed [1/min]"),
    Param("Drive.FeedPerRevolution", REAL, 10.0, R, (), 0.0, E12, lo_open=True,
          doc="load travel per motor revolution [unit]"),
    Param("Drive.EncoderIncrements", INT, 4096, R, (), 1, 1 << 24, 
          doc="encoder lines per revolution (the actual value resolves each into 2^11 counts)"),
    Param("Drive.Inertia", REAL, None, R, (), 0.0, E12, lo_open=True, optional=True,
          doc="MC_TorqueControl load model: torque per unit/s^2 of load acceleration (unset: the simulated "
              "drive's own, Plant.Inertia x 2 pi / Drive.FeedPerRevolution)"),
    Param("Drive.EndStopNegative", REAL, None, R, (), -E12, E12, optional=True,
          doc="machine position of a mechanical end stop at the negative end (torque/force stop referencing)"),
    Param("Drive.EndStopPositive", REAL, None, R, (), -E12, E12, optional=True,
          doc="machine position of a mechanical end stop at the positive end"),
    Param("Drive.Friction", REAL, 0.0, R, (), 0.0, E12,
          doc="MC_TorqueControl load model: viscous friction torque per unit/s"),
]
# fmt: on


def rule_issues(cfg: Mapping[str, Any]) -> list[Issue]:
    """Rules over more than one parameter."""
    issues: list[Issue] = []
    if cfg["I50"] < cfg["I51"]:
        issues.append(Issue("I50", "rule:sw_limit_order", cfg["I50"],
                            f"the positive software limit switch I50 must not lie below I51 = {cfg['I51']!r}"))
    return issues


PILZ_AXIS = AxisSchema("Pilz drive axis", _PARAMS + list(PLANT_PARAMS), rules=rule_issues, build=axis_config)

__all__ = ["PILZ_AXIS", "rule_issues"]
