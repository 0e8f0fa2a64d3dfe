"""The technology parameter list of S7-Technology V4.1 §9.4 and MC_WriteParameter's checks (§6.7.5, §6.9.3).

Expected values are transcribed from the manual's parameter list; the catalog's machine-extracted index
(tests/s7t/data/s7-technology-parameters.csv, 318 rows) checks completeness row by row.
"""
from __future__ import annotations

import csv
import math
import pathlib

import pytest
from hypothesis import given, strategies as st

from plcmotion.s7t.technology import parameters as P
from plcmotion.s7t.technology.to_kinds import AxisType, TOKind

CSV = pathlib.Path(__file__).parent / "data" / "s7-technology-parameters.csv"
V, POS, Y = AxisType.SPEED, AxisType.POSITIONING, AxisType.SYNCHRONIZATION
VPY, PY = frozenset({V, POS, Y}), frozenset({POS, Y})
A, EE, OC, CT, CAM, MI = ("Axis", "ExternalEncoder", "OutputCam", "CamTrack", "Cam", "MeasuringInput")

# (TO, number, index, expert name, data type, min, max, access, effective, axis types) as the manual prints them
SAMPLES = [
    (A, 1, None, "positioningstate.commandposition", "REAL", "-1E+12", "1E+12", "R", None, PY),
    (A, 2, None, "swlimit.minusposition", "REAL", "-1E+12", "1E+12", "RW", "Immediately", PY),
    (A, 4, None, "swlimit.state", "EnumActiveInactive", None, None, "RW", "Immediately", PY),
    (A, 6, (1, 16), "TypeOfAxis.NumberOfDataSets.DataSet_x.DynamicFollowing.enable", "EnumYesNo", None, None, "RW",
     "Restart", PY),
    (A, 8, None, "TypeOfAxis.MaxVelocity.maximum", "REAL", "0.0", "1E+12", "RW", "Restart", VPY),
    (A, 10, None, "motionstatedata.actualvelocity", "REAL", "-1E12", "+1E12", "R", None, VPY),
    (A, 1100, None, "LeadScrew.pitchVal", "REAL", "0.0", "+1E12", "RW", "Restart", PY),
    (A, 1123, None, "TypeOfAxis.Homing.referencingNecessary", "EnumYesNo", None, None, "RW", "Immediately", PY),
    (A, 1130, None, "TypeOfAxis.Extrapolation.ExtrapolationPositionFilter.enable", "EnumYesNo", None, None, "RW",
     "Restart", frozenset({Y})),
    (A, 1201, None, "Modulo.state", "EnumActiveInactive", None, None, "RW", "Restart", PY),
    (A, 1202, None, "Modulo.length", "REAL", "0.0", "1E+12", "RW", "Restart", PY),
    (A, 1241, None, "TypeOfAxis.EmergencyRampGenerator.maxDeceleration", "REAL", "-1E+12", "1E+12", "RW",
     "Immediately", PY),
    (A, 1263, None, "TypeOfAxis.Friction.delayTimeStandStill", "REAL", "0.0", "2^31 * Servotime * 9", "RW",
     "Immediately", VPY),
    (A, 1313, None, "TypeOfAxis.PositionMonitoring.tolerance", "REAL", "-1E+12", "1E+12", "RW", "Immediately", PY),
    (A, 1351, None, "TypeOfAxis.StandStillSignal.delayTimeToActivate", "REAL", "0.0", "214748", "RW", "Immediately",
     VPY),
    (A, 1352, None, "TypeOfAxis.StandStillSignal.filterDegree", "DINT", "0", "15", "RW", "Immediately", VPY),
    (A, 2000, None, "TypeOfAxis.NumberOfDataSets.numberOfDataSets", "DINT", "0", "16", "R", None, VPY),
    (A, 2002, None, "TypeOfAxis.NumberOfDataSets.changeMode", "EnumChangeMode", None, None, "RW", "Restart", VPY),
    (A, 2011, (1, 16), "TypeOfAxis.NumberOfDataSets.DataSet_x.ClampingMonitoring.positionTolerance", "REAL", "0.0",
     "1E+12", "RW", "Immediately", PY),
    (A, 2020, (1, 16), "TypeOfAxis.NumberOfDataSets.DataSet_x.Gear.denFactor", "DINT", "0", "2147483647", "RW",
     "Restart", VPY),
    (A, 2033, (1, 16), "TypeOfAxis.NumberOfDataSets.DataSet_x.ControllerStruct.PV_Controller.kv", "REAL", "0.0",
     "< 1E+7", "RW", "Immediately", PY),
    (A, 2035, (1, 16), "TypeOfAxis.NumberOfDataSets.DataSet_x.ControllerStruct.PV_Controller.balanceFilterMode",
     "EnumBalanceFilterMode", None, None, "RW", "Immediately", PY),
    (A, 2061, (1, 16), "TypeOfAxis.NumberOfDataSets.DataSet_x.DynamicData.positionTimeConstant", "REAL", "0.0",
     "1E+12", "RW", "Immediately", PY),
    (A, 2072, (1, 16), "TypeOfAxis.NumberOfDataSets.DataSet_x.DynamicFollowing.minVelocity", "REAL", "-1E+12",
     "1E+12", "RW", "Immediately", PY),
    (A, 3015, (1, 8), "TypeOfAxis.NumberOfEncoders.Encoder_x.PathPerRevolution.length", "REAL", "> 0.0", "1E+12", "RW",
     "Restart", PY),
    (A, 3031, (1, 8), "TypeOfAxis.NumberOfEncoders.Encoder_x.AbsHomingEncoder.absShift", "REAL", "0.0", "1E+12", "RW",
     "Immediately", PY),
    (A, 3064, (1, 8), "TypeOfAxis.NumberOfEncoders.Encoder_x.IncHomingEncoder.homingMode", "EnumAxisHomingMode", None,
     None, "RW", "Restart", VPY),
    (A, 4001, None, "activationmodechangedconfigdata", "EnumToActivationModeSetConfigData", None, None, "RW",
     "Immediately", VPY),
    (A, 4010, (1, 8), "absoluteencoder_x.totaloffsetvalue", "2xDWORD", None, None, "RW", "Immediately", PY),
    (A, 4050, (1, 8), "sensordata_x.state", "EnumSensorState", None, None, "R", None, VPY),
    (A, 4141, None, "override.acceleration", "REAL", "1.0", "1000.0", "RW", "Immediately", VPY),
    (A, 4142, None, "override.velocity", "REAL", "0.0", "200.0", "RW", "Immediately", VPY),
    (A, 4248, None, "userdefaultdynamics.profile", "EnumProfile", None, None, "RW", "Immediately", VPY),
    (A, 4249, None, "userdefaultdynamics.stoptime", "REAL", "0.0", "1E+12", "RW", "Immediately", VPY),
    (A, 4266, (1, 2), "userdefault.cammingsettings.synchronizingmode", "EnumSyncModeCamming", None, None, "RW",
     "Immediately", frozenset({Y})),
    (A, 4269, (1, 2), "userdefault.cammingsettings.syncpositionslave", "REAL", "-1E+12", "1E+12", "RW", "Immediately",
     frozenset({Y})),
    (A, 4337, None, "SyncingMotion.synchronizingAdaption", "EnumYesNo", None, None, "RW", "Immediately",
     frozenset({Y})),
    (A, 4338, None, "currentsyncposition.master", "REAL", "-3.402823E+38", "3.402823E+38", "R", None, frozenset({Y})),
    (A, 4500, None, "drivedata.stw", "DWORD", None, None, "RW", None, VPY),
    (A, 4502, None, "TypeOfAxis.SetPointDriverInfo.DriveData.torqueReductionGranularity",
     "EnumAxisTorqueForceReductionGranularity", None, None, "RW", "Restart", VPY),
    (A, 5009, None, "userdefaultqfaxis.maxderivative.qoutput", "REAL", "0.0", "1E+12", "RW", "Immediately", VPY),
    (A, 5065, (1, 8), "TypeOfAxis.DriveControllConfig.ReleaseDisableMode", "WORD", "1", "127", "RW", "Immediately",
     PY),
    (EE, 1400, None, "TypeOfAxis.SpeedLimitation.Enable", "EnumAxisFilterMode", None, None, "RW", "Restart",
     frozenset()),
    (EE, 4010, None, "absoluteencoder.totaloffsetvalue", "2xDWORD", None, None, "RW", "Immediately", frozenset()),
    (EE, 4341, None, "userdefault.syncposition", "REAL", "-1E+12", "1E+12", "RW", "Immediately", frozenset()),
    (EE, 4411, None, "sensormonitoring.hwlimitswitchplus", "EnumLimitExceededOk", None, None, "R", None,
     frozenset()),
    (OC, 1371, None, "OcaType._type", "EnumOutputCamType", None, None, "RW", "Restart", frozenset()),
    (CT, 5052, None, "enablevalidcam", "DWORD", "0", "FFFF FFFF", "RW", "Immediately", frozenset()),
    (CT, 5064, None, "Userdefault.singleCamsettings.cam.cam[1..32].Validity", "EnumYesNo", None, None, "RW",
     "Immediately", frozenset()),
    (CAM, 4203, None, "leadingrange.start", "REAL", "-1E+12", "1E+12", "R", "Immediately", frozenset()),
    (CAM, 4211, None, "userdefault.campositionmode", "EnumCamPositionMode", None, None, "RW", "Immediately",
     frozenset()),
    (MI, 4001, None, "activationmodechanged.configdata", "EnumToActivationModeSetConfigData", None, None, "RW",
     "Immediately", frozenset()),
]


