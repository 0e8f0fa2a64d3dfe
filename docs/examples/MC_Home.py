"""MC_Home Mode 3: active homing of a stepper (PTO) axis on a homing switch.

The switch (input I0.3) is actuated between machine positions 60 and 70.  Homing runs in positive
direction and references on the upper end of the switch (SideInput TRUE) with a home position offset
of 5.0, the sequence of the manual's example: search at the approach velocity, cross the upper end at
the referencing velocity (the homing event), then travel the offset and stop at Position = 0.0.
Writes docs/img/MC_Home.png (or into the directory named by PLCMOTION_DOCS_IMG).
"""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7_1200 import MC_Home, MC_Power
from plcmotion.trace import Trace

ctl = Controller(servo_cycle=0.001, app_cycle=0.004)
axis = ctl.add_positioning_axis("Axis_1", {
    "Actor": {"Type": 2},                            # PTO: homing on a digital input only
    "DynamicLimits": {"MaxVelocity": 100.0, "MinVelocity": 2.0},
    "DynamicDefaults": {"Acceleration": 200.0, "Deceleration": 200.0, "Jerk": 0.0},
    "Sensor[1].ActiveHoming": {"Mode": 2, "DigitalInputAddress": "I0.3", "SideInput": True,
                               "SwitchLevel": True, "HomePositionOffset": 5.0},
    "Homing": {"ApproachDirection": True, "ApproachVelocity": 40.0, "ReferencingVelocity": 8.0},
    "Plant": {"HomingSwitchPosition": 60.0, "HomingSwitchLength": 10.0},
})
power = MC_Power(Axis=axis, Enable=True)
home = MC_Home(Axis=axis, Mode=3, Position=0.0)


@ctl.program
def main():
    power()
    home(Execute=power.Status)


trace = Trace(ctl, {
    "Axis_1.Position": "Axis_1.Position",
    "Axis_1.Velocity": "Axis_1.Velocity",
    "I0.3 homing switch": lambda: ctl.inputs["I0.3"],
    "home.Busy": lambda: home.Busy,
    "home.Done": lambda: home.Done,
    "StatusBits.HomingCommand": lambda: axis.StatusBits.HomingCommand,
    "StatusBits.HomingDone": lambda: axis.StatusBits.HomingDone,
}).start()
ctl.run_until(lambda: home.Done, timeout=10.0)
ctl.run(0.3)
trace.stop()
assert home.Done and axis.StatusBits.HomingDone and abs(axis.Position) < 1e-9
assert home.ReferenceMarkPosition == -5.0            # Position - HomePositionOffset (docs/decisions.md #32)

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[1] / "img"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_Home.png", title="MC_Home Mode 3: search, reference on the upper switch end, travel the offset")
print(f"wrote {out / 'MC_Home.png'}; machine position at Position 0.0: {axis.drive.mechanical_position():.3f}")
