"""FB-level ErrorIDs of S7-Technology V4.1 (§6.2-§6.7): the codes each FB's ErrorID table lists, transcribed from
the manual, the named common codes, the FB numbers, and describe()."""
from __future__ import annotations

import pytest
from hypothesis import given, strategies as st

from plcmotion.s7t import fb_errors as E
from plcmotion.s7t import fb_tables

# the codes every motion FB table repeats (§6, e.g. MC_Power's table)
BASE = {0x0000, 0x8001, 0x8005, 0x804C, 0x8050, 0x8052, 0x8053, 0x8083, 0x8084}

TABLES = {
    "MC_Power": BASE | {0x8043, 0x8044, 0x8045, 0x804E, 0x804F, 0x808B},
    "MC_Reset": BASE | {0x8045, 0x8047, 0x8048},
    "MC_Home": BASE | {0x8022, 0x8040, 0x8043, 0x8044, 0x8045, 0x804D, 0x808B},
    "MC_Stop": BASE | {0x0021, 0x0028, 0x8043, 0x8044, 0x808B},
    "MC_Halt": BASE | {0x8040, 0x8043, 0x8044, 0x8045, 0x8056, 0x808B},
    "MC_ChangeDataset": BASE | {0x8043, 0x8044, 0x8045, 0x804D},
    "MC_MoveAbsolute": BASE | {0x8040, 0x8043, 0x8044, 0x8045, 0x8055, 0x8056, 0x808B},
    "MC_MoveRelative": BASE | {0x8040, 0x8043, 0x8044, 0x8045, 0x8055, 0x8056, 0x808B},
    "MC_MoveAdditive": BASE | {0x8040, 0x8043, 0x8044, 0x8045, 0x8056, 0x808B},
    "MC_MoveVelocity": BASE | {0x8040, 0x8043, 0x8044, 0x8045, 0x8055, 0x8056, 0x808B},
    "MC_MoveToEndPos": BASE | {0x0029, 0x8040, 0x8043, 0x8044, 0x8045, 0x804D, 0x8056, 0x808B},
    "MC_SetTorqueLimit": BASE | {0x8043, 0x8044, 0x8045, 0x804D, 0x8056, 0x808B},
    "MC_SetCharacteristic": BASE | {0x8043, 0x8044, 0x804A, 0x804D},
    "MC_GearIn": BASE | {0x8022, 0x8040, 0x8043, 0x8044, 0x8045, 0x804A, 0x8056, 0x807A, 0x807B, 0x808B},
    "MC_GearOut": BASE | {0x8040, 0x8043, 0x8044, 0x8045},
    "MC_Phasing": BASE | {0x8040, 0x8043, 0x8044, 0x8045, 0x8056, 0x8079, 0x808B},
    "MC_CamClear": BASE | {0x8044, 0x8045, 0x8051},
    "MC_CamSectorAdd": BASE | {0x8006, 0x800B, 0x8043, 0x8044, 0x8045, 0x8051, 0x8062, 0x8088, 0x8089, 0x808A,
                               0x808C},
    "MC_CamInterpolate": BASE | {0x0027, 0x8006, 0x8043, 0x8044, 0x8045, 0x8051, 0x8062, 0x8066, 0x808B},
    "MC_GetCamPoint": BASE | {0x8043, 0x8044, 0x8045, 0x8061, 0x808B},
    "MC_MeasuringInput": BASE | {0x8034, 0x8043, 0x8044, 0x8045, 0x804A, 0x808B},
    "MC_ExternalEncoder": BASE | {0x8022, 0x8040, 0x8043, 0x8044, 0x8045, 0x808B},
    "MC_ReadSysParameter": BASE | {0x8043, 0x8044, 0x8045, 0x8080, 0x8086},
    "MC_WriteParameter": BASE | {0x0020, 0x8043, 0x8044, 0x8080, 0x8081, 0x8086, 0x808B},
    "MC_ActivateTO": BASE | {0x8043, 0x8045, 0x8054, 0x8057},
    "MC_ActivateDPSlave": {0x0000, 0x8001, 0x8005, 0x8043, 0x8050, 0x8052, 0x8053, 0x8057, 0x8058, 0x8090},
    "MC_ReadCamTrackData": BASE | {0x800B, 0x8043, 0x8044, 0x8086, 0x8088, 0x8089, 0x808C},
}


@pytest.mark.parametrize("fb", sorted(TABLES))
def test_s7t_fb_error_table(fb):
    """S7-Technology V4.1 §6.2-§6.7: the ErrorIDs of the FB's table, no more, no fewer."""
    assert E.fb_codes(fb) == frozenset(TABLES[fb])


def test_s7t_drive_parameter_tables_include_the_drive_ranges():
    """S7-Technology V4.1 §6.7.10-§6.7.11: the drive's parameter errors 8120..8164 (reserved) and 8165..81FF
    (manufacturer-specific) are rows of MC_ReadDriveParameter / MC_WriteDriveParameter; 8101, 8102 only when
    writing."""
    read, write = E.fb_codes("MC_ReadDriveParameter"), E.fb_codes("MC_WriteDriveParameter")
    assert {0x8120, 0x8140, 0x8164, 0x8165, 0x81FF} <= read & write
    assert {0x8101, 0x8102, 0x8105, 0x8106, 0x810B, 0x8114, 0x8117, 0x8118, 0x808E, 0x80A1} <= write - read
    assert {0x80A0, 0x8115} <= read - write


