"""Single-axis instructions of the S7-1500 (technology version V5): dynamic inputs (> 0 use, = 0 not
permitted except Jerk, < 0 DynamicDefaults, §9.1 conventions), limits, MC_Stop, MC_MoveSuperimposed,
MC_Home modes, StatusWord bits, ErrorIDs."""
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from plcmotion import Controller
from plcmotion.s7_1500 import (MC_Halt, MC_Home, MC_MoveAbsolute, MC_MoveJog, MC_MoveRelative, MC_MoveSuperimposed,
                               MC_MoveVelocity, MC_Power, MC_Reset, MC_Stop, describe)
from plcmotion.s7_1500 import errors as E

V = {"VirtualAxis": {"Mode": 1}}
DYN = {"DynamicDefaults": {"Velocity": 100.0, "Acceleration": 500.0, "Deceleration": 800.0, "Jerk": 0.0,
                           "EmergencyDeceleration": 4000.0},
       "DynamicLimits": {"MaxVelocity": 1000.0, "Velocity": 600.0, "MaxAcceleration": 5000.0,
                         "MaxDeceleration": 6000.0, "MaxJerk": 0.0}}


def axis_rig(params=None):
    ctl = Controller(family="S7-1500")
    axis = ctl.add_positioning_axis("Axis", {**V, **DYN, **(params or {})})
    power = MC_Power()
    steps = []
    trace = []

    @ctl.program
    def main():
        power(Axis=axis, Enable=True)
        for s in steps:
            s()
        trace.append((ctl.time, axis.Position, axis.Velocity, axis.Acceleration))
    ctl.run_until(lambda: power.Status, timeout=1.0)
    return ctl, axis, steps, trace


def test_s7_1500_dynamic_inputs_below_zero_take_the_defaults_s9_1():
    ctl, axis, steps, trace = axis_rig()
    home, move = MC_Home(), MC_MoveAbsolute()
    steps.append(lambda: home(Axis=axis, Execute=True, Mode=0, Position=0.0))
    steps.append(lambda: move(Axis=axis, Execute=home.Done, Position=200.0))
    ctl.run_until(lambda: move.Done, timeout=10.0)
    v = np.array([r[2] for r in trace])
    a = np.array([r[3] for r in trace])
    assert v.max() == pytest.approx(100.0)                  # DynamicDefaults.Velocity
    assert a.max() == pytest.approx(500.0)                  # DynamicDefaults.Acceleration
    assert a.min() == pytest.approx(-800.0)                 # DynamicDefaults.Deceleration
    assert axis.Position == pytest.approx(200.0)


def test_s7_1500_jerk_zero_gives_a_trapezoidal_profile_and_jerk_limits_otherwise_s9_1():
    for jerk, expect_ramp in ((0.0, False), (5000.0, True)):
        ctl, axis, steps, trace = axis_rig()
        move = MC_MoveRelative()
        steps.append(lambda: move(Axis=axis, Execute=True, Distance=100.0, Velocity=200.0, Acceleration=1000.0,
                                  Deceleration=1000.0, Jerk=jerk))
        ctl.run_until(lambda: move.Done, timeout=10.0)
        a = np.array([r[3] for r in trace])
        steps_in_a = np.abs(np.diff(a)).max()
        if expect_ramp:
            assert steps_in_a <= 5000.0 * ctl.app_cycle * 1.01      # acceleration changes at most with Jerk
        else:
            assert steps_in_a >= 999.0                               # acceleration jumps: trapezoid


