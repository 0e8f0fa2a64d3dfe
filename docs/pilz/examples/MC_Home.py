"""MC_Home (command 6): CiA 402 method 34 (Tab. 22 N): positive, the first zero pulse becomes I34."""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.pilz import MC_Home, trace_signals
from plcmotion.trace import Trace

ctl = Controller(family="Pilz", servo_cycle=0.001, app_cycle=0.001)
axis = ctl.add_positioning_axis("X", {"A586": 34, "I33": 10.0, "I34": 100.0, "Plant.ZeroMarkDistance": 10.0,
                                      "Plant.ZeroMarkOffset": 3.0})
axis.enable()
ctl.run_until(lambda: axis.status.I89 == 2)     # the drive is enabled: standstill
trace = Trace(ctl, trace_signals(axis)).start()     # set/actual values, status timeline
home = MC_Home(Axis=axis)
states = set()


@ctl.program
def program():
    home(Execute=True)
    states.add(axis.status.I89)


ctl.run_until(lambda: home.Done, timeout=5.0)
print(f"referenced: I86 = {axis.status.I86}, states seen {sorted(states)}, "
      f"machine position {axis.drive.mechanical_position():.3f} -> {ctl.bank.act_p[axis.index]:.3f}")
assert axis.status.I86 and 8 in states and axis.status.I89 == 2

trace.stop()
out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[1] / "img"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_Home.png", title="MC_Home (command 6)")
print(f"wrote {out / 'MC_Home.png'}")
