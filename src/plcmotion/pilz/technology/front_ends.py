"""How the applications of a Pilz drive feed the motion core: the front-end tables of Pilz V6.5 as data.

Every command's "Basic settings" and "Control commands" tables (Tab. 2 ... Tab. 37) name, per application,
the parameter that ends up in each motion-core parameter: CiA 402 (A parameters), Drive Based (J/I/D/G/C
parameters; motion block / command / velocity-torque operating mode), PROFIdrive application class 3 with
telegram 111 (program mode / MDI mode) and the motion control panel.  Only what the manual prints is here;
"—" in the manual is absent.  ``cia402_command`` and ``profidrive_mdi_command`` decode the command
selection of those two front-ends.
"""
from __future__ import annotations

from . import command as C

CIA402, DRIVE_BASED, PROFIDRIVE, PANEL = "CiA 402", "Drive Based", "PROFIdrive", "motion control panel"

#: CiA 402 modes of operation A541 -> command (Tab. 2, 3, 6, 9, 20, 24, 27, 30, 33); mode 1 needs the
#: selector bits of ``cia402_command``
CIA402_MODES: dict[int, tuple[int, ...]] = {
    0: (C.DO_NOTHING,), 1: (C.MOVE_ABSOLUTE, C.MOVE_RELATIVE, C.MOVE_ADDITIVE), 3: (C.MOVE_SPEED,),
    4: (C.TORQUE_CONTROL,), 6: (C.HOME,), 7: (C.CYCLIC_POSITION,), 8: (C.CYCLIC_POSITION,), 9: (C.CYCLIC_SPEED,),
    10: (C.TORQUE_CONTROL,),
}
#: the commands no CiA 402 mode selects (Tab. 13, 16, 36: "—")
NOT_IN_CIA402 = frozenset({C.MOVE_VELOCITY, C.STOP, C.HALT})


def cia402_command(a541: int, controlword: int = 0, option_code: int = 0) -> int | None:
    """The command a CiA 402 drive runs: modes of operation A541, controlword A515 (bit 6: relative) and
    positioning option code A621 (bits 0/1) for profile position mode (Tab. 3, 6, 9).  None: not a mode
    the motion core serves, or a selector combination the manual does not list."""
    commands = CIA402_MODES.get(a541)
    if commands is None:
        return None
    if a541 != 1:
        return commands[0]
    if not controlword & (1 << 6):
        return C.MOVE_ABSOLUTE
    bits = option_code & 0b11
    if bits == 0b10:
        return C.MOVE_RELATIVE
    if bits == 0b00:
        return C.MOVE_ADDITIVE
    return None


#: Execute I402 per application (§1.2.1 ff.): CiA 402 A515 bit 4; DB and PROFIdrive I100 (MC_Home via
#: PROFIdrive: M515 bit 11); panel: the start button
EXECUTE = {CIA402: "A515 bit 4", DRIVE_BASED: "I100", PROFIDRIVE: "I100", PANEL: "Start button"}
EXECUTE_HOME_PROFIDRIVE = "M515 bit 11"

#: the velocity override I230 per application (§1.2.5)
OVERRIDE = {CIA402: "A340", DRIVE_BASED: "G467/J56", PROFIDRIVE: "M554", PANEL: "K408"}

#: command -> motion-core parameter -> CiA 402 source (Tab. 4, 7, 10, 21, 25, 28, 31, 34; "PT/CST" and
#: "IP/CSP" alternatives separated by " / ")
CIA402_INPUTS: dict[int, dict[str, str]] = {
    C.MOVE_ABSOLUTE: {"I402": "A515 bit 4", "I403": "A567", "I404": "A574", "I405": "A576", "I406": "A577",
                      "I407": "A590", "I411": "A621 bit 6-7"},
    C.MOVE_RELATIVE: {"I402": "A515 bit 4", "I403": "A567", "I404": "A574", "I405": "A576", "I406": "A577",
                      "I407": "A590"},
    C.MOVE_ADDITIVE: {"I402": "A515 bit 4", "I403": "A567", "I404": "A574", "I405": "A576", "I406": "A577",
                      "I407": "A590"},
    C.HOME: {"I402": "A515 bit 4", "I30": "A586", "I32": "A587[0]", "I33": "A587[1]", "I34": "A569",
             "I39": "A588", "I28": "I28", "I29": "I29", "I36": "I36", "I37": "I37", "I40": "I40", "I41": "I41",
             "I43": "I43", "I44": "I44", "I101": "I101", "I102": "I102", "I103": "I103"},
    C.CYCLIC_SPEED: {"I402": "A515 bit 4", "I426": "A592 + A638", "I119": "I119"},
    C.MOVE_SPEED: {"I402": "A515 bit 4", "I426": "A592 + A638", "I216": "A576", "I217": "A577", "I407": "A590",
                   "I119": "I119"},
    C.TORQUE_CONTROL: {"I402": "A515 bit 4", "I428": "A558 / A558 + A593", "I430": "A561", "I431": "A561"},
    C.CYCLIC_POSITION: {"I402": "A515 bit 4", "I421": "A601 / A567", "I426": "A592 / A592 + A638",
                        "I119": "I119"},
}