@pytest.mark.parametrize("fb, inputs, code", [
    (MC_MoveRelative, {"Distance": 10.0, "Velocity": 0.0}, E.parameter("Velocity")),
    (MC_MoveRelative, {"Distance": 10.0, "Acceleration": 0.0}, E.parameter("Acceleration")),
    (MC_MoveRelative, {"Distance": 10.0, "Deceleration": 0.0}, E.parameter("Deceleration")),
    (MC_MoveRelative, {"Distance": float("nan")}, E.parameter("Distance")),
    (MC_MoveRelative, {"Distance": 2e12}, E.parameter("Distance")),
    (MC_MoveVelocity, {"Velocity": 10.0, "Direction": 3}, E.parameter("Direction")),
    (MC_MoveVelocity, {"Velocity": float("inf")}, E.parameter("Velocity")),
    (MC_Halt, {"Deceleration": 0.0}, E.parameter("Deceleration")),
    (MC_Stop, {"Mode": 1}, E.parameter("Mode")),
    (MC_Home, {"Mode": 4}, E.parameter("Mode")),
    (MC_Home, {"Mode": 6}, E.MODE_NEEDS_ABSOLUTE),            # absolute encoder adjustment, incremental encoder
    (MC_MoveSuperimposed, {"Distance": 1.0, "VelocityDiff": 0.0}, E.parameter("VelocityDiff")),
])
def test_s7_1500_invalid_inputs_give_the_errorid_of_the_input(fb, inputs, code):
    ctl, axis, steps, _ = axis_rig()
    inst = fb()
    steps.append(lambda: inst(Axis=axis, Execute=True, **inputs))
    ctl.run_until(lambda: inst.Error, timeout=1.0)
    assert inst.ErrorID == code and "no error" not in describe(code)
    assert axis.StatusWord.Enable and not axis.StatusWord.Error      # a rejected job leaves the axis as it is


def test_s7_1500_commanded_values_above_the_limits_are_limited_with_a_warning_sA_1_16():
    ctl, axis, steps, trace = axis_rig()
    move = MC_MoveVelocity()
    steps.append(lambda: move(Axis=axis, Execute=True, Velocity=900.0, Acceleration=9000.0))
    ctl.run_until(lambda: move.InVelocity, timeout=5.0)
    assert axis.Velocity == pytest.approx(600.0)            # DynamicLimits.Velocity
    a = np.array([r[3] for r in trace])
    assert a.max() == pytest.approx(5000.0)                 # DynamicLimits.MaxAcceleration
    assert axis.WarningWord.X6 and axis.WarningWord.DynamicWarning and not move.Error
    reset = MC_Reset()
    steps.append(lambda: reset(Axis=axis, Execute=True))
    ctl.run_until(lambda: reset.Done, timeout=1.0)
    assert not axis.WarningWord.X6


def test_s7_1500_velocity_override_scales_the_motion_sA_1_21():
    ctl, axis, steps, _ = axis_rig()
    move = MC_MoveVelocity()
    steps.append(lambda: move(Axis=axis, Execute=True, Velocity=200.0))
    ctl.run_until(lambda: move.InVelocity, timeout=5.0)
    axis.Override.Velocity = 50.0
    ctl.run(1.0)
    assert axis.Velocity == pytest.approx(100.0)


def test_s7_1500_move_velocity_zero_stays_busy_in_velocity_at_standstill():
    ctl, axis, steps, _ = axis_rig()
    move = MC_MoveVelocity()
    cmd = {"v": 50.0, "exe": True}
    steps.append(lambda: move(Axis=axis, Execute=cmd["exe"], Velocity=cmd["v"]))
    ctl.run_until(lambda: move.InVelocity, timeout=5.0)
    assert axis.StatusWord.X10 and not axis.StatusWord.X6     # VelocityCommand, not Done
    cmd.update(exe=False)
    ctl.step()
    cmd.update(v=0.0, exe=True)
    ctl.run_until(lambda: move.InVelocity and axis.Velocity == 0.0, timeout=5.0)
    ctl.run(0.5)
    assert move.Busy and move.InVelocity and axis.StatusWord.X7


def test_s7_1500_jog_and_both_directions_error_s9_1():
    ctl, axis, steps, _ = axis_rig()
    jog = MC_MoveJog()
    keys = {"f": True, "b": False}
    steps.append(lambda: jog(Axis=axis, JogForward=keys["f"], JogBackward=keys["b"], Velocity=80.0))
    ctl.run_until(lambda: jog.InVelocity, timeout=5.0)
    assert axis.Velocity == pytest.approx(80.0) and axis.StatusWord.X9
    keys["b"] = True
    ctl.run_until(lambda: jog.Error, timeout=1.0)
    assert jog.ErrorID == E.JOG_BOTH
    ctl.run(1.0)
    assert axis.Velocity == 0.0


