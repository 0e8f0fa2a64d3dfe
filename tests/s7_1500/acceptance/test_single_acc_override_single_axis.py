"""§9.3.1 override response, part 1 (homing and motion jobs), cell by cell on an S7-1500 positioning axis
with a (simulated) PROFIdrive drive, and part 2 rows for the jobs the single axis can run.

A = the running job ends with CommandAborted = TRUE; '-' = the running job continues (the new job may also
be rejected, e.g. while MC_Stop holds the axis)."""
import pytest

from plcmotion.s7_1500 import (MC_Halt, MC_Home, MC_MoveAbsolute, MC_MoveJog, MC_MoveRelative, MC_MoveSuperimposed,
                               MC_MoveVelocity, MC_Stop)

from _single_h import AxisRig

HOMING = {"Sensor": {"Sensor[1]": {"ActiveHoming": {"Mode": 2, "DigitalInputAddress": "I0.0"},
                                   "PassiveHoming": {"Mode": 2, "DigitalInputAddress": "I0.0"}}},
          "Plant": {"HomingSwitchPosition": 1.0e6},
          "FollowingError": {"EnableMonitoring": False},
          "DynamicLimits": {"MaxDeceleration": 300.0},
          "DynamicDefaults": {"EmergencyDeceleration": 300.0}}

# columns of §9.3.1
P_HOME, A_HOME, MOTION, STOP, SUP = "home 2/8/10", "home 3/5", "halt/move/jog", "stop", "superimposed"
# rows: new job -> {column: aborted?}
TABLE = {
    "home3": {P_HOME: True, A_HOME: True, MOTION: True, STOP: False, SUP: True},
    "home5": {P_HOME: True, A_HOME: True, MOTION: True, STOP: False, SUP: True},
    "home9": {P_HOME: True, A_HOME: False, MOTION: False, STOP: False, SUP: False},
    "halt": {P_HOME: False, A_HOME: True, MOTION: True, STOP: False, SUP: True},
    "absolute": {P_HOME: False, A_HOME: True, MOTION: True, STOP: False, SUP: True},
    "relative": {P_HOME: False, A_HOME: True, MOTION: True, STOP: False, SUP: True},
    "velocity": {P_HOME: False, A_HOME: True, MOTION: True, STOP: False, SUP: True},
    "jog": {P_HOME: False, A_HOME: True, MOTION: True, STOP: False, SUP: True},
    "superimposed": {P_HOME: False, A_HOME: False, MOTION: False, STOP: False, SUP: True},
    "stop": {P_HOME: True, A_HOME: True, MOTION: True, STOP: True, SUP: True},
}
RUNNING = {"home8": P_HOME, "home3": A_HOME, "velocity": MOTION, "absolute": MOTION, "jog": MOTION, "halt": MOTION,
           "stop": STOP, "superimposed": SUP}


def start_running(r, kind):
    if kind == "home8":
        fb = MC_Home()
        r.call(fb, Execute=True, Mode=8)
    elif kind == "home3":
        fb = MC_Home()
        r.call(fb, Execute=True, Mode=3)
    elif kind == "velocity":
        fb = MC_MoveVelocity()
        r.call(fb, Execute=True, Velocity=30.0)
    elif kind == "absolute":
        fb = MC_MoveAbsolute()
        r.call(fb, Execute=True, Position=5000.0, Velocity=30.0)
    elif kind == "jog":
        fb = MC_MoveJog()
        r.call(fb, JogForward=True, JogBackward=False, Velocity=30.0)
    elif kind == "halt":
        pre = MC_MoveVelocity()
        r.call(pre, Execute=True, Velocity=200.0)
        r.run_until(lambda: pre.InVelocity, 3)
        fb = MC_Halt()
        r.call(fb, Execute=True, Deceleration=20.0)
    elif kind == "stop":
        pre = MC_MoveVelocity()
        r.call(pre, Execute=True, Velocity=250.0)
        r.run_until(lambda: pre.InVelocity, 3)
        fb = MC_Stop()
        r.call(fb, Execute=True, Mode=2)
    elif kind == "superimposed":
        fb = MC_MoveSuperimposed()
        r.call(fb, Execute=True, Distance=1.0e4, VelocityDiff=20.0)
    r.step(3)
    assert fb.Busy, kind
    return fb


