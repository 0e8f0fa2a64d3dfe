"""MC_MoveAbsolute (command 1): move to 100, Done when I85 = 1 and the actual position stayed in I22 for I87."""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.pilz import MC_Home, MC_MoveAbsolute, trace_signals
from plcmotion.trace import Trace

ctl = Controller(family="Pilz", servo_cycle=0.001, app_cycle=0.001)
axis = ctl.add_positioning_axis("X", {"I30": 5, "I22": 1.0, "I87": 0.05})    # I30 = 5: define home
axis.enable()
ctl.run_until(lambda: axis.status.I89 == 2)     # the drive is enabled: standstill
trace = Trace(ctl, trace_signals(axis)).start()     # set/actual values, status timeline
home = MC_Home(Axis=axis)
move = MC_MoveAbsolute(Axis=axis, Position=100.0, Velocity=200.0, Acceleration=2000.0, Deceleration=2000.0,
                       Jerk=100000.0)
log = []


@ctl.program
def program():
    home(Execute=True)
    move(Execute=home.Done or move.Busy)
    if move.Active or move.Done:                # the status words of *its* command
        log.append((ctl.time, axis.status.I180, axis.status.I85, axis.status.I92))


ctl.run_until(lambda: move.Done, timeout=5.0)
first = {name: next(t for t, *bits in log if bits[k]) for k, name in enumerate(("I180", "I85", "I92"))}
print(f"position {axis.status.I96:.3f}; I180 at {first['I180']:.3f} s, I85 at {first['I85']:.3f} s, "
      f"I92 at {first['I92']:.3f} s")
assert abs(axis.status.I96 - 100.0) < 1e-9 and first["I180"] <= first["I85"] <= first["I92"]

trace.stop()
out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[1] / "img"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_MoveAbsolute.png", title="MC_MoveAbsolute (command 1)")
print(f"wrote {out / 'MC_MoveAbsolute.png'}")
