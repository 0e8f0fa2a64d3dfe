"""StatusWord / StatusWord2 / ErrorWord / WarningWord / ErrorDetail of the S7-1500 axis, from the manual
(S7-1500T Synchronous operation V5: §7.1.1 status and error bits, §A.1.37-§A.1.41 tag tables, §6.1.5.4
limits, §6.1.5.6 position monitoring)."""
import pytest

from plcmotion.s7_1500 import (MC_MoveAbsolute, MC_MoveJog, MC_MoveRelative, MC_MoveSuperimposed,
                               MC_MoveVelocity, MC_Reset, MC_Stop)

from _single_h import AxisRig

# §A.1.37: bit number -> name (appendix spelling)
STATUS_BITS = {0: "Enable", 1: "Error", 2: "RestartActive", 3: "OnlineStartValuesChanged", 4: "ControlPanelActive",
               5: "HomingDone", 6: "Done", 8: "PositioningCommand", 9: "JogCommand", 10: "VelocityCommand",
               11: "HomingCommand", 12: "ConstantVelocity", 13: "Accelerating", 14: "Decelerating",
               15: "SWLimitMinActive", 16: "SWLimitMaxActive", 17: "HWLimitMinActive", 18: "HWLimitMaxActive",
               21: "Synchronizing", 22: "Synchronous", 23: "SuperimposedMotionCommand", 24: "PhasingCommand",
               25: "AxisSimulation", 26: "TorqueLimitingCommand", 27: "InLimitation", 28: "NonPositionControlled",
               29: "KinematicsMotionCommand", 30: "InClamping", 31: "MotionInCommand"}
ERROR_BITS = {0: "SystemFault", 1: "ConfigFault", 2: "UserFault", 3: "CommandNotAccepted", 4: "DriveFault",
              5: "SensorFault", 6: "DynamicError", 7: "CommunicationFault", 8: "SWLimit", 9: "HWLimit",
              10: "HomingError", 11: "FollowingErrorFault", 12: "PositioningFault", 13: "PeripheralError",
              14: "SynchronousError", 15: "AdaptionError"}
WARNING_BITS = {0: "SystemWarning", 1: "ConfigWarning", 2: "UserWarning", 3: "CommandNotAccepted", 4: "DriveWarning",
                5: "SensorWarning", 6: "DynamicWarning", 7: "CommunicationWarning", 8: "SWLimitMin", 9: "SWLimitMax",
                10: "HomingWarning", 11: "FollowingErrorWarning", 12: "PositioningWarning", 13: "PeripheralWarning",
                14: "SynchronousWarning", 15: "AdaptionWarning"}


@pytest.mark.parametrize("word, table", [("StatusWord", STATUS_BITS), ("ErrorWord", ERROR_BITS),
                                         ("WarningWord", WARNING_BITS)])
def test_s7_1500_bit_names_and_numbers_sA_1_37_39_41(word, table):
    r = AxisRig(synchronous=True, family="S7-1500T")
    w = getattr(r.axis, word)
    for bit, name in table.items():
        assert getattr(w, name) == getattr(w, f"X{bit}"), (word, bit, name)
    assert r.axis.StatusWord2.StopCommand == r.axis.StatusWord2.X0


def test_s7_1500_standstill_bit_name_of_the_appendix_sA_1_37():
    """§A.1.37 bit 7 and §A.1.26 call the bit "Standstill" (the §7.1.1 diagnostics view: "StandStill")."""
    r = AxisRig()
    assert r.axis.StatusWord.Standstill == r.axis.StatusWord.X7


def test_s7_1500_enabled_axis_at_rest_s7_1_1():
    r = AxisRig()
    sw = r.axis.StatusWord
    assert sw.Enable and not sw.Error and sw.Done and sw.StandStill
    assert not (sw.PositioningCommand or sw.JogCommand or sw.VelocityCommand or sw.HomingCommand)
    assert not sw.HomingDone and not sw.Accelerating and not sw.Decelerating


def test_s7_1500_constant_velocity_is_shown_at_standstill_s7_1_1():
    """§7.1.1 Motion status: "Constant velocity: The axis is moved with constant velocity or is stationary.
    (<TO>.StatusWord.X12 (ConstantVelocity))"."""
    r = AxisRig()
    assert r.axis.StatusWord.StandStill
    assert r.axis.StatusWord.ConstantVelocity
    rel = MC_MoveRelative()
    r.call(rel, Execute=True, Distance=20.0)
    r.run_until(lambda: rel.Done)
    r.step(2)
    assert r.axis.StatusWord.StandStill and r.axis.StatusWord.ConstantVelocity


