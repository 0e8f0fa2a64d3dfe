"""MC_MoveAdditive (command 3): a distance from the last valid set position (Tab. 11: MC_Stop keeps it)."""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.pilz import MC_Home, MC_MoveAdditive, MC_Stop, trace_signals
from plcmotion.trace import Trace

ctl = Controller(family="Pilz", servo_cycle=0.001, app_cycle=0.001)
axis = ctl.add_positioning_axis("X", {"I30": 5})
axis.enable()
ctl.run_until(lambda: axis.status.I89 == 2)     # the drive is enabled: standstill
trace = Trace(ctl, trace_signals(axis)).start()     # set/actual values, status timeline
dyn = dict(Velocity=200.0, Acceleration=2000.0, Deceleration=2000.0, Jerk=100000.0)
home, first, second = MC_Home(Axis=axis), MC_MoveAdditive(Axis=axis, Distance=200.0, **dyn), \
    MC_MoveAdditive(Axis=axis, Distance=200.0, **dyn)
stop = MC_Stop(Axis=axis, Deceleration=2000.0, Jerk=100000.0)
step = {"n": 0}


@ctl.program
def program():
    n = step["n"] = step["n"] + 1
    home(Execute=True)
    first(Execute=n > 3)
    stop(Execute=300 < n < 600)             # interrupts the first one on its way
    second(Execute=n > 650)                 # after MC_Stop released the axis (standstill, Execute low)


ctl.run(3.0)
print(f"stopped on the way, then +200: ends at {axis.status.I96:.3f}")
assert abs(axis.status.I96 - 400.0) < 1e-6

trace.stop()
out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[1] / "img"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_MoveAdditive.png", title="MC_MoveAdditive (command 3)")
print(f"wrote {out / 'MC_MoveAdditive.png'}")
