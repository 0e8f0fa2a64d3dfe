"""S7-1500 single-axis instructions against the manual: dynamic input rule (§9.1 intro / §6.1.5.2 /
§A.1.16-17), emergency stop (§6.1.5.3), MC_Power stop modes, MC_Stop, MC_Home modes (§6.1.5.5),
MC_MoveAbsolute/-Relative/-Velocity/-Jog, MC_Halt, MC_MoveSuperimposed, bad inputs."""
import math

import numpy as np
import pytest

from plcmotion.s7_1500 import (MC_Halt, MC_Home, MC_MoveAbsolute, MC_MoveJog, MC_MoveRelative, MC_MoveSuperimposed,
                               MC_MoveVelocity, MC_Reset, MC_Stop)

from _single_h import AxisRig

MOD = {"Modulo": {"Enable": True, "Length": 360.0, "StartValue": 0.0}}


# --- dynamic input rule --------------------------------------------------------------------------------
def test_s7_1500_negative_dynamic_inputs_take_the_defaults_and_zero_jerk_is_a_trapezoid_s9_1():
    r = AxisRig({"DynamicDefaults": {"Velocity": 80.0, "Acceleration": 400.0, "Deceleration": 200.0,
                                     "Jerk": 0.0}})
    ax = r.axis
    rel = MC_MoveRelative()
    r.call(rel, Execute=True, Distance=100.0, Velocity=-5.0, Acceleration=-1.0, Deceleration=-3.0, Jerk=-1.0)
    acc = []
    r.record = lambda: acc.append((ax.Velocity, ax.Acceleration))
    r.run_until(lambda: rel.Done, 10)
    v = np.array([x[0] for x in acc])
    a = np.array([x[1] for x in acc])
    assert v.max() == pytest.approx(80.0) and a.max() == pytest.approx(400.0) and a.min() == pytest.approx(-200.0)


def test_s7_1500_default_jerk_is_used_for_negative_jerk_s9_1():
    r = AxisRig({"DynamicDefaults": {"Jerk": 2000.0}, "DynamicLimits": {"MaxJerk": 0.0}})
    ax = r.axis
    rel = MC_MoveRelative()
    r.call(rel, Execute=True, Distance=100.0, Velocity=100.0, Acceleration=500.0, Deceleration=500.0, Jerk=-1.0)
    acc = []
    r.record = lambda: acc.append(ax.Acceleration)
    r.run_until(lambda: rel.Done, 10)
    jerk = np.abs(np.diff(acc)).max() / r.ctl.app_cycle
    assert jerk == pytest.approx(2000.0, rel=0.02)


def test_s7_1500_changed_defaults_act_at_the_next_execute_edge_not_on_the_running_job_sA_1_17():
    r = AxisRig()
    ax = r.axis
    rel = MC_MoveRelative()
    inp = r.call(rel, Execute=True, Distance=400.0)
    r.run(1.0)
    assert ax.Velocity == pytest.approx(100.0)
    ax.DynamicDefaults.Velocity = 50.0
    r.run(0.5)
    assert ax.Velocity == pytest.approx(100.0)            # the running job keeps its dynamics
    r.run_until(lambda: rel.Done, 10)
    inp["Execute"] = False
    r.step()
    inp["Execute"] = True
    r.run(1.0)
    assert ax.Velocity == pytest.approx(50.0)


def test_s7_1500_move_velocity_negative_velocity_is_not_the_default_sA_1_17():
    """§A.1.17: defaults are used for values < 0 "exceptions: MC_MoveJog.Velocity, MC_MoveVelocity.Velocity"."""
    r = AxisRig()
    mv = MC_MoveVelocity()
    r.call(mv, Execute=True, Velocity=-30.0, Direction=0)
    r.run_until(lambda: mv.InVelocity, 3)
    assert r.axis.Velocity == pytest.approx(-30.0)


@pytest.mark.parametrize("v, d, expect", [(40.0, 0, 40.0), (-40.0, 0, -40.0), (-40.0, 1, 40.0), (40.0, 1, 40.0),
                                          (40.0, 2, -40.0), (-40.0, 2, -40.0)])
def test_s7_1500_move_velocity_direction(v, d, expect):
    r = AxisRig()
    mv = MC_MoveVelocity()
    r.call(mv, Execute=True, Velocity=v, Direction=d)
    r.run_until(lambda: mv.InVelocity, 3)
    assert r.axis.Velocity == pytest.approx(expect) and mv.Busy and not mv.Error


