"""MC_MoveAbsolute: append (Mode 1), overlay (Mode 2) and override (Mode 0) on a positioning axis.

1. Append: move_1 to 100 at 50; move_2 to 150 starts in the same cycle with Mode 1: the axis stops at 100
   (move_1 Done), then goes on to 150.
2. Overlay: move_3 to 250 at 50; move_4 to 300 at 30 with Mode 2: the axis arrives at 250 at 30 without
   stopping (move_3 Done) and goes on at 30.
3. Override: move_5 to 400 at 50; at 7 s move_6 to 450 at 80 takes over (move_5 CommandAborted).
The sequences of S7-Technology V4.1 §6.2.6, scaled by 1/10.  Writes docs/img/s7t/MC_MoveAbsolute.png (or
into the directory named by PLCMOTION_DOCS_IMG).
"""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7t import MC_MoveAbsolute, MC_Power
from plcmotion.trace import Trace

ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
axis = ctl.add_positioning_axis("Axis_1", {
    "DBNumber": 10,
    "TypeOfAxis.Homing.referencingNecessary": 0,     # absolute moves without homing
    "userdefaultdynamics": {"positiveaccel": 50.0, "negativeaccel": 50.0, "positiveaccelstartjerk": 0.0},
})
power = MC_Power(Axis=10, Enable=True)               # Axis: the number of the technology DB
move_1 = MC_MoveAbsolute(Axis=10, Position=100.0, Velocity=50.0)
move_2 = MC_MoveAbsolute(Axis=10, Position=150.0, Velocity=50.0, Mode=1)
move_3 = MC_MoveAbsolute(Axis=10, Position=250.0, Velocity=50.0)
move_4 = MC_MoveAbsolute(Axis=10, Position=300.0, Velocity=30.0, Mode=2)
move_5 = MC_MoveAbsolute(Axis=10, Position=400.0, Velocity=50.0)
move_6 = MC_MoveAbsolute(Axis=10, Position=450.0, Velocity=80.0)


@ctl.program
def main():
    t = ctl.time
    power()
    move_1(Execute=power.Status)
    move_2(Execute=power.Status)                     # appended in the same cycle
    move_3(Execute=move_2.Done)
    move_4(Execute=move_2.Done)                      # overlaid onto move_3
    move_5(Execute=move_4.Done)
    move_6(Execute=t >= 11.0)


trace = Trace(ctl, {
    "Axis_1.CommandPosition": "Axis_1.CommandPosition",
    "Axis_1.ActualPosition": "Axis_1.ActualPosition",
    "Axis_1.CommandVelocity": "Axis_1.CommandVelocity",
    "move_1.Done": lambda: move_1.Done,
    "move_2.Busy": lambda: move_2.Busy,
    "move_2.Done": lambda: move_2.Done,
    "move_3.Done": lambda: move_3.Done,
    "move_4.Done": lambda: move_4.Done,
    "move_5.CommandAborted": lambda: move_5.CommandAborted,
    "move_6.Done": lambda: move_6.Done,
}).start()
ctl.run(15.0)
trace.stop()
assert move_1.Done and move_3.Done and move_5.CommandAborted and move_6.Done
assert abs(axis.db.ActualPosition - 450.0) < 0.1

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[2] / "img" / "s7t"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_MoveAbsolute.png", title="MC_MoveAbsolute: append (Mode 1), overlay (Mode 2), override (Mode 0)")
print(f"wrote {out / 'MC_MoveAbsolute.png'}")
