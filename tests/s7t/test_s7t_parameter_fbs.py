"""FB 406 MC_ReadSysParameter and FB 407 MC_WriteParameter (S7-Technology V4.1 §6.7.4, §6.7.5, §5.16, §9.4).

Parameter numbers, ranges, access, the "Activation" column and the ENUM codes (§9.4.12) are the manual's; the
axes are virtual unless the rule needs a drive.  Values are read and written through the FBs as a user
program does, and their effect is checked on the axis's motion.
"""
from __future__ import annotations

import math

import pytest

from plcmotion.s7t import (MC_ChangeDataset, MC_MoveVelocity, MC_Power, MC_ReadSysParameter, MC_Reset, MC_WriteParameter)

from _s7t_rig import VIRTUAL, controller, enabled


def _read(axis, number: int, index: int = 1) -> MC_ReadSysParameter:
    fb = MC_ReadSysParameter()
    return fb(Axis=axis, Execute=True, ParameterNumber=number, Index=index)


def _write(axis, number: int, index: int = 1, **value) -> MC_WriteParameter:
    fb = MC_WriteParameter()
    return fb(Axis=axis, Execute=True, ParameterNumber=number, Index=index, **value)


def _axis(params: dict | None = None):
    ctl = controller()
    axis = ctl.add_positioning_axis("Axis1", VIRTUAL if params is None else params)
    ctl.run(0.02)
    return ctl, axis


# --- reading by number ----------------------------------------------------------------------------------------
@pytest.mark.parametrize("number, output, configured, expected", [
    (2, "Value", {"swlimit.minusposition": -123.5}, -123.5),             # swlimit.minusposition, REAL
    (3, "Value", {"swlimit.plusposition": 456.25}, 456.25),
    (4, "ValueDInt", {"swlimit.state": 1}, 1),                           # EnumActiveInactive ACTIVE = 1
    (1123, "ValueDInt", {"TypeOfAxis.Homing.referencingNecessary": 0}, 0),   # EnumYesNo NO = 0
    (1121, "ValueDInt", {"TypeOfAxis.Homing.direction": 4}, 4),          # EnumDirectionType NEGATIVE = 4
    (4241, "ValueDInt", {"userdefaultdynamics.direction": 39}, 39),      # EnumDirection SHORTEST_WAY = 39
    (4248, "ValueDInt", {"userdefaultdynamics.profile": 66}, 66),        # EnumProfile SMOOTH = 66
    (4250, "Value", {"userdefaultdynamics.velocity": 77.0}, 77.0),
    (2033, "Value", {"TypeOfAxis.NumberOfDataSets.DataSet_1.ControllerStruct.PV_Controller.kv": 33.0}, 33.0),
    (2021, "ValueDInt", {"TypeOfAxis.NumberOfDataSets.DataSet_1.Gear.numFactor": 3}, 3),
])
def test_s7t_read_parameter_by_number(number, output, configured, expected):
    """S7-Technology V4.1 §6.7.4: the value is at the output of its data type (REAL at Value, DINT and ENUM
    at ValueDInt, §9.4.12 codes); the other outputs are 0."""
    ctl, axis = _axis({**VIRTUAL, **configured})
    fb = _read(axis, number)
    assert fb.Done and not fb.Error and fb.ErrorID == 0
    assert getattr(fb, output) == expected
    for other, zero in (("Value", 0.0), ("ValueDInt", 0), ("ValueDword1", 0), ("ValueDword2", 0)):
        if other != output:
            assert getattr(fb, other) == zero


def test_s7t_read_parameter_axis_as_db_number_and_done_while_execute():
    """S7-Technology V4.1 §6.7.4, §6.9.3: Axis may be the technology DB number; Done stays while Execute is
    TRUE and goes with it (§5.8)."""
    ctl, axis = _axis()
    fb = MC_ReadSysParameter()
    fb(Axis=axis.db_number, Execute=True, ParameterNumber=3)
    assert fb.Done and fb.Value == 10000.0
    fb(Execute=True)
    assert fb.Done and fb.Value == 10000.0
    fb(Execute=False)
    assert not fb.Done and fb.Value == 0.0


