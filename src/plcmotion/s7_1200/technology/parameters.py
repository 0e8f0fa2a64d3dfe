"""Configuration schema of the positioning axis technology object.

Every configurable tag of the axis is declared here once, by the path the technology data block uses
(S7-1200 Motion Control V6 §12.9), with its data type, start value, access right, the moments at which a
change takes effect (effective codes of the §12.9 legends) and its admissible range.  The project loader,
``Controller.add_positioning_axis``, direct tag writes and MC_WriteParam all validate against this table.

Ranges come from the configuration dialogs (§5.4) and, where V6 prints none, from the V7 manual's tables.
``Plant.*`` entries are not tags of the technology object: they describe the simulated machine (drive
dynamics, pulse output hardware) and are only set by configuration.
"""
from __future__ import annotations

from typing import Any, Mapping

from ...kernel.plant_schema import PLANT_PARAMS
from ...kernel.schema import ADDR, BOOL, E12, INT, P, R, REAL, RW, WP, AxisSchema, Issue, Param, _check
from .builder import axis_config

#: tags whose WP access the manual grants only to PTO axes (read-only on PROFIdrive/analog axes)
PTO_ONLY_WP = frozenset({"Simulation.Mode"})


_S = "Sensor[1]"

# fmt: off
_PARAMS: list[Param] = [
    # --- Actor (drive) §12.9.5 -------------------------------------------------------------------
    Param("Actor.Type", INT, 2, R, (), choices=(0, 1, 2), doc="0 analog output, 1 PROFIdrive, 2 PTO"),
    Param("Actor.InverseDirection", BOOL, False, WP, (2,)),
    Param("Actor.DirectionMode", INT, 0, WP, (2,), choices=(0, 1, 2),
          doc="permitted direction (PTO): 0 both, 1 positive, 2 negative"),
    Param("Actor.DataAdaption", INT, 0, R, (), choices=(0, 1)),
    Param("Actor.DriveParameter.ReferenceSpeed", REAL, 3000.0, R, (), 0.0, E12, lo_open=True,
          doc="motor speed [1/min] that corresponds to 100 % of the speed setpoint"),
    Param("Actor.DriveParameter.MaxSpeed", REAL, 3000.0, R, (), 0.0, E12, lo_open=True,
          doc="maximum motor speed [1/min]; <= 2 x ReferenceSpeed (PROFIdrive), <= 1.17 x (analog)"),
    Param("Actor.DriveParameter.PulsesPerDriveRevolution", INT, 1000, WP, (2,), 1, 2147483647),
    Param("Actor.Interface.EnableDriveOutput", ADDR, "", R, (), choices=("Q",),
          doc="digital output 'Drive enabled' set by MC_Power ('' = none)"),
    Param("Actor.Interface.DriveReadyInput", ADDR, "", R, (), choices=("I",),
          doc="digital input 'Drive ready' ('' = none: the drive counts as ready)"),
    Param("Actor.Interface.Telegram", INT, 3, R, (), choices=(1, 2, 3, 4),
          doc="PROFIdrive standard telegram of the drive (3: 32-bit speed setpoint with encoder 1)"),
    Param("Actor.Interface.PTO", INT, 0, R, (), choices=(0, 1, 2, 3, 4),
          doc="pulse generator PTO1..PTO4 of a PTO axis (0 = a pulse output of its own)"),
    Param("Actor.Interface.PTO_SignalType", INT, 2, R, (), choices=(2, 3, 4, 5),
          doc="2 pulse A / direction B, 3 count up A / down B, 4 A/B phase-shifted, 5 A/B quadruple"),
    Param("Actor.Interface.PTO_OutputBEnable", BOOL, True, R, (),
          doc="direction output used (signal type 2); without it only one direction is possible"),
    Param("Actor.PTOSliceTime", INT, 2, WP, (2,), choices=tuple(range(0, 256)),
          doc="V7: PTO segment time [ms], 2..20; commands take effect at segment boundaries"),
    # --- Sensor[1] §12.9.6 --------------------------------------------------------------------------
    Param(f"{_S}.Type", INT, 0, R, (), choices=(0, 1, 2),
          doc="0 incremental, 1 absolute, 2 cyclic absolute (the S7-1500 encoder type: the range repeats)"),
    Param(f"{_S}.InverseDirection", BOOL, False, R),
    Param(f"{_S}.System", INT, 1, R, (), choices=(0, 1), doc="0 linear, 1 rotary (§12.9.6.1)"),
    Param(f"{_S}.MountingMode", INT, 0, R, (), choices=(0, 2), doc="0 motor shaft, 2 external"),
    Param(f"{_S}.DataAdaption", INT, 0, R, (), choices=(0, 1)),
    Param(f"{_S}.Interface.Type", INT, 4, R, (), choices=(0, 1, 2, 4),
          doc="0 PROFIdrive encoder, 1 technology module, 2 encoder on drive, 4 HSC"),
    Param(f"{_S}.Interface.Number", INT, 1, R, (), 1, 2),
    Param(f"{_S}.Parameter.Resolution", REAL, 0.001, R, (), 0.0, E12, lo_open=True,
          doc="linear encoder: distance between two increments"),
    Param(f"{_S}.Parameter.StepsPerRevolution", INT, 2048, R, (), 1, 8388608),
    Param(f"{_S}.Parameter.FineResolutionXist1", INT, 11, R, (), 0, 31),
    Param(f"{_S}.Parameter.FineResolutionXist2", INT, 9, R, (), 0, 31),
    Param(f"{_S}.Parameter.DeterminableRevolutions", INT, 1, R, (), 0, 8388608),
    Param(f"{_S}.Parameter.DistancePerRevolution", REAL, 100.0, R, (), 0.0, E12, lo_open=True),
    Param(f"{_S}.Parameter.BehaviorGx_XIST1", INT, 1, R, (), choices=tuple(range(0, 256)),
          doc="V7: 0 evaluate only the bits of Gx_XIST1 the resolution occupies, 1 all 32 bits"),
    Param(f"{_S}.ActiveHoming.Mode", INT, 2, WP, (2,), choices=(0, 1, 2)),
    Param(f"{_S}.ActiveHoming.SideInput", BOOL, False, RW, (1, 8, 10)),
    Param(f"{_S}.ActiveHoming.HomePositionOffset", REAL, 0.0, RW, (1, 8, 10), -E12, E12),
    Param(f"{_S}.ActiveHoming.SwitchLevel", BOOL, True, RW, (1, 8, 10)),
    Param(f"{_S}.ActiveHoming.DigitalInputAddress", ADDR, "", R, (), choices=("I",)),
    Param(f"{_S}.PassiveHoming.Mode", INT, 2, WP, (2,), choices=(0, 1, 2)),
    Param(f"{_S}.PassiveHoming.SideInput", BOOL, False, RW, (1, 7, 10)),
    Param(f"{_S}.PassiveHoming.SwitchLevel", BOOL, True, RW, (1, 7, 10)),
    Param(f"{_S}.PassiveHoming.DigitalInputAddress", ADDR, "", R, (), choices=("I",)),
    # --- Units, mechanics, modulo §12.9.7-§12.9.9 ---------------------------------------------------
    Param("Units.LengthUnit", INT, 1013, WP, (2,), choices=(-1, 1005, 1010, 1013, 1018, 1019),
          doc="-1 pulse, 1005 degree, 1010 m, 1013 mm, 1018 ft, 1019 in"),
    Param("Mechanics.LeadScrew", REAL, 10.0, WP, (2,), 0.0, E12, lo_open=True,
          doc="load distance per motor revolution"),
    Param("Modulo.Enable", BOOL, False, R),
    Param("Modulo.Length", REAL, 360.0, R, (), 0.001, E12),
    Param("Modulo.StartValue", REAL, 0.0, R, (), -E12, E12),
    # --- Dynamics §12.9.10, §12.9.11 ----------------------------------------------------------------
    Param("DynamicLimits.MaxVelocity", REAL, 250.0, WP, (2,), 0.0, E12, lo_open=True),
    Param("DynamicLimits.MinVelocity", REAL, 10.0, WP, (2,), 0.0, E12,
          doc="start/stop velocity (PTO only; fixed at 0 for PROFIdrive/analog)"),
    Param("DynamicDefaults.Acceleration", REAL, 48.0, RW, (1, 5, 6, 10), 0.0, E12, lo_open=True),
    Param("DynamicDefaults.Deceleration", REAL, 48.0, RW, (1, 5, 6, 10), 0.0, E12, lo_open=True),
    Param("DynamicDefaults.EmergencyDeceleration", REAL, 120.0, RW, (1, 5, 6, 10), 0.0, E12, lo_open=True),
    Param("DynamicDefaults.Jerk", REAL, 192.0, RW, (1, 5, 10), 0.0, E12,
          doc="0 (PTO: below 0.004 pulses/s^3) disables the jerk limit"),
    # --- Position limits §12.9.12, §12.9.13 ---------------------------------------------------------
    Param("PositionLimits_SW.Active", BOOL, False, RW, (1, 5, 6, 10)),
    Param("PositionLimits_SW.MinPosition", REAL, -10000.0, RW, (1, 5, 6, 10), -E12, E12),
    Param("PositionLimits_SW.MaxPosition", REAL, 10000.0, RW, (1, 5, 6, 10), -E12, E12),
    Param("PositionLimits_HW.Active", BOOL, False, RW, (1, 5, 6, 10)),
    Param("PositionLimits_HW.MinSwitchLevel", BOOL, False, WP, (2,),
          doc="FALSE low level (NC contact) = approached, TRUE high level (NO contact) = approached"),
    Param("PositionLimits_HW.MaxSwitchLevel", BOOL, False, WP, (2,)),
    Param("PositionLimits_HW.MinSwitchAddress", ADDR, "", R, (), choices=("I",)),
    Param("PositionLimits_HW.MaxSwitchAddress", ADDR, "", R, (), choices=("I",)),
    # --- Homing §12.9.14 ----------------------------------------------------------------------------
    Param("Homing.AutoReversal", BOOL, False, RW, (1, 8, 10)),
    Param("Homing.ApproachDirection", BOOL, True, RW, (1, 8, 10)),
    Param("Homing.ApproachVelocity", REAL, 200.0, RW, (1, 8, 10), 0.0, E12),
    Param("Homing.ReferencingVelocity", REAL, 40.0, RW, (1, 8, 10), 0.0, E12),
    # --- Closed loop and monitoring §12.9.15-§12.9.18 -----------------------------------------------
    Param("PositionControl.Kv", REAL, 10.0, WP, (10,), 0.0, 2147480.0, lo_open=True),
    Param("PositionControl.Kpc", REAL, 100.0, WP, (10,), 0.0, 150.0),
    Param("FollowingError.EnableMonitoring", BOOL, True, R),
    Param("FollowingError.MinValue", REAL, 10.0, WP, (10,), 0.0, E12),
    Param("FollowingError.MaxValue", REAL, 100.0, WP, (10,), 0.0, E12),
    Param("FollowingError.MinVelocity", REAL, 10.0, WP, (10,), 0.0, E12),
    Param("PositioningMonitoring.ToleranceTime", REAL, 1.0, WP, (10,), 0.0, E12),
    Param("PositioningMonitoring.MinDwellTime", REAL, 0.1, WP, (10,), 0.0, E12),
    Param("PositioningMonitoring.Window", REAL, 1.0, WP, (10,), 0.001, E12),
    Param("StandstillSignal.VelocityThreshold", REAL, 5.0, WP, (10,), 0.0, E12),
    Param("StandstillSignal.MinDwellTime", REAL, 0.01, WP, (10,), 0.0, E12),
    # §12.9.19: WP (effective at enable) for a PTO axis - where Mode 1 then gives 16#8647 -, while
    # PROFIdrive/analog axes change it only through the load memory (WRIT_DBL) and a restart, which
    # plcmotion does not have: read-only for them (PTO_ONLY_WP, docs/decisions.md)
    Param("Simulation.Mode", INT, 0, WP, (2, 9), choices=(0, 1)),
]
_PARAMS += PLANT_PARAMS
# fmt: on

