"""MC_MoveVelocity: run at constant velocity, override, and stop with Velocity = 0.0.

0.2 s: run_1 at 50.0 (Execute held until 2.5 s); InVelocity once 50.0 is reached.
1.5 s: run_2 at 20.0 (Execute only pulsed) takes over: run_1 shows CommandAborted (its Execute is still
       TRUE); run_2 keeps Busy and InVelocity TRUE after Execute has gone.
3.5 s: stop (MC_MoveVelocity with Velocity 0.0) brakes like MC_Halt.  run_2 ends without
       CommandAborted: its velocity was reached and Execute was FALSE (§9.5.3).  At standstill stop shows
       InVelocity, latched with Busy while its Execute stays TRUE.
Acceleration = Deceleration = 100 (the manual's chart x 10).
Writes docs/img/MC_MoveVelocity.png (or into the directory named by PLCMOTION_DOCS_IMG).
"""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7_1200 import MC_MoveVelocity, MC_Power
from plcmotion.trace import Trace

ctl = Controller(servo_cycle=0.001, app_cycle=0.004)
axis = ctl.add_positioning_axis("Axis_1", {
    "Actor": {"Type": 1},
    "DynamicLimits": {"MaxVelocity": 200.0},
    "DynamicDefaults": {"Acceleration": 100.0, "Deceleration": 100.0, "Jerk": 0.0},
})
power = MC_Power(Axis=axis, Enable=True)
run_1 = MC_MoveVelocity(Axis=axis, Velocity=50.0)
run_2 = MC_MoveVelocity(Axis=axis, Velocity=20.0, Direction=1)
stop = MC_MoveVelocity(Axis=axis, Velocity=0.0)


@ctl.program
def main():
    t = ctl.time
    power()
    run_1(Execute=0.2 <= t < 2.5)
    run_2(Execute=1.5 <= t < 1.6)
    stop(Execute=3.5 <= t < 5.0)


trace = Trace(ctl, {
    "Axis_1.Velocity": "Axis_1.Velocity",
    "Axis_1.ActualVelocity": "Axis_1.ActualVelocity",
    "run_1.Execute": lambda: run_1.Execute,
    "run_1.Busy": lambda: run_1.Busy,
    "run_1.InVelocity": lambda: run_1.InVelocity,
    "run_1.CommandAborted": lambda: run_1.CommandAborted,
    "run_2.Execute": lambda: run_2.Execute,
    "run_2.Busy": lambda: run_2.Busy,
    "run_2.InVelocity": lambda: run_2.InVelocity,
    "run_2.CommandAborted": lambda: run_2.CommandAborted,
    "stop.Execute": lambda: stop.Execute,
    "stop.Busy": lambda: stop.Busy,
    "stop.InVelocity": lambda: stop.InVelocity,
    "StatusBits.ConstantVelocity": lambda: axis.StatusBits.ConstantVelocity,
}).start()
ctl.run(5.5)
trace.stop()
assert not (run_1.Busy or run_2.Busy or stop.Busy) and axis.StatusBits.StandStill

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[1] / "img"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_MoveVelocity.png", title="MC_MoveVelocity: InVelocity, override, stop with Velocity 0.0")
print(f"wrote {out / 'MC_MoveVelocity.png'}")
