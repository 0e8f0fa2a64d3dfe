"""MC_MoveVelocity: run at a velocity, override it, reverse, and stop with Velocity = 0.0.

fast runs the axis at 50; at 2 s slow (15) overrides it (fast CommandAborted, which stays TRUE while its
Execute is TRUE); at 4 s reverse runs at 30 in the negative direction (Direction 3); at 7 s zero sets
Velocity 0.0: InVelocity at standstill, and the command is complete (Busy FALSE).  The conveyor axis is a
speed-controlled axis (technology 0).  S7-Technology V4.1 §6.2.10.  Writes docs/img/s7t/MC_MoveVelocity.png
(or into the directory named by PLCMOTION_DOCS_IMG).
"""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7t import MC_MoveVelocity, MC_Power
from plcmotion.trace import Trace

ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
axis = ctl.add_positioning_axis("Conveyor", {
    "DBNumber": 11,
    "Wizard": {"Technology": 0},                     # speed-controlled axis
    "userdefaultdynamics": {"positiveaccel": 50.0, "negativeaccel": 50.0, "positiveaccelstartjerk": 500.0},
})
power = MC_Power(Axis=11, Enable=True)
fast = MC_MoveVelocity(Axis=11, Velocity=50.0)
slow = MC_MoveVelocity(Axis=11, Velocity=15.0)
reverse = MC_MoveVelocity(Axis=11, Velocity=30.0, Direction=3)
zero = MC_MoveVelocity(Axis=11, Velocity=0.0)


@ctl.program
def main():
    t = ctl.time
    power()
    fast(Execute=power.Status and t < 6.0)
    slow(Execute=t >= 2.0)
    reverse(Execute=t >= 4.0)
    zero(Execute=t >= 7.0)


trace = Trace(ctl, {
    "Conveyor.CommandVelocity": "Conveyor.CommandVelocity",
    "Conveyor.ActualVelocity": "Conveyor.ActualVelocity",
    "fast.InVelocity": lambda: fast.InVelocity,
    "fast.CommandAborted": lambda: fast.CommandAborted,
    "slow.InVelocity": lambda: slow.InVelocity,
    "reverse.InVelocity": lambda: reverse.InVelocity,
    "zero.Busy": lambda: zero.Busy,
    "zero.InVelocity": lambda: zero.InVelocity,
}).start()
ctl.run(10.0)
trace.stop()
assert zero.InVelocity and not zero.Busy and axis.db.CommandVelocity == 0.0

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[2] / "img" / "s7t"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_MoveVelocity.png", title="MC_MoveVelocity: override, reversal, Velocity = 0.0")
print(f"wrote {out / 'MC_MoveVelocity.png'}")
