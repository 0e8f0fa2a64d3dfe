"""MC_MoveAdditive: correct the target of a running positioning.

move positions the axis at 200 at 50.  At 2 s, while it runs, additive adds 50 to its *target* (not to the
position where the correction starts): move shows CommandAborted, the axis goes on to 250 without stopping
and additive is Done there.  At 8 s a second MC_MoveAdditive at standstill moves by -30 like MC_MoveRelative.
S7-Technology V4.1 §6.2.8.  Writes docs/img/s7t/MC_MoveAdditive.png (or into the directory named by
PLCMOTION_DOCS_IMG).
"""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7t import MC_MoveAbsolute, MC_MoveAdditive, MC_Power
from plcmotion.trace import Trace

ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
axis = ctl.add_positioning_axis("Axis_1", {
    "DBNumber": 10,
    "TypeOfAxis.Homing.referencingNecessary": 0,
    "userdefaultdynamics": {"positiveaccel": 50.0, "negativeaccel": 50.0, "positiveaccelstartjerk": 500.0},
})
power = MC_Power(Axis=axis, Enable=True)
move = MC_MoveAbsolute(Axis=axis, Position=200.0, Velocity=50.0)
additive = MC_MoveAdditive(Axis=axis, Distance=50.0, Velocity=50.0)
back = MC_MoveAdditive(Axis=axis, Distance=-30.0, Velocity=30.0)


@ctl.program
def main():
    t = ctl.time
    power()
    move(Execute=power.Status)
    additive(Execute=t >= 2.0)
    back(Execute=t >= 8.0)


trace = Trace(ctl, {
    "Axis_1.CommandPosition": "Axis_1.CommandPosition",
    "Axis_1.ActualPosition": "Axis_1.ActualPosition",
    "Axis_1.CommandVelocity": "Axis_1.CommandVelocity",
    "Axis_1.TargetPosition": "Axis_1.TargetPosition",
    "move.Busy": lambda: move.Busy,
    "move.CommandAborted": lambda: move.CommandAborted,
    "additive.Busy": lambda: additive.Busy,
    "additive.Done": lambda: additive.Done,
    "back.Done": lambda: back.Done,
}).start()
ctl.run(11.0)
trace.stop()
assert move.CommandAborted and additive.Done and back.Done
assert abs(axis.db.ActualPosition - 220.0) < 0.1

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[2] / "img" / "s7t"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_MoveAdditive.png", title="MC_MoveAdditive: target correction of a running positioning")
print(f"wrote {out / 'MC_MoveAdditive.png'}")
