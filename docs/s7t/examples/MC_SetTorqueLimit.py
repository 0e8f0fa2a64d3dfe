"""MC_SetTorqueLimit: a slide runs speed-controlled against a fixed end stop at 50 mm and presses there with the
torque the limit allows (S7-Technology V4.1 §6.2.12, §9.3.2.2).

The drive is on telegram 105 (torque reduction), torque reference `maxTorque` 3.2 N m.  At 0.1 s the limit is
set to 0.5 N m, then MC_MoveVelocity runs the slide at 20 mm/s (PositionControl FALSE) into the stop at 50 mm:
the speed controller asks for more torque, the drive gives 0.5 N m (Statusword.TorqueLimiting).  At 3.5 s
EnableLimit FALSE lifts the limit and the drive presses with what the speed controller asks for (about 4 N m);
at 4.5 s the limit is set to 1.0 N m.  Writes docs/img/s7t/MC_SetTorqueLimit.png (or into the directory named by
PLCMOTION_DOCS_IMG).
"""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7t import MC_MoveVelocity, MC_Power, MC_SetTorqueLimit
from plcmotion.trace import Trace

ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
slide = ctl.add_positioning_axis("Slide", {
    "Wizard.Telegram": 105,
    "TypeOfAxis.Homing.referencingNecessary": 0,
    "TypeOfAxis.SetPointDriverInfo.DriveData.maxTorque": 3.2,
    "Plant.EndStopMaxPosition": 50.0,
})
power, run = MC_Power(), MC_MoveVelocity()
limit, lift, harder = MC_SetTorqueLimit(), MC_SetTorqueLimit(), MC_SetTorqueLimit()
seen = {}


@ctl.program
def main():
    power(Axis=slide, Enable=True)
    limit(Axis=slide, Execute=power.Status and ctl.time >= 0.1, EnableLimit=True, MaxTorque=0.5)
    run(Axis=slide, Execute=limit.Done, Velocity=20.0, PositionControl=False)
    lift(Axis=slide, Execute=ctl.time >= 3.5, EnableLimit=False)
    harder(Axis=slide, Execute=ctl.time >= 4.5, EnableLimit=True, MaxTorque=1.0)
    if 3.4 <= ctl.time < 3.5:
        seen["limited"] = (slide.drive.torque, bool(slide.db.Statusword.TorqueLimiting))
    if 4.4 <= ctl.time < 4.5:
        seen["free"] = slide.drive.torque


trace = Trace(ctl, {
    "Slide.CommandVelocity": "Slide.CommandVelocity",
    "Slide.ActualPosition": "Slide.ActualPosition",
    "Slide.ActualVelocity": "Slide.ActualVelocity",
    "drive torque [N m]": lambda: slide.drive.torque,
    "MaxTorque in force [N m]": lambda: (1.0 if harder.Done else float("nan") if lift.Done else
                                         0.5 if limit.Done else float("nan")),
    "limit.Done": lambda: limit.Done, "lift.Done": lambda: lift.Done, "harder.Done": lambda: harder.Done,
    "Slide.Statusword.TorqueLimitingCommand": lambda: bool(slide.db.Statusword.TorqueLimitingCommand),
    "Slide.Statusword.TorqueLimiting": lambda: bool(slide.db.Statusword.TorqueLimiting),
}).start()
ctl.run(6.0)
trace.stop()
torque, limiting = seen["limited"]
assert limiting and abs(torque - 0.5) < 1e-9                  # pressed with the limit, 0.5 N m
assert seen["free"] > 1.0                                       # without the limit: more
assert abs(slide.drive.torque - 1.0) < 1e-9 and slide.db.Statusword.TorqueLimiting
assert abs(slide.db.ActualPosition - 50.0) < 0.01               # at the end stop all along
print(f"at the end stop: {torque} N m limited, {seen['free']:.2f} N m without the limit, then "
      f"{slide.drive.torque} N m")

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[2] / "img" / "s7t"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_SetTorqueLimit.png", title="MC_SetTorqueLimit: pressing against an end stop, 0.5 N m / no limit / 1.0 N m")
print(f"wrote {out / 'MC_SetTorqueLimit.png'}")