def test_s7t_read_system_variables_of_a_moving_axis():
    """S7-Technology V4.1 §9.4 parameters 1 (commandposition), 10 (actualvelocity), 11 (commandvelocity),
    4040 (basic motion position): a virtual axis at constant velocity 40 (actual = setpoint)."""
    ctl, axis, _ = enabled()
    move = MC_MoveVelocity()
    move(Axis=axis, Execute=True, Velocity=40.0, Acceleration=400.0, Deceleration=400.0, Jerk=0.0)
    ctl.run(0.5)
    p = float(ctl.bank.sp_p[axis.index])
    assert _read(axis, 10).Value == pytest.approx(40.0)
    assert _read(axis, 11).Value == pytest.approx(40.0)
    assert _read(axis, 1).Value == pytest.approx(p)
    assert _read(axis, 4040).Value == pytest.approx(p)
    assert _read(axis, 4030).Value == 0.0                      # no superimposed motion
    assert _read(axis, 4400).ValueDInt == 102                  # EnumLimitExceededOk O_K_ = 102


def test_s7t_read_system_variable_homeposition_after_restart_is_zero():
    """S7-Technology V4.1 §9.4 parameter 4173 positioningstate.homeposition: no homing yet, 0.0; 2000
    numberOfDataSets (one configured)."""
    ctl, axis = _axis()
    assert _read(axis, 4173).Value == 0.0
    assert _read(axis, 2000).ValueDInt == 1


# --- ErrorIDs of FB 406 ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("inputs, error_id", [
    (dict(ParameterNumber=9999), 0x8080),                     # no such parameter
    (dict(ParameterNumber=5), 0x8080),                        # §9.4 has no number 5
    (dict(ParameterNumber=7, Index=17), 0x8080),              # data sets 1..16
    (dict(ParameterNumber=7, Index=2), 0x8080),               # data set 2 not configured
    (dict(ParameterNumber=40000), 0x8043),                    # not an INT
    (dict(ParameterNumber=3, Index=1.5), 0x8043),
    (dict(ParameterNumber=3, Axis=1), 0x8044),                # the MCDevice DB
    (dict(ParameterNumber=3, Axis=999), 0x8083),              # no technology DB
])
def test_s7t_read_parameter_errors(inputs, error_id):
    """S7-Technology V4.1 §6.7.4 ErrorIDs: 8080 invalid number or index, 8043 ParameterNumber / Index, 8044
    e.g. the MCDevice DB, 8083 no technology DB."""
    ctl, axis = _axis()
    fb = MC_ReadSysParameter()
    fb(**{"Axis": axis, "Execute": True, **inputs})
    assert fb.Error and fb.ErrorID == error_id and not fb.Done and not fb.ENO


def test_s7t_read_position_of_speed_axis_is_no_parameter():
    """S7-Technology V4.1 §9.4: parameter 1 (axis position setpoint) serves positioning and synchronization
    axes only: a speed-controlled axis gives 8080."""
    ctl = controller()
    axis = ctl.add_positioning_axis("Speed", {**VIRTUAL, "Wizard.Technology": 0})
    ctl.run(0.01)
    assert _read(axis, 1).ErrorID == 0x8080
    assert _read(axis, 11).Done


# --- writing: ranges and ENUM codes --------------------------------------------------------------------------------
@pytest.mark.parametrize("number, value, error_id", [
    (4142, 0.0, 0), (4142, 200.0, 0), (4142, 200.001, 0x8043), (4142, -0.5, 0x8043),   # override 0..200 %
    (2032, 150.0, 0), (2032, 150.5, 0x8043),                                           # kpc 0..150 %
    (2073, 100.0, 0), (2073, 100.1, 0x8043),                                           # warning limit 0..100 %
    (4181, 10000.0, 0), (4181, 10000.5, 0x8043),                                       # approach velocity
    (4183, 1000.0, 0), (4183, 1000.5, 0x8043),                                         # reduced velocity
    (2033, 9999999.0, 0), (2033, 1.0e7, 0x8043),                                       # kv < 1E+7
    (4250, 1.0e12, 0x8043), (4250, math.nan, 0x808B), (4250, math.inf, 0x808B),        # REAL inputs
    (1351, 214748.0, 0), (1351, 214749.0, 0x8043),
])
def test_s7t_write_real_parameter_ranges(number, value, error_id):
    """S7-Technology V4.1 §6.7.5, §9.4: Value is checked against the parameter's Min./Max.; 8043 outside,
    808B for an invalid REAL; the value is in effect from the next IPO cycle and reads back."""
    ctl, axis = _axis()
    fb = _write(axis, number, Value=value)
    assert fb.ErrorID == error_id and fb.Error == bool(error_id) and fb.Done != bool(error_id)
    if not error_id:
        ctl.run(0.004)
        assert _read(axis, number).Value == value