@pytest.mark.parametrize("to, no, index, expert, dtype, lo, hi, access, effective, types", SAMPLES,
                         ids=[f"{s[0]}-{s[1]}" for s in SAMPLES])
def test_s7t_parameter_as_the_manual_lists_it(to, no, index, expert, dtype, lo, hi, access, effective, types):
    """S7-Technology V4.1 §9.4: number, index, expert name, type, range, access, activation, axis types."""
    p = P.parameter(to, no)
    assert (p.number, p.index, p.expert_name, p.data_type) == (no, index, expert, dtype)
    assert (p.min_text, p.max_text, p.access, p.effective, p.axis_types) == (lo, hi, access, effective, types)
    assert P.by_name(to, expert) is p


def _csv_rows() -> list[dict[str, str]]:
    with CSV.open(encoding="utf-8", newline="") as f:
        return list(csv.DictReader(f))


def test_s7t_parameter_list_is_complete():
    """S7-Technology V4.1 §9.4: 318 entries (242 axis, 54 external encoder, 4 output cam, 11 cam track, 6 cam,
    1 measuring input); no number twice per TO."""
    rows = _csv_rows()
    assert len(rows) == 318 == len(P.all_parameters())
    counts = {k: len(P.all_parameters(k)) for k in (A, EE, OC, CT, CAM, MI)}
    assert counts == {A: 242, EE: 54, OC: 4, CT: 11, CAM: 6, MI: 1}
    numbers = [(p.to, p.number) for p in P.all_parameters()]
    assert len(numbers) == len(set(numbers))