SCHEMA: dict[str, Param] = {p.path: p for p in _PARAMS}

#: S7 data type of the integer tags (§12.9 tables); BOOL tags are Bool, REAL tags Real
_INT_TYPES = {
    "Actor.DirectionMode": "Int", "Units.LengthUnit": "Int",
    "Sensor[1].Interface.Number": "UDInt", "Sensor[1].Parameter.StepsPerRevolution": "UDInt",
    "Sensor[1].Parameter.FineResolutionXist1": "UDInt", "Sensor[1].Parameter.FineResolutionXist2": "UDInt",
    "Sensor[1].Parameter.DeterminableRevolutions": "UDInt", "Actor.Interface.PTO": "DWord",
    "Actor.PTOSliceTime": "Int",
}


def data_type(path: str) -> str:
    """S7 data type of a configuration tag: Bool, Int, DInt, UDInt, Real, DWord or VRef (addresses)."""
    param = SCHEMA[path]
    if param.kind == BOOL:
        return "Bool"
    if param.kind == REAL:
        return "Real"
    if param.kind == ADDR:
        return "VRef"
    return _INT_TYPES.get(path, "DInt")

# Alternative spellings found in the manuals (catalog §11 item 8, §7.15) mapped to the canonical path.
_PREFIX_ALIASES = (
    ("Sensor.Sensor[1].", "Sensor[1]."),
    ("PositionMonitoring.", "PositioningMonitoring."),
    ("PositionLimitsSW.", "PositionLimits_SW."),
    ("PositionLimitsHW.", "PositionLimits_HW."),
    ("StandStillSignal.", "StandstillSignal."),
)
_WORD_ALIASES = {"SidelInput": "SideInput"}