def test_s7_1500_move_velocity_current_keeps_the_present_velocity():
    r = AxisRig()
    mv = MC_MoveVelocity()
    r.call(mv, Execute=True, Velocity=70.0)
    r.run(0.05)                                            # still accelerating
    v0 = r.axis.Velocity
    assert 0 < v0 < 70
    cur = MC_MoveVelocity()
    r.call(cur, Execute=True, Velocity=10.0, Current=True)
    r.run_until(lambda: cur.InVelocity, 2)
    r.run(0.3)
    assert mv.CommandAborted and cur.InVelocity
    assert r.axis.Velocity == pytest.approx(v0, rel=0.1)


# --- emergency stop, MC_Power -------------------------------------------------------------------------
@pytest.mark.parametrize("mode, decel", [(0, 4000.0), (2, 6000.0)])
def test_s7_1500_mc_stop_modes_ramps_s9_3_1(mode, decel):
    r = AxisRig({"DynamicLimits": {"MaxJerk": 1.0e5}, "DynamicDefaults": {"Jerk": 1.0e5}})
    ax = r.axis
    mv = MC_MoveVelocity()
    r.call(mv, Execute=True, Velocity=800.0)
    r.run_until(lambda: mv.InVelocity, 5)
    acc = []
    r.record = lambda: acc.append(ax.Acceleration)
    stop = MC_Stop()
    r.call(stop, Execute=True, Mode=mode)
    r.run_until(lambda: stop.Done, 5)
    assert min(acc) == pytest.approx(-decel)
    if mode == 0:     # §6.1.5.2: emergency stop deceleration without jerk limit
        assert acc[1] == pytest.approx(-decel) or acc[0] == pytest.approx(-decel)
    assert mv.CommandAborted and ax.Velocity == 0.0


def test_s7_1500_power_stop_mode_1_removes_the_enable_at_once():
    r = AxisRig(stop_mode=1)
    ax = r.axis
    mv = MC_MoveVelocity()
    r.call(mv, Execute=True, Velocity=400.0)
    r.run_until(lambda: mv.InVelocity)
    r.en["on"] = False
    r.step()
    assert not r.power.Status and not ax.StatusWord.Enable


def test_s7_1500_power_invalid_stop_mode_is_an_error_and_error_has_an_id():
    r = AxisRig(enable=False)
    r.en.update(on=True, stop_mode=7)
    r.run(0.1)
    assert r.power.Error and r.power.ErrorID != 0 and not r.power.Status


def test_s7_1500_power_reports_an_alarm_and_reset_clears_it():
    r = AxisRig({"PositionLimits_SW": {"Active": True, "MinPosition": -10.0, "MaxPosition": 10.0}})
    r.home(0.0)
    mv = MC_MoveVelocity()
    inp = r.call(mv, Execute=True, Velocity=100.0)
    r.run_until(lambda: mv.Error, 3)
    r.step(2)
    assert r.power.Error and r.power.ErrorID != 0
    inp["Execute"] = False
    reset = MC_Reset()
    r.call(reset, Execute=True)
    r.run_until(lambda: reset.Done, 1)
    r.step(2)
    assert not r.power.Error and r.power.ErrorID == 0 and r.power.Status


# --- MC_Reset ---------------------------------------------------------------------------------------------
def test_s7_1500_reset_restart_reloads_start_values_and_loses_incremental_homing():
    r = AxisRig(virtual=False)
    ax = r.axis
    r.home(5.0)
    ax.DynamicDefaults.Velocity = 33.0
    r.en["on"] = False
    r.run_until(lambda: not r.power.Status and not r.power.Busy, 2)
    reset = MC_Reset()
    r.call(reset, Execute=True, Restart=True)
    r.run_until(lambda: reset.Done or reset.Error, 2)
    assert reset.Done and not reset.Error
    assert ax.DynamicDefaults.Velocity == pytest.approx(100.0)
    assert not ax.StatusWord.HomingDone


