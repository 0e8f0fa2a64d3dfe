"""MC_Halt: brake a moving PROFIdrive axis to standstill, then be aborted while braking.

1.0 s: MC_Halt aborts the running MC_MoveVelocity and brakes with the configured deceleration (50);
       Done once the axis stands still.
4.0 s: a second halt; while it is still braking, an MC_MoveRelative takes over at 4.4 s and MC_Halt
       shows CommandAborted.  (Acceleration 100, deceleration 50: the manual's chart x 10.)
Writes docs/img/MC_Halt.png (or into the directory named by PLCMOTION_DOCS_IMG).
"""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7_1200 import MC_Halt, MC_MoveRelative, MC_MoveVelocity, MC_Power
from plcmotion.trace import Trace

ctl = Controller(servo_cycle=0.001, app_cycle=0.004)
axis = ctl.add_positioning_axis("Axis_1", {
    "Actor": {"Type": 1},
    "DynamicLimits": {"MaxVelocity": 200.0},
    "DynamicDefaults": {"Acceleration": 100.0, "Deceleration": 50.0, "Jerk": 0.0},
})
power = MC_Power(Axis=axis, Enable=True)
run = MC_MoveVelocity(Axis=axis, Velocity=50.0)
halt = MC_Halt(Axis=axis)
move = MC_MoveRelative(Axis=axis, Distance=20.0, Velocity=50.0)


@ctl.program
def main():
    t = ctl.time
    power()
    run(Execute=power.Status and (t < 1.5 or 3.0 <= t < 3.5))
    halt(Execute=1.0 <= t < 2.5 or 4.0 <= t < 4.8)   # Execute held: Done / CommandAborted stay visible
    move(Execute=4.4 <= t < 5.5)


trace = Trace(ctl, {
    "Axis_1.Position": "Axis_1.Position",
    "Axis_1.Velocity": "Axis_1.Velocity",
    "Axis_1.ActualVelocity": "Axis_1.ActualVelocity",
    "run.Busy": lambda: run.Busy,
    "run.CommandAborted": lambda: run.CommandAborted,
    "halt.Execute": lambda: halt.Execute,
    "halt.Busy": lambda: halt.Busy,
    "halt.Done": lambda: halt.Done,
    "halt.CommandAborted": lambda: halt.CommandAborted,
    "move.Busy": lambda: move.Busy,
    "move.Done": lambda: move.Done,
}).start()
ctl.run(6.0)
trace.stop()
assert not halt.Busy and not move.Busy and axis.StatusBits.StandStill

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[1] / "img"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_Halt.png",
           title="MC_Halt: braking to standstill (Done), overridden while braking (CommandAborted)")
print(f"wrote {out / 'MC_Halt.png'}")