def test_s7_1500_motion_bits_through_a_positioning_sA_1_37():
    r = AxisRig()
    rel = MC_MoveRelative()
    r.call(rel, Execute=True, Distance=200.0, Velocity=100.0, Acceleration=500.0, Deceleration=500.0)
    ax = r.axis
    seen = {"acc": False, "const": False, "dec": False}

    def rec():
        sw = ax.StatusWord
        if rel.Busy:
            assert sw.PositioningCommand and not sw.Done
            assert not (sw.Accelerating and sw.Decelerating)
            if sw.Accelerating:
                seen["acc"] = True
                assert ax.Acceleration > 0 and not sw.ConstantVelocity
            if sw.Decelerating:
                seen["dec"] = True
                assert ax.Acceleration < 0 and not sw.ConstantVelocity
            if sw.ConstantVelocity and ax.Velocity != 0.0:
                seen["const"] = True
                assert ax.Velocity == pytest.approx(100.0)
            assert ax.StatusPositioning.TargetPosition == pytest.approx(200.0)      # §7.1.2
        return None
    r.record = rec
    r.run_until(lambda: rel.Done, 10)
    assert all(seen.values()), seen
    sw = ax.StatusWord
    assert sw.Done and not sw.PositioningCommand


def test_s7_1500_velocity_jog_homing_superimposed_command_bits_sA_1_37():
    r = AxisRig()
    ax = r.axis
    mv = MC_MoveVelocity()
    inp = r.call(mv, Execute=True, Velocity=50.0)
    r.run_until(lambda: mv.InVelocity)
    assert ax.StatusWord.VelocityCommand and not ax.StatusWord.JogCommand and not ax.StatusWord.Done
    sup = MC_MoveSuperimposed()
    r.call(sup, Execute=True, Distance=10.0)
    r.step(2)
    assert ax.StatusWord.SuperimposedMotionCommand
    r.run_until(lambda: sup.Done)
    assert not ax.StatusWord.SuperimposedMotionCommand
    inp["Execute"] = False
    jog = MC_MoveJog()
    keys = r.call(jog, JogForward=True, JogBackward=False, Velocity=30.0)
    r.run_until(lambda: jog.InVelocity)
    assert ax.StatusWord.JogCommand and not ax.StatusWord.VelocityCommand
    keys["JogForward"] = False
    r.run_until(lambda: not jog.Busy)
    r.step(2)
    assert not ax.StatusWord.JogCommand and ax.StatusWord.StandStill


def test_s7_1500_done_bit_is_false_while_mc_stop_brakes_the_axis_sA_1_37():
    """§A.1.37 bit 6 Done: "0 = A motion job is in progress"; §7.1.1: "Done (no job running): No job active at
    technology object". MC_Stop braking the axis is a job in progress."""
    r = AxisRig()
    ax = r.axis
    mv = MC_MoveVelocity()
    r.call(mv, Execute=True, Velocity=600.0)
    r.run_until(lambda: mv.InVelocity)
    stop = MC_Stop()
    r.call(stop, Execute=True, Mode=2)
    r.step(2)
    assert stop.Busy and abs(ax.Velocity) > 0.0 and ax.StatusWord2.StopCommand
    assert not ax.StatusWord.Done


def test_s7_1500_stopcommand_bit_follows_mc_stop_sA_1_38():
    r = AxisRig()
    ax = r.axis
    stop = MC_Stop()
    inp = r.call(stop, Execute=True, Mode=0)
    r.run_until(lambda: stop.Done)
    assert ax.StatusWord2.StopCommand
    r.step(5)
    assert ax.StatusWord2.X0 and stop.Done            # still held while Execute is TRUE
    inp["Execute"] = False
    r.step(2)
    assert not ax.StatusWord2.X0


def test_s7_1500_rejected_job_sets_command_not_accepted_s7_1_1():
    """§7.1.1 Error table: "Job rejected: A job cannot be executed. You cannot execute a Motion Control
    instruction because necessary requirements are not fulfilled (for example, technology object not
    homed). (<TO>.ErrorWord.X3 (CommandNotAccepted))"; warnings table: the same as WarningWord.X3."""
    r = AxisRig()
    mv = MC_MoveAbsolute()
    r.call(mv, Execute=True, Position=10.0)
    r.run_until(lambda: mv.Error, 1.0)
    assert mv.ErrorID != 0
    assert r.axis.ErrorWord.CommandNotAccepted or r.axis.WarningWord.CommandNotAccepted


SW = {"PositionLimits_SW": {"Active": True, "MinPosition": -100.0, "MaxPosition": 100.0}}


