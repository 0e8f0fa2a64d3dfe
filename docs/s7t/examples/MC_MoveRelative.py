"""MC_MoveRelative: a relative move, an appended one, and an overlaid one that reverses the direction.

1. rel_1 moves by 100 at 50; rel_2 (Mode 1, append) by another 50: the axis stops after 100, then goes on.
2. rel_3 moves by 100 at 50; rel_4 (Mode 2, overlay) by -30 at 30: the direction reverses, so the axis
   reaches the end of rel_3 at velocity 0 (rel_3 Done) and returns 30 without a pause.
S7-Technology V4.1 §6.2.7 (the sequences of §6.2.6 with distances), scaled by 1/10.  Writes
docs/img/s7t/MC_MoveRelative.png (or into the directory named by PLCMOTION_DOCS_IMG).
"""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7t import MC_MoveRelative, MC_Power
from plcmotion.trace import Trace

ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
axis = ctl.add_positioning_axis("Axis_1", {
    "DBNumber": 10,
    "userdefaultdynamics": {"positiveaccel": 50.0, "negativeaccel": 50.0, "positiveaccelstartjerk": 500.0},
})
power = MC_Power(Axis=axis, Enable=True)
rel_1 = MC_MoveRelative(Axis=axis, Distance=100.0, Velocity=50.0)
rel_2 = MC_MoveRelative(Axis=axis, Distance=50.0, Velocity=50.0, Mode=1)
rel_3 = MC_MoveRelative(Axis=axis, Distance=100.0, Velocity=50.0)
rel_4 = MC_MoveRelative(Axis=axis, Distance=-30.0, Velocity=30.0, Mode=2)


@ctl.program
def main():
    power()
    rel_1(Execute=power.Status)
    rel_2(Execute=power.Status)                      # appended: starts when rel_1 is done
    rel_3(Execute=rel_2.Done)
    rel_4(Execute=rel_2.Done)                        # overlaid onto rel_3, reversing


trace = Trace(ctl, {
    "Axis_1.CommandPosition": "Axis_1.CommandPosition",
    "Axis_1.ActualPosition": "Axis_1.ActualPosition",
    "Axis_1.CommandVelocity": "Axis_1.CommandVelocity",
    "Axis_1.FollowingError": "Axis_1.FollowingError",
    "rel_1.Done": lambda: rel_1.Done,
    "rel_2.Busy": lambda: rel_2.Busy,
    "rel_2.Done": lambda: rel_2.Done,
    "rel_3.Done": lambda: rel_3.Done,
    "rel_4.Busy": lambda: rel_4.Busy,
    "rel_4.Done": lambda: rel_4.Done,
}).start()
ctl.run(12.0)
trace.stop()
assert rel_2.Done and rel_3.Done and rel_4.Done
assert abs(axis.db.ActualPosition - 220.0) < 0.1

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[2] / "img" / "s7t"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_MoveRelative.png", title="MC_MoveRelative: append (Mode 1), overlay with reversal (Mode 2)")
print(f"wrote {out / 'MC_MoveRelative.png'}")