def test_s7_1500_power_stop_modes_sA_1_17():
    """StopMode 0 brakes with the emergency deceleration, 2 with the maximum deceleration, 1 removes the
    enable at once."""
    for mode, decel in ((0, 4000.0), (2, 6000.0)):
        ctl = Controller(family="S7-1500")
        axis = ctl.add_positioning_axis("Axis", {**V, **DYN})
        power, move = MC_Power(), MC_MoveVelocity()
        en = {"on": True}
        trace = []

        @ctl.program
        def main():
            power(Axis=axis, Enable=en["on"], StopMode=mode)
            move(Axis=axis, Execute=power.Status, Velocity=400.0)
            trace.append(axis.Acceleration)
            aborted.append(move.CommandAborted)
        aborted = []
        ctl.run_until(lambda: move.InVelocity, timeout=5.0)
        en["on"] = False
        ctl.run_until(lambda: not power.Status, timeout=5.0)
        assert min(trace) == pytest.approx(-decel)
        assert any(aborted)


def test_s7_1500_superimposed_motion_adds_to_the_basic_motion_sA_1_37_x23():
    ctl, axis, steps, _ = axis_rig()
    move, sup = MC_MoveVelocity(), MC_MoveSuperimposed()
    go = {"sup": False}
    steps.append(lambda: move(Axis=axis, Execute=True, Velocity=50.0))
    steps.append(lambda: sup(Axis=axis, Execute=go["sup"], Distance=30.0, VelocityDiff=40.0,
                             AccelerationDiff=400.0, DecelerationDiff=400.0, JerkDiff=0.0))
    ctl.run_until(lambda: move.InVelocity, timeout=5.0)
    t0, p0 = ctl.time, axis.Position
    go["sup"] = True
    ctl.step()
    assert sup.Busy and axis.StatusWord.X23 and move.Busy
    ctl.run_until(lambda: sup.Done, timeout=5.0)
    assert not axis.StatusWord.X23 and move.InVelocity and not move.CommandAborted
    assert axis.Position == pytest.approx(p0 + 50.0 * (ctl.time - t0) + 30.0, abs=1e-6)
    assert axis.Velocity == pytest.approx(50.0)


def test_s7_1500_superimposed_on_a_standing_axis_moves_by_the_distance():
    ctl, axis, steps, _ = axis_rig()
    sup = MC_MoveSuperimposed()
    steps.append(lambda: sup(Axis=axis, Execute=True, Distance=-12.5))
    ctl.run_until(lambda: sup.Done, timeout=5.0)
    assert axis.Position == pytest.approx(-12.5)


def test_s7_1500_superimposed_distance_zero_is_done_and_not_busy_forever_issue8():
    """MC_MoveSuperimposed with Distance 0 on a resting axis has nothing to add: Done, not Busy forever
    (found by the fuzzer, issue 8)."""
    ctl, axis, steps, _ = axis_rig()
    sup = MC_MoveSuperimposed()
    steps.append(lambda: sup(Axis=axis, Execute=True, Distance=0.0))
    ctl.run_until(lambda: sup.Done or sup.Error, timeout=1.0)
    assert sup.Done and not sup.Busy and not sup.Error
    assert axis.Position == 0.0


def test_s7_1500_home_modes_direct_and_home_position_s6_1_5_5():
    ctl, axis, steps, _ = axis_rig({"Homing": {"HomePosition": 42.0}})
    home = MC_Home()
    cmd = {"mode": 0, "pos": 10.0, "exe": True}
    steps.append(lambda: home(Axis=axis, Execute=cmd["exe"], Mode=cmd["mode"], Position=cmd["pos"]))
    ctl.run_until(lambda: home.Done, timeout=1.0)
    assert axis.Position == 10.0 and axis.StatusWord.X5 and home.ReferenceMarkPosition == 10.0
    for mode, pos, expect in ((1, 5.0, 15.0), (5, 0.0, 42.0), (10, 0.0, 42.0)):
        cmd.update(exe=False)
        ctl.step()
        cmd.update(mode=mode, pos=pos, exe=True)
        ctl.run_until(lambda: home.Done, timeout=1.0)
        assert axis.Position == pytest.approx(expect)        # virtual axis: homing done at once