# --- MC_Home ----------------------------------------------------------------------------------------------
@pytest.mark.parametrize("mode", [0, 1])
def test_s7_1500_direct_homing_does_not_abort_the_running_motion_s6_1_5_5(mode):
    r = AxisRig()
    ax = r.axis
    mv = MC_MoveVelocity()
    r.call(mv, Execute=True, Velocity=100.0)
    r.run_until(lambda: mv.InVelocity)
    h = MC_Home()
    before = {}
    r.steps.insert(0, lambda: before.setdefault("p", ax.Position))
    r.call(h, Execute=True, Mode=mode, Position=1000.0)
    r.run_until(lambda: h.Done, 1)
    r.step(2)
    assert mv.Busy and not mv.CommandAborted and ax.Velocity == pytest.approx(100.0)
    assert ax.StatusWord.HomingDone
    expect = 1000.0 if mode == 0 else before["p"] + 1000.0
    assert ax.Position == pytest.approx(expect + 100.0 * 3 * r.ctl.app_cycle, abs=1.0)


@pytest.mark.parametrize("virtual", [True, False], ids=["virtual", "drive"])
def test_s7_1500_active_homing_aborts_the_running_motion_and_ends_at_standstill_s6_1_5_5(virtual):
    """§6.1.5.5: "With active homing, MC_Home performs the configured home position approach. Active traversing
    motions are aborted." After the homing job is Done no motion may be left running without a job."""
    params = {} if virtual else {"Sensor": {"Sensor[1]": {"ActiveHoming": {"Mode": 2, "DigitalInputAddress": "I0.0"}}},
                                 "Plant": {"HomingSwitchPosition": 300.0}}
    r = AxisRig(params, virtual=virtual)
    ax = r.axis
    mv = MC_MoveVelocity()
    r.call(mv, Execute=True, Velocity=100.0)
    r.run_until(lambda: mv.InVelocity)
    h = MC_Home()
    r.call(h, Execute=True, Mode=3)
    r.run_until(lambda: h.Done or h.Error, 20)
    r.step(2)
    assert h.Done and mv.CommandAborted
    r.run(1.0)
    assert ax.StatusWord.HomingDone
    assert ax.Velocity == 0.0 and ax.StatusWord.StandStill and ax.StatusWord.Done


def test_s7_1500_active_homing_aborts_a_superimposed_motion_virtual_axis_s9_3_1():
    r = AxisRig()
    ax = r.axis
    sup = MC_MoveSuperimposed()
    r.call(sup, Execute=True, Distance=1000.0, VelocityDiff=50.0)
    r.run(0.5)
    h = MC_Home()
    r.call(h, Execute=True, Mode=3)
    r.run_until(lambda: h.Done or h.Error, 2)
    r.step(2)
    assert sup.CommandAborted and not ax.StatusWord.SuperimposedMotionCommand


def test_s7_1500_active_homing_is_rejected_while_mc_stop_holds_the_axis_virtual_axis():
    """§9.3.1: running MC_Stop vs new MC_Home Mode 3/5 = '-' (MC_Stop continues); decisions #24: the axis stays
    locked while MC_Stop.Execute is TRUE (new jobs rejected, 16#800F)."""
    r = AxisRig()
    ax = r.axis
    stop = MC_Stop()
    r.call(stop, Execute=True, Mode=0)
    r.run_until(lambda: stop.Done)
    h = MC_Home()
    r.call(h, Execute=True, Mode=3)
    r.run_until(lambda: h.Done or h.Error, 1)
    assert h.Error and not stop.CommandAborted and ax.StatusWord2.StopCommand


@pytest.mark.parametrize("mode, expect", [(5, 42.0), (10, 42.0), (0, 7.0)])
def test_s7_1500_home_position_modes_use_the_configured_home_position(mode, expect):
    r = AxisRig({"Homing": {"HomePosition": 42.0},
                 "Sensor": {"Sensor[1]": {"PassiveHoming": {"Mode": 2, "DigitalInputAddress": "I0.0", "Direction": 0},
                                          "ActiveHoming": {"Mode": 2, "DigitalInputAddress": "I0.0"}}},
                 "Plant": {"HomingSwitchPosition": 50.0}}, virtual=False)
    ax = r.axis
    h = MC_Home()
    r.call(h, Execute=True, Mode=mode, Position=7.0)
    if mode == 10:
        mv = MC_MoveVelocity()
        r.call(mv, Execute=True, Velocity=100.0)
    r.run_until(lambda: h.Done or h.Error, 20)
    assert h.Done and ax.StatusWord.HomingDone
    assert h.ReferenceMarkPosition == pytest.approx(expect)