def canonical(path: str) -> str:
    """Canonical tag path for any of the spellings the manuals use."""
    for old, new in _PREFIX_ALIASES:
        if path.startswith(old):
            path = new + path[len(old):]
            break
    if "SidelInput" in path:
        path = path.replace("SidelInput", _WORD_ALIASES["SidelInput"])
    return path


def _suggest(path: str) -> str:
    import difflib

    near = difflib.get_close_matches(path, SCHEMA.keys(), n=3, cutoff=0.6)
    return "did you mean " + " or ".join(near) + "?" if near else "not a tag of the positioning axis"


def defaults() -> dict[str, Any]:
    return {p.path: p.start for p in _PARAMS}


def check_values(values: Mapping[str, Any]) -> tuple[dict[str, Any], list[Issue]]:
    """Normalise and check single values; returns (normalised values, issues)."""
    return _check(SCHEMA, canonical, _suggest, values)


# Conversion to pulses for the PTO limits of §2.1.1 (limits are given in pulses/s, pulses/s^2, pulses/s^3).
PTO_MIN_FREQUENCY = 1.0
PTO_ACCEL_LIMITS = (5.0e-3, 9.5e9)
PTO_JERK_LIMITS = (4.0e-3, 1.0e10)
PTO_JERK_ENABLE = 4.0e-3          # §5.4.4.4: jerk below this value (pulses/s^3) disables the jerk limit
SERVO_JERK_ENABLE = 1.0e-9        # §5.4.4.4: position-controlled axes: jerk > 1e-9 enables the jerk limit
ANALOG_OVERDRIVE = 1.17           # §5.4.3.2: +-117 % on an analog output
PROFIDRIVE_OVERDRIVE = 2.0        # §5.4.3.2: +-200 % on the bus


