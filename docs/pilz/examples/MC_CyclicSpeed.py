"""MC_CyclicSpeed (command 7): the program sends a velocity every cycle; the drive follows it at once."""
import math
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.pilz import MC_CyclicSpeed, trace_signals
from plcmotion.trace import Trace

ctl = Controller(family="Pilz", servo_cycle=0.001, app_cycle=0.001)
axis = ctl.add_positioning_axis("X")
axis.enable()
ctl.run_until(lambda: axis.status.I89 == 2)     # the drive is enabled: standstill
trace = Trace(ctl, trace_signals(axis)).start()     # set/actual values, status timeline
cyc = MC_CyclicSpeed(Axis=axis)


@ctl.program
def program():
    cyc(Execute=True, Velocity=100.0 * math.sin(2 * math.pi * ctl.time))     # the controller's set values


ctl.run(0.5)
print(f"following: set velocity {axis.status.E07:.2f}, I92 = {axis.status.I92}, I89 = {axis.status.I89}")
assert cyc.Done and axis.status.I89 == 11 and abs(axis.status.E07 - 100.0 * math.sin(2 * math.pi * 0.5)) < 1.0

trace.stop()
out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[1] / "img"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_CyclicSpeed.png", title="MC_CyclicSpeed (command 7)")
print(f"wrote {out / 'MC_CyclicSpeed.png'}")
