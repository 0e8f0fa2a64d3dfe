"""MC_CyclicPosition (command 10): cyclic set positions 0 ... I01 on an endless axis; turns counted inside."""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.pilz import MC_CyclicPosition, trace_signals
from plcmotion.trace import Trace

ctl = Controller(family="Pilz", servo_cycle=0.001, app_cycle=0.002)
axis = ctl.add_positioning_axis("X", {"I00": 1, "I01": 360.0, "I10": 2000.0})
axis.enable()
ctl.run_until(lambda: axis.status.I89 == 2)     # the drive is enabled: standstill
trace = Trace(ctl, trace_signals(axis)).start()     # set/actual values, status timeline
cyc = MC_CyclicPosition(Axis=axis)


@ctl.program
def program():
    cyc(Execute=True, Position=(720.0 * ctl.time) % 360.0)     # 2 turns per second, wrapped


ctl.run(1.0)
print(f"unwrapped set position {axis.status.I96:.1f}, velocity {axis.status.E07:.1f}")
assert axis.status.I96 > 700.0 and abs(axis.status.E07 - 720.0) < 1.0

trace.stop()
out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[1] / "img"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_CyclicPosition.png", title="MC_CyclicPosition (command 10)")
print(f"wrote {out / 'MC_CyclicPosition.png'}")