def test_s7_1500_status_word_motion_bits_sA_1_37():
    ctl, axis, steps, _ = axis_rig()
    move = MC_MoveRelative()
    steps.append(lambda: move(Axis=axis, Execute=True, Distance=100.0))
    ctl.step()
    ctl.step()
    sw = axis.StatusWord
    assert sw.Enable and sw.PositioningCommand and not sw.Done and sw.Accelerating and not sw.StandStill
    ctl.run_until(lambda: axis.StatusWord.ConstantVelocity, timeout=5.0)
    ctl.run_until(lambda: move.Done, timeout=5.0)
    sw = axis.StatusWord
    assert sw.Done and sw.StandStill and not sw.PositioningCommand
    assert axis.StatusPositioning.TargetPosition == 0.0


def test_s7_1500_reset_restart_only_when_disabled_s9_1():
    ctl, axis, steps, _ = axis_rig()
    reset = MC_Reset()
    steps.append(lambda: reset(Axis=axis, Execute=True, Restart=True))
    ctl.run_until(lambda: reset.Error or reset.Done, timeout=1.0)
    assert reset.Error and reset.ErrorID == E.RESTART_IMPOSSIBLE


def test_s7_1500_s7_1200_instructions_reject_an_s7_1500_axis():
    from plcmotion.s7_1200 import MC_MoveRelative as MoveRelative1200
    ctl, axis, steps, _ = axis_rig()
    fb = MoveRelative1200()
    steps.append(lambda: fb(Axis=axis, Execute=True, Distance=1.0, Velocity=10.0))
    ctl.run_until(lambda: fb.Error, timeout=1.0)
    assert fb.ErrorID == 0x8408


@settings(max_examples=60)
@given(st.sampled_from([MC_MoveRelative, MC_MoveAbsolute, MC_MoveVelocity, MC_Halt, MC_MoveSuperimposed, MC_Stop,
                        MC_Home]),
       st.dictionaries(st.sampled_from(["Distance", "Position", "Velocity", "Acceleration", "Deceleration", "Jerk",
                                        "Direction", "Mode", "VelocityDiff", "JerkDiff"]),
                       st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.integers(-5, 15)), max_size=4))
def test_s7_1500_error_is_never_shown_with_errorid_zero_and_the_cycle_survives_property(fb, inputs):
    ctl, axis, steps, _ = axis_rig()
    inst = fb()
    names = {k: v for k, v in inputs.items() if k in fb.INPUTS}
    steps.append(lambda: inst(Axis=axis, Execute=True, **names))
    ctl.run(0.2)
    assert ctl.mode == "RUN"
    assert not inst.Error or inst.ErrorID != 0
    assert all(math.isfinite(v) for v in (axis.Position, axis.Velocity))


# --- active homing of a virtual / simulated axis (§6.1.5.5, §9.3.1, §9.3.2) -------------------------------
SIMULATED = {"Simulation": {"Mode": 1}}


