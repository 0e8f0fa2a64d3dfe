"""MC_Power: enable an axis, run it, disable it with two emergency programs.

power enables the axis (Enable TRUE at 0.1 s), run moves it at 100.  At 2 s Enable falls with StopMode 0
(DefaultStop): the axis brakes with its emergency deceleration, all commands end (run CommandAborted), then
the drive is disabled and Status falls.  At 3.5 s the axis is enabled again and run again; at 5.5 s it is
disabled with StopMode 2 (TimeStop): it stops within userdefaultdynamics.stoptime = 1 s.
S7-Technology V4.1 §6.2.1.  Writes docs/img/s7t/MC_Power.png (or into the directory named by
PLCMOTION_DOCS_IMG).
"""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7t import MC_MoveVelocity, MC_Power
from plcmotion.trace import Trace

ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
axis = ctl.add_positioning_axis("Axis_1", {
    "DBNumber": 10,
    "TypeOfAxis.EmergencyRampGenerator.maxDeceleration": 400.0,
    "userdefaultdynamics": {"positiveaccel": 200.0, "negativeaccel": 200.0, "positiveaccelstartjerk": 0.0,
                            "stoptime": 1.0},
})
power = MC_Power(Axis=axis)
run = MC_MoveVelocity(Axis=axis, Velocity=100.0)


@ctl.program
def main():
    t = ctl.time
    enable = 0.1 <= t < 2.0 or 3.5 <= t < 5.5
    power(Enable=enable, StopMode=0 if t < 3.0 else 2)
    run(Execute=power.Status)


trace = Trace(ctl, {
    "Axis_1.CommandVelocity": "Axis_1.CommandVelocity",
    "Axis_1.ActualVelocity": "Axis_1.ActualVelocity",
    "Axis_1.Statusword.DriveEnabled": "Axis_1.Statusword.DriveEnabled",
    "Axis_1.Statusword.FollowUpControl": "Axis_1.Statusword.FollowUpControl",
    "power.Enable": lambda: power.Enable,
    "power.Status": lambda: power.Status,
    "power.Busy": lambda: power.Busy,
    "run.InVelocity": lambda: run.InVelocity,
    "run.CommandAborted": lambda: run.CommandAborted,
}).start()
ctl.run(7.5)
trace.stop()
assert not power.Status and not power.Error and axis.db.CommandVelocity == 0.0

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[2] / "img" / "s7t"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_Power.png", title="MC_Power: enable, disable with DefaultStop (0) and TimeStop (2)")
print(f"wrote {out / 'MC_Power.png'}")
