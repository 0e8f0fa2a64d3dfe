"""MC_MoveAbsolute: two moves one after the other, then a move overridden by another one.

The axis is homed first (MC_Home Mode 0: Position := 0.0); MC_MoveAbsolute needs a homed axis.
1. move_1 to 100.0; when it is Done, move_2 starts to 150.0: the axis stands still briefly in between.
2. move_3 to 300.0 at 50.0; at 8.0 s move_4 to 400.0 at 100.0 takes over: move_3 shows
   CommandAborted and the axis goes on to 400.0 at the new velocity without stopping.
The manual's chart (§11.1.5.2) with positions and velocities / 10 and Acceleration = Deceleration = 100.
Writes docs/img/MC_MoveAbsolute.png (or into the directory named by PLCMOTION_DOCS_IMG).
"""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7_1200 import MC_Home, MC_MoveAbsolute, MC_Power
from plcmotion.trace import Trace

ctl = Controller(servo_cycle=0.001, app_cycle=0.004)
axis = ctl.add_positioning_axis("Axis_1", {
    "Actor": {"Type": 1},
    "DynamicLimits": {"MaxVelocity": 200.0},
    "DynamicDefaults": {"Acceleration": 100.0, "Deceleration": 100.0, "Jerk": 0.0},
    "PositioningMonitoring": {"Window": 0.1, "MinDwellTime": 0.05},
})
power = MC_Power(Axis=axis, Enable=True)
home = MC_Home(Axis=axis, Mode=0, Position=0.0)
move_1 = MC_MoveAbsolute(Axis=axis, Position=100.0, Velocity=50.0)
move_2 = MC_MoveAbsolute(Axis=axis, Position=150.0, Velocity=50.0)
move_3 = MC_MoveAbsolute(Axis=axis, Position=300.0, Velocity=50.0)
move_4 = MC_MoveAbsolute(Axis=axis, Position=400.0, Velocity=100.0)


@ctl.program
def main():
    t = ctl.time
    power()
    home(Execute=power.Status)
    move_1(Execute=home.Done and t < 5.0)
    move_2(Execute=move_1.Done)                      # starts on the Done of the first move
    move_3(Execute=6.0 <= t < 9.0)
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
    "StatusBits.PositioningCommand": lambda: axis.StatusBits.PositioningCommand,
}).start()
ctl.run(11.0)
trace.stop()
assert move_4.Done and abs(axis.Position - 400.0) < 1e-9

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[1] / "img"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_MoveAbsolute.png", title="MC_MoveAbsolute: sequential moves, then an override without stop")
print(f"wrote {out / 'MC_MoveAbsolute.png'}")
