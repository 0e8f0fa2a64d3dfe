"""MC_Reset: acknowledge a drive fault; the axis enables itself again because Enable stayed TRUE.

At 0.5 s the simulated PROFIdrive drive shuts down (injected fault 16#800C/16#003D, persistent): the
enable is removed, MC_Power shows the error.  The first MC_Reset at 0.9 s fails because the cause is
still there; the fault is cleared at 1.2 s and the second MC_Reset at 1.4 s acknowledges it.
Writes docs/img/MC_Reset.png (or into the directory named by PLCMOTION_DOCS_IMG).
"""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7_1200 import MC_MoveVelocity, MC_Power, MC_Reset
from plcmotion.trace import Trace

ctl = Controller(servo_cycle=0.001, app_cycle=0.004)
axis = ctl.add_positioning_axis("Axis_1", {
    "Actor": {"Type": 1},
    "DynamicLimits": {"MaxVelocity": 400.0},
    "DynamicDefaults": {"Acceleration": 800.0, "Deceleration": 800.0, "Jerk": 0.0},
    "Plant": {"ReadyDelay": 0.05, "OffRampTime": 0.3},
})
power = MC_Power(Axis=axis, Enable=True)
reset = MC_Reset(Axis=axis)
run = MC_MoveVelocity(Axis=axis, Velocity=200.0)
faults = {0.5: lambda: axis.inject_fault("drive", "shutdown", persistent=True),
          1.2: lambda: axis.clear_fault("drive")}
seen = []                                            # (time, ErrorID) of the MC_Reset errors


@ctl.program
def main():
    t = ctl.time
    for when in [w for w in faults if t >= w]:
        faults.pop(when)()
    power()
    reset(Execute=0.9 <= t < 1.0 or 1.4 <= t < 1.5)
    run(Execute=power.Status)
    if reset.Error and not seen:
        seen.append((t, reset.ErrorID))


trace = Trace(ctl, {
    "Axis_1.Velocity": "Axis_1.Velocity",
    "Axis_1.ActualVelocity": "Axis_1.ActualVelocity",
    "power.Status": lambda: power.Status,
    "power.Error": lambda: power.Error,
    "StatusBits.Error": lambda: axis.StatusBits.Error,
    "reset.Execute": lambda: reset.Execute,
    "reset.Done": lambda: reset.Done,
    "reset.Error": lambda: reset.Error,
    "run.InVelocity": lambda: run.InVelocity,
}).start()
ctl.run(2.0)
trace.stop()
assert seen and seen[0][1] == 0x800C                  # first reset: the drive is still faulty
assert power.Status and not axis.StatusBits.Error and run.InVelocity

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[1] / "img"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_Reset.png", title="MC_Reset: drive fault 16#800C, acknowledged once the cause is gone")
print(f"wrote {out / 'MC_Reset.png'}")
