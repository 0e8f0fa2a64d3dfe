"""MC_MoveSuperImposed: a print-mark correction on a web that keeps running.

run moves the web axis at 50 (MC_MoveVelocity).  At 2 s a superimposed positioning by 40 (VelocityDiff 20)
runs on top of it: the basic motion goes on (run stays InVelocity, it is not aborted), the velocity rises by
up to 20 while the correction runs, and the web ends 40 ahead of where it would be.  At 6 s a correction by
-20 runs the other way.  S7-Technology V4.1 §6.2.9.  Writes docs/img/s7t/MC_MoveSuperImposed.png (or into
the directory named by PLCMOTION_DOCS_IMG).
"""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7t import MC_MoveSuperImposed, MC_MoveVelocity, MC_Power
from plcmotion.trace import Trace

ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
axis = ctl.add_positioning_axis("Web", {
    "DBNumber": 10,
    "userdefaultdynamics": {"positiveaccel": 50.0, "negativeaccel": 50.0, "positiveaccelstartjerk": 500.0},
})
power = MC_Power(Axis=axis, Enable=True)
run = MC_MoveVelocity(Axis=axis, Velocity=50.0)
ahead = MC_MoveSuperImposed(Axis=axis, Distance=40.0, VelocityDiff=20.0, Acceleration=20.0, Deceleration=20.0)
back = MC_MoveSuperImposed(Axis=axis, Distance=-20.0, VelocityDiff=20.0, Acceleration=20.0, Deceleration=20.0)
shift = {}


@ctl.program
def main():
    t = ctl.time
    power()
    run(Execute=power.Status)
    ahead(Execute=t >= 2.0)
    back(Execute=t >= 6.0)
    if run.InVelocity and "start" not in shift:     # the web at its velocity: position and time
        shift["start"] = (axis.db.CommandPosition, t)


trace = Trace(ctl, {
    "Web.CommandVelocity": "Web.CommandVelocity",
    "Web.ActualVelocity": "Web.ActualVelocity",
    "Web.FollowingError": "Web.FollowingError",
    "Web.Statusword.SuperImposedCommand": "Web.Statusword.SuperImposedCommand",
    "run.InVelocity": lambda: run.InVelocity,
    "ahead.Busy": lambda: ahead.Busy,
    "ahead.Done": lambda: ahead.Done,
    "back.Busy": lambda: back.Busy,
    "back.Done": lambda: back.Done,
}).start()
ctl.run(10.0)
trace.stop()
assert ahead.Done and back.Done and run.InVelocity and not run.CommandAborted
p0, t0 = shift["start"]
assert abs(axis.db.CommandPosition - (p0 + 50.0 * (ctl.time - t0) + 20.0)) < 0.5     # 40 - 20 ahead

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[2] / "img" / "s7t"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_MoveSuperImposed.png", title="MC_MoveSuperImposed: corrections on top of a running motion")
print(f"wrote {out / 'MC_MoveSuperImposed.png'}")
