"""MC_WriteDriveParameter: write p1082 (maximum speed, REAL) of the drive at logical base address 256; a value
below the parameter's limit is refused by the drive with 16#8102 (S7-Technology V4.1 §6.7.11).
Writes docs/img/s7t/MC_WriteDriveParameter.png (or into the directory named by PLCMOTION_DOCS_IMG)."""
import os
import struct
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7t import MC_WriteDriveParameter
from plcmotion.trace import Trace

ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
ctl.add_positioning_axis("Axis1", {})
good, bad = MC_WriteDriveParameter(), MC_WriteDriveParameter()


@ctl.program
def ob1():
    good(Execute=True, Address=256, ParameterNumber=1082, Data=struct.pack(">f", 4500.0))
    bad(Execute=good.Done, Address=256, ParameterNumber=1082, Data=struct.pack(">f", -1.0))


trace = Trace(ctl, {
    "good.Busy": lambda: good.Busy, "good.Done": lambda: good.Done,
    "bad.Busy": lambda: bad.Busy, "bad.Error": lambda: bad.Error, "bad.ErrorID": lambda: bad.ErrorID,
}).start()
ctl.run(0.1)
trace.stop()
assert good.Done and bad.Error and bad.ErrorID == 0x8102
print(f"p1082 = 4500.0 written; -1.0 refused with 16#{bad.ErrorID:04X}")

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[2] / "img" / "s7t"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_WriteDriveParameter.png", title="MC_WriteDriveParameter: write p1082 = 4500.0, then -1.0 (16#8102)")
print(f"wrote {out / 'MC_WriteDriveParameter.png'}")
