"""MC_MoveJog: jog forward, then backward with a velocity change while the button is held.

0.2 s - 2.0 s: JogForward at 50.0; InVelocity once 50.0 is reached; released: the axis brakes with
               the configured deceleration and Busy goes FALSE at standstill.
3.5 s - 7.0 s: JogBackward at 50.0; at 5.0 s the Velocity input changes to 25.0 and is taken over at
               once (InVelocity FALSE until -25.0 is reached); released at 7.0 s.
Acceleration 100, deceleration 50: the manual's chart (§11.1.8.2) x 10.
Writes docs/img/MC_MoveJog.png (or into the directory named by PLCMOTION_DOCS_IMG).
"""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7_1200 import MC_MoveJog, MC_Power
from plcmotion.trace import Trace

ctl = Controller(servo_cycle=0.001, app_cycle=0.004)
axis = ctl.add_positioning_axis("Axis_1", {
    "Actor": {"Type": 1},
    "DynamicLimits": {"MaxVelocity": 200.0},
    "DynamicDefaults": {"Acceleration": 100.0, "Deceleration": 50.0, "Jerk": 0.0},
})
power = MC_Power(Axis=axis, Enable=True)
jog = MC_MoveJog(Axis=axis)


@ctl.program
def main():
    t = ctl.time
    power()
    jog(JogForward=0.2 <= t < 2.0, JogBackward=3.5 <= t < 7.0, Velocity=50.0 if t < 5.0 else 25.0)


trace = Trace(ctl, {
    "Axis_1.Velocity": "Axis_1.Velocity",
    "Axis_1.ActualVelocity": "Axis_1.ActualVelocity",
    "jog.Velocity": lambda: jog.Velocity,
    "jog.JogForward": lambda: jog.JogForward,
    "jog.JogBackward": lambda: jog.JogBackward,
    "jog.Busy": lambda: jog.Busy,
    "jog.InVelocity": lambda: jog.InVelocity,
}).start()
ctl.run(8.0)
trace.stop()
assert not jog.Busy and not jog.Error and axis.StatusBits.StandStill

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[1] / "img"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_MoveJog.png", title="MC_MoveJog: jog forward, jog backward with a velocity change")
print(f"wrote {out / 'MC_MoveJog.png'}")
