"""MC_TorqueControl (command 9): the set torque accelerates the load model; E65/E66 limit it, I10 the speed."""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.pilz import MC_TorqueControl, trace_signals
from plcmotion.trace import Trace

ctl = Controller(family="Pilz", servo_cycle=0.001, app_cycle=0.001)
axis = ctl.add_positioning_axis("X", {"Drive.Inertia": 0.01, "E65": 2.0, "I10": 200.0})
axis.enable()
ctl.run_until(lambda: axis.status.I89 == 2)     # the drive is enabled: standstill
trace = Trace(ctl, trace_signals(axis)).start()     # set/actual values, status timeline
torque = MC_TorqueControl(Axis=axis, Torque=5.0)
ctl.program(lambda: torque(Execute=True))
ctl.run(0.5)
print(f"torque {axis.status.E02} (I194 = {axis.status.I194}), velocity {axis.status.E07:.1f}")
assert axis.status.E02 == 2.0 and axis.status.I194 and axis.status.E07 <= 200.0 and torque.InTorque

trace.stop()
out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[1] / "img"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_TorqueControl.png", title="MC_TorqueControl (command 9)")
print(f"wrote {out / 'MC_TorqueControl.png'}")
