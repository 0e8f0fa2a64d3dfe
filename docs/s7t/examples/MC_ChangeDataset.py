"""MC_ChangeDataset: change over to a data set with another encoder and another controller gain.

The axis has two encoders (motor encoder 1, machine encoder 2) and two data sets without precontrol: data set
1 measures with encoder 1 at Kv 10, data set 2 with encoder 2 at Kv 40, so at 50 the following error is
50 / 10 = 5 with data set 1 and 50 / 40 = 1.25 with data set 2.  Encoder 1 was homed to 10 (Mode 3), encoder 2
still counts from 0.  to_200 positions at 200; change, started at 1 s with SyncEncoder, waits for the
positioning window (changeMode IN_POSITION) and is Done when to_200 is; the encoders are synchronized there,
so the actual value does not jump.  to_0 then runs back with the smaller following error of data set 2.
S7-Technology V4.1 §6.2.5, §3.1.10.  Writes docs/img/s7t/MC_ChangeDataset.png (or into the directory named by
PLCMOTION_DOCS_IMG).
"""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7t import MC_ChangeDataset, MC_Home, MC_MoveAbsolute, MC_Power, MC_ReadSysParameter
from plcmotion.trace import Trace

DS = "TypeOfAxis.NumberOfDataSets"
ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
axis = ctl.add_positioning_axis("Axis_1", {
    "DBNumber": 10,
    "TypeOfAxis.NumberOfEncoders.numberOfEncoders": 2,
    f"{DS}.numberOfDataSets": 2, f"{DS}.changeMode": 93,                      # 93: IN_POSITION
    f"{DS}.DataSet_1.ControllerStruct.PV_Controller.kpc": 0.0,
    f"{DS}.DataSet_2.ControllerStruct.PV_Controller.kpc": 0.0,
    f"{DS}.DataSet_2.ControllerStruct.PV_Controller.kv": 40.0,
    f"{DS}.DataSet_2.EncoderNumber.EncoderNumber": 2,
    "userdefaultdynamics": {"positiveaccel": 100.0, "negativeaccel": 100.0, "positiveaccelstartjerk": 1000.0},
})
power = MC_Power(Axis=axis, Enable=True)
home = MC_Home(Axis=axis, Mode=3, Position=10.0)
to_200 = MC_MoveAbsolute(Axis=axis, Position=200.0, Velocity=50.0)
change = MC_ChangeDataset(Axis=axis, Dataset=2, SyncEncoder=True)
to_0 = MC_MoveAbsolute(Axis=axis, Position=0.0, Velocity=50.0)
encoder = MC_ReadSysParameter(Axis=axis, ParameterNumber=4412)                # the encoder in force


@ctl.program
def main():
    t = ctl.time
    power()
    home(Execute=power.Status)
    to_200(Execute=home.Done)
    change(Execute=t >= 1.0)
    to_0(Execute=change.Done)
    encoder(Execute=False)
    encoder(Execute=True)


trace = Trace(ctl, {
    "Axis_1.CommandPosition": "Axis_1.CommandPosition",
    "Axis_1.ActualPosition": "Axis_1.ActualPosition",
    "Axis_1.CommandVelocity": "Axis_1.CommandVelocity",
    "Axis_1.FollowingError": "Axis_1.FollowingError",
    "change.Busy": lambda: change.Busy,
    "change.Done": lambda: change.Done,
    "encoder 2 in force": lambda: encoder.ValueDInt == 2,
    "to_0.Busy": lambda: to_0.Busy,
}).start()
ctl.run(10.0)
trace.stop()
assert to_200.Done and change.Done and to_0.Done and encoder.ValueDInt == 2
assert abs(axis.db.ActualPosition) < 0.01

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[2] / "img" / "s7t"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_ChangeDataset.png", title="MC_ChangeDataset: encoder and Kv changed over in position")
print(f"wrote {out / 'MC_ChangeDataset.png'}")
