"""MC_Reset: acknowledge an error of the technology DB and go on.

The axis runs at 100 (MC_MoveVelocity).  At 1.5 s its drive reports a fault (simulated with
``axis.inject_fault``): the axis stops, its technology DB shows the error (Statusword.Error, ErrorID) and
MC_Power's Status falls although Enable stays TRUE.  At 3 s MC_Reset acknowledges the error: the technology
DB's ErrorID is cleared, MC_Power enables the axis again, and a new MC_MoveVelocity starts.
S7-Technology V4.1 §6.7.1 (and the MC_Power sequence of §6.2.1).  Writes docs/img/s7t/MC_Reset.png (or into
the directory named by PLCMOTION_DOCS_IMG).
"""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7t import MC_MoveVelocity, MC_Power, MC_Reset
from plcmotion.trace import Trace

ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
axis = ctl.add_positioning_axis("Axis_1", {
    "DBNumber": 10,
    "userdefaultdynamics": {"positiveaccel": 200.0, "negativeaccel": 200.0, "positiveaccelstartjerk": 0.0},
})
power = MC_Power(Axis=10, Enable=True)
run = MC_MoveVelocity(Axis=10, Velocity=100.0)
reset = MC_Reset(Axis=10)
seen = {}


@ctl.program
def main():
    t = ctl.time
    power()
    run(Execute=power.Status)
    reset(Execute=t >= 3.0)
    if axis.db.ErrorID and "error" not in seen:
        seen["error"] = axis.db.ErrorID
    if t >= 1.5 and "fault" not in seen:
        axis.inject_fault("drive")
        seen["fault"] = t


trace = Trace(ctl, {
    "Axis_1.CommandVelocity": "Axis_1.CommandVelocity",
    "Axis_1.ActualVelocity": "Axis_1.ActualVelocity",
    "Axis_1.ErrorID": "Axis_1.ErrorID",
    "Axis_1.Statusword.Error": "Axis_1.Statusword.Error",
    "Axis_1.Statusword.Errorstop": "Axis_1.Statusword.Errorstop",
    "power.Status": lambda: power.Status,
    "run.InVelocity": lambda: run.InVelocity,
    "run.CommandAborted": lambda: run.CommandAborted,
    "reset.Busy": lambda: reset.Busy,
    "reset.Done": lambda: reset.Done,
}).start()
ctl.run(5.0)
trace.stop()
assert seen["error"] and reset.Done and axis.db.ErrorID == 0 and power.Status and run.InVelocity

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[2] / "img" / "s7t"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_Reset.png", title="MC_Reset: acknowledge a drive error, enable again, go on")
print(f"wrote {out / 'MC_Reset.png'}")