@pytest.mark.parametrize("mode, homed_while_busy", [(2, False), (8, True)])
def test_s7_1500_passive_homing_reset_of_the_homing_status(mode, homed_while_busy):
    r = AxisRig({"Sensor": {"Sensor[1]": {"PassiveHoming": {"Mode": 2, "DigitalInputAddress": "I0.0",
                                                            "Direction": 0}}},
                 "Plant": {"HomingSwitchPosition": 50.0}}, virtual=False)
    ax = r.axis
    r.home(0.0)
    h = MC_Home()
    r.call(h, Execute=True, Mode=mode, Position=-3.0)
    r.step(2)
    assert h.Busy and ax.StatusWord.HomingCommand
    assert ax.StatusWord.HomingDone == homed_while_busy
    mv = MC_MoveVelocity()
    r.call(mv, Execute=True, Velocity=100.0)
    r.run_until(lambda: h.Done or h.Error, 5)
    assert h.Done and ax.StatusWord.HomingDone and mv.Busy and not mv.CommandAborted   # passive: no abort
    assert not ax.StatusWord.HomingCommand


def test_s7_1500_home_mode_9_cancels_passive_homing_s9_3_1():
    r = AxisRig({"Sensor": {"Sensor[1]": {"PassiveHoming": {"Mode": 2, "DigitalInputAddress": "I0.0"}}},
                 "Plant": {"HomingSwitchPosition": 1.0e6}}, virtual=False)
    h = MC_Home()
    r.call(h, Execute=True, Mode=2)
    r.step(3)
    assert h.Busy
    c = MC_Home()
    r.call(c, Execute=True, Mode=9)
    r.run_until(lambda: c.Done or c.Error, 1)
    r.step()
    assert c.Done and h.CommandAborted and not r.axis.StatusWord.HomingCommand


@pytest.mark.parametrize("d, start, target, sign", [(1, 350.0, 10.0, 1), (2, 350.0, 10.0, -1), (3, 350.0, 10.0, 1),
                                                    (3, 10.0, 350.0, -1), (1, 10.0, 350.0, 1), (2, 10.0, 350.0, -1)])
def test_s7_1500_move_absolute_direction_on_a_modulo_axis(d, start, target, sign):
    r = AxisRig(MOD)
    ax = r.axis
    r.home(start)
    ma = MC_MoveAbsolute()
    r.call(ma, Execute=True, Position=target, Direction=d, Velocity=200.0)
    vs = []
    r.record = lambda: vs.append(ax.Velocity)
    r.run_until(lambda: ma.Done, 10)
    assert ax.Position == pytest.approx(target)
    assert (max(vs) > 0 and min(vs) >= 0) if sign > 0 else (min(vs) < 0 and max(vs) <= 0)
    assert 0.0 <= ax.Position < 360.0


@pytest.mark.parametrize("d", [0, 4, -1])
def test_s7_1500_move_absolute_invalid_direction_modulo(d):
    r = AxisRig(MOD)
    r.home(0.0)
    ma = MC_MoveAbsolute()
    r.call(ma, Execute=True, Position=10.0, Direction=d)
    r.run_until(lambda: ma.Error or ma.Done, 1)
    assert ma.Error and ma.ErrorID != 0 and r.axis.Position == 0.0


def test_s7_1500_done_stays_while_execute_true_and_one_cycle_after_a_short_pulse():
    r = AxisRig()
    rel = MC_MoveRelative()
    inp = r.call(rel, Execute=True, Distance=10.0)
    r.run_until(lambda: rel.Done)
    r.step(5)
    assert rel.Done and not rel.Busy
    inp["Execute"] = False
    r.step()
    assert not rel.Done
    inp["Execute"] = True
    r.step()
    inp["Execute"] = False
    log = []
    r.record = lambda: log.append((rel.Busy, rel.Done))
    r.run(1.0)
    assert log[0][0] and sum(d for b, d in log) == 1          # Done visible for exactly one call


def test_s7_1500_command_aborted_and_busy_false_when_overridden():
    r = AxisRig()
    rel = MC_MoveRelative()
    inp = r.call(rel, Execute=True, Distance=1000.0)
    r.run(0.3)
    halt = MC_Halt()
    r.call(halt, Execute=True)
    r.step(2)
    assert rel.CommandAborted and not rel.Busy and not rel.Done and not rel.Error
    r.run_until(lambda: halt.Done, 3)
    assert r.axis.Velocity == 0.0
    r.step(3)
    assert rel.CommandAborted                          # stays while Execute is TRUE
    inp["Execute"] = False
    r.step()
    assert not rel.CommandAborted


