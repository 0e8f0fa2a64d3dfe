"""Configuration tags of the S7-Technology axes (S7-Technology V4.1 §3.1, §4.5, §9.4).

The tags carry the expert-list names of the technology parameters (§9.4, ``s7-technology-parameters.csv``),
data set 1 and encoder 1 where the list numbers them ``DataSet_x`` / ``Encoder_x``.  ENUM-valued tags hold
their ValueDint (§9.4.12).  What the axis wizard of S7T Config decides when the object is created (§4.5:
technology, real or virtual, linear or rotary, the drive's telegram) are family tags under ``Wizard.``, the
simulated drive's speeds under ``Drive.``; ``DBNumber`` is the number of the technology DB (§2.5.3).

Access and effectiveness follow the list: "Read, Write" tags are written by MC_WriteParameter (access
``WP``); "Immediately" tags take effect in the next IPO cycle, "Restart" tags with MC_Reset Restart = TRUE
(kept as start values).  The list gives ranges, not start values; the start values chosen here are listed
in the report of issue 11 (docs/s7t/decisions.md).
"""
from __future__ import annotations

from typing import Any, Mapping

from ...kernel.plant_schema import PLANT_PARAMS
from ...kernel.schema import E12, INT, REAL, WP, R, AxisSchema, Issue, Param
from . import hydraulic_params as H
from .datasets import DATASET_PARAMS, dataset_rule_issues
from .encoders import ENCODER_PARAMS
from .homing_params import HOMING_PARAMS, homing_rule_issues
from .schema_io import IO_PARAMS
from .stored_params import generated
from .builder import (DYN, FE, GEAR, PV, TELEGRAMS_NO_ENCODER, TELEGRAMS_ONE_ENCODER, TELEGRAMS_TWO_ENCODERS,
                      axis_config, max_drive_velocity)

NOW = (10,)            # "Immediately": the next IPO cycle
RESTART = ()           # "Restart": a start value, in effect after MC_Reset Restart = TRUE

YES_NO = (0, 1)                          # §9.4.12 EnumYesNo: NO = 0, YES = 1
ACTIVE_INACTIVE = (0, 1)                 # EnumActiveInactive: INACTIVE = 0, ACTIVE = 1
DIRECTION_TYPE = (4, 5)                  # EnumDirectionType: NEGATIVE = 4, POSITIVE = 5
#: EnumDirection: EFFECTIVE = 3 (the current direction), NEGATIVE = 4, POSITIVE = 5, BY_VALUE = 38 (sign of
#: the velocity), SHORTEST_WAY = 39
DIRECTIONS = (3, 4, 5, 38, 39)
PROFILES = (66, 67)                      # EnumProfile: SMOOTH = 66, TRAPEZOIDAL = 67
TELEGRAMS = TELEGRAMS_NO_ENCODER + TELEGRAMS_ONE_ENCODER + TELEGRAMS_TWO_ENCODERS