@pytest.mark.parametrize("number, code, ok", [
    (4241, 3, True), (4241, 38, True), (4241, 39, True), (4241, 6, False),   # EnumDirection 3/4/5/38/39
    (4248, 66, True), (4248, 67, True), (4248, 68, False),                 # EnumProfile
    (1123, 0, True), (1123, 1, True), (1123, 2, False),                    # EnumYesNo
    (4, 1, True), (4, 61, False),                                          # ValueDint, not the expert value
    (1121, 4, True), (1121, 5, True), (1121, 3, False),                    # EnumDirectionType
])
def test_s7t_write_enum_parameter_as_value_dint(number, code, ok):
    """S7-Technology V4.1 §6.7.5, §9.4.12: an ENUM parameter is written with its ValueDint code at ValueDInt;
    a code the ENUM does not have (e.g. its expert-list number) gives 8043."""
    ctl, axis = _axis()
    fb = _write(axis, number, ValueDInt=code)
    if ok:
        assert fb.Done and fb.ErrorID == 0
        ctl.run(0.004)
        assert _read(axis, number).ValueDInt == code
    else:
        assert fb.Error and fb.ErrorID == 0x8043


def test_s7t_write_only_the_input_of_the_data_type_counts():
    """S7-Technology V4.1 §6.7.5: only the input of the parameter's data type is evaluated (a REAL parameter
    ignores ValueDInt, an ENUM parameter ignores Value)."""
    ctl, axis = _axis()
    assert _write(axis, 3, Value=700.0, ValueDInt=-5).Done
    assert _write(axis, 4248, ValueDInt=66, Value=math.nan).Done
    ctl.run(0.004)
    assert _read(axis, 3).Value == 700.0 and _read(axis, 4248).ValueDInt == 66


@pytest.mark.parametrize("inputs, error_id", [
    (dict(ParameterNumber=10, Value=1.0), 0x8081),              # actualvelocity: read-only
    (dict(ParameterNumber=1, Value=1.0), 0x8081),               # commandposition: read-only
    (dict(ParameterNumber=9999, Value=1.0), 0x8080),
    (dict(ParameterNumber=7, Index=2, Value=1.0), 0x8080),      # data set 2 not configured
    (dict(ParameterNumber=7, Index=0, Value=1.0), 0x8080),
    (dict(ParameterNumber=-1, Value=1.0), 0x8080),
    (dict(ParameterNumber=70000, Value=1.0), 0x8043),
    (dict(ParameterNumber=4241, ValueDInt=1.5), 0x8043),
    (dict(ParameterNumber=3, Value="1"), 0x8043),
    (dict(ParameterNumber=3, Value=1.0, Axis=1), 0x8044),
    (dict(ParameterNumber=3, Value=1.0, Axis=4711), 0x8083),
    (dict(ParameterNumber=2021, ValueDInt=0), 0x8043),          # gear factor: at least 1 (schema)
])
def test_s7t_write_parameter_errors(inputs, error_id):
    """S7-Technology V4.1 §6.7.5 ErrorIDs: 8080 number/index, 8081 read-only, 8043 value or input, 8044 the
    MCDevice DB, 8083 no technology DB; the configuration stays as it was."""
    ctl, axis = _axis()
    before = dict(axis.parameters.values)
    fb = MC_WriteParameter()
    fb(**{"Axis": axis, "Execute": True, **inputs})
    assert fb.Error and fb.ErrorID == error_id and not fb.Done
    ctl.run(0.004)
    assert axis.parameters.values == before


