"""DINT values of the ENUM parameters, S7-Technology V4.1 §9.4.12: ValueDint at MC_ReadSysParameter /
MC_WriteParameter versus the number of the S7T Config expert list, transcribed from the manual's tables."""
from __future__ import annotations

import pytest

from plcmotion.s7t.technology import parameters as P
from plcmotion.s7t.technology.enums import ENUMS, enum, value_name

# (ENUM type, value, ValueDint, expert-list number)
VALUES = [
    ("EnumActiveInactive", "INACTIVE", 0, 61), ("EnumActiveInactive", "ACTIVE", 1, 4),
    ("EnumYesNo", "NO", 0, 91), ("EnumYesNo", "YES", 1, 173),
    ("EnumAxisApproachDirection", "EDGE_NEG_SIDE_NEG", 20, 5),
    ("EnumAxisEncoderAssemblyType", "ASSEMBLY_BASE_LINEAR", 86, 3),
    ("EnumAxisExtrapolatedVelocitySwitch", "TRANSFER", 1, 409),
    ("EnumAxisFilterMode", "DEFAULT_MODE", 9, 0), ("EnumAxisFilterMode", "PT1", 11, 2),
    ("EnumAxisFineInterpolatorMode", "CUBIC_MODE", 14, 2),
    ("EnumAxisHomingMode", "MODE_NO_REFERENCE", 88, 0), ("EnumAxisHomingMode", "MODE_CAM_AND_ZM", 22, 1),
    ("EnumAxisPassiveApproachDirection", "ACTUAL_DIRECTION_PASSIVE", 21, 6),
    ("EnumAxisPassiveHomingMode", "DEFAULT_PASSIVE", 25, 4),
    ("EnumAxisTorqueForceReductionGranularity", "BASIC", 1, 16),
    ("EnumAxisTorqueForceReductionGranularity", "STANDARD", 0, 0),
    ("EnumBackLashType", "POSITIVE", 5, 0), ("EnumBalanceFilterMode", "OFF", 89, 0),
    ("EnumBalanceFilterMode", "MODE_2", 91, 2), ("EnumCamInterpolationMode", "B_SPLINE", 28, 25),
    ("EnumCamMode", "NO_CONSTRAINTS", 37, 96), ("EnumCamPositionMode", "BASIC", 34, 16),
    ("EnumCamTrackType", "TYPE_TIME_WITH_MAX_LENGTH", 64, 4),
    ("EnumChangeMode", "NEVER", 92, 0), ("EnumChangeMode", "IN_POSITION", 93, 1),
    ("EnumChangeMode", "IN_STANDSTILL", 94, 3), ("EnumChangeMode", "IMMEDIATELY", 95, 7),
    ("EnumDirection", "SHORTEST_WAY", 39, 121), ("EnumDirectionType", "NEGATIVE", 4, 1),
    ("EnumErrorReporting", "ACTUAL_VALUE_TOLERANCE", 42, 2),
    ("EnumFollowingObjectSynchronizeWithLookAhead", "EXTENDED_LOOK_AHEAD", 113, 359),
    ("EnumFollowingObjectSynchronizingDirection", "SYSTEM_DEFINED", 97, 316),
    ("EnumGearingDirection", "REVERSE", 45, 116), ("EnumGearingPosToleranceCommandValue", "WITH_JERK", 50, 2),
    ("EnumLimitExceededOk", "LIMIT_EXCEEDED", 101, 71), ("EnumLimitExceededOk", "O_K_", 102, 102),
    ("EnumMeasuredEdge", "BOTH_EDGES_FIRST_FALLING", 57, 226), ("EnumMountSwitch", "FLEXIBLE_MOUNTED_SWITCH", 104, 1),
    ("EnumOutputCamType", "TYPE_REVERSE", 63, 3), ("EnumProfile", "TRAPEZOIDAL", 67, 146),
    ("EnumRecognitionMode", "CLAMP_BY_FOLLOWING_ERROR_DEVIATION", 106, 1), ("EnumSensorState", "VALID", 206, 111),
    ("EnumSyncModeCamming", "AT_THE_END_OF_CAM_CYCLE", 68, 14),
    ("EnumSyncModeCamming", "IMMEDIATELY_AND_SLAVE_POSITION", 108, 315),
    ("EnumSyncModeGearing", "IMMEDIATELY_AND_BE_SYNCHRONOUS_AT_MASTER_POSITION", 74, 370),
    ("EnumSyncOffPositionReference", "BEGIN_TO_STOP_WHEN_POSITION_REACHED", 74, 18),
    ("EnumSyncPositionReference", "SYNCHRONIZE_WHEN_POSITION_REACHED", 78, 144),
    ("EnumSyncProfileReference", "RELATE_SYNC_PROFILE_TO_TIME", 80, 114),
    ("EnumToActivationModeSetConfigData", "ACTIVATE_CHANGED_CONFIG_DATA", 81, 291),
    ("EnumToActivationModeSetConfigData", "COLLECT_CHANGED_CONFIG_DATA", 82, 292),
]


@pytest.mark.parametrize("enum_name, name, value, expert", VALUES, ids=[f"{v[0]}.{v[1]}" for v in VALUES])
def test_s7t_enum_value_dint(enum_name, name, value, expert):
    """S7-Technology V4.1 §9.4.12: the ValueDint code and the expert-list number of an ENUM value."""
    v = enum(enum_name).by_name(name)
    assert (v.value, v.expert_value) == (value, expert)
    assert ENUMS[enum_name][name] == value
    assert value_name(enum_name, value) == name


def test_s7t_enum_types_and_sizes():
    """S7-Technology V4.1 §9.4.12.1-§9.4.12.50: 50 ENUM types; value counts of a few; codes unique per type."""
    assert len(ENUMS) == 50
    sizes = {"EnumYesNo": 2, "EnumChangeMode": 4, "EnumSyncModeGearing": 9, "EnumSyncModeCamming": 8,
             "EnumAxisPassiveApproachDirection": 7, "EnumProfile": 6, "EnumGearingDirection": 7}
    assert {k: len(ENUMS[k].values) for k in sizes} == sizes
    for e in ENUMS.values():
        assert len(e.codes()) == len(e.values), e.name


def test_s7t_enum_values_not_available():
    """S7-Technology V4.1 §9.4.12.38, §9.4.12.43: PARABOLIC, SINUSOIDAL and NEXT_WITH_REFERENCE are listed as not
    available."""
    assert not enum("EnumProfile").by_name("PARABOLIC").available
    assert not enum("EnumSyncModeGearing").by_name("NEXT_WITH_REFERENCE").available
    assert enum("EnumProfile").by_name("SMOOTH").available


def test_s7t_every_enum_parameter_links_a_known_enum():
    """S7-Technology V4.1 §9.4: each "DINT Enum" parameter names an ENUM of §9.4.12 and accepts exactly its codes."""
    enum_params = [p for p in P.all_parameters() if p.enum]
    assert len(enum_params) == 118           # the rows typed "DINT Enum..." in §9.4
    for p in enum_params:
        assert p.enum in ENUMS
        if p.writable:
            assert all(p.check(c) is None for c in ENUMS[p.enum].codes())
            assert p.check(max(ENUMS[p.enum].codes()) + 1000) == 0x8043


def test_s7t_enum_lookup_errors():
    """Unknown ENUM types and values are named in the error."""
    with pytest.raises(KeyError, match="EnumColour"):
        enum("EnumColour")
    with pytest.raises(KeyError, match="MAYBE"):
        enum("EnumYesNo").by_name("MAYBE")
    assert value_name("EnumYesNo", 7) is None