def test_s7t_parameters_agree_with_the_catalog_index_row_by_row():
    """S7-Technology V4.1 §9.4: every row of the catalog's index has a parameter of the same TO, number, index,
    access and activation, and the same ENUM or data type (names printed with stray blanks compare without them)."""
    for row in _csv_rows():
        p = P.parameter(row["to"], int(row["no"]))
        index = None if row["index"] == "-" else tuple(int(x) for x in row["index"].split("-"))
        assert p.index == index, row
        assert p.access == {"Read": "R", "Read, Write": "RW"}[row["access"]], row
        assert p.effective == (None if row["active"] == "-" else row["active"]), row
        printed = row["data_type"].replace(" ", "")
        printed = printed.removeprefix("DINT") if printed.startswith("DINTEnum") else printed
        assert p.data_type.replace("Extrapolated", "Extrapolation") == printed.replace("Extrapolated",
                                                                                      "Extrapolation"), row
        assert P.by_name(row["to"], row["expert_name"]) is p, row


def test_s7t_parameter_names_in_either_form():
    """S7-Technology V4.1 §9.4: a parameter is found by its expert name or its DB-Param ("Normal") name,
    also in the forms the print splits with blanks."""
    assert P.by_name(A, "Setpoints.Override.Velocity").number == 4142
    assert P.by_name(A, "override.velocity").number == 4142
    assert P.by_name(A, "TypeOfAxis.NumberOfData Sets.changeMode").number == 2002
    assert P.by_name(A, "activationmodechanged configdata").number == 4001
    assert P.by_name(EE, "absoluteencoder.totaloffset value").number == 4010
    with pytest.raises(LookupError, match="1371, 1372"):
        P.by_name(CT, "Configuration.Cam type")           # two cam-track parameters share this DB-Param name
    with pytest.raises(LookupError):
        P.by_name(A, "no.such.parameter")


