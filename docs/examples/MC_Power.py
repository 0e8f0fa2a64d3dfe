"""MC_Power: enable an analog servo axis, then disable it twice, once per stop mode.

The drive reports "ready" 150 ms after its enable output is set; MC_Power shows Status only then.
The first disable brakes with the emergency deceleration (StopMode 0), the second one removes the
enable at once (StopMode 1) and the drive coasts down on its own ramp.
Writes docs/img/MC_Power.png (or into the directory named by PLCMOTION_DOCS_IMG).
"""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7_1200 import MC_MoveVelocity, MC_Power
from plcmotion.trace import Trace

ctl = Controller(servo_cycle=0.001, app_cycle=0.004)
axis = ctl.add_positioning_axis("Axis_1", {
    "Actor": {"Type": 0, "Interface": {"EnableDriveOutput": "Q0.0", "DriveReadyInput": "I0.0"}},
    "DynamicLimits": {"MaxVelocity": 400.0},
    "DynamicDefaults": {"Acceleration": 800.0, "Deceleration": 800.0, "EmergencyDeceleration": 2000.0,
                        "Jerk": 0.0},
    "Plant": {"ReadyDelay": 0.15, "OffRampTime": 0.6},
})
power = MC_Power(Axis=axis, StartMode=1)
run = MC_MoveVelocity(Axis=axis, Velocity=200.0)


@ctl.program
def main():
    t = ctl.time
    stop_mode = 0 if t < 1.4 else 1                  # taken over while Enable is TRUE
    power(Enable=0.1 <= t < 1.0 or 1.5 <= t < 2.4, StopMode=stop_mode)
    run(Execute=power.Status)                        # a new command after every enable


trace = Trace(ctl, {
    "Axis_1.Velocity": "Axis_1.Velocity",
    "Axis_1.ActualVelocity": "Axis_1.ActualVelocity",
    "power.Enable": lambda: power.Enable,
    "Q0.0 drive enable": lambda: ctl.outputs["Q0.0"],
    "I0.0 drive ready": lambda: ctl.inputs["I0.0"],
    "power.Status": lambda: power.Status,
    "power.Busy": lambda: power.Busy,
    "StatusBits.Enable": lambda: axis.StatusBits.Enable,
}).start()
ctl.run(3.2)
trace.stop()
assert not power.Status and not power.Busy and not axis.StatusBits.Enable and not power.Error

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[1] / "img"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_Power.png", title="MC_Power: enable with drive ready, disable with StopMode 0 and 1")
print(f"wrote {out / 'MC_Power.png'}")
