"""MC_DoNothing (command 0): no status, no motion ID switch - the default of the command selection."""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.pilz import trace_signals
from plcmotion.trace import Trace

ctl = Controller(family="Pilz", servo_cycle=0.001, app_cycle=0.001)
axis = ctl.add_positioning_axis("X", {"I30": 5})
axis.enable()
ctl.run_until(lambda: axis.status.I89 == 2)     # the drive is enabled: standstill
trace = Trace(ctl, trace_signals(axis)).start()     # set/actual values, status timeline
reg = axis.registers
reg.I400, reg.I401, reg.I402 = 7, 6, True          # MC_Home (define home) with motion ID 7
ctl.run(0.01)
before = (axis.status.I82, axis.status.I92, axis.status.I89)
reg.I402 = False
ctl.step()
reg.I400, reg.I401, reg.I402 = 9, 0, True          # MC_DoNothing with motion ID 9
ctl.run(0.01)
print(f"I82, I92, I89 before {before}, after {(axis.status.I82, axis.status.I92, axis.status.I89)}")
assert (axis.status.I82, axis.status.I92, axis.status.I89) == before

trace.stop()
out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[1] / "img"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_DoNothing.png", title="MC_DoNothing (command 0)")
print(f"wrote {out / 'MC_DoNothing.png'}")