@pytest.mark.parametrize("sign", [1, -1])
def test_s7_1500_sw_limit_stops_at_the_switch_and_signals_an_error_s6_1_5_4(sign):
    r = AxisRig(SW)
    ax = r.axis
    r.home(0.0)
    mv = MC_MoveVelocity()
    r.call(mv, Execute=True, Velocity=sign * 200.0)
    r.run_until(lambda: mv.Error or mv.CommandAborted, 5)
    r.run(0.2)
    assert ax.Position == pytest.approx(sign * 100.0, abs=1e-6)     # stops AT the switch position
    assert ax.Velocity == 0.0
    assert mv.Error and mv.ErrorID != 0 and not mv.Busy
    sw = ax.StatusWord
    assert sw.Error and ax.ErrorWord.SWLimit and ax.ErrorDetail.Number != 0
    assert (sw.SWLimitMaxActive, sw.SWLimitMinActive) == ((True, False) if sign > 0 else (False, True))
    # after acknowledgement the axis can be moved back into the working range
    reset = MC_Reset()
    r.call(reset, Execute=True)
    r.run_until(lambda: reset.Done, 1.0)
    assert not ax.StatusWord.Error and not ax.ErrorWord.SWLimit
    back = MC_MoveRelative()
    r.call(back, Execute=True, Distance=-sign * 30.0)
    r.run_until(lambda: back.Done or back.Error, 3)
    assert back.Done and ax.Position == pytest.approx(sign * 70.0)
    assert not ax.StatusWord.SWLimitMaxActive and not ax.StatusWord.SWLimitMinActive


def test_s7_1500_sw_limits_act_only_on_a_homed_axis_s6_1_5_4():
    r = AxisRig(SW)
    rel = MC_MoveRelative()
    r.call(rel, Execute=True, Distance=300.0, Velocity=300.0)
    r.run_until(lambda: rel.Done or rel.Error, 5)
    assert rel.Done and r.axis.Position == pytest.approx(300.0)
    assert not r.axis.ErrorWord.SWLimit and not r.axis.StatusWord.SWLimitMaxActive


def test_s7_1500_hw_limit_switch_alarm_531_removes_the_enable_s6_1_5_4():
    r = AxisRig({"PositionLimits_HW": {"Active": True, "MinSwitchAddress": "I1.0", "MaxSwitchAddress": "I1.1",
                                       "MinSwitchLevel": True, "MaxSwitchLevel": True}}, virtual=False, enable=False)
    ax = r.axis
    r.ctl.inputs["I1.0"] = False
    r.ctl.inputs["I1.1"] = False
    r.en["on"] = True
    r.run_until(lambda: r.power.Status, 2)
    mv = MC_MoveVelocity()
    r.call(mv, Execute=True, Velocity=100.0)
    r.run(0.3)
    r.ctl.inputs["I1.1"] = True
    r.run(0.3)
    assert ax.ErrorDetail.Number == 531 and ax.ErrorDetail.Reaction == 4      # remove enable
    assert ax.ErrorWord.HWLimit and ax.StatusWord.HWLimitMaxActive and not ax.StatusWord.HWLimitMinActive
    assert not ax.StatusWord.Enable and mv.Error


def test_s7_1500_following_error_alarm_521_and_warning_522_s6_1_5_6():
    r = AxisRig({"FollowingError": {"MaxValue": 0.5, "MinValue": 0.5, "WarningLevel": 50.0},
                 "PositionControl": {"Kpc": 0.0}}, virtual=False)
    ax = r.axis
    warn = []
    r.record = lambda: warn.append(bool(ax.WarningWord.FollowingErrorWarning))
    mv = MC_MoveVelocity()
    r.call(mv, Execute=True, Velocity=300.0)
    r.run_until(lambda: ax.StatusWord.Error, 3)
    r.step(2)
    assert any(warn)                                         # WarningLevel reached before the limit
    assert ax.ErrorWord.FollowingErrorFault and ax.ErrorDetail.Number == 521 and ax.ErrorDetail.Reaction == 4
    assert not ax.StatusWord.Enable and mv.Error and mv.ErrorID != 0


def test_s7_1500_positioning_monitoring_alarm_541_s6_1_5_6():
    r = AxisRig({"PositioningMonitoring": {"ToleranceTime": 0.01, "Window": 0.001},
                 "PositionControl": {"Kv": 2.0, "Kpc": 0.0}, "FollowingError": {"EnableMonitoring": False}},
                virtual=False)
    ax = r.axis
    rel = MC_MoveRelative()
    r.call(rel, Execute=True, Distance=50.0, Velocity=200.0, Acceleration=2000.0, Deceleration=2000.0)
    r.run_until(lambda: rel.Done or rel.Error, 5)
    assert rel.Error and not rel.Done
    assert ax.ErrorWord.PositioningFault and ax.ErrorDetail.Number == 541 and ax.ErrorDetail.Reaction == 4
    assert not ax.StatusWord.Enable