#: command -> motion-core parameter -> Drive Based source per operating mode (motion block, command,
#: velocity/torque); None where the manual prints "—" (Tab. 2 ... Tab. 37)
_DB_PROFILE = {"I403": ("J13", "J42", None), "I404": ("J14", "J43 + J49", None), "I405": ("J15", "J44", None),
               "I406": ("J16", "J45", None), "I407": ("J17", "J46", None), "I409": ("J21", None, None),
               "I410": ("J27", "J53", None), "I429": ("J18", None, None)}
DRIVE_BASED_INPUTS: dict[int, dict[str, tuple[str | None, str | None, str | None]]] = {
    C.DO_NOTHING: {"I401": ("J11", "J40", "D01")},
    C.MOVE_ABSOLUTE: {"I401": ("J11", "J40", None), "I400": ("J300", "J41", None), "I402": ("I100", "I100", None),
                      **_DB_PROFILE, "I411": ("C243 = 0 + C241", "C241", None)},
    C.MOVE_RELATIVE: {"I401": ("J11", "J40", None), "I400": ("J300", "J41", None), "I402": ("I100", "I100", None),
                      **_DB_PROFILE},
    C.MOVE_ADDITIVE: {"I401": ("J11", "J40", None), "I400": ("J300", "J41", None), "I402": ("I100", "I100", None),
                      **_DB_PROFILE},
    C.MOVE_VELOCITY: {"I401": ("J11", "J40", "D01"), "I400": ("J300", "J41", None),
                      "I402": ("I100", "I100", "I100"), "I404": ("J14", "J43 + J49", "D12, D13"),
                      "I405": ("J15", "J44", "D14, D15"), "I406": ("J16", "J45", "D16, D17"),
                      "I407": ("J17", "J46", "D18, D19"), "I409": ("J21", None, None),
                      "I424": ("I113", "I113", "I113")},
    C.STOP: {"I401": ("J11", "J40", None), "I400": ("J300", "J41", None), "I402": ("I100", "I100", None),
             "I406": ("J16", "J45", None), "I407": ("J17", "J46", None), "I410": ("J27", "J53", None)},
    C.HOME: {"I401": ("J11", "J40", None), "I400": ("J300", "J41", None), "I402": ("I100", "I100", None),
             "I30": ("I30", "I30", None), "I31": ("I31", "I31", None), "I32": ("I32", "I32", None),
             "I33": ("I33", "I33", None), "I34": ("I34", "I34", None), "I35": ("I35", "I35", None),
             "I39": ("I39", "I39", None), "I43": ("I43", "I43", None), "I44": ("I44", "I44", None)},
    C.MOVE_SPEED: {"I401": ("J11", "J40", "D01"), "I400": ("J300", "J41", None),
                   "I402": ("I100", "I100", "Enable-on"), "I426": ("J14", "J43 + J49", "D12, D13"),
                   "I216": ("J15", "J44", "D14, D15"), "I217": ("J16", "J45", "D16, D17"),
                   "I407": ("J17", "J46", "D18, D19"), "I409": ("J21", None, None),
                   "I119": ("I119", "I119", "I119")},
    C.TORQUE_CONTROL: {"I401": ("J11", "J40", "D01"), "I400": ("J300", "J41", None),
                       "I402": ("I100", "I100", "Enable-on"), "I428": ("G469", "G469", "G469"),
                       "I430": ("G500", "G500", "G500"), "I431": ("G501", "G501", "G501"),
                       "I409": ("J21", "J21", "J21")},
    C.HALT: {"I401": ("J11", "J40", None), "I400": ("J300", "J41", None), "I402": ("I100", "I100", None),
             "I406": ("J16", "J45", None), "I407": ("J17", "J46", None), "I410": ("J27", "J53", None)},
}