def test_s7t_write_leadscrew_pitch_that_makes_max_velocity_unreachable():
    """S7-Technology V4.1 §6.7.5 (8043): reducing the leadscrew pitch 1100 so that the maximum velocity 8 is
    no longer reachable is refused.  Drive 6000 1/min, pitch 10 mm: 1000 mm/s = parameter 8; pitch 5 gives
    500 mm/s."""
    ctl = controller()
    axis = ctl.add_positioning_axis("Real", {"TypeOfAxis.MaxVelocity.maximum": 1000.0})
    ctl.run(0.01)
    assert _write(axis, 1100, Value=5.0).ErrorID == 0x8043
    assert _write(axis, 1100, Value=20.0).ErrorID == 0x0020          # 2000 mm/s: possible, after a restart


# --- "effective": Immediately / Restart --------------------------------------------------------------------------
def test_s7t_write_restart_parameter_needs_mc_reset_restart():
    """S7-Technology V4.1 §6.7.5 (warning 0020), §6.7.1, §7.1 Statusword.RequestRestart: a "Restart" parameter
    (1100 leadscrew pitch) is Done with ErrorID 0020, the axis keeps the old value until MC_Reset with
    Restart = TRUE; RequestRestart is TRUE until then."""
    ctl = controller()
    axis = ctl.add_positioning_axis("Real", {"TypeOfAxis.MaxVelocity.maximum": 100.0})
    ctl.run(0.01)
    fb = _write(axis, 1100, Value=20.0)
    assert fb.Done and fb.ErrorID == 0x0020 and fb.ENO and not fb.Error
    ctl.run(0.01)
    assert axis.db.Statusword.RequestRestart
    assert _read(axis, 1100).Value == 10.0
    assert axis.config.drive.length_per_revolution == 10.0
    reset = MC_Reset()
    reset(Axis=axis, Execute=True, Restart=True)
    for _ in range(100):
        ctl.run(0.004)
        if reset(Execute=True).Done:
            break
    assert reset.Done
    ctl.run(0.01)
    assert not axis.db.Statusword.RequestRestart
    assert _read(axis, 1100).Value == 20.0 and axis.config.drive.length_per_revolution == 20.0
    assert _write(axis, 1100, Value=20.0).ErrorID == 0                 # unchanged: no restart needed


def test_s7t_write_restart_parameter_back_to_the_effective_value_needs_no_restart():
    """S7-Technology V4.1 §6.7.5: 0020 is not given when the value is the one in effect; writing the old
    value back clears RequestRestart."""
    ctl, axis = _axis()
    assert _write(axis, 1202, Value=720.0).ErrorID == 0x0020            # modulo length, Restart
    ctl.run(0.01)
    assert axis.db.Statusword.RequestRestart
    assert _write(axis, 1202, Value=360.0).ErrorID == 0
    ctl.run(0.01)
    assert not axis.db.Statusword.RequestRestart


def test_s7t_write_software_limit_acts_on_the_moving_axis():
    """S7-Technology V4.1 §6.7.5, §9.4 parameter 3 (Immediately), §4.5.7.3: the positive software limit
    switch written while the axis moves at 20 towards it stops the axis there (TDB ErrorID 8014), never
    beyond it."""
    ctl, axis, _ = enabled({**VIRTUAL, "swlimit.state": 1})
    move = MC_MoveVelocity()
    move(Axis=axis, Execute=True, Velocity=20.0, Acceleration=-1.0, Deceleration=-1.0, Jerk=-1.0)
    ctl.run(1.0)
    assert float(ctl.bank.sp_p[axis.index]) < 30.0
    assert _write(axis, 3, Value=30.0).Done
    highest = 0.0
    for _ in range(500):
        ctl.run(0.004)
        highest = max(highest, float(ctl.bank.sp_p[axis.index]))
    assert highest <= 30.0 + 1e-9
    assert float(ctl.bank.sp_v[axis.index]) == 0.0
    assert axis.db.ErrorID == 0x8014
    assert move(Execute=True).CommandAborted