def test_s7_1500_done_only_after_the_minimum_dwell_time_in_the_window_sA_1_25():
    r = AxisRig({"PositioningMonitoring": {"MinDwellTime": 0.2, "Window": 1.0}}, virtual=False)
    ax = r.axis
    rel = MC_MoveRelative()
    r.call(rel, Execute=True, Distance=50.0, Velocity=200.0, Acceleration=2000.0, Deceleration=2000.0)
    log = []
    r.record = lambda: log.append((r.ctl.time, ax.ActualPosition, rel.Done))
    r.run_until(lambda: rel.Done, 5)
    t_done = r.ctl.time
    inside_since = None
    for t, p, d in log:
        if abs(p - 50.0) <= 1.0:
            inside_since = t if inside_since is None else inside_since
        else:
            inside_since = None
    assert inside_since is not None and t_done - inside_since >= 0.2 - 1e-9


def test_s7_1500_standstill_signal_needs_the_minimum_dwell_time_sA_1_26():
    r = AxisRig({"StandstillSignal": {"VelocityThreshold": 5.0, "MinDwellTime": 0.2}}, virtual=False)
    ax = r.axis
    rel = MC_MoveRelative()
    r.call(rel, Execute=True, Distance=50.0, Velocity=200.0, Acceleration=2000.0, Deceleration=2000.0)
    log = []
    r.record = lambda: log.append((r.ctl.time, ax.ActualVelocity, bool(ax.StatusWord.StandStill)))
    r.run(0.05)
    r.run_until(lambda: rel.Done, 5)
    r.run(0.5)
    moving = [i for i, (t, v, s) in enumerate(log) if abs(v) >= 5.0]
    last_fast = log[moving[-1]][0]
    first_ss = next(t for t, v, s in log if s and t > last_fast)
    assert first_ss - last_fast >= 0.2 - 0.005
    assert all(not s for t, v, s in log if abs(v) >= 5.0)


@pytest.mark.parametrize("fb, inputs", [
    (MC_MoveVelocity, dict(Execute=True, Velocity=500.0)),
    (MC_MoveJog, dict(JogForward=True, Velocity=500.0)),
    (MC_MoveRelative, dict(Execute=True, Distance=1000.0, Velocity=500.0)),
])
def test_s7_1500_dynamic_warning_when_the_velocity_limit_cuts_a_job_sA_1_16(fb, inputs):
    """§A.1.16: "If you have specified greater values in a Motion Control instruction, then motion is
    performed using the dynamic limits, and a warning is indicated (alarm 501 to 503)" -> WarningWord.X6."""
    r = AxisRig({"DynamicLimits": {"Velocity": 300.0}})
    inst = fb()
    r.call(inst, **inputs)
    seen = []
    r.record = lambda: seen.append(bool(r.axis.WarningWord.DynamicWarning))
    r.run(1.2)
    assert r.axis.Velocity == pytest.approx(300.0)
    assert any(seen) and not r.axis.StatusWord.Error and not inst.Error


def test_s7_1500_error_detail_is_zero_without_alarm_sA_1_40():
    r = AxisRig()
    assert r.axis.ErrorDetail.Number == 0 and r.axis.ErrorDetail.Reaction == 0 and int(r.axis.ErrorWord) == 0


def test_s7_1500_axis_simulation_bit_sA_1_37():
    r = AxisRig({"Simulation": {"Mode": 1}}, virtual=False)
    assert r.axis.StatusWord.AxisSimulation
    r2 = AxisRig(virtual=False)
    assert not r2.axis.StatusWord.AxisSimulation


def test_s7_1500_non_position_controlled_bit_sA_1_37():
    r = AxisRig(virtual=False)
    mv = MC_MoveVelocity()
    r.call(mv, Execute=True, Velocity=50.0, PositionControlled=False)
    r.run_until(lambda: mv.InVelocity, 3)
    assert r.axis.StatusWord.NonPositionControlled
    mv2 = MC_MoveVelocity()
    r.call(mv2, Execute=True, Velocity=50.0, PositionControlled=True)
    r.run_until(lambda: mv2.InVelocity, 3)
    assert not r.axis.StatusWord.NonPositionControlled