def pulse_length(cfg: Mapping[str, Any]) -> float:
    """Load distance of one pulse of a PTO axis [user unit]."""
    return cfg["Mechanics.LeadScrew"] / cfg["Actor.DriveParameter.PulsesPerDriveRevolution"]


def rule_issues(cfg: Mapping[str, Any]) -> list[Issue]:
    """Checks that involve more than one tag (valid single values assumed)."""
    issues: list[Issue] = []
    pto = cfg["Actor.Type"] == 2
    vmax = cfg["DynamicLimits.MaxVelocity"]
    vmin = cfg["DynamicLimits.MinVelocity"]

    def add(path: str, rule: str, allowed: str) -> None:
        issues.append(Issue(path, "rule:" + rule, cfg[path], allowed))

    if pto:
        pulse = pulse_length(cfg)
        # A/B quadruple: every edge is a step, the outputs run at a quarter of the step rate (§2.1.3)
        f_lim = cfg["Plant.PTOLimitFrequency"] * (4.0 if cfg["Actor.Interface.PTO_SignalType"] == 5 else 1.0)
        for path in ("DynamicLimits.MaxVelocity", "DynamicLimits.MinVelocity"):
            f = cfg[path] / pulse
            if f > f_lim * (1 + 1e-12):
                add(path, "above_hw_limit", f"at most {f_lim:g} pulses/s = {f_lim * pulse:g} user units/s "
                                            f"with this pulse output")
            elif f < PTO_MIN_FREQUENCY * (1 - 1e-12):
                add(path, "below_hw_limit", f"at least {PTO_MIN_FREQUENCY:g} pulse/s = {pulse:g} user units/s")
        lo, hi = PTO_ACCEL_LIMITS
        for path in ("DynamicDefaults.Acceleration", "DynamicDefaults.Deceleration",
                     "DynamicDefaults.EmergencyDeceleration"):
            a = cfg[path] / pulse
            if a > hi:
                add(path, "above_hw_limit", f"at most {hi:g} pulses/s^2 = {hi * pulse:g} user units/s^2")
            elif a < lo:
                add(path, "below_hw_limit", f"at least {lo:g} pulses/s^2 = {lo * pulse:g} user units/s^2")
        j = cfg["DynamicDefaults.Jerk"] / pulse
        if j > PTO_JERK_LIMITS[1]:
            add("DynamicDefaults.Jerk", "above_max_jerk",
                f"at most {PTO_JERK_LIMITS[1]:g} pulses/s^3 = {PTO_JERK_LIMITS[1] * pulse:g} user units/s^3")
        if cfg["Modulo.Enable"]:
            add("Modulo.Enable", "pto_modulo", "modulo is only available with PROFIdrive/analog drives (§5.4.4.2)")
        if cfg["Simulation.Mode"] == 1:
            add("Simulation.Mode", "pto_simulation", "simulation is not supported for PTO axes (16#8647)")
        for path in ("Sensor[1].ActiveHoming.Mode", "Sensor[1].PassiveHoming.Mode"):
            if cfg[path] != 2:
                add(path, "pto_homing_mode", "2 (homing via digital input) for PTO axes (16#8617/16#8618)")
        if (cfg["Actor.Interface.PTO_SignalType"] == 2 and not cfg["Actor.Interface.PTO_OutputBEnable"]
                and cfg["Actor.DirectionMode"] == 0):
            add("Actor.DirectionMode", "both_without_direction_output",
                "1 (positive) or 2 (negative) when the direction output is not used (16#861A/16#002D)")
        slice_ms = cfg["Actor.PTOSliceTime"]
        if slice_ms > 20:
            add("Actor.PTOSliceTime", "above_20ms", "2..20 ms (16#864A/16#006D)")
        elif slice_ms < 2:
            add("Actor.PTOSliceTime", "below_2ms", "2..20 ms (16#864A/16#006E)")
    else:
        if cfg["DynamicDefaults.Jerk"] > E12:
            add("DynamicDefaults.Jerk", "above_max_jerk", f"at most {E12:g}")
        if (cfg["Actor.Type"] == 1 and cfg["Sensor[1].Interface.Type"] == 2
                and cfg["Actor.Interface.Telegram"] not in (3, 4)):
            add("Actor.Interface.Telegram", "no_encoder_in_telegram",
                "3 or 4 for an encoder on the drive (Sensor[1].Interface.Type = 2)")
        if cfg["Actor.Type"] == 0 and cfg["Sensor[1].Interface.Type"] == 2:
            add("Sensor[1].Interface.Type", "encoder_on_analog_drive", "0, 1 or 4: an analog drive has no encoder telegram")
        ref = cfg["Actor.DriveParameter.ReferenceSpeed"]
        nmax = cfg["Actor.DriveParameter.MaxSpeed"]
        factor = PROFIDRIVE_OVERDRIVE if cfg["Actor.Type"] == 1 else ANALOG_OVERDRIVE
        if nmax > factor * ref * (1 + 1e-12):
            add("Actor.DriveParameter.MaxSpeed", "above_reference",
                f"at most {factor:g} x ReferenceSpeed = {factor * ref:g} 1/min")
        # §12.8 16#8645: the configured maximum velocity must be reachable with MaxSpeed
        if vmax > max_load_velocity(cfg) * (1 + 1e-9):
            add("DynamicLimits.MaxVelocity", "unreachable",
                f"at most {max_load_velocity(cfg):g} user units/s with MaxSpeed "
                f"{nmax:g} 1/min and {cfg['Mechanics.LeadScrew']:g} user units per motor revolution")
    if vmin > vmax:
        add("DynamicLimits.MinVelocity", "min_above_max", f"at most DynamicLimits.MaxVelocity = {vmax:g}")
    if cfg["Sensor[1].Parameter.BehaviorGx_XIST1"] not in (0, 1):
        add("Sensor[1].Parameter.BehaviorGx_XIST1", "invalid", "0 or 1 (16#864B/16#0001)")
    # hardware limit switches need their inputs (§5.4.4.3)
    if cfg["PositionLimits_HW.Active"]:
        for path in ("PositionLimits_HW.MinSwitchAddress", "PositionLimits_HW.MaxSwitchAddress"):
            if not cfg[path]:
                add(path, "missing", "an input address like 'I0.1' when PositionLimits_HW.Active is true")
    if cfg["Homing.AutoReversal"] and not (cfg["PositionLimits_HW.MinSwitchAddress"]
                                           or cfg["PositionLimits_HW.MaxSwitchAddress"]):
        add("Homing.AutoReversal", "no_hw_limits", "false unless hardware limit switch inputs are configured")
    # the simulated plant drives configured inputs only
    lo_sw, hi_sw = cfg["Plant.HWLimitMinPosition"], cfg["Plant.HWLimitMaxPosition"]
    if lo_sw is not None and hi_sw is not None and lo_sw >= hi_sw:
        add("Plant.HWLimitMinPosition", "low_above_high", f"below Plant.HWLimitMaxPosition = {hi_sw:g}")
    for plant, inputs in (("Plant.HWLimitMinPosition", ("PositionLimits_HW.MinSwitchAddress",)),
                          ("Plant.HWLimitMaxPosition", ("PositionLimits_HW.MaxSwitchAddress",)),
                          ("Plant.HomingSwitchPosition", ("Sensor[1].ActiveHoming.DigitalInputAddress",
                                                          "Sensor[1].PassiveHoming.DigitalInputAddress"))):
        if cfg[plant] is not None and not any(cfg[i] for i in inputs):
            add(plant, "no_input", "a switch needs its input: set " + " or ".join(inputs))
    if (not cfg["Modulo.Enable"]
            and cfg["PositionLimits_SW.MinPosition"] > cfg["PositionLimits_SW.MaxPosition"]):
        add("PositionLimits_SW.MinPosition", "low_above_high",
            f"at most PositionLimits_SW.MaxPosition = {cfg['PositionLimits_SW.MaxPosition']:g}")
    return issues


