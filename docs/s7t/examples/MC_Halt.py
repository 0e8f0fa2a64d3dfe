"""MC_Halt: brake to standstill; a new motion command may take over.

move positions the axis at 300 at 100.  At 1.5 s halt brakes it (Deceleration 50): move shows
CommandAborted.  At 2.5 s, before the axis stands still, resume (MC_MoveAbsolute to 250) takes over from the
halt (halt CommandAborted) and the axis speeds up again without stopping.  At 3.2 s halt_2 takes over from
resume and brakes to standstill: Done there.  S7-Technology V4.1 §6.2.4.  Writes docs/img/s7t/MC_Halt.png
(or into the directory named by PLCMOTION_DOCS_IMG).
"""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7t import MC_Halt, MC_MoveAbsolute, MC_Power
from plcmotion.trace import Trace

ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
axis = ctl.add_positioning_axis("Axis_1", {
    "DBNumber": 10,
    "TypeOfAxis.Homing.referencingNecessary": 0,
    "userdefaultdynamics": {"positiveaccel": 100.0, "negativeaccel": 100.0, "positiveaccelstartjerk": 1000.0},
})
power = MC_Power(Axis=axis, Enable=True)
move = MC_MoveAbsolute(Axis=axis, Position=300.0, Velocity=100.0)
halt = MC_Halt(Axis=axis, Deceleration=50.0)
resume = MC_MoveAbsolute(Axis=axis, Position=250.0, Velocity=100.0)
halt_2 = MC_Halt(Axis=axis, Deceleration=50.0)


@ctl.program
def main():
    t = ctl.time
    power()
    move(Execute=power.Status)
    halt(Execute=t >= 1.5)
    resume(Execute=t >= 2.5)
    halt_2(Execute=t >= 3.2)


trace = Trace(ctl, {
    "Axis_1.CommandPosition": "Axis_1.CommandPosition",
    "Axis_1.ActualPosition": "Axis_1.ActualPosition",
    "Axis_1.CommandVelocity": "Axis_1.CommandVelocity",
    "move.CommandAborted": lambda: move.CommandAborted,
    "halt.Busy": lambda: halt.Busy,
    "halt.CommandAborted": lambda: halt.CommandAborted,
    "resume.Busy": lambda: resume.Busy,
    "resume.CommandAborted": lambda: resume.CommandAborted,
    "halt_2.Busy": lambda: halt_2.Busy,
    "halt_2.Done": lambda: halt_2.Done,
}).start()
ctl.run(6.0)
trace.stop()
assert move.CommandAborted and halt.CommandAborted and resume.CommandAborted and halt_2.Done
assert axis.db.Statusword.Standstill

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[2] / "img" / "s7t"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_Halt.png", title="MC_Halt: brake, taken over by a new command, brake to standstill")
print(f"wrote {out / 'MC_Halt.png'}")
