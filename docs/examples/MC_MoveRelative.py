"""MC_MoveRelative: two relative moves one after the other, then a move overridden by another one.

1. move_1 by 100.0; when it is Done, move_2 by 50.0 more (150.0 from the start in total).
2. move_3 by 200.0 from 6.0 s; at 8.0 s move_4 by 50.0 at 100.0 takes over: move_3 shows
   CommandAborted and the axis stops 50.0 beyond the position it had when move_4 started.
The manual's chart (§11.1.6.2) with distances and velocities / 10 and Acceleration = Deceleration = 100.
No homing is needed.  Writes docs/img/MC_MoveRelative.png (or into PLCMOTION_DOCS_IMG).
"""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7_1200 import MC_MoveRelative, MC_Power
from plcmotion.trace import Trace

ctl = Controller(servo_cycle=0.001, app_cycle=0.004)
axis = ctl.add_positioning_axis("Axis_1", {
    "Actor": {"Type": 1},
    "DynamicLimits": {"MaxVelocity": 200.0},
    "DynamicDefaults": {"Acceleration": 100.0, "Deceleration": 100.0, "Jerk": 0.0},
    "PositioningMonitoring": {"Window": 0.1, "MinDwellTime": 0.05},
})
power = MC_Power(Axis=axis, Enable=True)
move_1 = MC_MoveRelative(Axis=axis, Distance=100.0, Velocity=50.0)
move_2 = MC_MoveRelative(Axis=axis, Distance=50.0, Velocity=50.0)
move_3 = MC_MoveRelative(Axis=axis, Distance=200.0, Velocity=50.0)
move_4 = MC_MoveRelative(Axis=axis, Distance=50.0, Velocity=100.0)
start_4 = []                                         # Position when move_4 started


@ctl.program
def main():
    t = ctl.time
    power()
    move_1(Execute=power.Status and t < 5.0)
    move_2(Execute=move_1.Done)                      # starts on the Done of the first move
    move_3(Execute=6.0 <= t < 9.0)
    if 8.0 <= t and not start_4:
        start_4.append(axis.Position)
    move_4(Execute=8.0 <= t)


trace = Trace(ctl, {
    "Axis_1.Position": "Axis_1.Position",
    "Axis_1.Velocity": "Axis_1.Velocity",
    "move_1.Busy": lambda: move_1.Busy,
    "move_1.Done": lambda: move_1.Done,
    "move_2.Busy": lambda: move_2.Busy,
    "move_2.Done": lambda: move_2.Done,
    "move_3.Busy": lambda: move_3.Busy,
    "move_3.CommandAborted": lambda: move_3.CommandAborted,
    "move_4.Busy": lambda: move_4.Busy,
    "move_4.Done": lambda: move_4.Done,
}).start()
ctl.run(10.0)
trace.stop()
assert move_4.Done and abs(axis.Position - (start_4[0] + 50.0)) < 1e-9

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[1] / "img"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_MoveRelative.png", title="MC_MoveRelative: sequential moves, then an override")
print(f"wrote {out / 'MC_MoveRelative.png'}")