# fmt: off
_PARAMS: list[Param] = [
    # --- the axis wizard (§4.5) and the technology DB ----------------------------------------------------
    Param("Wizard.Technology", INT, 1, R, (), choices=(0, 1, 2),
          doc="axis technology (§3.1.1): 0 speed-controlled, 1 positioning, 2 synchronization"),
    Param("Wizard.Virtual", INT, 0, R, (), choices=(0, 1), doc="1: virtual axis, no drive and no encoder (§3.1.5)"),
    Param("Wizard.AxisType", INT, 0, R, (), choices=(0, 1), doc="0 linear, 1 rotary (§3.1.3)"),
    Param("Wizard.Telegram", INT, 3, R, (), choices=TELEGRAMS,
          doc="PROFIdrive telegram of the drive (§4.2.3 Table 4-1)"),
    Param("DBNumber", INT, None, R, (), 1, 65535, optional=True, unique=True,
          doc="number of the technology DB (auto-assigned when absent)"),
    # --- the simulated drive ------------------------------------------------------------------------------
    Param("Drive.ReferenceSpeed", REAL, 6000.0, R, (), 0.0, E12, lo_open=True,
          doc="motor speed [1/min] of a 100 % speed setpoint"),
    Param("Drive.MaxSpeed", REAL, 6000.0, R, (), 0.0, E12, lo_open=True, doc="maximum motor speed [1/min]"),
    # --- mechanics §4.5.5 (numbers 1100, 1201-1203, 2020/2021) -------------------------------------------
    Param("LeadScrew.pitchVal", REAL, 10.0, WP, RESTART, 0.0, E12, lo_open=True),
    Param(f"{GEAR}.numFactor", INT, 1, WP, RESTART, 1, 2147483647, doc="motor revolutions"),
    Param(f"{GEAR}.denFactor", INT, 1, WP, RESTART, 1, 2147483647, doc="load revolutions"),
    Param("Modulo.state", INT, 0, WP, RESTART, choices=ACTIVE_INACTIVE),
    Param("Modulo.length", REAL, 360.0, WP, RESTART, 0.0, E12, lo_open=True),
    Param("Modulo.startValue", REAL, 0.0, WP, RESTART, -E12, E12),
    # --- limits §4.5.7 (numbers 8, 12, 16, 1241, 2-4) ----------------------------------------------------
    Param("TypeOfAxis.MaxVelocity.maximum", REAL, 1000.0, WP, RESTART, 0.0, E12, lo_open=True),
    Param("TypeOfAxis.MaxAcceleration.maximum", REAL, 10000.0, WP, NOW, 0.0, E12, lo_open=True),
    Param("TypeOfAxis.MaxJerk.maximum", REAL, 1.0e6, WP, NOW, 0.0, E12, lo_open=True),
    Param("TypeOfAxis.EmergencyRampGenerator.maxDeceleration", REAL, 1000.0, WP, NOW, 0.0, E12, lo_open=True),
    Param("swlimit.state", INT, 0, WP, NOW, choices=ACTIVE_INACTIVE),
    Param("swlimit.minusposition", REAL, -10000.0, WP, NOW, -E12, E12),
    Param("swlimit.plusposition", REAL, 10000.0, WP, NOW, -E12, E12),
    # --- default dynamics §4.5.6 (numbers 4241-4250) -----------------------------------------------------
    Param(f"{DYN}.velocity", REAL, 100.0, WP, NOW, 0.0, E12, lo_open=True),
    Param(f"{DYN}.positiveaccel", REAL, 100.0, WP, NOW, 0.0, E12, lo_open=True),
    Param(f"{DYN}.negativeaccel", REAL, 100.0, WP, NOW, 0.0, E12, lo_open=True),
    Param(f"{DYN}.positiveaccelstartjerk", REAL, 1000.0, WP, NOW, 0.0, E12, doc="0: trapezoidal profile"),
    Param(f"{DYN}.stoptime", REAL, 1.0, WP, NOW, 0.0, E12, lo_open=True,
          doc="MC_Power StopMode 2: the axis stops within this time [s]"),
    Param(f"{DYN}.profile", INT, 67, WP, NOW, choices=PROFILES,
          doc="default profile (the instructions choose theirs with their Jerk input)"),
    Param(f"{DYN}.direction", INT, 5, WP, NOW, choices=DIRECTIONS, doc="Direction = 0 of the instructions"),
    Param("override.velocity", REAL, 100.0, WP, NOW, 0.0, 200.0, doc="velocity override [%] (number 4142)"),
    # --- homing §4.5.10 (numbers 1121, 1123, 4180-4183) --------------------------------------------------
    Param("TypeOfAxis.Homing.referencingNecessary", INT, 1, WP, RESTART, choices=YES_NO,
          doc="YES: absolute motion needs a homed axis"),
    Param("TypeOfAxis.Homing.direction", INT, 5, WP, RESTART, choices=DIRECTION_TYPE),
    Param("userdefaulthoming.homeposition", REAL, 0.0, WP, NOW, -E12, E12),
    Param("userdefaulthoming.homingapproachvelocity", REAL, 100.0, WP, NOW, 0.0, 10000.0, lo_open=True),
    Param("userdefaulthoming.homingentryvelocity", REAL, 20.0, WP, NOW, 0.0, 2000.0, lo_open=True),
    Param("userdefaulthoming.homingreducedvelocity", REAL, 10.0, WP, NOW, 0.0, 1000.0, lo_open=True),
    # --- position control §4.5.9 (numbers 2032, 2033) ----------------------------------------------------
    Param(f"{PV}.kv", REAL, 10.0, WP, NOW, 0.0, 1.0e7, lo_open=True),
    Param(f"{PV}.kpc", REAL, 100.0, WP, NOW, 0.0, 150.0),
    # --- monitoring §4.5.11 (numbers 6, 7, 2071-2073, 1311-1313, 1351, 1354) ----------------------------
    Param(f"{FE}.enable", INT, 1, WP, RESTART, choices=YES_NO),
    Param(f"{FE}.maxPositionTolerance", REAL, 100.0, WP, NOW, 0.0, E12),
    Param(f"{FE}.minPositionTolerance", REAL, 10.0, WP, NOW, 0.0, E12),
    Param(f"{FE}.minVelocity", REAL, 10.0, WP, NOW, 0.0, E12),
    Param(f"{FE}.warningLimit", REAL, 100.0, WP, NOW, 0.0, 100.0,
          doc="[%] of the admissible following error; 8017 above it (100: the error limit, no warning)"),
    Param("TypeOfAxis.PositionMonitoring.tolerance", REAL, 1.0, WP, NOW, 0.0, E12, doc="positioning window"),
    Param("TypeOfAxis.PositionMonitoring.posWinTolTime", REAL, 1.0, WP, NOW, 0.0, E12,
          doc="time [s] to reach the positioning window after the end of the setpoint interpolation"),
    Param("TypeOfAxis.PositionMonitoring.posWinTolDelayTime", REAL, 0.0, WP, NOW, 0.0, E12,
          doc="minimum dwell time [s] in the positioning window"),
    Param("TypeOfAxis.StandStillSignal.maxVeloStandStill", REAL, 1.0, WP, NOW, 0.0, E12),
    Param("TypeOfAxis.StandStillSignal.delayTimeToActivate", REAL, 0.01, WP, NOW, 0.0, 214748.0),
]
# fmt: on

