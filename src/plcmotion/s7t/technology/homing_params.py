"""Homing, limit switch and standstill monitoring tags of the S7-Technology axes and what they make of the
kernel configuration (S7-Technology V4.1 §4.5.7.2, §4.5.10, §4.5.11.2, §6.2.2, §9.4).

Tags carry the expert-list names (encoder 1); ENUM tags hold their ValueDint (§9.4.12).  Three things have
no expert-list name in the manual and are family tags: the input addresses of the hardware limit switches
(``Wizard.HWLimitSwitchMinusInput`` / ``...PlusInput``, NC contacts, §4.5.7.2) and the process-image input at
which the simulation shows the drive's measuring input of an external zero mark
(``Drive.ExternalZeroMarkInput``).  The reference cam is addressed by byte and bit as in S7T Config.

:func:`refine` puts these tags into the neutral :class:`~plcmotion.kernel.axis_config.AxisConfig` the core
builder made (homing with the kernel's ``ReferenceApproach``, hardware limit switches, standstill monitoring);
:func:`plant_wiring` wires the reference cam and the limit switches of the simulated machine.
"""
from __future__ import annotations

from dataclasses import replace
from typing import Any, Mapping

from ...kernel.axis_config import AxisConfig, HardwareLimits, ReferenceApproach
from ...kernel.schema import ADDR, E12, INT, REAL, WP, R, Issue, Param

ENC = "TypeOfAxis.NumberOfEncoders.Encoder_1.IncHomingEncoder"

# §9.4.12 ValueDint codes (the ENUM tables are r11-s7t-data's ``technology.enums``; the codes are the manual's)
YES = 1
#: EnumAxisHomingMode
MODE_CAM_AND_ZM, MODE_ZM, MODE_CAM, MODE_NO_REFERENCE = 22, 23, 24, 88
#: EnumAxisPassiveHomingMode
CAM_AND_ZM_PASSIVE, ZM_PASSIVE, CAM_PASSIVE, DEFAULT_PASSIVE = 22, 23, 24, 25
#: EnumAxisApproachDirection / EnumAxisPassiveApproachDirection (ACTUAL_DIRECTION_PASSIVE passive only)
APPROACH_NEGATIVE, APPROACH_POSITIVE = 15, 16
EDGE_POS_SIDE_NEG, EDGE_POS_SIDE_POS, EDGE_NEG_SIDE_POS, EDGE_NEG_SIDE_NEG = 17, 18, 19, 20
ACTUAL_DIRECTION_PASSIVE = 21
#: EnumMountSwitch
END_MOUNTED_SWITCH, FLEXIBLE_MOUNTED_SWITCH = 103, 104
#: TypeOfAxis.DecodingConfig.transferSuperimposed: TRANSFER_STANDSTILL (0) is printed in §6.8; the numbers of
#: TRANSFER_MERGE and TRANSFER_RESET are plcmotion's (1, 2), in the order of §6.2.2
TRANSFER_STANDSTILL, TRANSFER_MERGE, TRANSFER_RESET = 0, 1, 2
_TRANSFER = {TRANSFER_STANDSTILL: "standstill", TRANSFER_MERGE: "merge", TRANSFER_RESET: "reset"}

#: the kernel's homing methods: 0 encoder zero mark only, 1 cam then zero mark, 2 external zero mark only
_ACTIVE_METHOD = {MODE_ZM: 0, MODE_CAM_AND_ZM: 1, MODE_CAM: 2, MODE_NO_REFERENCE: 0}
_PASSIVE_METHOD = {ZM_PASSIVE: 0, CAM_AND_ZM_PASSIVE: 1, CAM_PASSIVE: 2}
#: edge of an external zero mark: (rising edge, direction of motion) - the side named in the value is the
#: side the axis comes from (SIDE_NEG: moving positive), §4.12.3
EDGES = {EDGE_POS_SIDE_NEG: (True, 1), EDGE_POS_SIDE_POS: (True, -1), EDGE_NEG_SIDE_NEG: (False, 1),
         EDGE_NEG_SIDE_POS: (False, -1)}
_ZM_DIRECTIONS = {APPROACH_NEGATIVE: -1, APPROACH_POSITIVE: 1, ACTUAL_DIRECTION_PASSIVE: 0}

