"""MC_ReadSysParameter: read the positive software limit switch (parameter 3, REAL) and the default direction
(parameter 4241, ENUM EnumDirection) of an axis by number (S7-Technology V4.1 §6.7.4).
Writes docs/img/s7t/MC_ReadSysParameter.png (or into the directory named by PLCMOTION_DOCS_IMG)."""
import os
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7t import MC_ReadSysParameter
from plcmotion.trace import Trace

ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
axis = ctl.add_positioning_axis("Axis1", {"Wizard": {"Virtual": 1}, "swlimit.plusposition": 250.0})
read_limit, read_direction = MC_ReadSysParameter(), MC_ReadSysParameter()


@ctl.program
def ob1():
    read_limit(Axis=axis.db_number, Execute=True, ParameterNumber=3)
    read_direction(Axis=axis.db_number, Execute=True, ParameterNumber=4241)


trace = Trace(ctl, {
    "read_limit.Busy": lambda: read_limit.Busy, "read_limit.Done": lambda: read_limit.Done,
    "read_limit.Value": lambda: read_limit.Value,
    "read_direction.Done": lambda: read_direction.Done, "read_direction.ValueDInt": lambda: read_direction.ValueDInt,
}).start()
ctl.run(0.02)
trace.stop()
assert read_limit.Done and read_limit.Value == 250.0
assert read_direction.Done and read_direction.ValueDInt == 5          # POSITIVE
print(f"swlimit.plusposition = {read_limit.Value}, userdefaultdynamics.direction = {read_direction.ValueDInt}")

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[2] / "img" / "s7t"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_ReadSysParameter.png", title="MC_ReadSysParameter: read parameter 3 (REAL) and 4241 (ENUM)")
print(f"wrote {out / 'MC_ReadSysParameter.png'}")