#: tags that are not the expert list's: the wizard's, the simulated drive's, the DB number
FAMILY_TAGS = frozenset(p.path for p in _PARAMS + H.PARAMS + HOMING_PARAMS + ENCODER_PARAMS
                        if p.path.startswith(("Wizard.", "Drive.")) or p.path == "DBNumber")

#: the manual's spellings with stray blanks, cleaned (s7-technology-parameters.csv numbers 2020, 2021)
_ALIASES = {"TypeOfAxis.NumberOfData Sets.DataSet_1.Gear denFactor": f"{GEAR}.denFactor",
            "TypeOfAxis.NumberOfData Sets.DataSet_1.Gear.numFactor": f"{GEAR}.numFactor"}


def canonical(path: str) -> str:
    return _ALIASES.get(path, path)


def rule_issues(cfg: Mapping[str, Any]) -> list[Issue]:
    issues: list[Issue] = []

    def add(path: str, rule: str, allowed: str) -> None:
        issues.append(Issue(path, "rule:" + rule, cfg[path], allowed))

    if cfg["swlimit.minusposition"] >= cfg["swlimit.plusposition"]:
        add("swlimit.minusposition", "low_above_high",
            f"below swlimit.plusposition = {cfg['swlimit.plusposition']:g} (§4.5.7.3, ErrorID 8085)")
    issues += H.rule_issues(cfg)
    if cfg["Wizard.Virtual"] == 0:
        if cfg["Wizard.Technology"] != 0 and cfg["Wizard.Telegram"] in TELEGRAMS_NO_ENCODER:
            add("Wizard.Telegram", "no_encoder", "a telegram with an encoder (3, 4, 5, 6, 102, 103, 105, 106) for a "
                                                 "positioning or synchronization axis (§4.2.3)")
        if cfg["Drive.MaxSpeed"] > 2.0 * cfg["Drive.ReferenceSpeed"] * (1 + 1e-12):
            add("Drive.MaxSpeed", "above_reference", f"at most 2 x Drive.ReferenceSpeed = {2 * cfg['Drive.ReferenceSpeed']:g}")
        vmax = max_drive_velocity(cfg)
        if not H.hydraulic(cfg) and cfg["TypeOfAxis.MaxVelocity.maximum"] > vmax * (1 + 1e-9):
            add("TypeOfAxis.MaxVelocity.maximum", "unreachable",
                f"at most {vmax:g} (Drive.MaxSpeed {cfg['Drive.MaxSpeed']:g} 1/min over the mechanics)")
    if cfg["Wizard.Technology"] == 0 and cfg["Modulo.state"] == 1:
        add("Modulo.state", "speed_axis", "INACTIVE (0): a speed-controlled axis has no position (§3.2)")
    lo, hi = cfg["Plant.HWLimitMinPosition"], cfg["Plant.HWLimitMaxPosition"]
    if lo is not None and hi is not None and lo >= hi:
        add("Plant.HWLimitMinPosition", "low_above_high", f"below Plant.HWLimitMaxPosition = {hi:g}")
    return issues + homing_rule_issues(cfg) + dataset_rule_issues(cfg)


_MODELLED = _PARAMS + H.PARAMS + HOMING_PARAMS + DATASET_PARAMS + ENCODER_PARAMS + IO_PARAMS + PLANT_PARAMS
#: the §9.4 parameters the model stores without an effect (technology.stored_params), and their numbers
_STORED, STORED_NUMBERS = generated(p.path for p in _MODELLED)

AXIS = AxisSchema("S7-Technology axis", _MODELLED + _STORED,
                  rules=rule_issues, canonical=canonical, build=axis_config, real_type="Real")

__all__ = ["AXIS", "STORED_NUMBERS", "FAMILY_TAGS", "DIRECTIONS", "canonical", "rule_issues"]