# fmt: off
HOMING_PARAMS: list[Param] = [
    # --- active homing §4.5.10.2 (numbers 3061, 3064, 3070, 3071, 3063, 1120, 1122) ----------------------
    Param(f"{ENC}.homingMode", INT, MODE_ZM, WP, (10,), choices=tuple(_ACTIVE_METHOD),
          doc="EnumAxisHomingMode: 22 cam and zero mark, 23 zero mark only, 24 external zero mark only, 88 none"),
    Param(f"{ENC}.approachDirection", INT, APPROACH_POSITIVE, WP, (10,), choices=(15, 16, 17, 18, 19, 20),
          doc="EnumAxisApproachDirection: direction at the zero mark (15/16) or edge of the external mark (17-20)"),
    Param(f"{ENC}.proceedShiftPos", REAL, 0.0, WP, (10,), -E12, E12, doc="reference point offset"),
    Param(f"{ENC}.enableZeroMarkDistance", INT, 0, WP, (10,), choices=(0, 1)),
    Param(f"{ENC}.zeroMarkDistance", REAL, 1000.0, WP, (10,), 0.0, E12,
          doc="most travel from the cam (zero mark only: from the start) to the zero mark"),
    Param("TypeOfAxis.Homing.enableBeroDistance", INT, 0, WP, (10,), choices=(0, 1)),
    Param("TypeOfAxis.Homing.beroDistance", REAL, 1000.0, WP, (10,), 0.0, E12,
          doc="most travel from the start to the reference cam / external zero mark"),
    Param(f"{ENC}.logAdressBero", INT, None, R, (), 0, 9999, optional=True,
          doc="byte of the reference cam input of active homing (none: no cam)"),
    Param(f"{ENC}.bitNumberBero", INT, 0, R, (), 0, 7),
    # --- passive homing §4.5.10.3 (numbers 3066, 3068) ----------------------------------------------------
    Param(f"{ENC}.passiveHomingMode", INT, DEFAULT_PASSIVE, WP, (), choices=(22, 23, 24, 25),
          doc="EnumAxisPassiveHomingMode (takes effect with a restart)"),
    Param(f"{ENC}.passiveApproachDirection", INT, ACTUAL_DIRECTION_PASSIVE, WP, (10,),
          choices=(15, 16, 17, 18, 19, 20, 21), doc="EnumAxisPassiveApproachDirection"),
    Param(f"{ENC}.passiveLogAdressBero", INT, None, R, (), 0, 9999, optional=True,
          doc="byte of the reference cam input of passive homing (none: the active one's)"),
    Param(f"{ENC}.passiveBitNumberBero", INT, 0, R, (), 0, 7),
    Param("Drive.ExternalZeroMarkInput", ADDR, "", R, (), choices=("I",),
          doc="simulation: input showing the drive's measuring input of the external zero mark"),
    # --- MC_Home Mode 7 §6.2.2 ----------------------------------------------------------------------------
    Param("TypeOfAxis.DecodingConfig.transferSuperimposed", INT, TRANSFER_STANDSTILL, WP, (),
          choices=tuple(_TRANSFER), doc="0 TRANSFER_STANDSTILL, 1 TRANSFER_MERGE, 2 TRANSFER_RESET"),
    # --- hardware limit switches §4.5.7.2 (numbers 1281, 1284) ---------------------------------------------
    Param("TypeOfAxis.HWEndPos.enable", INT, 0, WP, (10,), choices=(0, 1)),
    Param("TypeOfAxis.HWEndPos.mode", INT, END_MOUNTED_SWITCH, WP, (10,),
          choices=(END_MOUNTED_SWITCH, FLEXIBLE_MOUNTED_SWITCH)),
    Param("Wizard.HWLimitSwitchMinusInput", ADDR, "", R, (), choices=("I",), doc="NC contact of the minus switch"),
    Param("Wizard.HWLimitSwitchPlusInput", ADDR, "", R, (), choices=("I",), doc="NC contact of the plus switch"),
    Param("Wizard.SWLimitMonitoringAtStart", INT, 0, R, (), choices=(0, 1),
          doc="§4.5.7.3 check box: warning 0026 at the start of a command beyond a software limit switch"),
    # --- standstill monitoring §4.5.11.2 (numbers 1341, 1342) ---------------------------------------------
    Param("TypeOfAxis.StandStillMonitoring.delayTimeToActivate", REAL, 0.1, WP, (10,), 0.0, E12),
    Param("TypeOfAxis.StandStillMonitoring.stillStandTolerance", REAL, 1.0, WP, (10,), 0.0, E12, lo_open=True),
]
# fmt: on