def test_s7_1500_move_relative_target_status_sA_1_28():
    r = AxisRig()
    r.home(10.0)
    rel = MC_MoveRelative()
    r.call(rel, Execute=True, Distance=25.0)
    r.step(2)
    assert r.axis.StatusPositioning.TargetPosition == pytest.approx(35.0)
    r.run_until(lambda: rel.Done)
    assert r.axis.Position == pytest.approx(35.0)


# --- MC_MoveJog, MC_Halt ----------------------------------------------------------------------------------
def test_s7_1500_jog_release_brakes_and_the_job_ends():
    r = AxisRig()
    jog = MC_MoveJog()
    keys = r.call(jog, JogForward=False, JogBackward=True, Velocity=60.0)
    r.run_until(lambda: jog.InVelocity)
    assert r.axis.Velocity == pytest.approx(-60.0)
    keys["JogBackward"] = False
    r.run_until(lambda: r.axis.Velocity == 0.0, 2)
    r.step(2)
    assert not jog.Busy and not jog.Error and not jog.InVelocity


def test_s7_1500_jog_aborted_by_move_velocity():
    r = AxisRig()
    jog = MC_MoveJog()
    r.call(jog, JogForward=True, JogBackward=False, Velocity=60.0)
    r.run_until(lambda: jog.InVelocity)
    mv = MC_MoveVelocity()
    r.call(mv, Execute=True, Velocity=20.0)
    r.run_until(lambda: mv.InVelocity, 2)
    assert jog.CommandAborted and r.axis.Velocity == pytest.approx(20.0)


def test_s7_1500_halt_done_at_standstill_with_its_deceleration():
    r = AxisRig()
    ax = r.axis
    mv = MC_MoveVelocity()
    r.call(mv, Execute=True, Velocity=200.0)
    r.run_until(lambda: mv.InVelocity)
    acc = []
    r.record = lambda: acc.append(ax.Acceleration)
    halt = MC_Halt()
    r.call(halt, Execute=True, Deceleration=250.0)
    r.run_until(lambda: halt.Done, 3)
    assert min(acc) == pytest.approx(-250.0) and ax.Velocity == 0.0 and mv.CommandAborted


# --- MC_Stop lock -------------------------------------------------------------------------------------------
@pytest.mark.parametrize("fb, inputs", [
    (MC_MoveRelative, dict(Distance=5.0)), (MC_MoveVelocity, dict(Velocity=5.0)), (MC_Halt, {}),
    (MC_MoveSuperimposed, dict(Distance=5.0)), (MC_Home, dict(Mode=3)),
])
def test_s7_1500_mc_stop_holds_the_axis_while_execute_is_true(fb, inputs):
    r = AxisRig()
    stop = MC_Stop()
    si = r.call(stop, Execute=True, Mode=2)
    r.run_until(lambda: stop.Done)
    inst = fb()
    r.call(inst, Execute=True, **inputs)
    r.run(0.2)
    assert inst.Error and inst.ErrorID != 0 and r.axis.Position == 0.0


def test_s7_1500_same_stop_mode_aborts_the_running_stop_s9_3_1_b():
    r = AxisRig({"DynamicLimits": {"MaxDeceleration": 500.0}})
    mv = MC_MoveVelocity()
    r.call(mv, Execute=True, Velocity=400.0)
    r.run_until(lambda: mv.InVelocity, 5)
    s1, s2 = MC_Stop(), MC_Stop()
    r.call(s1, Execute=True, Mode=2)
    r.step(3)
    assert s1.Busy
    r.call(s2, Execute=True, Mode=2)
    r.step(3)
    assert s1.CommandAborted and s2.Busy and not s2.Error


# --- MC_MoveSuperimposed ----------------------------------------------------------------------------------
def test_s7_1500_new_motion_job_aborts_a_superimposed_motion_s9_3_1():
    r = AxisRig()
    mv = MC_MoveVelocity()
    r.call(mv, Execute=True, Velocity=50.0)
    r.run_until(lambda: mv.InVelocity)
    sup = MC_MoveSuperimposed()
    r.call(sup, Execute=True, Distance=500.0, VelocityDiff=20.0)
    r.run(0.3)
    assert sup.Busy
    halt = MC_Halt()
    r.call(halt, Execute=True)
    r.run_until(lambda: halt.Done, 3)
    assert sup.CommandAborted and mv.CommandAborted and r.axis.Velocity == 0.0
    assert not r.axis.StatusWord.SuperimposedMotionCommand