def test_s7t_unknown_numbers_and_types():
    """S7-Technology V4.1 §6.7.5: a number the TO does not have gives 8080; it is not an exception at the FB."""
    with pytest.raises(KeyError):
        P.parameter(A, 9999)
    with pytest.raises(KeyError):
        P.parameter("Conveyor", 1)
    assert P.write_check(A, 9999, 1.0) == 0x8080
    assert P.write_check(MI, 1100, 1.0) == 0x8080      # the measuring input has only parameter 4001
    assert P.write_check(A, 4142, 100.0) is None


CHECKS = [
    # (TO, number, value, index, ErrorID) -- §6.7.5 and §6.9.3
    (A, 4142, 0.0, None, None), (A, 4142, 200.0, None, None), (A, 4142, 200.000_1, None, 0x8043),
    (A, 4142, -0.1, None, 0x8043), (A, 4141, 1.0, None, None), (A, 4141, 0.99, None, 0x8043),
    (A, 4141, 1000.0, None, None), (A, 4141, 1000.5, None, 0x8043),
    (A, 4142, math.nan, None, 0x808B), (A, 4142, math.inf, None, 0x808B), (A, 2, -math.inf, None, 0x808B),
    (A, 2, 1e12, None, 0x8043), (A, 2, -1e12, None, 0x8043), (A, 2, 999_999_999_999.0, None, None),
    (A, 3015, 0.0, 1, 0x8043), (A, 3015, 1e-9, 1, None),            # "> 0.0"
    (A, 2033, 9_999_999.0, 1, None), (A, 2033, 1e7, 1, 0x8043),     # "< 1E+7"
    (A, 1351, 214748, None, None), (A, 1351, 214748.5, None, 0x8043),
    (A, 1, 5.0, None, 0x8081), (A, 4050, 206, 1, 0x8081), (CAM, 4203, 0.0, None, 0x8081),   # read-only
    (A, 2011, 1.0, 16, None), (A, 2011, 1.0, 17, 0x8080), (A, 2011, 1.0, 0, 0x8080),        # data sets 1-16
    (A, 3031, 1.0, 8, None), (A, 3031, 1.0, 9, 0x8080), (A, 4266, 68, 2, None), (A, 4266, 68, 3, 0x8080),
    (A, 8, 100.0, 5, None),                                    # no index: the Index input is ignored
    (A, 2002, 95, None, None), (A, 2002, 7, None, 0x8043),     # IMMEDIATELY is 95, its expert-list number 7
    (A, 4001, 82, None, None), (A, 4001, 81, None, None), (A, 4001, 83, None, 0x8043),
    (A, 4502, 1, None, None), (A, 4502, 0, None, None), (A, 4502, 16, None, 0x8043),
    (A, 1352, 15, None, None), (A, 1352, 16, None, 0x8043), (A, 1352, -1, None, 0x8043),
    (A, 2020, 2_147_483_647, 1, None), (A, 2020, 2_147_483_648, 1, 0x8043),
    (A, 5065, 127, 1, None), (A, 5065, 0, 1, 0x8043), (A, 5065, 128, 1, 0x8043),
    (CT, 5052, 0xFFFF_FFFF, None, None), (CT, 5052, 0x1_0000_0000, None, 0x8043), (CT, 5052, -1, None, 0x8043),
    (A, 4010, (0x1234, 0xFFFF_FFFF), 1, None), (A, 4010, (1, 2, 3), 1, 0x8043), (A, 4010, 5, 1, 0x8043),
    (A, 4500, (0x0001_0300, 0x0FFF_FB00), None, None), (A, 4500, 0x0300, None, 0x8043),
    # wrong kind of value for the parameter's input
    (A, 4142, "100", None, 0x8043), (A, 4142, None, None, 0x8043), (A, 4142, True, None, 0x8043),
    (A, 2002, 95.0, None, 0x8043), (A, 2002, True, None, 0x8043), (A, 1352, 3.0, None, 0x8043),
]