def _address(byte: int | None, bit: int) -> str:
    return "" if byte is None else f"I{byte}.{bit}"


def cam_inputs(p: Mapping[str, Any]) -> tuple[str, str]:
    """(active, passive) input of the reference cam ("" none); passive homing without an address of its own
    uses the active one's."""
    active = _address(p[f"{ENC}.logAdressBero"], p[f"{ENC}.bitNumberBero"])
    passive = _address(p[f"{ENC}.passiveLogAdressBero"], p[f"{ENC}.passiveBitNumberBero"]) or active
    return active, passive


def passive_mode(p: Mapping[str, Any], zero_marks: bool = True) -> int:
    """The passive homing mode in force: DEFAULT_PASSIVE is the zero mark of the encoder if it has one, the
    external zero mark otherwise (§4.5.10.3)."""
    mode = p[f"{ENC}.passiveHomingMode"]
    if mode == DEFAULT_PASSIVE:
        return ZM_PASSIVE if zero_marks else CAM_PASSIVE
    return mode


def homing_rule_issues(cfg: Mapping[str, Any]) -> list[Issue]:
    """The approach direction must fit the homing mode (§4.12.3 table: X valid, F invalid, N not supported);
    a mode with a reference cam or an external zero mark needs its input."""
    issues: list[Issue] = []
    active, direction = cfg[f"{ENC}.homingMode"], cfg[f"{ENC}.approachDirection"]
    if active == MODE_CAM and direction not in EDGES:
        issues.append(Issue(f"{ENC}.approachDirection", "rule:edge_required", direction,
                            "an EDGE_* value (17-20) for external zero mark homing (homingMode 24)"))
    if active in (MODE_CAM_AND_ZM, MODE_ZM) and direction in EDGES:
        issues.append(Issue(f"{ENC}.approachDirection", "rule:zero_mark_direction", direction,
                            "APPROACH_NEGATIVE (15) or APPROACH_POSITIVE (16) for homing to a zero mark"))
    # the inputs a mode needs (a real axis; a virtual one has no homing modes, §6.2.2)
    cam, passive_cam = cam_inputs(cfg)
    external = cfg["Drive.ExternalZeroMarkInput"]
    real = not cfg.get("Wizard.Virtual")
    if real and active == MODE_CAM_AND_ZM and not cam:
        issues.append(Issue(f"{ENC}.logAdressBero", "rule:cam_required", None,
                            "the byte address of the reference cam for homingMode 22 (cam and zero mark)"))
    if real and active == MODE_CAM and not external:
        issues.append(Issue("Drive.ExternalZeroMarkInput", "rule:input_required", "",
                            "the input of the external zero mark for homingMode 24"))
    passive = passive_mode(cfg)
    if real and passive == CAM_AND_ZM_PASSIVE and not passive_cam:
        issues.append(Issue(f"{ENC}.passiveLogAdressBero", "rule:cam_required", None,
                            "the byte address of the reference cam for passiveHomingMode 22"))
    if real and passive == CAM_PASSIVE and not external:
        issues.append(Issue("Drive.ExternalZeroMarkInput", "rule:input_required", "",
                            "the input of the external zero mark for passiveHomingMode 24"))
    pdir = cfg[f"{ENC}.passiveApproachDirection"]
    if passive == CAM_PASSIVE and pdir not in EDGES:
        issues.append(Issue(f"{ENC}.passiveApproachDirection", "rule:edge_required", pdir,
                            "an EDGE_*_PASSIVE value (17-20) for passive external zero mark homing"))
    if passive in (CAM_AND_ZM_PASSIVE, ZM_PASSIVE) and pdir in EDGES:
        issues.append(Issue(f"{ENC}.passiveApproachDirection", "rule:zero_mark_direction", pdir,
                            "15, 16 or 21 (ACTUAL_DIRECTION_PASSIVE) for passive homing to a zero mark"))
    return issues