def test_s7t_write_velocity_override_acts_on_the_running_motion():
    """S7-Technology V4.1 §6.7.5 example "Override": parameter 4142 = 50 % halves the velocity of the running
    MC_MoveVelocity (100 -> 50); the write neither aborts it nor is aborted (§6.8)."""
    ctl, axis, _ = enabled()
    move = MC_MoveVelocity()
    move(Axis=axis, Execute=True, Velocity=100.0, Acceleration=1000.0, Deceleration=1000.0, Jerk=0.0)
    ctl.run(0.3)
    assert float(ctl.bank.sp_v[axis.index]) == pytest.approx(100.0)
    assert _write(axis, 4142, Value=50.0).Done
    ctl.run(0.3)
    assert float(ctl.bank.sp_v[axis.index]) == pytest.approx(50.0)
    assert move(Execute=True).Busy and not move.CommandAborted
    assert axis.db.SpeedOverride == 50.0


def test_s7t_written_values_survive_restart_not_power_off():
    """S7-Technology V4.1 §5.16, §6.7.5: a written value lasts through MC_Reset Restart = TRUE and CPU
    STOP -> RUN; after POWER OFF -> ON the configured value is in effect again."""
    ctl, axis = _axis()
    assert _write(axis, 3, Value=500.0).Done
    ctl.run(0.01)
    reset = MC_Reset()
    reset(Axis=axis, Execute=True, Restart=True)
    ctl.run(0.5)
    assert _read(axis, 3).Value == 500.0
    ctl.stop()
    ctl.start()
    ctl.run(0.01)
    assert _read(axis, 3).Value == 500.0 and axis.config.software_limits.maximum == 500.0
    ctl.power_cycle()
    ctl.run(0.01)
    assert _read(axis, 3).Value == 10000.0 and axis.config.software_limits.maximum == 10000.0


def test_s7t_collect_and_activate_changed_config_data():
    """S7-Technology V4.1 §6.7.5 "collect": 4001 = COLLECT_CHANGED_CONFIG_DATA (82) holds the changes back,
    4001 = ACTIVATE_CHANGED_CONFIG_DATA (81) makes them effective together."""
    ctl, axis = _axis()
    assert _write(axis, 4001, ValueDInt=82).Done
    assert _read(axis, 4001).ValueDInt == 82
    assert _write(axis, 2, Value=-50.0).Done and _write(axis, 3, Value=50.0).Done
    ctl.run(0.02)
    assert axis.config.software_limits.minimum == -10000.0 and axis.config.software_limits.maximum == 10000.0
    assert _write(axis, 4001, ValueDInt=81).Done
    ctl.run(0.01)
    assert (axis.config.software_limits.minimum, axis.config.software_limits.maximum) == (-50.0, 50.0)
    assert _read(axis, 4001).ValueDInt == 81
    assert _write(axis, 4001, ValueDInt=83).ErrorID == 0x8043


def test_s7t_parameter_fbs_on_a_restarting_axis():
    """S7-Technology V4.1 §6.7.4 / §6.7.5 (8086): while the TO restarts its parameters are not available."""
    ctl, axis = _axis()
    reset = MC_Reset()
    reset(Axis=axis, Execute=True, Restart=True)
    assert _read(axis, 3).ErrorID == 0x8086
    assert _write(axis, 3, Value=1.0).ErrorID == 0x8086


def test_s7t_parameter_fbs_do_not_abort_motion():
    """S7-Technology V4.1 §6.8: MC_ReadSysParameter and MC_WriteParameter abort no command."""
    ctl, axis, power = enabled()
    move = MC_MoveVelocity()
    move(Axis=axis, Execute=True, Velocity=30.0)
    ctl.run(0.2)
    for number in (3, 1100, 4250):
        _read(axis, number)
        _write(axis, number, Value=5000.0 if number == 3 else 50.0)
    ctl.run(0.01)
    assert move(Execute=True).Busy and not move.CommandAborted and power(Enable=True).Status