@pytest.mark.parametrize("to, no, value, index, code", CHECKS, ids=[f"{c[0]}-{c[1]}-{c[2]!r}" for c in CHECKS])
def test_s7t_write_parameter_error_ids(to, no, value, index, code):
    """S7-Technology V4.1 §6.7.5: 8043 for a value out of range or no code of the ENUM, 8080 for an index the
    parameter does not have, 8081 for a read-only parameter, 808B for a REAL that is no number; REALs strictly
    inside +/-1E+12 (§6.9.3)."""
    assert P.parameter(to, no).check(value, index) == code


def test_s7t_servo_dependent_bound_of_1263():
    """S7-Technology V4.1 §9.4.2, parameter 1263: maximum 2^31 * servo cycle * 9, checked when the cycle is known."""
    p = P.parameter(A, 1263)
    limit = 2 ** 31 * 0.002 * 9
    assert p.check(limit, servo_cycle=0.002) is None
    assert p.check(limit * 1.001, servo_cycle=0.002) == 0x8043
    assert p.check(limit * 1.001) is None and p.check(-1.0) == 0x8043


def test_s7t_parameter_properties():
    """S7-Technology V4.1 §9.4, §6.7.4: input that carries the value, hydraulic parameters, restart."""
    assert P.parameter(A, 4142).value_input == "Value"
    assert P.parameter(A, 2002).value_input == "ValueDInt" and P.parameter(A, 2002).enum == "EnumChangeMode"
    assert P.parameter(A, 4010).value_input == "ValueDword1+ValueDword2"
    assert P.parameter(CT, 5052).value_input == "ValueDword1"
    assert P.parameter(A, 5009).hydraulic and not P.parameter(A, 5011).hydraulic
    assert P.parameter(A, 8).needs_restart and not P.parameter(A, 4142).needs_restart
    assert P.parameter(A, 1116).enum == "EnumAxisExtrapolatedVelocitySwitch" == P.parameter(EE, 1116).enum
    assert P.parameter(A, 4152).db_name == "Limits.Dynamic response.Positive direction of travel.Negative jerk"
    assert all(p.firmware is None for p in P.all_parameters())


_values = st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.integers(-2 ** 40, 2 ** 40), st.booleans(),
                    st.none(), st.text(max_size=3), st.tuples(st.integers(-5, 2 ** 33), st.integers(-5, 2 ** 33)),
                    st.lists(st.floats(), max_size=3))


@given(p=st.sampled_from(P.all_parameters()), value=_values,
       index=st.one_of(st.none(), st.integers(-3, 20), st.floats(), st.text(max_size=2)))
def test_s7t_check_never_raises_and_gives_a_write_parameter_code(p, value, index):
    """S7-Technology V4.1 §6.7.5: whatever is written, the answer is None or an ErrorID of MC_WriteParameter."""
    assert p.check(value, index) in (None, 0x8043, 0x8080, 0x8081, 0x808B)


@given(p=st.sampled_from([p for p in P.all_parameters() if p.data_type == "REAL" and p.writable]),
       value=st.floats(allow_nan=False, allow_infinity=False))
def test_s7t_accepted_reals_lie_inside_the_ranges(p, value):
    """S7-Technology V4.1 §6.9.3, §9.4: an accepted REAL is inside +/-1E+12 and the printed Min./Max."""
    if p.check(value) is None:
        assert -1e12 < value < 1e12
        assert p.minimum is None or value >= p.minimum
        assert p.maximum is None or value <= p.maximum
