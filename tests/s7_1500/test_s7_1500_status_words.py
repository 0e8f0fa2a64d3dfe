"""StatusWord and WarningWord of the S7-1500 axis (S7-1500T V5 §7.1.1 status and error bits, §A.1.37
StatusWord, §A.1.41 WarningWord, §A.1.16 dynamic limits)."""
import pytest

from plcmotion import Controller
from plcmotion.s7_1500 import (MC_Home, MC_MoveAbsolute, MC_MoveJog, MC_MoveRelative, MC_MoveVelocity, MC_Power,
                               MC_Reset, MC_Stop)
from plcmotion.s7_1500 import errors as E

V = {"VirtualAxis": {"Mode": 1}}
DYN = {"DynamicDefaults": {"Velocity": 100.0, "Acceleration": 500.0, "Deceleration": 800.0, "Jerk": 0.0,
                           "EmergencyDeceleration": 4000.0},
       "DynamicLimits": {"MaxVelocity": 1000.0, "Velocity": 600.0, "MaxAcceleration": 5000.0,
                         "MaxDeceleration": 6000.0, "MaxJerk": 0.0}}
#: a drive axis whose passive homing switch is never reached
DRIVE = {"Actor": {"Type": 1}, "Sensor": {"Sensor[1]": {"PassiveHoming": {"Mode": 2, "DigitalInputAddress": "I0.0"}}},
         "Plant": {"HomingSwitchPosition": 1.0e6}}


def axis_rig(params=None, *, enable=True):
    ctl = Controller(family="S7-1500")
    axis = ctl.add_positioning_axis("Axis", {**(params if params is not None else V), **DYN})
    power = MC_Power()
    steps = []
    en = {"on": enable}

    @ctl.program
    def main():
        power(Axis=axis, Enable=en["on"])
        for s in steps:
            s()
    if enable:
        ctl.run_until(lambda: power.Status, timeout=2.0)
    return ctl, axis, steps, power


# --- §A.1.37 names -------------------------------------------------------------------------------------
def test_s7_1500_standstill_is_the_appendix_name_of_bit_7_sA_1_37():
    """§A.1.37 calls bit 7 "Standstill", the §7.1.1 diagnostics "StandStill": both read the bit."""
    ctl, axis, steps, _ = axis_rig()
    sw = axis.StatusWord
    assert sw.Standstill and sw.Standstill == sw.StandStill == sw.X7
    assert axis.tag("StatusWord.Standstill") is True
    assert "Standstill" not in sw.bits() and sw.bits()["StandStill"]          # one name per bit in bits()
    move = MC_MoveVelocity()
    steps.append(lambda: move(Axis=axis, Execute=True, Velocity=50.0))
    ctl.run_until(lambda: move.InVelocity, timeout=2.0)
    assert not axis.StatusWord.Standstill and not axis.StatusWord.X7


# --- X12 ConstantVelocity ------------------------------------------------------------------------------
def test_s7_1500_constant_velocity_is_true_at_standstill_s7_1_1():
    """§7.1.1 "Constant velocity: The axis is moved with constant velocity or is stationary" (X12)."""
    ctl, axis, steps, _ = axis_rig()
    assert axis.StatusWord.StandStill and axis.StatusWord.ConstantVelocity
    move = MC_MoveRelative()
    steps.append(lambda: move(Axis=axis, Execute=True, Distance=50.0))
    ctl.step()
    ctl.step()
    sw = axis.StatusWord
    assert sw.Accelerating and not sw.ConstantVelocity                    # §A.1.37: 0 while accelerating
    ctl.run_until(lambda: axis.StatusWord.ConstantVelocity and axis.Velocity > 0.0, timeout=2.0)
    assert axis.Velocity == pytest.approx(100.0)
    ctl.run_until(lambda: axis.StatusWord.Decelerating, timeout=2.0)
    assert not axis.StatusWord.ConstantVelocity
    ctl.run_until(lambda: move.Done, timeout=2.0)
    ctl.step()
    assert axis.StatusWord.StandStill and axis.StatusWord.ConstantVelocity


# --- X6 Done -------------------------------------------------------------------------------------------
def test_s7_1500_done_is_false_while_mc_stop_brakes_the_axis_sA_1_37():
    """§A.1.37 bit 6 "Done": 0 = a motion job is in progress.  MC_Stop braking the axis is one; once the axis
    stands (MC_Stop.Done, still holding the axis) no motion job is in progress."""
    ctl, axis, steps, _ = axis_rig()
    move, stop = MC_MoveVelocity(), MC_Stop()
    go = {"stop": False}
    steps.append(lambda: move(Axis=axis, Execute=True, Velocity=500.0))
    steps.append(lambda: stop(Axis=axis, Execute=go["stop"], Mode=2))
    ctl.run_until(lambda: move.InVelocity, timeout=2.0)
    go["stop"] = True
    ctl.step()
    assert stop.Busy and axis.Velocity > 0.0 and axis.StatusWord2.StopCommand
    assert not axis.StatusWord.Done
    ctl.run_until(lambda: stop.Done, timeout=2.0)
    assert axis.StatusWord.Done and axis.StatusWord2.StopCommand


def test_s7_1500_done_stays_true_during_passive_homing_s6_1_5_5():
    """Passive homing moves nothing ("MC_Home does not carry out any homing motion", §6.1.5.5), so it is no
    motion job in the sense of §A.1.37 bit 6; HomingCommand (X11) shows it (docs/s7_1500/decisions.md)."""
    ctl, axis, steps, _ = axis_rig(DRIVE)
    ctl.inputs["I0.0"] = False
    home = MC_Home()
    steps.append(lambda: home(Axis=axis, Execute=True, Mode=2))
    ctl.run_until(lambda: home.Busy, timeout=1.0)
    ctl.step()
    assert home.Busy and axis.StatusWord.HomingCommand and axis.StatusWord.Done