@pytest.mark.parametrize("params", [V, SIMULATED], ids=["virtual", "simulated"])
@pytest.mark.parametrize("mode, position, expect", [(3, 25.0, 25.0), (5, 0.0, 42.0)])
def test_s7_1500_active_homing_of_a_virtual_axis_aborts_brakes_and_homes_at_standstill_s6_1_5_5(params, mode, position,
                                                                                        expect):
    """§6.1.5.5: active homing aborts the traversing motion.  A virtual/simulated axis has no switch to search:
    it brakes with the default deceleration (HomingCommand set, not homed), then takes the home position at
    standstill; no motion is left running without a job."""
    ctl = Controller(family="S7-1500")
    axis = ctl.add_positioning_axis("Axis", {**params, **DYN, "Homing": {"HomePosition": 42.0}})
    power, move, home = MC_Power(), MC_MoveVelocity(), MC_Home()
    go = {"home": False}
    trace = []

    @ctl.program
    def main():
        power(Axis=axis, Enable=True)
        move(Axis=axis, Execute=power.Status, Velocity=400.0)
        home(Axis=axis, Execute=go["home"], Mode=mode, Position=position)
        trace.append((axis.Velocity, axis.Acceleration, bool(axis.StatusWord.HomingCommand), home.Busy))
    ctl.run_until(lambda: move.InVelocity, timeout=3.0)
    start = len(trace)
    go["home"] = True
    ctl.run_until(lambda: home.Done or home.Error, timeout=3.0)
    assert home.Done and move.CommandAborted
    braking = trace[start + 1:-1]
    assert braking and all(busy and homing for _v, _a, homing, busy in braking)
    assert min(a for _v, a, _h, _b in braking) == pytest.approx(-800.0)      # DynamicDefaults.Deceleration
    ctl.run(0.5)
    sw = axis.StatusWord
    assert axis.Velocity == 0.0 and axis.Position == pytest.approx(expect) and home.ReferenceMarkPosition == expect
    assert sw.HomingDone and sw.StandStill and sw.Done and not sw.HomingCommand


def test_s7_1500_active_homing_of_a_virtual_axis_aborts_a_superimposed_motion_s9_3_1():
    ctl, axis, steps, _ = axis_rig()
    sup, home = MC_MoveSuperimposed(), MC_Home()
    go = {"home": False}
    steps.append(lambda: sup(Axis=axis, Execute=True, Distance=1000.0, VelocityDiff=50.0))
    steps.append(lambda: home(Axis=axis, Execute=go["home"], Mode=3, Position=0.0))
    ctl.run(0.5)
    go["home"] = True
    ctl.run_until(lambda: home.Done or home.Error, timeout=2.0)
    assert home.Done and sup.CommandAborted and not axis.StatusWord.SuperimposedMotionCommand
    ctl.run(0.2)
    assert axis.Velocity == 0.0 and axis.Position == 0.0


def test_s7_1500_active_homing_of_a_virtual_axis_is_rejected_while_mc_stop_holds_it_s9_3_1():
    """§9.3.1: a running MC_Stop is not aborted by MC_Home Mode 3/5; the stop lock rejects it (decisions #24)."""
    ctl, axis, steps, _ = axis_rig()
    stop, home = MC_Stop(), MC_Home()
    steps.append(lambda: stop(Axis=axis, Execute=True, Mode=0))
    ctl.run_until(lambda: stop.Done, timeout=1.0)
    steps.append(lambda: home(Axis=axis, Execute=True, Mode=3, Position=5.0))
    ctl.run_until(lambda: home.Error or home.Done, timeout=1.0)
    assert home.Error and home.ErrorID == E.STOP_ACTIVE
    assert not stop.CommandAborted and axis.StatusWord2.StopCommand and not axis.StatusWord.HomingDone


def test_s7_1500_active_homing_of_a_virtual_following_axis_aborts_gearing_s9_3_2():
    """§9.3.2 row "MC_Home Mode 3, 5", column MC_GearIn: the gearing is aborted, also on a virtual axis."""
    from plcmotion.s7_1500 import MC_GearIn
    ctl = Controller(family="S7-1500T")
    master = ctl.add_positioning_axis("M", V)
    slave = ctl.add_synchronous_axis("S", {**V, **DYN}, leading_values=["M"])
    pm, ps, move, gear, home = MC_Power(), MC_Power(), MC_MoveVelocity(), MC_GearIn(), MC_Home()
    go = {"home": False}

    @ctl.program
    def main():
        pm(Axis=master, Enable=True)
        ps(Axis=slave, Enable=True)
        move(Axis=master, Execute=pm.Status, Velocity=20.0)
        gear(Master=master, Slave=slave, Execute=ps.Status and pm.Status, RatioNumerator=1, RatioDenominator=1)
        home(Axis=slave, Execute=go["home"], Mode=3, Position=0.0)
    ctl.run_until(lambda: gear.InGear, timeout=3.0)
    go["home"] = True
    ctl.run_until(lambda: home.Done or home.Error, timeout=2.0)
    assert home.Done and gear.CommandAborted and not slave.StatusWord.Synchronous
    ctl.run(0.2)
    assert slave.Velocity == 0.0 and slave.Position == 0.0 and slave.StatusWord.Done


