"""MC_Home: active homing with reference cam and encoder zero mark, then a correction of the actual value.

The reference cam of the simulated machine is on I0.0 (machine position 100 ... 120), the encoder has a zero
mark every 10 starting at 5.  home (Mode 1, Position 0.0) searches the cam at the approach velocity 50, goes
on at the shutdown velocity 5 and homes at the first zero mark after the cam (machine 125), which becomes 0.0:
Statusword.HomingDone.  At 8 s correct (Mode 4, Position 25.0) subtracts 25 from the actual value without a
motion; the axis stays homed.  S7-Technology V4.1 §6.2.2, §4.5.10.  Writes docs/img/s7t/MC_Home.png (or into
the directory named by PLCMOTION_DOCS_IMG).
"""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7t import MC_Home, MC_Power
from plcmotion.trace import Trace

ENC = "TypeOfAxis.NumberOfEncoders.Encoder_1.IncHomingEncoder"
ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
axis = ctl.add_positioning_axis("Axis_1", {
    "DBNumber": 10,
    f"{ENC}.homingMode": 22, f"{ENC}.logAdressBero": 0, f"{ENC}.bitNumberBero": 0,   # cam and zero mark
    "Plant.HomingSwitchPosition": 100.0, "Plant.HomingSwitchLength": 20.0,
    "Plant.ZeroMarkDistance": 10.0, "Plant.ZeroMarkOffset": 5.0,
    "userdefaulthoming": {"homingapproachvelocity": 50.0, "homingentryvelocity": 20.0,
                          "homingreducedvelocity": 5.0},
    "userdefaultdynamics": {"positiveaccel": 200.0, "negativeaccel": 200.0, "positiveaccelstartjerk": 0.0},
})
power = MC_Power(Axis=axis, Enable=True)
home = MC_Home(Axis=axis, Mode=1, Position=0.0)
correct = MC_Home(Axis=axis, Mode=4, Position=25.0)


@ctl.program
def main():
    power()
    home(Execute=power.Status)
    correct(Execute=ctl.time >= 8.0)


trace = Trace(ctl, {
    "Axis_1.CommandPosition": "Axis_1.CommandPosition",
    "Axis_1.ActualPosition": "Axis_1.ActualPosition",
    "Axis_1.CommandVelocity": "Axis_1.CommandVelocity",
    "Axis_1.Statusword.HomingDone": lambda: bool(axis.db.Statusword.HomingDone),
    "home.Busy": lambda: home.Busy,
    "home.Done": lambda: home.Done,
    "correct.Done": lambda: correct.Done,
}).start()
ctl.run(9.0)
trace.stop()
assert home.Done and correct.Done and axis.db.Statusword.HomingDone
assert abs(axis.db.ActualPosition - (-25.0)) < 0.01        # 0.0 at the zero mark, corrected by 25

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[2] / "img" / "s7t"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_Home.png", title="MC_Home: active homing (cam and zero mark), then Mode 4 correction")
print(f"wrote {out / 'MC_Home.png'}")
