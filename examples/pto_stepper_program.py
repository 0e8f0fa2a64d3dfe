"""User program for pto_stepper.toml: a stepper homes on its reference cam, then shuttles between two stations.

Run it with:  plcmotion run examples/pto_stepper.toml examples/pto_stepper_program.py --duration 20 --plot shuttle.png
"""
from plcmotion.s7_1200 import MC_Home, MC_MoveAbsolute, MC_Power, MC_Reset


def setup(ctl):
    axis = ctl.axes["Shuttle"]
    power, reset, home = MC_Power(), MC_Reset(), MC_Home()
    to_a, to_b = MC_MoveAbsolute(), MC_MoveAbsolute()
    state = {"step": "home"}

    @ctl.program
    def main():
        power(Axis=axis, Enable=True)
        reset(Axis=axis, Execute=axis.StatusBits.Error and not reset.Done)
        step = state["step"]
        home(Axis=axis, Execute=step == "home" and power.Status, Mode=3, Position=0.0)   # active homing
        to_b(Axis=axis, Execute=step == "to_b", Position=180.0, Velocity=120.0)
        to_a(Axis=axis, Execute=step == "to_a", Position=20.0, Velocity=120.0)
        if step == "home" and home.Done:
            state["step"] = "to_b"
        elif step == "to_b" and to_b.Done:
            state["step"] = "to_a"
        elif step == "to_a" and to_a.Done:
            state["step"] = "to_b"
