"""The front-end tables of Pilz V6.5 (CiA 402, Drive Based, PROFIdrive telegram 111, control panel) against the
manual's "Basic settings" and "Control commands" tables."""
from __future__ import annotations

import pytest

from plcmotion.pilz.technology import front_ends as FE

# Tab. 1 numbers
NOTHING, ABS, REL, ADD, VEL, STOP, HOME, CSPEED, MSPEED, TORQUE, CPOS, HALT = range(12)


@pytest.mark.parametrize("a541,controlword,option,command", [
    (0, 0, 0, NOTHING), (1, 0, 0, ABS), (1, 1 << 6, 0b10, REL), (1, 1 << 6, 0b00, ADD), (3, 0, 0, MSPEED),
    (4, 0, 0, TORQUE), (6, 0, 0, HOME), (7, 0, 0, CPOS), (8, 0, 0, CPOS), (9, 0, 0, CSPEED), (10, 0, 0, TORQUE),
    (1, 1 << 6, 0b01, None), (2, 0, 0, None), (5, 0, 0, None)])
def test_pilz_front_ends_cia402_selection(a541, controlword, option, command):
    """Pilz V6.5 Tab. 2, 3, 6, 9, 20, 24, 27, 30, 33: A541 (+ A515 bit 6, A621 bits 0/1) select the command."""
    assert FE.cia402_command(a541, controlword, option) == command


def test_pilz_front_ends_cia402_missing_commands():
    """Pilz V6.5 Tab. 13, 16, 36: MC_MoveVelocity, MC_Stop and MC_Halt have no CiA 402 source."""
    selectable = {c for cmds in FE.CIA402_MODES.values() for c in cmds}
    assert FE.NOT_IN_CIA402 == {VEL, STOP, HALT} and not selectable & FE.NOT_IN_CIA402


def test_pilz_front_ends_cia402_inputs():
    """Pilz V6.5 Tab. 4, 21, 25, 28, 31, 34: CiA 402 sources of the motion-core inputs."""
    assert FE.CIA402_INPUTS[ABS] == {"I402": "A515 bit 4", "I403": "A567", "I404": "A574", "I405": "A576",
                                     "I406": "A577", "I407": "A590", "I411": "A621 bit 6-7"}
    assert "I411" not in FE.CIA402_INPUTS[REL] and "I411" not in FE.CIA402_INPUTS[ADD]
    assert FE.CIA402_INPUTS[HOME]["I30"] == "A586" and FE.CIA402_INPUTS[HOME]["I34"] == "A569"
    assert (FE.CIA402_INPUTS[HOME]["I32"], FE.CIA402_INPUTS[HOME]["I33"]) == ("A587[0]", "A587[1]")
    assert FE.CIA402_INPUTS[HOME]["I39"] == "A588"
    assert FE.CIA402_INPUTS[MSPEED] == {"I402": "A515 bit 4", "I426": "A592 + A638", "I216": "A576",
                                        "I217": "A577", "I407": "A590", "I119": "I119"}
    assert FE.CIA402_INPUTS[TORQUE]["I428"] == "A558 / A558 + A593"
    assert FE.CIA402_INPUTS[TORQUE]["I430"] == FE.CIA402_INPUTS[TORQUE]["I431"] == "A561"
    assert FE.CIA402_INPUTS[CPOS]["I421"] == "A601 / A567"
    assert FE.CIA402_INPUTS[CSPEED]["I426"] == "A592 + A638"


def test_pilz_front_ends_drive_based():
    """Pilz V6.5 Tab. 3-38, Drive Based column (motion block / command / velocity-torque operating mode)."""
    db = FE.DRIVE_BASED_INPUTS
    assert db[ABS]["I403"] == ("J13", "J42", None) and db[ABS]["I404"] == ("J14", "J43 + J49", None)
    assert db[ABS]["I409"] == ("J21", None, None) and db[ABS]["I429"] == ("J18", None, None)
    assert db[ABS]["I411"] == ("C243 = 0 + C241", "C241", None) and "I411" not in db[REL]
    assert db[VEL]["I404"] == ("J14", "J43 + J49", "D12, D13") and db[VEL]["I424"] == ("I113",) * 3
    assert db[MSPEED]["I402"] == ("I100", "I100", "Enable-on") and db[MSPEED]["I216"][2] == "D14, D15"
    assert db[TORQUE]["I428"] == ("G469",) * 3 and db[TORQUE]["I430"] == ("G500",) * 3
    assert db[STOP]["I410"] == ("J27", "J53", None) and db[HALT]["I406"] == ("J16", "J45", None)
    assert db[NOTHING]["I401"] == ("J11", "J40", "D01")
    assert CSPEED not in db and CPOS not in db


@pytest.mark.parametrize("m550,homing,command", [
    ((1 << 15) | (1 << 8), False, ABS), (1 << 15, False, REL), ((1 << 15) | (1 << 14), False, VEL),
    (1 << 15, True, HOME), (0, False, None)])
def test_pilz_front_ends_profidrive_mdi(m550, homing, command):
    """Pilz V6.5 Tab. 3, 6, 13, 20: MDI selection with M550 bits 15, 14, 8 (MC_Home started by M515 bit 11)."""
    assert FE.profidrive_mdi_command(m550, homing) == command


def test_pilz_front_ends_profidrive_inputs():
    """Pilz V6.5 Tab. 4, 10, 14: PROFIdrive program / MDI sources; MDI has no jerk field (I16 applies)."""
    pd = FE.PROFIDRIVE_INPUTS
    assert pd[ABS]["I403"] == ("J13", "M530") and pd[ABS]["I407"] == ("J17", "I16")
    assert pd[ABS]["I411"] == ("C243 = 0 + C241", "M550 bit 9-10")
    assert pd[ADD]["I403"] == ("J13", None)             # MC_MoveAdditive: program mode only
    assert FE.PROFIDRIVE_MDI == {ABS, REL, VEL, HOME}
    assert FE.NOT_IN_PROFIDRIVE == {CSPEED, CPOS}
    assert pd[HOME]["I402"] == ("M515 bit 11", "M515 bit 11")


def test_pilz_front_ends_override_and_execute():
    """Pilz V6.5 §1.2.1 / §1.2.5: Execute and override sources per application."""
    assert FE.OVERRIDE == {FE.CIA402: "A340", FE.DRIVE_BASED: "G467/J56", FE.PROFIDRIVE: "M554",
                           FE.PANEL: "K408"}
    assert FE.EXECUTE[FE.CIA402] == "A515 bit 4" and FE.EXECUTE[FE.DRIVE_BASED] == "I100"


def test_pilz_front_ends_panels():
    """Pilz V6.5 Tab. 13, 16, 36: MC_MoveVelocity, MC_Stop and MC_Halt only on the K402 panel; the cyclic
    commands on none (Tab. 24, 33)."""
    assert FE.PANEL_K402 - FE.PANEL_K399 == {VEL, STOP, HALT}
    assert not {CSPEED, CPOS} & FE.PANEL_K402
