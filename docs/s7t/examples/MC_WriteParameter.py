"""MC_WriteParameter: the velocity override (parameter 4142, effective immediately) halves the speed of a
running motion; the leadscrew pitch (1100, effective after a restart) answers with warning 16#0020 and
Statusword.RequestRestart (S7-Technology V4.1 §6.7.5).
Writes docs/img/s7t/MC_WriteParameter.png (or into the directory named by PLCMOTION_DOCS_IMG)."""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7t import MC_MoveVelocity, MC_Power, MC_WriteParameter
from plcmotion.trace import Trace

ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
axis = ctl.add_positioning_axis("Axis1", {"Wizard": {"Virtual": 1}})
power, move, override, pitch = MC_Power(), MC_MoveVelocity(), MC_WriteParameter(), MC_WriteParameter()


@ctl.program
def ob1():
    power(Axis=axis, Enable=True)
    move(Axis=axis, Execute=power.Status, Velocity=100.0)
    override(Axis=axis, Execute=ctl.time >= 2.0, ParameterNumber=4142, Value=50.0)
    pitch(Axis=axis, Execute=ctl.time >= 2.0, ParameterNumber=1100, Value=5.0)


trace = Trace(ctl, {
    "Axis1.CommandPosition": "Axis1.CommandPosition", "Axis1.CommandVelocity": "Axis1.CommandVelocity",
    "override.Busy": lambda: override.Busy, "override.Done": lambda: override.Done,
    "pitch.Done": lambda: pitch.Done, "pitch.ErrorID": lambda: pitch.ErrorID,
    "Axis1.Statusword.RequestRestart": lambda: bool(axis.db.Statusword.RequestRestart),
}).start()
ctl.run(3.0)
trace.stop()
assert override.Done and abs(axis.db.CommandVelocity - 50.0) < 1e-9
assert pitch.Done and pitch.ErrorID == 0x0020 and axis.db.Statusword.RequestRestart
print(f"velocity with 50 % override: {axis.db.CommandVelocity}, leadscrew pitch: warning 16#{pitch.ErrorID:04X}")

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[2] / "img" / "s7t"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_WriteParameter.png", title="MC_WriteParameter: override 4142 = 50 % at 2 s, pitch 1100 (warning 16#0020)")
print(f"wrote {out / 'MC_WriteParameter.png'}")
