"""MC_Stop (command 5): stop; I89 = 6 while Execute is TRUE; other commands wait / are denied meanwhile."""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.pilz import MC_MoveVelocity, MC_Stop, trace_signals
from plcmotion.trace import Trace

ctl = Controller(family="Pilz", servo_cycle=0.001, app_cycle=0.001)
axis = ctl.add_positioning_axis("X")
axis.enable()
ctl.run_until(lambda: axis.status.I89 == 2)     # the drive is enabled: standstill
trace = Trace(ctl, trace_signals(axis)).start()     # set/actual values, status timeline
vel = MC_MoveVelocity(Axis=axis, Velocity=200.0, Acceleration=2000.0, Deceleration=2000.0, Jerk=100000.0)
stop = MC_Stop(Axis=axis, Deceleration=1000.0, Jerk=100000.0)
step = {"n": 0}


@ctl.program
def program():
    step["n"] += 1
    vel(Execute=True)
    stop(Execute=step["n"] > 300)


ctl.run_until(lambda: stop.Done, timeout=3.0)
print(f"standstill at {ctl.time:.3f} s; MC_MoveVelocity aborted: {vel.CommandAborted}; I89 = {axis.status.I89}")
assert axis.status.E07 == 0.0 and axis.status.I89 == 6 and axis.status.I92

trace.stop()
out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[1] / "img"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_Stop.png", title="MC_Stop (command 5)")
print(f"wrote {out / 'MC_Stop.png'}")