def plant_wiring(p: Mapping[str, Any]) -> dict[str, Any]:
    """The keyword arguments of ``kernel.plant_schema.plant_spec``: the simulated reference cam (or external
    zero mark) on its inputs and the NC hardware limit switches (actuated while the input is FALSE)."""
    active, passive = cam_inputs(p)
    marks = [(a, True) for a in (active, passive, p["Drive.ExternalZeroMarkInput"]) if a]
    return dict(hw_min=(p["Wizard.HWLimitSwitchMinusInput"], False), hw_max=(p["Wizard.HWLimitSwitchPlusInput"], False),
                homing_inputs=marks, ready_input="")


def refine(config: AxisConfig, p: Mapping[str, Any]) -> AxisConfig:
    """``config`` with the homing, hardware limit switch and standstill monitoring tags of ``p`` in it."""
    h = config.homing
    active_in, passive_in = cam_inputs(p)
    external = p["Drive.ExternalZeroMarkInput"]
    mode = p[f"{ENC}.homingMode"]
    direction = p[f"{ENC}.approachDirection"]
    start = 1 if h.approach_positive else -1
    rising, _ = EDGES.get(direction, (True, start))
    zm_dir = _ZM_DIRECTIONS.get(direction, start)
    pmode = passive_mode(p)
    pdir = p[f"{ENC}.passiveApproachDirection"]
    p_rising, p_edge_dir = EDGES.get(pdir, (True, 0))
    settings = ReferenceApproach(
        entry_velocity=p["userdefaulthoming.homingentryvelocity"],
        # §4.5.10.2: the zero mark is taken in the approach direction: the start direction -> after the cam
        zero_mark_after_cam=zm_dir == start,
        cam_distance=p["TypeOfAxis.Homing.beroDistance"] if p["TypeOfAxis.Homing.enableBeroDistance"] == YES else None,
        zero_mark_distance=p[f"{ENC}.zeroMarkDistance"] if p[f"{ENC}.enableZeroMarkDistance"] == YES else None,
        external_rising=rising,
        passive_direction=p_edge_dir if pmode == CAM_PASSIVE else _ZM_DIRECTIONS.get(pdir, 0),
        passive_rising=p_rising,
        transfer_superimposed=_TRANSFER[p["TypeOfAxis.DecodingConfig.transferSuperimposed"]])
    active = replace(h.active, mode=_ACTIVE_METHOD[mode], input=external if mode == MODE_CAM else active_in,
                     active_high=True, home_offset=p[f"{ENC}.proceedShiftPos"])
    passive = replace(h.passive, mode=_PASSIVE_METHOD[pmode], input=external if pmode == CAM_PASSIVE else passive_in,
                      active_high=True)
    homing = replace(h, referencing_velocity=p["userdefaulthoming.homingreducedvelocity"], active=active,
                     passive=passive, approach=settings,
                     required=p["TypeOfAxis.Homing.referencingNecessary"] == YES)
    minus, plus = p["Wizard.HWLimitSwitchMinusInput"], p["Wizard.HWLimitSwitchPlusInput"]
    hw = HardwareLimits(enabled=p["TypeOfAxis.HWEndPos.enable"] == YES and bool(minus or plus), min_input=minus,
                        max_input=plus, min_active_high=False, max_active_high=False)
    positioning = replace(config.positioning,
                          standstill_window=p["TypeOfAxis.StandStillMonitoring.stillStandTolerance"],
                          standstill_delay=p["TypeOfAxis.StandStillMonitoring.delayTimeToActivate"])
    names = dict(config.tag_names, **{"homing.referencing_velocity": "userdefaulthoming.homingreducedvelocity"})
    return replace(config, homing=homing, hardware_limits=hw, positioning=positioning, tag_names=names)


__all__ = ["HOMING_PARAMS", "homing_rule_issues", "plant_wiring", "refine", "cam_inputs", "passive_mode", "ENC",
           "EDGES"]