def test_s7_1500_superimposed_distance_during_positioning_on_a_drive_axis():
    """S7-1500T V5 §6.1.5.4 (MC_MoveSuperimposed) with §5.4.4 positioning monitoring: a superimposed distance
    started while an MC_MoveAbsolute runs on a PROFIdrive axis moves the axis by that distance on top of the
    target; the positioning monitor checks the actual value against target plus superimposed distance, so
    the positioning ends Done at 340 without technology alarm 541 (defect: the window was checked around the
    basic target alone and raised 541 with the axis standing at 340)."""
    from plcmotion import Controller
    from plcmotion.s7_1500 import MC_Home, MC_MoveAbsolute, MC_MoveSuperimposed, MC_Power
    ctl = Controller(family="S7-1500")
    ax = ctl.add_positioning_axis("A", {"Actor": {"Type": 1}})
    power, home, move, sup = MC_Power(), MC_Home(), MC_MoveAbsolute(), MC_MoveSuperimposed()

    @ctl.program
    def main():
        power(Axis=ax, Enable=True)
        home(Axis=ax, Execute=power.Status, Mode=0, Position=0.0)
        move(Axis=ax, Execute=home.Done, Position=300.0, Velocity=100.0)
        sup(Axis=ax, Execute=move.Busy and ctl.time > 2.0, Distance=40.0, VelocityDiff=50.0)

    ctl.run_until(lambda: move.Done or move.Error or move.CommandAborted, timeout=10.0)
    assert move.Done and ax.ErrorDetail.Number == 0 and not ax.StatusWord.Error
    assert abs(ax.ActualPosition - 340.0) <= ax.tag("PositioningMonitoring.Window")    # Done: inside the window
    ctl.run(1.0)
    assert abs(ax.ActualPosition - 340.0) < 1e-3 and ax.ErrorDetail.Number == 0


def test_s7_1500_move_velocity_keeps_its_dynamics_with_active_software_limits():
    """S7-1500T V5 §6.1.5.1 / §9.1 (MC_MoveVelocity accelerates with its Acceleration input) with the software
    limit switches active (§5.4.3): far from the limits the job's own Acceleration applies - 10 mm/s² from
    standstill gives 10 mm/s after 1 s, the same as without limits (defect: the limit guard re-planned the
    motion towards the limit with the dynamic defaults and the axis was at 50 mm/s)."""
    from plcmotion import Controller
    from plcmotion.s7_1500 import MC_Home, MC_MoveVelocity, MC_Power
    velocities = []
    for active in (False, True):
        ctl = Controller(family="S7-1500")
        ax = ctl.add_positioning_axis("A", {"VirtualAxis": {"Mode": 1}, "PositionLimits_SW": {
            "Active": active, "MinPosition": -1.0e6, "MaxPosition": 1.0e6}})
        power, home, move = MC_Power(), MC_Home(), MC_MoveVelocity()
        started = []

        @ctl.program
        def main():
            power(Axis=ax, Enable=True)
            home(Axis=ax, Execute=power.Status, Mode=0, Position=0.0)
            move(Axis=ax, Execute=home.Done, Velocity=50.0, Acceleration=10.0, Jerk=0.0)   # Jerk 0: trapezoid
            if move.Busy and not started:
                started.append(ctl.time)

        ctl.run_until(lambda: bool(started), timeout=2.0)
        ctl.run(1.0)
        velocities.append(ax.Velocity)
    assert velocities[0] == pytest.approx(velocities[1], abs=1e-9)
    assert 9.0 < velocities[1] < 11.5