#: PROFIdrive telegram 111: command -> motion-core parameter -> (program mode, MDI mode); None: "—"
_PD_PROFILE = {"I403": ("J13", "M530"), "I404": ("J14", "M531"), "I405": ("J15", "M532"),
               "I406": ("J16", "M533"), "I407": ("J17", "I16"), "I409": ("J21", None), "I410": ("J27", None),
               "I429": ("J18", None)}
PROFIDRIVE_INPUTS: dict[int, dict[str, tuple[str | None, str | None]]] = {
    C.MOVE_ABSOLUTE: {"I402": ("I100", "I100"), **_PD_PROFILE, "I411": ("C243 = 0 + C241", "M550 bit 9-10")},
    C.MOVE_RELATIVE: {"I402": ("I100", "I100"), **_PD_PROFILE},
    C.MOVE_ADDITIVE: {"I402": ("I100", None), **{k: (v[0], None) for k, v in _PD_PROFILE.items()}},
    C.MOVE_VELOCITY: {"I402": ("I100", "I100"), "I404": ("J14", "M531"), "I405": ("J15", "M532"),
                      "I406": ("J16", "M533"), "I407": ("J17", "I16"), "I409": ("J21", None),
                      "I424": ("I113", "I113")},
    C.STOP: {"I402": ("I100", None), "I406": ("J16", None), "I407": ("J17", None), "I410": ("J27", None)},
    C.HOME: {"I402": ("M515 bit 11", "M515 bit 11")},
    C.MOVE_SPEED: {"I402": ("I100", None), "I426": ("J14", None), "I216": ("J15", None), "I217": ("J16", None),
                   "I407": ("J17", None), "I409": ("J21", None), "I119": ("I119", None)},
    C.TORQUE_CONTROL: {"I402": ("I100", None), "I428": ("G469", None), "I430": ("G500", None),
                       "I431": ("G501", None), "I409": ("J21", None)},
    C.HALT: {"I402": ("I100", None), "I406": ("J16", None), "I407": ("J17", None), "I410": ("J27", None)},
}
#: the commands PROFIdrive MDI mode can select (Tab. 3, 6, 13, 20); the rest only in program mode
PROFIDRIVE_MDI = frozenset({C.MOVE_ABSOLUTE, C.MOVE_RELATIVE, C.MOVE_VELOCITY, C.HOME})
#: commands of neither PROFIdrive mode (Tab. 24, 33: "—")
NOT_IN_PROFIDRIVE = frozenset({C.CYCLIC_SPEED, C.CYCLIC_POSITION})


def profidrive_mdi_command(m550: int, homing: bool = False) -> int | None:
    """The command MDI mode selects with M550 (Tab. 3, 6, 13, 20): bit 15 MDI, bit 14 velocity, bit 8
    absolute/relative; ``homing``: the start comes from M515 bit 11 (MC_Home).  None: program mode."""
    if not m550 & (1 << 15):
        return None
    if homing:
        return C.HOME
    if m550 & (1 << 14):
        return C.MOVE_VELOCITY
    return C.MOVE_ABSOLUTE if m550 & (1 << 8) else C.MOVE_RELATIVE


#: commands on the motion control panels (Tab. 2 ...): K399 is the CiA 402 panel, K402 the DB/PROFIdrive one
PANEL_K399 = frozenset({C.DO_NOTHING, C.MOVE_ABSOLUTE, C.MOVE_RELATIVE, C.MOVE_ADDITIVE, C.HOME, C.MOVE_SPEED,
                        C.TORQUE_CONTROL})
PANEL_K402 = PANEL_K399 | {C.MOVE_VELOCITY, C.STOP, C.HALT}

__all__ = ["CIA402", "CIA402_INPUTS", "CIA402_MODES", "DRIVE_BASED", "DRIVE_BASED_INPUTS", "EXECUTE",
           "EXECUTE_HOME_PROFIDRIVE", "NOT_IN_CIA402", "NOT_IN_PROFIDRIVE", "OVERRIDE", "PANEL", "PANEL_K399",
           "PANEL_K402", "PROFIDRIVE", "PROFIDRIVE_INPUTS", "PROFIDRIVE_MDI", "cia402_command",
           "profidrive_mdi_command"]
