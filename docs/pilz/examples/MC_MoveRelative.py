"""MC_MoveRelative (command 2): a distance from the actual position at the start (I80), also while moving."""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.pilz import trace_signals
from plcmotion.trace import Trace

ctl = Controller(family="Pilz", servo_cycle=0.001, app_cycle=0.001)
axis = ctl.add_positioning_axis("X", {"I10": 1000.0})
axis.enable()
ctl.run_until(lambda: axis.status.I89 == 2)     # the drive is enabled: standstill
trace = Trace(ctl, trace_signals(axis)).start()     # set/actual values, status timeline
reg = axis.registers                       # the command register, driven directly
reg.I404, reg.I405, reg.I406, reg.I407 = 500.0, 2000.0, 2000.0, 100000.0
reg.I401, reg.I403, reg.I402 = 2, 1000.0, True
ctl.run_until(lambda: ctl.bank.act_p[axis.index] >= 570.0)
reg.I402 = False
ctl.step()                                 # Execute low for one cycle: the next high is a new edge
reg.I402 = True
ctl.step()
base = axis.status.I80
ctl.run(3.0)
print(f"second MC_MoveRelative started at {base:.3f}, ends at {axis.status.I96:.3f}")
assert abs(axis.status.I96 - (base + 1000.0)) < 1e-6

trace.stop()
out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[1] / "img"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_MoveRelative.png", title="MC_MoveRelative (command 2)")
print(f"wrote {out / 'MC_MoveRelative.png'}")
