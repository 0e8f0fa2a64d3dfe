"""MC_ReadDriveParameter: read p2000 (reference speed, REAL) of the drive at logical base address 256; Busy
while the request travels to the drive and back (S7-Technology V4.1 §6.7.10).
Writes docs/img/s7t/MC_ReadDriveParameter.png (or into the directory named by PLCMOTION_DOCS_IMG)."""
import os
import struct
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7t import MC_ReadDriveParameter
from plcmotion.trace import Trace

ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
ctl.add_positioning_axis("Axis1", {"Drive": {"ReferenceSpeed": 3000.0}})
data = bytearray(4)
read = MC_ReadDriveParameter()
calls = []


@ctl.program
def ob1():
    read(Execute=True, Address=256, ParameterNumber=2000, NumberOfElements=0, Data=data)
    calls.append("Busy" if read.Busy else "Done" if read.Done else "Error")


trace = Trace(ctl, {
    "read.Busy": lambda: read.Busy, "read.Done": lambda: read.Done, "read.Error": lambda: read.Error,
    "read.DataLength": lambda: read.DataLength, "p2000 (Data)": lambda: struct.unpack(">f", data)[0],
}).start()
ctl.run(0.02)
trace.stop()
assert calls[:3] == ["Busy", "Busy", "Done"] and read.DataLength == 4
print(f"p2000 = {struct.unpack('>f', data)[0]} 1/min; outputs per call: {calls[:3]}")

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[2] / "img" / "s7t"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_ReadDriveParameter.png", title="MC_ReadDriveParameter: read p2000 of the drive at address 256")
print(f"wrote {out / 'MC_ReadDriveParameter.png'}")