def test_s7t_write_homing_required_acts_immediately():
    """S7-Technology V4.1 §9.4 parameter 1123 "Homing required" (Activation: Immediately), §3.1.8: with NO
    (EnumYesNo 0) an absolute positioning of an axis that is not homed runs at once, without a restart."""
    from plcmotion.s7t import MC_MoveAbsolute
    ctl, axis, _ = enabled({"Wizard": {"Virtual": 1}, "TypeOfAxis.Homing.referencingNecessary": 1})
    move = MC_MoveAbsolute()
    move(Axis=axis, Execute=True, Position=10.0, Velocity=50.0)
    ctl.run(0.01)
    assert not move(Execute=True).Busy and not move.Done                  # refused: not homed
    fb = _write(axis, 1123, ValueDInt=0)
    assert fb.Done and fb.ErrorID == 0
    move(Execute=False)
    move(Execute=True)
    ctl.run(1.0)
    assert move(Execute=True).Done and float(ctl.bank.sp_p[axis.index]) == pytest.approx(10.0)


def test_s7t_write_acceleration_override_acts_on_the_next_motion():
    """S7-Technology V4.1 §6.7.5 example "Override": parameter 4141 (1.0 ... 1000.0 %) scales acceleration and
    deceleration; at 50 % an MC_MoveVelocity with Acceleration 100 reaches 50 after 1.0 s instead of 0.5 s;
    AccelerationOverride of the technology DB shows it; 0.5 and 1000.5 are out of range."""
    ctl, axis, _ = enabled()
    assert _read(axis, 4141).Value == 100.0
    assert _write(axis, 4141, Value=0.5).ErrorID == 0x8043
    assert _write(axis, 4141, Value=1000.5).ErrorID == 0x8043
    assert _write(axis, 4141, Value=50.0).Done
    ctl.run(0.01)
    assert axis.db.AccelerationOverride == 50.0
    move = MC_MoveVelocity()
    move(Axis=axis, Execute=True, Velocity=50.0, Acceleration=100.0, Deceleration=100.0, Jerk=0.0)
    ctl.run(0.5)
    assert float(ctl.bank.sp_v[axis.index]) == pytest.approx(25.0, abs=0.5)
    ctl.run(0.6)
    assert float(ctl.bank.sp_v[axis.index]) == pytest.approx(50.0)


def test_s7t_read_parameter_of_a_data_set_without_own_value():
    """S7-Technology V4.1 §6.7.4 with §3.1.10 data sets: an axis with two data sets reads Kv (number 2033) of
    data set 2 as data set 1's when data set 2 sets none, and 8080 for data set 3 it does not have; an
    MC_ReadSysParameter never ends in an internal error (16#8001) for a data set index (merge defect: data
    set tags without a value made the read raise).  ErrorID 8086: the data set of the Index must be the one in
    force (MC_ChangeDataset)."""
    ctl = controller()
    axis = ctl.add_positioning_axis("A", {"TypeOfAxis.Homing.referencingNecessary": 0,     # a real axis
                                          "TypeOfAxis.NumberOfDataSets.numberOfDataSets": 2,
                                          "TypeOfAxis.NumberOfDataSets.changeMode": 95,
                                          "TypeOfAxis.NumberOfDataSets.DataSet_1.ControllerStruct.PV_Controller.kv": 25.0})
    for index, error_id, value in ((1, 0, 25.0), (2, 0x8086, None), (3, 0x8080, None)):
        fb = MC_ReadSysParameter()
        fb(Axis=axis, Execute=True, ParameterNumber=2033, Index=index)
        assert fb.ErrorID == error_id and fb.Error == (error_id != 0)
        if value is not None:
            assert fb.Done and fb.Value == value
    change = MC_ChangeDataset()
    change(Axis=axis, Execute=True, Dataset=2)
    assert change.Done
    for index, error_id, value in ((1, 0x8086, None), (2, 0, 25.0)):
        fb = MC_ReadSysParameter()
        fb(Axis=axis, Execute=True, ParameterNumber=2033, Index=index)
        assert fb.ErrorID == error_id and (value is None or fb.Value == value)
