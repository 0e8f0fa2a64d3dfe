"""MC_Stop: stop the axis and keep it from moving while Execute is TRUE.

run moves the axis at 100.  At 1 s stop (Execute TRUE until 3 s) brakes it to standstill; a MC_MoveAbsolute
started at 2 s, while the stop is held, is refused (Error, ErrorID 16#8045).  stop is Busy until Execute
falls, then Done for one call; afterwards the same kind of command moves the axis again.
S7-Technology V4.1 §6.2.3.  Writes docs/img/s7t/MC_Stop.png (or into the directory named by
PLCMOTION_DOCS_IMG).
"""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7t import MC_MoveAbsolute, MC_MoveVelocity, MC_Power, MC_Stop
from plcmotion.trace import Trace

ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
axis = ctl.add_positioning_axis("Axis_1", {
    "DBNumber": 10,
    "TypeOfAxis.Homing.referencingNecessary": 0,
    "userdefaultdynamics": {"positiveaccel": 200.0, "negativeaccel": 200.0, "positiveaccelstartjerk": 2000.0},
})
power = MC_Power(Axis=axis, Enable=True)
run = MC_MoveVelocity(Axis=axis, Velocity=100.0)
stop = MC_Stop(Axis=axis, Deceleration=150.0)
refused = MC_MoveAbsolute(Axis=axis, Position=0.0)
later = MC_MoveAbsolute(Axis=axis, Position=0.0, Velocity=100.0)
seen = {}


@ctl.program
def main():
    t = ctl.time
    power()
    run(Execute=power.Status)
    stop(Execute=1.0 <= t < 3.0)
    refused(Execute=t >= 2.0)
    later(Execute=t >= 3.5)
    if refused.Error:
        seen["refused"] = refused.ErrorID
    if stop.Done:
        seen["stop_done"] = t


trace = Trace(ctl, {
    "Axis_1.CommandPosition": "Axis_1.CommandPosition",
    "Axis_1.ActualPosition": "Axis_1.ActualPosition",
    "Axis_1.CommandVelocity": "Axis_1.CommandVelocity",
    "Axis_1.Statusword.Stopping": "Axis_1.Statusword.Stopping",
    "run.CommandAborted": lambda: run.CommandAborted,
    "stop.Execute": lambda: stop.Execute,
    "stop.Busy": lambda: stop.Busy,
    "stop.Done": lambda: stop.Done,
    "refused.Error": lambda: refused.Error,
    "later.Done": lambda: later.Done,
}).start()
ctl.run(7.0)
trace.stop()
assert seen["refused"] == 0x8045 and seen["stop_done"] >= 3.0 and later.Done
assert abs(axis.db.ActualPosition) < 0.1

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[2] / "img" / "s7t"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_Stop.png", title="MC_Stop: stop and lock the axis while Execute is TRUE")
print(f"wrote {out / 'MC_Stop.png'}")
