"""User program for profidrive_servo.toml: jog, home on the proximity switch and the encoder zero mark, then
index in steps, then a velocity run and a halt.

Run it with:  plcmotion run examples/profidrive_servo.toml examples/profidrive_servo_program.py --duration 12 --plot servo.png
"""
from plcmotion.s7_1200 import MC_Halt, MC_Home, MC_MoveJog, MC_MoveRelative, MC_MoveVelocity, MC_Power


def setup(ctl):
    axis = ctl.axes["Spindle"]
    power, home, jog = MC_Power(), MC_Home(), MC_MoveJog()
    index, run, halt = MC_MoveRelative(), MC_MoveVelocity(), MC_Halt()
    state = {"step": "jog", "t0": 0.0, "count": 0}

    @ctl.program
    def main():
        now = ctl.time
        power(Axis=axis, Enable=True, StartMode=1)
        step = state["step"]
        jog(Axis=axis, JogForward=step == "jog" and power.Status and now - state["t0"] < 1.0, Velocity=50.0)
        home(Axis=axis, Execute=step == "home", Mode=3, Position=0.0)   # proximity switch + zero mark
        index(Axis=axis, Execute=step == "index", Distance=90.0, Velocity=300.0)
        run(Axis=axis, Execute=step == "run", Velocity=200.0)
        halt(Axis=axis, Execute=step == "halt")
        if step == "jog" and now - state["t0"] >= 1.0 and not jog.Busy:
            state["step"] = "home"
        elif step == "home" and home.Done:
            state["step"] = "index"
        elif step == "index" and index.Done:
            state["count"] += 1
            state["step"] = "pause" if state["count"] < 4 else "run"
            state["t0"] = now
        elif step == "pause" and now - state["t0"] > 0.2:
            state["step"] = "index"
        elif step == "run" and run.InVelocity and now - state["t0"] > 2.0:
            state["step"] = "halt"
        elif step == "halt" and halt.Done:
            state["step"] = "idle"