def test_s7t_fb_numbers_and_names():
    """S7-Technology V4.1 §6.1: FB 401 ... FB 463, 45 FBs, 408, 452, 458 and 459 unused; FB 457 is
    MC_ActivateDPSlave, FB 460 MC_ActivateTO and FB 461 MC_CamTrack (the lists of §6.1 mix these up)."""
    names = fb_tables.FB_NAMES
    assert len(names) == 45 and min(names) == 401 and max(names) == 463
    assert not {408, 452, 458, 459} & set(names)
    expected = {401: "MC_Power", 402: "MC_Reset", 403: "MC_Home", 404: "MC_Stop", 405: "MC_Halt",
                406: "MC_ReadSysParameter", 407: "MC_WriteParameter", 409: "MC_ChangeDataset",
                410: "MC_MoveAbsolute", 414: "MC_MoveVelocity", 415: "MC_MoveToEndPos", 420: "MC_GearIn",
                421: "MC_CamIn", 430: "MC_CamSwitch", 437: "MC_SetTorqueLimit", 439: "MC_SetCharacteristic",
                444: "MC_PhasingSuperImposed", 450: "MC_ReadPeriphery", 456: "MC_WriteDriveParameter",
                457: "MC_ActivateDPSlave", 460: "MC_ActivateTO", 461: "MC_CamTrack", 463: "MC_WriteCamTrackData"}
    assert {k: names[k] for k in expected} == expected
    assert fb_tables.table(404).name == "MC_Stop" and fb_tables.table("MC_Stop").number == 404
    with pytest.raises(KeyError):
        E.fb_codes("MC_Jog")


def test_s7t_named_common_codes():
    """S7-Technology V4.1 §6 (common rows of every FB table)."""
    assert (E.DISABLED_OR_WRONG_MODE, E.ILLEGAL_PARAMETER, E.NOT_SUPPORTED, E.NOT_ALLOWED) == (
        0x8040, 0x8043, 0x8044, 0x8045)
    assert (E.LATCHING_NOT_ALLOWED, E.FIXED_STOP_ACTIVE, E.INVALID_REAL, E.RATE_TOO_HIGH) == (
        0x8055, 0x8056, 0x808B, 0x804C)
    assert (E.INVALID_PARAMETER_NUMBER, E.PARAMETER_READ_ONLY, E.ONE_INSTANCE_PER_AXIS) == (0x8080, 0x8081, 0x804E)
    assert E.COMMON[0x8055].message == "Latching motion not allowed in current state"
    assert E.COMMON[0x804C].message == "Command output rate too high"


def test_s7t_parameter_checks_use_the_fb_codes():
    """S7-Technology V4.1 §6.7.5: the parameter checks of the technology layer give MC_WriteParameter's codes."""
    from plcmotion.s7t.technology import parameters as P
    assert (P.ILLEGAL_PARAMETER, P.INVALID_NUMBER, P.READ_ONLY, P.INVALID_REAL, P.RESTART_REQUIRED) == (
        E.ILLEGAL_PARAMETER, E.INVALID_PARAMETER_NUMBER, E.PARAMETER_READ_ONLY, E.INVALID_REAL, E.RESTART_REQUIRED)
    assert {P.ILLEGAL_PARAMETER, P.INVALID_NUMBER, P.READ_ONLY, P.INVALID_REAL} <= E.fb_codes("MC_WriteParameter")


def test_s7t_describe():
    """S7-Technology V4.1 §6: a code's meaning, the FB's own cause, FB-specific names, unknown codes."""
    assert E.describe(0x8043).startswith("16#8043 Illegal parameter value")
    assert "StopMode" in E.describe(0x8043, "MC_Power")
    assert E.describe(0x8055, "MC_Power").endswith("(not an ErrorID of MC_Power)")
    assert E.describe(0x80C0, "MC_WriteRecord").startswith("16#80C0 Previous write command is still busy")
    assert E.describe(0x80C0, "MC_ReadRecord").startswith("16#80C0 No read data")
    assert E.describe(0x8062, "MC_CamInterpolate").startswith("16#8062 Cam interpolation failed")
    assert E.describe(0x8170, "MC_ReadDriveParameter").startswith("16#8170 Manufacturer-specific")
    assert "unknown ErrorID" in E.describe(0x1234)
    assert "unknown ErrorID" in E.describe(0x8099)


@given(code=st.one_of(st.integers(-10, 0x2_0000), st.none(), st.text(max_size=4), st.floats()),
       fb=st.one_of(st.none(), st.sampled_from(sorted(fb_tables.FB_BY_NAME)), st.text(max_size=5)))
def test_s7t_describe_never_raises(code, fb):
    """describe() answers every input with a text."""
    assert isinstance(E.describe(code, fb), str)


def test_s7t_every_listed_code_has_a_meaning():
    """S7-Technology V4.1 §6: every code of every FB table has a common meaning; causes name listed codes only."""
    for fb in fb_tables.FBS:
        for code in fb.all_codes():
            assert E.common(code) is not None, (fb.name, hex(code))
        assert set(fb.causes) <= fb.codes and set(fb.messages) <= fb.codes