def max_load_velocity(cfg: Mapping[str, Any]) -> float:
    """Load velocity [user unit/s] at the drive's maximum speed (PROFIdrive/analog)."""
    return cfg["Actor.DriveParameter.MaxSpeed"] / 60.0 * cfg["Mechanics.LeadScrew"]


def validate(values: Mapping[str, Any], base: Mapping[str, Any] | None = None) -> tuple[dict[str, Any], list[Issue]]:
    """Merge ``values`` over ``base`` (default: start values), check all, return (config, issues)."""
    cfg = dict(defaults() if base is None else base)
    norm, issues = check_values(values)
    cfg.update(norm)
    if not any(i.path in ("Actor.Type",) for i in issues):
        if cfg["Actor.Type"] != 2 and "DynamicLimits.MinVelocity" not in norm:
            cfg["DynamicLimits.MinVelocity"] = 0.0       # §5.4.4.4: fixed at zero for PROFIdrive/analog
        bad = {i.path for i in issues}
        if not bad & {"Mechanics.LeadScrew", "Actor.DriveParameter.PulsesPerDriveRevolution",
                      "DynamicLimits.MaxVelocity", "DynamicLimits.MinVelocity", "Actor.DriveParameter.MaxSpeed",
                      "Actor.DriveParameter.ReferenceSpeed"}:
            issues.extend(i for i in rule_issues(cfg) if i.path not in bad)
    if cfg["Actor.Type"] != 2 and cfg["DynamicLimits.MinVelocity"] != 0.0:
        issues.append(Issue("DynamicLimits.MinVelocity", "rule:servo_min_velocity", cfg["DynamicLimits.MinVelocity"],
                            "fixed at 0.0 for PROFIdrive/analog drives (§5.4.4.4)"))
    return cfg, issues


#: §12.9 legends: when a written tag takes effect on a PTO axis (PROFIdrive/analog: every code at the next
#: servo cycle): 1, 2 at enable (1 also at disable), 5 at the next command, 6 when a jog stops, 7 at the
#: start of passive and 8 of active homing
PTO_MOMENTS = {"enable": {1, 2}, "command": {5}, "jog_stop": {6}, "passive_homing": {7}, "active_homing": {8},
               "disable": {1}}


class _S71200Schema(AxisSchema):
    """The S7-1200 positioning axis (validation with its PTO rules, Real data types)."""

    def validate(self, values, base=None):
        return validate(values, base)

    def data_type(self, path: str) -> str:
        return data_type(path)

    def check_values(self, values):
        return check_values(values)


S7_1200 = _S71200Schema("positioning axis", _PARAMS, rules=rule_issues, canonical=canonical, int_types=_INT_TYPES,
                         real_type="Real", build=axis_config, pulse_moments=PTO_MOMENTS,
                         pulse_only_write_param=PTO_ONLY_WP)
