"""User program for analog_drive.toml: enable, home on the cam, position, run at constant speed, stop.

The slide starts below the homing cam, so active homing (MC_Home Mode 3) searches downwards, reaches
the low hardware limit switch, turns back (Homing.AutoReversal), finds the cam and references on its
lower end.  Then two positioning moves, a constant-velocity run and a halt.

Run it with:  plcmotion run examples/analog_drive.toml examples/analog_drive_program.py --duration 15 --plot slide.png
"""
from plcmotion.s7_1200 import MC_Halt, MC_Home, MC_MoveAbsolute, MC_MoveRelative, MC_MoveVelocity, MC_Power, MC_Reset


def setup(ctl):
    axis = ctl.axes["Slide"]
    power, reset, home = MC_Power(), MC_Reset(), MC_Home()
    to_station, back = MC_MoveAbsolute(), MC_MoveRelative()
    run, halt = MC_MoveVelocity(), MC_Halt()
    state = {"step": "home", "t0": 0.0}

    @ctl.program
    def main():
        now = ctl.time
        step = state["step"]
        power(Axis=axis, Enable=True, StartMode=1, StopMode=0)
        reset(Axis=axis, Execute=axis.StatusBits.Error and not reset.Done)
        # the home position is the lower end of the cam; Position 0.0 is assigned there
        home(Axis=axis, Execute=step == "home" and power.Status, Mode=3, Position=0.0)
        to_station(Axis=axis, Execute=step == "to_station", Position=400.0, Velocity=300.0)
        back(Axis=axis, Execute=step == "back", Distance=-150.0, Velocity=100.0)
        run(Axis=axis, Execute=step == "run", Velocity=-200.0)
        halt(Axis=axis, Execute=step == "halt")
        if step == "home" and home.Done:
            state["step"] = "to_station"
        elif step == "to_station" and to_station.Done:
            state["step"] = "back"
        elif step == "back" and back.Done:
            state["step"], state["t0"] = "run", now
        elif step == "run" and run.InVelocity and now - state["t0"] > 1.0:
            state["step"] = "halt"
        elif step == "halt" and halt.Done:
            state["step"] = "idle"