def start_new(r, kind):
    m = {"home3": (MC_Home, dict(Mode=3)), "home5": (MC_Home, dict(Mode=5)), "home9": (MC_Home, dict(Mode=9)),
         "halt": (MC_Halt, {}), "absolute": (MC_MoveAbsolute, dict(Position=-50.0)),
         "relative": (MC_MoveRelative, dict(Distance=-50.0)), "velocity": (MC_MoveVelocity, dict(Velocity=-10.0)),
         "superimposed": (MC_MoveSuperimposed, dict(Distance=1.0)), "stop": (MC_Stop, dict(Mode=0))}
    if kind == "jog":
        fb = MC_MoveJog()
        r.call(fb, JogForward=False, JogBackward=True, Velocity=10.0)
        return fb
    cls, inputs = m[kind]
    fb = cls()
    r.call(fb, Execute=True, **inputs)
    return fb


@pytest.mark.parametrize("new", list(TABLE))
@pytest.mark.parametrize("running", list(RUNNING))
def test_s7_1500_override_s9_3_1(running, new):
    r = AxisRig(HOMING, virtual=False)
    r.ctl.inputs["I0.0"] = False
    if running != "home3":
        r.home(0.0)                                 # MC_MoveAbsolute needs a homed axis
    run = start_running(r, running)
    fb = start_new(r, new)
    r.step(4)
    expect = TABLE[new][RUNNING[running]]
    if expect and new == "absolute" and running == "home3":
        pytest.skip("MC_MoveAbsolute is rejected on the axis that active homing has un-homed")
    assert run.CommandAborted == expect, (f"running {running} / new {new}: new Error={fb.Error} "
                                          f"16#{fb.ErrorID:04X}")
    if not expect:
        assert run.Busy or run.Done, f"running {running} ended otherwise"


@pytest.mark.parametrize("mode", [3, 5])
@pytest.mark.parametrize("running", ["velocity", "absolute", "jog", "halt", "superimposed", "stop"])
def test_s7_1500_override_active_homing_row_on_a_virtual_axis_s9_3_1(running, mode):
    """The same row 'MC_Home Mode 3, 5' on a virtual axis (homing completes at once there). A cell: the running
    job is aborted AND its motion ends (no setpoint motion left without a job); '-' (MC_Stop): MC_Stop goes on
    and the lock rejects the homing job (decisions #24)."""
    r = AxisRig({"DynamicLimits": {"MaxDeceleration": 300.0}})
    r.home(0.0)
    run = start_running(r, running)
    h = MC_Home()
    r.call(h, Execute=True, Mode=mode)
    r.step(4)
    if running == "stop":
        assert not run.CommandAborted and h.Error
        return
    assert run.CommandAborted
    r.run(3.0)
    assert r.axis.Velocity == 0.0 and r.axis.StatusWord.Done


@pytest.mark.parametrize("virtual", [True, False], ids=["virtual-slave", "drive-slave"])
def test_s7_1500_active_homing_aborts_gear_in_s9_3_2(virtual):
    """§9.3.2 row 'MC_Home Mode 3, 5', column MC_GearIn: A."""
    from plcmotion import Controller
    from plcmotion.s7_1500 import MC_GearIn, MC_Power
    ctl = Controller(family="S7-1500T")
    master = ctl.add_positioning_axis("M", {"VirtualAxis": {"Mode": 1}})
    scfg = {"VirtualAxis": {"Mode": 1}} if virtual else {k: v for k, v in HOMING.items()
                                                        if k in ("Sensor", "Plant", "FollowingError")}
    slave = ctl.add_synchronous_axis("S", scfg, leading_values=["M"])
    pm, ps, mv, gi, h = MC_Power(), MC_Power(), MC_MoveVelocity(), MC_GearIn(), MC_Home()
    ex = {"home": False}

    @ctl.program
    def main():
        pm(Axis=master, Enable=True)
        ps(Axis=slave, Enable=True)
        mv(Axis=master, Execute=pm.Status, Velocity=20.0)
        gi(Master=master, Slave=slave, Execute=ps.Status and pm.Status, RatioNumerator=1, RatioDenominator=1)
        h(Axis=slave, Execute=ex["home"], Mode=3)
    ctl.run_until(lambda: gi.InGear, timeout=3.0)
    ex["home"] = True
    ctl.run(0.05)
    assert not h.Error
    assert gi.CommandAborted and not slave.StatusWord.Synchronous
