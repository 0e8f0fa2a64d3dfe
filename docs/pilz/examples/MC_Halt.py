"""MC_Halt (command 11): stop; a new command may take over before standstill (no automatic resume)."""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.pilz import MC_Halt, MC_MoveVelocity, trace_signals
from plcmotion.trace import Trace

ctl = Controller(family="Pilz", servo_cycle=0.001, app_cycle=0.001)
axis = ctl.add_positioning_axis("X")
axis.enable()
ctl.run_until(lambda: axis.status.I89 == 2)     # the drive is enabled: standstill
trace = Trace(ctl, trace_signals(axis)).start()     # set/actual values, status timeline
vel = MC_MoveVelocity(Axis=axis, Velocity=200.0, Acceleration=2000.0, Deceleration=2000.0, Jerk=100000.0)
halt = MC_Halt(Axis=axis, Deceleration=500.0, Jerk=100000.0)
back = MC_MoveVelocity(Axis=axis, Velocity=-50.0, Acceleration=2000.0, Deceleration=2000.0, Jerk=100000.0)
step = {"n": 0}


@ctl.program
def program():
    n = step["n"] = step["n"] + 1
    vel(Execute=True)
    halt(Execute=n > 300)
    back(Execute=n > 350)                   # before the halt reached standstill


ctl.run(1.0)
print(f"halt aborted: {halt.CommandAborted}; now {axis.status.E07}")
assert halt.CommandAborted and axis.status.E07 == -50.0

trace.stop()
out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[1] / "img"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_Halt.png", title="MC_Halt (command 11)")
print(f"wrote {out / 'MC_Halt.png'}")
