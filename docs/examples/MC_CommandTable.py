"""MC_CommandTable: run a motion sequence from a command table on a stepper (PTO) axis.

An MC_MoveVelocity runs when the table starts at 1.0 s.  Step 1 (Wait) leaves it alone; it is aborted
only when step 2, the first motion step, starts.  Step 2 blends into the velocity step 3 (the axis
reaches 150.0 at 20.0 instead of stopping), step 4 brakes, steps 5 and 6 move back, step 5 blending
into step 6.  CurrentStep and StepCode follow the running step.
Writes docs/img/MC_CommandTable.png (or into the directory named by PLCMOTION_DOCS_IMG).
"""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7_1200 import MC_CommandTable, MC_Home, MC_MoveVelocity, MC_Power
from plcmotion.trace import Trace

ctl = Controller(servo_cycle=0.001, app_cycle=0.004)
axis = ctl.add_positioning_axis("Axis_1", {
    "Actor": {"Type": 2},                            # command tables need a PTO axis
    "DynamicLimits": {"MaxVelocity": 100.0, "MinVelocity": 2.0},
    "DynamicDefaults": {"Acceleration": 100.0, "Deceleration": 100.0, "Jerk": 0.0},
})
# Type: 151 Wait, 6 Positioning Absolute, 7 Velocity set point, 2 Halt, 5 Positioning Relative
# NextStep: 0 "Complete command", 1 "Blend motion" (positioning steps only)
table = ctl.add_command_table("Table_1", [
    {"Type": 151, "Duration": 0.5, "StepCode": 10},
    {"Type": 6, "Position": 150.0, "Velocity": 60.0, "NextStep": 1, "StepCode": 20},
    {"Type": 7, "Velocity": 20.0, "Duration": 1.5, "StepCode": 30},
    {"Type": 2, "StepCode": 40},
    {"Type": 5, "Position": -80.0, "Velocity": 60.0, "NextStep": 1, "StepCode": 50},
    {"Type": 5, "Position": -40.0, "Velocity": 20.0, "StepCode": 60},
])
power = MC_Power(Axis=axis, Enable=True)
home = MC_Home(Axis=axis, Mode=0, Position=0.0)      # absolute steps need a homed axis
run = MC_MoveVelocity(Axis=axis, Velocity=30.0)
sequence = MC_CommandTable(Axis=axis, CommandTable=table, StartStep=1, EndStep=6)


@ctl.program
def main():
    t = ctl.time
    power()
    home(Execute=power.Status)
    run(Execute=home.Done and t < 2.0)
    sequence(Execute=t >= 1.0)


trace = Trace(ctl, {
    "Axis_1.Position": "Axis_1.Position",
    "Axis_1.Velocity": "Axis_1.Velocity",
    "run.Busy": lambda: run.Busy,
    "run.CommandAborted": lambda: run.CommandAborted,
    "sequence.Busy": lambda: sequence.Busy,
    "sequence.Done": lambda: sequence.Done,
    "StatusBits.CommandTableActive": lambda: axis.StatusBits.CommandTableActive,
    "sequence.CurrentStep": lambda: sequence.CurrentStep,
    "sequence.StepCode": lambda: sequence.StepCode,
}).start()
ctl.run_until(lambda: sequence.Done, timeout=20.0)
ctl.run(0.5)
trace.stop()
assert sequence.Done and sequence.CurrentStep == 6 and sequence.StepCode == 60

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[1] / "img"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_CommandTable.png",
           title="MC_CommandTable: wait, blended positioning, velocity, halt, relative moves")
print(f"wrote {out / 'MC_CommandTable.png'}; end position {axis.Position:.3f}")
