"""MC_MoveVelocity (command 4): endless motion with position control; InVelocity = I92 = I85 and I183."""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.pilz import MC_MoveVelocity, trace_signals
from plcmotion.trace import Trace

ctl = Controller(family="Pilz", servo_cycle=0.001, app_cycle=0.001)
axis = ctl.add_positioning_axis("X")
axis.enable()
ctl.run_until(lambda: axis.status.I89 == 2)     # the drive is enabled: standstill
trace = Trace(ctl, trace_signals(axis)).start()     # set/actual values, status timeline
vel = MC_MoveVelocity(Axis=axis, Velocity=300.0, Acceleration=2000.0, Deceleration=2000.0, Jerk=100000.0)
ctl.program(lambda: vel(Execute=True))
ctl.run_until(lambda: vel.InVelocity, timeout=2.0)
print(f"InVelocity at {ctl.time:.3f} s, set velocity {axis.status.E07}, I89 = {axis.status.I89}")
assert axis.status.E07 == 300.0 and axis.status.I89 == 4 and axis.status.I183

trace.stop()
out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[1] / "img"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_MoveVelocity.png", title="MC_MoveVelocity (command 4)")
print(f"wrote {out / 'MC_MoveVelocity.png'}")
