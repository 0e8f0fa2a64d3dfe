"""MC_MoveSpeed (command 8): velocity control without position control, ramps I216 / I217, cyclic takeover."""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.pilz import MC_MoveSpeed, trace_signals
from plcmotion.trace import Trace

ctl = Controller(family="Pilz", servo_cycle=0.001, app_cycle=0.001)
axis = ctl.add_positioning_axis("X")
axis.enable()
ctl.run_until(lambda: axis.status.I89 == 2)     # the drive is enabled: standstill
trace = Trace(ctl, trace_signals(axis)).start()     # set/actual values, status timeline
speed = MC_MoveSpeed(Axis=axis, Velocity=100.0, Acceleration=1000.0, Deceleration=1000.0, Jerk=100000.0)
ctl.program(lambda: speed(Execute=True))
ctl.run_until(lambda: speed.InVelocity, timeout=2.0)
speed.Velocity = 150.0                    # taken over while the command runs (I119 = 0)
ctl.run(0.2)
print(f"set velocity {axis.status.E07}, position control {axis.position_controlled}")
assert axis.status.E07 == 150.0 and not axis.position_controlled

trace.stop()
out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[1] / "img"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_MoveSpeed.png", title="MC_MoveSpeed (command 8)")
print(f"wrote {out / 'MC_MoveSpeed.png'}")