def test_s7_1500_superimposed_does_not_abort_the_basic_motion_but_a_new_superimposed_one_s9_3_1():
    r = AxisRig()
    rel = MC_MoveRelative()
    r.call(rel, Execute=True, Distance=300.0)
    r.run(0.2)
    s1, s2 = MC_MoveSuperimposed(), MC_MoveSuperimposed()
    r.call(s1, Execute=True, Distance=50.0, VelocityDiff=10.0)
    r.run(0.2)
    r.call(s2, Execute=True, Distance=5.0)
    r.step(3)
    assert s1.CommandAborted and s2.Busy and rel.Busy and not rel.CommandAborted


# --- bad inputs do not disturb the axis --------------------------------------------------------------------
BAD = [
    (MC_MoveRelative, dict(Distance=float("nan"))),
    (MC_MoveRelative, dict(Distance=5.0, Velocity=0.0)),
    (MC_MoveRelative, dict(Distance=5.0, Acceleration=float("nan"))),
    (MC_MoveRelative, dict(Distance=5.0, Jerk=float("nan"))),
    (MC_MoveAbsolute, dict(Position=float("inf"))),
    (MC_MoveVelocity, dict(Velocity=float("nan"))),
    (MC_MoveVelocity, dict(Velocity=5.0, Direction=7)),
    (MC_MoveVelocity, dict(Velocity=5.0, Deceleration=0.0)),
    (MC_Halt, dict(Deceleration=0.0)),
    (MC_Halt, dict(Jerk=float("nan"))),
    (MC_Stop, dict(Mode=1)),
    (MC_Home, dict(Mode=4)),
    (MC_Home, dict(Mode=0, Position=float("nan"))),
    (MC_MoveSuperimposed, dict(Distance=float("nan"))),
    (MC_MoveSuperimposed, dict(Distance=5.0, AccelerationDiff=0.0)),
]


@pytest.mark.parametrize("fb, inputs", BAD, ids=[f"{f.__name__}-{i}" for i, (f, _) in enumerate(BAD)])
def test_s7_1500_bad_input_rejected_running_job_unaffected(fb, inputs):
    r = AxisRig()
    r.home(0.0)
    ax = r.axis
    mv = MC_MoveVelocity()
    r.call(mv, Execute=True, Velocity=40.0)
    r.run_until(lambda: mv.InVelocity)
    inst = fb()
    r.call(inst, Execute=True, **inputs)
    r.run_until(lambda: inst.Error or getattr(inst, "Done", False), 1)
    r.step(2)
    assert inst.Error and inst.ErrorID != 0
    assert mv.Busy and not mv.CommandAborted and ax.Velocity == pytest.approx(40.0)
    assert not ax.StatusWord.Error and math.isfinite(ax.Position)


def test_s7_1500_bad_jog_velocity_rejected():
    r = AxisRig()
    jog = MC_MoveJog()
    r.call(jog, JogForward=True, JogBackward=False, Velocity=float("nan"))
    r.run(0.2)
    assert jog.Error and jog.ErrorID != 0 and r.axis.Velocity == 0.0


# --- velocity override §A.1.21 ------------------------------------------------------------------------------
def test_s7_1500_override_change_acts_at_once_with_the_jobs_dynamics_sA_1_21():
    """§A.1.21: "An override change takes effect immediately, and is performed with the dynamic settings in
    effect in the Motion Control instruction"."""
    r = AxisRig()
    ax = r.axis
    mv = MC_MoveVelocity()
    r.call(mv, Execute=True, Velocity=200.0, Acceleration=150.0, Deceleration=120.0)
    r.run_until(lambda: mv.InVelocity, 5)
    acc = []
    r.record = lambda: acc.append(ax.Acceleration)
    ax.Override.Velocity = 50.0
    r.run(2.0)
    assert ax.Velocity == pytest.approx(100.0)
    assert min(acc) == pytest.approx(-120.0)


def test_s7_1500_override_zero_holds_a_positioning_busy_and_resumes_sA_1_21():
    r = AxisRig()
    ax = r.axis
    rel = MC_MoveRelative()
    r.call(rel, Execute=True, Distance=300.0)
    r.run(0.5)
    ax.Override.Velocity = 0.0
    r.run(1.0)
    assert ax.Velocity == 0.0 and rel.Busy and not rel.Done
    ax.Override.Velocity = 100.0
    r.run_until(lambda: rel.Done, 10)
    assert ax.Position == pytest.approx(300.0)