# --- X3 CommandNotAccepted -----------------------------------------------------------------------------
def test_s7_1500_absolute_move_of_an_unhomed_axis_is_alarm_321_s7_1_1():
    """§7.1.1 "Job rejected ... (for example, technology object not homed)" is an ErrorWord bit: the CPU's
    technology alarm 321 (ErrorWord.X3, reaction 3 emergency stop ramp), 16#8001 at the instruction and at
    MC_Power, until MC_Reset; after it a relative move runs (docs/s7_1500/decisions.md #84)."""
    ctl, axis, steps, power = axis_rig()
    absolute = MC_MoveAbsolute()
    steps.append(lambda: absolute(Axis=axis, Execute=True, Position=10.0))
    ctl.run_until(lambda: absolute.Error, timeout=1.0)
    ctl.step()
    assert absolute.ErrorID == E.TO_ALARM and power.Error and power.ErrorID == E.TO_ALARM
    assert axis.ErrorWord.CommandNotAccepted and axis.StatusWord.Error and not axis.WarningWord.X3
    assert (axis.ErrorDetail.Number, axis.ErrorDetail.Reaction) == (321, 3)
    steps.clear()
    reset = MC_Reset()
    steps.append(lambda: reset(Axis=axis, Execute=True))
    ctl.run_until(lambda: reset.Done, timeout=1.0)
    assert int(axis.ErrorWord) == 0 and axis.ErrorDetail.Number == 0
    relative = MC_MoveRelative()
    steps.append(lambda: relative(Axis=axis, Execute=True, Distance=5.0))
    ctl.run_until(lambda: relative.Done, timeout=2.0)


@pytest.mark.parametrize("case", ["not_enabled", "stop_lock"])
def test_s7_1500_other_rejections_set_command_not_accepted_s7_1_1(case):
    ctl, axis, steps, _ = axis_rig(enable=case != "not_enabled")
    if case == "stop_lock":
        stop = MC_Stop()
        steps.append(lambda: stop(Axis=axis, Execute=True, Mode=0))
        ctl.run_until(lambda: stop.Done, timeout=1.0)
    move = MC_MoveRelative()
    steps.append(lambda: move(Axis=axis, Execute=True, Distance=5.0))
    ctl.run_until(lambda: move.Error, timeout=1.0)
    assert move.ErrorID == (E.NOT_ENABLED if case == "not_enabled" else E.STOP_ACTIVE)
    assert axis.WarningWord.CommandNotAccepted


def test_s7_1500_an_invalid_input_value_is_not_command_not_accepted_s7_1_1():
    """An invalid input value is an error of the instruction's use, not a requirement of the technology
    object that is not met: X3 stays FALSE."""
    ctl, axis, steps, _ = axis_rig()
    move = MC_MoveRelative()
    steps.append(lambda: move(Axis=axis, Execute=True, Distance=float("nan")))
    ctl.run_until(lambda: move.Error, timeout=1.0)
    assert move.ErrorID == E.parameter("Distance") and not axis.WarningWord.X3


# --- X6 DynamicWarning ---------------------------------------------------------------------------------
@pytest.mark.parametrize("fb, inputs", [(MC_MoveVelocity, {"Execute": True}), (MC_MoveJog, {"JogForward": True})])
@pytest.mark.parametrize("velocity, warned", [(900.0, True), (400.0, False)])
def test_s7_1500_velocity_limit_of_a_velocity_job_warns_sA_1_16(fb, inputs, velocity, warned):
    """§A.1.16: values above the dynamic limits are limited "and a warning is indicated" (WarningWord.X6),
    also when DynamicLimits.Velocity cuts the velocity of MC_MoveVelocity / MC_MoveJog."""
    ctl, axis, steps, _ = axis_rig()
    inst = fb()
    steps.append(lambda: inst(Axis=axis, Velocity=velocity, **inputs))
    ctl.run_until(lambda: inst.InVelocity, timeout=3.0)
    assert axis.Velocity == pytest.approx(min(velocity, 600.0))
    assert bool(axis.WarningWord.DynamicWarning) == warned and not inst.Error and not axis.StatusWord.Error


def test_s7_1500_new_jog_velocity_above_the_limit_warns_sA_1_16():
    ctl, axis, steps, _ = axis_rig()
    jog = MC_MoveJog()
    cmd = {"v": 200.0}
    steps.append(lambda: jog(Axis=axis, JogForward=True, Velocity=cmd["v"]))
    ctl.run_until(lambda: jog.InVelocity, timeout=3.0)
    assert not axis.WarningWord.X6
    cmd["v"] = 800.0
    ctl.step()
    ctl.run_until(lambda: jog.InVelocity, timeout=3.0)
    assert axis.Velocity == pytest.approx(600.0) and axis.WarningWord.X6


def test_s7_1500_alarm_description_names_number_text_and_reaction_s7_1_1():
    """§6.1.5.6 / §7.1.1: the following error alarm is 521 with the reaction "remove enable" (ErrorDetail)."""
    from plcmotion.kernel import faults as F
    from plcmotion.kernel.faults import Reaction
    from plcmotion.s7_1500.technology.tags import alarm_description

    text = alarm_description(F.alarm(F.FOLLOWING_ERROR, "", Reaction.REMOVE_ENABLE))
    assert text == "alarm 521 Following error too large (reaction: remove enable)"
