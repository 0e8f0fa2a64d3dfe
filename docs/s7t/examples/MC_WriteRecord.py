"""MC_WriteRecord + MC_ReadRecord: a PROFIdrive parameter request in data record 47 of the drive at logical
base address 256 (read p2000, the reference speed) and its answer (S7-Technology V4.1 §6.7.8, §6.7.9).
Writes docs/img/s7t/MC_WriteRecord.png (or into the directory named by PLCMOTION_DOCS_IMG)."""
import os
import struct
from pathlib import Path

from plcmotion import Controller
from plcmotion.s7t import MC_ReadRecord, MC_WriteRecord
from plcmotion.trace import Trace

ctl = Controller(family="S7-Technology", servo_cycle=0.002, app_cycle=0.004)
ctl.add_positioning_axis("Axis1", {"Drive": {"ReferenceSpeed": 3000.0}})
# reference 1, request 1 (read value), axis 0, one parameter: attribute 16#10, 1 element, p2000 index 0
request = bytes([1, 0x01, 0, 1, 0x10, 1]) + struct.pack(">HH", 2000, 0)
answer = bytearray(16)
write, read = MC_WriteRecord(), MC_ReadRecord()


@ctl.program
def ob1():
    write(Execute=True, Address=256, RecordNumber=47, Data=request)
    read(Execute=write.Done, Address=256, RecordNumber=47, Data=answer)


trace = Trace(ctl, {
    "write.Busy": lambda: write.Busy, "write.Done": lambda: write.Done, "write.Error": lambda: write.Error,
    "read.Busy": lambda: read.Busy, "read.Done": lambda: read.Done,
    "read.DataLength": lambda: read.DataLength,
    "p2000 (answer[6:10])": lambda: struct.unpack(">f", answer[6:10])[0],
}).start()
ctl.run(0.1)
trace.stop()
assert read.Done and read.DataLength == 10
assert struct.unpack(">f", answer[6:10])[0] == 3000.0
print(f"record 47 answer: {answer[:read.DataLength].hex()}")

out = Path(os.environ.get("PLCMOTION_DOCS_IMG", Path(__file__).resolve().parents[2] / "img" / "s7t"))
out.mkdir(parents=True, exist_ok=True)
trace.plot(out / "MC_WriteRecord.png", title="MC_WriteRecord: record 47 request (MC_WriteRecord) and answer (MC_ReadRecord)")
print(f"wrote {out / 'MC_WriteRecord.png'}")
